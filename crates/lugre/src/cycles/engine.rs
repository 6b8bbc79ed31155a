//! The streaming engine: reversal filter, three-point rainflow stack and the closure walk, in
//! one pass over the samples with O(stack) memory.
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
//! cycle is a coin toss on a noisy history. Into [`CycleColumns`] (which takes whole blocks of
//! cycles at once), stretches of reversals are therefore counted without a branch on the test
//! ([`Engine::count_fast`]): each step pops a pair or pushes the next reversal, chosen by masks,
//! and the full cycles are written out afterwards, their closures searched as above.

use super::columns::FullCycle;
use super::{Closure, Cycle, CycleColumns, CycleEnergy, CycleSink, Reversal};
use crate::error::HistoryError;

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
    /// Samples taken.
    n: u64,
    /// The previous sample.
    prev: f64,
    /// The first sample (the first reversal).
    first: f64,
    /// Direction of the current run, +1 or -1; 0 before the history leaves the gate band
    /// around its first sample.
    o: f64,
    /// `o` times the candidate extreme; NaN while `o == 0`, so that every comparison with it
    /// fails and such samples fall through to the start logic.
    c: f64,
    c_index: u64,
    c_state: T::State,
    stack: Vec<Open<T::State, T::Energy>>,
    /// The pending pair of the closure walk: `o u_B` and `Y = |u_B - u_A|` (`Y = inf` when no
    /// full cycle is pending).
    w_ref: f64,
    w_y: f64,
    /// Pairs of the current run already found closed (their closures are on the stack).
    w_depth: usize,
    /// The block path's reversal buffer (`BLOCK + 1` slots).
    buf: Vec<(u64, f64)>,
    /// [`Engine::count_fast`]'s full cycles and the room it makes on the stack.
    full_buf: Vec<FullCycle>,
    room: usize,
    reversals: u64,
    full: u64,
    half: u64,
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
            n: 0,
            prev: 0.0,
            first: 0.0,
            o: 0.0,
            c: f64::NAN,
            c_index: 0,
            c_state: state,
            stack: Vec::with_capacity(64),
            w_ref: 0.0,
            w_y: f64::INFINITY,
            w_depth: 0,
            buf: Vec::new(),
            full_buf: Vec::new(),
            room: MIN_ROOM,
            reversals: 0,
            full: 0,
            half: 0,
        })
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
        while self.o == 0.0 && !rest.is_empty() {
            self.push_each(&rest[..1], sink)?;
            rest = &rest[1..];
        }
        for block in rest.chunks(BLOCK) {
            self.push_block(block, sink)?;
        }
        Ok(())
    }

    /// The per-sample path (any gate, any tracker).
    fn push_each(&mut self, us: &[f64], sink: &mut impl CycleSink) -> Result<(), HistoryError> {
        let gate = self.gate;
        let (mut o, mut c, mut c_index) = (self.o, self.c, self.c_index);
        let (mut w_ref, mut w_y) = (self.w_ref, self.w_y);
        let (mut i, mut prev) = (self.n, self.prev);
        let mut result = Ok(());
        for &u in us {
            // One comparison rejects NaN, infinities and values whose ranges could overflow.
            if !admissible(u) {
                result = Err(bad_sample(i, u));
                break;
            }
            self.track.sample(i, u);
            let v = o * u;
            if v >= c {
                // At or beyond the candidate: the run goes on.
                if v - w_ref >= w_y {
                    match self.close_pending(i, u, v, prev, o) {
                        Ok(w) => (w_ref, w_y) = w,
                        Err(e) => {
                            result = Err(e);
                            break;
                        }
                    }
                }
                c = v;
                c_index = i;
                self.c_state = self.track.state();
            } else if c - v >= gate {
                // Back from the candidate by the gate: it is a reversal, and `u` starts the
                // next run.
                let r = Open::new(c_index, o * c, self.c_state);
                self.push_reversal(r, sink, |_, _| None);
                self.track.confirm(&r.state);
                o = -o;
                c = -v;
                c_index = i;
                self.c_state = self.track.state();
                self.w_depth = 0;
                (w_ref, w_y) = self.pair(o, 0);
                if c - w_ref >= w_y {
                    match self.close_pending(i, u, c, prev, o) {
                        Ok(w) => (w_ref, w_y) = w,
                        Err(e) => {
                            result = Err(e);
                            break;
                        }
                    }
                }
            } else if o == 0.0 {
                if let Some(dir) = self.start(i, u, sink) {
                    o = dir;
                    c = o * u;
                    c_index = i;
                    self.c_state = self.track.state();
                    // One reversal on the stack: no pair is pending yet.
                    (w_ref, w_y) = (0.0, f64::INFINITY);
                }
            }
            prev = u;
            i += 1;
        }
        (self.o, self.c, self.c_index) = (o, c, c_index);
        (self.w_ref, self.w_y) = (w_ref, w_y);
        (self.n, self.prev) = (i, prev);
        result
    }

    /// Before the first run: the first sample is a reversal; the first sample out of the gate
    /// band starts the first run, in the direction returned.
    #[cold]
    fn start(&mut self, i: u64, u: f64, sink: &mut impl CycleSink) -> Option<f64> {
        if i == 0 {
            self.first = u;
            self.reversals += 1;
            sink.reversal(Reversal { index: 0, u });
            self.stack.push(Open::new(0, u, self.track.state()));
            None
        } else if u != self.first && (u - self.first).abs() >= self.gate {
            Some(if u > self.first { 1.0 } else { -1.0 })
        } else {
            None
        }
    }

    /// The walk's pair `depth` below the top of the stack for a run in direction `o`: `o u_B`
    /// and `Y` (`Y = inf` when that pair would be a half cycle or does not exist).
    #[inline]
    fn pair(&self, o: f64, depth: usize) -> (f64, f64) {
        let len = self.stack.len();
        let j2 = 2 * depth;
        if len >= 3 + j2 {
            let b = self.stack[len - 1 - j2].u;
            let a = self.stack[len - 2 - j2].u;
            (o * b, (b - a).abs())
        } else {
            (0.0, f64::INFINITY)
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
    ) -> Result<(f64, f64), HistoryError> {
        loop {
            let depth = self.w_depth;
            let len = self.stack.len();
            if len < 3 + 2 * depth {
                // Only reachable through an overflowed difference; nothing is pending.
                return Ok((0.0, f64::INFINITY));
            }
            let start = len - 2 - 2 * depth;
            let (closure, frac) = closure_at(i, u, prev, self.stack[start].u);
            let energy = self.track.closure(&self.stack, start, i, frac)?;
            let entry = &mut self.stack[start];
            entry.closure = closure;
            entry.energy = energy;
            self.w_depth = depth + 1;
            let (w_ref, w_y) = self.pair(o, depth + 1);
            // No NaN here: samples are admissible, `w_y` is finite or infinite.
            if v - w_ref < w_y {
                return Ok((w_ref, w_y));
            }
        }
    }

    /// Pushes a confirmed reversal and counts the cycles it completes. The closures of the
    /// first `w_depth` full cycles are on the stack; `find(stack, start)` supplies the others
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
            if (x3 - x2).abs() < (x2 - x1).abs() {
                break;
            }
            if m == 3 {
                self.half += 1;
                sink.cycle(cycle(&self.stack[0], &self.stack[1], 0.5, None, None));
                self.stack.remove(0);
            } else {
                let a = self.stack[m - 3];
                let (closure, energy) = if counted < self.w_depth {
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
                self.full += 1;
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
        match self.n {
            0 => return Err(HistoryError::Empty),
            1 => return Err(HistoryError::TooShort { samples: 1 }),
            _ => {}
        }
        let last = if self.o == 0.0 {
            Open::new(self.n - 1, self.prev, self.track.state())
        } else {
            Open::new(self.c_index, self.o * self.c, self.c_state)
        };
        self.push_reversal(last, sink, |_, _| None);
        for k in 1..self.stack.len() {
            self.half += 1;
            sink.cycle(cycle(&self.stack[k - 1], &self.stack[k], 0.5, None, None));
        }
        Ok(Counts {
            samples: self.n,
            reversals: self.reversals,
            full: self.full,
            half: self.half,
            track: self.track,
        })
    }
}

/// Samples per block of the block path, and the fewest worth a block.
const BLOCK: usize = 2048;
const BLOCK_MIN: usize = 64;
/// The stack depth from which [`Engine::count_fast`] takes over (it needs two entries below
/// the top three; shallower, a half cycle may be due).
const FAST_DEPTH: usize = 5;
/// Full cycles [`Engine::count_fast`] holds before writing them out.
const FULL_CAP: usize = 1024;
/// Room [`Engine::count_fast`] makes on the stack for its pushes: at first, and at most.
const MIN_ROOM: usize = 32;
const MAX_ROOM: usize = 4096;

impl<T: Track> Engine<T> {
    /// The block path (no gate, nothing tracked, first run started): see the module docs.
    fn push_block(&mut self, block: &[f64], sink: &mut impl CycleSink) -> Result<(), HistoryError> {
        let bad = block.iter().position(|&u| !admissible(u));
        let good = &block[..bad.unwrap_or(block.len())];
        if good.is_empty() {
            return bad.map_or(Ok(()), |k| Err(bad_sample(self.n, block[k])));
        }
        let base = self.n;
        let before = self.prev;
        let samples = Samples { good, base, before };

        // Reversals, branch-free. Without a gate every sample becomes the candidate (it is
        // at or beyond the old one, or it turns), so a reversal is the previous sample exactly
        // when the direction flips; the slot is written every sample and kept on a flip.
        self.buf.resize(BLOCK + 1, (0, 0.0));
        let mut up = self.o > 0.0;
        let mut last = before;
        let mut found = 0;
        for (k, &u) in good.iter().enumerate() {
            let turn = (up & (u < last)) | (!up & (u > last));
            self.buf[found] = ((base + k as u64).wrapping_sub(1), last);
            found += usize::from(turn);
            up ^= turn;
            last = u;
        }
        let o = if up { 1.0 } else { -1.0 };
        let (c, ci) = (o * last, base + good.len() as u64 - 1);

        // Count them; a full cycle's closure lies on the run into the reversal that closes it.
        if let Some(columns) = sink.columns() {
            self.count_into(found, samples, columns);
        } else {
            for j in 0..found {
                self.push_found(j, samples, sink);
            }
        }

        // The run still open: record the pending pairs its samples here already reach.
        let mut from = self.stack.last().map_or(0, |q| q.index + 1).max(base);
        loop {
            let (w_ref, w_y) = self.pair(o, self.w_depth);
            let lo = (from - base) as usize;
            let k = lo + good[lo..].partition_point(|&w| o * w - w_ref < w_y);
            if k == good.len() {
                (self.w_ref, self.w_y) = (w_ref, w_y);
                break;
            }
            let i = base + k as u64;
            let start = self.stack.len() - 2 - 2 * self.w_depth;
            self.stack[start].closure = samples.closure(i, self.stack[start].u);
            self.w_depth += 1;
            from = i;
        }

        (self.o, self.c, self.c_index) = (o, c, ci);
        self.n = base + good.len() as u64;
        self.prev = good[good.len() - 1];
        match bad {
            Some(k) => Err(bad_sample(self.n, block[k])),
            None => Ok(()),
        }
    }
}

impl<T: Track> Engine<T> {
    /// Pushes the block's reversal `self.buf[j]` and counts what it completes, the closures
    /// searched on the block's samples.
    #[inline(always)]
    fn push_found(&mut self, j: usize, s: Samples<'_>, sink: &mut impl CycleSink) {
        let (index, u) = self.buf[j];
        let mut from = self.stack.last().map_or(0, |q| q.index + 1).max(s.base);
        self.push_reversal(Open::new(index, u, self.c_state), sink, |stack, start| {
            if index < s.base {
                // A run that ended with the previous block: its closures are recorded.
                return None;
            }
            let (a, b) = (stack[start].u, stack[start + 1].u);
            let i = s.first_reaching(from, index, b, (b - a).abs())?;
            from = i;
            Some(s.closure(i, a))
        });
        self.w_depth = 0;
    }

    /// Counts the block's reversals `self.buf[..found]` into columns. The first (whose run may
    /// have begun in the previous block) and those met while the stack is shallow go one by
    /// one as [`Self::push_found`]; stretches of the others go through [`Self::count_fast`].
    fn count_into(&mut self, found: usize, s: Samples<'_>, columns: &mut CycleColumns) {
        let mut j = 0;
        while j < found {
            if j == 0 || self.stack.len() < FAST_DEPTH {
                self.push_found(j, s, columns);
                j += 1;
            } else {
                j = self.count_fast(j, found, s, columns);
            }
        }
    }

    /// The three-point test over a stretch of reversals `self.buf[j..found]` without a branch
    /// on its outcome (which on a noisy history is a coin toss, and a mispredicted branch costs
    /// more than the test): each step either takes the top pair off as a full cycle or pushes
    /// the next reversal, chosen by masks. The top three entries live in registers and the
    /// rest of the stack is written by index. The full cycles are kept with the reversal that
    /// closes each (on whose run the closure lies) and written to the columns in bulk at the
    /// end, closures included. The stretch ends when the
    /// stack gets shallow (a half cycle may be due), runs out of room, or the block ends; the
    /// stack is then settled as usual. Returns the next reversal to push.
    ///
    /// Called with a settled stack at least `FAST_DEPTH` deep whose top is `self.buf[j - 1]`,
    /// and only on the block path (nothing tracked: the entries carry no state to merge).
    fn count_fast(
        &mut self,
        mut j: usize,
        found: usize,
        s: Samples<'_>,
        columns: &mut CycleColumns,
    ) -> usize {
        let j0 = j;
        let state = self.c_state;
        let m = self.stack.len();
        let lim = m + self.room;
        self.stack.resize(lim, Open::new(0, 0.0, state));
        self.full_buf.resize(FULL_CAP, FullCycle::default());
        let stack = &mut self.stack[..lim];
        let full_buf = &mut self.full_buf[..FULL_CAP];
        let buf = &self.buf[..found];
        // The top three `a, b, p` live in registers; `p` is always `buf[j - 1]` (the last
        // reversal pushed stays on top), so its index is read from there when needed.
        let mut l = m - 3;
        let (mut ia, mut ua) = (stack[l].index, stack[l].u.to_bits());
        let (mut ib, mut ub) = (stack[l + 1].index, stack[l + 1].u.to_bits());
        let mut up = stack[l + 2].u.to_bits();
        debug_assert_eq!(stack[l + 2].index, buf[j - 1].0);
        let mut nf = 0;
        // The test of `settle` (and `rainflow`) on the top three: `(a, b)` is a full cycle.
        // Each step works out the next step's test for both of its outcomes, so that the
        // chain from one test to the next spans two steps.
        let test = |a: f64, b: f64, p: f64| (p - b).abs() >= (b - a).abs();
        let mut full = test(f64::from_bits(ua), f64::from_bits(ub), f64::from_bits(up));
        while l >= 2 && l + 3 < lim && j < found && nf < FULL_CAP {
            let (a, b, p) = (f64::from_bits(ua), f64::from_bits(ub), f64::from_bits(up));
            full_buf[nf] = FullCycle {
                a_index: ia,
                a_u: a,
                b_index: ib,
                b_u: b,
                closer: j - 1,
            };
            nf += usize::from(full);
            let (below2, below1) = (stack[l - 2], stack[l - 1]);
            let (ip, next) = (buf[j - 1].0, buf[j]);
            stack[l] = Open::new(ia, a, state);
            let then_full = test(below2.u, below1.u, p);
            let then_push = test(b, p, next.1);
            let mask = 0u64.wrapping_sub(u64::from(full));
            let pick = |x: u64, y: u64| (x & mask) | (y & !mask);
            // Full: `a, b` leave, the two entries below come up, `p` stays on top. Otherwise
            // `a` goes to memory and `next` comes on top.
            (ia, ua) = (pick(below2.index, ib), pick(below2.u.to_bits(), ub));
            (ib, ub) = (pick(below1.index, ip), pick(below1.u.to_bits(), up));
            up = pick(up, next.1.to_bits());
            l = l + 1 - 3 * usize::from(full);
            j += usize::from(!full);
            full = (full & then_full) | (!full & then_push);
        }
        if l + 3 >= lim {
            // Out of room: more next time (resizing costs `room` writes).
            self.room = (2 * self.room).min(MAX_ROOM);
        }
        let top = self.buf[j - 1].0;
        self.stack[l] = Open::new(ia, f64::from_bits(ua), state);
        self.stack[l + 1] = Open::new(ib, f64::from_bits(ub), state);
        self.stack[l + 2] = Open::new(top, f64::from_bits(up), state);
        self.stack.truncate(l + 3);

        columns.extend_reversals(&self.buf[j0..j]);
        self.reversals += (j - j0) as u64;
        self.full += nf as u64;
        let buf = &self.buf;
        columns.extend_full(&self.full_buf[..nf], |c| {
            // The run into `P` starts after the reversal before it (both in this block: the
            // stretch starts after the block's first reversal).
            let (p, run) = (buf[c.closer].0, buf[c.closer.saturating_sub(1)].0 + 1);
            let y = (c.b_u - c.a_u).abs();
            match s.first_reaching(run, p, c.b_u, y) {
                Some(i) => s.closure(i, c.a_u),
                None => {
                    // `P` itself passes the test: see `settle`.
                    debug_assert!(false, "closure not found");
                    Closure {
                        index: p,
                        position: p as f64,
                    }
                }
            }
        });

        // The last step took a pair off or pushed: the top may complete more.
        let mut from = self.buf[j.saturating_sub(2)].0 + 1;
        self.settle(columns, |stack, start| {
            let (a, b) = (stack[start].u, stack[start + 1].u);
            let i = s.first_reaching(from, top, b, (b - a).abs())?;
            from = i;
            Some(s.closure(i, a))
        });
        j
    }
}

/// The samples of a block: `good[k]` is sample `base + k`, `before` the sample before it.
#[derive(Debug, Clone, Copy)]
struct Samples<'a> {
    good: &'a [f64],
    base: u64,
    before: f64,
}

impl Samples<'_> {
    /// The sample before sample `i` (in this block, or the one before it).
    #[inline]
    fn prev_of(&self, i: u64) -> f64 {
        match i.checked_sub(self.base + 1) {
            Some(k) => self.good[k as usize],
            None => self.before,
        }
    }

    /// The first sample in `from..=to` (one run: monotone) back at `b`'s distance `y`, by the
    /// test that counts a cycle: `|u - b| >= y`.
    #[inline]
    fn first_reaching(&self, from: u64, to: u64, b: f64, y: f64) -> Option<u64> {
        let lo = from.checked_sub(self.base)? as usize;
        let hi = to.checked_sub(self.base)? as usize + 1;
        let run = self.good.get(lo..hi)?;
        let k = run.partition_point(|&w| (w - b).abs() < y);
        (k < run.len()).then(|| self.base + (lo + k) as u64)
    }

    /// The closure at sample `i` (of this block) of a cycle starting at `ua`.
    #[inline]
    fn closure(&self, i: u64, ua: f64) -> Closure {
        let u = self.good[(i - self.base) as usize];
        closure_at(i, u, self.prev_of(i), ua).0
    }
}

/// The closure at sample `i` (value `u`, after `prev`) of a cycle starting at `ua`, and the
/// fraction of the step where the history is at `ua`.
#[inline]
fn closure_at(i: u64, u: f64, prev: f64, ua: f64) -> (Closure, f64) {
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

/// Finite with `|u| <= MAX_ABS` (one comparison, false for NaN).
#[inline(always)]
fn admissible(u: f64) -> bool {
    u.abs() <= MAX_ABS
}

#[cold]
fn bad_sample(index: u64, u: f64) -> HistoryError {
    if u.is_finite() {
        HistoryError::TooLarge { index, value: u }
    } else {
        HistoryError::NotFinite { index, value: u }
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
