//! `lugre.dynamics`: the closed-loop system of the core's `lugre::dynamics` (a mass with LuGre
//! friction driven by a force, a spring, a PID controller or a prescribed velocity), as a dict of
//! numpy arrays with the events, the solver's statistics and the experiments' headlines.

use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use crate::convert::{floats, real, value_error, vec_out};
use crate::models::lugre_of;
use lugre::dynamics::{Pid, Profile, Scenario, Steps, System, Tolerances, Velocity};

/// The motion of a mass with friction, from rest.
///
/// dynamics(model=None, *, mass=1.0, scenario=None, force=None, force_rate=None, spring=None,
///          pull=None, end=None, damping=0.0, pid=None, setpoint=0.0, velocity=None,
///          t_end=None, times=None, samples=1001, rtol=1e-8, atol=None)
///
/// * model: a lugre.LuGre or lugre.Dahl (default: Table I of Canudas de Wit et al. 1995 with a
///   scenario, else LuGre()); mass in kg;
/// * scenario: "presliding", "breakaway" (with force_rate, default 10 N/s), "stick-slip",
///   "lag", "pid": the experiments of Canudas de Wit et al. (1995) (`lugre dynamics --scenario`);
/// * force: (t, F) arrays, linear in between; force_rate: F = r t; spring: k [N/m] with pull
///   (speed of the free end, m/s) or end ((t, y) arrays); damping c; pid: (Kp, Ki, Kv) with
///   setpoint (a number, or (t, xd) arrays stepping at those times); velocity: (t, v) arrays,
///   prescribed;
/// * output at times (array) or samples evenly spaced times over [0, t_end].
///
/// Returns a dict: t, x, v, z, friction, drive (float64 arrays), events (a list of dicts t,
/// kind, x: "velocity_zero", "velocity_up", "kink"), stats (a dict), and breakaway (t, force,
/// x) with a force ramp, slip_onsets (array) and period with a pulled spring.
#[pyfunction]
#[pyo3(signature = (model=None, *, mass=1.0, scenario=None, force=None, force_rate=None, spring=None, pull=None, end=None, damping=0.0, pid=None, setpoint=None, velocity=None, t_end=None, times=None, samples=1001, rtol=1e-8, atol=None))]
#[allow(clippy::too_many_arguments)]
pub fn dynamics<'py>(
    py: Python<'py>,
    model: Option<&Bound<'py, PyAny>>,
    mass: f64,
    scenario: Option<&str>,
    force: Option<&Bound<'py, PyAny>>,
    force_rate: Option<f64>,
    spring: Option<f64>,
    pull: Option<f64>,
    end: Option<&Bound<'py, PyAny>>,
    damping: f64,
    pid: Option<(f64, f64, f64)>,
    setpoint: Option<&Bound<'py, PyAny>>,
    velocity: Option<&Bound<'py, PyAny>>,
    t_end: Option<f64>,
    times: Option<&Bound<'py, PyAny>>,
    samples: usize,
    rtol: f64,
    atol: Option<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    let lugre_model = match model.filter(|m| !m.is_none()) {
        None if scenario.is_some() => {
            lugre::LuGre::from_params(lugre::LuGreParams::canudas_de_wit_1995())
                .map_err(value_error)?
        }
        None => lugre::LuGre::paper(),
        Some(m) => lugre_of(m)?,
    };
    let mut watch = pull;
    let (mut system, mut rate, t_end) = match scenario {
        Some(name) => {
            let sc = Scenario::from_name(name, force_rate, None).ok_or_else(|| {
                PyValueError::new_err(format!(
                    "unknown scenario '{name}' (scenarios: {})",
                    Scenario::NAMES.join(", ")
                ))
            })?;
            let setup = sc.setup(lugre_model, mass).map_err(value_error)?;
            if setup.pull.is_some() {
                // The scenario watches its own pull speed already.
                watch = None;
            }
            (setup.system, setup.rate, t_end.or(Some(setup.t_end)))
        }
        None => (
            System::new(lugre_model, mass).map_err(value_error)?,
            None,
            t_end,
        ),
    };
    let pulled = pull.is_some() || matches!(scenario, Some("stick-slip"));
    if scenario.is_none() {
        if let Some(r) = force_rate {
            system = system.with_force(Profile::ramp(0.0, r).map_err(value_error)?);
            rate = Some(r);
        }
    }
    if let Some(f) = force {
        let (t, v) = pair(f, "force")?;
        system = system.with_force(Profile::new("force", t, v).map_err(value_error)?);
    }
    if let Some(k) = spring {
        let end = match (pull, end) {
            (Some(_), Some(_)) => return Err(PyValueError::new_err("give pull or end, not both")),
            (Some(v), None) => Profile::ramp(0.0, v).map_err(value_error)?,
            (None, Some(e)) => {
                let (t, y) = pair(e, "end")?;
                Profile::new("end", t, y).map_err(value_error)?
            }
            (None, None) => {
                return Err(PyValueError::new_err(
                    "a spring needs pull (the free end's speed) or end ((t, y) arrays)",
                ))
            }
        };
        system = system.with_spring(k, end).map_err(value_error)?;
    }
    system = system.with_damping(damping).map_err(value_error)?;
    if let Some((kp, ki, kv)) = pid {
        let setpoint = match setpoint.filter(|s| !s.is_none()) {
            None => Steps::constant(0.0),
            Some(s) => match real(s, "setpoint") {
                Ok(x) => Steps::constant(x),
                Err(_) => {
                    let (t, x) = pair(s, "setpoint")?;
                    Steps::new(t, x)
                }
            },
        }
        .map_err(value_error)?;
        system = system
            .with_pid(Pid {
                kp,
                ki,
                kv,
                setpoint,
            })
            .map_err(value_error)?;
    }
    if let Some(v) = velocity {
        let (t, v) = pair(v, "velocity")?;
        let profile = Profile::new("velocity", t, v).map_err(value_error)?;
        system = system
            .with_velocity(Velocity::Profile(profile))
            .map_err(value_error)?;
    }
    if let Some(v) = watch {
        system = system.with_velocity_watch(v).map_err(value_error)?;
    }
    let t_end = t_end.ok_or_else(|| PyValueError::new_err("give t_end (the end of the run, s)"))?;
    let tol = Tolerances::new(rtol, atol).map_err(value_error)?;
    let times: Vec<f64> = match times.filter(|t| !t.is_none()) {
        Some(t) => floats(t, "times")?.one_dimensional("times", t)?,
        None => {
            if samples < 2 {
                return Err(PyValueError::new_err(format!(
                    "samples must be at least 2, got {samples}"
                )));
            }
            lugre::simulate::uniform_times(0.0, t_end, 1, samples - 1)
        }
    };
    let (motion, breakaway) = py
        .detach(|| {
            let m = system.solve(t_end, &times, tol)?;
            let b = match rate {
                Some(_) => system.breakaway(t_end, tol)?,
                None => None,
            };
            Ok::<_, lugre::DynamicsError>((m, b))
        })
        .map_err(value_error)?;

    let d = PyDict::new(py);
    let events = PyList::empty(py);
    for e in &motion.events {
        let ev = PyDict::new(py);
        ev.set_item("t", e.t)?;
        ev.set_item("kind", e.kind.name())?;
        ev.set_item("x", e.x)?;
        events.append(ev)?;
    }
    let onsets: Vec<f64> = motion
        .events
        .iter()
        .filter(|e| e.kind == lugre::dynamics::EventKind::VelocityUp)
        .map(|e| e.t)
        .collect();
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
    d.set_item("energy", energy)?;
    let lugre::dynamics::Motion {
        t,
        x,
        v,
        z,
        friction,
        drive,
        ..
    } = motion;
    d.set_item("t", vec_out(py, t))?;
    d.set_item("x", vec_out(py, x))?;
    d.set_item("v", vec_out(py, v))?;
    d.set_item("z", vec_out(py, z))?;
    d.set_item("friction", vec_out(py, friction))?;
    d.set_item("drive", vec_out(py, drive))?;
    d.set_item("events", events)?;
    d.set_item("stats", stats)?;
    if let Some(b) = breakaway {
        let bd = PyDict::new(py);
        bd.set_item("t", b.t)?;
        bd.set_item("force", b.force)?;
        bd.set_item("x", b.x)?;
        d.set_item("breakaway", bd)?;
    }
    if pulled {
        if onsets.len() >= 2 {
            d.set_item(
                "period",
                onsets[onsets.len() - 1] - onsets[onsets.len() - 2],
            )?;
        }
        d.set_item("slip_onsets", vec_out(py, onsets))?;
    }
    Ok(d)
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
