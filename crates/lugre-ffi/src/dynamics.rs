//! The closed-loop dynamics through the C ABI: the core's request (`lugre::dynamics::Request`)
//! built field by field with the core's field names (`"mass"`, `"force_rate"`, `"pid"`, ...:
//! the Python keywords, the MEX struct fields), run into a motion whose columns and summary
//! the caller reads. The same defaults, checks and messages as `lugre dynamics` and
//! `lugre.dynamics`.
//!
//! ```c
//! LugreDynamics *d; LugreMotion *m;
//! lugre_dynamics_new(&d);
//! lugre_dynamics_set_scenario(d, "pid");
//! double gains[3] = {3, 8, 6};
//! lugre_dynamics_set(d, "pid", gains, 3);     /* new gains, the set point kept */
//! lugre_dynamics_run(d, &m);
//! ```

use std::ffi::c_char;

use lugre::dynamics::{Field, Outcome, Request, Scenario};

use super::{
    fail, free, guard, handle, handle_mut, input, output, set_out, text, Failure, LugreModel,
    LugreStatus,
};
use crate::zoo::LugreZoo;

/// A dynamics request being built (see [`lugre_dynamics_new`]).
pub struct LugreDynamics {
    request: Request,
}

/// A solved run: the motion at the output times, its events, energies and headlines.
pub struct LugreMotion {
    t_end: f64,
    outcome: Outcome,
}

/// What a run gives besides its columns. `has_breakaway` is 1 when a force ramp located the
/// break-away (`breakaway_t`, `breakaway_force`, `breakaway_x`; else 0 and the three 0), and
/// `slip_onsets` counts the upward crossings of a pulled spring's speed (`period`: the last
/// interval between two, 0 with fewer than two).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct LugreMotionSummary {
    pub t_end: f64,
    pub steps: usize,
    pub rejected: usize,
    pub events: usize,
    pub energy_input: f64,
    pub stored_start: f64,
    pub stored_end: f64,
    pub dissipated: f64,
    pub has_breakaway: i32,
    pub breakaway_t: f64,
    pub breakaway_force: f64,
    pub breakaway_x: f64,
    pub slip_onsets: usize,
    pub period: f64,
    /// The friction-displacement loops computed (0 unless asked for with `"loops"` or the
    /// pre-sliding scenario), read one by one with [`lugre_motion_loop`].
    pub loops: usize,
}

/// One friction-displacement loop of a run (the core's `lugre::dynamics::FrictionLoop`, a
/// loop of `lugre dynamics --json`'s `loops`): it starts at `t_start` (a reversal of `x`),
/// turns at `t_turn` and closes at `t_close` (`x` back at its start value); its
/// `turning_points_len` turning points (its start and the reversals inside it) are at
/// `turning_points`, owned by the motion (valid until [`lugre_motion_free`]). `work` is
/// `integral F dx` over the loop, `bristle_energy_change` the change of the energy stored in
/// the friction (the bristles', or the elements' springs' for GMS), `dissipation` their
/// difference, `rate_independent_work` the work per period of `lugre loop` on the same turning
/// points.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct LugreFrictionLoop {
    pub t_start: f64,
    pub t_turn: f64,
    pub t_close: f64,
    pub turning_points: *const f64,
    pub turning_points_len: usize,
    pub work: f64,
    pub bristle_energy_change: f64,
    pub dissipation: f64,
    pub rate_independent_work: f64,
}

/// An empty request to `out`: every field at the core's default (free it with
/// [`lugre_dynamics_free`]).
#[no_mangle]
pub extern "C" fn lugre_dynamics_new(out: *mut *mut LugreDynamics) -> LugreStatus {
    guard(|| {
        set_out(
            out,
            LugreDynamics {
                request: Request::new(),
            },
        )
    })
}

#[no_mangle]
pub extern "C" fn lugre_dynamics_free(request: *mut LugreDynamics) {
    free(request)
}

/// Applies `change` to the request, which stays as it was if the change fails.
fn change(
    request: *mut LugreDynamics,
    change: impl FnOnce(Request) -> Result<Request, Failure>,
) -> LugreStatus {
    guard(|| {
        let d = handle_mut(request, "request")?;
        d.request = change(d.request.clone())?;
        Ok(())
    })
}

/// The field called `name` (the core's names: `lugre_dynamics_set`'s list).
fn field(name: *const c_char) -> Result<Field, Failure> {
    let name =
        text(name, "field")?.ok_or_else(|| fail(LugreStatus::NullPointer, "field is NULL"))?;
    Field::from_name(&name).ok_or_else(|| {
        fail(
            LugreStatus::InvalidArgument,
            format!(
                "unknown field '{name}' (fields: {})",
                Field::ALL.map(Field::name).join(", ")
            ),
        )
    })
}

/// The scenario called `name`.
pub(crate) fn scenario_named(name: &str) -> Result<Scenario, Failure> {
    Ok(Scenario::named(name)?)
}

/// One of the 1995 experiments as the request's preset ("presliding", "breakaway",
/// "stick-slip", "lag", "pid"): its model (Table I), drive and end, each replaced by a field
/// set on top of it, before or after.
#[no_mangle]
pub extern "C" fn lugre_dynamics_set_scenario(
    request: *mut LugreDynamics,
    name: *const c_char,
) -> LugreStatus {
    change(request, |r| {
        let name = text(name, "scenario")?
            .ok_or_else(|| fail(LugreStatus::NullPointer, "scenario is NULL"))?;
        Ok(r.with_scenario(scenario_named(&name)?))
    })
}

/// The friction model (copied: the model may be freed after).
#[no_mangle]
pub extern "C" fn lugre_dynamics_set_model(
    request: *mut LugreDynamics,
    model: *const LugreModel,
) -> LugreStatus {
    change(request, |r| {
        Ok(r.with_model(handle(model, "model")?.model.clone()))
    })
}

/// A model of the zoo as the friction (copied: the model may be freed after): the
/// elasto-plastic one (`lugre_zoo_new("elastoplastic", ...)`, its `sigma0, sigma1, sigma2,
/// fc, fs, vs, beta, zba`; on a scenario, those `lugre_zoo_new` was not given are the
/// scenario's, Table I); the other models are refused with the core's message.
#[no_mangle]
pub extern "C" fn lugre_dynamics_set_zoo(
    request: *mut LugreDynamics,
    model: *const LugreZoo,
) -> LugreStatus {
    change(request, |r| Ok(r.with_zoo(&handle(model, "model")?.model)?))
}

/// A field from `n` numbers: one for `mass`, `damping`, `force_rate`, `spring`, `pull`,
/// `setpoint`, `t_end`, `samples`, `rtol`, `atol`, `loops` (0 or 1); three for `pid`
/// (`Kp, Ki, Kv`); the output times for `times`. Two fields that cannot hold together (two
/// applied forces, `times` and `samples`) fail naming both.
#[no_mangle]
pub extern "C" fn lugre_dynamics_set(
    request: *mut LugreDynamics,
    name: *const c_char,
    values: *const f64,
    n: usize,
) -> LugreStatus {
    change(request, |r| {
        let field = field(name)?;
        // As given: the core checks each field's numbers and names the field.
        let values = super::values(values, n, field.name())?;
        Ok(r.with_numbers(field, values)?)
    })
}

/// A field from `n` points `(t[i], values[i])`: `force` (an applied force, linear between the
/// points, held after), `input` (a measured force history: the run ends at its last time),
/// `end` (the spring's free end), `setpoint` (steps), `velocity` (prescribed).
#[no_mangle]
pub extern "C" fn lugre_dynamics_set_points(
    request: *mut LugreDynamics,
    name: *const c_char,
    t: *const f64,
    values: *const f64,
    n: usize,
) -> LugreStatus {
    change(request, |r| {
        let field = field(name)?;
        let t = input(t, n, "t")?.to_vec();
        let v = input(values, n, field.name())?.to_vec();
        Ok(r.with_points(field, t, v)?)
    })
}

/// Checks the request as a whole and solves it into `out` (free it with
/// [`lugre_motion_free`]).
#[no_mangle]
pub extern "C" fn lugre_dynamics_run(
    request: *const LugreDynamics,
    out: *mut *mut LugreMotion,
) -> LugreStatus {
    guard(|| {
        let plan = handle(request, "request")?.request.build()?;
        let outcome = plan.run()?;
        set_out(
            out,
            LugreMotion {
                t_end: plan.t_end,
                outcome,
            },
        )
    })
}

#[no_mangle]
pub extern "C" fn lugre_motion_free(motion: *mut LugreMotion) {
    free(motion)
}

/// The number of output times, to `len`.
#[no_mangle]
pub extern "C" fn lugre_motion_len(motion: *const LugreMotion, len: *mut usize) -> LugreStatus {
    guard(|| {
        *handle_mut(len, "len")? = handle(motion, "motion")?.outcome.motion.t.len();
        Ok(())
    })
}

/// The sampled columns `t, x, v, z, friction, drive` (`lugre dynamics --csv`), each into a
/// buffer of `capacity` values (NULL skips a column).
#[no_mangle]
pub extern "C" fn lugre_motion_columns(
    motion: *const LugreMotion,
    capacity: usize,
    t: *mut f64,
    x: *mut f64,
    v: *mut f64,
    z: *mut f64,
    friction: *mut f64,
    drive: *mut f64,
) -> LugreStatus {
    guard(|| {
        let m = &handle(motion, "motion")?.outcome.motion;
        super::capacity(m.t.len(), capacity)?;
        for (p, column) in [t, x, v, z, friction, drive].into_iter().zip(m.columns()) {
            output(p, column);
        }
        Ok(())
    })
}

/// The run's summary (see [`LugreMotionSummary`]), to `out`.
#[no_mangle]
pub extern "C" fn lugre_motion_summary(
    motion: *const LugreMotion,
    out: *mut LugreMotionSummary,
) -> LugreStatus {
    guard(|| {
        let m = handle(motion, "motion")?;
        let o = &m.outcome;
        let e = o.motion.energy;
        let onsets = o.slip_onsets();
        let b = o.breakaway.as_ref();
        *handle_mut(out, "out")? = LugreMotionSummary {
            t_end: m.t_end,
            steps: o.motion.stats.steps,
            rejected: o.motion.stats.rejected,
            events: o.motion.events.len(),
            energy_input: e.input,
            stored_start: e.stored_start,
            stored_end: e.stored_end,
            dissipated: e.dissipated,
            has_breakaway: i32::from(b.is_some()),
            breakaway_t: b.map_or(0.0, |b| b.t),
            breakaway_force: b.map_or(0.0, |b| b.force),
            breakaway_x: b.map_or(0.0, |b| b.x),
            slip_onsets: onsets.len(),
            period: match onsets[..] {
                [.., a, b] => b - a,
                _ => 0.0,
            },
            loops: o.loops.len(),
        };
        Ok(())
    })
}

/// Loop `index` of the run (below [`LugreMotionSummary::loops`], in the order of `lugre
/// dynamics --json`'s `loops`), to `out`.
#[no_mangle]
pub extern "C" fn lugre_motion_loop(
    motion: *const LugreMotion,
    index: usize,
    out: *mut LugreFrictionLoop,
) -> LugreStatus {
    guard(|| {
        let loops = &handle(motion, "motion")?.outcome.loops;
        let l = loops.get(index).ok_or_else(|| {
            fail(
                LugreStatus::InvalidArgument,
                format!("index must be below {}, got {index}", loops.len()),
            )
        })?;
        *handle_mut(out, "out")? = LugreFrictionLoop {
            t_start: l.t_start,
            t_turn: l.t_turn,
            t_close: l.t_close,
            turning_points: l.turning_points.as_ptr(),
            turning_points_len: l.turning_points.len(),
            work: l.work,
            bristle_energy_change: l.bristle_energy_change,
            dissipation: l.dissipation,
            rate_independent_work: l.rate_independent_work,
        };
        Ok(())
    })
}
