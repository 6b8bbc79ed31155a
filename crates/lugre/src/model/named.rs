//! The named-model rule: forces and energies of a measured history or a physical system come
//! from a model the user named (every parameter the computation uses given, or a preset), never
//! from the paper's dimensionless defaults alone. Parameters whose default means absence
//! ([`Parameter::default_is_absence`]: no viscous term, no damping) need not be given.
//!
//! Every front end that takes parameters one by one (CLI flags, MEX struct fields) asks here, so
//! they refuse the same partly named models; each spells the names its own way
//! ([`PartlyNamed::render`]).

use super::Parameter;

/// Which parameters a computation uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Needed {
    /// Every parameter of the model (a simulation of a physical system).
    All,
    /// Those of the rate-independent loop (energies along `y*`:
    /// [`Parameter::LUGRE_RATE_INDEPENDENT`] for LuGre, both of Dahl's).
    RateIndependent,
}

/// A model named only in part: the parameters still to give.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PartlyNamed {
    /// The parameters the computation uses that were not given, in the table's order.
    pub missing: Vec<Parameter>,
    /// Whether a preset (Table I of Canudas de Wit et al. 1995) would name the model instead.
    pub preset: bool,
}

impl PartlyNamed {
    /// The message, with each missing parameter spelled by `spell` (`--sigma0`, `sigma0`) and
    /// the preset alternative as `preset` (`--preset canudas1995`).
    pub fn render(&self, spell: impl Fn(Parameter) -> String, preset: &str) -> String {
        let names: Vec<String> = self.missing.iter().map(|&p| spell(p)).collect();
        let or_preset = if self.preset {
            format!(", or {preset}")
        } else {
            String::new()
        };
        format!(
            "the model is only partly named: give {} too{or_preset} (forces and energies of a measured or physical system are not computed from the dimensionless defaults)",
            names.join(", ")
        )
    }
}

/// The parameters of `family` (one of [`Parameter::LUGRE`], [`Parameter::DAHL`]) used for
/// `needed`.
pub fn acting(family: &'static [Parameter], needed: Needed) -> &'static [Parameter] {
    if needed == Needed::RateIndependent && family == Parameter::LUGRE.as_slice() {
        &Parameter::LUGRE_RATE_INDEPENDENT
    } else {
        family
    }
}

/// Checks that a model of `family` with the parameters for which `given` is true names every
/// parameter `needed` uses. A preset names them all: call this only without one.
///
/// # Errors
/// [`PartlyNamed`] listing the parameters still to give.
pub fn check_named(
    family: &'static [Parameter],
    needed: Needed,
    given: impl Fn(Parameter) -> bool,
) -> Result<(), PartlyNamed> {
    let missing: Vec<Parameter> = acting(family, needed)
        .iter()
        .copied()
        .filter(|&p| !given(p) && !p.default_is_absence())
        .collect();
    if missing.is_empty() {
        return Ok(());
    }
    Err(PartlyNamed {
        missing,
        // Only LuGre has a preset.
        preset: family == Parameter::LUGRE.as_slice(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_rule_follows_the_table() {
        let none = |_| false;
        let e = check_named(&Parameter::LUGRE, Needed::RateIndependent, none).unwrap_err();
        assert_eq!(e.missing, Parameter::LUGRE_RATE_INDEPENDENT);
        assert!(e.preset);
        // Everything the table does not call absence is needed for a simulation.
        let e = check_named(&Parameter::LUGRE, Needed::All, none).unwrap_err();
        let want: Vec<Parameter> = Parameter::LUGRE
            .into_iter()
            .filter(|p| !p.default_is_absence())
            .collect();
        assert_eq!(e.missing, want);
        let e = check_named(&Parameter::DAHL, Needed::RateIndependent, none).unwrap_err();
        assert_eq!(e.missing, Parameter::DAHL);
        assert!(!e.preset);
        assert_eq!(
            check_named(&Parameter::LUGRE, Needed::RateIndependent, |p| {
                Parameter::LUGRE_RATE_INDEPENDENT.contains(&p)
            }),
            Ok(())
        );
    }

    #[test]
    fn the_message_spells_the_names_as_asked() {
        let e = check_named(&Parameter::LUGRE, Needed::RateIndependent, |p| {
            p == Parameter::Fs
        })
        .unwrap_err();
        assert_eq!(
            e.render(|p| format!("--{}", p.name()), "--preset canudas1995"),
            "the model is only partly named: give --sigma0 too, or --preset canudas1995 (forces and energies of a measured or physical system are not computed from the dimensionless defaults)"
        );
    }
}
