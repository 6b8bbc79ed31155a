//! The streaming engine: reversal filter, three-point rainflow stack and the closure walk, in
//! one pass over the samples with O(stack) memory. Three execution paths keep the same state
//! and may alternate: the per-sample walk (`walk.rs`: any gate, any tracker), the block path
//! (`block.rs`: no gate, nothing tracked), and the branch-free count into columns (`fast.rs`);
//! this file holds the state and the stack operations they share.
//!
//! **Reversals.** The filter keeps a candidate extreme of the current run. A sample at or
//! beyond it (ties included, so a plateau ends up at its last sample) replaces it; a sample
//! that has come back from it by at least the gate `H` (and by more than nothing) confirms it
//! as a reversal and starts the next run from itself. Before the history first leaves the band
//! `|u - u_0| < H` around its first sample there is no run. Values are compared in the frame
//! oriented by the run's direction `o = +-1` (`v = o u`), which is exact and lets one code path
//! serve rising and falling runs.
//!
//! **Counting.** Each reversal is pushed on the stack and the three-point test of ASTM E1049-85
//! §5.4.4 is applied exactly as `rainflow.extract_cycles` (3.x) does: `X = |P - B|`,
//! `Y = |B - A|` for the top three points `A, B, P`; `X < Y` reads on; otherwise `(A, B)` is a
//! half cycle when `A` is the bottom of the stack (then dropped), a full cycle otherwise (then
//! `A` and `B` are dropped). What is left at the end is counted as half cycles.
//!
//! **Closure walk.** A full cycle `(A, B)` is closed by the first reversal `P` after `B` that
//! reaches `u_A` (every reversal in between stayed strictly inside `(u_A, u_B)`, or it would
//! have closed the cycle itself), so the history first returns to `u_A` on the run into `P`.
//! The pairs that run can close are the stack's top pairs in the order the test will visit
//! them, so while the run goes on each new extreme is checked against the next pending pair
//! with the very expression the test will use (`|u - u_B| >= Y`): the first sample that passes
//! is the closure, and when `P` is pushed the cycles it closes are exactly the ones recorded.
//! The samples themselves are never stored; a closure is kept on the stack entry of its
//! cycle's start until the cycle is counted.
//!
//! **Speed.** A random walk turns every other sample and closes a cycle every fourth, so a
//! per-sample branch on "does it turn" is mispredicted half the time. Without a gate and
//! without energies the samples are therefore taken in blocks: a branch-free pass writes the
//! block's reversals to a buffer, the stack then counts them, and the closures are found by
//! binary search on the block's samples (a run is monotone, and so is the closing test along
//! it); for a run still open at the end of the block, the pending pairs it already reaches are
//! recorded before the block's samples are let go. The per-sample walk above does the same
//! work one sample at a time and serves the gate and the energies.
//!
//! Counting a block's reversals has the same problem: whether the three-point test counts a
//! cycle is a coin toss on a noisy history. Into [`CycleColumns`](crate::CycleColumns) (which takes whole blocks of
//! cycles at once), stretches of reversals are therefore counted without a branch on the test
//! ([`Engine::count_fast`]): each step pops a pair or pushes the next reversal, chosen by masks,
//! and the full cycles are written out afterwards, their closures searched as above.

mod block;
mod fast;
mod walk;

use super::columns::FullCycle;
use super::{Closure, Cycle, CycleEnergy, CycleSink, CycleSummary, HistoryEnergy, Reversal};
use crate::error::HistoryError;
use crate::kernel::numerics::DoubleDouble;
use block::{BLOCK, BLOCK_MIN};
use fast::MIN_ROOM;

/// `|u|` above this could make a range or a mean overflow.
pub(crate) const MAX_ABS: f64 = f64::MAX / 2.0;

/// A reversal on the stack, with what the tracker needs to know about the history there, and
/// the closure of the cycle that starts here once the current run has reached it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Open<S, E> {
    pub index: u64,
    pub u: f64,
    pub state: S,
    closure: Closure,
    energy: E,
}

impl<S, E: Default> Open<S, E> {
    fn new(index: u64, u: f64, state: S) -> Self {
        Self {
            index,
            u,
            state,
            closure: Closure {
                index: 0,
                position: 0.0,
            },
            energy: E::default(),
        }
    }
}

/// What is computed along the history besides the counting (nothing, or the energies).
///
/// A stack entry's state covers the history from the entry below it; a sample's state covers
/// the history from the top of the stack.
pub(crate) trait Track {
    /// The running quantities at one sample.
    type State: Copy;
    /// What is reported for a full cycle.
    type Energy: Copy + Default;
    /// Whether the block path may be used (nothing to follow sample by sample).
    const BLOCKS: bool;
    /// Takes sample `index` (called first for every sample).
    fn sample(&mut self, index: u64, u: f64);
    /// The running quantities at the last sample taken.
    fn state(&self) -> Self::State;
    /// The candidate whose state is `c` has become the top of the stack.
    fn confirm(&mut self, c: &Self::State);
    /// The state of `p` once the pair `a, b` below it is removed from the stack.
    fn merge(a: &Self::State, b: &Self::State, p: &Self::State) -> Self::State;
    /// The energies of the cycle that starts at `stack[start]` and whose closure is at
    /// fraction `frac` of the step from the previous sample to the last one (index `index`).
    fn closure(
        &self,
        stack: &[Open<Self::State, Self::Energy>],
        start: usize,
        index: u64,
        frac: f64,
    ) -> Result<Self::Energy, HistoryError>;
    fn report(e: Self::Energy) -> Option<CycleEnergy>;
}

/// Counting only.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct NoTrack;

impl Track for NoTrack {
    type State = ();
    type Energy = ();
    const BLOCKS: bool = true;
    #[inline(always)]
    fn sample(&mut self, _index: u64, _u: f64) {}
    #[inline(always)]
    fn state(&self) {}
    #[inline(always)]
    fn confirm(&mut self, _c: &()) {}
    #[inline(always)]
    fn merge(_a: &(), _b: &(), _p: &()) {}
    #[inline(always)]
    fn closure(
        &self,
        _stack: &[Open<(), ()>],
        _start: usize,
        _index: u64,
        _frac: f64,
    ) -> Result<(), HistoryError> {
        Ok(())
    }
    #[inline(always)]
    fn report(_e: ()) -> Option<CycleEnergy> {
        None
    }
}

#[derive(Debug, Clone)]
pub(crate) struct Engine<T: Track> {
    gate: f64,
    pub(crate) track: T,
    /// The index of the first sample (0 but for a chunk of a longer history).
    origin: u64,
    /// The index of the next sample (`origin` + samples taken).
    taken: u64,
    /// The previous sample.
    prev: f64,
    /// The first sample (the first reversal).
    first: f64,
    /// Direction of the current run, +1 or -1; 0 before the history leaves the gate band
    /// around its first sample.
    direction: f64,
    /// `direction` times the candidate extreme of the current run; NaN while
    /// `direction == 0`, so that every comparison with it fails and such samples fall through
    /// to the start logic.
    candidate: f64,
    candidate_index: u64,
    candidate_state: T::State,
    /// The rainflow stack of open reversals.
    stack: Vec<Open<T::State, T::Energy>>,
    /// The pending pair of the closure walk: `direction u_B`, `Y = |u_B - u_A|` (`Y = inf`
    /// when no full cycle is pending) and `u_A` (for [`reaches`]' ties).
    pending_b: f64,
    pending_range: f64,
    pending_a: f64,
    /// Pairs of the current run already found closed (their closures are on the stack).
    pending_closed: usize,
    /// The block path's reversals of the current block (`BLOCK + 1` slots).
    block_reversals: Vec<(u64, f64)>,
    /// [`Engine::count_fast`]'s full cycles, and the room it makes on the stack.
    fast_full: Vec<FullCycle>,
    fast_room: usize,
    /// Reversals, full and half cycles counted.
    reversals: u64,
    full_count: u64,
    half_count: u64,
}

impl<T: Track> Engine<T> {
    /// `gate` must be finite and `>= 0`.
    pub fn new(gate: f64, track: T) -> Result<Self, HistoryError> {
        if !(gate.is_finite() && gate >= 0.0) {
            return Err(HistoryError::BadGate { value: gate });
        }
        let state = track.state();
        Ok(Self {
            gate,
            track,
            origin: 0,
            taken: 0,
            prev: 0.0,
            first: 0.0,
            direction: 0.0,
            candidate: f64::NAN,
            candidate_index: 0,
            candidate_state: state,
            stack: Vec::with_capacity(64),
            pending_b: 0.0,
            pending_range: f64::INFINITY,
            pending_a: 0.0,
            pending_closed: 0,
            block_reversals: Vec::new(),
            fast_full: Vec::new(),
            fast_room: MIN_ROOM,
            reversals: 0,
            full_count: 0,
            half_count: 0,
        })
    }

    /// The noise gate.
    pub fn gate(&self) -> f64 {
        self.gate
    }

    /// The index of the first sample.
    pub fn origin(&self) -> u64 {
        self.origin
    }

    /// The number of samples taken.
    pub fn taken(&self) -> u64 {
        self.taken - self.origin
    }

    /// The same engine for a history whose first sample has index `origin` (a chunk of a
    /// longer one): reversals, cycles and closures carry indices from `origin`.
    pub fn with_origin(mut self, origin: u64) -> Self {
        debug_assert_eq!(self.taken, self.origin, "set before the first sample");
        (self.origin, self.taken) = (origin, origin);
        self
    }

    /// Takes the next samples.
    #[inline]
    pub fn push_slice(
        &mut self,
        us: &[f64],
        sink: &mut impl CycleSink,
    ) -> Result<(), HistoryError> {
        // Short slices (one sample at a time) cost less through the walk; both paths keep
        // the same state, so they may alternate.
        if !(T::BLOCKS && self.gate == 0.0) || us.len() < BLOCK_MIN {
            return self.push_each(us, sink);
        }
        // The first run starts sample by sample (the first sample, then the first move).
        let mut rest = us;
        while self.direction == 0.0 && !rest.is_empty() {
            self.push_each(&rest[..1], sink)?;
            rest = &rest[1..];
        }
        for block in rest.chunks(BLOCK) {
            self.push_block(block, sink)?;
        }
        Ok(())
    }

    /// The walk's pair `depth` below the top of the stack for a run in direction `o`: `o u_B`,
    /// `Y` (`Y = inf` when that pair would be a half cycle or does not exist) and `u_A`.
    #[inline]
    fn pair(&self, o: f64, depth: usize) -> (f64, f64, f64) {
        let len = self.stack.len();
        let j2 = 2 * depth;
        if len >= 3 + j2 {
            let b = self.stack[len - 1 - j2].u;
            let a = self.stack[len - 2 - j2].u;
            (o * b, (b - a).abs(), a)
        } else {
            NO_PAIR
        }
    }

    /// Sample `i` (value `u`, oriented `v`, after `prev`) closes the pending pair: records its
    /// closure and that of every further pair it also closes; returns the next pending pair.
    #[inline]
    fn close_pending(
        &mut self,
        i: u64,
        u: f64,
        v: f64,
        prev: f64,
        o: f64,
    ) -> Result<(f64, f64, f64), HistoryError> {
        loop {
            let depth = self.pending_closed;
            let len = self.stack.len();
            if len < 3 + 2 * depth {
                // Only reachable through an overflowed difference; nothing is pending.
                return Ok(NO_PAIR);
            }
            let start = len - 2 - 2 * depth;
            let (closure, frac) = closure_at(i, u, prev, self.stack[start].u);
            let energy = self.track.closure(&self.stack, start, i, frac)?;
            let entry = &mut self.stack[start];
            entry.closure = closure;
            entry.energy = energy;
            self.pending_closed = depth + 1;
            let (w_ref, w_y, w_a) = self.pair(o, depth + 1);
            // No NaN here: samples are admissible, `w_y` is finite or infinite.
            if !reaches(v - w_ref, w_y, u, o * w_ref, w_a) {
                return Ok((w_ref, w_y, w_a));
            }
        }
    }

    /// Pushes a confirmed reversal and counts the cycles it completes. The closures of the
    /// first `pending_closed` full cycles are on the stack; `find(stack, start)` supplies the others
    /// (the block path searches its samples; elsewhere there are none).
    #[inline]
    fn push_reversal(
        &mut self,
        r: Open<T::State, T::Energy>,
        sink: &mut impl CycleSink,
        find: impl FnMut(&[Open<T::State, T::Energy>], usize) -> Option<Closure>,
    ) {
        self.reversals += 1;
        sink.reversal(Reversal {
            index: r.index,
            u: r.u,
        });
        self.stack.push(r);
        self.settle(sink, find);
    }

    /// Counts the cycles the top of the stack completes (see [`Self::push_reversal`]).
    #[inline]
    fn settle(
        &mut self,
        sink: &mut impl CycleSink,
        mut find: impl FnMut(&[Open<T::State, T::Energy>], usize) -> Option<Closure>,
    ) {
        let mut counted = 0;
        loop {
            let m = self.stack.len();
            if m < 3 {
                break;
            }
            let (x1, x2, x3) = (
                self.stack[m - 3].u,
                self.stack[m - 2].u,
                self.stack[m - 1].u,
            );
            if !reaches((x3 - x2).abs(), (x2 - x1).abs(), x3, x2, x1) {
                break;
            }
            if m == 3 {
                self.half_count += 1;
                sink.cycle(cycle(&self.stack[0], &self.stack[1], 0.5, None, None));
                self.stack.remove(0);
            } else {
                let a = self.stack[m - 3];
                let (closure, energy) = if counted < self.pending_closed {
                    (a.closure, T::report(a.energy))
                } else if let Some(closure) = find(&self.stack, m - 3) {
                    (closure, None)
                } else {
                    // The walk and the search see every sample of the run with the test that
                    // counts, so this cannot happen; should rounding ever disagree, close at
                    // the reversal.
                    debug_assert!(false, "closure not found");
                    let p = self.stack[m - 1].index;
                    let closure = Closure {
                        index: p,
                        position: p as f64,
                    };
                    (closure, None)
                };
                counted += 1;
                self.full_count += 1;
                sink.cycle(cycle(&a, &self.stack[m - 2], 1.0, Some(closure), energy));
                let p = self.stack[m - 1];
                self.stack[m - 3] = Open {
                    state: T::merge(&a.state, &self.stack[m - 2].state, &p.state),
                    ..p
                };
                self.stack.truncate(m - 2);
            }
        }
    }

    /// Ends the history: the last extreme (or, if the history never left the gate band, the
    /// last sample) is the last reversal, and the stack's residue is counted as half cycles.
    pub fn finish(mut self, sink: &mut impl CycleSink) -> Result<Counts<T>, HistoryError> {
        match self.taken - self.origin {
            0 => return Err(HistoryError::Empty),
            1 => return Err(HistoryError::TooShort { samples: 1 }),
            _ => {}
        }
        let last = if self.direction == 0.0 {
            Open::new(self.taken - 1, self.prev, self.track.state())
        } else {
            Open::new(
                self.candidate_index,
                self.direction * self.candidate,
                self.candidate_state,
            )
        };
        self.push_reversal(last, sink, |_, _| None);
        for k in 1..self.stack.len() {
            self.half_count += 1;
            sink.cycle(cycle(&self.stack[k - 1], &self.stack[k], 0.5, None, None));
        }
        Ok(Counts {
            samples: self.taken - self.origin,
            reversals: self.reversals,
            full: self.full_count,
            half: self.half_count,
            track: self.track,
        })
    }
}

/// The closure at sample `i` (value `u`, after `prev`) of a cycle starting at `ua`, and the
/// fraction of the step where the history is at `ua`.
#[inline]
pub(crate) fn closure_at(i: u64, u: f64, prev: f64, ua: f64) -> (Closure, f64) {
    let step = u - prev;
    let frac = if step != 0.0 {
        ((ua - prev) / step).clamp(0.0, 1.0)
    } else {
        1.0
    };
    let closure = Closure {
        index: i,
        position: i.saturating_sub(1) as f64 + frac,
    };
    (closure, frac)
}

/// No pending pair: nothing reaches `Y = inf`.
const NO_PAIR: (f64, f64, f64) = (0.0, f64::INFINITY, 0.0);

/// The three-point test `|x - b| >= |b - a|` **in exact arithmetic** (of the samples as they
/// are), given its rounded sides `d` (`|x - b|`, or `o (x - b)` for a run in direction `o`)
/// and `y = |b - a|`: the rounded sides decide unless they are equal (rounding is monotone),
/// and then their rounding errors do. `y = inf` (no pair) is never reached, and a NaN `d`
/// (before the first run) never reaches.
///
/// Exact, the four-point removal is confluent (see `chunk`): a chunk reduced on its own gives
/// the single pass's cycles. Rounded, it is not: with samples near `2^53`, `|R - Q|` and
/// `|Q - P|` can round to equal values while `|R - B| < |P - B|` for an earlier pair
/// `(A, B)`, so that removing `(P, Q)` first changes what `(A, B)` does. The rounded test
/// differs from the exact one only where two ranges round to the same double without being
/// equal (never on data whose differences are exact, such as integers).
#[inline(always)]
pub(crate) fn reaches(d: f64, y: f64, x: f64, b: f64, a: f64) -> bool {
    if d != y {
        d > y
    } else {
        reaches_on_tie(x, b, a)
    }
}

/// [`reaches`] when the rounded sides are equal: compare the rounding errors (`|e| <=` half
/// an ulp of the side, so `|x - b| = |s1| + sign(s1) e1` exactly).
#[cold]
#[inline(never)]
fn reaches_on_tie(x: f64, b: f64, a: f64) -> bool {
    let (s1, e1) = DoubleDouble::two_sum(x, -b);
    let (s2, e2) = DoubleDouble::two_sum(b, -a);
    let e1 = if s1 < 0.0 { -e1 } else { e1 };
    let e2 = if s2 < 0.0 { -e2 } else { e2 };
    e1 >= e2
}

/// Finite with `|u| <= MAX_ABS` (one comparison, false for NaN).
#[inline(always)]
pub(crate) fn admissible(u: f64) -> bool {
    u.abs() <= MAX_ABS
}

#[cold]
pub(crate) fn bad_sample(index: u64, u: f64) -> HistoryError {
    if u.is_finite() {
        HistoryError::TooLarge { index, value: u }
    } else {
        crate::DataError::NotFinite {
            what: "u",
            index,
            value: u,
        }
        .into()
    }
}

/// What [`Engine::finish`] hands back.
pub(crate) struct Counts<T> {
    pub samples: u64,
    pub reversals: u64,
    pub full: u64,
    pub half: u64,
    pub track: T,
}

impl<T> Counts<T> {
    /// The counts as a summary, with the energy totals `energy` (when followed).
    pub fn summary(&self, energy: Option<HistoryEnergy>) -> CycleSummary {
        CycleSummary {
            samples: self.samples,
            reversals: self.reversals,
            full_cycles: self.full,
            half_cycles: self.half,
            energy,
        }
    }
}

/// A cycle between reversals `a` and `b`, with range and mean computed as `rainflow` does.
#[inline]
fn cycle<S, E>(
    a: &Open<S, E>,
    b: &Open<S, E>,
    count: f64,
    closure: Option<Closure>,
    energy: Option<CycleEnergy>,
) -> Cycle {
    Cycle {
        range: (a.u - b.u).abs(),
        mean: 0.5 * (a.u + b.u),
        count,
        start: a.index,
        end: b.index,
        closure,
        energy,
    }
}
