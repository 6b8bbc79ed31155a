//! The block path (no gate, nothing tracked): a branch-free pass finds a block's reversals,
//! the stack counts them, and closures are found by binary search on the block's samples; see
//! the module docs of [`super`].

use super::{admissible, bad_sample, closure_at, reaches, Engine, Open, Track};
use crate::cycles::{Closure, CycleSink};
use crate::error::HistoryError;

/// Samples per block of the block path, and the fewest worth a block.
pub(super) const BLOCK: usize = 2048;
pub(super) const BLOCK_MIN: usize = 64;
impl<T: Track> Engine<T> {
    /// The block path (no gate, nothing tracked, first run started): see the module docs.
    pub(super) fn push_block(
        &mut self,
        block: &[f64],
        sink: &mut impl CycleSink,
    ) -> Result<(), HistoryError> {
        let bad = block.iter().position(|&u| !admissible(u));
        let good = &block[..bad.unwrap_or(block.len())];
        if good.is_empty() {
            return bad.map_or(Ok(()), |k| Err(bad_sample(self.taken, block[k])));
        }
        let base = self.taken;
        let before = self.prev;
        let samples = Samples { good, base, before };

        // Reversals, branch-free. Without a gate every sample becomes the candidate (it is
        // at or beyond the old one, or it turns), so a reversal is the previous sample exactly
        // when the direction flips; the slot is written every sample and kept on a flip.
        self.block_reversals.resize(BLOCK + 1, (0, 0.0));
        let mut up = self.direction > 0.0;
        let mut last = before;
        let mut found = 0;
        for (k, &u) in good.iter().enumerate() {
            let turn = (up & (u < last)) | (!up & (u > last));
            self.block_reversals[found] = ((base + k as u64).wrapping_sub(1), last);
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
            let (w_ref, w_y, w_a) = self.pair(o, self.pending_closed);
            let lo = (from - base) as usize;
            let k = lo
                + good[lo..].partition_point(|&w| !reaches(o * w - w_ref, w_y, w, o * w_ref, w_a));
            if k == good.len() {
                (self.pending_b, self.pending_range, self.pending_a) = (w_ref, w_y, w_a);
                break;
            }
            let i = base + k as u64;
            let start = self.stack.len() - 2 - 2 * self.pending_closed;
            self.stack[start].closure = samples.closure(i, self.stack[start].u);
            self.pending_closed += 1;
            from = i;
        }

        (self.direction, self.candidate, self.candidate_index) = (o, c, ci);
        self.taken = base + good.len() as u64;
        self.prev = good[good.len() - 1];
        match bad {
            Some(k) => Err(bad_sample(self.taken, block[k])),
            None => Ok(()),
        }
    }

    /// Pushes the block's reversal `self.block_reversals[j]` and counts what it completes, the closures
    /// searched on the block's samples.
    #[inline(always)]
    pub(super) fn push_found(&mut self, j: usize, s: Samples<'_>, sink: &mut impl CycleSink) {
        let (index, u) = self.block_reversals[j];
        let mut from = self.stack.last().map_or(0, |q| q.index + 1).max(s.base);
        self.push_reversal(
            Open::new(index, u, self.candidate_state),
            sink,
            |stack, start| {
                if index < s.base {
                    // A run that ended with the previous block: its closures are recorded.
                    return None;
                }
                let (a, b) = (stack[start].u, stack[start + 1].u);
                let i = s.first_reaching(from, index, b, a)?;
                from = i;
                Some(s.closure(i, a))
            },
        );
        self.pending_closed = 0;
    }
}

/// The samples of a block: `good[k]` is sample `base + k`, `before` the sample before it.
#[derive(Debug, Clone, Copy)]
pub(super) struct Samples<'a> {
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

    /// The first sample in `from..=to` (one run: monotone) back at `b`'s distance from `a`, by
    /// the test that counts a cycle: `|u - b| >= |b - a|` ([`reaches`]).
    #[inline]
    pub(super) fn first_reaching(&self, from: u64, to: u64, b: f64, a: f64) -> Option<u64> {
        let lo = from.checked_sub(self.base)? as usize;
        let hi = to.checked_sub(self.base)? as usize + 1;
        let run = self.good.get(lo..hi)?;
        let y = (b - a).abs();
        let k = run.partition_point(|&w| !reaches((w - b).abs(), y, w, b, a));
        (k < run.len()).then(|| self.base + (lo + k) as u64)
    }

    /// The closure at sample `i` (of this block) of a cycle starting at `ua`.
    #[inline]
    pub(super) fn closure(&self, i: u64, ua: f64) -> Closure {
        let u = self.good[(i - self.base) as usize];
        closure_at(i, u, self.prev_of(i), ua).0
    }
}
