//! `lugre.fit(u, f, model="bouc-wen")` or `model=lugre.ZooModel(...)`: the slow-loop fit of a
//! model of the zoo (core `lugre::fit::fit_zoo`, the engine of `lugre fit --model NAME`), or,
//! with `kind="full"` and `t`, the full fit of a model with a finite-rate form
//! (`lugre::fit::fit_zoo_full`, `lugre fit --model NAME --fit full`). A model object's values
//! are the start values (and an element model's thresholds); a name starts every parameter
//! from the data.

use lugre::fit::{
    fit_zoo, fit_zoo_full, FitError, FitKind, FullOptions, Noise, SlowOptions, ZooFitReport,
    ZooFitSpec,
};
use lugre::zoo::{Shape, ZooModelSpec};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyMapping, PyString};

use super::{explain, items, names, noise_arg, summary_items, unidentifiable, FLOATS_PER_SAMPLE};
use crate::convert::{count, floats, real, try_vec, value_error, vec_out};
use crate::zoo::PyZooModel;

/// The request for `model`, if it names a model of the zoo or is a `lugre.ZooModel`.
pub(super) fn spec_of(model: Option<&Bound<'_, PyAny>>) -> PyResult<Option<ZooFitSpec>> {
    let Some(m) = model else {
        return Ok(None);
    };
    if let Ok(z) = m.cast::<PyZooModel>() {
        let z = z.get().model();
        let mut spec = ZooFitSpec::new(z.spec().name).map_err(value_error)?;
        for (name, values) in z.named() {
            spec = spec.set(name, &values).map_err(value_error)?;
        }
        return Ok(Some(spec));
    }
    let Ok(s) = m.cast::<PyString>() else {
        return Ok(None);
    };
    let name = s.to_cow()?;
    Ok(ZooModelSpec::find(&name).and_then(|spec| ZooFitSpec::new(spec.name).ok()))
}

/// `kind` for a model of the zoo: "slow" (default) or "full"; a full fit of a model without a
/// finite-rate form refused with the core's message, in the keyword's terms.
pub(super) fn kind_of(spec: &ZooFitSpec, kind: Option<&Bound<'_, PyAny>>) -> PyResult<FitKind> {
    let Some(k) = kind else {
        return Ok(FitKind::Slow);
    };
    let kind = super::kind_arg(k)?;
    if !matches!(kind, FitKind::Slow | FitKind::Full) {
        return Err(PyValueError::new_err(format!(
            "kind={}: the {} model is fitted to its slow loop (kind='slow') or, with a finite-rate form, to a rate-dependent record (kind='full')",
            k.repr()?,
            spec.model().label
        )));
    }
    if kind == FitKind::Full {
        spec.check_finite_rate().map_err(|e| {
            PyValueError::new_err(
                e.to_string()
                    .replace("--fit full", "kind='full'")
                    .replace("--fit slow", "kind='slow'"),
            )
        })?;
    }
    Ok(kind)
}

/// The keywords of `lugre.fit` the zoo fit reads (`None`: not given).
pub(super) struct Args<'py> {
    pub kind: FitKind,
    /// The full fit's times, start state and number of starts.
    pub t: Option<Bound<'py, PyAny>>,
    pub x0: Option<Bound<'py, PyAny>>,
    pub starts: Option<Bound<'py, PyAny>>,
    pub fix: Option<Bound<'py, PyAny>>,
    pub free: Option<Bound<'py, PyAny>>,
    pub start: Option<Bound<'py, PyAny>>,
    pub elements: Option<Bound<'py, PyAny>>,
    pub noise: Option<Bound<'py, PyAny>>,
    pub gate: Option<Bound<'py, PyAny>>,
    /// The keywords of the LuGre fits, refused by name.
    pub others: Vec<(&'static str, Option<Bound<'py, PyAny>>)>,
}

/// One value or a list of them (an element model's arrays).
fn values(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<f64>> {
    if obj.is_instance_of::<PyString>()
        || obj.cast::<PyMapping>().is_ok()
        || obj.try_iter().is_err()
    {
        return Ok(vec![real(obj, name)?]);
    }
    floats(obj, name)?.one_dimensional(name, obj)
}

/// The request from the keywords, as `lugre fit --model NAME` builds it from its flags.
fn build(mut spec: ZooFitSpec, args: &Args<'_>) -> PyResult<ZooFitSpec> {
    let label = spec.model().label;
    if let Some((name, _)) = args.others.iter().find(|(_, v)| v.is_some()) {
        return Err(PyValueError::new_err(match (*name, args.kind) {
            ("x0" | "starts", FitKind::Slow) => {
                format!("{name} applies to the full fit (add kind='full')")
            }
            ("gate", _) => "gate applies to the slow fit (kind='slow'): the full fit simulates every turn of the input".to_string(),
            (_, FitKind::Full) => format!(
                "{name} does not apply to the {label} full fit (of t, u and f; its bounds are the parameters' domains)"
            ),
            _ => format!(
                "{name} does not apply to the {label} fit (a slow-loop fit of u and f; its bounds are the parameters' domains)"
            ),
        }));
    }
    if let Some(start) = &args.start {
        for (name, value) in items(start, "start", "start value")? {
            let v = values(&value, &format!("start['{name}']"))?;
            spec = spec
                .set(&name, &v)
                .map_err(|e| PyValueError::new_err(format!("start: {e}")))?;
        }
    }
    if let Some(fix) = &args.fix {
        let held: Vec<(String, Option<Vec<f64>>)> = if fix.cast::<PyMapping>().is_ok() {
            items(fix, "fix", "value")?
                .into_iter()
                .map(|(n, v)| values(&v, &format!("fix['{n}']")).map(|v| (n, Some(v))))
                .collect::<PyResult<_>>()?
        } else {
            names(fix, "fix")?.into_iter().map(|n| (n, None)).collect()
        };
        for (name, value) in held {
            if let Some(v) = value {
                spec = spec
                    .set(&name, &v)
                    .map_err(|e| PyValueError::new_err(format!("fix: {e}")))?;
            }
            spec = spec
                .fix(&name)
                .map_err(|e| PyValueError::new_err(format!("fix: {e}")))?;
        }
    }
    if let Some(free) = &args.free {
        for name in names(free, "free")? {
            spec = spec
                .free(&name)
                .map_err(|e| PyValueError::new_err(format!("free: {e}")))?;
        }
    }
    if let Some(n) = &args.elements {
        let n = count(n, "elements")?;
        spec = spec.with_elements(usize::try_from(n).unwrap_or(usize::MAX));
    }
    Ok(spec)
}

/// The fit, detached from the interpreter, and its dict.
pub(super) fn fit<'py>(
    py: Python<'py>,
    spec: ZooFitSpec,
    u: &Bound<'py, PyAny>,
    f: &Bound<'py, PyAny>,
    args: Args<'py>,
) -> PyResult<Bound<'py, PyDict>> {
    let spec = build(spec, &args)?;
    let u = floats(u, "u")?.one_dimensional("u", u)?;
    let f = floats(f, "f")?.one_dimensional("f", f)?;
    let noise = args.noise.as_ref().map(noise_arg).transpose()?;
    let run = run_of(&args, noise)?;
    drop(try_vec::<[f64; FLOATS_PER_SAMPLE]>(u.len())?);
    let report = py
        .detach(|| match run {
            Run::Full { t, x0, starts } => {
                let mut options = FullOptions::default().with_x0(x0).with_starts(starts);
                if let Some(n) = noise {
                    options = options.with_noise(n);
                }
                fit_zoo_full(&spec, &t, &u, &f, options)
            }
            Run::Slow(options) => fit_zoo(&spec, &u, &f, options),
        })
        .map_err(|e| fit_error(py, e))?;
    report_dict(py, &report, &f)
}

/// The fit `args` ask for: the slow fit's options with `noise` and `gate`, or the full fit's
/// `t`, `x0` and `starts`.
fn run_of(args: &Args<'_>, noise: Option<Noise>) -> PyResult<Run> {
    if args.kind != FitKind::Full {
        let mut options = SlowOptions::default();
        if let Some(n) = noise {
            options = options.with_noise(n);
        }
        if let Some(g) = &args.gate {
            options = options.with_gate(real(g, "gate")?);
        }
        return Ok(Run::Slow(options));
    }
    let Some(t) = &args.t else {
        return Err(PyValueError::new_err(
            "a full fit needs the samples' times: give t (strictly increasing, one per sample)",
        ));
    };
    let t = floats(t, "t")?.one_dimensional("t", t)?;
    let x0 = args.x0.as_ref().map(|x| real(x, "x0")).transpose()?;
    let starts = match &args.starts {
        Some(n) => usize::try_from(count(n, "starts")?).unwrap_or(usize::MAX),
        None => FullOptions::DEFAULT_STARTS,
    };
    Ok(Run::Full {
        t,
        x0: x0.unwrap_or(0.0),
        starts,
    })
}

/// A zoo fit's error in the keywords' terms.
fn fit_error(py: Python<'_>, e: FitError) -> PyErr {
    match e {
        FitError::BadGate { .. } => PyValueError::new_err(format!("gate: {e}")),
        FitError::BadStarts { .. } => PyValueError::new_err(format!("starts: {e}")),
        FitError::BadElements { .. } => PyValueError::new_err(format!("elements: {e}")),
        FitError::Unidentifiable { ref parameters } => {
            let names: Vec<&str> = parameters.iter().map(|p| p.name).collect();
            unidentifiable(
                py,
                &e,
                &names,
                "hold a scalar at a value you know (fix={'NAME': value}), fit fewer elements (elements=N), or fit data that excite it".to_string(),
            )
        }
        e => explain(py, e),
    }
}

/// The slow fit's options, or the full fit's times, start state and number of starts (its
/// options are made where it runs: they may hold a progress callback, which stays there).
enum Run {
    Slow(SlowOptions),
    Full { t: Vec<f64>, x0: f64, starts: usize },
}

/// The report as a dict: the keys of the LuGre fit's, "values" the fitted model's parameters
/// by name (lugre.ZooModel(r["model"], **r["values"]) is the fitted model).
fn report_dict<'py>(py: Python<'py>, r: &ZooFitReport, f: &[f64]) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    summary_items(py, &d, &r.summary(), |name| name)?;
    let spec = r.model.spec();
    let value = |name: &str, v: &[f64]| -> Bound<'py, PyAny> {
        let scalar = spec
            .parameter(name)
            .is_some_and(|p| p.shape == Shape::Scalar);
        match v {
            [x] if scalar => x
                .into_pyobject(py)
                .map_or_else(|_| py.None().into_bound(py), |x| x.into_any()),
            _ => vec_out(py, v.to_vec()),
        }
    };
    let values = PyDict::new(py);
    for (name, v) in r.model.named() {
        values.set_item(name, value(name, &v))?;
    }
    let fixed = PyDict::new(py);
    for (name, v) in &r.fixed {
        fixed.set_item(*name, value(name, v))?;
    }
    d.set_item("values", values)?;
    d.set_item("fixed", fixed)?;
    d.set_item("model", spec.name)?;
    d.set_item("kind", r.kind.label())?;
    d.set_item("normal_force", false)?;
    let residuals: Vec<f64> = f.iter().zip(&r.fitted).map(|(f, y)| f - y).collect();
    d.set_item("residuals", vec_out(py, residuals))?;
    Ok(d)
}
