//! The models' parameters by name: one place for their names, units, defaults, bounds and
//! descriptions, used by the models' validation, the fit's specification, the command line's
//! flags, the Python keywords, the C header's parameter struct and the FMUs' model descriptions
//! (the last two checked against this table by their crates' tests).

use super::{check_non_negative, check_positive, LuGreParams};
use crate::error::ModelError;

/// A parameter of the LuGre or the Dahl model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Parameter {
    /// LuGre bristle stiffness `sigma0 > 0`.
    Sigma0,
    /// LuGre micro-damping `sigma1 >= 0`.
    Sigma1,
    /// LuGre viscous coefficient `sigma2 >= 0`, `f(v) = sigma2 v`.
    Sigma2,
    /// Coulomb force `Fc > 0` (LuGre and Dahl).
    Fc,
    /// LuGre stiction force `Fs > 0`; `g(0) = Fs`.
    Fs,
    /// LuGre Stribeck velocity `vs > 0`.
    Vs,
    /// LuGre Stribeck exponent `beta > 0`.
    Beta,
    /// Dahl parameter `rho > 0`.
    Rho,
}

/// What values a parameter may take.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Domain {
    /// Finite and `> 0`.
    Positive,
    /// Finite and `>= 0`.
    NonNegative,
}

impl Domain {
    /// The condition as the messages and the FMUs' descriptions write it: `"> 0"`, `">= 0"`.
    pub const fn condition(self) -> &'static str {
        match self {
            Domain::Positive => "> 0",
            Domain::NonNegative => ">= 0",
        }
    }
}

impl Parameter {
    /// The LuGre parameters, in the order of [`LuGreParams`].
    pub const LUGRE: [Parameter; 7] = [
        Parameter::Sigma0,
        Parameter::Sigma1,
        Parameter::Sigma2,
        Parameter::Fc,
        Parameter::Fs,
        Parameter::Vs,
        Parameter::Beta,
    ];

    /// The Dahl parameters.
    pub const DAHL: [Parameter; 2] = [Parameter::Rho, Parameter::Fc];

    /// Every parameter of every model, each once: the LuGre parameters, then the Dahl
    /// model's own (`rho`). The order of the command line's flags.
    pub const ALL: [Parameter; Parameter::LUGRE.len() + 1] = {
        let mut all = [Parameter::Rho; Parameter::LUGRE.len() + 1];
        let mut i = 0;
        while i < Parameter::LUGRE.len() {
            all[i] = Parameter::LUGRE[i];
            i += 1;
        }
        all
    };

    /// The LuGre parameters of the rate-independent loop (eqs. 6-10: only `sigma0` and
    /// `g(0) = Fs` matter there).
    pub const LUGRE_RATE_INDEPENDENT: [Parameter; 2] = [Parameter::Sigma0, Parameter::Fs];

    /// The name used everywhere: the command line's flag (`--sigma0`), the Python keyword,
    /// the fit's parameter name and every message.
    pub const fn name(self) -> &'static str {
        match self {
            Parameter::Sigma0 => "sigma0",
            Parameter::Sigma1 => "sigma1",
            Parameter::Sigma2 => "sigma2",
            Parameter::Fc => "fc",
            Parameter::Fs => "fs",
            Parameter::Vs => "vs",
            Parameter::Beta => "beta",
            Parameter::Rho => "rho",
        }
    }

    /// The parameter called `name` (case-insensitive, surrounding blanks ignored).
    pub fn from_name(name: &str) -> Option<Parameter> {
        let name = name.trim();
        Self::ALL
            .into_iter()
            .find(|p| p.name().eq_ignore_ascii_case(name))
    }

    /// The symbol the paper and the text outputs write: `Fc`, `Fs`, else the name.
    pub const fn symbol(self) -> &'static str {
        match self {
            Parameter::Fc => "Fc",
            Parameter::Fs => "Fs",
            _ => self.name(),
        }
    }

    /// The unit with displacements in metres and forces in newtons.
    pub const fn unit(self) -> &'static str {
        match self {
            Parameter::Sigma0 => "N/m",
            Parameter::Sigma1 | Parameter::Sigma2 => "N s/m",
            Parameter::Fc | Parameter::Fs => "N",
            Parameter::Vs => "m/s",
            Parameter::Beta => "1",
            Parameter::Rho => "1/m",
        }
    }

    /// What the parameter is, in a few words (e.g. "bristle stiffness").
    pub const fn description(self) -> &'static str {
        match self {
            Parameter::Sigma0 => "bristle stiffness",
            Parameter::Sigma1 => "micro-damping",
            Parameter::Sigma2 => "viscous coefficient",
            Parameter::Fc => "Coulomb force",
            Parameter::Fs => "stiction force",
            Parameter::Vs => "Stribeck velocity",
            Parameter::Beta => "Stribeck exponent",
            Parameter::Rho => "stiffness over the Coulomb force (sigma0 / Fc)",
        }
    }

    /// The default: the paper's Examples 2-3 (`sigma0 = sigma1 = 1`, `sigma2 = 0`, `Fc = 1`,
    /// `Fs = 2`, `vs = 1`, `beta = 1`; Dahl `rho = 1`).
    pub const fn default_value(self) -> f64 {
        match self {
            Parameter::Sigma2 => 0.0,
            Parameter::Fs => 2.0,
            _ => 1.0,
        }
    }

    /// Whether the default means "absent" (`sigma2 = 0`: no viscous friction), so that a model
    /// of a physical system may leave the parameter unnamed. The other defaults are the
    /// paper's dimensionless values: a force or an energy of a real system never comes from
    /// them alone.
    pub const fn default_is_absence(self) -> bool {
        matches!(self, Parameter::Sigma2)
    }

    /// Whether a full fit frees the parameter unless told otherwise: every one but `beta`,
    /// which most records determine poorly (a parameter the fit has no derivative for is held
    /// whatever this says).
    pub const fn fit_frees_by_default(self) -> bool {
        !matches!(self, Parameter::Beta)
    }

    /// What values the parameter may take.
    pub const fn domain(self) -> Domain {
        match self {
            Parameter::Sigma1 | Parameter::Sigma2 => Domain::NonNegative,
            _ => Domain::Positive,
        }
    }

    /// `value` if it lies in the parameter's domain, else the error that names it.
    pub fn check(self, value: f64) -> Result<f64, ModelError> {
        match self.domain() {
            Domain::Positive => check_positive(self.name(), value),
            Domain::NonNegative => check_non_negative(self.name(), value),
        }
    }
}

impl std::fmt::Display for Parameter {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl LuGreParams {
    /// The value of a LuGre parameter (`None` for the Dahl model's `rho`).
    pub fn get(&self, p: Parameter) -> Option<f64> {
        Some(match p {
            Parameter::Sigma0 => self.sigma0,
            Parameter::Sigma1 => self.sigma1,
            Parameter::Sigma2 => self.sigma2,
            Parameter::Fc => self.fc,
            Parameter::Fs => self.fs,
            Parameter::Vs => self.vs,
            Parameter::Beta => self.beta,
            Parameter::Rho => return None,
        })
    }

    /// Sets a LuGre parameter (unchecked, as the fields are; `rho` is not one and is ignored).
    pub fn set(&mut self, p: Parameter, value: f64) {
        let field = match p {
            Parameter::Sigma0 => &mut self.sigma0,
            Parameter::Sigma1 => &mut self.sigma1,
            Parameter::Sigma2 => &mut self.sigma2,
            Parameter::Fc => &mut self.fc,
            Parameter::Fs => &mut self.fs,
            Parameter::Vs => &mut self.vs,
            Parameter::Beta => &mut self.beta,
            Parameter::Rho => return,
        };
        *field = value;
    }

    /// The parameters with their names, in the order of [`Parameter::LUGRE`].
    pub fn named(&self) -> [(Parameter, f64); Parameter::LUGRE.len()] {
        Parameter::LUGRE.map(|p| (p, self.get(p).unwrap_or(f64::NAN)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_defaults_and_checks() {
        let d = LuGreParams::default();
        for p in Parameter::LUGRE {
            assert_eq!(Parameter::from_name(&p.name().to_uppercase()), Some(p));
            assert_eq!(d.get(p), Some(p.default_value()), "{p}");
        }
        assert_eq!(Parameter::from_name(" Rho "), Some(Parameter::Rho));
        // ALL holds every parameter of both models, each once.
        for p in Parameter::LUGRE.iter().chain(&Parameter::DAHL) {
            assert!(Parameter::ALL.contains(p), "{p}");
        }
        for (i, p) in Parameter::ALL.iter().enumerate() {
            assert!(!Parameter::ALL[..i].contains(p), "{p}");
            assert!(Parameter::LUGRE.contains(p) || Parameter::DAHL.contains(p));
        }
        assert_eq!(Parameter::from_name("mu"), None);
        assert!(Parameter::Sigma1.check(0.0).is_ok());
        assert_eq!(
            Parameter::Sigma0.check(0.0).unwrap_err().to_string(),
            "sigma0 must be > 0, got 0"
        );
        let mut p = d;
        p.set(Parameter::Vs, 1e-3);
        assert_eq!(p.vs, 1e-3);
    }
}
