//! `lugre.ZooModel` and `lugre.ZooLoop`: every model of the core's zoo table
//! ([`lugre::zoo::MODELS`]) through one class, its parameters by the table's names, and
//! `lugre.ZOO_MODELS`, the table itself. No model is named here: a model added to the table is
//! in Python without a change.

use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString, PyTuple};

use crate::convert::{float_repr, floats, list_repr, type_name, value_error, vec_out};
use crate::loops::{loop_list, map_points, records_table, samples_n, PyCurve};
use crate::simulate::zoo_input;
use lugre::zoo::{Shape, ZooModel, ZooModelSpec, ZooParameter, MODELS};
use lugre::ZooError;

/// A model of the zoo (Maxwell-slip, Prandtl-Ishlinskii, ... : `lugre.ZOO_MODELS` lists them
/// with their parameters), made by name with its parameters as keywords, by the table's names:
///
/// >>> m = lugre.ZooModel("maxwell-slip", stiffness=[1, 2], slip_force=[1, 0.5])
/// >>> hl = m.loop([3, 1, 2, -3])
///
/// An element array is any sequence or numpy array of real numbers (a number is one element),
/// a scalar parameter a real number; a parameter not given takes the table's default. Invalid
/// values and a keyword the model does not have raise ValueError with the message of
/// `lugre loop --model NAME` (and of C and MATLAB); a value of the wrong type raises
/// TypeError naming the keyword.
///
/// Attributes: name, label, parameters (a dict: each parameter by name, a float64 array for
/// element arrays, a float for scalars). Method: loop(turning_points). Picklable.
#[pyclass(frozen, eq, module = "lugre", name = "ZooModel")]
#[derive(Clone, PartialEq)]
pub struct PyZooModel {
    inner: ZooModel,
}

impl PyZooModel {
    /// The core's model.
    pub(crate) fn model(&self) -> &ZooModel {
        &self.inner
    }
}

/// The values of `parameters` by name (keywords of [`PyZooModel::new`]), as the core takes
/// them; the core checks names against the model's table.
fn given_values(
    spec: &ZooModelSpec,
    parameters: Option<&Bound<'_, PyDict>>,
) -> PyResult<Vec<(String, Vec<f64>)>> {
    let mut out = Vec::new();
    let Some(d) = parameters else {
        return Ok(out);
    };
    for (key, value) in d.iter() {
        let name = key.str()?.to_string();
        let values = match spec.parameter(&name) {
            Some(p) => parameter_values(p, &value)?,
            // Handed to the core unread: its message names the model's parameters.
            None => Vec::new(),
        };
        out.push((name, values));
    }
    Ok(out)
}

/// One parameter's values: a number, or a one-dimensional sequence or array of them (the core
/// refuses more than one value for a scalar parameter, as every front end's).
fn parameter_values(p: &ZooParameter, value: &Bound<'_, PyAny>) -> PyResult<Vec<f64>> {
    let x = floats(value, p.name)?;
    if x.shape.is_empty() {
        Ok(x.data)
    } else {
        x.one_dimensional(p.name, value)
    }
}

/// A core error as Python raises it: a ValueError with the core's message (a parameter the
/// model does not have included: the name is a value here, the model being chosen by name,
/// and C and MATLAB refuse it in the same words).
fn zoo_error(e: ZooError) -> PyErr {
    value_error(e)
}

/// The model of the zoo called `name` (a `str`), or the core's refusal; LuGre and Dahl are
/// their own classes.
fn spec_named(name: &Bound<'_, PyAny>) -> PyResult<&'static ZooModelSpec> {
    let text = name.cast::<PyString>().map_err(|_| {
        PyTypeError::new_err(format!("name must be a string, got {}", type_name(name)))
    })?;
    let text = text.to_cow()?;
    if let Some(f) = lugre::fit::Family::ALL
        .into_iter()
        .find(|f| f.name().eq_ignore_ascii_case(text.trim()))
    {
        return Err(PyValueError::new_err(format!(
            "name: '{}' is not a model of the zoo; use lugre.{}",
            text.trim(),
            f.label()
        )));
    }
    match ZooModelSpec::find(&text) {
        Some(spec) => Ok(spec),
        // The core's refusal of the name, naming the models.
        None => Err(ZooModel::new(&text, &[]).map_or_else(zoo_error, |_| {
            PyValueError::new_err(format!("name: unknown model '{text}'"))
        })),
    }
}

/// Each parameter of `model` by name into `d`: a float64 array for an element array, a float
/// for a scalar.
fn set_parameters(d: &Bound<'_, PyDict>, model: &ZooModel) -> PyResult<()> {
    let py = d.py();
    for (p, (name, values)) in model.spec().parameters.iter().zip(model.named()) {
        match p.shape {
            Shape::Scalar => d.set_item(name, values.first().copied().unwrap_or_default())?,
            Shape::Elements => d.set_item(name, vec_out(py, values))?,
        }
    }
    Ok(())
}

/// The model as every command's JSON echoes it (`lugre simulate --model NAME --json`'s
/// `model`): its name as `kind`, then each parameter by name.
pub(crate) fn echo<'py>(py: Python<'py>, model: &ZooModel) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("kind", model.spec().name)?;
    set_parameters(&d, model)?;
    Ok(d)
}

#[pymethods]
impl PyZooModel {
    #[new]
    #[pyo3(signature = (name, **parameters))]
    fn new(name: &Bound<'_, PyAny>, parameters: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        let spec = spec_named(name)?;
        let given = given_values(spec, parameters)?;
        let borrowed: Vec<(&str, &[f64])> = given
            .iter()
            .map(|(n, v)| (n.as_str(), v.as_slice()))
            .collect();
        Ok(Self {
            inner: ZooModel::new(spec.name, &borrowed).map_err(zoo_error)?,
        })
    }

    /// The model's name in the table (`--model NAME`).
    #[getter]
    fn name(&self) -> &'static str {
        self.inner.spec().name
    }

    /// The model's name in reports.
    #[getter]
    fn label(&self) -> &'static str {
        self.inner.spec().label
    }

    /// Each parameter by name in the table's order: a float64 array for an element array, a
    /// float for a scalar (the values of `lugre loop --json`'s `model`).
    #[getter]
    fn parameters<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        set_parameters(&d, &self.inner)?;
        Ok(d)
    }

    /// The loop and every minor loop for one period of a periodic input given by its turning
    /// points (any sequence or array of real numbers, as LuGre.loop takes them), with their
    /// energies. Returns a ZooLoop.
    #[pyo3(signature = (turning_points))]
    fn r#loop(slf: &Bound<'_, Self>, turning_points: &Bound<'_, PyAny>) -> PyResult<PyZooLoop> {
        PyZooLoop::new(slf, turning_points)
    }

    /// The force at each sample of a piecewise-linear input from rest (as `lugre simulate
    /// --model NAME`): exact for a rate-independent model, at finite rate where the model has
    /// rate dependence (elasto-plastic). Exactly one input:
    ///
    /// * t, u: samples (t strictly increasing, in s), u linear in between;
    /// * turning_points: through these values at the constant `speed` (default 1), one period.
    ///
    /// Returns a dict: model (the model's name as "kind" and its parameters by name, as
    /// `lugre simulate --json` echoes it), t, u, y (float64 arrays; y the force at each
    /// sample; turning points at 200 times per period and each turning point, or
    /// samples_per_period). LuGre's own keywords (x0, gamma, periods, tol, times, sine,
    /// interpolate='cubic') raise ValueError, as the CLI refuses their flags; invalid
    /// input raises ValueError naming the argument, a wrong type TypeError.
    #[pyo3(signature = (turning_points=None, t=None, u=None, speed=None, samples_per_period=None, **others))]
    #[allow(clippy::too_many_arguments)]
    fn simulate<'py>(
        &self,
        py: Python<'py>,
        turning_points: Option<&Bound<'py, PyAny>>,
        t: Option<&Bound<'py, PyAny>>,
        u: Option<&Bound<'py, PyAny>>,
        speed: Option<&Bound<'py, PyAny>>,
        samples_per_period: Option<&Bound<'py, PyAny>>,
        others: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let input = [turning_points, t, u, speed, samples_per_period];
        let (t, u) = zoo_input(&self.inner, input, others)?;
        let y = py
            .detach(|| self.inner.simulate(&t, &u))
            .map_err(value_error)?;
        let d = PyDict::new(py);
        d.set_item("model", echo(py, &self.inner)?)?;
        d.set_item("t", vec_out(py, t))?;
        d.set_item("u", vec_out(py, u))?;
        d.set_item("y", vec_out(py, y))?;
        Ok(d)
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        let items: Vec<String> = self
            .inner
            .spec()
            .parameters
            .iter()
            .zip(self.inner.named())
            .map(|(p, (name, v))| match p.shape {
                Shape::Scalar => format!("{name}={}", float_repr(py, v[0])),
                Shape::Elements => format!("{name}={}", list_repr(py, &v, usize::MAX)),
            })
            .collect();
        format!("ZooModel('{}', {})", self.name(), items.join(", "))
    }

    /// Pickling and copying: the name and the parameters as keywords.
    fn __getnewargs_ex__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyTuple>, Bound<'py, PyDict>)> {
        Ok((PyTuple::new(py, [self.name()])?, self.parameters(py)?))
    }
}

/// The loop of a model of the zoo for one periodic input, with every minor loop and their
/// energies: the surface of `lugre.HysteresisLoop` (rho, u, y at the turning points, period,
/// work_per_period, model, loops, loop_table, y_at, u_at, sample), the force F in the place of
/// y°. Made by ZooModel.loop; picklable (it pickles as its model and input and is computed
/// again on loading, to the same bits).
#[pyclass(frozen, module = "lugre", name = "ZooLoop")]
pub struct PyZooLoop {
    zl: lugre::zoo::ZooLoop,
    /// The model's object (returned by `model`, pickled) and the model itself.
    model: Py<PyZooModel>,
    inner: ZooModel,
}

impl PyZooLoop {
    fn new(model: &Bound<'_, PyZooModel>, turning_points: &Bound<'_, PyAny>) -> PyResult<Self> {
        let py = model.py();
        let u = floats(turning_points, "turning_points")?
            .one_dimensional("turning_points", turning_points)?;
        let m = &model.get().inner;
        let zl = py
            .detach(|| {
                let tp = lugre::TurningPoints::new(&u)?;
                m.loops(&tp)
            })
            .map_err(|e| match e {
                ZooError::Input(e) => PyValueError::new_err(format!("turning_points: {e}")),
                e => zoo_error(e),
            })?;
        Ok(Self {
            zl,
            model: model.clone().unbind(),
            inner: m.clone(),
        })
    }

    /// The loop's points at `rho` (finite values), one walk over the period.
    fn at(&self, rho: &[f64]) -> Vec<lugre::LoopPoint> {
        self.inner.points(&self.zl, rho)
    }
}

#[pymethods]
impl PyZooLoop {
    /// rho at the turning points (float64 array, from 0).
    #[getter]
    fn rho<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        vec_out(py, self.zl.turning_rho().to_vec())
    }

    /// The turning points u_k in the loop's order (float64 array; the first is at rho = 0).
    #[getter]
    fn u<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        vec_out(py, self.zl.turning_points().to_vec())
    }

    /// The periodic force F at the turning points (float64 array).
    #[getter]
    fn y<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        vec_out(py, self.zl.turning_force().to_vec())
    }

    /// The period P in rho: the total variation of the input over one period.
    #[getter]
    fn period(&self) -> f64 {
        self.zl.period()
    }

    /// The work of the force over one period, integral of F du (the major loop's work).
    #[getter]
    fn work_per_period(&self) -> f64 {
        self.zl.work_per_period()
    }

    /// The ZooModel this loop was computed for.
    #[getter]
    fn model(&self, py: Python<'_>) -> Py<PyZooModel> {
        self.model.clone_ref(py)
    }

    /// Every loop, as HysteresisLoop.loops: [0] is the major loop, then the minor loops
    /// ordered by where their arcs start, each a Loop with its energies (work,
    /// stored_energy_change, dissipation, closure_gap: the model's stored energy and
    /// dissipation) and its parent and depth.
    #[getter]
    fn loops<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        loop_list(py, self.zl.loops())
    }

    /// Every loop of `loops` as numpy columns, as HysteresisLoop.loop_table.
    #[getter]
    fn loop_table<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        records_table(py, self.zl.loops())
    }

    /// The force F(rho), elementwise and periodic in rho: a float for a number, a float64
    /// array of the same shape for any array-like. NaN where rho is NaN or infinite.
    #[pyo3(signature = (rho))]
    fn y_at<'py>(&self, rho: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        map_points(rho, |r| self.at(r).iter().map(|p| p.y).collect())
    }

    /// The input u(rho), elementwise and periodic in rho (a float or a float64 array, like
    /// y_at).
    #[pyo3(signature = (rho))]
    fn u_at<'py>(&self, rho: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        map_points(rho, |r| self.at(r).iter().map(|p| p.u).collect())
    }

    /// n >= 2 points evenly spaced over one period, both ends included, as
    /// HysteresisLoop.sample: a Curve with float64 arrays rho, u, y (the force).
    #[pyo3(signature = (n=None), text_signature = "($self, n=1001)")]
    fn sample(&self, py: Python<'_>, n: Option<&Bound<'_, PyAny>>) -> PyResult<PyCurve> {
        let n = samples_n(n)?;
        PyCurve::from_points(py, n, || self.inner.sample(&self.zl, n))
    }

    /// Number of turning points in one period.
    fn __len__(&self) -> usize {
        self.zl.len()
    }

    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        Ok(format!(
            "ZooLoop(model={}, turning_points={}, period={}, work_per_period={}, loops={})",
            self.model.bind(py).repr()?,
            list_repr(py, self.zl.turning_points(), 8),
            float_repr(py, self.zl.period()),
            float_repr(py, self.zl.work_per_period()),
            self.zl.loops().len()
        ))
    }

    /// Pickling: the model's `loop` with the turning points it kept.
    fn __reduce__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let method = self.model.bind(py).getattr("loop")?;
        let u = vec_out(py, self.zl.turning_points().to_vec());
        Ok((method, PyTuple::new(py, [u])?))
    }

    fn __traverse__(&self, visit: pyo3::PyVisit<'_>) -> Result<(), pyo3::PyTraverseError> {
        visit.call(&self.model)
    }
}

/// `lugre.ZOO_MODELS`: the core's zoo table, `{name: {"label", "equations", "reference",
/// "closes_minor_loops", "finite_rate", "parameters": {name: {"unit", "description", "domain", "shape"
/// ("scalar" or "elements"), "default" (a float, or a list for an element array), "slow_loop"
/// (whether the rate-independent loop depends on it)}}}}`.
pub(crate) fn zoo_table(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    let table = PyDict::new(py);
    for m in &MODELS {
        let parameters = PyDict::new(py);
        for p in m.parameters {
            let row = PyDict::new(py);
            row.set_item("unit", p.unit)?;
            row.set_item("description", p.description)?;
            row.set_item("domain", p.domain.text())?;
            match p.shape {
                Shape::Scalar => {
                    row.set_item("shape", "scalar")?;
                    row.set_item("default", p.default.first().copied().unwrap_or_default())?;
                }
                Shape::Elements => {
                    row.set_item("shape", "elements")?;
                    row.set_item("default", p.default.to_vec())?;
                }
            }
            row.set_item("slow_loop", p.slow_loop)?;
            parameters.set_item(p.name, row)?;
        }
        let entry = PyDict::new(py);
        entry.set_item("label", m.label)?;
        entry.set_item("equations", m.equations)?;
        entry.set_item("reference", m.reference)?;
        entry.set_item("closes_minor_loops", m.closes_minor_loops)?;
        entry.set_item("finite_rate", m.finite_rate)?;
        entry.set_item("parameters", parameters)?;
        table.set_item(m.name, entry)?;
    }
    Ok(table)
}
