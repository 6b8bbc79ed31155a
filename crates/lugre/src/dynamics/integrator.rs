//! A dedicated integrator for the small stiff system of [`super::System`]: Radau IIA with three
//! stages (order 5, L-stable, stiffly accurate) in the form of Hairer & Wanner (Solving ODEs II,
//! IV.8): simplified Newton on the stage equations transformed by the eigenvectors of `A^-1`
//! (eq. (8.16)-(8.17): one real `n x n` system and one complex one, solved here as a real
//! `2n x 2n`), the embedded error estimate of eq. (8.19)-(8.20) filtered through
//! `(I - h gamma0 J)^-1`, and the collocation polynomial of each step as dense output (for the
//! output times and for locating the sign changes of `v`). The step-size control and the
//! reuse of Jacobians and factorizations are the solver's (`solver.rs`).

use crate::kernel::radau::{ALPH, BETA, C, DD, T, TI, U1};
use num_complex::Complex64;
use std::ops::{Mul, SubAssign};

/// The dimension of the LuGre system's state `(x, v, z, q)`; the integrator takes any `D`.
pub(super) const N: usize = 4;

/// Newton iterations before a step is given up (radau5's `NIT`).
pub(super) const NIT: usize = 7;

/// A solved step: the end state and the stage values (the collocation polynomial's nodes at
/// `t + c_i h`), plus the work done.
#[derive(Debug, Clone, Copy)]
pub(super) struct Step<const D: usize> {
    pub y: [f64; D],
    pub stages: [[f64; D]; 3],
    /// The stage increments `Z_i = stages_i - y0` (the error estimate's input).
    z: [[f64; D]; 3],
    pub evaluations: usize,
    pub iterations: usize,
    /// Newton's observed contraction rate (0 when one iteration sufficed).
    pub theta: f64,
}

/// The factored iteration matrices of steps of size `h` with the Jacobian `J`:
/// `E1 = (U1 / h) I - J` (real) and `E2 = ((ALPH + i BETA) / h) I - J` (complex). One
/// factorization serves every step of that size and Jacobian.
pub(super) struct Factors<const D: usize> {
    h: f64,
    e1: Lu<f64, D>,
    e2: Lu<Complex64, D>,
}

impl<const D: usize> Factors<D> {
    /// `None` if either matrix is singular.
    pub fn new(jac: &[[f64; D]; D], h: f64) -> Option<Self> {
        let fac1 = U1 / h;
        let fac2 = Complex64::new(ALPH / h, BETA / h);
        let e1 = std::array::from_fn(|r| {
            std::array::from_fn(|c| if r == c { fac1 } else { 0.0 } - jac[r][c])
        });
        let e2 = std::array::from_fn(|r| {
            std::array::from_fn(|c| {
                let diagonal = if r == c {
                    fac2
                } else {
                    Complex64::new(0.0, 0.0)
                };
                diagonal - jac[r][c]
            })
        });
        Some(Self {
            h,
            e1: Lu::new(e1)?,
            e2: Lu::new(e2)?,
        })
    }

    /// The step size these factors are for.
    pub fn h(&self) -> f64 {
        self.h
    }
}

/// Newton's state carried from step to step: the convergence factor of the last iteration
/// (radau5's `FACCON`) and the tolerance on the scaled increments.
#[derive(Debug, Clone, Copy)]
pub(super) struct Newton {
    pub faccon: f64,
    pub tol: f64,
    /// Iterate on while the increments do not grow (up to [`NIT`] iterations) instead of giving
    /// up once the contraction predicts no convergence in time: for a right-hand side with a
    /// kink (`|v|` at `v = 0`), where the contraction is erratic.
    pub lenient: bool,
}

/// The stages of a step of size `factors.h()` from `(t, y)` for `y' = f(t, y)`, by simplified
/// Newton from the stage increments `guess`, to `newton.tol` in the norm scaled by `scal`.
/// `Err(q)`: Newton diverges or would not converge within [`NIT`] iterations; retry with the
/// step times `q` (radau5's estimate of the size that would converge).
pub(super) fn solve_stages<const D: usize>(
    f: &impl Fn(f64, &[f64; D]) -> [f64; D],
    factors: &Factors<D>,
    t: f64,
    y: &[f64; D],
    scal: &[f64; D],
    guess: [[f64; D]; 3],
    newton: &mut Newton,
) -> Result<Step<D>, f64> {
    let h = factors.h;
    let (fac1, alphn, betan) = (U1 / h, ALPH / h, BETA / h);
    let mut z = guess;
    let mut w = transform(&TI, &z);
    newton.faccon = newton.faccon.max(f64::EPSILON).powf(0.8);
    let (mut theta, mut dyno_old, mut thq_old) = (0.0, 0.0, 0.0);
    for iteration in 1..=NIT {
        let fz: [[f64; D]; 3] = std::array::from_fn(|i| {
            let yi = std::array::from_fn(|r| y[r] + z[i][r]);
            f(t + C[i] * h, &yi)
        });
        let a = transform(&TI, &fz);
        let rhs1 = std::array::from_fn(|r| a[0][r] - fac1 * w[0][r]);
        let rhs23 = std::array::from_fn(|r| {
            Complex64::new(
                a[1][r] - alphn * w[1][r] + betan * w[2][r],
                a[2][r] - alphn * w[2][r] - betan * w[1][r],
            )
        });
        let d1 = factors.e1.solve(rhs1);
        let d23 = factors.e2.solve(rhs23);
        let mut dyno = 0.0;
        for r in 0..D {
            dyno += (d1[r] / scal[r]).powi(2)
                + (d23[r].re / scal[r]).powi(2)
                + (d23[r].im / scal[r]).powi(2);
        }
        let dyno = (dyno / (3 * D) as f64).sqrt();
        if !dyno.is_finite() {
            return Err(0.5);
        }
        if iteration > 1 {
            // The contraction rate and, from it, whether the iteration will converge in time.
            let thq = dyno / dyno_old;
            theta = if iteration == 2 {
                thq
            } else {
                f64::sqrt(thq * thq_old)
            };
            thq_old = thq;
            if newton.lenient {
                if thq >= 2.0 {
                    return Err(0.5);
                }
                newton.faccon = if theta < 0.99 {
                    theta / (1.0 - theta)
                } else {
                    1.0
                };
            } else if theta >= 0.99 {
                return Err(0.5);
            } else {
                newton.faccon = theta / (1.0 - theta);
            }
            let left = (NIT - 1).saturating_sub(iteration) as i32;
            let predicted = newton.faccon * dyno * theta.powi(left) / newton.tol;
            if predicted >= 1.0 && !newton.lenient {
                let q = predicted.clamp(1e-4, 20.0);
                return Err(0.8 * q.powf(-1.0 / (4.0 + f64::from(left))));
            }
        }
        dyno_old = dyno.max(f64::EPSILON);
        for r in 0..D {
            w[0][r] += d1[r];
            w[1][r] += d23[r].re;
            w[2][r] += d23[r].im;
        }
        z = transform(&T, &w);
        if newton.faccon * dyno <= newton.tol {
            let stages = std::array::from_fn(|i| std::array::from_fn(|r| y[r] + z[i][r]));
            return Ok(Step {
                y: stages[2],
                stages,
                z,
                evaluations: 3 * iteration,
                iterations: iteration,
                theta,
            });
        }
    }
    Err(0.5)
}

/// `out_i = sum_j m[i][j] v_j` over the three stages, component by component.
fn transform<const D: usize>(m: &[[f64; 3]; 3], v: &[[f64; D]; 3]) -> [[f64; D]; 3] {
    std::array::from_fn(|i| std::array::from_fn(|r| (0..3).map(|j| m[i][j] * v[j][r]).sum()))
}

/// The scaled error of `step` from `y` with `f0 = f(t, y)` (Hairer & Wanner IV.8,
/// eq. (8.19)-(8.20)): `err = (I - h gamma0 J)^-1 (gamma0 h f0 + sum e_i Z_i)`, whose
/// filter keeps the estimate bounded for stiff components. With `refine` (the first step and
/// after a rejection) an estimate above 1 is filtered once more through `f_start`, the rate at
/// the step's start time, at `y + err`. Returns the root mean square of `err / scal` (at least
/// 1e-10) and the evaluations of the rate.
pub(super) fn error_estimate<const D: usize>(
    f_start: impl Fn(&[f64; D]) -> [f64; D],
    factors: &Factors<D>,
    y: &[f64; D],
    f0: &[f64; D],
    step: &Step<D>,
    scal: &[f64; D],
    refine: bool,
) -> (f64, usize) {
    let h = factors.h;
    let f2: [f64; D] =
        std::array::from_fn(|r| (0..3).map(|i| DD[i] * step.z[i][r]).sum::<f64>() / h);
    let norm = |e: &[f64; D]| {
        let s: f64 = (0..D).map(|r| (e[r] / scal[r]).powi(2)).sum();
        (s / D as f64).sqrt().max(1e-10)
    };
    let e = factors.e1.solve(std::array::from_fn(|r| f0[r] + f2[r]));
    let err = norm(&e);
    if !(err >= 1.0 && refine) {
        return (err, 0);
    }
    let f1 = f_start(&std::array::from_fn(|r| y[r] + e[r]));
    let e = factors.e1.solve(std::array::from_fn(|r| f1[r] + f2[r]));
    (norm(&e), 1)
}

/// The collocation polynomial of a step `(y0, stages)` at `theta` of the step (`0` its start,
/// `1` its end): Lagrange through the nodes `0, c1, c2, 1`.
pub(super) fn dense<const D: usize>(y0: &[f64; D], stages: &[[f64; D]; 3], theta: f64) -> [f64; D] {
    let values = [y0, &stages[0], &stages[1], &stages[2]];
    let mut out = [0.0; D];
    for (k, value) in values.iter().enumerate() {
        let mut l = 1.0;
        for (m, &node) in NODES.iter().enumerate() {
            if m != k {
                l *= (theta - node) / (NODES[k] - node);
            }
        }
        for r in 0..D {
            out[r] += l * value[r];
        }
    }
    out
}

/// Newton's starting stage increments for a step that starts at `from` (in `theta` of the
/// step `(y0, stages)`) and is `ratio` times its size: the collocation polynomial extrapolated
/// (radau5's starting values; `from = 1` for the next step, `0` for a step of its own to a
/// point inside this one).
pub(super) fn guess<const D: usize>(
    y0: &[f64; D],
    stages: &[[f64; D]; 3],
    from: f64,
    ratio: f64,
) -> [[f64; D]; 3] {
    let base = dense(y0, stages, from);
    std::array::from_fn(|i| {
        let p = dense(y0, stages, from + C[i] * ratio);
        std::array::from_fn(|r| p[r] - base[r])
    })
}

/// `integral f(t, y(t)) dt` over a step of size `h` from `t0`, by the Radau quadrature at its
/// stages (the weights are the tableau's last row): as accurate as the step.
pub(super) fn quadrature<const D: usize>(
    h: f64,
    t0: f64,
    stages: &[[f64; D]; 3],
    f: impl Fn(f64, &[f64; D]) -> [f64; 2],
) -> [f64; 2] {
    use crate::kernel::radau::A;
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

/// The numbers [`Lu`] factors over: real and complex.
pub(super) trait Scalar: Copy + SubAssign + Mul<Output = Self> {
    /// The pivot's size (any norm does for partial pivoting; the 1-norm is cheapest).
    fn size(self) -> f64;
    fn recip(self) -> Self;
}

impl Scalar for f64 {
    fn size(self) -> f64 {
        self.abs()
    }
    fn recip(self) -> Self {
        1.0 / self
    }
}

impl Scalar for Complex64 {
    fn size(self) -> f64 {
        self.l1_norm()
    }
    fn recip(self) -> Self {
        self.inv()
    }
}

/// LU factors with partial pivoting of an `D x D` matrix.
pub(super) struct Lu<S, const D: usize> {
    a: [[S; D]; D],
    pivot: [usize; D],
    /// The reciprocals of the pivots: the solves multiply (a complex division costs several
    /// multiplications and two divisions).
    inverse_pivots: [S; D],
}

impl<S: Scalar, const D: usize> Lu<S, D> {
    /// `None` if singular (or not finite).
    fn new(mut a: [[S; D]; D]) -> Option<Self> {
        let mut pivot = [0; D];
        for k in 0..D {
            let mut p = k;
            for i in k + 1..D {
                if a[i][k].size() > a[p][k].size() {
                    p = i;
                }
            }
            let size = a[p][k].size();
            if !(size > 0.0 && size.is_finite()) {
                return None;
            }
            a.swap(k, p);
            pivot[k] = p;
            let pivot_row = a[k];
            let inverse = pivot_row[k].recip();
            for row in a.iter_mut().skip(k + 1) {
                let factor = row[k] * inverse;
                row[k] = factor;
                for c in k + 1..D {
                    row[c] -= factor * pivot_row[c];
                }
            }
        }
        let inverse_pivots = std::array::from_fn(|k| a[k][k].recip());
        Some(Self {
            a,
            pivot,
            inverse_pivots,
        })
    }

    fn solve(&self, mut b: [S; D]) -> [S; D] {
        // The factorization swapped whole rows (multipliers included): all the swaps first,
        // then the unit lower triangle.
        for k in 0..D {
            b.swap(k, self.pivot[k]);
        }
        for k in 0..D {
            for i in k + 1..D {
                let m = self.a[i][k] * b[k];
                b[i] -= m;
            }
        }
        for k in (0..D).rev() {
            for j in k + 1..D {
                let m = self.a[k][j] * b[j];
                b[k] -= m;
            }
            b[k] = b[k] * self.inverse_pivots[k];
        }
        b
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn step(
        f: &impl Fn(f64, &[f64; N]) -> [f64; N],
        jac: &[[f64; N]; N],
        y: &[f64; N],
        h: f64,
        scal: f64,
    ) -> Step<N> {
        let factors = Factors::new(jac, h).unwrap();
        let mut newton = Newton {
            faccon: 1.0,
            tol: 1e-3,
            lenient: false,
        };
        solve_stages(f, &factors, 0.0, y, &[scal; N], [[0.0; N]; 3], &mut newton).unwrap()
    }

    const OSCILLATOR: [[f64; N]; N] = [
        [0.0, 1.0, 0.0, 0.0],
        [-1.0, 0.0, 0.0, 0.0],
        [0.0; 4],
        [0.0; 4],
    ];

    fn oscillator(_t: f64, y: &[f64; N]) -> [f64; N] {
        [y[1], -y[0], 0.0, 0.0]
    }

    #[test]
    fn exact_for_a_linear_oscillator_to_order_five() {
        // y'' = -y as a system, one step of h: error O(h^6) per step.
        let err = |h: f64| {
            let s = step(&oscillator, &OSCILLATOR, &[1.0, 0.0, 0.0, 0.0], h, 1e-12);
            (s.y[0] - h.cos()).abs()
        };
        let (e1, e2) = (err(0.2), err(0.1));
        assert!(e1 / e2 > 40.0, "order: {e1:e} / {e2:e}");
        // Dense output reproduces the nodes.
        let s = step(&oscillator, &OSCILLATOR, &[1.0, 0.0, 0.0, 0.0], 0.1, 1e-12);
        let d = dense(&[1.0, 0.0, 0.0, 0.0], &s.stages, C[1]);
        assert!((d[0] - s.stages[1][0]).abs() < 1e-15);
    }

    #[test]
    fn the_error_estimate_is_of_order_four() {
        // The embedded estimate of the oscillator's step behaves as h^4: halving h divides
        // it by about 16.
        let y0 = [1.0, 0.0, 0.0, 0.0];
        let est = |h: f64| {
            let s = step(&oscillator, &OSCILLATOR, &y0, h, 1e-14);
            let factors = Factors::new(&OSCILLATOR, h).unwrap();
            let f0 = oscillator(0.0, &y0);
            let f_start = |y: &[f64; N]| oscillator(0.0, y);
            error_estimate(f_start, &factors, &y0, &f0, &s, &[1.0; N], false).0
        };
        let ratio = est(0.1) / est(0.05);
        assert!((12.0..20.0).contains(&ratio), "{ratio}");
    }

    #[test]
    fn stable_at_any_stiffness() {
        let k = 1e12;
        let f = move |_t: f64, y: &[f64; N]| [-k * (y[0] - 1.0), 0.0, 0.0, 0.0];
        let jac = [[-k, 0.0, 0.0, 0.0], [0.0; 4], [0.0; 4], [0.0; 4]];
        let s = step(&f, &jac, &[0.0; N], 1.0, 1e-12);
        // The stability function at z = -k h is about -3 / z: the step lands within 3 / k.
        assert!((s.y[0] - 1.0).abs() <= 3.5 / k, "{}", s.y[0]);
    }

    #[test]
    fn lu_solves_with_pivoting() {
        // Matrices that need row swaps at several columns, real and complex.
        let a: [[f64; N]; N] = std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                ((i * 7 + j * 3) % 5) as f64 - 2.0 + if i == (j + 2) % N { 9.0 } else { 0.0 }
            })
        });
        let x: [f64; N] = std::array::from_fn(|i| i as f64 - 1.5);
        let b: [f64; N] = std::array::from_fn(|i| (0..N).map(|j| a[i][j] * x[j]).sum());
        let got = Lu::new(a).unwrap().solve(b);
        for i in 0..N {
            assert!((got[i] - x[i]).abs() < 1e-13, "{i}: {} vs {}", got[i], x[i]);
        }
        let c: [[Complex64; N]; N] = std::array::from_fn(|i| {
            std::array::from_fn(|j| Complex64::new(a[i][j], (i + 2 * j) as f64 - 3.0))
        });
        let xc: [Complex64; N] = std::array::from_fn(|i| Complex64::new(x[i], 1.0 - x[i]));
        let bc: [Complex64; N] = std::array::from_fn(|i| (0..N).map(|j| c[i][j] * xc[j]).sum());
        let got = Lu::new(c).unwrap().solve(bc);
        for i in 0..N {
            assert!(
                (got[i] - xc[i]).norm() < 1e-13,
                "{i}: {} vs {}",
                got[i],
                xc[i]
            );
        }
        // Singular: refused.
        let mut singular = a;
        singular[3] = singular[1];
        assert!(Lu::new(singular).is_none());
    }
}
