//! `lugre fit --fit stribeck|presliding|staged`: the lab's experiments (`lugre::fit`).
//!
//! * `--fit stribeck --input FILE`: `Fc, Fs, vs, sigma2` (`--free beta` adds `beta`) from the
//!   steady-state friction of constant-velocity runs: a record `t,u,F` (or `t,v,F`) whose
//!   runs are found without help (a header with `t`, or three columns), or a table `v,F` (one
//!   row a run: its velocity and steady force; a header `v,F`, or two columns); `--csv` writes
//!   the points with the fitted curve and `--plot` draws friction against velocity;
//! * `--fit presliding --input FILE`: `sigma0`, `sigma1` from a presliding test `t,u,F`, the
//!   Stribeck curve held at the model flags' values (`--fc --fs --vs --beta --sigma2`);
//! * `--fit staged --stribeck FILE --presliding FILE [--input FILE]`: the two in turn, the
//!   second holding the first's curve, then, with `--input`, a full fit of that rate-dependent
//!   record `t,u,F` started from them. The data flags (`--columns`, `--scale`, `--delimiter`)
//!   apply to every file.
//!
//! Each parameter is reported with its 95 % interval and the stage that determined it.

use anyhow::{anyhow, bail, Result};
use lugre::fit::{
    find_plateaus, fit_presliding, fit_stribeck, table_points, FitError, FitReport, FitSpec,
    Motion, Plateaus, SteadyPoint,
};
use std::io::Write;
use std::path::Path;

use super::spec::{build_spec, explain};
use super::{FitArgs, FitChoice, Record};
use crate::args::Interpolate;
use crate::fmt::sig;
use crate::io::atomic::write_atomic;
use crate::io::csv::NumberRows;
use crate::io::outputs::Files;
use lugre_io::{Reader, Role, Rows, Spec};

mod staged;
mod steady_plot;

/// The constant-velocity data: the points fitted.
pub(super) struct Steady {
    pub(super) points: Vec<SteadyPoint>,
    /// The plateaus found in a record, and its times.
    pub(super) plateaus: Option<(Plateaus, Vec<f64>)>,
}

pub(super) fn run(args: &FitArgs) -> Result<()> {
    Files::new()
        .input("--input", args.input.as_deref())
        .input("--stribeck", args.stribeck.as_deref())
        .input("--presliding", args.presliding.as_deref())
        .output("--csv", args.output.csv.as_deref())
        .output("--plot", args.plot.path.as_deref())
        .check()?;
    refuse_flags(args)?;
    if let Some(plot) = &args.plot.path {
        crate::plot::check_path(plot)?;
    }
    let spec = build_spec(args)?;
    match args.fit {
        FitChoice::Stribeck => {
            let path = input(
                args,
                "constant-velocity runs: a record t,u,F or a table v,F",
            )?;
            let steady = read_steady(args, path)?;
            let report = stribeck(&spec, &steady, path)?;
            report_stribeck(args, path, &spec, &steady, &report)
        }
        FitChoice::Presliding => {
            let path = input(args, "a presliding test: t,u,F")?;
            let (t, record) = read_timed(args, path)?;
            let report =
                fit_presliding(&spec, &t, &record.u, &record.f).map_err(|e| in_file(e, path))?;
            super::report_fit(args, path, &record, &report)
        }
        _ => staged::run(args, &spec),
    }
}

/// A record `t,u,F` (or `t,v,F`) with its times, which the presliding and full fits need.
pub(super) fn read_timed(args: &FitArgs, path: &Path) -> Result<(Vec<f64>, Record)> {
    let record = super::read_record(args, path)?;
    let Some(t) = record.t.clone() else {
        bail!(
            "{}: the {} fit needs the samples' times: columns t,u,F (this file has u,F)",
            path.display(),
            args.fit.kind().label()
        );
    };
    if let Some(i) = record.f.iter().position(|f| f.is_nan()) {
        bail!("{}: row {} has no force", path.display(), i + 1);
    }
    Ok((t, record))
}

/// A core error about the data, prefixed with the file; others explained with the flags.
pub(super) fn in_file(e: FitError, path: &Path) -> anyhow::Error {
    match e {
        FitError::TooFewSamples { .. }
        | FitError::NoReversal { .. }
        | FitError::ZeroForce
        | FitError::LengthMismatch { .. }
        | FitError::Data(_)
        | FitError::BreaksAway { .. }
        | FitError::Slides { .. }
        | FitError::NoiseAboveSignal { .. } => anyhow!("{}: {e}", path.display()),
        other => explain(other),
    }
}

/// `--input`, which the fit needs (`what`: what it holds).
fn input<'a>(args: &'a FitArgs, what: &str) -> Result<&'a Path> {
    args.input
        .as_deref()
        .ok_or_else(|| anyhow!("no data: give --input FILE.csv ({what})"))
}

/// Flags of the other fits.
fn refuse_flags(args: &FitArgs) -> Result<()> {
    let fit = args.fit.kind().label();
    if args.x0.is_some() {
        bail!("--x0 applies to the full fit, not to --fit {fit}");
    }
    if args.starts.is_some() {
        bail!("--starts applies to the full fit, not to --fit {fit}");
    }
    if args.interpolate == Interpolate::Cubic {
        bail!("--interpolate cubic applies to the full fit, not to --fit {fit}");
    }
    if args.data.selects(Role::N) {
        bail!("--columns N=...: the normal force is read by the slow and full fits only, not by --fit {fit}");
    }
    Ok(())
}

/// The steady-state points: of a table `v,F` (a header with `v` and no `t`, or two columns
/// without a header), or found in a record `t,u,F` / `t,v,F` (a header with `t`, or three
/// columns without one) by [`find_plateaus`].
pub(super) fn read_steady(args: &FitArgs, path: &Path) -> Result<Steady> {
    let options = args.data.options(&[Role::U, Role::V, Role::F])?;
    let reader = Reader::open(path, options.clone())?;
    let timed = if reader.header().is_some() || options.selects_any() {
        reader.header_has(&Role::T) || options.selects(&Role::T)
    } else {
        reader.width() >= 3
    };
    let motion = if timed { reader.motion() } else { Role::V };
    let mut spec = Spec::new([motion.clone(), Role::F]);
    if timed {
        spec = spec.require_time();
    }
    let mut table = reader
        .rows(&spec)
        .and_then(Rows::collect_table)
        .map_err(|e| e.in_file(path))?;
    let (x, f) = (
        table.take(&motion).unwrap_or_default(),
        table.take(&Role::F).unwrap_or_default(),
    );
    if !timed {
        let points = table_points(&x, &f).map_err(|e| anyhow!("{}: {e}", path.display()))?;
        return Ok(Steady {
            points,
            plateaus: None,
        });
    }
    let t = table.take(&Role::T).unwrap_or_default();
    let kind = if motion == Role::V {
        Motion::Velocity
    } else {
        Motion::Displacement
    };
    let found = find_plateaus(&t, &x, &f, kind).map_err(|e| anyhow!("{}: {e}", path.display()))?;
    Ok(Steady {
        points: found.points(),
        plateaus: Some((found, t)),
    })
}

/// The Stribeck fit, its errors in terms of the file and the flags.
pub(super) fn stribeck(spec: &FitSpec, steady: &Steady, path: &Path) -> Result<FitReport> {
    fit_stribeck(spec, &steady.points).map_err(|e| match e {
        FitError::TooFewPlateaus { .. }
        | FitError::BadSteadyVelocity { .. }
        | FitError::BadSteadyError { .. }
        | FitError::BadSteadyForce { .. } => anyhow!("{}: {e}", path.display()),
        other => explain(other),
    })
}

fn report_stribeck(
    args: &FitArgs,
    path: &Path,
    spec: &FitSpec,
    steady: &Steady,
    r: &FitReport,
) -> Result<()> {
    if let Some(csv) = &args.output.csv {
        write_atomic(csv, |w| write_steady_csv(w, steady, r))?;
    }
    if let Some(plot) = &args.plot.path {
        steady_plot::figure(steady, r, spec).save(plot)?;
    }
    super::warn_unconverged(r);
    let stdout = std::io::stdout();
    if args.output.json {
        let mut doc = super::output::json_value(r, path, false)?;
        doc["points"] = points_json(steady, r);
        if let Some((found, t)) = &steady.plateaus {
            doc["plateaus"] = plateaus_json(found, t);
        }
        let mut out = stdout.lock();
        serde_json::to_writer(&mut out, &doc)?;
        writeln!(out)?;
        return Ok(());
    }
    let mut out = std::io::BufWriter::new(stdout.lock());
    if let Some((found, _)) = &steady.plateaus {
        writeln!(
            out,
            "{} constant-velocity runs found in {}{} (velocity noise {}); each point is the mean force over the run's steady part, weighted by its standard error",
            found.plateaus.len(),
            path.display(),
            match found.skipped {
                0 => String::new(),
                n => format!(", {n} more skipped: their transient filled them"),
            },
            sig(found.velocity_noise, 3)
        )?;
    }
    super::output::print_table(&mut out, r, path, false)?;
    if let Some(csv) = &args.output.csv {
        writeln!(
            out,
            "\nWrote the points and the fitted curve (v,F,stderr,fit,residual) to {}",
            csv.display()
        )?;
    }
    if let Some(plot) = &args.plot.path {
        writeln!(
            out,
            "Drew friction against velocity, the points and the fitted curve, to {}",
            plot.display()
        )?;
    }
    out.flush()?;
    Ok(())
}

/// `[{"v", "F", "stderr", "fit"}, ...]` (`stderr` null without one).
pub(super) fn points_json(steady: &Steady, r: &FitReport) -> serde_json::Value {
    steady
        .points
        .iter()
        .zip(&r.fitted)
        .map(|(p, fit)| {
            serde_json::json!({
                "v": p.v,
                "F": p.f,
                "stderr": p.stderr,
                "fit": fit,
            })
        })
        .collect()
}

/// `{"runs", "skipped", "velocity_noise", "runs": [{"v", "F", "stderr", "sd", "samples",
/// "t_start", "t_end"}]}`: the steady part of each run.
fn plateaus_json(found: &Plateaus, t: &[f64]) -> serde_json::Value {
    let runs: Vec<serde_json::Value> = found
        .plateaus
        .iter()
        .map(|p| {
            serde_json::json!({
                "v": p.v,
                "F": p.f,
                "stderr": p.stderr,
                "sd": p.f_sd,
                "samples": p.steady.1 - p.steady.0,
                "t_start": t[p.steady.0],
                "t_end": t[p.steady.1 - 1],
            })
        })
        .collect();
    serde_json::json!({
        "skipped": found.skipped,
        "velocity_noise": found.velocity_noise,
        "runs": runs,
    })
}

pub(super) fn write_steady_csv(w: &mut dyn Write, steady: &Steady, r: &FitReport) -> Result<()> {
    let mut rows = NumberRows::new();
    writeln!(w, "v,F,stderr,fit,residual")?;
    for (p, &fit) in steady.points.iter().zip(&r.fitted) {
        match p.stderr {
            Some(e) => rows.write(w, &[p.v, p.f, e, fit, p.f - fit])?,
            None => {
                let mut text = Vec::new();
                rows.write(&mut text, &[p.v, p.f])?;
                let head = String::from_utf8_lossy(&text);
                let mut tail = Vec::new();
                rows.write(&mut tail, &[fit, p.f - fit])?;
                write!(w, "{},,{}", head.trim_end(), String::from_utf8_lossy(&tail))?;
            }
        }
    }
    Ok(())
}
