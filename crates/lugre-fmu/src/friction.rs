//! `lugre-friction.fmu`: the friction element (see the crate docs for the equations).

use lugre::simulate::FrictionElement;
use lugre::LuGreParams;

use crate::{param, set_param, Kind, Unit};

/// The token of `fmu/lugre-friction.xml` (`instantiationToken`).
pub const TOKEN: &str = "{7f6c1c2e-3b1d-4c55-9a57-lugre-friction-1}";

/// Value references (as in `fmu/lugre-friction.xml`; the parameters' are [`crate::vr`]'s).
pub mod vr {
    pub const X: u32 = 1;
    pub const V: u32 = 2;
    pub const F: u32 = 3;
    pub const Z: u32 = 4;
    pub const DER_Z: u32 = 5;
    /// The initial bristle deflection `z(0)` (as the mass FMU's): the model's own parameters
    /// from [`crate::vr::OWN`] on, after the room left for the table's.
    pub const Z0: u32 = crate::vr::OWN;
}

/// One instance of the friction FMU.
pub(crate) struct Friction {
    kind: Kind,
    params: LuGreParams,
    z0: f64,
    time: f64,
    x: f64,
    v: f64,
    /// The state (model exchange; co-simulation: the element's).
    z: f64,
    /// The element, from the end of initialization: it steps in co-simulation and gives the
    /// rates in model exchange.
    element: Option<FrictionElement>,
}

impl Friction {
    pub(crate) fn new(kind: Kind) -> Self {
        Self {
            kind,
            params: LuGreParams::canudas_de_wit_1995(),
            z0: 0.0,
            time: 0.0,
            x: 0.0,
            v: 0.0,
            z: 0.0,
            element: None,
        }
    }

    /// `z'` and `F` at the current state and inputs (model exchange), from the core.
    fn rates(&self) -> Result<(f64, f64), String> {
        crate::rates(self.element.as_ref(), self.params, self.v, self.z)
    }

    fn co_simulation(&self) -> Option<&FrictionElement> {
        self.element
            .as_ref()
            .filter(|_| self.kind == Kind::CoSimulation)
    }
}

impl Unit for Friction {
    fn name_of(&self, vr: u32) -> &'static str {
        match vr {
            vr::X => "x",
            vr::V => "v",
            vr::F => "F",
            vr::Z => "z",
            vr::DER_Z => "der(z)",
            vr::Z0 => "z0",
            _ => crate::param_name(vr),
        }
    }

    fn get(&self, r: u32) -> Result<f64, String> {
        Ok(match r {
            crate::vr::TIME => self.time(),
            vr::X => self.x,
            vr::V => self.v,
            vr::F => match (&self.element, self.kind) {
                (Some(e), Kind::CoSimulation) => e.force(),
                _ => self.rates()?.1,
            },
            vr::Z => self.co_simulation().map_or(self.z, FrictionElement::state),
            vr::DER_Z => self.rates()?.0,
            vr::Z0 => self.z0,
            _ => return param(&self.params, r),
        })
    }

    fn set(&mut self, r: u32, value: f64) -> Result<(), String> {
        let initialized = self.element.is_some();
        match r {
            vr::X => self.x = value,
            vr::V => self.v = value,
            vr::Z0 if !initialized => self.z0 = value,
            _ => {
                let name = self.name_of(r);
                set_param(&mut self.params, r, value, initialized, name)?
            }
        }
        Ok(())
    }

    fn initialize(&mut self, start: f64, _tolerance: Option<f64>) -> Result<(), String> {
        self.time = start;
        self.element = Some(crate::element(self.params, start, self.x, self.z0)?);
        self.z = self.z0;
        Ok(())
    }

    fn set_time(&mut self, t: f64) {
        self.time = t;
    }

    fn time(&self) -> f64 {
        self.time
    }

    fn do_step(&mut self, t: f64, h: f64) -> Result<(), String> {
        let (x_end, v) = (self.x + self.v * h, self.v);
        let Some(e) = self.element.as_mut() else {
            return Err("fmi3DoStep before the end of initialization".into());
        };
        if !x_end.is_finite() {
            return Err(format!(
                "the displacement x + v h at the step's end is not finite (x = {}, v = {}, h = {})",
                lugre::error::num(self.x),
                lugre::error::num(v),
                lugre::error::num(h)
            ));
        }
        e.step(x_end, h).map_err(|err| err.to_string())?;
        self.time = t + h;
        self.x = x_end;
        Ok(())
    }

    fn states(&self) -> Vec<f64> {
        vec![self.z]
    }

    fn set_states(&mut self, states: &[f64]) {
        self.z = states[0];
    }

    fn derivatives(&self) -> Result<Vec<f64>, String> {
        Ok(vec![self.rates()?.0])
    }

    fn nominals(&self) -> Vec<f64> {
        // z is of the order of g(0) / sigma0.
        vec![(self.params.fs.max(self.params.fc) / self.params.sigma0).max(1e-300)]
    }

    fn indicators(&self) -> Vec<f64> {
        Vec::new()
    }
}
