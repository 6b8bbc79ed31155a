//! Samples of a smooth motion: the cubic reading.
//!
//! A record sampled from a smooth motion (a sine on a shaker, a velocity-controlled drive) is
//! not piecewise linear between its samples. Read as such ([`PiecewiseLinear`], the *linear
//! reading*) the motion's velocity is wrong by `O(h)` inside each interval of length `h`, and
//! the output at a sample, which uses the next interval's velocity, is off by `O(h)` (second
//! order between samples, where the interval's mean velocity is met). The *cubic reading* takes
//! the motion as the C1 piecewise-cubic Hermite interpolant of the samples:
//!
//! * with the slopes of the data where they are known (a velocity record `(t, v)`: `x` is the
//!   trapezoid integral of `v`, exact for `v` linear between samples, and the slopes are `v`);
//! * otherwise with shape-preserving slopes: 0 where the data reverse, so the interpolant never
//!   overshoots a reversal, and elsewhere the three-point (Bessel) slope, second-order accurate,
//!   limited to three times the smaller neighbouring secant so that each interval stays
//!   monotone (Hyman 1983; the Fritsch-Carlson harmonic mean of SciPy's `PchipInterpolator` is
//!   only first-order accurate near extrema, which the velocity and so the output show).
//!
//! The exact simulator then runs on the interpolant subdivided so that its piecewise-linear
//! reading is within `tol` times the record's range of it: on an interval the cubic's second
//! derivative is linear, so `n = ceil(h sqrt(max|x''| / (8 tol range)))` equal parts bound the
//! chord error by `max|x''| (h/n)^2 / 8`. At the samples the output uses the interpolant's own
//! velocity. Orders of accuracy of the output at the samples (`tests/smooth.rs`, a sine against
//! an independent adaptive solution): the linear reading is first order in `h`; the cubic
//! reading is second order, except at a sample where the data reverse and its two neighbours,
//! where the shape rule (slope 0 at the reversal sample, limited slopes beside it) leaves a
//! velocity error of up to the distance to the true reversal times the acceleration: first
//! order there, still below the linear reading's error.

use super::inputs::PiecewiseLinear;
use super::SimulateError;
use crate::input::{check_finite, check_increasing};

/// The refined knots are limited to this many (the memory of a request).
const MAX_KNOTS: usize = 100_000_000;

/// Samples of a smooth motion with their slopes, and the subdivided piecewise-linear motion the
/// exact simulator runs on.
#[derive(Debug, Clone, PartialEq)]
pub struct SmoothSamples {
    t: Vec<f64>,
    x: Vec<f64>,
    v: Vec<f64>,
    refined: PiecewiseLinear,
    /// The refined knot of each sample.
    index: Vec<usize>,
}

impl SmoothSamples {
    /// Displacement samples `(t, x)` with shape-preserving (PCHIP) slopes; `tol` as in the
    /// module docs (relative to the range of `x`, in `[1e-14, 1e-2]`).
    pub fn pchip(t: Vec<f64>, x: Vec<f64>, tol: f64) -> Result<Self, SimulateError> {
        check(&t, &x, "x")?;
        let v = pchip_slopes(&t, &x);
        Self::hermite(t, x, v, tol)
    }

    /// Velocity samples `(t, v)`: `x` from `x0` by the trapezoid rule, the slopes `v`.
    pub fn from_velocity(
        t: Vec<f64>,
        v: Vec<f64>,
        x0: f64,
        tol: f64,
    ) -> Result<Self, SimulateError> {
        check(&t, &v, "v")?;
        let mut x = Vec::with_capacity(t.len());
        x.push(x0);
        for i in 1..t.len() {
            x.push(x[i - 1] + 0.5 * (v[i - 1] + v[i]) * (t[i] - t[i - 1]));
        }
        Self::hermite(t, x, v, tol)
    }

    fn hermite(t: Vec<f64>, x: Vec<f64>, v: Vec<f64>, tol: f64) -> Result<Self, SimulateError> {
        if !(1e-14..=1e-2).contains(&tol) {
            return Err(SimulateError::BadTolerance { value: tol });
        }
        check_finite("x", &x).map_err(data)?;
        let (lo, hi) = x
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &u| {
                (a.min(u), b.max(u))
            });
        let chord = (tol * (hi - lo)).max(f64::MIN_POSITIVE);
        let n = t.len();
        let parts: Vec<usize> = (0..n - 1)
            .map(|k| {
                let h = t[k + 1] - t[k];
                let [c0, c1] = second_derivatives(h, x[k], x[k + 1], v[k], v[k + 1]);
                let m = c0.abs().max(c1.abs());
                let parts = (h * (m / (8.0 * chord)).sqrt()).ceil();
                if parts.is_finite() && parts >= 1.0 {
                    parts.min(MAX_KNOTS as f64) as usize
                } else {
                    1
                }
            })
            .collect();
        let total = parts.iter().try_fold(1usize, |acc, &p| acc.checked_add(p));
        let Some(total) = total.filter(|&m| m <= MAX_KNOTS) else {
            return Err(SimulateError::TooManyKnots { limit: MAX_KNOTS });
        };
        let (mut rt, mut rx) = (Vec::with_capacity(total), Vec::with_capacity(total));
        let mut index = Vec::with_capacity(n);
        for k in 0..n - 1 {
            index.push(rt.len());
            let h = t[k + 1] - t[k];
            for j in 0..parts[k] {
                let s = j as f64 / parts[k] as f64;
                rt.push(t[k] + s * h);
                rx.push(hermite_at(s, h, x[k], x[k + 1], v[k], v[k + 1]));
            }
        }
        index.push(rt.len());
        rt.push(t[n - 1]);
        rx.push(x[n - 1]);
        let refined = PiecewiseLinear::new(rt, rx)?;
        Ok(Self {
            t,
            x,
            v,
            refined,
            index,
        })
    }

    /// The piecewise-linear motion the exact simulator runs on.
    pub fn refined(&self) -> &PiecewiseLinear {
        &self.refined
    }
    /// The samples' times, displacements and velocities (the interpolant's slopes).
    pub fn samples(&self) -> (&[f64], &[f64], &[f64]) {
        (&self.t, &self.x, &self.v)
    }
    /// The refined knot of each sample.
    pub fn sample_knots(&self) -> &[usize] {
        &self.index
    }
}

fn check(t: &[f64], values: &[f64], what: &'static str) -> Result<(), SimulateError> {
    if t.len() != values.len() || t.len() < 2 {
        return Err(SimulateError::TooFewSamples {
            count: t.len().min(values.len()),
        });
    }
    check_finite("t", t).map_err(data)?;
    check_finite(what, values).map_err(data)?;
    check_increasing(t).map_err(data)?;
    Ok(())
}

fn data(e: crate::error::DataError) -> SimulateError {
    SimulateError::Input(e.into())
}

/// Shape-preserving slopes: 0 where the data reverse, else the three-point (Bessel) slope
/// limited to three times the smaller neighbouring secant (Hyman's monotonicity filter); at the
/// ends SciPy's `PchipInterpolator` three-point condition.
pub(crate) fn pchip_slopes(t: &[f64], x: &[f64]) -> Vec<f64> {
    let n = t.len();
    let h: Vec<f64> = (0..n - 1).map(|k| t[k + 1] - t[k]).collect();
    let d: Vec<f64> = (0..n - 1).map(|k| (x[k + 1] - x[k]) / h[k]).collect();
    if n == 2 {
        return vec![d[0], d[0]];
    }
    let mut m = vec![0.0; n];
    for k in 1..n - 1 {
        if d[k - 1] * d[k] > 0.0 {
            // The three-point (Bessel) slope, second-order accurate, limited to three times
            // the smaller secant so that the cubic stays monotone (Hyman 1983).
            let bessel = (h[k] * d[k - 1] + h[k - 1] * d[k]) / (h[k - 1] + h[k]);
            let limit = 3.0 * d[k - 1].abs().min(d[k].abs());
            m[k] = bessel.signum() * bessel.abs().min(limit);
        }
    }
    m[0] = edge(h[0], h[1], d[0], d[1]);
    m[n - 1] = edge(h[n - 2], h[n - 3], d[n - 2], d[n - 3]);
    m
}

/// The one-sided three-point slope at an end, kept shape-preserving.
fn edge(h0: f64, h1: f64, d0: f64, d1: f64) -> f64 {
    let m = ((2.0 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
    if m.signum() != d0.signum() || d0 == 0.0 {
        0.0
    } else if d0.signum() != d1.signum() && m.abs() > 3.0 * d0.abs() {
        3.0 * d0
    } else {
        m
    }
}

/// The cubic Hermite interpolant on `[0, h]` at `s h`, `s` in `[0, 1]`.
fn hermite_at(s: f64, h: f64, x0: f64, x1: f64, m0: f64, m1: f64) -> f64 {
    let (s2, s3) = (s * s, s * s * s);
    (2.0 * s3 - 3.0 * s2 + 1.0) * x0
        + (s3 - 2.0 * s2 + s) * h * m0
        + (-2.0 * s3 + 3.0 * s2) * x1
        + (s3 - s2) * h * m1
}

/// Its second derivative at both ends (it is linear in between).
fn second_derivatives(h: f64, x0: f64, x1: f64, m0: f64, m1: f64) -> [f64; 2] {
    let secant = (x1 - x0) / h;
    [
        (6.0 * secant - 4.0 * m0 - 2.0 * m1) / h,
        (-6.0 * secant + 2.0 * m0 + 4.0 * m1) / h,
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cubic is reproduced by the Hermite form with its own slopes, and the refinement puts
    /// the chords within the tolerance.
    #[test]
    fn hermite_reproduces_a_cubic_and_refines_to_the_tolerance() {
        let f = |t: f64| 0.3 * t * t * t - t * t + 0.5;
        let df = |t: f64| 0.9 * t * t - 2.0 * t;
        let t: Vec<f64> = (0..5).map(|k| k as f64 * 0.75).collect();
        let x: Vec<f64> = t.iter().map(|&t| f(t)).collect();
        let v: Vec<f64> = t.iter().map(|&t| df(t)).collect();
        let range = x.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
            - x.iter().cloned().fold(f64::INFINITY, f64::min);
        let s = SmoothSamples::hermite(t.clone(), x, v, 1e-6).unwrap();
        let r = s.refined();
        for (tk, xk) in r.times().iter().zip(r.values()) {
            assert!((xk - f(*tk)).abs() < 1e-14, "{tk}: {xk}");
        }
        for w in r.times().windows(2) {
            let mid = 0.5 * (w[0] + w[1]);
            let chord = 0.5 * (f(w[0]) + f(w[1]));
            assert!((chord - f(mid)).abs() <= 1e-6 * range * (1.0 + 1e-9));
        }
        assert_eq!(s.sample_knots().len(), t.len());
    }

    /// PCHIP: 0 at a reversal, the secant on a straight line, never overshooting.
    #[test]
    fn pchip_slopes_preserve_the_shape() {
        let m = pchip_slopes(&[0.0, 1.0, 2.0, 3.0], &[0.0, 1.0, 2.0, 1.0]);
        assert_eq!(m[2], 0.0);
        assert_eq!(m[1], 1.0);
        let m = pchip_slopes(&[0.0, 1.0, 2.0], &[0.0, 2.0, 4.0]);
        assert_eq!(m, vec![2.0, 2.0, 2.0]);
    }
}
