//! Elements plotters lacks: a legend sample of a dash pattern, and open markers.

use plotters::element::{Drawable, PointCollection};
use plotters::prelude::*;
use plotters_backend::{BackendCoord as BackendCoordinate, DrawingErrorKind};

use super::dashes::dash;
use super::Shape;

/// A legend sample of a curve's line style, `length` pixels long, starting at `at`.
pub(super) struct DashSample {
    pub(super) at: (i32, i32),
    pub(super) length: f64,
    pub(super) pattern: Vec<f64>,
    pub(super) style: ShapeStyle,
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
pub(super) struct MarkerElement<C> {
    at: C,
    shape: Shape,
    style: ShapeStyle,
    radius: i32,
}

impl<C> MarkerElement<C> {
    pub(super) fn new(at: C, shape: Shape, style: ShapeStyle, s: f64) -> Self {
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
            // A closed path, not a rectangle: the SVG backend draws rectangles one pixel wide
            // whatever the style says. The first side is drawn twice so its corner is joined.
            Shape::Square => backend.draw_path(
                [
                    (x - r, y - r),
                    (x + r, y - r),
                    (x + r, y + r),
                    (x - r, y + r),
                    (x - r, y - r),
                    (x + r, y - r),
                ],
                &self.style,
            ),
        }
    }
}
