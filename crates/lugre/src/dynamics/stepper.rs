//! A mass with a finite-rate friction of the zoo (the elasto-plastic law (D2), GMS (G6)) or
//! LuGre's (D1), advanced step by step under an applied force linear over each step: what a
//! co-simulation host needs (the FMUs `lugre-mass-NAME.fmu`).
//!
//! ```text
//! M x'' = P(t) - F,     P(t) = P_k + P'_k (t - t_k)  on [t_k, t_k + h_k]
//! ```
//!
//! Each step is solved by the same solver as `lugre dynamics --model NAME` (Radau IIA, the
//! sign changes of `v` and GMS's mode switches located as events), from the full state at the
//! step's start: `(x, v, z)` for a bristle law, `(x, v)` and every element's force and mode
//! for GMS. A step's end is a restart of the solver (the same state, a fresh step size), so
//! the motion does not depend on where the host puts its communication points beyond the
//! solver's tolerance.

use super::gms::{GmsRun, GmsState};
use super::request::ZooFriction;
use super::{Profile, State, System, Tolerances};
use crate::error::DynamicsError;
use crate::zoo::ZooModel;

/// A mass with friction, stepped under a piecewise-linear applied force.
#[derive(Debug, Clone)]
pub struct MassStepper {
    /// The mass and its friction law, no drive.
    system: System,
    tol: Tolerances,
    state: Carried,
    friction: f64,
}

/// The state carried from step to step.
#[derive(Debug, Clone)]
enum Carried {
    Bristle(State),
    /// GMS friction in place of the system's bristle law, and its state.
    Gms(Box<(GmsState, crate::zoo::MaxwellSlip)>),
}

impl MassStepper {
    /// The mass of `system` with its friction law (LuGre's, or the elasto-plastic one) and no
    /// drive of its own, from `start` (its time, position, velocity and deflection; the PID's
    /// integral is not used): the stepper of `lugre-mass.fmu`.
    ///
    /// # Errors
    /// A start that is not finite.
    pub fn new(system: System, start: State, tol: Tolerances) -> Result<Self, DynamicsError> {
        check_start(&start)?;
        let state = Carried::Bristle(State { q: 0.0, ..start });
        Ok(Self::with_state(system, tol, state))
    }

    /// The stepper in `state`, its friction force computed.
    fn with_state(system: System, tol: Tolerances, state: Carried) -> Self {
        let mut out = Self {
            system,
            tol,
            state,
            friction: 0.0,
        };
        out.friction = out.friction_now();
        out
    }

    /// The mass `mass` with the friction of the finite-rate model `model`, at time `t0`,
    /// position `x0` and velocity `v0`, at rest in its friction (bristles undeflected, every
    /// GMS element sticking at force 0): the friction of `lugre dynamics --model NAME` with
    /// the model's values as given ([`super::Request::with_zoo`] without a scenario).
    ///
    /// # Errors
    /// [`DynamicsError::NoFiniteRate`] for a model without a finite-rate form; the mass's and
    /// the model's checks; a start that is not finite.
    pub fn of_zoo(
        model: &ZooModel,
        mass: f64,
        start: State,
        tol: Tolerances,
    ) -> Result<Self, DynamicsError> {
        ZooFriction::check(model)?;
        let friction = ZooFriction::of(model)?.ok_or(DynamicsError::NoModel)?;
        let mut system = System::new(friction.model, mass)?;
        if let Some(zba) = friction.zba {
            system = system.with_elastoplastic(zba)?;
        }
        let start = State { z: 0.0, ..start };
        let Some(ms) = friction.gms else {
            return Self::new(system, start, tol);
        };
        check_start(&start)?;
        let n = ms.stiffness().len();
        let rest = GmsState::at_rest(n, start.t, start.x, start.v);
        Ok(Self::with_state(
            system,
            tol,
            Carried::Gms(Box::new((rest, ms))),
        ))
    }

    /// The friction force in the state as it stands.
    fn friction_now(&self) -> f64 {
        match &self.state {
            Carried::Gms(g) => {
                let (s, ms) = &**g;
                GmsRun::new(&self.system, ms.gms(), self.tol, false).friction_at(s)
            }
            Carried::Bristle(s) => self.system.friction(s.v, s.z, 0.0).0,
        }
    }

    /// Advances the mass by `h > 0` under the applied force moving linearly from `force` to
    /// `force + dforce h`.
    ///
    /// # Errors
    /// A step that is not finite and positive, a force or rate that is not finite
    /// ([`DynamicsError::NotFinite`]), and the solver's.
    pub fn step(&mut self, force: f64, dforce: f64, h: f64) -> Result<(), DynamicsError> {
        let t = self.t();
        if !(h.is_finite() && h > 0.0) {
            return Err(DynamicsError::NotPositive {
                name: "the step size",
                value: h,
            });
        }
        let end = force + dforce * h;
        let drive = Profile::new("the drive force", vec![t, t + h], vec![force, end])?;
        let system = self.system.clone().with_force(drive);
        let (state, friction) = match &self.state {
            Carried::Bristle(start) => {
                let m = system.solve_from(*start, t + h, &[t + h], self.tol)?;
                let (x, v, z) = (m.x[0], m.v[0], m.z[0]);
                let end = State {
                    t: t + h,
                    x,
                    v,
                    z,
                    q: 0.0,
                };
                (Carried::Bristle(end), m.friction[0])
            }
            Carried::Gms(g) => {
                let (start, ms) = &**g;
                let run = GmsRun::new(&system, ms.gms(), self.tol, false);
                let (end, friction) = run.run_from(start, t + h)?;
                (Carried::Gms(Box::new((end, ms.clone()))), friction)
            }
        };
        (self.state, self.friction) = (state, friction);
        Ok(())
    }

    /// The time.
    pub fn t(&self) -> f64 {
        match &self.state {
            Carried::Bristle(s) => s.t,
            Carried::Gms(g) => g.0.t,
        }
    }

    /// The position.
    pub fn x(&self) -> f64 {
        match &self.state {
            Carried::Bristle(s) => s.x,
            Carried::Gms(g) => g.0.x,
        }
    }

    /// The velocity.
    pub fn v(&self) -> f64 {
        match &self.state {
            Carried::Bristle(s) => s.v,
            Carried::Gms(g) => g.0.v,
        }
    }

    /// The bristle deflection (GMS: the elements' force over their stiffness, `sum F_i / K`,
    /// as [`super::Outcome`]'s `z`).
    pub fn z(&self) -> f64 {
        match &self.state {
            Carried::Bristle(s) => s.z,
            Carried::Gms(g) => {
                let k: f64 = g.1.stiffness().iter().sum();
                g.0.forces.iter().sum::<f64>() / k
            }
        }
    }

    /// The friction force on the mass (at the end of the last step).
    pub fn friction(&self) -> f64 {
        self.friction
    }

    /// The mass.
    pub fn mass(&self) -> f64 {
        self.system.mass()
    }
}

/// A start state with every component finite.
fn check_start(start: &State) -> Result<(), DynamicsError> {
    for (name, value) in [
        ("the start time", start.t),
        ("the start position", start.x),
        ("the start velocity", start.v),
    ] {
        if !value.is_finite() {
            return Err(DynamicsError::NotFinite { name, value });
        }
    }
    Ok(())
}
