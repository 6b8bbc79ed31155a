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
use lugre::simulate::{merge_times, uniform_times};
use lugre::{Gamma, LuGre, PiecewiseLinear, SimulateError, Simulator, Sine, Tolerance, Trajectory};
use std::io::Write;

use crate::args::{ModelArgs, ModelChoice, OutputArgs, PeriodicInputArgs, PlotArgs};
use crate::fmt::{quoted, sig};
use crate::io::atomic::write_atomic;
use crate::io::csv::NumberRows;
use crate::io::json::JsonOut;
use crate::io::progress::{styled, Progress};
use crate::numbers::{parse_list, Whole};
use crate::plot::{Curve, Figure, LineStyle, Panels, BLUE};

/// Output times per period when none are asked for (piecewise-linear inputs also get their
/// kinks; sampled data get exactly their samples).
const DEFAULT_SAMPLES_PER_PERIOD: usize = 200;

/// Rows of the table printed before the rest is summarised (all of it is in --json / --csv).
const TABLE_HEAD: usize = 20;

/// At most this many output rows (40 bytes each in memory, more as text).
const MAX_ROWS: usize = 50_000_000;

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
    /// A sine u(t) = A sin(2 pi t / T + PHASE) + OFFSET, A > 0, T > 0, PHASE in radians
    /// (PHASE and OFFSET default to 0).
    #[arg(
        long,
        value_name = "A,T[,PHASE[,OFFSET]]",
        allow_hyphen_values = true,
        help_heading = "Input"
    )]
    pub(crate) sine: Option<String>,
    /// Slowness gamma of eq. 5 (the input runs as u(t / gamma) in physical time): a number > 0
    /// (1 = the model as given, eq. 1) or 'inf' (the rate-independent limit y*_u, eq. 6).
    #[arg(
        long,
        value_name = "G",
        default_value = "1",
        allow_hyphen_values = true,
        help_heading = "Simulation"
    )]
    pub(crate) gamma: String,
    /// Number of periods K >= 1. An --input file is one period, repeated only if it ends where
    /// it starts.
    #[arg(
        long,
        value_name = "K",
        default_value = "1",
        allow_hyphen_values = true,
        help_heading = "Simulation"
    )]
    pub(crate) periods: String,
    /// Initial state x0 = x(0) of eq. 1 (the bristle deflection [m]; for the Dahl model
    /// w(0) / rho).
    #[arg(
        long,
        value_name = "X",
        default_value = "0",
        allow_hyphen_values = true,
        help_heading = "Simulation"
    )]
    pub(crate) x0: String,
    /// Relative tolerance of the adaptive integrator for --sine, in [1e-14, 1).
    #[arg(
        long,
        value_name = "TOL",
        default_value = "1e-10",
        allow_hyphen_values = true,
        help_heading = "Simulation"
    )]
    pub(crate) tol: String,
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

/// What drives the simulation.
enum Drive {
    /// Periodic turning points at unit speed.
    TurningPoints(PiecewiseLinear),
    /// Sampled data, linear between samples.
    Samples(PiecewiseLinear),
    Sine(Sine),
}

impl Drive {
    /// `(start, period)`.
    fn period(&self) -> (f64, f64) {
        match self {
            Drive::TurningPoints(pl) | Drive::Samples(pl) => (pl.times()[0], pl.period()),
            Drive::Sine(s) => (0.0, s.period()),
        }
    }
}

/// The request, from the flags, each checked in turn before anything is computed.
struct Request {
    choice: ModelChoice,
    model: LuGre,
    gamma: Gamma,
    periods: u32,
    x0: f64,
    tol: Tolerance,
    drive: Drive,
    /// The input, described for the table.
    input: String,
    /// The output times (`None`: the knots of a piecewise-linear input, its samples).
    times: Option<Vec<f64>>,
}

pub(crate) fn run(args: &SimulateArgs) -> Result<()> {
    let request = parse(args)?;
    let out = compute(&request)?;
    report(args, &request, &out)
}

fn parse(args: &SimulateArgs) -> Result<Request> {
    let choice = args.model.build()?;
    let model = choice.lugre();
    let gamma = parse_gamma(&args.gamma)?;
    let periods = parse_periods(&args.periods)?;
    let x0 = parse_scalar("--x0", &args.x0)?;
    let tol =
        Tolerance::new(parse_scalar("--tol", &args.tol)?).map_err(|e| anyhow!("--tol: {e}"))?;
    let (drive, input) = build_drive(args)?;
    if let Some(path) = &args.plot.path {
        // Before a possibly long run, not after it.
        crate::plot::check_path(path)?;
    }
    // Checked here, in its turn; `compute` builds the simulator again.
    Simulator::new(&model, gamma, x0).map_err(|e| anyhow!("--x0: {e}"))?;
    if args.times.is_some() && args.samples_per_period.is_some() {
        bail!("give --times or --samples-per-period, not both");
    }
    let times = output_times(args, &drive, periods)?;
    if let (Drive::TurningPoints(pl) | Drive::Samples(pl), None) = (&drive, &times) {
        check_rows((pl.len() - 1).saturating_mul(periods as usize) + 1)?;
    }
    Ok(Request {
        choice,
        model,
        gamma,
        periods,
        x0,
        tol,
        drive,
        input,
        times,
    })
}

/// The output times: `--times`, `--samples-per-period`, or the default for the input (`None`
/// for sampled data: its own samples).
fn output_times(args: &SimulateArgs, drive: &Drive, periods: u32) -> Result<Option<Vec<f64>>> {
    let (start, period) = drive.period();
    Ok(match (&args.times, args.samples_per_period) {
        (Some(text), _) => Some(parse_list("--times", text)?),
        (None, Some(n)) => {
            check_rows((periods as usize).saturating_mul(n).saturating_add(1))?;
            Some(uniform_times(start, period, periods, n))
        }
        (None, None) => match drive {
            Drive::Samples(_) => None,
            Drive::TurningPoints(pl) => {
                check_rows(
                    (periods as usize).saturating_mul(DEFAULT_SAMPLES_PER_PERIOD + pl.len()),
                )?;
                Some(merge_times(
                    &uniform_times(start, period, periods, DEFAULT_SAMPLES_PER_PERIOD),
                    &pl.knot_times(periods),
                ))
            }
            Drive::Sine(_) => {
                check_rows(periods as usize * DEFAULT_SAMPLES_PER_PERIOD + 1)?;
                Some(uniform_times(
                    start,
                    period,
                    periods,
                    DEFAULT_SAMPLES_PER_PERIOD,
                ))
            }
        },
    })
}

/// The response, with a progress bar for a long run.
fn compute(r: &Request) -> Result<Trajectory> {
    let sim = Simulator::new(&r.model, r.gamma, r.x0).map_err(|e| anyhow!("--x0: {e}"))?;
    let mut progress = Progress::new();
    let mut out = Trajectory::default();
    let result = {
        let mut report = |fraction: f64| show_progress(&mut progress, fraction);
        match (&r.drive, &r.times) {
            (Drive::TurningPoints(pl) | Drive::Samples(pl), None) => {
                sim.at_knots(pl, r.periods, &mut out, &mut report)
            }
            (Drive::TurningPoints(pl) | Drive::Samples(pl), Some(times)) => {
                sim.at_times(pl, r.periods, times, &mut out, &mut report)
            }
            // A sine always has output times (the default is set by `output_times`).
            (Drive::Sine(sine), times) => sim.sine(
                sine,
                r.periods,
                times.as_deref().unwrap_or_default(),
                r.tol,
                &mut out,
                &mut report,
            ),
        }
    };
    progress.finish();
    result.map_err(|e| match &e {
        SimulateError::TimeOutOfRange { .. }
        | SimulateError::TimesNotIncreasing { .. }
        | SimulateError::TimeNotFinite { .. } => anyhow!("--times: {e}"),
        SimulateError::NotClosed { .. } => anyhow!("--periods: {e}"),
        _ => anyhow!("{e}"),
    })?;
    Ok(out)
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
        let what = if r.gamma.is_infinite() {
            "y⋆ᵤ (γ = ∞)".to_string()
        } else {
            format!("γ = {}", sig(r.gamma.value(), 6))
        };
        response_figure(out, &what).save(path)?;
    }
    let stdout = std::io::stdout();
    if args.output.json {
        write_json(JsonOut::new(stdout.lock()), out)?;
    } else {
        let mut w = std::io::BufWriter::new(stdout.lock());
        print_table(&mut w, r, out)?;
        if let Some(path) = &args.output.csv {
            writeln!(
                w,
                "\nWrote t,u,z,dz,y ({} rows) to {}",
                out.len(),
                path.display()
            )?;
        }
        if let Some(path) = &args.plot.path {
            writeln!(w, "Drew y against t and y against u to {}", path.display())?;
        }
        w.flush()?;
    }
    Ok(())
}

/// `{"t": [...], "u": [...], "z": [...], "dz": [...], "y": [...]}`.
fn write_json<W: Write>(mut j: JsonOut<W>, out: &Trajectory) -> std::io::Result<()> {
    j.raw("{\"t\":")?;
    j.array(&out.t)?;
    j.raw(",\"u\":")?;
    j.array(&out.u)?;
    j.raw(",\"z\":")?;
    j.array(&out.z)?;
    j.raw(",\"dz\":")?;
    j.array(&out.dz)?;
    j.raw(",\"y\":")?;
    j.array(&out.y)?;
    j.raw("}\n")?;
    j.finish()
}

/// The input flag given (exactly one), with a description for the summary.
fn build_drive(args: &SimulateArgs) -> Result<(Drive, String)> {
    let mut given = args.input.given();
    if args.sine.is_some() {
        given.push("--sine");
    }
    if given.len() > 1 {
        bail!("give one input, not {}", given.join(" and "));
    }
    if let Some(text) = &args.sine {
        let v = parse_list("--sine", text)?;
        if !(2..=4).contains(&v.len()) {
            bail!(
                "--sine takes A,T[,PHASE[,OFFSET]] (2 to 4 numbers), got {}",
                v.len()
            );
        }
        let sine = Sine::new(
            v[0],
            v[1],
            v.get(2).copied().unwrap_or(0.0),
            v.get(3).copied().unwrap_or(0.0),
        )
        .map_err(|e| anyhow!("--sine: {e}"))?;
        let text = format!(
            "sine u(t) = {} sin(2 pi t / {} + {}) + {}",
            sig(sine.amplitude(), 10),
            sig(sine.period(), 10),
            sig(sine.phase(), 10),
            sig(sine.offset(), 10)
        );
        return Ok((Drive::Sine(sine), text));
    }
    if let Some(path) = &args.input.input {
        let series = crate::io::csv::read_series(path)?;
        let Some(t) = series.t else {
            bail!(
                "{}: simulate needs the samples' times: a header 't,u' and two columns (a single column 'u' has no time)",
                path.display()
            );
        };
        let n = t.len();
        let pl =
            PiecewiseLinear::new(t, series.u).map_err(|e| anyhow!("{}: {e}", path.display()))?;
        let text = format!(
            "{} samples from {}, linear between samples, t in [{}, {}]",
            n,
            path.display(),
            sig(pl.times()[0], 10),
            sig(pl.times()[n - 1], 10)
        );
        return Ok((Drive::Samples(pl), text));
    }
    if given.is_empty() {
        bail!("no input: give --turning-points U0,U1,..., --bimodal UMIN1,UMIN2,UMAX1,UMAX2, --input FILE.csv (t,u) or --sine A,T[,PHASE[,OFFSET]]");
    }
    let tp = args.input.build()?.turning_points();
    let pl = PiecewiseLinear::from_turning_points(&tp, 1.0)?;
    let values: Vec<String> = tp.values().iter().map(|&u| sig(u, 10)).collect();
    let text = format!(
        "turning points {} at unit speed (t = rho)",
        if values.len() > 8 {
            format!("{},... ({} in all)", values[..8].join(","), values.len())
        } else {
            values.join(",")
        }
    );
    Ok((Drive::TurningPoints(pl), text))
}

/// Points drawn per panel at most: beyond this, buckets of consecutive samples are reduced to
/// their first, lowest, highest and last points (in order), which keeps every peak and jump a
/// plot can show at its resolution.
const MAX_DRAWN_BUCKETS: usize = 20_000;

/// The response as two panels: y against t, and y against u.
fn response_figure(out: &Trajectory, what: &str) -> Panels {
    let keep = envelope_indices(&out.y, MAX_DRAWN_BUCKETS);
    let pick = |x: &[f64]| -> Vec<(f64, f64)> { keep.iter().map(|&i| (x[i], out.y[i])).collect() };
    let time = Figure::new("time t", "output y")
        .title(format!("y against t, {what}"))
        .curve(Curve::new(pick(&out.t), LineStyle::Solid, BLUE));
    let input = Figure::new("input u", "output y")
        .title(format!("y against u, {what}"))
        .curve(Curve::new(pick(&out.u), LineStyle::Solid, BLUE));
    Panels::side_by_side(time, input)
}

/// Indices of the samples to draw: all of them when there are at most `4 buckets`, else per
/// bucket of consecutive samples the first, the lowest, the highest and the last of `y`.
fn envelope_indices(y: &[f64], buckets: usize) -> Vec<usize> {
    let n = y.len();
    if n <= 4 * buckets {
        return (0..n).collect();
    }
    let size = n.div_ceil(buckets);
    let mut keep = Vec::with_capacity(4 * buckets);
    for start in (0..n).step_by(size) {
        let end = (start + size).min(n);
        let (mut lo, mut hi) = (start, start);
        for i in start..end {
            if y[i] < y[lo] {
                lo = i;
            }
            if y[i] > y[hi] {
                hi = i;
            }
        }
        let mut four = [start, lo, hi, end - 1];
        four.sort_unstable();
        for i in four {
            if keep.last() != Some(&i) {
                keep.push(i);
            }
        }
    }
    keep
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

fn check_rows(rows: usize) -> Result<()> {
    if rows > MAX_ROWS {
        bail!("the run would produce {rows} output rows (more than {MAX_ROWS}): lower --periods or --samples-per-period, or give --times");
    }
    Ok(())
}

fn write_csv(w: &mut dyn Write, out: &Trajectory) -> Result<()> {
    let mut rows = NumberRows::new();
    writeln!(w, "t,u,z,dz,y")?;
    for i in 0..out.len() {
        rows.write(w, &[out.t[i], out.u[i], out.z[i], out.dz[i], out.y[i]])?;
    }
    Ok(())
}

fn print_table(w: &mut impl Write, r: &Request, out: &Trajectory) -> Result<()> {
    print_summary(w, r)?;
    let n = out.len();
    if n == 0 {
        return Ok(());
    }
    let (imin, imax) = (0..n).fold((0, 0), |(lo, hi), i| {
        (
            if out.y[i] < out.y[lo] { i } else { lo },
            if out.y[i] > out.y[hi] { i } else { hi },
        )
    });
    writeln!(
        w,
        "{} rows, t from {} to {} (at a kink: the value just after it); y from {} (t = {}) to {} (t = {}); y at the end {}",
        n,
        sig(out.t[0], 10),
        sig(out.t[n - 1], 10),
        sig(out.y[imin], 10),
        sig(out.t[imin], 10),
        sig(out.y[imax], 10),
        sig(out.t[imax], 10),
        sig(out.y[n - 1], 10),
    )?;
    writeln!(
        w,
        "\n{:>16} {:>16} {:>16} {:>16} {:>16}",
        "t", "u", "z", "z'", "y"
    )?;
    for i in 0..n.min(TABLE_HEAD) {
        writeln!(
            w,
            "{:>16} {:>16} {:>16} {:>16} {:>16}",
            sig(out.t[i], 10),
            sig(out.u[i], 10),
            sig(out.z[i], 10),
            sig(out.dz[i], 10),
            sig(out.y[i], 10)
        )?;
    }
    if n > TABLE_HEAD {
        writeln!(
            w,
            "{:>16} ... {} more rows: use --json or --csv FILE to get all",
            "",
            n - TABLE_HEAD
        )?;
    }
    Ok(())
}

/// The model, the input, gamma, the periods, x0 and (for a sine) the tolerance.
fn print_summary(w: &mut impl Write, r: &Request) -> Result<()> {
    writeln!(w, "{}", r.choice.describe())?;
    writeln!(w, "Input: {}", r.input)?;
    let what = if r.gamma.is_infinite() {
        "gamma = inf: the rate-independent limit y*_u (eq. 6)".to_string()
    } else {
        format!("gamma = {} (eq. 5)", sig(r.gamma.value(), 10))
    };
    let adaptive = matches!(r.drive, Drive::Sine(_)) && !r.gamma.is_infinite();
    writeln!(
        w,
        "{what}; period T = {}; {} period{}; x0 = {}{}",
        sig(r.drive.period().1, 10),
        r.periods,
        if r.periods == 1 { "" } else { "s" },
        sig(r.x0, 10),
        if adaptive {
            format!("; adaptive integration to tol = {}", sig(r.tol.value(), 3))
        } else {
            String::new()
        }
    )?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_drawn_envelope_keeps_every_extreme_in_order() {
        let y: Vec<f64> = (0..100_000)
            .map(|i| ((i as f64) * 0.01).sin() + if i == 54_321 { 5.0 } else { 0.0 })
            .collect();
        let keep = envelope_indices(&y, 1000);
        assert!(keep.len() <= 4000 && keep.len() > 1000);
        assert!(keep.windows(2).all(|w| w[0] < w[1]));
        assert!(keep.contains(&54_321) && keep[0] == 0 && keep[keep.len() - 1] == 99_999);
        assert_eq!(
            envelope_indices(&y[..10], 1000),
            (0..10).collect::<Vec<_>>()
        );
    }
}
