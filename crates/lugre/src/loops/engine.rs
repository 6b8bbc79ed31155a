//! The pairing engine: every loop of a periodic input in one pass over the period, with `y°`
//! and the energies (the paper's closing remark made precise).
//!
//! The cyclic sequence of turning points is started at a global maximum and its reversals are
//! paired by the ASTM E1049 three-point rule for repeating histories (rainflow): with the last
//! three points `A, B, P` on the stack, `X = |P - B|`, `Y = |B - A|`, the pair `(A, B)` is a
//! cycle once `X >= Y`. Each cycle is a loop: the arc from `rho_A` through `rho_B` to `rho_C`,
//! the first `rho > rho_B` where the input is back at `u_A`. That return lies on the last
//! segment into `P` (everything in between stayed strictly inside `(u_A, u_B)`), so `rho_C`
//! costs O(1) even when cycles are nested on the return branch.
//!
//! **Ties** (`X == Y`, the input comes back exactly to `u_A`): a return *upwards* to a maximum
//! closes the cycle, a return *downwards* to a minimum does not (the input must go strictly
//! below). This is the one convention under which every input of Definition 1, including
//! `umin1 == umin2` and `umax1 == umax2`, has exactly Theorem A's minor loop
//! `[rho_1, rho_5]`. When a minimum is touched without closing, the touch is remembered: if
//! that cycle closes later, its arc still ends at the first return (the touch).
//!
//! **Start**: among the global maxima the start is the one whose rotation of the sequence is
//! lexicographically greatest, so the set of loops does not depend on where the user's
//! period begins, even with repeated extreme values.
//!
//! **One pass.** The pairing runs on the period started at its canonical global maximum, with
//! `y°` and the energies carried on the rainflow stack (the same scheme as histories,
//! [`crate::cycles`]).
//!
//! Each stack entry holds the sums of the kernel (`kernel::arc::Sums`) over the pieces from its turning
//! point to the next entry up (the top entry: to the last point pushed). When the pair
//! `(A, B)` closes at the point `P`, its arc is `A -> B -> ... -> C`, `C` on the segment into
//! `P` where the input is back at `u_A`: its sums are `A`'s and `B`'s plus the piece from the
//! point before `P` to `C`. `A`'s and `B`'s sums then join the entry below. Each piece of the
//! period is thus evaluated once (plus one partial piece per loop), each loop costs O(1), the
//! stack holds `O(log n)` entries for typical inputs, and nothing is kept per turning point
//! but `y°` itself: the work is linear in `n` and streams through memory.
//!
//! Sums are double-double (`kernel::arc::Sums`) and cover only their own arc, so their rounding
//! scales with the loop they describe, not with the period.
//!
//! Rows come out in the order rainflow closes the loops: every loop after the loops it
//! contains (post-order), the major loop last. A loop's parent is the first loop after it
//! whose arc starts before it: kept with a stack of loops still without a parent.

//! **Dispatch.** [`Period::loops`] is compiled twice, portable and AVX2, chosen at run time;
//! results are bit for bit the same (no fused multiply-adds are introduced; a test compares the
//! two). Every helper it calls is `#[inline(always)]` (the kernel's inlining rule,
//! [`crate::kernel`]).

use super::table::{LoopTable, NONE};
use crate::kernel::arc::{arc_energy, Sums};
use crate::kernel::numerics::{PhiBlock, BLOCK};
use crate::kernel::piece::step;
use crate::kernel::{ArcEnergy, Relaxation};

/// The rotation of `u` that starts at a global maximum and is lexicographically greatest
/// (the minimum-expression algorithm, O(n)).
pub(super) fn canonical_start(u: &[f64]) -> usize {
    // A unique global maximum starts the greatest rotation (the common case): three
    // branch-free passes instead of the comparisons below.
    let max = u
        .iter()
        .fold(f64::NEG_INFINITY, |m, &x| if x > m { x } else { m });
    if u.iter().filter(|&&x| x == max).count() == 1 {
        return u.iter().position(|&x| x == max).unwrap_or(0);
    }
    let n = u.len();
    let (mut i, mut j, mut k) = (0usize, 1usize, 0usize);
    while i < n && j < n && k < n {
        // `i, j, k < n`: one conditional subtraction instead of an integer division.
        let wrap = |m: usize| if m >= n { m - n } else { m };
        let (x, y) = (u[wrap(i + k)], u[wrap(j + k)]);
        if x == y {
            k += 1;
            continue;
        }
        if x < y {
            i += k + 1;
        } else {
            j += k + 1;
        }
        if i == j {
            j += 1;
        }
        k = 0;
    }
    i.min(j)
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

/// Where the input came back to `u_A` without closing the cycle (the tie rule of [`crate::loops`]).
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
pub(super) struct Period<'a> {
    pub model: Relaxation,
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
    /// introduced). Why not AVX-512: BENCHMARKS.md.
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
                        let parent = table.parents_mut();
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
        let parent = table.parents_mut();
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
            ArcEnergy {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::loops::HysteresisLoop;
    use proptest::strategy::Strategy;

    #[test]
    fn canonical_start_is_the_greatest_rotation() {
        assert_eq!(canonical_start(&[0.0, 1.0, 0.2, 1.5]), 3);
        // Repeated maximum: [1, 0.5, 1, 0] > [1, 0, 1, 0.5].
        assert_eq!(canonical_start(&[0.0, 1.0, 0.5, 1.0]), 1);
        assert_eq!(canonical_start(&[1.0, 0.0, 1.0, 0.0]), 0);
    }

    #[test]
    fn astm_worked_example_as_a_repeating_history() {
        // ASTM E1049 Fig. 6 (repeating history): peaks/valleys -2 1 -3 5 -1 3 -4 4 -2, started
        // at the greatest peak 5: 5 -1 3 -4 4 -2 -2(merged) 1 -3 5. By hand: stack 5,-1,3 ; -4
        // closes (-1,3) r=4 ; 5,-4,4 ; -2 ; 1 ; -3 closes (-2,1) r=3 ; 5,-4,4,-3 ; 5 closes
        // (4,-3) r=7, then (5,-4) r=9, the major loop.
        let u = [-2.0, 1.0, -3.0, 5.0, -1.0, 3.0, -4.0, 4.0];
        let model = crate::LuGre::paper().rate_independent();
        let hl = HysteresisLoop::new(model, &crate::TurningPoints::new(&u).unwrap()).unwrap();
        let t = hl.loop_table();
        let ranges: Vec<f64> = (0..t.len())
            .map(|i| (u[t.reversal()[i]] - u[t.start()[i]]).abs())
            .collect();
        assert_eq!(ranges, vec![4.0, 3.0, 7.0, 9.0]);
        assert_eq!(t.major(), 3);
        // (-2, 1) lies inside (4, -3).
        assert_eq!(t.depth(), &[1, 2, 1, 0]);
    }

    /// Every column of a table, bit for bit.
    fn bits(t: &LoopTable) -> Vec<u64> {
        let reals = [
            t.reversal_rho(),
            t.end_rho(),
            t.end_u(),
            t.end_y(),
            t.work(),
            t.stored_energy_change(),
            t.dissipation(),
            t.closure_gap(),
        ];
        let indices = [t.start(), t.reversal(), t.depth()];
        let parents = (0..t.len()).map(|r| t.parent(r).map_or(u64::MAX, |p| p as u64));
        reals
            .iter()
            .flat_map(|c| c.iter().map(|x| x.to_bits()))
            .chain(indices.iter().flat_map(|c| c.iter().map(|&k| k as u64)))
            .chain(parents)
            .collect()
    }

    /// Both passes of `u` for `(sigma0, g0)`: `(portable, avx2)` tables and `y°`, or `None`
    /// where the CPU has no AVX2 (nothing to compare there).
    #[cfg(target_arch = "x86_64")]
    #[allow(clippy::type_complexity)]
    fn both_passes(
        u: &[f64],
        sigma0: f64,
        g0: f64,
    ) -> Option<((LoopTable, Vec<f64>), (LoopTable, Vec<f64>))> {
        if !std::arch::is_x86_feature_detected!("avx2") {
            return None;
        }
        let hl = HysteresisLoop::new(
            crate::RateIndependent::new(sigma0, g0).ok()?,
            &crate::TurningPoints::new(u).ok()?,
        )
        .ok()?;
        let (u, rho) = (hl.turning_points(), &hl.rho);
        let r = canonical_start(u);
        let period = Period {
            model: Relaxation::new(sigma0, g0),
            u,
            rho,
            r,
            y_r: hl.periodic_value(r),
        };
        let mut y_portable = vec![0.0; u.len() + 1];
        let mut y_avx2 = vec![0.0; u.len() + 1];
        let portable = period.loops_portable(&mut y_portable);
        // SAFETY: the CPU has AVX2 (checked above).
        let avx2 = unsafe { period.loops_avx2(&mut y_avx2) };
        Some(((portable, y_portable), (avx2, y_avx2)))
    }

    #[cfg(target_arch = "x86_64")]
    proptest::proptest! {
        #![proptest_config(proptest::test_runner::Config {
            cases: 500,
            rng_seed: proptest::test_runner::RngSeed::Fixed(0x6176_7832),
            ..Default::default()
        })]

        /// The AVX2 and the portable pass give bit-identical tables and `y°`: integers (ties,
        /// repeated extrema) and continuous values, over stiffnesses from the series path
        /// (`a l < 1/2`) to saturation (`a l` in the hundreds), and periods longer than a block.
        #[test]
        fn avx2_and_portable_passes_agree_bit_for_bit(
            values in proptest::prop_oneof![
                proptest::collection::vec((-8i32..=8).prop_map(f64::from), 2..200),
                proptest::collection::vec(-1.0f64..1.0, 2..300),
            ],
            log_a in -3.0f64..3.0,
        ) {
            let g0 = 1.5;
            if let Some(((tp, yp), (ta, ya))) = both_passes(&values, g0 * 10f64.powf(log_a), g0) {
                proptest::prop_assert_eq!(bits(&tp), bits(&ta));
                let bits_of = |y: &[f64]| y.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
                proptest::prop_assert_eq!(bits_of(&yp), bits_of(&ya));
            }
        }
    }
}
