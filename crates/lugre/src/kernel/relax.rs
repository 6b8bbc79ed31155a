//! One step of a linear relaxation, exactly: the primitive behind the loop's closed form
//! (eq. 8 on one piece of the normalized input) and the exact simulation (eq. 5 on one segment
//! of a piecewise-linear input); `docs/mathematics.md#the-stable-closed-form` and
//! `#piecewise-linear-inputs-in-closed-form`.

/// The exact solution of `w' = -r w + q` with constant `r >= 0` and `q` over a duration
/// `tau`, from `w0`: `w0 exp(-c) + d phi(c)` with `c = r tau`, `d = q tau` and
/// `phi(c) = (1 - exp(-c)) / c`.
///
/// This is eq. 8 on one segment of the normalized input (`w = y°`, `c = a l`,
/// `d = s sigma0 l`), and eq. 5 on one segment of a piecewise-linear input (`w = z`,
/// `c = sigma0 |du| / g(v / gamma)`, `d = du`): one piece of code for
/// both. The form never divides by `r` (so `r = 0` and tiny `r` are exact), its only exponent,
/// `-c`, is `<= 0`, and nothing cancels. `c = inf` gives `w = 0` for finite `d`.
#[inline]
pub fn relax(w0: f64, c: f64, d: f64) -> f64 {
    let (e, one_minus_e) = decay(c);
    let phi = if c > 0.0 { one_minus_e / c } else { 1.0 };
    w0 * e + d * phi
}

/// [`relax`] written with the state relaxed to, `w_inf = q / r = d / c`:
/// `w0 exp(-c) + w_inf (1 - exp(-c))`. Where `w_inf` is known without dividing by `c` (eq. 5:
/// `w_inf = sign(v) g(v / gamma) / sigma0`) this saves the division on the critical path of the
/// simulation's per-sample loop. Equally exact: a product of two accurate factors.
#[inline]
pub fn relax_toward(w0: f64, c: f64, w_inf: f64) -> f64 {
    let (e, one_minus_e) = decay(c);
    w0 * e + w_inf * one_minus_e
}

/// `(exp(-c), 1 - exp(-c))` for `c >= 0`, within about 1 and 3 ulps, from a single
/// exponential: `exp` for `c > 1/4`, where `exp(-c) < 0.78` and `1 - exp(-c)` loses at most two
/// bits to the subtraction; below, `expm1(-c)` from its [6/6] Padé approximant (truncation error
/// under `1e-20` relative at `c = 1/4`, so only the dozen roundings count), and `1 + expm1(-c)`,
/// which rounds once. The Padé form is inlined arithmetic with one division, cheaper on the
/// simulation's per-sample loop than the library's `expm1` (BENCHMARKS.md).
#[inline]
pub fn decay(c: f64) -> (f64, f64) {
    if c > 0.25 {
        let e = (-c).exp();
        (e, 1.0 - e)
    } else {
        let m = expm1_pade(-c);
        (1.0 + m, -m)
    }
}

/// `expm1(x)` for `|x| <= 1/4`: `e^x = P(x) / P(-x)` with `P` the numerator of the [6/6] Padé
/// approximant of `exp` (coefficients `(12 - k)! 6! / (12! k! (6 - k)!)`). With
/// `P(x) = E(x^2) + x O(x^2)`, `expm1(x) = 2 x O / (E - x O)`: no cancellation, exact at 0.
#[inline]
fn expm1_pade(x: f64) -> f64 {
    let y = x * x;
    let even = 1.0 + y * (5.0 / 44.0 + y * (1.0 / 792.0 + y * (1.0 / 665_280.0)));
    let odd = x * (0.5 + y * (1.0 / 66.0 + y * (1.0 / 15_840.0)));
    2.0 * odd / (even - odd)
}
