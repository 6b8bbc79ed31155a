//! `lugre sweep`: the periodic steady state under `u = OFFSET + A sin(2 pi f t)` for every
//! amplitude and frequency of a grid — energy dissipated per cycle, peak force, equivalent
//! stiffness and damping, describing function — found directly as the fixed point of the
//! period map (`lugre::sweep`), in parallel over the points.
//!
//! Everything is computed and checked before anything is printed or written.

use anyhow::{anyhow, Result};
use clap::Args;
use indicatif::ProgressBar;
use lugre::sweep::{self, parse_values, Point, Sweep, SweepError, COLUMNS};
use lugre::Tolerance;
use std::io::Write;
use std::sync::Mutex;

use crate::args::{check_files, ModelArgs, ModelChoice, Needed, OutputArgs, PlotArgs};
use crate::fmt::sig;
use crate::io::atomic::write_atomic;
use crate::io::csv::NumberRows;
use crate::io::json::JsonOut;
use crate::io::progress::{styled, Progress};
use crate::numbers::{Real, Whole};
use crate::plot::Units;

mod plot;

/// The help of `--plot` for this command.
const PLOT_HELP: &str = "Draw the steady-state loops of the amplitudes at the first frequency \
    (in the (u, F) and (u', F) planes, coloured by amplitude), the energy per cycle and the \
    describing function's gain and phase against the amplitude (one curve per frequency), to an \
    SVG or PNG file";

/// The help of `--json` for this command.
fn json_help() -> String {
    format!(
        r#"Print {{"model": {{...}}, "parameters": {{...}}, "points": [{{{}, "loop"?}}, ...]}} instead of the table"#,
        COLUMNS
            .iter()
            .map(|c| format!("\"{c}\""))
            .collect::<Vec<_>>()
            .join(", ")
    )
}

/// The help of `--csv` for this command.
fn csv_help() -> String {
    format!(
        "Write one row per point (columns {}) to this CSV file; the loops (--loops) are in --json only",
        COLUMNS.join(",")
    )
}

#[derive(Args, Debug)]
#[command(
    mut_arg("json", |a| a.help(json_help())),
    mut_arg("csv", |a| a.help(csv_help())),
    mut_arg("plot", |a| a.help(PLOT_HELP))
)]
pub(crate) struct SweepArgs {
    #[command(flatten)]
    pub(crate) model: ModelArgs,
    /// Amplitudes A > 0 of the sine [m]: A1,A2,... or START:STOP:COUNT (COUNT values evenly
    /// spaced on a log scale, both ends included).
    #[arg(
        long,
        value_name = "A1,A2,...|START:STOP:COUNT",
        allow_hyphen_values = true,
        help_heading = "Input"
    )]
    pub(crate) amplitudes: String,
    /// Frequencies f > 0 of the sine [Hz]: F1,F2,... or START:STOP:COUNT (log spacing).
    #[arg(
        long,
        value_name = "F1,F2,...|START:STOP:COUNT",
        allow_hyphen_values = true,
        help_heading = "Input"
    )]
    pub(crate) frequencies: String,
    /// The sine's mean value [m] (default 0): it shifts the loops along u, nothing else.
    #[arg(long, value_name = "U0", allow_hyphen_values = true, value_parser = Real, help_heading = "Input")]
    pub(crate) offset: Option<f64>,
    #[arg(long, value_name = "TOL", value_parser = Real, help_heading = "Sweep", help = tol_help())]
    pub(crate) tol: Option<f64>,
    /// Each point's steady-state loop (t, u, F) at N >= 2 evenly spaced times over one
    /// period, both ends included, in --json.
    #[arg(long = "loops", value_name = "N", value_parser = Whole(2), help_heading = "Output")]
    pub(crate) loops: Option<usize>,
    #[command(flatten)]
    pub(crate) output: OutputArgs,
    #[command(flatten)]
    pub(crate) plot: PlotArgs,
}

/// `--tol`'s help, with the core's default.
fn tol_help() -> String {
    format!(
        "Relative tolerance of the integrator, in [1e-14, 1) (default {}: energies to about ten times that)",
        sig(sweep::Request::DEFAULT_TOLERANCE, 3)
    )
}

/// The front end's spelling of a request error: the flag, then the core's message.
fn flagged(flag: &str, e: SweepError) -> anyhow::Error {
    anyhow!("{flag}: {e}")
}

pub(crate) fn run(args: &SweepArgs) -> Result<()> {
    check_files(None, &args.output, Some(&args.plot))?;
    let choice = args.model.build()?;
    let model = choice.lugre();
    // No input file: a preset's parameters are SI; the flag names others (labels only).
    let units = Units::for_figure(
        None,
        &lugre_io::ReadOptions::default(),
        args.model.preset.is_some(),
        args.plot.units.as_deref(),
    )?;
    let request = build(args)?;
    let sweep = compute(&request, &model)?;
    if let Some(path) = &args.plot.path {
        plot::figure(&model, &request, &sweep, &units)?.save(path)?;
    }
    report(args, &choice, &request, &sweep)
}

/// The core's request from the flags, each checked in turn.
fn build(args: &SweepArgs) -> Result<sweep::Request> {
    let amplitudes = parse_values("--amplitudes", &args.amplitudes).map_err(|e| anyhow!("{e}"))?;
    let frequencies =
        parse_values("--frequencies", &args.frequencies).map_err(|e| anyhow!("{e}"))?;
    let mut r = sweep::Request::new(amplitudes, frequencies).map_err(|e| match e {
        SweepError::NotPositive {
            what: "frequency", ..
        } => flagged("--frequencies", e),
        SweepError::NotPositive { .. } => flagged("--amplitudes", e),
        e => anyhow!("{e}"),
    })?;
    if let Some(offset) = args.offset {
        r = r.with_offset(offset).map_err(|e| flagged("--offset", e))?;
    }
    if let Some(tol) = args.tol {
        r = r.with_tolerance(Tolerance::new(tol).map_err(|e| anyhow!("--tol: {e}"))?);
    }
    if let Some(n) = args.loops {
        r = r.with_loop_samples(n).map_err(|e| match e {
            SweepError::TooLarge { .. } => anyhow!("{e}"),
            e => flagged("--loops", e),
        })?;
    }
    Ok(r)
}

/// The points, with a progress bar on a terminal once the grid has run for a second.
fn compute(r: &sweep::Request, model: &lugre::LuGre) -> Result<Sweep> {
    let progress = Mutex::new(Progress::new());
    let report = |done: usize, total: usize| {
        let mut p = progress.lock().unwrap_or_else(|e| e.into_inner());
        let bar = p.bar(|_| {
            styled(
                ProgressBar::new(total as u64),
                "sweeping {bar:40} {pos}/{len} points ({elapsed} elapsed, about {eta} left)",
            )
        });
        if let Some(bar) = bar {
            bar.set_position(done as u64);
        }
    };
    let result = r.run(model, Some(&report));
    progress.lock().unwrap_or_else(|e| e.into_inner()).finish();
    Ok(result?)
}

/// Writes the CSV asked for, then prints the JSON document or the table.
fn report(args: &SweepArgs, choice: &ModelChoice, r: &sweep::Request, s: &Sweep) -> Result<()> {
    if let Some(path) = &args.output.csv {
        write_atomic(path, |w| write_csv(w, s))?;
    }
    let stdout = std::io::stdout();
    if args.output.json {
        write_json(JsonOut::new(stdout.lock()), choice, r, s)?;
        return Ok(());
    }
    let mut w = std::io::BufWriter::new(stdout.lock());
    print_table(&mut w, choice, r, s)?;
    if let Some(path) = &args.output.csv {
        writeln!(w, "\nWrote {} points to {}", s.points.len(), path.display())?;
    }
    w.flush()?;
    Ok(())
}

fn write_csv(w: &mut dyn Write, s: &Sweep) -> Result<()> {
    writeln!(w, "{}", COLUMNS.join(","))?;
    let mut rows = NumberRows::new();
    for p in &s.points {
        rows.write(w, &p.values())?;
    }
    Ok(())
}

/// `{"model": {...}, "parameters": {...}, "points": [...]}` (keys may be added, never renamed).
fn write_json<W: Write>(
    mut j: JsonOut<W>,
    choice: &ModelChoice,
    r: &sweep::Request,
    s: &Sweep,
) -> std::io::Result<()> {
    j.raw("{\"model\":")?;
    j.raw(&choice.to_json().to_string())?;
    j.raw(",\"parameters\":{\"input\":\"u = offset + amplitude sin(2 pi frequency t)\"")?;
    j.field(",\"offset\":", r.offset())?;
    j.field(",\"tolerance\":", r.tolerance().value())?;
    j.raw(",\"loop_samples\":")?;
    j.int(r.loop_samples())?;
    j.raw(",\"phase_unit\":\"rad\",\"amplitudes\":")?;
    j.array(r.amplitudes())?;
    j.raw(",\"frequencies\":")?;
    j.array(r.frequencies())?;
    j.raw("},\"points\":[")?;
    for (i, p) in s.points.iter().enumerate() {
        if i > 0 {
            j.raw(",")?;
        }
        write_point(&mut j, p)?;
    }
    j.raw("]}\n")?;
    j.finish()
}

fn write_point<W: Write>(j: &mut JsonOut<W>, p: &Point) -> std::io::Result<()> {
    for (k, (name, x)) in COLUMNS.iter().zip(p.values()).enumerate() {
        j.key(k == 0, name);
        j.num(x)?;
    }
    if let Some(l) = &p.samples {
        j.raw(",\"loop\":{\"t\":")?;
        j.array(&l.t)?;
        j.raw(",\"u\":")?;
        j.array(&l.u)?;
        j.raw(",\"force\":")?;
        j.array(&l.force)?;
        j.raw("}")?;
    }
    j.raw("}")
}

fn print_table(
    w: &mut impl Write,
    choice: &ModelChoice,
    r: &sweep::Request,
    s: &Sweep,
) -> Result<()> {
    writeln!(w, "{}", choice.describe(Needed::All))?;
    writeln!(
        w,
        "Input: u = {}A sin(2 pi f t); {} amplitudes x {} frequencies = {} points; periodic steady state (fixed point of the period map), tol = {}",
        if r.offset() == 0.0 {
            String::new()
        } else {
            format!("{} + ", sig(r.offset(), 10))
        },
        r.amplitudes().len(),
        r.frequencies().len(),
        s.points.len(),
        sig(r.tolerance().value(), 3)
    )?;
    let head = [
        "A", "f", "E/cycle", "peak |F|", "k_eq", "c_eq", "gain", "phase",
    ];
    writeln!(w)?;
    row(w, head.map(String::from))?;
    for p in &s.points {
        row(
            w,
            [
                sig(p.amplitude, 6),
                sig(p.frequency, 6),
                sig(p.dissipation, 10),
                sig(p.peak_force, 8),
                sig(p.stiffness, 8),
                sig(p.damping, 8),
                sig(p.gain, 8),
                sig(p.phase, 6),
            ],
        )?;
    }
    writeln!(
        w,
        "\nE/cycle: energy dissipated per cycle; k_eq, c_eq: equivalent stiffness and viscous damping of the first harmonic; gain, phase [rad]: describing function. --json or --csv FILE for every column."
    )?;
    Ok(())
}

/// One line of the table, right-aligned in its columns.
fn row(w: &mut impl Write, cells: [String; 8]) -> std::io::Result<()> {
    const WIDTHS: [usize; 8] = [12, 12, 16, 14, 14, 14, 14, 10];
    let line: Vec<String> = cells
        .iter()
        .zip(WIDTHS)
        .map(|(c, n)| format!("{c:>n$}"))
        .collect();
    writeln!(w, "{}", line.join(" "))
}
