//! `lugre simulate`: the response `y_gamma` of eq. 5 (`gamma = 1`: the model as given, eq. 1;
//! `gamma = inf`: the rate-independent limit `y*_u`, eq. 6) from an initial state `x0`, over K
//! periods of a periodic input (turning points at unit speed), sampled data (linear between
//! samples) or a sine. Piecewise-linear inputs are solved exactly; a sine by the adaptive,
//! L-stable integrator to `--tol` (exactly for `gamma = inf`). See `lugre::simulate`.
//!
//! Everything is computed and checked before anything is printed or written: an error leaves no
//! half-written output.

use anyhow::{anyhow, bail, Result};
use clap::Args;
use indicatif::ProgressBar;
use lugre::model::normal;
use lugre::simulate::{self, Output};
use lugre::{Gamma, LuGre, SimulateError, Tolerance, Trajectory};
use std::io::Write;

use crate::args::{check_files, ModelArgs, ModelChoice, OutputArgs, PeriodicInputArgs, PlotArgs};
use crate::fmt::{quoted, sig};
use crate::io::atomic::write_atomic;
use crate::io::json::JsonOut;
use crate::io::progress::{styled, Progress};
use crate::numbers::{parse_list, Whole};
use crate::plot::Units;
use lugre_io::Role;

mod drive;
mod output;
mod zoo;

use drive::build_drive;
use output::{print_table, response_figure, write_csv, write_json};

/// The help of `--json` for this command.
const JSON_HELP: &str =
    r#"Print {"t": [...], "u": [...], "z": [...], "dz": [...], "y": [...]} instead of the table"#;
/// The help of `--csv` for this command.
const CSV_HELP: &str = "Write the columns t,u,z,dz,y to this CSV file";
/// The help of `--plot` for this command.
const PLOT_HELP: &str =
    "Draw the response to an SVG or PNG file: y against t (left panel) and y against \
    u (right panel), side by side";

#[derive(Args, Debug)]
#[command(
    mut_arg("json", |a| a.help(JSON_HELP)),
    mut_arg("csv", |a| a.help(CSV_HELP)),
    mut_arg("plot", |a| a.help(PLOT_HELP))
)]
pub(crate) struct SimulateArgs {
    #[command(flatten)]
    pub(crate) model: ModelArgs,
    #[command(flatten)]
    pub(crate) input: PeriodicInputArgs,
    #[command(flatten)]
    pub(crate) data: crate::args::DataArgs,
    /// A sine u(t) = A sin(2 pi t / T + PHASE) + OFFSET, A > 0, T > 0, PHASE in radians
    /// (PHASE and OFFSET default to 0).
    #[arg(
        long,
        value_name = "A,T[,PHASE[,OFFSET]]",
        allow_hyphen_values = true,
        help_heading = "Input"
    )]
    pub(crate) sine: Option<String>,
    /// The constant speed of --turning-points or --bimodal [input units per s; m/s for a
    /// physical model] (default 1: time is rho, the paper's normalized time).
    #[arg(long, value_name = "V", value_parser = crate::numbers::Real, help_heading = "Input")]
    pub(crate) speed: Option<f64>,
    /// Slowness gamma of eq. 5 (the input runs as u(t / gamma) in physical time): a number > 0
    /// (1 = the model as given, eq. 1) or 'inf' (the rate-independent limit y*_u, eq. 6).
    #[arg(
        long,
        value_name = "G",
        allow_hyphen_values = true,
        help_heading = "Simulation"
    )]
    pub(crate) gamma: Option<String>,
    /// Number of periods K >= 1. An --input file is one period, repeated only if it ends where
    /// it starts.
    #[arg(
        long,
        value_name = "K",
        allow_hyphen_values = true,
        help_heading = "Simulation"
    )]
    pub(crate) periods: Option<String>,
    /// Initial state x0 = x(0) of eq. 1 (the bristle deflection [m]; for the Dahl model
    /// w(0) / rho).
    #[arg(
        long,
        value_name = "X",
        allow_hyphen_values = true,
        help_heading = "Simulation"
    )]
    pub(crate) x0: Option<String>,
    /// How a sampled --input is read between its samples: 'linear' (a piecewise-linear motion,
    /// exact as given) or 'cubic' (samples of a smooth motion: the C1 shape-preserving cubic
    /// through them, output with its velocity at the samples). A velocity column (header 'v'
    /// or 'velocity', or --columns v=NAME) is integrated to the displacement and always read
    /// as cubic.
    #[arg(long, value_enum, default_value = "linear", help_heading = "Data file")]
    pub(crate) interpolate: crate::args::Interpolate,
    /// Relative tolerance of the adaptive integrator for --sine (and of the cubic reading's
    /// subdivision, relative to the record's range), in [1e-14, 1).
    #[arg(
        long,
        value_name = "TOL",
        allow_hyphen_values = true,
        help_heading = "Simulation"
    )]
    pub(crate) tol: Option<String>,
    /// Output at these times (eq. 5's time t: the period does not depend on gamma), strictly
    /// increasing, within the K periods. At a kink the value just after it.
    #[arg(
        long,
        value_name = "T1,T2,...",
        allow_hyphen_values = true,
        help_heading = "Output"
    )]
    pub(crate) times: Option<String>,
    /// N >= 1 evenly spaced output times per period, both ends of the run included. Default:
    /// the samples of an --input file; 200 per period plus every turning point otherwise.
    #[arg(
        long,
        value_name = "N",
        allow_hyphen_values = true,
        value_parser = Whole(1),
        help_heading = "Output"
    )]
    pub(crate) samples_per_period: Option<usize>,
    #[command(flatten)]
    pub(crate) output: OutputArgs,
    #[command(flatten)]
    pub(crate) plot: PlotArgs,
}

/// The request, from the flags, each checked in turn before anything is computed.
struct Request {
    choice: ModelChoice,
    model: LuGre,
    /// What to simulate and where to sample it (the core's request, with its defaults).
    simulation: simulate::Request,
    /// The input, described for the table.
    input: String,
    /// The normal force of the record (`--columns N=NAME`) at its times: the model is then the
    /// friction coefficient's and `y` is `N(t)` times it.
    normal: drive::Normal,
}

pub(crate) fn run(args: &SimulateArgs) -> Result<()> {
    check_files(args.input.input.as_deref(), &args.output, Some(&args.plot))?;
    if let Some(model) = args.model.build_zoo()? {
        return zoo::run(args, &model);
    }
    let request = parse(args)?;
    let mut out = compute(&request)?;
    if let Some((t, n)) = &request.normal {
        // mu to the force: y times N(t), linear between the record's samples.
        normal::to_force(t, n, &out.t, &mut out.y);
    }
    report(args, &request, &out)
}

fn parse(args: &SimulateArgs) -> Result<Request> {
    let choice = args.model.build()?;
    let model = choice.lugre();
    let (drive, mut input, normal) = build_drive(args)?;
    if normal.is_some() {
        input.push_str("; y = N(t) times the friction coefficient of the model (N from the record, linear between samples; the model's parameters per newton)");
    }
    if let Some(path) = &args.plot.path {
        // Before a possibly long run, not after it.
        crate::plot::check_path(path)?;
    }
    // Only the flags given change the request; the rest are its defaults.
    let mut simulation = simulate::Request::new(drive);
    if let Some(text) = &args.gamma {
        simulation = simulation.with_gamma(parse_gamma(text)?);
    }
    if let Some(text) = &args.periods {
        simulation = simulation.with_periods(parse_periods(text)?)?;
    }
    if let Some(text) = &args.x0 {
        simulation = simulation.with_x0(parse_scalar("--x0", text)?);
    }
    if let Some(text) = &args.tol {
        let tol =
            Tolerance::new(parse_scalar("--tol", text)?).map_err(|e| anyhow!("--tol: {e}"))?;
        simulation = simulation.with_tolerance(tol);
    }
    // Checked here, in its turn; `compute` builds the simulator again.
    simulation
        .simulator(&model)
        .map_err(|e| anyhow!("--x0: {e}"))?;
    if args.times.is_some() && args.samples_per_period.is_some() {
        bail!("give --times or --samples-per-period, not both");
    }
    let output = match (&args.times, args.samples_per_period) {
        (Some(text), _) => Output::Times(parse_list("--times", text)?),
        (None, Some(n)) => Output::PerPeriod(n),
        (None, None) => Output::Default,
    };
    let simulation = simulation.with_output(output)?;
    simulation.check_work().map_err(flagged)?;
    Ok(Request {
        choice,
        model,
        simulation,
        input,
        normal,
    })
}

/// The response, with a progress bar for a long run.
fn compute(r: &Request) -> Result<Trajectory> {
    let sim = r
        .simulation
        .simulator(&r.model)
        .map_err(|e| anyhow!("--x0: {e}"))?;
    let mut progress = Progress::new();
    let result = {
        let mut report = |fraction: f64| show_progress(&mut progress, fraction);
        r.simulation.run_on(&sim, Some(&mut report))
    };
    progress.finish();
    let out = result.map_err(|e| match &e {
        // Only the output times are checked as data by the run itself.
        SimulateError::Data(_) => anyhow!("--times: {e}"),
        SimulateError::NotClosed { .. } => anyhow!("--periods: {e}"),
        _ => flagged(e),
    })?;
    Ok(out)
}

/// The core's message, with the count it names first (`periods must be at most ...`) spelled
/// as the flag that sets it (`--periods must be at most ...`, Python's `periods=`).
fn flagged(e: SimulateError) -> anyhow::Error {
    match e {
        SimulateError::TooManyPeriods { .. } | SimulateError::TooMuchWork { .. } => {
            anyhow!("--{e}")
        }
        e => anyhow!("{e}"),
    }
}

fn show_progress(progress: &mut Progress, fraction: f64) {
    let bar = progress.bar(|_| {
        styled(
            ProgressBar::new(1000),
            "simulating {bar:40} {percent:>3}% ({elapsed} elapsed, about {eta} left)",
        )
    });
    if let Some(bar) = bar {
        bar.set_position((fraction.clamp(0.0, 1.0) * 1000.0) as u64);
    }
}

/// Writes the CSV and the figure asked for, then prints the JSON document or the table.
fn report(args: &SimulateArgs, r: &Request, out: &Trajectory) -> Result<()> {
    if let Some(path) = &args.output.csv {
        write_atomic(path, |w| write_csv(w, out))?;
    }
    if let Some(path) = &args.plot.path {
        let what = if r.simulation.gamma().is_infinite() {
            "y⋆ᵤ (γ = ∞)".to_string()
        } else {
            format!("γ = {}", sig(r.simulation.gamma().value(), 6))
        };
        let units = Units::for_figure(
            args.input.input.as_deref(),
            &args.data.options(&[Role::U, Role::V])?,
            args.model.preset.is_some(),
            args.plot.units.as_deref(),
        )?;
        response_figure(out, &what, &units).save(path)?;
    }
    let stdout = std::io::stdout();
    if args.output.json {
        write_json(JsonOut::new(stdout.lock()), out)?;
    } else {
        let mut w = std::io::BufWriter::new(stdout.lock());
        print_table(&mut w, r, out)?;
        output::print_written(&mut w, args, "t,u,z,dz,y", out.len())?;
        w.flush()?;
    }
    Ok(())
}

fn parse_scalar(flag: &str, text: &str) -> Result<f64> {
    let t = text.trim();
    match t.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(_) => bail!("{flag} must be a finite number, got {}", quoted(t)),
        Err(_) => bail!("{flag} must be a number, got {}", quoted(t)),
    }
}

/// A positive number or `inf`.
fn parse_gamma(text: &str) -> Result<Gamma> {
    let t = text.trim();
    let value = match t.to_ascii_lowercase().as_str() {
        "inf" | "+inf" | "infinity" | "+infinity" => f64::INFINITY,
        _ => match t.parse::<f64>() {
            Ok(v) if v.is_finite() => v,
            _ => bail!("--gamma must be a number > 0 or 'inf', got {}", quoted(t)),
        },
    };
    Gamma::new(value).map_err(|e| anyhow!("--gamma: {e}"))
}

fn parse_periods(text: &str) -> Result<u32> {
    let t = text.trim();
    match t.parse::<i64>() {
        Ok(k) if k >= 1 && k <= i64::from(u32::MAX) => Ok(k as u32),
        Ok(k) if k < 1 => bail!("--periods must be at least 1, got {k}"),
        _ => bail!(
            "--periods must be a whole number from 1 to {}, got {}",
            u32::MAX,
            quoted(t)
        ),
    }
}
