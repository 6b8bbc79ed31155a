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
    for c in &history.cycles {
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

/// A start state kept until its cycle closes: the cycle's index, the state, `D(A)`.
type Open<S> = (usize, S, DoubleDouble);

/// Fills `energy` of every full cycle of `cycles` (counted on `u`, the history) along the path
/// of `model` from `start` (its state at `u[0]`), and returns the totals over the history.
pub(crate) fn cycle_energies<M: Segmental>(
    model: &M,
    start: M::State,
    u: &[f64],
    cycles: &mut [Cycle],
) -> HistoryEnergy {
    // Full cycles by start sample, and by closure (index, then position along the step).
    let mut by_start: Vec<usize> = (0..cycles.len())
        .filter(|&i| cycles[i].closure.is_some())
        .collect();
    by_start.sort_by_key(|&i| cycles[i].start);
    let mut by_closure = by_start.clone();
    by_closure.sort_by(|&a, &b| {
        let (ca, cb) = (
            cycles[a].closure.unwrap_or_else(no_closure),
            cycles[b].closure.unwrap_or_else(no_closure),
        );
        ca.index
            .cmp(&cb.index)
            .then(ca.position.total_cmp(&cb.position))
    });
    let first = start.clone();
    let mut state = start;
    let mut d = DoubleDouble::ZERO;
    let mut open: Vec<Open<M::State>> = Vec::new();
    let (mut next_start, mut next_closure) = (0, 0);
    for k in 0..u.len() {
        if k > 0 {
            while let Some(&i) = by_closure.get(next_closure) {
                if cycles[i].closure.is_none_or(|c| c.index != k as u64) {
                    break;
                }
                next_closure += 1;
                close(model, &state, &d, u, &mut open, &mut cycles[i], i);
            }
            d = d.add_f64(model.advance(&mut state, u[k]));
        }
        while let Some(&i) = by_start.get(next_start) {
            if cycles[i].start != k as u64 {
                break;
            }
            next_start += 1;
            open.push((i, state.clone(), d));
        }
    }
    let arc = model.arc(&first, &state, d.to_f64());
    HistoryEnergy {
        y_start: model.force(&first),
        y_end: model.force(&state),
        work: arc.work,
        stored_energy_change: arc.stored_energy_change,
        dissipation: arc.dissipation,
    }
}

fn no_closure() -> crate::cycles::Closure {
    crate::cycles::Closure {
        index: u64::MAX,
        position: f64::INFINITY,
    }
}

/// The energy (H1) of cycle `i`, closing on the step into sample `index` from `state` (at the
/// sample before it, where the dissipation so far is `d`).
fn close<M: Segmental>(
    model: &M,
    state: &M::State,
    d: &DoubleDouble,
    u: &[f64],
    open: &mut Vec<Open<M::State>>,
    cycle: &mut Cycle,
    i: usize,
) {
    let Some(at) = open.iter().position(|(j, _, _)| *j == i) else {
        return;
    };
    let (_, a, d_a) = open.swap_remove(at);
    let mut c = state.clone();
    let d_c = d.add_f64(model.advance(&mut c, u[cycle.start as usize]));
    let dissipation = (d_c - d_a).to_f64();
    cycle.energy = Some(CycleEnergy {
        arc: model.arc(&a, &c, dissipation),
        y_start: model.force(&a),
        y_closure: model.force(&c),
    });
}
