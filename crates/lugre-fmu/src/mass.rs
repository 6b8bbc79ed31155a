//! `lugre-mass.fmu`: the one-degree-of-freedom system of `lugre dynamics` (a mass with LuGre
//! friction) driven by a force from the host, so that a host closes its own loop around it:
//!
//! ```text
//! M x'' = F_drive - F,   z' = v - sigma0 |v| z / g(v),   F = sigma0 z + sigma1 z' + f(v)
//! ```
//!
//! * Co-simulation: a step moves the drive force linearly from `force` to `force + dforce h`
//!   (`dforce`, the force's rate over the step: a host with a spring sets `k (V - v)`) and solves
//!   the step with `lugre::dynamics` ([`MassStepper`], as the zoo's mass FMUs do: Radau IIA
//!   with the sign changes of `v` located, to the host's tolerance, 1e-8 by default): exact to
//!   that tolerance, whatever the step.
//! * Model exchange: states `x`, `v`, `z`; one event indicator, `v` (where `|v|` kinks); `z'`
//!   and the friction force are the core's ([`FrictionElement::rates_at`]).
//!
//! The run starts at the parameters `x0`, `v0` and `z0` (position, velocity, bristle
//! deflection; all 0 by default).

use lugre::dynamics::{MassStepper, State, System, Tolerances};
use lugre::simulate::FrictionElement;
use lugre::LuGreParams;

use crate::{param, set_param, Kind, Unit};

/// The token of `fmu/lugre-mass.xml` (`instantiationToken`).
pub const TOKEN: &str = "{3c9e4a51-0d7b-4f2e-8e61-lugre-mass-1}";

/// Value references (as in `fmu/lugre-mass.xml`; the friction parameters' are [`crate::vr`]'s).
pub mod vr {
    pub const FORCE: u32 = 1;
    pub const DFORCE: u32 = 2;
    pub const X: u32 = 3;
    pub const V: u32 = 4;
    pub const FRICTION: u32 = 5;
    pub const Z: u32 = 6;
    pub const DER_X: u32 = 7;
    pub const DER_V: u32 = 8;
    pub const DER_Z: u32 = 9;
    /// The model's own parameters from [`crate::vr::OWN`] on, after the room left for the
    /// table's.
    pub const Z0: u32 = crate::vr::OWN;
    pub const M: u32 = crate::vr::OWN + 1;
    /// The initial position `x(0)`.
    pub const X0: u32 = crate::vr::OWN + 2;
    /// The initial velocity `v(0)`.
    pub const V0: u32 = crate::vr::OWN + 3;
}

/// One instance of the mass FMU.
pub(crate) struct Mass {
    kind: Kind,
    params: LuGreParams,
    mass: f64,
    /// The initial position, velocity and bristle deflection.
    x0: f64,
    v0: f64,
    z0: f64,
    time: f64,
    force: f64,
    dforce: f64,
    x: f64,
    v: f64,
    z: f64,
    /// The friction force at the end of the last co-simulation step.
    friction: f64,
    /// The friction law, from the end of initialization (its model solves the co-simulation
    /// steps; its rates are model exchange's).
    element: Option<FrictionElement>,
    tolerance: Tolerances,
}

impl Mass {
    pub(crate) fn new(kind: Kind) -> Self {
        Self {
            kind,
            params: LuGreParams::canudas_de_wit_1995(),
            mass: 1.0,
            x0: 0.0,
            v0: 0.0,
            z0: 0.0,
            time: 0.0,
            force: 0.0,
            dforce: 0.0,
            x: 0.0,
            v: 0.0,
            z: 0.0,
            friction: 0.0,
            element: None,
            tolerance: Tolerances::default(),
        }
    }

    /// `z'`, the friction force and `v'` at the current state and input (model exchange).
    fn rates(&self) -> Result<(f64, f64, f64), String> {
        let (dz, friction) = crate::rates(self.element.as_ref(), self.params, self.v, self.z)?;
        Ok((dz, friction, (self.force - friction) / self.mass))
    }
}

impl Unit for Mass {
    fn name_of(&self, r: u32) -> &'static str {
        match r {
            vr::FORCE => "force",
            vr::DFORCE => "dforce",
            vr::X => "x",
            vr::V => "v",
            vr::FRICTION => "friction",
            vr::Z => "z",
            vr::DER_X => "der(x)",
            vr::DER_V => "der(v)",
            vr::DER_Z => "der(z)",
            vr::Z0 => "z0",
            vr::M => "m",
            vr::X0 => "x0",
            vr::V0 => "v0",
            _ => crate::param_name(r),
        }
    }

    fn get(&self, r: u32) -> Result<f64, String> {
        let cs = self.kind == Kind::CoSimulation;
        Ok(match r {
            crate::vr::TIME => self.time(),
            vr::FORCE => self.force,
            vr::DFORCE => self.dforce,
            vr::X => self.x,
            vr::V => self.v,
            vr::FRICTION if cs => self.friction,
            vr::FRICTION => self.rates()?.1,
            vr::Z => self.z,
            vr::DER_X => self.v,
            vr::DER_V => self.rates()?.2,
            vr::DER_Z => self.rates()?.0,
            vr::Z0 => self.z0,
            vr::M => self.mass,
            vr::X0 => self.x0,
            vr::V0 => self.v0,
            _ => return param(&self.params, r),
        })
    }

    fn set(&mut self, r: u32, value: f64) -> Result<(), String> {
        let initialized = self.element.is_some();
        match r {
            vr::FORCE => self.force = value,
            vr::DFORCE => self.dforce = value,
            vr::Z0 if !initialized => self.z0 = value,
            vr::M if !initialized => self.mass = value,
            vr::X0 if !initialized => self.x0 = value,
            vr::V0 if !initialized => self.v0 = value,
            _ => {
                let name = self.name_of(r);
                set_param(&mut self.params, r, value, initialized, name)?
            }
        }
        Ok(())
    }

    fn initialize(&mut self, start: f64, tolerance: Option<f64>) -> Result<(), String> {
        let element = crate::element(self.params, start, self.x0, self.z0)?;
        // The same checks as `lugre dynamics`: the mass, the tolerance.
        System::new(element.model().clone(), self.mass).map_err(|e| e.to_string())?;
        if let Some(rtol) = tolerance {
            self.tolerance = Tolerances::new(rtol, None).map_err(|e| e.to_string())?;
        }
        let (_, friction) = crate::rates(Some(&element), self.params, self.v0, self.z0)?;
        self.time = start;
        (self.x, self.v, self.z, self.friction) = (self.x0, self.v0, self.z0, friction);
        self.element = Some(element);
        Ok(())
    }

    fn set_time(&mut self, t: f64) {
        self.time = t;
    }

    fn time(&self) -> f64 {
        self.time
    }

    fn do_step(&mut self, t: f64, h: f64) -> Result<(), String> {
        let Some(element) = &self.element else {
            return Err("fmi3DoStep before the end of initialization".into());
        };
        if h == 0.0 {
            // Nothing moves in no time (the caller checked h finite and >= 0).
            return Ok(());
        }
        // The core's stepper from the state as it stands (model exchange keeps its own).
        let system = System::new(element.model().clone(), self.mass).map_err(|e| e.to_string())?;
        let start = State {
            t,
            x: self.x,
            v: self.v,
            z: self.z,
            q: 0.0,
        };
        let mut stepper =
            MassStepper::new(system, start, self.tolerance).map_err(|e| e.to_string())?;
        stepper
            .step(self.force, self.dforce, h)
            .map_err(|e| e.to_string())?;
        (self.x, self.v, self.z) = (stepper.x(), stepper.v(), stepper.z());
        self.friction = stepper.friction();
        self.time = t + h;
        Ok(())
    }

    fn states(&self) -> Vec<f64> {
        vec![self.x, self.v, self.z]
    }

    fn set_states(&mut self, states: &[f64]) {
        (self.x, self.v, self.z) = (states[0], states[1], states[2]);
    }

    fn derivatives(&self) -> Result<Vec<f64>, String> {
        let (dz, _, dv) = self.rates()?;
        Ok(vec![self.v, dv, dz])
    }

    fn nominals(&self) -> Vec<f64> {
        let length = (self.params.fs.max(self.params.fc) / self.params.sigma0).max(1e-300);
        vec![1.0, 1.0, length]
    }

    fn indicators(&self) -> Vec<f64> {
        vec![self.v]
    }
}
