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

/// Energies of a cycle in a measured history ([`crate::cycles`]: work, dissipation), absolute,
/// relative to the cycle's scale `g0 * range`: per-step closed forms summed in double-double
/// over the arc, against mpmath quadrature and against the periodic loop.
pub const CYCLE_ENERGY: f64 = 1e-13;
