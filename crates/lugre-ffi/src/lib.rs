//! The C ABI of lugre: a small, stable interface for C, C++, Julia (`ccall`), MATLAB/Octave
//! (the MEX gateway in `matlab/`) and any host that loads a shared library. The header,
//! `include/lugre.h`, is generated from this file by cbindgen (checked by `tests/header.rs`).
//!
//! Conventions, for every function:
//! * the return value is a [`LugreStatus`]: `LUGRE_STATUS_OK` (0) or an error code; after an
//!   error [`lugre_last_error`] returns the message (the same text the CLI prints), valid until
//!   the next failing call on the same thread;
//! * objects are opaque handles created by a `*_new` function into an out-pointer and released
//!   by the matching `*_free` (which accepts NULL);
//! * arrays are caller-owned: the caller passes a pointer and a length (inputs) or a capacity
//!   (outputs: the call fails with `LUGRE_STATUS_BUFFER_TOO_SMALL` rather than write past it);
//! * no Rust panic crosses the boundary (it becomes `LUGRE_STATUS_PANIC`), nothing is written
//!   on failure, and no output is ever NaN or infinite.
//!
//! Units are SI, as in the CLI: displacements in m, forces in N, `sigma0` in N/m, `sigma1` and
//! `sigma2` in N s/m, `vs` in m/s, Dahl's `rho` in 1/m.

// The entry points are called from C, where Rust's `unsafe` means nothing: the pointer contract
// is the module documentation's, and every pointer is checked for NULL before use.
#![allow(clippy::not_unsafe_ptr_arg_deref)]

use std::cell::RefCell;
use std::ffi::{c_char, CStr, CString};
use std::panic::{catch_unwind, AssertUnwindSafe};

use lugre::dynamics::{Scenario, Tolerances};
use lugre::simulate::FrictionElement;
use lugre::{
    CycleColumns, CycleCounter, Dahl, EnergyCycleCounter, Gamma, HysteresisLoop, LoopKind, LuGre,
    LuGreParams, PiecewiseLinear, Simulator, Trajectory, TurningPoints,
};

/// The outcome of a call.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LugreStatus {
    Ok = 0,
    /// An invalid parameter or input (non-finite values, a non-physical model, ...).
    InvalidArgument = 1,
    /// An output buffer is shorter than the result (ask for the length first).
    BufferTooSmall = 2,
    /// A required pointer is NULL.
    NullPointer = 3,
    /// An internal error (a caught panic): please report it.
    Panic = 4,
}

/// The parameters of a LuGre model (SI units; see [`lugre_params_default`]).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LugreParams {
    pub sigma0: f64,
    pub sigma1: f64,
    pub sigma2: f64,
    pub fc: f64,
    pub fs: f64,
    pub vs: f64,
    pub beta: f64,
}

/// The CLI's defaults (as [`lugre_params_default`]).
impl Default for LugreParams {
    fn default() -> Self {
        LuGreParams::default().into()
    }
}

impl From<LugreParams> for LuGreParams {
    fn from(p: LugreParams) -> Self {
        Self {
            sigma0: p.sigma0,
            sigma1: p.sigma1,
            sigma2: p.sigma2,
            fc: p.fc,
            fs: p.fs,
            vs: p.vs,
            beta: p.beta,
        }
    }
}

impl From<LuGreParams> for LugreParams {
    fn from(p: LuGreParams) -> Self {
        Self {
            sigma0: p.sigma0,
            sigma1: p.sigma1,
            sigma2: p.sigma2,
            fc: p.fc,
            fs: p.fs,
            vs: p.vs,
            beta: p.beta,
        }
    }
}

/// A validated friction model (LuGre, or Dahl as the LuGre model it equals).
pub struct LugreModel {
    model: LuGre,
    /// Dahl's rate-independent limit differs from its LuGre form's only in name; kept for it.
    dahl: Option<Dahl>,
}

/// The periodic hysteresis loop of one input.
pub struct LugreLoop {
    hl: HysteresisLoop,
}

/// The rainflow cycles of a history, as columns.
pub struct LugreCycles {
    columns: CycleColumns,
}

/// A stateful friction element for host simulators.
pub struct LugreElement {
    element: FrictionElement,
}

/// The loop table's columns (each of the table's length; NULL skips a column). `kind` is 0 for
/// the major loop, 1 for a minor loop; `parent` is -1 for none.
#[repr(C)]
pub struct LugreLoopColumns {
    pub kind: *mut i32,
    pub start_rho: *mut f64,
    pub start_u: *mut f64,
    pub start_y: *mut f64,
    pub reversal_rho: *mut f64,
    pub reversal_u: *mut f64,
    pub reversal_y: *mut f64,
    pub end_rho: *mut f64,
    pub end_u: *mut f64,
    pub end_y: *mut f64,
    pub work: *mut f64,
    pub stored_energy_change: *mut f64,
    pub dissipation: *mut f64,
    pub closure_gap: *mut f64,
    pub parent: *mut i64,
    pub depth: *mut i64,
}

/// The cycle columns (each of the count's length; NULL skips a column). `closure` is -1 and
/// `closure_position` 0 for half cycles; the energy columns are 0 without a model.
#[repr(C)]
pub struct LugreCycleColumns {
    pub range: *mut f64,
    pub mean: *mut f64,
    pub count: *mut f64,
    pub start: *mut i64,
    pub end: *mut i64,
    pub closure: *mut i64,
    pub closure_position: *mut f64,
    pub work: *mut f64,
    pub stored_energy_change: *mut f64,
    pub dissipation: *mut f64,
    pub closure_gap: *mut f64,
}

thread_local! {
    static LAST_ERROR: RefCell<CString> = RefCell::new(CString::default());
}

/// A failed call: its status and message.
struct Failure(LugreStatus, String);

impl<E: std::error::Error> From<E> for Failure {
    fn from(e: E) -> Self {
        Failure(LugreStatus::InvalidArgument, e.to_string())
    }
}

fn fail(status: LugreStatus, message: impl Into<String>) -> Failure {
    Failure(status, message.into())
}

/// Runs `body`, turning errors and panics into a status and the thread's last message.
fn guard(body: impl FnOnce() -> Result<(), Failure>) -> LugreStatus {
    let outcome = catch_unwind(AssertUnwindSafe(body)).unwrap_or_else(|_| {
        Err(fail(
            LugreStatus::Panic,
            "internal error in lugre (a panic was caught); please report it",
        ))
    });
    match outcome {
        Ok(()) => LugreStatus::Ok,
        Err(Failure(status, message)) => {
            let text = CString::new(message.replace('\0', " ")).unwrap_or_default();
            LAST_ERROR.with(|e| *e.borrow_mut() = text);
            status
        }
    }
}

/// A shared reference from a handle, or a NullPointer failure naming it.
fn handle<'a, T>(p: *const T, name: &str) -> Result<&'a T, Failure> {
    // SAFETY: the caller passes a handle made by this library (or NULL, refused here).
    unsafe { p.as_ref() }.ok_or_else(|| fail(LugreStatus::NullPointer, format!("{name} is NULL")))
}

fn handle_mut<'a, T>(p: *mut T, name: &str) -> Result<&'a mut T, Failure> {
    // SAFETY: as `handle`, and the caller does not share the handle across threads meanwhile.
    unsafe { p.as_mut() }.ok_or_else(|| fail(LugreStatus::NullPointer, format!("{name} is NULL")))
}

/// `n` input values at `p` (checked finite), or a failure naming them.
fn input<'a>(p: *const f64, n: usize, name: &str) -> Result<&'a [f64], Failure> {
    if n == 0 {
        return Ok(&[]);
    }
    if p.is_null() {
        return Err(fail(LugreStatus::NullPointer, format!("{name} is NULL")));
    }
    // SAFETY: the caller guarantees `n` readable values at `p`.
    let values = unsafe { std::slice::from_raw_parts(p, n) };
    if let Some(i) = values.iter().position(|v| !v.is_finite()) {
        return Err(fail(
            LugreStatus::InvalidArgument,
            format!("{name}[{i}] = {} is not a finite number", values[i]),
        ));
    }
    Ok(values)
}

/// Writes `values` to `p` (NULL skips), after checking `capacity`.
fn output<T: Copy>(p: *mut T, values: &[T]) {
    if !p.is_null() {
        // SAFETY: the caller guarantees `capacity >= values.len()` writable values (checked by
        // the callers against the capacity it passed).
        unsafe { std::ptr::copy_nonoverlapping(values.as_ptr(), p, values.len()) };
    }
}

fn capacity(len: usize, cap: usize) -> Result<(), Failure> {
    if cap < len {
        return Err(fail(
            LugreStatus::BufferTooSmall,
            format!("the output buffers hold {cap}, the result has {len} values"),
        ));
    }
    Ok(())
}

fn set_out<T>(out: *mut *mut T, value: T) -> Result<(), Failure> {
    if out.is_null() {
        return Err(fail(LugreStatus::NullPointer, "the out-pointer is NULL"));
    }
    // SAFETY: `out` is a valid place for a pointer (checked non-NULL).
    unsafe { *out = Box::into_raw(Box::new(value)) };
    Ok(())
}

fn free<T>(p: *mut T) {
    if !p.is_null() {
        // SAFETY: `p` was made by `set_out` and is freed once.
        drop(unsafe { Box::from_raw(p) });
    }
}

/// The message of the last failed call on this thread ("" if none). The pointer stays valid
/// until the next failing call on the same thread.
#[no_mangle]
pub extern "C" fn lugre_last_error() -> *const c_char {
    LAST_ERROR.with(|e| e.borrow().as_ptr())
}

/// The library's version, e.g. "0.1.0" (static).
#[no_mangle]
pub extern "C" fn lugre_version() -> *const c_char {
    concat!(env!("CARGO_PKG_VERSION"), "\0").as_ptr().cast()
}

/// The CLI's defaults (the paper's dimensionless values: sigma0 = 1, sigma1 = 1, sigma2 = 0,
/// Fc = 1, Fs = 2, vs = 1, beta = 1).
#[no_mangle]
pub extern "C" fn lugre_params_default(out: *mut LugreParams) -> LugreStatus {
    guard(|| {
        let p = handle_mut(out, "out")?;
        *p = LugreParams::default();
        Ok(())
    })
}

/// Table I of Canudas de Wit et al. (1995) (`--preset canudas1995`).
#[no_mangle]
pub extern "C" fn lugre_params_canudas1995(out: *mut LugreParams) -> LugreStatus {
    guard(|| {
        let p = handle_mut(out, "out")?;
        *p = LuGreParams::canudas_de_wit_1995().into();
        Ok(())
    })
}

/// A LuGre model, validated as the CLI validates its flags.
#[no_mangle]
pub extern "C" fn lugre_model_new(
    params: *const LugreParams,
    out: *mut *mut LugreModel,
) -> LugreStatus {
    guard(|| {
        let model = LuGre::from_params((*handle(params, "params")?).into())?;
        set_out(out, LugreModel { model, dahl: None })
    })
}

/// A Dahl model `w' = rho (u' - |u'| w)`, `y = Fc w`.
#[no_mangle]
pub extern "C" fn lugre_model_new_dahl(
    rho: f64,
    fc: f64,
    out: *mut *mut LugreModel,
) -> LugreStatus {
    guard(|| {
        let dahl = Dahl::new(rho, fc)?;
        set_out(
            out,
            LugreModel {
                model: dahl.to_lugre(),
                dahl: Some(dahl),
            },
        )
    })
}

#[no_mangle]
pub extern "C" fn lugre_model_free(model: *mut LugreModel) {
    free(model)
}

impl LugreModel {
    fn rate_independent(&self) -> lugre::RateIndependent {
        self.dahl
            .as_ref()
            .map_or_else(|| self.model.rate_independent(), Dahl::rate_independent)
    }
}

/// The hysteresis loop y° of the periodic input with one period's turning points `u[0..n]`
/// (as `lugre loop --turning-points`).
#[no_mangle]
pub extern "C" fn lugre_loop_new(
    model: *const LugreModel,
    u: *const f64,
    n: usize,
    out: *mut *mut LugreLoop,
) -> LugreStatus {
    guard(|| {
        let m = handle(model, "model")?;
        let tp = TurningPoints::new(input(u, n, "u")?)?;
        let hl = HysteresisLoop::new(m.rate_independent(), &tp)?;
        set_out(out, LugreLoop { hl })
    })
}

#[no_mangle]
pub extern "C" fn lugre_loop_free(hl: *mut LugreLoop) {
    free(hl)
}

/// The number of turning points of the loop (repeated values and points where the input keeps
/// its direction are dropped: at most the `n` given).
#[no_mangle]
pub extern "C" fn lugre_loop_turning_len(hl: *const LugreLoop, len: *mut usize) -> LugreStatus {
    guard(|| {
        *handle_mut(len, "len")? = handle(hl, "loop")?.hl.turning_points().len();
        Ok(())
    })
}

/// The turning points: `u`, the total variation `rho` there and `y°` (any pointer may be NULL).
#[no_mangle]
pub extern "C" fn lugre_loop_turning(
    hl: *const LugreLoop,
    u: *mut f64,
    rho: *mut f64,
    y: *mut f64,
    cap: usize,
) -> LugreStatus {
    guard(|| {
        let hl = &handle(hl, "loop")?.hl;
        capacity(hl.turning_points().len(), cap)?;
        output(u, hl.turning_points());
        output(rho, hl.turning_rho());
        output(y, hl.turning_y());
        Ok(())
    })
}

/// The work per period (all of it dissipated), the period and `g(0)`.
#[no_mangle]
pub extern "C" fn lugre_loop_summary(
    hl: *const LugreLoop,
    work_per_period: *mut f64,
    period: *mut f64,
) -> LugreStatus {
    guard(|| {
        let hl = &handle(hl, "loop")?.hl;
        output(work_per_period, &[hl.work_per_period()]);
        output(period, &[hl.period()]);
        Ok(())
    })
}

/// The number of loops (the major loop and every minor loop).
#[no_mangle]
pub extern "C" fn lugre_loop_table_len(hl: *const LugreLoop, len: *mut usize) -> LugreStatus {
    guard(|| {
        *handle_mut(len, "len")? = handle(hl, "loop")?.hl.loops().len();
        Ok(())
    })
}

/// Every loop, in the order of `lugre loop --json`'s `loops`.
#[no_mangle]
pub extern "C" fn lugre_loop_table(
    hl: *const LugreLoop,
    columns: *const LugreLoopColumns,
    cap: usize,
) -> LugreStatus {
    guard(|| {
        let loops = handle(hl, "loop")?.hl.loops();
        let c = handle(columns, "columns")?;
        capacity(loops.len(), cap)?;
        let col = |f: &dyn Fn(&lugre::Loop) -> f64| loops.iter().map(f).collect::<Vec<f64>>();
        let kinds: Vec<i32> = loops
            .iter()
            .map(|l| i32::from(l.kind != LoopKind::Major))
            .collect();
        output(c.kind, &kinds);
        output(c.start_rho, &col(&|l| l.start.rho));
        output(c.start_u, &col(&|l| l.start.u));
        output(c.start_y, &col(&|l| l.start.y));
        output(c.reversal_rho, &col(&|l| l.reversal.rho));
        output(c.reversal_u, &col(&|l| l.reversal.u));
        output(c.reversal_y, &col(&|l| l.reversal.y));
        output(c.end_rho, &col(&|l| l.end.rho));
        output(c.end_u, &col(&|l| l.end.u));
        output(c.end_y, &col(&|l| l.end.y));
        output(c.work, &col(&|l| l.energy.work));
        output(
            c.stored_energy_change,
            &col(&|l| l.energy.stored_energy_change),
        );
        output(c.dissipation, &col(&|l| l.energy.dissipation));
        output(c.closure_gap, &col(&|l| l.energy.closure_gap));
        let parent: Vec<i64> = loops
            .iter()
            .map(|l| l.parent.map_or(-1, |p| p as i64))
            .collect();
        output(c.parent, &parent);
        let depth: Vec<i64> = loops.iter().map(|l| l.depth as i64).collect();
        output(c.depth, &depth);
        Ok(())
    })
}

/// `y°` sampled at `n` points evenly spaced in `rho` over one period (`rho`, `u`, `y`; any
/// pointer may be NULL).
#[no_mangle]
pub extern "C" fn lugre_loop_sample(
    hl: *const LugreLoop,
    n: usize,
    rho: *mut f64,
    u: *mut f64,
    y: *mut f64,
) -> LugreStatus {
    guard(|| {
        let points = handle(hl, "loop")?.hl.sample(n);
        output(rho, &points.iter().map(|p| p.rho).collect::<Vec<_>>());
        output(u, &points.iter().map(|p| p.u).collect::<Vec<_>>());
        output(y, &points.iter().map(|p| p.y).collect::<Vec<_>>());
        Ok(())
    })
}

/// The rainflow cycles (ASTM E1049, as `lugre cycles`) of the history `u[0..n]` with noise gate
/// `gate` (0: none); with a model (non-NULL), the energy of each full cycle along `y*` from
/// the initial deflection `x0`.
#[no_mangle]
pub extern "C" fn lugre_cycles_new(
    u: *const f64,
    n: usize,
    gate: f64,
    model: *const LugreModel,
    x0: f64,
    out: *mut *mut LugreCycles,
) -> LugreStatus {
    guard(|| {
        let u = input(u, n, "u")?;
        // SAFETY: NULL or a handle made by this library.
        let model = unsafe { model.as_ref() };
        let mut columns = CycleColumns::new()
            .with_reversals(false)
            .with_closures(true)
            .with_energy(model.is_some());
        match model {
            Some(m) => {
                let mut counter = EnergyCycleCounter::new(gate, m.rate_independent(), x0)?;
                counter.push_all(u, &mut columns)?;
                counter.finish(&mut columns)?;
            }
            None => {
                let mut counter = CycleCounter::new(gate)?;
                counter.push_all(u, &mut columns)?;
                counter.finish(&mut columns)?;
            }
        }
        set_out(out, LugreCycles { columns })
    })
}

#[no_mangle]
pub extern "C" fn lugre_cycles_free(cycles: *mut LugreCycles) {
    free(cycles)
}

/// The number of cycles (full and half).
#[no_mangle]
pub extern "C" fn lugre_cycles_len(cycles: *const LugreCycles, len: *mut usize) -> LugreStatus {
    guard(|| {
        *handle_mut(len, "len")? = handle(cycles, "cycles")?.columns.len();
        Ok(())
    })
}

/// The cycles as columns, in the order they close (as `lugre cycles`).
#[no_mangle]
pub extern "C" fn lugre_cycles_columns(
    cycles: *const LugreCycles,
    columns: *const LugreCycleColumns,
    cap: usize,
) -> LugreStatus {
    guard(|| {
        let c = &handle(cycles, "cycles")?.columns;
        let out = handle(columns, "columns")?;
        capacity(c.len(), cap)?;
        output(out.range, &c.range);
        output(out.mean, &c.mean);
        output(out.count, &c.count);
        output(out.start, &c.start);
        output(out.end, &c.end);
        output(out.closure, &c.closure);
        // The core marks "none" with NaN (half cycles, no model); C gets 0 there: `count` and
        // `closure` say which rows are full cycles.
        let defined = |v: &[f64]| -> Vec<f64> {
            (0..c.len())
                .map(|i| v.get(i).copied().filter(|x| x.is_finite()).unwrap_or(0.0))
                .collect()
        };
        output(out.closure_position, &defined(&c.closure_position));
        output(out.work, &defined(&c.work));
        output(out.stored_energy_change, &defined(&c.stored_energy_change));
        output(out.dissipation, &defined(&c.dissipation));
        output(out.closure_gap, &defined(&c.closure_gap));
        Ok(())
    })
}

/// The exact response to the displacement `x(t)` given at `n >= 2` strictly increasing times,
/// linear in between (as `lugre simulate --input` at its knots, gamma = 1): the bristle
/// deflection `z` and the friction force `F` at every knot (the value just after the kink; at
/// the last knot the value with the last segment's velocity), from `z(t[0]) = z0`.
#[no_mangle]
pub extern "C" fn lugre_simulate(
    model: *const LugreModel,
    t: *const f64,
    x: *const f64,
    n: usize,
    z0: f64,
    z_out: *mut f64,
    force_out: *mut f64,
) -> LugreStatus {
    guard(|| {
        let m = handle(model, "model")?;
        let input = PiecewiseLinear::new(input(t, n, "t")?.to_vec(), input(x, n, "x")?.to_vec())?;
        let mut out = Trajectory::with_capacity(n);
        Simulator::new(&m.model, Gamma::ONE, z0)?.at_knots(&input, 1, &mut out)?;
        output(z_out, &out.z);
        output(force_out, &out.y);
        Ok(())
    })
}

/// A friction element at rest at displacement 0 with bristle deflection `z0`, for a host that
/// advances it step by step ([`lugre_element_step`]).
#[no_mangle]
pub extern "C" fn lugre_element_new(
    model: *const LugreModel,
    z0: f64,
    out: *mut *mut LugreElement,
) -> LugreStatus {
    guard(|| {
        let m = handle(model, "model")?;
        let element = FrictionElement::new(m.model.clone(), z0)?;
        set_out(out, LugreElement { element })
    })
}

#[no_mangle]
pub extern "C" fn lugre_element_free(element: *mut LugreElement) {
    free(element)
}

/// Moves the relative displacement to `x` over the next `dt >= 0` seconds (linearly in time:
/// exact at any stiffness) and writes the friction force at the step's end to `force` (may be
/// NULL). A failed step leaves the element as it was.
#[no_mangle]
pub extern "C" fn lugre_element_step(
    element: *mut LugreElement,
    x: f64,
    dt: f64,
    force: *mut f64,
) -> LugreStatus {
    guard(|| {
        let e = handle_mut(element, "element")?;
        let s = e.element.step(x, dt)?;
        output(force, &[s.y]);
        Ok(())
    })
}

/// The element's time, displacement, bristle deflection `z` and friction force (any pointer
/// may be NULL).
#[no_mangle]
pub extern "C" fn lugre_element_state(
    element: *const LugreElement,
    t: *mut f64,
    x: *mut f64,
    z: *mut f64,
    force: *mut f64,
) -> LugreStatus {
    guard(|| {
        let s = handle(element, "element")?.element.sample();
        output(t, &[s.t]);
        output(x, &[s.u]);
        output(z, &[s.z]);
        output(force, &[s.y]);
        Ok(())
    })
}

/// At rest at time `t`, displacement `x`, deflection `z0` (the new reset point).
#[no_mangle]
pub extern "C" fn lugre_element_reset(
    element: *mut LugreElement,
    t: f64,
    x: f64,
    z0: f64,
) -> LugreStatus {
    guard(|| {
        handle_mut(element, "element")?.element.reset_to(t, x, z0)?;
        Ok(())
    })
}

/// One of the experiments of Canudas de Wit et al. (1995) (`lugre dynamics --scenario NAME`:
/// "presliding", "breakaway" (10 N/s), "stick-slip", "lag", "pid"), with Table I and a 1 kg
/// mass, at relative tolerance `rtol` (0: the default 1e-8), reported at the `n` times
/// (strictly increasing, within the scenario's run): position, velocity, bristle deflection and
/// friction force (any output may be NULL).
#[no_mangle]
pub extern "C" fn lugre_dynamics_scenario(
    name: *const c_char,
    rtol: f64,
    times: *const f64,
    n: usize,
    x: *mut f64,
    v: *mut f64,
    z: *mut f64,
    friction: *mut f64,
) -> LugreStatus {
    guard(|| {
        if name.is_null() {
            return Err(fail(LugreStatus::NullPointer, "name is NULL"));
        }
        // SAFETY: a NUL-terminated string from the caller.
        let name = unsafe { CStr::from_ptr(name) }.to_string_lossy();
        let scenario = Scenario::from_name(&name, None, None).ok_or_else(|| {
            fail(
                LugreStatus::InvalidArgument,
                format!(
                    "unknown scenario '{name}' (scenarios: {})",
                    Scenario::NAMES.join(", ")
                ),
            )
        })?;
        let times = input(times, n, "times")?;
        let model = LuGre::from_params(LuGreParams::canudas_de_wit_1995())?;
        let setup = scenario.setup(model, 1.0)?;
        let tol = Tolerances::new(
            if rtol == 0.0 {
                Tolerances::DEFAULT_RTOL
            } else {
                rtol
            },
            None,
        )?;
        let m = setup.system.solve(setup.t_end, times, tol)?;
        output(x, &m.x);
        output(v, &m.v);
        output(z, &m.z);
        output(friction, &m.friction);
        Ok(())
    })
}
