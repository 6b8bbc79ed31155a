//! What `lugre fit` writes: the CSV of the data with the fit and residuals, the figure, the
//! table and the JSON document.

use anyhow::Result;
use lugre::fit::{
    Covariance, Estimate, Family, FitKind, FitReport, FitSummary, FitWarning, NoiseLevels,
    PositionHandling,
};
use lugre::model::{normal, Parameter};
use std::io::Write;
use std::path::Path;

use super::Record;
use crate::fmt::sig;
use crate::io::csv::NumberRows;
use crate::io::json::JsonOut;
use crate::plot::{Curve, Figure, LineStyle, Panels, Units, BLACK, BLUE, RED};

/// Vertical strokes in the residual figure (at most).
const RESIDUAL_BINS: usize = 600;

pub(super) fn write_csv(
    w: &mut dyn Write,
    record: &Record,
    fitted: &[f64],
    res: &[f64],
) -> Result<()> {
    let mut rows = NumberRows::new();
    // With a normal force, the fit's quantity is the friction coefficient mu = F / N.
    let f_name = if record.normal.is_some() {
        normal::COEFFICIENT
    } else {
        "F"
    };
    match &record.t {
        Some(_) => writeln!(w, "t,u,{f_name},fit,residual")?,
        None => writeln!(w, "u,{f_name},fit,residual")?,
    }
    for i in 0..record.u.len() {
        let (u, f, fit, r) = (record.u[i], record.f[i], fitted[i], res[i]);
        let lead: &[f64] = match &record.t {
            Some(t) => &[t[i], u],
            None => &[u],
        };
        if f.is_nan() {
            // An input-only row: no force, so no residual (empty fields, never NaN).
            let mut text = Vec::new();
            rows.write(&mut text, &[lead, &[fit]].concat())?;
            let text = String::from_utf8_lossy(&text);
            let (head, fit) = text
                .trim_end()
                .rsplit_once(',')
                .unwrap_or(("", text.trim_end()));
            let head = if head.is_empty() {
                String::new()
            } else {
                format!("{head},")
            };
            writeln!(w, "{head},{fit},")?;
        } else {
            rows.write(w, &[lead, &[f, fit, r]].concat())?;
        }
    }
    Ok(())
}

/// The fit's check: the data with the fit in the (u, F) plane, and the residuals against t (or
/// the sample) and against the input u, where structure the fit missed shows (a bias at the
/// reversals, a trend with the velocity).
pub(super) fn figure(record: &Record, report: &FitReport, res: &[f64], units: &Units) -> Panels {
    let title = format!(
        "{} {} fit: residual RMS {}",
        report.family.label(),
        report.kind.label(),
        sig(report.rms, 4)
    );
    figure_of(record, title, &report.fitted, res, units)
}

/// [`figure`] of any fit: `title` over the fit `fitted` at the samples.
pub(super) fn figure_of(
    record: &Record,
    title: String,
    fitted: &[f64],
    res: &[f64],
    units: &Units,
) -> Panels {
    let data: Vec<(f64, f64)> = record
        .u
        .iter()
        .copied()
        .zip(record.f.iter().copied())
        .filter(|(_, f)| !f.is_nan())
        .collect();
    let fit: Vec<(f64, f64)> = record
        .u
        .iter()
        .copied()
        .zip(fitted.iter().copied())
        .collect();
    let (y_label, residual_label) = if record.normal.is_some() {
        (
            "friction coefficient F / N".to_string(),
            "residual (F - fit) / N".to_string(),
        )
    } else {
        (
            units.force("friction force F"),
            units.force("residual F - fit"),
        )
    };
    let fit_fig = Figure::new(units.u("input u"), y_label)
        .title(title)
        .curve(
            Curve::new(data, LineStyle::Solid, BLUE)
                .width(1)
                .label("data"),
        )
        .curve(Curve::new(fit, LineStyle::Dashed, RED).label("fit"));
    let (x_label, xs): (String, Vec<f64>) = match &record.t {
        Some(t) => (units.t("time t"), t.clone()),
        None => (
            "sample".to_string(),
            (0..res.len()).map(|i| i as f64).collect(),
        ),
    };
    let by_time = residual_figure(&xs, res, x_label, &residual_label, "against time");
    let by_input = residual_figure(
        &record.u,
        res,
        units.u("input u"),
        &residual_label,
        "against the input",
    );
    let mut panels = Panels::side_by_side(fit_fig, by_time);
    panels.panels.push(by_input);
    panels.cols = 3;
    panels.size = (2250, 650);
    panels
}

/// The residuals against `xs` (any order). Noise drawn as one polyline zigzags at sharp
/// angles, which the bitmap backend renders with long miter spikes: separate vertical strokes
/// instead, from 0 to each residual (few samples) or over the range of each of
/// [`RESIDUAL_BINS`] groups of samples consecutive in `x`.
fn residual_figure(xs: &[f64], res: &[f64], x_label: String, y_label: &str, what: &str) -> Figure {
    let mut order: Vec<usize> = (0..res.len()).collect();
    order.sort_by(|&a, &b| xs[a].total_cmp(&xs[b]));
    let n = res.len();
    let bins = n.min(RESIDUAL_BINS);
    let mut fig = Figure::new(x_label, y_label).title(if bins < n {
        format!(
            "Residuals {what}, min to max of each {}-sample group",
            n.div_ceil(bins)
        )
    } else {
        format!("Residuals {what}")
    });
    for b in 0..bins {
        let (lo, hi) = (b * n / bins, ((b + 1) * n / bins).max(b * n / bins + 1));
        let group = &order[lo..hi];
        let x = 0.5 * (xs[group[0]] + xs[group[group.len() - 1]]);
        let (mut r0, mut r1) = if bins < n {
            (f64::INFINITY, f64::NEG_INFINITY)
        } else {
            (0.0, 0.0)
        };
        for r in group.iter().map(|&i| res[i]).filter(|r| !r.is_nan()) {
            r0 = r0.min(r);
            r1 = r1.max(r);
        }
        if r0 > r1 {
            continue; // only input-only rows in this group
        }
        fig = fig.curve(Curve::new(vec![(x, r0), (x, r1)], LineStyle::Solid, BLACK).width(1));
    }
    let (Some(&i0), Some(&i1)) = (order.first(), order.last()) else {
        return fig;
    };
    let (first, last) = (xs[i0], xs[i1]);
    fig.curve(Curve::new(
        vec![(first, 0.0), (last, 0.0)],
        LineStyle::Dashed,
        RED,
    ))
}

/// The name shown for a parameter (`fs` is `g(0)` in a slow LuGre fit), and with a normal
/// force (`normal`) the core's names per newton (the friction coefficients `mu_c`, `mu_s`).
fn label(report: &FitReport, name: &'static str, normal: bool) -> String {
    let g0 = report.kind == FitKind::Slow && report.family == Family::LuGre && name == "fs";
    match (normal, g0) {
        (true, true) => format!("{} = g(0)/N", normal::name_of(name)),
        (true, false) => normal::name_of(name).into(),
        (false, true) => "fs = g(0)".into(),
        (false, false) => name.into(),
    }
}

/// The key of a parameter in the JSON document (the core's names per newton with a normal
/// force).
fn key(name: &'static str, normal: bool) -> &'static str {
    if normal {
        normal::name_of(name)
    } else {
        name
    }
}

pub(super) fn print_table(
    w: &mut impl Write,
    r: &FitReport,
    path: &Path,
    normal: bool,
) -> Result<()> {
    let what = match r.kind {
        FitKind::Slow => "slow-loop fit (the hysteresis loop y°, eqs. 8-10)".to_string(),
        FitKind::Stribeck => {
            "Stribeck fit (the steady-state curve F_ss(v) = g(v) sgn(v) + sigma2 v)".to_string()
        }
        FitKind::Presliding => {
            "presliding fit (exact simulation of eq. 1, Stribeck curve held)".to_string()
        }
        FitKind::Full | FitKind::Staged => format!(
            "full fit (exact simulation of eq. 1, {} start{})",
            r.starts,
            if r.starts == 1 { "" } else { "s" }
        ),
    };
    writeln!(
        w,
        "{} {what} to {} {} from {}{}",
        r.family.label(),
        r.samples,
        if r.kind == FitKind::Stribeck {
            "constant-velocity points"
        } else {
            "samples"
        },
        path.display(),
        match r.turning_points {
            Some(n) => format!(" ({n} turning points)"),
            None => String::new(),
        }
    )?;
    if normal {
        let parameters = match r.family {
            Family::LuGre => &Parameter::LUGRE[..],
            Family::Dahl => &Parameter::DAHL[..],
        };
        writeln!(
            w,
            "fitted to the friction coefficient {mu} = F / N: {} (per newton of N)",
            normal::units(parameters),
            mu = normal::COEFFICIENT
        )?;
    }
    writeln!(w)?;
    let summary = Summary::of(r, normal);
    print_estimates(w, &summary)?;
    write_fixed(w, r.fixed.iter().map(|(n, v)| (label(r, n, normal), *v)))?;
    print_statistics(w, &summary)
}

/// What the table and the JSON document of every fit show: the core's view of a LuGre or Dahl
/// fit ([`Summary::of`]) or of a model of the zoo's, with each estimate's label and key.
pub(super) struct Summary<'a> {
    pub(super) core: FitSummary<'a>,
    /// Each estimate's label in the table and key in the JSON document.
    pub(super) labels: Vec<String>,
    pub(super) keys: Vec<String>,
}

impl<'a> Summary<'a> {
    /// A LuGre or Dahl fit's.
    pub(super) fn of(r: &'a FitReport, normal: bool) -> Self {
        Self {
            core: r.summary(),
            labels: r
                .estimates
                .iter()
                .map(|e| label(r, e.name, normal))
                .collect(),
            keys: r
                .estimates
                .iter()
                .map(|e| key(e.name, normal).to_string())
                .collect(),
        }
    }
}

impl<'a> std::ops::Deref for Summary<'a> {
    type Target = FitSummary<'a>;

    fn deref(&self) -> &FitSummary<'a> {
        &self.core
    }
}

/// The table's rows of the estimates.
pub(super) fn print_estimates(w: &mut impl Write, s: &Summary) -> Result<()> {
    writeln!(
        w,
        "{:<12} {:>16} {:>14}   {:<36}",
        "parameter", "value", "std. error", "95 % confidence interval"
    )?;
    for (e, label) in s.estimates.iter().zip(&s.labels) {
        writeln!(
            w,
            "{:<12} {:>16} {:>14}   [{}, {}]{}",
            label,
            sig(e.value, 10),
            sig(e.stderr, 4),
            sig(e.ci95[0], 8),
            sig(e.ci95[1], 8),
            own_dof(s.dof, e)
        )?;
    }
    Ok(())
}

/// The table's lines after the estimates: residual, iterations, noise, correlation,
/// covariance and warnings.
pub(super) fn print_statistics(w: &mut impl Write, r: &Summary) -> Result<()> {
    writeln!(w)?;
    writeln!(
        w,
        "residual RMS {}   ({} degrees of freedom; intervals: value -+ {} standard errors, Student's t, unless noted)",
        sig(r.rms, 6),
        r.dof,
        sig(r.t_quantile, 6)
    )?;
    writeln!(
        w,
        "{} iterations, {} model evaluations: {}",
        r.iterations, r.evaluations, r.termination
    )?;
    if let Some(n) = &r.noise {
        writeln!(
            w,
            "noise estimated in the record: position {}, force {} (standard deviations); {}",
            sig(n.position, 4),
            sig(n.force, 4),
            n.handling.describe()
        )?;
    }
    if r.estimates.len() > 1 {
        print_correlation(w, r)?;
    }
    writeln!(w, "standard errors: {}", r.covariance.describe())?;
    for warning in r.warnings {
        writeln!(w, "warning: {}", warning_text(warning))?;
    }
    Ok(())
}

/// The lines naming the files written (`--csv`, `--plot`; `times`: the CSV has a column t).
pub(super) fn print_written(w: &mut impl Write, args: &super::FitArgs, times: bool) -> Result<()> {
    if let Some(csv) = &args.output.csv {
        writeln!(
            w,
            "\nWrote the data, fit and residuals ({}u,F,fit,residual) to {}",
            if times { "t," } else { "" },
            csv.display()
        )?;
    }
    if let Some(plot) = &args.plot.path {
        writeln!(
            w,
            "Drew the data, the fit and the residuals to {}",
            plot.display()
        )?;
    }
    Ok(())
}

/// The line `fixed: name = value, ...` (nothing without held parameters).
pub(super) fn write_fixed(
    w: &mut impl Write,
    fixed: impl Iterator<Item = (String, f64)>,
) -> Result<()> {
    let fixed: Vec<String> = fixed
        .map(|(n, v)| format!("{n} = {}", sig(v, 10)))
        .collect();
    if !fixed.is_empty() {
        writeln!(w, "fixed: {}", fixed.join(", "))?;
    }
    Ok(())
}

/// A warning of the core, with the flag that does what it suggests.
pub(super) fn warning_text(warning: &FitWarning) -> String {
    match warning {
        FitWarning::Misfit { slow: true, .. } | FitWarning::Structured { slow: true, .. } => {
            format!("{warning} (--fit full)")
        }
        FitWarning::AtBound { name, bound } if *bound == 0.0 => {
            format!("{warning} (--fix {name}=0)")
        }
        _ => warning.to_string(),
    }
}

fn print_correlation(w: &mut impl Write, r: &Summary) -> Result<()> {
    writeln!(
        w,
        "correlation of the estimates (condition number of the scaled J^T J: {}):",
        sig(r.condition_number, 3)
    )?;
    for (row, label) in r.correlation.iter().zip(&r.labels) {
        let cells: Vec<String> = row.iter().map(|c| format!("{c:>7.3}")).collect();
        writeln!(w, "  {:<12} {}", label, cells.join(" "))?;
    }
    Ok(())
}

/// The note after an estimate's row: at its bound, or an interval whose t has fewer degrees of
/// freedom than the fit's (S4).
fn own_dof(dof: usize, e: &Estimate) -> String {
    if e.at_bound {
        "  (at its bound)".to_string()
    } else if e.dof < dof as f64 - 0.5 {
        format!("  (t on {:.1} degrees of freedom)", e.dof)
    } else {
        String::new()
    }
}

/// `{"parameters": {name: {"value", "stderr", "dof", "ci95": [lo, hi], "at_bound"}}, "rms",
/// "iterations", ...}` (keys may be added, never renamed).
pub(super) fn write_json<W: Write>(
    mut j: JsonOut<W>,
    r: &FitReport,
    path: &Path,
    normal: bool,
) -> std::io::Result<()> {
    let summary = Summary::of(r, normal);
    write_json_head(&mut j, &summary)?;
    j.raw(&format!(
        ",\"model\":{},\"fit\":{}",
        quote(&r.family.label().to_ascii_lowercase()),
        quote(r.kind.label())
    ))?;
    j.raw(",\"fixed\":{")?;
    for (k, (n, v)) in r.fixed.iter().enumerate() {
        if k > 0 {
            j.raw(",")?;
        }
        j.raw(&quote(key(n, normal)))?;
        j.raw(":")?;
        num_or_null(&mut j, *v)?;
    }
    j.raw("}")?;
    write_json_tail(j, &summary, path, normal)
}

/// The document's start: `{"parameters": {...}, "rms", "iterations", "evaluations", "starts",
/// "converged", "termination"`.
pub(super) fn write_json_head<W: Write>(j: &mut JsonOut<W>, r: &Summary) -> std::io::Result<()> {
    j.raw("{\"parameters\":{")?;
    for (k, (e, key)) in r.estimates.iter().zip(&r.keys).enumerate() {
        if k > 0 {
            j.raw(",")?;
        }
        j.raw(&quote(key))?;
        j.raw(":{\"value\":")?;
        num_or_null(j, e.value)?;
        j.raw(",\"stderr\":")?;
        num_or_null(j, e.stderr)?;
        j.raw(",\"dof\":")?;
        num_or_null(j, e.dof)?;
        j.raw(",\"ci95\":[")?;
        num_or_null(j, e.ci95[0])?;
        j.raw(",")?;
        num_or_null(j, e.ci95[1])?;
        j.raw(&format!("],\"at_bound\":{}}}", e.at_bound))?;
    }
    j.raw("},\"rms\":")?;
    num_or_null(j, r.rms)?;
    j.raw(",\"iterations\":")?;
    j.int(r.iterations)?;
    j.raw(",\"evaluations\":")?;
    j.int(r.evaluations)?;
    j.raw(",\"starts\":")?;
    j.int(r.starts)?;
    j.raw(&format!(
        ",\"converged\":{},\"termination\":{}",
        r.converged,
        quote(r.termination)
    ))
}

/// The document's end: `"samples", "dof", ..., "covariance", "normal_force", "input"}`.
pub(super) fn write_json_tail<W: Write>(
    mut j: JsonOut<W>,
    r: &Summary,
    path: &Path,
    normal: bool,
) -> std::io::Result<()> {
    j.raw(",\"samples\":")?;
    j.int(r.samples)?;
    j.raw(",\"dof\":")?;
    j.int(r.dof)?;
    j.raw(",\"t_quantile\":")?;
    num_or_null(&mut j, r.t_quantile)?;
    j.raw(",\"condition_number\":")?;
    num_or_null(&mut j, r.condition_number)?;
    j.raw(",\"correlation\":")?;
    write_matrix(&mut j, r.correlation)?;
    if let Some(n) = r.turning_points {
        j.raw(",\"turning_points\":")?;
        j.int(n)?;
    }
    if let Some(n) = r.noise {
        write_noise(&mut j, n)?;
    }
    j.raw(",\"warnings\":[")?;
    for (k, warning) in r.warnings.iter().enumerate() {
        if k > 0 {
            j.raw(",")?;
        }
        j.raw(&quote(&warning_text(warning)))?;
    }
    j.raw("]")?;
    j.raw(&format!(
        ",\"covariance\":{{\"method\":{},\"description\":{}",
        quote(r.covariance.key()),
        quote(&r.covariance.describe())
    ))?;
    if let Covariance::NeweyWest { lags } = r.covariance {
        j.raw(",\"lags\":")?;
        j.int(lags)?;
    }
    j.raw(",\"lag1_autocorrelation\":")?;
    num_or_null(&mut j, r.serial.lag1)?;
    j.raw(",\"ljung_box\":")?;
    num_or_null(&mut j, r.serial.ljung_box)?;
    j.raw(",\"ljung_box_95\":")?;
    num_or_null(&mut j, r.serial.critical)?;
    j.raw("}")?;
    j.raw(&format!(",\"normal_force\":{normal}"))?;
    j.raw(",\"input\":")?;
    j.raw(&quote(&path.display().to_string()))?;
    j.raw("}\n")?;
    j.finish()
}

/// `,"noise": {"position", "force", "handling", "description"[, "lambda" | "gate"]}`.
fn write_noise<W: Write>(j: &mut JsonOut<W>, n: &NoiseLevels) -> std::io::Result<()> {
    j.raw(",\"noise\":{\"position\":")?;
    num_or_null(j, n.position)?;
    j.raw(",\"force\":")?;
    num_or_null(j, n.force)?;
    j.raw(&format!(
        ",\"handling\":{},\"description\":{}",
        quote(n.handling.key()),
        quote(&n.handling.describe())
    ))?;
    match n.handling {
        PositionHandling::Smoothed { lambda } => {
            j.raw(",\"lambda\":")?;
            num_or_null(j, lambda)?;
        }
        PositionHandling::Gate { gate } => {
            j.raw(",\"gate\":")?;
            num_or_null(j, gate)?;
        }
        _ => {}
    }
    j.raw("}")
}

/// The JSON document of [`write_json`] as a value, for the lab's fits to add their keys to.
pub(super) fn json_value(r: &FitReport, path: &Path, normal: bool) -> Result<serde_json::Value> {
    let mut text = Vec::new();
    write_json(JsonOut::new(&mut text), r, path, normal)?;
    Ok(serde_json::from_slice(&text)?)
}

/// `s` as a JSON string.
pub(super) fn quote(s: &str) -> String {
    serde_json::Value::from(s).to_string()
}

/// `x`, or `null` when it is not finite (JSON has no NaN or infinity).
pub(super) fn num_or_null<W: Write>(j: &mut JsonOut<W>, x: f64) -> std::io::Result<()> {
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
