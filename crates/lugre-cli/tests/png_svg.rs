//! PNG = SVG: the same figure written as PNG and as SVG must show the same ink. Each SVG is
//! rasterised (resvg, with the font the binary embeds) and compared with the PNG the binary
//! draws, as coverage masks: a pixel is ink when it is darker than the light grid lines.
//!
//! Tolerance: anti-aliasing, glyph rasterisation and line joins differ between the two
//! renderers by a pixel or so, so each mask is widened by `SLACK` pixels before the other is
//! checked against it, and at least `MIN_SHARE` of each mask's ink must fall inside the other's
//! widened mask. A PNG that drops part of a curve fails the first share (SVG ink missing from
//! the PNG); a PNG that draws where the SVG does not (lines out of the axes, to the image's
//! edge) fails the second.

mod common;
use common::{lugre, TempDir};

/// Pixels each mask is widened by before the other is compared with it.
const SLACK: usize = 2;
/// The share of each image's ink that must lie within `SLACK` pixels of the other's.
const MIN_SHARE: f64 = 0.99;
/// A pixel whose darkest channel is below this is ink (the grid lines are 210 and 235).
const INK: u8 = 190;

/// An image as a coverage mask.
struct Mask {
    w: usize,
    h: usize,
    ink: Vec<bool>,
}

impl Mask {
    /// From RGB(A) pixels, `channels` bytes each.
    fn from_pixels(w: usize, h: usize, bytes: &[u8], channels: usize) -> Self {
        let ink = bytes
            .chunks(channels)
            .map(|p| p[..3].iter().copied().min().unwrap_or(255) < INK)
            .collect();
        Self { w, h, ink }
    }

    fn count(&self) -> usize {
        self.ink.iter().filter(|&&b| b).count()
    }

    /// The mask with every ink pixel grown into a square of side `2 r + 1`.
    fn widened(&self, r: usize) -> Self {
        let mut out = vec![false; self.ink.len()];
        for y in 0..self.h {
            for x in 0..self.w {
                if !self.ink[y * self.w + x] {
                    continue;
                }
                for yy in y.saturating_sub(r)..(y + r + 1).min(self.h) {
                    for xx in x.saturating_sub(r)..(x + r + 1).min(self.w) {
                        out[yy * self.w + xx] = true;
                    }
                }
            }
        }
        Self {
            w: self.w,
            h: self.h,
            ink: out,
        }
    }

    /// The share of this mask's ink inside `other` widened by `SLACK`.
    fn share_within(&self, other: &Mask) -> f64 {
        let wide = other.widened(SLACK);
        let inside = self
            .ink
            .iter()
            .zip(&wide.ink)
            .filter(|(&a, &b)| a && b)
            .count();
        inside as f64 / self.count().max(1) as f64
    }
}

fn png_mask(path: &std::path::Path) -> Mask {
    let decoder = png::Decoder::new(std::fs::File::open(path).expect("the PNG was written"));
    let mut reader = decoder.read_info().expect("a PNG");
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).expect("a PNG frame");
    let channels = info.color_type.samples();
    Mask::from_pixels(
        info.width as usize,
        info.height as usize,
        &buf[..info.buffer_size()],
        channels,
    )
}

fn svg_mask(path: &std::path::Path) -> Mask {
    let mut options = resvg::usvg::Options::default();
    options
        .fontdb_mut()
        .load_font_data(dejavu::sans::regular().to_vec());
    options.fontdb_mut().set_sans_serif_family("DejaVu Sans");
    options.font_family = "DejaVu Sans".into();
    let data = std::fs::read(path).expect("the SVG was written");
    let tree = resvg::usvg::Tree::from_data(&data, &options).expect("a valid SVG");
    let size = tree.size().to_int_size();
    let mut pixmap =
        resvg::tiny_skia::Pixmap::new(size.width(), size.height()).expect("a non-empty image");
    pixmap.fill(resvg::tiny_skia::Color::WHITE);
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::default(),
        &mut pixmap.as_mut(),
    );
    // Premultiplied over an opaque white background: the colours are final.
    Mask::from_pixels(
        size.width() as usize,
        size.height() as usize,
        pixmap.data(),
        4,
    )
}

/// Where the masks differ, for a person to look at (`LUGRE_PNG_SVG_DIFF=DIR`): red where only
/// the SVG has ink, blue where only the PNG has, grey where both have.
fn write_difference(path: &std::path::Path, svg: &Mask, png: &Mask) {
    let (svg_wide, png_wide) = (svg.widened(SLACK), png.widened(SLACK));
    let mut rgb = Vec::with_capacity(svg.ink.len() * 3);
    for i in 0..svg.ink.len() {
        rgb.extend_from_slice(match (svg.ink[i], png.ink[i]) {
            (true, _) if !png_wide.ink[i] => &[220, 0, 0],
            (_, true) if !svg_wide.ink[i] => &[0, 0, 220],
            (true, _) | (_, true) => &[170, 170, 170],
            _ => &[255, 255, 255],
        });
    }
    let file = std::io::BufWriter::new(std::fs::File::create(path).expect("create the difference"));
    let mut encoder = png::Encoder::new(file, svg.w as u32, svg.h as u32);
    encoder.set_color(png::ColorType::Rgb);
    let mut writer = encoder.write_header().expect("a PNG header");
    writer.write_image_data(&rgb).expect("the difference");
}

/// Runs `lugre args --plot NAME.svg` and `--plot NAME.png` in `dir` and compares the two.
fn same_ink(dir: &TempDir, name: &str, args: &[&str]) {
    let mut masks = Vec::new();
    for ext in ["svg", "png"] {
        let path = dir.path().join(format!("{name}.{ext}"));
        let mut all = args.to_vec();
        all.extend(["--plot", path.to_str().unwrap()]);
        let out = lugre(&all);
        assert!(
            out.status.success(),
            "{all:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        masks.push(if ext == "svg" {
            svg_mask(&path)
        } else {
            png_mask(&path)
        });
    }
    let (svg, png) = (&masks[0], &masks[1]);
    assert_eq!((svg.w, svg.h), (png.w, png.h), "{name}: the image sizes");
    assert!(svg.count() > 1000, "{name}: the SVG has ink");
    if let Some(dir) = std::env::var_os("LUGRE_PNG_SVG_DIFF") {
        write_difference(
            &std::path::Path::new(&dir).join(format!("{name}-diff.png")),
            svg,
            png,
        );
    }
    let drawn = svg.share_within(png);
    let extra = png.share_within(svg);
    eprintln!(
        "{name}: SVG ink in the PNG {:.3} %, PNG ink in the SVG {:.3} %",
        100.0 * drawn,
        100.0 * extra
    );
    assert!(
        drawn >= MIN_SHARE && extra >= MIN_SHARE,
        "{name}: {:.2} % of the SVG's ink is in the PNG and {:.2} % of the PNG's ink is in the \
         SVG (within {SLACK} px); both must be at least {:.0} %",
        100.0 * drawn,
        100.0 * extra,
        100.0 * MIN_SHARE
    );
}

/// The reproduction of the issue: Canudas de Wit's parameters on 0 -> 8 -> 4 -> 10 -> 0 mm at
/// 10 mm/s, two periods. The PNG drew a fraction of the sliding plateaus, and lines from the
/// frame to the image's edges.
#[test]
fn simulate_on_a_stiff_model_draws_the_same_png_as_svg() {
    let dir = TempDir::new("png-svg-simulate");
    let path = dir.file(
        "path.csv",
        "t,u\n0,0\n0.8,0.008\n1.2,0.004\n1.8,0.010\n2.8,0\n",
    );
    same_ink(
        &dir,
        "simulate",
        &[
            "simulate",
            "--preset",
            "canudas1995",
            "--input",
            &path,
            "--periods",
            "2",
            "--samples-per-period",
            "2000",
        ],
    );
}

/// A loop with its minor loops: curves in several colours and dash patterns, markers, legend.
#[test]
fn loop_draws_the_same_png_as_svg() {
    let dir = TempDir::new("png-svg-loop");
    same_ink(&dir, "loop", &["loop", "--bimodal", "0,0.2,1,1.5"]);
}

/// A dynamics run: stick-slip's time histories, panels side by side.
#[test]
fn dynamics_draws_the_same_png_as_svg() {
    let dir = TempDir::new("png-svg-dynamics");
    same_ink(&dir, "dynamics", &["dynamics", "--scenario", "stick-slip"]);
}

/// A sweep: five panels in two rows, log axes, a sequential colour scale, markers.
#[test]
fn sweep_draws_the_same_png_as_svg() {
    let dir = TempDir::new("png-svg-sweep");
    same_ink(
        &dir,
        "sweep",
        &[
            "sweep",
            "--preset",
            "canudas1995",
            "--amplitudes",
            "1e-6:1e-4:4",
            "--frequencies",
            "0.1,10",
        ],
    );
}
