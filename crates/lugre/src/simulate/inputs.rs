//! The inputs a simulation is driven by: piecewise-linear (knots, linear in between) and sine.

use super::SimulateError;
use crate::error::InputError;
use crate::input::{check_all_finite, check_times, TurningPoints};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// An input linear between knots `(t_i, u_i)`: sampled data, or turning points at a constant
/// speed. Repeated over several periods when it closes on itself (`u` ends where it starts);
/// the period is then `T = t_last - t_first`.
#[derive(Debug, Clone, PartialEq)]
pub struct PiecewiseLinear {
    t: Vec<f64>,
    u: Vec<f64>,
}

impl PiecewiseLinear {
    /// Validated: equal lengths, at least 2 knots, all finite, `t` strictly increasing, and
    /// every increment `u_{i+1} - u_i` finite (the exact solution is built from them).
    pub fn new(t: Vec<f64>, u: Vec<f64>) -> Result<Self, SimulateError> {
        if t.len() != u.len() {
            return Err(InputError::LengthMismatch {
                t: t.len(),
                u: u.len(),
            }
            .into());
        }
        check_times(&t)?;
        check_all_finite("u", &u)?;
        if t.len() < 2 {
            return Err(SimulateError::TooFewSamples { count: t.len() });
        }
        let overflows = |w: &[f64]| w.iter().zip(&w[1..]).any(|(a, b)| !(b - a).is_finite());
        if overflows(&t) || overflows(&u) || !(t[t.len() - 1] - t[0]).is_finite() {
            return Err(InputError::VariationOverflow.into());
        }
        Ok(Self { t, u })
    }

    /// One period of a periodic input through its turning points at constant `speed > 0`,
    /// from the first turning point (`t = 0`) back to it: knots at `t_k = rho_k / speed`, the
    /// turning points' `rho` (eq. 7) as [`crate::HysteresisLoop`] computes them. With
    /// `speed = 1` time is the normalized variable `rho` (the paper's Examples 2-4).
    pub fn from_turning_points(tp: &TurningPoints, speed: f64) -> Result<Self, SimulateError> {
        if !(speed > 0.0 && speed.is_finite()) {
            return Err(SimulateError::BadSpeed { value: speed });
        }
        let values = tp.values();
        let n = values.len();
        let mut u = Vec::with_capacity(n + 1);
        let mut rho = Vec::with_capacity(n + 1);
        let mut r = 0.0;
        for k in 0..=n {
            let v = values[k % n];
            if k > 0 {
                r += (v - values[k - 1]).abs();
            }
            u.push(v);
            rho.push(r);
        }
        if !r.is_finite() {
            // Named as the loop names it, not as a bad time the user never gave.
            return Err(InputError::VariationOverflow.into());
        }
        let t = if speed == 1.0 {
            rho
        } else {
            rho.iter().map(|r| r / speed).collect()
        };
        Self::new(t, u)
    }

    /// Knot times.
    pub fn times(&self) -> &[f64] {
        &self.t
    }

    /// Knot values.
    pub fn values(&self) -> &[f64] {
        &self.u
    }

    pub fn len(&self) -> usize {
        self.t.len()
    }

    pub fn is_empty(&self) -> bool {
        self.t.is_empty()
    }

    /// `T = t_last - t_first`, the period when repeated.
    pub fn period(&self) -> f64 {
        self.t[self.len() - 1] - self.t[0]
    }

    /// Whether `u` ends where it starts, so that the input can be repeated.
    pub fn is_closed(&self) -> bool {
        self.u[0] == self.u[self.len() - 1]
    }

    /// The time of knot `i` (`0..len`) in period `p`: `t_i + p T`.
    #[inline]
    pub(crate) fn knot_time(&self, i: usize, p: u32) -> f64 {
        if p == 0 {
            self.t[i]
        } else {
            self.t[i] + f64::from(p) * self.period()
        }
    }

    /// The interval `[start, end]` covered by `periods` periods. `end` is the later of
    /// `t_first + K T` and `t_last + (K - 1) T`, which can differ by an ulp.
    pub fn span(&self, periods: u32) -> (f64, f64) {
        let start = self.t[0];
        let a = start + f64::from(periods) * self.period();
        let b = self.knot_time(self.len() - 1, periods.saturating_sub(1));
        (start, a.max(b))
    }

    /// Every knot time over `periods` periods (a period's last knot is the next one's first,
    /// listed once).
    pub fn knot_times(&self, periods: u32) -> Vec<f64> {
        let n = self.len();
        let mut out = Vec::with_capacity((n - 1) * periods as usize + 1);
        for p in 0..periods {
            for i in 0..n - 1 {
                out.push(self.knot_time(i, p));
            }
        }
        out.push(self.knot_time(n - 1, periods.saturating_sub(1)));
        out
    }

    /// One period sampled at `per_period` evenly spaced times (at least 1) and at every knot,
    /// in order, with `u` on the input's lines there: the same motion, seen more often (the
    /// default output of the zoo's models for turning points, as LuGre's).
    pub fn resampled(&self, per_period: usize) -> (Vec<f64>, Vec<f64>) {
        let uniform = super::uniform_times(self.t[0], self.period(), 1, per_period);
        let t = super::merge_times(&uniform, &self.t);
        let mut k = 0;
        let u = t
            .iter()
            .map(|&x| {
                while k + 2 < self.len() && self.t[k + 1] <= x {
                    k += 1;
                }
                let (t0, t1, u0, u1) = (self.t[k], self.t[k + 1], self.u[k], self.u[k + 1]);
                // The knots themselves exactly; in between on the line.
                if x == t1 {
                    u1
                } else {
                    u0 + (u1 - u0) * ((x - t0) / (t1 - t0))
                }
            })
            .collect();
        (t, u)
    }

    /// Checks that the input can run `periods` periods.
    pub(crate) fn check_periods(&self, periods: u32) -> Result<(), SimulateError> {
        if periods < 1 {
            return Err(SimulateError::BadPeriods { value: periods });
        }
        if periods > 1 && !self.is_closed() {
            return Err(SimulateError::NotClosed {
                periods,
                first: self.u[0],
                last_index: self.len() - 1,
                last: self.u[self.len() - 1],
            });
        }
        Ok(())
    }
}

/// The largest `|phase|` a [`Sine`] takes, in radians.
const MAX_PHASE: f64 = 1e6;

/// `u(t) = A sin(2 pi t / T + phase) + offset`, from `t = 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sine {
    amplitude: f64,
    period: f64,
    phase: f64,
    offset: f64,
}

impl Sine {
    /// Validated: `A > 0` and `T > 0` finite, `phase` finite with `|phase| <= 1e6`, `offset`
    /// finite, and `A 2 pi / T` (the largest speed) finite.
    pub fn new(
        amplitude: f64,
        period: f64,
        phase: f64,
        offset: f64,
    ) -> Result<Self, SimulateError> {
        let positive = |name, value: f64| {
            if value > 0.0 && value.is_finite() {
                Ok(value)
            } else {
                Err(SimulateError::BadSine {
                    name,
                    requirement: "a finite number > 0",
                    value,
                })
            }
        };
        let finite = |name, value: f64| {
            if value.is_finite() {
                Ok(value)
            } else {
                Err(SimulateError::BadSine {
                    name,
                    requirement: "a finite number",
                    value,
                })
            }
        };
        // An angle beyond this has lost its fraction of a turn to rounding (the ulp of 1e6 is
        // 1e-10 rad), and past ~1e16 the reversal search cannot step from one extreme to the
        // next.
        if phase.is_finite() && phase.abs() > MAX_PHASE {
            return Err(SimulateError::BadSine {
                name: "phase",
                requirement: "at most 1e6 radians in magnitude (reduce it modulo 2 pi)",
                value: phase,
            });
        }
        let s = Self {
            amplitude: positive("amplitude", amplitude)?,
            period: positive("period", period)?,
            phase: finite("phase", phase)?,
            offset: finite("offset", offset)?,
        };
        finite("largest speed A 2 pi / T", s.omega() * amplitude)?;
        finite("largest value |offset| + A", offset.abs() + amplitude)?;
        Ok(s)
    }

    pub fn amplitude(&self) -> f64 {
        self.amplitude
    }
    pub fn period(&self) -> f64 {
        self.period
    }
    pub fn phase(&self) -> f64 {
        self.phase
    }
    pub fn offset(&self) -> f64 {
        self.offset
    }

    /// `omega = 2 pi / T`.
    #[inline]
    pub fn omega(&self) -> f64 {
        TAU / self.period
    }

    #[inline]
    pub fn u(&self, t: f64) -> f64 {
        self.amplitude * (self.omega() * t + self.phase).sin() + self.offset
    }

    /// `u'(t)`.
    #[inline]
    pub fn du(&self, t: f64) -> f64 {
        self.amplitude * self.omega() * (self.omega() * t + self.phase).cos()
    }

    /// The first reversal (where `u' = 0`: `omega t + phase = pi/2 + m pi`) strictly after
    /// `t`: its time and the exact extreme there, `offset + A` or `offset - A`.
    pub fn next_reversal(&self, t: f64) -> (f64, f64) {
        let w = self.omega();
        let at = |m: f64| (FRAC_PI_2 + m * PI - self.phase) / w;
        // The floor can be off by one either way after rounding: start one early and step.
        let mut m = ((w * t + self.phase - FRAC_PI_2) / PI).floor() - 1.0;
        while at(m) <= t {
            m += 1.0;
        }
        let top = m.rem_euclid(2.0) == 0.0;
        let extreme = if top {
            self.offset + self.amplitude
        } else {
            self.offset - self.amplitude
        };
        (at(m), extreme)
    }

    /// The reversal times strictly inside `(start, end)`, in order.
    pub fn reversals(&self, start: f64, end: f64) -> Vec<f64> {
        let mut out = Vec::new();
        let mut t = start;
        loop {
            let (next, _) = self.next_reversal(t);
            if next >= end || next <= t {
                return out;
            }
            out.push(next);
            t = next;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_phase_beyond_1e6_is_refused() {
        // The reversal search stepped m -> m + 1 with m ~ 1e16, where m + 1 == m: it hung.
        let e = Sine::new(1.0, 1.0, 1e17, 0.0).unwrap_err();
        assert!(
            e.to_string()
                .starts_with("the sine's phase must be at most 1e6"),
            "{e}"
        );
        let s = Sine::new(1.0, 1.0, -1e6, 0.0).unwrap();
        let (t, _) = s.next_reversal(0.0);
        assert!(t > 0.0 && t <= 1.0);
    }

    #[test]
    fn turning_points_whose_variation_overflows() {
        // Named as the loop names it, not as a time t[1] = inf the user never gave.
        let tp = TurningPoints::new(&[1e308, -1e308]).unwrap();
        assert_eq!(
            PiecewiseLinear::from_turning_points(&tp, 1.0),
            Err(SimulateError::Input(InputError::VariationOverflow))
        );
    }
}
