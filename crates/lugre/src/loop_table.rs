//! Every loop of a periodic input in one pass: the rainflow pairing of [`crate::minor`] run on
//! the period started at its canonical global maximum, with `y°` and the energies carried on
//! the rainflow stack (the same scheme as histories, [`crate::cycles`]).
//!
//! Each stack entry holds the sums of [`crate::arc_energy`] over the pieces from its turning
//! point to the next entry up (the top entry: to the last point pushed). When the pair
//! `(A, B)` closes at the point `P`, its arc is `A -> B -> ... -> C`, `C` on the segment into
//! `P` where the input is back at `u_A`: its sums are `A`'s and `B`'s plus the piece from the
//! point before `P` to `C`. `A`'s and `B`'s sums then join the entry below. Each piece of the
//! period is thus evaluated once (plus one partial piece per loop), each loop costs O(1), the
//! stack holds `O(log n)` entries for typical inputs, and nothing is kept per turning point
//! but `y°` itself: the work is linear in `n` and streams through memory.
//!
//! Sums are double-double (`arc_energy::Sums`) and cover only their own arc, so their rounding
//! scales with the loop they describe, not with the period.
//!
//! Rows come out in the order rainflow closes the loops: every loop after the loops it
//! contains (post-order), the major loop last. A loop's parent is the first loop after it
//! whose arc starts before it: kept with a stack of loops still without a parent.

use crate::arc_energy::{arc_energy, Sums};
use crate::hysteresis::step;
use crate::memory::Columns;
use crate::model::RateIndependent;
use crate::numerics::{PhiBlock, BLOCK};

/// Marks a stack entry without a touch, and the major loop's parent.
const NONE: usize = usize::MAX;

/// All loops of a periodic input as columns, one row per loop, in the order the loops close:
/// each loop after every loop nested in it, the major loop last (see [`crate::minor`] for the
/// pairing rule and [`crate::HysteresisLoop::loops`] for the same loops as records ordered by
/// where they start).
///
/// Start and reversal are turning points, given by their index `k` into
/// [`HysteresisLoop::turning_points`](crate::HysteresisLoop::turning_points) (the loop's `u`
/// and `y°` there are that array's and
/// [`turning_y`](crate::HysteresisLoop::turning_y)'s); the start's `rho` is in `[0, P)`, the
/// reversal's and the end's may exceed `P` when the arc wraps round the period.
///
/// ```
/// use lugre::{HysteresisLoop, LuGre, TurningPoints};
///
/// // The ASTM E1049 history as one period: three minor loops and the major loop.
/// let u = [-2.0, 1.0, -3.0, 5.0, -1.0, 3.0, -4.0, 4.0];
/// let model = LuGre::paper().rate_independent();
/// let hl = HysteresisLoop::new(model, &TurningPoints::new(&u).unwrap()).unwrap();
/// let t = hl.loop_table();
/// assert_eq!(t.len(), 4);
/// assert_eq!(t.major(), 3); // closes last
/// let u_a: Vec<f64> = t.start().iter().map(|&k| u[k]).collect();
/// assert_eq!(u_a, [-1.0, -2.0, 4.0, 5.0]);
/// assert!(t.dissipation().iter().all(|&d| d > 0.0));
/// assert_eq!(t.parent(1), Some(2)); // (-2, 1) lies inside (4, -3)
/// assert_eq!(hl.work_per_period(), t.work()[t.major()]);
/// ```
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LoopTable {
    len: usize,
    /// Turning points in the period.
    turning_points: usize,
    /// [`START`], [`REVERSAL`], [`PARENT`], [`DEPTH`].
    indices: Columns<usize>,
    /// [`REVERSAL_RHO`] to [`CLOSURE_GAP`].
    reals: Columns<f64>,
}

const START: usize = 0;
const REVERSAL: usize = 1;
const PARENT: usize = 2;
const DEPTH: usize = 3;
const REVERSAL_RHO: usize = 0;
const END_RHO: usize = 1;
const END_U: usize = 2;
const END_Y: usize = 3;
const WORK: usize = 4;
const STORED_ENERGY_CHANGE: usize = 5;
const DISSIPATION: usize = 6;
const CLOSURE_GAP: usize = 7;

impl LoopTable {
    /// Number of loops, the major loop included.
    pub fn len(&self) -> usize {
        self.len
    }

    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The row of the major loop (the last one).
    pub fn major(&self) -> usize {
        self.len - 1
    }

    fn index(&self, i: usize) -> &[usize] {
        &self.indices.column(i)[..self.len]
    }

    fn real(&self, i: usize) -> &[f64] {
        &self.reals.column(i)[..self.len]
    }

    /// Index `k` of the turning point each loop starts at (`rho_A = rho_k`, `u_A = u_k`).
    pub fn start(&self) -> &[usize] {
        self.index(START)
    }

    /// Index `k` of the turning point each loop turns at.
    pub fn reversal(&self) -> &[usize] {
        self.index(REVERSAL)
    }

    /// `rho_B` of each loop's reversal (`rho_k`, plus `P` when the arc wrapped before it).
    pub fn reversal_rho(&self) -> &[f64] {
        self.real(REVERSAL_RHO)
    }

    /// `rho_C`, where the input first returns to `u_A`.
    pub fn end_rho(&self) -> &[f64] {
        self.real(END_RHO)
    }

    /// `u` at the end (`u_A` up to the rounding of `u_k + s offset`).
    pub fn end_u(&self) -> &[f64] {
        self.real(END_U)
    }

    /// `y°(rho_C)`.
    pub fn end_y(&self) -> &[f64] {
        self.real(END_Y)
    }

    /// `W = integral y° dpsi` over each arc, nested loops included.
    pub fn work(&self) -> &[f64] {
        self.real(WORK)
    }

    /// `dV = (y_C^2 - y_A^2) / (2 sigma0)`.
    pub fn stored_energy_change(&self) -> &[f64] {
        self.real(STORED_ENERGY_CHANGE)
    }

    /// `D = W - dV >= 0`.
    pub fn dissipation(&self) -> &[f64] {
        self.real(DISSIPATION)
    }

    /// `y_C - y_A`.
    pub fn closure_gap(&self) -> &[f64] {
        self.real(CLOSURE_GAP)
    }

    /// Row of the smallest loop containing each one (always a later row); `None` for the major
    /// loop.
    pub fn parent(&self, row: usize) -> Option<usize> {
        let p = self.index(PARENT)[row];
        (p != NONE).then_some(p)
    }

    /// 0 for the major loop, the parent's depth + 1 otherwise.
    pub fn depth(&self) -> &[usize] {
        self.index(DEPTH)
    }

    /// The rows in the order of [`crate::HysteresisLoop::loops`] (the major loop, then the
    /// minor loops by where their arcs start in the major loop's period), and the place of
    /// each row in that order (to renumber parents). A counting sort: each turning point starts
    /// at most one minor loop.
    pub fn rows_by_start(&self) -> (Vec<usize>, Vec<usize>) {
        if self.is_empty() {
            return (Vec::new(), Vec::new());
        }
        let (n, major) = (self.turning_points, self.major());
        let r = self.start()[major];
        let mut by_start = vec![NONE; n];
        for (row, &k) in self.start()[..major].iter().enumerate() {
            by_start[if k >= r { k - r } else { k + n - r }] = row;
        }
        let order: Vec<usize> = std::iter::once(major)
            .chain(by_start.into_iter().filter(|&row| row != NONE))
            .collect();
        let mut place = vec![0; self.len];
        for (i, &row) in order.iter().enumerate() {
            place[row] = i;
        }
        (order, place)
    }

    /// Room for the loops of a period of `n` turning points (at most `n / 2 + 1`).
    fn for_turning_points(n: usize) -> Self {
        let rows = n / 2 + 1;
        Self {
            len: 0,
            turning_points: n,
            indices: Columns::zeroed(4, rows),
            reals: Columns::zeroed(8, rows),
        }
    }

    /// The loop in row `row` (its parent entry was made when it closed, [`adopt`]).
    #[inline]
    fn set(
        &mut self,
        row: usize,
        (start, reversal): (usize, usize),
        reversal_rho: f64,
        end: (f64, f64, f64),
        energy: crate::arc_energy::ArcEnergy,
    ) {
        self.indices.column_mut(START)[row] = start;
        self.indices.column_mut(REVERSAL)[row] = reversal;
        let reals = [
            (REVERSAL_RHO, reversal_rho),
            (END_RHO, end.0),
            (END_U, end.1),
            (END_Y, end.2),
            (WORK, energy.work),
            (STORED_ENERGY_CHANGE, energy.stored_energy_change),
            (DISSIPATION, energy.dissipation),
            (CLOSURE_GAP, energy.closure_gap),
        ];
        for (column, value) in reals {
            self.reals.column_mut(column)[row] = value;
        }
        self.len = self.len.max(row + 1);
    }

    /// Depths from the parents: a parent is always a later row, so one backward pass.
    fn fill_depths(&mut self) {
        for i in (0..self.len).rev() {
            let p = self.index(PARENT)[i];
            if p != NONE {
                let d = self.index(DEPTH)[p] + 1;
                self.indices.column_mut(DEPTH)[i] = d;
            }
        }
    }
}

/// An open reversal on the rainflow stack.
#[derive(Debug, Clone, Copy)]
struct Entry {
    /// Index in the rotated period.
    j: usize,
    u: f64,
    y: f64,
    /// Index into the touches of the first later point equal to the value below this entry
    /// (a tie that did not close the cycle), or [`NONE`].
    touch: usize,
}

/// Where the input came back to `u_A` without closing the cycle (see [`crate::minor`]).
#[derive(Debug, Clone, Copy)]
struct Touch {
    j: usize,
    u: f64,
    y: f64,
    /// Sums from `A` to the touch.
    sums: Sums,
}

/// The period of `u` (with `rho_k` in `rho`, `rho[n] = P`) started at turning point `r`, where
/// `y° = y_r`.
pub(crate) struct Period<'a> {
    pub model: RateIndependent,
    pub u: &'a [f64],
    pub rho: &'a [f64],
    pub r: usize,
    pub y_r: f64,
}

impl Period<'_> {
    /// Turning point `k` and the period it falls in, for index `j <= n` of the rotated period.
    #[inline]
    fn position(&self, j: usize) -> (usize, u32) {
        let k = self.r + j;
        let n = self.u.len();
        if k >= n {
            (k - n, 1)
        } else {
            (k, 0)
        }
    }

    /// The index in the rotated period of the first global minimum, where the major loop
    /// turns.
    fn first_minimum(&self) -> usize {
        let u = self.u;
        let min = u
            .iter()
            .fold(f64::INFINITY, |m, &x| if x < m { x } else { m });
        let (after, before) = (&u[self.r..], &u[..self.r]);
        match after.iter().position(|&x| x == min) {
            Some(j) => j,
            None => after.len() + before.iter().position(|&x| x == min).unwrap_or(0),
        }
    }

    #[inline]
    fn rho_at(&self, k: usize, wraps: u32, offset: f64) -> f64 {
        self.rho[k] + f64::from(wraps) * self.rho[self.u.len()] + offset
    }

    /// Every loop, and `y°` at every turning point (written to `y`, `n + 1` long with
    /// `y[n] = y[0]`), in one pass over the period.
    ///
    /// The pass is compiled a second time for AVX2, chosen at run time: the sums are lane
    /// arrays, and adding two of them is then a few vector instructions, as is the series of a
    /// block of pieces. Results are bit for bit the same (no fused multiply-adds are
    /// introduced). (An AVX-512 build measured no faster.)
    pub fn loops(&self, y: &mut [f64]) -> LoopTable {
        #[cfg(target_arch = "x86_64")]
        {
            if std::arch::is_x86_feature_detected!("avx2") {
                // SAFETY: the CPU has the features the function is compiled for.
                return unsafe { self.loops_avx2(y) };
            }
        }
        self.loops_portable(y)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn loops_avx2(&self, y: &mut [f64]) -> LoopTable {
        self.loops_portable(y)
    }

    #[inline(always)]
    fn loops_portable(&self, y: &mut [f64]) -> LoopTable {
        let (model, u, n) = (self.model, self.u, self.u.len());
        let lowest = self.first_minimum();
        let mut table = LoopTable::for_turning_points(n);
        // Loops closed so far (rows taken, some still in `closed`).
        let mut rows = 0;
        let mut stack: Vec<Entry> = Vec::with_capacity(64);
        // The sums of each entry, from its point to the next entry up (the top entry: to the
        // last point pushed); apart from the entries, which are read far more often.
        // `open_sums[i + 1]` belongs to `stack[i]`; `open_sums[0]` collects what falls off the
        // bottom of the stack (after a repeated global maximum), so that every merge has an
        // entry below it to go to.
        let mut open_sums: Vec<Sums> = Vec::with_capacity(64);
        open_sums.push(Sums::default());
        let mut touches: Vec<Touch> = Vec::new();
        // Loops without a parent yet: (rotated start, row).
        let mut roots: Vec<(usize, usize)> = Vec::with_capacity(64);

        let (mut u_prev, mut y_prev) = (u[self.r], self.y_r);
        y[self.r] = self.y_r;
        stack.push(Entry {
            j: 0,
            u: u_prev,
            y: y_prev,
            touch: NONE,
        });
        open_sums.push(Sums::default());
        let mut z = [0.0; BLOCK];
        let mut family = PhiBlock::default();
        // Loops closed but not yet in the table: the pieces to their ends are evaluated a
        // block at a time, like the walk's.
        let mut closed: Vec<Closed> = Vec::with_capacity(BLOCK);
        let mut ends = PhiBlock::default();
        // Turning point `k` of each point of the block.
        let mut turning = [0; BLOCK];
        let mut k_prev = self.r;
        for first in (1..=n).step_by(BLOCK) {
            let points = first..(first + BLOCK).min(n + 1);
            // The families of the block's pieces in one go (vectorized), then the walk.
            for i in 0..points.len() {
                let k = if k_prev + 1 == n { 0 } else { k_prev + 1 };
                (turning[i], z[i]) = (k, model.a() * (u[k] - u[k_prev]).abs());
                k_prev = k;
            }
            family.fill(&z);
            for (i, p) in points.enumerate() {
                let k = turning[i];
                let u_p = u[k];
                let (s, l) = step(u_prev, u_p);
                let (piece_p, last) = Sums::with_piece(model, y_prev, s, l, &family.get(i));
                // The period closes: y° is periodic.
                let y_p = if p == n { self.y_r } else { piece_p.y_end };
                y[k] = y_p;

                while stack.len() >= 2 {
                    let m = stack.len();
                    let (a, b) = (stack[m - 2], stack[m - 1]);
                    let (sums_a, sums_b) = (&open_sums[m - 1], &open_sums[m]);
                    let x = (u_p - b.u).abs();
                    let range = (b.u - a.u).abs();
                    if !(x > range || (x == range && u_p > b.u)) {
                        if x == range && b.touch == NONE {
                            stack[m - 1].touch = touches.len();
                            touches.push(Touch {
                                j: p,
                                u: u_p,
                                y: y_p,
                                sums: *sums_a + *sums_b + last,
                            });
                        }
                        break;
                    }
                    let merged = *sums_a + *sums_b;
                    if b.j != lowest {
                        let (sums, end_j, offset, end_u, end) = if b.touch != NONE {
                            let t = touches[b.touch];
                            (t.sums, t.j, 0.0, t.u, End::At(t.y))
                        } else if x == range {
                            (merged + last, p, 0.0, u_p, End::At(y_p))
                        } else {
                            let offset = (a.u - u_prev).abs();
                            let end = End::Piece { y: y_prev, s };
                            (merged, p - 1, offset, u_prev + s * offset, end)
                        };
                        let parent = table.indices.column_mut(PARENT);
                        adopt(&mut roots, parent, rows, a.j, (end_j, offset));
                        closed.push(Closed {
                            row: rows,
                            start: a.j,
                            y_start: a.y,
                            reversal: b.j,
                            end_j,
                            offset,
                            end_u,
                            end,
                            sums,
                        });
                        rows += 1;
                        if closed.len() == BLOCK {
                            self.finish_rows(&mut closed, &mut ends, &mut table);
                        }
                    }
                    stack.truncate(m - 2);
                    open_sums.truncate(m - 1);
                    open_sums[m - 2] = open_sums[m - 2] + merged;
                }
                let top = stack.len();
                open_sums[top] = open_sums[top] + last;
                stack.push(Entry {
                    j: p,
                    u: u_p,
                    y: y_p,
                    touch: NONE,
                });
                open_sums.push(Sums::default());
                (u_prev, y_prev) = (u_p, y_p);
            }
        }
        y[n] = y[0];
        self.finish_rows(&mut closed, &mut ends, &mut table);

        let total = open_sums.iter().fold(Sums::default(), |acc, e| acc + *e);
        let major = rows;
        let parent = table.indices.column_mut(PARENT);
        for &(_, r) in &roots {
            parent[r] = major;
        }
        parent[major] = NONE;
        let d = total.dissipation();
        let (k_low, wraps_low) = self.position(lowest);
        table.set(
            major,
            (self.r, k_low),
            self.rho_at(k_low, wraps_low, 0.0),
            (self.rho_at(self.r, 1, 0.0), u[self.r], self.y_r),
            crate::arc_energy::ArcEnergy {
                work: d,
                stored_energy_change: 0.0,
                dissipation: d,
                closure_gap: 0.0,
            },
        );
        table.fill_depths();
        table
    }

    /// The rows of the loops in `closed`, in order: the pieces to their ends (one block of
    /// families), their energies, their places in the period.
    #[inline(always)]
    fn finish_rows(&self, closed: &mut Vec<Closed>, ends: &mut PhiBlock, table: &mut LoopTable) {
        let model = self.model;
        let mut z = [0.0; BLOCK];
        for (z, c) in z.iter_mut().zip(closed.iter()) {
            *z = match c.end {
                End::Piece { .. } => model.a() * c.offset,
                End::At(_) => 0.0,
            };
        }
        ends.fill(&z);
        for (i, c) in closed.iter().enumerate() {
            let (sums, end_y) = match c.end {
                End::Piece { y, s } => {
                    let (to_end, sums) = Sums::with_piece(model, y, s, c.offset, &ends.get(i));
                    (c.sums + sums, to_end.y_end)
                }
                End::At(y) => (c.sums, y),
            };
            let (k_a, wraps_a) = self.position(c.start);
            let (k_b, wraps_b) = self.position(c.reversal);
            let (k_c, wraps_c) = self.position(c.end_j);
            // The start is reported within [0, P).
            table.set(
                c.row,
                (k_a, k_b),
                self.rho_at(k_b, wraps_b - wraps_a, 0.0),
                (
                    self.rho_at(k_c, wraps_c - wraps_a, c.offset),
                    c.end_u,
                    end_y,
                ),
                arc_energy(model, &sums, c.y_start, end_y),
            );
        }
        closed.clear();
    }
}

/// How a closed loop's arc ends.
#[derive(Debug, Clone, Copy)]
enum End {
    /// At a point where `y°` is known.
    At(f64),
    /// `offset` along the piece from `y` in direction `s`.
    Piece { y: f64, s: f64 },
}

/// A loop that closed, before the piece to its end is evaluated: indices in the rotated
/// period, and the sums over its arc up to that piece.
#[derive(Debug, Clone, Copy)]
struct Closed {
    row: usize,
    start: usize,
    y_start: f64,
    reversal: usize,
    end_j: usize,
    offset: f64,
    end_u: f64,
    end: End,
    sums: Sums,
}

/// Makes the parent entry of the loop that closed as row `row`, with its arc from index
/// `start` to `end` (index, offset) of the rotated period, in `roots` (loops without a parent yet,
/// disjoint, ordered by where they start), and makes it the parent of the roots inside its
/// arc. A loop closes after every loop inside it, so those are on the top of `roots`, except
/// for loops past its end, which only a touch (an arc ending before its cycle closed) leaves
/// there.
#[inline]
fn adopt(
    roots: &mut Vec<(usize, usize)>,
    parent: &mut [usize],
    row: usize,
    start: usize,
    end: (usize, f64),
) {
    parent[row] = NONE;
    let past_end = |j: usize| j > end.0 || (j == end.0 && end.1 == 0.0);
    let mut top = roots.len();
    while top > 0 && past_end(roots[top - 1].0) {
        top -= 1;
    }
    let mut inside = top;
    while inside > 0 && roots[inside - 1].0 > start {
        inside -= 1;
        parent[roots[inside].1] = row;
    }
    if top == roots.len() {
        roots.truncate(inside);
        roots.push((start, row));
    } else {
        roots.splice(inside..top, std::iter::once((start, row)));
    }
}
