//! The chunked rainflow count (core `lugre::cycles::chunk`) over numpy arrays: the pieces
//! `lugre.dask` schedules as tasks. Summaries pickle (as bytes); everything else is a dict of
//! numpy arrays.

use lugre::cycles::chunk::{
    self, ArcSpan, ChunkEnergy, ChunkSummary, ClosureQuery, OpenCycle, RowKey, StateBounds,
};
use lugre::cycles::ColumnMut;
use lugre::{Closure, Cycle, CycleColumns};
use numpy::{IntoPyArray, PyReadonlyArray1};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList};

use crate::convert::{self, value_error, vec_out};
use crate::cycles::{cycle_table, summary_dict};
use crate::cycles::{energy_model, Energy};
use lugre::zoo::{ZooChunkEnergy, ZooChunkState};

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
        columns_of(columns, "columns").map(Self)
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

/// The columns of a dict a chunk function takes (named `what` in errors): each column asked
/// for must be there, a 1-D numpy array of the right dtype, as long as the first one read.
struct Columns<'a, 'py> {
    d: &'a Bound<'py, PyDict>,
    what: &'static str,
    /// The first column read and its length.
    first: Option<(&'static str, usize)>,
}

impl<'a, 'py> Columns<'a, 'py> {
    fn new(d: &'a Bound<'py, PyDict>, what: &'static str) -> Self {
        Self {
            d,
            what,
            first: None,
        }
    }

    fn has(&self, key: &str) -> PyResult<bool> {
        self.d.contains(key)
    }

    fn item(&self, key: &str) -> PyResult<Bound<'py, PyAny>> {
        self.d
            .get_item(key)?
            .ok_or_else(|| PyValueError::new_err(format!("{}: no column '{key}'", self.what)))
    }

    /// Column `key` as `T`s (`dtype` names numpy's type in errors), of the common length.
    fn column<T: numpy::Element + Copy>(
        &mut self,
        key: &'static str,
        dtype: &str,
    ) -> PyResult<Vec<T>> {
        let mut item = self.item(key)?;
        // A misaligned buffer (an array unpickled from a Dask worker can be) is copied into
        // numpy's own aligned memory first: viewing it in place would be undefined behaviour.
        if let Ok(u) = item.cast::<numpy::PyUntypedArray>() {
            if !numpy::PyUntypedArrayMethods::is_aligned(u) {
                item = item.call_method0("copy")?;
            }
        }
        let a: PyReadonlyArray1<T> = item.extract().map_err(|_| {
            PyTypeError::new_err(format!(
                "{}: column '{key}' must be a 1-D numpy array of {dtype}, got {}",
                self.what,
                convert::type_name(&item)
            ))
        })?;
        let n = a.len()?;
        match self.first {
            None => self.first = Some((key, n)),
            Some((name, len)) if len != n => {
                return Err(PyValueError::new_err(format!(
                    "{}: column '{key}' has {n} values, column '{name}' has {len}",
                    self.what
                )))
            }
            Some(_) => {}
        }
        Ok(a.as_array().to_vec())
    }

    fn f64s(&mut self, key: &'static str) -> PyResult<Vec<f64>> {
        self.column(key, "float64")
    }

    fn i64s(&mut self, key: &'static str) -> PyResult<Vec<i64>> {
        self.column(key, "int64")
    }

    /// An int64 column of sample indices or ids (none negative).
    fn indices(&mut self, key: &'static str) -> PyResult<Vec<u64>> {
        let v = self.i64s(key)?;
        v.iter()
            .map(|&i| {
                u64::try_from(i).map_err(|_| {
                    PyValueError::new_err(format!(
                        "{}: column '{key}' must hold indices >= 0, got {i}",
                        self.what
                    ))
                })
            })
            .collect()
    }
}

/// The cycle table columns of `c` (those of `lugre.cycles`, closures included).
fn table<'py>(py: Python<'py>, c: CycleColumns) -> PyResult<Bound<'py, PyDict>> {
    cycle_table(py, c)
}

/// The cycle table in the dict `d` (the argument `what`): the columns of `lugre.cycles`,
/// closures included, with energies when "work" is there; all of one length.
fn columns_of(d: &Bound<'_, PyDict>, what: &'static str) -> PyResult<CycleColumns> {
    let mut t = Columns::new(d, what);
    // With energies when the first energy column is there (the core's names throughout).
    let energy = t.has(CycleColumns::NAMES[7])?;
    let mut c = CycleColumns::new()
        .with_reversals(false)
        .with_energy(energy);
    for name in c.kept_names() {
        match c.column_mut(name) {
            Some(ColumnMut::Real(v)) => *v = t.f64s(name)?,
            Some(ColumnMut::Index(v)) => *v = t.i64s(name)?,
            None => {}
        }
    }
    Ok(c)
}

/// Where a chunk lies: `offset` (an index >= 0) such that its `samples` samples end at or
/// before the last index a history can have, and `prev` (the sample before it) only after
/// u[0] and a sample the count takes; each error names its argument.
fn placed(offset: &Bound<'_, PyAny>, samples: usize, prev: Option<f64>) -> PyResult<u64> {
    let offset = convert::count(offset, "offset")?;
    chunk::check_offset(offset, samples)
        .map_err(|e| PyValueError::new_err(format!("offset: {e}")))?;
    chunk::check_prev(offset, prev).map_err(|e| PyValueError::new_err(format!("prev: {e}")))?;
    Ok(offset)
}

/// `chunk_count(samples, offset)`: the chunk's summary and its own rows (`ChunkRows`; the few
/// half cycles among them are dropped by `chunk_assemble`).
#[pyfunction]
pub fn chunk_count<'py>(
    py: Python<'py>,
    samples: &Bound<'py, PyAny>,
    offset: &Bound<'py, PyAny>,
) -> PyResult<(PyChunkSummary, PyChunkRows)> {
    let u = convert::series(samples, "samples")?;
    let u = u.as_slice();
    let offset = placed(offset, u.len(), None)?;
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
    let [range, mean, count, start, end, ..] = CycleColumns::NAMES;
    d.set_item(range, vec_out(py, col(|o| o.cycle.range)))?;
    d.set_item(mean, vec_out(py, col(|o| o.cycle.mean)))?;
    d.set_item(count, vec_out(py, col(|o| o.cycle.count)))?;
    d.set_item("u_start", vec_out(py, col(|o| o.u_start)))?;
    d.set_item("u_end", vec_out(py, col(|o| o.u_end)))?;
    let idx = |f: fn(&OpenCycle) -> u64| {
        open.iter()
            .map(|o| f(o) as i64)
            .collect::<Vec<i64>>()
            .into_pyarray(py)
    };
    d.set_item(start, idx(|o| o.cycle.start))?;
    d.set_item(end, idx(|o| o.cycle.end))?;
    Ok((PyChunkSummary(s), d))
}

fn open_of(d: &Bound<'_, PyDict>) -> PyResult<Vec<OpenCycle>> {
    let mut t = Columns::new(d, "open");
    let [range, mean, count, start, end, ..] = CycleColumns::NAMES;
    let (range, mean, count) = (t.f64s(range)?, t.f64s(mean)?, t.f64s(count)?);
    let (u_start, u_end) = (t.f64s("u_start")?, t.f64s("u_end")?);
    let (start, end) = (t.indices(start)?, t.indices(end)?);
    Ok((0..range.len())
        .map(|k| OpenCycle {
            cycle: Cycle {
                range: range[k],
                mean: mean[k],
                count: count[k],
                start: start[k],
                end: end[k],
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
        let mut t = Columns::new(found, "found");
        let (id, index, position) = (t.indices("id")?, t.indices("index")?, t.f64s("position")?);
        let found: Vec<(usize, Closure)> = (0..id.len())
            .map(|k| {
                (
                    id[k] as usize,
                    Closure {
                        index: index[k],
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
        match energy_model(model, None)? {
            Energy::Classic(m) => self.0.attach_energy(m, &energies(&passes)?),
            Energy::Zoo(z) => z.attach_energy(&mut self.0, &zoo_energies(&passes)?),
        }
        .map_err(value_error)
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
    offset: &Bound<'py, PyAny>,
    prev: Option<f64>,
    queries: &Bound<'py, PyDict>,
) -> PyResult<Bound<'py, PyDict>> {
    let mut t = Columns::new(queries, "queries");
    let (id, after) = (t.indices("id")?, t.indices("after")?);
    let (u_start, u_end) = (t.f64s("u_start")?, t.f64s("u_end")?);
    let qs: Vec<ClosureQuery> = (0..id.len())
        .map(|k| ClosureQuery {
            id: id[k] as usize,
            after: after[k],
            u_start: u_start[k],
            u_end: u_end[k],
        })
        .collect();
    let u = convert::series(samples, "samples")?;
    let u = u.as_slice();
    let offset = placed(offset, u.len(), prev)?;
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
    let more = columns_of(extras, "extras")?;
    let keys: Vec<u8> = Columns::new(extras, "extras")
        .item("key")?
        .extract()
        .map_err(|_| PyTypeError::new_err("extras: 'key' must be bytes"))?;
    if keys.len() != RowKey::BYTES * more.len() {
        return Err(PyValueError::new_err(format!(
            "extras: 'key' has {} bytes, {} for the {} rows",
            keys.len(),
            RowKey::BYTES * more.len(),
            more.len()
        )));
    }
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

fn zoo_energies(passes: &[Vec<u8>]) -> PyResult<Vec<ZooChunkEnergy>> {
    passes
        .iter()
        .map(|b| ZooChunkEnergy::from_bytes(b).map_err(value_error))
        .collect()
}

/// An entry state: LuGre's `y*` (a float) or a zoo model's state (bytes), named `what`.
fn zoo_state(state: &Bound<'_, PyAny>, what: &str) -> PyResult<ZooChunkState> {
    let bytes: Vec<u8> = state.extract().map_err(|_| {
        PyTypeError::new_err(format!(
            "{what}: the entry state of a model of the zoo is bytes (of chunk_start_entry, \
             chunk_guess_entries or chunk_count_energy), got {}",
            crate::convert::type_name(state)
        ))
    })?;
    ZooChunkState::from_bytes(&bytes).map_err(|e| PyValueError::new_err(format!("{what}: {e}")))
}

/// `chunk_start_entry(model, x0, first)`: the first chunk's entry state (exact): LuGre's
/// `y* = sigma0 x0` (a float), or a zoo model's state at rest at the history's first sample
/// `first` (bytes; `x0` must be None).
#[pyfunction]
#[pyo3(signature = (model, x0, first))]
pub fn chunk_start_entry<'py>(
    py: Python<'py>,
    model: &Bound<'py, PyAny>,
    x0: Option<f64>,
    first: f64,
) -> PyResult<Bound<'py, PyAny>> {
    Ok(match energy_model(model, x0)? {
        Energy::Classic(m) => (m.sigma0() * x0.unwrap_or(0.0))
            .into_pyobject(py)?
            .into_any(),
        Energy::Zoo(z) => PyBytes::new(py, &z.chunk_start(first).to_bytes()).into_any(),
    })
}

/// `chunk_bounds(samples, offset, prev, model)`: the state at the chunk's last sample from
/// the two extreme entry states (LuGre's `y*` from `+g0` and `-g0`; a single-state model's
/// `z` from its bounds), as a tuple (upper, lower); None for a Masing model of the zoo (its
/// entries follow from the chunks' residues).
#[pyfunction]
pub fn chunk_bounds(
    py: Python<'_>,
    samples: &Bound<'_, PyAny>,
    offset: &Bound<'_, PyAny>,
    prev: Option<f64>,
    model: &Bound<'_, PyAny>,
) -> PyResult<Option<(f64, f64)>> {
    let model = energy_model(model, None)?;
    let u = convert::series(samples, "samples")?;
    let u = u.as_slice();
    let offset = placed(offset, u.len(), prev)?;
    let b = py
        .detach(|| match model {
            Energy::Classic(m) => chunk::state_bounds(u, offset, prev, m).map(Some),
            Energy::Zoo(z) => z.chunk_bounds(u, offset, prev),
        })
        .map_err(value_error)?;
    Ok(b.map(|b| (b.upper, b.lower)))
}

/// `chunk_guess_entries(model, y_start, bounds, leaves=None)`: every chunk's guessed entry
/// state from the chunks' `chunk_bounds` (and, for a model of the zoo, their summaries
/// `leaves`), in order, from `y_start` (`chunk_start_entry`; chunk 0's, exact).
#[pyfunction]
#[pyo3(signature = (model, y_start, bounds, leaves=None))]
pub fn chunk_guess_entries<'py>(
    py: Python<'py>,
    model: &Bound<'py, PyAny>,
    y_start: &Bound<'py, PyAny>,
    bounds: Vec<Option<(f64, f64)>>,
    leaves: Option<Vec<Bound<'py, PyChunkSummary>>>,
) -> PyResult<Bound<'py, PyList>> {
    let b = |(upper, lower)| StateBounds { upper, lower };
    match energy_model(model, None)? {
        Energy::Classic(m) => {
            let y: f64 = y_start.extract()?;
            let bounds = bounds
                .into_iter()
                .enumerate()
                .map(|(k, x)| {
                    x.map(b).ok_or_else(|| {
                        PyValueError::new_err(format!(
                            "bounds[{k}] is None: LuGre's entry states need both bounds of \
                             every chunk (chunk_bounds)"
                        ))
                    })
                })
                .collect::<PyResult<Vec<_>>>()?;
            let g = chunk::guess_entries(m, y, &bounds).map_err(value_error)?;
            PyList::new(py, g)
        }
        Energy::Zoo(z) => {
            let start = zoo_state(y_start, "y_start")?;
            let leaves: Vec<ChunkSummary> = leaves
                .ok_or_else(|| {
                    PyValueError::new_err(
                        "leaves: a model of the zoo needs the chunks' summaries (chunk_count's), \
                         got None",
                    )
                })?
                .iter()
                .map(|l| l.get().0.clone())
                .collect();
            let bounds: Vec<_> = bounds.into_iter().map(|x| x.map(b)).collect();
            let g = z
                .guess_entries(&start, &bounds, &leaves)
                .map_err(value_error)?;
            PyList::new(py, g.iter().map(|s| PyBytes::new(py, &s.to_bytes())))
        }
    }
}

/// `chunk_count_energy(samples, offset, prev, y_entry, model, spans)`: the chunk's own rows
/// with energies (`ChunkRows`), its energy pass for the driver (bytes) and the state at its
/// last sample (LuGre's `y*`, a float; a zoo model's state, bytes), entering at `y_entry`.
#[pyfunction]
#[pyo3(signature = (samples, offset, prev, y_entry, model, spans))]
pub fn chunk_count_energy<'py>(
    py: Python<'py>,
    samples: &Bound<'py, PyAny>,
    offset: &Bound<'py, PyAny>,
    prev: Option<f64>,
    y_entry: &Bound<'py, PyAny>,
    model: &Bound<'py, PyAny>,
    spans: Option<&Bound<'py, PyDict>>,
) -> PyResult<(PyChunkRows, Bound<'py, PyBytes>, Bound<'py, PyAny>)> {
    let model = energy_model(model, None)?;
    let spans: Vec<ArcSpan> = match spans {
        None => Vec::new(),
        Some(d) => {
            let mut t = Columns::new(d, "spans");
            let (id, from, to) = (t.indices("id")?, t.i64s("from")?, t.i64s("to")?);
            let u_a = t.f64s("u_start")?;
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
    let offset = placed(offset, u.len(), prev)?;
    match model {
        Energy::Classic(m) => {
            let y: f64 = y_entry.extract()?;
            let (rows, pass) = py
                .detach(|| chunk::count_chunk_energy(u, offset, prev, y, m, &spans))
                .map_err(value_error)?;
            let last = pass.y_last.into_pyobject(py)?.into_any();
            Ok((PyChunkRows(rows), PyBytes::new(py, &pass.to_bytes()), last))
        }
        Energy::Zoo(z) => {
            let entry = zoo_state(y_entry, "y_entry")?;
            let (rows, pass) = py
                .detach(|| z.count_chunk_energy(u, offset, prev, &entry, &spans))
                .map_err(value_error)?;
            let last = PyBytes::new(py, &pass.last.to_bytes()).into_any();
            Ok((PyChunkRows(rows), PyBytes::new(py, &pass.to_bytes()), last))
        }
    }
}

/// `chunk_history_energy(model, y_start, passes)`: the totals along the whole history (the
/// summary's "energy") from every chunk's energy pass, in order.
#[pyfunction]
pub fn chunk_history_energy<'py>(
    py: Python<'py>,
    model: &Bound<'py, PyAny>,
    y_start: &Bound<'py, PyAny>,
    passes: Vec<Vec<u8>>,
) -> PyResult<Bound<'py, PyAny>> {
    let e = match energy_model(model, None)? {
        Energy::Classic(m) => chunk::history_energy(m, y_start.extract()?, &energies(&passes)?),
        Energy::Zoo(z) => {
            z.history_energy(&zoo_state(y_start, "y_start")?, &zoo_energies(&passes)?)
        }
    }
    .map_err(value_error)?;
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
