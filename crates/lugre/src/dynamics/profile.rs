//! Functions of time given by points: piecewise-linear profiles (an applied force, the free end
//! of a spring) and piecewise-constant steps (a set point).

use crate::error::DynamicsError;

/// `f(t)` through the points `(t_i, f_i)`, linear in between, constant before the first and
/// after the last. Times strictly increasing, values finite.
#[derive(Debug, Clone, PartialEq)]
pub struct Profile {
    t: Vec<f64>,
    f: Vec<f64>,
    /// Whether the first and last pieces extend beyond the points (a ramp) rather than hold.
    extend: bool,
}

impl Profile {
    /// `what` names the profile in errors (`"the force profile"`).
    pub fn new(what: &'static str, t: Vec<f64>, f: Vec<f64>) -> Result<Self, DynamicsError> {
        check_points(what, &t, &f)?;
        Ok(Self {
            t,
            f,
            extend: false,
        })
    }

    /// `f(t) = f0 + slope t` at every `t` (a ramp, unbounded).
    pub fn ramp(f0: f64, slope: f64) -> Result<Self, DynamicsError> {
        for (name, value) in [("the ramp's start", f0), ("the ramp's rate", slope)] {
            if !value.is_finite() {
                return Err(DynamicsError::NotFinite { name, value });
            }
        }
        Ok(Self {
            t: vec![0.0, 1.0],
            f: vec![f0, f0 + slope],
            extend: true,
        })
    }

    /// The value at `t`: linear between points; before the first and after the last point a
    /// ramp keeps its slope, a profile holds its end values.
    pub fn value(&self, t: f64) -> f64 {
        self.value_and_slope(t).0
    }

    /// `(f(t), f'(t))`, with the slope just after `t` at a knot.
    pub fn value_and_slope(&self, t: f64) -> (f64, f64) {
        let (ts, fs) = (&self.t, &self.f);
        let n = ts.len();
        if n == 1 {
            return (fs[0], 0.0);
        }
        let i = ts.partition_point(|&x| x <= t);
        let k = if self.extend {
            i.clamp(1, n - 1) - 1
        } else if i == 0 || i == n {
            return (if i == 0 { fs[0] } else { fs[n - 1] }, 0.0);
        } else {
            i - 1
        };
        let slope = (fs[k + 1] - fs[k]) / (ts[k + 1] - ts[k]);
        (fs[k] + slope * (t - ts[k]), slope)
    }

    /// The last point's time.
    pub fn last_time(&self) -> f64 {
        self.t[self.t.len() - 1]
    }

    /// The times where the slope jumps (a ramp's points are not kinks).
    pub fn kinks(&self) -> &[f64] {
        if self.extend {
            &self.t[1..self.t.len() - 1]
        } else {
            &self.t
        }
    }
}

/// A set point that steps: `x_i` from `t_i` on (`x_0` before `t_1`).
#[derive(Debug, Clone, PartialEq)]
pub struct Steps {
    t: Vec<f64>,
    x: Vec<f64>,
}

impl Steps {
    /// `x_0` from the start, then `x_i` from `t_i` (strictly increasing) on.
    pub fn new(t: Vec<f64>, x: Vec<f64>) -> Result<Self, DynamicsError> {
        check_points("setpoint", &t, &x)?;
        Ok(Self { t, x })
    }

    /// A constant set point.
    pub fn constant(x: f64) -> Result<Self, DynamicsError> {
        Self::new(vec![0.0], vec![x])
    }

    pub fn value(&self, t: f64) -> f64 {
        let i = self.t.partition_point(|&s| s <= t);
        self.x[i.saturating_sub(1)]
    }

    /// The times where it steps (the first point's time is not one).
    pub fn steps(&self) -> &[f64] {
        &self.t[1..]
    }
}

fn check_points(what: &'static str, t: &[f64], f: &[f64]) -> Result<(), DynamicsError> {
    if t.is_empty() || t.len() != f.len() {
        return Err(DynamicsError::BadProfile {
            what,
            times: t.len(),
            values: f.len(),
        });
    }
    for (i, (&ti, &fi)) in t.iter().zip(f).enumerate() {
        if !ti.is_finite() || !fi.is_finite() {
            return Err(DynamicsError::ProfileNotFinite { what, index: i });
        }
        if i > 0 && ti <= t[i - 1] {
            return Err(DynamicsError::ProfileTimes {
                what,
                index: i,
                prev: t[i - 1],
                value: ti,
            });
        }
    }
    Ok(())
}
