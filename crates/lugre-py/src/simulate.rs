//! `LuGre.simulate` / `Dahl.simulate`: the finite-rate response of eq. 5 (core
//! `lugre::simulate`), as a dict of float64 arrays `t, u, z, dz, y`; `ZooModel.simulate` and
//! `lugre.simulate(model, ...)` (in Python, over the models' methods): a model of the zoo through
//! [`lugre::zoo::ZooModel::simulate`], as a dict `model, t, u, y` (`lugre simulate --model
//! NAME --json`). No model of the zoo is named here.

use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::convert::{count, floats, real, try_vec, type_name, value_error, vec_out};
use lugre::simulate::{Drive, Output, Request};
use lugre::zoo::ZooModel;

/// The arguments of `simulate`, as Python objects (`None` when not given).
pub struct SimulateArgs<'a, 'py> {
    pub turning_points: Option<&'a Bound<'py, PyAny>>,
    pub t: Option<&'a Bound<'py, PyAny>>,
    pub u: Option<&'a Bound<'py, PyAny>>,
    pub sine: Option<&'a Bound<'py, PyAny>>,
    pub gamma: Option<&'a Bound<'py, PyAny>>,
    pub periods: Option<&'a Bound<'py, PyAny>>,
    pub x0: Option<&'a Bound<'py, PyAny>>,
    pub times: Option<&'a Bound<'py, PyAny>>,
    pub samples_per_period: Option<&'a Bound<'py, PyAny>>,
    pub tol: Option<&'a Bound<'py, PyAny>>,
    /// "linear" (default) or "cubic": how samples `t, u` are read between them.
    pub interpolate: Option<&'a Bound<'py, PyAny>>,
    /// The constant speed of the turning points (default [`Request::DEFAULT_SPEED`]).
    pub speed: Option<&'a Bound<'py, PyAny>>,
}

fn given<'a, 'py>(o: Option<&'a Bound<'py, PyAny>>) -> Option<&'a Bound<'py, PyAny>> {
    o.filter(|o| !o.is_none())
}

fn sine_arg(obj: &Bound<'_, PyAny>) -> PyResult<lugre::Sine> {
    let bad_type = || {
        PyTypeError::new_err(format!(
            "sine must be a tuple (A, T[, phase[, offset]]) of real numbers, got {}",
            type_name(obj)
        ))
    };
    if obj.is_instance_of::<pyo3::types::PyString>() {
        return Err(bad_type());
    }
    let items: Vec<Bound<'_, PyAny>> = obj
        .try_iter()
        .map_err(|_| bad_type())?
        .collect::<PyResult<_>>()?;
    if !(2..=4).contains(&items.len()) {
        return Err(PyValueError::new_err(format!(
            "sine takes 2 to 4 numbers (A, T[, phase[, offset]]), got {}",
            items.len()
        )));
    }
    let names = [
        "sine amplitude A",
        "sine period T",
        "sine phase",
        "sine offset",
    ];
    let mut v = [0.0; 4];
    for (i, item) in items.iter().enumerate() {
        v[i] = real(item, names[i])?;
    }
    lugre::Sine::new(v[0], v[1], v[2], v[3]).map_err(value_error)
}

fn one_dimensional(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<f64>> {
    floats(obj, name)?.one_dimensional(name, obj)
}

/// Runs eq. 5 for `model` as `args` ask, detached from the interpreter.
pub fn simulate<'py>(
    py: Python<'py>,
    model: &lugre::LuGre,
    args: SimulateArgs<'_, 'py>,
) -> PyResult<Bound<'py, PyDict>> {
    let request = request(&args)?;
    // The core's bounds first, then the memory there is before the core allocates (a failed
    // allocation there would abort the interpreter).
    request.check_work().map_err(value_error)?;
    match request.rows() {
        Some(n) => drop(try_vec::<[f64; 6]>(n)?),
        None => {
            return Err(pyo3::exceptions::PyMemoryError::new_err(
                "the requested output has more samples than can be held",
            ))
        }
    }
    let simulator = request.simulator(model).map_err(value_error)?;
    let trajectory = py
        .detach(|| request.run_on(&simulator, None))
        .map_err(value_error)?;
    let d = PyDict::new(py);
    let lugre::Trajectory { t, u, z, dz, y } = trajectory;
    d.set_item("t", vec_out(py, t))?;
    d.set_item("u", vec_out(py, u))?;
    d.set_item("z", vec_out(py, z))?;
    d.set_item("dz", vec_out(py, dz))?;
    d.set_item("y", vec_out(py, y))?;
    Ok(d)
}

/// The samples `(t, u)` a model of the zoo is simulated at ([`ZooModel::simulate`]): the
/// piecewise-linear input `t, u`, or `turning_points` at `speed`, sampled by the core's
/// `Drive::zoo_samples`. Of the `others` keywords, LuGre's own are refused in the core's words
/// (`interpolate` may be "linear").
pub fn zoo_input(
    model: &ZooModel,
    input: [Option<&Bound<'_, PyAny>>; 5],
    others: Option<&Bound<'_, PyDict>>,
) -> PyResult<(Vec<f64>, Vec<f64>)> {
    refuse_lugre_keywords(model, others)?;
    let [turning_points, t, u, speed, samples_per_period] = input;
    if [turning_points, t, u].iter().all(|x| given(*x).is_none()) {
        return Err(PyValueError::new_err(
            "no input: give t and u (samples, linear in between) or turning_points (at speed)",
        ));
    }
    let args = SimulateArgs {
        turning_points,
        t,
        u,
        speed,
        sine: None,
        gamma: None,
        periods: None,
        x0: None,
        times: None,
        samples_per_period,
        tol: None,
        interpolate: None,
    };
    let per_period = match output(&args)? {
        Output::PerPeriod(n) => Some(n),
        _ => None,
    };
    // Not None: no sine nor cubic reading without their keywords.
    drive(&args)?
        .zoo_samples(per_period)
        .map_err(value_error)?
        .ok_or_else(|| value_error(model.simulate_option("sine")))
}

/// LuGre's and Dahl's own keywords of `simulate` (a model of the zoo starts from rest and
/// answers at the input's own samples).
const LUGRE_KEYWORDS: [&str; 6] = ["x0", "gamma", "periods", "tol", "times", "sine"];

/// The first of LuGre's and Dahl's own keywords given (not None), refused for a model of the
/// zoo as `lugre simulate --model` refuses their flags; any other keyword is a TypeError.
fn refuse_lugre_keywords(model: &ZooModel, others: Option<&Bound<'_, PyDict>>) -> PyResult<()> {
    let Some(others) = others else {
        return Ok(());
    };
    for (key, value) in others.iter() {
        let name = key.str()?.to_string();
        if name == "interpolate" {
            if cubic_arg(given(Some(&value)))? {
                return Err(value_error(model.simulate_option("interpolate='cubic'")));
            }
        } else if LUGRE_KEYWORDS.contains(&name.as_str()) {
            if given(Some(&value)).is_some() {
                return Err(value_error(model.simulate_option(&name)));
            }
        } else {
            return Err(PyTypeError::new_err(format!(
                "simulate() got an unexpected keyword argument '{name}'"
            )));
        }
    }
    Ok(())
}

/// The core's request from the keywords: each one given replaces the core's default
/// ([`Request::new`]).
fn request(args: &SimulateArgs<'_, '_>) -> PyResult<Request> {
    let mut r = Request::new(drive(args)?);
    if let Some(g) = given(args.gamma) {
        r = r.with_gamma(lugre::Gamma::new(real(g, "gamma")?).map_err(value_error)?);
    }
    if let Some(p) = given(args.periods) {
        let periods = count(p, "periods")?;
        let periods = u32::try_from(periods).map_err(|_| {
            PyValueError::new_err(format!(
                "periods must be at most {}, got {periods}",
                u32::MAX
            ))
        })?;
        r = r.with_periods(periods).map_err(value_error)?;
    }
    if let Some(x) = given(args.x0) {
        r = r.with_x0(real(x, "x0")?);
    }
    if let Some(t) = given(args.tol) {
        r = r.with_tolerance(lugre::Tolerance::new(real(t, "tol")?).map_err(value_error)?);
    }
    r.with_output(output(args)?).map_err(value_error)
}

/// The one input the keywords give: `turning_points` (at `speed`), `t, u` or `sine`.
fn drive(args: &SimulateArgs<'_, '_>) -> PyResult<Drive> {
    let mut inputs = Vec::new();
    if given(args.turning_points).is_some() {
        inputs.push("turning_points");
    }
    if given(args.t).is_some() || given(args.u).is_some() {
        inputs.push("t, u");
    }
    if given(args.sine).is_some() {
        inputs.push("sine");
    }
    match inputs.len() {
        0 => {
            return Err(PyValueError::new_err(
                "no input: give turning_points, t and u, or sine=(A, T[, phase[, offset]])",
            ))
        }
        1 => {}
        _ => {
            return Err(PyValueError::new_err(format!(
                "give one input, not {}",
                inputs.join(" and ")
            )))
        }
    }
    let input = if let Some(tp) = given(args.turning_points) {
        turning_points(tp, given(args.speed))?
    } else if given(args.speed).is_some() {
        return Err(PyValueError::new_err(
            "speed is the turning points' speed: the other inputs carry their own times",
        ));
    } else if let Some(sine) = given(args.sine) {
        Drive::Sine(sine_arg(sine)?)
    } else {
        sampled(args)?
    };
    if given(args.interpolate).is_some() && !matches!(input, Drive::Samples(_) | Drive::Smooth(_)) {
        return Err(PyValueError::new_err(
            "interpolate applies to sampled inputs (t, u)",
        ));
    }
    Ok(input)
}

/// Turning points at `speed` (the core's default speed if not given).
fn turning_points(tp: &Bound<'_, PyAny>, speed: Option<&Bound<'_, PyAny>>) -> PyResult<Drive> {
    let values = one_dimensional(tp, "turning_points")?;
    let tp = lugre::TurningPoints::new(&values)
        .map_err(|e| PyValueError::new_err(format!("turning_points: {e}")))?;
    let speed = match speed {
        Some(v) => real(v, "speed")?,
        None => Request::DEFAULT_SPEED,
    };
    Ok(Drive::TurningPoints(
        lugre::PiecewiseLinear::from_turning_points(&tp, speed)
            .map_err(|e| PyValueError::new_err(format!("speed: {e}")))?,
    ))
}

/// Samples `t, u`, read linearly or as a smooth motion (`interpolate="cubic"`).
fn sampled(args: &SimulateArgs<'_, '_>) -> PyResult<Drive> {
    let (Some(t), Some(u)) = (given(args.t), given(args.u)) else {
        return Err(PyValueError::new_err(
            "a sampled input needs both t and u (arrays of equal length)",
        ));
    };
    let t = one_dimensional(t, "t")?;
    let u = one_dimensional(u, "u")?;
    if !cubic_arg(given(args.interpolate))? {
        return Ok(Drive::Samples(
            lugre::PiecewiseLinear::new(t, u).map_err(value_error)?,
        ));
    }
    // The chord tolerance of the subdivision: `tol`, as `lugre simulate --tol`.
    let tol = match given(args.tol) {
        Some(x) => real(x, "tol")?,
        None => lugre::Tolerance::DEFAULT.value(),
    };
    Ok(Drive::Smooth(
        lugre::simulate::SmoothSamples::pchip(t, u, tol).map_err(value_error)?,
    ))
}

/// Where to sample: `times` (or "knots"), `samples_per_period`, or the core's default.
fn output(args: &SimulateArgs<'_, '_>) -> PyResult<Output> {
    Ok(match (given(args.times), given(args.samples_per_period)) {
        (Some(_), Some(_)) => {
            return Err(PyValueError::new_err(
                "give times or samples_per_period, not both",
            ))
        }
        (Some(times), None) if times.extract::<String>().is_ok_and(|s| s == "knots") => {
            Output::Knots
        }
        (Some(times), None) => Output::Times(one_dimensional(times, "times")?),
        (None, Some(n)) => {
            let n = count(n, "samples_per_period")?;
            if n < 1 {
                return Err(PyValueError::new_err(format!(
                    "samples_per_period must be at least 1, got {n}"
                )));
            }
            Output::PerPeriod(usize::try_from(n).map_err(|_| {
                PyValueError::new_err(format!("samples_per_period is too large, got {n}"))
            })?)
        }
        (None, None) => Output::Default,
    })
}

/// `interpolate`: "linear" (default, `false`) or "cubic" (`true`).
pub(crate) fn cubic_arg(obj: Option<&Bound<'_, PyAny>>) -> PyResult<bool> {
    match obj {
        None => Ok(false),
        Some(i) => match i.extract::<String>().as_deref() {
            Ok("linear") => Ok(false),
            Ok("cubic") => Ok(true),
            _ => Err(PyValueError::new_err(format!(
                "interpolate must be 'linear' or 'cubic', got {}",
                i.repr().map_or_else(|_| "?".into(), |r| r.to_string())
            ))),
        },
    }
}
