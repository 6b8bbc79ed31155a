//! The LuGre model (paper eq. 1).

use super::{Parameter, RateIndependent, Stribeck, VelocityFn, Viscous};
use crate::error::ModelError;

/// The parameters of the LuGre model with the Stribeck `g` and viscous `f`.
///
/// The default is the paper's Examples 2-3: `sigma0 = sigma1 = 1`, `sigma2 = 0`, `Fc = 1`,
/// `Fs = 2`, `vs = 1`, `beta = 1`.
///
/// The fields are the table's [`Parameter::LUGRE`], in its order, laid out as C lays out a
/// struct of `double`s: the C ABI's `LugreParams` is this struct (its header is written from
/// the table, and a test of the C ABI checks each field's place against it).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LuGreParams {
    pub sigma0: f64,
    pub sigma1: f64,
    pub sigma2: f64,
    pub fc: f64,
    pub fs: f64,
    pub vs: f64,
    pub beta: f64,
}

impl Default for LuGreParams {
    fn default() -> Self {
        let mut p = Self {
            sigma0: 0.0,
            sigma1: 0.0,
            sigma2: 0.0,
            fc: 0.0,
            fs: 0.0,
            vs: 0.0,
            beta: 0.0,
        };
        for q in Parameter::LUGRE {
            p.set(q, q.default_value());
        }
        p
    }
}

impl LuGreParams {
    /// The canonical parameters of Canudas de Wit et al. (1995): `sigma0 = 1e5 N/m`,
    /// `sigma1 = sqrt(1e5) N s/m`, `sigma2 = 0.4 N s/m`, `Fc = 1 N`, `Fs = 1.5 N`,
    /// `vs = 1e-3 m/s`, `beta = 2`.
    pub fn canudas_de_wit_1995() -> Self {
        Self {
            sigma0: 1e5,
            sigma1: 1e5f64.sqrt(),
            sigma2: 0.4,
            fc: 1.0,
            fs: 1.5,
            vs: 1e-3,
            beta: 2.0,
        }
    }
}

/// A published LuGre parameter set, by the name every front end uses (`--preset canudas1995`,
/// `LuGre.preset("canudas1995")`, `struct('preset', 'canudas1995')`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Preset {
    /// Table I of Canudas de Wit et al. (1995): [`LuGreParams::canudas_de_wit_1995`].
    Canudas1995,
}

impl Preset {
    /// Every preset, in the order help texts list them.
    pub const ALL: [Preset; 1] = [Preset::Canudas1995];

    /// The preset's name.
    pub const fn name(self) -> &'static str {
        match self {
            Preset::Canudas1995 => "canudas1995",
        }
    }

    /// The preset's values.
    pub fn params(self) -> LuGreParams {
        match self {
            Preset::Canudas1995 => LuGreParams::canudas_de_wit_1995(),
        }
    }

    /// The preset called `name` (exactly, as listed).
    ///
    /// # Errors
    /// [`ModelError::UnknownPreset`] naming `name` and the presets there are.
    pub fn named(name: &str) -> Result<Self, ModelError> {
        Self::ALL
            .into_iter()
            .find(|p| p.name() == name)
            .ok_or_else(|| ModelError::UnknownPreset {
                name: name.to_string(),
                known: &PRESET_NAMES,
            })
    }
}

/// [`Preset::ALL`]'s names.
const PRESET_NAMES: [&str; Preset::ALL.len()] = {
    let mut out = [""; Preset::ALL.len()];
    let mut i = 0;
    while i < out.len() {
        out[i] = Preset::ALL[i].name();
        i += 1;
    }
    out
};

/// A LuGre model with macro-damping `g` and viscous term `f`.
///
/// `LuGre` (the default type parameters) is the Stribeck/viscous model of the paper; any
/// closures can stand for `g` and `f` through [`LuGre::new`].
#[derive(Clone, PartialEq)]
pub struct LuGre<G = Stribeck, F = Viscous> {
    sigma0: f64,
    sigma1: f64,
    g: G,
    f: F,
    g0: f64,
}

impl<G, F> std::fmt::Debug for LuGre<G, F> {
    // g and f may be closures, which have no Debug: show what defines the model's limit.
    fn fmt(&self, fmt: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        fmt.debug_struct("LuGre")
            .field("sigma0", &self.sigma0)
            .field("sigma1", &self.sigma1)
            .field("g0", &self.g0)
            .finish_non_exhaustive()
    }
}

impl<G: VelocityFn, F: VelocityFn> LuGre<G, F> {
    /// A LuGre model with user-supplied `g` and `f`. Checks `sigma0 > 0`, `sigma1 >= 0`,
    /// `g(0)` finite and `> 0`, and `f(0) = 0` (the conditions of paper §1).
    pub fn new(sigma0: f64, sigma1: f64, g: G, f: F) -> Result<Self, ModelError> {
        Parameter::Sigma0.check(sigma0)?;
        Parameter::Sigma1.check(sigma1)?;
        let g0 = g.eval(0.0);
        RateIndependent::new(sigma0, g0)?;
        let f0 = f.eval(0.0);
        if f0 != 0.0 {
            return Err(ModelError::BadF0 { value: f0 });
        }
        Ok(Self {
            sigma0,
            sigma1,
            g,
            f,
            g0,
        })
    }

    pub fn sigma0(&self) -> f64 {
        self.sigma0
    }
    pub fn sigma1(&self) -> f64 {
        self.sigma1
    }
    /// `g(0)`.
    pub fn g0(&self) -> f64 {
        self.g0
    }
    /// `g(v)`.
    pub fn g(&self, v: f64) -> f64 {
        self.g.eval(v)
    }
    /// `f(v)`.
    pub fn f(&self, v: f64) -> f64 {
        self.f.eval(v)
    }

    /// Whether `g` is even and `f` odd (the Stribeck/viscous model; user functions say so
    /// through [`VelocityFn::is_even`] and [`VelocityFn::is_odd`]): the response to `-u` is
    /// then `-F`.
    pub fn is_symmetric(&self) -> bool {
        self.g.is_even() && self.f.is_odd()
    }

    /// The part of the model the hysteresis loop depends on (`sigma0`, `g(0)`).
    pub fn rate_independent(&self) -> RateIndependent {
        RateIndependent::new(self.sigma0, self.g0).expect("validated in new()")
    }
}

impl LuGre {
    /// The Stribeck/viscous LuGre model, validated.
    pub fn from_params(p: LuGreParams) -> Result<Self, ModelError> {
        let g = Stribeck::new(p.fc, p.fs, p.vs, p.beta)?;
        let f = Viscous::new(p.sigma2)?;
        Self::new(p.sigma0, p.sigma1, g, f)
    }

    /// The paper's Examples 2-3 model (see [`LuGreParams::default`]).
    pub fn paper() -> Self {
        Self::from_params(LuGreParams::default()).expect("the paper's parameters are valid")
    }

    /// The parameters this model was built from.
    pub fn params(&self) -> LuGreParams {
        LuGreParams {
            sigma0: self.sigma0,
            sigma1: self.sigma1,
            sigma2: self.f.sigma2(),
            fc: self.g.fc(),
            fs: self.g.fs(),
            vs: self.g.vs(),
            beta: self.g.beta(),
        }
    }

    fn with(self, edit: impl FnOnce(&mut LuGreParams)) -> Result<Self, ModelError> {
        let mut p = self.params();
        edit(&mut p);
        Self::from_params(p)
    }

    pub fn with_sigma0(self, v: f64) -> Result<Self, ModelError> {
        self.with(|p| p.sigma0 = v)
    }
    pub fn with_sigma1(self, v: f64) -> Result<Self, ModelError> {
        self.with(|p| p.sigma1 = v)
    }
    pub fn with_sigma2(self, v: f64) -> Result<Self, ModelError> {
        self.with(|p| p.sigma2 = v)
    }
    pub fn with_fc(self, v: f64) -> Result<Self, ModelError> {
        self.with(|p| p.fc = v)
    }
    pub fn with_fs(self, v: f64) -> Result<Self, ModelError> {
        self.with(|p| p.fs = v)
    }
    pub fn with_vs(self, v: f64) -> Result<Self, ModelError> {
        self.with(|p| p.vs = v)
    }
    pub fn with_beta(self, v: f64) -> Result<Self, ModelError> {
        self.with(|p| p.beta = v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_invalid_parameter_is_named() {
        let bad = [
            ("sigma0", LuGre::paper().with_sigma0(0.0)),
            ("sigma0", LuGre::paper().with_sigma0(f64::NAN)),
            ("sigma1", LuGre::paper().with_sigma1(-1.0)),
            ("sigma2", LuGre::paper().with_sigma2(-1e-9)),
            ("fc", LuGre::paper().with_fc(0.0)),
            ("fs", LuGre::paper().with_fs(-2.0)),
            ("vs", LuGre::paper().with_vs(f64::INFINITY)),
            ("beta", LuGre::paper().with_beta(0.0)),
        ];
        for (name, r) in bad {
            let e = r.expect_err(name);
            assert!(e.to_string().starts_with(name), "{e}");
        }
    }

    #[test]
    fn stribeck_curve_at_known_points() {
        let m = LuGre::paper();
        assert_eq!(m.g0(), 2.0);
        // g(1) = 1 + exp(-1) with Fc = 1, Fs = 2, vs = 1, beta = 1.
        assert_eq!(m.g(1.0), 1.0 + (-1.0f64).exp());
        assert_eq!(m.g(-1.0), m.g(1.0));
        let c = LuGre::from_params(LuGreParams::canudas_de_wit_1995()).unwrap();
        assert_eq!(c.g0(), 1.5);
        assert_eq!(c.f(0.01), 0.4 * 0.01);
    }

    #[test]
    fn user_supplied_functions() {
        let m = LuGre::new(3.0, 0.0, |v: f64| 2.0 + v * v, |v: f64| 0.1 * v).unwrap();
        assert_eq!(m.g0(), 2.0);
        assert_eq!(m.rate_independent().a(), 1.5);
        let e = LuGre::new(3.0, 0.0, |_v: f64| 1.0, |_v: f64| 0.5).unwrap_err();
        assert_eq!(e, ModelError::BadF0 { value: 0.5 });
        let e = LuGre::new(3.0, 0.0, |_v: f64| -1.0, |_v: f64| 0.0).unwrap_err();
        assert_eq!(e, ModelError::BadG0 { value: -1.0 });
    }
}
