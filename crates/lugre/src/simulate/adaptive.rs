//! Smooth inputs: an adaptive integrator for the scalar linear ODE
//!
//! ```text
//! z' = -r(t) z + q(t)          r >= 0
//! ```
//!
//! which is what eq. 5 is for a given input (`r = sigma0 |u'| / g(u' / gamma)`, `q = u'`), and
//! what the lag of the paper's Example 1 is (`r = 1`, `q = x(t)`).
//!
//! **Method.** Radau IIA with three stages (order 5, stage order 3), the collocation method
//! at the Radau points. It is L-stable (its stability function vanishes at infinity), so it
//! is stable at any stiffness `r h`; it is stiffly accurate (the step's result is the last
//! stage), so where `r h` is large the solution follows the quasi-static state `q / r`
//! instead of lagging behind it. (An exponential step with coefficients frozen at one point
//! of the step, the other stiff-proof choice, lags by half a step there and is only first order
//! in the stiff regime.) The ODE is linear in `z`, so the stage equations
//! `Z_i = z + h sum_j a_ij (q_j - r_j Z_j)` are a 3 x 3 linear system, solved directly by
//! Gaussian elimination with partial pivoting: no Newton iteration, no Jacobian. Pivoting makes
//! the solve indifferent to the scaling of the columns by `r_j`, which can differ by many
//! orders of magnitude next to a reversal (`u' = 0`).
//!
//! **Error control** by step doubling: a step of `h` and two of `h/2` from the same point; their
//! difference bounds the error of the (kept) two-half-step result with a margin of about
//! `2^5 - 1`. The step is accepted when the difference is at most `tol * max(scale, |z|)`,
//! `scale` being the size of the state (`g(0) / sigma0` for eq. 5).
//!
//! Coefficients must be smooth between the stops the caller gives (reversals, where `|u'|` has
//! a kink, are stops).

use super::inputs::Sine;
use super::{check_output_times, Sample, SimulateError, Simulator, Tolerance, Trajectory};
use crate::kernel::radau::{A, C};
use crate::kernel::relax::relax;
use crate::model::VelocityFn;

/// A scalar linear ODE `z' = -r(t) z + q(t)`: `coefficients(t) = (r(t), q(t))`.
pub trait LinearOde {
    fn coefficients(&self, t: f64) -> (f64, f64);
}

impl<C: Fn(f64) -> (f64, f64)> LinearOde for C {
    #[inline]
    fn coefficients(&self, t: f64) -> (f64, f64) {
        self(t)
    }
}

/// Step-size controller: `h_new = h * clamp(SAFETY * err^(-1/5), MIN_FACTOR, MAX_FACTOR)`.
/// The exponent is the local order in the stiff regime plus one (stage order 3 + 2 for the
/// last stage); where the method does better (order 5, local error `h^6`) the controller is
/// merely cautious.
const SAFETY: f64 = 0.9;
const EXPONENT: f64 = 0.2;
const MIN_FACTOR: f64 = 0.2;
const MAX_FACTOR: f64 = 5.0;

/// One Radau IIA step: the coefficients `(r_i, q_i)` at the stage times `t + c_i h` and the
/// stage values `Z_i` (`Z_3` is the step's result: the method is stiffly accurate).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Stages {
    pub r: [f64; 3],
    pub q: [f64; 3],
    pub z: [f64; 3],
}

/// The stage system of a step of `h` with coefficients `r` and `q` at the stages:
/// `(I + h A diag(r)) Z = z 1 + h A q`, returned as the matrix and `h A q`. It is linear in
/// the start `z`, which is what makes the period map of [`crate::sweep`] affine step by step.
#[inline]
pub(crate) fn stage_system(h: f64, r: &[f64; 3], q: &[f64; 3]) -> ([[f64; 3]; 3], [f64; 3]) {
    let mut m = [[0.0; 3]; 3];
    let mut b = [0.0; 3];
    for i in 0..3 {
        for j in 0..3 {
            m[i][j] = h * A[i][j] * r[j] + if i == j { 1.0 } else { 0.0 };
            b[i] += h * A[i][j] * q[j];
        }
    }
    (m, b)
}

/// One Radau IIA step of `h` from `(t, z)`, with its stages.
#[inline]
pub(crate) fn radau_stages<O: LinearOde>(ode: &O, t: f64, z: f64, h: f64) -> Stages {
    let mut r = [0.0; 3];
    let mut q = [0.0; 3];
    for i in 0..3 {
        (r[i], q[i]) = ode.coefficients(t + C[i] * h);
    }
    let (m, haq) = stage_system(h, &r, &q);
    Stages {
        r,
        q,
        z: solve3(m, haq.map(|x| z + x)),
    }
}

/// The Radau quadrature `h sum b_j rate(t_j, Z_j, r_j, q_j)` of a step (`b` the last row of
/// `A`), and the largest `|rate|` at its stages.
#[inline]
fn quadrature<R: Fn(f64, f64, f64, f64) -> f64>(
    rate: &R,
    t: f64,
    h: f64,
    s: &Stages,
) -> (f64, f64) {
    let (mut sum, mut big) = (0.0, 0.0f64);
    for j in 0..3 {
        let x = rate(t + C[j] * h, s.z[j], s.r[j], s.q[j]);
        sum += A[2][j] * x;
        big = big.max(x.abs());
    }
    (h * sum, big)
}

/// One Radau IIA step of `h` from `(t, z)`.
#[inline]
pub(crate) fn radau_step<O: LinearOde>(ode: &O, t: f64, z: f64, h: f64) -> f64 {
    radau_stages(ode, t, z, h).z[2]
}

/// `m x = b` by Gaussian elimination with partial pivoting. A zero pivot gives a non-finite
/// result, which the step control rejects.
#[allow(clippy::needless_range_loop)] // indices as in the textbook algorithm
#[inline]
pub(crate) fn solve3(mut m: [[f64; 3]; 3], mut b: [f64; 3]) -> [f64; 3] {
    for col in 0..3 {
        let mut p = col;
        for row in col + 1..3 {
            if m[row][col].abs() > m[p][col].abs() {
                p = row;
            }
        }
        m.swap(col, p);
        b.swap(col, p);
        for row in col + 1..3 {
            let f = m[row][col] / m[col][col];
            for k in col..3 {
                m[row][k] -= f * m[col][k];
            }
            b[row] -= f * b[col];
        }
    }
    let mut x = [0.0; 3];
    for i in (0..3).rev() {
        let mut s = b[i];
        for k in i + 1..3 {
            s -= m[i][k] * x[k];
        }
        x[i] = s / m[i][i];
    }
    x
}

/// The adaptive integrator; it keeps its step size from one call to the next.
#[derive(Debug, Clone)]
pub struct Integrator {
    tol: f64,
    scale: f64,
    /// The step the controller proposes next (0 before the first step).
    h: f64,
    accepted: u64,
    rejected: u64,
}

impl Integrator {
    /// `scale > 0` is the size below which `z` is compared absolutely.
    pub fn new(tol: Tolerance, scale: f64) -> Self {
        Self {
            tol: tol.value(),
            scale: if scale > 0.0 && scale.is_finite() {
                scale
            } else {
                1.0
            },
            h: 0.0,
            accepted: 0,
            rejected: 0,
        }
    }

    /// Steps accepted and rejected so far (what the tests check the controller by).
    #[cfg(test)]
    pub fn steps(&self) -> (u64, u64) {
        (self.accepted, self.rejected)
    }

    /// `z(t1)` from `z(t0) = z0`; `r` and `q` must be smooth on `(t0, t1)`.
    pub fn advance<O: LinearOde>(
        &mut self,
        ode: &O,
        t0: f64,
        z0: f64,
        t1: f64,
    ) -> Result<f64, SimulateError> {
        self.advance_observed(
            ode,
            t0,
            z0,
            t1,
            (&|_, _, _, _| 0.0, 1.0),
            &mut |_, _, _, _| {},
        )
    }

    /// [`Self::advance`], showing every step kept to `on_step(t, h, z, stages)`: its start
    /// `(t, z)`, its length and its stages, in order, covering `[t0, t1]` without gap (the
    /// two half steps of each accepted step of the step-doubling control).
    ///
    /// The step control also holds the Radau quadrature of `rate(t, z, r, q)` on the stages
    /// (the integral a caller sums from the steps shown) to the tolerance, relative to the
    /// larger of the largest `|rate|` on the step and `rate_scale` (the integrand's typical
    /// size, below which it is compared absolutely): where `z` barely moves (a stiff,
    /// quasi-static stretch) the steps stay short enough for the integrand (`rate = 0`: `z`
    /// alone).
    pub(crate) fn advance_observed<O, R, S>(
        &mut self,
        ode: &O,
        t0: f64,
        z0: f64,
        t1: f64,
        (rate, rate_scale): (&R, f64),
        on_step: &mut S,
    ) -> Result<f64, SimulateError>
    where
        O: LinearOde,
        R: Fn(f64, f64, f64, f64) -> f64,
        S: FnMut(f64, f64, f64, &Stages),
    {
        let (mut t, mut z) = (t0, z0);
        if t1 <= t0 {
            return Ok(z0);
        }
        if self.h <= 0.0 {
            self.h = t1 - t0;
        }
        loop {
            let last = self.h >= t1 - t;
            let t_end = if last { t1 } else { t + self.h };
            let h = t_end - t;
            let t_mid = t + 0.5 * h;
            if !(t_mid > t && t_end > t_mid) {
                if last {
                    // What is left is an ulp or two of t (two stops that differ by rounding):
                    // one step over it errs by O(h^2), far below any tolerance.
                    self.accepted += 1;
                    let s = radau_stages(ode, t, z, h);
                    on_step(t, h, z, &s);
                    return Ok(s.z[2]);
                }
                return Err(SimulateError::StepUnderflow { t, tol: self.tol });
            }
            let full = radau_stages(ode, t, z, h);
            let half = radau_stages(ode, t, z, t_mid - t);
            let second = radau_stages(ode, t_mid, half.z[2], t_end - t_mid);
            let two = second.z[2];
            let err_z =
                (two - full.z[2]).abs() / (self.tol * self.scale.max(z.abs()).max(two.abs()));
            let (q_full, big) = quadrature(rate, t, h, &full);
            let (q_1, big_1) = quadrature(rate, t, t_mid - t, &half);
            let (q_2, big_2) = quadrature(rate, t_mid, t_end - t_mid, &second);
            let q_diff = (q_1 + q_2 - q_full).abs();
            let err_q = if q_diff == 0.0 {
                0.0
            } else {
                q_diff / (self.tol * h * big.max(big_1).max(big_2).max(rate_scale))
            };
            let err = err_z.max(err_q);
            if err <= 1.0 {
                self.accepted += 1;
                on_step(t, t_mid - t, z, &half);
                on_step(t_mid, t_end - t_mid, half.z[2], &second);
                t = t_end;
                z = two;
                let grow = if err == 0.0 {
                    MAX_FACTOR
                } else {
                    (SAFETY * err.powf(-EXPONENT)).clamp(MIN_FACTOR, MAX_FACTOR)
                };
                // A step cut short by the stop says nothing against the longer one proposed.
                self.h = if last { self.h.max(h * grow) } else { h * grow };
                if last {
                    return Ok(z);
                }
            } else {
                self.rejected += 1;
                let shrink = if err.is_finite() {
                    (SAFETY * err.powf(-EXPONENT)).clamp(MIN_FACTOR, SAFETY)
                } else {
                    MIN_FACTOR
                };
                self.h = h * shrink;
            }
        }
    }
}

/// The solution of `z' = -a |u'| z + u'` along a sine, stretch by stretch between reversals
/// (eq. 6's ODE, or the Dahl model's): on a monotone stretch from `(u_k, z_k)`,
/// `z = relax(z_k, a |u - u_k|, u - u_k)`, exact. Reversals are found one at a time, so a long
/// run costs no memory.
#[derive(Debug, Clone)]
pub(crate) struct RateIndependentSine<'a> {
    input: &'a Sine,
    a: f64,
    /// The next reversal after the current stretch's start: time and extreme value.
    next: (f64, f64),
    u_k: f64,
    z_k: f64,
}

impl<'a> RateIndependentSine<'a> {
    /// From `z(0) = z0`.
    pub fn new(input: &'a Sine, a: f64, z0: f64) -> Self {
        Self {
            input,
            a,
            next: input.next_reversal(0.0),
            u_k: input.u(0.0),
            z_k: z0,
        }
    }

    /// The time of the next reversal after the current stretch's start.
    pub fn next_reversal_time(&self) -> f64 {
        self.next.0
    }

    /// Moves the stretch start past every reversal at or before `t` (non-decreasing `t`).
    pub fn pass_reversals_until(&mut self, t: f64) {
        while self.next.0 <= t {
            let (t_r, u_r) = self.next;
            self.z_k = relax(self.z_k, self.a * (u_r - self.u_k).abs(), u_r - self.u_k);
            self.u_k = u_r;
            self.next = self.input.next_reversal(t_r);
        }
    }

    /// `z` at `t` in the current stretch.
    #[inline]
    pub fn z_in_stretch(&self, t: f64) -> f64 {
        let du = self.input.u(t) - self.u_k;
        relax(self.z_k, self.a * du.abs(), du)
    }
}

impl<'m, G: VelocityFn, F: VelocityFn> Simulator<'m, G, F> {
    /// The response to a sine over `periods` periods (`t` in `[0, periods T]`) at the given
    /// times (strictly increasing), appended to `out`.
    ///
    /// For finite `gamma` by the adaptive integrator to the relative tolerance `tol` (on `z`,
    /// against the scale `g(0) / sigma0`), stopping at every reversal and output time; for
    /// `gamma = inf`, exactly (eq. 6 in closed form, stretch by stretch; `tol` is unused).
    pub fn sine(
        &self,
        input: &Sine,
        periods: u32,
        times: &[f64],
        tol: Tolerance,
        out: &mut Trajectory,
    ) -> Result<(), SimulateError> {
        self.observed_sine(input, periods, times, tol, out, &mut |_| {})
    }

    pub(super) fn observed_sine(
        &self,
        input: &Sine,
        periods: u32,
        times: &[f64],
        tol: Tolerance,
        out: &mut Trajectory,
        progress: &mut dyn FnMut(f64),
    ) -> Result<(), SimulateError> {
        if periods < 1 {
            return Err(SimulateError::BadPeriods { value: periods });
        }
        let end = f64::from(periods) * input.period();
        check_output_times(times, 0.0, end)?;
        let first = out.len();
        out.reserve(times.len());
        let Some(&last) = times.last() else {
            return Ok(());
        };
        let sigma0 = self.model.sigma0();
        let a = sigma0 / self.model.g0();
        let mut relaxation = RateIndependentSine::new(input, a, self.x0());
        let sample =
            |t: f64, z: f64| -> Sample { self.sample_at_slope(t, input.u(t), input.du(t), z) };
        let report_every = (times.len() / 256).max(1);
        if self.gamma().is_infinite() {
            for (j, &t) in times.iter().enumerate() {
                relaxation.pass_reversals_until(t);
                out.push(sample(t, relaxation.z_in_stretch(t)));
                if j % report_every == 0 {
                    progress(t / last);
                }
            }
            return out.check_finite(first);
        }
        let ode = |t: f64| {
            let v = input.du(t);
            (self.rate(v), v)
        };
        let mut integrator = Integrator::new(tol, self.model.g0() / sigma0);
        let (mut t, mut z) = (0.0, self.x0());
        let mut next_reversal = input.next_reversal(0.0).0;
        let mut j = 0;
        while j < times.len() {
            // The next stop: a reversal (where |u'| has a kink) or an output time.
            let stop = times[j].min(next_reversal);
            z = integrator.advance(&ode, t, z, stop)?;
            t = stop;
            if next_reversal <= stop {
                next_reversal = input.next_reversal(stop).0;
            }
            if times[j] == stop {
                out.push(sample(t, z));
                if j % report_every == 0 {
                    progress(t / last);
                }
                j += 1;
            }
        }
        out.check_finite(first)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_ode_with_known_solution() {
        // z' = -(1 + t) z + 1 + t  (r = q): z = 1 + (z0 - 1) exp(-(t + t^2/2)).
        let ode = |t: f64| (1.0 + t, 1.0 + t);
        let mut it = Integrator::new(Tolerance::new(1e-12).unwrap(), 1.0);
        let z = it.advance(&ode, 0.0, 3.0, 2.0).unwrap();
        let want = 1.0 + 2.0 * (-4.0f64).exp();
        assert!((z - want).abs() < 1e-11, "{z} vs {want}");
    }

    #[test]
    fn stable_at_huge_stiffness() {
        // z' = -1e12 (z - cos t) - sin t: z = cos t once the initial layer is gone.
        let ode = |t: f64| (1e12, 1e12 * t.cos() - t.sin());
        let mut it = Integrator::new(Tolerance::new(1e-10).unwrap(), 1.0);
        let z = it.advance(&ode, 0.0, 5.0, 3.0).unwrap();
        assert!((z - 3f64.cos()).abs() < 1e-10, "{z}");
        let (accepted, _) = it.steps();
        assert!(accepted < 2000, "{accepted} steps");
    }
}
