//! The flags of the zoo's parameters (`--stiffness`, `--slip-force`, ...), generated from the
//! core's zoo table ([`lugre::zoo::MODELS`]): one flag per parameter name (shared by the models
//! that have it), taking one number or a comma-separated list; a parameter whose name is a
//! LuGre or Dahl parameter (`--sigma0`, `--rho`) uses that flag. A model added to the table
//! has its flags here without a change.

use anyhow::{bail, Result};
use clap::{Arg, ArgMatches, Args, Command};
use lugre::model::Parameter;
use lugre::zoo::{Shape, ZooModel, ZooModelSpec, ZooParameter, MODELS};

use crate::fmt::sig;
use crate::numbers::parse_list;

/// The heading of the model's flags in `--help` (the LuGre flags' heading).
const HEADING: &str = "Model";

/// The values given to the zoo's flags, as written (parsed once the model is known).
#[derive(Debug, Clone, Default)]
pub(crate) struct ZooFlags {
    given: Vec<(&'static str, String)>,
}

/// The flag of a parameter name: `--slip-force` for `slip_force`.
pub(crate) fn flag(name: &str) -> String {
    format!("--{}", name.replace('_', "-"))
}

/// The zoo's parameters with a flag of their own (not a LuGre or Dahl flag), each name once.
fn own_parameters() -> Vec<&'static ZooParameter> {
    let mut out: Vec<&'static ZooParameter> = Vec::new();
    for p in MODELS.iter().flat_map(|m| m.parameters) {
        if Parameter::from_name(p.name).is_none() && !out.iter().any(|q| q.name == p.name) {
            out.push(p);
        }
    }
    out
}

/// The labels of the models that have a parameter `name`, joined with "and".
fn models_with(name: &str) -> String {
    let labels: Vec<&str> = MODELS
        .iter()
        .filter(|m| m.parameter(name).is_some())
        .map(|m| m.label)
        .collect();
    labels.join(" and ")
}

/// `the Maxwell-slip model (--model maxwell-slip)`: which models have the flag `flag`.
pub(crate) fn owners(flag_given: &str) -> String {
    let names: Vec<String> = MODELS
        .iter()
        .filter(|m| m.parameters.iter().any(|p| flag(p.name) == flag_given))
        .map(|m| format!("--model {}", m.name))
        .collect();
    names.join(", ")
}

/// For a LuGre or Dahl flag that a model of the zoo takes too (`--rho` of Bouc-Wen): `; also
/// Bouc-Wen (default 0.5)`, each such model with its own default; empty otherwise.
pub(crate) fn shared_help(name: &str) -> String {
    let items: Vec<String> = MODELS
        .iter()
        .filter_map(|m| m.parameter(name).map(|p| (m, p)))
        .map(|(m, p)| {
            let default: Vec<String> = p.default.iter().map(|v| sig(*v, 10)).collect();
            format!("{}, default {}", m.label, default.join(","))
        })
        .collect();
    if items.is_empty() {
        String::new()
    } else {
        format!("; also {}", items.join("; "))
    }
}

/// The zoo's part of `--model`'s help: each model with its parameters.
pub(crate) fn models_help() -> String {
    let items: Vec<String> = MODELS
        .iter()
        .map(|m| format!("{} ({}: {})", m.name, m.parameter_names(), m.equations))
        .collect();
    items.join("; ")
}

/// `Element stiffnesses k_i: > 0 [N/m], one per element (Maxwell-slip; default 0.25,...)`.
fn help(p: &ZooParameter) -> String {
    let capitalized = crate::fmt::capitalized(p.description);
    let shape = match p.shape {
        Shape::Scalar => "",
        Shape::Elements => ", one per element, comma-separated",
    };
    let default: Vec<String> = p.default.iter().map(|v| sig(*v, 10)).collect();
    format!(
        "{capitalized}: {} [{}]{shape} ({}; default {})",
        p.domain.text(),
        p.unit,
        models_with(p.name),
        default.join(",")
    )
}

impl ZooFlags {
    /// Whether any of the zoo's own flags was given.
    pub(crate) fn any(&self) -> bool {
        !self.given.is_empty()
    }

    /// The first flag given, as written on the command line.
    pub(crate) fn first_given(&self) -> Option<String> {
        self.given.first().map(|(name, _)| flag(name))
    }
}

impl clap::FromArgMatches for ZooFlags {
    fn from_arg_matches(matches: &ArgMatches) -> Result<Self, clap::Error> {
        let mut flags = Self::default();
        flags.update_from_arg_matches(matches)?;
        Ok(flags)
    }

    fn update_from_arg_matches(&mut self, matches: &ArgMatches) -> Result<(), clap::Error> {
        for p in own_parameters() {
            let value = matches
                .try_get_one::<String>(p.name)
                .map_err(|e| clap::Error::raw(clap::error::ErrorKind::ArgumentConflict, e))?;
            if let Some(v) = value {
                self.given.retain(|(q, _)| *q != p.name);
                self.given.push((p.name, v.clone()));
            }
        }
        Ok(())
    }
}

impl Args for ZooFlags {
    fn augment_args(cmd: Command) -> Command {
        own_parameters().into_iter().fold(cmd, |cmd, p| {
            let long = flag(p.name)[2..].to_string();
            cmd.arg(
                Arg::new(p.name)
                    .long(long)
                    .value_name(match p.shape {
                        Shape::Scalar => "X",
                        Shape::Elements => "X1,X2,...",
                    })
                    .allow_hyphen_values(true)
                    .help(help(p))
                    .help_heading(HEADING),
            )
        })
    }

    fn augment_args_for_update(cmd: Command) -> Command {
        Self::augment_args(cmd)
    }
}

/// The model of the zoo `spec` from its flags: the zoo's own (`zoo`) and the LuGre or Dahl
/// flags given (`classic`); every parameter not given at its default.
///
/// # Errors
/// A flag of a parameter the model does not have, `--preset` (`preset_given`), a list that
/// is not numbers, and the core's checks of the values (one line naming the flag and value).
pub(crate) fn build(
    spec: &ZooModelSpec,
    preset_given: bool,
    zoo: &ZooFlags,
    classic: &[(Parameter, f64)],
) -> Result<ZooModel> {
    let given = given_values(spec, preset_given, zoo, classic)?;
    let borrowed: Vec<(&str, &[f64])> = given.iter().map(|(n, v)| (*n, v.as_slice())).collect();
    ZooModel::new(spec.name, &borrowed).map_err(|e| anyhow::anyhow!(e))
}

/// The values the flags give to the parameters of the model of the zoo `spec`, by name (those
/// not given are absent), checked as [`build`] checks them but for the model's own checks.
pub(crate) fn given_values(
    spec: &ZooModelSpec,
    preset_given: bool,
    zoo: &ZooFlags,
    classic: &[(Parameter, f64)],
) -> Result<Vec<(&'static str, Vec<f64>)>> {
    if preset_given {
        bail!(
            "--preset is a LuGre parameter set; the {} model takes {}",
            spec.label,
            flags_of(spec)
        );
    }
    let mut given: Vec<(&'static str, Vec<f64>)> = Vec::new();
    for (name, text) in &zoo.given {
        check_owned(spec, &flag(name))?;
        given.push((name, parse_list(&flag(name), text)?));
    }
    for &(q, v) in classic {
        check_owned(spec, &format!("--{}", q.name()))?;
        given.push((q.name(), vec![v]));
    }
    Ok(given)
}

/// The flags of `spec`'s parameters, comma-separated.
fn flags_of(spec: &ZooModelSpec) -> String {
    let flags: Vec<String> = spec.parameters.iter().map(|p| flag(p.name)).collect();
    flags.join(", ")
}

/// Refuses a flag the model of `spec` does not have, naming the ones it has.
fn check_owned(spec: &ZooModelSpec, given: &str) -> Result<()> {
    if spec.parameters.iter().any(|p| flag(p.name) == given) {
        return Ok(());
    }
    bail!(
        "{given} is not a parameter of the {} model (its parameters: {})",
        spec.label,
        flags_of(spec)
    )
}

/// The model as a JSON object: `kind` and each parameter by name (a list for element arrays).
pub(crate) fn zoo_json(model: &ZooModel) -> serde_json::Value {
    let mut j = serde_json::json!({ "kind": model.spec().name });
    for (p, (name, values)) in model.spec().parameters.iter().zip(model.named()) {
        j[name] = match p.shape {
            Shape::Scalar => values.first().copied().unwrap_or_default().into(),
            Shape::Elements => values.into(),
        };
    }
    j
}

/// One line naming the model and its values (`Maxwell-slip: stiffness = 0.25,...`).
pub(crate) fn zoo_line(model: &ZooModel) -> String {
    let items: Vec<String> = model
        .named()
        .into_iter()
        .map(|(name, values)| {
            let v: Vec<String> = values.iter().map(|x| sig(*x, 10)).collect();
            format!("{name} = {}", v.join(","))
        })
        .collect();
    format!("{}: {}", model.spec().label, items.join(", "))
}
