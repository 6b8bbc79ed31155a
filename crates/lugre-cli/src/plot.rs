//! Figures for papers: curves with line styles that survive black-and-white printing, open
//! markers, axis labels and a legend, rendered to SVG or PNG with a font embedded in the binary
//! (DejaVu Sans), so text renders on machines with no fonts installed.
//!
//! A [`Figure`] is one chart; [`Panels`] put several side by side in one image. Notes (short
//! texts such as `t₁`) can sit next to points; the legend goes in the inside corner where it
//! hides nothing, or above the data when every corner is taken.
//!
//! Dash patterns are drawn in pixel space (plotters has no dash-dot, and dashing in data space
//! would stretch with the axes' aspect ratio). PNGs are drawn at twice their size and averaged
//! down, because plotters' bitmap backend does not anti-alias. Files are written atomically.

use anyhow::{bail, Context, Result};
use plotters::coord::Shift;
use plotters::element::{Drawable, PointCollection};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters_backend::{BackendCoord as BackendCoordinate, DrawingErrorKind};
use std::path::Path;

/// Colours that stay distinct in grey scale too (dark to mid tones).
pub const BLACK: RGBColor = RGBColor(0, 0, 0);
pub const BLUE: RGBColor = RGBColor(0, 90, 181);
pub const RED: RGBColor = RGBColor(200, 30, 40);
pub const GREEN: RGBColor = RGBColor(0, 130, 70);
pub const ORANGE: RGBColor = RGBColor(220, 120, 0);
pub const GREY: RGBColor = RGBColor(80, 80, 80);

/// The palette in order of use for a family of curves.
pub const PALETTE: [RGBColor; 5] = [BLUE, RED, GREEN, ORANGE, BLACK];

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineStyle {
    Solid,
    Dashed,
    Dotted,
    DashDot,
}

impl LineStyle {
    /// On/off lengths in pixels at scale `s`.
    fn pattern(self, s: f64) -> Vec<f64> {
        let base: &[f64] = match self {
            LineStyle::Solid => &[],
            LineStyle::Dashed => &[11.0, 6.0],
            LineStyle::Dotted => &[2.0, 4.0],
            LineStyle::DashDot => &[11.0, 4.0, 2.0, 4.0],
        };
        base.iter().map(|v| v * s).collect()
    }
}

#[derive(Debug, Clone)]
pub struct Curve {
    pub label: Option<String>,
    /// A short ASCII name for the curve's data file (e.g. `steady-gamma20`).
    pub key: Option<String>,
    pub points: Vec<(f64, f64)>,
    pub style: LineStyle,
    pub color: RGBColor,
    pub width: u32,
}

impl Curve {
    pub fn new(points: Vec<(f64, f64)>, style: LineStyle, color: RGBColor) -> Self {
        Self {
            label: None,
            key: None,
            points,
            style,
            color,
            width: 2,
        }
    }

    pub fn label(mut self, label: impl Into<String>) -> Self {
        self.label = Some(label.into());
        self
    }

    pub fn key(mut self, key: impl Into<String>) -> Self {
        self.key = Some(key.into());
        self
    }

    pub fn width(mut self, width: u32) -> Self {
        self.width = width;
        self
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    Circle,
    Square,
}

#[derive(Debug, Clone)]
pub struct Marker {
    pub label: Option<String>,
    pub at: (f64, f64),
    pub shape: Shape,
    pub color: RGBColor,
}

/// A short text centred at a data point shifted by `offset` pixels (x right, y down), e.g.
/// `t₁` next to a marker.
#[derive(Debug, Clone)]
pub struct Note {
    pub at: (f64, f64),
    pub text: String,
    pub offset: (i32, i32),
}

/// The legend's corner inside the plotting area.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Corner {
    UpperLeft,
    UpperRight,
    LowerLeft,
    LowerRight,
}

impl Corner {
    const ALL: [Corner; 4] = [
        Corner::UpperLeft,
        Corner::UpperRight,
        Corner::LowerRight,
        Corner::LowerLeft,
    ];

    fn is_upper(self) -> bool {
        matches!(self, Corner::UpperLeft | Corner::UpperRight)
    }
}

/// One chart: curves, markers and notes in data coordinates, axis labels, and a legend of the
/// labelled curves and markers, in the inside corner that hides none of them (when every
/// corner would, the y axis is extended upwards to make room above the data).
#[derive(Debug, Clone)]
pub struct Figure {
    pub title: Option<String>,
    pub x_label: String,
    pub y_label: String,
    pub curves: Vec<Curve>,
    pub markers: Vec<Marker>,
    pub notes: Vec<Note>,
    /// Axis ranges; `None`: the data's, padded by 5 %.
    pub x_range: Option<(f64, f64)>,
    pub y_range: Option<(f64, f64)>,
    /// Pixels of the PNG (the SVG uses the same units).
    pub size: (u32, u32),
}

impl Figure {
    pub fn new(x_label: impl Into<String>, y_label: impl Into<String>) -> Self {
        Self {
            title: None,
            x_label: x_label.into(),
            y_label: y_label.into(),
            curves: Vec::new(),
            markers: Vec::new(),
            notes: Vec::new(),
            x_range: None,
            y_range: None,
            size: (1000, 700),
        }
    }

    pub fn title(mut self, title: impl Into<String>) -> Self {
        self.title = Some(title.into());
        self
    }

    pub fn curve(mut self, curve: Curve) -> Self {
        self.curves.push(curve);
        self
    }

    pub fn marker(mut self, marker: Marker) -> Self {
        self.markers.push(marker);
        self
    }

    pub fn note(mut self, at: (f64, f64), text: impl Into<String>, offset: (i32, i32)) -> Self {
        self.notes.push(Note {
            at,
            text: text.into(),
            offset,
        });
        self
    }

    pub fn y_range(mut self, lo: f64, hi: f64) -> Self {
        self.y_range = Some((lo, hi));
        self
    }

    /// Writes the figure as SVG or PNG, chosen by the file's extension.
    pub fn save(&self, path: &Path) -> Result<()> {
        save(self, self.size, path)
    }

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

    /// Draws the figure on `area` (the whole image, or one panel of it), every size in pixels
    /// multiplied by `s` (PNGs are drawn at twice their size and scaled down: anti-aliasing).
    fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>, s: f64) -> Result<()>
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

        // The plotting area's pixels depend on the layout only, not on the axis ranges.
        let plot = {
            let chart = Self::chart_builder(&area, s)
                .build_cartesian_2d(x0..x1, y0..y1)
                .map_err(err)?;
            let (xs, ys) = chart.plotting_area().get_pixel_range();
            PixelBox {
                left: f64::from(xs.start),
                right: f64::from(xs.end),
                top: f64::from(ys.start),
                bottom: f64::from(ys.end),
            }
        };
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
        let x_tick = |v: &f64| tick_label(*v, x1 - x0);
        let y_tick = |v: &f64| tick_label(*v, y1 - y0);
        chart
            .configure_mesh()
            .x_label_formatter(&x_tick)
            .y_label_formatter(&y_tick)
            .x_desc(&self.x_label)
            .y_desc(&self.y_label)
            .axis_desc_style(("sans-serif", AXIS_FONT * s))
            .label_style(("sans-serif", TICK_FONT * s))
            .light_line_style(RGBColor(235, 235, 235))
            .bold_line_style(RGBColor(210, 210, 210))
            .x_labels(9)
            .y_labels(9)
            .draw()
            .map_err(err)?;

        // The pixel-space dashes are drawn outside the chart's coordinate system, which would
        // clip them: points beyond the plotting area are pinned to its edges instead (axis
        // ranges contain the data unless a figure sets them narrower).
        let clip = chart.plotting_area().get_pixel_range();
        for curve in &self.curves {
            let pixels: Vec<(f64, f64)> = curve
                .points
                .iter()
                .filter(|(x, y)| x.is_finite() && y.is_finite())
                .map(|&p| {
                    let (px, py) = chart.backend_coord(&p);
                    (px as f64, py as f64)
                })
                .collect();
            let pixels = thin(&pixels, MIN_PIXEL_STEP * s);
            let style = ShapeStyle::from(&curve.color).stroke_width(scaled(curve.width, s));
            for piece in dash(&pixels, &curve.style.pattern(s)) {
                let piece: Vec<(i32, i32)> = piece
                    .iter()
                    .map(|&(x, y)| {
                        (
                            (x.round() as i32).clamp(clip.0.start, clip.0.end),
                            (y.round() as i32).clamp(clip.1.start, clip.1.end),
                        )
                    })
                    .collect();
                screen.draw(&PathElement::new(piece, style)).map_err(err)?;
            }
        }
        for m in &self.markers {
            let style = ShapeStyle::from(&m.color).stroke_width(scaled(2, s));
            chart
                .draw_series(std::iter::once(MarkerElement::new(m.at, m.shape, style, s)))
                .map_err(err)?;
        }
        for n in &self.notes {
            let (px, py) = chart.backend_coord(&n.at);
            let font = TextStyle::from(("sans-serif", NOTE_FONT * s).into_font())
                .pos(Pos::new(HPos::Center, VPos::Center));
            let (dx, dy) = (f64::from(n.offset.0) * s, f64::from(n.offset.1) * s);
            screen
                .draw(&Text::new(
                    n.text.clone(),
                    (px + dx.round() as i32, py + dy.round() as i32),
                    font,
                ))
                .map_err(err)?;
        }
        if let (Some(lb), Some(at)) = (&legend, legend_at) {
            lb.draw(&screen, at).map_err(err)?;
        }
        Ok(())
    }

    /// The legend's corner, and the top of the y axis (raised when no corner is free).
    fn place_legend(
        &self,
        lb: &LegendBox,
        plot: &PixelBox,
        (x0, x1): (f64, f64),
        (y0, y1): (f64, f64),
        s: f64,
    ) -> (f64, Corner) {
        let score = |top: f64, corner: Corner| {
            let map = plot.mapping((x0, x1), (y0, top));
            let rect = lb.rect(corner, plot).grow(6.0 * s);
            self.hits(&map, &rect, s)
        };
        let best = |top: f64, corners: &[Corner]| {
            corners
                .iter()
                .map(|&c| (score(top, c), c))
                .min_by_key(|(s, _)| *s)
                .unwrap_or((0, Corner::UpperLeft))
        };
        let (hits, corner) = best(y1, &Corner::ALL);
        if hits == 0 {
            return (y1, corner);
        }
        // Room above the data: the data keep the plot's lower part, the legend gets the top.
        let height = plot.bottom - plot.top;
        let need = lb.height + (2.0 * LEGEND_INSET + 8.0) * s;
        if need < 0.6 * height && y1 > y0 {
            let top = y0 + (y1 - y0) * height / (height - need);
            let (raised_hits, raised) = best(top, &[Corner::UpperLeft, Corner::UpperRight]);
            if raised_hits < hits {
                return (top, raised);
            }
        }
        (y1, corner)
    }

    /// How many drawn things (curve points every few pixels, markers, notes) fall in `rect`.
    fn hits(&self, map: &Mapping, rect: &PixelBox, s: f64) -> usize {
        let mut n = 0;
        for c in &self.curves {
            let px: Vec<(f64, f64)> = c
                .points
                .iter()
                .filter(|(x, y)| x.is_finite() && y.is_finite())
                .map(|&p| map.apply(p))
                .collect();
            for w in px.windows(2) {
                let len = (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1);
                let steps = (len / (3.0 * s)).ceil().clamp(1.0, 10_000.0) as usize;
                n += (0..steps)
                    .map(|i| {
                        let f = i as f64 / steps as f64;
                        (
                            w[0].0 + f * (w[1].0 - w[0].0),
                            w[0].1 + f * (w[1].1 - w[0].1),
                        )
                    })
                    .filter(|&p| rect.contains(p))
                    .count();
            }
            if let Some(&last) = px.last() {
                n += usize::from(rect.contains(last));
            }
        }
        for m in &self.markers {
            n += 20 * usize::from(rect.grow(8.0 * s).contains(map.apply(m.at)));
        }
        for note in &self.notes {
            let (x, y) = map.apply(note.at);
            let p = (
                x + f64::from(note.offset.0) * s,
                y + f64::from(note.offset.1) * s,
            );
            n += 20 * usize::from(rect.grow(16.0 * s).contains(p));
        }
        n
    }
}

/// Several figures side by side (and in rows) in one image, each with its own axes.
#[derive(Debug, Clone)]
pub struct Panels {
    pub title: Option<String>,
    pub panels: Vec<Figure>,
    pub cols: usize,
    /// Pixels of the whole image.
    pub size: (u32, u32),
}

impl Panels {
    /// Writes the panels as SVG or PNG, chosen by the file's extension.
    pub fn save(&self, path: &Path) -> Result<()> {
        save(self, self.size, path)
    }
}

/// Something drawn on a whole image.
trait Render {
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

/// PNGs are drawn this many times larger and averaged down: plotters' bitmap backend draws
/// lines without anti-aliasing, and curves drawn at 1x look jagged.
const SUPERSAMPLE: u32 = 2;

/// The image format of `path`, from its extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Format {
    Svg,
    Png,
}

fn format_of(path: &Path) -> Result<Format> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("svg") => Ok(Format::Svg),
        Some("png") => Ok(Format::Png),
        _ => bail!(
            "cannot plot to '{}': the file name must end in .svg or .png",
            path.display()
        ),
    }
}

/// Checks that a plot can be written to `path` (its extension), before any work is done.
pub fn check_path(path: &Path) -> Result<()> {
    format_of(path).map(|_| ())
}

/// Writes `what` as SVG or PNG (by `path`'s extension), atomically.
fn save(what: &impl Render, size: (u32, u32), path: &Path) -> Result<()> {
    let format = format_of(path)?;
    register_font();
    match format {
        Format::Svg => {
            let mut svg = String::new();
            {
                let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
                what.render(&root, 1.0)?;
                root.present().map_err(|e| anyhow::anyhow!("{e}"))?;
            }
            crate::io::atomic::write_atomic(path, |w| Ok(w.write_all(svg.as_bytes())?))
        }
        Format::Png => {
            let k = SUPERSAMPLE;
            let (w, h) = (size.0 * k, size.1 * k);
            let mut big = vec![255u8; w as usize * h as usize * 3];
            {
                let root = BitMapBackend::with_buffer(&mut big, (w, h)).into_drawing_area();
                what.render(&root, f64::from(k))?;
                root.present().map_err(|e| anyhow::anyhow!("{e}"))?;
            }
            let small = downsample(&big, (w, h), k);
            crate::io::atomic::write_atomic(path, |out| {
                use image::ImageEncoder;
                image::codecs::png::PngEncoder::new(out)
                    .write_image(&small, size.0, size.1, image::ColorType::Rgb8)
                    .with_context(|| format!("cannot write '{}'", path.display()))
            })
        }
    }
}

/// The RGB image `rgb` of `size` shrunk by `k` in each direction, each pixel the mean of a
/// `k x k` block.
fn downsample(rgb: &[u8], (w, h): (u32, u32), k: u32) -> Vec<u8> {
    let (w, h, k) = (w as usize, h as usize, k as usize);
    let (sw, sh) = (w / k, h / k);
    let mut out = vec![0u8; sw * sh * 3];
    let n = (k * k) as u32;
    for y in 0..sh {
        for x in 0..sw {
            for c in 0..3 {
                let mut sum = 0u32;
                for dy in 0..k {
                    let row = (y * k + dy) * w;
                    for dx in 0..k {
                        sum += u32::from(rgb[(row + x * k + dx) * 3 + c]);
                    }
                }
                out[(y * sw + x) * 3 + c] = ((sum + n / 2) / n) as u8;
            }
        }
    }
    out
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

/// `width` pixels at scale `s`.
fn scaled(width: u32, s: f64) -> u32 {
    (f64::from(width) * s).round().max(1.0) as u32
}

/// Font sizes (pixels at scale 1).
const TITLE_FONT: f64 = 26.0;
const AXIS_FONT: f64 = 24.0;
const TICK_FONT: f64 = 19.0;
const LEGEND_FONT: f64 = 19.0;
const NOTE_FONT: f64 = 21.0;
/// Pixels between the legend and the plotting area's edges.
const LEGEND_INSET: f64 = 10.0;

/// A rectangle in backend pixels.
#[derive(Debug, Clone, Copy)]
struct PixelBox {
    left: f64,
    right: f64,
    top: f64,
    bottom: f64,
}

impl PixelBox {
    fn grow(self, by: f64) -> Self {
        Self {
            left: self.left - by,
            right: self.right + by,
            top: self.top - by,
            bottom: self.bottom + by,
        }
    }

    fn contains(&self, (x, y): (f64, f64)) -> bool {
        x >= self.left && x <= self.right && y >= self.top && y <= self.bottom
    }

    /// The data-to-pixel map of a plotting area with these axis ranges (as plotters maps).
    fn mapping(&self, x: (f64, f64), y: (f64, f64)) -> Mapping {
        Mapping { x, y, plot: *self }
    }
}

struct Mapping {
    x: (f64, f64),
    y: (f64, f64),
    plot: PixelBox,
}

impl Mapping {
    fn apply(&self, (x, y): (f64, f64)) -> (f64, f64) {
        let fx = (x - self.x.0) / (self.x.1 - self.x.0);
        let fy = (y - self.y.0) / (self.y.1 - self.y.0);
        (
            self.plot.left + fx * (self.plot.right - self.plot.left),
            self.plot.bottom - fy * (self.plot.bottom - self.plot.top),
        )
    }
}

enum Sample {
    Line(LineStyle, ShapeStyle),
    Marker(Shape, ShapeStyle),
}

/// The legend: one entry per labelled curve or marker, laid out in pixels.
struct LegendBox {
    entries: Vec<(String, Sample)>,
    width: f64,
    height: f64,
    line_height: f64,
    /// The drawing's scale.
    s: f64,
}

/// Pixels of padding inside the legend, of a line sample, and between sample and text.
const LEGEND_PAD: f64 = 9.0;
const LEGEND_SAMPLE: f64 = 34.0;
const LEGEND_GAP: f64 = 10.0;

impl LegendBox {
    fn new<DB: DrawingBackend>(
        fig: &Figure,
        screen: &DrawingArea<DB, Shift>,
        s: f64,
    ) -> Result<Option<Self>, DrawingAreaErrorKind<DB::ErrorType>> {
        let mut entries = Vec::new();
        for c in &fig.curves {
            if let Some(label) = &c.label {
                let style = ShapeStyle::from(&c.color).stroke_width(scaled(c.width, s));
                entries.push((label.clone(), Sample::Line(c.style, style)));
            }
        }
        for m in &fig.markers {
            if let Some(label) = &m.label {
                let style = ShapeStyle::from(&m.color).stroke_width(scaled(2, s));
                entries.push((label.clone(), Sample::Marker(m.shape, style)));
            }
        }
        if entries.is_empty() {
            return Ok(None);
        }
        let font = legend_font(s);
        let (mut text_w, mut text_h) = (0u32, 0u32);
        for (label, _) in &entries {
            let (w, h) = screen.estimate_text_size(label, &font)?;
            text_w = text_w.max(w);
            text_h = text_h.max(h);
        }
        let line_height = f64::from(text_h).max(LEGEND_FONT * s) + 7.0 * s;
        Ok(Some(Self {
            width: (2.0 * LEGEND_PAD + LEGEND_SAMPLE + LEGEND_GAP) * s + f64::from(text_w),
            height: (2.0 * LEGEND_PAD - 7.0) * s + line_height * entries.len() as f64,
            line_height,
            entries,
            s,
        }))
    }

    fn origin(&self, corner: Corner, plot: &PixelBox) -> (f64, f64) {
        let inset = LEGEND_INSET * self.s;
        let left = match corner {
            Corner::UpperLeft | Corner::LowerLeft => plot.left + inset,
            Corner::UpperRight | Corner::LowerRight => plot.right - inset - self.width,
        };
        let top = if corner.is_upper() {
            plot.top + inset
        } else {
            plot.bottom - inset - self.height
        };
        (left, top)
    }

    fn rect(&self, corner: Corner, plot: &PixelBox) -> PixelBox {
        let (left, top) = self.origin(corner, plot);
        PixelBox {
            left,
            right: left + self.width,
            top,
            bottom: top + self.height,
        }
    }

    fn draw<DB: DrawingBackend>(
        &self,
        screen: &DrawingArea<DB, Shift>,
        (left, top): (f64, f64),
    ) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
        let (l, t) = (left.round() as i32, top.round() as i32);
        let (r, b) = (
            (left + self.width).round() as i32,
            (top + self.height).round() as i32,
        );
        screen.draw(&Rectangle::new([(l, t), (r, b)], WHITE.mix(0.9).filled()))?;
        screen.draw(&Rectangle::new([(l, t), (r, b)], RGBColor(160, 160, 160)))?;
        let s = self.s;
        let font = legend_font(s).pos(Pos::new(HPos::Left, VPos::Center));
        for (i, (label, sample)) in self.entries.iter().enumerate() {
            let y = top + LEGEND_PAD * s + self.line_height * (i as f64 + 0.5) - 3.5 * s;
            let x = left + LEGEND_PAD * s;
            match sample {
                Sample::Line(line, style) => screen.draw(&DashSample {
                    at: (x.round() as i32, y.round() as i32),
                    length: LEGEND_SAMPLE * s,
                    pattern: line.pattern(s),
                    style: *style,
                })?,
                Sample::Marker(shape, style) => screen.draw(&MarkerElement::new(
                    (
                        (x + LEGEND_SAMPLE * s / 2.0).round() as i32,
                        y.round() as i32,
                    ),
                    *shape,
                    *style,
                    s,
                ))?,
            }
            screen.draw(&Text::new(
                label.clone(),
                (
                    (x + (LEGEND_SAMPLE + LEGEND_GAP) * s).round() as i32,
                    y.round() as i32,
                ),
                font.clone(),
            ))?;
        }
        Ok(())
    }
}

fn legend_font(s: f64) -> TextStyle<'static> {
    TextStyle::from(("sans-serif", LEGEND_FONT * s).into_font())
}

/// A legend sample of a curve's line style, `length` pixels long, starting at `at`.
struct DashSample {
    at: (i32, i32),
    length: f64,
    pattern: Vec<f64>,
    style: ShapeStyle,
}

impl<'a> PointCollection<'a, (i32, i32)> for &'a DashSample {
    type Point = &'a (i32, i32);
    type IntoIter = std::iter::Once<&'a (i32, i32)>;
    fn point_iter(self) -> Self::IntoIter {
        std::iter::once(&self.at)
    }
}

impl<DB: DrawingBackend> Drawable<DB> for DashSample {
    fn draw<I: Iterator<Item = BackendCoordinate>>(
        &self,
        mut pos: I,
        backend: &mut DB,
        _size: (u32, u32),
    ) -> Result<(), DrawingErrorKind<DB::ErrorType>> {
        let Some((x, y)) = pos.next() else {
            return Ok(());
        };
        let line = [(x as f64, y as f64), (x as f64 + self.length, y as f64)];
        for piece in dash(&line, &self.pattern) {
            let piece = piece
                .iter()
                .map(|&(px, py)| (px.round() as i32, py.round() as i32));
            backend.draw_path(piece, &self.style)?;
        }
        Ok(())
    }
}

/// An open circle or square of radius 7 px (at scale 1), as the paper marks `t1` and `t5`;
/// `C` is a data coordinate (on the chart) or a pixel (in the legend).
struct MarkerElement<C> {
    at: C,
    shape: Shape,
    style: ShapeStyle,
    radius: i32,
}

impl<C> MarkerElement<C> {
    fn new(at: C, shape: Shape, style: ShapeStyle, s: f64) -> Self {
        Self {
            at,
            shape,
            style,
            radius: (7.0 * s).round() as i32,
        }
    }
}

impl<'a, C: 'a> PointCollection<'a, C> for &'a MarkerElement<C> {
    type Point = &'a C;
    type IntoIter = std::iter::Once<&'a C>;
    fn point_iter(self) -> Self::IntoIter {
        std::iter::once(&self.at)
    }
}

impl<C, DB: DrawingBackend> Drawable<DB> for MarkerElement<C> {
    fn draw<I: Iterator<Item = BackendCoordinate>>(
        &self,
        mut pos: I,
        backend: &mut DB,
        _size: (u32, u32),
    ) -> Result<(), DrawingErrorKind<DB::ErrorType>> {
        let Some((x, y)) = pos.next() else {
            return Ok(());
        };
        let r = self.radius;
        match self.shape {
            Shape::Circle => backend.draw_circle((x, y), r as u32, &self.style, false),
            Shape::Square => backend.draw_rect((x - r, y - r), (x + r, y + r), &self.style, false),
        }
    }
}

/// Points of a drawn polyline closer than this (pixels) to the previous one are dropped: the
/// bitmap backend rounds to whole pixels, and runs of sub-pixel steps draw as jagged lines.
const MIN_PIXEL_STEP: f64 = 2.5;

/// `points` without those closer than `step` to the last kept one (the last point is kept).
fn thin(points: &[(f64, f64)], step: f64) -> Vec<(f64, f64)> {
    let mut kept: Vec<(f64, f64)> = Vec::with_capacity(points.len());
    for (i, &p) in points.iter().enumerate() {
        let far = kept
            .last()
            .is_none_or(|q| (p.0 - q.0).hypot(p.1 - q.1) >= step);
        if far || i + 1 == points.len() {
            kept.push(p);
        }
    }
    kept
}

/// Splits a pixel polyline into the "on" pieces of a dash pattern (solid: one piece).
fn dash(points: &[(f64, f64)], pattern: &[f64]) -> Vec<Vec<(f64, f64)>> {
    if pattern.is_empty() || points.len() < 2 {
        return vec![points.to_vec()];
    }
    let mut pieces = Vec::new();
    let mut current: Vec<(f64, f64)> = vec![points[0]];
    let (mut idx, mut left, mut on) = (0usize, pattern[0], true);
    for w in points.windows(2) {
        let (mut a, b) = (w[0], w[1]);
        let mut seg = ((b.0 - a.0).powi(2) + (b.1 - a.1).powi(2)).sqrt();
        while seg > left {
            let t = left / seg;
            let cut = (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1));
            if on {
                current.push(cut);
                pieces.push(std::mem::take(&mut current));
            } else {
                current = vec![cut];
            }
            seg -= left;
            a = cut;
            idx = (idx + 1) % pattern.len();
            left = pattern[idx];
            on = !on;
        }
        left -= seg;
        if on {
            current.push(b);
        }
    }
    if on && current.len() > 1 {
        pieces.push(current);
    }
    pieces
}

fn register_font() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        // The embedded DejaVu Sans serves every family name used above.
        let _ = plotters::style::register_font(
            "sans-serif",
            FontStyle::Normal,
            dejavu::sans::regular(),
        );
    });
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
    fn dashes_cover_the_pattern() {
        let line = [(0.0, 0.0), (34.0, 0.0)];
        let pieces = dash(&line, &[10.0, 5.0]);
        let spans: Vec<(f64, f64)> = pieces.iter().map(|p| (p[0].0, p[p.len() - 1].0)).collect();
        assert_eq!(spans, vec![(0.0, 10.0), (15.0, 25.0), (30.0, 34.0)]);
        assert_eq!(dash(&line, &[]).len(), 1);
    }
}
