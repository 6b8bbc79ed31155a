//! Typed errors, one enum per domain. Every variant carries the offending value so that a
//! front end (CLI, Python) can print one clear line.

use thiserror::Error;

/// An invalid model parameter.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ModelError {
    #[error("{name} must be a finite number, got {value}")]
    NotFinite { name: &'static str, value: f64 },
    #[error("{name} must be > 0, got {value}")]
    NotPositive { name: &'static str, value: f64 },
    #[error("{name} must be >= 0, got {value}")]
    Negative { name: &'static str, value: f64 },
    #[error("g(0) must be finite and > 0, got {value}")]
    BadG0 { value: f64 },
    #[error("f(0) must be 0, got {value}")]
    BadF0 { value: f64 },
    #[error("a = sigma0 / g(0) = {sigma0} / {g0} is not a finite positive number")]
    BadRatio { sigma0: f64, g0: f64 },
}

/// An invalid input signal.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum InputError {
    #[error("{what}[{index}] must be a finite number, got {value}")]
    NotFinite {
        what: &'static str,
        index: usize,
        value: f64,
    },
    #[error("the input is empty")]
    Empty,
    #[error("a periodic input needs at least 2 distinct values, got {distinct}")]
    TooFewDistinct { distinct: usize },
    #[error("bimodal input breaks Definition 1: {inequality} fails ({detail})")]
    Definition1 {
        inequality: &'static str,
        detail: String,
    },
    #[error("times must be strictly increasing: t[{index}] = {value} after t[{prev_index}] = {prev}", prev_index = index - 1)]
    TimesNotIncreasing { index: usize, prev: f64, value: f64 },
    #[error("t and u have different lengths ({t} and {u})")]
    LengthMismatch { t: usize, u: usize },
    #[error("the input's total variation over one period overflows f64 (values too far apart)")]
    VariationOverflow,
}

/// A result that cannot be represented (it overflows f64).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum LoopError {
    #[error("{what} overflows f64 for this model and input")]
    Overflow { what: &'static str },
}

/// An invalid measured history or counting option ([`crate::cycles`]).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum HistoryError {
    #[error("the history is empty (no samples)")]
    Empty,
    #[error("a history needs at least 2 samples, got {samples}")]
    TooShort { samples: u64 },
    #[error("u[{index}] must be a finite number, got {value}")]
    NotFinite { index: u64, value: f64 },
    #[error("u[{index}] = {value:e} is too large: |u| must be at most {limit:e} so that ranges and means stay finite", limit = f64::MAX / 2.0)]
    TooLarge { index: u64, value: f64 },
    #[error("the gate must be a finite number >= 0, got {value}")]
    BadGate { value: f64 },
    #[error("x0 must satisfy |sigma0 x0| <= g(0) (the bristle deflection the model can hold), got x0 = {x0} with sigma0 = {sigma0}, g(0) = {g0}")]
    BadInitialState { x0: f64, sigma0: f64, g0: f64 },
    #[error("the energies of the cycle closing at u[{index}] overflow f64 (values too large)")]
    EnergyOverflow { index: u64 },
    #[error("a histogram needs at least 1 bin, got {bins}")]
    NoBins { bins: usize },
    #[error("histogram bounds must be finite with min <= max, got [{min}, {max}]")]
    BadBounds { min: f64, max: f64 },
}
