//! The paper's Example 1 (eq. 18, Fig. 4): the Dahl model with `rho = 1` followed by a
//! first-order lag, driven by `u_gamma(t) = sin(2 pi t / gamma)` in physical time:
//!
//! ```text
//! x' = u' - |u'| x          y' = -y + x          x(0) = y(0) = 0
//! ```
//!
//! Its output-versus-input graph tends to the hysteresis loop as `gamma -> inf` (the lag
//! becomes instantaneous and `y -> x`, the Dahl loop with `a = 1`).
//!
//! `x` is exact: between reversals it is the kernel's `relax` in the variable
//! `u` (the Dahl model is rate independent). `y` is the linear ODE `y' = -y + x(t)`, integrated
//! by the adaptive method of [`Simulator::sine`](super::Simulator::sine) with a stop at every
//! reversal, where `x` has a kink in its second derivative.
//!
//! The steady state is the periodic solution, from the fixed point of the period map, which is
//! affine: `x(T) = exp(-4) x(0) + X` (the input travels 4 per period) and
//! `y(T) = exp(-T) y(0) + Y(x(0))`. The transient is the response from rest minus the steady
//! state; it decays like `exp(-t)` (and `x`'s like `exp(-rho_u(t))`).

use super::adaptive::{Integrator, RateIndependentSine};
use super::inputs::Sine;
use super::{uniform_times, SimulateError, Tolerance};

/// Example 1 sampled on a uniform grid: the response from rest and the periodic steady state at
/// the same times.
#[derive(Debug, Clone, PartialEq)]
pub struct Example1 {
    pub gamma: f64,
    /// Physical time, `samples_per_period` steps per period `gamma`, both ends included.
    pub t: Vec<f64>,
    /// `u_gamma(t) = sin(2 pi t / gamma)`.
    pub u: Vec<f64>,
    /// The response from rest (`x(0) = y(0) = 0`).
    pub x: Vec<f64>,
    pub y: Vec<f64>,
    /// The periodic steady state at the same times.
    pub x_steady: Vec<f64>,
    pub y_steady: Vec<f64>,
}

impl Example1 {
    /// The transient part of `y`: the response minus the steady state.
    pub fn y_transient(&self) -> Vec<f64> {
        self.y
            .iter()
            .zip(&self.y_steady)
            .map(|(a, b)| a - b)
            .collect()
    }

    /// The transient part of `x`.
    pub fn x_transient(&self) -> Vec<f64> {
        self.x
            .iter()
            .zip(&self.x_steady)
            .map(|(a, b)| a - b)
            .collect()
    }
}

/// Example 1 for one `gamma` (the paper: 20, 200, 2000) over `periods` periods.
pub fn paper_example_1(
    gamma: f64,
    periods: u32,
    samples_per_period: usize,
    tol: Tolerance,
) -> Result<Example1, SimulateError> {
    if !(gamma > 0.0 && gamma.is_finite()) {
        return Err(SimulateError::BadGamma { value: gamma });
    }
    if periods < 1 {
        return Err(SimulateError::BadPeriods { value: periods });
    }
    let n = samples_per_period.max(1);
    let input = Sine::new(1.0, gamma, 0.0, 0.0)?;
    let times = uniform_times(0.0, gamma, periods, n);
    let (x, y) = run(&input, 0.0, 0.0, &times, tol)?;

    // The period map's fixed point.
    let one_period = [0.0, gamma];
    let (x_free, _) = run(&input, 0.0, 0.0, &one_period, tol)?;
    let x_star = x_free[1] / -(-4.0f64).exp_m1();
    let (_, y_free) = run(&input, x_star, 0.0, &one_period, tol)?;
    let y_star = y_free[1] / -(-gamma).exp_m1();
    let (xs, ys) = run(&input, x_star, y_star, &times[..=n], tol)?;
    // `uniform_times` gives every period the same offsets: period p's sample i is the first
    // period's.
    let x_steady = (0..times.len()).map(|j| xs[j % n]).collect();
    let y_steady = (0..times.len()).map(|j| ys[j % n]).collect();
    let u = times.iter().map(|&t| input.u(t)).collect();
    Ok(Example1 {
        gamma,
        t: times,
        u,
        x,
        y,
        x_steady,
        y_steady,
    })
}

/// `(x, y)` at `times` (from 0, strictly increasing) from `(x0, y0)`.
fn run(
    input: &Sine,
    x0: f64,
    y0: f64,
    times: &[f64],
    tol: Tolerance,
) -> Result<(Vec<f64>, Vec<f64>), SimulateError> {
    let mut xs = Vec::with_capacity(times.len());
    let mut ys = Vec::with_capacity(times.len());
    if times.is_empty() {
        return Ok((xs, ys));
    }
    let mut x = RateIndependentSine::new(input, 1.0, x0);
    let mut integrator = Integrator::new(tol, 1.0);
    let (mut t, mut y) = (0.0, y0);
    let mut j = 0;
    while j < times.len() {
        // The next stop: a reversal (where x'' jumps) or an output time.
        let stop = times[j].min(x.next_reversal_time());
        {
            let lag = |s: f64| (1.0, x.z_in_stretch(s));
            y = integrator.advance(&lag, t, y, stop)?;
        }
        t = stop;
        x.pass_reversals_until(t);
        if times[j] == stop {
            xs.push(x.z_in_stretch(t));
            ys.push(y);
            j += 1;
        }
    }
    Ok((xs, ys))
}
