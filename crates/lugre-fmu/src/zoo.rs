//! `lugre-NAME.fmu`, one for each model of the core's zoo table ([`lugre::zoo::MODELS`]): the
//! model as a rate-independent hysteresis element in co-simulation, displacement in, force,
//! work and dissipation out. Nothing here names a model: the instantiation token names the
//! table's entry, the parameters are the entry's by name and position, and the model is built
//! by [`ZooModel::new`] from the values by name.
//!
//! ```text
//! inputs  u [m], der(u) [m/s]      u(t) = u + der(u) (t - t_u),  t_u the time u was set
//! outputs F [N], work W = integral F du [J], dissipation D [J], from the start
//! ```
//!
//! The element starts at rest at `u` at the end of initialization. `fmi3DoStep(t, h)` moves
//! the element from where it stands to `u(t)` and on to `u(t + h)`: one monotone segment each
//! (an input linear between communication points), by the model's exact segment map
//! ([`lugre::zoo::ZooElement`]), exact at any step size. A host that sets `u` at every
//! communication point and no `der(u)` holds `u` over each step (the force after a step is the
//! force at the `u` set before it).
//!
//! A model with a finite-rate form ([`ZooModelSpec::finite_rate`]) is stepped at finite rate
//! instead ([`lugre::zoo::ZooStepper`]): `fmi3DoStep(t, h)` moves the input from where the
//! element stands to `u(t + h)` at the constant velocity of that change over `h`, the exact
//! interval map of `ZooModel::simulate`; `F` after the step is the force moving at that
//! velocity (the value at the last sample of `simulate` over the input up to `t + h`).
//!
//! **Element arrays** are FMI 3.0 arrays whose one dimension is the structural parameter
//! `elements` (a `UInt64`, start: the default arrays' length). A host keeps the default count,
//! or sets `elements` in configuration mode (`fmi3EnterConfigurationMode` from the instantiated
//! state) and then every element array with that many values; an array not set for a new count
//! is an error at the end of initialization, naming it.

use lugre::error::num;
use lugre::zoo::{Shape, ZooElement, ZooModel, ZooModelSpec, ZooStepper, MAX_STATES};

use crate::Unit;

/// The token of the FMU of `spec`: `{lugre-zoo/NAME}`.
pub fn token(spec: &ZooModelSpec) -> String {
    format!("{{lugre-zoo/{}}}", spec.name)
}

/// The model of the table a token names.
pub(crate) fn model_of(token: &[u8]) -> Option<&'static ZooModelSpec> {
    let name = std::str::from_utf8(token).ok()?;
    let name = name.strip_prefix("{lugre-zoo/")?.strip_suffix('}')?;
    lugre::zoo::MODELS.iter().find(|m| m.name == name)
}

/// Value references, the same for every model; the table's parameters follow from
/// [`crate::vr::PARAMETERS`] on, in the table's order.
pub mod vr {
    pub const U: u32 = 1;
    pub const DER_U: u32 = 2;
    pub const F: u32 = 3;
    pub const WORK: u32 = 4;
    pub const DISSIPATION: u32 = 5;
    /// The structural parameter: the length of every element array (models that have any).
    pub const ELEMENTS: u32 = 6;
}

/// The variables before the parameters: (name, value reference).
pub const VARIABLES: [(&str, u32); 7] = [
    ("time", crate::vr::TIME),
    ("u", vr::U),
    ("der(u)", vr::DER_U),
    ("F", vr::F),
    ("work", vr::WORK),
    ("dissipation", vr::DISSIPATION),
    ("elements", vr::ELEMENTS),
];

/// The default length of the element arrays of `spec` (`None`: it has none).
pub fn default_elements(spec: &ZooModelSpec) -> Option<usize> {
    spec.parameters
        .iter()
        .find(|p| p.shape == Shape::Elements)
        .map(|p| p.default.len())
}

/// The table's parameters of one instance (the zoo FMUs' and the mass FMUs' of the table),
/// at the value references from [`crate::vr::PARAMETERS`] on, with the structural parameter
/// `elements` at [`vr::ELEMENTS`].
pub(crate) struct Params {
    pub(crate) spec: &'static ZooModelSpec,
    /// The length of the element arrays.
    elements: usize,
    /// Each parameter's values in the table's order; `None`: an element array not set since
    /// `elements` changed.
    values: Vec<Option<Vec<f64>>>,
}

impl Params {
    pub(crate) fn new(spec: &'static ZooModelSpec) -> Self {
        Self {
            spec,
            elements: default_elements(spec).unwrap_or(1),
            values: spec
                .parameters
                .iter()
                .map(|p| Some(p.default.to_vec()))
                .collect(),
        }
    }

    /// The index in the table of the parameter at `r`.
    fn parameter(&self, r: u32) -> Option<usize> {
        let i = usize::try_from(r.checked_sub(crate::vr::PARAMETERS)?).ok()?;
        (i < self.spec.parameters.len()).then_some(i)
    }

    /// The name of the parameter at `r` (`elements` too, where the model has arrays).
    pub(crate) fn name_of(&self, r: u32) -> Option<&'static str> {
        if let Some(i) = self.parameter(r) {
            return Some(self.spec.parameters[i].name);
        }
        (r == vr::ELEMENTS && self.structural()).then_some("elements")
    }

    /// The name of the variable at `r`: a parameter's, else the one `variables` (name, value
    /// reference) give it (`elements` only where the model has arrays).
    pub(crate) fn name_among(&self, variables: &[(&'static str, u32)], r: u32) -> &'static str {
        if let Some(name) = self.name_of(r) {
            return name;
        }
        variables
            .iter()
            .find(|(_, v)| *v == r && (r != vr::ELEMENTS || self.structural()))
            .map_or("an unknown variable", |(name, _)| name)
    }

    /// The number of values at `r`: an element array's length, else 1.
    pub(crate) fn size(&self, r: u32) -> usize {
        match self.parameter(r) {
            Some(i) if self.spec.parameters[i].shape == Shape::Elements => self.elements,
            _ => 1,
        }
    }

    /// The model of the parameters as they stand (the core's checks and messages).
    pub(crate) fn model(&self) -> Result<ZooModel, String> {
        let mut given = Vec::with_capacity(self.values.len());
        for (p, v) in self.spec.parameters.iter().zip(&self.values) {
            let Some(v) = v else {
                return Err(format!(
                    "{} has no values for elements = {}: set its {} values before the end of initialization",
                    p.name, self.elements, self.elements
                ));
            };
            given.push((p.name, v.as_slice()));
        }
        ZooModel::new(self.spec.name, &given).map_err(|e| e.to_string())
    }

    /// The values of the parameter at `r` into `out`; `None`: `r` is no parameter's.
    pub(crate) fn get(&self, r: u32, out: &mut [f64]) -> Option<Result<(), String>> {
        let i = self.parameter(r)?;
        let Some(v) = &self.values[i] else {
            return Some(Err(format!(
                "{} has no values for elements = {} yet",
                self.spec.parameters[i].name, self.elements
            )));
        };
        out.copy_from_slice(v);
        Some(Ok(()))
    }

    /// Sets the parameter at `r` (`fixed`: after the end of initialization, refused); `None`:
    /// `r` is no parameter's.
    pub(crate) fn set(
        &mut self,
        r: u32,
        values: &[f64],
        fixed: bool,
    ) -> Option<Result<(), String>> {
        let i = self.parameter(r)?;
        if fixed {
            return Some(Err(fixed_message(self.spec.parameters[i].name)));
        }
        self.values[i] = Some(values.to_vec());
        Some(Ok(()))
    }

    pub(crate) fn structural(&self) -> bool {
        default_elements(self.spec).is_some()
    }

    pub(crate) fn get_count(&self, r: u32) -> Result<u64, String> {
        match r {
            vr::ELEMENTS if self.structural() => Ok(self.elements as u64),
            _ => Err(format!("no UInt64 variable has value reference {r}")),
        }
    }

    pub(crate) fn set_count(&mut self, r: u32, value: u64) -> Result<(), String> {
        if !(r == vr::ELEMENTS && self.structural()) {
            return Err(format!("no UInt64 variable has value reference {r}"));
        }
        let n = usize::try_from(value)
            .ok()
            .filter(|n| (1..=MAX_STATES).contains(n))
            .ok_or_else(|| format!("elements must be in [1, {MAX_STATES}], got {value}"))?;
        self.elements = n;
        for (p, v) in self.spec.parameters.iter().zip(&mut self.values) {
            if p.shape == Shape::Elements && v.as_ref().is_some_and(|v| v.len() != n) {
                *v = (p.default.len() == n).then(|| p.default.to_vec());
            }
        }
        Ok(())
    }
}

/// The message for a fixed parameter set after the end of initialization.
pub(crate) fn fixed_message(name: &str) -> String {
    format!("{name} is a fixed parameter: set it before the end of initialization")
}

/// One instance of a zoo FMU.
pub(crate) struct Zoo {
    params: Params,
    time: f64,
    u: f64,
    du: f64,
    /// When `u` was last set.
    t_u: f64,
    element: Option<Driven>,
}

/// The model driven by the steps: by its exact segment map, or at finite rate.
enum Driven {
    Slow(ZooElement),
    Rate(ZooStepper),
}

impl Driven {
    /// `model` at rest at `u`: at finite rate where the table's entry has a finite-rate form.
    fn at_rest(model: &ZooModel, u: f64) -> Result<Self, String> {
        let driven = match model.spec().finite_rate {
            true => model.stepper(u).map(Driven::Rate),
            false => model.element(u).map(Driven::Slow),
        };
        driven.map_err(|e| e.to_string())
    }

    fn force(&self) -> f64 {
        match self {
            Driven::Slow(e) => e.force(),
            Driven::Rate(s) => s.force(),
        }
    }

    fn work(&self) -> f64 {
        match self {
            Driven::Slow(e) => e.work(),
            Driven::Rate(s) => s.work(),
        }
    }

    fn dissipation(&self) -> f64 {
        match self {
            Driven::Slow(e) => e.dissipation(),
            Driven::Rate(s) => s.dissipation(),
        }
    }
}

impl Zoo {
    pub(crate) fn new(spec: &'static ZooModelSpec) -> Self {
        Self {
            params: Params::new(spec),
            time: 0.0,
            u: 0.0,
            du: 0.0,
            t_u: 0.0,
            element: None,
        }
    }

    /// The input at time `t`.
    fn input_at(&self, t: f64) -> f64 {
        self.u + self.du * (t - self.t_u)
    }

    /// The element (after initialization), or the one the parameters give at rest at `u`.
    fn with_element<T>(&self, f: impl FnOnce(&Driven) -> T) -> Result<T, String> {
        match &self.element {
            Some(e) => Ok(f(e)),
            None => Ok(f(&Driven::at_rest(&self.params.model()?, self.u)?)),
        }
    }
}

/// The [`Unit`] methods an instance with the table's parameters in its field `params`
/// ([`Params`]), its other variables in `VARIABLES` and its time in `time` has alike.
macro_rules! table_parameters {
    () => {
        fn name_of(&self, r: u32) -> &'static str {
            self.params.name_among(&VARIABLES, r)
        }

        fn size(&self, r: u32) -> usize {
            self.params.size(r)
        }

        fn get(&self, r: u32) -> Result<f64, String> {
            let mut out = [0.0];
            self.get_values(r, &mut out)?;
            Ok(out[0])
        }

        fn set(&mut self, r: u32, value: f64) -> Result<(), String> {
            self.set_values(r, &[value])
        }

        fn structural(&self) -> bool {
            self.params.structural()
        }

        fn get_count(&self, r: u32) -> Result<u64, String> {
            self.params.get_count(r)
        }

        fn set_count(&mut self, r: u32, value: u64) -> Result<(), String> {
            self.params.set_count(r, value)
        }

        fn set_time(&mut self, t: f64) {
            self.time = t;
        }

        fn time(&self) -> f64 {
            self.time
        }
    };
}
pub(crate) use table_parameters;

impl Unit for Zoo {
    table_parameters!();

    fn get_values(&self, r: u32, out: &mut [f64]) -> Result<(), String> {
        if let Some(done) = self.params.get(r, out) {
            return done;
        }
        out[0] = match r {
            crate::vr::TIME => self.time,
            vr::U => self.u,
            vr::DER_U => self.du,
            vr::F => self.with_element(Driven::force)?,
            vr::WORK => self.with_element(Driven::work)?,
            vr::DISSIPATION => self.with_element(Driven::dissipation)?,
            _ => return Err(format!("no Float64 variable has value reference {r}")),
        };
        Ok(())
    }

    fn set_values(&mut self, r: u32, values: &[f64]) -> Result<(), String> {
        if let Some(done) = self.params.set(r, values, self.element.is_some()) {
            return done;
        }
        match r {
            vr::U => (self.u, self.t_u) = (values[0], self.time),
            vr::DER_U => {
                // The input goes on from where it is now, with the new slope.
                (self.u, self.t_u) = (self.input_at(self.time), self.time);
                self.du = values[0];
            }
            _ => return Err(not_settable(self.name_of(r), r)),
        }
        Ok(())
    }

    fn initialize(&mut self, start: f64, _tolerance: Option<f64>) -> Result<(), String> {
        let model = self.params.model()?;
        (self.time, self.t_u) = (start, start);
        self.element = Some(Driven::at_rest(&model, self.u)?);
        Ok(())
    }

    fn do_step(&mut self, t: f64, h: f64) -> Result<(), String> {
        let (now, end) = (self.input_at(t), self.input_at(t + h));
        if !end.is_finite() {
            return Err(format!(
                "the displacement u + der(u) (t - t_u) at the step's end is not finite (u = {}, der(u) = {}, t - t_u = {})",
                num(self.u),
                num(self.du),
                num(t + h - self.t_u)
            ));
        }
        let Some(e) = self.element.as_mut() else {
            return Err("fmi3DoStep before the end of initialization".into());
        };
        let stepped = match e {
            Driven::Slow(e) => e.advance(now).and_then(|()| e.advance(end)),
            // At finite rate, from where it stands to the step's end over the step.
            Driven::Rate(s) => s.step(end, h),
        };
        stepped.map_err(|err| err.to_string())?;
        self.time = t + h;
        Ok(())
    }
}

/// The message for a set of the variable `name` at `r` that cannot be set.
pub(crate) fn not_settable(name: &str, r: u32) -> String {
    match name {
        "an unknown variable" => format!("no settable Float64 variable has value reference {r}"),
        name => format!("{name} cannot be set (it is computed by the FMU)"),
    }
}

/// The SI base-unit exponents (kg, m, s) of the units the zoo FMUs use, in FMI's spelling.
const UNITS: [(&str, [i32; 3]); 11] = [
    ("s", [0, 0, 1]),
    ("kg", [1, 0, 0]),
    ("m", [0, 1, 0]),
    ("m/s", [0, 1, -1]),
    ("N", [1, 1, -2]),
    ("J", [1, 2, -2]),
    ("N/m", [1, 0, -2]),
    ("N.s/m", [1, 0, -1]),
    ("N/s", [1, 1, -3]),
    ("1/m", [0, -1, 0]),
    ("1", [0, 0, 0]),
];

/// A unit of the table in FMI's spelling (a product is written with `.`: `N s/m` is `N.s/m`).
pub fn fmi_unit(unit: &str) -> String {
    unit.trim().replace(' ', ".")
}

/// `text` as an XML attribute value.
pub(crate) fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('"', "&quot;")
}

/// Numbers as an FMI start value: space-separated, each the shortest round trip.
fn start(values: &[f64]) -> String {
    let text: Vec<String> = values.iter().map(f64::to_string).collect();
    text.join(" ")
}

/// The `<UnitDefinitions>` of the units `used`, in [`UNITS`]' order.
pub(crate) fn unit_definitions(used: &[String]) -> Result<String, String> {
    if let Some(unknown) = used.iter().find(|u| UNITS.iter().all(|(n, _)| n != u)) {
        return Err(format!(
            "the unit {unknown:?} has no SI base units in lugre-fmu's zoo::UNITS: add it there"
        ));
    }
    let mut out = String::from("  <UnitDefinitions>\n");
    for (name, exponents) in UNITS.iter().filter(|(n, _)| used.iter().any(|u| u == n)) {
        let base: Vec<String> = ["kg", "m", "s"]
            .iter()
            .zip(exponents)
            .filter(|(_, e)| **e != 0)
            .map(|(b, e)| format!(r#"{b}="{e}""#))
            .collect();
        let base = match base.is_empty() {
            true => "<BaseUnit/>".to_string(),
            false => format!("<BaseUnit {}/>", base.join(" ")),
        };
        out.push_str(&format!("    <Unit name=\"{name}\">{base}</Unit>\n"));
    }
    out.push_str("  </UnitDefinitions>\n");
    Ok(out)
}

/// The variables of the table's parameters of `spec` (and `elements`, if it has arrays).
pub(crate) fn parameter_variables(spec: &ZooModelSpec) -> String {
    let mut out = String::new();
    if let Some(n) = default_elements(spec) {
        out.push_str(&format!(
            "    <UInt64 name=\"elements\" valueReference=\"{}\" causality=\"structuralParameter\" variability=\"fixed\" start=\"{n}\" description=\"number of elements: the length of every element array (set in configuration mode)\"/>\n",
            vr::ELEMENTS
        ));
    }
    for (i, p) in spec.parameters.iter().enumerate() {
        let r = crate::vr::PARAMETERS + i as u32;
        let head = format!(
            r#"<Float64 name="{}" valueReference="{r}" causality="parameter" variability="fixed" start="{}" unit="{}" description="{}""#,
            p.name,
            start(p.default),
            fmi_unit(p.unit),
            escape(&format!("{} ({})", p.description, p.domain.text()))
        );
        match p.shape {
            Shape::Scalar => out.push_str(&format!("    {head}/>\n")),
            Shape::Elements => out.push_str(&format!(
                "    {head}>\n      <Dimension valueReference=\"{}\"/>\n    </Float64>\n",
                vr::ELEMENTS
            )),
        }
    }
    out
}

/// The `modelDescription.xml` of the FMU of `spec`, all of it from the table (what
/// `scripts/write-tables.sh` writes to `fmu/zoo/NAME.xml`).
///
/// # Errors
/// A unit of the table that this module's `UNITS` (SI base units of each) lacks.
pub fn model_description(spec: &ZooModelSpec) -> Result<String, String> {
    let mut used: Vec<String> = ["s", "m", "m/s", "N", "J"].map(String::from).to_vec();
    used.extend(spec.parameters.iter().map(|p| fmi_unit(p.unit)));
    let name = spec.name;
    let stepping = match spec.finite_rate {
        true => "at finite rate: each communication step moves u to its value at the step's end at constant velocity, by the exact map of an interval of constant velocity",
        false => "rate-independent: each communication step moves u along monotone segments by the exact segment map",
    };
    let description = format!(
        "{}: hysteresis element, displacement u in, force F, work and dissipation out; {stepping}. {} ({})",
        spec.label, spec.equations, spec.reference
    );
    let head = head(
        &format!("lugre-{name}"),
        &description,
        &token(spec),
        &identifier(spec),
        &unit_definitions(&used)?,
        "",
    );
    Ok(format!(
        r#"{head}  <ModelVariables>
    <Float64 name="time" valueReference="{time}" causality="independent" variability="continuous" unit="s"/>
    <Float64 name="u" valueReference="{u}" causality="input" variability="continuous" start="0" unit="m" description="displacement (the element starts at rest at its value at the end of initialization)"/>
    <Float64 name="der(u)" valueReference="{du}" causality="input" variability="continuous" start="0" unit="m/s" derivative="{u}" description="du/dt over the coming steps: u(t) = u + der(u) (t - t_u), t_u the time u was set (0: u held)"/>
    <Float64 name="F" valueReference="{f}" causality="output" variability="continuous" initial="calculated" unit="N" description="force"/>
    <Float64 name="work" valueReference="{w}" causality="output" variability="continuous" initial="calculated" unit="J" description="work integral of F du from the start"/>
    <Float64 name="dissipation" valueReference="{d}" causality="output" variability="continuous" initial="calculated" unit="J" description="energy dissipated from the start (the work minus the change of the stored energy)"/>
{parameters}{tail}"#,
        tail = tail(&[vr::F, vr::WORK, vr::DISSIPATION]),
        time = crate::vr::TIME,
        u = vr::U,
        du = vr::DER_U,
        f = vr::F,
        w = vr::WORK,
        d = vr::DISSIPATION,
        parameters = parameter_variables(spec),
    ))
}

/// The head of a description written from the table, up to its `<ModelVariables>`: a
/// co-simulation FMU named `model_name` with `units` (the `<UnitDefinitions>`) and `experiment`
/// (more attributes of the `<DefaultExperiment>`, each with a space before it).
pub(crate) fn head(
    model_name: &str,
    description: &str,
    token: &str,
    identifier: &str,
    units: &str,
    experiment: &str,
) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<!-- Written from the core's zoo table (lugre::zoo::MODELS) by scripts/write-tables.sh: do not edit. -->
<fmiModelDescription
  fmiVersion="3.0"
  modelName="{model_name}"
  description="{description}"
  generationTool="lugre (scripts/write-tables.sh)"
  instantiationToken="{token}"
  variableNamingConvention="structured">
  <CoSimulation modelIdentifier="{identifier}" canHandleVariableCommunicationStepSize="true" canGetAndSetFMUState="false" canSerializeFMUState="false"/>
{units}  <DefaultExperiment startTime="0" stopTime="1" stepSize="0.001"{experiment}/>
"#,
        description = escape(description),
        token = escape(token),
    )
}

/// The end of a description written from the table, from `</ModelVariables>` on: the
/// `outputs` (value references), each an initial unknown too.
pub(crate) fn tail(outputs: &[u32]) -> String {
    let mut out = String::from("  </ModelVariables>\n  <ModelStructure>\n");
    for kind in ["Output", "InitialUnknown"] {
        for r in outputs {
            out.push_str(&format!("    <{kind} valueReference=\"{r}\"/>\n"));
        }
    }
    out.push_str("  </ModelStructure>\n</fmiModelDescription>\n");
    out
}

/// The model identifier of the FMU of `spec` (its library's name): `lugre_NAME`, `-` as `_`.
pub fn identifier(spec: &ZooModelSpec) -> String {
    format!("lugre_{}", spec.name.replace('-', "_"))
}
