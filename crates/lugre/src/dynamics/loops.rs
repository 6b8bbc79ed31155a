//! The friction-displacement loops of a run (`lugre dynamics --loops`, `loops` of a
//! [`super::Request`], on by default for the pre-sliding scenario): the displacement history `x(t)` is a history like any other, so its
//! rainflow cycles (`lugre cycles`) say where loops close, and the friction along them gives each
//! loop's work.
//!
//! Over an arc from `t_A` to `t_C` the work the mass does on the contact splits exactly
//! (`F v = d/dt (sigma0 z^2 / 2) + sigma0^2 |v| z^2 / g + sigma1 z' v + f(v) v`) into the change
//! of the energy stored in the bristles and what is dissipated:
//!
//! ```text
//! W = integral F dx = sigma0 (z_C^2 - z_A^2) / 2 + D
//! ```
//!
//! `W` is taken by the trapezoid rule on [`LOOP_SAMPLES`] outputs (each exact to the solver's
//! tolerance), `D` as the difference. Beside each loop stands the rate-independent loop of
//! `lugre loop` on the same turning points (its work per period, all of it dissipated): for slow
//! drives the two agree to `O(rate)` (`crates/lugre/tests/dynamics.rs` shows it).

use super::{FrictionLaw, Motion, System, Tolerances};
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
    /// `sigma0 (z_C^2 - z_A^2) / 2`.
    pub bristle_energy_change: f64,
    /// `work - bristle_energy_change`.
    pub dissipation: f64,
    /// The work per period of `lugre loop` on the same turning points (of the same friction
    /// law: LuGre's slow loop, or the elasto-plastic model's).
    pub rate_independent_work: f64,
}

/// The closed loops of the run over `[0, t_end]`: every full rainflow cycle of `x`, and the
/// last open cycle when the run ends back at its start value (to the displacement tolerance).
pub(crate) fn friction_loops(
    system: &System,
    t_end: f64,
    tol: Tolerances,
) -> Result<Vec<FrictionLoop>> {
    let times = uniform_times(0.0, t_end, 1, LOOP_SAMPLES);
    let m = system.solve(t_end, &times, tol)?;
    let (lo, hi) =
        m.x.iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                (a.min(x), b.max(x))
            });
    if hi <= lo {
        return Ok(Vec::new());
    }
    let gate = GATE * (hi - lo);
    let history = count_cycles(&m.x, gate)?;
    let reversals: Vec<usize> = history.reversals.iter().map(|r| r.index as usize).collect();
    let mut loops = Vec::new();
    for c in history.cycles.iter().filter(|c| c.is_full()) {
        if let Some(close) = c.closure {
            loops.push(one_loop(
                system,
                &m,
                &reversals,
                c.start as usize,
                close.position,
            )?);
        }
    }
    // Two consecutive half cycles A -> B -> E of the residue with E back at A's value (the
    // pre-sliding scenario returns to the first hold's displacement, to rounding): within the
    // gate, that closes a loop too.
    let halves: Vec<_> = history.cycles.iter().filter(|c| !c.is_full()).collect();
    for pair in halves.windows(2) {
        let (first, second) = (pair[0], pair[1]);
        let (a, e) = (first.start as usize, second.end as usize);
        if second.start == first.end && (m.x[e] - m.x[a]).abs() <= gate {
            loops.push(one_loop(system, &m, &reversals, a, e as f64)?);
        }
    }
    loops.sort_by(|a, b| a.t_close.total_cmp(&b.t_close));
    Ok(loops)
}

/// The loop from sample `start` to the (fractional) sample position `close`.
fn one_loop(
    system: &System,
    m: &Motion,
    reversals: &[usize],
    start: usize,
    close: f64,
) -> Result<FrictionLoop> {
    let end = close.ceil() as usize;
    let at = |xs: &[f64]| -> f64 {
        let k = end.max(1);
        let s = close - (k - 1) as f64;
        xs[k - 1] + s * (xs[k] - xs[k - 1])
    };
    let (x_c, f_c, z_c, t_c) = (at(&m.x), at(&m.friction), at(&m.z), at(&m.t));
    let mut work = 0.0;
    for i in start + 1..end {
        work += 0.5 * (m.friction[i] + m.friction[i - 1]) * (m.x[i] - m.x[i - 1]);
    }
    if end > start {
        work += 0.5 * (f_c + m.friction[end - 1]) * (x_c - m.x[end - 1]);
    }
    let sigma0 = system.model().sigma0();
    let z_a = m.z[start];
    let stored = 0.5 * sigma0 * (z_c - z_a) * (z_c + z_a);
    let inner: Vec<usize> = reversals
        .iter()
        .copied()
        .filter(|&r| r > start && (r as f64) < close)
        .collect();
    let mut turning_points = vec![m.x[start]];
    turning_points.extend(inner.iter().map(|&r| m.x[r]));
    let input = TurningPoints::new(&turning_points)?;
    let rate_independent_work = match system.law() {
        FrictionLaw::LuGre => {
            HysteresisLoop::new(system.model().rate_independent(), &input)?.work_per_period()
        }
        FrictionLaw::ElastoPlastic { zba } => {
            let p = system.model().params();
            ElastoPlastic::new(p.sigma0, p.fc, p.fs, zba)?
                .loops(&input)?
                .work_per_period()
        }
    };
    Ok(FrictionLoop {
        t_start: m.t[start],
        t_turn: inner.first().map_or(t_c, |&r| m.t[r]),
        t_close: t_c,
        turning_points,
        work,
        bristle_energy_change: stored,
        dissipation: work - stored,
        rate_independent_work,
    })
}
