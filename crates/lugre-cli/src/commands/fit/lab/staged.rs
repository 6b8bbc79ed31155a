//! `lugre fit --fit staged`: the Stribeck, presliding and (with `--input`) full fits in turn.

use anyhow::{anyhow, bail, Result};
use lugre::fit::{fit_staged, FitError, FitKind, FitSpec, StagedReport, CUBIC_READING_TOL};
use lugre::simulate::SmoothSamples;
use std::io::Write;
use std::path::Path;

use super::super::{output, warn_unconverged, FitArgs};
use super::{in_file, read_steady, read_timed, steady_plot, write_steady_csv, Steady};
use crate::fmt::sig;
use crate::io::atomic::write_atomic;

pub(super) fn run(args: &FitArgs, spec: &FitSpec) -> Result<()> {
    let (Some(stribeck), Some(presliding)) = (&args.stribeck, &args.presliding) else {
        bail!("--fit staged needs --stribeck FILE (constant-velocity runs: t,u,F or v,F) and --presliding FILE (a presliding test: t,u,F); --input FILE adds a final full fit of a rate-dependent record");
    };
    let steady = read_steady(args, stribeck)?;
    let (tp, pre) = read_timed(args, presliding)?;
    let full = match &args.input {
        Some(path) => {
            let (t, record) = read_timed(args, path)?;
            let motion = SmoothSamples::pchip(t, record.u.clone(), CUBIC_READING_TOL)
                .map_err(|e| anyhow!("{}: {e}", path.display()))?;
            Some((path.as_path(), motion, record.f))
        }
        None => None,
    };
    let report = fit_staged(
        spec,
        &steady.points,
        (&tp, &pre.u, &pre.f),
        full.as_ref().map(|(_, m, f)| (m, &f[..])),
    )
    .map_err(|e| match e {
        FitError::InStage { stage, error } => {
            let path = match stage {
                "stribeck" => stribeck.as_path(),
                "presliding" => presliding.as_path(),
                _ => full.as_ref().map_or(presliding.as_path(), |(p, _, _)| p),
            };
            anyhow!("{stage} stage: {}", in_file(*error, path))
        }
        other => anyhow!("{other}"),
    })?;
    if let Some(csv) = &args.output.csv {
        write_atomic(csv, |w| write_steady_csv(w, &steady, &report.stribeck))?;
    }
    if let Some(plot) = &args.plot.path {
        steady_plot::figure(&steady, &report.stribeck, spec).save(plot)?;
    }
    for r in std::iter::once(&report.stribeck)
        .chain(std::iter::once(&report.presliding))
        .chain(&report.full)
    {
        warn_unconverged(r);
    }
    let files = Files {
        stribeck,
        presliding,
        full: full.as_ref().map(|(p, _, _)| *p),
    };
    if args.output.json {
        let mut out = std::io::stdout().lock();
        serde_json::to_writer(&mut out, &json(&report, &steady, &files)?)?;
        writeln!(out)?;
        return Ok(());
    }
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    print(&mut out, &report, &files)?;
    out.flush()?;
    Ok(())
}

/// The files of the stages.
struct Files<'a> {
    stribeck: &'a Path,
    presliding: &'a Path,
    full: Option<&'a Path>,
}

fn print(w: &mut impl Write, r: &StagedReport, files: &Files) -> Result<()> {
    writeln!(
        w,
        "LuGre staged identification: Stribeck fit of {} constant-velocity points from {}, presliding fit of {} samples from {}{}",
        r.stribeck.samples,
        files.stribeck.display(),
        r.presliding.samples,
        files.presliding.display(),
        match (&r.full, files.full) {
            (Some(full), Some(p)) => format!(
                ", then a full fit of {} samples from {} started from them",
                full.samples,
                p.display()
            ),
            _ => String::new(),
        }
    )?;
    writeln!(w)?;
    writeln!(
        w,
        "{:<12} {:>16} {:>14}   {:<36} determined by",
        "parameter", "value", "std. error", "95 % confidence interval"
    )?;
    for (e, stage) in &r.estimates {
        let interval = format!("[{}, {}]", sig(e.ci95[0], 8), sig(e.ci95[1], 8));
        writeln!(
            w,
            "{:<12} {:>16} {:>14}   {:<36} {} fit{}",
            e.name,
            sig(e.value, 10),
            sig(e.stderr, 4),
            interval,
            stage.label(),
            if e.at_bound { "  (at its bound)" } else { "" }
        )?;
    }
    output::write_fixed(w, r.fixed.iter().map(|(n, v)| (n.to_string(), *v)))?;
    writeln!(w)?;
    for (label, rep) in [
        ("Stribeck", Some(&r.stribeck)),
        ("presliding", Some(&r.presliding)),
        ("full", r.full.as_ref()),
    ] {
        if let Some(rep) = rep {
            let names: Vec<&str> = rep.estimates.iter().map(|e| e.name).collect();
            writeln!(
                w,
                "{label} stage: {} (residual RMS {}, {} degrees of freedom; {})",
                names.join(", "),
                sig(rep.rms, 6),
                rep.dof,
                rep.termination
            )?;
        }
    }
    Ok(())
}

/// `{"fit": "staged", "parameters": {name: {"value", "stderr", "ci95", "at_bound", "stage"}},
/// "fixed", "stages": {"stribeck": {...}, "presliding": {...}, "full": {...}}}`, each stage
/// the document of its own fit.
fn json(r: &StagedReport, steady: &Steady, files: &Files) -> Result<serde_json::Value> {
    let mut parameters = serde_json::Map::new();
    for (e, stage) in &r.estimates {
        parameters.insert(
            e.name.to_string(),
            serde_json::json!({
                "value": e.value,
                "stderr": e.stderr,
                "ci95": e.ci95,
                "at_bound": e.at_bound,
                "stage": stage.label(),
            }),
        );
    }
    let fixed: serde_json::Map<String, serde_json::Value> = r
        .fixed
        .iter()
        .map(|(n, v)| (n.to_string(), (*v).into()))
        .collect();
    let output = output::json_value;
    let mut stages = serde_json::Map::new();
    let mut stribeck = output(&r.stribeck, files.stribeck, false)?;
    stribeck["points"] = super::points_json(steady, &r.stribeck);
    stages.insert(FitKind::Stribeck.label().into(), stribeck);
    stages.insert(
        FitKind::Presliding.label().into(),
        output(&r.presliding, files.presliding, false)?,
    );
    if let (Some(full), Some(p)) = (&r.full, files.full) {
        stages.insert(FitKind::Full.label().into(), output(full, p, false)?);
    }
    Ok(serde_json::json!({
        "fit": "staged",
        "model": "lugre",
        "parameters": parameters,
        "fixed": fixed,
        "stages": stages,
    }))
}
