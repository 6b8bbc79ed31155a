//! The per-sample path: the reversal filter, the three-point test and the closure walk one
//! sample at a time (any gate, any tracker); see the module docs of [`super`].

use super::{admissible, bad_sample, reaches, Engine, Open, Track, NO_PAIR};
use crate::cycles::{CycleSink, Reversal};
use crate::error::HistoryError;

impl<T: Track> Engine<T> {
    /// The per-sample path (any gate, any tracker).
    pub(super) fn push_each(
        &mut self,
        us: &[f64],
        sink: &mut impl CycleSink,
    ) -> Result<(), HistoryError> {
        let gate = self.gate;
        let (mut o, mut c, mut c_index) = (self.direction, self.candidate, self.candidate_index);
        let (mut w_ref, mut w_y, mut w_a) = (self.pending_b, self.pending_range, self.pending_a);
        let (mut i, mut prev) = (self.taken, self.prev);
        let mut result = Ok(());
        for &u in us {
            // One comparison rejects NaN, infinities and values whose ranges could overflow.
            if !admissible(u) {
                result = Err(bad_sample(i, u));
                break;
            }
            self.track.sample(i - self.origin, u);
            let v = o * u;
            if v >= c {
                // At or beyond the candidate: the run goes on.
                if reaches(v - w_ref, w_y, u, o * w_ref, w_a) {
                    match self.close_pending(i, u, v, prev, o) {
                        Ok(w) => (w_ref, w_y, w_a) = w,
                        Err(e) => {
                            result = Err(e);
                            break;
                        }
                    }
                }
                c = v;
                c_index = i;
                self.candidate_state = self.track.state();
            } else if c - v >= gate {
                // Back from the candidate by the gate: it is a reversal, and `u` starts the
                // next run.
                let r = Open::new(c_index, o * c, self.candidate_state);
                self.push_reversal(r, sink, |_, _| None);
                self.track.confirm(&r.state);
                o = -o;
                c = -v;
                c_index = i;
                self.candidate_state = self.track.state();
                self.pending_closed = 0;
                (w_ref, w_y, w_a) = self.pair(o, 0);
                if reaches(c - w_ref, w_y, u, o * w_ref, w_a) {
                    match self.close_pending(i, u, c, prev, o) {
                        Ok(w) => (w_ref, w_y, w_a) = w,
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
                    self.candidate_state = self.track.state();
                    // One reversal on the stack: no pair is pending yet.
                    (w_ref, w_y, w_a) = NO_PAIR;
                }
            }
            prev = u;
            i += 1;
        }
        (self.direction, self.candidate, self.candidate_index) = (o, c, c_index);
        (self.pending_b, self.pending_range, self.pending_a) = (w_ref, w_y, w_a);
        (self.taken, self.prev) = (i, prev);
        result
    }

    /// Before the first run: the first sample is a reversal; the first sample out of the gate
    /// band starts the first run, in the direction returned.
    #[cold]
    fn start(&mut self, i: u64, u: f64, sink: &mut impl CycleSink) -> Option<f64> {
        if i == self.origin {
            self.first = u;
            self.reversals += 1;
            sink.reversal(Reversal { index: i, u });
            self.stack.push(Open::new(i, u, self.track.state()));
            None
        } else if u != self.first && (u - self.first).abs() >= self.gate {
            Some(if u > self.first { 1.0 } else { -1.0 })
        } else {
            None
        }
    }
}
