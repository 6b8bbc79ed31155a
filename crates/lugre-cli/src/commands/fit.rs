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
    fit_full, fit_slow, Family, FitError, FitKind, FitProgress, FitReport, FitSpec, FullOptions,
};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use crate::args::{ModelArgs, ModelKind, OutputArgs, PlotArgs};
use crate::fmt::{excerpt, quoted, sig};
use crate::io::atomic::write_atomic;
use crate::io::csv::NumberRows;
use crate::io::csv::{read_table, Columns};
use crate::io::json::JsonOut;
use crate::io::progress::{styled, Progress};
use crate::numbers::{parse_number, Whole};
use crate::plot::{Curve, Figure, LineStyle, Panels, BLACK, BLUE, RED};

/// Vertical strokes in the residual figure (at most).
const RESIDUAL_BINS: usize = 600;

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum FitChoice {
    /// The slow loop (rate-independent limit): sigma0 and g(0) = Fs (Dahl: rho, Fc).
    Slow,
    /// The exact simulation of rate-dependent data: sigma0, sigma1, sigma2, Fc, Fs, vs.
    Full,
}

/// The help of `--csv` for this command.
const CSV_HELP: &str =
    "Write the data with the fitted curve and the residuals ([t,]u,F,fit,residual) to \
    this CSV file";
/// The help of `--plot` for this command.
const PLOT_HELP: &str =
    "Draw the data and the fit in the (u, F) plane, and beside them the residuals, to \
    an SVG or PNG file";

#[derive(Args, Debug)]
#[command(
    mut_arg("csv", |a| a.help(CSV_HELP)),
    mut_arg("plot", |a| a.help(PLOT_HELP))
)]
pub(crate) struct FitArgs {
    #[command(flatten)]
    pub(crate) model: ModelArgs,
    /// The measured record: columns 'u,F' or 't,u,F' (header optional, in this order without
    /// one; '#' comments allowed). Times, when given, must be strictly increasing.
    #[arg(long, value_name = "FILE.csv", help_heading = "Input")]
    pub(crate) input: Option<PathBuf>,
    /// Which fit: 'slow' (one or more periods of a slow periodic test) or 'full'
    /// (rate-dependent t,u,F data, exact simulation).
    #[arg(long, value_enum, default_value = "slow", help_heading = "Fit")]
    pub(crate) fit: FitChoice,
    /// Parameters held at the model flags' values (e.g. --fix sigma2,fs).
    #[arg(long, value_name = "NAME,...", help_heading = "Fit")]
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
    #[command(flatten)]
    pub(crate) output: OutputArgs,
    #[command(flatten)]
    pub(crate) plot: PlotArgs,
}

/// The measured record.
struct Record {
    t: Option<Vec<f64>>,
    u: Vec<f64>,
    f: Vec<f64>,
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
    /// The full fit's options; `None` for the slow fit.
    full: Option<FullOptions>,
}

pub(crate) fn run(args: &FitArgs) -> Result<()> {
    let request = parse(args)?;
    let report = compute(&request)?;
    report_fit(args, &request, &report)
}

fn parse(args: &FitArgs) -> Result<Request<'_>> {
    let Some(path) = &args.input else {
        bail!("no data: give --input FILE.csv (columns u,F or t,u,F)");
    };
    let spec = build_spec(args)?;
    let kind = match args.fit {
        FitChoice::Slow => FitKind::Slow,
        FitChoice::Full => FitKind::Full,
    };
    if kind == FitKind::Slow {
        if args.x0.is_some() {
            bail!("--x0 applies to the full fit (add --fit full)");
        }
        if args.starts.is_some() {
            bail!("--starts applies to the full fit (add --fit full)");
        }
    }
    if let Some(plot) = &args.plot.path {
        crate::plot::check_path(plot)?;
    }
    let record = read_record(path)?;
    let full = match kind {
        FitKind::Slow => None,
        FitKind::Full => {
            // Checked here, in its turn; `compute` takes the times again.
            record.times_for_full_fit(path)?;
            let x0 = match &args.x0 {
                Some(text) => parse_number("--x0", 1, text)?,
                None => 0.0,
            };
            Some(FullOptions {
                x0,
                starts: args.starts.unwrap_or(FullOptions::default().starts),
            })
        }
    };
    Ok(Request {
        path,
        spec,
        record,
        full,
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
            | FitError::NotFinite { .. }
            | FitError::TimesNotIncreasing { .. } => anyhow!("{}: {e}", r.path.display()),
            other => explain(other),
        }
    };
    Ok(match &r.full {
        // Times, if any, were checked when read; the slow loop depends on the turning points
        // alone.
        None => fit_slow(&r.spec, &record.u, &record.f).map_err(with_file)?,
        Some(options) => {
            let t = record.times_for_full_fit(r.path)?;
            let mut progress = FitProgressBar::new();
            let result = fit_full(&r.spec, t, &record.u, &record.f, options, &mut |p| {
                progress.update(p)
            });
            progress.finish();
            result.map_err(with_file)?
        }
    })
}

/// Writes the CSV and the figure asked for, warns of a fit that did not converge, then prints
/// the JSON document or the table.
fn report_fit(args: &FitArgs, r: &Request, report: &FitReport) -> Result<()> {
    let record = &r.record;
    let residuals = report.residuals(&record.f);
    if let Some(csv) = &args.output.csv {
        write_atomic(csv, |w| write_csv(w, record, report, &residuals))?;
    }
    if let Some(plot) = &args.plot.path {
        figure(record, report, &residuals).save(plot)?;
    }
    if !report.converged {
        let _ = writeln!(
            std::io::stderr(),
            "lugre: warning: the fit did not converge ({}); the best point found is reported",
            report.termination
        );
    }
    let stdout = std::io::stdout();
    if args.output.json {
        write_json(JsonOut::new(stdout.lock()), report, r.path)?;
    } else {
        let mut out = std::io::BufWriter::new(stdout.lock());
        print_table(&mut out, report, r.path)?;
        if let Some(csv) = &args.output.csv {
            writeln!(
                out,
                "\nWrote the data, fit and residuals ({}u,F,fit,residual) to {}",
                if record.t.is_some() { "t," } else { "" },
                csv.display()
            )?;
        }
        if let Some(plot) = &args.plot.path {
            writeln!(
                out,
                "Drew the data, the fit and the residuals to {}",
                plot.display()
            )?;
        }
        out.flush()?;
    }
    Ok(())
}

/// The request from the flags: family, given values, fixed and freed names, bounds.
fn build_spec(args: &FitArgs) -> Result<FitSpec> {
    // The same checks as every command (flags of the other model, invalid values).
    args.model.build()?;
    let m = &args.model;
    let (family, given): (Family, Vec<(&str, Option<f64>)>) = match m.model {
        ModelKind::Lugre => (
            Family::LuGre,
            vec![
                ("sigma0", m.sigma0),
                ("sigma1", m.sigma1),
                ("sigma2", m.sigma2),
                ("fc", m.fc),
                ("fs", m.fs),
                ("vs", m.vs),
                ("beta", m.beta),
            ],
        ),
        ModelKind::Dahl => (Family::Dahl, vec![("rho", m.rho), ("fc", m.fc)]),
    };
    let mut spec = FitSpec::new(family);
    for (name, value) in given {
        if let Some(v) = value {
            spec = spec.set(name, v).map_err(explain)?;
        }
    }
    for name in names("--fix", args.fix.as_deref())? {
        spec = spec
            .fix(name)
            .map_err(|e| anyhow!("--fix: {}", short_name(e)))?;
    }
    for name in names("--free", args.free.as_deref())? {
        spec = spec
            .free(name)
            .map_err(|e| anyhow!("--free: {}", short_name(e)))?;
    }
    if let Some(text) = &args.bounds {
        for item in text.split(',') {
            let Some((name, range)) = item.split_once('=') else {
                bail!("--bounds: {} is not NAME=LO:HI", quoted(item.trim()));
            };
            let Some((lo, hi)) = range.split_once(':') else {
                bail!("--bounds: {} is not NAME=LO:HI", quoted(item.trim()));
            };
            let lo = parse_number("--bounds", 1, lo)?;
            let hi = match hi.trim().to_ascii_lowercase().as_str() {
                "inf" | "+inf" | "infinity" => f64::INFINITY,
                _ => parse_number("--bounds", 2, hi)?,
            };
            spec = spec
                .bounds(name, lo, hi)
                .map_err(|e| anyhow!("--bounds: {}", short_name(e)))?;
        }
    }
    Ok(spec)
}

/// `e` with an unknown parameter's name cut short: it is the user's text, of any length.
fn short_name(e: FitError) -> FitError {
    match e {
        FitError::UnknownParameter { name, model, known } => FitError::UnknownParameter {
            name: excerpt(&name),
            model,
            known,
        },
        other => other,
    }
}

/// The names of a comma-separated list (none for an absent flag).
fn names<'a>(flag: &str, text: Option<&'a str>) -> Result<Vec<&'a str>> {
    let Some(text) = text else {
        return Ok(Vec::new());
    };
    let items: Vec<&str> = text.split(',').map(str::trim).collect();
    if items.iter().any(|s| s.is_empty()) {
        bail!(
            "{flag}: empty name in {} (expected names separated by commas)",
            quoted(text)
        );
    }
    Ok(items)
}

/// A core error as one line, with what to do about it where the CLI knows.
fn explain(e: FitError) -> anyhow::Error {
    match &e {
        FitError::Unidentifiable { parameters } => {
            let names: Vec<&str> = parameters.iter().map(|p| p.name).collect();
            anyhow!(
                "{e}; fix {} (--fix {} with the values from the model flags) or fit data that excite {}",
                if names.len() == 1 { "it" } else { "them" },
                names.join(","),
                if names.len() == 1 { "it" } else { "them" }
            )
        }
        FitError::NotInSlowLoop { .. } => anyhow!("{e}"),
        FitError::StartOutsideBounds { name, .. } => {
            anyhow!("{e}: change --{name} or --bounds")
        }
        FitError::BadStart { name, .. } => {
            anyhow!("--{name}: {e} (to hold it at that value, add --fix {name})")
        }
        _ => anyhow!("{e}"),
    }
}

/// Reads `u,F` or `t,u,F` (header optional; a header may name the columns in any order).
fn read_record(path: &Path) -> Result<Record> {
    let table = read_table(path, Columns::Record)?;
    let mut columns = table.columns.into_iter();
    Ok(Record {
        t: table.t,
        u: columns.next().unwrap_or_default(),
        f: columns.next().unwrap_or_default(),
    })
}

fn write_csv(w: &mut dyn Write, record: &Record, report: &FitReport, res: &[f64]) -> Result<()> {
    let mut rows = NumberRows::new();
    match &record.t {
        Some(_) => writeln!(w, "t,u,F,fit,residual")?,
        None => writeln!(w, "u,F,fit,residual")?,
    }
    for i in 0..record.u.len() {
        let (u, f, fit, r) = (record.u[i], record.f[i], report.fitted[i], res[i]);
        match &record.t {
            Some(t) => rows.write(w, &[t[i], u, f, fit, r])?,
            None => rows.write(w, &[u, f, fit, r])?,
        }
    }
    Ok(())
}

/// Two panels: the data with the fit in the (u, F) plane, and the residuals against t (or the
/// sample).
fn figure(record: &Record, report: &FitReport, res: &[f64]) -> Panels {
    let what = match report.kind {
        FitKind::Slow => "slow-loop fit",
        FitKind::Full => "full fit",
    };
    let data: Vec<(f64, f64)> = record
        .u
        .iter()
        .copied()
        .zip(record.f.iter().copied())
        .collect();
    let fit: Vec<(f64, f64)> = record
        .u
        .iter()
        .copied()
        .zip(report.fitted.iter().copied())
        .collect();
    let fit_fig = Figure::new("input u", "friction force F")
        .title(format!(
            "{} {what}: residual RMS {}",
            report.family.label(),
            sig(report.rms, 4)
        ))
        .curve(
            Curve::new(data, LineStyle::Solid, BLUE)
                .width(1)
                .label("data"),
        )
        .curve(Curve::new(fit, LineStyle::Dashed, RED).label("fit"));
    Panels::side_by_side(fit_fig, residual_figure(record, res))
}

/// The residuals against t (or the sample).
fn residual_figure(record: &Record, res: &[f64]) -> Figure {
    let (x_label, xs): (&str, Vec<f64>) = match &record.t {
        Some(t) => ("time t", t.clone()),
        None => ("sample", (0..res.len()).map(|i| i as f64).collect()),
    };
    // Noise drawn as one polyline zigzags at sharp angles, which the bitmap backend renders
    // with long miter spikes: draw separate vertical strokes instead, from 0 to each residual
    // (few samples) or over the range of each of RESIDUAL_BINS consecutive groups.
    let n = res.len();
    let bins = n.min(RESIDUAL_BINS);
    let mut res_fig = Figure::new(x_label, "residual F - fit").title(if bins < n {
        format!(
            "Residuals, min to max of each {}-sample group",
            n.div_ceil(bins)
        )
    } else {
        "Residuals".to_string()
    });
    for b in 0..bins {
        let (lo, hi) = (b * n / bins, ((b + 1) * n / bins).max(b * n / bins + 1));
        let x = 0.5 * (xs[lo] + xs[hi - 1]);
        let (mut r0, mut r1) = if bins < n {
            (f64::INFINITY, f64::NEG_INFINITY)
        } else {
            (0.0, 0.0)
        };
        for &r in &res[lo..hi] {
            r0 = r0.min(r);
            r1 = r1.max(r);
        }
        res_fig =
            res_fig.curve(Curve::new(vec![(x, r0), (x, r1)], LineStyle::Solid, BLACK).width(1));
    }
    res_fig.curve(Curve::new(
        vec![(xs[0], 0.0), (xs[n - 1], 0.0)],
        LineStyle::Dashed,
        RED,
    ))
}

/// The name shown for a parameter (`fs` is `g(0)` in a slow LuGre fit).
fn label(report: &FitReport, name: &str) -> String {
    if report.kind == FitKind::Slow && report.family == Family::LuGre && name == "fs" {
        "fs = g(0)".into()
    } else {
        name.into()
    }
}

fn print_table(w: &mut impl Write, r: &FitReport, path: &Path) -> Result<()> {
    let what = match r.kind {
        FitKind::Slow => "slow-loop fit (the hysteresis loop y°, eqs. 8-10)".to_string(),
        FitKind::Full => format!(
            "full fit (exact simulation of eq. 1, {} start{})",
            r.starts,
            if r.starts == 1 { "" } else { "s" }
        ),
    };
    writeln!(
        w,
        "{} {what} to {} samples from {}{}",
        r.family.label(),
        r.samples,
        path.display(),
        match r.turning_points {
            Some(n) => format!(" ({n} turning points)"),
            None => String::new(),
        }
    )?;
    writeln!(w)?;
    writeln!(
        w,
        "{:<12} {:>16} {:>14}   {:<36}",
        "parameter", "value", "std. error", "95 % confidence interval"
    )?;
    for e in &r.estimates {
        writeln!(
            w,
            "{:<12} {:>16} {:>14}   [{}, {}]{}",
            label(r, e.name),
            sig(e.value, 10),
            sig(e.stderr, 4),
            sig(e.ci95[0], 8),
            sig(e.ci95[1], 8),
            if e.at_bound { "  (at its bound)" } else { "" }
        )?;
    }
    if !r.fixed.is_empty() {
        let fixed: Vec<String> = r
            .fixed
            .iter()
            .map(|(n, v)| format!("{} = {}", label(r, n), sig(*v, 10)))
            .collect();
        writeln!(w, "fixed: {}", fixed.join(", "))?;
    }
    writeln!(w)?;
    writeln!(
        w,
        "residual RMS {}   ({} degrees of freedom; intervals: value -+ {} standard errors, Student's t)",
        sig(r.rms, 6),
        r.dof,
        sig(r.t_quantile, 6)
    )?;
    writeln!(
        w,
        "{} iterations, {} model evaluations: {}",
        r.iterations, r.evaluations, r.termination
    )?;
    if r.estimates.len() > 1 {
        print_correlation(w, r)?;
    }
    Ok(())
}

fn print_correlation(w: &mut impl Write, r: &FitReport) -> Result<()> {
    writeln!(
        w,
        "correlation of the estimates (condition number of the scaled J^T J: {}):",
        sig(r.condition_number, 3)
    )?;
    for (i, row) in r.correlation.iter().enumerate() {
        let cells: Vec<String> = row.iter().map(|c| format!("{c:>7.3}")).collect();
        writeln!(
            w,
            "  {:<12} {}",
            label(r, r.estimates[i].name),
            cells.join(" ")
        )?;
    }
    Ok(())
}

/// `{"parameters": {name: {"value", "stderr", "ci95": [lo, hi], "at_bound"}}, "rms",
/// "iterations", ...}` (keys may be added, never renamed).
fn write_json<W: Write>(mut j: JsonOut<W>, r: &FitReport, path: &Path) -> std::io::Result<()> {
    j.raw("{\"parameters\":{")?;
    for (k, e) in r.estimates.iter().enumerate() {
        if k > 0 {
            j.raw(",")?;
        }
        j.raw(&quote(e.name))?;
        j.raw(":{\"value\":")?;
        num_or_null(&mut j, e.value)?;
        j.raw(",\"stderr\":")?;
        num_or_null(&mut j, e.stderr)?;
        j.raw(",\"ci95\":[")?;
        num_or_null(&mut j, e.ci95[0])?;
        j.raw(",")?;
        num_or_null(&mut j, e.ci95[1])?;
        j.raw(&format!("],\"at_bound\":{}}}", e.at_bound))?;
    }
    j.raw("},\"rms\":")?;
    num_or_null(&mut j, r.rms)?;
    j.raw(",\"iterations\":")?;
    j.int(r.iterations)?;
    j.raw(",\"evaluations\":")?;
    j.int(r.evaluations)?;
    j.raw(",\"starts\":")?;
    j.int(r.starts)?;
    j.raw(&format!(
        ",\"converged\":{},\"termination\":{}",
        r.converged,
        quote(&r.termination)
    ))?;
    j.raw(&format!(
        ",\"model\":{},\"fit\":{}",
        quote(&r.family.label().to_ascii_lowercase()),
        quote(match r.kind {
            FitKind::Slow => "slow",
            FitKind::Full => "full",
        })
    ))?;
    j.raw(",\"fixed\":{")?;
    for (k, (n, v)) in r.fixed.iter().enumerate() {
        if k > 0 {
            j.raw(",")?;
        }
        j.raw(&quote(n))?;
        j.raw(":")?;
        num_or_null(&mut j, *v)?;
    }
    j.raw("},\"samples\":")?;
    j.int(r.samples)?;
    j.raw(",\"dof\":")?;
    j.int(r.dof)?;
    j.raw(",\"t_quantile\":")?;
    num_or_null(&mut j, r.t_quantile)?;
    j.raw(",\"condition_number\":")?;
    num_or_null(&mut j, r.condition_number)?;
    j.raw(",\"correlation\":")?;
    write_matrix(&mut j, &r.correlation)?;
    if let Some(n) = r.turning_points {
        j.raw(",\"turning_points\":")?;
        j.int(n)?;
    }
    j.raw(",\"input\":")?;
    j.raw(&quote(&path.display().to_string()))?;
    j.raw("}\n")?;
    j.finish()
}

/// `s` as a JSON string.
fn quote(s: &str) -> String {
    serde_json::Value::from(s).to_string()
}

/// `x`, or `null` when it is not finite (JSON has no NaN or infinity).
fn num_or_null<W: Write>(j: &mut JsonOut<W>, x: f64) -> std::io::Result<()> {
    if x.is_finite() {
        j.num(x)
    } else {
        j.raw("null")
    }
}

/// `[[a, b, ...], ...]`, non-finite entries as `null`.
fn write_matrix<W: Write>(j: &mut JsonOut<W>, rows: &[Vec<f64>]) -> std::io::Result<()> {
    j.raw("[")?;
    for (k, row) in rows.iter().enumerate() {
        if k > 0 {
            j.raw(",")?;
        }
        j.raw("[")?;
        for (c, &x) in row.iter().enumerate() {
            if c > 0 {
                j.raw(",")?;
            }
            num_or_null(j, x)?;
        }
        j.raw("]")?;
    }
    j.raw("]")
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
