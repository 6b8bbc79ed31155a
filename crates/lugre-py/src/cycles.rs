//! `lugre.cycles`: reversals, ASTM E1049 rainflow cycles, loop closure and energies of a
//! measured history (core `lugre::cycles`), as columns of numpy arrays.

use numpy::IntoPyArray;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::convert::{floats, real, type_name, value_error, vec_out};
use crate::models::{PyDahl, PyLuGre};

/// Reversals and ASTM E1049-85 rainflow cycles of a measured history `series` (samples joined
/// by straight lines, not periodic), where each full cycle's loop closes and, with a `model`
/// (LuGre or Dahl), the energies over each loop's arc from the rate-independent response y*
/// (eq. 6) started at y*(0) = sigma0 x0.
///
/// `gate` >= 0 ignores reversals smaller than it (a hysteresis band filter; 0 is no gate).
/// Cycles follow the conventions of the Python package `rainflow` 3.x (same cycles, same
/// order, same indices) and of `lugre cycles`.
///
/// Returns a dict:
///
/// * "reversals": {"index": int64 array, "u": float64 array};
/// * "cycles": float64 columns "range", "mean", "count" (1.0 full, 0.5 half), int64 columns
///   "start", "end" (sample indices of the cycle's reversals) and "closure" (the first sample
///   index back at the start value, -1 for half cycles), float64 "closure_position" (the
///   interpolated position there, NaN for half cycles) and, with a model, "work",
///   "stored_energy_change", "dissipation", "closure_gap" (NaN for half cycles);
/// * "summary": {"samples", "reversals", "full_cycles", "half_cycles", "energy"}, "energy"
///   being None without a model, else a dict of the totals along the whole history
///   ("y_start", "y_end", "work", "stored_energy_change", "dissipation").
///
/// Invalid input raises ValueError with the message of `lugre cycles`.
#[pyfunction]
#[pyo3(
    signature = (series, gate=None, model=None, x0=None),
    text_signature = "(series, gate=0.0, model=None, x0=0.0)"
)]
pub fn cycles<'py>(
    py: Python<'py>,
    series: &Bound<'py, PyAny>,
    gate: Option<&Bound<'py, PyAny>>,
    model: Option<&Bound<'py, PyAny>>,
    x0: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let u = floats(series, "series")?.one_dimensional("series", series)?;
    let gate = match gate.filter(|g| !g.is_none()) {
        Some(g) => real(g, "gate")?,
        None => 0.0,
    };
    let x0 = match x0.filter(|x| !x.is_none()) {
        Some(x) => real(x, "x0")?,
        None => 0.0,
    };
    let model = match model.filter(|m| !m.is_none()) {
        None => None,
        Some(m) => Some(if let Ok(l) = m.cast::<PyLuGre>() {
            l.get().inner.rate_independent()
        } else if let Ok(d) = m.cast::<PyDahl>() {
            d.get().inner.rate_independent()
        } else {
            return Err(PyTypeError::new_err(format!(
                "model must be a lugre.LuGre or lugre.Dahl, got {}",
                type_name(m)
            )));
        }),
    };
    let history = py
        .detach(|| match model {
            Some(m) => lugre::count_cycles_with_energy(&u, gate, m, x0),
            None => lugre::count_cycles(&u, gate),
        })
        .map_err(value_error)?;

    let reversals = PyDict::new(py);
    let index: Vec<i64> = history.reversals.iter().map(|r| r.index as i64).collect();
    reversals.set_item("index", index.into_pyarray(py))?;
    let ru: Vec<f64> = history.reversals.iter().map(|r| r.u).collect();
    reversals.set_item("u", vec_out(py, ru))?;

    let c = &history.cycles;
    let col = |f: &dyn Fn(&lugre::Cycle) -> f64| vec_out(py, c.iter().map(f).collect());
    let icol = |f: &dyn Fn(&lugre::Cycle) -> i64| c.iter().map(f).collect::<Vec<i64>>();
    let cycles = PyDict::new(py);
    cycles.set_item("range", col(&|c| c.range))?;
    cycles.set_item("mean", col(&|c| c.mean))?;
    cycles.set_item("count", col(&|c| c.count))?;
    cycles.set_item("start", icol(&|c| c.start as i64).into_pyarray(py))?;
    cycles.set_item("end", icol(&|c| c.end as i64).into_pyarray(py))?;
    cycles.set_item(
        "closure",
        icol(&|c| c.closure.map_or(-1, |k| k.index as i64)).into_pyarray(py),
    )?;
    cycles.set_item(
        "closure_position",
        col(&|c| c.closure.map_or(f64::NAN, |k| k.position)),
    )?;
    if model.is_some() {
        let energy = |f: fn(&lugre::CycleEnergy) -> f64| {
            col(&|c: &lugre::Cycle| c.energy.as_ref().map_or(f64::NAN, f))
        };
        cycles.set_item("work", energy(|e| e.work))?;
        cycles.set_item("stored_energy_change", energy(|e| e.stored_energy_change))?;
        cycles.set_item("dissipation", energy(|e| e.dissipation))?;
        cycles.set_item("closure_gap", energy(|e| e.closure_gap))?;
    }

    let s = &history.summary;
    let summary = PyDict::new(py);
    summary.set_item("samples", s.samples)?;
    summary.set_item("reversals", s.reversals)?;
    summary.set_item("full_cycles", s.full_cycles)?;
    summary.set_item("half_cycles", s.half_cycles)?;
    match &s.energy {
        None => summary.set_item("energy", py.None())?,
        Some(e) => {
            let d = PyDict::new(py);
            d.set_item("y_start", e.y_start)?;
            d.set_item("y_end", e.y_end)?;
            d.set_item("work", e.work)?;
            d.set_item("stored_energy_change", e.stored_energy_change)?;
            d.set_item("dissipation", e.dissipation)?;
            summary.set_item("energy", d)?;
        }
    }

    let out = PyDict::new(py);
    out.set_item("reversals", reversals)?;
    out.set_item("cycles", cycles)?;
    out.set_item("summary", summary)?;
    Ok(out)
}
