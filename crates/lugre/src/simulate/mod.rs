//! Finite-rate simulation: the response `y_gamma` of the LuGre and Dahl models to slow inputs
//! (paper eq. 5), its rate-independent limit `y*_u` (eq. 6) and the paper's Example 1 (eq. 18).
//!
//! Replacing the input `u(t)` of eq. 1 by `u(t / gamma)` and rescaling time gives eq. 5:
//!
//! ```text
//! z' = -sigma0 |u'(t)| / g(u'(t) / gamma) z + u'(t)              z(0) = x0
//! y_gamma = sigma0 z + (sigma1 / gamma) z' + f(u'(t) / gamma)
//! ```
//!
//! `t` is eq. 5's time: the input's period does not depend on `gamma`. `gamma = 1` is eq. 1
//! itself; `gamma = inf` is the limit `y*_u` of eq. 6 (`g(0)` for `g`, no `sigma1` or `f`
//! term), which needs no special case: `v / gamma = 0` there.
//!
//! * [`PiecewiseLinear`] inputs (turning points at a constant speed, sampled data linear
//!   between samples) are solved **exactly** segment by segment ([`exact`]): on a segment
//!   where `u' = v` is constant eq. 5 is linear with constant coefficients, and
//!   the kernel's `relax` gives its solution at any stiffness, with no step-size limit.
//! * [`Sine`] inputs are integrated by an adaptive, L-stable method with a user tolerance
//!   ([`Simulator::sine`]; the method, Radau IIA with step doubling, in
//!   `docs/mathematics.md`, "Sines: adaptive Radau IIA"), except for `gamma = inf`, where eq. 6
//!   is again closed form.
//!
//! The output `y` jumps where `u'` does (through the `(sigma1 / gamma) z'` and `f` terms): at a
//! kink the value **just after** it is reported. At the end of a piecewise-linear input that
//! closes on itself (`u` back at its start, a periodic input) the end is a kink like the others
//! and the value reported is the next period's first; at the end of an open input it is the
//! value just before the end, the only one defined.
//!
//! In the rate-independent limit the k-th period `y*_{u,k}` of the response from `x0`
//! converges to the hysteresis loop `y°` of [`crate::HysteresisLoop`] geometrically: both obey
//! the same recursion, so their difference is `(sigma0 x0 - y°(0)) exp(-a rho_u(t))` and
//! `sup_t |y*_{u,k} - y°| = |y°(0) - sigma0 x0| exp(-a P k)` ([`crate::HysteresisLoop::transient_amplitude`]).
//!
//! ```
//! use lugre::simulate::{merge_times, uniform_times};
//! use lugre::{Bimodal, Gamma, LuGre, PiecewiseLinear, Simulator, Trajectory};
//!
//! // The paper's Example 3 (Fig. 11): gamma = 10, x0 = 0, three periods of the bimodal input
//! // 0 -> 1 -> 0.2 -> 1.5 at unit speed, 100 samples per period and every kink.
//! let model = LuGre::paper();
//! let b = Bimodal::new(0.0, 0.2, 1.0, 1.5).unwrap();
//! let input = PiecewiseLinear::from_turning_points(&b.turning_points(), 1.0).unwrap();
//! let times = merge_times(&uniform_times(0.0, input.period(), 3, 100), &input.knot_times(3));
//! let mut y_gamma = Trajectory::default();
//! Simulator::new(&model, Gamma::new(10.0).unwrap(), 0.0)
//!     .unwrap()
//!     .at_times(&input, 3, &times, &mut y_gamma)
//!     .unwrap();
//! // The rate-independent limit y*_u (the solid curve of Fig. 11).
//! let mut y_star = Trajectory::default();
//! Simulator::new(&model, Gamma::INFINITE, 0.0)
//!     .unwrap()
//!     .at_times(&input, 3, &times, &mut y_star)
//!     .unwrap();
//! let gap = y_gamma.y.iter().zip(&y_star.y).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
//! assert!(gap < 0.3); // O(1 / gamma)
//! ```

pub(crate) mod adaptive;
mod element;
pub mod exact;
pub mod example1;
mod inputs;
mod request;
pub mod smooth;

pub use element::FrictionElement;
pub use exact::{Observed, Simulator};
pub use example1::{paper_example_1, Example1};
pub use inputs::{PiecewiseLinear, Sine};
pub use request::{Drive, Output, Request, Samples};
pub use smooth::SmoothSamples;

pub use crate::error::SimulateError;

/// The slowness `gamma` of eq. 5: a finite positive number, or infinity (the rate-independent
/// limit `y*_u` of eq. 6).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Gamma(f64);

impl Gamma {
    /// `gamma = 1`: eq. 1 itself.
    pub const ONE: Gamma = Gamma(1.0);
    /// `gamma = inf`: the rate-independent limit.
    pub const INFINITE: Gamma = Gamma(f64::INFINITY);

    /// Validated: `> 0` (NaN and non-positive values are rejected; `+inf` is the limit).
    pub fn new(value: f64) -> Result<Self, SimulateError> {
        if value > 0.0 {
            Ok(Self(value))
        } else {
            Err(SimulateError::BadGamma { value })
        }
    }

    pub fn value(self) -> f64 {
        self.0
    }

    /// `1 / gamma` (exactly 0 for `gamma = inf`).
    pub fn inverse(self) -> f64 {
        1.0 / self.0
    }

    pub fn is_infinite(self) -> bool {
        self.0.is_infinite()
    }
}

/// The relative tolerance of the adaptive integrator.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerance(f64);

impl Tolerance {
    /// Default: `1e-10`, ten thousand times the rounding floor.
    pub const DEFAULT: Tolerance = Tolerance(1e-10);

    /// Validated: in `[1e-14, 1)` (below `1e-14` rounding dominates and steps would shrink
    /// without end).
    pub fn new(value: f64) -> Result<Self, SimulateError> {
        if (1e-14..1.0).contains(&value) {
            Ok(Self(value))
        } else {
            Err(SimulateError::BadTolerance { value })
        }
    }

    pub fn value(self) -> f64 {
        self.0
    }
}

/// One output sample: eq. 5's time, the input, the state `z`, its derivative `z'` and the
/// output `y_gamma` (just after a kink, see the module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    pub t: f64,
    pub u: f64,
    pub z: f64,
    pub dz: f64,
    pub y: f64,
}

/// A simulated response, column by column (what `--json` and `--csv` print).
///
/// Filling a trajectory whose capacity suffices allocates nothing: reuse one with
/// [`Trajectory::clear`] in loops.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Trajectory {
    pub t: Vec<f64>,
    pub u: Vec<f64>,
    pub z: Vec<f64>,
    pub dz: Vec<f64>,
    pub y: Vec<f64>,
}

impl Trajectory {
    pub fn with_capacity(n: usize) -> Self {
        Self {
            t: Vec::with_capacity(n),
            u: Vec::with_capacity(n),
            z: Vec::with_capacity(n),
            dz: Vec::with_capacity(n),
            y: Vec::with_capacity(n),
        }
    }

    pub fn len(&self) -> usize {
        self.t.len()
    }

    pub fn is_empty(&self) -> bool {
        self.t.is_empty()
    }

    /// Empties every column, keeping the capacity.
    pub fn clear(&mut self) {
        self.t.clear();
        self.u.clear();
        self.z.clear();
        self.dz.clear();
        self.y.clear();
    }

    /// Makes room for `additional` more samples.
    pub fn reserve(&mut self, additional: usize) {
        self.t.reserve(additional);
        self.u.reserve(additional);
        self.z.reserve(additional);
        self.dz.reserve(additional);
        self.y.reserve(additional);
    }

    #[inline]
    pub fn push(&mut self, s: Sample) {
        self.t.push(s.t);
        self.u.push(s.u);
        self.z.push(s.z);
        self.dz.push(s.dz);
        self.y.push(s.y);
    }

    pub fn get(&self, i: usize) -> Option<Sample> {
        Some(Sample {
            t: *self.t.get(i)?,
            u: self.u[i],
            z: self.z[i],
            dz: self.dz[i],
            y: self.y[i],
        })
    }

    /// The indices of the samples with `start <= t <= end` (the samples are in time order):
    /// e.g. the k-th period `y*_{u,k}` with `start = t0 + k T`, `end = start + T`.
    pub fn range_between(&self, start: f64, end: f64) -> std::ops::Range<usize> {
        let lo = self.t.partition_point(|&t| t < start);
        let hi = self.t.partition_point(|&t| t <= end);
        lo..hi.max(lo)
    }

    /// The first sample whose `z`, `z'` or `y` is not finite, as an error.
    pub(crate) fn check_finite(&self, from: usize) -> Result<(), SimulateError> {
        for i in from..self.len() {
            let what = if !self.z[i].is_finite() {
                "the state z"
            } else if !self.dz[i].is_finite() {
                "z'"
            } else if !self.y[i].is_finite() {
                "the output y"
            } else {
                continue;
            };
            return Err(SimulateError::Overflow { what, t: self.t[i] });
        }
        Ok(())
    }
}

/// Checks output times: finite, strictly increasing, inside `[start, end]` (the one rule of
/// [`crate::input::check_output_times`]).
pub(crate) fn check_output_times(times: &[f64], start: f64, end: f64) -> Result<(), SimulateError> {
    Ok(crate::input::check_output_times(times, start, end)?)
}

/// `per_period` evenly spaced times per period over `periods` periods from `start`, both ends
/// included: `periods * per_period + 1` times `start + T j / per_period`.
/// (`per_period = 0` counts as 1.)
pub fn uniform_times(start: f64, period: f64, periods: u32, per_period: usize) -> Vec<f64> {
    let per_period = per_period.max(1);
    let n = periods as usize * per_period;
    (0..=n)
        .map(|j| {
            // Whole periods are added separately so that every period gets the same offsets
            // and the last time is exactly `start + periods * period`, the run's end.
            let (p, i) = (j / per_period, j % per_period);
            start + p as f64 * period + period * (i as f64 / per_period as f64)
        })
        .collect()
}

/// The sorted union of two sorted time lists (equal times kept once).
pub fn merge_times(a: &[f64], b: &[f64]) -> Vec<f64> {
    let mut out = Vec::with_capacity(a.len() + b.len());
    let (mut i, mut j) = (0, 0);
    while i < a.len() || j < b.len() {
        let next = if j >= b.len() || (i < a.len() && a[i] <= b[j]) {
            i += 1;
            a[i - 1]
        } else {
            j += 1;
            b[j - 1]
        };
        if out.last() != Some(&next) {
            out.push(next);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use crate::kernel::relax::{decay, relax, relax_toward};

    // mpmath, mp.dps = 40: (c, exp(-c), -expm1(-c)), printed with mp.nstr(x, 20).
    const DECAY: [(f64, f64, f64); 12] = [
        (1e-300, 1.0, 1.0000000000000000251e-300),
        (1e-12, 0.999999999999, 9.9999999999949997989e-13),
        (0.001, 0.99900049983337499165, 0.00099950016662500835274),
        (0.1, 0.90483741803595956814, 0.095162581964040431859),
        (0.2499, 0.77887866704384571889, 0.22112133295615428111),
        (0.25, 0.77880078307140486825, 0.22119921692859513175),
        (0.2501, 0.77872290688697185481, 0.22127709311302814519),
        (0.5, 0.6065306597126334236, 0.3934693402873665764),
        (0.69, 0.50157606906605556065, 0.49842393093394443935),
        (0.7, 0.49658530379140953676, 0.50341469620859046324),
        (3.0, 0.049787068367863942979, 0.95021293163213605702),
        (40.0, 4.2483542552915889953e-18, 0.99999999999999999575),
    ];

    #[test]
    fn decay_is_accurate_to_a_few_ulps_on_both_sides_of_the_switch() {
        for (c, e, one_minus_e) in DECAY {
            let (got_e, got_o) = decay(c);
            assert!(
                ((got_e - e) / e).abs() <= 2.0 * f64::EPSILON,
                "exp(-{c}) = {got_e}"
            );
            assert!(
                ((got_o - one_minus_e) / one_minus_e).abs() <= 4.0 * f64::EPSILON,
                "1 - exp(-{c}) = {got_o}"
            );
        }
        assert_eq!(decay(0.0), (1.0, 0.0));
        assert_eq!(decay(f64::INFINITY), (0.0, 1.0));
    }

    #[test]
    fn relax_forms_agree_and_handle_the_limits() {
        // w' = -r w + q from w0: both forms, r = 0, and an infinite decay.
        for (w0, c, d) in [
            (0.3, 0.0, 0.0),
            (0.3, 1e-9, 2e-9),
            (-1.0, 0.2, 0.5),
            (2.0, 30.0, -3.0),
        ] {
            let a = relax(w0, c, d);
            if c > 0.0 {
                let b = relax_toward(w0, c, d / c);
                assert!(
                    (a - b).abs() <= 4.0 * f64::EPSILON * a.abs().max(w0.abs()),
                    "{a} {b}"
                );
            } else {
                assert_eq!(a, w0 + d);
            }
        }
        assert_eq!(relax(5.0, f64::INFINITY, 1.0), 0.0);
        assert_eq!(relax_toward(5.0, f64::INFINITY, 2.0), 2.0);
    }
}
