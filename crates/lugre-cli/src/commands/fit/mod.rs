//! `lugre fit`: parameter identification from a measured record (`lugre::fit`).
//!
//! * `--fit slow` (default): `sigma0` and `g(0) = Fs` (Dahl: `rho`, `Fc`) from one or more
//!   periods of a slow periodic test, columns `u,F` (or `t,u,F`; `t` is then only checked);
//! * `--fit full`: `sigma0, sigma1, sigma2, Fc, Fs, vs` (`--free beta` adds `beta`) from
//!   rate-dependent data, columns `t,u,F`, on the exact simulation from `--x0`.
//!
//! Fixed parameters keep the values of the usual model flags (defaults: the paper's); a model
//! flag given for a free parameter is its start value (else the start comes from the data).
//! Everything is computed and checked before anything is printed or written.
//!
//! A fit that ran out of evaluations at a usable point (finite, every parameter identifiable)
//! is reported with a warning on stderr and exit status 0; every other failure, including a
//! parameter the data cannot determine, is one line and status 2.

use anyhow::{anyhow, bail, Result};
use clap::{Args, ValueEnum};
use indicatif::ProgressBar;
use lugre::fit::{
    fit_full, fit_full_smooth, fit_slow_with, FitError, FitKind, FitProgress, FitReport, FitSpec,
    FullOptions, Noise, SlowOptions, CUBIC_READING_TOL,
};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use crate::args::{check_files, normal_force_error, ModelArgs, OutputArgs, PlotArgs};
use crate::fmt::sig;
use crate::io::atomic::write_atomic;
use crate::io::json::JsonOut;
use crate::io::progress::{styled, Progress};
use crate::numbers::{parse_number, Real, Whole};
use crate::plot::Units;
use lugre::model::normal;
use lugre::simulate::SmoothSamples;
use lugre_io::{Reader, Role, Rows, Spec};

mod lab;
mod output;
mod spec;
mod zoo;

use output::{figure, print_table, write_csv, write_json};
use spec::{build_spec, explain};

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum FitChoice {
    /// The slow loop (rate-independent limit): sigma0 and g(0) = Fs (Dahl: rho, Fc).
    Slow,
    /// The exact simulation of rate-dependent data: sigma0, sigma1, sigma2, Fc, Fs, vs.
    Full,
    /// The steady-state friction of constant-velocity runs: Fc, Fs, vs, sigma2.
    Stribeck,
    /// A presliding test (small reversals below break-away): sigma0, sigma1.
    Presliding,
    /// The Stribeck and presliding fits in turn (--stribeck FILE --presliding FILE), then a
    /// full fit of --input FILE, if given, started from them.
    Staged,
}

/// The help of `--csv` for this command.
const CSV_HELP: &str =
    "Write the data with the fitted curve and the residuals ([t,]u,F,fit,residual) to \
    this CSV file";
/// The help of `--plot` for this command.
const PLOT_HELP: &str =
    "Draw the data and the fit in the (u, F) plane, and beside them the residuals against \
    time and against the input (the Stribeck fit: friction against velocity with the fitted \
    curve), to an SVG or PNG file; the axes carry the file's units (--units)";

#[derive(Args, Debug)]
#[command(
    mut_arg("csv", |a| a.help(CSV_HELP)),
    mut_arg("plot", |a| a.help(PLOT_HELP))
)]
pub(crate) struct FitArgs {
    #[command(flatten)]
    pub(crate) model: ModelArgs,
    /// The measured record: columns 'u,F' or 't,u,F' (header optional, in this order without
    /// one; '#' comments allowed), or a velocity record 't,v,F'. Times, when given, must be
    /// strictly increasing.
    #[arg(long, value_name = "FILE.csv", help_heading = "Input")]
    pub(crate) input: Option<PathBuf>,
    #[command(flatten)]
    pub(crate) data: crate::args::DataArgs,
    /// Full fit: how the record's displacement is read between samples: 'linear' (exact as
    /// given) or 'cubic' (samples of a smooth motion: the C1 shape-preserving cubic, solved on
    /// a subdivision to 1e-9 of its range; the residual stays at the samples). A velocity
    /// record (t,v,F: a column 'v' or 'velocity', or --columns v=NAME) is integrated from
    /// u = 0 and always read this way.
    #[arg(long, value_enum, default_value = "linear", help_heading = "Data file")]
    pub(crate) interpolate: crate::args::Interpolate,
    /// Which fit: 'slow' (one or more periods of a slow periodic test) or 'full'
    /// (rate-dependent t,u,F data, exact simulation).
    #[arg(long, value_enum, default_value = "slow", help_heading = "Fit")]
    pub(crate) fit: FitChoice,
    /// Staged fit: the constant-velocity runs of the Stribeck stage (a record t,u,F or a
    /// table v,F, as --fit stribeck reads --input).
    #[arg(long, value_name = "FILE.csv", help_heading = "Fit")]
    pub(crate) stribeck: Option<PathBuf>,
    /// Staged fit: the presliding test t,u,F of the presliding stage (as --fit presliding reads
    /// --input).
    #[arg(long, value_name = "FILE.csv", help_heading = "Fit")]
    pub(crate) presliding: Option<PathBuf>,
    /// Parameters held, each at a value given with it or by its model flag (e.g.
    /// --fix sigma2=0.05,fs=1.5, or --fix sigma2 --sigma2 0.05).
    #[arg(long, value_name = "NAME[=VALUE],...", help_heading = "Fit")]
    pub(crate) fix: Option<String>,
    /// Parameters fitted besides the default ones (e.g. --free beta in a full fit).
    #[arg(long, value_name = "NAME,...", help_heading = "Fit")]
    pub(crate) free: Option<String>,
    /// Bounds on fitted parameters, 0 <= LO < HI (HI may be 'inf'); default (0, inf).
    #[arg(
        long,
        value_name = "NAME=LO:HI,...",
        allow_hyphen_values = true,
        help_heading = "Fit"
    )]
    pub(crate) bounds: Option<String>,
    /// Full fit: the initial state x0 = x(0) of eq. 1 (not fitted; default 0).
    #[arg(
        long,
        value_name = "X",
        allow_hyphen_values = true,
        help_heading = "Fit"
    )]
    pub(crate) x0: Option<String>,
    /// Full fit: the number of starts (the first from the data, then sigma0 and vs scaled by 4
    /// or 1/4; default 3).
    #[arg(
        long,
        value_name = "N",
        allow_hyphen_values = true,
        value_parser = Whole(1),
        help_heading = "Fit"
    )]
    pub(crate) starts: Option<usize>,
    /// Noise in the record: 'auto' (default) estimates the position and force noise from the
    /// samples (third differences) and, in a full fit, reads an equally spaced noisy
    /// displacement as the smooth motion nearest the samples; 'off' takes the samples as exact.
    #[arg(long, value_name = "auto|off", value_parser = parse_noise, help_heading = "Fit")]
    pub(crate) noise: Option<Noise>,
    /// Slow fit: the noise gate on the reversals, in units of u (after --scale): a turn counts
    /// once the input has come back from its extreme by at least H, so that noise makes no
    /// reversals (0: every turn counts). Default: 8 times the position noise estimated in the
    /// record (0 with --noise off).
    #[arg(
        long,
        value_name = "H",
        allow_hyphen_values = true,
        value_parser = Real,
        help_heading = "Fit"
    )]
    pub(crate) gate: Option<f64>,
    #[arg(
        long,
        value_name = "N",
        allow_hyphen_values = true,
        value_parser = Whole(1),
        help_heading = "Fit",
        help = elements_help()
    )]
    pub(crate) elements: Option<usize>,
    #[command(flatten)]
    pub(crate) output: OutputArgs,
    #[command(flatten)]
    pub(crate) plot: PlotArgs,
}

/// `--elements`'s help, with the core's default and limit.
fn elements_help() -> String {
    format!(
        "An element model of the zoo (maxwell-slip, prandtl-ishlinskii): the number of elements, their thresholds held on a grid spanning the record's amplitude (default {}, at most {}; the model's flags give them instead: --thresholds, or --slip-force with --stiffness)",
        lugre::fit::DEFAULT_ELEMENTS,
        lugre::fit::MAX_ELEMENTS
    )
}

/// `--noise`: one of the core's names.
fn parse_noise(text: &str) -> Result<Noise, String> {
    Noise::from_name(text).ok_or_else(|| {
        format!(
            "expected one of {}, got {}",
            Noise::NAMES.join(", "),
            crate::fmt::quoted(&crate::fmt::excerpt(text))
        )
    })
}

/// The measured record.
struct Record {
    t: Option<Vec<f64>>,
    u: Vec<f64>,
    f: Vec<f64>,
    /// A velocity record: the motion integrated from its samples (`u` holds it at the
    /// samples).
    velocity: Option<SmoothSamples>,
    /// The normal force at each sample, when the record has one: `f` then holds the friction
    /// coefficient `F / N`.
    normal: Option<Vec<f64>>,
    /// The units of the file's header (for the figure's labels).
    units: Units,
}

impl Record {
    /// The times, which a full fit needs (`path` names the file in the error).
    fn times_for_full_fit(&self, path: &Path) -> Result<&[f64]> {
        match &self.t {
            Some(t) => Ok(t),
            None => bail!(
                "{}: a full fit needs the samples' times: columns t,u,F (this file has u,F)",
                path.display()
            ),
        }
    }
}

/// The request: the flags and the record, each checked in turn before the fit runs.
struct Request<'a> {
    path: &'a Path,
    spec: FitSpec,
    record: Record,
    /// The full fit's `x0` and number of starts; `None` for the slow fit.
    full: Option<(f64, usize)>,
    /// The full fit's reading of the displacement between samples.
    cubic: bool,
    noise: Noise,
    gate: Option<f64>,
}

impl FitChoice {
    /// The core's kind of fit.
    fn kind(self) -> FitKind {
        match self {
            FitChoice::Slow => FitKind::Slow,
            FitChoice::Full => FitKind::Full,
            FitChoice::Stribeck => FitKind::Stribeck,
            FitChoice::Presliding => FitKind::Presliding,
            FitChoice::Staged => FitKind::Staged,
        }
    }
}

pub(crate) fn run(args: &FitArgs) -> Result<()> {
    if let Some(model) = args.model.model.zoo() {
        return zoo::run(args, model);
    }
    if args.elements.is_some() {
        bail!(
            "--elements applies to an element model of the zoo (--model maxwell-slip or prandtl-ishlinskii)"
        );
    }
    if args.fit != FitChoice::Staged {
        for (flag, given) in [
            ("--stribeck", args.stribeck.is_some()),
            ("--presliding", args.presliding.is_some()),
        ] {
            if given {
                bail!(
                    "{flag} gives a record of the staged fit (--fit staged); --fit {} reads --input",
                    args.fit.kind().label()
                );
            }
        }
    }
    if matches!(
        args.fit,
        FitChoice::Stribeck | FitChoice::Presliding | FitChoice::Staged
    ) {
        return lab::run(args);
    }
    check_files(args.input.as_deref(), &args.output, Some(&args.plot))?;
    let request = parse(args)?;
    let report = compute(&request)?;
    report_fit(args, request.path, &request.record, &report)
}

fn parse(args: &FitArgs) -> Result<Request<'_>> {
    let Some(path) = &args.input else {
        bail!("no data: give --input FILE.csv (columns u,F or t,u,F)");
    };
    let spec = build_spec(args)?;
    let kind = args.fit.kind();
    if kind == FitKind::Slow {
        if args.x0.is_some() {
            bail!("--x0 applies to the full fit (add --fit full)");
        }
        if args.starts.is_some() {
            bail!("--starts applies to the full fit (add --fit full)");
        }
    } else if args.gate.is_some() {
        bail!("--gate applies to the slow fit (the full fit simulates every turn of the input)");
    }
    if let Some(plot) = &args.plot.path {
        crate::plot::check_path(plot)?;
    }
    // A row without a force (empty or NaN) is an input-only sample of the full fit.
    // A velocity record is always read as a smooth motion (as `lugre simulate` reads it).
    let mut record = read_record(args, path)?;
    if let Some(n) = &record.normal {
        // The core's scaling (the reader checked N > 0 at every line already).
        normal::to_coefficient(&mut record.f, n).map_err(|e| normal_force_error(path, e))?;
    }
    if let Some(i) = record.f.iter().position(|f| f.is_nan()) {
        if kind == FitKind::Slow {
            bail!(
                "{}: row {} has no force: the slow fit needs one at every row (input-only rows are for the full fit, --fit full with times)",
                path.display(),
                i + 1
            );
        }
        if record.f.iter().all(|f| f.is_nan()) {
            bail!(
                "{}: no row has a force (F is empty everywhere)",
                path.display()
            );
        }
    }
    let full = match kind {
        FitKind::Slow => None,
        _ => {
            // Checked here, in its turn; `compute` takes the times again.
            record.times_for_full_fit(path)?;
            let x0 = match &args.x0 {
                Some(text) => parse_number("--x0", 1, text)?,
                None => 0.0,
            };
            Some((x0, args.starts.unwrap_or(FullOptions::DEFAULT_STARTS)))
        }
    };
    let cubic = args.interpolate == crate::args::Interpolate::Cubic;
    if cubic && full.is_none() && record.velocity.is_none() {
        bail!("--interpolate cubic applies to the full fit (--fit full): the slow loop depends on the turning points alone");
    }
    Ok(Request {
        path,
        spec,
        record,
        full,
        cubic,
        noise: args.noise.unwrap_or_default(),
        gate: args.gate,
    })
}

/// The fit, with a progress indicator for a long full fit.
fn compute(r: &Request) -> Result<FitReport> {
    let record = &r.record;
    let with_file = |e: FitError| -> anyhow::Error {
        match e {
            FitError::TooFewSamples { .. }
            | FitError::NoReversal { .. }
            | FitError::ZeroForce
            | FitError::LengthMismatch { .. }
            | FitError::Data(_) => anyhow!("{}: {e}", r.path.display()),
            other => explain(other),
        }
    };
    Ok(match &r.full {
        // Times, if any, were checked when read; the slow loop depends on the turning points
        // alone.
        None => {
            let mut options = SlowOptions::default().with_noise(r.noise);
            if let Some(gate) = r.gate {
                options = options.with_gate(gate);
            }
            fit_slow_with(&r.spec, &record.u, &record.f, options).map_err(|e| match e {
                FitError::BadGate { .. } => anyhow!("--gate: {e}"),
                other => with_file(other),
            })?
        }
        Some((x0, starts)) => {
            let t = record.times_for_full_fit(r.path)?;
            let mut progress = FitProgressBar::new();
            let mut report = |p: &FitProgress| progress.update(p);
            let options = FullOptions::default()
                .with_x0(*x0)
                .with_starts(*starts)
                .with_noise(r.noise)
                .with_progress(&mut report);
            let result = if let Some(motion) = &record.velocity {
                fit_full_smooth(&r.spec, motion, &record.f, options).map_err(with_file)
            } else if r.cubic {
                SmoothSamples::pchip(t.to_vec(), record.u.clone(), CUBIC_READING_TOL)
                    .map_err(FitError::from)
                    .and_then(|motion| fit_full_smooth(&r.spec, &motion, &record.f, options))
                    .map_err(with_file)
            } else {
                fit_full(&r.spec, t, &record.u, &record.f, options).map_err(with_file)
            };
            progress.finish();
            result?
        }
    })
}

/// Writes the CSV and the figure asked for, warns of a fit that did not converge, then prints
/// the JSON document or the table.
fn report_fit(args: &FitArgs, path: &Path, record: &Record, report: &FitReport) -> Result<()> {
    let normal = record.normal.is_some();
    let residuals = report.residuals(&record.f);
    if let Some(csv) = &args.output.csv {
        write_atomic(csv, |w| write_csv(w, record, &report.fitted, &residuals))?;
    }
    if let Some(plot) = &args.plot.path {
        let units = record.units.clone().with_flag(args.plot.units.as_deref())?;
        figure(record, report, &residuals, &units).save(plot)?;
    }
    warn_unconverged(report);
    let stdout = std::io::stdout();
    if args.output.json {
        write_json(JsonOut::new(stdout.lock()), report, path, normal)?;
    } else {
        let mut out = std::io::BufWriter::new(stdout.lock());
        print_table(&mut out, report, path, normal)?;
        output::print_written(&mut out, args, record.t.is_some())?;
        out.flush()?;
    }
    Ok(())
}

/// Warns on stderr of a fit that ran out of evaluations (its best point is reported).
fn warn_unconverged(report: &FitReport) {
    if !report.converged {
        let _ = writeln!(
            std::io::stderr(),
            "lugre: warning: the {} fit did not converge ({}); the best point found is reported",
            report.kind.label(),
            report.termination
        );
    }
}

/// Reads the record: `u,F` or `t,u,F` (the columns of those roles in any header, others
/// ignored; without a header, in this order), or a velocity record `t,v,F` (a header with `v`
/// and no `u`, or `--columns v=NAME`: integrated from `u = 0` at the first sample, the C1 cubic
/// reading of the motion subdivided to `CUBIC_READING_TOL`), with the normal force `N` when
/// `--columns` names it (never inferred from a header: a file that records its load would
/// otherwise change what the parameters mean). A force may be missing (empty or `NaN`): an
/// input-only row of the full fit.
fn read_record(args: &FitArgs, path: &Path) -> Result<Record> {
    let options = args.data.options(&[Role::U, Role::V, Role::F, Role::N])?;
    let reader = Reader::open(path, options.clone())?;
    let motion = reader.motion();
    let velocity = motion == Role::V;
    let normal = options.selects(&Role::N);
    let mut roles = vec![motion.clone(), Role::F];
    if normal {
        roles.push(Role::N);
    }
    let mut spec = Spec::new(roles).allow_missing(Role::F).positive(Role::N);
    if velocity {
        spec = spec.require_time();
    }
    let mut table = reader
        .rows(&spec)
        .and_then(Rows::collect_table)
        .map_err(|e| e.in_file(path))?;
    let units = Units::of_file(&table, &options);
    let (u, f, normal) = (
        table.take(&motion).unwrap_or_default(),
        table.take(&Role::F).unwrap_or_default(),
        table.take(&Role::N),
    );
    let t = table.take(&Role::T);
    if !velocity {
        return Ok(Record {
            t,
            u,
            f,
            velocity: None,
            normal,
            units,
        });
    }
    let t = t.unwrap_or_default(); // required above
    let motion = SmoothSamples::from_velocity(t.clone(), u, 0.0, CUBIC_READING_TOL)
        .map_err(|e| anyhow!("{}: {e}", path.display()))?;
    Ok(Record {
        t: Some(t),
        u: motion.samples().1.to_vec(),
        f,
        velocity: Some(motion),
        normal,
        units,
    })
}

/// A spinner on stderr for the full fit (see [`Progress`]), redrawn at most 20 times a second.
struct FitProgressBar {
    progress: Progress,
    last: Instant,
}

impl FitProgressBar {
    fn new() -> Self {
        Self {
            progress: Progress::new(),
            last: Instant::now(),
        }
    }

    fn update(&mut self, p: &FitProgress) {
        if !self.progress.is_terminal() {
            return;
        }
        let now = Instant::now();
        // The callback comes after every evaluation: redraw at most 20 times a second.
        if now.duration_since(self.last) < Duration::from_millis(50) {
            return;
        }
        self.last = now;
        // Elapsed from the start of the fit, not from when the spinner appears.
        let bar = self.progress.bar(|elapsed| {
            styled(
                ProgressBar::new_spinner().with_elapsed(elapsed),
                "{spinner} fitting: {msg} ({elapsed})",
            )
        });
        if let Some(bar) = bar {
            bar.set_message(format!(
                "start {}/{}, {} evaluations, residual RMS {}",
                p.start,
                p.starts,
                p.evaluations,
                sig(p.rms, 4)
            ));
            bar.tick();
        }
    }

    fn finish(&mut self) {
        self.progress.finish();
    }
}
