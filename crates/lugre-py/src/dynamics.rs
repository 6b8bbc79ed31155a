//! `lugre.dynamics`: the closed-loop system of the core's `lugre::dynamics` (a mass with LuGre
//! friction driven by a force, a spring, a PID controller or a prescribed velocity), as a dict of
//! numpy arrays with the events, the solver's statistics and the experiments' headlines.

use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyDict, PyList, PyType};

use crate::convert::{count, floats, real, type_name, value_error, vec_out};
use crate::models::lugre_of;
use crate::zoo::PyZooModel;
use lugre::dynamics::{Field, Motion, Outcome, Plan, Request, Scenario};

/// The motion of a mass with friction, from rest.
///
/// dynamics(model=None, *, scenario=None, mass=None, damping=None, force=None, force_rate=None,
///          spring=None, pull=None, end=None, pid=None, setpoint=None, velocity=None,
///          t_end=None, times=None, samples=None, rtol=None, atol=None, loops=None)
///
/// The keywords are the fields of the core's request (`lugre::dynamics::Request`, whose docs
/// give every default); `lugre dynamics` takes the same as flags.
///
/// * model: a lugre.LuGre or lugre.Dahl, or lugre.ZooModel("elastoplastic", ...) (the
///   elasto-plastic law of Dupont et al. (2002) with all its parameters as the model holds
///   them: sigma0, sigma1, sigma2, fc, fs, vs, beta, zba); required unless a scenario gives
///   Table I of Canudas de Wit et al. (1995); mass in kg (default 1);
/// * scenario: "presliding", "breakaway", "stick-slip", "lag", "pid": the experiments of
///   Canudas de Wit et al. (1995) as presets; every keyword given on top replaces that field
///   (pid=(3, 8, 6) on "pid" keeps its set point 1 m; force_rate on "breakaway" changes the
///   ramp and its end 2 N / r);
/// * force: (t, F) arrays, linear in between; force_rate: F = r t (give one of them);
///   spring: k [N/m] with pull (speed of the free end, m/s) or end ((t, y) arrays); damping c;
///   pid: (Kp, Ki, Kv) with setpoint (a number, or (t, xd) arrays stepping at those times,
///   default 0); velocity: (t, v) arrays, prescribed (nothing else may then drive the mass);
/// * t_end: default the last of times, else the scenario's; output at times (array) or samples
///   (default 1001) evenly spaced times over [0, t_end]; rtol (default 1e-8), atol;
/// * loops: the friction-displacement loops (default: on for "presliding").
///
/// Returns a DynamicsResult (a dict; `to_frame()` gives the sampled columns as a
/// pandas.DataFrame): t, x, v, z, friction, drive (float64 arrays; with a prescribed velocity
/// the drive is the force M v' + F that makes the mass follow it), events (a list of dicts t,
/// kind, x), stats, energy, breakaway (t, force, x) with a force ramp, slip_onsets and period
/// with a pulled spring, loops (a list of dicts) when computed, and description.
#[pyfunction]
#[pyo3(signature = (model=None, *, scenario=None, mass=None, damping=None, force=None, force_rate=None, spring=None, pull=None, end=None, pid=None, setpoint=None, velocity=None, t_end=None, times=None, samples=None, rtol=None, atol=None, loops=None))]
#[allow(clippy::too_many_arguments)]
pub fn dynamics<'py>(
    py: Python<'py>,
    model: Option<&Bound<'py, PyAny>>,
    scenario: Option<&Bound<'py, PyAny>>,
    mass: Option<&Bound<'py, PyAny>>,
    damping: Option<&Bound<'py, PyAny>>,
    force: Option<&Bound<'py, PyAny>>,
    force_rate: Option<&Bound<'py, PyAny>>,
    spring: Option<&Bound<'py, PyAny>>,
    pull: Option<&Bound<'py, PyAny>>,
    end: Option<&Bound<'py, PyAny>>,
    pid: Option<&Bound<'py, PyAny>>,
    setpoint: Option<&Bound<'py, PyAny>>,
    velocity: Option<&Bound<'py, PyAny>>,
    t_end: Option<&Bound<'py, PyAny>>,
    times: Option<&Bound<'py, PyAny>>,
    samples: Option<&Bound<'py, PyAny>>,
    rtol: Option<&Bound<'py, PyAny>>,
    atol: Option<&Bound<'py, PyAny>>,
    loops: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let given = |o: Option<&Bound<'py, PyAny>>| o.filter(|o| !o.is_none()).cloned();
    let mut r = Request::new();
    if let Some(name) = given(scenario) {
        r = r.with_scenario(scenario_of(&name)?);
    }
    if let Some(m) = given(model) {
        r = with_model(r, &m)?;
    }
    // One number each, through the core's own translation (as the C ABI's and MATLAB's).
    let scalars = [
        (Field::Mass, mass),
        (Field::Damping, damping),
        (Field::ForceRate, force_rate),
        (Field::Spring, spring),
        (Field::Pull, pull),
        (Field::TEnd, t_end),
        (Field::Rtol, rtol),
        (Field::Atol, atol),
    ];
    for (field, value) in scalars {
        if let Some(x) = given(value) {
            let x = real(&x, field.name())?;
            r = r.with_numbers(field, &[x]).map_err(request_error)?;
        }
    }
    // Points (t, value) each.
    for (field, value) in [
        (Field::Force, force),
        (Field::End, end),
        (Field::Velocity, velocity),
    ] {
        if let Some(points) = given(value) {
            let (t, v) = pair(&points, field.name())?;
            r = r.with_points(field, t, v).map_err(request_error)?;
        }
    }
    // Numbers go to the core as given: it counts them (`pid takes 3 numbers, got 2`).
    if let Some(g) = given(pid) {
        let g = floats(&g, "pid")?.one_dimensional("pid", &g)?;
        r = r.with_numbers(Field::Pid, &g).map_err(request_error)?;
    }
    if let Some(s) = given(setpoint) {
        r = with_setpoint(r, &s)?;
    }
    if let Some(t) = given(times) {
        let t = floats(&t, "times")?.one_dimensional("times", &t)?;
        r = r.with_times(t).map_err(request_error)?;
    }
    if let Some(n) = given(samples) {
        r = with_samples(r, &n)?;
    }
    if let Some(l) = given(loops) {
        let on = l.extract::<bool>().map_err(|_| {
            PyTypeError::new_err(format!(
                "loops must be True or False, got {}",
                type_name(&l)
            ))
        })?;
        r = r.with_loops(on);
    }
    let plan = r.build().map_err(request_error)?;
    let outcome = py.detach(|| plan.run()).map_err(value_error)?;
    result(py, &plan, outcome)
}

/// `model=`: a lugre.LuGre or lugre.Dahl, or a lugre.ZooModel (the core takes the
/// elasto-plastic one and refuses the others).
fn with_model(r: Request, m: &Bound<'_, PyAny>) -> PyResult<Request> {
    if let Ok(zoo) = m.cast::<PyZooModel>() {
        return r.with_zoo(zoo.get().model()).map_err(request_error);
    }
    lugre_of(m)
        .map_err(|_| {
            PyTypeError::new_err(format!(
                "model must be a lugre.LuGre, lugre.Dahl or lugre.ZooModel, got {}",
                type_name(m)
            ))
        })
        .map(|l| r.with_model(l))
}

/// `setpoint=`: a number, a flat list of numbers (counted by the core: one is expected), or
/// steps `(t, xd)`.
fn with_setpoint(r: Request, s: &Bound<'_, PyAny>) -> PyResult<Request> {
    match (real(s, Field::Setpoint.name()), numbers_only(s)) {
        (Ok(x), _) => r.with_setpoint(x),
        // A flat list of numbers is not (t, xd) steps: counted as a set point's numbers.
        (_, Some(xs)) => r.with_numbers(Field::Setpoint, &xs),
        _ => {
            let (t, x) = pair(s, Field::Setpoint.name())?;
            r.with_setpoint_steps(t, x)
        }
    }
    .map_err(request_error)
}

/// `samples=`: a count; a negative one gets the core's words for what a count must be (as
/// the CLI's).
fn with_samples(r: Request, n: &Bound<'_, PyAny>) -> PyResult<Request> {
    match count(n, Field::Samples.name()) {
        Ok(n) => r.with_samples(n),
        Err(e) => match n.extract::<i64>() {
            Ok(v) if v < 0 => r.with_numbers(Field::Samples, &[v as f64]),
            _ => return Err(e),
        },
    }
    .map_err(request_error)
}

/// A request's error with its fields spelled as keywords (a measured force is `force` here).
fn request_error(e: lugre::DynamicsError) -> PyErr {
    PyValueError::new_err(e.render(|f| match f {
        Field::Input => Field::Force.name().to_string(),
        other => other.name().to_string(),
    }))
}

/// The scenario called `name`.
fn scenario_of(name: &Bound<'_, PyAny>) -> PyResult<Scenario> {
    let name: String = name.extract().map_err(|_| {
        PyTypeError::new_err(format!(
            "scenario must be a string, got {}",
            type_name(name)
        ))
    })?;
    Scenario::named(&name).map_err(value_error)
}

/// `(Kp, Ki, Kv)`.
/// The numbers of a flat sequence of real numbers (None for anything else, e.g. a pair of
/// arrays).
fn numbers_only(obj: &Bound<'_, PyAny>) -> Option<Vec<f64>> {
    let items: Vec<Bound<'_, PyAny>> = obj.try_iter().ok()?.collect::<PyResult<_>>().ok()?;
    items.iter().map(|x| real(x, "setpoint").ok()).collect()
}

/// The result as a `lugre.DynamicsResult` (a dict with `to_frame()`).
fn result<'py>(py: Python<'py>, plan: &Plan, outcome: Outcome) -> PyResult<Bound<'py, PyAny>> {
    let d = PyDict::new(py);
    let onsets = outcome.slip_onsets();
    let Outcome {
        motion,
        breakaway,
        loops,
    } = outcome;
    let events = PyList::empty(py);
    for e in &motion.events {
        let ev = PyDict::new(py);
        ev.set_item("t", e.t)?;
        ev.set_item("kind", e.kind.name())?;
        ev.set_item("x", e.x)?;
        events.append(ev)?;
    }
    let s = motion.stats;
    let stats = PyDict::new(py);
    stats.set_item("steps", s.steps)?;
    stats.set_item("rejected", s.rejected)?;
    stats.set_item("rhs_evaluations", s.rhs_evaluations)?;
    stats.set_item("jacobians", s.jacobians)?;
    stats.set_item("restarts", s.restarts)?;
    let energy = PyDict::new(py);
    let e = motion.energy;
    energy.set_item("input", e.input)?;
    energy.set_item("stored_start", e.stored_start)?;
    energy.set_item("stored_end", e.stored_end)?;
    energy.set_item("dissipated", e.dissipated)?;
    let Motion {
        t,
        x,
        v,
        z,
        friction,
        drive,
        ..
    } = motion;
    for (key, column) in Motion::COLUMNS
        .into_iter()
        .zip([t, x, v, z, friction, drive])
    {
        d.set_item(key, vec_out(py, column))?;
    }
    d.set_item("events", events)?;
    d.set_item("stats", stats)?;
    d.set_item("energy", energy)?;
    d.set_item("description", &plan.description)?;
    if let Some(b) = breakaway {
        let bd = PyDict::new(py);
        bd.set_item("t", b.t)?;
        bd.set_item("force", b.force)?;
        bd.set_item("x", b.x)?;
        d.set_item("breakaway", bd)?;
    }
    if plan.pull.is_some() {
        if onsets.len() >= 2 {
            d.set_item(
                "period",
                onsets[onsets.len() - 1] - onsets[onsets.len() - 2],
            )?;
        }
        d.set_item("slip_onsets", vec_out(py, onsets))?;
    }
    if plan.loops {
        let list = PyList::empty(py);
        for l in &loops {
            let ld = PyDict::new(py);
            ld.set_item("t_start", l.t_start)?;
            ld.set_item("t_turn", l.t_turn)?;
            ld.set_item("t_close", l.t_close)?;
            ld.set_item("turning_points", vec_out(py, l.turning_points.clone()))?;
            ld.set_item("work", l.work)?;
            ld.set_item("bristle_energy_change", l.bristle_energy_change)?;
            ld.set_item("dissipation", l.dissipation)?;
            ld.set_item("rate_independent_work", l.rate_independent_work)?;
            list.append(ld)?;
        }
        d.set_item("loops", list)?;
    }
    // The class is looked up once, not in the package's module at every call.
    static DYNAMICS_RESULT: PyOnceLock<Py<PyType>> = PyOnceLock::new();
    DYNAMICS_RESULT
        .import(py, "lugre", "DynamicsResult")?
        .call1((d,))
}

/// `(t, values)`: two arrays of equal length.
fn pair(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<(Vec<f64>, Vec<f64>)> {
    let items: Vec<Bound<'_, PyAny>> = obj
        .try_iter()
        .map_err(|_| PyTypeError::new_err(format!("{name} must be a pair (t, values) of arrays")))?
        .collect::<PyResult<_>>()?;
    if items.len() != 2 {
        return Err(PyValueError::new_err(format!(
            "{name} must be a pair (t, values) of arrays, got {} items",
            items.len()
        )));
    }
    let t = floats(&items[0], name)?.one_dimensional(name, &items[0])?;
    let v = floats(&items[1], name)?.one_dimensional(name, &items[1])?;
    Ok((t, v))
}
