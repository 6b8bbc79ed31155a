//! [`Request`]: one run of the closed-loop dynamics, with the one set of defaults and the one
//! set of checks that every front end (`lugre dynamics`, `lugre.dynamics`, the C ABI and the
//! MEX function) fills in.
//!
//! **Fields and defaults.** Each field is named by a [`Field`] (its name is the Python keyword
//! and the MEX struct field; the command line spells it as a flag):
//!
//! | field | default | meaning |
//! |---|---|---|
//! | `scenario` | none | a 1995 experiment ([`Scenario`]) that fills the fields below as a preset |
//! | `model` | the scenario's (Table I), else none: a model must be named | the LuGre (or Dahl) friction |
//! | `mass` | 1 kg | `M > 0` |
//! | `damping` | 0 | a linear damper `c >= 0` to the ground |
//! | `force` / `force_rate` / `input` | none | the applied force: a profile, a ramp `r t`, or a measured history |
//! | `spring` with `pull` or `end` | none | a spring `k` whose free end moves at a speed or along a profile |
//! | `pid` with `setpoint` | none; set point 0 | a PID controller on position |
//! | `velocity` | none | a prescribed velocity (the mass follows it; nothing else may drive it) |
//! | `t_end` | the last output time, else the input's last time, else the scenario's | the end of the run |
//! | `times` / `samples` | [`Request::DEFAULT_SAMPLES`] evenly spaced times | the output times |
//! | `rtol`, `atol` | [`Tolerances::DEFAULT_RTOL`], `rtol g(0) / sigma0` | the solver's tolerances |
//! | `loops` | on for the pre-sliding scenario | the friction-displacement loops |
//!
//! **A scenario is a preset.** Every field given on top of a scenario replaces the scenario's
//! value of that field and keeps the others (`pid` on the PID experiment changes the gains and
//! keeps its set point 1 m; `force_rate` on the break-away changes the ramp and its end
//! `2 N / r`). Two fields given by the user that cannot hold together are one error naming
//! both ([`DynamicsError::Conflict`]): two applied forces, `times` and `samples`, a prescribed
//! velocity with anything that would drive the mass, a set point with no controller.

use super::loops::{friction_loops, loops_of, FrictionLoop};
use super::{Breakaway, Motion, Pid, Profile, Scenario, Steps, System, Tolerances, Velocity};
use crate::error::{DynamicsError, Error, Field};
use crate::model::LuGre;

/// A value and who gave it: the scenario (replaced silently by the user's) or the user
/// (through the field named, which a second user value conflicts with).
#[derive(Debug, Clone, PartialEq)]
struct Given<T> {
    value: T,
    by: Option<Field>,
}

/// The applied force.
#[derive(Debug, Clone, PartialEq)]
enum Force {
    Profile(Profile),
    Ramp(f64),
}

/// Where the free end of the spring goes.
#[derive(Debug, Clone, PartialEq)]
enum End {
    Pull(f64),
    Profile(Profile),
}

/// The output times.
#[derive(Debug, Clone, PartialEq)]
enum Output {
    Times(Vec<f64>),
    Samples(u64),
}

/// One run of the dynamics: what drives the mass, the run and what to report, each with the
/// default of the module docs. Built `with_*` (each validates its value), checked as a whole
/// by [`Request::build`].
///
/// ```
/// use lugre::dynamics::{Request, Scenario};
///
/// // The PID experiment with other gains: its set point (1 m) is kept.
/// let plan = Request::new()
///     .with_scenario(Scenario::Pid)
///     .with_pid(3.0, 8.0, 6.0)
///     .unwrap()
///     .with_t_end(20.0)
///     .unwrap()
///     .build()
///     .unwrap();
/// let out = plan.run().unwrap();
/// assert!(out.motion.x.last().unwrap() > &0.5);
/// ```
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Request {
    scenario: Option<Scenario>,
    model: Option<Given<LuGre>>,
    /// The elasto-plastic break-away displacement: the friction law (D2) on the model.
    elastoplastic: Option<f64>,
    /// A model of the zoo as the friction, its parameters not named taken from the scenario's
    /// model where it has them ([`Request::with_zoo`]).
    zoo: Option<crate::zoo::ZooModel>,
    /// GMS friction (the Maxwell-slip model at finite rate) in place of the model's.
    gms: Option<crate::zoo::MaxwellSlip>,
    mass: Option<Given<f64>>,
    damping: Option<Given<f64>>,
    force: Option<Given<Force>>,
    /// A label for a measured force history (`input`): its file's name.
    input_label: Option<String>,
    spring: Option<Given<f64>>,
    end: Option<Given<End>>,
    pid: Option<Given<[f64; 3]>>,
    setpoint: Option<Given<Steps>>,
    velocity: Option<Given<Velocity>>,
    t_end: Option<Given<f64>>,
    output: Option<Given<Output>>,
    rtol: Option<f64>,
    atol: Option<f64>,
    loops: Option<bool>,
}

impl Request {
    /// Output samples over the run when neither `times` nor `samples` is given.
    pub const DEFAULT_SAMPLES: u64 = 1001;
    /// The most output times a run may ask for: 10^7 rows of six columns are 480 MB, and the
    /// solver lands a step on each.
    pub const MAX_OUTPUTS: u64 = 10_000_000;
    /// The mass when none is given (kg).
    pub const DEFAULT_MASS: f64 = 1.0;

    /// An empty request: every field at its default.
    pub fn new() -> Self {
        Self::default()
    }

    /// The 1995 experiment `scenario` as a preset: its model (Table I), drive and end, each
    /// replaced by a field given on top of it (in any order).
    pub fn with_scenario(mut self, scenario: Scenario) -> Self {
        self.scenario = Some(scenario);
        self
    }

    /// The friction model.
    pub fn with_model(mut self, model: LuGre) -> Self {
        self.model = user(Field::Model, model);
        self
    }

    /// A model of the zoo as the friction: the elasto-plastic one
    /// ([`crate::zoo::ZooKind::ElastoPlastic`]) is the LuGre model of its `sigma0, sigma1,
    /// sigma2, fc, fs, vs, beta` with its `zba` ([`Request::with_model`],
    /// [`Request::with_elastoplastic`]); Maxwell-slip runs as GMS (its finite-rate form,
    /// [`crate::zoo::gms`]), with the LuGre model of the same stiffness `sum k_i`, Stribeck
    /// curve and damping as the model's stand-in where one is needed (the default `atol`);
    /// the front ends' one way in. On a scenario, each parameter the model's maker did not
    /// name ([`crate::zoo::ZooModel::is_named`]) is the scenario's (Table I) where the model
    /// has it, and GMS's elements not named are the table's scaled to Table I's stiffness and
    /// static force ([`crate::zoo::gms::elements_on_scale`]), so that every front end runs the
    /// same friction for the same named values.
    ///
    /// # Errors
    /// [`DynamicsError::NoFiniteRate`] for the models of the zoo without a finite-rate form.
    pub fn with_zoo(mut self, model: &crate::zoo::ZooModel) -> Result<Self, DynamicsError> {
        ZooFriction::check(model)?;
        self.zoo = Some(model.clone());
        Ok(self)
    }

    /// The zoo model's friction on the request: its LuGre model and law, over `base` (a
    /// scenario's model) for the parameters not named.
    fn apply_zoo(&mut self, base: Option<&LuGre>) -> Result<(), DynamicsError> {
        let Some(zoo) = self.zoo.take() else {
            return Ok(());
        };
        let mut values: Vec<(&str, Vec<f64>)> = Vec::new();
        if let Some(m) = base {
            let p = m.params();
            values.extend(p.named().map(|(q, v)| (q.name(), vec![v])));
            let (k, f) = crate::zoo::gms::elements_on_scale(p.sigma0, p.fs);
            values.extend([("stiffness", k), ("slip_force", f)]);
        }
        let zoo = zoo.over(&values)?;
        if let Some(friction) = ZooFriction::of(&zoo)? {
            self.model = user(Field::Model, friction.model);
            self.elastoplastic = friction.zba.or(self.elastoplastic);
            self.gms = friction.gms.or(self.gms.take());
        }
        Ok(())
    }

    /// The elasto-plastic friction law ([`super::FrictionLaw::ElastoPlastic`]) with the
    /// break-away displacement `zba` (m) on the model (given or the scenario's); checked
    /// against the model by [`Request::build`].
    pub fn with_elastoplastic(mut self, zba: f64) -> Self {
        self.elastoplastic = Some(zba);
        self
    }

    /// `M > 0` (kg).
    pub fn with_mass(mut self, mass: f64) -> Result<Self, DynamicsError> {
        self.mass = user(Field::Mass, positive(Field::Mass, mass)?);
        Ok(self)
    }

    /// A damper `c >= 0` (N s/m).
    pub fn with_damping(mut self, c: f64) -> Result<Self, DynamicsError> {
        self.damping = user(Field::Damping, non_negative(Field::Damping, c)?);
        Ok(self)
    }

    /// An applied force along the points `(t, F)`, linear in between, held after.
    pub fn with_force(mut self, t: Vec<f64>, f: Vec<f64>) -> Result<Self, DynamicsError> {
        let profile = Profile::new("force", t, f)?;
        self.set_force(Field::Force, Force::Profile(profile))?;
        Ok(self)
    }

    /// An applied force `F = r t` (the break-away, the first peak of the friction, is located).
    pub fn with_force_rate(mut self, rate: f64) -> Result<Self, DynamicsError> {
        finite(Field::ForceRate, rate)?;
        self.set_force(Field::ForceRate, Force::Ramp(rate))?;
        Ok(self)
    }

    /// An applied force measured at the times `t` (a history read from a file named `label`):
    /// linear between rows, held after; the run ends at its last time unless `t_end` is given.
    pub fn with_input(
        mut self,
        label: &str,
        t: Vec<f64>,
        f: Vec<f64>,
    ) -> Result<Self, DynamicsError> {
        let profile = Profile::new("input", t, f)?;
        self.set_force(Field::Input, Force::Profile(profile))?;
        self.input_label = Some(label.to_string());
        Ok(self)
    }

    /// A spring `k >= 0` (N/m) from the mass to a free end (`pull` or `end`).
    pub fn with_spring(mut self, k: f64) -> Result<Self, DynamicsError> {
        self.spring = user(Field::Spring, non_negative(Field::Spring, k)?);
        Ok(self)
    }

    /// The spring's free end moves at `speed` (m/s) from 0.
    pub fn with_pull(mut self, speed: f64) -> Result<Self, DynamicsError> {
        finite(Field::Pull, speed)?;
        self.set_end(Field::Pull, End::Pull(speed))?;
        Ok(self)
    }

    /// The spring's free end along the points `(t, y)`, linear in between, held after.
    pub fn with_end(mut self, t: Vec<f64>, y: Vec<f64>) -> Result<Self, DynamicsError> {
        let profile = Profile::new("end", t, y)?;
        self.set_end(Field::End, End::Profile(profile))?;
        Ok(self)
    }

    /// A PID controller on position with gains `Kp`, `Ki`, `Kv` (finite).
    pub fn with_pid(mut self, kp: f64, ki: f64, kv: f64) -> Result<Self, DynamicsError> {
        for value in [kp, ki, kv] {
            finite(Field::Pid, value)?;
        }
        self.pid = user(Field::Pid, [kp, ki, kv]);
        Ok(self)
    }

    /// The PID's set point: a constant (m).
    pub fn with_setpoint(mut self, x: f64) -> Result<Self, DynamicsError> {
        finite(Field::Setpoint, x)?;
        self.setpoint = user(Field::Setpoint, Steps::constant(x)?);
        Ok(self)
    }

    /// The PID's set point stepping to `x_i` at `t_i` (`x_0` from the start).
    pub fn with_setpoint_steps(mut self, t: Vec<f64>, x: Vec<f64>) -> Result<Self, DynamicsError> {
        self.setpoint = user(Field::Setpoint, Steps::new(t, x)?);
        Ok(self)
    }

    /// A prescribed velocity along the points `(t, v)` (the mass follows it).
    pub fn with_velocity(mut self, t: Vec<f64>, v: Vec<f64>) -> Result<Self, DynamicsError> {
        let profile = Profile::new("velocity", t, v)?;
        self.velocity = user(Field::Velocity, Velocity::Profile(profile));
        Ok(self)
    }

    /// The end of the run (s), finite and `> 0`.
    pub fn with_t_end(mut self, t_end: f64) -> Result<Self, DynamicsError> {
        self.t_end = user(Field::TEnd, positive(Field::TEnd, t_end)?);
        Ok(self)
    }

    /// Output at these times (strictly increasing, in `[0, t_end]`; at most
    /// [`Self::MAX_OUTPUTS`]).
    pub fn with_times(mut self, times: Vec<f64>) -> Result<Self, DynamicsError> {
        count(Field::Times, times.len() as u64, 1)?;
        self.set_output(Field::Times, Output::Times(times))?;
        Ok(self)
    }

    /// `n` evenly spaced output times over `[0, t_end]`, `2 <= n <=` [`Self::MAX_OUTPUTS`].
    pub fn with_samples(mut self, n: u64) -> Result<Self, DynamicsError> {
        count(Field::Samples, n, 2)?;
        self.set_output(Field::Samples, Output::Samples(n))?;
        Ok(self)
    }

    /// The relative tolerance, in `(0, 1)`.
    pub fn with_rtol(mut self, rtol: f64) -> Result<Self, DynamicsError> {
        if !(rtol > 0.0 && rtol < 1.0) {
            return Err(DynamicsError::BadValue {
                field: Field::Rtol,
                rule: "a number in (0, 1)",
                value: rtol,
            });
        }
        self.rtol = Some(rtol);
        Ok(self)
    }

    /// The absolute tolerance on displacements (m), `> 0`.
    pub fn with_atol(mut self, atol: f64) -> Result<Self, DynamicsError> {
        self.atol = Some(positive(Field::Atol, atol)?);
        Ok(self)
    }

    /// Whether the friction-displacement loops are reported.
    pub fn with_loops(mut self, loops: bool) -> Self {
        self.loops = Some(loops);
        self
    }

    /// The field `field` from numbers, for hosts that pass a request field by field (the C
    /// ABI, the MEX function): one number for `mass`, `damping`, `force_rate`, `spring`,
    /// `pull`, `setpoint`, `t_end`, `samples` (whole), `rtol`, `atol`, `loops` (0 or 1); three
    /// for `pid`; the list for `times`. Fields given as points take [`Self::with_points`];
    /// `scenario` and `model` have their own setters.
    ///
    /// # Errors
    /// [`DynamicsError::Count`] for the wrong number of values (or a `samples` that is not a
    /// whole number in range), [`DynamicsError::NotNumbers`] for a field that does not take
    /// numbers, and the field's own check.
    pub fn with_numbers(self, field: Field, values: &[f64]) -> Result<Self, DynamicsError> {
        if field == Field::Times {
            return self.with_times(values.to_vec());
        }
        let want = if field == Field::Pid { 3 } else { 1 };
        if values.len() != want {
            return Err(DynamicsError::Count {
                field,
                value: values.len() as u64,
                least: want as u64,
                most: want as u64,
            });
        }
        let x = values[0];
        match field {
            Field::Mass => self.with_mass(x),
            Field::Damping => self.with_damping(x),
            Field::ForceRate => self.with_force_rate(x),
            Field::Spring => self.with_spring(x),
            Field::Pull => self.with_pull(x),
            Field::Setpoint => self.with_setpoint(x),
            Field::TEnd => self.with_t_end(x),
            Field::Rtol => self.with_rtol(x),
            Field::Atol => self.with_atol(x),
            Field::Pid => self.with_pid(values[0], values[1], values[2]),
            Field::Samples => self.with_samples(whole(field, x)?),
            Field::Loops => match x {
                0.0 => Ok(self.with_loops(false)),
                1.0 => Ok(self.with_loops(true)),
                _ => Err(DynamicsError::BadValue {
                    field,
                    rule: "0 or 1",
                    value: x,
                }),
            },
            _ => Err(DynamicsError::NotNumbers { field }),
        }
    }

    /// The field `field` from points `(t_i, value_i)`: `force`, `input` (a measured force;
    /// `label` names it), `end`, `setpoint` (steps), `velocity`.
    ///
    /// # Errors
    /// [`DynamicsError::NotPoints`] for a field that does not take points, and the profile's
    /// checks.
    pub fn with_points(
        self,
        field: Field,
        t: Vec<f64>,
        values: Vec<f64>,
    ) -> Result<Self, DynamicsError> {
        match field {
            Field::Force => self.with_force(t, values),
            Field::Input => self.with_input("a measured force", t, values),
            Field::End => self.with_end(t, values),
            Field::Setpoint => self.with_setpoint_steps(t, values),
            Field::Velocity => self.with_velocity(t, values),
            _ => Err(DynamicsError::NotPoints { field }),
        }
    }

    fn set_force(&mut self, field: Field, force: Force) -> Result<(), DynamicsError> {
        conflict(&self.force, field)?;
        self.force = user(field, force);
        Ok(())
    }

    fn set_end(&mut self, field: Field, end: End) -> Result<(), DynamicsError> {
        conflict(&self.end, field)?;
        self.end = user(field, end);
        Ok(())
    }

    fn set_output(&mut self, field: Field, output: Output) -> Result<(), DynamicsError> {
        conflict(&self.output, field)?;
        self.output = user(field, output);
        Ok(())
    }

    /// The user's fields over the scenario's: each field the user gave replaces the
    /// scenario's.
    fn merged(&self) -> Result<Request, DynamicsError> {
        let Some(scenario) = self.scenario else {
            let mut out = self.clone();
            out.apply_zoo(None)?;
            return Ok(out);
        };
        // The break-away's ramp and end follow a rate given on top of it.
        let scenario = match (scenario, &self.force) {
            (
                Scenario::Breakaway { .. },
                Some(Given {
                    value: Force::Ramp(rate),
                    ..
                }),
            ) => Scenario::Breakaway {
                rate: positive(Field::ForceRate, *rate)?,
            },
            _ => scenario,
        };
        let mut out = scenario.preset()?;
        out.scenario = Some(scenario);
        let mine = self.clone();
        let user_drives = mine.drives_the_mass();
        out.model = mine.model.or(out.model);
        out.elastoplastic = mine.elastoplastic;
        let base = out.model.as_ref().map(|m| m.value.clone());
        out.zoo = mine.zoo;
        out.apply_zoo(base.as_ref())?;
        out.mass = mine.mass.or(out.mass);
        out.damping = mine.damping.or(out.damping);
        if mine.force.is_some() {
            out.force = mine.force;
            out.input_label = mine.input_label;
        }
        let user_velocity = mine.velocity.is_some();
        out.spring = mine.spring.or(out.spring);
        out.end = mine.end.or(out.end);
        out.pid = mine.pid.or(out.pid);
        out.setpoint = mine.setpoint.or(out.setpoint);
        // A drive given on top of a prescribed-velocity scenario replaces its velocity, and a
        // prescribed velocity replaces the scenario's drives.
        if scenario_is_kinematic(scenario) && user_drives {
            out.velocity = None;
        }
        if user_velocity {
            out.velocity = mine.velocity;
        }
        if user_velocity {
            out.force = out.force.filter(|f| f.by.is_some());
            out.spring = out.spring.filter(|s| s.by.is_some());
            out.end = out.end.filter(|e| e.by.is_some());
            out.pid = out.pid.filter(|p| p.by.is_some());
            out.setpoint = out.setpoint.filter(|p| p.by.is_some());
        }
        out.t_end = mine.t_end.or(out.t_end);
        out.output = mine.output;
        out.rtol = mine.rtol;
        out.atol = mine.atol;
        out.loops = mine.loops.or(out.loops);
        Ok(out)
    }

    /// Whether the user gave anything that acts on the mass as a force.
    fn drives_the_mass(&self) -> bool {
        self.force.is_some() || self.spring.is_some() || self.pid.is_some()
    }

    /// Checks the request as a whole and builds the system and the run.
    ///
    /// # Errors
    /// [`DynamicsError::Conflict`] for two fields that cannot hold together,
    /// [`DynamicsError::Needs`] for a field without the one it belongs to (`setpoint` without
    /// `pid`, `pull` without `spring`), [`DynamicsError::NoModel`], [`DynamicsError::NoDrive`],
    /// [`DynamicsError::NoEnd`], and the checks of the times.
    pub fn build(&self) -> Result<Plan, DynamicsError> {
        let r = self.merged()?;
        r.check_together()?;
        if !(r.drives_the_mass() || r.velocity.is_some()) {
            return Err(DynamicsError::NoDrive);
        }
        let model = r
            .model
            .as_ref()
            .ok_or(DynamicsError::NoModel)?
            .value
            .clone();
        let mass = r.mass.as_ref().map_or(Self::DEFAULT_MASS, |m| m.value);
        let mut system = System::new(model, mass)?;
        if let Some(zba) = r.elastoplastic {
            system = system.with_elastoplastic(zba)?;
        }
        // The scenario's line, then one per field the user gave.
        let mut description: Vec<String> = r
            .scenario
            .iter()
            .map(|sc| sc.description().to_string())
            .collect();
        let rate;
        (system, rate) = r.add_force(system, &mut description)?;
        let pull;
        (system, pull) = r.add_spring(system, &mut description)?;
        if let Some(c) = &r.damping {
            system = system.with_damping(c.value)?;
        }
        system = r.add_pid(system, &mut description)?;
        if let Some(v) = &r.velocity {
            system = system.with_velocity(v.value.clone())?;
            if v.by.is_some() {
                description.push("prescribed velocity profile".to_string());
            }
        }
        if description.is_empty() {
            return Err(DynamicsError::NoDrive);
        }
        if r.scenario.is_some() && description.len() > 1 {
            // The scenario's line, then what the user replaced of it.
            let replaced = description.split_off(1).join(", ");
            description.push(format!("replaced: {replaced}"));
        }
        let t_end = r.end_of_run()?;
        let tol = Tolerances::new(r.rtol.unwrap_or(Tolerances::DEFAULT_RTOL), r.atol)?;
        Ok(Plan {
            system,
            description: description.join("; "),
            t_end,
            times: r.output_times(t_end),
            tol,
            rate,
            pull,
            loops: r.loops.unwrap_or(false),
            gms: r.gms.clone(),
        })
    }

    /// The applied force, if any, on `system` (its line in `description` when the user gave
    /// it), and the ramp's rate.
    fn add_force(
        &self,
        system: System,
        description: &mut Vec<String>,
    ) -> Result<(System, Option<f64>), DynamicsError> {
        let Some(force) = &self.force else {
            return Ok((system, None));
        };
        let (profile, what, rate) = match &force.value {
            Force::Ramp(slope) => (
                Profile::ramp(0.0, *slope)?,
                format!("force ramp F = {} t N", crate::error::num(*slope)),
                Some(*slope),
            ),
            Force::Profile(p) => (
                p.clone(),
                match &self.input_label {
                    Some(label) => format!("applied force from {label}"),
                    None => "applied force profile".to_string(),
                },
                None,
            ),
        };
        if force.by.is_some() {
            description.push(what);
        }
        Ok((system.with_force(profile), rate))
    }

    /// The spring and its free end's motion, if any, on `system`, and the pull speed.
    fn add_spring(
        &self,
        mut system: System,
        description: &mut Vec<String>,
    ) -> Result<(System, Option<f64>), DynamicsError> {
        let Some(k) = &self.spring else {
            return Ok((system, None));
        };
        let end = self.end.as_ref().ok_or(DynamicsError::Needs {
            field: Field::Spring,
            needs: &[Field::Pull, Field::End],
            why: "where its free end goes",
        })?;
        let (end, pull) = match &end.value {
            End::Pull(v) => (Profile::ramp(0.0, *v)?, Some(*v)),
            End::Profile(p) => (p.clone(), None),
        };
        system = system.with_spring(k.value, end)?;
        if k.by.is_some() {
            description.push(format!("spring k = {} N/m", crate::error::num(k.value)));
        }
        if let Some(v) = pull {
            system = system.with_velocity_watch(v)?;
        }
        Ok((system, pull))
    }

    /// The PID position controller, if any, on `system`.
    fn add_pid(
        &self,
        system: System,
        description: &mut Vec<String>,
    ) -> Result<System, DynamicsError> {
        let Some(g) = &self.pid else {
            return Ok(system);
        };
        let setpoint = match &self.setpoint {
            Some(s) => s.value.clone(),
            None => Steps::constant(0.0)?,
        };
        let [kp, ki, kv] = g.value;
        if g.by.is_some() || self.setpoint.as_ref().is_some_and(|s| s.by.is_some()) {
            let xd = match &self.setpoint {
                Some(s) if s.value.steps().is_empty() => {
                    format!("{} m", crate::error::num(s.value.value(0.0)))
                }
                Some(_) => "steps".to_string(),
                None => "0 m".to_string(),
            };
            description.push(format!(
                "PID Kp = {}, Ki = {}, Kv = {}, xd = {xd}",
                crate::error::num(kp),
                crate::error::num(ki),
                crate::error::num(kv)
            ));
        }
        system.with_pid(Pid {
            kp,
            ki,
            kv,
            setpoint,
        })
    }

    /// The output times: those given, else `samples` (or the default count) evenly spaced
    /// over `[0, t_end]`.
    fn output_times(&self, t_end: f64) -> Vec<f64> {
        let samples = match &self.output {
            Some(Given {
                value: Output::Times(t),
                ..
            }) => return t.clone(),
            Some(Given {
                value: Output::Samples(n),
                ..
            }) => *n,
            None => Self::DEFAULT_SAMPLES,
        };
        crate::simulate::uniform_times(0.0, t_end, 1, (samples - 1) as usize)
    }

    /// The fields that cannot hold together, each error naming both.
    fn check_together(&self) -> Result<(), DynamicsError> {
        let by = |g: Option<Field>, f: Field| g.unwrap_or(f);
        if let Some(v) = &self.velocity {
            let velocity = by(v.by, Field::Velocity);
            for (given, field) in [
                (self.force.as_ref().map(|g| g.by), Field::Force),
                (self.spring.as_ref().map(|g| g.by), Field::Spring),
                (self.pid.as_ref().map(|g| g.by), Field::Pid),
            ] {
                if let Some(who) = given {
                    return Err(DynamicsError::Conflict {
                        first: by(who, field),
                        second: velocity,
                        why: "a prescribed velocity moves the mass whatever the forces",
                    });
                }
            }
        }
        if self.pid.is_none() {
            if let Some(s) = &self.setpoint {
                return Err(DynamicsError::Needs {
                    field: by(s.by, Field::Setpoint),
                    needs: &[Field::Pid],
                    why: "the set point is the controller's",
                });
            }
        }
        if self.spring.is_none() {
            if let Some(e) = &self.end {
                return Err(DynamicsError::Needs {
                    field: by(e.by, Field::Pull),
                    needs: &[Field::Spring],
                    why: "it moves the spring's free end",
                });
            }
        }
        Ok(())
    }

    /// `t_end`: the user's, else the last output time the user gave, else the measured
    /// input's last time, else the scenario's.
    fn end_of_run(&self) -> Result<f64, DynamicsError> {
        let user_end = self.t_end.as_ref().filter(|g| g.by.is_some());
        if let Some(g) = user_end {
            return Ok(g.value);
        }
        if let Some(Given {
            value: Output::Times(t),
            ..
        }) = &self.output
        {
            if let Some(&last) = t.last() {
                if last > 0.0 {
                    return Ok(last);
                }
            }
        }
        if self.input_label.is_some() {
            if let Some(Given {
                value: Force::Profile(p),
                ..
            }) = &self.force
            {
                let last = p.last_time();
                return positive(Field::Input, last).map_err(|_| DynamicsError::NoEnd {
                    why: "the input's last time is not after 0",
                });
            }
        }
        self.t_end
            .as_ref()
            .map(|g| g.value)
            .ok_or(DynamicsError::NoEnd {
                why: "no scenario, output times or input sets it",
            })
    }

    /// A scenario's value of the model (replaced silently by the user's).
    pub(super) fn preset_model(mut self, model: LuGre) -> Self {
        self.model = preset(model);
        self
    }

    /// A scenario's applied force profile.
    pub(super) fn preset_force(mut self, force: Profile) -> Self {
        self.force = preset(Force::Profile(force));
        self
    }

    /// A scenario's force ramp `r t`.
    pub(super) fn preset_ramp(mut self, rate: f64) -> Self {
        self.force = preset(Force::Ramp(rate));
        self
    }

    /// A scenario's spring `k` pulled at `speed`.
    pub(super) fn preset_spring(mut self, k: f64, speed: f64) -> Self {
        self.spring = preset(k);
        self.end = preset(End::Pull(speed));
        self
    }

    /// A scenario's PID gains and constant set point.
    pub(super) fn preset_pid(mut self, gains: [f64; 3], setpoint: Steps) -> Self {
        self.pid = preset(gains);
        self.setpoint = preset(setpoint);
        self
    }

    /// A scenario's prescribed velocity.
    pub(super) fn preset_velocity(mut self, velocity: Velocity) -> Self {
        self.velocity = preset(velocity);
        self
    }

    /// A scenario's end of the run and whether it reports the loops.
    pub(super) fn preset_run(mut self, t_end: f64, loops: bool) -> Self {
        self.t_end = preset(t_end);
        self.loops = Some(loops);
        self
    }
}

fn scenario_is_kinematic(scenario: Scenario) -> bool {
    matches!(scenario, Scenario::Lag { .. })
}

/// A system ready to solve, with its run and what to report ([`Request::build`]).
#[derive(Debug, Clone)]
pub struct Plan {
    pub system: System,
    /// What drives the mass, in one line.
    pub description: String,
    pub t_end: f64,
    /// The output times.
    pub times: Vec<f64>,
    pub tol: Tolerances,
    /// The force rate of a ramp (its break-away is located).
    pub rate: Option<f64>,
    /// The pull speed of a spring (its upward crossings are the slip onsets).
    pub pull: Option<f64>,
    /// Whether the friction-displacement loops are computed.
    pub loops: bool,
    /// GMS friction (the Maxwell-slip model at finite rate) in place of the system's model
    /// ([`Request::with_zoo`]).
    pub gms: Option<crate::zoo::MaxwellSlip>,
}

/// What a run gives: the motion, the break-away of a ramp, the friction loops. With GMS
/// friction the motion's `z` is the elements' force over their stiffness, `sum F_i / K`, and
/// each loop's stored energy is the elements' (`sum F_i^2 / (2 k_i)`).
#[derive(Debug, Clone)]
pub struct Outcome {
    pub motion: Motion,
    pub breakaway: Option<Breakaway>,
    pub loops: Vec<FrictionLoop>,
}

impl Outcome {
    /// The slip onsets: the times of the upward crossings of the watched velocity.
    pub fn slip_onsets(&self) -> Vec<f64> {
        self.motion
            .events
            .iter()
            .filter(|e| e.kind == super::EventKind::VelocityUp)
            .map(|e| e.t)
            .collect()
    }
}

impl Plan {
    /// Solves the run.
    ///
    /// # Errors
    /// The solver's ([`DynamicsError`]), and those of the loops' rainflow count and loop
    /// computation.
    pub fn run(&self) -> Result<Outcome, Error> {
        if let Some(gms) = &self.gms {
            let run =
                super::gms::GmsRun::new(&self.system, gms.gms(), self.tol, self.rate.is_some());
            let (motion, breakaway) = run.solve(self.t_end, &self.times)?;
            let loops = if self.loops {
                gms_loops(&self.system, gms, self.t_end, self.tol)?
            } else {
                Vec::new()
            };
            return Ok(Outcome {
                motion,
                breakaway,
                loops,
            });
        }
        let motion = self.motion()?;
        let breakaway = match self.rate {
            Some(_) => self.system.breakaway(self.t_end, self.tol)?,
            None => None,
        };
        let loops = if self.loops {
            friction_loops(&self.system, self.t_end, self.tol)?
        } else {
            Vec::new()
        };
        Ok(Outcome {
            motion,
            breakaway,
            loops,
        })
    }

    /// The motion at the output times alone, for a caller that reports nothing else: a ramp's
    /// break-away is a second integration, and [`Plan::run`] would locate it for nothing.
    ///
    /// # Errors
    /// The solver's.
    pub fn motion(&self) -> Result<Motion, DynamicsError> {
        if let Some(gms) = &self.gms {
            let run = super::gms::GmsRun::new(&self.system, gms.gms(), self.tol, false);
            return Ok(run.solve(self.t_end, &self.times)?.0);
        }
        self.system.solve(self.t_end, &self.times, self.tol)
    }
}

/// The friction loops of `system` with the GMS friction of `ms` over `[0, t_end]`, each beside
/// the Maxwell-slip model's slow loop on its turning points.
fn gms_loops(
    system: &System,
    ms: &crate::zoo::MaxwellSlip,
    t_end: f64,
    tol: Tolerances,
) -> Result<Vec<FrictionLoop>, Error> {
    let trace = super::gms::GmsRun::new(system, ms.gms(), tol, false).trace(t_end)?;
    loops_of(&trace, |input| Ok(ms.loops(input)?.work_per_period()))
}

/// What a finite-rate model of the zoo is as the friction of the mass: the LuGre model of
/// its parameters (GMS: the stand-in of [`gms_lugre`]), the elasto-plastic law's `zba`, or
/// GMS friction in place of the model.
#[derive(Debug, Clone)]
pub(crate) struct ZooFriction {
    pub model: LuGre,
    pub zba: Option<f64>,
    pub gms: Option<crate::zoo::MaxwellSlip>,
}

impl ZooFriction {
    /// `None` for a model without a finite-rate form.
    pub(crate) fn of(zoo: &crate::zoo::ZooModel) -> Result<Option<Self>, DynamicsError> {
        Ok(match zoo.kind() {
            crate::zoo::ZooKind::ElastoPlastic(ep) => Some(Self {
                model: LuGre::from_params(ep.lugre_params())?,
                zba: Some(ep.zba()),
                gms: None,
            }),
            crate::zoo::ZooKind::MaxwellSlip(ms) => Some(Self {
                model: LuGre::from_params(gms_lugre(ms))?,
                zba: None,
                gms: Some(ms.clone()),
            }),
            _ => None,
        })
    }

    /// [`DynamicsError::NoFiniteRate`] unless `zoo` has a finite-rate form.
    pub(crate) fn check(zoo: &crate::zoo::ZooModel) -> Result<(), DynamicsError> {
        if !zoo.spec().finite_rate {
            return Err(DynamicsError::NoFiniteRate {
                model: zoo.spec().name,
                takes: crate::zoo::dynamics_model_names(),
            });
        }
        Ok(())
    }
}

/// The LuGre parameters standing in for the GMS model `ms` (stiffness `sum k_i`, static force
/// `sum f_i`, its Stribeck curve and damping).
fn gms_lugre(ms: &crate::zoo::MaxwellSlip) -> crate::model::LuGreParams {
    let r = ms.rate();
    crate::model::LuGreParams {
        sigma0: ms.stiffness().iter().sum(),
        sigma1: r.sigma1,
        sigma2: r.sigma2,
        fc: r.fc,
        fs: ms.slip_force().iter().sum(),
        vs: r.vs,
        beta: r.beta,
    }
}

fn preset<T>(value: T) -> Option<Given<T>> {
    Some(Given { value, by: None })
}

fn user<T>(field: Field, value: T) -> Option<Given<T>> {
    Some(Given {
        value,
        by: Some(field),
    })
}

/// A second user value for a slot one already holds.
fn conflict<T>(slot: &Option<Given<T>>, field: Field) -> Result<(), DynamicsError> {
    match slot {
        Some(Given {
            by: Some(first), ..
        }) => Err(DynamicsError::Conflict {
            first: *first,
            second: field,
            why: if *first == field {
                "it was given twice"
            } else {
                "they set the same thing"
            },
        }),
        _ => Ok(()),
    }
}

fn finite(field: Field, value: f64) -> Result<f64, DynamicsError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(DynamicsError::BadValue {
            field,
            rule: "a finite number",
            value,
        })
    }
}

fn positive(field: Field, value: f64) -> Result<f64, DynamicsError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(DynamicsError::BadValue {
            field,
            rule: "a finite number > 0",
            value,
        })
    }
}

fn non_negative(field: Field, value: f64) -> Result<f64, DynamicsError> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(DynamicsError::BadValue {
            field,
            rule: "a finite number >= 0",
            value,
        })
    }
}

/// A whole number `>= 0` given as a float.
fn whole(field: Field, x: f64) -> Result<u64, DynamicsError> {
    // 2^64 is the first float past u64::MAX.
    if x >= 0.0 && x.fract() == 0.0 && x < 18_446_744_073_709_551_616.0 {
        Ok(x as u64)
    } else {
        // The words of `count`'s error for a count out of range (the one field that takes a
        // count is `samples`): one message for -1, 1.5 and 10^12 in every front end.
        const _: () = assert!(Request::MAX_OUTPUTS == 10_000_000);
        Err(DynamicsError::BadValue {
            field,
            rule: "a whole number from 2 to 10000000",
            value: x,
        })
    }
}

/// An output count in `[least, MAX_OUTPUTS]`.
fn count(field: Field, n: u64, least: u64) -> Result<(), DynamicsError> {
    if n < least || n > Request::MAX_OUTPUTS {
        return Err(DynamicsError::Count {
            field,
            value: n,
            least,
            most: Request::MAX_OUTPUTS,
        });
    }
    Ok(())
}
