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
//! `sigma2` in N s/m, `vs` in m/s, Dahl's `rho` in 1/m. The parameters' names, order, units
//! and descriptions are the core's table ([`lugre::model::Parameter`]; the header's
//! `LugreParams` is checked against it by `tests/header.rs`).
//!
//! Indices in inputs and outputs (cycle starts, closures, a loop's parent) are 0-based, as in
//! C; the MEX gateway adds 1 for MATLAB.

// The entry points are called from C, where Rust's `unsafe` means nothing: the pointer contract
// is the module documentation's, and every pointer is checked for NULL before use.
#![allow(clippy::not_unsafe_ptr_arg_deref)]

use std::cell::RefCell;
use std::ffi::{c_char, CStr, CString};
use std::panic::{catch_unwind, AssertUnwindSafe};

use std::sync::OnceLock;

mod dynamics;
mod zoo;
mod zoo_fit;
pub use dynamics::{
    lugre_dynamics_free, lugre_dynamics_new, lugre_dynamics_run, lugre_dynamics_set,
    lugre_dynamics_set_model, lugre_dynamics_set_points, lugre_dynamics_set_scenario,
    lugre_dynamics_set_zoo, lugre_motion_columns, lugre_motion_free, lugre_motion_len,
    lugre_motion_loop, lugre_motion_summary, LugreDynamics, LugreFrictionLoop, LugreMotion,
    LugreMotionSummary,
};
pub use zoo::{
    lugre_zoo_cycles_new, lugre_zoo_free, lugre_zoo_loop_new, lugre_zoo_model_info,
    lugre_zoo_model_name, lugre_zoo_new, lugre_zoo_parameter, lugre_zoo_simulate, lugre_zoo_value,
    LugreZoo, LugreZooModelInfo, LugreZooParameter, LUGRE_ZOO_ELEMENTS, LUGRE_ZOO_SCALAR,
};
pub use zoo_fit::{
    lugre_zoo_fit, lugre_zoo_fit_estimate, lugre_zoo_fit_free, lugre_zoo_fit_full,
    lugre_zoo_fit_model, lugre_zoo_fit_summary, LugreZooEstimate, LugreZooFit, LugreZooFitSummary,
};

use lugre::fit::{fit_full, fit_slow, Family, FitReport, FitSpec, FullOptions};
use lugre::model::named::{check_named, Needed};
use lugre::model::Parameter;
use lugre::simulate::FrictionElement;
use lugre::{
    CycleColumns, CycleCounter, Dahl, Gamma, HysteresisLoop, LoopKind, LuGre, LuGreParams,
    PiecewiseLinear, Simulator, Trajectory, TurningPoints,
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

/// The parameters of a LuGre model (SI units; see [`lugre_params_default`]): the core's
/// [`LuGreParams`], a `#[repr(C)]` struct of the table's parameters ([`Parameter::LUGRE`]) in
/// its order. The header's `typedef struct LugreParams` is written from the table by
/// `tests/header.rs`; [`lugre_params_set`] sets a field by name.
pub use lugre::LuGreParams as LugreParams;

// The header declares the struct as `double`s only, one per parameter of the table.
const _: () = assert!(
    std::mem::size_of::<LugreParams>() == Parameter::LUGRE.len() * std::mem::size_of::<f64>()
        && std::mem::align_of::<LugreParams>() == std::mem::align_of::<f64>(),
    "LuGreParams is not the table's parameters as doubles"
);

/// A validated friction model (LuGre, or Dahl as the LuGre model it equals).
pub struct LugreModel {
    model: LuGre,
    /// Dahl's rate-independent limit differs from its LuGre form's only in name; kept for it.
    dahl: Option<Dahl>,
}

/// The periodic hysteresis loop of one input: LuGre's or Dahl's ([`lugre_loop_new`]) or a
/// model of the zoo's ([`lugre_zoo_loop_new`]); the `lugre_loop_*` accessors serve both.
pub struct LugreLoop {
    inner: Periodic,
}

/// What a [`LugreLoop`] holds.
enum Periodic {
    LuGre(HysteresisLoop),
    /// The model is kept: the loop's points between turning points are walked on it.
    Zoo(Box<(lugre::zoo::ZooModel, lugre::zoo::ZooLoop)>),
}

impl LugreLoop {
    /// The turning points `u`, `rho` there and the output there.
    fn turning(&self) -> [&[f64]; 3] {
        match &self.inner {
            Periodic::LuGre(hl) => [hl.turning_points(), hl.turning_rho(), hl.turning_y()],
            Periodic::Zoo(z) => [z.1.turning_points(), z.1.turning_rho(), z.1.turning_force()],
        }
    }

    /// The work per period and the period.
    fn summary(&self) -> [f64; 2] {
        match &self.inner {
            Periodic::LuGre(hl) => [hl.work_per_period(), hl.period()],
            Periodic::Zoo(z) => [z.1.work_per_period(), z.1.period()],
        }
    }

    /// Every loop with its energies (LuGre's are made on demand, the zoo's are kept).
    fn loops(&self) -> std::borrow::Cow<'_, [lugre::Loop]> {
        match &self.inner {
            Periodic::LuGre(hl) => hl.loops().into(),
            Periodic::Zoo(z) => z.1.loops().into(),
        }
    }

    fn sample(&self, n: usize) -> Result<Vec<lugre::LoopPoint>, lugre::SamplesError> {
        match &self.inner {
            Periodic::LuGre(hl) => hl.try_sample(n),
            Periodic::Zoo(z) => z.0.sample(&z.1, n),
        }
    }
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

/// `n` input values at `p` as given, or a failure if `p` is NULL.
fn values<'a>(p: *const f64, n: usize, name: &str) -> Result<&'a [f64], Failure> {
    if n == 0 {
        return Ok(&[]);
    }
    if p.is_null() {
        return Err(fail(LugreStatus::NullPointer, format!("{name} is NULL")));
    }
    // SAFETY: the caller guarantees `n` readable values at `p`.
    Ok(unsafe { std::slice::from_raw_parts(p, n) })
}

/// `n` input values at `p` (checked finite, with the library's message), or a failure naming
/// them.
fn input<'a>(p: *const f64, n: usize, name: &'static str) -> Result<&'a [f64], Failure> {
    let values = values(p, n, name)?;
    lugre::input::check_finite(name, values)?;
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
        *p = LuGreParams::canudas_de_wit_1995();
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
        let model = LuGre::from_params(*handle(params, "params")?)?;
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

/// A model of `family` (`LUGRE_FAMILY_LUGRE` or `LUGRE_FAMILY_DAHL`) from `count` parameters
/// given by name (`names[i]` is `values[i]`; case-insensitive, each once), the others at the
/// core's defaults ([`lugre_parameter_name`] lists a family's names): the way to make a model
/// of either family without knowing its parameters in advance (the MEX gateway's Dahl models).
#[no_mangle]
pub extern "C" fn lugre_model_new_named(
    family: i32,
    count: usize,
    names: *const *const c_char,
    values: *const f64,
    out: *mut *mut LugreModel,
) -> LugreStatus {
    guard(|| {
        let table = family_parameters(family)?;
        let mut given: Vec<Option<f64>> = vec![None; table.len()];
        let vs = self::values(values, count, "values")?;
        if count > 0 && names.is_null() {
            return Err(fail(LugreStatus::NullPointer, "names is NULL"));
        }
        for (i, &v) in vs.iter().enumerate() {
            // SAFETY: the caller guarantees `count` readable pointers at `names` (not NULL).
            let p = unsafe { *names.add(i) };
            let item = format!("names[{i}]");
            let name = text(p, &item)?
                .ok_or_else(|| fail(LugreStatus::NullPointer, format!("{item} is NULL")))?;
            // The fit's lookup: its message is the CLI's and Python's for an unknown name.
            let k = family_of(family).index(&name)?;
            if given[k].replace(v).is_some() {
                return Err(fail(
                    LugreStatus::InvalidArgument,
                    format!("{item} gives {} a second time", table[k]),
                ));
            }
        }
        let value = |p: Parameter| {
            let k = table.iter().position(|&q| q == p);
            k.and_then(|k| given[k]).unwrap_or(p.default_value())
        };
        let model = if family == LUGRE_FAMILY_DAHL {
            let dahl = Dahl::new(value(Parameter::Rho), value(Parameter::Fc))?;
            LugreModel {
                model: dahl.to_lugre(),
                dahl: Some(dahl),
            }
        } else {
            let mut p = LuGreParams::default();
            for &q in table {
                p.set(q, value(q));
            }
            LugreModel {
                model: LuGre::from_params(p)?,
                dahl: None,
            }
        };
        set_out(out, model)
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
        set_out(
            out,
            LugreLoop {
                inner: Periodic::LuGre(hl),
            },
        )
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
        *handle_mut(len, "len")? = handle(hl, "loop")?.turning()[0].len();
        Ok(())
    })
}

/// The turning points: `u`, the total variation `rho` there and `y°` (a model of the zoo: its
/// force) there (any pointer may be NULL).
#[no_mangle]
pub extern "C" fn lugre_loop_turning(
    hl: *const LugreLoop,
    u: *mut f64,
    rho: *mut f64,
    y: *mut f64,
    cap: usize,
) -> LugreStatus {
    guard(|| {
        let [tu, trho, ty] = handle(hl, "loop")?.turning();
        capacity(tu.len(), cap)?;
        output(u, tu);
        output(rho, trho);
        output(y, ty);
        Ok(())
    })
}

/// The work per period (LuGre's and Dahl's all dissipated; a model of the zoo's as its major
/// loop's `work`) and the period (in `rho`, the input's total variation over one period);
/// either pointer may be NULL.
#[no_mangle]
pub extern "C" fn lugre_loop_summary(
    hl: *const LugreLoop,
    work_per_period: *mut f64,
    period: *mut f64,
) -> LugreStatus {
    guard(|| {
        let [work, p] = handle(hl, "loop")?.summary();
        output(work_per_period, &[work]);
        output(period, &[p]);
        Ok(())
    })
}

/// The number of loops (the major loop and every minor loop).
#[no_mangle]
pub extern "C" fn lugre_loop_table_len(hl: *const LugreLoop, len: *mut usize) -> LugreStatus {
    guard(|| {
        *handle_mut(len, "len")? = handle(hl, "loop")?.loops().len();
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
        let loops = handle(hl, "loop")?.loops();
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

/// `y°` (a model of the zoo: its force) at `n >= 2` points evenly spaced in `rho` over one
/// period, both ends included (`rho = 0` and the period): `rho`, the input `u` and the output
/// there, each written to a buffer
/// of `n` (any pointer may be NULL). `n < 2` is an error (a period has two ends).
#[no_mangle]
pub extern "C" fn lugre_loop_sample(
    hl: *const LugreLoop,
    n: usize,
    rho: *mut f64,
    u: *mut f64,
    y: *mut f64,
) -> LugreStatus {
    guard(|| {
        let points = handle(hl, "loop")?
            .sample(n)
            .map_err(|e| fail(LugreStatus::InvalidArgument, e.render("n")))?;
        let column = |f: fn(&lugre::LoopPoint) -> f64| points.iter().map(f).collect::<Vec<_>>();
        output(rho, &column(|p| p.rho));
        output(u, &column(|p| p.u));
        output(y, &column(|p| p.y));
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
        let model = model.map(|m| m.rate_independent());
        let mut counter = CycleCounter::new(gate)?.with_energy(model, x0)?;
        counter.push_all(u, &mut columns)?;
        counter.finish(&mut columns)?;
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

/// The columns of a row of [`lugre_sweep`]'s table, in order: amplitude, frequency,
/// dissipation, work, stored_energy_change, peak_force, stiffness, damping, gain, phase (rad),
/// a1, b1 (`lugre::sweep::COLUMNS`).
pub const LUGRE_SWEEP_COLUMNS: usize = 12;
const _: () = assert!(LUGRE_SWEEP_COLUMNS == lugre::sweep::COLUMNS.len());

/// The name of column `index` of [`lugre_sweep`]'s table ("amplitude", "frequency", ...;
/// static, the core's names), or NULL past the last column.
#[no_mangle]
pub extern "C" fn lugre_sweep_column(index: usize) -> *const c_char {
    static NAMES: std::sync::OnceLock<Vec<CString>> = std::sync::OnceLock::new();
    let names = NAMES.get_or_init(|| {
        lugre::sweep::COLUMNS
            .iter()
            .map(|n| CString::new(*n).expect("no NUL in a column name"))
            .collect()
    });
    names.get(index).map_or(std::ptr::null(), |n| n.as_ptr())
}

/// The periodic steady state under `u = offset + A sin(2 pi f t)` for every amplitude with
/// every frequency (as `lugre sweep`): the fixed point of the period map, in parallel on all
/// cores. Row `i n_frequencies + j` of `table` (row-major, [`LUGRE_SWEEP_COLUMNS`] doubles a
/// row) is `amplitudes[i]` with `frequencies[j]`; `table` holds `rows` rows (at least
/// `n_amplitudes n_frequencies`). `tol` is the integrator's relative tolerance (0: the default
/// 1e-12).
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn lugre_sweep(
    model: *const LugreModel,
    amplitudes: *const f64,
    n_amplitudes: usize,
    frequencies: *const f64,
    n_frequencies: usize,
    offset: f64,
    tol: f64,
    table: *mut f64,
    rows: usize,
) -> LugreStatus {
    guard(|| {
        let m = handle(model, "model")?;
        // As given: the core judges every value (`amplitudes: amplitude must be a finite
        // number > 0, got NaN`, as every front end says it).
        let a = values(amplitudes, n_amplitudes, "amplitudes")?.to_vec();
        let f = values(frequencies, n_frequencies, "frequencies")?.to_vec();
        let named = |name: &str, e: lugre::SweepError| {
            fail(LugreStatus::InvalidArgument, format!("{name}: {e}"))
        };
        let mut r = lugre::sweep::Request::new(a, f).map_err(|e| match e {
            lugre::SweepError::NotPositive {
                what: "frequency", ..
            } => named("frequencies", e),
            lugre::SweepError::NotPositive { .. } => named("amplitudes", e),
            e => e.into(),
        })?;
        r = r.with_offset(offset).map_err(|e| named("offset", e))?;
        if tol != 0.0 {
            r = r.with_tolerance(
                lugre::Tolerance::new(tol)
                    .map_err(|e| fail(LugreStatus::InvalidArgument, format!("tol: {e}")))?,
            );
        }
        capacity(r.points(), rows)?;
        if table.is_null() {
            return Err(fail(LugreStatus::NullPointer, "table is NULL"));
        }
        let sweep = r.run(&m.model, None)?;
        let flat: Vec<f64> = sweep.points.iter().flat_map(|p| p.values()).collect();
        output(table, &flat);
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
/// NULL). A failed step leaves the element as it was; a step whose end time is not a finite
/// number is refused.
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
/// (strictly increasing; the run ends at the last): position, velocity, bristle deflection and
/// friction force (any output may be NULL). The shorthand of a request naming the scenario,
/// the times and the tolerance ([`lugre_dynamics_new`] for every other field).
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
        let name =
            text(name, "name")?.ok_or_else(|| fail(LugreStatus::NullPointer, "name is NULL"))?;
        let times = input(times, n, "times")?;
        let mut request = lugre::dynamics::Request::new()
            .with_scenario(dynamics::scenario_named(&name)?)
            .with_times(times.to_vec())?;
        if rtol != 0.0 {
            request = request.with_rtol(rtol)?;
        }
        // The columns alone: the motion without the ramp's break-away or the loops.
        let m = request.build()?.motion()?;
        output(x, &m.x);
        output(v, &m.v);
        output(z, &m.z);
        output(friction, &m.friction);
        Ok(())
    })
}

/// The LuGre family of [`lugre_parameter_name`] and [`LugreFitResult::family`].
pub const LUGRE_FAMILY_LUGRE: i32 = 0;
/// The Dahl family.
pub const LUGRE_FAMILY_DAHL: i32 = 1;
/// The most parameters a family has in the core's table (LuGre's): the length of the fit's
/// arrays. The header's `#define` is written from the table by `tests/header.rs`.
pub const LUGRE_MAX_PARAMETERS: usize = if Parameter::LUGRE.len() > Parameter::DAHL.len() {
    Parameter::LUGRE.len()
} else {
    Parameter::DAHL.len()
};

/// A C string argument (NULL: `None`), or a failure naming it.
fn text<'a>(p: *const c_char, name: &str) -> Result<Option<std::borrow::Cow<'a, str>>, Failure> {
    if p.is_null() {
        return Ok(None);
    }
    // SAFETY: a NUL-terminated string from the caller.
    let bytes = unsafe { CStr::from_ptr(p) };
    match bytes.to_str() {
        Ok(s) => Ok(Some(s.into())),
        Err(_) => Err(fail(
            LugreStatus::InvalidArgument,
            format!("{name} is not UTF-8 text"),
        )),
    }
}

/// The parameters of a family, in the core's order.
fn family_parameters(family: i32) -> Result<&'static [Parameter], Failure> {
    match family {
        LUGRE_FAMILY_LUGRE => Ok(&Parameter::LUGRE),
        LUGRE_FAMILY_DAHL => Ok(&Parameter::DAHL),
        _ => Err(fail(
            LugreStatus::InvalidArgument,
            format!(
                "family must be LUGRE_FAMILY_LUGRE ({LUGRE_FAMILY_LUGRE}) or LUGRE_FAMILY_DAHL ({LUGRE_FAMILY_DAHL}), got {family}"
            ),
        )),
    }
}

/// The core's family of a checked family number.
fn family_of(family: i32) -> Family {
    if family == LUGRE_FAMILY_DAHL {
        Family::Dahl
    } else {
        Family::LuGre
    }
}

/// The parameter names as C strings, made once from the core's table.
fn c_name(p: Parameter) -> *const c_char {
    static NAMES: OnceLock<Vec<(Parameter, CString)>> = OnceLock::new();
    let names = NAMES.get_or_init(|| {
        let all = Parameter::LUGRE.iter().chain(&Parameter::DAHL);
        all.map(|&q| (q, CString::new(q.name()).unwrap_or_default()))
            .collect()
    });
    names
        .iter()
        .find(|(q, _)| *q == p)
        .map_or(std::ptr::null(), |(_, c)| c.as_ptr())
}

/// The name of parameter `index` of `family` (`LUGRE_FAMILY_LUGRE`: sigma0, sigma1, sigma2,
/// fc, fs, vs, beta, the order of [`LugreParams`] and of the fit's arrays;
/// `LUGRE_FAMILY_DAHL`: rho, fc), a static string, to `name`.
#[no_mangle]
pub extern "C" fn lugre_parameter_name(
    family: i32,
    index: usize,
    name: *mut *const c_char,
) -> LugreStatus {
    guard(|| {
        let out = handle_mut(name, "name")?;
        let ps = family_parameters(family)?;
        let p = ps.get(index).ok_or_else(|| {
            fail(
                LugreStatus::InvalidArgument,
                format!("index must be below {}, got {index}", ps.len()),
            )
        })?;
        *out = c_name(*p);
        Ok(())
    })
}

/// Sets the LuGre parameter called `name` (case-insensitive, as the CLI's flags) to `value`
/// (checked when a model is made of the parameters, by [`lugre_model_new`]).
#[no_mangle]
pub extern "C" fn lugre_params_set(
    params: *mut LugreParams,
    name: *const c_char,
    value: f64,
) -> LugreStatus {
    guard(|| {
        let p = handle_mut(params, "params")?;
        let given =
            text(name, "name")?.ok_or_else(|| fail(LugreStatus::NullPointer, "name is NULL"))?;
        // The fit's lookup: its message is the CLI's and Python's for an unknown name.
        let q = Parameter::LUGRE[Family::LuGre.index(&given)?];
        p.set(q, value);
        Ok(())
    })
}

/// [`lugre_params_check_named`]: every parameter is used (a simulation of a physical system).
pub const LUGRE_NEEDED_ALL: i32 = 0;
/// [`lugre_params_check_named`]: those of the rate-independent loop (energies along `y*`).
pub const LUGRE_NEEDED_RATE_INDEPENDENT: i32 = 1;

/// The core's named-model rule for a front end that sets LuGre parameters one by one by name
/// (as the MEX gateway's struct fields): `given` lists the names set, separated by commas
/// (NULL or "": none). Fails (`LUGRE_STATUS_INVALID_ARGUMENT`) when a parameter that `needed`
/// (`LUGRE_NEEDED_ALL` or `LUGRE_NEEDED_RATE_INDEPENDENT`) uses was not given and its default
/// is not an absence (forces and energies of a measured or physical system are not computed
/// from the dimensionless defaults). A preset (`lugre_params_canudas1995`) names every
/// parameter: do not call this then.
#[no_mangle]
pub extern "C" fn lugre_params_check_named(needed: i32, given: *const c_char) -> LugreStatus {
    guard(|| {
        let needed = match needed {
            LUGRE_NEEDED_ALL => Needed::All,
            LUGRE_NEEDED_RATE_INDEPENDENT => Needed::RateIndependent,
            _ => {
                return Err(fail(
                    LugreStatus::InvalidArgument,
                    format!("needed must be LUGRE_NEEDED_ALL ({LUGRE_NEEDED_ALL}) or LUGRE_NEEDED_RATE_INDEPENDENT ({LUGRE_NEEDED_RATE_INDEPENDENT}), got {needed}"),
                ))
            }
        };
        let given = text(given, "given")?.unwrap_or_default();
        let mut named = Vec::new();
        for name in given.split(',').map(str::trim).filter(|n| !n.is_empty()) {
            named.push(Parameter::LUGRE[Family::LuGre.index(name)?]);
        }
        check_named(&Parameter::LUGRE, needed, |p| named.contains(&p)).map_err(|e| {
            fail(
                LugreStatus::InvalidArgument,
                e.render(|p| p.name().to_string(), "preset 'canudas1995'"),
            )
        })
    })
}

/// How to fit (all zero, [`lugre_fit_options_default`]: the defaults).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct LugreFitOptions {
    /// `LUGRE_FAMILY_LUGRE` (0) or `LUGRE_FAMILY_DAHL`: the model fitted when `model` is
    /// NULL (a model's own family must be this one).
    pub family: i32,
    /// The values the parameters that are not fitted keep: a LuGre model
    /// ([`lugre_model_new`]) or a Dahl model ([`lugre_model_new_dahl`]); NULL: no values given
    /// (a parameter the fit holds must then have one: give a model). Free parameters start
    /// from the data either way.
    pub model: *const LugreModel,
    /// The names of parameters held at the model's values, separated by commas (NULL or "":
    /// none), e.g. "sigma2" (a parameter whose value is 0 must be held: fitted ones are
    /// positive).
    pub fix: *const c_char,
    /// Names fitted besides the default ones, e.g. "beta" in a full fit (NULL or "": none).
    pub free: *const c_char,
    /// The initial bristle deflection `x(0)` (Dahl: `w(0) / rho`), full fit only.
    pub x0: f64,
    /// Start points of the full fit (0: the default, 3).
    pub starts: usize,
}

/// The fitted parameters with their standard errors and the fit's statistics (as
/// `lugre fit --json`). The arrays hold the family's parameters in the order of
/// [`lugre_parameter_name`] (`parameters` of them; 0 after).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct LugreFitResult {
    /// `LUGRE_FAMILY_LUGRE` or `LUGRE_FAMILY_DAHL`.
    pub family: i32,
    /// The family's number of parameters (7 or 2).
    pub parameters: usize,
    /// Every parameter of the fitted model: the estimates and the values held (for a slow
    /// LuGre fit, the parameters the loop does not depend on keep the model's values).
    pub value: [f64; LUGRE_MAX_PARAMETERS],
    /// 1 where the parameter was fitted, 0 where it was held.
    pub fitted: [i32; LUGRE_MAX_PARAMETERS],
    /// The standard error of each fitted parameter (linearised covariance; 0 if held).
    pub std_error: [f64; LUGRE_MAX_PARAMETERS],
    /// The 95 % confidence interval of each fitted parameter (the value if held).
    pub ci95_lo: [f64; LUGRE_MAX_PARAMETERS],
    pub ci95_hi: [f64; LUGRE_MAX_PARAMETERS],
    /// 1 where the estimate sits on one of its bounds.
    pub at_bound: [i32; LUGRE_MAX_PARAMETERS],
    /// The residual RMS.
    pub rms: f64,
    pub samples: usize,
    /// Degrees of freedom, samples - fitted parameters.
    pub dof: usize,
    /// The factor of the 95 % intervals, Student's t on `dof`.
    pub t_quantile: f64,
    /// Of the scaled normal matrix.
    pub condition_number: f64,
    pub iterations: usize,
    pub evaluations: usize,
    pub starts: usize,
    /// 0: the fit ran out of evaluations at a usable point, reported (the CLI warns).
    pub converged: i32,
    /// The turning points a slow fit found in the record (0 for a full fit).
    pub turning_points: usize,
}

/// The default options: no model (LuGre), nothing fixed or freed, `x0 = 0`, the default
/// number of starts.
#[no_mangle]
pub extern "C" fn lugre_fit_options_default(out: *mut LugreFitOptions) -> LugreStatus {
    guard(|| {
        *handle_mut(out, "out")? = options_or_default(std::ptr::null());
        Ok(())
    })
}

/// The request as `lugre fit` builds it from its model flags, `--fix` and `--free`.
fn fit_spec(o: &LugreFitOptions) -> Result<FitSpec, Failure> {
    let family = match o.family {
        LUGRE_FAMILY_DAHL => Family::Dahl,
        _ => {
            // Names the option in the message of an unknown family.
            family_parameters(o.family)
                .map_err(|Failure(status, m)| Failure(status, format!("options.{m}")))?;
            Family::LuGre
        }
    };
    // SAFETY: NULL or a handle made by this library.
    let mut spec = match unsafe { o.model.as_ref() } {
        None => FitSpec::new(family),
        Some(LugreModel { dahl: Some(d), .. }) => FitSpec::dahl(d.rho(), d.fc()),
        Some(m) => FitSpec::lugre(m.model.params()),
    };
    if spec.family() != family {
        return Err(fail(
            LugreStatus::InvalidArgument,
            format!(
                "options.model is a {} model, options.family says {}",
                spec.family().label(),
                family.label()
            ),
        ));
    }
    type Mark = fn(FitSpec, &str) -> Result<FitSpec, lugre::fit::FitError>;
    let lists: [(&str, *const c_char, Mark); 2] = [
        ("options.fix", o.fix, FitSpec::fix),
        ("options.free", o.free, FitSpec::free),
    ];
    for (arg, list, mark) in lists {
        for name in names(list, arg)? {
            spec = mark(spec, &name)
                .map_err(|e| fail(LugreStatus::InvalidArgument, format!("{arg}: {e}")))?;
        }
    }
    Ok(spec)
}

/// The names of a comma-separated list (blanks around them ignored, empty entries refused).
fn names(p: *const c_char, arg: &str) -> Result<Vec<String>, Failure> {
    let Some(list) = text(p, arg)? else {
        return Ok(Vec::new());
    };
    if list.trim().is_empty() {
        return Ok(Vec::new());
    }
    list.split(',')
        .map(|n| match n.trim() {
            "" => Err(fail(
                LugreStatus::InvalidArgument,
                format!("{arg} has an empty name in '{list}'"),
            )),
            n => Ok(n.to_string()),
        })
        .collect()
}

/// The options given, or the defaults for NULL.
fn options_or_default(options: *const LugreFitOptions) -> LugreFitOptions {
    // SAFETY: NULL or the caller's options.
    unsafe { options.as_ref() }
        .copied()
        .unwrap_or(LugreFitOptions {
            family: LUGRE_FAMILY_LUGRE,
            model: std::ptr::null(),
            fix: std::ptr::null(),
            free: std::ptr::null(),
            x0: 0.0,
            starts: 0,
        })
}

/// Writes the report to `out` and the fitted curve to `fitted` (NULL skips it).
fn deliver_fit(
    report: &FitReport,
    spec: &FitSpec,
    out: &mut LugreFitResult,
    fitted: *mut f64,
) -> Result<(), Failure> {
    let (family, ps): (i32, &[Parameter]) = match report.family {
        Family::LuGre => (LUGRE_FAMILY_LUGRE, &Parameter::LUGRE),
        Family::Dahl => (LUGRE_FAMILY_DAHL, &Parameter::DAHL),
    };
    // Every value of the fitted model (a slow LuGre fit's report holds only the loop's).
    let values: Vec<f64> = match report.family {
        Family::LuGre => report.lugre_params(spec).named().map(|(_, v)| v).to_vec(),
        Family::Dahl => report.values().into_iter().map(|(_, v)| v).collect(),
    };
    let mut r = LugreFitResult {
        family,
        parameters: ps.len(),
        value: [0.0; LUGRE_MAX_PARAMETERS],
        fitted: [0; LUGRE_MAX_PARAMETERS],
        std_error: [0.0; LUGRE_MAX_PARAMETERS],
        ci95_lo: [0.0; LUGRE_MAX_PARAMETERS],
        ci95_hi: [0.0; LUGRE_MAX_PARAMETERS],
        at_bound: [0; LUGRE_MAX_PARAMETERS],
        rms: report.rms,
        samples: report.samples,
        dof: report.dof,
        t_quantile: report.t_quantile,
        condition_number: report.condition_number,
        iterations: report.iterations,
        evaluations: report.evaluations,
        starts: report.starts,
        converged: i32::from(report.converged),
        turning_points: report.turning_points.unwrap_or(0),
    };
    for (i, (p, v)) in ps.iter().zip(values).enumerate() {
        r.value[i] = v;
        (r.ci95_lo[i], r.ci95_hi[i]) = (v, v);
        if let Some(e) = report.estimate(p.name()) {
            r.fitted[i] = 1;
            r.std_error[i] = e.stderr;
            [r.ci95_lo[i], r.ci95_hi[i]] = e.ci95;
            r.at_bound[i] = i32::from(e.at_bound);
        }
    }
    let numbers = r
        .value
        .iter()
        .chain(&r.std_error)
        .chain(&r.ci95_lo)
        .chain(&r.ci95_hi);
    let summary = [r.rms, r.t_quantile, r.condition_number];
    if !numbers
        .chain(&summary)
        .chain(&report.fitted)
        .all(|v| v.is_finite())
    {
        // The core returns finite reports; C gets no NaN or inf whatever happens.
        return Err(fail(
            LugreStatus::InvalidArgument,
            "the fit's result is not finite (the data cannot determine the model)",
        ));
    }
    *out = r;
    output(fitted, &report.fitted);
    Ok(())
}

/// The slow-loop fit of `sigma0` and `g(0) = fs` (Dahl: `rho`, `fc`) to `n` samples `(u, f)`
/// of one or more periods of a slow periodic test (as `lugre fit`: the record closes from its
/// last sample to its first; sample the reversals themselves). `options` may be NULL (the
/// defaults); `x0` and `starts` apply to the full fit and must be 0 here. The result goes to
/// `out`, the fitted force at every sample to `fitted` (`n` values; NULL skips it). A fit
/// that ran out of evaluations at a usable point is `LUGRE_STATUS_OK` with `converged = 0`.
#[no_mangle]
pub extern "C" fn lugre_fit_slow(
    u: *const f64,
    f: *const f64,
    n: usize,
    options: *const LugreFitOptions,
    out: *mut LugreFitResult,
    fitted: *mut f64,
) -> LugreStatus {
    guard(|| {
        let (u, f) = (input(u, n, "u")?, input(f, n, "f")?);
        let out = handle_mut(out, "out")?;
        let o = options_or_default(options);
        for (name, set) in [
            ("options.x0", o.x0 != 0.0),
            ("options.starts", o.starts != 0),
        ] {
            if set {
                return Err(fail(
                    LugreStatus::InvalidArgument,
                    format!("{name} applies to the full fit (lugre_fit), not the slow fit"),
                ));
            }
        }
        let spec = fit_spec(&o)?;
        let report = fit_slow(&spec, u, f)?;
        deliver_fit(&report, &spec, out, fitted)
    })
}

/// The full fit of `sigma0, sigma1, sigma2, fc, fs, vs` (and `beta` if freed; Dahl: `rho`,
/// `fc`) to `n` rate-dependent samples `(t, u, f)` (`t` strictly increasing) on the exact
/// simulation from `options->x0` (as `lugre fit --fit full`). Otherwise as
/// [`lugre_fit_slow`]. A NaN in `f` marks a sample with no measured force (its `u` still
/// drives the simulation; as an empty force cell in `lugre fit`'s files).
#[no_mangle]
pub extern "C" fn lugre_fit(
    t: *const f64,
    u: *const f64,
    f: *const f64,
    n: usize,
    options: *const LugreFitOptions,
    out: *mut LugreFitResult,
    fitted: *mut f64,
) -> LugreStatus {
    guard(|| {
        // The core refuses an infinite force; NaN is a missing one.
        let (t, u, f) = (input(t, n, "t")?, input(u, n, "u")?, values(f, n, "f")?);
        let out = handle_mut(out, "out")?;
        let o = options_or_default(options);
        let spec = fit_spec(&o)?;
        let starts = match o.starts {
            0 => FullOptions::DEFAULT_STARTS,
            k => k,
        };
        let full = FullOptions::default().with_x0(o.x0).with_starts(starts);
        let report = fit_full(&spec, t, u, f, full)?;
        deliver_fit(&report, &spec, out, fitted)
    })
}
