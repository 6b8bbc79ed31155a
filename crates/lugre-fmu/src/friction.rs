//! `lugre-friction.fmu`: the friction element (see the crate docs for the equations).

use lugre::simulate::FrictionElement;
use lugre::{LuGre, LuGreParams};

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
    pub const X0: u32 = 17;
}

/// One instance of the friction FMU.
pub(crate) struct Friction {
    kind: Kind,
    params: LuGreParams,
    x0: f64,
    time: f64,
    x: f64,
    v: f64,
    /// The state (model exchange).
    z: f64,
    model: Option<LuGre>,
    /// The element (co-simulation), from the end of initialization.
    element: Option<FrictionElement>,
}

impl Friction {
    pub(crate) fn new(kind: Kind) -> Self {
        Self {
            kind,
            params: LuGreParams::canudas_de_wit_1995(),
            x0: 0.0,
            time: 0.0,
            x: 0.0,
            v: 0.0,
            z: 0.0,
            model: None,
            element: None,
        }
    }

    /// `z'` and `F` at the current state and inputs (model exchange).
    fn rates(&self) -> (f64, f64) {
        let p = &self.params;
        let Some(m) = &self.model else {
            return (0.0, p.sigma0 * self.z);
        };
        let dz = self.v - p.sigma0 * self.v.abs() * self.z / m.g(self.v);
        (dz, p.sigma0 * self.z + p.sigma1 * dz + m.f(self.v))
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
            vr::X0 => "x0",
            _ => crate::param_name(vr),
        }
    }

    fn get(&self, r: u32) -> Option<f64> {
        Some(match r {
            crate::vr::TIME => self.time,
            vr::X => self.x,
            vr::V => self.v,
            vr::F => match &self.element {
                Some(e) => e.force(),
                None => self.rates().1,
            },
            vr::Z => self.element.as_ref().map_or(self.z, FrictionElement::state),
            vr::DER_Z => self.rates().0,
            vr::X0 => self.x0,
            _ => return param(&self.params, r),
        })
    }

    fn set(&mut self, r: u32, value: f64) -> Result<(), String> {
        let initialized = self.model.is_some();
        match r {
            vr::X => self.x = value,
            vr::V => self.v = value,
            vr::X0 if !initialized => self.x0 = value,
            _ => {
                let name = self.name_of(r);
                set_param(&mut self.params, r, value, initialized, name)?
            }
        }
        Ok(())
    }

    fn initialize(&mut self, start: f64, _tolerance: Option<f64>) -> Result<(), String> {
        self.time = start;
        let model = LuGre::from_params(self.params).map_err(|e| e.to_string())?;
        if self.kind == Kind::CoSimulation {
            let element = FrictionElement::starting_at(model.clone(), start, self.x, self.x0)
                .map_err(|e| e.to_string())?;
            self.element = Some(element);
        } else {
            self.z = self.x0;
        }
        self.model = Some(model);
        Ok(())
    }

    fn set_time(&mut self, t: f64) {
        self.time = t;
    }

    fn do_step(&mut self, t: f64, h: f64) -> Result<(), String> {
        let (x_end, v) = (self.x + self.v * h, self.v);
        let Some(e) = self.element.as_mut() else {
            return Err("fmi3DoStep before the end of initialization".into());
        };
        if !x_end.is_finite() {
            return Err(format!("the displacement x + v h is not finite (v = {v})"));
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

    fn derivatives(&self) -> Vec<f64> {
        vec![self.rates().0]
    }

    fn nominals(&self) -> Vec<f64> {
        // z is of the order of g(0) / sigma0.
        vec![(self.params.fs.max(self.params.fc) / self.params.sigma0).max(1e-300)]
    }

    fn indicators(&self) -> Vec<f64> {
        Vec::new()
    }
}
