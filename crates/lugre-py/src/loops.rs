//! `lugre.HysteresisLoop` and what it reports: `Loop`, `LoopPoint`, `TheoremA`, `Curve`.

use std::sync::OnceLock;

use numpy::IntoPyArray;
use pyo3::exceptions::{PyIndexError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};

use crate::convert::{
    count, float_repr, floats, list_repr, map_floats, try_vec, value_error, vec_out,
};

/// The hysteresis loop y° of a model for one periodic input (the rate-independent limit,
/// paper eqs. 8-10), with all its minor loops and their energies.
///
/// Made by LuGre.loop / Dahl.loop (turning points) or LuGre.loop_bimodal /
/// Dahl.loop_bimodal. `rho` is the normalized variable (the input's variation, eq. 7): the
/// input runs at unit speed in rho between turning points, rho = 0 at the first turning
/// point, and the loop is periodic in rho with period `period`.
///
/// Attributes: rho, u, y (float64 arrays at the turning points), period, work_per_period,
/// model, theorem_a (bimodal inputs; None otherwise), loops, loop_table (the loops as numpy
/// columns).
/// Methods: y_at(rho), u_at(rho), sample(n).
///
/// Picklable (multiprocessing, joblib, Dask): it pickles as its model and input and is
/// computed again on loading, to the same bits.
#[pyclass(frozen, module = "lugre", name = "HysteresisLoop")]
pub struct PyHysteresisLoop {
    hl: lugre::HysteresisLoop,
    model: Py<PyAny>,
    theorem_a: Option<lugre::TheoremA>,
    loops: OnceLock<Vec<lugre::Loop>>,
    /// What the loop was made from, to make it again (pickling): the bimodal corners, or the
    /// turning points.
    made_from: Input,
}

/// The input of a [`PyHysteresisLoop`], as the model's method that made it took it.
enum Input {
    TurningPoints(Vec<f64>),
    Bimodal([f64; 4]),
}

/// `f(r)` for a finite `r`, NaN otherwise (a NaN or infinite rho has no place on the loop).
#[inline]
fn finite_or_nan(r: f64, f: impl Fn(f64) -> f64) -> f64 {
    if r.is_finite() {
        f(r)
    } else {
        f64::NAN
    }
}

impl PyHysteresisLoop {
    fn build(
        py: Python<'_>,
        model_obj: &Bound<'_, PyAny>,
        model: lugre::RateIndependent,
        tp: &lugre::TurningPoints,
        bimodal: Option<(lugre::Bimodal, [f64; 4])>,
        input_name: &str,
    ) -> PyResult<Self> {
        let hl = py
            .detach(|| lugre::HysteresisLoop::new(model, tp))
            .map_err(|e| match e {
                lugre::LoopError::Input(e) => PyValueError::new_err(format!("{input_name}{e}")),
                e => value_error(e),
            })?;
        let theorem_a = bimodal.map(|(b, _)| lugre::TheoremA::new(&b, &hl));
        let made_from = match bimodal {
            Some((_, corners)) => Input::Bimodal(corners),
            None => Input::TurningPoints(tp.values().to_vec()),
        };
        Ok(Self {
            hl,
            model: model_obj.clone().unbind(),
            theorem_a,
            loops: OnceLock::new(),
            made_from,
        })
    }

    pub fn from_turning_points(
        model_obj: &Bound<'_, PyAny>,
        model: lugre::RateIndependent,
        turning_points: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        let py = model_obj.py();
        let u = floats(turning_points, "turning_points")?
            .one_dimensional("turning_points", turning_points)?;
        let tp = py
            .detach(|| lugre::TurningPoints::new(&u))
            .map_err(|e| PyValueError::new_err(format!("turning_points: {e}")))?;
        Self::build(py, model_obj, model, &tp, None, "turning_points: ")
    }

    pub fn from_bimodal(
        model_obj: &Bound<'_, PyAny>,
        model: lugre::RateIndependent,
        corners: [&Bound<'_, PyAny>; 4],
    ) -> PyResult<Self> {
        let py = model_obj.py();
        let [umin1, umin2, umax1, umax2] =
            crate::convert::reals(corners, ["umin1", "umin2", "umax1", "umax2"])?;
        let b = lugre::Bimodal::new(umin1, umin2, umax1, umax2).map_err(value_error)?;
        let corners = [umin1, umin2, umax1, umax2];
        Self::build(
            py,
            model_obj,
            model,
            &b.turning_points(),
            Some((b, corners)),
            "",
        )
    }

    fn rust_loops(&self, py: Python<'_>) -> &[lugre::Loop] {
        if self.loops.get().is_none() {
            let computed = py.detach(|| self.hl.loops());
            let _ = self.loops.set(computed);
        }
        self.loops.get().expect("set above")
    }
}

#[pymethods]
impl PyHysteresisLoop {
    /// rho at the turning points (float64 array, from 0).
    #[getter]
    fn rho<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        vec_out(py, self.hl.turning_rho().to_vec())
    }

    /// The turning points u_k in the loop's order (float64 array; the first is at rho = 0).
    #[getter]
    fn u<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        vec_out(py, self.hl.turning_points().to_vec())
    }

    /// y° at the turning points (float64 array).
    #[getter]
    fn y<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        vec_out(py, self.hl.turning_y().to_vec())
    }

    /// The period P in rho: the total variation of the input over one period.
    #[getter]
    fn period(&self) -> f64 {
        self.hl.period()
    }

    /// The work of the friction force over one period, integral of y° du: the energy
    /// dissipated per cycle.
    #[getter]
    fn work_per_period(&self) -> f64 {
        self.hl.work_per_period()
    }

    /// g(0) of the model: |y°| < g0.
    #[getter]
    fn g0(&self) -> f64 {
        self.hl.model().g0()
    }

    /// a = sigma0 / g(0).
    #[getter]
    fn a(&self) -> f64 {
        self.hl.model().a()
    }

    /// The model (LuGre or Dahl) this loop was computed for.
    #[getter]
    fn model(&self, py: Python<'_>) -> Py<PyAny> {
        self.model.clone_ref(py)
    }

    /// Theorem A for a bimodal input (LuGre.loop_bimodal): rho_0..rho_5, y° there and the
    /// minor loop [rho_1, rho_5]. None for other inputs.
    #[getter]
    fn theorem_a(&self) -> Option<PyTheoremA> {
        self.theorem_a.map(|inner| PyTheoremA { inner })
    }

    /// Every loop: [0] is the major loop (the whole period, starting at a global maximum),
    /// then the minor loops ordered by where their arcs start (a parent before its children).
    /// Each is a Loop with kind, start, reversal, end, work, stored_energy_change,
    /// dissipation, closure_gap, parent and depth.
    #[getter]
    fn loops<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        loop_list(py, self.rust_loops(py))
    }

    /// Every loop of `loops` as numpy columns, one row per loop in the same order: a dict
    /// with `kind` (0 for the major loop, 1 for a minor one), `start_rho`, `start_u`,
    /// `start_y`, `reversal_rho`, ..., `end_y`, `work`, `stored_energy_change`,
    /// `dissipation`, `closure_gap` (float64), `parent` (int64, -1 for the major loop) and
    /// `depth` (int64). Built without a Python object per loop: for inputs with many
    /// turning points (`pandas.DataFrame(hl.loop_table)` gives a table).
    #[getter]
    fn loop_table<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        // Straight from the engine's columns, in the order of `loops`: no record per loop.
        let hl = &self.hl;
        let t = hl.loop_table();
        let (order, place) = py.detach(|| t.rows_by_start());
        let (u, rho, y) = (hl.turning_points(), hl.turning_rho(), hl.turning_y());
        let (start, reversal) = (t.start(), t.reversal());
        let gather =
            |f: &dyn Fn(usize) -> f64| -> Vec<f64> { order.iter().map(|&r| f(r)).collect() };
        let gather_int =
            |f: &dyn Fn(usize) -> i64| -> Vec<i64> { order.iter().map(|&r| f(r)).collect() };
        let out = PyDict::new(py);
        let major = t.major();
        out.set_item(
            "kind",
            gather_int(&|r| i64::from(r != major)).into_pyarray(py),
        )?;
        let columns: [&dyn Fn(usize) -> f64; 13] = [
            &|r| rho[start[r]],
            &|r| u[start[r]],
            &|r| y[start[r]],
            &|r| t.reversal_rho()[r],
            &|r| u[reversal[r]],
            &|r| y[reversal[r]],
            &|r| t.end_rho()[r],
            &|r| t.end_u()[r],
            &|r| t.end_y()[r],
            &|r| t.work()[r],
            &|r| t.stored_energy_change()[r],
            &|r| t.dissipation()[r],
            &|r| t.closure_gap()[r],
        ];
        for (name, value) in TABLE_COLUMNS.into_iter().zip(columns) {
            out.set_item(name, vec_out(py, gather(value)))?;
        }
        out.set_item(
            "parent",
            gather_int(&|r| t.parent(r).map_or(-1, |p| place[p] as i64)).into_pyarray(py),
        )?;
        out.set_item(
            "depth",
            gather_int(&|r| t.depth()[r] as i64).into_pyarray(py),
        )?;
        Ok(out)
    }

    /// y°(rho), elementwise and periodic in rho: a float for a number, a float64 array of the
    /// same shape for any array-like (list, tuple, numpy array of any real dtype, contiguous
    /// or not). NaN where rho is NaN or infinite.
    #[pyo3(signature = (rho))]
    fn y_at<'py>(&self, rho: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        map_floats(rho, "rho", |r| finite_or_nan(r, |r| self.hl.y_at(r)))
    }

    /// The normalized input psi_u(rho) (eq. 12), elementwise and periodic in rho (a float or a
    /// float64 array, like y_at).
    #[pyo3(signature = (rho))]
    fn u_at<'py>(&self, rho: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        map_floats(rho, "rho", |r| finite_or_nan(r, |r| self.hl.psi_at(r)))
    }

    /// n >= 2 points evenly spaced over one period, both ends included (rho = 0 and rho =
    /// period). Returns a Curve with float64 arrays rho, u, y; it unpacks as
    /// `rho, u, y = hl.sample(1001)`.
    #[pyo3(signature = (n=None), text_signature = "($self, n=1001)")]
    fn sample(&self, py: Python<'_>, n: Option<&Bound<'_, PyAny>>) -> PyResult<PyCurve> {
        let n = samples_n(n)?;
        PyCurve::from_points(py, n, || Ok::<_, lugre::SamplesError>(self.hl.sample(n)))
    }

    /// Number of turning points in one period.
    fn __len__(&self) -> usize {
        self.hl.len()
    }

    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        Ok(format!(
            "HysteresisLoop(model={}, turning_points={}, period={}, work_per_period={}, loops={})",
            self.model.bind(py).repr()?,
            list_repr(py, self.hl.turning_points(), 8),
            float_repr(py, self.hl.period()),
            float_repr(py, self.hl.work_per_period()),
            self.rust_loops(py).len()
        ))
    }

    /// Pickling: the model's `loop` (or `loop_bimodal`) with the input it took.
    fn __reduce__<'py>(&self, py: Python<'py>) -> Pickle<'py, Bound<'py, PyTuple>> {
        let model = self.model.bind(py);
        match &self.made_from {
            Input::Bimodal(corners) => {
                Ok((model.getattr("loop_bimodal")?, PyTuple::new(py, corners)?))
            }
            Input::TurningPoints(u) => Ok((
                model.getattr("loop")?,
                PyTuple::new(py, [vec_out(py, u.clone())])?,
            )),
        }
    }

    fn __traverse__(&self, visit: pyo3::PyVisit<'_>) -> Result<(), pyo3::PyTraverseError> {
        visit.call(&self.model)
    }
}

/// The float columns of a loop table (`loop_table`), between `kind` and `parent`, `depth`.
const TABLE_COLUMNS: [&str; 13] = [
    "start_rho",
    "start_u",
    "start_y",
    "reversal_rho",
    "reversal_u",
    "reversal_y",
    "end_rho",
    "end_u",
    "end_y",
    "work",
    "stored_energy_change",
    "dissipation",
    "closure_gap",
];

/// The loop records as a list of `lugre.Loop`.
pub(crate) fn loop_list<'py>(
    py: Python<'py>,
    loops: &[lugre::Loop],
) -> PyResult<Bound<'py, PyList>> {
    PyList::new(py, loops.iter().map(|l| PyLoop { inner: l.clone() }))
}

/// The loop records as `loop_table`'s columns (rows in the records' order; `parent` -1 for
/// none), for a loop whose engine keeps records rather than columns.
pub(crate) fn records_table<'py>(
    py: Python<'py>,
    loops: &[lugre::Loop],
) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    let ints = |f: &dyn Fn(&lugre::Loop) -> i64| -> Vec<i64> { loops.iter().map(f).collect() };
    out.set_item(
        "kind",
        ints(&|l| i64::from(l.kind != lugre::LoopKind::Major)).into_pyarray(py),
    )?;
    let columns: [fn(&lugre::Loop) -> f64; 13] = [
        |l| l.start.rho,
        |l| l.start.u,
        |l| l.start.y,
        |l| l.reversal.rho,
        |l| l.reversal.u,
        |l| l.reversal.y,
        |l| l.end.rho,
        |l| l.end.u,
        |l| l.end.y,
        |l| l.energy.work,
        |l| l.energy.stored_energy_change,
        |l| l.energy.dissipation,
        |l| l.energy.closure_gap,
    ];
    for (name, f) in TABLE_COLUMNS.into_iter().zip(columns) {
        out.set_item(name, vec_out(py, loops.iter().map(f).collect()))?;
    }
    out.set_item(
        "parent",
        ints(&|l| l.parent.map_or(-1, |p| p as i64)).into_pyarray(py),
    )?;
    out.set_item("depth", ints(&|l| l.depth as i64).into_pyarray(py))?;
    Ok(out)
}

/// The `n` of `sample(n)`: 1001 when not given, checked as the core checks it.
pub(crate) fn samples_n(n: Option<&Bound<'_, PyAny>>) -> PyResult<usize> {
    let n = match n {
        Some(n) if !n.is_none() => count(n, "n")?,
        _ => 1001,
    };
    let n = usize::try_from(n).unwrap_or(usize::MAX);
    lugre::loops::check_samples(n).map_err(|e| PyValueError::new_err(e.render("n")))?;
    Ok(n)
}

/// `f(r)` for each of `rho`, elementwise (a float or a float64 array as [`map_floats`]), NaN
/// where `r` is not finite; `f` is handed every finite value at once (one walk of the loop).
pub(crate) fn map_points<'py>(
    rho: &Bound<'py, PyAny>,
    f: impl Fn(&[f64]) -> Vec<f64> + Send + Sync,
) -> PyResult<Bound<'py, PyAny>> {
    let py = rho.py();
    let x = crate::convert::floats(rho, "rho")?;
    let finite: Vec<f64> = x.data.iter().copied().filter(|r| r.is_finite()).collect();
    let mut values = py.detach(|| f(&finite)).into_iter();
    let out: Vec<f64> = x
        .data
        .iter()
        .map(|r| {
            if r.is_finite() {
                values.next().unwrap_or(f64::NAN)
            } else {
                f64::NAN
            }
        })
        .collect();
    if x.shape.is_empty() && !x.was_array {
        return Ok(pyo3::types::PyFloat::new(py, out[0]).into_any());
    }
    crate::convert::array_out(py, out, &x.shape)
}

/// What `__reduce__` returns: a callable and its arguments.
type Pickle<'py, S> = PyResult<(Bound<'py, PyAny>, S)>;

/// `(cls._restore, state)`: how the value classes below pickle.
fn restore_with<'py, S>(cls: Bound<'py, pyo3::types::PyType>, state: S) -> Pickle<'py, S> {
    Ok((cls.getattr("_restore")?, state))
}

/// A point of the loop: rho, the input u = psi_u(rho) and the output y = y°(rho). Unpacks as
/// `rho, u, y = point`.
#[pyclass(frozen, eq, module = "lugre", name = "LoopPoint")]
#[derive(Clone, PartialEq)]
pub struct PyLoopPoint {
    inner: lugre::LoopPoint,
}

#[pymethods]
impl PyLoopPoint {
    #[getter]
    fn rho(&self) -> f64 {
        self.inner.rho
    }
    #[getter]
    fn u(&self) -> f64 {
        self.inner.u
    }
    #[getter]
    fn y(&self) -> f64 {
        self.inner.y
    }

    fn __len__(&self) -> usize {
        3
    }

    fn __getitem__(&self, i: isize) -> PyResult<f64> {
        let p = self.inner;
        match i {
            0 | -3 => Ok(p.rho),
            1 | -2 => Ok(p.u),
            2 | -1 => Ok(p.y),
            _ => Err(PyIndexError::new_err("LoopPoint index out of range")),
        }
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        let p = self.inner;
        format!(
            "LoopPoint(rho={}, u={}, y={})",
            float_repr(py, p.rho),
            float_repr(py, p.u),
            float_repr(py, p.y)
        )
    }

    /// {"rho": ..., "u": ..., "y": ...}
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        point_dict(py, &self.inner)
    }

    /// Pickling: the point's three numbers.
    fn __reduce__<'py>(&self, py: Python<'py>) -> Pickle<'py, (f64, f64, f64)> {
        let p = self.inner;
        restore_with(py.get_type::<Self>(), (p.rho, p.u, p.y))
    }

    /// The point of a pickle.
    #[staticmethod]
    fn _restore(rho: f64, u: f64, y: f64) -> Self {
        Self {
            inner: lugre::LoopPoint { rho, u, y },
        }
    }
}

fn point_dict<'py>(py: Python<'py>, p: &lugre::LoopPoint) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("rho", p.rho)?;
    d.set_item("u", p.u)?;
    d.set_item("y", p.y)?;
    Ok(d)
}

/// One loop of the hysteresis curve: the arc from `start` (rho_A) through the reversal
/// `reversal` (rho_B) to `end` (rho_C, where the input first returns to u_A), with the
/// energy over the arc.
///
/// kind: "major" (the whole period) or "minor"; work: W = integral of y° du over the arc
/// (nested loops included); stored_energy_change: dV = (y_C^2 - y_A^2) / (2 sigma0);
/// dissipation: D = W - dV >= 0; closure_gap: y_C - y_A (minor loops do not close in
/// general); parent: index in HysteresisLoop.loops of the smallest loop containing this one
/// (None for the major loop); depth: 0 for the major loop, parent's depth + 1 otherwise.
#[pyclass(frozen, module = "lugre", name = "Loop")]
pub struct PyLoop {
    inner: lugre::Loop,
}

#[pymethods]
impl PyLoop {
    /// "major" or "minor".
    #[getter]
    fn kind(&self) -> &'static str {
        match self.inner.kind {
            lugre::LoopKind::Major => "major",
            lugre::LoopKind::Minor => "minor",
        }
    }
    /// Where the arc starts (rho_A, in [0, period)).
    #[getter]
    fn start(&self) -> PyLoopPoint {
        PyLoopPoint {
            inner: self.inner.start,
        }
    }
    /// The reversal the loop turns at (rho_B).
    #[getter]
    fn reversal(&self) -> PyLoopPoint {
        PyLoopPoint {
            inner: self.inner.reversal,
        }
    }
    /// Where the input first returns to u_A (rho_C; may exceed the period when the arc wraps).
    #[getter]
    fn end(&self) -> PyLoopPoint {
        PyLoopPoint {
            inner: self.inner.end,
        }
    }
    /// W = integral of y° du over the arc, nested loops included.
    #[getter]
    fn work(&self) -> f64 {
        self.inner.energy.work
    }
    /// dV = (y_C^2 - y_A^2) / (2 sigma0), the change of the energy stored in the bristles.
    #[getter]
    fn stored_energy_change(&self) -> f64 {
        self.inner.energy.stored_energy_change
    }
    /// D = W - dV = (1/g0) integral of y°^2 drho >= 0.
    #[getter]
    fn dissipation(&self) -> f64 {
        self.inner.energy.dissipation
    }
    /// y_C - y_A.
    #[getter]
    fn closure_gap(&self) -> f64 {
        self.inner.energy.closure_gap
    }
    /// Index of the smallest loop containing this one (None for the major loop).
    #[getter]
    fn parent(&self) -> Option<usize> {
        self.inner.parent
    }
    /// 0 for the major loop, parent's depth + 1 otherwise.
    #[getter]
    fn depth(&self) -> usize {
        self.inner.depth
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        let l = &self.inner;
        let f = |v| float_repr(py, v);
        let parent = l.parent.map_or("None".to_string(), |p| p.to_string());
        let point =
            |p: &lugre::LoopPoint| format!("(rho={}, u={}, y={})", f(p.rho), f(p.u), f(p.y));
        format!(
            "Loop(kind='{}', depth={}, parent={}, start={}, reversal={}, end={}, work={}, \
             stored_energy_change={}, dissipation={}, closure_gap={})",
            self.kind(),
            l.depth,
            parent,
            point(&l.start),
            point(&l.reversal),
            point(&l.end),
            f(l.energy.work),
            f(l.energy.stored_energy_change),
            f(l.energy.dissipation),
            f(l.energy.closure_gap)
        )
    }

    /// The loop as a dict, with the keys of `lugre loop --json` (start, reversal and end as
    /// dicts {"rho", "u", "y"}).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let l = &self.inner;
        let d = PyDict::new(py);
        d.set_item("kind", self.kind())?;
        d.set_item("start", point_dict(py, &l.start)?)?;
        d.set_item("reversal", point_dict(py, &l.reversal)?)?;
        d.set_item("end", point_dict(py, &l.end)?)?;
        d.set_item("work", l.energy.work)?;
        d.set_item("stored_energy_change", l.energy.stored_energy_change)?;
        d.set_item("dissipation", l.energy.dissipation)?;
        d.set_item("closure_gap", l.energy.closure_gap)?;
        d.set_item("parent", l.parent)?;
        d.set_item("depth", l.depth)?;
        Ok(d)
    }

    /// Pickling: the loop's fields.
    fn __reduce__<'py>(&self, py: Python<'py>) -> Pickle<'py, LoopState> {
        let l = &self.inner;
        let point = |p: &lugre::LoopPoint| (p.rho, p.u, p.y);
        let e = l.energy;
        let state = (
            l.kind == lugre::LoopKind::Major,
            [point(&l.start), point(&l.reversal), point(&l.end)],
            [e.work, e.stored_energy_change, e.dissipation, e.closure_gap],
            l.parent,
            l.depth,
        );
        restore_with(py.get_type::<Self>(), state)
    }

    /// The loop of a pickle.
    #[staticmethod]
    fn _restore(
        major: bool,
        points: [(f64, f64, f64); 3],
        energy: [f64; 4],
        parent: Option<usize>,
        depth: usize,
    ) -> Self {
        let point = |(rho, u, y)| lugre::LoopPoint { rho, u, y };
        let [work, stored_energy_change, dissipation, closure_gap] = energy;
        Self {
            inner: lugre::Loop {
                kind: if major {
                    lugre::LoopKind::Major
                } else {
                    lugre::LoopKind::Minor
                },
                start: point(points[0]),
                reversal: point(points[1]),
                end: point(points[2]),
                energy: lugre::ArcEnergy {
                    work,
                    stored_energy_change,
                    dissipation,
                    closure_gap,
                },
                parent,
                depth,
            },
        }
    }
}

/// A pickled [`PyLoop`]: major, (start, reversal, end), the four energies, parent, depth.
type LoopState = (bool, [(f64, f64, f64); 3], [f64; 4], Option<usize>, usize);

/// Theorem A for a bimodal input: rho_0..rho_5 (the turning points at rho_0..rho_3, the
/// period rho_4, and rho_5 where the input first returns to umax1), y° at each, and the minor
/// loop [rho_1, rho_5]. print() shows them as a table.
#[pyclass(frozen, module = "lugre", name = "TheoremA")]
pub struct PyTheoremA {
    inner: lugre::TheoremA,
}

#[pymethods]
impl PyTheoremA {
    /// rho_0..rho_5 (float64 array of 6).
    #[getter]
    fn rho<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        vec_out(py, self.inner.rho.to_vec())
    }
    /// y°(rho_0)..y°(rho_5) (float64 array of 6).
    #[getter]
    fn y<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        vec_out(py, self.inner.y.to_vec())
    }
    /// The minor loop's arc (rho_1, rho_5).
    #[getter]
    fn minor_loop(&self) -> (f64, f64) {
        (self.inner.minor_loop[0], self.inner.minor_loop[1])
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        format!(
            "TheoremA(rho={}, y={}, minor_loop=({}, {}))",
            list_repr(py, &self.inner.rho, 6),
            list_repr(py, &self.inner.y, 6),
            float_repr(py, self.inner.minor_loop[0]),
            float_repr(py, self.inner.minor_loop[1])
        )
    }

    fn __str__(&self, py: Python<'_>) -> String {
        let t = &self.inner;
        let mut s = String::from("Theorem A (bimodal input)\n");
        s.push_str(&format!(
            "{:>7}  {:>24}  {:>24}\n",
            "i", "rho_i", "y°(rho_i)"
        ));
        for i in 0..6 {
            s.push_str(&format!(
                "{:>7}  {:>24}  {:>24}\n",
                format!("rho_{i}"),
                float_repr(py, t.rho[i]),
                float_repr(py, t.y[i])
            ));
        }
        s.push_str(&format!(
            "minor loop: rho in [rho_1, rho_5] = [{}, {}]",
            float_repr(py, t.minor_loop[0]),
            float_repr(py, t.minor_loop[1])
        ));
        s
    }

    /// {"rho": [...6], "y": [...6], "minor_loop": [rho_1, rho_5]} (lists of floats, as in
    /// `lugre loop --json`).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("rho", self.inner.rho.to_vec())?;
        d.set_item("y", self.inner.y.to_vec())?;
        d.set_item("minor_loop", self.inner.minor_loop.to_vec())?;
        Ok(d)
    }

    /// Pickling: rho_0..rho_5, y there and the minor loop.
    fn __reduce__<'py>(&self, py: Python<'py>) -> Pickle<'py, ([f64; 6], [f64; 6], [f64; 2])> {
        let t = self.inner;
        restore_with(py.get_type::<Self>(), (t.rho, t.y, t.minor_loop))
    }

    /// Theorem A of a pickle.
    #[staticmethod]
    fn _restore(rho: [f64; 6], y: [f64; 6], minor_loop: [f64; 2]) -> Self {
        Self {
            inner: lugre::TheoremA { rho, y, minor_loop },
        }
    }
}

/// Points of the loop: float64 arrays rho, u (= psi_u(rho)) and y (= y°(rho)). Unpacks as
/// `rho, u, y = curve`.
#[pyclass(frozen, module = "lugre", name = "Curve")]
pub struct PyCurve {
    rho: Py<PyAny>,
    u: Py<PyAny>,
    y: Py<PyAny>,
}

impl PyCurve {
    /// The curve of the `n` points `points` makes (run detached).
    pub(crate) fn from_points<E: std::fmt::Display + Send>(
        py: Python<'_>,
        n: usize,
        points: impl FnOnce() -> Result<Vec<lugre::LoopPoint>, E> + Send,
    ) -> PyResult<Self> {
        let mut rho = try_vec(n)?;
        let mut u = try_vec(n)?;
        let mut y = try_vec(n)?;
        py.detach(|| -> Result<(), E> {
            for p in points()? {
                rho.push(p.rho);
                u.push(p.u);
                y.push(p.y);
            }
            Ok(())
        })
        .map_err(value_error)?;
        Ok(Self {
            rho: vec_out(py, rho).unbind(),
            u: vec_out(py, u).unbind(),
            y: vec_out(py, y).unbind(),
        })
    }
}

#[pymethods]
impl PyCurve {
    #[getter]
    fn rho(&self, py: Python<'_>) -> Py<PyAny> {
        self.rho.clone_ref(py)
    }
    #[getter]
    fn u(&self, py: Python<'_>) -> Py<PyAny> {
        self.u.clone_ref(py)
    }
    #[getter]
    fn y(&self, py: Python<'_>) -> Py<PyAny> {
        self.y.clone_ref(py)
    }

    fn __iter__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let t = PyTuple::new(
            py,
            [
                self.rho.clone_ref(py),
                self.u.clone_ref(py),
                self.y.clone_ref(py),
            ],
        )?;
        t.try_iter().map(|i| i.into_any())
    }

    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        Ok(format!("Curve(n={})", self.rho.bind(py).len()?))
    }

    /// {"rho": ..., "u": ..., "y": ...} (the arrays themselves, not copies).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("rho", self.rho.bind(py))?;
        d.set_item("u", self.u.bind(py))?;
        d.set_item("y", self.y.bind(py))?;
        Ok(d)
    }

    /// The points as a `pandas.DataFrame` with the columns rho, u, y (pandas is imported
    /// here, only).
    fn to_frame<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        py.import("pandas")?
            .getattr("DataFrame")?
            .call1((self.to_dict(py)?,))
    }

    /// Pickling: the three arrays.
    fn __reduce__<'py>(&self, py: Python<'py>) -> Pickle<'py, (Py<PyAny>, Py<PyAny>, Py<PyAny>)> {
        let state = (
            self.rho.clone_ref(py),
            self.u.clone_ref(py),
            self.y.clone_ref(py),
        );
        restore_with(py.get_type::<Self>(), state)
    }

    /// The curve of a pickle.
    #[staticmethod]
    fn _restore(rho: Py<PyAny>, u: Py<PyAny>, y: Py<PyAny>) -> Self {
        Self { rho, u, y }
    }

    fn __traverse__(&self, visit: pyo3::PyVisit<'_>) -> Result<(), pyo3::PyTraverseError> {
        visit.call(&self.rho)?;
        visit.call(&self.u)?;
        visit.call(&self.y)
    }
}
