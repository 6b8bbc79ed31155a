//! Counting a history in chunks: each chunk on its own, the chunks' summaries merged in any
//! tree order, the closures found by a second read-only pass, and the rows put in the single
//! pass's order. The result equals [`count_cycles`](super::count_cycles) (gate 0) row for row:
//! the same ranges, means, counts, indices, closures and positions, in the same order, for
//! every chunking and every merge tree.
//!
//! # Why chunks can be counted apart
//!
//! With reversals `... A, B, C, D ...`, the three-point test removes the pair `(B, C)` as a
//! full cycle when `|D - C| >= |C - B|`; the stack keeps `|C - B| < |B - A|` below it, so the
//! removal is the four-point rule "`|C - B| < |B - A|` and `|D - C| >= |C - B|`". Two such
//! removals never overlap and one never prevents another (the rule is confluent), so the full
//! cycles and the irreducible residue do not depend on the order of the removals, and a chunk
//! can be reduced on its own, its residue merged with its neighbour's later.
//!
//! This holds in exact arithmetic, so the engine decides every test `|x - b| >= |b - a|`
//! exactly on the samples (`engine::reaches`: the rounded differences, and their rounding
//! errors on a tie). With rounded comparisons it fails near ties: with samples near `2^53`,
//! `R` can close `(P, Q)` (`fl|R - Q| = fl|Q - P|`) while falling short of `P` for an earlier
//! pair (`fl|R - B| < fl|P - B|`), so that a chunk which removes `(P, Q)` first loses what `P`
//! did to `(A, B)` (the proptests over many binades found such a history).
//!
//! A chunk's first and last samples need not be reversals of the whole history, but using
//! them as the outer points `A` and `D` is safe: the history's true neighbour reversal lies
//! further out on the same monotone run, which only makes `|B - A|` and `|D - C|` larger. They
//! are kept as *tentative* points and decided at the merge, where a chunk's trailing run and
//! its neighbour's leading run (plateaus included, with their conventions) meet.
//!
//! # What a summary is
//!
//! [`ChunkSummary`] holds the chunk's first and last samples with their indices, where its
//! leading run of equal samples ends, its extremes, the irreducible residue between its ends,
//! and counts. Its *pseudo-history* (first sample, end of the leading plateau, residue, last
//! sample) has the same reversals near its ends and the same residue as the chunk: merging is
//! counting the concatenation of two pseudo-histories with the same engine, in `O(size of the
//! residues)`. The pseudo-history's full cycles are the merge's new full cycles
//! ([`OpenCycle`]); the residue of the whole history, counted by [`ChunkPlan::finish`], gives
//! the half cycles.
//!
//! # Closures and order
//!
//! A cycle `(A, B)` found at a merge closes at the first sample after `B` with
//! `|u - u_B| >= |u_B - u_A|` (the single pass's exact test). Every sample between two
//! consecutive points of a reduced sequence lies within their hull, and the test is monotone
//! in `u`, so whether a chunk holds the closure is decided exactly from
//! its extremes (and, in `B`'s own chunk, from its points after `B`): each query goes to one
//! chunk ([`ChunkPlan::queries`]), which scans only the blocks its extremes allow
//! ([`close_in_chunk`]).
//!
//! The single pass emits the cycles a reversal `P` completes when `P` arrives: the full cycles
//! innermost first (decreasing start index), then at most one half cycle `(A, B)` from the
//! bottom of the stack; the residue's half cycles come last. All full cycles completed by `P`
//! close on the run into `P`, so sorting full cycles by `(closure index, -start)` restores
//! their order. The bottom half cycle is placed where the run into `P` first comes back past
//! `A` (its own "closure", found by the same query): every full cycle completed by `P` has
//! closed by then (each starts strictly inside `(A, B)` by the stack's strict test, and the
//! test is monotone in `u`), and no later one has. The final residue goes last, by
//! start ([`RowKey`]).

mod energy;

pub use energy::{
    arc_energy_of, count_chunk_energy, guess_entries, history_energy, state_bounds, ArcSpan,
    ArcSums, ChunkEnergy, SpanPart, StateBounds,
};
pub(crate) use energy::{bounds_walk, guess_within};

use super::engine::{self, admissible, bad_sample, closure_at};
use super::{
    Closure, Cycle, CycleColumns, CycleCounter, CycleEnergy, CycleSink, CycleSummary, Reversal,
};
use crate::error::HistoryError;
use crate::model::RateIndependent;

/// A row's place in the single pass's order (see the module documentation).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct RowKey {
    at: u64,
    group: u8,
    tie: u64,
}

impl RowKey {
    /// A full cycle closing at sample `closure`.
    pub fn full(closure: u64, start: u64) -> Self {
        Self {
            at: closure,
            group: 0,
            tie: u64::MAX - start,
        }
    }

    /// A half cycle dropped from the bottom of the stack, where the history first comes back
    /// past its start (sample `at`).
    pub fn dropped(at: u64, start: u64) -> Self {
        Self {
            at,
            group: 1,
            tie: u64::MAX - start,
        }
    }

    /// A half cycle of the residue left at the end.
    pub fn residue(start: u64) -> Self {
        Self {
            at: u64::MAX,
            group: 2,
            tie: start,
        }
    }

    /// Bytes of [`to_bytes`](Self::to_bytes).
    pub const BYTES: usize = 17;

    /// The key as bytes (little-endian), to send between processes.
    pub fn to_bytes(&self) -> [u8; Self::BYTES] {
        let mut b = [0; Self::BYTES];
        b[..8].copy_from_slice(&self.at.to_le_bytes());
        b[8] = self.group;
        b[9..].copy_from_slice(&self.tie.to_le_bytes());
        b
    }

    /// Reads [`to_bytes`](Self::to_bytes)' output back.
    pub fn from_bytes(b: &[u8]) -> Result<Self, HistoryError> {
        let mut r = Reader(b);
        let at = r.u64()?;
        let (&group, rest) = r.0.split_first().ok_or(HistoryError::BadSummary {
            why: "row key too short",
        })?;
        r.0 = rest;
        let tie = r.u64()?;
        if group > 2 || !r.0.is_empty() {
            return Err(HistoryError::BadSummary {
                why: "not a row key",
            });
        }
        Ok(Self { at, group, tie })
    }

    /// The sample that places the row (`None`: at the end of the history).
    pub fn emitted_at(&self) -> Option<u64> {
        (self.group < 2).then_some(self.at)
    }
}

/// What the rest of the history needs to know about a chunk (or a run of adjacent chunks).
#[derive(Debug, Clone, PartialEq)]
pub struct ChunkSummary {
    start: u64,
    end: u64,
    lead_end: u64,
    first: f64,
    last: f64,
    min: f64,
    max: f64,
    residue: Vec<Reversal>,
    reversals: u64,
    full_cycles: u64,
}

/// A full cycle found at a merge, waiting for its closure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OpenCycle {
    /// Range, mean, count (1), start and end as in the single pass; no closure yet.
    pub cycle: Cycle,
    pub u_start: f64,
    pub u_end: f64,
}

/// "The first sample after `after` with `|u - u_end| >= |u_end - u_start|`", for the open
/// cycle `id` of a [`ChunkPlan`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClosureQuery {
    pub id: usize,
    pub after: u64,
    pub u_start: f64,
    pub u_end: f64,
}

impl ChunkSummary {
    /// Global index of the chunk's first sample.
    pub fn start(&self) -> u64 {
        self.start
    }
    /// Global index of the chunk's last sample.
    pub fn end(&self) -> u64 {
        self.end
    }
    pub fn first(&self) -> f64 {
        self.first
    }
    pub fn last(&self) -> f64 {
        self.last
    }
    pub fn min(&self) -> f64 {
        self.min
    }
    pub fn max(&self) -> f64 {
        self.max
    }
    /// The irreducible residue strictly between the chunk's tentative ends.
    pub fn residue(&self) -> &[Reversal] {
        &self.residue
    }
    /// Full cycles counted inside (leaves and merges below this summary).
    pub fn full_cycles(&self) -> u64 {
        self.full_cycles
    }

    /// The pseudo-history: first sample, end of the leading plateau, residue, last sample.
    pub(crate) fn pseudo(&self, out: &mut Vec<Reversal>) {
        out.push(Reversal {
            index: self.start,
            u: self.first,
        });
        if self.lead_end > self.start {
            out.push(Reversal {
                index: self.lead_end,
                u: self.first,
            });
        }
        out.extend_from_slice(&self.residue);
        if self.end > self.lead_end {
            out.push(Reversal {
                index: self.end,
                u: self.last,
            });
        }
    }

    /// Whether a sample of this chunk after `after` reaches the closure of `q`, decided from
    /// the pseudo-history's points after `after` (every sample lies in the hull of two
    /// consecutive points, and the test is monotone in `u`).
    fn reaches_after(&self, q: &ClosureQuery) -> bool {
        let mut points = Vec::with_capacity(self.residue.len() + 3);
        self.pseudo(&mut points);
        points.iter().any(|p| p.index > q.after && reaches(p.u, q))
    }

    /// The summary as bytes (little-endian), to send between processes.
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut b = Vec::with_capacity(MAGIC.len() + 8 * (10 + 2 * self.residue.len()));
        b.extend_from_slice(MAGIC);
        for v in [
            self.start,
            self.end,
            self.lead_end,
            self.reversals,
            self.full_cycles,
            self.residue.len() as u64,
        ] {
            b.extend_from_slice(&v.to_le_bytes());
        }
        for v in [self.first, self.last, self.min, self.max] {
            b.extend_from_slice(&v.to_le_bytes());
        }
        for r in &self.residue {
            b.extend_from_slice(&r.index.to_le_bytes());
            b.extend_from_slice(&r.u.to_le_bytes());
        }
        b
    }

    /// Reads [`to_bytes`](Self::to_bytes)' output back.
    pub fn from_bytes(bytes: &[u8]) -> Result<Self, HistoryError> {
        let mut r = Reader(bytes.strip_prefix(MAGIC).ok_or(HistoryError::BadSummary {
            why: "not a lugre chunk summary",
        })?);
        let (start, end, lead_end, reversals, full_cycles, n) =
            (r.u64()?, r.u64()?, r.u64()?, r.u64()?, r.u64()?, r.u64()?);
        let (first, last, min, max) = (r.f64()?, r.f64()?, r.f64()?, r.f64()?);
        if r.0.len() as u64 != n.saturating_mul(16) {
            return Err(HistoryError::BadSummary {
                why: "wrong length",
            });
        }
        let residue = (0..n)
            .map(|_| {
                Ok(Reversal {
                    index: r.u64()?,
                    u: r.f64()?,
                })
            })
            .collect::<Result<Vec<_>, HistoryError>>()?;
        let s = Self {
            start,
            end,
            lead_end,
            first,
            last,
            min,
            max,
            residue,
            reversals,
            full_cycles,
        };
        let ordered = s.start <= s.lead_end
            && s.lead_end <= s.end
            && s.residue.windows(2).all(|w| w[0].index < w[1].index)
            && s.residue
                .iter()
                .all(|p| p.index > s.lead_end && p.index < s.end);
        let values = [s.first, s.last, s.min, s.max]
            .iter()
            .chain(s.residue.iter().map(|p| &p.u))
            .all(|&v| admissible(v));
        if !(ordered && values) {
            return Err(HistoryError::BadSummary {
                why: "inconsistent fields",
            });
        }
        Ok(s)
    }
}

const MAGIC: &[u8] = b"lugre-chunk-1\0";

pub(crate) struct Reader<'a>(pub(crate) &'a [u8]);

impl Reader<'_> {
    fn take(&mut self) -> Result<[u8; 8], HistoryError> {
        let (head, rest) = self
            .0
            .split_first_chunk::<8>()
            .ok_or(HistoryError::BadSummary { why: "too short" })?;
        self.0 = rest;
        Ok(*head)
    }
    pub(crate) fn u64(&mut self) -> Result<u64, HistoryError> {
        self.take().map(u64::from_le_bytes)
    }
    pub(crate) fn f64(&mut self) -> Result<f64, HistoryError> {
        self.take().map(f64::from_le_bytes)
    }
}

/// The largest sample index a chunk may reach: rows carry indices as `i64` (numpy's and the C
/// ABI's columns), so a history ends at `u[i64::MAX]` at the latest.
pub const MAX_INDEX: u64 = i64::MAX as u64;

/// Checks that a chunk of `samples` samples from `offset` ends at or before [`MAX_INDEX`].
pub fn check_offset(offset: u64, samples: usize) -> Result<(), HistoryError> {
    let last = (samples as u64)
        .checked_sub(1)
        .and_then(|n| offset.checked_add(n));
    match last {
        Some(last) if last > MAX_INDEX => Err(HistoryError::IndexOverflow {
            offset,
            samples: samples as u64,
        }),
        None if samples > 0 => Err(HistoryError::IndexOverflow {
            offset,
            samples: samples as u64,
        }),
        _ => Ok(()),
    }
}

/// Checks `prev`, the sample before a chunk starting at `offset`: none before `u[0]`, and a
/// sample as the single pass takes it (finite, `|u| <=` [`MAX_SAMPLE`](super::MAX_SAMPLE),
/// named `u[offset - 1]`).
pub fn check_prev(offset: u64, prev: Option<f64>) -> Result<(), HistoryError> {
    match (offset.checked_sub(1), prev) {
        (_, None) => Ok(()),
        (None, Some(value)) => Err(HistoryError::PrevBeforeStart { value }),
        (Some(_), Some(p)) if admissible(p) => Ok(()),
        (Some(index), Some(p)) => Err(bad_sample(index, p)),
    }
}

/// The single pass's closing test for `q` at value `u`.
#[inline]
fn reaches(u: f64, q: &ClosureQuery) -> bool {
    engine::reaches(
        (u - q.u_end).abs(),
        (q.u_end - q.u_start).abs(),
        u,
        q.u_end,
        q.u_start,
    )
}

/// The chunk `u`, whose first sample is sample `offset` of the history: its summary and its
/// own rows: the full cycles in the single pass's order, with global indices and closures,
/// among a few half cycles of its residue ([`assemble`] skips those).
pub fn count_chunk(u: &[f64], offset: u64) -> Result<(ChunkSummary, CycleColumns), HistoryError> {
    let (&first, &last) = match (u.first(), u.last()) {
        (Some(f), Some(l)) => (f, l),
        _ => return Err(HistoryError::EmptyChunk { start: offset }),
    };
    check_offset(offset, u.len())?;
    if !admissible(first) {
        return Err(bad_sample(offset, first));
    }
    let lead = u.iter().position(|&x| x != first).unwrap_or(u.len());
    let end = offset + u.len() as u64 - 1;
    let mut summary = ChunkSummary {
        start: offset,
        end,
        lead_end: offset + lead as u64 - 1,
        first,
        last,
        min: first,
        max: first,
        residue: Vec::new(),
        reversals: 0,
        full_cycles: 0,
    };
    let mut rows = CycleColumns::new().with_reversals(false);
    if lead == u.len() {
        return Ok((summary, rows));
    }
    // As the single pass: room for every row up front (on huge pages, no reallocation).
    rows.reserve_for_samples(u.len());
    // The engine checks every sample (errors carry the history's index).
    let mut counter = CycleCounter::new(0.0)?.with_origin(offset);
    counter.push_all(u, &mut rows)?;
    let counts = counter.finish(&mut rows)?;
    rows.shrink_to_fit();
    let chain = residue_chain(&rows, u, offset);
    // Every sample lies in the hull of two consecutive points of the chain.
    for p in &chain {
        summary.min = summary.min.min(p.u);
        summary.max = summary.max.max(p.u);
    }
    summary.residue = chain[1..chain.len() - 1].to_vec();
    summary.reversals = counts.reversals - 2;
    summary.full_cycles = counts.full_cycles;
    Ok((summary, rows))
}

/// The chain of a leaf's half cycles' points (first sample, residue, last sample).
fn residue_chain(rows: &CycleColumns, u: &[f64], offset: u64) -> Vec<Reversal> {
    let at = |i: i64| Reversal {
        index: i as u64,
        u: u[(i as u64 - offset) as usize],
    };
    let mut chain = Vec::new();
    for k in (0..rows.len()).filter(|&k| rows.count[k] != 1.0) {
        if chain.is_empty() {
            chain.push(at(rows.start[k]));
        }
        chain.push(at(rows.end[k]));
    }
    chain
}

/// What the engine reports on a pseudo-history, in the order it reports it.
#[derive(Default)]
struct Trace {
    reversals: u64,
    full: Vec<Cycle>,
    /// Half cycles with the number of reversals seen then.
    halves: Vec<(Cycle, u64)>,
}

impl CycleSink for Trace {
    fn reversal(&mut self, _r: Reversal) {
        self.reversals += 1;
    }
    fn cycle(&mut self, c: Cycle) {
        if c.is_full() {
            self.full.push(c);
        } else {
            self.halves.push((c, self.reversals));
        }
    }
}

/// Counts a pseudo-history (at least 2 points); indices in the trace are positions in
/// `points`.
fn trace(points: &[Reversal]) -> Result<Trace, HistoryError> {
    let values: Vec<f64> = points.iter().map(|p| p.u).collect();
    let mut t = Trace::default();
    let mut counter = CycleCounter::new(0.0)?;
    counter.push_all(&values, &mut t)?;
    counter.finish(&mut t)?;
    Ok(t)
}

/// A trace's cycle with global indices.
fn global(c: &Cycle, points: &[Reversal]) -> Cycle {
    Cycle {
        start: points[c.start as usize].index,
        end: points[c.end as usize].index,
        ..*c
    }
}

/// A trace's full cycles, with global indices and values, waiting for closures.
fn open_cycles(t: &Trace, points: &[Reversal]) -> Vec<OpenCycle> {
    t.full
        .iter()
        .map(|c| OpenCycle {
            cycle: global(c, points),
            u_start: points[c.start as usize].u,
            u_end: points[c.end as usize].u,
        })
        .collect()
}

/// Merges the summaries of two adjacent runs of samples (`left` just before `right`): the
/// summary of both and the full cycles that only the two together complete.
pub fn merge(
    left: &ChunkSummary,
    right: &ChunkSummary,
) -> Result<(ChunkSummary, Vec<OpenCycle>), HistoryError> {
    if left.end.checked_add(1) != Some(right.start) {
        return Err(HistoryError::NotAdjacent {
            left_end: left.end,
            right_start: right.start,
        });
    }
    let mut points = Vec::with_capacity(left.residue.len() + right.residue.len() + 6);
    left.pseudo(&mut points);
    right.pseudo(&mut points);
    let t = trace(&points)?;
    let mut chain: Vec<Reversal> = Vec::with_capacity(t.halves.len() + 1);
    for (c, _) in &t.halves {
        if chain.is_empty() {
            chain.push(points[c.start as usize]);
        }
        chain.push(points[c.end as usize]);
    }
    let residue = chain[1..chain.len() - 1].to_vec();
    let new_reversals = t.reversals - 2 - (left.residue.len() + right.residue.len()) as u64;
    let left_flat = left.lead_end == left.end && left.first == right.first;
    let summary = ChunkSummary {
        start: left.start,
        end: right.end,
        lead_end: if left_flat {
            right.lead_end
        } else {
            left.lead_end
        },
        first: left.first,
        last: right.last,
        min: left.min.min(right.min),
        max: left.max.max(right.max),
        residue,
        reversals: left.reversals + right.reversals + new_reversals,
        full_cycles: left.full_cycles + right.full_cycles + t.full.len() as u64,
    };
    Ok((summary, open_cycles(&t, &points)))
}

/// The bookkeeping of a chunked count: the leaves' summaries, the open cycles of the merges,
/// their closures, and the residue's half cycles; it routes the closure queries and hands each
/// chunk the rows to merge into its own ([`assemble`]).
#[derive(Debug, Clone, Default)]
pub struct ChunkPlan {
    leaves: Vec<ChunkSummary>,
    open: Vec<OpenCycle>,
    closures: Vec<Option<Closure>>,
    halves: Vec<(RowKey, Cycle)>,
}

impl ChunkPlan {
    /// A plan over the leaves' summaries, in order from sample 0 (adjacent).
    pub fn new(leaves: Vec<ChunkSummary>) -> Result<Self, HistoryError> {
        let Some(first) = leaves.first() else {
            return Err(HistoryError::Empty);
        };
        if first.start != 0 {
            return Err(HistoryError::NotWhole {
                start: first.start,
                end: leaves[leaves.len() - 1].end,
            });
        }
        for w in leaves.windows(2) {
            if w[0].end.checked_add(1) != Some(w[1].start) {
                return Err(HistoryError::NotAdjacent {
                    left_end: w[0].end,
                    right_start: w[1].start,
                });
            }
        }
        Ok(Self {
            leaves,
            ..Self::default()
        })
    }

    pub fn leaves(&self) -> &[ChunkSummary] {
        &self.leaves
    }

    /// Adds the open cycles of a merge; returns the id of the first.
    pub fn add_open(&mut self, open: &[OpenCycle]) -> usize {
        let id = self.open.len();
        self.open.extend_from_slice(open);
        self.closures.resize(self.open.len(), None);
        id
    }

    /// Counts the residue of the whole history (`root`, the merge of every leaf): its half
    /// cycles are kept for [`extras`](Self::extras); returns the single pass's summary.
    pub fn finish(&mut self, root: &ChunkSummary) -> Result<CycleSummary, HistoryError> {
        let last = self.leaves[self.leaves.len() - 1].end;
        if root.start != 0 || root.end != last {
            return Err(HistoryError::NotWhole {
                start: root.start,
                end: root.end,
            });
        }
        if root.end == 0 {
            return Err(HistoryError::TooShort { samples: 1 });
        }
        let mut points = Vec::with_capacity(root.residue.len() + 3);
        root.pseudo(&mut points);
        let t = trace(&points)?;
        let open = open_cycles(&t, &points);
        self.add_open(&open);
        // A half cycle dropped from the bottom when `P` arrives is emitted after the full cycles
        // `P` completes and before those of the next reversal: its place is where the history
        // first comes back past its start (at or after every closure at `P`, before `P`), found
        // by the same query as a closure.
        // The halves emitted after the last reversal are the final stack, whose ranges
        // decrease strictly upwards, unless the last reversal dropped the bottom pair first
        // (then that pair's range is at most the next one's).
        let tail: Vec<&Cycle> = t
            .halves
            .iter()
            .filter(|(_, seen)| *seen == t.reversals)
            .map(|(c, _)| c)
            .collect();
        let last_drops = tail.len() >= 2 && {
            let at = |i: u64| points[i as usize].u;
            let (a, b, p) = (at(tail[0].start), at(tail[0].end), at(tail[1].end));
            engine::reaches((p - b).abs(), (b - a).abs(), p, b, a)
        };
        let mut dropped = Vec::new();
        self.halves.clear();
        for (k, (c, seen)) in t.halves.iter().enumerate() {
            let g = global(c, &points);
            let first_of_tail = k + tail.len() == t.halves.len();
            if *seen == t.reversals && !(first_of_tail && last_drops) {
                self.halves.push((RowKey::residue(g.start), g));
            } else {
                dropped.push(OpenCycle {
                    cycle: g,
                    u_start: points[c.start as usize].u,
                    u_end: points[c.end as usize].u,
                });
            }
        }
        self.add_open(&dropped);
        Ok(CycleSummary {
            samples: root.end + 1,
            reversals: root.reversals + t.reversals - root.residue.len() as u64,
            full_cycles: root.full_cycles + t.full.len() as u64,
            half_cycles: t.halves.len() as u64,
            energy: None,
        })
    }

    /// The closure queries of the open cycles, by the chunk that holds each answer.
    pub fn queries(&self) -> Result<Vec<Vec<ClosureQuery>>, HistoryError> {
        let mut out = vec![Vec::new(); self.leaves.len()];
        for (id, o) in self.open.iter().enumerate() {
            let q = ClosureQuery {
                id,
                after: o.cycle.end,
                u_start: o.u_start,
                u_end: o.u_end,
            };
            let own = self.leaves.partition_point(|l| l.end < q.after);
            let chunk = if own < self.leaves.len() && self.leaves[own].reaches_after(&q) {
                Some(own)
            } else {
                (own + 1..self.leaves.len())
                    .find(|&k| reaches(self.leaves[k].max, &q) || reaches(self.leaves[k].min, &q))
            };
            let chunk = chunk.ok_or(HistoryError::ClosureNotFound { end: q.after })?;
            out[chunk].push(q);
        }
        Ok(out)
    }

    /// Records closures found by [`close_in_chunk`].
    pub fn resolve(&mut self, found: &[(usize, Closure)]) {
        for &(id, c) in found {
            if let Some(slot) = self.closures.get_mut(id) {
                *slot = Some(c);
            }
        }
    }

    /// The chunk holding sample `i`.
    fn chunk_of(&self, i: u64) -> usize {
        self.leaves.partition_point(|l| l.end < i)
    }

    /// The parts of the merge-time full cycles' arcs, by chunk (after
    /// [`resolve`](Self::resolve)): each chunk's energy pass ([`count_chunk_energy`]) sums its
    /// own: from `A` in `A`'s chunk, the whole of each chunk in between, to `C` in `C`'s.
    pub fn energy_spans(&self) -> Result<Vec<Vec<ArcSpan>>, HistoryError> {
        let mut out = vec![Vec::new(); self.leaves.len()];
        for (id, (o, c)) in self.open.iter().zip(&self.closures).enumerate() {
            if !o.cycle.is_full() {
                continue;
            }
            let c = c.ok_or(HistoryError::ClosureNotFound { end: o.cycle.end })?;
            let (a, z) = (self.chunk_of(o.cycle.start), self.chunk_of(c.index));
            for (k, chunk) in out.iter_mut().enumerate().take(z + 1).skip(a) {
                chunk.push(ArcSpan {
                    id,
                    from: (k == a).then_some(o.cycle.start),
                    to: (k == z).then_some((c.index, o.u_start)),
                });
            }
        }
        Ok(out)
    }

    /// Attaches the energies of the merge-time full cycles from every chunk's energy pass (in
    /// order; see [`energy_spans`](Self::energy_spans)).
    pub fn attach_energy(
        &mut self,
        model: RateIndependent,
        chunks: &[ChunkEnergy],
    ) -> Result<(), HistoryError> {
        let missing = || HistoryError::BadSummary {
            why: "the energy passes lack a part of an arc",
        };
        // Each arc's parts added in chunk order: y at A from the first, y at C from the last.
        let mut arcs: Vec<Option<SpanPart>> = vec![None; self.open.len()];
        for p in chunks.iter().flat_map(|c| &c.parts) {
            let arc = arcs.get_mut(p.id).ok_or_else(missing)?;
            *arc = Some(match *arc {
                None => *p,
                Some(a) => SpanPart {
                    sums: a.sums + p.sums,
                    y_to: p.y_to,
                    ..a
                },
            });
        }
        self.attach_with(|id, closure| {
            let Some(Some(SpanPart {
                sums,
                y_from: Some(y_a),
                y_to: Some(y_c),
                ..
            })) = arcs.get(id)
            else {
                return Err(missing());
            };
            arc_energy_of(model, sums, *y_a, *y_c, closure)
        })
    }

    /// How many open cycles the plan holds (the ids of the arcs run below it).
    pub fn open_cycles(&self) -> usize {
        self.open.len()
    }

    /// Sets the energy of each merge-time full cycle `id` to `energy(id, closure index)`
    /// (after [`resolve`](Self::resolve)).
    pub(crate) fn attach_with(
        &mut self,
        mut energy: impl FnMut(usize, u64) -> Result<CycleEnergy, HistoryError>,
    ) -> Result<(), HistoryError> {
        for (id, o) in self.open.iter_mut().enumerate() {
            if !o.cycle.is_full() {
                continue;
            }
            let c = self.closures[id].ok_or(HistoryError::ClosureNotFound { end: o.cycle.end })?;
            o.cycle.energy = Some(energy(id, c.index)?);
        }
        Ok(())
    }

    /// The rows each chunk's own rows are merged with (closed open cycles by their closure's
    /// chunk, half cycles by the chunk where the single pass emits them, the final residue in
    /// the last chunk), each list in order.
    pub fn extras(&self) -> Result<Vec<Vec<(RowKey, Cycle)>>, HistoryError> {
        let mut out = vec![Vec::new(); self.leaves.len()];
        for (o, c) in self.open.iter().zip(&self.closures) {
            let c = c.ok_or(HistoryError::ClosureNotFound { end: o.cycle.end })?;
            let row = if o.cycle.is_full() {
                (
                    RowKey::full(c.index, o.cycle.start),
                    Cycle {
                        closure: Some(c),
                        ..o.cycle
                    },
                )
            } else {
                (RowKey::dropped(c.index, o.cycle.start), o.cycle)
            };
            out[self.chunk_of(c.index)].push(row);
        }
        let last = self.leaves.len() - 1;
        for &(key, c) in &self.halves {
            let k = key
                .emitted_at()
                .map_or(last, |i| self.chunk_of(i))
                .min(last);
            out[k].push((key, c));
        }
        for rows in &mut out {
            rows.sort_by_key(|r| r.0);
        }
        Ok(out)
    }
}

/// Samples per block of the closure search's extremes.
const SEARCH_BLOCK: usize = 1024;

/// Answers closure queries in the chunk `u` (first sample at `offset`; `prev` is the sample
/// before it, if any): the first sample after each query's `after` that reaches it, and the
/// interpolated position, exactly as the single pass computes them.
pub fn close_in_chunk(
    u: &[f64],
    offset: u64,
    prev: Option<f64>,
    queries: &[ClosureQuery],
) -> Result<Vec<(usize, Closure)>, HistoryError> {
    check_offset(offset, u.len())?;
    check_prev(offset, prev)?;
    if queries.is_empty() {
        return Ok(Vec::new());
    }
    let blocks: Vec<(f64, f64)> = u
        .chunks(SEARCH_BLOCK)
        .map(|b| {
            b.iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| {
                    (lo.min(x), hi.max(x))
                })
        })
        .collect();
    queries
        .iter()
        .map(|q| {
            let from = q.after.saturating_add(1).max(offset) - offset;
            let i = first_reaching(u, &blocks, from as usize, q)
                .ok_or(HistoryError::ClosureNotFound { end: q.after })?;
            let before = match i {
                0 => prev.ok_or(HistoryError::ClosureNotFound { end: q.after })?,
                _ => u[i - 1],
            };
            let (closure, _) = closure_at(offset + i as u64, u[i], before, q.u_start);
            Ok((q.id, closure))
        })
        .collect()
}

/// The first `i >= from` with `u[i]` reaching `q`, skipping blocks whose extremes do not.
fn first_reaching(
    u: &[f64],
    blocks: &[(f64, f64)],
    from: usize,
    q: &ClosureQuery,
) -> Option<usize> {
    let mut i = from;
    while i < u.len() {
        let b = i / SEARCH_BLOCK;
        let block_end = ((b + 1) * SEARCH_BLOCK).min(u.len());
        let (lo, hi) = blocks[b];
        if reaches(lo, q) || reaches(hi, q) {
            if let Some(k) = u[i..block_end].iter().position(|&x| reaches(x, q)) {
                return Some(i + k);
            }
        }
        i = block_end;
    }
    None
}

/// A chunk's rows: its own full cycles (from [`count_chunk`]; its half cycles are skipped) merged with the plan's `extras`
/// for it, in the single pass's order.
pub fn assemble(own: &CycleColumns, extras: &[(RowKey, Cycle)]) -> CycleColumns {
    let mut out = CycleColumns::new()
        .with_reversals(false)
        .with_energy(own.keeps_energy());
    let full = own.count.iter().filter(|&&c| c == 1.0).count();
    out.reserve_for_samples(full + extras.len());
    let mut extra = extras.iter().peekable();
    for k in (0..own.len()).filter(|&k| own.count[k] == 1.0) {
        let key = RowKey::full(own.closure[k] as u64, own.start[k] as u64);
        while let Some((_, c)) = extra.next_if(|(x, _)| *x < key) {
            out.cycle(*c);
        }
        out.cycle(own.cycle_at(k));
    }
    for (_, c) in extra {
        out.cycle(*c);
    }
    out
}
