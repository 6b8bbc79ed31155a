//! Figures for papers: curves with line styles that survive black-and-white printing, open
//! markers, axis labels and a legend, rendered to SVG or PNG with a font embedded in the binary
//! (DejaVu Sans), so text renders on machines with no fonts installed.
//!
//! A [`Figure`] is one chart; [`Panels`] put several side by side in one image. Notes (short
//! texts such as `t₁`) can sit next to points; the legend goes in the inside corner where it
//! hides nothing, or above the data when every corner is taken.
//!
//! Curves are mapped to pixels, cut to the plotting area and dashed in pixel space, once, for
//! both formats (plotters has no dash-dot, and dashing in data space would stretch with the
//! axes' aspect ratio). A PNG shows what the SVG shows: it is drawn by plotters' bitmap backend
//! with wide lines stroked and text sized as the SVG's (`raster`), at twice its size and
//! averaged down, because that backend does not anti-alias. Files are written atomically.
//!
//! This module holds what a figure is; `draw` lays it out and draws it, `legend` places and
//! draws the legend, `clip` cuts lines to the plotting area, `dashes` cuts them into dash
//! patterns, `elements` are the markers and legend samples plotters lacks, `raster` is the
//! PNG's drawing backend, and `output` writes SVG and PNG files.

use anyhow::Result;
pub(crate) use plotters::prelude::RGBColor;
use std::path::Path;

mod clip;
mod dashes;
mod draw;
mod elements;
mod legend;
mod output;
mod raster;
mod units;

pub(crate) use output::check_path;
use output::save;
pub(crate) use units::Units;

/// Colours that stay distinct in grey scale too (dark to mid tones).
pub(crate) const BLACK: RGBColor = RGBColor(0, 0, 0);
pub(crate) const BLUE: RGBColor = RGBColor(0, 90, 181);
pub(crate) const RED: RGBColor = RGBColor(200, 30, 40);
pub(crate) const GREEN: RGBColor = RGBColor(0, 130, 70);
pub(crate) const ORANGE: RGBColor = RGBColor(220, 120, 0);
pub(crate) const GREY: RGBColor = RGBColor(80, 80, 80);

/// The palette in order of use for a family of curves.
pub(crate) const PALETTE: [RGBColor; 5] = [BLUE, RED, GREEN, ORANGE, BLACK];

/// Anchors of a sequential colour scale (viridis: perceptually uniform, lightness rising
/// monotonically, so the order survives grey-scale printing and colour-blind readers).
const SCALE: [RGBColor; 9] = [
    RGBColor(68, 1, 84),
    RGBColor(71, 45, 123),
    RGBColor(59, 82, 139),
    RGBColor(44, 114, 142),
    RGBColor(33, 145, 140),
    RGBColor(40, 174, 128),
    RGBColor(94, 201, 98),
    RGBColor(173, 220, 48),
    RGBColor(253, 231, 37),
];

/// The colour of `k` of `n` curves ordered by a parameter (an amplitude, a frequency): dark to
/// light along the sequential scale, stopping short of its lightest yellow, which does not
/// show on white.
pub(crate) fn scale_color(k: usize, n: usize) -> RGBColor {
    let f = if n > 1 {
        0.85 * k as f64 / (n - 1) as f64
    } else {
        0.0
    };
    let x = f.clamp(0.0, 1.0) * (SCALE.len() - 1) as f64;
    let i = (x.floor() as usize).min(SCALE.len() - 2);
    let w = x - i as f64;
    let mix = |a: u8, b: u8| (f64::from(a) + w * (f64::from(b) - f64::from(a))).round() as u8;
    let (a, b) = (SCALE[i], SCALE[i + 1]);
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum LineStyle {
    Solid,
    Dashed,
    Dotted,
    DashDot,
}

#[derive(Debug, Clone)]
pub(crate) struct Curve {
    pub(crate) label: Option<String>,
    /// A short ASCII name for the curve's data file (e.g. `steady-gamma20`).
    pub(crate) key: Option<String>,
    pub(crate) points: Vec<(f64, f64)>,
    pub(crate) style: LineStyle,
    pub(crate) color: RGBColor,
    pub(crate) width: u32,
}

impl Curve {
    pub(crate) fn new(points: Vec<(f64, f64)>, style: LineStyle, color: RGBColor) -> Self {
        Self {
            label: None,
            key: None,
            points,
            style,
            color,
            width: 2,
        }
    }

    pub(crate) fn label(mut self, label: impl Into<String>) -> Self {
        self.label = Some(label.into());
        self
    }

    pub(crate) fn key(mut self, key: impl Into<String>) -> Self {
        self.key = Some(key.into());
        self
    }

    pub(crate) fn width(mut self, width: u32) -> Self {
        self.width = width;
        self
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Shape {
    Circle,
    Square,
}

#[derive(Debug, Clone)]
pub(crate) struct Marker {
    pub(crate) label: Option<String>,
    pub(crate) at: (f64, f64),
    pub(crate) shape: Shape,
    pub(crate) color: RGBColor,
}

/// A short text centred at a data point shifted by `offset` pixels (x right, y down), e.g.
/// `t₁` next to a marker.
#[derive(Debug, Clone)]
pub(crate) struct Note {
    pub(crate) at: (f64, f64),
    pub(crate) text: String,
    pub(crate) offset: (i32, i32),
}

/// One chart: curves, markers and notes in data coordinates, axis labels, and a legend of the
/// labelled curves and markers, in the inside corner that hides none of them (when every
/// corner would, the y axis is extended upwards to make room above the data).
#[derive(Debug, Clone)]
pub(crate) struct Figure {
    pub(crate) title: Option<String>,
    pub(crate) x_label: String,
    pub(crate) y_label: String,
    pub(crate) curves: Vec<Curve>,
    pub(crate) markers: Vec<Marker>,
    pub(crate) notes: Vec<Note>,
    /// Axis ranges; `None`: the data's, padded by 5 %.
    pub(crate) x_range: Option<(f64, f64)>,
    pub(crate) y_range: Option<(f64, f64)>,
    /// Pixels of the PNG (the SVG uses the same units).
    pub(crate) size: (u32, u32),
    /// Logarithmic axes (decades evenly spaced; points with a coordinate <= 0 on a log axis
    /// are not drawn).
    pub(crate) log_x: bool,
    pub(crate) log_y: bool,
}

impl Figure {
    pub(crate) fn new(x_label: impl Into<String>, y_label: impl Into<String>) -> Self {
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
            log_x: false,
            log_y: false,
        }
    }

    /// A logarithmic x axis.
    pub(crate) fn log_x(mut self) -> Self {
        self.log_x = true;
        self
    }

    /// A logarithmic y axis.
    pub(crate) fn log_y(mut self) -> Self {
        self.log_y = true;
        self
    }

    pub(crate) fn title(mut self, title: impl Into<String>) -> Self {
        self.title = Some(title.into());
        self
    }

    pub(crate) fn curve(mut self, curve: Curve) -> Self {
        self.curves.push(curve);
        self
    }

    pub(crate) fn marker(mut self, marker: Marker) -> Self {
        self.markers.push(marker);
        self
    }

    pub(crate) fn note(
        mut self,
        at: (f64, f64),
        text: impl Into<String>,
        offset: (i32, i32),
    ) -> Self {
        self.notes.push(Note {
            at,
            text: text.into(),
            offset,
        });
        self
    }

    pub(crate) fn y_range(mut self, lo: f64, hi: f64) -> Self {
        self.y_range = Some((lo, hi));
        self
    }

    /// Writes the figure as SVG or PNG, chosen by the file's extension.
    pub(crate) fn save(&self, path: &Path) -> Result<()> {
        save(self, self.size, path)
    }
}

/// Several figures side by side (and in rows) in one image, each with its own axes.
#[derive(Debug, Clone)]
pub(crate) struct Panels {
    pub(crate) title: Option<String>,
    pub(crate) panels: Vec<Figure>,
    pub(crate) cols: usize,
    /// Pixels of the whole image.
    pub(crate) size: (u32, u32),
}

impl Panels {
    /// Two figures side by side, 1600 x 650 pixels in all.
    pub(crate) fn side_by_side(left: Figure, right: Figure) -> Self {
        Self {
            title: None,
            panels: vec![left, right],
            cols: 2,
            size: (1600, 650),
        }
    }

    /// Writes the panels as SVG or PNG, chosen by the file's extension.
    pub(crate) fn save(&self, path: &Path) -> Result<()> {
        save(self, self.size, path)
    }
}
