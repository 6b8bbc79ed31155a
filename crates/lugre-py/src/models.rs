//! `lugre.LuGre` and `lugre.Dahl`: validated models and what is computed from them.

use pyo3::exceptions::{PyAttributeError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

use crate::convert::{float_repr, map_floats, real_or, value_error};
use crate::loops::PyHysteresisLoop;
use crate::simulate::{simulate, SimulateArgs};
use lugre::error::num;
use lugre::model::Parameter;

/// The LuGre friction model (paper eq. 1); the docstring Python shows is [`LUGRE_DOC`] with
/// the keywords from the core's table ([`document`]).
#[pyclass(frozen, eq, module = "lugre", name = "LuGre")]
#[derive(Clone, PartialEq)]
pub struct PyLuGre {
    pub inner: lugre::LuGre,
}

#[pymethods]
impl PyLuGre {
    /// The keywords are the table's ([`keyword_values`]); Python's signature is set at import
    /// ([`document`]).
    #[new]
    #[pyo3(signature = (**parameters))]
    fn new(parameters: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        let mut p = lugre::LuGreParams::default();
        for (q, value) in keyword_values("LuGre", &Parameter::LUGRE, parameters)? {
            p.set(q, value);
        }
        Ok(Self {
            inner: lugre::LuGre::from_params(p).map_err(value_error)?,
        })
    }

    /// A published parameter set by name, e.g. LuGre.preset("canudas1995") (Table I of Canudas
    /// de Wit et al. 1995, as the CLI's --preset), with any keyword parameter overriding the
    /// preset's value: LuGre.preset("canudas1995", fs=2.0).
    #[staticmethod]
    #[pyo3(signature = (name, **parameters))]
    fn preset(name: &str, parameters: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        let mut p = lugre::model::Preset::named(name)
            .map_err(value_error)?
            .params();
        check_keywords("LuGre.preset", &Parameter::LUGRE, parameters)?;
        if let Some(d) = parameters {
            for q in Parameter::LUGRE {
                if let Some(v) = d.get_item(q.name())? {
                    p.set(q, real_or(Some(&v), q.name(), q.default_value())?);
                }
            }
        }
        Ok(Self {
            inner: lugre::LuGre::from_params(p).map_err(value_error)?,
        })
    }

    /// A parameter of the table without a getter of its own.
    fn __getattr__(&self, name: &str) -> PyResult<f64> {
        parameter_attribute("LuGre", &Parameter::LUGRE, name, |p| {
            self.inner.params().get(p)
        })
    }

    /// Bristle stiffness sigma0 > 0.
    #[getter]
    fn sigma0(&self) -> f64 {
        self.inner.sigma0()
    }
    /// Micro-damping sigma1 >= 0.
    #[getter]
    fn sigma1(&self) -> f64 {
        self.inner.sigma1()
    }
    /// Viscous coefficient sigma2 >= 0: f(v) = sigma2 v.
    #[getter]
    fn sigma2(&self) -> f64 {
        self.inner.params().sigma2
    }
    /// Coulomb force fc > 0.
    #[getter]
    fn fc(&self) -> f64 {
        self.inner.params().fc
    }
    /// Stiction force fs > 0 (g(0) = fs).
    #[getter]
    fn fs(&self) -> f64 {
        self.inner.params().fs
    }
    /// Stribeck velocity vs > 0.
    #[getter]
    fn vs(&self) -> f64 {
        self.inner.params().vs
    }
    /// Stribeck exponent beta > 0.
    #[getter]
    fn beta(&self) -> f64 {
        self.inner.params().beta
    }
    /// g(0), the force the hysteresis loop saturates to.
    #[getter]
    fn g0(&self) -> f64 {
        self.inner.g0()
    }
    /// a = sigma0 / g(0), the inverse length over which the loop relaxes.
    #[getter]
    fn a(&self) -> f64 {
        self.inner.rate_independent().a()
    }

    /// The Stribeck curve g(v) = fc + (fs - fc) exp(-|v / vs|^beta), elementwise: a float for
    /// a number, a float64 array of the same shape for an array-like.
    #[pyo3(signature = (v))]
    fn g<'py>(&self, v: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        map_floats(v, "v", |x| self.inner.g(x))
    }

    /// The viscous friction f(v) = sigma2 v, elementwise (a float or a float64 array).
    #[pyo3(signature = (v))]
    fn f<'py>(&self, v: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        map_floats(v, "v", |x| self.inner.f(x))
    }

    /// The hysteresis loop y° (the periodic steady state for infinitely slow inputs, eqs.
    /// 8-10) for one period of a periodic input given by its turning points, e.g.
    /// [0, 1, 0.2, 1.5] (any sequence or array of real numbers; repeated values, a closing
    /// value equal to the first and values the input passes through without reversing are
    /// dropped, so one period of samples works too). Returns a HysteresisLoop.
    #[pyo3(signature = (turning_points))]
    fn r#loop(
        slf: &Bound<'_, Self>,
        turning_points: &Bound<'_, PyAny>,
    ) -> PyResult<PyHysteresisLoop> {
        let model = slf.get().inner.rate_independent();
        PyHysteresisLoop::from_turning_points(slf.as_any(), model, turning_points)
    }

    /// The hysteresis loop of the paper's bimodal input (Definition 1): turning points
    /// visited umin1 -> umax1 -> umin2 -> umax2, with umin1 <= umin2 < umax1 <= umax2 (not
    /// both equalities). The result's `theorem_a` holds Theorem A's rho_0..rho_5, y° there
    /// and the minor loop [rho_1, rho_5].
    #[pyo3(signature = (umin1, umin2, umax1, umax2))]
    fn loop_bimodal(
        slf: &Bound<'_, Self>,
        umin1: &Bound<'_, PyAny>,
        umin2: &Bound<'_, PyAny>,
        umax1: &Bound<'_, PyAny>,
        umax2: &Bound<'_, PyAny>,
    ) -> PyResult<PyHysteresisLoop> {
        let model = slf.get().inner.rate_independent();
        PyHysteresisLoop::from_bimodal(slf.as_any(), model, [umin1, umin2, umax1, umax2])
    }

    /// The response to a slow input (paper eq. 5) from the initial state x0, at slowness
    /// gamma (gamma = 1 is eq. 1 itself; gamma = math.inf is the rate-independent limit y*,
    /// eq. 6). Exactly one input:
    ///
    /// * turning_points: a periodic input through these values at unit speed (time = rho, as
    ///   in the paper's Examples 2-4), repeated over `periods` periods;
    /// * t, u: samples, linear in between (exact at any stiffness); with periods > 1 the
    ///   samples must end where they start;
    /// * sine=(A, T[, phase[, offset]]): u(t) = A sin(2 pi t / T + phase) + offset, from
    ///   t = 0 (an adaptive L-stable integrator with relative tolerance `tol`).
    ///
    /// Output at `times` (strictly increasing, inside the simulated interval; or "knots":
    /// at every knot of a piecewise-linear input), or at
    /// `samples_per_period` evenly spaced times per period, or else as `lugre simulate` does:
    /// samples t, u at their knots; turning points at 200 evenly spaced times per period and
    /// at every turning point (where y jumps by the sigma1 term); a sine at 200 evenly spaced
    /// times per period. t is eq. 5's time: the
    /// input's period does not depend on gamma. Where u' jumps, y is the value just after.
    ///
    /// Returns a dict of float64 arrays of equal length: t, u, z (the state), dz (z') and
    /// y (the friction force y_gamma). Invalid arguments raise ValueError (with the message
    /// of `lugre simulate`) or TypeError.
    #[pyo3(
        signature = (turning_points=None, t=None, u=None, sine=None, gamma=None, periods=None, x0=None, times=None, samples_per_period=None, tol=None, interpolate=None, speed=None),
        text_signature = "($self, turning_points=None, t=None, u=None, sine=None, gamma=1.0, periods=1, x0=0.0, times=None, samples_per_period=None, tol=1e-10, interpolate='linear', speed=None)"
    )]
    #[allow(clippy::too_many_arguments)]
    fn simulate<'py>(
        &self,
        py: Python<'py>,
        turning_points: Option<&Bound<'py, PyAny>>,
        t: Option<&Bound<'py, PyAny>>,
        u: Option<&Bound<'py, PyAny>>,
        sine: Option<&Bound<'py, PyAny>>,
        gamma: Option<&Bound<'py, PyAny>>,
        periods: Option<&Bound<'py, PyAny>>,
        x0: Option<&Bound<'py, PyAny>>,
        times: Option<&Bound<'py, PyAny>>,
        samples_per_period: Option<&Bound<'py, PyAny>>,
        tol: Option<&Bound<'py, PyAny>>,
        interpolate: Option<&Bound<'py, PyAny>>,
        speed: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let args = SimulateArgs {
            turning_points,
            t,
            u,
            sine,
            gamma,
            periods,
            x0,
            times,
            samples_per_period,
            tol,
            interpolate,
            speed,
        };
        simulate(py, &self.inner, args)
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        model_repr(py, "LuGre", &self.inner.params().named())
    }

    /// The model's parameters as a dict (keyword arguments of the constructor).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        values_dict(py, &self.inner.params().named())
    }

    /// Pickling and copying: the constructor's keyword arguments.
    fn __getnewargs_ex__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyTuple>, Bound<'py, PyDict>)> {
        Ok((PyTuple::empty(py), self.to_dict(py)?))
    }
}

/// The Dahl friction model; the docstring Python shows is [`DAHL_DOC`] ([`document`]).
#[pyclass(frozen, eq, module = "lugre", name = "Dahl")]
#[derive(Clone, PartialEq)]
pub struct PyDahl {
    pub inner: lugre::Dahl,
}

#[pymethods]
impl PyDahl {
    /// The keywords are the table's, as [`PyLuGre`]'s.
    #[new]
    #[pyo3(signature = (**parameters))]
    fn new(parameters: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        let values = keyword_values("Dahl", &Parameter::DAHL, parameters)?;
        let value = |p: Parameter| {
            values
                .iter()
                .find(|(q, _)| *q == p)
                .map_or(p.default_value(), |&(_, v)| v)
        };
        Ok(Self {
            inner: lugre::Dahl::new(value(Parameter::Rho), value(Parameter::Fc))
                .map_err(value_error)?,
        })
    }

    /// A parameter of the table without a getter of its own.
    fn __getattr__(&self, name: &str) -> PyResult<f64> {
        parameter_attribute("Dahl", &Parameter::DAHL, name, |p| self.inner.get(p))
    }

    /// The Dahl parameter rho > 0.
    #[getter]
    fn rho(&self) -> f64 {
        self.inner.rho()
    }
    /// Coulomb force fc > 0.
    #[getter]
    fn fc(&self) -> f64 {
        self.inner.fc()
    }
    /// sigma0 = rho fc, the stiffness of the equivalent LuGre model.
    #[getter]
    fn sigma0(&self) -> f64 {
        self.inner.rate_independent().sigma0()
    }
    /// g(0) = fc.
    #[getter]
    fn g0(&self) -> f64 {
        self.inner.rate_independent().g0()
    }
    /// a = sigma0 / g(0) = rho.
    #[getter]
    fn a(&self) -> f64 {
        self.inner.rate_independent().a()
    }

    /// The equivalent LuGre model (g = fc, sigma0 = rho fc, sigma1 = sigma2 = 0).
    fn to_lugre(&self) -> PyLuGre {
        PyLuGre {
            inner: self.inner.to_lugre(),
        }
    }

    /// The hysteresis loop for one period of a periodic input given by its turning points
    /// (see LuGre.loop).
    #[pyo3(signature = (turning_points))]
    fn r#loop(
        slf: &Bound<'_, Self>,
        turning_points: &Bound<'_, PyAny>,
    ) -> PyResult<PyHysteresisLoop> {
        let model = slf.get().inner.rate_independent();
        PyHysteresisLoop::from_turning_points(slf.as_any(), model, turning_points)
    }

    /// The hysteresis loop of the paper's bimodal input, with Theorem A (see
    /// LuGre.loop_bimodal).
    #[pyo3(signature = (umin1, umin2, umax1, umax2))]
    fn loop_bimodal(
        slf: &Bound<'_, Self>,
        umin1: &Bound<'_, PyAny>,
        umin2: &Bound<'_, PyAny>,
        umax1: &Bound<'_, PyAny>,
        umax2: &Bound<'_, PyAny>,
    ) -> PyResult<PyHysteresisLoop> {
        let model = slf.get().inner.rate_independent();
        PyHysteresisLoop::from_bimodal(slf.as_any(), model, [umin1, umin2, umax1, umax2])
    }

    /// The response to a slow input (paper eq. 5) of the equivalent LuGre model (see
    /// LuGre.simulate): a dict of float64 arrays t, u, z, dz, y.
    #[pyo3(
        signature = (turning_points=None, t=None, u=None, sine=None, gamma=None, periods=None, x0=None, times=None, samples_per_period=None, tol=None, interpolate=None, speed=None),
        text_signature = "($self, turning_points=None, t=None, u=None, sine=None, gamma=1.0, periods=1, x0=0.0, times=None, samples_per_period=None, tol=1e-10, interpolate='linear', speed=None)"
    )]
    #[allow(clippy::too_many_arguments)]
    fn simulate<'py>(
        &self,
        py: Python<'py>,
        turning_points: Option<&Bound<'py, PyAny>>,
        t: Option<&Bound<'py, PyAny>>,
        u: Option<&Bound<'py, PyAny>>,
        sine: Option<&Bound<'py, PyAny>>,
        gamma: Option<&Bound<'py, PyAny>>,
        periods: Option<&Bound<'py, PyAny>>,
        x0: Option<&Bound<'py, PyAny>>,
        times: Option<&Bound<'py, PyAny>>,
        samples_per_period: Option<&Bound<'py, PyAny>>,
        tol: Option<&Bound<'py, PyAny>>,
        interpolate: Option<&Bound<'py, PyAny>>,
        speed: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let args = SimulateArgs {
            turning_points,
            t,
            u,
            sine,
            gamma,
            periods,
            x0,
            times,
            samples_per_period,
            tol,
            interpolate,
            speed,
        };
        simulate(py, &self.inner.to_lugre(), args)
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        model_repr(py, "Dahl", &self.inner.named())
    }

    /// The model's parameters as a dict (keyword arguments of the constructor).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        values_dict(py, &self.inner.named())
    }

    /// Pickling and copying: the constructor's keyword arguments.
    fn __getnewargs_ex__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyTuple>, Bound<'py, PyDict>)> {
        Ok((PyTuple::empty(py), self.to_dict(py)?))
    }
}

/// `lugre.LuGre`'s docstring; `{keywords}` is replaced at import by one line per parameter
/// from the core's table ([`keyword_lines`]).
const LUGRE_DOC: &str =
    "The LuGre friction model (paper eq. 1) with the Stribeck curve and viscous friction.

    x' = -sigma0 |u'| / g(u') x + u'
    F  =  sigma0 x + sigma1 x' + f(u')
    g(v) = fc + (fs - fc) exp(-|v / vs|^beta)       f(v) = sigma2 v

Keyword arguments (the defaults are the paper's Examples 2-3):

{keywords}

An invalid value raises ValueError with the message the `lugre` command prints, e.g.
\"sigma0 must be > 0, got 0\".

The hysteresis loop depends only on sigma0 and g(0) = fs (a = sigma0 / g(0)).

>>> import lugre
>>> hl = lugre.LuGre(sigma0=6).loop_bimodal(0, 0.5, 1, 1.5)   # the paper's Example 4
>>> hl.theorem_a.minor_loop
(1.0, 2.0)
";

/// `lugre.Dahl`'s docstring, `{keywords}` as in [`LUGRE_DOC`].
const DAHL_DOC: &str = "The Dahl friction model: w' = rho (u' - |u'| w), y = fc w.

It is the LuGre model with g = fc, sigma0 = rho fc, sigma1 = 0 and f = 0. Keyword arguments:

{keywords}

An invalid value raises ValueError with the message the `lugre` command prints.
";

/// One line per parameter of `parameters`: `    sigma0 = 1   bristle stiffness, > 0 [N/m]`.
fn keyword_lines(parameters: &[Parameter]) -> String {
    let width = parameters.iter().map(|p| p.name().len()).max().unwrap_or(0);
    parameters
        .iter()
        .map(|p| {
            let unit = match p.unit() {
                "1" => String::new(),
                unit => format!(" [{unit}]"),
            };
            format!(
                "    {:<width$} = {:<4} {}, {}{unit}",
                p.name(),
                num(p.default_value()),
                p.description(),
                p.domain().condition(),
            )
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The value of every parameter of `table` from the keywords given to `class` (its default
/// where not given), each a real number; a keyword not in the table is a `TypeError`, as Python
/// says it.
fn keyword_values<'py>(
    class: &str,
    table: &[Parameter],
    given: Option<&Bound<'py, PyDict>>,
) -> PyResult<Vec<(Parameter, f64)>> {
    // One pass over the keywords given (usually one or two), not a lookup per parameter of
    // the table: each lookup made a Python string of the name and hashed it (a model took 6x
    // as long to make). The values are still checked in the table's order.
    let mut values: Vec<Option<Bound<'py, PyAny>>> = table.iter().map(|_| None).collect();
    if let Some(d) = given {
        for (key, value) in d.iter() {
            let key = key.str()?;
            let name = key.to_cow()?;
            match table.iter().position(|p| p.name() == name) {
                Some(i) => values[i] = Some(value),
                None => return Err(unknown_keyword(class, table, &name)),
            }
        }
    }
    table
        .iter()
        .zip(values)
        .map(|(&p, value)| Ok((p, real_or(value.as_ref(), p.name(), p.default_value())?)))
        .collect()
}

/// Every keyword in `given` is a parameter of `table`, else Python's `TypeError` naming it.
fn check_keywords(
    class: &str,
    table: &[Parameter],
    given: Option<&Bound<'_, PyDict>>,
) -> PyResult<()> {
    let Some(d) = given else { return Ok(()) };
    for key in d.keys() {
        let name = key.str()?.to_string();
        if !table.iter().any(|p| p.name() == name) {
            return Err(unknown_keyword(class, table, &name));
        }
    }
    Ok(())
}

/// Python's `TypeError` for a keyword `name` that is not a parameter of `table`.
fn unknown_keyword(class: &str, table: &[Parameter], name: &str) -> PyErr {
    let names: Vec<&str> = table.iter().map(|p| p.name()).collect();
    PyTypeError::new_err(format!(
        "{class}() got an unexpected keyword argument '{name}' (its parameters: {})",
        names.join(", ")
    ))
}

/// The attribute `name` of a `class` object: the value of its parameter of that name (`get`),
/// else Python's `AttributeError`.
fn parameter_attribute(
    class: &str,
    table: &[Parameter],
    name: &str,
    get: impl Fn(Parameter) -> Option<f64>,
) -> PyResult<f64> {
    table
        .iter()
        .find(|p| p.name() == name)
        .and_then(|&p| get(p))
        .ok_or_else(|| {
            PyAttributeError::new_err(format!("'{class}' object has no attribute '{name}'"))
        })
}

/// The models' docstrings with their keywords from the core's table, and their signatures
/// (`inspect.signature(lugre.LuGre)`: keyword-only, with the table's defaults), set on the
/// classes of module `m` at import.
pub(crate) fn document(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let inspect = m.py().import("inspect")?;
    let parameter = inspect.getattr("Parameter")?;
    let keyword_only = parameter.getattr("KEYWORD_ONLY")?;
    for (class, doc, table) in [
        ("LuGre", LUGRE_DOC, &Parameter::LUGRE[..]),
        ("Dahl", DAHL_DOC, &Parameter::DAHL[..]),
    ] {
        let cls = m.getattr(class)?;
        cls.setattr("__doc__", doc.replace("{keywords}", &keyword_lines(table)))?;
        let parameters = table
            .iter()
            .map(|p| {
                let default = PyDict::new(m.py());
                default.set_item("default", p.default_value())?;
                parameter.call((p.name(), &keyword_only), Some(&default))
            })
            .collect::<PyResult<Vec<_>>>()?;
        let signature = inspect.getattr("Signature")?.call1((parameters,))?;
        cls.setattr("__signature__", signature)?;
    }
    Ok(())
}

/// `lugre.PARAMETERS`: the core's table by model, `{"LuGre": {"sigma0": {"symbol": ...,
/// "description": ..., "unit": ..., "default": ..., "domain": "> 0"}, ...}, "Dahl": {...}}`,
/// each model's parameters in the order of its keywords.
pub(crate) fn parameter_table(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    let table = PyDict::new(py);
    for (model, parameters) in [("LuGre", &Parameter::LUGRE[..]), ("Dahl", &Parameter::DAHL)] {
        let by_name = PyDict::new(py);
        for p in parameters {
            let row = PyDict::new(py);
            row.set_item("symbol", p.symbol())?;
            row.set_item("description", p.description())?;
            row.set_item("unit", p.unit())?;
            row.set_item("default", p.default_value())?;
            row.set_item("domain", p.domain().condition())?;
            by_name.set_item(p.name(), row)?;
        }
        table.set_item(model, by_name)?;
    }
    Ok(table)
}

/// `Name(p1=v1, p2=v2, ...)` with Python's float reprs, in the table's order.
fn model_repr(py: Python<'_>, name: &str, values: &[(Parameter, f64)]) -> String {
    let items: Vec<String> = values
        .iter()
        .map(|&(p, v)| format!("{}={}", p.name(), float_repr(py, v)))
        .collect();
    format!("{name}({})", items.join(", "))
}

/// The parameters as a dict, the constructor's keyword arguments.
fn values_dict<'py>(py: Python<'py>, values: &[(Parameter, f64)]) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    for &(p, v) in values {
        d.set_item(p.name(), v)?;
    }
    Ok(d)
}

/// The LuGre model of a `lugre.LuGre` or `lugre.Dahl` object (Dahl: its equivalent LuGre).
pub fn lugre_of(model: &Bound<'_, PyAny>) -> PyResult<lugre::LuGre> {
    if let Ok(l) = model.cast::<PyLuGre>() {
        Ok(l.get().inner.clone())
    } else if let Ok(d) = model.cast::<PyDahl>() {
        Ok(d.get().inner.to_lugre())
    } else {
        Err(pyo3::exceptions::PyTypeError::new_err(format!(
            "model must be a lugre.LuGre or lugre.Dahl, got {}",
            crate::convert::type_name(model)
        )))
    }
}
