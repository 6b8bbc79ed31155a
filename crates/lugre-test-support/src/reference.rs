//! Closed forms written directly from their definitions, to check the library's kernel (which
//! uses other forms for speed and range) against.

/// The exact solution of `w' = -r w + q` over a duration `tau` from `w0`, with `c = r tau` and
/// `d = q tau`: `w0 exp(-c) + d (1 - exp(-c)) / c` (`w0 + d` at `c = 0`), by the standard
/// library's `exp` and `exp_m1`.
pub fn relax(w0: f64, c: f64, d: f64) -> f64 {
    let phi = if c > 0.0 { -(-c).exp_m1() / c } else { 1.0 };
    w0 * (-c).exp() + d * phi
}
