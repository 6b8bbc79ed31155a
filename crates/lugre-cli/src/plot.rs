//! Figures for papers: curves with line styles that survive black-and-white printing, open
//! markers, axis labels and a legend, rendered to SVG or PNG with a font embedded in the binary
//! (DejaVu Sans), so text renders on machines with no fonts installed.
//!
//! Dash patterns are drawn in pixel space (plotters has no dash-dot, and dashing in data space
//! would stretch with the axes' aspect ratio). Files are written atomically.

use anyhow::{bail, Context, Result};
use plotters::coord::Shift;
use plotters::element::{Drawable, PointCollection};
use plotters::prelude::*;
use plotters_backend::{BackendCoord as BackendCoordinate, DrawingErrorKind};
use std::path::Path;

use crate::atomic::write_atomic_path;

/// Colours that stay distinct in grey scale too (dark to mid tones).
pub const BLACK: RGBColor = RGBColor(0, 0, 0);
pub const BLUE: RGBColor = RGBColor(0, 90, 181);
pub const RED: RGBColor = RGBColor(200, 30, 40);
pub const GREEN: RGBColor = RGBColor(0, 130, 70);
pub const ORANGE: RGBColor = RGBColor(220, 120, 0);

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
    /// On/off lengths in pixels (at the 1x scale).
    fn pattern(self) -> &'static [f64] {
        match self {
            LineStyle::Solid => &[],
            LineStyle::Dashed => &[11.0, 6.0],
            LineStyle::Dotted => &[2.0, 4.0],
            LineStyle::DashDot => &[11.0, 4.0, 2.0, 4.0],
        }
    }
}

#[derive(Debug, Clone)]
pub struct Curve {
    pub label: Option<String>,
    pub points: Vec<(f64, f64)>,
    pub style: LineStyle,
    pub color: RGBColor,
    pub width: u32,
}

impl Curve {
    pub fn new(points: Vec<(f64, f64)>, style: LineStyle, color: RGBColor) -> Self {
        Self {
            label: None,
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

#[derive(Debug, Clone)]
pub struct Figure {
    pub title: Option<String>,
    pub x_label: String,
    pub y_label: String,
    pub curves: Vec<Curve>,
    pub markers: Vec<Marker>,
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

    /// Writes the figure as SVG or PNG, chosen by the file's extension.
    pub fn save(&self, path: &Path) -> Result<()> {
        register_font();
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        match ext.as_deref() {
            Some("svg") => {
                let mut svg = String::new();
                {
                    let root = SVGBackend::with_string(&mut svg, self.size).into_drawing_area();
                    self.draw(&root)?;
                    root.present().map_err(|e| anyhow::anyhow!("{e}"))?;
                }
                crate::atomic::write_atomic(path, |w| Ok(w.write_all(svg.as_bytes())?))
            }
            Some("png") => write_atomic_path(path, |tmp| {
                let root = BitMapBackend::new(tmp, self.size).into_drawing_area();
                self.draw(&root)?;
                root.present()
                    .map_err(|e| anyhow::anyhow!("{e}"))
                    .with_context(|| format!("cannot write '{}'", path.display()))
            }),
            _ => bail!(
                "cannot plot to '{}': the file name must end in .svg or .png",
                path.display()
            ),
        }
    }

    fn bounds(&self) -> ((f64, f64), (f64, f64)) {
        let pts = self
            .curves
            .iter()
            .flat_map(|c| c.points.iter().copied())
            .chain(self.markers.iter().map(|m| m.at));
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
        if x0 > x1 {
            return ((0.0, 1.0), (0.0, 1.0));
        }
        let pad = |lo: f64, hi: f64| {
            let span = if hi > lo { hi - lo } else { lo.abs().max(1.0) };
            (lo - 0.05 * span, hi + 0.05 * span)
        };
        (pad(x0, x1), pad(y0, y1))
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<()>
    where
        DB::ErrorType: 'static,
    {
        let err = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow::anyhow!("{e:?}");
        root.fill(&WHITE).map_err(err)?;
        let ((x0, x1), (y0, y1)) = self.bounds();
        let mut builder = ChartBuilder::on(root);
        builder
            .margin(18)
            .x_label_area_size(62)
            .y_label_area_size(92);
        if let Some(title) = &self.title {
            builder.caption(title, ("sans-serif", 26));
        }
        let mut chart = builder.build_cartesian_2d(x0..x1, y0..y1).map_err(err)?;
        chart
            .configure_mesh()
            .x_desc(&self.x_label)
            .y_desc(&self.y_label)
            .axis_desc_style(("sans-serif", 24))
            .label_style(("sans-serif", 19))
            .light_line_style(RGBColor(235, 235, 235))
            .bold_line_style(RGBColor(210, 210, 210))
            .x_labels(9)
            .y_labels(9)
            .draw()
            .map_err(err)?;

        let mut has_legend = false;
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
            let pixels = thin(&pixels, MIN_PIXEL_STEP);
            let style = ShapeStyle::from(&curve.color).stroke_width(curve.width);
            for piece in dash(&pixels, curve.style.pattern()) {
                let piece: Vec<(i32, i32)> = piece
                    .iter()
                    .map(|&(x, y)| (x.round() as i32, y.round() as i32))
                    .collect();
                root.draw(&PathElement::new(piece, style)).map_err(err)?;
            }
            if let Some(label) = &curve.label {
                has_legend = true;
                let (color, width, d) = (curve.color, curve.width, curve.style);
                chart
                    .draw_series(std::iter::empty::<PathElement<(f64, f64)>>())
                    .map_err(err)?
                    .label(label)
                    .legend(move |(x, y)| DashSample {
                        at: (x, y),
                        line: d,
                        style: ShapeStyle::from(&color).stroke_width(width),
                    });
            }
        }
        for m in &self.markers {
            let style = ShapeStyle::from(&m.color).stroke_width(2);
            let (shape, color) = (m.shape, m.color);
            let anno = chart
                .draw_series(std::iter::once(MarkerElement::new(m.at, shape, style)))
                .map_err(err)?;
            if let Some(label) = &m.label {
                has_legend = true;
                anno.label(label).legend(move |(x, y)| {
                    MarkerElement::new((x + 18, y), shape, ShapeStyle::from(&color).stroke_width(2))
                });
            }
        }
        if has_legend {
            chart
                .configure_series_labels()
                .label_font(("sans-serif", 19))
                .background_style(WHITE.mix(0.85))
                .border_style(RGBColor(160, 160, 160))
                .position(SeriesLabelPosition::UpperLeft)
                .draw()
                .map_err(err)?;
        }
        Ok(())
    }
}

/// A legend sample of a curve's line style, 24 px long, starting at `at`.
struct DashSample {
    at: (i32, i32),
    line: LineStyle,
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
        let line = [(x as f64 - 8.0, y as f64), (x as f64 + 16.0, y as f64)];
        for piece in dash(&line, self.line.pattern()) {
            let piece = piece
                .iter()
                .map(|&(px, py)| (px.round() as i32, py.round() as i32));
            backend.draw_path(piece, &self.style)?;
        }
        Ok(())
    }
}

/// An open circle or square of radius 7 px, as the paper marks `t1` and `t5`; `C` is a data
/// coordinate (on the chart) or a pixel (in the legend).
struct MarkerElement<C> {
    at: C,
    shape: Shape,
    style: ShapeStyle,
}

impl<C> MarkerElement<C> {
    fn new(at: C, shape: Shape, style: ShapeStyle) -> Self {
        Self { at, shape, style }
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
        let r = 7;
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
    fn dashes_cover_the_pattern() {
        let line = [(0.0, 0.0), (34.0, 0.0)];
        let pieces = dash(&line, &[10.0, 5.0]);
        let spans: Vec<(f64, f64)> = pieces.iter().map(|p| (p[0].0, p[p.len() - 1].0)).collect();
        assert_eq!(spans, vec![(0.0, 10.0), (15.0, 25.0), (30.0, 34.0)]);
        assert_eq!(dash(&line, &[]).len(), 1);
    }
}
