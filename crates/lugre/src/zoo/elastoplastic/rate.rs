//! The elasto-plastic model at finite rate (E1) for an input linear in time between samples
//! (`docs/mathematics.md#elasto-plastic-at-finite-rate`).
//!
//! On an interval the velocity `v` is constant, hence so are its sign `s`, `z_ss = g(v) /
//! sigma0` and `delta = 1 - zba / z_ss`: with `w = s z` and the length `l = |du|`, (E1) is
//! `dw/dl = 1 - alpha(w) w / z_ss`, the slow loop's (E3) with `z_max` replaced by `z_ss`. Its
//! elastic part (`w <= zba`) and the part above `z_ss` are closed forms; in the blend, with
//! `e = (z_ss - w) / z_ss` and `r = 1/h - 1/e` of (E5) (analytic on `[0, delta]`):
//!
//! ```text
//! (E8)  l / z_ss = ln(e_a / e_b) + ∫_{e_b}^{e_a} r(e) de
//! ```
//!
//! solved for `ln e_b` by a safeguarded Newton iteration (the derivative of the right side in
//! `ln e_b` is `-e_b / h(e_b)`, in `[-1, 0)`), the integral by 16-point Gauss-Legendre on
//! pieces graded toward `e = 0`: `r`'s nearest singularity is at `e ≈ -(2 delta / pi)^2`, and
//! a piece `[a, b]` is at most a quarter of its distance `a + (2 delta / pi)^2` from it and at
//! most `delta / 8` long, so the rule converges as `17.9^-32` per piece. No step crosses a
//! kink of the blend (`zba`, `z_ss`): each part is solved on its own. Working in `ln e` keeps
//! any length exact, however many `z_ss` it spans (`sigma0 = 1e8` N/m and more): `e_b`
//! underflows to 0, `w` to `z_ss`, with no step-size limit.
//!
//! At a sample the force is `F = sigma0 z + sigma1 z' + sigma2 v` with `z' = v h(w)` from (E1)
//! itself, `v` the velocity of the interval after the sample (at the last sample, the one
//! before): the value just after a kink, as `lugre simulate` reports LuGre's.

use super::{alpha, ElastoPlastic, Leg, Shape};
use crate::LuGre;

/// The positive nodes of the 16-point Gauss-Legendre rule on `[-1, 1]` and their weights
/// (`numpy.polynomial.legendre.leggauss(16)`).
const GAUSS16: [(f64, f64); 8] = [
    (0.09501250983763744, 0.18945061045506864),
    (0.2816035507792589, 0.18260341504492364),
    (0.45801677765722737, 0.16915651939500265),
    (0.6178762444026438, 0.1495959888165767),
    (0.755404408355003, 0.12462897125553407),
    (0.8656312023878318, 0.0951585116824926),
    (0.9445750230732326, 0.062253523938647456),
    (0.9894009349916499, 0.027152459411754176),
];

impl ElastoPlastic {
    /// (E1)'s force at deflection `z` moving at `v`: `sigma0 z + sigma1 z' + f(v)`, with
    /// `z' = v (1 - alpha(w) w / z_ss)`, `z_ss = g(v) / sigma0` (as `lugre dynamics` has it).
    pub(crate) fn rate_force(&self, model: &LuGre, z: f64, v: f64) -> f64 {
        let dz = if v == 0.0 {
            0.0
        } else {
            let z_ss = model.g(v) / self.sigma0;
            let w = v.signum() * z;
            v * (1.0 - alpha(w, self.zba, z_ss) * w / z_ss)
        };
        self.sigma0 * z + model.sigma1() * dz + model.f(v)
    }

    /// One step of the finite-rate stepper: from deflection `z`, the input moves by `du` at
    /// the constant velocity `v` (`du / dt`); the deflection after it and the work of the input
    /// over it, `∫ F du = sigma0 ∫ z du + sigma1 v Δz + f(v) du` (E9).
    pub(crate) fn rate_step(&self, model: &LuGre, z: f64, v: f64, du: f64) -> (f64, f64) {
        let (z_b, area) = self.interval(z, model.g(v) / self.sigma0, du);
        let work = self.sigma0 * area + model.sigma1() * v * (z_b - z) + model.f(v) * du;
        (z_b, work)
    }

    /// The energy stored in the bristles at deflection `z`: `sigma0 z^2 / 2` (E9).
    pub(crate) fn stored_energy(&self, z: f64) -> f64 {
        0.5 * self.sigma0 * z * z
    }

    /// The deflection after the input moves by `du` with the steady deflection `z_ss` of the
    /// interval's velocity, from `z`, and `∫ z du` over the move (E9).
    pub(crate) fn interval(&self, z: f64, z_ss: f64, du: f64) -> (f64, f64) {
        if du == 0.0 {
            return (z, 0.0);
        }
        let s = du.signum();
        let (w, length) = (s * z, du.abs());
        let shape = Shape::new(1.0 - self.zba / z_ss);
        let (w_b, area) = match Leg::of(w, length, self.zba, z_ss, shape.delta) {
            Leg::Elastic(w_b) => (w_b, 0.5 * (w + w_b) * length),
            // alpha = 1: w - z_ss decays as exp(-l / z_ss).
            Leg::Above => {
                let decayed = -(-length / z_ss).exp_m1();
                let w_b = z_ss + (w - z_ss) * (-length / z_ss).exp();
                (w_b, z_ss * length + (w - z_ss) * z_ss * decayed)
            }
            Leg::Blend { e_a, l } => {
                // The elastic part before the blend, then (E9) over the blend.
                let elastic = (self.zba - w).max(0.0);
                let before = 0.5 * (w + self.zba) * elastic;
                let e_b = shape.flow(e_a, l).exp();
                let deficit = (e_a - e_b) + shape.weighted(e_b, e_a, |e| e);
                (z_ss - z_ss * e_b, before + z_ss * z_ss * (l - deficit))
            }
        };
        (s * w_b, area)
    }
}

impl Shape {
    /// `ln e_b` of (E8): from `e_a` in `(0, delta]` over the length `l` (units of `z_ss`).
    fn flow(&self, e_a: f64, l: f64) -> f64 {
        let top = e_a.ln() - l;
        // r <= 0: ln e_b lies in top + [∫_0^e_a r, 0].
        let (mut lo, mut hi) = (top + self.integral(0.0, e_a), top);
        // The residual f(L) = top + ∫_{e^L}^{e_a} r - L, decreasing in L; `inside` is the
        // integral at the current L, updated by the integral over the move.
        let mut at = hi;
        let mut inside = self.integral(at.exp(), e_a);
        for _ in 0..100 {
            let f = top + inside - at;
            if f > 0.0 {
                lo = at;
            } else {
                hi = at;
            }
            let (x, s_e, _) = self.parts(at.exp());
            let newton = at + f * (1.0 + x * s_e);
            let next = if newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
            let tolerance = 2.0 * f64::EPSILON * at.abs().max(1.0);
            if (next - at).abs() <= tolerance || hi - lo <= tolerance {
                return next;
            }
            inside += self.integral(next.exp(), at.exp());
            at = next;
        }
        at
    }

    /// `∫_p^q r(e) de` (signed), `p, q` in `[0, delta]`, by 16-point Gauss-Legendre on pieces
    /// graded toward `e = 0` (see the module docs).
    fn integral(&self, p: f64, q: f64) -> f64 {
        self.weighted(p, q, |_| 1.0)
    }

    /// `∫_p^q weight(e) r(e) de` by the rule of [`Shape::integral`] (a polynomial `weight`
    /// keeps its error bound: the integrand's singularities are `r`'s).
    fn weighted(&self, p: f64, q: f64, weight: impl Fn(f64) -> f64) -> f64 {
        let (a, b, sign) = if p <= q { (p, q, 1.0) } else { (q, p, -1.0) };
        // (2 delta / pi)^2: the distance of r's nearest singularity from e = 0.
        let near = 1.0 / (self.a * self.a);
        let mut sum = 0.0;
        let mut lo = a;
        let f = |e: f64| weight(e) * self.r(e);
        while lo < b {
            let width = (0.25 * (lo + near)).min(0.125 * self.delta);
            let hi = (lo + width).min(b);
            let (m, h) = (0.5 * (lo + hi), 0.5 * (hi - lo));
            let piece: f64 = GAUSS16
                .iter()
                .map(|&(x, w)| w * (f(m - h * x) + f(m + h * x)))
                .sum();
            sum += h * piece;
            lo = hi;
        }
        sign * sum
    }
}
