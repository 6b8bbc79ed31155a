//! Writing figures to files: SVG, or PNG drawn at twice the size and averaged down (plotters'
//! bitmap backend does not anti-alias), atomically, with the embedded font.

use anyhow::{bail, Context, Result};
use plotters::prelude::*;
use std::path::Path;

use super::draw::Render;
use super::raster::Raster;

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
pub(crate) fn check_path(path: &Path) -> Result<()> {
    format_of(path).map(|_| ())
}

/// Writes `what` as SVG or PNG (by `path`'s extension), atomically.
pub(super) fn save(what: &impl Render, size: (u32, u32), path: &Path) -> Result<()> {
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
                let root = Raster::with_buffer(&mut big, (w, h)).into_drawing_area();
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
