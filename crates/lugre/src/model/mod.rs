//! The LuGre and Dahl models (paper eq. 1) and the functions `g` and `f` that shape them.
//!
//! LuGre, input displacement `u(t)`, output friction force `F(t)`:
//!
//! ```text
//! x' = -sigma0 |u'| / g(u') x + u'         x(0) = x0
//! F  =  sigma0 x + sigma1 x' + f(u')
//! ```
//!
//! with `sigma0 > 0`, `sigma1 >= 0`, `g > 0` continuous and `f` continuous with `f(0) = 0`.
//! The hysteresis loop (the limit of slow periodic inputs, eqs. 6-10) depends only on
//! `sigma0` and `g0 = g(0)`, gathered in [`RateIndependent`].

mod dahl;
mod functions;
mod lugre;
pub mod named;
pub mod normal;
mod parameter;

/// The names of LuGre and Dahl everywhere (`--model`, Python's `model=`, the C ABI's model
/// name), in the order `--model` lists them: `crate::fit::Family::name` of each family.
pub const FAMILY_NAMES: [&str; 2] = ["lugre", "dahl"];

pub use dahl::Dahl;
pub use functions::{Stribeck, VelocityFn, Viscous};
pub use lugre::{LuGre, LuGreParams, Preset};
pub use parameter::{Domain, Parameter};

use crate::error::ModelError;
use crate::kernel::Relaxation;

/// What the rate-independent limit of a LuGre model depends on: `sigma0` and `g0 = g(0)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RateIndependent {
    /// `sigma0`, `g0` and `a = sigma0 / g0` (kept: every piece of every loop needs it, and a
    /// division is slow).
    k: Relaxation,
}

impl RateIndependent {
    /// Validated: both finite and positive, and `a = sigma0 / g0` finite and positive.
    pub fn new(sigma0: f64, g0: f64) -> Result<Self, ModelError> {
        Parameter::Sigma0.check(sigma0)?;
        if !g0.is_finite() || g0 <= 0.0 {
            return Err(ModelError::BadG0 { value: g0 });
        }
        let a = sigma0 / g0;
        if !a.is_finite() || a <= 0.0 {
            return Err(ModelError::BadRatio { sigma0, g0 });
        }
        Ok(Self {
            k: Relaxation::new(sigma0, g0),
        })
    }

    #[inline]
    pub fn sigma0(&self) -> f64 {
        self.k.sigma0()
    }

    /// `g(0)`: the force the loop saturates to, `|y°| < g0`.
    #[inline]
    pub fn g0(&self) -> f64 {
        self.k.g0()
    }

    /// `a = sigma0 / g(0)`, the inverse length over which the loop relaxes.
    #[inline]
    pub fn a(&self) -> f64 {
        self.k.a()
    }

    /// The numbers the kernel's closed forms take.
    #[inline(always)]
    pub(crate) fn relaxation(&self) -> Relaxation {
        self.k
    }
}

pub(crate) fn check_finite(name: &'static str, value: f64) -> Result<f64, ModelError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(ModelError::NotFinite { name, value })
    }
}

pub(crate) fn check_positive(name: &'static str, value: f64) -> Result<f64, ModelError> {
    check_finite(name, value)?;
    if value > 0.0 {
        Ok(value)
    } else {
        Err(ModelError::NotPositive { name, value })
    }
}

pub(crate) fn check_non_negative(name: &'static str, value: f64) -> Result<f64, ModelError> {
    check_finite(name, value)?;
    if value >= 0.0 {
        Ok(value)
    } else {
        Err(ModelError::Negative { name, value })
    }
}
