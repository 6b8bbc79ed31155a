//! The flags several commands share, each defined once and flattened into the commands' own
//! flags: the model (`--model`, `--sigma0`, ...) and the periodic input (`--turning-points`,
//! `--bimodal`, `--input`), each with what it builds, and the outputs (`--json`, `--csv`,
//! `--plot`).

use anyhow::{bail, Result};
use clap::{Args, ValueEnum};
use lugre::model::Parameter;
use lugre::{Dahl, LuGre, LuGreParams, RateIndependent};
use lugre_io::{Delimiter, ReadOptions, Role, Spec};
use std::path::{Path, PathBuf};

use crate::io::outputs::Files;

use crate::numbers::{parse_list, Real};

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ModelKind {
    Lugre,
    Dahl,
}

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

/// Which parameters a command needs named ([`ModelArgs::check_named`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Needed {
    /// Every parameter (a simulation of a physical system).
    All,
    /// Those of the rate-independent loop (energies along `y*`).
    RateIndependent,
}

#[derive(Args, Debug, Clone)]
pub(crate) struct ModelArgs {
    /// Model: LuGre (sigma0, sigma1, sigma2, Fc, Fs, vs, beta) or Dahl (rho, Fc).
    #[arg(long, value_enum, default_value = "lugre", help_heading = "Model")]
    pub(crate) model: ModelKind,
    /// LuGre bristle stiffness sigma0 > 0 [N/m] (default 1).
    #[arg(long, allow_hyphen_values = true, value_parser = Real, help_heading = "Model")]
    pub(crate) sigma0: Option<f64>,
    /// LuGre micro-damping sigma1 >= 0 [N s/m] (default 1).
    #[arg(long, allow_hyphen_values = true, value_parser = Real, help_heading = "Model")]
    pub(crate) sigma1: Option<f64>,
    /// LuGre viscous coefficient sigma2 >= 0 [N s/m], f(v) = sigma2 v (default 0).
    #[arg(long, allow_hyphen_values = true, value_parser = Real, help_heading = "Model")]
    pub(crate) sigma2: Option<f64>,
    /// Coulomb force Fc > 0 [N] (LuGre and Dahl; default 1).
    #[arg(long, allow_hyphen_values = true, value_parser = Real, help_heading = "Model")]
    pub(crate) fc: Option<f64>,
    /// LuGre stiction force Fs > 0 [N]; g(0) = Fs (default 2).
    #[arg(long, allow_hyphen_values = true, value_parser = Real, help_heading = "Model")]
    pub(crate) fs: Option<f64>,
    /// LuGre Stribeck velocity vs > 0 [m/s] (default 1).
    #[arg(long, allow_hyphen_values = true, value_parser = Real, help_heading = "Model")]
    pub(crate) vs: Option<f64>,
    /// LuGre Stribeck exponent beta > 0: g(v) = Fc + (Fs - Fc) exp(-|v/vs|^beta) (default 1).
    #[arg(long, allow_hyphen_values = true, value_parser = Real, help_heading = "Model")]
    pub(crate) beta: Option<f64>,
    /// Dahl parameter rho > 0 [1/m] (default 1): w' = rho (u' - |u'| w), y = Fc w.
    #[arg(long, allow_hyphen_values = true, value_parser = Real, help_heading = "Model")]
    pub(crate) rho: Option<f64>,
    /// LuGre defaults from a published parameter set (the flags above override them):
    /// canudas1995 is Table I of Canudas de Wit et al. (1995): sigma0 = 1e5, sigma1 =
    /// sqrt(1e5), sigma2 = 0.4, Fc = 1, Fs = 1.5, vs = 1e-3, beta = 2.
    #[arg(long, value_enum, help_heading = "Model")]
    pub(crate) preset: Option<Preset>,
}

/// A published LuGre parameter set.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Preset {
    Canudas1995,
}

/// A validated model as chosen on the command line.
#[derive(Debug, Clone)]
pub(crate) enum ModelChoice {
    LuGre(LuGre),
    Dahl(Dahl),
}

impl ModelArgs {
    /// The value given for a parameter's flag (`--sigma0` for [`Parameter::Sigma0`], ...).
    pub(crate) fn given(&self, p: Parameter) -> Option<f64> {
        match p {
            Parameter::Sigma0 => self.sigma0,
            Parameter::Sigma1 => self.sigma1,
            Parameter::Sigma2 => self.sigma2,
            Parameter::Fc => self.fc,
            Parameter::Fs => self.fs,
            Parameter::Vs => self.vs,
            Parameter::Beta => self.beta,
            Parameter::Rho => self.rho,
            _ => None,
        }
    }

    /// Whether the flags name anything of a model (a preset, `--model` or a parameter).
    pub(crate) fn names_any(&self) -> bool {
        self.preset.is_some()
            || self.model != ModelKind::Lugre
            || Parameter::LUGRE
                .iter()
                .chain(&[Parameter::Rho])
                .any(|&p| self.given(p).is_some())
    }

    /// For a physical system: every parameter in `needed` of the chosen model has a value from
    /// a flag or the preset, except those whose default means absence
    /// ([`Parameter::default_is_absence`]); else the error names the missing flags.
    pub(crate) fn check_named(&self, needed: Needed) -> Result<()> {
        if self.preset.is_some() {
            return Ok(());
        }
        let parameters: &[Parameter] = match (self.model, needed) {
            (ModelKind::Lugre, Needed::All) => &Parameter::LUGRE,
            (ModelKind::Lugre, Needed::RateIndependent) => &Parameter::LUGRE_RATE_INDEPENDENT,
            (ModelKind::Dahl, _) => &Parameter::DAHL,
        };
        let missing: Vec<String> = parameters
            .iter()
            .filter(|p| self.given(**p).is_none() && !p.default_is_absence())
            .map(|p| format!("--{}", p.name()))
            .collect();
        if !missing.is_empty() {
            let preset = if self.model == ModelKind::Lugre {
                ", or --preset canudas1995"
            } else {
                ""
            };
            bail!(
                "the model is only partly named: give {} too{preset} (forces and energies of a measured or physical system are not computed from the dimensionless defaults)",
                missing.join(", ")
            );
        }
        Ok(())
    }

    /// The given value, else the preset's, else the parameter's default.
    fn value(&self, p: Parameter) -> f64 {
        let preset = match self.preset {
            Some(Preset::Canudas1995) => LuGreParams::canudas_de_wit_1995().get(p),
            None => None,
        };
        self.given(p).or(preset).unwrap_or(p.default_value())
    }

    pub(crate) fn build(&self) -> Result<ModelChoice> {
        match self.model {
            ModelKind::Lugre => {
                if self.rho.is_some() {
                    bail!("--rho is the Dahl model's parameter (add --model dahl)");
                }
                let mut p = LuGreParams::default();
                for q in Parameter::LUGRE {
                    p.set(q, self.value(q));
                }
                Ok(ModelChoice::LuGre(LuGre::from_params(p)?))
            }
            ModelKind::Dahl => {
                if self.preset.is_some() {
                    bail!("--preset is a LuGre parameter set; the Dahl model takes --rho and --fc");
                }
                let lugre_only = Parameter::LUGRE
                    .into_iter()
                    .filter(|q| !Parameter::DAHL.contains(q));
                if let Some(q) = lugre_only.into_iter().find(|&q| self.given(q).is_some()) {
                    bail!(
                        "--{} is a LuGre parameter; the Dahl model takes --rho and --fc",
                        q.name()
                    );
                }
                Ok(ModelChoice::Dahl(Dahl::new(
                    self.value(Parameter::Rho),
                    self.value(Parameter::Fc),
                )?))
            }
        }
    }
}

impl ModelChoice {
    pub(crate) fn rate_independent(&self) -> RateIndependent {
        match self {
            ModelChoice::LuGre(m) => m.rate_independent(),
            ModelChoice::Dahl(m) => m.rate_independent(),
        }
    }

    /// The equivalent LuGre model (Dahl maps exactly).
    pub(crate) fn lugre(&self) -> LuGre {
        match self {
            ModelChoice::LuGre(m) => m.clone(),
            ModelChoice::Dahl(m) => m.to_lugre(),
        }
    }

    /// The model as a JSON object: `kind` and its parameters.
    pub(crate) fn to_json(&self) -> serde_json::Value {
        match self {
            ModelChoice::LuGre(m) => {
                let mut j = serde_json::json!({ "kind": "lugre" });
                for (q, value) in m.params().named() {
                    j[q.name()] = value.into();
                }
                j
            }
            ModelChoice::Dahl(m) => serde_json::json!({
                "kind": "dahl", "rho": m.rho(), "fc": m.fc(),
            }),
        }
    }

    /// One line describing the model.
    pub(crate) fn describe(&self) -> String {
        use crate::fmt::sig;
        match self {
            ModelChoice::LuGre(m) => {
                let p = m.params();
                format!(
                    "LuGre: sigma0 = {}, sigma1 = {}, sigma2 = {}, Fc = {}, Fs = {}, vs = {}, beta = {}",
                    sig(p.sigma0, 10), sig(p.sigma1, 10), sig(p.sigma2, 10), sig(p.fc, 10),
                    sig(p.fs, 10), sig(p.vs, 10), sig(p.beta, 10)
                )
            }
            ModelChoice::Dahl(m) => format!(
                "Dahl: rho = {}, Fc = {} (LuGre with sigma0 = rho Fc = {}, g = Fc)",
                sig(m.rho(), 10),
                sig(m.fc(), 10),
                sig(m.rho() * m.fc(), 10)
            ),
        }
    }
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
}
