//! The loops of a model of the zoo for a periodic input: rainflow pairing (ASTM E1049, a pair
//! `(A, B)` closing at `P` once `|P - B| >= |B - A|`) in one pass over the period started at
//! its first global maximum, from the model's periodic state there
//! ([`Segmental::periodic_start`]). Each stack entry keeps its state and the dissipation from
//! its point to the next entry up; a loop's arc `A -> B -> C` ends on the segment into `P`
//! where the input is back at `u_A`, reached from the running state by one partial segment
//! map, which starts where the whole segment does ([`Segmental::Start`], from the periodic
//! solver's walk). Any model with an exact segment map ([`Segmental`]) runs on it: Masing models, whose
//! loops close, and single-state models, whose minor loops drift as LuGre's do.

use super::Segmental;
use crate::error::ZooError;
use crate::input::TurningPoints;
use crate::kernel::ArcEnergy;
use crate::loops::{Loop, LoopKind, LoopPoint};

/// The most element states (elements x turning points) a loop may keep on its stack.
pub const MAX_STATES: usize = 1 << 27;

/// The periodic response of a model of the zoo and every loop, with energies.
#[derive(Debug, Clone)]
pub struct ZooLoop {
    u: Vec<f64>,
    rho: Vec<f64>,
    force: Vec<f64>,
    loops: Vec<Loop>,
}

/// An open reversal: rotated index, its state, the dissipation to the next entry up.
struct Entry<S> {
    j: usize,
    state: S,
    d: f64,
}

/// The rainflow pass's work: the open reversals, the loops as they close, and a state to map
/// arcs' ends in.
struct Pairing<S> {
    /// The open reversals, the global maximum at the bottom.
    stack: Vec<Entry<S>>,
    /// The loops as they close; a loop's `parent` holds, until [`nest`], the index of the
    /// closed loop it lies in (`None`: the major loop). At most one loop per two turning
    /// points: reserved once, never moved by growth.
    found: Vec<Loop>,
    /// Closed loops without a parent yet, by where they start: (rotated index, loop).
    roots: Vec<(usize, usize)>,
    scratch: S,
}

impl<S: Clone> Pairing<S> {
    /// The pass's start at the periodic state `start`, for `n` turning points.
    fn new(start: &S, n: usize) -> Self {
        Self {
            stack: vec![Entry {
                j: 0,
                state: start.clone(),
                d: 0.0,
            }],
            found: Vec::with_capacity(n / 2 + 2),
            roots: Vec::new(),
            scratch: start.clone(),
        }
    }
}

impl ZooLoop {
    /// The loops of `model` for the periodic input `input`.
    ///
    /// # Errors
    /// [`ZooError::TooLarge`] when the worst-case stack of states would exceed [`MAX_STATES`];
    /// [`ZooError::Overflow`] when a force or energy is not finite.
    pub fn new<M: Segmental>(model: &M, input: &TurningPoints) -> Result<Self, ZooError> {
        let u = input.values().to_vec();
        let n = u.len();
        if model.state_len().saturating_mul(n) > MAX_STATES {
            return Err(ZooError::TooLarge {
                elements: model.state_len(),
                turning_points: n,
                limit: MAX_STATES,
            });
        }
        let mut rho = Vec::with_capacity(n + 1);
        let mut total = 0.0;
        rho.push(0.0);
        for k in 0..n {
            total += (u[(k + 1) % n] - u[k]).abs();
            rho.push(total);
        }
        if !total.is_finite() {
            return Err(crate::error::InputError::VariationOverflow.into());
        }
        let mut hl = Self {
            u,
            rho,
            force: vec![0.0; n],
            loops: Vec::new(),
        };
        hl.pair(model);
        hl.check_finite()?;
        Ok(hl)
    }

    /// The rainflow pass: forces at the turning points and every loop.
    fn pair<M: Segmental>(&mut self, bank: &M) {
        let n = self.u.len();
        let r = self.start_index();
        let min = self.u.iter().fold(f64::MAX, |m, &x| m.min(x));
        // The solver's last walk, reused from `first` on (the same states to rounding).
        let mut trail = Vec::with_capacity(n);
        let (start, first) = bank.periodic_trail(&self.u, r, min, &mut trail);
        let mut run = start.clone();
        let mut pairing = Pairing::new(&start, n);
        let mut d_period = 0.0;
        self.force[r] = bank.force(&start);
        for j in 1..=n {
            let k = (r + j) % n;
            // The segment into P starts at `run`: its shared start serves every loop closing
            // on it and the segment itself (the walk's, where `run` is the walk's state).
            let walked = trail.get(j - 1);
            let segment = match walked {
                Some(step) if j > first => step.start,
                _ => bank.start(&run, self.u[k]),
            };
            self.close_pairs(bank, &mut pairing, (&run, &segment), (j, r));
            let d = match walked {
                Some(step) if j >= first => {
                    M::assign(&mut run, &step.state);
                    step.d
                }
                _ => bank.advance_from(&segment, &mut run, self.u[k]),
            };
            d_period += d;
            if let Some(top) = pairing.stack.last_mut() {
                top.d += d;
            }
            self.force[k] = bank.force(&run);
            if j < n {
                pairing.stack.push(Entry {
                    j,
                    state: run.clone(),
                    d: 0.0,
                });
            }
        }
        let major = self.major(bank, (&start, &run), d_period, (r, min));
        self.loops = nest(major, pairing.found);
    }

    /// Closes every pair that the segment into `P` (rotated index `j`, from `run` with its
    /// shared start `segment`) completes, innermost first.
    #[inline]
    fn close_pairs<M: Segmental>(
        &self,
        bank: &M,
        p: &mut Pairing<M::State>,
        (run, segment): (&M::State, &M::Start),
        (j, r): (usize, usize),
    ) {
        let u_p = self.u[(r + j) % self.u.len()];
        // The pair on the bottom entry (the global maximum) is the major loop, closed at the end.
        while p.stack.len() >= 3 {
            let m = p.stack.len();
            let (a, b) = (&p.stack[m - 2], &p.stack[m - 1]);
            let (u_a, u_b) = (M::input(&a.state), M::input(&b.state));
            if (u_p - u_b).abs() < (u_b - u_a).abs() {
                break;
            }
            // The arc ends where the input is back at u_A, on the segment into P.
            M::assign(&mut p.scratch, run);
            let d = a.d + b.d + bank.advance_from(segment, &mut p.scratch, u_a);
            // Every loop closed since A was pushed starts after A and lies in this arc.
            let row = p.found.len();
            while let Some(&(_, inside)) = p.roots.last().filter(|&&(start, _)| start > a.j) {
                p.found[inside].parent = Some(row);
                p.roots.pop();
            }
            p.roots.push((a.j, row));
            p.found
                .push(self.found(bank, (a, b, j - 1), &p.scratch, d, r));
            let merged = a.d + b.d;
            p.stack.truncate(m - 2);
            if let Some(below) = p.stack.last_mut() {
                below.d += merged;
            }
        }
    }

    /// The major loop: from the global maximum `u[r]` (periodic state `start`) through the
    /// first global minimum `min` and back (state `end`), with the period's dissipation.
    fn major<M: Segmental>(
        &self,
        bank: &M,
        (start, end): (&M::State, &M::State),
        d_period: f64,
        (r, min): (usize, f64),
    ) -> Loop {
        let n = self.u.len();
        let lowest = (0..n).find(|&j| self.u[(r + j) % n] == min).unwrap_or(0);
        // Over the whole period the state returns to the periodic state: exactly for the
        // Masing models, to the fixed point's few ulps for single-state models (S1), which
        // would otherwise show as a stored-energy change and a gap of 1e-16.
        let energy = bank.arc(start, start, d_period);
        let rho_r = self.rho[r];
        Loop {
            kind: LoopKind::Major,
            start: self.point(r, rho_r),
            reversal: self.point((r + lowest) % n, rho_r + self.rotated(r, lowest)),
            end: LoopPoint {
                rho: rho_r + self.period(),
                u: self.u[r],
                y: bank.force(end),
            },
            energy,
            parent: None,
            depth: 0,
        }
    }

    /// The record of the loop `(A, B)` closing on the segment after rotated index `prev`, its
    /// end state `end` and dissipation `d`.
    fn found<M: Segmental>(
        &self,
        bank: &M,
        (a, b, prev): (&Entry<M::State>, &Entry<M::State>, usize),
        end: &M::State,
        d: f64,
        r: usize,
    ) -> Loop {
        let n = self.u.len();
        let from = self.rotated(r, a.j);
        let u_a = M::input(&a.state);
        let to = self.rotated(r, prev) + (u_a - self.u[(r + prev) % n]).abs();
        // Reported from rho_A within [0, P).
        let mut rho_a = self.rho[r] + from;
        if rho_a >= self.period() {
            rho_a -= self.period();
        }
        let k_a = (r + a.j) % n;
        Loop {
            kind: LoopKind::Minor,
            start: self.point(k_a, rho_a),
            reversal: self.point((r + b.j) % n, rho_a + self.rotated(r, b.j) - from),
            end: LoopPoint {
                rho: rho_a + (to - from),
                u: M::input(end),
                y: bank.force(end),
            },
            energy: bank.arc(&a.state, end, d),
            parent: None,
            depth: 0,
        }
    }

    /// `rho` of rotated index `j` from the start `r`.
    fn rotated(&self, r: usize, j: usize) -> f64 {
        let n = self.u.len();
        if r + j >= n {
            self.rho[r + j - n] + self.period() - self.rho[r]
        } else {
            self.rho[r + j] - self.rho[r]
        }
    }

    fn point(&self, k: usize, rho: f64) -> LoopPoint {
        LoopPoint {
            rho,
            u: self.u[k],
            y: self.force[k],
        }
    }

    fn check_finite(&self) -> Result<(), ZooError> {
        if !self.force.iter().all(|f| f.is_finite()) {
            return Err(ZooError::Overflow { what: "the force" });
        }
        let finite = |e: &ArcEnergy| {
            [e.work, e.stored_energy_change, e.dissipation, e.closure_gap]
                .iter()
                .all(|x| x.is_finite())
        };
        if !self.loops.iter().all(|l| finite(&l.energy)) {
            return Err(ZooError::Overflow {
                what: "the energy of a loop",
            });
        }
        Ok(())
    }

    /// Number of turning points in one period.
    pub fn len(&self) -> usize {
        self.u.len()
    }

    pub fn is_empty(&self) -> bool {
        self.u.is_empty()
    }

    /// The period `P`, the input's total variation over one period.
    pub fn period(&self) -> f64 {
        self.rho[self.u.len()]
    }

    /// Turning points `u_k`.
    pub fn turning_points(&self) -> &[f64] {
        &self.u
    }

    /// `rho_k` of the turning points.
    pub fn turning_rho(&self) -> &[f64] {
        &self.rho[..self.u.len()]
    }

    /// The periodic force at the turning points.
    pub fn turning_force(&self) -> &[f64] {
        &self.force
    }

    /// The major loop (`[0]`) and every minor loop, ordered by where their arcs start (a parent
    /// before its children), with their energies: the records of [`crate::HysteresisLoop`].
    pub fn loops(&self) -> &[Loop] {
        &self.loops
    }

    /// The work over one period.
    pub fn work_per_period(&self) -> f64 {
        self.loops[0].energy.work
    }
}

/// The major loop and the minor loops ordered by where their arcs start, with parents and
/// depths. Rainflow closes a loop after every loop inside it, and disjoint loops in the order
/// they start: `found` is the tree of loops in post-order, its parents known (the index of the
/// closed loop each lies in, `None` for the major loop), so each loop's place in pre-order (a
/// parent before its children, siblings by start) follows in two linear passes, without a sort:
/// a loop's subtree takes `size` places, handed out from the end of its parent's range to its
/// children from the last one back. The records are then moved to their places where they are.
fn nest(major: Loop, mut found: Vec<Loop>) -> Vec<Loop> {
    let m = found.len();
    // Node m is the major loop's. Indices fit u32: n <= MAX_STATES < 2^32.
    let mut tree = vec![Node::default(); m + 1];
    let up = |l: &Loop| l.parent.unwrap_or(m);
    for i in 0..m {
        tree[i].size += 1;
        let p = up(&found[i]);
        tree[p].size += tree[i].size;
    }
    tree[m].size += 1;
    tree[m].free = tree[m].size;
    for i in (0..m).rev() {
        let p = up(&found[i]);
        tree[p].free -= tree[i].size;
        let place = tree[p].free;
        tree[i] = Node {
            place,
            free: place + tree[i].size,
            depth: tree[p].depth + 1,
            ..tree[i]
        };
        tree[place as usize].at = i as u32;
    }
    tree[0].at = m as u32;
    for (record, node) in found.iter_mut().zip(&tree) {
        record.parent = Some(tree[record.parent.unwrap_or(m)].place as usize);
        record.depth = node.depth as usize;
    }
    found.push(major);
    // Each cycle of the permutation pulled round once: every record is copied once (a swap
    // would copy it three times).
    for start in 0..=m {
        if tree[start].at as usize == start {
            continue;
        }
        let first = found[start].clone();
        let mut k = start;
        loop {
            let from = tree[k].at as usize;
            tree[k].at = k as u32;
            if from == start {
                found[k] = first;
                break;
            }
            found[k] = found[from].clone();
            k = from;
        }
    }
    found
}

/// A loop's subtree in [`nest`]: its size, its place in pre-order, the first place after its
/// range not yet handed to a child, its depth; and the loop whose place is this index.
#[derive(Debug, Clone, Copy, Default)]
struct Node {
    size: u32,
    place: u32,
    free: u32,
    depth: u32,
    at: u32,
}

impl ZooLoop {
    /// The periodic response at each of `rhos` (any real numbers: the loop is periodic), by
    /// one walk over the period from the model's periodic state: `model` must be the one the
    /// loop was computed for.
    pub fn points<M: Segmental>(&self, model: &M, rhos: &[f64]) -> Vec<LoopPoint> {
        let n = self.u.len();
        let p = self.period();
        let r = self.start_index();
        let min = self.u.iter().fold(f64::MAX, |m, &x| m.min(x));
        // Each rho as an offset along the period walked from u[r].
        let offset = |rho: f64| {
            let x = (rho - self.rho[r]).rem_euclid(p);
            if x.is_finite() {
                x
            } else {
                0.0
            }
        };
        let mut order: Vec<usize> = (0..rhos.len()).collect();
        order.sort_by(|&a, &b| offset(rhos[a]).total_cmp(&offset(rhos[b])));
        let mut out = vec![
            LoopPoint {
                rho: 0.0,
                u: 0.0,
                y: 0.0
            };
            rhos.len()
        ];
        let mut run = model.periodic_start(&self.u, r, min);
        let mut scratch = run.clone();
        let (mut j, mut walked) = (0, 0.0);
        for i in order {
            let x = offset(rhos[i]);
            // Whole segments up to the one holding x.
            while j < n {
                let length = (self.u[(r + j + 1) % n] - self.u[(r + j) % n]).abs();
                if walked + length > x {
                    break;
                }
                model.advance(&mut run, self.u[(r + j + 1) % n]);
                walked += length;
                j += 1;
            }
            let k = (r + j) % n;
            let direction = (self.u[(k + 1) % n] - self.u[k]).signum();
            M::assign(&mut scratch, &run);
            let u = self.u[k] + direction * (x - walked);
            model.advance(&mut scratch, u);
            out[i] = LoopPoint {
                rho: rhos[i],
                u,
                y: model.force(&scratch),
            };
        }
        out
    }

    /// `n` points evenly spaced over one period, both ends included (`rho = 0` and `P`), `n`
    /// checked first as for LuGre's loop.
    ///
    /// # Errors
    /// [`crate::error::SamplesError::TooFew`] for `n < 2`, [`crate::error::SamplesError::TooMany`] above
    /// [`crate::loops::MAX_SAMPLES`].
    pub fn try_sample<M: Segmental>(
        &self,
        model: &M,
        n: usize,
    ) -> Result<Vec<LoopPoint>, crate::error::SamplesError> {
        crate::loops::check_samples(n)?;
        let p = self.period();
        let rhos: Vec<f64> = (0..n)
            .map(|i| {
                if i == n - 1 {
                    p
                } else {
                    p * (i as f64 / (n - 1) as f64)
                }
            })
            .collect();
        Ok(self.points(model, &rhos))
    }

    /// The index of the first global maximum, where the engine's walk starts.
    fn start_index(&self) -> usize {
        let max = self.u.iter().fold(f64::MIN, |m, &x| m.max(x));
        self.u.iter().position(|&x| x == max).unwrap_or(0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::zoo::{BoucWen, MaxwellSlip};

    /// Alternating steps of a fixed LCG in `[0.01, 1)`, with ties of extreme values now and
    /// then (steps repeated exactly).
    fn walk(n: usize, seed: u64) -> TurningPoints {
        let mut state = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
        let mut next = move || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let (mut u, mut step) = (0.0, 0.5);
        let values: Vec<f64> = (0..n)
            .map(|i| {
                if next() > 0.2 {
                    step = 0.01 + 0.99 * next();
                }
                u += if i % 2 == 0 { step } else { -step };
                u
            })
            .collect();
        TurningPoints::new(&values).expect("reversals")
    }

    /// The order, parents and depths against their definitions, from the records alone: loops
    /// by where their arcs start along the period walked from the major loop's start (longer
    /// first on a tie), each one's parent the last loop before it whose arc contains it.
    fn check(loops: &[Loop], period: f64) {
        let rho0 = loops[0].start.rho;
        let arc = |l: &Loop| {
            let from = (l.start.rho - rho0).rem_euclid(period);
            (from, from + (l.end.rho - l.start.rho))
        };
        assert_eq!(loops[0].parent, None);
        for (i, l) in loops.iter().enumerate().skip(1) {
            let (from, to) = arc(l);
            let (prev_from, prev_to) = arc(&loops[i - 1]);
            assert!(i == 1 || prev_from < from || (prev_from == from && prev_to >= to));
            let parent = (1..i)
                .rev()
                .find(|&k| {
                    let (a, c) = arc(&loops[k]);
                    a <= from && to <= c
                })
                .unwrap_or(0);
            assert_eq!(l.parent, Some(parent), "loop {i}");
            assert_eq!(l.depth, loops[parent].depth + 1, "loop {i}");
        }
    }

    #[test]
    fn loops_come_by_start_with_their_smallest_container() {
        let masing = MaxwellSlip::new(&[1.0, 2.0, 3.0], &[0.2, 0.5, 0.9]).expect("valid");
        let single = BoucWen::new(0.5, 1.0, 4.0, 0.75, 1.0).expect("valid");
        for seed in 0..300u64 {
            let input = walk(2 + (seed as usize * 7) % 200, seed);
            let hl = ZooLoop::new(masing.bank(), &input).expect("finite");
            check(hl.loops(), hl.period());
            let hl = ZooLoop::new(&single, &input).expect("finite");
            check(hl.loops(), hl.period());
        }
    }
}
