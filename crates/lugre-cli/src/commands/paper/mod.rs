//! `lugre paper`: the paper's Figures 3-17 redrawn from the library (SVG and PNG), the data of
//! every curve drawn (CSV), and `index.html`, one self-contained page with every figure, its
//! caption, the numbers of each example's loop (as `lugre loop --json` prints them) and the
//! errata of Theorem A.
//!
//! Everything is computed before anything is written, and every file is written atomically.
//! The figures follow the paper's captions: which curves, which line styles (dashed, dotted,
//! dash-dotted, solid), which markers. Where the paper leaves a choice open (how many periods
//! a time plot shows, which bimodal input Fig. 3 draws), the choice is stated in the caption.

use anyhow::{Context, Result};
use clap::Args;
use lugre::Bimodal;
use std::io::Write;
use std::path::{Path, PathBuf};

use crate::fmt::{exact, sig};
use crate::hysteresis::kind_name;
use crate::io::atomic::write_atomic;
use crate::io::outputs::OutputFolder;

mod canudas;
mod convergence;
mod examples;
mod figures;
mod html;
mod models;

use convergence::convergence_figures;
use examples::{LoopExample, PaperInput};
use figures::{fig03, fig04, fig05, fig14, loop_figure, PaperFigure};

#[derive(Args, Debug)]
pub(crate) struct PaperArgs {
    /// Directory to write the figures, their data and index.html to (created if missing). An
    /// existing folder must be empty or one lugre paper wrote (it holds the file .lugre-paper):
    /// files in a folder of yours are not replaced unless --force is given.
    #[arg(long, value_name = "DIR", default_value = "paper-figures")]
    pub(crate) out: PathBuf,
    /// Write into --out even when it is a folder lugre did not create that holds files (the
    /// files with the names lugre paper writes are replaced; others are left alone).
    #[arg(long)]
    pub(crate) force: bool,
}

/// Everything `lugre paper` draws and tabulates.
pub(crate) struct Paper {
    pub(crate) figures: Vec<PaperFigure>,
    pub(crate) examples: Vec<LoopExample>,
    /// The second report: the closed-loop experiments of Canudas de Wit et al. (1995).
    pub(crate) canudas: canudas::Report,
    /// The third report: LuGre next to every model of the zoo.
    pub(crate) models: canudas::Report,
}

pub(crate) fn run(args: &PaperArgs) -> Result<()> {
    let started = std::time::Instant::now();
    let folder = OutputFolder::check("--out", &args.out, args.force)?;
    let paper = build()?;
    let dir = folder.create()?;
    let written = write_all(&paper, dir)?;
    print_summary(&paper, dir, &written, started.elapsed())
}

/// Computes every figure and table.
pub(crate) fn build() -> Result<Paper> {
    let example2 = LoopExample::new(
        "example2",
        "Example 2: triangle input of period 2 (turning points 0, 1), sigma0 = 1",
        vec![6, 7, 8, 9],
        1.0,
        PaperInput::TurningPoints(vec![0.0, 1.0]),
    )?;
    let example3 = LoopExample::new(
        "example3",
        "Example 3: bimodal input, turning points 0, 1, 0.2, 1.5, sigma0 = 1",
        vec![10, 11, 12, 13],
        1.0,
        PaperInput::Bimodal(Bimodal::new(0.0, 0.2, 1.0, 1.5)?),
    )?;
    let example4 = LoopExample::new(
        "example4",
        "Example 4: bimodal input, turning points 0, 1, 0.5, 1.5, sigma0 = 6",
        vec![14, 15],
        6.0,
        PaperInput::Bimodal(Bimodal::new(0.0, 0.5, 1.0, 1.5)?),
    )?;
    let fig16 = LoopExample::new(
        "fig16",
        "Fig. 16: Example 4 with sigma0 = 1",
        vec![16],
        1.0,
        PaperInput::Bimodal(Bimodal::new(0.0, 0.5, 1.0, 1.5)?),
    )?;
    let mut fig17 = LoopExample::new(
        "fig17",
        "Fig. 17: Example 4 with sigma0 = 1 and umin2 = 0.2",
        vec![17],
        1.0,
        PaperInput::Bimodal(Bimodal::new(0.0, 0.2, 1.0, 1.5)?),
    )?;
    fig17.note = Some(
        "With sigma0 = 1 and umin2 = 0.2 this is Example 3's model and input: the same loop as \
         Fig. 13 and the same numbers as Example 3's table."
            .into(),
    );

    let mut figures = vec![fig03(&example3)?, fig04()?, fig05()?];
    figures.extend(convergence_figures(&example2, 6, 5, 4)?);
    figures.extend(convergence_figures(&example3, 10, 3, 3)?);
    figures.push(fig14(&example4)?);
    for (number, ex) in [(15, &example4), (16, &fig16), (17, &fig17)] {
        figures.push(loop_figure(number, ex)?);
    }
    Ok(Paper {
        figures,
        examples: vec![example2, example3, example4, fig16, fig17],
        canudas: canudas::build()?,
        models: models::build()?,
    })
}

/// Writes every file; returns their names in the order written.
fn write_all(paper: &Paper, dir: &Path) -> Result<Vec<String>> {
    let mut written = write_report(&paper.figures, &html::page(paper), dir, "")?;
    for (sub, report, page) in [
        (canudas::DIR, &paper.canudas, canudas::page(&paper.canudas)),
        (models::DIR, &paper.models, models::page(&paper.models)),
    ] {
        let folder = dir.join(sub);
        std::fs::create_dir_all(&folder)
            .with_context(|| format!("cannot create '{}'", folder.display()))?;
        let prefix = format!("{sub}/");
        written.extend(write_report(&report.figures, &page, &folder, &prefix)?);
    }
    Ok(written)
}

/// A report's figures (SVG, PNG, the CSV of every curve) and its `index.html` in `dir`; the
/// names written, each after `prefix`.
fn write_report(
    figures: &[PaperFigure],
    html: &str,
    dir: &Path,
    prefix: &str,
) -> Result<Vec<String>> {
    let mut written = Vec::new();
    for f in figures {
        for ext in ["svg", "png"] {
            let name = format!("{}.{ext}", f.stem());
            f.figure.save(&dir.join(&name))?;
            written.push(format!("{prefix}{name}"));
        }
        for (name, curve) in f.csv_files() {
            write_atomic(&dir.join(&name), |w| {
                writeln!(w, "{},{}", f.columns[0], f.columns[1])?;
                for &(x, y) in &curve.points {
                    writeln!(w, "{},{}", exact(x), exact(y))?;
                }
                Ok(())
            })?;
            written.push(format!("{prefix}{name}"));
        }
    }
    write_atomic(&dir.join("index.html"), |w| {
        Ok(w.write_all(html.as_bytes())?)
    })?;
    written.push(format!("{prefix}index.html"));
    Ok(written)
}

fn print_summary(
    paper: &Paper,
    dir: &Path,
    written: &[String],
    elapsed: std::time::Duration,
) -> Result<()> {
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    let csv = written.iter().filter(|n| n.ends_with(".csv")).count();
    let (first, last) = match (paper.figures.first(), paper.figures.last()) {
        (Some(a), Some(b)) => (a.stem(), b.stem()),
        _ => (String::new(), String::new()),
    };
    writeln!(
        out,
        "Wrote {} files to {} in {:.2} s:",
        written.len(),
        dir.display(),
        elapsed.as_secs_f64()
    )?;
    writeln!(
        out,
        "  {first}..{last}.svg and .png  {} figures of the paper, redrawn",
        paper.figures.len()
    )?;
    writeln!(
        out,
        "  figNN-CURVE.csv            {csv} CSV files, the points of every curve drawn"
    )?;
    writeln!(
        out,
        "  index.html                 every figure with its caption, the loop tables, Theorem A's errata"
    )?;
    writeln!(
        out,
        "  {}/                the second report: Canudas de Wit et al. (1995), Figs. 2, 3, 4, 6, 8 \
         (lugre dynamics)",
        canudas::DIR
    )?;
    writeln!(
        out,
        "  {}/                     the third report: LuGre next to every model of the zoo \
         (lugre loop --model NAME)",
        models::DIR
    )?;
    writeln!(out)?;
    for f in &paper.figures {
        writeln!(
            out,
            "  {}  {} ({} curve{})",
            f.stem(),
            f.title,
            f.figure.curves.len(),
            if f.figure.curves.len() == 1 { "" } else { "s" }
        )?;
    }
    writeln!(
        out,
        "\nHysteresis loops y° (rate-independent limit); the command shown prints the same \
         numbers with --json:"
    )?;
    for ex in &paper.examples {
        print_example(&mut out, ex)?;
    }
    writeln!(
        out,
        "\nOpen {} in a browser (it needs no network).",
        dir.join("index.html").display()
    )?;
    out.flush()?;
    Ok(())
}

/// An example's loop numbers, and the `lugre loop` command that prints them.
fn print_example(out: &mut impl Write, ex: &LoopExample) -> Result<()> {
    writeln!(out, "  {}", ex.title)?;
    writeln!(out, "    lugre {}", ex.loop_args().join(" "))?;
    let mut line = format!("    y°(0) = {}", sig(ex.hl.turning_y()[0], 10));
    if let Some(ta) = &ex.theorem_a {
        line += &format!(
            ", rho_5 = {}, minor loop [rho_1, rho_5] = [{}, {}]",
            sig(ta.rho[5], 10),
            sig(ta.minor_loop[0], 10),
            sig(ta.minor_loop[1], 10)
        );
    }
    writeln!(out, "{line}")?;
    for l in &ex.loops {
        writeln!(
            out,
            "    {} loop, rho in [{}, {}]: work W = {}, stored dV = {}, dissipated D = {}",
            kind_name(l.kind),
            sig(l.start.rho, 6),
            sig(l.end.rho, 6),
            sig(l.energy.work, 10),
            sig(l.energy.stored_energy_change, 10),
            sig(l.energy.dissipation, 10)
        )?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_character_drawn_is_in_the_embedded_font() {
        use ab_glyph::Font;
        let font = ab_glyph::FontRef::try_from_slice(dejavu::sans::regular()).unwrap();
        let paper = build().unwrap();
        for f in paper.figures.iter().chain(&paper.canudas.figures) {
            let fig = &f.figure;
            let texts = fig
                .curves
                .iter()
                .filter_map(|c| c.label.as_deref())
                .chain(fig.markers.iter().filter_map(|m| m.label.as_deref()))
                .chain(fig.notes.iter().map(|n| n.text.as_str()))
                .chain(fig.title.as_deref())
                .chain([fig.x_label.as_str(), fig.y_label.as_str()]);
            for text in texts {
                for c in text.chars() {
                    assert!(
                        font.glyph_id(c).0 != 0,
                        "Fig. {}: '{c}' (U+{:04X}) in '{text}' has no glyph",
                        f.number,
                        c as u32
                    );
                }
            }
        }
    }

    #[test]
    fn the_loop_examples_are_the_papers() {
        let paper = build().unwrap();
        let ids: Vec<&str> = paper.examples.iter().map(|e| e.id).collect();
        assert_eq!(ids, ["example2", "example3", "example4", "fig16", "fig17"]);
        let numbers: Vec<u32> = paper.figures.iter().map(|f| f.number).collect();
        assert_eq!(numbers, (3..=17).collect::<Vec<_>>());
        // Example 3 (paper §4.3): rho_1..rho_4 = 1, 1.8, 3.1, 4.6 and the minor loop [1, 2.6].
        let ta = paper.examples[1].theorem_a.unwrap();
        for (a, b) in ta.rho.iter().zip([0.0, 1.0, 1.8, 3.1, 4.6, 2.6]) {
            assert!((a - b).abs() < 1e-15, "{:?}", ta.rho);
        }
        // Fig. 17 is Example 3's model and input.
        assert_eq!(paper.examples[4].loop_args(), paper.examples[1].loop_args());
    }
}
