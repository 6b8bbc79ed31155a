//! A model of the zoo with a finite-rate form ([`super::ZooModelSpec::finite_rate`]) driven
//! one step at a time at the input's rate (a co-simulation's communication steps): at rest at
//! its first input, each step moves the input to `u_to` at the constant velocity
//! `v = (u_to - u) / dt` by the model's exact map of an interval of constant velocity (the one
//! [`super::ZooModel::simulate`] uses: GMS (G4)-(G5), elasto-plastic (E8)), and the stepper
//! keeps the force after the step (moving at `v`: the left limit), the stored energy `V` and,
//! from its start,
//!
//! ```text
//! (R1)  W = ∫ F du = ∫ F v dt,      D = W - (V - V_0)
//! ```
//!
//! each step's work in closed form (GMS, (G8) of `docs/mathematics.md`) or with the blend's
//! quadrature (elasto-plastic, (E9)), the sums in double-double arithmetic.

use super::element::finite;
use super::gms::GmsState;
use super::{ZooKind, ZooModel};
use crate::error::ZooError;
use crate::kernel::numerics::DoubleDouble;
use crate::LuGre;

/// The state of a finite-rate model.
#[derive(Debug, Clone)]
enum Rate {
    /// The GMS element forces and `sum_i dF_i/dt` at the end of the last step.
    Gms { state: GmsState, rate: f64 },
    /// The elasto-plastic deflection, with the model's LuGre parts (`g`, `f`, `sigma1`).
    ElastoPlastic { z: f64, lugre: Box<LuGre> },
}

/// A finite-rate model of the zoo driven step by step from rest, with its energies (R1).
#[derive(Debug, Clone)]
pub struct ZooStepper {
    model: ZooModel,
    state: Rate,
    u: f64,
    /// The velocity of the last step (0 at rest).
    v: f64,
    work: DoubleDouble,
    /// The stored energy at the start.
    stored0: f64,
}

impl ZooModel {
    /// This model at finite rate, at rest at input `u`, to be driven one step at a time
    /// ([`ZooStepper::step`]).
    ///
    /// # Errors
    /// [`ZooError::RateIndependent`] for a model without a finite-rate form (drive it by
    /// [`ZooModel::element`]), [`ZooError::Domain`] for a non-finite `u`, the model's LuGre
    /// checks (elasto-plastic).
    ///
    /// ```
    /// use lugre::zoo::ZooModel;
    /// let model = ZooModel::new("elastoplastic", &[])?;
    /// let mut s = model.stepper(0.0)?;
    /// s.step(0.25, 1.0)?; // inside the break-away band: no dissipation but the damping's
    /// assert!((s.stored_energy() - 0.5 * 0.25 * 0.25).abs() < 1e-15);
    /// # Ok::<(), lugre::Error>(())
    /// ```
    pub fn stepper(&self, u: f64) -> Result<ZooStepper, ZooError> {
        let u = finite("u", u)?;
        let state = match self.kind() {
            ZooKind::MaxwellSlip(m) => Rate::Gms {
                state: m.gms().rest(),
                rate: 0.0,
            },
            ZooKind::ElastoPlastic(m) => Rate::ElastoPlastic {
                z: 0.0,
                lugre: Box::new(LuGre::from_params(m.lugre_params())?),
            },
            _ => {
                return Err(ZooError::RateIndependent {
                    model: self.spec().label,
                })
            }
        };
        Ok(ZooStepper {
            model: self.clone(),
            state,
            u,
            v: 0.0,
            work: DoubleDouble::ZERO,
            stored0: 0.0,
        })
    }
}

impl ZooModel {
    /// [`ZooModel::simulate`] of a model with a finite-rate form: its stepper through the
    /// samples (`t`, `u` checked), at each sample the force moving at the velocity after it
    /// ([`ZooStepper::force_moving`]; the last sample: the velocity before).
    pub(super) fn simulate_rate(&self, t: &[f64], u: &[f64]) -> Result<Vec<f64>, ZooError> {
        let mut stepper = self.stepper(u[0])?;
        let n = u.len();
        let after = |i: usize| match n {
            0 | 1 => 0.0,
            _ => {
                let j = i.min(n - 2);
                (u[j + 1] - u[j]) / (t[j + 1] - t[j])
            }
        };
        let mut out = Vec::with_capacity(n);
        for i in 0..n {
            if i > 0 {
                stepper.step(u[i], t[i] - t[i - 1])?;
            }
            let force = stepper.force_moving(after(i));
            if !force.is_finite() {
                return Err(ZooError::Overflow { what: "the force" });
            }
            out.push(force);
        }
        Ok(out)
    }
}

impl ZooStepper {
    /// Moves the input to `u_to` over `dt` seconds at the constant velocity `(u_to - u) / dt`
    /// (`dt = 0` only with `u_to = u`: nothing moves).
    ///
    /// # Errors
    /// [`ZooError::Domain`] for a non-finite `u_to`, a `dt` not finite and `>= 0`, a velocity
    /// that is not finite; [`ZooError::Overflow`] when the force or the work would not be
    /// finite. The stepper is then as before the call.
    pub fn step(&mut self, u_to: f64, dt: f64) -> Result<(), ZooError> {
        let u_to = finite("u", u_to)?;
        let dt = finite("dt", dt)?;
        let du = u_to - self.u;
        let v = if dt > 0.0 { du / dt } else { f64::NAN };
        if dt < 0.0 || (dt == 0.0 && du != 0.0) || (dt > 0.0 && !v.is_finite()) {
            return Err(ZooError::Domain {
                name: "dt",
                value: dt,
                condition: format!(
                    ">= 0, with a finite velocity (u_to - u) / dt for the move from u = {} to {}",
                    crate::error::num(self.u),
                    crate::error::num(u_to)
                ),
            });
        }
        if dt == 0.0 {
            return Ok(());
        }
        let mut next = self.state.clone();
        let work = next.advance(&self.model, v, dt, du);
        let w = self.work.add_f64(work);
        if !w.to_f64().is_finite() {
            return Err(ZooError::Overflow { what: "the work" });
        }
        if !next.force(&self.model, v).is_finite() {
            return Err(ZooError::Overflow { what: "the force" });
        }
        (self.state, self.work, self.u, self.v) = (next, w, u_to, v);
        Ok(())
    }

    /// The model.
    pub fn model(&self) -> &ZooModel {
        &self.model
    }

    /// The input now.
    pub fn input(&self) -> f64 {
        self.u
    }

    /// The velocity of the last step (0 before the first).
    pub fn velocity(&self) -> f64 {
        self.v
    }

    /// The force after the last step, moving at its velocity (0 at rest).
    pub fn force(&self) -> f64 {
        self.state.force(&self.model, self.v)
    }

    /// The force of the state now moving at `v` (the elasto-plastic force just after a sample
    /// where the velocity changes to `v`; GMS's force depends on the step that led here, and
    /// is [`Self::force`] whatever `v`).
    pub(crate) fn force_moving(&self, v: f64) -> f64 {
        match &self.state {
            Rate::Gms { .. } => self.force(),
            Rate::ElastoPlastic { .. } => self.state.force(&self.model, v),
        }
    }

    /// The stored energy now (GMS: `sum_i F_i^2 / (2 k_i)`; elasto-plastic: `sigma0 z^2 / 2`).
    pub fn stored_energy(&self) -> f64 {
        self.state.stored(&self.model)
    }

    /// The work `W = ∫ F du` of the input from the start (R1).
    pub fn work(&self) -> f64 {
        self.work.to_f64()
    }

    /// The dissipation from the start: `W - (V - V_0)` (R1).
    pub fn dissipation(&self) -> f64 {
        self.work
            .add_f64(self.stored0 - self.stored_energy())
            .to_f64()
    }
}

impl Rate {
    /// Moves the state over `dt` seconds at `v` (`du = v dt`); the work over the step.
    fn advance(&mut self, model: &ZooModel, v: f64, dt: f64, du: f64) -> f64 {
        match (self, model.kind()) {
            (Rate::Gms { state, rate }, ZooKind::MaxwellSlip(m)) => {
                let gms = m.gms();
                let before: f64 = state.force.iter().sum();
                let (r, integral) = gms.advance(state, v, dt);
                *rate = r;
                let after: f64 = state.force.iter().sum();
                // (G8): v ∫ sum F_i dt + (sigma1 / K) v Δ sum F_i + sigma2 v du.
                v * integral + gms.damping() * v * (after - before) + gms.rate().sigma2 * v * du
            }
            (Rate::ElastoPlastic { z, lugre }, ZooKind::ElastoPlastic(m)) => {
                let (z_b, work) = m.rate_step(lugre, *z, v, du);
                *z = z_b;
                work
            }
            _ => 0.0,
        }
    }

    /// The force of the state moving at `v`.
    fn force(&self, model: &ZooModel, v: f64) -> f64 {
        match (self, model.kind()) {
            (Rate::Gms { state, rate }, ZooKind::MaxwellSlip(m)) => m.gms().force(state, v, *rate),
            (Rate::ElastoPlastic { z, lugre }, ZooKind::ElastoPlastic(m)) => {
                m.rate_force(lugre, *z, v)
            }
            _ => 0.0,
        }
    }

    fn stored(&self, model: &ZooModel) -> f64 {
        match (self, model.kind()) {
            (Rate::Gms { state, .. }, ZooKind::MaxwellSlip(m)) => m.gms().stored_energy(state),
            (Rate::ElastoPlastic { z, .. }, ZooKind::ElastoPlastic(m)) => m.stored_energy(*z),
            _ => 0.0,
        }
    }
}
