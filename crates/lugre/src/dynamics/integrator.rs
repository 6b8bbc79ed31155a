//! A dedicated integrator for the small stiff system of [`super::System`]: Radau IIA with three
//! stages (order 5, L-stable, stiffly accurate), simplified Newton on the full `3n x 3n` stage
//! system (`n = 4`: a 12 x 12 LU, cheaper than any transformation), error control by step
//! doubling, and the collocation polynomial of each half step as dense output for the output
//! times and for locating the sign changes of `v`.

use crate::kernel::radau::{A, C};

pub(super) const N: usize = 4;
const M: usize = 3 * N;

/// One step's result: the end state and the stage values (the collocation polynomial's nodes
/// at `t + c_i h`), plus the work done.
#[derive(Debug, Clone, Copy)]
pub(super) struct Step {
    pub y: [f64; N],
    pub stages: [[f64; N]; 3],
    pub evaluations: usize,
}

/// A Radau IIA step of size `h` from `(t, y)` for `y' = f(t, y)` with Jacobian `jac` (frozen
/// over the step), to the Newton tolerance `newton_tol` in the weighted norm `w`. `None` if
/// Newton does not converge (the caller halves the step).
pub(super) fn radau_step(
    f: &impl Fn(f64, &[f64; N]) -> [f64; N],
    jac: &[[f64; N]; N],
    t: f64,
    y: &[f64; N],
    h: f64,
    w: &[f64; N],
) -> Option<Step> {
    radau_step_with(f, &iteration_matrix(jac, h)?, t, y, h, w, [[0.0; N]; 3])
}

/// The iteration matrix `I - h (A (x) J)` of steps of size `h` with the Jacobian `jac`, factored
/// (`None` if singular): one factorization serves every step of that size and Jacobian.
pub(super) fn iteration_matrix(jac: &[[f64; N]; N], h: f64) -> Option<Lu> {
    let mut mat = [[0.0; M]; M];
    for i in 0..3 {
        for j in 0..3 {
            for r in 0..N {
                for c in 0..N {
                    mat[i * N + r][j * N + c] =
                        f64::from(u8::from(i == j && r == c)) - h * A[i][j] * jac[r][c];
                }
            }
        }
    }
    Lu::new(mat)
}

/// [`radau_step`] with the iteration matrix already factored ([`iteration_matrix`] at the same
/// `h`), Newton starting from the stage increments `guess` (`Z_i - y`; zeros, or a previous
/// collocation polynomial extrapolated to the stages).
pub(super) fn radau_step_with(
    f: &impl Fn(f64, &[f64; N]) -> [f64; N],
    lu: &Lu,
    t: f64,
    y: &[f64; N],
    h: f64,
    w: &[f64; N],
    guess: [[f64; N]; 3],
) -> Option<Step> {
    let mut z = guess; // stage increments Z_i - y
    let mut evaluations = 0;
    let mut previous = f64::INFINITY;
    for _ in 0..8 {
        let mut fz = [[0.0; N]; 3];
        for i in 0..3 {
            let mut yi = *y;
            for r in 0..N {
                yi[r] += z[i][r];
            }
            fz[i] = f(t + C[i] * h, &yi);
            evaluations += 1;
        }
        // The residual G(Z) = Z - h (A (x) I) F(Z), and the Newton update.
        let mut g = [0.0; M];
        for i in 0..3 {
            for r in 0..N {
                let mut s = z[i][r];
                for j in 0..3 {
                    s -= h * A[i][j] * fz[j][r];
                }
                g[i * N + r] = s;
            }
        }
        let dz = lu.solve(g);
        let mut norm = 0.0f64;
        for i in 0..3 {
            for r in 0..N {
                z[i][r] -= dz[i * N + r];
                norm = norm.max((dz[i * N + r] / w[r]).abs());
            }
        }
        if !norm.is_finite() || norm > 2.0 * previous && previous < f64::INFINITY {
            return None;
        }
        previous = norm;
        if norm <= 1e-3 {
            let mut stages = [*y; 3];
            for (i, s) in stages.iter_mut().enumerate() {
                for r in 0..N {
                    s[r] += z[i][r];
                }
            }
            return Some(Step {
                y: stages[2],
                stages,
                evaluations,
            });
        }
    }
    None
}

/// The collocation polynomial of a step `(t0, y0, h, stages)` at `t0 + theta h`,
/// `theta` in `[0, 1]`: Lagrange through the nodes `0, c1, c2, 1`.
pub(super) fn dense(y0: &[f64; N], stages: &[[f64; N]; 3], theta: f64) -> [f64; N] {
    let values = [y0, &stages[0], &stages[1], &stages[2]];
    let mut out = [0.0; N];
    for (k, value) in values.iter().enumerate() {
        let mut l = 1.0;
        for (m, &node) in NODES.iter().enumerate() {
            if m != k {
                l *= (theta - node) / (NODES[k] - node);
            }
        }
        for r in 0..N {
            out[r] += l * value[r];
        }
    }
    out
}

/// The stage increments of the step that follows the one `(y0, stages)` at the same size,
/// extrapolated from its collocation polynomial (Newton's starting point).
pub(super) fn next_guess(y0: &[f64; N], stages: &[[f64; N]; 3]) -> [[f64; N]; 3] {
    let y1 = stages[2];
    std::array::from_fn(|i| {
        let p = dense(y0, stages, 1.0 + C[i]);
        std::array::from_fn(|r| p[r] - y1[r])
    })
}

/// `integral f(t, y(t)) dt` over a step of size `h` from `t0`, by the Radau quadrature at its
/// stages (the weights are the tableau's last row): as accurate as the step.
pub(super) fn quadrature(
    h: f64,
    t0: f64,
    stages: &[[f64; N]; 3],
    f: impl Fn(f64, &[f64; N]) -> [f64; 2],
) -> [f64; 2] {
    let mut out = [0.0; 2];
    for i in 0..3 {
        let v = f(t0 + C[i] * h, &stages[i]);
        out[0] += h * A[2][i] * v[0];
        out[1] += h * A[2][i] * v[1];
    }
    out
}

/// The nodes of the collocation polynomial, in `theta`.
pub(super) const NODES: [f64; 4] = [0.0, C[0], C[1], C[2]];

/// LU factors with partial pivoting of a 12 x 12 matrix.
pub(super) struct Lu {
    a: [[f64; M]; M],
    pivot: [usize; M],
}

impl Lu {
    fn new(mut a: [[f64; M]; M]) -> Option<Self> {
        let mut pivot = [0; M];
        for k in 0..M {
            let p = (k..M).max_by(|&i, &j| a[i][k].abs().total_cmp(&a[j][k].abs()))?;
            if a[p][k] == 0.0 || !a[p][k].is_finite() {
                return None;
            }
            a.swap(k, p);
            pivot[k] = p;
            let pivot_row = a[k];
            for row in a.iter_mut().skip(k + 1) {
                let factor = row[k] / pivot_row[k];
                row[k] = factor;
                for (x, p) in row.iter_mut().zip(pivot_row.iter()).skip(k + 1) {
                    *x -= factor * p;
                }
            }
        }
        Some(Self { a, pivot })
    }

    fn solve(&self, mut b: [f64; M]) -> [f64; M] {
        // The factorization swapped whole rows (multipliers included): all the swaps first,
        // then the unit lower triangle.
        for k in 0..M {
            b.swap(k, self.pivot[k]);
        }
        for k in 0..M {
            for i in k + 1..M {
                b[i] -= self.a[i][k] * b[k];
            }
        }
        for k in (0..M).rev() {
            for j in k + 1..M {
                b[k] -= self.a[k][j] * b[j];
            }
            b[k] /= self.a[k][k];
        }
        b
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_for_a_linear_oscillator_to_order_five() {
        // y'' = -y as a system, one step of h: error O(h^6) per step.
        let f = |_t: f64, y: &[f64; N]| [y[1], -y[0], 0.0, 0.0];
        let jac = [
            [0.0, 1.0, 0.0, 0.0],
            [-1.0, 0.0, 0.0, 0.0],
            [0.0; 4],
            [0.0; 4],
        ];
        let w = [1e-12; 4];
        let err = |h: f64| {
            let s = radau_step(&f, &jac, 0.0, &[1.0, 0.0, 0.0, 0.0], h, &w).unwrap();
            (s.y[0] - h.cos()).abs()
        };
        let (e1, e2) = (err(0.2), err(0.1));
        assert!(e1 / e2 > 40.0, "order: {e1:e} / {e2:e}");
        // Dense output reproduces the nodes.
        let s = radau_step(&f, &jac, 0.0, &[1.0, 0.0, 0.0, 0.0], 0.1, &w).unwrap();
        let d = dense(&[1.0, 0.0, 0.0, 0.0], &s.stages, C[1]);
        assert!((d[0] - s.stages[1][0]).abs() < 1e-15);
    }

    #[test]
    fn stable_at_any_stiffness() {
        let k = 1e12;
        let f = move |_t: f64, y: &[f64; N]| [-k * (y[0] - 1.0), 0.0, 0.0, 0.0];
        let jac = [[-k, 0.0, 0.0, 0.0], [0.0; 4], [0.0; 4], [0.0; 4]];
        let s = radau_step(&f, &jac, 0.0, &[0.0; N], 1.0, &[1e-12; 4]).unwrap();
        // The stability function at z = -k h is about -3 / z: the step lands within 3 / k.
        assert!((s.y[0] - 1.0).abs() <= 3.5 / k, "{}", s.y[0]);
    }

    #[test]
    fn lu_solves_with_pivoting() {
        // A matrix that needs row swaps at several columns.
        let mut a = [[0.0; M]; M];
        for (i, row) in a.iter_mut().enumerate() {
            for (j, x) in row.iter_mut().enumerate() {
                *x =
                    ((i * 7 + j * 3) % 11) as f64 - 5.0 + if i == (j + 5) % M { 20.0 } else { 0.0 };
            }
        }
        let x: [f64; M] = std::array::from_fn(|i| i as f64 - 3.5);
        let b: [f64; M] = std::array::from_fn(|i| (0..M).map(|j| a[i][j] * x[j]).sum());
        let got = Lu::new(a).unwrap().solve(b);
        for i in 0..M {
            assert!((got[i] - x[i]).abs() < 1e-12, "{i}: {} vs {}", got[i], x[i]);
        }
    }
}
