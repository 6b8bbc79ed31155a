//! The PNG's drawing backend: plotters' bitmap backend with lines wider than a pixel stroked
//! here, and text at the SVG's size, so that a PNG shows what the SVG of the same figure shows.
//!
//! plotters strokes a wide polyline by turning its outline into one polygon and filling it.
//! Where the line runs back over itself (a loop retraced, a plateau crossed twice) the fill's
//! even-odd rule cancels the overlap and the line vanishes; where two pixels of the line
//! coincide the outline's normal is NaN (a vertex at the image's corner); and at a sharp
//! reversal the inner miter is not capped and runs far off the line, to the image's edge.
//! Here each segment is filled as its own rectangle, with round joins, so a polyline covers
//! the pixels within half its width of it and nothing else, like the SVG viewer's stroke.
//!
//! plotters' font rasteriser takes a text size as the font's line height, while its SVG
//! writes `font-size` as that size / 1.24: glyphs are drawn here at the size that gives the
//! SVG's em. Layout (label areas, the legend's size) is estimated the same way for both.

use plotters::prelude::*;
use plotters::style::text_anchor::VPos;
use plotters::style::FontDesc;
use plotters_backend::{
    BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingErrorKind,
};

/// The line height of DejaVu Sans (ascent - descent) in em.
const LINE_HEIGHT_EM: f64 = 2384.0 / 2048.0;
/// plotters' SVG backend writes `font-size` as the text size divided by this.
const SVG_SIZE_PER_EM: f64 = 1.24;
/// The text size given to the rasteriser for glyphs the size of the SVG's, per unit of size.
const TEXT_SCALE: f64 = LINE_HEIGHT_EM / SVG_SIZE_PER_EM;

type Inner<'a> = BitMapBackend<'a>;
type Error<'a> = DrawingErrorKind<<Inner<'a> as DrawingBackend>::ErrorType>;

/// An RGB buffer drawn like the SVG (see the module's documentation).
pub(super) struct Raster<'a>(Inner<'a>);

impl<'a> Raster<'a> {
    /// Draws on `buf`, RGB rows of `size.0` pixels.
    pub(super) fn with_buffer(buf: &'a mut [u8], size: (u32, u32)) -> Self {
        Self(BitMapBackend::with_buffer(buf, size))
    }

    /// Fills every segment of `path` as a rectangle `width` wide, and a disc at every joint.
    fn stroke(
        &mut self,
        path: &[BackendCoord],
        color: BackendColor,
        width: u32,
    ) -> Result<(), Error<'a>> {
        let mut path = path.to_vec();
        // A repeated pixel has no direction (and an SVG polyline draws nothing for it).
        path.dedup();
        let half = f64::from(width) / 2.0;
        for w in path.windows(2) {
            let corners = segment_rectangle(w[0], w[1], half);
            self.0.fill_polygon(corners, &color)?;
        }
        if path.len() > 2 {
            let radius = half.round() as u32;
            for &joint in &path[1..path.len() - 1] {
                self.0.draw_circle(joint, radius, &color, true)?;
            }
        }
        Ok(())
    }
}

/// How far (pixels, down the text) plotters' rasteriser must move text of `size` anchored at
/// `v` for its baseline to fall where the SVG's does.
///
/// The SVG puts the baseline 0.76 em below the anchor (top), 0.5 ex below it (centre) or 0.5 ex
/// above it (bottom), an ex being half an em (as CSS takes it when a font does not say). The
/// rasteriser, given size `k` (`TEXT_SCALE` times `size`), puts it `k / 2` below the top of a
/// box `k / 1.24` pixels high (rounded down) that it aligns with the anchor.
fn baseline_shift(size: f64, v: VPos) -> i32 {
    let em = size / SVG_SIZE_PER_EM;
    let k = size * TEXT_SCALE;
    let height = (k / SVG_SIZE_PER_EM) as i32;
    let (svg, top) = match v {
        VPos::Top => (0.76 * em, 0),
        VPos::Center => (0.25 * em, -height / 2),
        VPos::Bottom => (-0.25 * em, -height),
    };
    let raster = f64::from(top) + f64::from((k / 2.0) as i32);
    (svg - raster).round() as i32
}

/// The corners of the rectangle `2 half` wide around the segment `a`-`b` (`a != b`).
fn segment_rectangle(a: BackendCoord, b: BackendCoord, half: f64) -> [BackendCoord; 4] {
    let (dx, dy) = (f64::from(b.0 - a.0), f64::from(b.1 - a.1));
    let len = dx.hypot(dy);
    let (nx, ny) = (-dy / len * half, dx / len * half);
    let at = |p: BackendCoord, sign: f64| {
        (
            (f64::from(p.0) + sign * nx).round() as i32,
            (f64::from(p.1) + sign * ny).round() as i32,
        )
    };
    [at(a, 1.0), at(b, 1.0), at(b, -1.0), at(a, -1.0)]
}

impl<'a> DrawingBackend for Raster<'a> {
    type ErrorType = <Inner<'a> as DrawingBackend>::ErrorType;

    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        style: &S,
    ) -> Result<(), Error<'a>> {
        if style.stroke_width() <= 1 {
            return self.0.draw_path(path, style);
        }
        if style.color().alpha == 0.0 {
            return Ok(());
        }
        let path: Vec<BackendCoord> = path.into_iter().collect();
        self.stroke(&path, style.color(), style.stroke_width())
    }

    fn draw_text<T: BackendTextStyle>(
        &mut self,
        text: &str,
        style: &T,
        pos: BackendCoord,
    ) -> Result<(), Error<'a>> {
        let size = style.size() * TEXT_SCALE;
        let font = FontDesc::new(style.family(), size, style.style()).transform(style.transform());
        let scaled = TextStyle {
            font,
            color: style.color(),
            pos: style.anchor(),
        };
        // Moved along the text's own vertical so that its baseline is where the SVG puts it.
        let (dx, dy) = style
            .transform()
            .transform(0, baseline_shift(style.size(), style.anchor().v_pos));
        self.0.draw_text(text, &scaled, (pos.0 + dx, pos.1 + dy))
    }

    // Everything else as the bitmap backend draws it.

    fn get_size(&self) -> (u32, u32) {
        self.0.get_size()
    }

    fn ensure_prepared(&mut self) -> Result<(), Error<'a>> {
        self.0.ensure_prepared()
    }

    fn present(&mut self) -> Result<(), Error<'a>> {
        self.0.present()
    }

    fn draw_pixel(&mut self, point: BackendCoord, color: BackendColor) -> Result<(), Error<'a>> {
        self.0.draw_pixel(point, color)
    }

    fn draw_line<S: BackendStyle>(
        &mut self,
        from: BackendCoord,
        to: BackendCoord,
        style: &S,
    ) -> Result<(), Error<'a>> {
        self.0.draw_line(from, to, style)
    }

    fn draw_rect<S: BackendStyle>(
        &mut self,
        upper_left: BackendCoord,
        bottom_right: BackendCoord,
        style: &S,
        fill: bool,
    ) -> Result<(), Error<'a>> {
        self.0.draw_rect(upper_left, bottom_right, style, fill)
    }

    fn draw_circle<S: BackendStyle>(
        &mut self,
        center: BackendCoord,
        radius: u32,
        style: &S,
        fill: bool,
    ) -> Result<(), Error<'a>> {
        self.0.draw_circle(center, radius, style, fill)
    }

    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        vert: I,
        style: &S,
    ) -> Result<(), Error<'a>> {
        self.0.fill_polygon(vert, style)
    }

    fn blit_bitmap(
        &mut self,
        pos: BackendCoord,
        (iw, ih): (u32, u32),
        src: &[u8],
    ) -> Result<(), Error<'a>> {
        self.0.blit_bitmap(pos, (iw, ih), src)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ab_glyph::Font;

    #[test]
    fn the_line_height_is_the_embedded_fonts() {
        let font = ab_glyph::FontRef::try_from_slice(dejavu::sans::regular()).unwrap();
        let em = font.units_per_em().unwrap();
        let height = font.height_unscaled() / em;
        assert!(
            (f64::from(height) - LINE_HEIGHT_EM).abs() < 1e-6,
            "{height}"
        );
    }

    /// A line that runs back over itself stays drawn (plotters' own stroke cancels it), and
    /// nothing is drawn beyond half the width from it.
    #[test]
    fn a_retraced_line_is_drawn_once_and_nowhere_else() {
        let (w, h) = (60u32, 40u32);
        let mut buf = vec![255u8; (w * h * 3) as usize];
        {
            let mut r = Raster::with_buffer(&mut buf, (w, h));
            let path = [(10, 20), (50, 20), (30, 21), (50, 20)];
            r.draw_path(path, &ShapeStyle::from(&BLACK).stroke_width(4))
                .unwrap();
        }
        let dark = |x: u32, y: u32| buf[((y * w + x) * 3) as usize] < 128;
        for x in 12..48 {
            assert!(dark(x, 20), "x = {x}");
        }
        for y in (0..h).filter(|y| !(16..=25).contains(y)) {
            for x in 0..w {
                assert!(!dark(x, y), "({x}, {y})");
            }
        }
    }
}
