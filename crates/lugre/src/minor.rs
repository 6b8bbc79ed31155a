//! Every loop of a periodic input: the major loop (the whole period) and all minor loops,
//! with their nesting and energies (DESIGN §1, "Minor loops"; the paper's closing remark made
//! precise).
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
//! Energies over an arc (`arc_energy.rs`): short arcs are summed piece by piece, long ones
//! from double-double prefix sums, and the work is taken from whichever of its two forms
//! (`integral (y - y_A) dpsi` or `dV + D`) rounds less.

use crate::arc_energy::{arc_energy, direct_work_is_better, stored_energy_change, ArcEnergy};
use crate::hysteresis::{HysteresisLoop, LoopPoint, Position};

/// Minor loops whose arcs cross at most this many segments are summed piece by piece, which
/// also gives the direct form of their work (see [`crate::arc_energy`]); longer ones use the
/// loop's prefix sums.
const DIRECT_WORK_MAX_SEGMENTS: usize = 64;

/// Whether a loop is the major loop (the whole period) or a minor loop.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum LoopKind {
    Major,
    Minor,
}

/// One loop of the hysteresis curve, with the energy over its arc.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Loop {
    pub kind: LoopKind,
    /// Where the arc starts (`rho_A`, in `[0, P)`).
    pub start: LoopPoint,
    /// The reversal the loop turns at (`rho_B`).
    pub reversal: LoopPoint,
    /// Where the input first returns to `u_A` (`rho_C`; may exceed `P` when the arc wraps).
    pub end: LoopPoint,
    /// `W = integral y° dpsi` over the arc, nested loops included.
    pub work: f64,
    /// `dV = (y_C^2 - y_A^2) / (2 sigma0)`, the change of the energy stored in the bristles.
    pub stored_energy_change: f64,
    /// `D = W - dV = (1/g0) integral y°^2 drho >= 0`.
    pub dissipation: f64,
    /// `y_C - y_A`: minor loops do not close in general (paper Fig. 15).
    pub closure_gap: f64,
    /// Index of the smallest loop whose arc contains this one (`None` for the major loop).
    pub parent: Option<usize>,
    /// 0 for the major loop, parent's depth + 1 otherwise.
    pub depth: usize,
}

/// A rainflow cycle in the rotated sequence: indices `a`, `b` (turning points `j`, where
/// turning point `j` is `(start + j) % n` of the original) and the end of its arc.
#[derive(Debug, Clone, Copy)]
struct Cycle {
    a: usize,
    b: usize,
    /// End of the arc as (segment `j`, offset along it), ordered lexicographically.
    end: (usize, f64),
}

struct StackEntry {
    j: usize,
    /// The first later turning point equal to the value below this entry (a tie that did not
    /// close the cycle).
    touch: Option<usize>,
}

/// The rotation of `u` that starts at a global maximum and is lexicographically greatest
/// (the minimum-expression algorithm, O(n)).
pub(crate) fn canonical_start(u: &[f64]) -> usize {
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

/// The rainflow cycles of the cyclic sequence `v` (already rotated to a global maximum and
/// closed: `v[n] == v[0]`), in the order they close.
fn rainflow_cycles(v: &[f64]) -> Vec<Cycle> {
    let mut stack: Vec<StackEntry> = Vec::with_capacity(64);
    let mut cycles = Vec::with_capacity(v.len() / 2);
    for p in 0..v.len() {
        stack.push(StackEntry { j: p, touch: None });
        while stack.len() >= 3 {
            let m = stack.len();
            let (a, b) = (stack[m - 3].j, stack[m - 2].j);
            let x = (v[p] - v[b]).abs();
            let y = (v[b] - v[a]).abs();
            let rising = v[p] > v[b];
            if x > y || (x == y && rising) {
                let end = match stack[m - 2].touch {
                    Some(t) => (t, 0.0),
                    None if x == y => (p, 0.0),
                    None => (p - 1, (v[a] - v[p - 1]).abs()),
                };
                cycles.push(Cycle { a, b, end });
                stack.drain(m - 3..m - 1);
            } else {
                if x == y && stack[m - 2].touch.is_none() {
                    stack[m - 2].touch = Some(p);
                }
                break;
            }
        }
    }
    cycles
}

/// All loops of `hl`: `[0]` is the major loop, then the minor loops ordered by where their
/// arcs start (so a parent comes before its children).
pub fn minor_loops(hl: &HysteresisLoop) -> Vec<Loop> {
    let n = hl.len();
    let u = hl.turning_points();
    let start = canonical_start(u);
    let v: Vec<f64> = u[start..].iter().chain(&u[..=start]).copied().collect();

    let mut cycles = rainflow_cycles(&v);
    // The major loop turns at the first global minimum: nothing goes strictly below it, so it
    // is always a cycle's reversal, paired with the last global maximum before it. That cycle
    // ends at the next occurrence of the global maximum, which is the period's end unless the
    // maximum repeats; the major loop is the whole period all the same (Theorem A with
    // `umax1 == umax2`: the arc through the global minimum is not a minor loop).
    let lowest = (0..n).fold(0, |m, j| if v[j] < v[m] { j } else { m });
    let major_at = cycles
        .iter()
        .position(|c| c.b == lowest)
        .expect("the global minimum is a reversal of some cycle");
    let major = Cycle {
        a: 0,
        b: lowest,
        end: (n, 0.0),
    };
    cycles.swap_remove(major_at);
    // Every turning point starts at most one minor cycle: ordering them by where their arcs
    // start is a counting sort.
    let mut by_start = vec![usize::MAX; n];
    for (i, c) in cycles.iter().enumerate() {
        by_start[c.a] = i;
    }
    let ordered = by_start
        .iter()
        .filter(|&&i| i != usize::MAX)
        .map(|&i| &cycles[i]);

    // `start + j < 2n + 1` for every index of the closed sequence: at most two subtractions
    // rather than an integer division per point.
    let position = |j: usize, offset: f64| {
        let (mut k, mut wraps) = (start + j, 0u32);
        while k >= n {
            k -= n;
            wraps += 1;
        }
        Position { k, wraps, offset }
    };
    let model = hl.model();
    let mut loops = Vec::with_capacity(cycles.len() + 1);
    let mut open: Vec<(usize, (usize, f64))> = Vec::new(); // (loop index, arc end)
    for (i, c) in std::iter::once(&major).chain(ordered).enumerate() {
        while let Some(&(_, end)) = open.last() {
            if end.0 < c.a || (end.0 == c.a && end.1 == 0.0) {
                open.pop();
            } else {
                break;
            }
        }
        let parent = open.last().map(|&(p, _)| p);
        let depth = open.len();
        open.push((i, c.end));

        let (mut pa, mut pb, mut pc) = (
            position(c.a, 0.0),
            position(c.b, 0.0),
            position(c.end.0, c.end.1),
        );
        if pa.wraps > 0 {
            // Report the start within [0, P).
            pa.wraps -= 1;
            pb.wraps -= 1;
            pc.wraps -= 1;
        }
        // O(1) from the prefix sums; the arc is summed piece by piece only when the direct
        // form of the work rounds less than dV + D (narrow loops far from y = 0).
        let arc = hl.arc(pa, pc);
        let (start, end) = (arc.start, arc.end);
        let reversal = hl.position_point(pb);
        let dv = stored_energy_change(model, arc.closure_gap, start.y, end.y);
        let length = end.rho - start.rho;
        let energy = match (i > 0 && direct_work_is_better(model, length, dv, arc.dissipation))
            .then(|| hl.arc_sums(pa, pc, DIRECT_WORK_MAX_SEGMENTS))
            .flatten()
        {
            Some(sums) => arc_energy(model, &sums, start.y, end.y),
            None => ArcEnergy {
                work: dv + arc.dissipation,
                stored_energy_change: dv,
                dissipation: arc.dissipation,
                closure_gap: arc.closure_gap,
            },
        };
        loops.push(Loop {
            kind: if i == 0 {
                LoopKind::Major
            } else {
                LoopKind::Minor
            },
            start,
            reversal,
            end,
            work: energy.work,
            stored_energy_change: energy.stored_energy_change,
            dissipation: energy.dissipation,
            closure_gap: energy.closure_gap,
            parent,
            depth,
        });
    }
    loops
}

#[cfg(test)]
mod tests {
    use super::*;

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
        // at the greatest peak 5: 5 -1 3 -4 4 -2 -2(merged) 1 -3 5. Ranges counted by the
        // standard's §5.4.4 example: 4 (3,-1), 6 (4,-2)... checked by hand below.
        let v = [5.0, -1.0, 3.0, -4.0, 4.0, -2.0, 1.0, -3.0, 5.0];
        let cycles = rainflow_cycles(&v);
        let ranges: Vec<f64> = cycles.iter().map(|c| (v[c.b] - v[c.a]).abs()).collect();
        // (-1,3): 4; (-2,1): 3; (4,-3)... by hand: stack 5,-1,3 ; -4 closes (-1,3) r=4;
        // 5,-4,4 ; -2 ; 1 ; -3 closes (-2,1) r=3 ; 5,-4,4,-3 ; 5 closes (4,-3) r=7, then
        // (5,-4) r=9.
        assert_eq!(ranges, vec![4.0, 3.0, 7.0, 9.0]);
    }
}
