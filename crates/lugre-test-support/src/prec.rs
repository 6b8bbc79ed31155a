//! Tolerances of the test suites, collected in one place (as statrs' `prec`). Each says what
//! limits it.

/// Closed forms evaluated in a few operations, against high-precision references.
pub const CLOSED_FORM: f64 = 1e-14;

/// Sums and differences of a few f64 terms (`rho_k`, the input at the end of an arc), against
/// the exact value or the same sum in another order: a few rounding steps.
pub const FEW_ULPS: f64 = 4.0 * f64::EPSILON;

/// The loop `y°` and energies, against independent references (a handful of rounding steps
/// per segment).
pub const LOOP: f64 = 1e-13;

/// Eq. 8 integrated by adaptive quadrature (the quadrature's own tolerance).
pub const QUADRATURE: f64 = 1e-10;

/// Identities (periodicity, `W = dV + D`) checked relative to the loop's scale
/// `g0 * (period of work)`, summed over up to 10^4 segments.
pub const IDENTITY: f64 = 1e-12;

/// Relative difference of `|a - b|` against `|b|` (absolute when `b == 0`).
pub fn rel_diff(a: f64, b: f64) -> f64 {
    if b == 0.0 {
        a.abs()
    } else {
        ((a - b) / b).abs()
    }
}

/// Energies of a cycle in a measured history (`lugre::cycles`: work, dissipation), absolute,
/// relative to the cycle's scale `g0 * range`: per-step closed forms summed in double-double
/// over the arc, against mpmath quadrature and against the periodic loop.
pub const CYCLE_ENERGY: f64 = 1e-13;

/// Relative error of the work of a history's cycle as small as `a * range ~ 1e-5`, against
/// mpmath: summing per-step terms of size `sigma0 range^2` into `W ~ a sigma0 range^3` costs
/// `1e-16 / (a range)`.
pub const TINY_LOOP_WORK: f64 = 1e-10;

/// The exact simulation of eq. 5 on piecewise-linear inputs (`lugre::simulate`) against
/// mpmath and against closed forms, relative to the state's scale `g(0) / sigma0` (for `z`)
/// and the force's `g(0)` (for `y`): a few roundings per segment, at any `sigma0 / g`.
pub const EXACT_SIMULATION: f64 = 1e-13;

/// Agreement with the `differential-equations` crate's Radau5 at `rtol = 1e-12`, restarted at
/// every kink, relative to `g(0)`: the stiff solver's own error. On Example 1's `x`, whose exact
/// solution is known, it is 1.3e-9 (and larger, not smaller, at `rtol = 1e-13`).
pub const STIFF_SOLVER: f64 = 1e-8;

/// The adaptive integrator for smooth inputs at `tol = 1e-10` or tighter, against closed forms,
/// mpmath or Radau5, relative to `g(0)`: the tolerance bounds the local error per step, the
/// global error is that summed over the steps (damped by the model's dissipation), and Radau5
/// adds its own ([`STIFF_SOLVER`]).
pub const ADAPTIVE: f64 = 2e-8;

/// Parameter recovery of the slow-loop fit (`lugre::fit::fit_slow`) from synthetic data with
/// 1 % noise: the bound. The standard errors there are below 0.5 %, so this also
/// leaves room for an unlucky seed at 4 standard errors.
pub const SLOW_FIT_RECOVERY: f64 = 0.02;

/// Parameter recovery of the full fit (`lugre::fit::fit_full`) from synthetic data with 1 %
/// noise: the bound (standard errors up to about 1 %).
pub const FULL_FIT_RECOVERY: f64 = 0.05;
