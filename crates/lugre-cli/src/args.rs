//! The flags several commands share, each defined once and flattened into the commands' own
//! flags: the model (`--model`, `--sigma0`, ...) and the periodic input (`--turning-points`,
//! `--bimodal`, `--input`), each with what it builds, and the outputs (`--json`, `--csv`,
//! `--plot`).

use anyhow::{anyhow, bail, Result};
use clap::{Arg, ArgMatches, Args, Command, ValueEnum};
use lugre::error::NormalForceError;
use lugre::fit::Family;
use lugre::model::named;
/// Which parameters a command uses (the core's, for the commands that import it from here).
pub(crate) use lugre::model::named::Needed;
use lugre::model::Parameter;
use lugre::{Dahl, LuGre, LuGreParams, RateIndependent};
use lugre_io::{Delimiter, ReadOptions, Role, Spec};
use std::path::{Path, PathBuf};

use crate::fmt::{capitalized, sig};
use crate::io::outputs::Files;
use crate::numbers::{parse_list, Real};

/// The model `--model` names: LuGre, Dahl, or a model of the core's zoo table (by its index
/// in [`lugre::zoo::MODELS`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ModelKind {
    Lugre,
    Dahl,
    Zoo(usize),
}

impl ModelKind {
    /// Every model's name, in the order `--help` lists them (the core's names).
    fn names() -> Vec<&'static str> {
        Family::ALL
            .iter()
            .map(|f| f.name())
            .chain(lugre::zoo::MODELS.iter().map(|m| m.name))
            .collect()
    }

    /// The model called `name` (one of [`Self::names`]).
    fn from_name(name: &str) -> ModelKind {
        match name {
            n if n == Family::LuGre.name() => ModelKind::Lugre,
            n if n == Family::Dahl.name() => ModelKind::Dahl,
            n => ModelKind::Zoo(
                lugre::zoo::MODELS
                    .iter()
                    .position(|m| m.name == n)
                    .unwrap_or(0),
            ),
        }
    }

    /// The zoo's entry of a model of the zoo.
    pub(crate) fn zoo(self) -> Option<&'static lugre::zoo::ZooModelSpec> {
        match self {
            ModelKind::Zoo(i) => lugre::zoo::MODELS.get(i),
            _ => None,
        }
    }

    /// The name `--model` takes.
    pub(crate) fn name(self) -> &'static str {
        match self {
            ModelKind::Lugre => Family::LuGre.name(),
            ModelKind::Dahl => Family::Dahl.name(),
            ModelKind::Zoo(i) => lugre::zoo::MODELS[i].name,
        }
    }
}

/// `--model`'s parser: the core's model names, listed in `--help` and in the error.
fn model_parser() -> impl clap::builder::TypedValueParser<Value = ModelKind> {
    use clap::builder::TypedValueParser;
    clap::builder::PossibleValuesParser::new(ModelKind::names())
        .map(|name: String| ModelKind::from_name(&name))
}

/// A model of the zoo with the values its flags give, by name.
pub(crate) type ZooGiven = (
    &'static lugre::zoo::ZooModelSpec,
    Vec<(&'static str, Vec<f64>)>,
);

/// Model flags shared by every command. Defaults: the paper's Examples 2-3.
/// `--columns` and `--scale`: which column of a data file holds what, and the factors that
/// bring its values to SI units and lugre's sign convention.
#[derive(Args, Debug, Clone, Default)]
pub(crate) struct DataArgs {
    /// Which column holds what, by header name (units in brackets ignored, any case) or
    /// 1-based number: t=Time,u=Position,F=Friction or t=1,u=3,F=4 (other columns ignored;
    /// each role once, each column in one role);
    /// v=NAME a velocity record; N=NAME a normal force (fit and simulate: the model is then the
    /// friction coefficient's, its parameters per newton).
    #[arg(long, value_name = "ROLE=COLUMN,...", help_heading = "Data file")]
    pub(crate) columns: Option<String>,
    /// Factors applied to the columns as read (any factor, sign included), e.g. u=1e-3,F=-1e-6:
    /// a file in mm and uN with the opposite sign convention, read in m and N.
    #[arg(
        long,
        value_name = "ROLE=FACTOR,...",
        allow_hyphen_values = true,
        help_heading = "Data file"
    )]
    pub(crate) scale: Option<String>,
    /// How the fields are separated (default: found from the first line that is not a comment).
    #[arg(long, value_enum, help_heading = "Data file")]
    pub(crate) delimiter: Option<DelimiterArg>,
}

/// The core's normal-force error for the file `path`, naming the row (1-based, as the reader
/// counts the data rows).
pub(crate) fn normal_force_error(path: &Path, e: NormalForceError) -> anyhow::Error {
    match e {
        NormalForceError::NotPositive { index, .. } => {
            anyhow::anyhow!("{}: row {}: {e}", path.display(), index + 1)
        }
        e => anyhow::anyhow!("{}: {e}", path.display()),
    }
}

/// `--interpolate`'s values: how samples are read between them.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Interpolate {
    /// A piecewise-linear motion (exact as given).
    Linear,
    /// Samples of a smooth motion: the C1 shape-preserving cubic through them.
    Cubic,
}

/// `--delimiter`'s values.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum DelimiterArg {
    Comma,
    Semicolon,
    Tab,
    /// Runs of spaces (or tabs).
    Space,
}

impl DataArgs {
    /// Whether `--columns` names the column of `role` (`v`, `N`: roles that change what a
    /// command reads). False for a `--columns` that cannot be parsed: [`DataArgs::options`]
    /// then says why.
    pub(crate) fn selects(&self, role: Role) -> bool {
        self.columns.as_deref().is_some_and(|text| {
            ReadOptions::default()
                .parse_columns(text)
                .is_ok_and(|o| o.selects(&role))
        })
    }

    /// The reader's options; `roles` are the columns the command reads (`t` always allowed).
    pub(crate) fn options(&self, roles: &[Role]) -> Result<ReadOptions> {
        let mut options = ReadOptions::default();
        if let Some(text) = &self.columns {
            options = options.parse_columns(text)?;
        }
        if let Some(text) = &self.scale {
            options = options.parse_scale(text)?;
        }
        if let Some(d) = self.delimiter {
            options = options.with_delimiter(match d {
                DelimiterArg::Comma => Delimiter::Comma,
                DelimiterArg::Semicolon => Delimiter::Semicolon,
                DelimiterArg::Tab => Delimiter::Tab,
                DelimiterArg::Space => Delimiter::Spaces,
            });
        }
        options.check_roles(roles)?;
        Ok(options)
    }
}

impl ModelKind {
    /// The model's label in text and its parameters, from the core's table.
    fn family(self) -> (&'static str, &'static [Parameter]) {
        match self {
            ModelKind::Lugre => (Family::LuGre.label(), &Parameter::LUGRE),
            ModelKind::Dahl => (Family::Dahl.label(), &Parameter::DAHL),
            ModelKind::Zoo(i) => (lugre::zoo::MODELS[i].label, &[]),
        }
    }
}

/// The model's flags: `--model`, one flag per parameter of the core's table
/// ([`ParameterFlags`]) and `--preset`, under the heading "Model".
#[derive(Args, Debug, Clone)]
pub(crate) struct ModelArgs {
    #[arg(
        long,
        value_parser = model_parser(),
        default_value = "lugre",
        help_heading = MODEL_HEADING,
        help = model_help()
    )]
    pub(crate) model: ModelKind,
    // `--sigma0 ... --rho`, generated from the table.
    #[command(flatten)]
    pub(crate) values: ParameterFlags,
    // The zoo's own parameters (`--stiffness ...`), generated from its table.
    #[command(flatten)]
    pub(crate) zoo: crate::zoo_args::ZooFlags,
    #[arg(long, value_enum, help_heading = MODEL_HEADING, help = preset_help())]
    pub(crate) preset: Option<Preset>,
}

/// The heading of the model's flags in `--help`.
const MODEL_HEADING: &str = "Model";

/// `--model`'s help: each model with its parameters (from the table) and equations.
fn model_help() -> String {
    let list = |kind: ModelKind| {
        let (label, parameters) = kind.family();
        let symbols: Vec<&str> = parameters.iter().map(|p| p.symbol()).collect();
        format!("{label} ({})", symbols.join(", "))
    };
    format!(
        "Model: {} with g(v) = Fc + (Fs - Fc) exp(-|v/vs|^beta), f(v) = sigma2 v; or {} with w' = rho (u' - |u'| w), y = Fc w; or, for `lugre loop`, `lugre cycles` and `lugre simulate`, {}",
        list(ModelKind::Lugre),
        list(ModelKind::Dahl),
        crate::zoo_args::models_help()
    )
}

/// `--preset`'s help: the preset's values, from the core.
fn preset_help() -> String {
    let values: Vec<String> = LuGreParams::canudas_de_wit_1995()
        .named()
        .iter()
        .map(|(p, v)| format!("{} = {}", p.symbol(), sig(*v, 10)))
        .collect();
    format!(
        "LuGre defaults from a published parameter set (the parameters' flags override them): canudas1995 is Table I of Canudas de Wit et al. (1995): {}",
        values.join(", ")
    )
}

/// The flags of the models' parameters (`--sigma0`, ..., `--rho`): one per parameter of the
/// core's table ([`Parameter::ALL`]), named after it, its help (what it is, its domain, unit,
/// model and default) written from it, and read back by name. A parameter added to the table
/// is a flag here without a change.
#[derive(Debug, Clone, Default)]
pub(crate) struct ParameterFlags {
    given: Vec<(Parameter, f64)>,
}

impl ParameterFlags {
    /// The value given for `p`'s flag.
    pub(crate) fn get(&self, p: Parameter) -> Option<f64> {
        self.given.iter().find(|(q, _)| *q == p).map(|&(_, v)| v)
    }

    /// The flag of `p`: `--NAME VALUE`, any value starting with '-' taken as a number.
    fn arg(p: Parameter) -> Arg {
        Arg::new(p.name())
            .long(p.name())
            .value_name(p.name().to_uppercase())
            .allow_hyphen_values(true)
            .value_parser(Real)
            .help(Self::help(p))
            .help_heading(MODEL_HEADING)
    }

    /// `Bristle stiffness: sigma0 > 0 [N/m] (LuGre; default 1)`.
    fn help(p: Parameter) -> String {
        let models: Vec<&str> = [ModelKind::Lugre, ModelKind::Dahl]
            .into_iter()
            .map(ModelKind::family)
            .filter(|(_, parameters)| parameters.contains(&p))
            .map(|(label, _)| label)
            .collect();
        let unit = match p.unit() {
            "1" => String::new(),
            unit => format!(" [{unit}]"),
        };
        let capitalized = capitalized(p.description());
        format!(
            "{capitalized}: {} {}{unit} ({}; default {}){}",
            p.symbol(),
            p.domain().condition(),
            models.join(" and "),
            sig(p.default_value(), 10),
            crate::zoo_args::shared_help(p.name())
        )
    }
}

impl clap::FromArgMatches for ParameterFlags {
    fn from_arg_matches(matches: &ArgMatches) -> Result<Self, clap::Error> {
        let mut flags = Self::default();
        flags.update_from_arg_matches(matches)?;
        Ok(flags)
    }

    fn update_from_arg_matches(&mut self, matches: &ArgMatches) -> Result<(), clap::Error> {
        for p in Parameter::ALL {
            let value = matches
                .try_get_one::<f64>(p.name())
                .map_err(|e| clap::Error::raw(clap::error::ErrorKind::ArgumentConflict, e))?;
            if let Some(&v) = value {
                self.given.retain(|(q, _)| *q != p);
                self.given.push((p, v));
            }
        }
        Ok(())
    }
}

impl Args for ParameterFlags {
    fn augment_args(cmd: Command) -> Command {
        Parameter::ALL
            .into_iter()
            .fold(cmd, |cmd, p| cmd.arg(Self::arg(p)))
    }

    fn augment_args_for_update(cmd: Command) -> Command {
        Self::augment_args(cmd)
    }
}

/// A published LuGre parameter set: the core's [`lugre::model::Preset`], by its name.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Preset {
    Canudas1995,
}

impl Preset {
    /// The core's preset (one name for every front end: a test checks the flag's values).
    fn core(self) -> lugre::model::Preset {
        match self {
            Preset::Canudas1995 => lugre::model::Preset::Canudas1995,
        }
    }

    fn params(self) -> LuGreParams {
        self.core().params()
    }

    fn name(self) -> &'static str {
        self.core().name()
    }
}

/// A validated model as chosen on the command line.
#[derive(Debug, Clone)]
pub(crate) enum Model {
    LuGre(LuGre),
    Dahl(Dahl),
}

/// The model chosen on the command line, with where each value came from (for
/// [`ModelChoice::describe`]).
#[derive(Debug, Clone)]
pub(crate) struct ModelChoice {
    pub(crate) model: Model,
    kind: ModelKind,
    preset: Option<Preset>,
    /// The parameters left at the table's default.
    defaults: Vec<Parameter>,
}

impl ModelArgs {
    /// The value given for a parameter's flag (`--sigma0` for [`Parameter::Sigma0`], ...).
    pub(crate) fn given(&self, p: Parameter) -> Option<f64> {
        self.values.get(p)
    }

    /// Whether the flags name anything of a model (a preset, `--model` or a parameter).
    pub(crate) fn names_any(&self) -> bool {
        self.preset.is_some()
            || self.model != ModelKind::Lugre
            || Parameter::ALL.iter().any(|&p| self.given(p).is_some())
            || self.zoo.any()
    }

    /// For a physical system: every parameter in `needed` of the chosen model has a value from
    /// a flag or the preset, except those whose default means absence
    /// ([`Parameter::default_is_absence`]); else the error names the missing flags.
    pub(crate) fn check_named(&self, needed: Needed) -> Result<()> {
        if self.preset.is_some() {
            return Ok(());
        }
        named::check_named(self.model.family().1, needed, |p| self.given(p).is_some())
            .map_err(|e| anyhow!(e.render(|p| format!("--{}", p.name()), "--preset canudas1995")))
    }

    /// The given value, else the preset's, else the parameter's default (`None`).
    fn named_value(&self, p: Parameter) -> Option<f64> {
        self.given(p)
            .or_else(|| self.preset.and_then(|s| s.params().get(p)))
    }

    /// The model of the zoo the flags name, or `None` for LuGre and Dahl
    /// ([`crate::zoo_args::build`]).
    pub(crate) fn build_zoo(&self) -> Result<Option<lugre::zoo::ZooModel>> {
        let Some(spec) = self.model.zoo() else {
            return Ok(None);
        };
        crate::zoo_args::build(spec, self.preset.is_some(), &self.zoo, &self.classic()).map(Some)
    }

    /// The LuGre and Dahl flags given, by parameter.
    fn classic(&self) -> Vec<(Parameter, f64)> {
        Parameter::ALL
            .into_iter()
            .filter_map(|p| self.given(p).map(|v| (p, v)))
            .collect()
    }

    /// The model of the zoo the flags name with the values its flags give, by name (the
    /// parameters not given are absent: a fit starts those from the data), or `None` for
    /// LuGre and Dahl.
    pub(crate) fn zoo_given(&self) -> Result<Option<ZooGiven>> {
        let Some(spec) = self.model.zoo() else {
            return Ok(None);
        };
        crate::zoo_args::given_values(spec, self.preset.is_some(), &self.zoo, &self.classic())
            .map(|given| Some((spec, given)))
    }

    pub(crate) fn build(&self) -> Result<ModelChoice> {
        if let Some(spec) = self.model.zoo() {
            bail!(
                "--model {}: this command takes {} (the models of the zoo work with `lugre loop`, `lugre cycles`, `lugre simulate`, `lugre fit` and, those with a finite-rate form, `lugre dynamics`)",
                spec.name,
                Family::ALL.map(|f| f.name()).join(" or ")
            );
        }
        if let Some(flag) = self.zoo.first_given() {
            bail!(
                "{flag} is a parameter of {}: add that --model",
                crate::zoo_args::owners(&flag)
            );
        }
        let (_, parameters) = self.model.family();
        let names: Vec<String> = parameters.iter().map(|p| format!("--{p}")).collect();
        if self.model == ModelKind::Dahl && self.preset.is_some() {
            bail!(
                "--preset is a LuGre parameter set; the Dahl model takes {}",
                names.join(" and ")
            );
        }
        // A flag of a parameter the chosen model does not have.
        if let Some(q) = Parameter::ALL
            .into_iter()
            .find(|q| !parameters.contains(q) && self.given(*q).is_some())
        {
            match self.model {
                ModelKind::Dahl => bail!(
                    "--{q} is a LuGre parameter; the Dahl model takes {}",
                    names.join(" and ")
                ),
                _ => bail!("--{q} is the Dahl model's parameter (add --model dahl)"),
            }
        }
        let value = |p: Parameter| self.named_value(p).unwrap_or(p.default_value());
        let model = match self.model {
            ModelKind::Lugre => {
                let mut p = LuGreParams::default();
                for &q in parameters {
                    p.set(q, value(q));
                }
                Model::LuGre(LuGre::from_params(p)?)
            }
            _ => Model::Dahl(Dahl::new(value(Parameter::Rho), value(Parameter::Fc))?),
        };
        Ok(ModelChoice {
            model,
            kind: self.model,
            preset: self.preset,
            defaults: parameters
                .iter()
                .copied()
                .filter(|&p| self.named_value(p).is_none())
                .collect(),
        })
    }
}

impl ModelChoice {
    pub(crate) fn rate_independent(&self) -> RateIndependent {
        match &self.model {
            Model::LuGre(m) => m.rate_independent(),
            Model::Dahl(m) => m.rate_independent(),
        }
    }

    /// The equivalent LuGre model (Dahl maps exactly).
    pub(crate) fn lugre(&self) -> LuGre {
        match &self.model {
            Model::LuGre(m) => m.clone(),
            Model::Dahl(m) => m.to_lugre(),
        }
    }

    /// The model's parameters with their values, in the table's order.
    fn values(&self) -> Vec<(Parameter, f64)> {
        match &self.model {
            Model::LuGre(m) => m.params().named().to_vec(),
            Model::Dahl(m) => m.named().to_vec(),
        }
    }

    /// The model as a JSON object: `kind` and its parameters.
    pub(crate) fn to_json(&self) -> serde_json::Value {
        let mut j = serde_json::json!({ "kind": self.kind.name() });
        for (q, value) in self.values() {
            j[q.name()] = value.into();
        }
        j
    }

    /// One line naming the model, its values with the defaults marked, and which of them act
    /// in a computation that uses `needed` ([`model_line`]).
    pub(crate) fn describe(&self, needed: Needed) -> String {
        let (label, _) = self.kind.family();
        let origin = self.preset.map(|p| format!("preset {}", p.name()));
        let values: Vec<(Parameter, f64, bool)> = self
            .values()
            .into_iter()
            .map(|(p, v)| (p, v, self.defaults.contains(&p)))
            .collect();
        let mut line = model_line(
            label,
            origin.as_deref(),
            &values,
            named::acting(self.kind.family().1, needed),
        );
        if let Model::Dahl(m) = &self.model {
            line += &format!(
                "; LuGre with sigma0 = rho Fc = {}, g = Fc",
                sig(m.rho() * m.fc(), 10)
            );
        }
        line
    }
}

/// The one line every text output names its model with: `LuGre: sigma0 = 6, sigma1 = 1*, ...,
/// beta = 1* (* default)`, the label followed by where the values come from (`origin`, e.g. a
/// preset), each value marked `*` where it is the table's default; where only `acting` of
/// the parameters act (the rate-independent loop: `sigma0` and `Fs`), it says so.
pub(crate) fn model_line(
    label: &str,
    origin: Option<&str>,
    values: &[(Parameter, f64, bool)],
    acting: &[Parameter],
) -> String {
    let items: Vec<String> = values
        .iter()
        .map(|&(p, v, default)| {
            format!(
                "{} = {}{}",
                p.symbol(),
                sig(v, 10),
                if default { "*" } else { "" }
            )
        })
        .collect();
    let mut line = match origin {
        Some(origin) => format!("{label} ({origin}): {}", items.join(", ")),
        None => format!("{label}: {}", items.join(", ")),
    };
    if values.iter().any(|&(_, _, default)| default) {
        line += " (* default)";
    }
    if values.iter().any(|(p, _, _)| !acting.contains(p)) {
        let names: Vec<&str> = acting.iter().map(|p| p.symbol()).collect();
        line += &format!(
            "; only {} act on the rate-independent loop",
            names.join(" and ")
        );
    }
    line
}

/// Periodic input flags shared by `loop` and `simulate`: exactly one of them.
#[derive(Args, Debug, Clone)]
pub(crate) struct PeriodicInputArgs {
    /// One period as its turning points, e.g. 0,1,0.2,1.5 (negative numbers work, with or
    /// without '=').
    #[arg(
        long,
        value_name = "U0,U1,...",
        allow_hyphen_values = true,
        help_heading = "Input"
    )]
    pub(crate) turning_points: Option<String>,
    /// The paper's bimodal input (Definition 1), visited umin1 -> umax1 -> umin2 -> umax2.
    #[arg(
        long,
        value_name = "UMIN1,UMIN2,UMAX1,UMAX2",
        allow_hyphen_values = true,
        help_heading = "Input"
    )]
    pub(crate) bimodal: Option<String>,
    /// One period of samples from a data file: its column u (u, x, position or displacement;
    /// other columns ignored) and t if it has one (see the README's "Data files").
    #[arg(long, value_name = "FILE.csv", help_heading = "Input")]
    pub(crate) input: Option<PathBuf>,
}

/// The periodic input as given.
#[derive(Debug, Clone)]
pub(crate) enum PeriodicInput {
    TurningPoints(lugre::TurningPoints),
    Bimodal(lugre::Bimodal),
    /// One period of samples, reduced to its turning points.
    Samples(lugre::TurningPoints),
}

impl PeriodicInputArgs {
    /// The flags given, by name.
    pub(crate) fn given(&self) -> Vec<&'static str> {
        let mut v = Vec::new();
        if self.turning_points.is_some() {
            v.push("--turning-points");
        }
        if self.bimodal.is_some() {
            v.push("--bimodal");
        }
        if self.input.is_some() {
            v.push("--input");
        }
        v
    }

    pub(crate) fn build(&self) -> Result<PeriodicInput> {
        let given = self.given();
        if given.len() > 1 {
            bail!("give one input, not {}", given.join(" and "));
        }
        if let Some(text) = &self.turning_points {
            let u = parse_list("--turning-points", text)?;
            return Ok(PeriodicInput::TurningPoints(
                lugre::TurningPoints::new(&u)
                    .map_err(|e| anyhow::anyhow!("--turning-points: {e}"))?,
            ));
        }
        if let Some(text) = &self.bimodal {
            let v = parse_list("--bimodal", text)?;
            if v.len() != 4 {
                bail!(
                    "--bimodal takes 4 numbers UMIN1,UMIN2,UMAX1,UMAX2, got {}",
                    v.len()
                );
            }
            return Ok(PeriodicInput::Bimodal(
                lugre::Bimodal::new(v[0], v[1], v[2], v[3])
                    .map_err(|e| anyhow::anyhow!("--bimodal: {e}"))?,
            ));
        }
        if let Some(path) = &self.input {
            let mut table =
                lugre_io::read_file(path, &Spec::new([Role::U]), ReadOptions::default())?;
            let u = table.take(&Role::U).unwrap_or_default();
            let turning_points = match table.take(&Role::T) {
                Some(t) => lugre::TurningPoints::from_samples(&t, &u),
                None => lugre::TurningPoints::new(&u),
            }
            .map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
            return Ok(PeriodicInput::Samples(turning_points));
        }
        bail!("no input: give --turning-points U0,U1,..., --bimodal UMIN1,UMIN2,UMAX1,UMAX2 or --input FILE.csv")
    }
}

impl PeriodicInput {
    pub(crate) fn turning_points(&self) -> lugre::TurningPoints {
        match self {
            PeriodicInput::TurningPoints(tp) => tp.clone(),
            PeriodicInput::Bimodal(b) => b.turning_points(),
            PeriodicInput::Samples(turning_points) => turning_points.clone(),
        }
    }
}

/// `--json` and `--csv FILE`, the outputs besides the table. What the CSV holds is each
/// command's to say: its arguments set `--csv`'s help (and `--json`'s, when it prints more than
/// "one JSON document") with `#[command(mut_arg(...))]`.
#[derive(Args, Debug, Clone)]
pub(crate) struct OutputArgs {
    /// Print one JSON document instead of the table.
    #[arg(long, help_heading = "Output")]
    pub(crate) json: bool,
    #[arg(long, value_name = "FILE.csv", help_heading = "Output")]
    pub(crate) csv: Option<PathBuf>,
}

/// Checks a run's files against the output policy (`io::outputs`) before anything is read or
/// computed: `--input` (when the command reads one), and the outputs `--csv` and `--plot` (when
/// the command has it).
pub(crate) fn check_files(
    input: Option<&Path>,
    output: &OutputArgs,
    plot: Option<&PlotArgs>,
) -> Result<()> {
    Files::new()
        .input("--input", input)
        .output("--csv", output.csv.as_deref())
        .output("--plot", plot.and_then(|p| p.path.as_deref()))
        .check()
}

/// `--plot FILE`, a figure (SVG or PNG, by the file's extension). Each command says what it
/// draws, with `#[command(mut_arg("plot", ...))]`.
#[derive(Args, Debug, Clone)]
pub(crate) struct PlotArgs {
    #[arg(
        id = "plot",
        long = "plot",
        value_name = "FILE.svg|FILE.png",
        help_heading = "Output"
    )]
    pub(crate) path: Option<PathBuf>,
    /// Units on the figure's axes, e.g. t=s,u=mm,F=N (default: those of the input file's
    /// header, for columns not scaled; a preset's SI where the command has no file). Labels
    /// only: the values are not converted.
    #[arg(
        long,
        value_name = "ROLE=UNIT,...",
        help_heading = "Output",
        requires = "plot"
    )]
    pub(crate) units: Option<String>,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_preset_flag_takes_the_cores_names() {
        let flag: Vec<String> = Preset::value_variants()
            .iter()
            .filter_map(|p| p.to_possible_value())
            .map(|v| v.get_name().to_string())
            .collect();
        let core: Vec<&str> = lugre::model::Preset::ALL.iter().map(|p| p.name()).collect();
        assert_eq!(flag, core);
        for p in Preset::value_variants() {
            assert_eq!(p.to_possible_value().unwrap().get_name(), p.name());
        }
    }
}
