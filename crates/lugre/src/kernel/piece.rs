//! One piece of the normalized input: `y` at its end, its dissipation and the two terms of its
//! work, from the closed forms of eq. 8 (see the module docs of [`crate::loops`]).

use super::numerics::{one_minus_exp, PhiFamily};
use super::relax::{relax, relax_toward};
use super::Relaxation;

/// `y` a length `l` along a piece of the normalized input with direction `s` (+-1), from `y_k`
/// at its start (eq. 8 on one piece). The per-piece closed forms below are shared by the
/// periodic loop and by histories ([`crate::cycles`]).
#[inline]
pub(crate) fn advance(model: Relaxation, y_k: f64, s: f64, l: f64) -> f64 {
    // |y°| < g0 holds exactly; near saturation `sigma0 l phi(a l)` can round an ulp above g0.
    let g0 = model.g0();
    let (z, d) = (model.a() * l, s * model.sigma0() * l);
    let y = if z.is_finite() && d.is_finite() {
        relax(y_k, z, d)
    } else {
        // A long piece at a huge stiffness, where `a l` or `sigma0 l` overflows:
        // `s sigma0 l phi(z) = s g0 (1 - exp(-z))` needs neither.
        relax_toward(y_k, z, s * g0)
    };
    y.clamp(-g0, g0)
}

/// Direction `s` (+-1) and length `l` of the piece of the normalized input from `from` to
/// `to`.
#[inline]
pub(crate) fn step(from: f64, to: f64) -> (f64, f64) {
    let du = to - from;
    (if du >= 0.0 { 1.0 } else { -1.0 }, du.abs())
}

/// Everything about one piece of the loop (direction `s`, length `l`, from `y_k`): `y` at its
/// end, the dissipation `(1/g0) integral y^2 drho` over it (never < 0), and the two terms of
/// its work, `(c, e) = (l phi(a l), sigma0 l^2 h(a l))`, so that `integral y dpsi = s y_k c + e`
/// and `integral (y - y_ref) dpsi = s (y_k - y_ref) c + (1 - s y_ref / g0) e`
/// ([`crate::cycles`] sums the work relative to a loop's start value this way, without
/// cancellation). `e` is an energy, `sigma0` already applied: `l^2` alone overflows long before
/// `sigma0 l^2 h <= g0 l` does when `sigma0` is tiny.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Piece {
    pub y_end: f64,
    pub dissipation: f64,
    pub c: f64,
    pub e: f64,
}

/// [`Piece`] from a single [`PhiFamily`] (at most one exponential for all of it):
///
/// ```text
/// y_end = y_k exp(-z) + s sigma0 l phi(z)
/// D     = a y_k^2 l phi(2z) / sigma0 + 2 s y_k l (phi(z) - phi(2z)) + sigma0 l^2 q(z)/z
/// ```
///
/// with `z = a l`. Where `a l`, `sigma0 l` or `l^2` overflows, or `a l > 1e300` (a long piece
/// at a huge stiffness), the same terms are taken in units of `1/a`.
#[inline(always)]
pub(crate) fn piece(model: Relaxation, y_k: f64, s: f64, l: f64) -> Piece {
    piece_with(model, y_k, s, l, &PhiFamily::new(model.a() * l))
}

/// [`piece`] with the family at `z = a l` already evaluated (in blocks, [`crate::kernel::numerics::PhiBlock`]).
#[inline(always)]
pub(crate) fn piece_with(model: Relaxation, y_k: f64, s: f64, l: f64, f: &PhiFamily) -> Piece {
    let (a, sigma0, g0) = (model.a(), model.sigma0(), model.g0());
    let z = a * l;
    let (c, e) = (l * f.phi, sigma0 * l * l * f.h);
    // Short pieces (`exp(-z) > 1/2`) add the small change to `y_k` rather than scaling it by
    // the rounded `exp(-z)`: the same form as the closure gap's (`y_end - y_k = s sigma0 c -
    // y_k (1 - exp(-z))`), so that the two agree to an ulp of `y`.
    let y_end = if f.e > 0.5 {
        y_k + (s * sigma0 * c - y_k * f.one_minus_e)
    } else {
        y_k * f.e + s * sigma0 * c
    };
    // a / sigma0 = 1 / g0; `y_k / g0` first (it is <= 1), so that `y_k^2` neither overflows
    // (|y| > 1e154) nor underflows (|y| < 1e-154) where D itself is representable.
    let d = y_k / g0 * y_k * l * f.phi2
        + 2.0 * s * y_k * l * f.phi_minus_phi2
        + sigma0 * l * l * f.q_over_z;
    // Past z = 1e300, 1/z is near the subnormals and loses bits: the saturated forms then.
    // `0 x` is 0 for a finite `x`, NaN otherwise: one test for the three.
    let finite = 0.0 * e + 0.0 * y_end + 0.0 * d == 0.0;
    if z < 1e300 && finite {
        // |y°| < g0 holds exactly; near saturation `sigma0 l phi(a l)` can round an ulp above.
        Piece {
            y_end: y_end.clamp(-g0, g0),
            dissipation: d.max(0.0),
            c,
            e,
        }
    } else {
        saturated_piece(model, y_k, s, l)
    }
}

/// [`piece`] in units of `1/a`: `l phi(z) = (1 - exp(-z)) / a`,
/// `sigma0 l^2 h(z) = sigma0 (l - l phi(z)) / a = g0 (l - l phi(z))`,
/// `l phi(2z) = (1 - exp(-2z)) / (2a)`, finite wherever the results are. The piece is saturated:
/// `y` relaxes to `s g0` and `D = g0 l` to rounding.
#[cold]
fn saturated_piece(model: Relaxation, y_k: f64, s: f64, l: f64) -> Piece {
    let (a, sigma0, g0) = (model.a(), model.sigma0(), model.g0());
    let z = a * l;
    let inv_a = g0 / sigma0;
    let c = one_minus_exp(z) * inv_a;
    let c2 = 0.5 * one_minus_exp(2.0 * z) * inv_a;
    let d = y_k * y_k * one_minus_exp(2.0 * z) / (2.0 * sigma0)
        + 2.0 * s * y_k * (c - c2)
        + g0 * (l - 2.0 * c + c2);
    Piece {
        y_end: relax_toward(y_k, z, s * g0).clamp(-g0, g0),
        dissipation: if l == 0.0 { 0.0 } else { d.max(0.0) },
        c,
        e: g0 * (l - c),
    }
}
