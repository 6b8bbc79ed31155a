//! The legend: its entries, size and drawing, and the corner where it hides the least.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::draw::{scaled, Mapping, PixelBox};
use super::elements::{DashSample, MarkerElement};
use super::{Figure, LineStyle, Shape};

const LEGEND_FONT: f64 = 19.0;
/// Pixels between the legend and the plotting area's edges.
const LEGEND_INSET: f64 = 10.0;

/// The legend's corner inside the plotting area.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Corner {
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

impl Figure {
    /// The legend's corner, and the top of the y axis (raised when no corner is free).
    pub(super) fn place_legend(
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

enum Sample {
    Line(LineStyle, ShapeStyle),
    Marker(Shape, ShapeStyle),
}

/// The legend: one entry per labelled curve or marker, laid out in pixels.
pub(super) struct LegendBox {
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
    pub(super) fn new<DB: DrawingBackend>(
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

    pub(super) fn origin(&self, corner: Corner, plot: &PixelBox) -> (f64, f64) {
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

    pub(super) fn draw<DB: DrawingBackend>(
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
