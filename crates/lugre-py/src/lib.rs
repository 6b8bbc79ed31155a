//! The Python package `lugre`: the LuGre and Dahl hysteresis engine of the `lugre` crate,
//! from numpy. Every number comes from the core library; this crate only converts arguments
//! and results and maps the core's errors to Python exceptions (`ValueError` with the message
//! the `lugre` command prints, `TypeError` for arguments of the wrong type).

mod chunk;
mod convert;
mod cycles;
mod dynamics;
mod fit;
mod loops;
mod models;
mod read;
mod simulate;
mod sweep;
mod zoo;

use pyo3::prelude::*;

/// The compiled core of the `lugre` package (import `lugre`, not this module).
#[pymodule]
fn _lugre(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_class::<models::PyLuGre>()?;
    m.add_class::<models::PyDahl>()?;
    m.add_class::<loops::PyHysteresisLoop>()?;
    m.add_class::<loops::PyLoop>()?;
    m.add_class::<loops::PyLoopPoint>()?;
    m.add_class::<loops::PyTheoremA>()?;
    m.add_class::<loops::PyCurve>()?;
    m.add_class::<zoo::PyZooModel>()?;
    m.add_class::<zoo::PyZooLoop>()?;
    m.add_function(wrap_pyfunction!(cycles::cycles, m)?)?;
    m.add_class::<chunk::PyChunkSummary>()?;
    m.add_class::<chunk::PyChunkPlan>()?;
    m.add_class::<chunk::PyChunkRows>()?;
    m.add_function(wrap_pyfunction!(chunk::chunk_count, m)?)?;
    m.add_function(wrap_pyfunction!(chunk::chunk_merge, m)?)?;
    m.add_function(wrap_pyfunction!(chunk::chunk_close, m)?)?;
    m.add_function(wrap_pyfunction!(chunk::chunk_assemble, m)?)?;
    m.add_function(wrap_pyfunction!(chunk::chunk_bounds, m)?)?;
    m.add_function(wrap_pyfunction!(chunk::chunk_start_entry, m)?)?;
    m.add_function(wrap_pyfunction!(chunk::chunk_guess_entries, m)?)?;
    m.add_function(wrap_pyfunction!(chunk::chunk_count_energy, m)?)?;
    m.add_function(wrap_pyfunction!(chunk::chunk_history_energy, m)?)?;
    m.add_function(wrap_pyfunction!(fit::fit, m)?)?;
    m.add_function(wrap_pyfunction!(dynamics::dynamics, m)?)?;
    m.add("DYNAMICS_COLUMNS", lugre::dynamics::Motion::COLUMNS)?;
    m.add(
        "DYNAMICS_FIELDS",
        lugre::dynamics::Field::ALL.map(|f| f.name()),
    )?;
    m.add_function(wrap_pyfunction!(sweep::sweep, m)?)?;
    m.add("SWEEP_COLUMNS", lugre::sweep::COLUMNS)?;
    m.add_function(wrap_pyfunction!(read::read, m)?)?;
    // The core's tables: the models' parameters, the columns of cycles and sampled loops.
    m.add("PARAMETERS", models::parameter_table(m.py())?)?;
    m.add("ZOO_MODELS", zoo::zoo_table(m.py())?)?;
    m.add("CYCLE_COLUMNS", lugre::CycleColumns::NAMES)?;
    m.add("LOOP_COLUMNS", lugre::LoopPoint::COLUMNS)?;
    models::document(m)?;
    Ok(())
}
