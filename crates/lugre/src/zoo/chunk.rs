//! Rainflow cycles of a history counted in chunks ([`crate::cycles::chunk`]) with the energies
//! of a model of the zoo: every chunk walked from its *entry state* (the model's state at the
//! sample before it), the cycles inside a chunk by (H1) there, the cycles found at merges from
//! the parts of their arcs each chunk sums. The rows, the states and therefore every force and
//! stored energy equal the single pass's ([`ZooModel::count_cycles`]) bit for bit; the
//! dissipations are the same double-double sums (H1) cut at the chunks' entries and added
//! back, so they agree with the single pass's to the double-double's rounding before the final
//! one: bit for bit in practice, within a unit in the last place otherwise (as LuGre's arcs,
//! [`crate::cycles::chunk`]'s energies).
//!
//! # Entry states
//!
//! * **Masing models** (Maxwell-slip, Prandtl-Ishlinskii: play operators, `p_i <- max(p_i,
//!   u - r_i)` moving up, `min(p_i, u + r_i)` down, (Z1)): by the wiping-out property the state
//!   after a prefix of the history equals the state after walking, from rest at the history's
//!   first sample, the prefix's pseudo-history (its first sample, its irreducible residue, its
//!   last sample: what the chunks' summaries merge). This holds in floating point: along a
//!   monotone run `max(max(p, fl(x1 - r)), fl(x2 - r)) = max(p, fl(x2 - r))` because rounding
//!   is monotone, and removing a full cycle `(B, C)` of `A, B, C, D` (`A < C < B <= D`, or the
//!   mirror) leaves the state unchanged: a state valid at `A` has `p <= fl(A + r) <= fl(C + r)`,
//!   so the clamp at `C` either does nothing or gives `fl(C + r) < fl(B - r) <= fl(D - r)`,
//!   which the run to `D` overwrites. So each chunk's entry is exact, without its prefix
//!   ((Z6) in `docs/mathematics.md`).
//! * **Single-state models** (Bouc-Wen, elasto-plastic: `z` in [`SingleState::bounds`]): each
//!   chunk is run from both bounds of `z` (the segment maps are monotone in `z`); where the two
//!   runs land on the same double, that is the next chunk's entry whatever the state before,
//!   else it is interpolated ([`crate::cycles::chunk::guess_entries`]' rule). The guesses are
//!   verified in order by the driver, as LuGre's: a chunk whose guess is not the state its
//!   predecessor's walk ended at is walked again from that state.
//!
//! Entry states travel as their numbers ([`ZooChunkState`]: the input, then `z` or each `p_i`).

use super::history::{arc_energy, check_energies, totals, walk, Walked, WalkedSpan};
use super::table::each;
use super::{MasingState, PlayBank, Point, Segmental, SingleState, ZooKind, ZooModel};
use crate::cycles::chunk::{
    self, bounds_walk, count_chunk, guess_within, ArcSpan, ChunkPlan, ChunkSummary, Reader,
    StateBounds,
};
use crate::cycles::{CycleColumns, CycleSink, HistoryEnergy};
use crate::error::HistoryError;
use crate::kernel::numerics::DoubleDouble;

/// A state of a model of the zoo as its numbers (the input first), as chunks send it.
#[derive(Debug, Clone, PartialEq)]
pub struct ZooChunkState(Vec<f64>);

impl ZooChunkState {
    /// The numbers: the input, then the model's internal state.
    pub fn values(&self) -> &[f64] {
        &self.0
    }

    /// The state as bytes (little-endian doubles), to send between processes; equal states
    /// give equal bytes, bit for bit.
    pub fn to_bytes(&self) -> Vec<u8> {
        self.0.iter().flat_map(|x| x.to_le_bytes()).collect()
    }

    /// Reads [`to_bytes`](Self::to_bytes)' output back (checked against a model where used).
    pub fn from_bytes(bytes: &[u8]) -> Result<Self, HistoryError> {
        if bytes.is_empty() || !bytes.len().is_multiple_of(8) {
            return Err(HistoryError::BadSummary {
                why: "a state is one or more little-endian doubles",
            });
        }
        let mut r = Reader(bytes);
        let values = (0..bytes.len() / 8)
            .map(|_| r.f64())
            .collect::<Result<Vec<f64>, _>>()?;
        Ok(Self(values))
    }

    fn of<M: Segmental>(state: &M::State) -> Self {
        Self(M::values(state))
    }

    /// The state of `model` (the zoo's `label`) these numbers are; `name` is the argument's.
    fn state<M: Segmental>(
        &self,
        model: &M,
        label: &'static str,
        name: &'static str,
    ) -> Result<M::State, HistoryError> {
        model
            .state_of_values(&self.0)
            .ok_or(HistoryError::NotAZooState {
                name,
                model: label,
                count: self.0.len(),
            })
    }
}

/// A chunk's part of an arc across chunks: the dissipation along it (double-double), the
/// state at `A` (where the arc starts in this chunk) and at `C` (where it ends in it).
#[derive(Debug, Clone, PartialEq)]
pub struct ZooSpanPart {
    pub id: usize,
    d: DoubleDouble,
    pub from: Option<ZooChunkState>,
    pub to: Option<ZooChunkState>,
}

/// What a chunk's energy pass with a model of the zoo tells the driver: the parts of the arcs
/// across it, the dissipation along all its pieces, the state at its last sample.
#[derive(Debug, Clone, PartialEq)]
pub struct ZooChunkEnergy {
    pub parts: Vec<ZooSpanPart>,
    d: DoubleDouble,
    pub last: ZooChunkState,
}

impl ZooModel {
    /// The model's state at rest at the history's first sample `u0`: the entry state of the
    /// first chunk (exact).
    pub fn chunk_start(&self, u0: f64) -> ZooChunkState {
        each!(self, m => rest_of(m, u0))
    }

    /// The state at the last sample of the chunk `u` (first sample at `offset`, `prev` the
    /// sample before it) from the two bounds of a single-state model's `z`, entering at `prev`
    /// (or at `u[0]`); `None` for a Masing model (its entries follow from the residues).
    pub fn chunk_bounds(
        &self,
        u: &[f64],
        offset: u64,
        prev: Option<f64>,
    ) -> Result<Option<StateBounds>, HistoryError> {
        chunk::check_offset(offset, u.len())?;
        chunk::check_prev(offset, prev)?;
        match self.kind() {
            ZooKind::BoucWen(m) => single_bounds(m, u, offset, prev).map(Some),
            ZooKind::ElastoPlastic(m) => single_bounds(m, u, offset, prev).map(Some),
            ZooKind::MaxwellSlip(_) | ZooKind::PrandtlIshlinskii(_) => Ok(None),
        }
    }

    /// Every chunk's entry state (the state at the sample before it; chunk 0: `start`, of
    /// [`Self::chunk_start`]) from the chunks' summaries `leaves` and [`Self::chunk_bounds`],
    /// in order: exact for a Masing model, guesses to verify for a single-state one (see the
    /// module documentation).
    pub fn guess_entries(
        &self,
        start: &ZooChunkState,
        bounds: &[Option<StateBounds>],
        leaves: &[ChunkSummary],
    ) -> Result<Vec<ZooChunkState>, HistoryError> {
        if bounds.len() != leaves.len() {
            return Err(HistoryError::BadSummary {
                why: "one state bound per chunk summary",
            });
        }
        match self.kind() {
            ZooKind::BoucWen(m) => {
                let first = start.state(m, self.spec().label, "y_start")?;
                single_entries(m, first, bounds, leaves)
            }
            ZooKind::ElastoPlastic(m) => {
                let first = start.state(m, self.spec().label, "y_start")?;
                single_entries(m, first, bounds, leaves)
            }
            ZooKind::MaxwellSlip(m) => {
                let first = start.state(m.bank(), self.spec().label, "y_start")?;
                masing_entries(m.bank(), first, leaves)
            }
            ZooKind::PrandtlIshlinskii(m) => {
                let first = start.state(m.bank(), self.spec().label, "y_start")?;
                masing_entries(m.bank(), first, leaves)
            }
        }
    }

    /// Counts the chunk `u` (first sample at `offset`, `prev` the sample before it) with the
    /// energies of its own full cycles along this model's path from `entry` (its state at
    /// `prev`, or at `u[0]` for the first chunk), and sums the parts of the arcs `spans`
    /// ([`ChunkPlan::energy_spans`]) in the same walk.
    ///
    /// # Errors
    /// The count's ([`count_chunk`]), [`HistoryError::HeldTooLong`] for a chunk longer than
    /// [`super::MAX_HISTORY_SAMPLES`], [`HistoryError::BadSummary`] for an entry that is not a
    /// state of this model or a span outside the chunk, [`HistoryError::EnergyOverflow`].
    pub fn count_chunk_energy(
        &self,
        u: &[f64],
        offset: u64,
        prev: Option<f64>,
        entry: &ZooChunkState,
        spans: &[ArcSpan],
    ) -> Result<(CycleColumns, ZooChunkEnergy), HistoryError> {
        super::check_held(self, u.len())?;
        chunk::check_prev(offset, prev)?;
        let (_, rows) = count_chunk(u, offset)?;
        let end = offset + u.len() as u64 - 1;
        let inside = |i: u64| (offset..=end).contains(&i);
        let spans_inside = spans
            .iter()
            .all(|s| s.from.is_none_or(inside) && s.to.is_none_or(|(c, _)| inside(c)));
        if !spans_inside {
            return Err(HistoryError::BadSummary {
                why: "an arc's span lies outside its chunk",
            });
        }
        let mut cycles: Vec<_> = (0..rows.len())
            .filter(|&k| rows.count[k] == 1.0)
            .map(|k| rows.cycle_at(k))
            .collect();
        let pass = each!(self, m => {
            let entry = entry.state(m, self.spec().label, "y_entry")?;
            let w = walk(m, entry, u, offset, prev, &mut cycles, spans);
            pass_of(m, w)
        });
        check_energies(&cycles)?;
        let mut out = CycleColumns::new().with_reversals(false).with_energy(true);
        out.reserve_for_samples(cycles.len());
        for c in cycles {
            out.cycle(c);
        }
        Ok((out, pass))
    }

    /// Attaches the energies of `plan`'s merge-time full cycles (after its closures are
    /// resolved) from every chunk's energy pass, in chunk order: each arc's dissipation the sum
    /// of its parts, its states those at `A` and `C`.
    pub fn attach_energy(
        &self,
        plan: &mut ChunkPlan,
        chunks: &[ZooChunkEnergy],
    ) -> Result<(), HistoryError> {
        let missing = || HistoryError::BadSummary {
            why: "the energy passes lack a part of an arc",
        };
        let mut arcs: Vec<Option<ZooSpanPart>> = vec![None; plan.open_cycles()];
        for p in chunks.iter().flat_map(|c| &c.parts) {
            let arc = arcs.get_mut(p.id).ok_or_else(missing)?;
            *arc = Some(match arc.take() {
                None => p.clone(),
                Some(a) => ZooSpanPart {
                    d: a.d + p.d,
                    to: p.to.clone(),
                    ..a
                },
            });
        }
        plan.attach_with(|id, closure| {
            let Some(Some(ZooSpanPart {
                d,
                from: Some(a),
                to: Some(c),
                ..
            })) = arcs.get(id)
            else {
                return Err(missing());
            };
            let e = each!(self, m => {
                let label = self.spec().label;
                let (a, c) = (a.state(m, label, "from")?, c.state(m, label, "to")?);
                arc_energy(m, &a, &c, d.to_f64())
            });
            let a = e.arc;
            let values = [a.work, a.stored_energy_change, a.dissipation, a.closure_gap];
            if values
                .iter()
                .chain(&[e.y_start, e.y_closure])
                .all(|x| x.is_finite())
            {
                Ok(e)
            } else {
                Err(HistoryError::EnergyOverflow { index: closure })
            }
        })
    }

    /// The totals along the whole history from every chunk's energy pass, in order, entering
    /// at `start` ([`Self::chunk_start`]).
    pub fn history_energy(
        &self,
        start: &ZooChunkState,
        chunks: &[ZooChunkEnergy],
    ) -> Result<HistoryEnergy, HistoryError> {
        let d = chunks.iter().fold(DoubleDouble::ZERO, |d, c| d + c.d);
        let end = chunks.last().map_or(start, |c| &c.last);
        let label = self.spec().label;
        let totals = each!(self, m => {
            let (first, end) = (start.state(m, label, "y_start")?, end.state(m, label, "y_last")?);
            totals(m, &first, &end, d)
        });
        totals.check_finite()?;
        Ok(totals)
    }
}

/// The state at rest at `u0`, as numbers.
fn rest_of<M: Segmental>(m: &M, u0: f64) -> ZooChunkState {
    ZooChunkState::of::<M>(&Segmental::rest(m, u0))
}

/// The energy pass of a walk, its states as numbers.
fn pass_of<M: Segmental>(_: &M, w: Walked<M::State>) -> ZooChunkEnergy {
    let num = |s: Option<M::State>| s.map(|s| ZooChunkState::of::<M>(&s));
    ZooChunkEnergy {
        parts: w
            .spans
            .into_iter()
            .map(|WalkedSpan { id, d, from, to }| ZooSpanPart {
                id,
                d,
                from: num(from),
                to: num(to),
            })
            .collect(),
        d: w.d,
        last: ZooChunkState::of::<M>(&w.end),
    }
}

/// [`bounds_walk`] of a single-state model: `z` from both bounds along the chunk.
fn single_bounds<T: SingleState>(
    m: &T,
    u: &[f64],
    offset: u64,
    prev: Option<f64>,
) -> Result<StateBounds, HistoryError> {
    bounds_walk(u, offset, prev, m.bounds(), |z, from, to| {
        m.segment(from, z, to).0
    })
}

/// The guessed entries of a single-state model: `z` by [`guess_within`], the input the sample
/// before each chunk (the previous chunk's last).
fn single_entries<T: SingleState>(
    m: &T,
    first: Point,
    bounds: &[Option<StateBounds>],
    leaves: &[ChunkSummary],
) -> Result<Vec<ZooChunkState>, HistoryError> {
    let bounds = bounds
        .iter()
        .map(|b| {
            b.ok_or(HistoryError::BadSummary {
                why: "a single-state model needs every chunk's state bounds",
            })
        })
        .collect::<Result<Vec<_>, _>>()?;
    let zs = guess_within(m.bounds(), first.z, &bounds)?;
    Ok(zs
        .into_iter()
        .enumerate()
        .map(|(k, z)| match k {
            0 => first,
            _ => Point {
                u: leaves[k - 1].last(),
                z,
            },
        })
        .map(|p| ZooChunkState::of::<T>(&p))
        .collect())
}

/// The entries of a Masing model: the state after walking each prefix's pseudo-history from
/// `start` (the wiping-out property; see the module documentation), the prefixes merged in
/// order.
fn masing_entries(
    bank: &PlayBank,
    first: MasingState,
    leaves: &[ChunkSummary],
) -> Result<Vec<ZooChunkState>, HistoryError> {
    let mut out = Vec::with_capacity(leaves.len());
    let mut prefix: Option<ChunkSummary> = None;
    let mut points = Vec::new();
    for leaf in leaves {
        let mut state = first.clone();
        if let Some(p) = &prefix {
            points.clear();
            p.pseudo(&mut points);
            for r in &points {
                bank.advance(&mut state, r.u);
            }
        }
        out.push(ZooChunkState::of::<PlayBank>(&state));
        prefix = Some(match prefix {
            None => leaf.clone(),
            Some(p) => chunk::merge(&p, leaf)?.0,
        });
    }
    Ok(out)
}

const MAGIC: &[u8] = b"lugre-zoo-energy1\0";

/// A state's numbers behind their count (`u64::MAX` for none).
fn put_state(b: &mut Vec<u8>, s: Option<&ZooChunkState>) {
    let values = s.map_or(&[][..], |s| s.values());
    let n = s.map_or(u64::MAX, |s| s.0.len() as u64);
    b.extend_from_slice(&n.to_le_bytes());
    values
        .iter()
        .for_each(|x| b.extend_from_slice(&x.to_le_bytes()));
}

fn get_state(r: &mut Reader) -> Result<Option<ZooChunkState>, HistoryError> {
    let n = r.u64()?;
    if n == u64::MAX {
        return Ok(None);
    }
    if n.saturating_mul(8) > r.0.len() as u64 {
        return Err(HistoryError::BadSummary { why: "too short" });
    }
    let values = (0..n).map(|_| r.f64()).collect::<Result<Vec<_>, _>>()?;
    Ok(Some(ZooChunkState(values)))
}

impl ZooChunkEnergy {
    /// The energy pass's result as bytes (little-endian), to send between processes.
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut b = MAGIC.to_vec();
        put_state(&mut b, Some(&self.last));
        for x in [self.d.hi, self.d.lo] {
            b.extend_from_slice(&x.to_le_bytes());
        }
        b.extend_from_slice(&(self.parts.len() as u64).to_le_bytes());
        for p in &self.parts {
            b.extend_from_slice(&(p.id as u64).to_le_bytes());
            for x in [p.d.hi, p.d.lo] {
                b.extend_from_slice(&x.to_le_bytes());
            }
            put_state(&mut b, p.from.as_ref());
            put_state(&mut b, p.to.as_ref());
        }
        b
    }

    /// Reads [`to_bytes`](Self::to_bytes)' output back.
    pub fn from_bytes(bytes: &[u8]) -> Result<Self, HistoryError> {
        let bad = |why| HistoryError::BadSummary { why };
        let rest = bytes
            .strip_prefix(MAGIC)
            .ok_or(bad("not a chunk's energies with a model of the zoo"))?;
        let mut r = Reader(rest);
        let last = get_state(&mut r)?.ok_or(bad("no last state"))?;
        let d = DoubleDouble {
            hi: r.f64()?,
            lo: r.f64()?,
        };
        let n = r.u64()?;
        let mut parts = Vec::new();
        for _ in 0..n {
            let id = r.u64()? as usize;
            let d = DoubleDouble {
                hi: r.f64()?,
                lo: r.f64()?,
            };
            let (from, to) = (get_state(&mut r)?, get_state(&mut r)?);
            parts.push(ZooSpanPart { id, d, from, to });
        }
        if !r.0.is_empty() {
            return Err(bad("trailing bytes after a chunk's energies"));
        }
        Ok(Self { parts, d, last })
    }
}
