//! The FMI 3.0 functions of lugre's FMUs, for any FMI host (Simulink's FMU block, Dymola,
//! OpenModelica, fmpy), in model exchange and co-simulation. One library serves both FMUs; the
//! instantiation token says which model an instance is:
//!
//! * `lugre-friction.fmu` ([`friction`]): the friction element, relative displacement in,
//!   friction force out;
//! * `lugre-mass.fmu` ([`mass`]): the mass with friction of `lugre dynamics`, drive force in,
//!   position, velocity and friction out;
//! * `lugre-NAME.fmu` ([`zoo`]), one for each model of the core's zoo table (Maxwell-slip,
//!   Prandtl-Ishlinskii, Bouc-Wen, ...): the model as a rate-independent hysteresis element in
//!   co-simulation, displacement in, force, work and dissipation out, with no code of its own
//!   here (the token names the table's entry; the description is written from the table);
//! * `lugre-mass-NAME.fmu` ([`zoo_mass`]), one for each model of the table with a finite-rate
//!   form (elasto-plastic, Maxwell-slip as GMS): the mass of `lugre dynamics --model NAME`,
//!   drive force in, position, velocity and friction out, in co-simulation.
//!
//! `bash scripts/build-fmu.sh` bundles this library with `fmu/lugre-friction.xml`,
//! `fmu/lugre-mass.xml`, each `fmu/zoo/NAME.xml` and each `fmu/mass/NAME.xml`.
//!
//! **Why one FMU per zoo model** rather than one FMU with a String parameter naming the model:
//! an FMU's variables are fixed by its description, so one FMU for all would list every model's
//! parameters (most of them unused by the model chosen) with dimensions that could not follow
//! the choice; one description per model lists exactly that model's parameters with their
//! units, defaults and array dimensions, as a host's parameter dialog shows them. Adding a model
//! to the table adds its FMU (`scripts/write-tables.sh`), with no code here.
//!
//! **Why hand-written.** The FMI 3.0 C interface is a flat list of functions over plain types;
//! writing them here against the standard's signatures (`fmi3FunctionTypes.h`) costs no
//! bindgen/libclang build step, and the few that matter are small. Everything these models do
//! not use (clocks, other types, FMU states, scheduled execution) returns `fmi3Error` with a
//! logged message.
//!
//! **The friction element** (SI units; parameters as the CLI's flags; defaults Table I of
//! Canudas de Wit et al. 1995):
//!
//! ```text
//! inputs x [m], v = dx/dt [m/s]     state z [m], z(0) = z0
//! z' = v - sigma0 |v| z / g(v)      g(v) = Fc + (Fs - Fc) exp(-|v/vs|^beta)
//! output F = sigma0 z + sigma1 z' + sigma2 v   [N]
//! ```
//!
//! * Model exchange: the host integrates `z` (one continuous state, no event indicator: the
//!   non-smoothness of `|v|` is in the input the host provides); `z'` and `F` are the core's
//!   ([`lugre::simulate::FrictionElement::rates_at`], the arithmetic of a co-simulation step's
//!   output).
//! * Co-simulation: `fmi3DoStep(t, h)` moves the displacement linearly from where it is to
//!   `x + v h` (`x`, `v` the inputs set for `t`) and advances the element exactly
//!   ([`lugre::simulate::FrictionElement`]): exact for a displacement linear over each step at
//!   any stiffness and step size. A host that gives no `v` holds `x` over each step.
//!
//! The parameters' names, units, start values and descriptions in `fmu/*.xml` are the core's
//! ([`Parameter`], Table I's values; checked by this crate's tests).
//!
//! **The state machine.** Every call is checked against FMI 3.0's modes (`Phase`): a call out
//! of order (a second `fmi3EnterInitializationMode` after steps, `fmi3DoStep` before the end of
//! initialization or after `fmi3Terminate`, ...) is `fmi3Error` with a message naming the call,
//! the mode the instance is in and the modes it is allowed in; `fmi3Reset` starts again.
//!
//! No panic crosses the boundary; a bad parameter or a non-finite input is `fmi3Error` with the
//! message sent to the host's logger.

#![allow(clippy::not_unsafe_ptr_arg_deref)]

use std::ffi::{c_char, c_void, CStr, CString};
use std::panic::{catch_unwind, AssertUnwindSafe};

use lugre::error::num;
use lugre::model::Parameter;
use lugre::simulate::FrictionElement;
use lugre::{LuGre, LuGreParams};

pub mod friction;
pub mod mass;
#[cfg(test)]
mod tests;
pub mod zoo;
pub mod zoo_mass;
#[cfg(test)]
mod zoo_mass_tests;
#[cfg(test)]
mod zoo_tests;

pub use friction::TOKEN as FRICTION_TOKEN;
pub use mass::TOKEN as MASS_TOKEN;

/// `fmi3Status`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Status {
    Ok = 0,
    Warning = 1,
    Discard = 2,
    Error = 3,
    Fatal = 4,
}

type Instance = *mut c_void;
type LogMessage = Option<unsafe extern "C" fn(*mut c_void, Status, *const c_char, *const c_char)>;

/// The value references both models share: time, the friction parameters from
/// [`vr::PARAMETERS`] on, in the order of [`Parameter::LUGRE`] (sigma0 = 10, ..., beta = 16),
/// and the start of each model's own parameters ([`vr::OWN`], `z0` = 100), which leaves room
/// for 90 parameters in the core's table: one added there takes the next reference and the XML
/// is written from the table (`src/tests.rs`), with no other change.
pub mod vr {
    pub const TIME: u32 = 0;
    pub const PARAMETERS: u32 = 10;
    pub const OWN: u32 = 100;
}

// The parameters' value references end before each model's own begin (z0).
const _: () = assert!(
    vr::PARAMETERS + Parameter::LUGRE.len() as u32 <= vr::OWN,
    "the friction parameters' value references run into the models' own (vr::OWN)"
);

/// The friction parameter at value reference `r`.
fn parameter(r: u32) -> Option<Parameter> {
    let i = r.checked_sub(vr::PARAMETERS)?;
    Parameter::LUGRE.get(usize::try_from(i).ok()?).copied()
}

/// The interface an instance runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Kind {
    ModelExchange,
    CoSimulation,
}

/// Which FMU an instance is (from its instantiation token).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Model {
    Friction,
    Mass,
    /// A model of the core's zoo table.
    Zoo(&'static lugre::zoo::ZooModelSpec),
    /// A mass with a finite-rate model of the zoo table as its friction.
    ZooMass(&'static lugre::zoo::ZooModelSpec),
}

impl Model {
    fn of_token(token: &[u8]) -> Option<Self> {
        if token == FRICTION_TOKEN.as_bytes() {
            Some(Self::Friction)
        } else if token == MASS_TOKEN.as_bytes() {
            Some(Self::Mass)
        } else if let Some(spec) = zoo_mass::model_of(token) {
            Some(Self::ZooMass(spec))
        } else {
            zoo::model_of(token).map(Self::Zoo)
        }
    }
}

/// Where an instance is in FMI 3.0's state machine: each call is allowed in some of these.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Phase {
    /// After instantiation or `fmi3Reset`.
    Instantiated,
    /// Structural parameters can be set.
    Configuration,
    Initialization,
    Event,
    /// Model exchange, between events.
    ContinuousTime,
    /// Co-simulation, between communication points.
    Step,
    Terminated,
}

impl Phase {
    fn name(self) -> &'static str {
        match self {
            Phase::Instantiated => "the instantiated state (after instantiation or fmi3Reset)",
            Phase::Configuration => "configuration mode",
            Phase::Initialization => "initialization mode",
            Phase::Event => "event mode",
            Phase::ContinuousTime => "continuous-time mode",
            Phase::Step => "step mode",
            Phase::Terminated => "the terminated state",
        }
    }
}

/// What a model provides to the FMI functions. Values are checked finite before `set`.
pub(crate) trait Unit {
    fn name_of(&self, vr: u32) -> &'static str;
    /// How many Float64 values the variable at `vr` holds (an array's length; 1 for a scalar
    /// and for a reference no variable has, which `get`/`set` then refuse).
    fn size(&self, _vr: u32) -> usize {
        1
    }
    /// The value at `vr` (an error for an unknown reference or a value that cannot be had).
    fn get(&self, vr: u32) -> Result<f64, String>;
    /// The `size(vr)` values at `vr` into `out` (as long).
    fn get_values(&self, vr: u32, out: &mut [f64]) -> Result<(), String> {
        out[0] = self.get(vr)?;
        Ok(())
    }
    fn set(&mut self, vr: u32, value: f64) -> Result<(), String>;
    /// Sets the `size(vr)` values at `vr` (`values` as long, each finite).
    fn set_values(&mut self, vr: u32, values: &[f64]) -> Result<(), String> {
        self.set(vr, values[0])
    }
    /// Whether the model has structural parameters (set in configuration mode).
    fn structural(&self) -> bool {
        false
    }
    /// The UInt64 variable at `vr` (the structural parameters).
    fn get_count(&self, vr: u32) -> Result<u64, String> {
        Err(format!("no UInt64 variable has value reference {vr}"))
    }
    fn set_count(&mut self, vr: u32, _value: u64) -> Result<(), String> {
        Err(format!("no UInt64 variable has value reference {vr}"))
    }
    /// The end of initialization: the parameters checked, the state set.
    fn initialize(&mut self, start: f64, tolerance: Option<f64>) -> Result<(), String>;
    fn set_time(&mut self, t: f64);
    /// The instance's time (what `get(vr::TIME)` returns, without its error path).
    fn time(&self) -> f64;
    fn do_step(&mut self, t: f64, h: f64) -> Result<(), String>;
    /// Model exchange's continuous states (none by default: a co-simulation-only model).
    fn states(&self) -> Vec<f64> {
        Vec::new()
    }
    /// `states` has the model's number of states (checked by the caller).
    fn set_states(&mut self, _states: &[f64]) {}
    fn derivatives(&self) -> Result<Vec<f64>, String> {
        Ok(Vec::new())
    }
    fn nominals(&self) -> Vec<f64> {
        Vec::new()
    }
    fn indicators(&self) -> Vec<f64> {
        Vec::new()
    }
}

/// A friction parameter's value, or the error for a reference no variable has.
pub(crate) fn param(p: &LuGreParams, r: u32) -> Result<f64, String> {
    parameter(r)
        .and_then(|q| p.get(q))
        .ok_or_else(|| format!("no Float64 variable has value reference {r}"))
}

/// The friction element of the parameters (checked as the models check them), at rest at
/// time `t`, displacement `x`, deflection `z`: the core's friction law for both models.
pub(crate) fn element(p: LuGreParams, t: f64, x: f64, z: f64) -> Result<FrictionElement, String> {
    let model = LuGre::from_params(p).map_err(|e| e.to_string())?;
    FrictionElement::starting_at(model, t, x, z).map_err(|e| e.to_string())
}

/// `(z', F)` at deflection `z` and velocity `v` from `element` (built at the end of
/// initialization), or, before that, from the parameters as they stand.
pub(crate) fn rates(
    element: Option<&FrictionElement>,
    p: LuGreParams,
    v: f64,
    z: f64,
) -> Result<(f64, f64), String> {
    let built;
    let e = match element {
        Some(e) => e,
        None => {
            built = self::element(p, 0.0, 0.0, 0.0)?;
            &built
        }
    };
    let s = e.rates_at(v, z).map_err(|e| e.to_string())?;
    Ok((s.dz, s.y))
}

/// Sets a friction parameter (before the end of initialization only).
pub(crate) fn set_param(
    p: &mut LuGreParams,
    r: u32,
    value: f64,
    initialized: bool,
    name: &str,
) -> Result<(), String> {
    let Some(q) = parameter(r) else {
        return Err(match name {
            "an unknown variable" => format!("no settable variable has value reference {r}"),
            _ => format!("{name} cannot be set (it is computed by the FMU)"),
        });
    };
    if initialized {
        return Err(format!(
            "{name} is a fixed parameter: set it before the end of initialization"
        ));
    }
    p.set(q, value);
    Ok(())
}

pub(crate) fn param_name(r: u32) -> &'static str {
    match (r, parameter(r)) {
        (vr::TIME, _) => "time",
        (_, Some(q)) => q.name(),
        _ => "an unknown variable",
    }
}

/// One instance: the host's callbacks and the model.
struct Fmu {
    environment: *mut c_void,
    log: LogMessage,
    kind: Kind,
    model: Model,
    /// Co-simulation: `fmi3ExitInitializationMode` enters event mode rather than step mode.
    event_mode_used: bool,
    start: f64,
    tolerance: Option<f64>,
    phase: Phase,
    unit: Box<dyn Unit>,
    /// The model has arrays (`unit.structural()`, which does not change).
    arrays: bool,
}

impl Fmu {
    fn error(&self, message: &str) -> Status {
        log_error(self.environment, self.log, message);
        Status::Error
    }

    fn fresh(kind: Kind, model: Model) -> Box<dyn Unit> {
        match model {
            Model::Mass => Box::new(mass::Mass::new(kind)),
            Model::Friction => Box::new(friction::Friction::new(kind)),
            Model::Zoo(spec) => Box::new(zoo::Zoo::new(spec)),
            Model::ZooMass(spec) => Box::new(zoo_mass::ZooMass::new(spec)),
        }
    }

    /// How many values the variable at `r` holds: 1 but for the arrays, which only a model
    /// with structural parameters has (their dimensions); a scalar model's calls skip asking.
    #[inline]
    fn size(&self, r: u32) -> usize {
        if self.arrays {
            self.unit.size(r)
        } else {
            1
        }
    }

    /// Refuses `call` unless the instance is in one of the phases `allowed`.
    #[inline]
    fn expect(&self, call: &str, allowed: &[Phase]) -> Result<(), String> {
        if allowed.contains(&self.phase) {
            Ok(())
        } else {
            Err(self.out_of_order(call, allowed))
        }
    }

    /// The message of a call out of order (off the hot path of every call).
    #[cold]
    #[inline(never)]
    fn out_of_order(&self, call: &str, allowed: &[Phase]) -> String {
        let names: Vec<&str> = allowed.iter().map(|p| p.name()).collect();
        format!(
            "{call} is not allowed in {}: only in {}{}",
            self.phase.name(),
            names.join(" or "),
            match self.phase {
                Phase::Instantiated => "",
                _ => " (fmi3Reset starts the instance again)",
            }
        )
    }

    /// [`Self::expect`] for a function of model exchange only.
    fn expect_model_exchange(&self, call: &str, allowed: &[Phase]) -> Result<(), String> {
        if self.kind != Kind::ModelExchange {
            return Err(format!(
                "{call} is a model-exchange function: this instance is a co-simulation"
            ));
        }
        self.expect(call, allowed)
    }

    fn check_states(&self, n: usize) -> Result<usize, String> {
        let want = self.unit.states().len();
        if n != want {
            return Err(format!("{want} continuous states, got {n}"));
        }
        Ok(want)
    }
}

fn log_error(environment: *mut c_void, log: LogMessage, message: &str) {
    if let Some(log) = log {
        let category = c"logStatusError";
        let text = CString::new(message.replace('\0', " ")).unwrap_or_default();
        // SAFETY: the host's callback with its own environment pointer.
        unsafe { log(environment, Status::Error, category.as_ptr(), text.as_ptr()) };
    }
}

/// Runs `body` on the instance; a panic becomes `fmi3Fatal`, an error `fmi3Error` (logged).
fn with(instance: Instance, body: impl FnOnce(&mut Fmu) -> Result<(), String>) -> Status {
    if instance.is_null() {
        return Status::Error;
    }
    // SAFETY: a non-NULL instance is one this library made and has not freed.
    let fmu = unsafe { &mut *instance.cast::<Fmu>() };
    match catch_unwind(AssertUnwindSafe(|| body(fmu))) {
        Ok(Ok(())) => Status::Ok,
        Ok(Err(message)) => fmu.error(&message),
        Err(_) => {
            fmu.error("internal error in lugre (a panic was caught); please report it");
            Status::Fatal
        }
    }
}

fn slice<'a, T>(p: *const T, n: usize) -> &'a [T] {
    if n == 0 || p.is_null() {
        &[]
    } else {
        // SAFETY: the host passes `n` values at `p` (FMI's calling convention).
        unsafe { std::slice::from_raw_parts(p, n) }
    }
}

fn slice_mut<'a, T>(p: *mut T, n: usize) -> &'a mut [T] {
    if n == 0 || p.is_null() {
        &mut []
    } else {
        // SAFETY: as `slice`, writable.
        unsafe { std::slice::from_raw_parts_mut(p, n) }
    }
}

fn write<T>(p: *mut T, value: T) {
    if !p.is_null() {
        // SAFETY: an out-parameter of the host.
        unsafe { *p = value };
    }
}

/// Copies `values` (all finite) to the host's buffer of `n`.
fn deliver(fmu: &Fmu, what: &str, values: Vec<f64>, out: *mut f64, n: usize) -> Result<(), String> {
    if values.len() != n {
        return Err(format!("{} {what}, asked for {n}", values.len()));
    }
    if values.iter().any(|v| !v.is_finite()) {
        return Err(format!(
            "the {what} are not finite at t = {}",
            fmu.unit.time()
        ));
    }
    slice_mut(out, n).copy_from_slice(&values);
    Ok(())
}

fn instantiate(
    kind: Kind,
    event_mode_used: bool,
    token: *const c_char,
    environment: *mut c_void,
    log: LogMessage,
) -> Instance {
    catch_unwind(|| {
        // SAFETY: a NUL-terminated string from the host.
        let given = (!token.is_null()).then(|| unsafe { CStr::from_ptr(token) }.to_bytes());
        let Some(model) = given.and_then(Model::of_token) else {
            log_error(
                environment,
                log,
                "the instantiation token is not one of lugre's FMUs (a different modelDescription.xml?)",
            );
            return std::ptr::null_mut();
        };
        let refused = match (model, kind) {
            (Model::Zoo(spec), Kind::ModelExchange) => Some(format!(
                "lugre-{}.fmu is co-simulation only (a rate-independent element has no continuous state)",
                spec.name
            )),
            (Model::ZooMass(spec), Kind::ModelExchange) => Some(format!(
                "lugre-mass-{}.fmu is co-simulation only (its friction's events switch the equations: see lugre-fmu's zoo_mass module)",
                spec.name
            )),
            _ => None,
        };
        if let Some(message) = refused {
            log_error(environment, log, &message);
            return std::ptr::null_mut();
        }
        let unit = Fmu::fresh(kind, model);
        let fmu = Fmu {
            environment,
            log,
            kind,
            model,
            event_mode_used,
            start: 0.0,
            tolerance: None,
            phase: Phase::Instantiated,
            arrays: unit.structural(),
            unit,
        };
        Box::into_raw(Box::new(fmu)).cast::<c_void>()
    })
    .unwrap_or(std::ptr::null_mut())
}

#[no_mangle]
pub extern "C" fn fmi3GetVersion() -> *const c_char {
    c"3.0".as_ptr()
}

#[no_mangle]
pub extern "C" fn fmi3SetDebugLogging(
    instance: Instance,
    _logging_on: bool,
    _n_categories: usize,
    _categories: *const *const c_char,
) -> Status {
    with(instance, |_| Ok(()))
}

#[no_mangle]
pub extern "C" fn fmi3InstantiateModelExchange(
    _name: *const c_char,
    token: *const c_char,
    _resource_path: *const c_char,
    _visible: bool,
    _logging_on: bool,
    environment: *mut c_void,
    log: LogMessage,
) -> Instance {
    instantiate(Kind::ModelExchange, false, token, environment, log)
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn fmi3InstantiateCoSimulation(
    _name: *const c_char,
    token: *const c_char,
    _resource_path: *const c_char,
    _visible: bool,
    _logging_on: bool,
    event_mode_used: bool,
    _early_return_allowed: bool,
    _required_intermediate: *const u32,
    _n_required_intermediate: usize,
    environment: *mut c_void,
    log: LogMessage,
    _intermediate_update: *const c_void,
) -> Instance {
    instantiate(Kind::CoSimulation, event_mode_used, token, environment, log)
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn fmi3InstantiateScheduledExecution(
    _name: *const c_char,
    _token: *const c_char,
    _resource_path: *const c_char,
    _visible: bool,
    _logging_on: bool,
    environment: *mut c_void,
    log: LogMessage,
    _clock_update: *const c_void,
    _lock: *const c_void,
    _unlock: *const c_void,
) -> Instance {
    let _ = catch_unwind(|| {
        log_error(
            environment,
            log,
            "lugre's FMUs do not support scheduled execution",
        );
    });
    std::ptr::null_mut()
}

#[no_mangle]
pub extern "C" fn fmi3FreeInstance(instance: Instance) {
    if !instance.is_null() {
        // SAFETY: made by `instantiate`, freed once by the host.
        let _ = catch_unwind(|| drop(unsafe { Box::from_raw(instance.cast::<Fmu>()) }));
    }
}

#[no_mangle]
pub extern "C" fn fmi3EnterInitializationMode(
    instance: Instance,
    tolerance_defined: bool,
    tolerance: f64,
    start_time: f64,
    _stop_time_defined: bool,
    _stop_time: f64,
) -> Status {
    with(instance, |fmu| {
        // Once more after steps would silently rewind time: fmi3Reset says so.
        fmu.expect("fmi3EnterInitializationMode", &[Phase::Instantiated])?;
        if !start_time.is_finite() {
            return Err(format!(
                "the start time must be finite, got {}",
                num(start_time)
            ));
        }
        fmu.start = start_time;
        fmu.unit.set_time(start_time);
        fmu.tolerance = tolerance_defined.then_some(tolerance);
        fmu.phase = Phase::Initialization;
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn fmi3ExitInitializationMode(instance: Instance) -> Status {
    with(instance, |fmu| {
        fmu.expect("fmi3ExitInitializationMode", &[Phase::Initialization])?;
        fmu.unit.initialize(fmu.start, fmu.tolerance)?;
        fmu.phase = match fmu.kind {
            Kind::CoSimulation if !fmu.event_mode_used => Phase::Step,
            _ => Phase::Event,
        };
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn fmi3EnterEventMode(instance: Instance) -> Status {
    with(instance, |fmu| {
        fmu.expect("fmi3EnterEventMode", &[Phase::ContinuousTime, Phase::Step])?;
        fmu.phase = Phase::Event;
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn fmi3Terminate(instance: Instance) -> Status {
    with(instance, |fmu| {
        let live = [Phase::Event, Phase::ContinuousTime, Phase::Step];
        fmu.expect("fmi3Terminate", &live)?;
        fmu.phase = Phase::Terminated;
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn fmi3Reset(instance: Instance) -> Status {
    with(instance, |fmu| {
        fmu.unit = Fmu::fresh(fmu.kind, fmu.model);
        fmu.phase = Phase::Instantiated;
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn fmi3GetFloat64(
    instance: Instance,
    vrs: *const u32,
    n_vrs: usize,
    values: *mut f64,
    n_values: usize,
) -> Status {
    with(instance, |fmu| {
        fmu.expect("fmi3GetFloat64", AFTER_INSTANTIATION)?;
        let (vrs, values) = (slice(vrs, n_vrs), slice_mut(values, n_values));
        check_count(fmu, vrs, values.len())?;
        let mut at = 0;
        for r in vrs {
            let out = &mut values[at..at + fmu.size(*r)];
            fmu.unit.get_values(*r, out)?;
            if out.iter().any(|v| !v.is_finite()) {
                return Err(format!("{} is not finite", fmu.unit.name_of(*r)));
            }
            at += out.len();
        }
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn fmi3SetFloat64(
    instance: Instance,
    vrs: *const u32,
    n_vrs: usize,
    values: *const f64,
    n_values: usize,
) -> Status {
    with(instance, |fmu| {
        fmu.expect(
            "fmi3SetFloat64",
            &[
                Phase::Instantiated,
                Phase::Initialization,
                Phase::Event,
                Phase::ContinuousTime,
                Phase::Step,
            ],
        )?;
        let (vrs, values) = (slice(vrs, n_vrs), slice(values, n_values));
        check_count(fmu, vrs, values.len())?;
        let mut at = 0;
        for r in vrs {
            let these = &values[at..at + fmu.size(*r)];
            if let Some(bad) = these.iter().find(|v| !v.is_finite()) {
                return Err(format!(
                    "the value of {} must be a finite number, got {}",
                    fmu.unit.name_of(*r),
                    num(*bad)
                ));
            }
            fmu.unit.set_values(*r, these)?;
            at += these.len();
        }
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn fmi3UpdateDiscreteStates(
    instance: Instance,
    discrete_states_need_update: *mut bool,
    terminate: *mut bool,
    nominals_changed: *mut bool,
    values_changed: *mut bool,
    next_event_time_defined: *mut bool,
    _next_event_time: *mut f64,
) -> Status {
    with(instance, |fmu| {
        fmu.expect("fmi3UpdateDiscreteStates", &[Phase::Event])?;
        write(discrete_states_need_update, false);
        write(terminate, false);
        write(nominals_changed, false);
        write(values_changed, false);
        write(next_event_time_defined, false);
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn fmi3EnterContinuousTimeMode(instance: Instance) -> Status {
    with(instance, |fmu| {
        fmu.expect_model_exchange("fmi3EnterContinuousTimeMode", &[Phase::Event])?;
        fmu.phase = Phase::ContinuousTime;
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn fmi3EnterStepMode(instance: Instance) -> Status {
    with(instance, |fmu| {
        if fmu.kind != Kind::CoSimulation {
            return Err(
                "fmi3EnterStepMode is a co-simulation function: this instance is model exchange"
                    .into(),
            );
        }
        fmu.expect("fmi3EnterStepMode", &[Phase::Event])?;
        fmu.phase = Phase::Step;
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn fmi3CompletedIntegratorStep(
    instance: Instance,
    _no_set_state_prior: bool,
    enter_event_mode: *mut bool,
    terminate: *mut bool,
) -> Status {
    with(instance, |fmu| {
        fmu.expect_model_exchange("fmi3CompletedIntegratorStep", &[Phase::ContinuousTime])?;
        write(enter_event_mode, false);
        write(terminate, false);
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn fmi3SetTime(instance: Instance, time: f64) -> Status {
    with(instance, |fmu| {
        fmu.expect_model_exchange("fmi3SetTime", &[Phase::ContinuousTime])?;
        if !time.is_finite() {
            return Err(format!("the time must be finite, got {}", num(time)));
        }
        fmu.unit.set_time(time);
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn fmi3SetContinuousStates(
    instance: Instance,
    states: *const f64,
    n: usize,
) -> Status {
    with(instance, |fmu| {
        fmu.expect_model_exchange("fmi3SetContinuousStates", &[Phase::ContinuousTime])?;
        fmu.check_states(n)?;
        let states = slice(states, n);
        if let Some(bad) = states.iter().find(|v| !v.is_finite()) {
            return Err(format!(
                "the continuous states must be finite, got {}",
                num(*bad)
            ));
        }
        fmu.unit.set_states(states);
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn fmi3GetContinuousStates(
    instance: Instance,
    states: *mut f64,
    n: usize,
) -> Status {
    with(instance, |fmu| {
        fmu.expect_model_exchange("fmi3GetContinuousStates", AFTER_INSTANTIATION)?;
        deliver(fmu, "continuous states", fmu.unit.states(), states, n)
    })
}

#[no_mangle]
pub extern "C" fn fmi3GetContinuousStateDerivatives(
    instance: Instance,
    derivatives: *mut f64,
    n: usize,
) -> Status {
    with(instance, |fmu| {
        let call = "fmi3GetContinuousStateDerivatives";
        fmu.expect_model_exchange(call, AFTER_INSTANTIATION)?;
        deliver(fmu, "derivatives", fmu.unit.derivatives()?, derivatives, n)
    })
}

#[no_mangle]
pub extern "C" fn fmi3GetNominalsOfContinuousStates(
    instance: Instance,
    nominals: *mut f64,
    n: usize,
) -> Status {
    with(instance, |fmu| {
        deliver(fmu, "nominals", fmu.unit.nominals(), nominals, n)
    })
}

#[no_mangle]
pub extern "C" fn fmi3GetEventIndicators(
    instance: Instance,
    indicators: *mut f64,
    n: usize,
) -> Status {
    with(instance, |fmu| {
        fmu.expect_model_exchange("fmi3GetEventIndicators", AFTER_INSTANTIATION)?;
        deliver(
            fmu,
            "event indicators",
            fmu.unit.indicators(),
            indicators,
            n,
        )
    })
}

#[no_mangle]
pub extern "C" fn fmi3GetNumberOfEventIndicators(instance: Instance, n: *mut usize) -> Status {
    with(instance, |fmu| {
        write(n, fmu.unit.indicators().len());
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn fmi3GetNumberOfContinuousStates(instance: Instance, n: *mut usize) -> Status {
    with(instance, |fmu| {
        write(n, fmu.unit.states().len());
        Ok(())
    })
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn fmi3DoStep(
    instance: Instance,
    current: f64,
    step: f64,
    _no_set_state_prior: bool,
    event_handling_needed: *mut bool,
    terminate: *mut bool,
    early_return: *mut bool,
    last_successful_time: *mut f64,
) -> Status {
    with(instance, |fmu| {
        write(event_handling_needed, false);
        write(terminate, false);
        write(early_return, false);
        fmu.expect("fmi3DoStep", &[Phase::Step])?;
        let result = check_step(current, step).and_then(|()| fmu.unit.do_step(current, step));
        write(last_successful_time, fmu.unit.time());
        result
    })
}

/// As many values as value references (scalar variables).
fn one_each(n_vrs: usize, n_values: usize) -> Result<(), String> {
    if n_vrs != n_values {
        return Err(format!("{n_vrs} value references for {n_values} values"));
    }
    Ok(())
}

/// `n` values for the value references `vrs`: as many as their variables hold.
fn check_count(fmu: &Fmu, vrs: &[u32], n: usize) -> Result<(), String> {
    let want = vrs
        .iter()
        .fold(0_usize, |sum, r| sum.saturating_add(fmu.size(*r)));
    if want != n {
        return Err(format!(
            "{} value references for {n} values: their variables hold {want}",
            vrs.len()
        ));
    }
    Ok(())
}

#[no_mangle]
pub extern "C" fn fmi3GetUInt64(
    instance: Instance,
    vrs: *const u32,
    n_vrs: usize,
    values: *mut u64,
    n_values: usize,
) -> Status {
    with(instance, |fmu| {
        let (vrs, values) = (slice(vrs, n_vrs), slice_mut(values, n_values));
        one_each(vrs.len(), values.len())?;
        for (r, out) in vrs.iter().zip(values.iter_mut()) {
            *out = fmu.unit.get_count(*r)?;
        }
        Ok(())
    })
}

/// Sets structural parameters: in configuration mode only (FMI 3.0, variability fixed).
#[no_mangle]
pub extern "C" fn fmi3SetUInt64(
    instance: Instance,
    vrs: *const u32,
    n_vrs: usize,
    values: *const u64,
    n_values: usize,
) -> Status {
    with(instance, |fmu| {
        fmu.expect("fmi3SetUInt64", &[Phase::Configuration])?;
        let (vrs, values) = (slice(vrs, n_vrs), slice(values, n_values));
        one_each(vrs.len(), values.len())?;
        vrs.iter()
            .zip(values)
            .try_for_each(|(r, v)| fmu.unit.set_count(*r, *v))
    })
}

#[no_mangle]
pub extern "C" fn fmi3EnterConfigurationMode(instance: Instance) -> Status {
    with(instance, |fmu| {
        fmu.expect("fmi3EnterConfigurationMode", &[Phase::Instantiated])?;
        if !fmu.unit.structural() {
            return Err("fmi3EnterConfigurationMode: this FMU has no structural parameters".into());
        }
        fmu.phase = Phase::Configuration;
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn fmi3ExitConfigurationMode(instance: Instance) -> Status {
    with(instance, |fmu| {
        fmu.expect("fmi3ExitConfigurationMode", &[Phase::Configuration])?;
        fmu.phase = Phase::Instantiated;
        Ok(())
    })
}

/// The phases after `fmi3EnterInitializationMode`, where values can be read.
const AFTER_INSTANTIATION: &[Phase] = &[
    Phase::Initialization,
    Phase::Event,
    Phase::ContinuousTime,
    Phase::Step,
    Phase::Terminated,
];

/// `fmi3DoStep`'s arguments: a finite communication point, a finite step size `h >= 0`, and a
/// finite time at the step's end.
#[inline]
fn check_step(current: f64, h: f64) -> Result<(), String> {
    if current.is_finite() && h >= 0.0 && (current + h).is_finite() {
        Ok(())
    } else {
        Err(bad_step(current, h))
    }
}

/// Which of `fmi3DoStep`'s arguments is wrong, in words (off the hot path).
#[cold]
#[inline(never)]
fn bad_step(current: f64, h: f64) -> String {
    if !current.is_finite() {
        format!(
            "fmi3DoStep: the current communication point must be a finite number, got {}",
            num(current)
        )
    } else if !(h >= 0.0 && h.is_finite()) {
        format!(
            "fmi3DoStep: the communication step size must be a finite number >= 0, got {}",
            num(h)
        )
    } else {
        format!(
            "fmi3DoStep: the step size {} from t = {} takes the time past the largest finite number",
            num(h),
            num(current)
        )
    }
}

/// Functions these models do not use: `fmi3Error`, logged.
macro_rules! unsupported {
    ($name:ident($instance:ident: Instance $(, $arg:ident: $ty:ty)*)) => {
        #[no_mangle]
        #[allow(non_snake_case, clippy::too_many_arguments)]
        pub extern "C" fn $name($instance: Instance $(, $arg: $ty)*) -> Status {
            with($instance, |_| {
                Err(concat!(stringify!($name), " is not supported by lugre's FMUs").to_string())
            })
        }
    };
}

unsupported!(fmi3GetFloat32(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void, _nv: usize));
unsupported!(fmi3GetInt8(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void, _nv: usize));
unsupported!(fmi3GetUInt8(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void, _nv: usize));
unsupported!(fmi3GetInt16(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void, _nv: usize));
unsupported!(fmi3GetUInt16(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void, _nv: usize));
unsupported!(fmi3GetInt32(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void, _nv: usize));
unsupported!(fmi3GetUInt32(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void, _nv: usize));
unsupported!(fmi3GetInt64(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void, _nv: usize));
unsupported!(fmi3GetBoolean(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void, _nv: usize));
unsupported!(fmi3GetString(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void, _nv: usize));
unsupported!(fmi3GetBinary(instance: Instance, _vr: *const c_void, _nvr: usize, _sizes: *const c_void, _v: *const c_void, _nv: usize));
unsupported!(fmi3GetClock(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void));
unsupported!(fmi3SetFloat32(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void, _nv: usize));
unsupported!(fmi3SetInt8(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void, _nv: usize));
unsupported!(fmi3SetUInt8(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void, _nv: usize));
unsupported!(fmi3SetInt16(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void, _nv: usize));
unsupported!(fmi3SetUInt16(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void, _nv: usize));
unsupported!(fmi3SetInt32(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void, _nv: usize));
unsupported!(fmi3SetUInt32(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void, _nv: usize));
unsupported!(fmi3SetInt64(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void, _nv: usize));
unsupported!(fmi3SetBoolean(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void, _nv: usize));
unsupported!(fmi3SetString(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void, _nv: usize));
unsupported!(fmi3SetBinary(instance: Instance, _vr: *const c_void, _nvr: usize, _sizes: *const c_void, _v: *const c_void, _nv: usize));
unsupported!(fmi3SetClock(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void));
unsupported!(fmi3GetNumberOfVariableDependencies(instance: Instance, _vr: u32, _n: *const c_void));
unsupported!(fmi3GetVariableDependencies(instance: Instance, _vr: u32, _a: *const c_void, _b: *const c_void, _c: *const c_void, _d: *const c_void, _n: usize));
unsupported!(fmi3GetFMUState(instance: Instance, _s: *const c_void));
unsupported!(fmi3SetFMUState(instance: Instance, _s: *const c_void));
unsupported!(fmi3FreeFMUState(instance: Instance, _s: *const c_void));
unsupported!(fmi3SerializedFMUStateSize(instance: Instance, _s: *const c_void, _n: *const c_void));
unsupported!(fmi3SerializeFMUState(instance: Instance, _s: *const c_void, _b: *const c_void, _n: usize));
unsupported!(fmi3DeserializeFMUState(instance: Instance, _b: *const c_void, _n: usize, _s: *const c_void));
unsupported!(fmi3GetDirectionalDerivative(instance: Instance, _u: *const c_void, _nu: usize, _k: *const c_void, _nk: usize, _s: *const c_void, _ns: usize, _o: *const c_void, _no: usize));
unsupported!(fmi3GetAdjointDerivative(instance: Instance, _u: *const c_void, _nu: usize, _k: *const c_void, _nk: usize, _s: *const c_void, _ns: usize, _o: *const c_void, _no: usize));
unsupported!(fmi3GetIntervalDecimal(instance: Instance, _vr: *const c_void, _n: usize, _i: *const c_void, _q: *const c_void));
unsupported!(fmi3GetIntervalFraction(instance: Instance, _vr: *const c_void, _n: usize, _c: *const c_void, _r: *const c_void, _q: *const c_void));
unsupported!(fmi3GetShiftDecimal(instance: Instance, _vr: *const c_void, _n: usize, _s: *const c_void));
unsupported!(fmi3GetShiftFraction(instance: Instance, _vr: *const c_void, _n: usize, _c: *const c_void, _r: *const c_void));
unsupported!(fmi3SetIntervalDecimal(instance: Instance, _vr: *const c_void, _n: usize, _i: *const c_void));
unsupported!(fmi3SetIntervalFraction(instance: Instance, _vr: *const c_void, _n: usize, _c: *const c_void, _r: *const c_void));
unsupported!(fmi3SetShiftDecimal(instance: Instance, _vr: *const c_void, _n: usize, _s: *const c_void));
unsupported!(fmi3SetShiftFraction(instance: Instance, _vr: *const c_void, _n: usize, _c: *const c_void, _r: *const c_void));
unsupported!(fmi3EvaluateDiscreteStates(instance: Instance));
unsupported!(fmi3GetOutputDerivatives(instance: Instance, _vr: *const c_void, _n: usize, _o: *const c_void, _v: *const c_void, _nv: usize));
unsupported!(fmi3ActivateModelPartition(instance: Instance, _clock: u32, _t: f64));
