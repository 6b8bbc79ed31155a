//! The Dahl model in the paper's form: `w' = rho (u' - |u'| w)`, `y = Fc w`, `|w(0)| <= 1`.
//!
//! It is the LuGre model with `g == Fc`, `sigma0 = rho Fc`, `sigma1 = 0`, `f = 0`, and
//! `x = w / rho` (paper §1); [`Dahl::to_lugre`] returns exactly that model.

use super::{check_positive, LuGre, LuGreParams, Parameter, RateIndependent};
use crate::error::ModelError;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dahl {
    rho: f64,
    fc: f64,
}

impl Dahl {
    /// Validated: `rho` and `Fc` finite and `> 0`, and `rho Fc` finite.
    pub fn new(rho: f64, fc: f64) -> Result<Self, ModelError> {
        Parameter::Rho.check(rho)?;
        Parameter::Fc.check(fc)?;
        check_positive("sigma0 = rho * fc", rho * fc)?;
        Ok(Self { rho, fc })
    }

    pub fn rho(&self) -> f64 {
        self.rho
    }
    pub fn fc(&self) -> f64 {
        self.fc
    }

    /// The value of a Dahl parameter (`None` for the LuGre model's own).
    pub fn get(&self, p: Parameter) -> Option<f64> {
        match p {
            Parameter::Rho => Some(self.rho),
            Parameter::Fc => Some(self.fc),
            _ => None,
        }
    }

    /// The parameters with their names, in the order of [`Parameter::DAHL`].
    pub fn named(&self) -> [(Parameter, f64); Parameter::DAHL.len()] {
        Parameter::DAHL.map(|p| (p, self.get(p).unwrap_or(f64::NAN)))
    }

    /// The equivalent LuGre model. `g` is the Stribeck curve with `Fs = Fc`, which is the
    /// constant `Fc` exactly (the exponential's coefficient is 0).
    pub fn to_lugre(&self) -> LuGre {
        LuGre::from_params(Self::lugre_params(self.rho, self.fc)).expect("validated in new()")
    }

    /// The parameters of the LuGre model equivalent to the Dahl model `(rho, fc)`, unchecked:
    /// `sigma0 = rho Fc`, `g = Fc` (`Fs = Fc`), `sigma1 = sigma2 = 0`; the others at their
    /// defaults, where they do not act (`vs`, `beta` shape `g - Fc = 0`).
    pub(crate) fn lugre_params(rho: f64, fc: f64) -> LuGreParams {
        let mut p = LuGreParams::default();
        p.set(Parameter::Sigma0, rho * fc);
        p.set(Parameter::Sigma1, 0.0);
        p.set(Parameter::Sigma2, 0.0);
        p.set(Parameter::Fc, fc);
        p.set(Parameter::Fs, fc);
        p
    }

    pub fn rate_independent(&self) -> RateIndependent {
        self.to_lugre().rate_independent()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn maps_to_lugre() {
        let d = Dahl::new(2.5, 0.8).unwrap();
        let m = d.to_lugre();
        assert_eq!(m.sigma0(), 2.0);
        assert_eq!(m.sigma1(), 0.0);
        assert_eq!(d.named(), [(Parameter::Rho, 2.5), (Parameter::Fc, 0.8)]);
        assert_eq!(d.get(Parameter::Sigma1), None);
        for v in [-10.0, -1e-3, 0.0, 0.3, 7.0] {
            assert_eq!(m.g(v), 0.8);
            assert_eq!(m.f(v), 0.0);
        }
        assert_eq!(d.rate_independent().a(), 2.5);
        assert!(Dahl::new(0.0, 1.0).is_err());
        assert!(Dahl::new(1.0, f64::NAN).is_err());
    }
}
