//! `lugre.fit(kind="stribeck" | "presliding" | "staged")`: the lab's experiments (core
//! `lugre::fit::{find_plateaus, fit_stribeck, fit_presliding, fit_staged}`, the engine of
//! `lugre fit --fit stribeck|presliding|staged`).
//!
//! The records come as the positional `u, f` with `t` (or `v`), or, for the stages of the
//! staged fit, as the keywords `stribeck=` and `presliding=`: a mapping by role (the columns
//! `lugre.read` returns: "t", "u" or "v", "F") or a tuple `(t, u, F)` (a table of runs:
//! `(v, F)`).

use lugre::fit::{
    find_plateaus, fit_presliding, fit_staged, fit_stribeck, table_points, FitError, FitKind,
    FitReport, FitSpec, Motion, Plateaus, StagedReport, SteadyPoint, CUBIC_READING_TOL,
};
use lugre::simulate::SmoothSamples;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyMapping, PyString};

use super::{explain, report_dict, FLOATS_PER_SAMPLE};
use crate::convert::{floats, try_vec, type_name, value_error, vec_out};

/// The arguments of `lugre.fit` a lab fit reads besides the request (`None`: not given).
pub(super) struct Args<'py> {
    pub u: Option<Bound<'py, PyAny>>,
    pub f: Option<Bound<'py, PyAny>>,
    pub t: Option<Bound<'py, PyAny>>,
    pub v: Option<Bound<'py, PyAny>>,
    pub stribeck: Option<Bound<'py, PyAny>>,
    pub presliding: Option<Bound<'py, PyAny>>,
    /// The options of the other fits, refused by name: `x0`, `starts`, `interpolate`,
    /// `normal`.
    pub others: [(&'static str, Option<Bound<'py, PyAny>>); 6],
}

/// Whether `kind` is one of the lab's fits.
pub(super) fn is_lab(kind: FitKind) -> bool {
    matches!(
        kind,
        FitKind::Stribeck | FitKind::Presliding | FitKind::Staged
    )
}

/// `stribeck=` and `presliding=` name the staged fit's records: refused with another kind.
pub(super) fn refuse_records(
    kind: FitKind,
    records: [(&str, Option<&Bound<'_, PyAny>>); 2],
) -> PyResult<()> {
    for (name, given) in records {
        if given.is_some_and(|o| !o.is_none()) {
            return Err(PyValueError::new_err(format!(
                "{name} is a record of the staged fit (kind='staged'), not of kind='{}'",
                kind.label()
            )));
        }
    }
    Ok(())
}

/// The columns of one record, as given (`name`: the argument, "" for the positional ones).
struct Columns {
    name: &'static str,
    t: Option<Vec<f64>>,
    u: Option<Vec<f64>>,
    v: Option<Vec<f64>>,
    f: Vec<f64>,
}

impl Columns {
    /// `what` of this record in messages: "u", or "stribeck['u']".
    fn label(&self, what: &str) -> String {
        if self.name.is_empty() {
            what.to_string()
        } else {
            format!("{}['{what}']", self.name)
        }
    }

    /// A core error about this record's data, naming the argument it came from.
    fn error(&self, e: FitError) -> PyErr {
        if self.name.is_empty() {
            value_error(e)
        } else {
            PyValueError::new_err(format!("{}: {e}", self.name))
        }
    }

    fn len(&self) -> usize {
        self.f.len()
    }
}

/// A 1-D array argument.
fn column(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<f64>> {
    floats(obj, name)?.one_dimensional(name, obj)
}

fn optional_column(obj: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<Option<Vec<f64>>> {
    obj.filter(|o| !o.is_none())
        .map(|o| column(o, name))
        .transpose()
}

/// The positional record `u, f` with `t` and `v`.
fn positional(a: &Args<'_>) -> PyResult<Columns> {
    let Some(f) = &a.f else {
        return Err(PyTypeError::new_err(
            "f must be the measured friction force, got None",
        ));
    };
    Ok(Columns {
        name: "",
        t: optional_column(a.t.as_ref(), "t")?,
        u: optional_column(a.u.as_ref(), "u")?,
        v: optional_column(a.v.as_ref(), "v")?,
        f: column(f, "f")?,
    })
}

/// A keyword record: a mapping by role ("t", "u" or "v", "F"; `lugre.read`'s columns) or a
/// tuple `(t, u, F)`, or `(v, F)` where `table` allows a table of runs.
fn keyword(obj: &Bound<'_, PyAny>, name: &'static str, table: bool) -> PyResult<Columns> {
    let expected = if table {
        "a record (t, u, F), a table (v, F) or a mapping of columns by role (lugre.read)"
    } else {
        "a record (t, u, F) or a mapping of columns by role (lugre.read)"
    };
    let bad = |what: String| PyTypeError::new_err(format!("{name} must be {expected}, got {what}"));
    if let Ok(m) = obj.cast::<PyMapping>() {
        let get = |role: &str| -> PyResult<Option<Vec<f64>>> {
            match m.contains(role)? {
                true => optional_column(Some(&m.get_item(role)?), &format!("{name}['{role}']")),
                false => Ok(None),
            }
        };
        let Some(f) = get("F")? else {
            return Err(PyValueError::new_err(format!(
                "{name} has no force column 'F' (its keys must name the roles t, u or v, F)"
            )));
        };
        return Ok(Columns {
            name,
            t: get("t")?,
            u: get("u")?,
            v: get("v")?,
            f,
        });
    }
    if obj.is_instance_of::<PyString>() {
        return Err(bad(type_name(obj)));
    }
    let parts: Vec<Bound<'_, PyAny>> = obj
        .try_iter()
        .map_err(|_| bad(type_name(obj)))?
        .collect::<PyResult<_>>()?;
    let at = |i: usize| column(&parts[i], &format!("{name}[{i}]"));
    match parts.len() {
        3 => Ok(Columns {
            name,
            t: Some(at(0)?),
            u: Some(at(1)?),
            v: None,
            f: at(2)?,
        }),
        2 if table => Ok(Columns {
            name,
            t: None,
            u: None,
            v: Some(at(0)?),
            f: at(1)?,
        }),
        n => Err(PyValueError::new_err(format!(
            "{name} must be {expected}, got {n} columns"
        ))),
    }
}

/// The motion of a record: its displacement `u` or its velocity `v`, not both.
fn motion(c: &Columns) -> PyResult<Option<(&[f64], Motion)>> {
    match (&c.u, &c.v) {
        (Some(_), Some(_)) => Err(PyValueError::new_err(format!(
            "give the displacement {} or the velocity {}, not both",
            c.label("u"),
            c.label("v")
        ))),
        (Some(u), None) => Ok(Some((u, Motion::Displacement))),
        (None, Some(v)) => Ok(Some((v, Motion::Velocity))),
        (None, None) => Ok(None),
    }
}

/// The constant-velocity data of a Stribeck fit: its points and, for a record, the plateaus
/// found in it with its times.
struct Steady {
    points: Vec<SteadyPoint>,
    plateaus: Option<(Plateaus, Vec<f64>)>,
}

/// The points of a record `(t, u, F)` / `(t, v, F)` (found by [`find_plateaus`]) or of a table
/// `(v, F)` (without `t`).
fn steady(c: &Columns) -> PyResult<Steady> {
    let Some((x, kind)) = motion(c)? else {
        return Err(PyValueError::new_err(format!(
            "the Stribeck fit needs the motion: the displacement {} with the times {}, or the velocity {} (with {}: a record; without: a table of runs)",
            c.label("u"),
            c.label("t"),
            c.label("v"),
            c.label("t")
        )));
    };
    match (&c.t, kind) {
        (Some(t), _) => {
            let found = find_plateaus(t, x, &c.f, kind).map_err(|e| c.error(e))?;
            Ok(Steady {
                points: found.points(),
                plateaus: Some((found, t.clone())),
            })
        }
        (None, Motion::Velocity) => Ok(Steady {
            points: table_points(x, &c.f).map_err(|e| c.error(e))?,
            plateaus: None,
        }),
        (None, Motion::Displacement) => Err(PyValueError::new_err(format!(
            "a record of displacements {} needs the samples' times: give {} (a table of runs is the velocity {} with the force)",
            c.label("u"),
            c.label("t"),
            c.label("v")
        ))),
    }
}

/// A timed record `(t, u, F)` (a velocity record integrated from u = 0, as `lugre fit` reads
/// `t,v,F`): the times, the displacement.
fn timed(c: &Columns, fit: &str) -> PyResult<(Vec<f64>, Vec<f64>)> {
    let Some(t) = c.t.clone() else {
        return Err(PyValueError::new_err(format!(
            "the {fit} fit needs the samples' times: give {}",
            c.label("t")
        )));
    };
    match motion(c)? {
        Some((u, Motion::Displacement)) => Ok((t, u.to_vec())),
        Some((v, Motion::Velocity)) => {
            let m = SmoothSamples::from_velocity(t.clone(), v.to_vec(), 0.0, CUBIC_READING_TOL)
                .map_err(|e| c.error(e.into()))?;
            Ok((t, m.samples().1.to_vec()))
        }
        None => Err(PyValueError::new_err(format!(
            "the {fit} fit needs the motion: give the displacement {} (or the velocity {})",
            c.label("u"),
            c.label("v")
        ))),
    }
}

/// Options of the other fits, refused by name (as `lugre fit` refuses --x0, --starts,
/// --interpolate cubic and --columns N=... for these fits).
fn refuse_options(kind: FitKind, a: &Args<'_>) -> PyResult<()> {
    for (name, value) in &a.others {
        if value.as_ref().is_some_and(|v| !v.is_none()) {
            let whose = if *name == "normal" {
                "the slow and full fits"
            } else {
                "the full fit"
            };
            return Err(PyValueError::new_err(format!(
                "{name} applies to {whose}, not to kind='{}'",
                kind.label()
            )));
        }
    }
    Ok(())
}

/// Reserves the fit's working memory for `n` samples before the core allocates.
fn reserve(n: usize) -> PyResult<()> {
    drop(try_vec::<[f64; FLOATS_PER_SAMPLE]>(n)?);
    Ok(())
}

/// `lugre.fit` for the lab's fits (see `lugre.fit`'s docs).
pub(super) fn fit<'py>(
    py: Python<'py>,
    kind: FitKind,
    spec: &FitSpec,
    a: Args<'py>,
) -> PyResult<Bound<'py, PyDict>> {
    refuse_options(kind, &a)?;
    if kind != FitKind::Staged {
        refuse_records(
            kind,
            [
                ("stribeck", a.stribeck.as_ref()),
                ("presliding", a.presliding.as_ref()),
            ],
        )?;
    }
    match kind {
        FitKind::Stribeck => {
            let c = positional(&a)?;
            reserve(c.len())?;
            let s = steady(&c)?;
            let r = py
                .detach(|| fit_stribeck(spec, &s.points))
                .map_err(|e| explain(py, e))?;
            super::warn_unconverged(py, &r)?;
            stribeck_dict(py, &r, spec, &s)
        }
        FitKind::Presliding => {
            let c = positional(&a)?;
            let (t, u) = timed(&c, "presliding")?;
            reserve(c.len())?;
            let r = py
                .detach(|| fit_presliding(spec, &t, &u, &c.f))
                .map_err(|e| explain(py, e))?;
            super::warn_unconverged(py, &r)?;
            report_dict(py, &r, spec, &c.f, false)
        }
        _ => staged(py, spec, a),
    }
}

/// The staged fit: `stribeck=`, `presliding=` and, optionally, the positional record of the
/// final full fit.
fn staged<'py>(py: Python<'py>, spec: &FitSpec, a: Args<'py>) -> PyResult<Bound<'py, PyDict>> {
    let (Some(sk), Some(pk)) = (&a.stribeck, &a.presliding) else {
        return Err(PyValueError::new_err(
            "kind='staged' needs stribeck= (constant-velocity runs: (t, u, F), (v, F) or lugre.read's columns) and presliding= (a presliding test: (t, u, F)); u, f with t add a final full fit of a rate-dependent record",
        ));
    };
    let s = steady(&keyword(sk, "stribeck", true)?)?;
    let pc = keyword(pk, "presliding", false)?;
    let (tp, up) = timed(&pc, "presliding")?;
    let given = [&a.u, &a.v, &a.t, &a.f];
    let full = if given.iter().all(|o| o.is_none()) {
        None
    } else {
        let c = positional(&a)?;
        let (t, u) = timed(&c, "final full")?;
        let m = SmoothSamples::pchip(t, u, CUBIC_READING_TOL).map_err(|e| c.error(e.into()))?;
        Some((m, c.f))
    };
    reserve(pc.len() + full.as_ref().map_or(0, |(_, f)| f.len()))?;
    let r = py
        .detach(|| {
            fit_staged(
                spec,
                &s.points,
                (&tp, &up, &pc.f),
                full.as_ref().map(|(m, f)| (m, &f[..])),
            )
        })
        .map_err(|e| stage_error(py, e))?;
    for rep in [&r.stribeck, &r.presliding].into_iter().chain(&r.full) {
        super::warn_unconverged(py, rep)?;
    }
    staged_dict(py, &r, spec, &s, &pc.f, full.as_ref().map(|(_, f)| &f[..]))
}

/// A stage's error as `lugre.fit` words it, after the stage's name.
fn stage_error(py: Python<'_>, e: FitError) -> PyErr {
    let FitError::InStage { stage, error } = e else {
        return explain(py, e);
    };
    let inner = explain(py, *error);
    let err = PyValueError::new_err(format!("{stage} stage: {}", inner.value(py)));
    // The names of the parameters the data cannot determine, as `explain` attaches them.
    if let Ok(names) = inner.value(py).getattr("parameters") {
        if let Err(other) = err.value(py).setattr("parameters", names) {
            return other;
        }
    }
    err
}

/// The Stribeck fit's dict: the report's, its "fitted" and "residuals" at the points, with
/// "points" (the points' columns) and, for a record, "plateaus".
fn stribeck_dict<'py>(
    py: Python<'py>,
    r: &FitReport,
    spec: &FitSpec,
    s: &Steady,
) -> PyResult<Bound<'py, PyDict>> {
    let f: Vec<f64> = s.points.iter().map(|p| p.f).collect();
    let d = report_dict(py, r, spec, &f, false)?;
    d.set_item("points", points_dict(py, s)?)?;
    d.set_item(
        "plateaus",
        match &s.plateaus {
            Some((found, t)) => Some(plateaus_dict(py, found, t)?),
            None => None,
        },
    )?;
    Ok(d)
}

/// `{"v", "F", "stderr"}`: float64 arrays, "stderr" None for a table.
fn points_dict<'py>(py: Python<'py>, s: &Steady) -> PyResult<Bound<'py, PyDict>> {
    let column = |get: fn(&SteadyPoint) -> f64| s.points.iter().map(get).collect::<Vec<f64>>();
    let d = PyDict::new(py);
    d.set_item("v", vec_out(py, column(|p| p.v)))?;
    d.set_item("F", vec_out(py, column(|p| p.f)))?;
    let stderr: Option<Vec<f64>> = s.points.iter().map(|p| p.stderr).collect();
    d.set_item("stderr", stderr.map(|e| vec_out(py, e)))?;
    Ok(d)
}

/// `{"skipped", "velocity_noise", "runs": {"v", "F", "stderr", "sd", "samples", "t_start",
/// "t_end"}}` (the keys of `lugre fit --json`, the runs as columns).
fn plateaus_dict<'py>(
    py: Python<'py>,
    found: &Plateaus,
    t: &[f64],
) -> PyResult<Bound<'py, PyDict>> {
    let p = &found.plateaus;
    let column =
        |get: &dyn Fn(&lugre::fit::Plateau) -> f64| -> Vec<f64> { p.iter().map(get).collect() };
    let runs = PyDict::new(py);
    runs.set_item("v", vec_out(py, column(&|q| q.v)))?;
    runs.set_item("F", vec_out(py, column(&|q| q.f)))?;
    runs.set_item("stderr", vec_out(py, column(&|q| q.stderr)))?;
    runs.set_item("sd", vec_out(py, column(&|q| q.f_sd)))?;
    let samples: Vec<u64> = p.iter().map(|q| (q.steady.1 - q.steady.0) as u64).collect();
    runs.set_item("samples", numpy::IntoPyArray::into_pyarray(samples, py))?;
    runs.set_item("t_start", vec_out(py, column(&|q| t[q.steady.0])))?;
    runs.set_item("t_end", vec_out(py, column(&|q| t[q.steady.1 - 1])))?;
    let d = PyDict::new(py);
    d.set_item("skipped", found.skipped)?;
    d.set_item("velocity_noise", found.velocity_noise)?;
    d.set_item("runs", runs)?;
    Ok(d)
}

/// The staged fit's dict: "parameters" with each one's "stage", "fixed", "values" (the
/// identified model), and "stages": each stage's dict as its own kind returns it (without
/// "values": a stage alone is not the model).
fn staged_dict<'py>(
    py: Python<'py>,
    r: &StagedReport,
    spec: &FitSpec,
    s: &Steady,
    f_presliding: &[f64],
    f_full: Option<&[f64]>,
) -> PyResult<Bound<'py, PyDict>> {
    let parameters = PyDict::new(py);
    for (e, stage) in &r.estimates {
        let d = PyDict::new(py);
        d.set_item("value", e.value)?;
        d.set_item("stderr", e.stderr)?;
        d.set_item("ci95", (e.ci95[0], e.ci95[1]))?;
        d.set_item("at_bound", e.at_bound)?;
        d.set_item("stage", stage.label())?;
        parameters.set_item(e.name, d)?;
    }
    let fixed = PyDict::new(py);
    for (name, v) in &r.fixed {
        fixed.set_item(name, *v)?;
    }
    // Every parameter is either estimated by a stage or held: together, the model.
    let mut all: Vec<(&str, f64)> = r
        .estimates
        .iter()
        .map(|(e, _)| (e.name, e.value))
        .chain(r.fixed.iter().copied())
        .collect();
    let order = spec.family().parameters();
    all.sort_by_key(|(n, _)| order.iter().position(|o| o == n));
    let values = PyDict::new(py);
    for (name, v) in all {
        values.set_item(name, v)?;
    }
    let stages = PyDict::new(py);
    let stribeck = stribeck_dict(py, &r.stribeck, spec, s)?;
    let presliding = report_dict(py, &r.presliding, spec, f_presliding, false)?;
    stages.set_item(FitKind::Stribeck.label(), stribeck)?;
    stages.set_item(FitKind::Presliding.label(), presliding)?;
    if let (Some(full), Some(f)) = (&r.full, f_full) {
        stages.set_item(
            FitKind::Full.label(),
            report_dict(py, full, spec, f, false)?,
        )?;
    }
    for (_, stage) in stages.iter() {
        stage.del_item("values")?;
    }
    let d = PyDict::new(py);
    d.set_item("parameters", parameters)?;
    d.set_item("fixed", fixed)?;
    d.set_item("values", values)?;
    d.set_item("stages", stages)?;
    d.set_item("model", "lugre")?;
    d.set_item("kind", FitKind::Staged.label())?;
    Ok(d)
}
