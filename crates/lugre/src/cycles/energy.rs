//! The rate-independent response `y*` along a history (paper eq. 6, from `y*(0) = sigma0 x0`)
//! and the energies over each full cycle's arc, by the closed forms of [`crate::loops`].
//!
//! Samples are joined by straight lines, so each step is one piece of the normalized input
//! (direction `s`, length `l = |du|`) and `y*` advances exactly, at any stiffness. Over a piece
//! from `y_k` the work is `s y_k c + e` with `(c, e)` from `hysteresis::piece`. The sums over
//! an arc's pieces ([`crate::kernel::arc::Sums`]) give its work, stored-energy change,
//! dissipation and closure gap in O(1) per cycle without keeping samples, each in the form
//! that rounds least (`kernel::arc`).
//!
//! Sums are kept per stack segment, from one open reversal to the next (and from the top one
//! to the current sample), never from the start of the history: the rounding of a sum then
//! scales with the arc it covers, not with the 10^8 samples before it. A cycle's sums are the
//! segments above its start reversal plus the current run up to the closure.

use super::engine::{Open, Track};
use super::{CycleEnergy, HistoryEnergy};
use crate::error::HistoryError;
use crate::kernel::arc::{arc_energy, Sums};
use crate::kernel::numerics::DoubleDouble;
use crate::kernel::piece::step;
use crate::model::RateIndependent;

/// `y*` at a sample and the sums from the reversal below it on the stack (for a stack entry)
/// or from the top of the stack (for a sample of the current run).
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct State {
    y: f64,
    sums: Sums,
}

#[derive(Debug, Clone, Copy, Default)]
struct Point {
    u: f64,
    state: State,
}

/// Tracks `y*` and the sums along the history.
#[derive(Debug, Clone)]
pub(crate) struct EnergyTrack {
    model: RateIndependent,
    y0: f64,
    prev: Point,
    cur: Point,
    /// Work and dissipation from the first sample (for the summary).
    total_work: DoubleDouble,
    total_dissipation: DoubleDouble,
    /// For a chunk of a longer history: the sample before it and `y*` there (the first
    /// piece runs from it to the chunk's first sample).
    entry: Option<(f64, f64)>,
    /// Observer (opt-in): the sums between given samples.
    cuts: Option<Box<CutSums>>,
}

/// The sums of the pieces between given samples ("cuts"), recorded along the walk: what a
/// chunk contributes to the arcs of cycles that span chunks (`cycles::chunk`).
#[derive(Debug, Clone, Default)]
pub(crate) struct CutSums {
    /// Local sample indices, increasing: a stretch ends after the piece into each.
    cuts: Vec<u64>,
    next: usize,
    seg: Sums,
    /// The sums of each stretch and `y*` at its cut.
    pub stretches: Vec<(Sums, f64)>,
}

impl CutSums {
    pub fn new(cuts: Vec<u64>) -> Self {
        Self {
            stretches: Vec::with_capacity(cuts.len()),
            cuts,
            ..Self::default()
        }
    }

    #[inline]
    fn record(&mut self, index: u64, terms: Sums, y: f64) {
        self.seg = self.seg + terms;
        if self.cuts.get(self.next) == Some(&index) {
            self.stretches.push((self.seg, y));
            self.seg = Sums::default();
            self.next += 1;
        }
    }
}

impl EnergyTrack {
    /// `|sigma0 x0| <= g0`: the bristle state starts in the set the model keeps it in (for
    /// Dahl, `|w(0)| <= 1`).
    pub fn new(model: RateIndependent, x0: f64) -> Result<Self, HistoryError> {
        let y0 = model.sigma0() * x0;
        if y0.is_nan() || y0.abs() > model.g0() {
            return Err(HistoryError::BadInitialState {
                x0,
                sigma0: model.sigma0(),
                g0: model.g0(),
            });
        }
        Ok(Self::starting(model, y0, None, None))
    }

    fn starting(
        model: RateIndependent,
        y0: f64,
        entry: Option<(f64, f64)>,
        cuts: Option<Box<CutSums>>,
    ) -> Self {
        Self {
            model,
            y0,
            prev: Point::default(),
            cur: Point::default(),
            total_work: DoubleDouble::ZERO,
            total_dissipation: DoubleDouble::ZERO,
            entry,
            cuts,
        }
    }

    /// A track for a chunk of a longer history: the sample before it is `prev`, where
    /// `y* = y_entry` (the single pass's value), or, without `prev`, `y* = y_entry` at the
    /// first sample. The totals count the piece from `prev` in; `cuts` records the sums
    /// between the local sample indices given.
    pub fn for_chunk(
        model: RateIndependent,
        y_entry: f64,
        prev: Option<f64>,
        cuts: CutSums,
    ) -> Self {
        let entry = prev.map(|p| (p, y_entry));
        Self::starting(model, y_entry, entry, Some(Box::new(cuts)))
    }

    /// Work and dissipation along the pieces taken, `y*` at the last sample, and the
    /// recorded stretches.
    pub fn chunk_totals(self) -> (DoubleDouble, DoubleDouble, f64, Vec<(Sums, f64)>) {
        let stretches = self.cuts.map(|c| c.stretches).unwrap_or_default();
        (
            self.total_work,
            self.total_dissipation,
            self.cur.state.y,
            stretches,
        )
    }

    /// Totals over the whole history.
    pub fn summary(&self) -> HistoryEnergy {
        let y_end = self.cur.state.y;
        HistoryEnergy {
            y_start: self.y0,
            y_end,
            work: self.total_work.to_f64(),
            stored_energy_change: (y_end - self.y0) * (y_end + self.y0)
                / (2.0 * self.model.sigma0()),
            dissipation: self.total_dissipation.to_f64().max(0.0),
        }
    }
}

impl Track for EnergyTrack {
    type State = State;
    type Energy = Option<CycleEnergy>;
    const BLOCKS: bool = false;

    #[inline]
    fn sample(&mut self, index: u64, u: f64) {
        let model = self.model.relaxation();
        if index == 0 {
            let (mut y, mut terms) = (self.y0, Sums::default());
            if let Some((p, y_p)) = self.entry {
                // A chunk's first piece, from the sample before it: in the totals, and in
                // the first stretch, not in the rainflow stack's sums (its arcs start here).
                let (s, l) = step(p, u);
                let (t, w, d, y_end) = Sums::piece_terms(model, y_p, s, l);
                (y, terms) = (y_end, t);
                self.total_work = w;
                self.total_dissipation = DoubleDouble::ZERO.add_f64(d);
            }
            if let Some(c) = &mut self.cuts {
                c.record(0, terms, y);
            }
            self.cur = Point {
                u,
                state: State {
                    y,
                    sums: Sums::default(),
                },
            };
            self.prev = self.cur;
            return;
        }
        self.prev = self.cur;
        let y = self.prev.state.y;
        let (s, l) = step(self.prev.u, u);
        let (terms, w, d, y_end) = Sums::piece_terms(model, y, s, l);
        self.total_work = self.total_work + w;
        self.total_dissipation = self.total_dissipation.add_f64(d);
        if let Some(c) = &mut self.cuts {
            c.record(index, terms, y_end);
        }
        self.cur = Point {
            u,
            state: State {
                y: y_end,
                sums: self.prev.state.sums + terms,
            },
        };
    }

    #[inline]
    fn state(&self) -> State {
        self.cur.state
    }

    #[inline]
    fn confirm(&mut self, c: &State) {
        self.prev.state.sums = self.prev.state.sums - c.sums;
        self.cur.state.sums = self.cur.state.sums - c.sums;
    }

    #[inline]
    fn merge(a: &State, b: &State, p: &State) -> State {
        State {
            y: p.y,
            sums: a.sums + b.sums + p.sums,
        }
    }

    fn closure(
        &self,
        stack: &[Open<State, Option<CycleEnergy>>],
        start: usize,
        index: u64,
        frac: f64,
    ) -> Result<Option<CycleEnergy>, HistoryError> {
        let model = self.model.relaxation();
        let a = &stack[start];
        let mut sums = self.prev.state.sums;
        for entry in &stack[start + 1..] {
            sums = sums + entry.state.sums;
        }
        // The last piece, from the previous sample to the closure.
        let (s, full) = step(self.prev.u, self.cur.u);
        let l = if frac >= 1.0 {
            full
        } else if frac <= 0.0 {
            0.0
        } else {
            (a.u - self.prev.u).abs().min(full)
        };
        let y_prev = self.prev.state.y;
        let (_, _, y_end) = sums.add_piece(model, y_prev, s, l);

        let y_a = a.state.y;
        let e = arc_energy(model, &sums, y_a, y_end);
        let energy = CycleEnergy {
            arc: e,
            y_start: y_a,
            y_closure: y_end,
        };
        let finite = [
            energy.arc.work,
            energy.arc.stored_energy_change,
            energy.arc.dissipation,
            energy.arc.closure_gap,
            energy.y_closure,
        ]
        .iter()
        .all(|v| v.is_finite());
        if !finite {
            return Err(HistoryError::EnergyOverflow { index });
        }
        Ok(Some(energy))
    }

    #[inline]
    fn report(e: Option<CycleEnergy>) -> Option<CycleEnergy> {
        e
    }
}
