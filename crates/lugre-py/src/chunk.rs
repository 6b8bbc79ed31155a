//! The chunked rainflow count (core `lugre::cycles::chunk`) over numpy arrays: the pieces
//! `lugre.dask` schedules as tasks. Summaries pickle (as bytes); everything else is a dict of
//! numpy arrays.

use lugre::cycles::chunk::{
    self, ArcSpan, ChunkEnergy, ChunkSummary, ClosureQuery, OpenCycle, RowKey, StateBounds,
};
use lugre::{Closure, Cycle, CycleColumns};
use numpy::{IntoPyArray, PyReadonlyArray1};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList};

use crate::convert::{self, value_error, vec_out};
use crate::cycles::{cycle_table, summary_dict};
use crate::models::lugre_of;

/// What a chunk (or a run of adjacent chunks) tells the rest of the history: its ends, extremes
/// and irreducible residue. Picklable.
#[pyclass(name = "ChunkSummary", module = "lugre._lugre", frozen)]
#[derive(Clone)]
pub struct PyChunkSummary(pub ChunkSummary);

#[pymethods]
impl PyChunkSummary {
    /// Global index of the first sample.
    #[getter]
    fn start(&self) -> u64 {
        self.0.start()
    }
    /// Global index of the last sample.
    #[getter]
    fn end(&self) -> u64 {
        self.0.end()
    }
    #[getter]
    fn first(&self) -> f64 {
        self.0.first()
    }
    #[getter]
    fn last(&self) -> f64 {
        self.0.last()
    }
    #[getter]
    fn min(&self) -> f64 {
        self.0.min()
    }
    #[getter]
    fn max(&self) -> f64 {
        self.0.max()
    }
    /// Full cycles closed inside (a leaf's own rows).
    #[getter]
    fn full_cycles(&self) -> u64 {
        self.0.full_cycles()
    }
    /// Length of the irreducible residue kept.
    #[getter]
    fn residue_len(&self) -> usize {
        self.0.residue().len()
    }
    fn to_bytes<'py>(&self, py: Python<'py>) -> Bound<'py, PyBytes> {
        PyBytes::new(py, &self.0.to_bytes())
    }
    #[staticmethod]
    fn from_bytes(data: &[u8]) -> PyResult<Self> {
        ChunkSummary::from_bytes(data)
            .map(Self)
            .map_err(value_error)
    }
    fn __reduce__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyAny>, (Bound<'py, PyBytes>,))> {
        let from = py.get_type::<Self>().getattr("from_bytes")?;
        Ok((from, (self.to_bytes(py),)))
    }
    fn __repr__(&self) -> String {
        format!(
            "ChunkSummary(u[{}..={}], residue of {})",
            self.0.start(),
            self.0.end(),
            self.0.residue().len()
        )
    }
}

/// A chunk's own rows, kept in Rust between the count and the assembly (no copy through
/// numpy). Picklable (as its columns).
#[pyclass(name = "ChunkRows", module = "lugre._lugre", frozen)]
pub struct PyChunkRows(CycleColumns);

#[pymethods]
impl PyChunkRows {
    fn __len__(&self) -> usize {
        self.0.len()
    }
    /// The rows as a dict of numpy columns (a copy).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        table(py, self.0.clone())
    }
    #[staticmethod]
    fn from_dict(columns: &Bound<'_, PyDict>) -> PyResult<Self> {
        columns_of(columns).map(Self)
    }
    fn __reduce__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyAny>, (Bound<'py, PyDict>,))> {
        let from = py.get_type::<Self>().getattr("from_dict")?;
        Ok((from, (self.to_dict(py)?,)))
    }
    /// The bytes held (Dask's memory accounting reads it).
    fn __sizeof__(&self) -> usize {
        let columns = if self.0.keeps_energy() { 11 } else { 7 };
        64 + 8 * columns * self.0.len()
    }
    fn __repr__(&self) -> String {
        format!("ChunkRows({} rows)", self.0.len())
    }
}

fn f64s(d: &Bound<'_, PyDict>, key: &str) -> PyResult<Vec<f64>> {
    let a: PyReadonlyArray1<f64> = item(d, key)?.extract()?;
    Ok(a.as_array().to_vec())
}

fn i64s(d: &Bound<'_, PyDict>, key: &str) -> PyResult<Vec<i64>> {
    let a: PyReadonlyArray1<i64> = item(d, key)?.extract()?;
    Ok(a.as_array().to_vec())
}

fn item<'py>(d: &Bound<'py, PyDict>, key: &str) -> PyResult<Bound<'py, PyAny>> {
    d.get_item(key)?
        .ok_or_else(|| pyo3::exceptions::PyKeyError::new_err(key.to_string()))
}

/// The cycle table columns of `c` (those of `lugre.cycles`, closures included).
fn table<'py>(py: Python<'py>, c: CycleColumns) -> PyResult<Bound<'py, PyDict>> {
    let energy = c.keeps_energy();
    cycle_table(py, c, energy)
}

fn columns_of(d: &Bound<'_, PyDict>) -> PyResult<CycleColumns> {
    let mut c = CycleColumns::new().with_reversals(false);
    c.range = f64s(d, "range")?;
    c.mean = f64s(d, "mean")?;
    c.count = f64s(d, "count")?;
    c.start = i64s(d, "start")?;
    c.end = i64s(d, "end")?;
    c.closure = i64s(d, "closure")?;
    c.closure_position = f64s(d, "closure_position")?;
    if d.contains("work")? {
        c = c.with_energy(true);
        c.work = f64s(d, "work")?;
        c.stored_energy_change = f64s(d, "stored_energy_change")?;
        c.dissipation = f64s(d, "dissipation")?;
        c.closure_gap = f64s(d, "closure_gap")?;
    }
    Ok(c)
}

/// `chunk_count(samples, offset)`: the chunk's summary and its own rows (`ChunkRows`; the few
/// half cycles among them are dropped by `chunk_assemble`).
#[pyfunction]
pub fn chunk_count<'py>(
    py: Python<'py>,
    samples: &Bound<'py, PyAny>,
    offset: u64,
) -> PyResult<(PyChunkSummary, PyChunkRows)> {
    let u = convert::series(samples, "samples")?;
    let u = u.as_slice();
    let (s, rows) = py
        .detach(|| chunk::count_chunk(u, offset))
        .map_err(value_error)?;
    Ok((PyChunkSummary(s), PyChunkRows(rows)))
}

/// `chunk_merge(left, right)`: the summary of two adjacent runs and the full cycles only the
/// two together complete (a dict of columns with their values, waiting for closures).
#[pyfunction]
pub fn chunk_merge<'py>(
    py: Python<'py>,
    left: &PyChunkSummary,
    right: &PyChunkSummary,
) -> PyResult<(PyChunkSummary, Bound<'py, PyDict>)> {
    let (s, open) = chunk::merge(&left.0, &right.0).map_err(value_error)?;
    let d = PyDict::new(py);
    let col = |f: fn(&OpenCycle) -> f64| open.iter().map(f).collect::<Vec<f64>>();
    d.set_item("range", vec_out(py, col(|o| o.cycle.range)))?;
    d.set_item("mean", vec_out(py, col(|o| o.cycle.mean)))?;
    d.set_item("count", vec_out(py, col(|o| o.cycle.count)))?;
    d.set_item("u_start", vec_out(py, col(|o| o.u_start)))?;
    d.set_item("u_end", vec_out(py, col(|o| o.u_end)))?;
    let idx = |f: fn(&OpenCycle) -> u64| {
        open.iter()
            .map(|o| f(o) as i64)
            .collect::<Vec<i64>>()
            .into_pyarray(py)
    };
    d.set_item("start", idx(|o| o.cycle.start))?;
    d.set_item("end", idx(|o| o.cycle.end))?;
    Ok((PyChunkSummary(s), d))
}

fn open_of(d: &Bound<'_, PyDict>) -> PyResult<Vec<OpenCycle>> {
    let (range, mean, count) = (f64s(d, "range")?, f64s(d, "mean")?, f64s(d, "count")?);
    let (u_start, u_end) = (f64s(d, "u_start")?, f64s(d, "u_end")?);
    let (start, end) = (i64s(d, "start")?, i64s(d, "end")?);
    Ok((0..range.len())
        .map(|k| OpenCycle {
            cycle: Cycle {
                range: range[k],
                mean: mean[k],
                count: count[k],
                start: start[k] as u64,
                end: end[k] as u64,
                closure: None,
                energy: None,
            },
            u_start: u_start[k],
            u_end: u_end[k],
        })
        .collect())
}

/// The driver's bookkeeping of a chunked count (core `ChunkPlan`).
#[pyclass(name = "ChunkPlan", module = "lugre._lugre")]
pub struct PyChunkPlan(chunk::ChunkPlan);

#[pymethods]
impl PyChunkPlan {
    #[new]
    fn new(leaves: Vec<Bound<'_, PyChunkSummary>>) -> PyResult<Self> {
        chunk::ChunkPlan::new(leaves.iter().map(|l| l.get().0.clone()).collect())
            .map(Self)
            .map_err(value_error)
    }

    /// Adds the open cycles of a merge (`chunk_merge`'s dict).
    fn add_open(&mut self, open: &Bound<'_, PyDict>) -> PyResult<()> {
        self.0.add_open(&open_of(open)?);
        Ok(())
    }

    /// Counts the whole history's residue (`root`: the merge of every leaf); returns the
    /// summary of `lugre.cycles` ("samples", "reversals", "full_cycles", "half_cycles").
    fn finish<'py>(
        &mut self,
        py: Python<'py>,
        root: &PyChunkSummary,
    ) -> PyResult<Bound<'py, PyDict>> {
        let s = self.0.finish(&root.0).map_err(value_error)?;
        summary_dict(py, &s)
    }

    /// The closure queries, one entry per chunk: None or a dict of columns.
    fn queries<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let out = PyList::empty(py);
        for qs in self.0.queries().map_err(value_error)? {
            if qs.is_empty() {
                out.append(py.None())?;
                continue;
            }
            let d = PyDict::new(py);
            let ids: Vec<i64> = qs.iter().map(|q| q.id as i64).collect();
            let after: Vec<i64> = qs.iter().map(|q| q.after as i64).collect();
            d.set_item("id", ids.into_pyarray(py))?;
            d.set_item("after", after.into_pyarray(py))?;
            d.set_item(
                "u_start",
                vec_out(py, qs.iter().map(|q| q.u_start).collect()),
            )?;
            d.set_item("u_end", vec_out(py, qs.iter().map(|q| q.u_end).collect()))?;
            out.append(d)?;
        }
        Ok(out)
    }

    /// Records the closures `chunk_close` found.
    fn resolve(&mut self, found: &Bound<'_, PyDict>) -> PyResult<()> {
        let (id, index, position) = (
            i64s(found, "id")?,
            i64s(found, "index")?,
            f64s(found, "position")?,
        );
        let found: Vec<(usize, Closure)> = (0..id.len())
            .map(|k| {
                (
                    id[k] as usize,
                    Closure {
                        index: index[k] as u64,
                        position: position[k],
                    },
                )
            })
            .collect();
        self.0.resolve(&found);
        Ok(())
    }

    /// The parts of the merge-time cycles' arcs each chunk's energy pass sums: one entry per
    /// chunk, None or a dict of columns "id", "from" and "to" (sample indices, -1 for the
    /// chunk's entry or end) and "u_start".
    fn energy_spans<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let out = PyList::empty(py);
        for spans in self.0.energy_spans().map_err(value_error)? {
            if spans.is_empty() {
                out.append(py.None())?;
                continue;
            }
            let col = |f: &dyn Fn(&ArcSpan) -> i64| spans.iter().map(f).collect::<Vec<i64>>();
            let d = PyDict::new(py);
            d.set_item("id", col(&|s| s.id as i64).into_pyarray(py))?;
            d.set_item(
                "from",
                col(&|s| s.from.map_or(-1, |i| i as i64)).into_pyarray(py),
            )?;
            d.set_item(
                "to",
                col(&|s| s.to.map_or(-1, |t| t.0 as i64)).into_pyarray(py),
            )?;
            let u_a: Vec<f64> = spans.iter().map(|s| s.to.map_or(0.0, |t| t.1)).collect();
            d.set_item("u_start", vec_out(py, u_a))?;
            out.append(d)?;
        }
        Ok(out)
    }

    /// Attaches the merge-time cycles' energies from every chunk's energy pass (the bytes of
    /// `chunk_count_energy`, in chunk order).
    fn attach_energy(&mut self, model: &Bound<'_, PyAny>, passes: Vec<Vec<u8>>) -> PyResult<()> {
        let m = lugre_of(model)?.rate_independent();
        let passes = energies(&passes)?;
        self.0.attach_energy(m, &passes).map_err(value_error)
    }

    /// The rows to merge into each chunk's own: a dict of columns (and sort keys) per chunk.
    #[pyo3(signature = (energy=false))]
    fn extras<'py>(&self, py: Python<'py>, energy: bool) -> PyResult<Bound<'py, PyList>> {
        let out = PyList::empty(py);
        for rows in self.0.extras().map_err(value_error)? {
            let mut c = CycleColumns::new()
                .with_reversals(false)
                .with_energy(energy);
            let mut keys = Vec::with_capacity(rows.len());
            for (key, cycle) in rows {
                lugre::CycleSink::cycle(&mut c, cycle);
                keys.push(key.to_bytes());
            }
            let d = table(py, c)?;
            let flat: Vec<u8> = keys.concat();
            d.set_item("key", PyBytes::new(py, &flat))?;
            out.append(d)?;
        }
        Ok(out)
    }
}

/// `chunk_close(samples, offset, prev, queries)`: the closures of `queries` in this chunk
/// (`prev`: the sample before it, None for the first chunk).
#[pyfunction]
#[pyo3(signature = (samples, offset, prev, queries))]
pub fn chunk_close<'py>(
    py: Python<'py>,
    samples: &Bound<'py, PyAny>,
    offset: u64,
    prev: Option<f64>,
    queries: &Bound<'py, PyDict>,
) -> PyResult<Bound<'py, PyDict>> {
    let (id, after) = (i64s(queries, "id")?, i64s(queries, "after")?);
    let (u_start, u_end) = (f64s(queries, "u_start")?, f64s(queries, "u_end")?);
    let qs: Vec<ClosureQuery> = (0..id.len())
        .map(|k| ClosureQuery {
            id: id[k] as usize,
            after: after[k] as u64,
            u_start: u_start[k],
            u_end: u_end[k],
        })
        .collect();
    let u = convert::series(samples, "samples")?;
    let u = u.as_slice();
    let found = py
        .detach(|| chunk::close_in_chunk(u, offset, prev, &qs))
        .map_err(value_error)?;
    let d = PyDict::new(py);
    let ids: Vec<i64> = found.iter().map(|f| f.0 as i64).collect();
    let index: Vec<i64> = found.iter().map(|f| f.1.index as i64).collect();
    d.set_item("id", ids.into_pyarray(py))?;
    d.set_item("index", index.into_pyarray(py))?;
    d.set_item(
        "position",
        vec_out(py, found.iter().map(|f| f.1.position).collect()),
    )?;
    Ok(d)
}

/// `chunk_assemble(own, extras)`: a chunk's rows (`ChunkRows`) merged with the plan's extras
/// for it, in the single pass's order (a dict of the cycle table's columns).
#[pyfunction]
pub fn chunk_assemble<'py>(
    py: Python<'py>,
    own: &PyChunkRows,
    extras: &Bound<'py, PyDict>,
) -> PyResult<Bound<'py, PyDict>> {
    let more = columns_of(extras)?;
    let keys: Vec<u8> = item(extras, "key")?.extract()?;
    let rows: Vec<(RowKey, Cycle)> = keys
        .chunks_exact(RowKey::BYTES)
        .zip(0..more.len())
        .map(|(k, i)| {
            Ok((
                RowKey::from_bytes(k).map_err(value_error)?,
                more.cycle_at(i),
            ))
        })
        .collect::<PyResult<_>>()?;
    let own = &own.0;
    let out = py.detach(|| chunk::assemble(own, &rows));
    table(py, out)
}

fn energies(passes: &[Vec<u8>]) -> PyResult<Vec<ChunkEnergy>> {
    passes
        .iter()
        .map(|b| ChunkEnergy::from_bytes(b).map_err(value_error))
        .collect()
}

/// `chunk_bounds(samples, offset, prev, model)`: `y*` at the chunk's last sample from the
/// entry states `+g0` and `-g0`, as a tuple (upper, lower).
#[pyfunction]
pub fn chunk_bounds(
    py: Python<'_>,
    samples: &Bound<'_, PyAny>,
    offset: u64,
    prev: Option<f64>,
    model: &Bound<'_, PyAny>,
) -> PyResult<(f64, f64)> {
    let m = lugre_of(model)?.rate_independent();
    let u = convert::series(samples, "samples")?;
    let u = u.as_slice();
    let b = py
        .detach(|| chunk::state_bounds(u, offset, prev, m))
        .map_err(value_error)?;
    Ok((b.upper, b.lower))
}

/// `chunk_guess_entries(model, y_start, bounds)`: every chunk's guessed entry state from the
/// chunks' `chunk_bounds`, in order (exact for chunk 0).
#[pyfunction]
pub fn chunk_guess_entries(
    model: &Bound<'_, PyAny>,
    y_start: f64,
    bounds: Vec<(f64, f64)>,
) -> PyResult<Vec<f64>> {
    let m = lugre_of(model)?.rate_independent();
    let b: Vec<StateBounds> = bounds
        .into_iter()
        .map(|(upper, lower)| StateBounds { upper, lower })
        .collect();
    Ok(chunk::guess_entries(m, y_start, &b))
}

/// `chunk_count_energy(samples, offset, prev, y_entry, model, spans)`: the chunk's own rows
/// with energies (`ChunkRows`), its energy pass for the driver (bytes) and `y*` at its
/// last sample.
#[pyfunction]
#[pyo3(signature = (samples, offset, prev, y_entry, model, spans))]
pub fn chunk_count_energy<'py>(
    py: Python<'py>,
    samples: &Bound<'py, PyAny>,
    offset: u64,
    prev: Option<f64>,
    y_entry: f64,
    model: &Bound<'py, PyAny>,
    spans: Option<&Bound<'py, PyDict>>,
) -> PyResult<(PyChunkRows, Bound<'py, PyBytes>, f64)> {
    let m = lugre_of(model)?.rate_independent();
    let spans: Vec<ArcSpan> = match spans {
        None => Vec::new(),
        Some(d) => {
            let (id, from, to) = (i64s(d, "id")?, i64s(d, "from")?, i64s(d, "to")?);
            let u_a = f64s(d, "u_start")?;
            (0..id.len())
                .map(|k| ArcSpan {
                    id: id[k] as usize,
                    from: (from[k] >= 0).then_some(from[k] as u64),
                    to: (to[k] >= 0).then_some((to[k] as u64, u_a[k])),
                })
                .collect()
        }
    };
    let u = convert::series(samples, "samples")?;
    let u = u.as_slice();
    let (rows, pass) = py
        .detach(|| chunk::count_chunk_energy(u, offset, prev, y_entry, m, &spans))
        .map_err(value_error)?;
    let y_last = pass.y_last;
    Ok((
        PyChunkRows(rows),
        PyBytes::new(py, &pass.to_bytes()),
        y_last,
    ))
}

/// `chunk_history_energy(model, y_start, passes)`: the totals along the whole history (the
/// summary's "energy") from every chunk's energy pass, in order.
#[pyfunction]
pub fn chunk_history_energy<'py>(
    py: Python<'py>,
    model: &Bound<'py, PyAny>,
    y_start: f64,
    passes: Vec<Vec<u8>>,
) -> PyResult<Bound<'py, PyAny>> {
    let m = lugre_of(model)?.rate_independent();
    let e = chunk::history_energy(m, y_start, &energies(&passes)?);
    let s = lugre::CycleSummary {
        samples: 0,
        reversals: 0,
        full_cycles: 0,
        half_cycles: 0,
        energy: Some(e),
    };
    summary_dict(py, &s)?
        .get_item("energy")?
        .ok_or_else(|| pyo3::exceptions::PyKeyError::new_err("energy"))
}
