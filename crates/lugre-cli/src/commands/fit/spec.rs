//! The fit's specification from the flags (family, start values, fixed and freed parameters,
//! bounds), and the core's errors explained in terms of the flags.

use anyhow::{anyhow, bail, Result};
use lugre::fit::{Family, FitError, FitSpec};
use lugre::model::Parameter;

use super::FitArgs;
use crate::args::ModelKind;
use crate::fmt::{excerpt, quoted};
use crate::numbers::parse_number;

/// The request from the flags: family, given values, fixed and freed names, bounds.
pub(super) fn build_spec(args: &FitArgs) -> Result<FitSpec> {
    // The same checks as every command (flags of the other model, invalid values).
    args.model.build()?;
    let m = &args.model;
    let (family, parameters) = match m.model {
        ModelKind::Lugre => (Family::LuGre, &Parameter::LUGRE[..]),
        // A model of the zoo was refused by `build` above.
        _ => (Family::Dahl, &Parameter::DAHL[..]),
    };
    let mut spec = FitSpec::new(family);
    for &p in parameters {
        if let Some(v) = m.given(p) {
            spec = spec.set(p.name(), v).map_err(explain)?;
        }
    }
    for item in names("--fix", args.fix.as_deref())? {
        let (name, value) = fixed_item(item)?;
        if let Some(v) = value {
            spec = spec
                .set(name, v)
                .map_err(|e| anyhow!("--fix: {}", short_name(e)))?;
        }
        spec = spec
            .fix(name)
            .map_err(|e| anyhow!("--fix: {}", short_name(e)))?;
    }
    for name in names("--free", args.free.as_deref())? {
        spec = spec
            .free(name)
            .map_err(|e| anyhow!("--free: {}", short_name(e)))?;
    }
    if let Some(text) = &args.bounds {
        once("--bounds", &text.split(',').collect::<Vec<_>>())?;
        for item in text.split(',') {
            let Some((name, range)) = item.split_once('=') else {
                bail!("--bounds: {} is not NAME=LO:HI", quoted(item.trim()));
            };
            let Some((lo, hi)) = range.split_once(':') else {
                bail!("--bounds: {} is not NAME=LO:HI", quoted(item.trim()));
            };
            let lo = parse_number("--bounds", 1, lo)?;
            let hi = match hi.trim().to_ascii_lowercase().as_str() {
                "inf" | "+inf" | "infinity" => f64::INFINITY,
                _ => parse_number("--bounds", 2, hi)?,
            };
            spec = spec
                .bounds(name, lo, hi)
                .map_err(|e| anyhow!("--bounds: {}", short_name(e)))?;
        }
    }
    Ok(spec)
}

/// An item of `--fix`: NAME, or NAME=VALUE (the value given with it: --fix sigma2=0.05).
pub(super) fn fixed_item(item: &str) -> Result<(&str, Option<f64>)> {
    Ok(match item.split_once('=') {
        Some((name, value)) => match value.trim().parse::<f64>() {
            Ok(v) if v.is_finite() => (name.trim(), Some(v)),
            _ => bail!(
                "--fix: {}: the value is not a finite number",
                quoted(&excerpt(item))
            ),
        },
        None => (item, None),
    })
}

/// `e` with an unknown parameter's name cut short: it is the user's text, of any length.
fn short_name(e: FitError) -> FitError {
    match e {
        FitError::UnknownParameter { name, model, known } => FitError::UnknownParameter {
            name: excerpt(&name),
            model,
            known,
        },
        other => other,
    }
}

/// The names of a comma-separated list (none for an absent flag).
pub(super) fn names<'a>(flag: &str, text: Option<&'a str>) -> Result<Vec<&'a str>> {
    let Some(text) = text else {
        return Ok(Vec::new());
    };
    let items: Vec<&str> = text.split(',').map(str::trim).collect();
    if items.iter().any(|s| s.is_empty()) {
        bail!(
            "{flag}: empty name in {} (expected names separated by commas)",
            quoted(text)
        );
    }
    once(flag, &items)?;
    Ok(items)
}

/// Refuses a parameter named twice in one flag's `NAME[=...]` items (`--fix fs=1,fs=2`: which
/// value was meant cannot be known).
fn once(flag: &str, items: &[&str]) -> Result<()> {
    fn name(item: &str) -> &str {
        item.split_once('=').map_or(item, |(n, _)| n).trim()
    }
    for (k, first) in items.iter().enumerate() {
        if let Some(second) = items[k + 1..].iter().find(|i| name(i) == name(first)) {
            bail!(
                "{flag}: {} is given twice ({} and {})",
                quoted(&excerpt(name(first))),
                quoted(&excerpt(first)),
                quoted(&excerpt(second))
            );
        }
    }
    Ok(())
}

/// A core error as one line, with what to do about it where the CLI knows.
pub(super) fn explain(e: FitError) -> anyhow::Error {
    match &e {
        FitError::Unidentifiable { parameters } => {
            let names: Vec<&str> = parameters.iter().map(|p| p.name).collect();
            let example: Vec<String> = names.iter().map(|n| format!("{n}=VALUE")).collect();
            anyhow!(
                "{e}; fix {} at values you know (--fix {}: the flags' defaults are the paper's dimensionless values, not yours) or fit data that excite {}",
                if names.len() == 1 { "it" } else { "them" },
                example.join(","),
                if names.len() == 1 { "it" } else { "them" }
            )
        }
        FitError::NotInSlowLoop { .. } => anyhow!("{e}"),
        FitError::NotGiven { name, .. } => {
            let flag = name.replace('_', "-");
            anyhow!("{e} (--{flag} V, --fix {name}=V or --free {name})")
        }
        FitError::NoStart { .. } => anyhow!(
            "{e} (--NAME VALUE for each, e.g. --vs at the order of the record's velocities), or fewer free parameters (--fix)"
        ),
        FitError::StartOutsideBounds { name, .. } => {
            anyhow!("{e}: change --{name} or --bounds")
        }
        FitError::BadStart { name, .. } => {
            anyhow!("--{name}: {e} (to hold it at that value, add --fix {name})")
        }
        _ => anyhow!("{e}"),
    }
}
