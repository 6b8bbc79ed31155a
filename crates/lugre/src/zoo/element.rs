//! A model of the zoo as a hysteresis element driven one step at a time (a co-simulation's
//! communication steps, a host's time loop): at rest at its first input, each step moves the
//! input along one monotone segment by the model's exact segment map
//! ([`Segmental::advance`]), and the element keeps the force and, from its start,
//!
//! ```text
//! (E1)  W = integral F du = sum over steps (dV + D),    D = sum over steps of D_step
//! ```
//!
//! each step's `dV` from the two states ([`Segmental::arc`]), the sums in double-double
//! arithmetic so that a long run keeps the digits of its latest steps. An input linear in time
//! between the host's points makes each step one monotone segment, whatever its length: the
//! element is exact at any step size, for every model of the table alike.

use super::Segmental;
use crate::error::ZooError;
use crate::kernel::numerics::DoubleDouble;

/// What the element asks of the model it walks (object-safe, over the model's own state).
trait Walk: Send + Sync {
    fn input(&self) -> f64;
    fn force(&self) -> f64;
    /// Moves to `to` along one monotone segment: `(dV + D, D)` over it.
    fn advance(&mut self, to: f64) -> (f64, f64);
    /// Back to the state before the last `advance`.
    fn undo(&mut self);
}

/// A model with its state, and the state before the last step (kept to avoid allocating).
struct Walker<M: Segmental> {
    model: M,
    state: M::State,
    before: M::State,
}

impl<M> Walk for Walker<M>
where
    M: Segmental + Send + Sync,
    M::State: Send + Sync,
{
    fn input(&self) -> f64 {
        M::input(&self.state)
    }

    fn force(&self) -> f64 {
        self.model.force(&self.state)
    }

    fn advance(&mut self, to: f64) -> (f64, f64) {
        M::assign(&mut self.before, &self.state);
        let d = self.model.advance(&mut self.state, to);
        let arc = self.model.arc(&self.before, &self.state, d);
        (arc.work, d)
    }

    fn undo(&mut self) {
        M::assign(&mut self.state, &self.before);
    }
}

/// A model of the zoo driven step by step from rest, with its work and dissipation (E1).
pub struct ZooElement {
    model: super::ZooModel,
    walk: Box<dyn Walk>,
    work: DoubleDouble,
    dissipation: DoubleDouble,
}

impl std::fmt::Debug for ZooElement {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ZooElement")
            .field("model", &self.model.spec().name)
            .field("u", &self.input())
            .field("force", &self.force())
            .field("work", &self.work())
            .field("dissipation", &self.dissipation())
            .finish()
    }
}

impl ZooElement {
    /// `model` (its concrete form `m`) at rest at input `u`: built by [`super::ZooModel::element`].
    pub(crate) fn at_rest<M>(model: &super::ZooModel, m: &M, u: f64) -> Result<Self, ZooError>
    where
        M: Segmental + Clone + Send + Sync + 'static,
        M::State: Send + Sync,
    {
        let u = finite("u", u)?;
        let state = m.rest(u);
        let walk = Walker {
            model: m.clone(),
            before: state.clone(),
            state,
        };
        Ok(Self {
            model: model.clone(),
            walk: Box::new(walk),
            work: DoubleDouble::ZERO,
            dissipation: DoubleDouble::ZERO,
        })
    }

    /// Moves the input to `u` along one monotone segment (the exact segment map).
    ///
    /// # Errors
    /// [`ZooError::Domain`] for a non-finite `u`, [`ZooError::Overflow`] when the force or
    /// an energy would not be finite; the element is then as before the call.
    pub fn advance(&mut self, u: f64) -> Result<(), ZooError> {
        let u = finite("u", u)?;
        let (work, dissipation) = self.walk.advance(u);
        let (w, d) = (
            self.work.add_f64(work),
            self.dissipation.add_f64(dissipation),
        );
        let overflow = [
            ("the force", self.walk.force()),
            ("the work", w.to_f64()),
            ("the dissipation", d.to_f64()),
        ]
        .into_iter()
        .find(|(_, x)| !x.is_finite());
        if let Some((what, _)) = overflow {
            self.walk.undo();
            return Err(ZooError::Overflow { what });
        }
        (self.work, self.dissipation) = (w, d);
        Ok(())
    }

    /// The model.
    pub fn model(&self) -> &super::ZooModel {
        &self.model
    }

    /// The input now.
    pub fn input(&self) -> f64 {
        self.walk.input()
    }

    /// The force now.
    pub fn force(&self) -> f64 {
        self.walk.force()
    }

    /// The work `W = integral F du` from the start (E1).
    pub fn work(&self) -> f64 {
        self.work.to_f64()
    }

    /// The dissipation from the start (E1); `W - D` is the change of the stored energy.
    pub fn dissipation(&self) -> f64 {
        self.dissipation.to_f64()
    }
}

/// `x` if finite, else the error naming it (`name`).
pub(super) fn finite(name: &'static str, x: f64) -> Result<f64, ZooError> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(ZooError::Domain {
            name,
            value: x,
            condition: "a finite number".into(),
        })
    }
}
