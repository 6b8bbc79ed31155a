//! The energies of the rainflow cycles of a measured history along the path of a model of the
//! zoo, from rest at the first sample: the history's samples joined by straight lines, each
//! step one monotone segment of the model's exact map.
//!
//! Dissipation adds along the path, so one walk gives it all: with `D(P)` the dissipation from
//! the first sample to the point `P`, a cycle from its start `A` to its closure `C` (where the
//! history is back at `u_A`) has
//!
//! ```text
//! (H1)  D = D(C) - D(A),   dV = V(C) - V(A) (from the two states),   W = dV + D
//! ```
//!
//! `D(P)` is summed in double-double arithmetic, so that the difference keeps its digits
//! however long the history before `A`. The states at the open cycles' starts are kept until
//! their closures (as many as the rainflow stack holds).

use super::{Segmental, ZooModel};
use crate::cycles::chunk::ArcSpan;
use crate::cycles::{
    Collect, Cycle, CycleCounter, CycleEnergy, CycleSink, CycleSummary, HistoryEnergy,
};
use crate::error::HistoryError;
use crate::kernel::numerics::DoubleDouble;

/// The most samples a history may have for the energies of a model of the zoo: the history,
/// its reversals and cycles are held in memory (the states at the open cycles' starts are kept
/// until their closures), about 200 bytes a sample at most. Every front end refuses more with
/// [`HistoryError::HeldTooLong`] ([`check_held`]).
pub const MAX_HISTORY_SAMPLES: usize = 1 << 27;

/// Refuses a history of `samples` samples for the energies of `model` when it is longer than
/// [`MAX_HISTORY_SAMPLES`] (a reader calls it before holding more).
pub fn check_held(model: &ZooModel, samples: usize) -> Result<(), HistoryError> {
    if samples > MAX_HISTORY_SAMPLES {
        return Err(HistoryError::HeldTooLong {
            limit: MAX_HISTORY_SAMPLES,
            model: model.spec().label,
        });
    }
    Ok(())
}

/// Reversals and rainflow cycles of `u` with the noise gate `gate`, every full cycle with its
/// energies along the path of `model` from rest at `u[0]`, passed to `sink` (reversals first,
/// then the cycles in the order they close, as [`CycleCounter`] passes them); returns the
/// summary with the totals along the history. What `lugre cycles --model NAME` reports.
pub(crate) fn count(
    model: &ZooModel,
    u: &[f64],
    gate: f64,
    sink: &mut impl CycleSink,
) -> Result<CycleSummary, HistoryError> {
    check_held(model, u.len())?;
    let mut counter = CycleCounter::new(gate)?;
    let mut history = Collect::default();
    counter.push_all(u, &mut history)?;
    let mut summary = counter.finish(&mut history)?;
    let totals = model.cycle_energies(u, &mut history.cycles);
    check_energies(&history.cycles)?;
    totals.check_finite()?;
    summary.energy = Some(totals);
    for r in history.reversals {
        sink.reversal(r);
    }
    for c in history.cycles {
        sink.cycle(c);
    }
    Ok(summary)
}

/// Refuses energies that overflowed (naming the cycle's closure).
pub(crate) fn check_energies(cycles: &[Cycle]) -> Result<(), HistoryError> {
    for c in cycles {
        let Some(e) = c.energy else { continue };
        let a = e.arc;
        let values = [a.work, a.stored_energy_change, a.dissipation, a.closure_gap];
        if !values
            .iter()
            .chain(&[e.y_start, e.y_closure])
            .all(|x| x.is_finite())
        {
            let index = c.closure.map_or(c.end, |k| k.index);
            return Err(HistoryError::EnergyOverflow { index });
        }
    }
    Ok(())
}

/// What a walk opens at one sample and closes at a later one: a full cycle of the slice it
/// fills, or the part of an arc across chunks ([`ArcSpan`]).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Mark {
    Cycle(usize),
    Span(usize),
}

/// A state kept until its mark closes: the mark, the state (none for a span from the chunk's
/// entry), `D` there.
type Open<S> = (Mark, Option<S>, DoubleDouble);

/// The part of an arc inside one chunk ([`ArcSpan`]): the dissipation along it (double-double),
/// the state at `A` where it starts there, at `C` where it ends there.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct WalkedSpan<S> {
    pub id: usize,
    pub d: DoubleDouble,
    pub from: Option<S>,
    pub to: Option<S>,
}

/// What a walk over a chunk ends with: the state at its last sample, the dissipation along all
/// its pieces, the parts of the arcs across it.
pub(crate) struct Walked<S> {
    pub end: S,
    pub d: DoubleDouble,
    pub spans: Vec<WalkedSpan<S>>,
}

/// Fills `energy` of every full cycle of `cycles` (counted on `u`, the history) along the path
/// of `model` from `start` (its state at `u[0]`), and returns the totals over the history.
pub(crate) fn cycle_energies<M: Segmental>(
    model: &M,
    start: M::State,
    u: &[f64],
    cycles: &mut [Cycle],
) -> HistoryEnergy {
    let w = walk(model, start.clone(), u, 0, None, cycles, &[]);
    totals(model, &start, &w.end, w.d)
}

/// The totals (H1) over a path from `first` to `end` with dissipation `d` along it.
pub(crate) fn totals<M: Segmental>(
    model: &M,
    first: &M::State,
    end: &M::State,
    d: DoubleDouble,
) -> HistoryEnergy {
    let arc = model.arc(first, end, d.to_f64());
    HistoryEnergy {
        y_start: model.force(first),
        y_end: model.force(end),
        work: arc.work,
        stored_energy_change: arc.stored_energy_change,
        dissipation: arc.dissipation,
    }
}

/// Walks `model` over the chunk `u` (first sample at `offset`; `prev` the sample before it,
/// `None` for the history's first chunk) from `entry`, its state at `prev` (or at `u[0]`),
/// filling `energy` of every full cycle of `cycles` (global indices, inside the chunk) by
/// (H1) with `D` counted from the entry, and summing the parts of the arcs `spans`. The single
/// pass is the walk over the whole history from rest.
pub(crate) fn walk<M: Segmental>(
    model: &M,
    entry: M::State,
    u: &[f64],
    offset: u64,
    prev: Option<f64>,
    cycles: &mut [Cycle],
    spans: &[ArcSpan],
) -> Walked<M::State> {
    let Marks {
        opens,
        closes,
        mut open,
    } = Marks::of(u, offset, cycles, spans);
    let mut state = entry;
    let mut d = DoubleDouble::ZERO;
    let mut parts = Vec::new();
    let (mut next_open, mut next_close) = (0, 0);
    for (k, &x) in u.iter().enumerate() {
        let k = k as u64;
        if k > 0 || prev.is_some() {
            // The step's start on its exact relation, shared by the marks closing on it.
            let start = model.start(&state, x);
            while let Some(&(_, mark, u_a)) = closes.get(next_close).filter(|c| c.0 <= k) {
                next_close += 1;
                let here = (&state, &start, d);
                close_mark(model, (mark, u_a), &mut open, here, cycles, &mut parts);
            }
            d = d.add_f64(model.advance_from(&start, &mut state, x));
        }
        while let Some(&(_, mark)) = opens.get(next_open).filter(|o| o.0 == k) {
            next_open += 1;
            open.push((mark, Some(state.clone()), d));
        }
    }
    // The spans that run to the chunk's end.
    parts.extend(open.into_iter().filter_map(|(mark, a, d_a)| match mark {
        Mark::Span(id) => Some(WalkedSpan {
            id,
            d: d - d_a,
            from: a,
            to: None,
        }),
        Mark::Cycle(_) => None,
    }));
    Walked {
        end: state,
        d,
        spans: parts,
    }
}

/// A walk's marks: where each opens (local sample, sorted), where each closes (local sample,
/// sorted; on the step into it, cut at the start's value), and those open at the chunk's
/// entry (the spans from an earlier chunk).
struct Marks<S> {
    opens: Vec<(u64, Mark)>,
    closes: Vec<(u64, Mark, f64)>,
    open: Vec<Open<S>>,
}

impl<S> Marks<S> {
    /// The marks of the full cycles of `cycles` and of the arcs `spans` over the chunk `u`
    /// whose first sample is at `offset`.
    fn of(u: &[f64], offset: u64, cycles: &[Cycle], spans: &[ArcSpan]) -> Self {
        let mut opens: Vec<(u64, Mark)> = Vec::new();
        let mut closes: Vec<(u64, Mark, f64)> = Vec::new();
        let mut open: Vec<Open<S>> = Vec::new();
        for (i, c) in cycles.iter().enumerate() {
            if let Some(k) = c.closure {
                let a = c.start - offset;
                opens.push((a, Mark::Cycle(i)));
                closes.push((k.index - offset, Mark::Cycle(i), u[a as usize]));
            }
        }
        for s in spans {
            match s.from {
                Some(a) => opens.push((a - offset, Mark::Span(s.id))),
                None => open.push((Mark::Span(s.id), None, DoubleDouble::ZERO)),
            }
            if let Some((c, u_a)) = s.to {
                closes.push((c - offset, Mark::Span(s.id), u_a));
            }
        }
        opens.sort_by_key(|o| o.0);
        closes.sort_by_key(|c| c.0);
        Self {
            opens,
            closes,
            open,
        }
    }
}

/// Closes `mark` (if open) on the step from the walk's `state` (with `D = d` there, the
/// step's start `start`) to `u_a`, its start's value: a cycle's energy (H1) is filled, a
/// span's part kept.
#[inline]
fn close_mark<M: Segmental>(
    model: &M,
    (mark, u_a): (Mark, f64),
    open: &mut Vec<Open<M::State>>,
    (state, start, d): (&M::State, &M::Start, DoubleDouble),
    cycles: &mut [Cycle],
    parts: &mut Vec<WalkedSpan<M::State>>,
) {
    let Some(at) = open.iter().position(|o| o.0 == mark) else {
        return;
    };
    let (_, a, d_a) = open.swap_remove(at);
    let mut c = state.clone();
    let d_c = d.add_f64(model.advance_from(start, &mut c, u_a));
    match mark {
        Mark::Cycle(i) => close(model, a, c, d_c - d_a, &mut cycles[i]),
        Mark::Span(id) => parts.push(WalkedSpan {
            id,
            d: d_c - d_a,
            from: a,
            to: Some(c),
        }),
    }
}

/// The energy (H1) of `cycle` from the state `a` at its start to `c` at its closure, with
/// dissipation `d` between.
fn close<M: Segmental>(
    model: &M,
    a: Option<M::State>,
    c: M::State,
    d: DoubleDouble,
    cycle: &mut Cycle,
) {
    if let Some(a) = a {
        cycle.energy = Some(arc_energy(model, &a, &c, d.to_f64()));
    }
}

/// The energies (H1) of an arc from the state `a` to `c` with dissipation `d` along it.
pub(crate) fn arc_energy<M: Segmental>(
    model: &M,
    a: &M::State,
    c: &M::State,
    d: f64,
) -> CycleEnergy {
    CycleEnergy {
        arc: model.arc(a, c, d),
        y_start: model.force(a),
        y_closure: model.force(c),
    }
}
