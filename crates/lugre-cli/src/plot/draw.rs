//! Drawing a figure (or panels of figures) on a plotters drawing area: axes, curves, markers,
//! notes and the legend, every size in pixels scaled by `s`.

use anyhow::Result;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::clip::clip;
use super::dashes::{dash, thin, MIN_PIXEL_STEP};
use super::elements::MarkerElement;
use super::legend::LegendBox;
use super::{Figure, Panels};

impl Figure {
    fn bounds(&self) -> ((f64, f64), (f64, f64)) {
        let pts = self
            .curves
            .iter()
            .flat_map(|c| c.points.iter().copied())
            .chain(self.markers.iter().map(|m| m.at))
            .chain(self.notes.iter().map(|n| n.at));
        let (mut x0, mut x1, mut y0, mut y1) = (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        );
        for (x, y) in pts.filter(|(x, y)| x.is_finite() && y.is_finite()) {
            x0 = x0.min(x);
            x1 = x1.max(x);
            y0 = y0.min(y);
            y1 = y1.max(y);
        }
        let pad = |lo: f64, hi: f64| {
            if lo > hi {
                return (0.0, 1.0);
            }
            let span = if hi > lo { hi - lo } else { lo.abs().max(1.0) };
            (lo - 0.05 * span, hi + 0.05 * span)
        };
        (
            self.x_range.unwrap_or_else(|| pad(x0, x1)),
            self.y_range.unwrap_or_else(|| pad(y0, y1)),
        )
    }

    fn chart_builder<'a, 'b, DB: DrawingBackend>(
        area: &'a DrawingArea<DB, Shift>,
        s: f64,
    ) -> ChartBuilder<'a, 'b, DB> {
        let px = |v: f64| (v * s).round() as u32;
        let mut builder = ChartBuilder::on(area);
        builder
            .margin(px(18.0))
            .x_label_area_size(px(62.0))
            .y_label_area_size(px(92.0));
        builder
    }

    /// The figure with its log axes' coordinates replaced by their base-10 logarithms (drawn
    /// on linear axes whose tick labels show `10^v`); points with a coordinate <= 0 on a log
    /// axis are left out, splitting a curve there.
    fn in_log_space(&self) -> Figure {
        let (lx, ly) = (self.log_x, self.log_y);
        let f = |v: f64, log: bool| if log { v.log10() } else { v };
        let keep = |&(x, y): &(f64, f64)| (!lx || x > 0.0) && (!ly || y > 0.0);
        let map = |(x, y): (f64, f64)| (f(x, lx), f(y, ly));
        let mut out = self.clone();
        out.curves = self
            .curves
            .iter()
            .flat_map(|c| {
                c.points
                    .split(|p| !keep(p))
                    .filter(|run| !run.is_empty())
                    .enumerate()
                    .map(move |(i, run)| {
                        let mut piece = c.clone();
                        piece.points = run.iter().copied().map(map).collect();
                        // One legend entry per curve, on its first piece.
                        if i > 0 {
                            piece.label = None;
                        }
                        piece
                    })
            })
            .collect();
        out.markers.retain(|m| keep(&m.at));
        out.markers.iter_mut().for_each(|m| m.at = map(m.at));
        out.notes.retain(|n| keep(&n.at));
        out.notes.iter_mut().for_each(|n| n.at = map(n.at));
        let range = |r: Option<(f64, f64)>, log: bool| match r {
            Some((lo, hi)) if log && lo > 0.0 && hi > lo => Some((lo.log10(), hi.log10())),
            Some(_) if log => None,
            r => r,
        };
        out.x_range = range(self.x_range, lx);
        out.y_range = range(self.y_range, ly);
        out
    }

    /// Draws the figure on `area` (the whole image, or one panel of it), every size in pixels
    /// multiplied by `s` (PNGs are drawn at twice their size and scaled down: anti-aliasing).
    fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>, s: f64) -> Result<()>
    where
        DB::ErrorType: 'static,
    {
        if (self.log_x || self.log_y) && !self.curves.iter().all(|c| c.points.is_empty()) {
            let mut linear = self.in_log_space();
            // Drawn on linear axes; the flags now only choose the tick labels.
            linear.curves.retain(|c| !c.points.is_empty());
            return linear.draw_linear(area, s);
        }
        self.draw_linear(area, s)
    }

    /// [`Self::draw`] in the figure's own coordinates (a log axis's already in decades).
    fn draw_linear<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>, s: f64) -> Result<()>
    where
        DB::ErrorType: 'static,
    {
        let err = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow::anyhow!("{e:?}");
        area.fill(&WHITE).map_err(err)?;
        let area = with_title(area, self.title.as_deref(), s).map_err(err)?;
        // Everything drawn in pixels goes through `screen`, whose coordinates are the
        // backend's (the chart reports backend pixels, and a panel's area is offset).
        let screen = area.use_screen_coord();
        let ((x0, x1), (y0, mut y1)) = self.bounds();

        let plot = Self::plot_box(&area, (x0, x1), (y0, y1), s).map_err(err)?;
        let legend = LegendBox::new(self, &screen, s).map_err(err)?;
        let mut legend_at = None;
        if let Some(lb) = &legend {
            let (top, corner) = self.place_legend(lb, &plot, (x0, x1), (y0, y1), s);
            y1 = top;
            legend_at = Some(lb.origin(corner, &plot));
        }

        let mut chart = Self::chart_builder(&area, s)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(err)?;
        self.draw_mesh(&mut chart, (x0, x1), (y0, y1), s)
            .map_err(err)?;
        let map = plot.mapping((x0, x1), (y0, y1));
        self.draw_curves(&screen, &plot, &map, s).map_err(err)?;
        self.draw_markers(&mut chart, s).map_err(err)?;
        self.draw_notes(&chart, &screen, s).map_err(err)?;
        if let (Some(lb), Some(at)) = (&legend, legend_at) {
            lb.draw(&screen, at).map_err(err)?;
        }
        Ok(())
    }

    /// The plotting area's pixels: they depend on the layout only, not on the axis ranges.
    fn plot_box<DB: DrawingBackend>(
        area: &DrawingArea<DB, Shift>,
        (x0, x1): (f64, f64),
        (y0, y1): (f64, f64),
        s: f64,
    ) -> Result<PixelBox, DrawingAreaErrorKind<DB::ErrorType>> {
        let chart = Self::chart_builder(area, s).build_cartesian_2d(x0..x1, y0..y1)?;
        let (xs, ys) = chart.plotting_area().get_pixel_range();
        Ok(PixelBox {
            left: f64::from(xs.start),
            right: f64::from(xs.end),
            top: f64::from(ys.start),
            bottom: f64::from(ys.end),
        })
    }

    /// The grid, the ticks and the axis labels.
    fn draw_mesh<DB: DrawingBackend>(
        &self,
        chart: &mut Chart<'_, DB>,
        (x0, x1): (f64, f64),
        (y0, y1): (f64, f64),
        s: f64,
    ) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
        let x_tick = |v: &f64| axis_label(*v, x1 - x0, self.log_x);
        let y_tick = |v: &f64| axis_label(*v, y1 - y0, self.log_y);
        chart
            .configure_mesh()
            .x_label_formatter(&x_tick)
            .y_label_formatter(&y_tick)
            .x_desc(&self.x_label)
            .y_desc(&self.y_label)
            .axis_desc_style(("sans-serif", AXIS_FONT * s))
            .label_style(("sans-serif", TICK_FONT * s))
            .light_line_style(RGBColor(235, 235, 235).stroke_width(scaled(1, s)))
            .bold_line_style(RGBColor(210, 210, 210).stroke_width(scaled(1, s)))
            .axis_style(BLACK.stroke_width(scaled(1, s)))
            // plotters' own tick length is in pixels whatever the scale (half as long in a PNG).
            .set_all_tick_mark_size(scaled(TICK_LENGTH, s))
            .x_labels(9)
            .y_labels(9)
            .draw()
    }

    /// The curves, cut to the plotting area `plot`, thinned and dashed in pixel space on
    /// `screen` (`map` takes data to its pixels).
    fn draw_curves<DB: DrawingBackend>(
        &self,
        screen: &DrawingArea<DB, Shift>,
        plot: &PixelBox,
        map: &Mapping,
        s: f64,
    ) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
        for curve in &self.curves {
            let pixels: Vec<(f64, f64)> = curve.points.iter().map(|&p| map.apply(p)).collect();
            let style = ShapeStyle::from(&curve.color).stroke_width(scaled(curve.width, s));
            for inside in clip(&pixels, plot) {
                let inside = thin(&inside, MIN_PIXEL_STEP * s);
                for piece in dash(&inside, &curve.style.pattern(s)) {
                    let piece: Vec<(i32, i32)> = piece
                        .iter()
                        .map(|&(x, y)| (x.round() as i32, y.round() as i32))
                        .collect();
                    screen.draw(&PathElement::new(piece, style))?;
                }
            }
        }
        Ok(())
    }

    fn draw_markers<DB: DrawingBackend>(
        &self,
        chart: &mut Chart<'_, DB>,
        s: f64,
    ) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
        for m in &self.markers {
            let style = ShapeStyle::from(&m.color).stroke_width(scaled(2, s));
            chart.draw_series(std::iter::once(MarkerElement::new(m.at, m.shape, style, s)))?;
        }
        Ok(())
    }

    fn draw_notes<DB: DrawingBackend>(
        &self,
        chart: &Chart<'_, DB>,
        screen: &DrawingArea<DB, Shift>,
        s: f64,
    ) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
        for n in &self.notes {
            let (px, py) = chart.backend_coord(&n.at);
            let font = TextStyle::from(("sans-serif", NOTE_FONT * s).into_font())
                .pos(Pos::new(HPos::Center, VPos::Center));
            let (dx, dy) = (f64::from(n.offset.0) * s, f64::from(n.offset.1) * s);
            screen.draw(&Text::new(
                n.text.clone(),
                (px + dx.round() as i32, py + dy.round() as i32),
                font,
            ))?;
        }
        Ok(())
    }
}

/// A chart with `f64` axes.
type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Something drawn on a whole image.
pub(super) trait Render {
    fn render<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>, s: f64) -> Result<()>
    where
        DB::ErrorType: 'static;
}

impl Render for Figure {
    fn render<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>, s: f64) -> Result<()>
    where
        DB::ErrorType: 'static,
    {
        self.draw(area, s)
    }
}

impl Render for Panels {
    fn render<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>, s: f64) -> Result<()>
    where
        DB::ErrorType: 'static,
    {
        let err = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow::anyhow!("{e:?}");
        area.fill(&WHITE).map_err(err)?;
        let area = with_title(area, self.title.as_deref(), s).map_err(err)?;
        let cols = self.cols.max(1);
        let rows = self.panels.len().div_ceil(cols).max(1);
        for (panel, cell) in self.panels.iter().zip(area.split_evenly((rows, cols))) {
            panel.draw(&cell, s)?;
        }
        Ok(())
    }
}

/// `area` below a band holding `title` (plotters' own `titled` leaves too little room above
/// the text at large sizes and clips its top).
fn with_title<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: Option<&str>,
    s: f64,
) -> Result<DrawingArea<DB, Shift>, DrawingAreaErrorKind<DB::ErrorType>> {
    let Some(title) = title else {
        return Ok(area.clone());
    };
    let band = (TITLE_FONT * s * 1.9).round() as u32;
    let (head, rest) = area.split_vertically(band);
    let (w, h) = head.dim_in_pixel();
    let font = TextStyle::from(("sans-serif", TITLE_FONT * s).into_font())
        .pos(Pos::new(HPos::Center, VPos::Center));
    head.draw(&Text::new(
        title.to_string(),
        (
            (w / 2) as i32,
            (h / 2) as i32 + (0.2 * TITLE_FONT * s) as i32,
        ),
        font,
    ))?;
    Ok(rest)
}

/// A tick value on an axis spanning `span`: rounded to a millionth of the span (ticks are
/// computed in floating point: 0.30000000000000004, -1e-17), then as few digits as needed,
/// and never "-0".
fn tick_label(v: f64, span: f64) -> String {
    if !(span > 0.0 && span.is_finite() && v.is_finite()) {
        return crate::fmt::sig(v, 6);
    }
    let q = 10f64.powi(span.log10().floor() as i32 - 6);
    let r = (v / q).round() * q;
    crate::fmt::sig(r, 6)
}

/// A tick label: [`tick_label`] on a linear axis; on a log axis (whose coordinate `v` is
/// `log10` of the value) the value `10^v`, to three digits (`1e-05`, `3.16e-05`).
fn axis_label(v: f64, span: f64, log: bool) -> String {
    if !log {
        return tick_label(v, span);
    }
    // Whole decades exactly (the ticks are computed in floating point: -4.999999999).
    let r = (v * 1e6).round() / 1e6;
    crate::fmt::sig(10f64.powf(r), 3)
}

/// `width` pixels at scale `s`.
pub(super) fn scaled(width: u32, s: f64) -> u32 {
    (f64::from(width) * s).round().max(1.0) as u32
}

/// The length of the axes' tick marks (pixels at scale 1; plotters' default).
const TICK_LENGTH: u32 = 5;

/// Font sizes (pixels at scale 1).
const TITLE_FONT: f64 = 26.0;
const AXIS_FONT: f64 = 24.0;
const TICK_FONT: f64 = 19.0;
const NOTE_FONT: f64 = 21.0;

/// A rectangle in backend pixels.
#[derive(Debug, Clone, Copy)]
pub(super) struct PixelBox {
    pub(super) left: f64,
    pub(super) right: f64,
    pub(super) top: f64,
    pub(super) bottom: f64,
}

impl PixelBox {
    pub(super) fn grow(self, by: f64) -> Self {
        Self {
            left: self.left - by,
            right: self.right + by,
            top: self.top - by,
            bottom: self.bottom + by,
        }
    }

    pub(super) fn contains(&self, (x, y): (f64, f64)) -> bool {
        x >= self.left && x <= self.right && y >= self.top && y <= self.bottom
    }

    /// The data-to-pixel map of a plotting area with these axis ranges (as plotters maps).
    pub(super) fn mapping(&self, x: (f64, f64), y: (f64, f64)) -> Mapping {
        Mapping { x, y, plot: *self }
    }
}

pub(super) struct Mapping {
    x: (f64, f64),
    y: (f64, f64),
    plot: PixelBox,
}

impl Mapping {
    pub(super) fn apply(&self, (x, y): (f64, f64)) -> (f64, f64) {
        let fx = (x - self.x.0) / (self.x.1 - self.x.0);
        let fy = (y - self.y.0) / (self.y.1 - self.y.0);
        (
            self.plot.left + fx * (self.plot.right - self.plot.left),
            self.plot.bottom - fy * (self.plot.bottom - self.plot.top),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tick_labels_are_short_and_never_negative_zero() {
        assert_eq!(tick_label(0.1 + 0.2, 1.0), "0.3");
        assert_eq!(tick_label(-1e-17, 1.6), "0");
        assert_eq!(tick_label(-0.0, 1.0), "0");
        assert_eq!(tick_label(2.0, 4.0), "2");
        assert_eq!(tick_label(-0.25, 1.0), "-0.25");
        assert_eq!(tick_label(1500.0, 3000.0), "1500");
    }

    #[test]
    fn log_axes_label_the_values_and_leave_out_what_they_cannot_show() {
        assert_eq!(
            axis_label(-5.0000000001, 4.0, true),
            crate::fmt::sig(1e-5, 3)
        );
        assert_eq!(axis_label(2.0, 4.0, true), "100");
        assert_eq!(axis_label(2.0, 4.0, false), "2");
        let c = super::super::Curve::new(
            vec![(1.0, 1.0), (10.0, 0.0), (100.0, 100.0), (1000.0, 1000.0)],
            super::super::LineStyle::Solid,
            super::super::BLACK,
        )
        .label("y");
        let f = Figure::new("x", "y")
            .curve(c)
            .log_x()
            .log_y()
            .in_log_space();
        // The point with y = 0 splits the curve; one legend entry stays.
        assert_eq!(f.curves.len(), 2);
        assert_eq!(f.curves[0].points, [(0.0, 0.0)]);
        assert_eq!(f.curves[1].points, [(2.0, 2.0), (3.0, 3.0)]);
        assert_eq!(f.curves[1].label, None);
    }

    #[test]
    fn the_colour_scale_runs_dark_to_light() {
        let lightness =
            |c: RGBColor| 0.3 * f64::from(c.0) + 0.59 * f64::from(c.1) + 0.11 * f64::from(c.2);
        let colors: Vec<RGBColor> = (0..6).map(|k| super::super::scale_color(k, 6)).collect();
        assert_eq!(colors[0], RGBColor(68, 1, 84));
        assert!(colors.windows(2).all(|w| lightness(w[1]) > lightness(w[0])));
        assert_eq!(super::super::scale_color(0, 1), RGBColor(68, 1, 84));
    }
}
