//! The velocity functions of the LuGre model: `g` (macro-damping, Stribeck curve) and `f`
//! (viscous friction). Any `Fn(f64) -> f64` is also a [`VelocityFn`], for user-supplied shapes.

use super::Parameter;
use crate::error::ModelError;

/// A function of the sliding velocity, `g(v)` or `f(v)`.
pub trait VelocityFn {
    fn eval(&self, v: f64) -> f64;

    /// Whether `eval(-v) = eval(v)` for every `v` (the Stribeck curve). A model whose `g` is
    /// even and `f` odd answers a symmetric input symmetrically, which halves the work of its
    /// periodic orbit ([`crate::sweep`]). `false` (the default) only forgoes that.
    fn is_even(&self) -> bool {
        false
    }

    /// Whether `eval(-v) = -eval(v)` for every `v` (viscous friction); see [`Self::is_even`].
    fn is_odd(&self) -> bool {
        false
    }
}

impl<F: Fn(f64) -> f64> VelocityFn for F {
    fn eval(&self, v: f64) -> f64 {
        self(v)
    }
}

/// The smallest positive `x` with a finite `1 / x` (a subnormal, just above `1 / f64::MAX`).
pub(crate) const MIN_INVERTIBLE: f64 = 5.56268464626801e-309;

/// Above it `exp(-x)` rounds to 0 (below `2^-1075`, half the smallest subnormal, past
/// `x = 1075 ln 2 = 745.133`).
const UNDERFLOW: f64 = 745.2;

/// The Stribeck curve (paper §4.2): `g(v) = Fc + (Fs - Fc) exp(-|v / vs|^beta)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stribeck {
    fc: f64,
    fs: f64,
    vs: f64,
    beta: f64,
    /// `1 / vs`: `g` is evaluated once per sample in simulations, where a division costs.
    inv_vs: f64,
}

impl Stribeck {
    /// Validated: `Fc, Fs, vs, beta` finite and `> 0`.
    pub fn new(fc: f64, fs: f64, vs: f64, beta: f64) -> Result<Self, ModelError> {
        let vs = Parameter::Vs.check(vs)?;
        if vs < MIN_INVERTIBLE {
            // A subnormal vs whose reciprocal overflows: g(0) would be 0 * inf.
            return Err(ModelError::TooSmall {
                name: "vs",
                value: vs,
                min: MIN_INVERTIBLE,
            });
        }
        let inv_vs = 1.0 / vs;
        Ok(Self {
            fc: Parameter::Fc.check(fc)?,
            fs: Parameter::Fs.check(fs)?,
            vs,
            beta: Parameter::Beta.check(beta)?,
            inv_vs,
        })
    }

    pub fn fc(&self) -> f64 {
        self.fc
    }
    pub fn fs(&self) -> f64 {
        self.fs
    }
    pub fn vs(&self) -> f64 {
        self.vs
    }
    pub fn beta(&self) -> f64 {
        self.beta
    }
}

impl VelocityFn for Stribeck {
    fn is_even(&self) -> bool {
        true
    }

    #[inline]
    fn eval(&self, v: f64) -> f64 {
        let r = (v * self.inv_vs).abs();
        // r^beta with the common exponents done without powf.
        let x = if self.beta == 1.0 {
            r
        } else if self.beta == 2.0 {
            r * r
        } else {
            r.powf(self.beta)
        };
        if self.fs >= self.fc {
            // exp(-x) is exactly 0 past 745.2; libm gets there through its underflow path
            // (errno and all), which costs more than the rest of g: sliding at 100 vs does it.
            let decay = if x > UNDERFLOW { 0.0 } else { (-x).exp() };
            self.fc + (self.fs - self.fc) * decay
        } else {
            // g rises from Fs to Fc: `Fs + (Fc - Fs)(1 - exp(-x))`, two terms >= 0, so g(0) is
            // Fs exactly and g never rounds to 0 (`Fc + (Fs - Fc) exp(-x)` cancels, to 0 when
            // Fs < Fc eps).
            let (_, one_minus_e) = crate::kernel::relax::decay(x);
            self.fs + (self.fc - self.fs) * one_minus_e
        }
    }
}

/// Linear viscous friction `f(v) = sigma2 v`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Viscous {
    sigma2: f64,
}

impl Viscous {
    /// Validated: `sigma2` finite and `>= 0`.
    pub fn new(sigma2: f64) -> Result<Self, ModelError> {
        Ok(Self {
            sigma2: Parameter::Sigma2.check(sigma2)?,
        })
    }

    pub fn sigma2(&self) -> f64 {
        self.sigma2
    }
}

impl VelocityFn for Viscous {
    fn is_odd(&self) -> bool {
        true
    }

    #[inline]
    fn eval(&self, v: f64) -> f64 {
        self.sigma2 * v
    }
}
