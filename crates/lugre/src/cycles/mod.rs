//! Minor loops in measured (non-periodic) histories: reversals, ASTM E1049-85 rainflow cycles,
//! where each loop closes, and, with a model, the energy over each loop's arc.
//!
//! A history is a sequence of samples `u_0, u_1, ...`, joined by straight lines. Everything is
//! computed in one streaming pass with memory bounded by the rainflow stack (the open
//! reversals), so histories of any length can be fed as they are read ([`CycleCounter`], with
//! or without energies; blocks of a few thousand samples through `push_all` are fastest,
//! and fastest of all without gate and energies into [`CycleColumns`]: BENCHMARKS.md);
//! [`count_cycles`] and [`count_cycles_with_energy`] take a slice.
//!
//! Conventions (those of the Python package `rainflow` 3.x, so results compare row by row with
//! its `extract_cycles`):
//!
//! * **Reversals**: the first and the last samples are reversals; repeated equal samples are
//!   collapsed and a plateau extremum is reported at its *last* sample (the first sample is
//!   reported as itself even when a plateau starts there). With a gate `H > 0`, a turn is a
//!   reversal only once the history has come back from the extreme by at least `H`: every
//!   range between consecutive reversals is then `>= H`, and the history's final wiggle of
//!   less than `H` is dropped (the last reversal is the last extreme). `H = 0` is no gate.
//! * **Cycles**: the three-point method of §5.4.4 for a non-repeating history. With `A, B, P`
//!   the last three reversals on the stack, `X = |P - B|`, `Y = |B - A|`: when `X >= Y` (ties
//!   close), `(A, B)` is a full cycle, or a half cycle if `A` is the first point on the stack.
//!   What remains at the end is counted as half cycles. Each cycle has `range = |u_A - u_B|`,
//!   `mean = (u_A + u_B) / 2`, `count` 1 or 0.5, and the sample indices of `A` and `B`, in the
//!   order cycles are closed. (`minor` pairs reversals of a *repeating* history instead, with a
//!   tie rule chosen for Theorem A.)
//! * **Closure** (full cycles): the first sample after `B` at which the history is back at
//!   `u_A` (reached or passed, by the same test `|u - u_B| >= Y` that counts the cycle), and
//!   the fractional position there by linear interpolation between samples, where `u = u_A`:
//!   the end `C` of the loop's arc `A -> B -> C`, as for periodic inputs (`docs/mathematics.md#measured-histories`).
//! * **Energy**: with a model, `y*` (eq. 6) from `y*(0) = sigma0 x0` along the history, and over
//!   each full cycle's arc the work `W = integral y* du`, the change of stored energy
//!   `dV = (y_C^2 - y_A^2) / (2 sigma0)`, the dissipation `D = W - dV >= 0` and the closure gap
//!   `y_C - y_A` (see "Energy" below).
//!
//! Checked against `rainflow` 3.2.0 on 60 000 random series (26.7 M samples, 8.5 M cycles:
//! small integers, plateaus, ties, random walks; see `testdata/`): the same reversals and the
//! same cycles in the same order. Where it differs, it has no meaningful answer: a 2-sample
//! history has two reversals and one half cycle (`rainflow` yields nothing); reversals are found
//! by comparing values, not by the sign of a product of differences (which underflows for steps
//! below about `1e-154`); a reversal's value is the sample at its index (`rainflow` gives
//! the plateau's first value, which differs only in the sign of a zero); and the three-point
//! test `X >= Y` is decided in exact arithmetic on the samples (`rainflow` compares the
//! rounded differences): the two differ only where two ranges round to the same double
//! without being equal (samples near `2^53`, say), and exactness is what lets a history be
//! counted in chunks ([`chunk`]).
//!
//! # Energy
//!
//! Closed forms per step as in `lugre loop` (see [`crate::loops`]), summed in
//! double-double per stack segment (see the `energy` submodule), so one cycle costs O(1) and
//! the rounding scales with its arc, not with the history before it. The work is carried in
//! both of its forms, summed relative to the loop's start value, `integral (y* - y_A) du`, and
//! as `dV + D`, and taken from the one whose rounding bound is smaller (the kernel's
//! `best_work`, as for periodic loops): on a loop much narrower than `1/a` away from `y* = 0`,
//! `dV` and `D` are `~1e6` times `W` and cancel, while the direct sum keeps about
//! `1e-16 / (a range)` relative accuracy (against mpmath: 1e-11 on loops 1e-5 wide); in the
//! elastic regime it is the other way round.
//!
//! ```
//! use lugre::count_cycles;
//!
//! // ASTM E1049-85 Fig. 6, counted as a non-repeating history (§5.4.4, Table 4).
//! let h = count_cycles(&[-2.0, 1.0, -3.0, 5.0, -1.0, 3.0, -4.0, 4.0, -2.0], 0.0).unwrap();
//! let table: Vec<(f64, f64)> = h.cycles.iter().map(|c| (c.range, c.count)).collect();
//! assert_eq!(
//!     table,
//!     [(3.0, 0.5), (4.0, 0.5), (4.0, 1.0), (8.0, 0.5), (9.0, 0.5), (8.0, 0.5), (6.0, 0.5)]
//! );
//! // The full cycle (-1, 3) closes where the history first comes back to -1, 4/7 of the way
//! // from sample 5 (u = 3) to sample 6 (u = -4).
//! let closure = h.cycles[2].closure.unwrap();
//! assert_eq!((closure.index, closure.position), (6, 5.0 + 4.0 / 7.0));
//! ```

pub mod chunk;
mod columns;
mod energy;
mod engine;
mod histogram;
mod row;
#[cfg(test)]
mod tests;

pub use columns::CycleColumns;
pub use histogram::Histogram;
pub use row::{Cell, ColumnMut};

/// The largest `|u|` a sample may have: ranges and means of any two samples stay finite.
pub const MAX_SAMPLE: f64 = engine::MAX_ABS;

use crate::error::HistoryError;
use crate::kernel::ArcEnergy;
use crate::model::RateIndependent;
pub(crate) use energy::{CutSums, EnergyTrack};
pub(crate) use engine::Engine;
use engine::NoTrack;

/// A reversal: its sample index and value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reversal {
    pub index: u64,
    pub u: f64,
}

/// Where a full cycle's loop closes: the first sample index at which the history is back at
/// the cycle's start value, and the interpolated position (`index - 1 < position <= index`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Closure {
    pub index: u64,
    pub position: f64,
}

/// The energies over a full cycle's arc, from its start `A` through its reversal to the
/// closure `C`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CycleEnergy {
    /// Work `W = integral y* du` (nested cycles included), stored-energy change, dissipation
    /// and closure gap over the arc.
    pub arc: ArcEnergy,
    /// `y*` at the start `A`.
    pub y_start: f64,
    /// `y*` at the closure `C`.
    pub y_closure: f64,
}

/// A rainflow cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cycle {
    /// `|u_start - u_end|`.
    pub range: f64,
    /// `(u_start + u_end) / 2`.
    pub mean: f64,
    /// 1.0 for a full cycle, 0.5 for a half cycle.
    pub count: f64,
    /// Sample index of the reversal the cycle starts at.
    pub start: u64,
    /// Sample index of the reversal the cycle turns at.
    pub end: u64,
    /// Where the loop closes (full cycles only).
    pub closure: Option<Closure>,
    /// Energies over the arc (full cycles, with a model).
    pub energy: Option<CycleEnergy>,
}

impl Cycle {
    pub fn is_full(&self) -> bool {
        self.count == 1.0
    }
}

/// Receives reversals and cycles as they are found (reversals in order of index, cycles in the
/// order they close).
pub trait CycleSink {
    fn reversal(&mut self, r: Reversal);
    fn cycle(&mut self, c: Cycle);
    /// The sink as columns, if it is [`CycleColumns`]: the counter then writes whole blocks of
    /// cycles into them (see [`CycleColumns`]). Other sinks keep the default, `None`.
    fn columns(&mut self) -> Option<&mut CycleColumns> {
        None
    }
}

/// Keeps the cycles, drops the reversals.
impl CycleSink for Vec<Cycle> {
    fn reversal(&mut self, _r: Reversal) {}
    fn cycle(&mut self, c: Cycle) {
        self.push(c);
    }
}

/// Totals along the whole history, from its first to its last sample.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HistoryEnergy {
    /// `y*(0) = sigma0 x0`.
    pub y_start: f64,
    /// `y*` at the last sample.
    pub y_end: f64,
    pub work: f64,
    pub stored_energy_change: f64,
    pub dissipation: f64,
}

impl HistoryEnergy {
    /// The totals are finite numbers ([`HistoryError::TotalsOverflow`] otherwise: the
    /// energies of a model and input with values too large for f64).
    pub fn check_finite(&self) -> Result<(), HistoryError> {
        let values = [
            self.work,
            self.stored_energy_change,
            self.dissipation,
            self.y_start,
            self.y_end,
        ];
        if values.iter().all(|x| x.is_finite()) {
            Ok(())
        } else {
            Err(HistoryError::TotalsOverflow)
        }
    }
}

/// What a finished count reports besides the reversals and cycles.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CycleSummary {
    pub samples: u64,
    pub reversals: u64,
    pub full_cycles: u64,
    pub half_cycles: u64,
    pub energy: Option<HistoryEnergy>,
}

/// Everything about a history held in memory.
#[derive(Debug, Clone, PartialEq)]
pub struct History {
    pub reversals: Vec<Reversal>,
    pub cycles: Vec<Cycle>,
    pub summary: CycleSummary,
}

/// Keeps everything a count reports, in order.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Collect {
    pub reversals: Vec<Reversal>,
    pub cycles: Vec<Cycle>,
}

impl CycleSink for Collect {
    fn reversal(&mut self, r: Reversal) {
        self.reversals.push(r);
    }
    fn cycle(&mut self, c: Cycle) {
        self.cycles.push(c);
    }
}

/// Streaming rainflow counter: push samples (in blocks, or one at a time), then finish.
/// [`CycleCounter::new`] counts; [`CycleCounter::with_energy`] also follows `y*` and reports
/// each full cycle's energies. The two are one type, so a caller with an optional model builds
/// one counter and feeds it the same way.
///
/// ```
/// use lugre::cycles::Collect;
/// use lugre::{CycleCounter, LuGre};
///
/// let model = Some(LuGre::paper().rate_independent());
/// let mut counter = CycleCounter::new(0.0)?.with_energy(model, 0.0)?;
/// let mut sink = Collect::default();
/// counter.push_all(&[0.0, 2.0, 1.0, 3.0, 0.0], &mut sink)?;
/// let summary = counter.finish(&mut sink)?;
/// assert_eq!(summary.full_cycles, 1);
/// assert!(sink.cycles.iter().any(|c| c.energy.is_some()));
/// assert!(summary.energy.is_some());
/// # Ok::<(), lugre::HistoryError>(())
/// ```
#[derive(Debug, Clone)]
pub struct CycleCounter {
    engine: Counting,
}

/// The engine of a [`CycleCounter`]: counting only (the block paths), or with the energies
/// (the per-sample walk). Chosen once, before the first sample; each call dispatches once.
#[derive(Debug, Clone)]
enum Counting {
    Plain(Engine<NoTrack>),
    Energy(Box<Engine<EnergyTrack>>),
}

impl CycleCounter {
    /// A counter with noise gate `gate` (finite, `>= 0`; 0 is no gate).
    pub fn new(gate: f64) -> Result<Self, HistoryError> {
        Ok(Self {
            engine: Counting::Plain(Engine::new(gate, NoTrack)?),
        })
    }

    /// The counter with the energies of `model` (when given) from the initial state `x0`
    /// (`y*(0) = sigma0 x0`, with `|sigma0 x0| <= g(0)`): `y*` is followed along the history
    /// and every full cycle carries its energies, the summary the totals. `None` leaves the
    /// counter as it is (`x0` unused). Call it before the first sample: the energies start at
    /// the first sample (a counter that has taken samples is refused).
    pub fn with_energy(
        self,
        model: impl Into<Option<RateIndependent>>,
        x0: f64,
    ) -> Result<Self, HistoryError> {
        let Some(model) = model.into() else {
            return Ok(self);
        };
        let (gate, origin, taken) = match &self.engine {
            Counting::Plain(e) => (e.gate(), e.origin(), e.taken()),
            Counting::Energy(e) => (e.gate(), e.origin(), e.taken()),
        };
        if taken > 0 {
            return Err(HistoryError::EnergyAfterStart { samples: taken });
        }
        let engine = Engine::new(gate, EnergyTrack::new(model, x0)?)?.with_origin(origin);
        Ok(Self {
            engine: Counting::Energy(Box::new(engine)),
        })
    }

    /// A counter for a chunk whose first sample is sample `origin` of a longer history: its
    /// indices, closures and errors are the history's.
    pub(crate) fn with_origin(self, origin: u64) -> Self {
        let engine = match self.engine {
            Counting::Plain(e) => Counting::Plain(e.with_origin(origin)),
            Counting::Energy(e) => Counting::Energy(Box::new(e.with_origin(origin))),
        };
        Self { engine }
    }

    /// Takes the next sample (finite, `|u| <= f64::MAX / 2`).
    #[inline]
    pub fn push(&mut self, u: f64, sink: &mut impl CycleSink) -> Result<(), HistoryError> {
        self.push_all(std::slice::from_ref(&u), sink)
    }

    /// Takes the next samples (faster than one at a time: feed blocks of a few thousand).
    #[inline]
    pub fn push_all(&mut self, u: &[f64], sink: &mut impl CycleSink) -> Result<(), HistoryError> {
        match &mut self.engine {
            Counting::Plain(e) => e.push_slice(u, sink),
            Counting::Energy(e) => e.push_slice(u, sink),
        }
    }

    /// Ends the history (at least 2 samples): the last reversal and the residue's half cycles
    /// go to `sink`; with energies, the summary has the totals along the whole history.
    pub fn finish(self, sink: &mut impl CycleSink) -> Result<CycleSummary, HistoryError> {
        match self.engine {
            Counting::Plain(e) => Ok(e.finish(sink)?.summary(None)),
            Counting::Energy(e) => {
                let counts = e.finish(sink)?;
                let energy = counts.track.summary();
                Ok(counts.summary(Some(energy)))
            }
        }
    }
}

/// Checks a whole history as a count of it would, before counting: every sample finite with
/// `|u| <=` [`MAX_SAMPLE`], then at least 2 samples. The same errors, in the same order, as
/// [`CycleCounter`] gives on `u`: one rule for every front end (a history of 0 or 1 samples
/// has no range and is refused, where the `rainflow` package returns nothing).
pub fn check_history(u: &[f64]) -> Result<(), HistoryError> {
    if let Some(k) = u.iter().position(|&x| !engine::admissible(x)) {
        return Err(engine::bad_sample(k as u64, u[k]));
    }
    match u.len() {
        0 => Err(HistoryError::Empty),
        1 => Err(HistoryError::TooShort { samples: 1 }),
        _ => Ok(()),
    }
}

/// Reversals and rainflow cycles of the history `u` with noise gate `gate`.
pub fn count_cycles(u: &[f64], gate: f64) -> Result<History, HistoryError> {
    count_with(CycleCounter::new(gate)?, u)
}

/// [`count_cycles`] with `y*` for `model` from `x0` and the energies of every full cycle.
pub fn count_cycles_with_energy(
    u: &[f64],
    gate: f64,
    model: RateIndependent,
    x0: f64,
) -> Result<History, HistoryError> {
    count_with(CycleCounter::new(gate)?.with_energy(model, x0)?, u)
}

/// Everything `counter` reports on the history `u`.
fn count_with(mut counter: CycleCounter, u: &[f64]) -> Result<History, HistoryError> {
    let mut sink = Collect::default();
    counter.push_all(u, &mut sink)?;
    let summary = counter.finish(&mut sink)?;
    Ok(History {
        reversals: sink.reversals,
        cycles: sink.cycles,
        summary,
    })
}
