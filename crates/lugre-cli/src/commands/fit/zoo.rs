//! `lugre fit --model NAME` for a model of the zoo: the slow-loop fit of its table's
//! parameters to a slow periodic record `u,F` (`lugre::fit::fit_zoo`), or, for a model with a
//! finite-rate form, the full fit to a rate-dependent record `t,u,F` (`--fit full`,
//! `lugre::fit::fit_zoo_full`: its path from rest at the record's rate), through the same
//! table, JSON and CSV as the LuGre fit. The model's flags given are held values (with
//! `--fix`) or start values; an element model's thresholds come from its flags
//! (`--thresholds`; `--slip-force` with `--stiffness`) or the grid on the record's amplitude,
//! `--elements N` of them.

use anyhow::{anyhow, bail, Result};
use lugre::fit::{
    fit_zoo, fit_zoo_full, FitError, FitProgress, FullOptions, SlowOptions, ZooFitReport,
    ZooFitSpec,
};
use lugre::zoo::{Shape, ZooModelSpec};
use std::io::Write;
use std::path::Path;

use super::output::{
    figure_of, print_estimates, print_statistics, quote, write_csv, write_json_head,
    write_json_tail, Summary,
};
use super::{read_record, FitArgs, FitChoice, FitProgressBar, Record};
use crate::args::check_files;
use crate::fmt::sig;
use crate::io::atomic::write_atomic;
use crate::io::json::JsonOut;
use crate::numbers::parse_number;

pub(super) fn run(args: &FitArgs, model: &'static ZooModelSpec) -> Result<()> {
    refuse_flags(args, model)?;
    check_files(args.input.as_deref(), &args.output, Some(&args.plot))?;
    let full = args.fit == FitChoice::Full;
    let Some(path) = &args.input else {
        bail!("no data: give --input FILE.csv (columns {})", columns(full));
    };
    let spec = build_spec(args)?;
    if full {
        spec.check_finite_rate()?;
    }
    if let Some(plot) = &args.plot.path {
        crate::plot::check_path(plot)?;
    }
    let record = read_record(args, path)?;
    check_record(args, path, model, &record)?;
    let report = fit_record(args, &spec, path, &record)?;
    show(args, path, &record, &report)
}

/// The record's columns for the fit `full` or slow.
fn columns(full: bool) -> &'static str {
    if full {
        "t,u,F"
    } else {
        "u,F"
    }
}

/// Refuses a record with columns the fit does not read, or a row without a force.
fn check_record(args: &FitArgs, path: &Path, model: &ZooModelSpec, record: &Record) -> Result<()> {
    if record.normal.is_some() || record.velocity.is_some() {
        bail!(
            "{}: the {} fit reads a record {} (no normal force, no velocity)",
            path.display(),
            model.label,
            columns(args.fit == FitChoice::Full)
        );
    }
    if let Some(i) = record.f.iter().position(|f| f.is_nan()) {
        bail!(
            "{}: row {} has no force: the {} fit of the {} model needs one at every row",
            path.display(),
            i + 1,
            args.fit.kind().label(),
            model.name
        );
    }
    Ok(())
}

/// The fit asked for (slow, or `--fit full` with `--x0`), its errors in the terms of the
/// flags and of the file.
fn fit_record(
    args: &FitArgs,
    spec: &ZooFitSpec,
    path: &Path,
    record: &Record,
) -> Result<ZooFitReport> {
    if args.fit != FitChoice::Full {
        let mut options = SlowOptions::default().with_noise(args.noise.unwrap_or_default());
        if let Some(gate) = args.gate {
            options = options.with_gate(gate);
        }
        return fit_zoo(spec, &record.u, &record.f, options).map_err(|e| file_error(path, e));
    }
    let t = record.times_for_full_fit(path)?;
    let x0 = match &args.x0 {
        Some(text) => parse_number("--x0", 1, text)?,
        None => 0.0,
    };
    fit_full(args, spec, t, x0, record).map_err(|e| match e {
        FitError::ZooFromRest { .. } => anyhow!("--x0: {e}"),
        other => file_error(path, other),
    })
}

/// A fit's error naming the file (the record's faults) or the flag (`--gate`, `--elements`,
/// `--starts`), with what to do for a parameter that cannot be identified.
fn file_error(path: &Path, e: FitError) -> anyhow::Error {
    match e {
        FitError::TooFewSamples { .. }
        | FitError::NoReversal { .. }
        | FitError::ZeroForce
        | FitError::LengthMismatch { .. }
        | FitError::Data(_) => anyhow!("{}: {e}", path.display()),
        FitError::BadGate { .. } => anyhow!("--gate: {e}"),
        FitError::BadElements { .. } => anyhow!("--elements: {e}"),
        FitError::BadStarts { .. } => anyhow!("--starts: {e}"),
        FitError::Unidentifiable { .. } => anyhow!(
            "{e}; hold a scalar at a value you know (--fix NAME=VALUE), fit fewer elements (--elements), or fit data that excite it"
        ),
        other => anyhow!("{other}"),
    }
}

/// The full fit (`--fit full`) from rest with `--starts`, and a progress indicator.
fn fit_full(
    args: &FitArgs,
    spec: &ZooFitSpec,
    t: &[f64],
    x0: f64,
    record: &Record,
) -> Result<ZooFitReport, FitError> {
    let mut progress = FitProgressBar::new();
    let mut report = |p: &FitProgress| progress.update(p);
    let options = FullOptions::default()
        .with_x0(x0)
        .with_starts(args.starts.unwrap_or(FullOptions::DEFAULT_STARTS))
        .with_noise(args.noise.unwrap_or_default())
        .with_progress(&mut report);
    let result = fit_zoo_full(spec, t, &record.u, &record.f, options);
    progress.finish();
    result
}

/// Flags of the LuGre fits that a model of the zoo does not take.
fn refuse_flags(args: &FitArgs, model: &ZooModelSpec) -> Result<()> {
    if !matches!(args.fit, FitChoice::Slow | FitChoice::Full) {
        bail!(
            "--fit {}: the {} model is fitted to its slow loop (--fit slow) or, with a finite-rate form, to a rate-dependent record (--fit full)",
            args.fit.kind().label(),
            model.label
        );
    }
    if args.fit == FitChoice::Slow {
        for (flag, given) in [
            ("--x0", args.x0.is_some()),
            ("--starts", args.starts.is_some()),
        ] {
            if given {
                bail!("{flag} applies to the full fit (add --fit full)");
            }
        }
    } else if args.gate.is_some() {
        bail!("--gate applies to the slow fit (the full fit simulates every turn of the input)");
    }
    let given = [
        ("--bounds", args.bounds.is_some()),
        ("--stribeck", args.stribeck.is_some()),
        ("--presliding", args.presliding.is_some()),
        (
            "--interpolate cubic",
            args.interpolate == crate::args::Interpolate::Cubic,
        ),
    ];
    if let Some((flag, _)) = given.into_iter().find(|(_, g)| *g) {
        bail!(
            "{flag} does not apply to the {} fit (its bounds are the parameters' domains)",
            model.label
        );
    }
    Ok(())
}

/// The request from the flags: the model's values given, `--fix`, `--free`, `--elements`.
fn build_spec(args: &FitArgs) -> Result<ZooFitSpec> {
    let Some((model, given)) = args.model.zoo_given()? else {
        bail!("--model names no model of the zoo");
    };
    let mut spec = ZooFitSpec::new(model.name)?;
    for (name, values) in &given {
        spec = spec.set(name, values)?;
    }
    for item in super::spec::names("--fix", args.fix.as_deref())? {
        let (name, value) = super::spec::fixed_item(item)?;
        if let Some(v) = value {
            spec = spec.set(name, &[v]).map_err(|e| anyhow!("--fix: {e}"))?;
        }
        spec = spec.fix(name).map_err(|e| anyhow!("--fix: {e}"))?;
    }
    for name in super::spec::names("--free", args.free.as_deref())? {
        spec = spec.free(name).map_err(|e| anyhow!("--free: {e}"))?;
    }
    if let Some(n) = args.elements {
        spec = spec.with_elements(n);
    }
    Ok(spec)
}

/// The CSV and the figure asked for, a warning for a fit that did not converge, then the JSON
/// document or the table.
fn show(args: &FitArgs, path: &Path, record: &Record, r: &ZooFitReport) -> Result<()> {
    let residuals: Vec<f64> = record.f.iter().zip(&r.fitted).map(|(f, y)| f - y).collect();
    if let Some(csv) = &args.output.csv {
        write_atomic(csv, |w| write_csv(w, record, &r.fitted, &residuals))?;
    }
    let label = r.model.spec().label;
    let kind = r.kind.label();
    if let Some(plot) = &args.plot.path {
        let units = record.units.clone().with_flag(args.plot.units.as_deref())?;
        let title = format!("{label} {kind} fit: residual RMS {}", sig(r.rms, 4));
        figure_of(record, title, &r.fitted, &residuals, &units).save(plot)?;
    }
    if !r.converged {
        let _ = writeln!(
            std::io::stderr(),
            "lugre: warning: the {kind} fit did not converge ({}); the best point found is reported",
            r.termination
        );
    }
    let summary = summary(r);
    if args.output.json {
        return write_json(path, r, &summary);
    }
    print_table(args, path, record, r, &summary)
}

/// The JSON document: the LuGre fit's, with the model, the fit's kind, the fitted model's
/// values and the held ones.
fn write_json(path: &Path, r: &ZooFitReport, summary: &Summary<'_>) -> Result<()> {
    let stdout = std::io::stdout();
    let mut j = JsonOut::new(stdout.lock());
    write_json_head(&mut j, summary)?;
    j.raw(&format!(
        ",\"model\":{},\"fit\":{},\"values\":{},\"fixed\":{}",
        quote(r.model.spec().name),
        quote(r.kind.label()),
        crate::zoo_args::zoo_json(&r.model),
        fixed_json(r)
    ))?;
    write_json_tail(j, summary, path, false)?;
    Ok(())
}

/// The table: what was fitted to what, the estimates, the held values, the fitted model, the
/// statistics and the files written.
fn print_table(
    args: &FitArgs,
    path: &Path,
    record: &Record,
    r: &ZooFitReport,
    summary: &Summary<'_>,
) -> Result<()> {
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    let what = match r.kind {
        lugre::fit::FitKind::Full => format!(
            "full fit (the model's exact path from rest at the record's rate; {} start{})",
            r.starts,
            if r.starts == 1 { "" } else { "s" }
        ),
        _ => "slow-loop fit (the model's exact periodic loop)".to_string(),
    };
    writeln!(
        out,
        "{} {what} to {} samples from {} ({} turning points)\n",
        r.model.spec().label,
        r.samples,
        path.display(),
        r.turning_points
    )?;
    print_estimates(&mut out, summary)?;
    for (name, values) in &r.fixed {
        let v: Vec<String> = values.iter().map(|x| sig(*x, 10)).collect();
        writeln!(out, "fixed: {name} = {}", v.join(","))?;
    }
    writeln!(out, "fitted model: {}", crate::zoo_args::zoo_line(&r.model))?;
    print_statistics(&mut out, summary)?;
    super::output::print_written(&mut out, args, record.t.is_some())?;
    out.flush()?;
    Ok(())
}

fn summary(r: &ZooFitReport) -> Summary<'_> {
    let names: Vec<String> = r.estimates.iter().map(|e| e.name.to_string()).collect();
    Summary {
        core: r.summary(),
        labels: names.clone(),
        keys: names,
    }
}

/// The held parameters: a number for a scalar, a list for an element model's thresholds.
fn fixed_json(r: &ZooFitReport) -> serde_json::Value {
    let mut j = serde_json::Map::new();
    for (name, values) in &r.fixed {
        let finite: Vec<f64> = values.iter().copied().filter(|x| x.is_finite()).collect();
        j.insert(
            (*name).to_string(),
            match finite.as_slice() {
                [x] if r
                    .model
                    .spec()
                    .parameter(name)
                    .is_some_and(|p| p.shape == Shape::Scalar) =>
                {
                    (*x).into()
                }
                _ => finite.into(),
            },
        );
    }
    j.into()
}
