//! A stateful friction element for host simulators (the C ABI, the FMUs, a user's own loop).
//!
//! A host advances time in steps of its own choosing and knows the relative displacement `x`
//! at their ends. The element takes each step as a segment of a piecewise-linear input
//! (`x` linear in time over the step, the reading of [`super::exact`]), so a step is exact
//! whatever its length or the stiffness, and a run of steps through the knots of a
//! piecewise-linear input gives exactly what [`Simulator::at_knots`] gives there. Eq. 1 is
//! taken at `gamma = 1` (physical time):
//!
//! ```text
//! z' = x' - sigma0 |x'| / g(x') z          F = sigma0 z + sigma1 z' + f(x')
//! ```
//!
//! The force after a step is the value **at its end with the step's velocity** (the value
//! just before a kink at the end, the only one the element can know: the next step's velocity
//! is not known yet). Before any step the element is at rest: `F = sigma0 z`.
//!
//! ```
//! use lugre::simulate::FrictionElement;
//! use lugre::{LuGre, LuGreParams};
//!
//! // A 1 kg-scale Table I model pulled by 10 um in 10 ms, then held for 10 ms.
//! let model = LuGre::from_params(LuGreParams::canudas_de_wit_1995()).unwrap();
//! let mut element = FrictionElement::new(model, 0.0).unwrap();
//! element.step(1e-5, 1e-2).unwrap();
//! element.step(1e-5, 1e-2).unwrap();
//! assert!((element.force() - 1e5 * element.state()).abs() < 1e-12); // at rest: F = sigma0 z
//! ```

use super::{Gamma, Sample, SimulateError, Simulator};
use crate::model::{LuGre, Stribeck, VelocityFn, Viscous};

/// The friction of one contact, advanced step by step by a host (see the module docs).
#[derive(Debug, Clone)]
pub struct FrictionElement<G = Stribeck, F = Viscous> {
    model: LuGre<G, F>,
    /// The state at the last reset, and the displacement and time there.
    start: (f64, f64, f64),
    /// The sample at the end of the last step (or at rest after a reset).
    now: Sample,
}

impl<G: VelocityFn, F: VelocityFn> FrictionElement<G, F> {
    /// At rest at `t = 0`, displacement `0`, bristle deflection `z0` (validated like
    /// [`Simulator::new`]'s `x0`).
    pub fn new(model: LuGre<G, F>, z0: f64) -> Result<Self, SimulateError> {
        Self::starting_at(model, 0.0, 0.0, z0)
    }

    /// At rest at time `t`, displacement `x`, bristle deflection `z0`.
    pub fn starting_at(model: LuGre<G, F>, t: f64, x: f64, z0: f64) -> Result<Self, SimulateError> {
        let now = rest(&model, t, x, z0)?;
        Ok(Self {
            model,
            start: (t, x, z0),
            now,
        })
    }

    /// Move the displacement to `x` over the next `dt` (linearly in time: exact, see the
    /// module docs) and return the sample at the step's end. `dt = 0` is allowed for a step
    /// that does not move; a failed step leaves the element as it was.
    #[inline]
    pub fn step(&mut self, x: f64, dt: f64) -> Result<Sample, SimulateError> {
        if !x.is_finite() {
            return Err(SimulateError::BadDisplacement { value: x });
        }
        if !(dt >= 0.0 && dt.is_finite()) {
            return Err(SimulateError::BadStep { value: dt });
        }
        if !(self.now.t + dt).is_finite() {
            // A time of inf would make every later step a zero step.
            return Err(SimulateError::TimeOverflow {
                t: self.now.t,
                step: dt,
            });
        }
        let du = x - self.now.u;
        if dt == 0.0 || dt + self.now.t == self.now.t {
            if du != 0.0 {
                return Err(SimulateError::JumpInZeroStep {
                    from: self.now.u,
                    to: x,
                });
            }
            return Ok(self.now);
        }
        let simulator = Simulator::new(&self.model, Gamma::ONE, self.now.z)?;
        let next = simulator.advance(self.now.z, self.now.t + dt, x, du, dt);
        if !(next.y.is_finite() && next.dz.is_finite()) {
            return Err(SimulateError::Overflow {
                what: "the friction force",
                t: next.t,
            });
        }
        self.now = next;
        Ok(next)
    }

    /// Eq. 1's right-hand side at deflection `z` with the displacement moving at `v`, without
    /// stepping: the sample at the element's time and displacement with `z' = v - sigma0 |v|
    /// z / g(v)` (`dz`) and `F = sigma0 z + sigma1 z' + f(v)` (`y`), the same arithmetic as a
    /// step's output. For a host that integrates `z` itself (an FMU in model exchange).
    ///
    /// ```
    /// use lugre::simulate::FrictionElement;
    /// use lugre::{LuGre, LuGreParams};
    ///
    /// let model = LuGre::from_params(LuGreParams::canudas_de_wit_1995()).unwrap();
    /// let element = FrictionElement::new(model, 0.0).unwrap();
    /// let s = element.rates_at(1e-3, 0.0).unwrap();
    /// assert_eq!(s.dz, 1e-3); // no deflection yet: z' = v
    /// ```
    #[inline]
    pub fn rates_at(&self, v: f64, z: f64) -> Result<Sample, SimulateError> {
        let simulator = Simulator::new(&self.model, Gamma::ONE, z)?;
        Ok(simulator.sample_at_slope(self.now.t, self.now.u, v, z))
    }

    /// The friction force `F` after the last step.
    pub fn force(&self) -> f64 {
        self.now.y
    }
    /// The bristle deflection `z` after the last step.
    pub fn state(&self) -> f64 {
        self.now.z
    }
    /// Time, displacement, `z`, `z'` and `F` after the last step.
    pub fn sample(&self) -> Sample {
        self.now
    }
    pub fn model(&self) -> &LuGre<G, F> {
        &self.model
    }

    /// Back to the state of the last reset (or of construction).
    pub fn reset(&mut self) {
        let (t, x, z0) = self.start;
        // Validated when it was set.
        self.now = rest(&self.model, t, x, z0).unwrap_or(self.now);
    }

    /// At rest at time `t`, displacement `x`, deflection `z0`, and make that the reset point.
    pub fn reset_to(&mut self, t: f64, x: f64, z0: f64) -> Result<(), SimulateError> {
        if !t.is_finite() {
            return Err(crate::DataError::NotFinite {
                what: "t",
                index: 0,
                value: t,
            }
            .into());
        }
        self.now = rest(&self.model, t, x, z0)?;
        self.start = (t, x, z0);
        Ok(())
    }
}

/// The sample at rest (`x' = 0`, so `z' = 0` and `F = sigma0 z`).
fn rest<G: VelocityFn, F: VelocityFn>(
    model: &LuGre<G, F>,
    t: f64,
    x: f64,
    z0: f64,
) -> Result<Sample, SimulateError> {
    if !x.is_finite() {
        return Err(SimulateError::BadDisplacement { value: x });
    }
    Simulator::new(model, Gamma::ONE, z0)?;
    Ok(Sample {
        t,
        u: x,
        z: z0,
        dz: 0.0,
        y: model.sigma0() * z0 + model.f(0.0),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::LuGreParams;
    use crate::simulate::{PiecewiseLinear, Trajectory};

    /// Stepping through the knots of a piecewise-linear input is `at_knots`, to the bit for
    /// the state (the same operations in the same order).
    #[test]
    fn steps_through_knots_are_at_knots() {
        let model = LuGre::from_params(LuGreParams::canudas_de_wit_1995()).unwrap();
        let t = [0.0, 0.01, 0.02, 0.05, 0.06, 0.1];
        let u = [0.0, 1e-5, 3e-5, -2e-5, -2e-5, 4e-5];
        let input = PiecewiseLinear::new(t.to_vec(), u.to_vec()).unwrap();
        let mut out = Trajectory::default();
        Simulator::new(&model, Gamma::ONE, 1e-6)
            .unwrap()
            .at_knots(&input, 1, &mut out)
            .unwrap();
        let mut element = FrictionElement::new(model, 1e-6).unwrap();
        for i in 1..t.len() {
            let s = element.step(u[i], t[i] - t[i - 1]).unwrap();
            assert_eq!(s.z, out.z[i], "z at knot {i}");
        }
        // The last knot of an open input is reported with the last segment's slope: equal.
        assert_eq!(element.force(), *out.y.last().unwrap());
    }

    #[test]
    fn bad_steps_leave_the_element_as_it_was() {
        let mut element = FrictionElement::new(
            LuGre::from_params(LuGreParams::canudas_de_wit_1995()).unwrap(),
            0.0,
        )
        .unwrap();
        element.step(1e-6, 1e-3).unwrap();
        let before = element.sample();
        assert!(element.step(f64::NAN, 1e-3).is_err());
        assert!(element.step(1e-6, -1.0).is_err());
        assert!(element.step(1e-6, f64::INFINITY).is_err());
        assert!(element.step(2e-6, 0.0).is_err());
        assert_eq!(element.step(1e-6, 0.0).unwrap(), before);
        assert_eq!(element.sample(), before);
        element.reset();
        assert_eq!(element.state(), 0.0);
        assert!(element.reset_to(0.0, 0.0, f64::NAN).is_err());
        // A step whose end time overflows is refused; the time stays finite.
        element.step(0.0, 1.7e308).unwrap();
        assert_eq!(
            element.step(0.0, 1.7e308).unwrap_err().to_string(),
            "the step 1.7e308 from t = 1.7e308 takes the time past the largest finite number"
        );
        assert_eq!(element.sample().t, 1.7e308);
    }

    /// The rates a model-exchange host integrates are the step's own output arithmetic: at a
    /// step's end, with its slope and state, they give the step's `z'` and force to the bit.
    #[test]
    fn rates_are_the_steps_output() {
        let model = LuGre::from_params(LuGreParams::canudas_de_wit_1995()).unwrap();
        let mut element = FrictionElement::new(model, 2e-6).unwrap();
        let s = element.step(3e-6, 2e-3).unwrap();
        let r = element.rates_at(3e-6 / 2e-3, s.z).unwrap();
        assert_eq!((r.dz, r.y, r.t, r.u), (s.dz, s.y, s.t, s.u));
        assert!(element.rates_at(1.0, f64::NAN).is_err());
    }
}
