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
//! The pairing, `y°` and the energies over each arc are computed in one pass over the period
//! ([`crate::LoopTable`]: the loops as columns, in the order they close); the
//! work is taken from whichever of its two forms (`integral (y - y_A) dpsi` or `dV + D`)
//! rounds less (`arc_energy.rs`). [`minor_loops`] gives the same loops as records ordered
//! by where they start.

use crate::hysteresis::{HysteresisLoop, LoopPoint};

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

/// The rotation of `u` that starts at a global maximum and is lexicographically greatest
/// (the minimum-expression algorithm, O(n)).
pub(crate) fn canonical_start(u: &[f64]) -> usize {
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

/// All loops of `hl`: `[0]` is the major loop, then the minor loops ordered by where their
/// arcs start (so a parent comes before its children). The same loops as
/// [`HysteresisLoop::loop_table`], as records.
pub fn minor_loops(hl: &HysteresisLoop) -> Vec<Loop> {
    let table = hl.loop_table();
    let (u, rho, y) = (hl.turning_points(), hl.turning_rho(), hl.turning_y());
    let major = table.major();
    let (order, place) = table.rows_by_start();
    let turning = |k: usize, rho: f64| LoopPoint {
        rho,
        u: u[k],
        y: y[k],
    };
    order
        .iter()
        .map(|&row| {
            let (a, b) = (table.start()[row], table.reversal()[row]);
            Loop {
                kind: if row == major {
                    LoopKind::Major
                } else {
                    LoopKind::Minor
                },
                start: turning(a, rho[a]),
                reversal: turning(b, table.reversal_rho()[row]),
                end: LoopPoint {
                    rho: table.end_rho()[row],
                    u: table.end_u()[row],
                    y: table.end_y()[row],
                },
                work: table.work()[row],
                stored_energy_change: table.stored_energy_change()[row],
                dissipation: table.dissipation()[row],
                closure_gap: table.closure_gap()[row],
                parent: table.parent(row).map(|p| place[p]),
                depth: table.depth()[row],
            }
        })
        .collect()
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
}
