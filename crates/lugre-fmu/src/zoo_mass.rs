//! `lugre-mass-NAME.fmu`, one for each model of the core's zoo table with a finite-rate form
//! ([`ZooModelSpec::finite_rate`]: the elasto-plastic model, Maxwell-slip as GMS): the mass of
//! `lugre dynamics --model NAME` with that friction, driven by a force from the host, as
//! `lugre-mass.fmu` is with LuGre's. Nothing here names a model: the token names the table's
//! entry, the parameters are the entry's (at the value references and with the element arrays
//! of `lugre-NAME.fmu`, [`crate::zoo`]) and the mass's own (`m`, `x0`, `v0` at
//! `lugre-mass.fmu`'s references), and the dynamics are the core's
//! ([`lugre::dynamics::MassStepper`]).
//!
//! ```text
//! inputs  force [N], dforce [N/s]        P(t) = force + dforce (t - t_k) over the step from t_k
//! M x'' = P(t) - F                       F: the model's friction (D2) or GMS (G6)
//! outputs x [m], v [m/s], friction F [N]
//! ```
//!
//! The mass starts at `x0`, `v0` at the end of initialization with its friction at rest
//! (bristles undeflected; every GMS element sticking at force 0). `fmi3DoStep(t, h)` solves the
//! step with the solver of `lugre dynamics` (Radau IIA to the host's tolerance, 1e-8 by
//! default, the sign changes of `v` and GMS's stick/slip switches located as events), from the
//! full state the last step ended in (for GMS every element's force and mode): the result does
//! not depend on the host's step size beyond that tolerance.
//!
//! **Co-simulation only.** GMS's state between events is every element's force and mode; its
//! events (an element reaching its slip level, a reversal) switch modes and change which
//! equations hold, so model exchange would need the modes as discrete states and one event
//! indicator per element, with the host restarting its integrator at each; and the
//! elasto-plastic law (D2) is only `C^1` in `z` where its blend starts and ends. The
//! co-simulation steps handle both exactly with the core's event location; model exchange is
//! not offered (the description has no `<ModelExchange>` and instantiating it is refused).

use lugre::dynamics::{MassStepper, State, Tolerances};
use lugre::zoo::ZooModelSpec;

use crate::zoo::{self, Params};
use crate::Unit;

/// The token of the mass FMU of `spec`: `{lugre-mass/NAME}`.
pub fn token(spec: &ZooModelSpec) -> String {
    format!("{{lugre-mass/{}}}", spec.name)
}

/// The finite-rate model of the table a token names.
pub(crate) fn model_of(token: &[u8]) -> Option<&'static ZooModelSpec> {
    let name = std::str::from_utf8(token).ok()?;
    let name = name.strip_prefix("{lugre-mass/")?.strip_suffix('}')?;
    lugre::zoo::MODELS
        .iter()
        .find(|m| m.name == name && m.finite_rate)
}

/// The model identifier of the mass FMU of `spec`: `lugre_mass_NAME`, `-` as `_`.
pub fn identifier(spec: &ZooModelSpec) -> String {
    format!("lugre_mass_{}", spec.name.replace('-', "_"))
}

/// Value references: `lugre-mass.fmu`'s for the same variables, `elements` and the table's
/// parameters as `lugre-NAME.fmu`'s ([`crate::zoo::vr`]).
pub mod vr {
    pub use crate::mass::vr::{DFORCE, FORCE, FRICTION, M, V, V0, X, X0};
    pub use crate::zoo::vr::ELEMENTS;
}

/// The variables other than the table's parameters: (name, value reference).
pub const VARIABLES: [(&str, u32); 10] = [
    ("time", crate::vr::TIME),
    ("force", vr::FORCE),
    ("dforce", vr::DFORCE),
    ("x", vr::X),
    ("v", vr::V),
    ("friction", vr::FRICTION),
    ("elements", vr::ELEMENTS),
    ("m", vr::M),
    ("x0", vr::X0),
    ("v0", vr::V0),
];

/// One instance of a mass FMU of the table.
pub(crate) struct ZooMass {
    params: Params,
    mass: f64,
    x0: f64,
    v0: f64,
    time: f64,
    force: f64,
    dforce: f64,
    tolerance: Tolerances,
    /// The mass with its friction, from the end of initialization.
    stepper: Option<MassStepper>,
}

impl ZooMass {
    pub(crate) fn new(spec: &'static ZooModelSpec) -> Self {
        Self {
            params: Params::new(spec),
            mass: 1.0,
            x0: 0.0,
            v0: 0.0,
            time: 0.0,
            force: 0.0,
            dforce: 0.0,
            tolerance: Tolerances::default(),
            stepper: None,
        }
    }

    /// The mass with the friction of the parameters as they stand, at `t`, `x0`, `v0` (the
    /// core's checks and messages).
    fn build(&self, t: f64) -> Result<MassStepper, String> {
        let model = self.params.model()?;
        let start = State {
            t,
            x: self.x0,
            v: self.v0,
            ..State::default()
        };
        MassStepper::of_zoo(&model, self.mass, start, self.tolerance).map_err(|e| e.to_string())
    }

    /// `(x, v, friction)`: the stepper's, or before the end of initialization the start's.
    fn outputs(&self) -> Result<[f64; 3], String> {
        let s = match &self.stepper {
            Some(s) => return Ok([s.x(), s.v(), s.friction()]),
            None => self.build(self.time)?,
        };
        Ok([s.x(), s.v(), s.friction()])
    }

    /// The mass's own parameter at `r`, mutably (`None`: `r` is not one).
    fn own(&mut self, r: u32) -> Option<&mut f64> {
        match r {
            vr::M => Some(&mut self.mass),
            vr::X0 => Some(&mut self.x0),
            vr::V0 => Some(&mut self.v0),
            _ => None,
        }
    }
}

impl Unit for ZooMass {
    zoo::table_parameters!();

    fn get_values(&self, r: u32, out: &mut [f64]) -> Result<(), String> {
        if let Some(done) = self.params.get(r, out) {
            return done;
        }
        out[0] = match r {
            crate::vr::TIME => self.time,
            vr::FORCE => self.force,
            vr::DFORCE => self.dforce,
            vr::X => self.outputs()?[0],
            vr::V => self.outputs()?[1],
            vr::FRICTION => self.outputs()?[2],
            vr::M => self.mass,
            vr::X0 => self.x0,
            vr::V0 => self.v0,
            _ => return Err(format!("no Float64 variable has value reference {r}")),
        };
        Ok(())
    }

    fn set_values(&mut self, r: u32, values: &[f64]) -> Result<(), String> {
        let fixed = self.stepper.is_some();
        if let Some(done) = self.params.set(r, values, fixed) {
            return done;
        }
        match r {
            vr::FORCE => self.force = values[0],
            vr::DFORCE => self.dforce = values[0],
            _ => {
                let name = self.name_of(r);
                match self.own(r) {
                    Some(_) if fixed => return Err(zoo::fixed_message(name)),
                    Some(own) => *own = values[0],
                    None => return Err(zoo::not_settable(name, r)),
                }
            }
        }
        Ok(())
    }

    fn initialize(&mut self, start: f64, tolerance: Option<f64>) -> Result<(), String> {
        if let Some(rtol) = tolerance {
            self.tolerance = Tolerances::new(rtol, None).map_err(|e| e.to_string())?;
        }
        self.stepper = Some(self.build(start)?);
        self.time = start;
        Ok(())
    }

    fn do_step(&mut self, t: f64, h: f64) -> Result<(), String> {
        let Some(stepper) = self.stepper.as_mut() else {
            return Err("fmi3DoStep before the end of initialization".into());
        };
        if h == 0.0 {
            // Nothing moves in no time (the caller checked h finite and >= 0).
            return Ok(());
        }
        stepper
            .step(self.force, self.dforce, h)
            .map_err(|e| e.to_string())?;
        self.time = t + h;
        Ok(())
    }
}

/// The `modelDescription.xml` of the mass FMU of `spec`, all of it from the table (what
/// `scripts/write-tables.sh` writes to `fmu/mass/NAME.xml`).
///
/// # Errors
/// A unit of the table that [`crate::zoo`]'s units lack.
pub fn model_description(spec: &ZooModelSpec) -> Result<String, String> {
    let mut used: Vec<String> = ["s", "m", "m/s", "N", "N/s", "kg"]
        .map(String::from)
        .to_vec();
    used.extend(spec.parameters.iter().map(|p| zoo::fmi_unit(p.unit)));
    let name = spec.name;
    let description = format!(
        "A mass with {} friction (lugre dynamics --model {name}): drive force in, position, velocity and friction force out; co-simulation only, each step solved to the tolerance with the sign changes of v and the friction's events located. {} ({})",
        spec.label, spec.equations, spec.reference
    );
    let head = zoo::head(
        &format!("lugre-mass-{name}"),
        &description,
        &token(spec),
        &identifier(spec),
        &zoo::unit_definitions(&used)?,
        r#" tolerance="1e-8""#,
    );
    Ok(format!(
        r#"{head}  <ModelVariables>
    <Float64 name="time" valueReference="{time}" causality="independent" variability="continuous" unit="s"/>
    <Float64 name="force" valueReference="{force}" causality="input" variability="continuous" start="0" unit="N" description="drive force on the mass"/>
    <Float64 name="dforce" valueReference="{dforce}" causality="input" variability="continuous" start="0" unit="N/s" description="rate of the drive force over the coming co-simulation step (0: held)"/>
    <Float64 name="x" valueReference="{x}" causality="output" variability="continuous" initial="calculated" unit="m" description="position (x0 at the start)"/>
    <Float64 name="v" valueReference="{v}" causality="output" variability="continuous" initial="calculated" unit="m/s" description="velocity (v0 at the start)"/>
    <Float64 name="friction" valueReference="{friction}" causality="output" variability="continuous" initial="calculated" unit="N" description="friction force on the mass"/>
{parameters}    <Float64 name="m" valueReference="{m}" causality="parameter" variability="fixed" start="1" unit="kg" description="mass (> 0)"/>
    <Float64 name="x0" valueReference="{x0}" causality="parameter" variability="fixed" start="0" unit="m" description="initial position x(0)"/>
    <Float64 name="v0" valueReference="{v0}" causality="parameter" variability="fixed" start="0" unit="m/s" description="initial velocity v(0) (the friction starts at rest)"/>
{tail}"#,
        tail = zoo::tail(&[vr::X, vr::V, vr::FRICTION]),
        time = crate::vr::TIME,
        force = vr::FORCE,
        dforce = vr::DFORCE,
        x = vr::X,
        v = vr::V,
        friction = vr::FRICTION,
        m = vr::M,
        x0 = vr::X0,
        v0 = vr::V0,
        parameters = zoo::parameter_variables(spec),
    ))
}
