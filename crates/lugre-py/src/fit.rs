//! `lugre.fit`: parameter identification from measured data (core `lugre::fit`, the engine of
//! `lugre fit`), as a dict of numbers and numpy arrays.
//!
//! The request is built the way the command builds it from its flags: the model's values (the
//! paper's defaults, or those of a `LuGre`/`Dahl` object), start values (`FitSpec::set`), fixed
//! and freed parameters, bounds; the fit then runs detached from the interpreter.

use std::ffi::CString;

use lugre::error::NormalForceError;
use lugre::fit::{
    fit_full, fit_full_smooth, fit_slow_with, Covariance, Family, FitError, FitKind, FitReport,
    FitSpec, FitSummary, FitWarning, FullOptions, Noise, PositionHandling, SlowOptions, ZooFitSpec,
    CUBIC_READING_TOL,
};
use lugre::model::{normal as normal_force, Parameter};
use lugre::simulate::SmoothSamples;
use pyo3::exceptions::{PyRuntimeWarning, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyMapping, PyString, PyTuple};

use crate::convert::{
    array_out, count, float_repr, floats, real, try_vec, type_name, value_error, vec_out,
};
use crate::models::{PyDahl, PyLuGre};

mod lab;
mod zoo;

/// A rough upper estimate of the fit's working memory per sample, in floats (the Jacobian of
/// up to 7 columns and the optimizer's copies of it, the output, residuals and the simulation's
/// state), reserved once before the core allocates: a failed allocation there would abort the
/// interpreter.
const FLOATS_PER_SAMPLE: usize = 48;

/// Identifies the parameters of the LuGre or Dahl model from measured samples: the engine of
/// `lugre fit`.
///
/// * kind="slow" (default): sigma0 and g(0) = fs (Dahl: rho and fc) from one or more periods
///   of a slow periodic test, samples (u, f) (the record closes from its last sample back to
///   its first: trim start-up transients; sample the reversals themselves). The fit runs on
///   the closed-form hysteresis loop y° (eqs. 8-10) with the data's turning points; `t` is
///   optional and only checked (the loop depends on the turning points alone).
/// * kind="full": sigma0, sigma1, sigma2, fc, fs, vs (Dahl: rho, fc; beta stays fixed unless
///   freed) from rate-dependent samples (t, u, f), on the exact simulation of eq. 1 from the
///   initial state x0 (given, not fitted), from `starts` start points (the first from the
///   data, then sigma0 and vs scaled by 4 or 1/4); the best end point wins.
///
/// The lab's experiments (Canudas de Wit et al. 1995; Olsson et al. 1998), LuGre only, as
/// `lugre fit --fit stribeck|presliding|staged`:
///
/// * kind="stribeck": fc, fs, vs, sigma2 (free=["beta"] adds beta; sigma0, sigma1 do not
///   enter) from the steady-state curve F_ss(v) = g(v) sgn(v) + sigma2 v of constant-velocity
///   runs: a record (u, f, t=t), or (None, f, t=t, v=v), whose runs are found without help
///   (each point the mean force over a run's steady part, weighted by its standard error), or
///   a table of runs (None, f, v=v) without t (one velocity and steady force a run). beta is
///   held: give it (model=lugre.LuGre(beta=2) or fix={"beta": 2}). "fitted" and "residuals"
///   are at the points; "points" holds their columns {"v", "F", "stderr"} ("stderr" None for
///   a table) and "plateaus" the runs found in a record ({"skipped", "velocity_noise",
///   "runs": {"v", "F", "stderr", "sd", "samples", "t_start", "t_end"}}; None for a table).
/// * kind="presliding": sigma0, sigma1 from a presliding test (u, f, t=t) from rest (small
///   reversals below break-away), the Stribeck curve held at the model's values
///   (model=lugre.LuGre(fc=..., fs=..., vs=..., beta=..., sigma2=...), or fix={...}); a test
///   that breaks away raises ValueError.
/// * kind="staged": the two in turn, the second holding the first's curve, then, with (u, f,
///   t=t), a full fit of that rate-dependent record (read as the C1 cubic through its samples)
///   started from them. The stages' records are keywords: stribeck= (t, u, F), a table (v, F)
///   or the columns of lugre.read (a mapping by role "t", "u" or "v", "F"), and presliding=
///   (t, u, F) or lugre.read's columns; u and f are None without the final fit. The result:
///   "parameters" (each with the "stage" that determined it: "stribeck", "presliding" or
///   "full"), "fixed", "values" (the identified model), "model", "kind" and "stages" (each
///   stage's dict as its kind returns it, without "values").
///
/// The models of the zoo (as `lugre fit --model NAME`): model="maxwell-slip",
/// "prandtl-ishlinskii", "bouc-wen" or "elastoplastic", or a lugre.ZooModel (its values the
/// start values, an element model's thresholds its own), fits the model's slow loop (its exact
/// periodic loop through the record's turning points) to (u, f): every parameter of the loop,
/// an element model's weights as "stiffness[i]" or "weights[i]" with the thresholds held on a
/// grid spanning the record's amplitude (elements=N of them, default 4); fix, free, start (a
/// number, or a list for an element array), noise and gate as for LuGre; "values" is the fitted
/// model (lugre.ZooModel(r["model"], **r["values"])). The elasto-plastic fc, sigma1, sigma2,
/// vs, beta do not enter the slow loop: freeing one raises ValueError; the LuGre fits' other
/// keywords (t, bounds, x0, starts, interpolate, normal, v, stribeck, presliding) are refused.
/// kind="full" with t (as `lugre fit --model NAME --fit full`), for a model with a finite-rate
/// form ("maxwell-slip" as GMS, "elastoplastic"): every parameter of its table from a
/// rate-dependent record (t, u, f), on the model's exact path from rest at the record's rate,
/// from `starts` start points (x0, if given, must be 0); "turning_points" is None, as in the
/// LuGre full fit. A model without that form raises ValueError.
///
/// Arguments:
///
/// * u, f: the input and the measured friction force, equal-length sequences or arrays of
///   real numbers; t (keyword): the sample times, strictly increasing (needed by the full fit).
/// * model: "lugre" (default) or "dahl", or a lugre.LuGre / lugre.Dahl whose values the
///   parameters that are not fitted keep (default: the paper's, Dahl rho = fc = 1). Free
///   parameters start from the data either way.
/// * fix: parameter names held at the model's value (a name or a sequence of names), or a dict
///   name -> value held at that value (e.g. fix={"sigma2": 0}: a parameter whose value is 0
///   must be fixed, fitted parameters are positive).
/// * free: names fitted besides the default ones (e.g. free=["beta"] in a full fit).
/// * start: dict name -> start value of a free parameter (else it starts from the data, so no
///   guess is needed); a value given for a parameter that is not fitted is the value it keeps.
/// * bounds: dict name -> (lo, hi) with 0 <= lo < hi; hi may be math.inf (None: no bound on
///   that side). Default (0, inf): every parameter is positive.
/// * x0 (full fit only): the initial bristle deflection x(0) (Dahl: w(0) / rho); None: 0.
/// * starts (full fit only): the number of start points; None: 3.
///
/// Parameter names are those of the models' keyword arguments (sigma0, sigma1, sigma2, fc, fs,
/// vs, beta; Dahl rho, fc), case-insensitive.
///
/// Returns a dict:
///
/// * "parameters": {name: {"value", "stderr", "dof", "ci95": (lo, hi), "at_bound"}} for the
///   fitted parameters in the model's order (standard errors from the linearised covariance
///   s^2 (J^T J)^-1, or the Newey-West sandwich where the residuals are correlated, plus the
///   share of a smoothed displacement's error; 95 % intervals value -+ t * stderr with Student's
///   t on the estimate's own dof, m - p for the linearised covariance alone; at_bound: the
///   estimate sits on one of its bounds);
/// * "fixed": {name: value} of the parameters held (slow fit: only those of the loop);
/// * "values": every parameter of the fitted model, estimates included (for a slow LuGre fit
///   the parameters the loop does not depend on keep the model's values), so
///   lugre.LuGre(**r["values"]) (or lugre.Dahl) is the fitted model;
/// * "rms" (residual RMS), "samples", "dof", "t_quantile", "condition_number" (of the scaled
///   J^T J), "correlation" (float64 array, one row and column per fitted parameter, in the
///   order of "parameters"), "iterations", "evaluations", "starts", "converged",
///   "termination" (why the iteration stopped), "turning_points" (how many a slow fit found in
///   the data; None for a full fit), "model" ("lugre" or "dahl"), "kind" (its label);
/// * "fitted": the model's output at every sample and "residuals" = f - fitted (float64
///   arrays).
///
/// `v` (with `u=None` and `t`): a velocity record, integrated from u = 0 and read as the C1
/// cubic through the samples (as `lugre fit` reads `t,v,F`); the result's "u" holds the
/// displacement at the samples.
///
/// `normal` (one value per sample, > 0): fit the friction coefficient f / normal instead of the
/// force (as `lugre fit --columns N=NAME`): "parameters" and "fixed" then name Fc and Fs
/// "mu_c" and "mu_s", sigma0 is in 1/m and sigma1, sigma2 in s/m (per newton), "fitted" and
/// "residuals" are coefficients, "normal_force" is True; "values" keeps the model's names
/// (lugre.LuGre(**r["values"]) is the model per newton).
///
/// `noise` ("auto", default, or "off"): "auto" estimates the position and force noise from the
/// samples (third differences) and, in a full fit, reads an equally spaced noisy displacement
/// as the smooth motion nearest the samples (as `lugre fit --noise`); the result's "noise" is
/// {"position", "force", "handling", "description"} (estimated with "off" too, not used), and
/// "warnings" lists,
/// in words, why the estimates or intervals may not be trusted (a parameter at its bound, a
/// residual RMS above 1.3 times the estimated force noise, residuals with a lag-1
/// autocorrelation above 0.5). "covariance" says which covariance the standard errors come
/// from: {"method": "classical" or "newey-west", "lags", "description", "lag1_autocorrelation",
/// "ljung_box", "ljung_box_95"} (the sandwich when the Ljung-Box test finds the residuals
/// correlated).
///
/// `gate` (slow fit): the noise gate on the reversals, in units of u: a turn counts once the
/// input has come back from its extreme by at least gate (as `lugre fit --gate`); None: 8 times
/// the estimated position noise (0 with noise="off").
///
/// `interpolate="cubic"` (full fit): the samples of a smooth motion read as the C1 cubic through
/// them, subdivided to 1e-9 of their range (as `lugre fit --interpolate cubic`); the residual
/// stays at the samples.
///
/// A fit that ran out of evaluations at a usable point is returned with converged = False and
/// a RuntimeWarning. Every other failure raises ValueError with the message of `lugre fit`,
/// among them a parameter the data cannot determine (e.g. sigma1 from quasi-static data): the
/// message names every such parameter and why, and the exception's `parameters` attribute
/// holds their names. Arguments of the wrong type raise TypeError. The interpreter lock is
/// released while the fit runs.
///
/// >>> import numpy as np, lugre
/// >>> hl = lugre.LuGre(sigma0=6).loop_bimodal(0, 0.5, 1, 1.5)   # the paper's Example 4
/// >>> rho = np.linspace(0, hl.period, 401)
/// >>> r = lugre.fit(hl.u_at(rho), hl.y_at(rho))
/// >>> round(r["parameters"]["sigma0"]["value"], 9), round(r["parameters"]["fs"]["value"], 9)
/// (6.0, 2.0)
#[pyfunction]
#[pyo3(
    signature = (u, f, *, t=None, model=None, kind=None, fix=None, free=None, start=None, bounds=None, x0=None, starts=None, interpolate=None, normal=None, v=None, noise=None, gate=None, stribeck=None, presliding=None, elements=None),
    text_signature = "(u, f, *, t=None, model='lugre', kind='slow', fix=(), free=(), start=None, bounds=None, x0=None, starts=None, interpolate='linear', normal=None, v=None, noise='auto', gate=None, stribeck=None, presliding=None, elements=None)"
)]
#[allow(clippy::too_many_arguments)]
pub fn fit<'py>(
    py: Python<'py>,
    u: &Bound<'py, PyAny>,
    f: &Bound<'py, PyAny>,
    t: Option<&Bound<'py, PyAny>>,
    model: Option<&Bound<'py, PyAny>>,
    kind: Option<&Bound<'py, PyAny>>,
    fix: Option<&Bound<'py, PyAny>>,
    free: Option<&Bound<'py, PyAny>>,
    start: Option<&Bound<'py, PyAny>>,
    bounds: Option<&Bound<'py, PyAny>>,
    x0: Option<&Bound<'py, PyAny>>,
    starts: Option<&Bound<'py, PyAny>>,
    interpolate: Option<&Bound<'py, PyAny>>,
    normal: Option<&Bound<'py, PyAny>>,
    v: Option<&Bound<'py, PyAny>>,
    noise: Option<&Bound<'py, PyAny>>,
    gate: Option<&Bound<'py, PyAny>>,
    stribeck: Option<&Bound<'py, PyAny>>,
    presliding: Option<&Bound<'py, PyAny>>,
    elements: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let k = Keywords {
        t: given(t),
        model: given(model),
        kind: given(kind),
        fix: given(fix),
        free: given(free),
        start: given(start),
        bounds: given(bounds),
        x0: given(x0),
        starts: given(starts),
        interpolate: given(interpolate),
        normal: given(normal),
        v: given(v),
        noise: given(noise),
        gate: given(gate),
        stribeck: given(stribeck),
        presliding: given(presliding),
        elements: given(elements),
    };
    match zoo::spec_of(k.model.as_ref())? {
        Some(spec) => fit_zoo(py, spec, u, f, k),
        None => fit_lugre(py, u, f, k),
    }
}

/// The keywords of `lugre.fit` (`None`: not given, or given as None).
struct Keywords<'py> {
    t: Option<Bound<'py, PyAny>>,
    model: Option<Bound<'py, PyAny>>,
    kind: Option<Bound<'py, PyAny>>,
    fix: Option<Bound<'py, PyAny>>,
    free: Option<Bound<'py, PyAny>>,
    start: Option<Bound<'py, PyAny>>,
    bounds: Option<Bound<'py, PyAny>>,
    x0: Option<Bound<'py, PyAny>>,
    starts: Option<Bound<'py, PyAny>>,
    interpolate: Option<Bound<'py, PyAny>>,
    normal: Option<Bound<'py, PyAny>>,
    v: Option<Bound<'py, PyAny>>,
    noise: Option<Bound<'py, PyAny>>,
    gate: Option<Bound<'py, PyAny>>,
    stribeck: Option<Bound<'py, PyAny>>,
    presliding: Option<Bound<'py, PyAny>>,
    elements: Option<Bound<'py, PyAny>>,
}

/// An argument as given: Python's None reads as not given (the signature's defaults are None).
fn given<'py>(o: Option<&Bound<'py, PyAny>>) -> Option<Bound<'py, PyAny>> {
    o.filter(|o| !o.is_none()).cloned()
}

/// A model of the zoo (`lugre fit --model NAME`): its slow-loop or full fit.
fn fit_zoo<'py>(
    py: Python<'py>,
    spec: ZooFitSpec,
    u: &Bound<'py, PyAny>,
    f: &Bound<'py, PyAny>,
    k: Keywords<'py>,
) -> PyResult<Bound<'py, PyDict>> {
    let kind = zoo::kind_of(&spec, k.kind.as_ref())?;
    let full = kind == FitKind::Full;
    // The full fit's keywords, refused by name in the slow fit, and the slow fit's gate in
    // the full fit (as `lugre fit --model NAME` refuses the flags).
    let only = |full_only: bool, o: Option<Bound<'py, PyAny>>| {
        if full == full_only {
            (o, None)
        } else {
            (None, o)
        }
    };
    let (t, t_other) = only(true, k.t);
    let (x0, x0_other) = only(true, k.x0);
    let (starts, starts_other) = only(true, k.starts);
    let (gate, gate_other) = only(false, k.gate);
    let args = zoo::Args {
        kind,
        t,
        x0,
        starts,
        fix: k.fix,
        free: k.free,
        start: k.start,
        elements: k.elements,
        noise: k.noise,
        gate,
        others: vec![
            ("t", t_other),
            ("x0", x0_other),
            ("starts", starts_other),
            ("gate", gate_other),
            ("bounds", k.bounds),
            ("interpolate", k.interpolate),
            ("normal", k.normal),
            ("v", k.v),
            ("stribeck", k.stribeck),
            ("presliding", k.presliding),
        ],
    };
    zoo::fit(py, spec, u, f, args)
}

/// The LuGre or Dahl model: the request from the keywords, then the lab's fit or the slow or
/// full one.
fn fit_lugre<'py>(
    py: Python<'py>,
    u: &Bound<'py, PyAny>,
    f: &Bound<'py, PyAny>,
    k: Keywords<'py>,
) -> PyResult<Bound<'py, PyDict>> {
    if k.elements.is_some() {
        return Err(PyValueError::new_err(
            "elements applies to an element model of the zoo (model='maxwell-slip' or 'prandtl-ishlinskii', or a lugre.ZooModel of them)",
        ));
    }
    let kind = match &k.kind {
        Some(kind) => kind_arg(kind)?,
        None => FitKind::Slow,
    };
    let spec = build_spec(
        k.model.clone(),
        k.fix.clone(),
        k.free.clone(),
        k.start.clone(),
        k.bounds.clone(),
    )?;
    if lab::is_lab(kind) {
        fit_lab(py, kind, &spec, u, f, k)
    } else {
        fit_slow_or_full(py, kind, &spec, u, f, k)
    }
}

/// The lab's experiments (`lugre fit --fit stribeck|presliding|staged`), the keywords of the
/// other fits refused by name.
fn fit_lab<'py>(
    py: Python<'py>,
    kind: FitKind,
    spec: &FitSpec,
    u: &Bound<'py, PyAny>,
    f: &Bound<'py, PyAny>,
    k: Keywords<'py>,
) -> PyResult<Bound<'py, PyDict>> {
    // interpolate='linear' is the default reading, not a refused option.
    let cubic = crate::simulate::cubic_arg(k.interpolate.as_ref())?;
    let args = lab::Args {
        u: given(Some(u)),
        f: given(Some(f)),
        t: k.t,
        v: k.v,
        stribeck: k.stribeck,
        presliding: k.presliding,
        others: [
            ("x0", k.x0),
            ("starts", k.starts),
            ("interpolate='cubic'", k.interpolate.filter(|_| cubic)),
            ("normal", k.normal),
            ("noise", k.noise),
            ("gate", k.gate),
        ],
    };
    lab::fit(py, kind, spec, args)
}

/// The slow fit (the closed-form loop, eqs. 8-10) or the full fit (the simulation of eq. 1)
/// of `lugre fit --fit slow|full`: the samples and options checked, the fit run without the
/// interpreter lock, the report as a dict.
fn fit_slow_or_full<'py>(
    py: Python<'py>,
    kind: FitKind,
    spec: &FitSpec,
    u: &Bound<'py, PyAny>,
    f: &Bound<'py, PyAny>,
    k: Keywords<'py>,
) -> PyResult<Bound<'py, PyDict>> {
    lab::refuse_records(
        kind,
        [
            ("stribeck", k.stribeck.as_ref()),
            ("presliding", k.presliding.as_ref()),
        ],
    )?;
    let t = match &k.t {
        Some(t) => Some(floats(t, "t")?.one_dimensional("t", t)?),
        None => None,
    };
    let (u, motion) = motion_of(py, given(Some(u)), k.v, t.as_deref())?;
    let (f, normal) = friction_of(f, k.normal)?;
    let options = [k.x0, k.starts, k.interpolate, k.noise, k.gate];
    let run = run_options(py, kind, options, t.as_deref(), u.len())?;
    drop(try_vec::<[f64; FLOATS_PER_SAMPLE]>(u.len())?);

    let report = py
        .detach(|| run_fit(spec, run, t.as_deref(), &u, motion.as_ref(), &f))
        .map_err(|e| match e {
            FitError::BadGate { .. } => PyValueError::new_err(format!("gate: {e}")),
            e => explain(py, e),
        })?;

    warn_unconverged(py, &report)?;
    let d = report_dict(py, &report, spec, &f, normal.is_some())?;
    if motion.is_some() {
        // The displacement the velocity record integrates to, at the samples.
        d.set_item("u", vec_out(py, u.to_vec()))?;
    }
    Ok(d)
}

/// The core's slow or full fit as `run` says: the full fit on the smooth motion of a velocity
/// record, on the C1 cubic through the samples (`interpolate='cubic'`), or on the samples.
fn run_fit(
    spec: &FitSpec,
    run: Run,
    t: Option<&[f64]>,
    u: &[f64],
    motion: Option<&SmoothSamples>,
    f: &[f64],
) -> Result<FitReport, FitError> {
    // `run.full` is set for the full fit only, which has times.
    let (Some((x0, starts)), Some(t)) = (run.full, t) else {
        return fit_slow_with(spec, u, f, run.slow);
    };
    let options = FullOptions::default()
        .with_x0(x0)
        .with_starts(starts)
        .with_noise(run.noise);
    if let Some(m) = motion {
        fit_full_smooth(spec, m, f, options)
    } else if run.cubic {
        SmoothSamples::pchip(t.to_vec(), u.to_vec(), CUBIC_READING_TOL)
            .map_err(FitError::from)
            .and_then(|m| fit_full_smooth(spec, &m, f, options))
    } else {
        fit_full(spec, t, u, f, options)
    }
}

/// How the slow or full fit runs, from its keywords.
struct Run {
    slow: SlowOptions,
    /// The full fit's `x0` and number of starts (None: the slow fit).
    full: Option<(f64, usize)>,
    cubic: bool,
    noise: Noise,
}

/// The keywords `x0, starts, interpolate, noise, gate` of the slow or full fit, checked
/// against the kind of fit and the times `t` of `samples` samples (as `lugre fit` checks its
/// flags).
fn run_options(
    py: Python<'_>,
    kind: FitKind,
    [x0, starts, interpolate, noise, gate]: [Option<Bound<'_, PyAny>>; 5],
    t: Option<&[f64]>,
    samples: usize,
) -> PyResult<Run> {
    let x0 = x0.map(|x| real(&x, "x0")).transpose()?;
    let cubic = crate::simulate::cubic_arg(interpolate.as_ref())?;
    if cubic && kind == FitKind::Slow {
        return Err(PyValueError::new_err(
            "interpolate='cubic' applies to the full fit (kind='full'): the slow loop depends on the turning points alone",
        ));
    }
    let starts = starts.map(|s| count(&s, "starts")).transpose()?;
    let noise = match noise {
        Some(n) => noise_arg(&n)?,
        None => Noise::Auto,
    };
    let gate = gate.map(|g| real(&g, "gate")).transpose()?;
    if gate.is_some() && kind == FitKind::Full {
        return Err(PyValueError::new_err(
            "gate applies to the slow fit (kind='slow'): the full fit simulates every turn of the input",
        ));
    }
    let mut slow_options = SlowOptions::default().with_noise(noise);
    if let Some(g) = gate {
        slow_options = slow_options.with_gate(g);
    }
    let options = match kind {
        FitKind::Slow => {
            // As `lugre fit` refuses --x0 and --starts without --fit full.
            for (name, set) in [("x0", x0.is_some()), ("starts", starts.is_some())] {
                if set {
                    return Err(PyValueError::new_err(format!(
                        "{name} applies to the full fit (add kind='full')"
                    )));
                }
            }
            if let Some(t) = t {
                check_times(t, samples).map_err(|e| explain(py, e))?;
            }
            None
        }
        _ => {
            if t.is_none() {
                return Err(PyValueError::new_err(
                    "a full fit needs the samples' times: give t (strictly increasing, one per sample)",
                ));
            }
            let starts = match starts {
                Some(n) => usize::try_from(n)
                    .map_err(|_| PyValueError::new_err(format!("starts is too large, got {n}")))?,
                None => FullOptions::DEFAULT_STARTS,
            };
            Some((x0.unwrap_or(0.0), starts))
        }
    };
    Ok(Run {
        slow: slow_options,
        full: options,
        cubic,
        noise,
    })
}

/// The displacement at the samples: `u` as given, or a velocity record `v` (as `lugre fit`
/// reads t,v,F) integrated from u = 0 and read as the C1 cubic, which is also returned.
fn motion_of(
    py: Python<'_>,
    u: Option<Bound<'_, PyAny>>,
    v: Option<Bound<'_, PyAny>>,
    t: Option<&[f64]>,
) -> PyResult<(Vec<f64>, Option<SmoothSamples>)> {
    match (u, v) {
        (Some(_), Some(_)) => Err(PyValueError::new_err(
            "give the displacement u or the velocity v, not both (u=None with v)",
        )),
        (None, None) => Err(PyTypeError::new_err(
            "u must be the displacement samples (None only with the velocity v), got None",
        )),
        (Some(u), None) => Ok((floats(&u, "u")?.one_dimensional("u", &u)?, None)),
        (None, Some(v)) => {
            let v = floats(&v, "v")?.one_dimensional("v", &v)?;
            let Some(t) = t else {
                return Err(PyValueError::new_err(
                    "a velocity record needs the samples' times: give t",
                ));
            };
            let motion =
                SmoothSamples::from_velocity(t.to_vec(), v.to_vec(), 0.0, CUBIC_READING_TOL)
                    .map_err(|e| explain(py, FitError::from(e)))?;
            Ok((motion.samples().1.to_vec(), Some(motion)))
        }
    }
}

/// The force samples; with the normal force, the friction coefficient F / N (as `lugre fit
/// --columns N=NAME`), and the normal force.
fn friction_of(
    f: &Bound<'_, PyAny>,
    normal: Option<Bound<'_, PyAny>>,
) -> PyResult<(Vec<f64>, Option<Vec<f64>>)> {
    let mut f = floats(f, "f")?.one_dimensional("f", f)?;
    let normal = match normal {
        Some(n) => Some(floats(&n, "normal")?.one_dimensional("normal", &n)?),
        None => None,
    };
    if let Some(n) = &normal {
        normal_force::to_coefficient(&mut f, n).map_err(|e| match e {
            NormalForceError::NotPositive { index, .. } => {
                PyValueError::new_err(format!("normal[{index}]: {e}"))
            }
            e => PyValueError::new_err(format!("normal: {e}")),
        })?;
    }
    Ok((f, normal))
}

/// A fit that ran out of evaluations at a usable point: `lugre fit` warns on stderr and
/// reports the point; Python's way is a warning.
fn warn_unconverged(py: Python<'_>, report: &FitReport) -> PyResult<()> {
    if !report.converged {
        let message = CString::new(format!(
            "the fit did not converge ({}); the best point found is reported",
            report.termination
        ))
        .unwrap_or_default();
        PyErr::warn(py, &py.get_type::<PyRuntimeWarning>(), &message, 1)?;
    }
    Ok(())
}

/// The kinds of fit `kind` names (the labels of `lugre fit --fit`), in the message's order.
const KINDS: [FitKind; 5] = [
    FitKind::Slow,
    FitKind::Full,
    FitKind::Stribeck,
    FitKind::Presliding,
    FitKind::Staged,
];

/// `kind`: "slow", "full", "stribeck", "presliding" or "staged" (case-insensitive).
pub(super) fn kind_arg(obj: &Bound<'_, PyAny>) -> PyResult<FitKind> {
    let names: Vec<String> = KINDS.iter().map(|k| format!("'{}'", k.label())).collect();
    let expected = format!(
        "{} or {}",
        names[..names.len() - 1].join(", "),
        names[names.len() - 1]
    );
    let s = text(obj, "kind", &expected)?;
    let s = s.trim().to_ascii_lowercase();
    KINDS
        .into_iter()
        .find(|k| k.label() == s)
        .ok_or_else(|| match obj.repr() {
            Ok(r) => PyValueError::new_err(format!("kind must be {expected}, got {r}")),
            Err(e) => e,
        })
}

/// `noise`: "auto" or "off" (the core's names, case-insensitive).
fn noise_arg(obj: &Bound<'_, PyAny>) -> PyResult<Noise> {
    let expected = format!(
        "one of {}",
        Noise::NAMES.map(|n| format!("'{n}'")).join(", ")
    );
    let s = text(obj, "noise", &expected)?;
    Noise::from_name(&s).ok_or_else(|| {
        PyValueError::new_err(match obj.repr() {
            Ok(r) => format!("noise must be {expected}, got {r}"),
            Err(_) => format!("noise must be {expected}"),
        })
    })
}

/// A `str` argument, else a `TypeError` saying what was expected.
fn text(obj: &Bound<'_, PyAny>, name: &str, expected: &str) -> PyResult<String> {
    match obj.cast::<PyString>() {
        Ok(s) => Ok(s.to_cow()?.into_owned()),
        Err(_) => Err(PyTypeError::new_err(format!(
            "{name} must be {expected}, got {}",
            type_name(obj)
        ))),
    }
}

/// The model's family and values: a name (the defaults) or a model object (its values).
fn model_spec(model: Option<Bound<'_, PyAny>>) -> PyResult<FitSpec> {
    const EXPECTED: &str = "'lugre', 'dahl', a lugre.LuGre or a lugre.Dahl";
    let Some(m) = model else {
        return Ok(FitSpec::new(Family::LuGre));
    };
    if let Ok(l) = m.cast::<PyLuGre>() {
        return Ok(FitSpec::lugre(l.get().inner.params()));
    }
    if let Ok(d) = m.cast::<PyDahl>() {
        let d = &d.get().inner;
        return Ok(FitSpec::dahl(d.rho(), d.fc()));
    }
    let s = text(&m, "model", EXPECTED)?;
    match s.trim().to_ascii_lowercase().as_str() {
        "lugre" => Ok(FitSpec::new(Family::LuGre)),
        "dahl" => Ok(FitSpec::new(Family::Dahl)),
        _ => Err(PyValueError::new_err(format!(
            "model must be {EXPECTED}, got {}",
            m.repr()?
        ))),
    }
}

/// Parameter names: one `str` or an iterable of them (not a dict: `fix` handles those).
fn names(obj: &Bound<'_, PyAny>, arg: &str) -> PyResult<Vec<String>> {
    let bad = |what: String| {
        PyTypeError::new_err(format!(
            "{arg} must be a parameter name or a sequence of names, got {what}"
        ))
    };
    if let Ok(s) = obj.cast::<PyString>() {
        return Ok(vec![s.to_cow()?.into_owned()]);
    }
    let mut out = Vec::new();
    for item in obj.try_iter().map_err(|_| bad(type_name(obj)))? {
        let item = item?;
        match item.cast::<PyString>() {
            Ok(s) => out.push(s.to_cow()?.into_owned()),
            Err(_) => return Err(bad(format!("an element of type {}", type_name(&item)))),
        }
    }
    Ok(out)
}

/// The `(key, value)` pairs of a mapping argument, keys `str`.
fn items<'py>(
    obj: &Bound<'py, PyAny>,
    arg: &str,
    what: &str,
) -> PyResult<Vec<(String, Bound<'py, PyAny>)>> {
    let mapping = obj.cast::<PyMapping>().map_err(|_| {
        PyTypeError::new_err(format!(
            "{arg} must be a dict of parameter name -> {what}, got {}",
            type_name(obj)
        ))
    })?;
    let mut out = Vec::new();
    for pair in mapping.items()?.iter() {
        let (key, value): (Bound<'py, PyAny>, Bound<'py, PyAny>) = pair.extract()?;
        let name = text(&key, &format!("each key of {arg}"), "a parameter name")?;
        out.push((name, value));
    }
    Ok(out)
}

/// `(lo, hi)`: two real numbers, `None` for no bound on that side.
fn bound_pair(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<(f64, f64)> {
    let arg = format!("bounds['{name}']");
    let bad = || {
        PyTypeError::new_err(format!(
            "{arg} must be a pair (lo, hi) of real numbers, got {}",
            type_name(obj)
        ))
    };
    if obj.is_instance_of::<PyString>() || obj.cast::<PyMapping>().is_ok() {
        return Err(bad());
    }
    let pair: Vec<Bound<'_, PyAny>> = obj
        .try_iter()
        .map_err(|_| bad())?
        .collect::<PyResult<_>>()?;
    if pair.len() != 2 {
        return Err(PyValueError::new_err(format!(
            "{arg} must be a pair (lo, hi), got {} values",
            pair.len()
        )));
    }
    let side = |o: &Bound<'_, PyAny>, which: &str, none: f64| {
        if o.is_none() {
            Ok(none)
        } else {
            real(o, &format!("{arg} {which}"))
        }
    };
    Ok((
        side(&pair[0], "lo", 0.0)?,
        side(&pair[1], "hi", f64::INFINITY)?,
    ))
}

/// The request, as `lugre fit` builds it from the model flags, --fix, --free and --bounds.
fn build_spec(
    model: Option<Bound<'_, PyAny>>,
    fix: Option<Bound<'_, PyAny>>,
    free: Option<Bound<'_, PyAny>>,
    start: Option<Bound<'_, PyAny>>,
    bounds: Option<Bound<'_, PyAny>>,
) -> PyResult<FitSpec> {
    let mut spec = model_spec(model)?;
    let family = spec.family();
    // The canonical name of a parameter, or the core's error with the argument's name.
    let canonical = |arg: &str, name: &str| -> PyResult<&'static str> {
        family
            .index(name)
            .map(|i| family.parameters()[i])
            .map_err(|e| PyValueError::new_err(format!("{arg}: {e}")))
    };

    let mut started = Vec::new();
    if let Some(start) = &start {
        for (name, value) in items(start, "start", "start value")? {
            let canon = canonical("start", &name)?;
            let v = real(&value, &format!("start['{name}']"))?;
            spec = spec.set(canon, v).map_err(value_error)?;
            started.push(canon);
        }
    }
    if let Some(fix) = &fix {
        if fix.cast::<PyMapping>().is_ok() {
            for (name, value) in items(fix, "fix", "value")? {
                let canon = canonical("fix", &name)?;
                if started.contains(&canon) {
                    return Err(PyValueError::new_err(format!(
                        "{canon} is given both in start and in fix (a fixed parameter keeps the value in fix)"
                    )));
                }
                let v = real(&value, &format!("fix['{name}']"))?;
                spec = spec
                    .set(canon, v)
                    .and_then(|s| s.fix(canon))
                    .map_err(value_error)?;
            }
        } else {
            for name in names(fix, "fix")? {
                spec = spec.fix(canonical("fix", &name)?).map_err(value_error)?;
            }
        }
    }
    if let Some(free) = &free {
        for name in names(free, "free")? {
            spec = spec.free(canonical("free", &name)?).map_err(value_error)?;
        }
    }
    if let Some(bounds) = &bounds {
        for (name, value) in items(bounds, "bounds", "(lo, hi)")? {
            let canon = canonical("bounds", &name)?;
            let (lo, hi) = bound_pair(&value, &name)?;
            spec = spec
                .bounds(canon, lo, hi)
                .map_err(|e| PyValueError::new_err(format!("bounds: {e}")))?;
        }
    }
    check_model(&spec)?;
    Ok(spec)
}

/// The values given must make a valid model (as `lugre fit` checks its model flags first):
/// the model's own message otherwise, e.g. "fs must be > 0, got 0".
fn check_model(spec: &FitSpec) -> PyResult<()> {
    let v = |name: &str| spec.value(name).map_err(value_error);
    match spec.family() {
        Family::LuGre => {
            let mut p = lugre::LuGreParams::default();
            for q in Parameter::LUGRE {
                p.set(q, v(q.name())?);
            }
            lugre::LuGre::from_params(p).map_err(value_error)?;
        }
        Family::Dahl => {
            lugre::Dahl::new(v("rho")?, v("fc")?).map_err(value_error)?;
        }
    }
    Ok(())
}

/// The checks of the full fit's times, for a slow fit given `t` (as `lugre fit` checks the
/// times of a `t,u,F` file): the core's errors.
fn check_times(t: &[f64], n: usize) -> Result<(), FitError> {
    if t.len() != n {
        return Err(FitError::LengthMismatch {
            what: "t",
            got: t.len(),
            u: n,
        });
    }
    lugre::input::check_finite("t", t)?;
    Ok(lugre::input::check_increasing(t)?)
}

/// A core error as a `ValueError`, with what to do about it where `lugre fit` says so (in the
/// terms of this function's arguments rather than the command's flags).
fn explain(py: Python<'_>, e: FitError) -> PyErr {
    match &e {
        FitError::Unidentifiable { parameters } => {
            let names: Vec<&str> = parameters.iter().map(|p| p.name).collect();
            let (it, example) = if names.len() == 1 {
                ("it", format!("fix={{'{}': value}}", names[0]))
            } else {
                ("them", format!("fix={{'{}': value, ...}}", names[0]))
            };
            unidentifiable(
                py,
                &e,
                &names,
                format!("fix {it} at values you know ({example}) or fit data that excite {it}"),
            )
        }
        FitError::NotGiven { name, .. } => PyValueError::new_err(format!(
            "{e} (fix={{'{name}': value}}, a model object that has it, or free=['{name}'])"
        )),
        FitError::StartOutsideBounds { name, .. } => {
            PyValueError::new_err(format!("{e}: change start['{name}'] or bounds['{name}']"))
        }
        FitError::BadStart { name, value } => PyValueError::new_err(format!(
            "start['{name}']: {e} (to hold it at that value, give fix={{'{name}': {}}})",
            float_repr(py, *value)
        )),
        _ => value_error(e),
    }
}

/// A `ValueError` for parameters the data cannot determine: the message with `advice`, and the
/// exception's `parameters` attribute holding their names.
fn unidentifiable(py: Python<'_>, e: &FitError, names: &[&str], advice: String) -> PyErr {
    let err = PyValueError::new_err(format!("{e}; {advice}"));
    let attached = PyTuple::new(py, names).and_then(|n| err.value(py).setattr("parameters", n));
    match attached {
        Ok(()) => err,
        Err(other) => other,
    }
}

/// The report as a dict (the keys of `lugre fit --json`, with "kind" for its "fit", plus the
/// fitted values and curve).
fn report_dict<'py>(
    py: Python<'py>,
    r: &FitReport,
    spec: &FitSpec,
    f: &[f64],
    normal: bool,
) -> PyResult<Bound<'py, PyDict>> {
    // With a normal force, the core's names per newton (Fc and Fs: mu_c and mu_s).
    let key = |name: &'static str| {
        if normal {
            normal_force::name_of(name)
        } else {
            name
        }
    };
    let fixed = PyDict::new(py);
    for (name, v) in &r.fixed {
        fixed.set_item(key(name), *v)?;
    }
    let values = PyDict::new(py);
    match r.family {
        Family::LuGre => {
            let p = r.lugre_params(spec);
            for (q, v) in p.named() {
                values.set_item(q.name(), v)?;
            }
        }
        Family::Dahl => {
            for (name, v) in r.values() {
                values.set_item(name, v)?;
            }
        }
    }
    let d = PyDict::new(py);
    summary_items(py, &d, &r.summary(), key)?;
    d.set_item("fixed", fixed)?;
    d.set_item("values", values)?;
    d.set_item("model", r.family.label().to_ascii_lowercase())?;
    d.set_item("kind", r.kind.label())?;
    d.set_item("normal_force", normal)?;
    d.set_item("residuals", vec_out(py, r.residuals(f)))?;
    Ok(d)
}

/// The items every fit's dict has, from the core's view: "parameters" (each estimate under
/// `key(name)`), "rms", "samples", "dof", "t_quantile", "condition_number", "correlation",
/// "iterations", "evaluations", "starts", "converged", "termination", "turning_points",
/// "noise", "warnings", "covariance", "fitted".
fn summary_items<'py>(
    py: Python<'py>,
    d: &Bound<'py, PyDict>,
    r: &FitSummary<'_>,
    key: impl Fn(&'static str) -> &'static str,
) -> PyResult<()> {
    let parameters = PyDict::new(py);
    for e in r.estimates {
        let p = PyDict::new(py);
        p.set_item("value", e.value)?;
        p.set_item("stderr", e.stderr)?;
        p.set_item("dof", e.dof)?;
        p.set_item("ci95", (e.ci95[0], e.ci95[1]))?;
        p.set_item("at_bound", e.at_bound)?;
        parameters.set_item(key(e.name), p)?;
    }
    let p = r.estimates.len();
    let correlation: Vec<f64> = r.correlation.iter().flatten().copied().collect();
    d.set_item("parameters", parameters)?;
    d.set_item("rms", r.rms)?;
    d.set_item("samples", r.samples)?;
    d.set_item("dof", r.dof)?;
    d.set_item("t_quantile", r.t_quantile)?;
    d.set_item("condition_number", r.condition_number)?;
    d.set_item("correlation", array_out(py, correlation, &[p, p])?)?;
    d.set_item("iterations", r.iterations)?;
    d.set_item("evaluations", r.evaluations)?;
    d.set_item("starts", r.starts)?;
    d.set_item("converged", r.converged)?;
    d.set_item("termination", r.termination)?;
    d.set_item("turning_points", r.turning_points)?;
    match r.noise {
        Some(n) => {
            let nd = PyDict::new(py);
            nd.set_item("position", n.position)?;
            nd.set_item("force", n.force)?;
            nd.set_item("handling", n.handling.key())?;
            nd.set_item("description", n.handling.describe())?;
            match n.handling {
                PositionHandling::Smoothed { lambda } => nd.set_item("lambda", lambda)?,
                PositionHandling::Gate { gate } => nd.set_item("gate", gate)?,
                _ => {}
            }
            d.set_item("noise", nd)?;
        }
        None => d.set_item("noise", py.None())?,
    }
    let warnings: Vec<String> = r
        .warnings
        .iter()
        .map(|w| match w {
            FitWarning::Misfit { slow: true, .. } | FitWarning::Structured { slow: true, .. } => {
                format!("{w} (kind='full')")
            }
            _ => w.to_string(),
        })
        .collect();
    d.set_item("warnings", warnings)?;
    let cov = PyDict::new(py);
    cov.set_item("method", r.covariance.key())?;
    cov.set_item("description", r.covariance.describe())?;
    if let Covariance::NeweyWest { lags } = r.covariance {
        cov.set_item("lags", lags)?;
    }
    cov.set_item("lag1_autocorrelation", r.serial.lag1)?;
    cov.set_item("ljung_box", r.serial.ljung_box)?;
    cov.set_item("ljung_box_95", r.serial.critical)?;
    d.set_item("covariance", cov)?;
    d.set_item("fitted", vec_out(py, r.fitted.to_vec()))?;
    Ok(())
}
