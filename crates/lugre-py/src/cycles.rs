//! `lugre.cycles`: reversals, ASTM E1049 rainflow cycles, loop closure and energies of a
//! measured history (core `lugre::cycles`), as columns of numpy arrays.

use lugre::cycles::ColumnMut;
use lugre::CycleColumns;
use numpy::IntoPyArray;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyBool, PyDict, PyType};

use crate::convert::{self, real, type_name, value_error, vec_out};
use crate::models::lugre_of;
use crate::zoo::PyZooModel;
use lugre::HistoryError;

/// Reversals and ASTM E1049-85 rainflow cycles of a measured history `series` (samples joined
/// by straight lines, not periodic), where each full cycle's loop closes and, with a `model`,
/// the energies over each loop's arc: for LuGre or Dahl along the rate-independent response y*
/// (eq. 6) started at y*(0) = sigma0 x0; for a `lugre.ZooModel` along the model's exact path
/// from rest at series[0] (no `x0`; the history is held in memory, at most 2^27 samples), as
/// `lugre cycles --model NAME`.
///
/// `gate` >= 0 ignores reversals smaller than it (a hysteresis band filter; 0 is no gate).
/// Cycles follow the conventions of the Python package `rainflow` 3.x (same cycles, same
/// order, same indices) and of `lugre cycles`.
///
/// Returns a CyclesResult, a dict (picklable) whose `to_frame()` gives the cycle table as a
/// `pandas.DataFrame`:
///
/// * "reversals": {"index": int64 array, "u": float64 array}, or None with
///   `reversals=False`;
/// * "cycles": float64 columns "range", "mean", "count" (1.0 full, 0.5 half), int64 columns
///   "start", "end" (sample indices of the cycle's reversals) and, unless `closures=False`,
///   "closure" (the first sample index back at the start value, -1 for half cycles) and
///   float64 "closure_position" (the interpolated position there, NaN for half cycles); with a
///   model, "work", "stored_energy_change", "dissipation", "closure_gap" (NaN for half
///   cycles). Row k of the columns is the k-th cycle: `zip(*(c[k] for k in ("range", "mean",
///   "count", "start", "end")))` gives the tuples `rainflow.extract_cycles` yields;
/// * "summary": {"samples", "reversals", "full_cycles", "half_cycles", "energy"}, "energy"
///   being None without a model, else a dict of the totals along the whole history
///   ("y_start", "y_end", "work", "stored_energy_change", "dissipation").
///
/// A contiguous float64 array is read in place (not copied) and the count runs with the GIL
/// released: do not modify the array from another thread during the call. Columns are built
/// in Rust and handed to numpy without a copy; `reversals=False` and `closures=False` skip
/// what is not needed (less memory and time for long histories).
///
/// Invalid input raises ValueError with the message of `lugre cycles` and the C ABI (a sample
/// that is not a finite number, fewer than 2 samples, a bad gate or x0, x0 with a model of the
/// zoo); a model of another type raises TypeError.
#[pyfunction]
#[pyo3(
    signature = (series, gate=None, model=None, x0=None, *, reversals=None, closures=None),
    text_signature = "(series, gate=0.0, model=None, x0=None, *, reversals=True, closures=True)"
)]
pub fn cycles<'py>(
    py: Python<'py>,
    series: &Bound<'py, PyAny>,
    gate: Option<&Bound<'py, PyAny>>,
    model: Option<&Bound<'py, PyAny>>,
    x0: Option<&Bound<'py, PyAny>>,
    reversals: Option<&Bound<'py, PyAny>>,
    closures: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let u = convert::series(series, "series")?;
    let gate = match gate.filter(|g| !g.is_none()) {
        Some(g) => real(g, "gate")?,
        None => 0.0,
    };
    let x0 = x0
        .filter(|x| !x.is_none())
        .map(|x| real(x, "x0"))
        .transpose()?;
    let keep_reversals = flag(reversals, "reversals")?;
    let keep_closures = flag(closures, "closures")?;
    let model = match model.filter(|m| !m.is_none()) {
        None => None,
        Some(m) => Some(energy_model(m, x0)?),
    };
    let u = u.as_slice();
    let columns = CycleColumns::new()
        .with_reversals(keep_reversals)
        .with_closures(keep_closures)
        .with_energy(model.is_some());
    let (columns, summary) = py
        .detach(|| count(u, gate, model, x0.unwrap_or(0.0), columns))
        .map_err(value_error)?;
    let result = to_dict(py, columns, &summary)?;
    // The class is looked up once, not in the package's module at every call.
    static CYCLES_RESULT: PyOnceLock<Py<PyType>> = PyOnceLock::new();
    CYCLES_RESULT
        .import(py, "lugre", "CyclesResult")?
        .call1((result,))
}

/// A keyword that must be a `bool` (`TypeError` otherwise); `True` when not given.
fn flag(obj: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<bool> {
    let Some(obj) = obj.filter(|o| !o.is_none()) else {
        return Ok(true);
    };
    obj.cast::<PyBool>().map(|b| b.is_true()).map_err(|_| {
        PyTypeError::new_err(format!(
            "{name} must be True or False, got {}",
            type_name(obj)
        ))
    })
}

/// The model whose energies a count follows: LuGre's or Dahl's y*, or a model of the zoo.
pub(crate) enum Energy {
    Classic(lugre::RateIndependent),
    Zoo(Box<lugre::zoo::ZooModel>),
}

/// The `model` argument of [`cycles`]; a model of the zoo starts from rest, so an `x0` given
/// with one is refused in the core's words.
pub(crate) fn energy_model(m: &Bound<'_, PyAny>, x0: Option<f64>) -> PyResult<Energy> {
    let Ok(zoo) = m.cast::<PyZooModel>() else {
        return match lugre_of(m) {
            Ok(l) => Ok(Energy::Classic(l.rate_independent())),
            Err(_) => Err(PyTypeError::new_err(format!(
                "model must be a lugre.LuGre, lugre.Dahl or lugre.ZooModel, got {}",
                type_name(m)
            ))),
        };
    };
    let model = zoo.get().model();
    if x0.is_some() {
        let label = model.spec().label;
        return Err(value_error(HistoryError::StartsFromRest { model: label }));
    }
    Ok(Energy::Zoo(Box::new(model.clone())))
}

/// Counts `u` into `c` (room for every reversal and cycle there can be, one per sample, so
/// that counting never reallocates), trimmed at the end. A history of 0 or 1 samples is
/// refused, as by `lugre cycles` and the C ABI (the core's one rule).
fn count(
    u: &[f64],
    gate: f64,
    model: Option<Energy>,
    x0: f64,
    mut c: CycleColumns,
) -> Result<(CycleColumns, lugre::CycleSummary), HistoryError> {
    if let Some(Energy::Zoo(z)) = &model {
        // Checked before the columns take room for the history.
        lugre::zoo::check_held(z, u.len())?;
    }
    c.reserve_for_samples(u.len());
    let summary = match model {
        Some(Energy::Zoo(z)) => z.count_cycles(u, gate, &mut c)?,
        classic => {
            let ri = match classic {
                Some(Energy::Classic(m)) => Some(m),
                _ => None,
            };
            let mut counter = lugre::CycleCounter::new(gate)?.with_energy(ri, x0)?;
            counter.push_all(u, &mut c)?;
            counter.finish(&mut c)?
        }
    };
    c.shrink_to_fit();
    Ok((c, summary))
}

/// The result dict of [`cycles`]; the columns become numpy arrays without a copy.
fn to_dict<'py>(
    py: Python<'py>,
    mut c: CycleColumns,
    s: &lugre::CycleSummary,
) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    if c.keeps_reversals() {
        let reversals = PyDict::new(py);
        let index = std::mem::take(&mut c.reversal_index);
        reversals.set_item("index", index.into_pyarray(py))?;
        reversals.set_item("u", vec_out(py, std::mem::take(&mut c.reversal_u)))?;
        out.set_item("reversals", reversals)?;
    } else {
        out.set_item("reversals", py.None())?;
    }

    let cycles = cycle_table(py, c)?;
    out.set_item("cycles", cycles)?;

    let summary = summary_dict(py, s)?;
    out.set_item("summary", summary)?;
    Ok(out)
}

/// The summary dict of [`cycles`] (also the chunked count's).
pub(crate) fn summary_dict<'py>(
    py: Python<'py>,
    s: &lugre::CycleSummary,
) -> PyResult<Bound<'py, PyDict>> {
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
    Ok(summary)
}

/// The cycle table of [`cycles`]: one numpy array per column kept, by the core's names
/// ([`CycleColumns::kept_names`]), each column moved, not copied.
pub(crate) fn cycle_table<'py>(
    py: Python<'py>,
    mut c: CycleColumns,
) -> PyResult<Bound<'py, PyDict>> {
    let cycles = PyDict::new(py);
    for name in c.kept_names() {
        match c.column_mut(name) {
            Some(ColumnMut::Real(v)) => cycles.set_item(name, vec_out(py, std::mem::take(v)))?,
            Some(ColumnMut::Index(v)) => {
                cycles.set_item(name, std::mem::take(v).into_pyarray(py))?
            }
            None => {}
        }
    }
    Ok(cycles)
}
