//! The friction-displacement loops of a run (`lugre dynamics --loops`, `loops` of a
//! [`super::Request`], on by default for the pre-sliding scenario): the displacement history `x(t)` is a history like any other, so its
//! rainflow cycles (`lugre cycles`) say where loops close, and the friction along them gives each
//! loop's work.
//!
//! Over an arc from `t_A` to `t_C` the work the mass does on the contact splits exactly into
//! the change of the energy `V` stored in the friction and what is dissipated:
//!
//! ```text
//! (L1)  W = integral F dx = V_C - V_A + D
//! (L2)  V = sigma0 z^2 / 2                      LuGre, elasto-plastic (the bristles)
//!       V = sum_i F_i^2 / (2 k_i)               GMS (the elements' springs, (G7))
//! ```
//!
//! (LuGre: `F v = d/dt (sigma0 z^2 / 2) + sigma0^2 |v| z^2 / g + sigma1 z' v + f(v) v`; GMS:
//! (G7) of [`super::gms`].) `W` is taken by the trapezoid rule on [`LOOP_SAMPLES`] outputs
//! (each exact to the solver's tolerance), `D` as the difference. Beside each loop stands the
//! rate-independent loop of `lugre loop` on the same turning points for the same friction
//! (LuGre's slow loop, the elasto-plastic model's, or the Maxwell-slip model's for GMS: its
//! work per period, all of it dissipated): for slow drives the two agree to `O(rate)`
//! (`crates/lugre/tests/dynamics.rs`, `crates/lugre/tests/dynamics_gms.rs` show it).

use super::{FrictionLaw, System, Tolerances};
use crate::cycles::count_cycles;
use crate::error::Error;
use crate::input::TurningPoints;
use crate::loops::HysteresisLoop;
use crate::simulate::uniform_times;
use crate::zoo::ElastoPlastic;

type Result<T> = std::result::Result<T, Error>;

/// Outputs over the run from which the loops are taken.
pub(crate) const LOOP_SAMPLES: usize = 20_000;
/// Reversals of `x` smaller than this fraction of its span are ringing, not loops.
pub(crate) const GATE: f64 = 1e-3;

/// The outputs the loops are taken from: at each time, the displacement, the friction and the
/// energy stored in the friction (L2).
#[derive(Debug, Clone, Default, PartialEq)]
pub(crate) struct LoopTrace {
    pub t: Vec<f64>,
    pub x: Vec<f64>,
    pub friction: Vec<f64>,
    pub stored: Vec<f64>,
}

/// The output times of a [`LoopTrace`] over `[0, t_end]`.
pub(crate) fn loop_times(t_end: f64) -> Vec<f64> {
    uniform_times(0.0, t_end, 1, LOOP_SAMPLES)
}

/// The trace of `system` (LuGre or elasto-plastic friction, `V = sigma0 z^2 / 2`) over
/// `[0, t_end]`.
fn bristle_trace(system: &System, t_end: f64, tol: Tolerances) -> Result<LoopTrace> {
    let m = system.solve(t_end, &loop_times(t_end), tol)?;
    let sigma0 = system.model().sigma0();
    let stored = m.z.iter().map(|z| 0.5 * sigma0 * z * z).collect();
    Ok(LoopTrace {
        t: m.t,
        x: m.x,
        friction: m.friction,
        stored,
    })
}

/// The loops of `system` (LuGre or elasto-plastic friction) over `[0, t_end]`, each beside
/// its law's slow loop.
pub(crate) fn friction_loops(
    system: &System,
    t_end: f64,
    tol: Tolerances,
) -> Result<Vec<FrictionLoop>> {
    let trace = bristle_trace(system, t_end, tol)?;
    loops_of(&trace, |input| match system.law() {
        FrictionLaw::LuGre => {
            Ok(HysteresisLoop::new(system.model().rate_independent(), input)?.work_per_period())
        }
        FrictionLaw::ElastoPlastic { zba } => {
            let p = system.model().params();
            Ok(ElastoPlastic::new(p.sigma0, p.fc, p.fs, zba)?
                .loops(input)?
                .work_per_period())
        }
    })
}

/// One closed friction-displacement loop.
#[derive(Debug, Clone, PartialEq)]
pub struct FrictionLoop {
    /// Where the loop starts (a reversal of x), turns, and closes (x back at its start value).
    pub t_start: f64,
    pub t_turn: f64,
    pub t_close: f64,
    /// The turning points of the loop: its start and the reversals inside it.
    pub turning_points: Vec<f64>,
    /// `integral F dx` over the loop.
    pub work: f64,
    /// The change of the energy stored in the friction over the loop, `V_C - V_A` of (L2):
    /// `sigma0 (z_C^2 - z_A^2) / 2` in the bristles (LuGre, elasto-plastic), `sum_i (F_i,C^2 -
    /// F_i,A^2) / (2 k_i)` in the elements' springs (GMS).
    pub bristle_energy_change: f64,
    /// `work - bristle_energy_change`.
    pub dissipation: f64,
    /// The work per period of `lugre loop` on the same turning points (of the same friction
    /// law: LuGre's slow loop, the elasto-plastic model's, or the Maxwell-slip model's for GMS).
    pub rate_independent_work: f64,
}

impl FrictionLoop {
    /// The fields' names in order: the keys of a loop of `lugre dynamics --json`'s `loops`
    /// (and Python's), the fields of the C ABI's `LugreFrictionLoop` (`turning_points` with its
    /// length beside it) and of the MEX gateway's `loops` struct array.
    pub const FIELDS: [&'static str; 8] = [
        "t_start",
        "t_turn",
        "t_close",
        "turning_points",
        "work",
        "bristle_energy_change",
        "dissipation",
        "rate_independent_work",
    ];
}

/// The closed loops of `trace`: every full rainflow cycle of `x`, and the last open cycle
/// when the run ends back at its start value (to the displacement gate); `slow` gives the
/// rate-independent work per period on a loop's turning points.
pub(crate) fn loops_of(
    trace: &LoopTrace,
    slow: impl Fn(&TurningPoints) -> Result<f64>,
) -> Result<Vec<FrictionLoop>> {
    let (lo, hi) = trace
        .x
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    if hi <= lo {
        return Ok(Vec::new());
    }
    let gate = GATE * (hi - lo);
    let history = count_cycles(&trace.x, gate)?;
    let reversals: Vec<usize> = history.reversals.iter().map(|r| r.index as usize).collect();
    let mut loops = Vec::new();
    for c in history.cycles.iter().filter(|c| c.is_full()) {
        if let Some(close) = c.closure {
            let start = c.start as usize;
            loops.push(one_loop(trace, &reversals, start, close.position, &slow)?);
        }
    }
    // Two consecutive half cycles A -> B -> E of the residue with E back at A's value (the
    // pre-sliding scenario returns to the first hold's displacement, to rounding): within the
    // gate, that closes a loop too.
    let halves: Vec<_> = history.cycles.iter().filter(|c| !c.is_full()).collect();
    for pair in halves.windows(2) {
        let (first, second) = (pair[0], pair[1]);
        let (a, e) = (first.start as usize, second.end as usize);
        if second.start == first.end && (trace.x[e] - trace.x[a]).abs() <= gate {
            loops.push(one_loop(trace, &reversals, a, e as f64, &slow)?);
        }
    }
    loops.sort_by(|a, b| a.t_close.total_cmp(&b.t_close));
    Ok(loops)
}

/// The loop of `trace` from sample `start` to the (fractional) sample position `close`.
fn one_loop(
    trace: &LoopTrace,
    reversals: &[usize],
    start: usize,
    close: f64,
    slow: impl Fn(&TurningPoints) -> Result<f64>,
) -> Result<FrictionLoop> {
    let end = close.ceil() as usize;
    let at = |xs: &[f64]| -> f64 {
        let k = end.max(1);
        let s = close - (k - 1) as f64;
        xs[k - 1] + s * (xs[k] - xs[k - 1])
    };
    let (x, f) = (&trace.x, &trace.friction);
    let (x_c, f_c, t_c) = (at(x), at(f), at(&trace.t));
    let mut work = 0.0;
    for i in start + 1..end {
        work += 0.5 * (f[i] + f[i - 1]) * (x[i] - x[i - 1]);
    }
    if end > start {
        work += 0.5 * (f_c + f[end - 1]) * (x_c - x[end - 1]);
    }
    let stored = at(&trace.stored) - trace.stored[start];
    let inner: Vec<usize> = reversals
        .iter()
        .copied()
        .filter(|&r| r > start && (r as f64) < close)
        .collect();
    let mut turning_points = vec![x[start]];
    turning_points.extend(inner.iter().map(|&r| x[r]));
    let rate_independent_work = slow(&TurningPoints::new(&turning_points)?)?;
    Ok(FrictionLoop {
        t_start: trace.t[start],
        t_turn: inner.first().map_or(t_c, |&r| trace.t[r]),
        t_close: t_c,
        turning_points,
        work,
        bristle_energy_change: stored,
        dissipation: work - stored,
        rate_independent_work,
    })
}
