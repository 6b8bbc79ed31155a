//! Reversals and cycles as columns (one `Vec` per field), the layout numpy and data frames
//! take without a copy.

use super::{Closure, Cycle, CycleEnergy, CycleSink, Reversal};
use crate::kernel::ArcEnergy;

/// A [`CycleSink`] that keeps reversals and cycles as columns: one `Vec` per field, indices as
/// `i64` (numpy's default integer). Which columns are filled is chosen up front; the others
/// stay empty. The cycle columns `range`, `mean`, `count`, `start`, `end` are always filled
/// (the table `rainflow.extract_cycles` yields).
///
/// Counting into columns is also the fastest way to count: without a gate and without energies
/// the counter writes a block's full cycles straight into the columns instead of handing them
/// over one by one (BENCHMARKS.md, "Rainflow").
///
/// The fields are public so that a caller can hand in vectors it allocated (e.g. with capacity
/// reserved up front) and take the filled ones out.
///
/// ```
/// use lugre::{CycleColumns, CycleCounter};
///
/// let mut columns = CycleColumns::new().with_reversals(false);
/// let mut counter = CycleCounter::new(0.0).unwrap();
/// counter.push_all(&[-2.0, 1.0, -3.0, 5.0, -1.0, 3.0, -4.0, 4.0, -2.0], &mut columns).unwrap();
/// counter.finish(&mut columns).unwrap();
/// assert_eq!(columns.range, [3.0, 4.0, 4.0, 8.0, 9.0, 8.0, 6.0]);
/// assert_eq!(columns.count[2], 1.0); // the full cycle (-1, 3) ...
/// assert_eq!((columns.start[2], columns.end[2]), (4, 5));
/// assert_eq!(columns.closure[2], 6); // ... closes at sample 6
/// assert_eq!(columns.closure[0], -1); // half cycles do not close
/// assert!(columns.reversal_index.is_empty());
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct CycleColumns {
    /// Sample index of each reversal (with [`with_reversals`](Self::with_reversals)).
    pub reversal_index: Vec<i64>,
    /// Value of each reversal (with [`with_reversals`](Self::with_reversals)).
    pub reversal_u: Vec<f64>,
    /// `|u_start - u_end|` of each cycle.
    pub range: Vec<f64>,
    /// `(u_start + u_end) / 2`.
    pub mean: Vec<f64>,
    /// 1.0 for a full cycle, 0.5 for a half cycle.
    pub count: Vec<f64>,
    /// Sample index of the reversal the cycle starts at.
    pub start: Vec<i64>,
    /// Sample index of the reversal the cycle turns at.
    pub end: Vec<i64>,
    /// Sample index of the closure, -1 for half cycles (with
    /// [`with_closures`](Self::with_closures)).
    pub closure: Vec<i64>,
    /// Interpolated position of the closure, NaN for half cycles (with
    /// [`with_closures`](Self::with_closures)).
    pub closure_position: Vec<f64>,
    /// Energies over the arc, NaN for half cycles and without a model (with
    /// [`with_energy`](Self::with_energy)): [`CycleEnergy`]'s fields.
    pub work: Vec<f64>,
    pub stored_energy_change: Vec<f64>,
    pub dissipation: Vec<f64>,
    pub closure_gap: Vec<f64>,
    keep_reversals: bool,
    keep_closures: bool,
    keep_energy: bool,
}

impl Default for CycleColumns {
    fn default() -> Self {
        Self::new()
    }
}

impl CycleColumns {
    /// Empty columns for reversals, cycles and closures (no energies).
    pub fn new() -> Self {
        Self {
            reversal_index: Vec::new(),
            reversal_u: Vec::new(),
            range: Vec::new(),
            mean: Vec::new(),
            count: Vec::new(),
            start: Vec::new(),
            end: Vec::new(),
            closure: Vec::new(),
            closure_position: Vec::new(),
            work: Vec::new(),
            stored_energy_change: Vec::new(),
            dissipation: Vec::new(),
            closure_gap: Vec::new(),
            keep_reversals: true,
            keep_closures: true,
            keep_energy: false,
        }
    }

    /// Whether to fill `reversal_index` and `reversal_u` (default: yes).
    pub fn with_reversals(mut self, keep: bool) -> Self {
        self.keep_reversals = keep;
        self
    }

    /// Whether to fill `closure` and `closure_position` (default: yes).
    pub fn with_closures(mut self, keep: bool) -> Self {
        self.keep_closures = keep;
        self
    }

    /// Whether to fill the energy columns (default: no).
    pub fn with_energy(mut self, keep: bool) -> Self {
        self.keep_energy = keep;
        self
    }

    /// Room for everything an `n`-sample history can produce (at most one reversal and one
    /// cycle per sample) in the columns kept, so that counting never reallocates. Large
    /// columns are backed by huge pages where the OS has them (feature `huge-pages`): writing
    /// fresh memory then takes one page fault per 2 MiB, and only the pages written are ever
    /// backed. [`shrink_to_fit`](Self::shrink_to_fit) trims them once counted.
    pub fn reserve_for_samples(&mut self, n: usize) {
        use crate::memory::column;
        if self.keep_reversals {
            (self.reversal_index, self.reversal_u) = (column(n), column(n));
        }
        (self.range, self.mean, self.count) = (column(n), column(n), column(n));
        (self.start, self.end) = (column(n), column(n));
        if self.keep_closures {
            (self.closure, self.closure_position) = (column(n), column(n));
        }
        if self.keep_energy {
            self.work = column(n);
            self.stored_energy_change = column(n);
            self.dissipation = column(n);
            self.closure_gap = column(n);
        }
    }

    /// Frees the room no row uses.
    pub fn shrink_to_fit(&mut self) {
        let (indices, reals) = self.all_columns();
        indices.into_iter().for_each(Vec::shrink_to_fit);
        reals.into_iter().for_each(Vec::shrink_to_fit);
    }

    /// Every column, the index columns and the real ones.
    #[allow(clippy::type_complexity)]
    fn all_columns(&mut self) -> ([&mut Vec<i64>; 4], [&mut Vec<f64>; 9]) {
        (
            [
                &mut self.reversal_index,
                &mut self.start,
                &mut self.end,
                &mut self.closure,
            ],
            [
                &mut self.reversal_u,
                &mut self.range,
                &mut self.mean,
                &mut self.count,
                &mut self.closure_position,
                &mut self.work,
                &mut self.stored_energy_change,
                &mut self.dissipation,
                &mut self.closure_gap,
            ],
        )
    }

    pub fn keeps_reversals(&self) -> bool {
        self.keep_reversals
    }

    pub fn keeps_closures(&self) -> bool {
        self.keep_closures
    }

    pub fn keeps_energy(&self) -> bool {
        self.keep_energy
    }

    /// Empties every column, keeping its memory (to count another history, or to take the
    /// next piece of a long one after writing this one out).
    pub fn clear(&mut self) {
        let (indices, reals) = self.all_columns();
        indices.into_iter().for_each(Vec::clear);
        reals.into_iter().for_each(Vec::clear);
    }

    /// Cycle `k` back from the columns (its energy, where kept, without the states `y_start`
    /// and `y_closure`, which are not columns: NaN).
    pub fn cycle_at(&self, k: usize) -> Cycle {
        let closure = (self.keep_closures && self.closure[k] >= 0).then(|| Closure {
            index: self.closure[k] as u64,
            position: self.closure_position[k],
        });
        let energy = (self.keep_energy && !self.work[k].is_nan()).then(|| CycleEnergy {
            arc: ArcEnergy {
                work: self.work[k],
                stored_energy_change: self.stored_energy_change[k],
                dissipation: self.dissipation[k],
                closure_gap: self.closure_gap[k],
            },
            y_start: f64::NAN,
            y_closure: f64::NAN,
        });
        Cycle {
            range: self.range[k],
            mean: self.mean[k],
            count: self.count[k],
            start: self.start[k] as u64,
            end: self.end[k] as u64,
            closure,
            energy,
        }
    }

    /// The number of cycles held.
    pub fn len(&self) -> usize {
        self.range.len()
    }

    pub fn is_empty(&self) -> bool {
        self.range.is_empty()
    }

    /// The reversals found by the block path, in order.
    pub(crate) fn extend_reversals(&mut self, found: &[(u64, f64)]) {
        if self.keep_reversals {
            self.reversal_index
                .extend(found.iter().map(|&(i, _)| i as i64));
            self.reversal_u.extend(found.iter().map(|&(_, u)| u));
        }
    }

    /// Full cycles `(u_A, u_B)` found by the block path, in the order they close, with their
    /// closures (`closure(k)` for the `k`-th, called only when closures are kept). The
    /// cycle's fields are computed as [`Cycle`]'s.
    pub(crate) fn extend_full(
        &mut self,
        full: &[FullCycle],
        mut closure: impl FnMut(&FullCycle) -> super::Closure,
    ) {
        self.range
            .extend(full.iter().map(|c| (c.a_u - c.b_u).abs()));
        self.mean.extend(full.iter().map(|c| 0.5 * (c.a_u + c.b_u)));
        self.count.extend(full.iter().map(|_| 1.0));
        self.start.extend(full.iter().map(|c| c.a_index as i64));
        self.end.extend(full.iter().map(|c| c.b_index as i64));
        if self.keep_closures {
            for c in full {
                let k = closure(c);
                self.closure.push(k.index as i64);
                self.closure_position.push(k.position);
            }
        }
        if self.keep_energy {
            // The block path runs without energies.
            for col in [
                &mut self.work,
                &mut self.stored_energy_change,
                &mut self.dissipation,
                &mut self.closure_gap,
            ] {
                col.extend(full.iter().map(|_| f64::NAN));
            }
        }
    }
}

/// A full cycle found by the block path: its start `A`, its turn `B`, and where the reversal
/// `P` that closed it is in the block's reversal buffer (`closer`; the run into `P`, where the
/// closure lies, begins after the reversal before it there).
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct FullCycle {
    pub a_index: u64,
    pub a_u: f64,
    pub b_index: u64,
    pub b_u: f64,
    pub closer: usize,
}

impl CycleSink for CycleColumns {
    fn reversal(&mut self, r: Reversal) {
        if self.keep_reversals {
            self.reversal_index.push(r.index as i64);
            self.reversal_u.push(r.u);
        }
    }

    fn cycle(&mut self, c: Cycle) {
        self.range.push(c.range);
        self.mean.push(c.mean);
        self.count.push(c.count);
        self.start.push(c.start as i64);
        self.end.push(c.end as i64);
        if self.keep_closures {
            self.closure.push(c.closure.map_or(-1, |k| k.index as i64));
            self.closure_position
                .push(c.closure.map_or(f64::NAN, |k| k.position));
        }
        if self.keep_energy {
            let e = c.energy;
            self.work.push(e.map_or(f64::NAN, |e| e.arc.work));
            self.stored_energy_change
                .push(e.map_or(f64::NAN, |e| e.arc.stored_energy_change));
            self.dissipation
                .push(e.map_or(f64::NAN, |e| e.arc.dissipation));
            self.closure_gap
                .push(e.map_or(f64::NAN, |e| e.arc.closure_gap));
        }
    }

    fn columns(&mut self) -> Option<&mut CycleColumns> {
        Some(self)
    }
}
