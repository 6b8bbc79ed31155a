//! Counting a block's reversals into columns without a branch on the three-point test
//! ([`Engine::count_fast`]); see the module docs of [`super`].

use super::block::Samples;
use super::{reaches, Engine, Open, Track};
use crate::cycles::columns::FullCycle;
use crate::cycles::{Closure, CycleColumns};

/// The stack depth from which [`Engine::count_fast`] takes over (it needs two entries below
/// the top three; shallower, a half cycle may be due).
const FAST_DEPTH: usize = 5;
/// Full cycles [`Engine::count_fast`] holds before writing them out.
const FULL_CAP: usize = 1024;
/// Room [`Engine::count_fast`] makes on the stack for its pushes: at first, and at most.
pub(super) const MIN_ROOM: usize = 32;
const MAX_ROOM: usize = 4096;

impl<T: Track> Engine<T> {
    /// Counts the block's reversals `self.block_reversals[..found]` into columns. The first (whose run may
    /// have begun in the previous block) and those met while the stack is shallow go one by
    /// one as [`Self::push_found`]; stretches of the others go through [`Self::count_fast`].
    pub(super) fn count_into(&mut self, found: usize, s: Samples<'_>, columns: &mut CycleColumns) {
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

    /// The three-point test over a stretch of reversals `self.block_reversals[j..found]` without a branch
    /// on its outcome (which on a noisy history is a coin toss, and a mispredicted branch costs
    /// more than the test): each step either takes the top pair off as a full cycle or pushes
    /// the next reversal, chosen by masks. The top three entries live in registers and the
    /// rest of the stack is written by index. The full cycles are kept with the reversal that
    /// closes each (on whose run the closure lies) and written to the columns in bulk at the
    /// end, closures included. The stretch ends when the
    /// stack gets shallow (a half cycle may be due), runs out of room, or the block ends; the
    /// stack is then settled as usual. Returns the next reversal to push.
    ///
    /// Called with a settled stack at least `FAST_DEPTH` deep whose top is `self.block_reversals[j - 1]`,
    /// and only on the block path (nothing tracked: the entries carry no state to merge).
    fn count_fast(
        &mut self,
        mut j: usize,
        found: usize,
        s: Samples<'_>,
        columns: &mut CycleColumns,
    ) -> usize {
        let j0 = j;
        let state = self.candidate_state;
        let m = self.stack.len();
        let lim = m + self.fast_room;
        self.stack.resize(lim, Open::new(0, 0.0, state));
        self.fast_full.resize(FULL_CAP, FullCycle::default());
        let stack = &mut self.stack[..lim];
        let full_buf = &mut self.fast_full[..FULL_CAP];
        let buf = &self.block_reversals[..found];
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
        let test = |a: f64, b: f64, p: f64| reaches((p - b).abs(), (b - a).abs(), p, b, a);
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
            self.fast_room = (2 * self.fast_room).min(MAX_ROOM);
        }
        let top = self.block_reversals[j - 1].0;
        self.stack[l] = Open::new(ia, f64::from_bits(ua), state);
        self.stack[l + 1] = Open::new(ib, f64::from_bits(ub), state);
        self.stack[l + 2] = Open::new(top, f64::from_bits(up), state);
        self.stack.truncate(l + 3);

        columns.extend_reversals(&self.block_reversals[j0..j]);
        self.reversals += (j - j0) as u64;
        self.full_count += nf as u64;
        let buf = &self.block_reversals;
        columns.extend_full(&self.fast_full[..nf], |c| {
            // The run into `P` starts after the reversal before it (both in this block: the
            // stretch starts after the block's first reversal).
            let (p, run) = (buf[c.closer].0, buf[c.closer.saturating_sub(1)].0 + 1);
            match s.first_reaching(run, p, c.b_u, c.a_u) {
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
        let mut from = self.block_reversals[j.saturating_sub(2)].0 + 1;
        self.settle(columns, |stack, start| {
            let (a, b) = (stack[start].u, stack[start + 1].u);
            let i = s.first_reaching(from, top, b, a)?;
            from = i;
            Some(s.closure(i, a))
        });
        j
    }
}
