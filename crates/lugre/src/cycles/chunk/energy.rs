//! Energies of a chunked count: `y*` (paper eq. 6) at each chunk's start, each chunk's own
//! cycles counted with energies from there, and the arcs of the cycles found at merges summed
//! from the pieces each chunk contributes.
//!
//! # `y*` at a chunk's start
//!
//! Over a piece of the input, `y*` moves by the affine contraction `y -> y e^{-a l} + s sigma0
//! l phi(a l)` (`a = sigma0 / g0`), so the state at a chunk's last sample depends on the
//! state it entered with only through a factor `e^{-a L}` (`L` the chunk's path length), and
//! every state lies in `[-g0, g0]`. [`state_bounds`] runs each chunk from both bounds with the
//! single pass's piece function: where the two runs land on the same double, that double is
//! the next chunk's entry state up to rounding (the rounded map is not exactly monotone:
//! the proptests find states a few ulps off); elsewhere [`guess_entries`] interpolates. The
//! energy passes run in parallel from these guesses and are then *verified* in order: chunk
//! 0 enters at `sigma0 x0` exactly; a chunk whose guess equals the exact state the previous
//! chunk's pass ended at is exact; one whose guess differs is counted again from that state.
//! So the states, and everything computed from them, are the single pass's bit for bit
//! always; the guesses only decide how much runs in parallel (on a record whose chunks each
//! travel `a L >> 40`, every guess holds).
//!
//! # Arcs across chunks
//!
//! A cycle `(A, B)` found at a merge closes at `C` in a later chunk (or in `A`'s own). Its
//! arc's sums ([`ArcSums`], the double-double sums of `kernel::arc`) are the pieces from `A`
//! to the end of `A`'s chunk, the totals of the chunks in between, and the pieces from the
//! start of `C`'s chunk to `C` (the last one cut at `u = u_A` as the single pass cuts it).
//! Each chunk's energy pass ([`count_chunk_energy`]) returns its part of every arc that
//! crosses it ([`ArcSpan`]); [`ChunkPlan::attach_energy`](super::ChunkPlan::attach_energy)
//! adds them up and forms the energies. The sums are added in a different order than the
//! single pass adds them (which keeps running sums per stack segment), so a cycle's energies
//! agree with the single pass to the double-double sums' rounding before the final one: in
//! practice bit for bit, and within a few units in the last place otherwise.

use super::super::engine::Track;
use super::super::engine::{admissible, bad_sample, closure_at};
use super::super::{CutSums, CycleColumns, CycleEnergy, EnergyTrack, Engine, HistoryEnergy};
use super::Reader;
use crate::error::HistoryError;
use crate::kernel::arc::{arc_energy, Sums, LANES};
use crate::kernel::numerics::DoubleDouble;
use crate::kernel::piece::{piece, step};
use crate::model::RateIndependent;

/// `y*` at a chunk's last sample from the two extreme states it could enter with: `+g0`
/// (`upper`) and `-g0` (`lower`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StateBounds {
    pub upper: f64,
    pub lower: f64,
}

impl StateBounds {
    /// The state at the chunk's last sample when both runs agree (whatever the state before).
    pub fn certified(&self) -> Option<f64> {
        (self.upper == self.lower).then_some(self.upper)
    }
}

/// The double-double sums over some pieces of an arc (opaque; added with `+`).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ArcSums(Sums);

impl std::ops::Add for ArcSums {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Self(self.0 + o.0)
    }
}

/// Checks that `y` (the argument `name`) is a state `y*` can hold: finite, `|y| <= g0`.
fn check_state(name: &'static str, y: f64, model: RateIndependent) -> Result<(), HistoryError> {
    if y.abs() <= model.g0() {
        Ok(())
    } else {
        Err(HistoryError::BadEntryState {
            name,
            value: y,
            g0: model.g0(),
        })
    }
}

/// `y*` after the piece from `from` to `to` entered at `y` (the single pass's step).
#[inline]
fn advance(model: RateIndependent, y: f64, from: f64, to: f64) -> f64 {
    let (s, l) = step(from, to);
    piece(model.relaxation(), y, s, l).y_end
}

/// Runs the chunk `u` (first sample at `offset`, `prev` the sample before it) from `y* = +g0`
/// and from `-g0` at its entry: the last sample's state from each. The entry is the sample
/// before the chunk (the first piece is `prev -> u[0]`), or the first sample when `prev` is
/// `None`.
pub fn state_bounds(
    u: &[f64],
    offset: u64,
    prev: Option<f64>,
    model: RateIndependent,
) -> Result<StateBounds, HistoryError> {
    let g0 = model.g0();
    bounds_walk(u, offset, prev, (-g0, g0), |y, from, to| {
        advance(model, y, from, to)
    })
}

/// Runs the chunk `u` (first sample at `offset`, `prev` the sample before it) from the two
/// extreme states `hi` and `lo` of a model with one state, moved along each piece `from -> to`
/// by `advance(state, from, to)` (monotone in the state): the last sample's state from each
/// ([`state_bounds`] for LuGre's `y*`, the zoo's single-state models alike).
pub(crate) fn bounds_walk(
    u: &[f64],
    offset: u64,
    prev: Option<f64>,
    (lo, hi): (f64, f64),
    advance: impl Fn(f64, f64, f64) -> f64,
) -> Result<StateBounds, HistoryError> {
    super::check_offset(offset, u.len())?;
    super::check_prev(offset, prev)?;
    let (mut upper, mut lower) = (hi, lo);
    let mut from = prev;
    for (i, &x) in u.iter().enumerate() {
        if !admissible(x) {
            return Err(bad_sample(offset + i as u64, x));
        }
        if let Some(p) = from {
            // Once equal, equal for good: one run.
            let same = lower == upper;
            upper = advance(upper, p, x);
            lower = if same { upper } else { advance(lower, p, x) };
        }
        from = Some(x);
    }
    Ok(StateBounds { upper, lower })
}

/// Guesses of every chunk's entry state (chunk 0: `y_start`, exact) from the chunks'
/// [`state_bounds`] (in order; the last one is not needed): the certified value where the
/// bounds agree, else the affine interpolation between them at the previous guess (clamped to
/// `[-g0, g0]`). `y_start` must be a state `y*` can hold (finite, in `[-g0, g0]`), the bounds
/// finite.
pub fn guess_entries(
    model: RateIndependent,
    y_start: f64,
    bounds: &[StateBounds],
) -> Result<Vec<f64>, HistoryError> {
    let g0 = model.g0();
    check_state("y_start", y_start, model)?;
    guess_within((-g0, g0), y_start, bounds)
}

/// The guesses of [`guess_entries`] for a state in `[lo, hi]` entering the history at `start`
/// (the bounds must be finite): the certified value where a chunk's bounds agree, else the
/// affine interpolation between them at the previous guess, clamped to `[lo, hi]`.
pub(crate) fn guess_within(
    (lo, hi): (f64, f64),
    start: f64,
    bounds: &[StateBounds],
) -> Result<Vec<f64>, HistoryError> {
    if let Some(index) = bounds
        .iter()
        .position(|b| !(b.upper.is_finite() && b.lower.is_finite()))
    {
        let b = bounds[index];
        return Err(HistoryError::BadStateBounds {
            index,
            upper: b.upper,
            lower: b.lower,
        });
    }
    let mut y = start;
    let mut out = Vec::with_capacity(bounds.len());
    for b in bounds {
        out.push(y);
        y = b.certified().unwrap_or_else(|| {
            let t = (y - lo) / (hi - lo);
            (b.lower + t * (b.upper - b.lower)).clamp(lo, hi)
        });
    }
    Ok(out)
}

/// The part of a merge-time cycle's arc inside one chunk: from `A` (`from`, a sample of this
/// chunk) or from the chunk's entry (`None`), to the closure `C` (`to`: its sample index and
/// the cycle's start value `u_A`, where the last piece is cut) or to the chunk's last sample
/// (`None`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArcSpan {
    pub id: usize,
    pub from: Option<u64>,
    pub to: Option<(u64, f64)>,
}

/// A chunk's part of an arc: its sums, `y*` at `A` (where the span starts at `A`) and at `C`
/// (where it ends at `C`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpanPart {
    pub id: usize,
    pub sums: ArcSums,
    pub y_from: Option<f64>,
    pub y_to: Option<f64>,
}

/// What a chunk's energy pass tells the driver: the parts of the arcs across it, the work and
/// dissipation along all its pieces (from the sample before it), and `y*` at its last sample.
#[derive(Debug, Clone, PartialEq)]
pub struct ChunkEnergy {
    pub parts: Vec<SpanPart>,
    work: DoubleDouble,
    dissipation: DoubleDouble,
    pub y_last: f64,
}

/// Counts the chunk `u` (first sample at `offset`, `prev` the sample before it) with energies,
/// entering at `y* = y_entry` (the state at `prev`, or at the first sample when `prev` is
/// `None`): its own rows as [`count_chunk`](super::count_chunk) gives them, with the energies
/// of the full cycles, and the parts of the arcs `spans`, in one walk.
pub fn count_chunk_energy(
    u: &[f64],
    offset: u64,
    prev: Option<f64>,
    y_entry: f64,
    model: RateIndependent,
    spans: &[ArcSpan],
) -> Result<(CycleColumns, ChunkEnergy), HistoryError> {
    let Some(&first) = u.first() else {
        return Err(HistoryError::EmptyChunk { start: offset });
    };
    super::check_offset(offset, u.len())?;
    super::check_prev(offset, prev)?;
    check_state("y_entry", y_entry, model)?;
    let cuts = cuts(offset, u.len() as u64 - 1, spans)?;
    let track = EnergyTrack::for_chunk(model, y_entry, prev, CutSums::new(cuts.clone()));
    let mut rows = CycleColumns::new().with_reversals(false).with_energy(true);
    let track = if u.iter().any(|&x| x != first) {
        rows.reserve_for_samples(u.len());
        // The engine itself (no gate), for the track it hands back.
        let mut engine = Engine::new(0.0, track)?.with_origin(offset);
        engine.push_slice(u, &mut rows)?;
        let track = engine.finish(&mut rows)?.track;
        rows.shrink_to_fit();
        track
    } else if !admissible(first) {
        return Err(bad_sample(offset, first));
    } else {
        // One value throughout: no reversal inside, only the walk.
        let mut track = track;
        for i in 0..u.len() as u64 {
            track.sample(i, first);
        }
        track
    };
    let (work, dissipation, y_last, stretches) = track.chunk_totals();
    let parts = span_parts(u, offset, prev, y_entry, model, spans, &cuts, &stretches)?;
    Ok((
        rows,
        ChunkEnergy {
            parts,
            work,
            dissipation,
            y_last,
        },
    ))
}

/// The walk's cuts: the local sample indices where a span starts (`A`) or before its closing
/// piece (`C - 1`), and the last sample; a span from the chunk's entry starts before every
/// piece (no cut needed).
fn cuts(offset: u64, last: u64, spans: &[ArcSpan]) -> Result<Vec<u64>, HistoryError> {
    let local = |i: u64| {
        i.checked_sub(offset)
            .filter(|&j| j <= last)
            .ok_or(HistoryError::BadSummary {
                why: "an arc's span lies outside its chunk",
            })
    };
    let mut cuts = vec![last];
    for s in spans {
        if let Some(a) = s.from {
            cuts.push(local(a)?);
        }
        if let Some((c, _)) = s.to {
            // A closure at the chunk's first sample closes on the piece into it.
            if let Some(j) = local(c)?.checked_sub(1) {
                cuts.push(j);
            }
        }
    }
    cuts.sort_unstable();
    cuts.dedup();
    Ok(cuts)
}

/// The spans' parts from the walk's stretches (`stretches[m]`: the pieces after cut `m - 1`
/// up to cut `m`, and `y*` at cut `m`).
#[allow(clippy::too_many_arguments)]
fn span_parts(
    u: &[f64],
    offset: u64,
    prev: Option<f64>,
    y_entry: f64,
    model: RateIndependent,
    spans: &[ArcSpan],
    cuts: &[u64],
    stretches: &[(Sums, f64)],
) -> Result<Vec<SpanPart>, HistoryError> {
    if stretches.len() != cuts.len() {
        return Err(HistoryError::BadSummary {
            why: "the walk missed a cut",
        });
    }
    // Position 0 is the chunk's entry (before every piece); position m + 1 is cut m.
    let pos = |j: Option<u64>| j.map_or(0, |j| 1 + cuts.partition_point(|&c| c < j));
    let y_at = |p: usize| if p == 0 { y_entry } else { stretches[p - 1].1 };
    let sum = |a: usize, b: usize| {
        stretches[a..b]
            .iter()
            .fold(Sums::default(), |acc, s| acc + s.0)
    };
    let mut parts = Vec::with_capacity(spans.len());
    for s in spans {
        let a = pos(s.from.map(|i| i - offset));
        let mut part = SpanPart {
            id: s.id,
            sums: ArcSums::default(),
            y_from: s.from.map(|_| y_at(a)),
            y_to: None,
        };
        match s.to {
            None => part.sums = ArcSums(sum(a, cuts.len())),
            Some((c, u_a)) => {
                let local = (c - offset) as usize;
                let b = pos(local.checked_sub(1).map(|j| j as u64));
                let before = match local {
                    0 => prev.ok_or(HistoryError::ClosureNotFound { end: c })?,
                    _ => u[local - 1],
                };
                let mut sums = sum(a, b);
                let (_, frac) = closure_at(c, u[local], before, u_a);
                let (dir, full) = step(before, u[local]);
                let l = cut_piece(frac, full, (u_a - before).abs());
                part.y_to = Some(sums.add_piece(model.relaxation(), y_at(b), dir, l).2);
                part.sums = ArcSums(sums);
            }
        }
        parts.push(part);
    }
    Ok(parts)
}

/// The length of the closing piece up to the closure, as the single pass cuts it.
fn cut_piece(frac: f64, full: f64, to_closure: f64) -> f64 {
    if frac >= 1.0 {
        full
    } else if frac <= 0.0 {
        0.0
    } else {
        to_closure.min(full)
    }
}

/// The energies of an arc from its summed parts, `y*` at `A` and at `C` (as the single pass
/// forms them); `closure` names the cycle in the error.
pub fn arc_energy_of(
    model: RateIndependent,
    sums: &ArcSums,
    y_a: f64,
    y_c: f64,
    closure: u64,
) -> Result<CycleEnergy, HistoryError> {
    let arc = arc_energy(model.relaxation(), &sums.0, y_a, y_c);
    let energy = CycleEnergy {
        arc,
        y_start: y_a,
        y_closure: y_c,
    };
    let finite = [arc.work, arc.stored_energy_change, arc.dissipation]
        .iter()
        .chain([arc.closure_gap, y_c].iter())
        .all(|v| v.is_finite());
    if !finite {
        return Err(HistoryError::EnergyOverflow { index: closure });
    }
    Ok(energy)
}

/// The history's totals from its chunks' energy passes, in order, entering at `y_start` (a
/// state `y*` can hold).
pub fn history_energy(
    model: RateIndependent,
    y_start: f64,
    chunks: &[ChunkEnergy],
) -> Result<HistoryEnergy, HistoryError> {
    check_state("y_start", y_start, model)?;
    let (mut work, mut dissipation) = (DoubleDouble::ZERO, DoubleDouble::ZERO);
    for c in chunks {
        work = work + c.work;
        dissipation = dissipation + c.dissipation;
    }
    let y_end = chunks.last().map_or(y_start, |c| c.y_last);
    Ok(HistoryEnergy {
        y_start,
        y_end,
        work: work.to_f64(),
        stored_energy_change: (y_end - y_start) * (y_end + y_start) / (2.0 * model.sigma0()),
        dissipation: dissipation.to_f64().max(0.0),
    })
}

const MAGIC: &[u8; 14] = b"lugre-energy1\0";

impl ChunkEnergy {
    /// The energy pass's result as bytes (little-endian), to send between processes.
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut b = Vec::with_capacity(MAGIC.len() + 8 * (4 + 2 * LANES) * (self.parts.len() + 1));
        b.extend_from_slice(MAGIC);
        let f = |b: &mut Vec<u8>, x: f64| b.extend_from_slice(&x.to_le_bytes());
        f(&mut b, self.y_last);
        for x in [self.work, self.dissipation] {
            f(&mut b, x.hi);
            f(&mut b, x.lo);
        }
        b.extend_from_slice(&(self.parts.len() as u64).to_le_bytes());
        for p in &self.parts {
            b.extend_from_slice(&(p.id as u64).to_le_bytes());
            // NaN marks an absent state (a state is never NaN).
            f(&mut b, p.y_from.unwrap_or(f64::NAN));
            f(&mut b, p.y_to.unwrap_or(f64::NAN));
            p.sums.0.to_array().iter().for_each(|&x| f(&mut b, x));
        }
        b
    }

    /// Reads [`to_bytes`](Self::to_bytes)' output back.
    pub fn from_bytes(bytes: &[u8]) -> Result<Self, HistoryError> {
        let bad = |why| HistoryError::BadSummary { why };
        let rest = bytes
            .strip_prefix(MAGIC.as_slice())
            .ok_or(bad("not a chunk's energies"))?;
        let mut r = Reader(rest);
        let sums = |r: &mut Reader| -> Result<ArcSums, HistoryError> {
            let mut a = [0.0; 2 * LANES];
            for x in &mut a {
                *x = r.f64()?;
            }
            Ok(ArcSums(Sums::from_array(&a)))
        };
        let y_last = r.f64()?;
        let work = DoubleDouble {
            hi: r.f64()?,
            lo: r.f64()?,
        };
        let dissipation = DoubleDouble {
            hi: r.f64()?,
            lo: r.f64()?,
        };
        let n = r.u64()?;
        let mut parts = Vec::new();
        for _ in 0..n {
            let id = r.u64()? as usize;
            let (y_from, y_to) = (r.f64()?, r.f64()?);
            let s = sums(&mut r)?;
            parts.push(SpanPart {
                id,
                sums: s,
                y_from: (!y_from.is_nan()).then_some(y_from),
                y_to: (!y_to.is_nan()).then_some(y_to),
            });
        }
        if !r.0.is_empty() {
            return Err(bad("trailing bytes after a chunk's energies"));
        }
        Ok(Self {
            parts,
            work,
            dissipation,
            y_last,
        })
    }
}
