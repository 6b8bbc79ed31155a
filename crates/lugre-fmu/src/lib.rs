//! The FMI 3.0 functions of `lugre-friction.fmu`: the LuGre friction element for any FMI host
//! (Simulink's FMU block, Dymola, OpenModelica, fmpy), in model exchange and co-simulation.
//! `bash scripts/build-fmu.sh` bundles this library with `fmu/lugre-friction.xml`.
//!
//! **Why hand-written.** The FMI 3.0 C interface is a flat list of functions over plain types;
//! writing them here against the standard's signatures (`fmi3FunctionTypes.h`) costs no
//! bindgen/libclang build step, and the few that matter are small. Everything the friction
//! element does not use (clocks, other types, FMU states, scheduled execution) returns
//! `fmi3Error` with a logged message.
//!
//! **The model** (SI units; parameters as the CLI's flags; defaults Table I of Canudas de Wit
//! et al. 1995):
//!
//! ```text
//! inputs x [m], v = dx/dt [m/s]     state z [m], z(0) = x0
//! z' = v - sigma0 |v| z / g(v)      g(v) = Fc + (Fs - Fc) exp(-|v/vs|^beta)
//! output F = sigma0 z + sigma1 z' + sigma2 v   [N]
//! ```
//!
//! * Model exchange: the host integrates `z` (one continuous state, no event indicator: the
//!   non-smoothness of `|v|` is in the input the host provides).
//! * Co-simulation: `fmi3DoStep(t, h)` moves the displacement linearly from where it is to
//!   `x + v h` (`x`, `v` the inputs set for `t`) and advances the element exactly
//!   ([`lugre::simulate::FrictionElement`]): exact for a displacement linear over each step at
//!   any stiffness and step size. A host that gives no `v` holds `x` over each step; a change of
//!   `x` at the next communication point is then taken linearly over that next step.
//!
//! No panic crosses the boundary; a bad parameter or a non-finite input is `fmi3Error` with the
//! message sent to the host's logger.

#![allow(clippy::not_unsafe_ptr_arg_deref)]

use std::ffi::{c_char, c_void, CStr, CString};
use std::panic::{catch_unwind, AssertUnwindSafe};

use lugre::simulate::FrictionElement;
use lugre::{LuGre, LuGreParams};

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

/// The token of `fmu/lugre-friction.xml` (`instantiationToken`).
pub const FRICTION_TOKEN: &str = "{7f6c1c2e-3b1d-4c55-9a57-lugre-friction-1}";

/// Value references (as in `fmu/lugre-friction.xml`).
pub mod vr {
    pub const TIME: u32 = 0;
    pub const X: u32 = 1;
    pub const V: u32 = 2;
    pub const F: u32 = 3;
    pub const Z: u32 = 4;
    pub const DER_Z: u32 = 5;
    pub const SIGMA0: u32 = 10;
    pub const SIGMA1: u32 = 11;
    pub const SIGMA2: u32 = 12;
    pub const FC: u32 = 13;
    pub const FS: u32 = 14;
    pub const VS: u32 = 15;
    pub const BETA: u32 = 16;
    pub const X0: u32 = 17;
}

/// The interface an instance runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    ModelExchange,
    CoSimulation,
}

/// One instance of the friction FMU.
struct Friction {
    kind: Kind,
    name: CString,
    environment: *mut c_void,
    log: LogMessage,
    params: LuGreParams,
    x0: f64,
    time: f64,
    x: f64,
    v: f64,
    /// The state (model exchange).
    z: f64,
    model: Option<LuGre>,
    /// The element (co-simulation), from the end of initialization.
    element: Option<FrictionElement>,
}

impl Friction {
    fn new(kind: Kind, name: CString, environment: *mut c_void, log: LogMessage) -> Self {
        let params = LuGreParams::canudas_de_wit_1995();
        Self {
            kind,
            name,
            environment,
            log,
            params,
            x0: 0.0,
            time: 0.0,
            x: 0.0,
            v: 0.0,
            z: 0.0,
            model: None,
            element: None,
        }
    }

    fn error(&self, message: &str) -> Status {
        if let Some(log) = self.log {
            let category = c"logStatusError";
            let text = CString::new(message.replace('\0', " ")).unwrap_or_default();
            // SAFETY: the host's callback with its own environment pointer.
            unsafe {
                log(
                    self.environment,
                    Status::Error,
                    category.as_ptr(),
                    text.as_ptr(),
                )
            };
        }
        let _ = &self.name;
        Status::Error
    }

    /// The model from the parameters (validated as the CLI validates its flags).
    fn build(&mut self) -> Result<(), String> {
        let model = LuGre::from_params(self.params).map_err(|e| e.to_string())?;
        self.model = Some(model.clone());
        if self.kind == Kind::CoSimulation {
            let element = FrictionElement::starting_at(model, self.time, self.x, self.x0)
                .map_err(|e| e.to_string())?;
            self.element = Some(element);
        } else {
            self.z = self.x0;
        }
        Ok(())
    }

    /// `z'` and `F` at the current state and inputs (model exchange).
    fn rates(&self) -> (f64, f64) {
        let p = &self.params;
        let Some(m) = &self.model else {
            return (0.0, p.sigma0 * self.z);
        };
        let dz = self.v - p.sigma0 * self.v.abs() * self.z / m.g(self.v);
        (dz, p.sigma0 * self.z + p.sigma1 * dz + m.f(self.v))
    }

    fn get(&self, vr: u32) -> Option<f64> {
        let p = &self.params;
        Some(match vr {
            vr::TIME => self.time,
            vr::X => self.x,
            vr::V => self.v,
            vr::F => match &self.element {
                Some(e) => e.force(),
                None => self.rates().1,
            },
            vr::Z => self.element.as_ref().map_or(self.z, FrictionElement::state),
            vr::DER_Z => self.rates().0,
            vr::SIGMA0 => p.sigma0,
            vr::SIGMA1 => p.sigma1,
            vr::SIGMA2 => p.sigma2,
            vr::FC => p.fc,
            vr::FS => p.fs,
            vr::VS => p.vs,
            vr::BETA => p.beta,
            vr::X0 => self.x0,
            _ => return None,
        })
    }

    fn set(&mut self, vr: u32, value: f64) -> Result<(), String> {
        if !value.is_finite() {
            return Err(format!(
                "the value of {} must be a finite number, got {value}",
                name_of(vr)
            ));
        }
        let initialized = self.model.is_some();
        let p = &mut self.params;
        let parameter = match vr {
            vr::X => {
                self.x = value;
                return Ok(());
            }
            vr::V => {
                self.v = value;
                return Ok(());
            }
            vr::SIGMA0 => &mut p.sigma0,
            vr::SIGMA1 => &mut p.sigma1,
            vr::SIGMA2 => &mut p.sigma2,
            vr::FC => &mut p.fc,
            vr::FS => &mut p.fs,
            vr::VS => &mut p.vs,
            vr::BETA => &mut p.beta,
            vr::X0 => &mut self.x0,
            _ => return Err(format!("no settable variable has value reference {vr}")),
        };
        if initialized {
            return Err(format!(
                "{} is a fixed parameter: set it before the end of initialization",
                name_of(vr)
            ));
        }
        *parameter = value;
        Ok(())
    }

    /// One co-simulation step (see the module docs).
    fn do_step(&mut self, t: f64, h: f64) -> Result<(), String> {
        let (x_end, v) = (self.x + self.v * h, self.v);
        let Some(e) = self.element.as_mut() else {
            return Err("fmi3DoStep before the end of initialization".into());
        };
        if !x_end.is_finite() {
            return Err(format!("the displacement x + v h is not finite (v = {v})"));
        }
        e.step(x_end, h).map_err(|err| err.to_string())?;
        self.time = t + h;
        self.x = x_end;
        Ok(())
    }
}

fn name_of(vr: u32) -> &'static str {
    match vr {
        vr::TIME => "time",
        vr::X => "x",
        vr::V => "v",
        vr::F => "F",
        vr::Z => "z",
        vr::DER_Z => "der(z)",
        vr::SIGMA0 => "sigma0",
        vr::SIGMA1 => "sigma1",
        vr::SIGMA2 => "sigma2",
        vr::FC => "fc",
        vr::FS => "fs",
        vr::VS => "vs",
        vr::BETA => "beta",
        vr::X0 => "x0",
        _ => "an unknown variable",
    }
}

/// Runs `body` on the instance; a panic becomes `fmi3Fatal`, an error `fmi3Error` (logged).
fn with(instance: Instance, body: impl FnOnce(&mut Friction) -> Result<(), String>) -> Status {
    if instance.is_null() {
        return Status::Error;
    }
    // SAFETY: a non-NULL instance is one this library made and has not freed.
    let fmu = unsafe { &mut *instance.cast::<Friction>() };
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

fn instantiate(
    kind: Kind,
    name: *const c_char,
    token: *const c_char,
    environment: *mut c_void,
    log: LogMessage,
) -> Instance {
    catch_unwind(|| {
        let name = if name.is_null() {
            CString::default()
        } else {
            // SAFETY: a NUL-terminated string from the host.
            unsafe { CStr::from_ptr(name) }.to_owned()
        };
        let fmu = Friction::new(kind, name, environment, log);
        // SAFETY: as above.
        let token_ok = !token.is_null()
            && unsafe { CStr::from_ptr(token) }.to_bytes() == FRICTION_TOKEN.as_bytes();
        if !token_ok {
            fmu.error("the instantiation token is not lugre-friction's (a different modelDescription.xml?)");
            return std::ptr::null_mut();
        }
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
#[allow(clippy::too_many_arguments)]
pub extern "C" fn fmi3InstantiateModelExchange(
    name: *const c_char,
    token: *const c_char,
    _resource_path: *const c_char,
    _visible: bool,
    _logging_on: bool,
    environment: *mut c_void,
    log: LogMessage,
) -> Instance {
    instantiate(Kind::ModelExchange, name, token, environment, log)
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn fmi3InstantiateCoSimulation(
    name: *const c_char,
    token: *const c_char,
    _resource_path: *const c_char,
    _visible: bool,
    _logging_on: bool,
    _event_mode_used: bool,
    _early_return_allowed: bool,
    _required_intermediate: *const u32,
    _n_required_intermediate: usize,
    environment: *mut c_void,
    log: LogMessage,
    _intermediate_update: *const c_void,
) -> Instance {
    instantiate(Kind::CoSimulation, name, token, environment, log)
}

#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn fmi3InstantiateScheduledExecution(
    _name: *const c_char,
    _token: *const c_char,
    _resource_path: *const c_char,
    _visible: bool,
    _logging_on: bool,
    _environment: *mut c_void,
    _log: LogMessage,
    _clock_update: *const c_void,
    _lock: *const c_void,
    _unlock: *const c_void,
) -> Instance {
    std::ptr::null_mut()
}

#[no_mangle]
pub extern "C" fn fmi3FreeInstance(instance: Instance) {
    if !instance.is_null() {
        // SAFETY: made by `instantiate`, freed once by the host.
        let _ = catch_unwind(|| drop(unsafe { Box::from_raw(instance.cast::<Friction>()) }));
    }
}

#[no_mangle]
pub extern "C" fn fmi3EnterInitializationMode(
    instance: Instance,
    _tolerance_defined: bool,
    _tolerance: f64,
    start_time: f64,
    _stop_time_defined: bool,
    _stop_time: f64,
) -> Status {
    with(instance, |fmu| {
        if !start_time.is_finite() {
            return Err(format!("the start time must be finite, got {start_time}"));
        }
        fmu.time = start_time;
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn fmi3ExitInitializationMode(instance: Instance) -> Status {
    with(instance, Friction::build)
}

#[no_mangle]
pub extern "C" fn fmi3EnterEventMode(instance: Instance) -> Status {
    with(instance, |_| Ok(()))
}

#[no_mangle]
pub extern "C" fn fmi3Terminate(instance: Instance) -> Status {
    with(instance, |_| Ok(()))
}

#[no_mangle]
pub extern "C" fn fmi3Reset(instance: Instance) -> Status {
    with(instance, |fmu| {
        *fmu = Friction::new(fmu.kind, fmu.name.clone(), fmu.environment, fmu.log);
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
        let (vrs, values) = (slice(vrs, n_vrs), slice_mut(values, n_values));
        if vrs.len() != values.len() {
            return Err(format!(
                "{} value references for {} values",
                vrs.len(),
                values.len()
            ));
        }
        for (vr, out) in vrs.iter().zip(values.iter_mut()) {
            let value = fmu
                .get(*vr)
                .ok_or_else(|| format!("no Float64 variable has value reference {vr}"))?;
            if !value.is_finite() {
                return Err(format!(
                    "{} is not finite at t = {}",
                    name_of(*vr),
                    fmu.time
                ));
            }
            *out = value;
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
        let (vrs, values) = (slice(vrs, n_vrs), slice(values, n_values));
        if vrs.len() != values.len() {
            return Err(format!(
                "{} value references for {} values",
                vrs.len(),
                values.len()
            ));
        }
        vrs.iter()
            .zip(values)
            .try_for_each(|(vr, value)| fmu.set(*vr, *value))
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
    with(instance, |_| {
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
    with(instance, |_| Ok(()))
}

#[no_mangle]
pub extern "C" fn fmi3EnterStepMode(instance: Instance) -> Status {
    with(instance, |_| Ok(()))
}

#[no_mangle]
pub extern "C" fn fmi3CompletedIntegratorStep(
    instance: Instance,
    _no_set_state_prior: bool,
    enter_event_mode: *mut bool,
    terminate: *mut bool,
) -> Status {
    with(instance, |_| {
        write(enter_event_mode, false);
        write(terminate, false);
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn fmi3SetTime(instance: Instance, time: f64) -> Status {
    with(instance, |fmu| {
        if !time.is_finite() {
            return Err(format!("the time must be finite, got {time}"));
        }
        fmu.time = time;
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn fmi3SetContinuousStates(
    instance: Instance,
    states: *const f64,
    n: usize,
) -> Status {
    with(instance, |fmu| match slice(states, n) {
        [z] if z.is_finite() => {
            fmu.z = *z;
            Ok(())
        }
        [z] => Err(format!("the state z must be finite, got {z}")),
        other => Err(format!("one continuous state (z), got {}", other.len())),
    })
}

#[no_mangle]
pub extern "C" fn fmi3GetContinuousStates(
    instance: Instance,
    states: *mut f64,
    n: usize,
) -> Status {
    with(instance, |fmu| match slice_mut(states, n) {
        [z] => {
            *z = fmu.z;
            Ok(())
        }
        other => Err(format!("one continuous state (z), got {}", other.len())),
    })
}

#[no_mangle]
pub extern "C" fn fmi3GetContinuousStateDerivatives(
    instance: Instance,
    derivatives: *mut f64,
    n: usize,
) -> Status {
    with(instance, |fmu| {
        let dz = fmu.rates().0;
        match slice_mut(derivatives, n) {
            [d] if dz.is_finite() => {
                *d = dz;
                Ok(())
            }
            [_] => Err(format!("der(z) is not finite at t = {}", fmu.time)),
            other => Err(format!("one continuous state (z), got {}", other.len())),
        }
    })
}

#[no_mangle]
pub extern "C" fn fmi3GetNominalsOfContinuousStates(
    instance: Instance,
    nominals: *mut f64,
    n: usize,
) -> Status {
    with(instance, |fmu| match slice_mut(nominals, n) {
        // z is of the order of g(0) / sigma0.
        [z] => {
            *z = (fmu.params.fs.max(fmu.params.fc) / fmu.params.sigma0)
                .abs()
                .max(1e-300);
            Ok(())
        }
        other => Err(format!("one continuous state (z), got {}", other.len())),
    })
}

#[no_mangle]
pub extern "C" fn fmi3GetEventIndicators(
    instance: Instance,
    _indicators: *mut f64,
    n: usize,
) -> Status {
    with(instance, |_| {
        if n != 0 {
            return Err(format!("no event indicators, asked for {n}"));
        }
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn fmi3GetNumberOfEventIndicators(instance: Instance, n: *mut usize) -> Status {
    with(instance, |_| {
        write(n, 0);
        Ok(())
    })
}

#[no_mangle]
pub extern "C" fn fmi3GetNumberOfContinuousStates(instance: Instance, n: *mut usize) -> Status {
    with(instance, |_| {
        write(n, 1);
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
        let result = fmu.do_step(current, step);
        write(last_successful_time, fmu.time);
        result
    })
}

/// Functions the friction element does not use: `fmi3Error`, logged.
macro_rules! unsupported {
    ($name:ident($instance:ident: Instance $(, $arg:ident: $ty:ty)*)) => {
        #[no_mangle]
        #[allow(non_snake_case, clippy::too_many_arguments)]
        pub extern "C" fn $name($instance: Instance $(, $arg: $ty)*) -> Status {
            with($instance, |_| {
                Err(concat!(stringify!($name), " is not supported by lugre-friction").to_string())
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
unsupported!(fmi3GetUInt64(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void, _nv: usize));
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
unsupported!(fmi3SetUInt64(instance: Instance, _vr: *const c_void, _nvr: usize, _v: *const c_void, _nv: usize));
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
unsupported!(fmi3EnterConfigurationMode(instance: Instance));
unsupported!(fmi3ExitConfigurationMode(instance: Instance));
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
