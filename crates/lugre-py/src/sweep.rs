//! `lugre.sweep`: the periodic steady state under sines over a grid of amplitudes and
//! frequencies (the core's `lugre::sweep`), as a dict of numpy columns.

use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString};

use crate::convert::{count, floats, real, value_error, vec_out};
use crate::models::lugre_of;
use lugre::sweep::{parse_values, Request, COLUMNS};
use lugre::Tolerance;

/// The periodic steady state of a LuGre or Dahl model under u = offset + A sin(2 pi f t), for
/// every amplitude A with every frequency f (the fixed point of the period map, computed in
/// parallel on all cores; ``lugre sweep``).
///
/// sweep(model, *, amplitudes, frequencies, offset=None, tol=None, loop_samples=None)
///
/// The keywords are the fields of the core's request (``lugre::sweep::Request``):
///
/// * amplitudes, frequencies: sequences of numbers > 0, or a string "a,b,c" or
///   "start:stop:count" (count values evenly spaced on a log scale, both ends included);
/// * offset: the sine's mean value (default 0); tol: the integrator's relative tolerance
///   (default 1e-12); loop_samples: each point's loop at that many evenly spaced times over a
///   period, both ends included (default 0: none).
///
/// Returns a SweepResult (a dict; ``to_frame()`` gives the columns as a pandas.DataFrame):
/// one float64 array per column of SWEEP_COLUMNS (amplitude, frequency, dissipation, work,
/// stored_energy_change, peak_force, stiffness, damping, gain, phase [rad], a1, b1), one entry
/// per point (amplitude-major), and "loops" (a list of dicts t, u, force) when asked for.
#[pyfunction]
#[pyo3(signature = (model, *, amplitudes, frequencies, offset=None, tol=None, loop_samples=None))]
pub fn sweep<'py>(
    py: Python<'py>,
    model: &Bound<'py, PyAny>,
    amplitudes: &Bound<'py, PyAny>,
    frequencies: &Bound<'py, PyAny>,
    offset: Option<&Bound<'py, PyAny>>,
    tol: Option<&Bound<'py, PyAny>>,
    loop_samples: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let model = lugre_of(model)?;
    let a = values(amplitudes, "amplitudes")?;
    let f = values(frequencies, "frequencies")?;
    let named =
        |name: &'static str| move |e: lugre::SweepError| value_error(format!("{name}: {e}"));
    let mut r = Request::new(a, f).map_err(|e| match &e {
        lugre::SweepError::NotPositive {
            what: "frequency", ..
        } => named("frequencies")(e),
        lugre::SweepError::NotPositive { .. } => named("amplitudes")(e),
        _ => value_error(e),
    })?;
    let given = |o: Option<&Bound<'py, PyAny>>| o.filter(|o| !o.is_none()).cloned();
    if let Some(x) = given(offset) {
        r = r
            .with_offset(real(&x, "offset")?)
            .map_err(named("offset"))?;
    }
    if let Some(x) = given(tol) {
        let t = Tolerance::new(real(&x, "tol")?).map_err(|e| value_error(format!("tol: {e}")))?;
        r = r.with_tolerance(t);
    }
    if let Some(n) = given(loop_samples) {
        let n = usize::try_from(count(&n, "loop_samples")?).unwrap_or(usize::MAX);
        r = r.with_loop_samples(n).map_err(|e| match e {
            lugre::SweepError::TooLarge { .. } => value_error(e),
            e => named("loop_samples")(e),
        })?;
    }
    let sweep = py.detach(|| r.run(&model, None)).map_err(value_error)?;
    let d = PyDict::new(py);
    for (k, name) in COLUMNS.iter().enumerate() {
        let column: Vec<f64> = sweep.points.iter().map(|p| p.values()[k]).collect();
        d.set_item(name, vec_out(py, column))?;
    }
    if r.loop_samples() > 0 {
        let loops = PyList::empty(py);
        for p in sweep.points {
            let l = p.samples.unwrap_or_default();
            let ld = PyDict::new(py);
            ld.set_item("t", vec_out(py, l.t))?;
            ld.set_item("u", vec_out(py, l.u))?;
            ld.set_item("force", vec_out(py, l.force))?;
            loops.append(ld)?;
        }
        d.set_item("loops", loops)?;
    }
    py.import("lugre")?.getattr("SweepResult")?.call1((d,))
}

/// A list of values: numbers, or the text the command line takes ("a,b,c", "start:stop:count").
fn values(obj: &Bound<'_, PyAny>, name: &'static str) -> PyResult<Vec<f64>> {
    if let Ok(text) = obj.cast::<PyString>() {
        return parse_values(name, &text.to_cow()?).map_err(value_error);
    }
    match floats(obj, name) {
        Ok(v) => v.one_dimensional(name, obj),
        Err(_) => Err(PyTypeError::new_err(format!(
            "{name} must be a sequence of real numbers or a string 'a,b,c' or 'start:stop:count', got {}",
            crate::convert::type_name(obj)
        ))),
    }
}
