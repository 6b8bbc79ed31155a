//! The hysteresis loop `y°` of the LuGre and Dahl models (paper eqs. 8-10) for any periodic
//! input, by the stable closed form of DESIGN §1.
//!
//! In the normalized variable `rho` (the variation, eq. 7) the input `psi_u` runs at unit speed
//! between turning points `u_k` at `rho_k` (eq. 12). On segment `k`, of length
//! `L_k = |u_{k+1} - u_k|` and direction `s_k = sign(u_{k+1} - u_k)`, eq. 8 integrates to
//!
//! ```text
//! y(rho_k + l) = s_k g0 + (y_k - s_k g0) exp(-a l)
//!              = y_k exp(-a l) + s_k sigma0 l phi(a l)          phi(z) = (1 - exp(-z)) / z
//! ```
//!
//! with `a = sigma0 / g(0)`. The second form never multiplies by `g0`, which is huge when `a`
//! is tiny, and every exponent is `<= 0`: nothing overflows at any stiffness (the paper's
//! eq. 13 multiplies `exp(a rho_i)` factors and overflows once `a rho_4 > ~709`).
//!
//! One period is the affine map `y_N = E y_0 + c`, `E = exp(-a P)`; the periodic solution
//! (eq. 10) is `y°(0) = c / (1 - E)`. For `a P > 1` `c` is the recursion run from 0. For
//! `a P <= 1` that sum cancels (its terms are `O(a)`, the sum `O(a^2)`), so the identity
//! `sum_k s_k L_k = 0` (the period closes) is subtracted analytically:
//!
//! ```text
//! y°(0) = -sigma0 / (P phi(aP)) * sum_k s_k L_k [R_k phi(a R_k) + L_k h(a L_k) exp(-a R_k)]
//! ```
//!
//! with `R_k = P - rho_{k+1}` and `h(z) = (1 - phi(z)) / z`.
//!
//! Energy. Along the loop `dy/drho = a (s g0 - y)`, so `y dpsi = d(y^2 / (2 sigma0)) + y^2 / g0
//! drho`: over any arc the work `W = integral y dpsi` is the change of the stored energy
//! `dV = (y_end^2 - y_start^2) / (2 sigma0)` plus the dissipation `D = (1/g0) integral y^2 drho`.
//! `W` is reported as `dV + D`: summing `W`'s own closed form `sigma0 l^2 h(z) + s y_k l phi(z)`
//! piece by piece cancels (its terms are `O(sigma0 l^2)`, the elastic energy that comes back,
//! while `W` is `O(a sigma0 P^3)` for small `a P`), whereas `D`'s terms are all positive:
//!
//! ```text
//! D over a piece = a y_k^2 l phi(2z) / sigma0 + 2 s y_k l (phi(z) - phi(2z)) + sigma0 l^2 q(z)/z
//! ```
//!
//! with `z = a l` and `q(z) = 1 - 2 phi(z) + phi(2z)`. `dV` needs the closure gap
//! `y_end - y_start`, which is `O(a)` on loops shorter than `1/a`; it is computed without
//! taking the difference of the two values (`arc_energy.rs`). The sums over every loop's
//! arc are carried on the rainflow stack in one pass over the period ([`crate::LoopTable`]),
//! which also writes `y°` at the turning points: each piece is evaluated once.

use crate::error::{InputError, LoopError};
use crate::input::TurningPoints;
use crate::loop_table::{LoopTable, Period};
use crate::memory::column;
use crate::minor::canonical_start;
use crate::model::RateIndependent;
use crate::numerics::{h, one_minus_exp, phi, PhiFamily};

/// The exact solution of `w' = -r w + q` with constant `r >= 0` and `q` over a duration
/// `tau`, from `w0`: `w0 exp(-c) + d phi(c)` with `c = r tau`, `d = q tau` and
/// `phi(c) = (1 - exp(-c)) / c`.
///
/// This is eq. 8 on one segment of the normalized input (`w = y°`, `c = a l`,
/// `d = s sigma0 l`), and eq. 5 on one segment of a piecewise-linear input (`w = z`,
/// `c = sigma0 |du| / g(v / gamma)`, `d = du`, see [`crate::simulate`]): one piece of code for
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
/// which rounds once. The Padé form is inlined arithmetic with one division: the simulation's
/// per-sample loop runs about 12 % faster with it than with the library's `expm1`.
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

/// `y` a length `l` along a piece of the normalized input with direction `s` (+-1), from `y_k`
/// at its start (eq. 8 on one piece). The per-piece closed forms below are shared by the
/// periodic loop and by histories ([`crate::cycles`]).
#[inline]
pub(crate) fn advance(model: RateIndependent, y_k: f64, s: f64, l: f64) -> f64 {
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
pub(crate) fn piece(model: RateIndependent, y_k: f64, s: f64, l: f64) -> Piece {
    piece_with(model, y_k, s, l, &PhiFamily::new(model.a() * l))
}

/// [`piece`] with the family at `z = a l` already evaluated (in blocks, [`crate::numerics::PhiBlock`]).
#[inline(always)]
pub(crate) fn piece_with(model: RateIndependent, y_k: f64, s: f64, l: f64, f: &PhiFamily) -> Piece {
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
fn saturated_piece(model: RateIndependent, y_k: f64, s: f64, l: f64) -> Piece {
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

/// A point of the loop: the normalized variable, the input and the output there.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct LoopPoint {
    pub rho: f64,
    pub u: f64,
    pub y: f64,
}

/// The periodic steady state `y°` in the rate-independent limit, for one model and input.
#[derive(Debug, Clone)]
pub struct HysteresisLoop {
    model: RateIndependent,
    /// Turning points `u_k`, `k < n`.
    u: Vec<f64>,
    /// `rho_k`, `k = 0..=n`; `rho_n` is the period.
    rho: Vec<f64>,
    /// `y°(rho_k)`, `k = 0..=n`; `y_n = y_0`.
    y: Vec<f64>,
    /// Every loop, with energies.
    loops: LoopTable,
}

impl HysteresisLoop {
    /// The loop of `model` for the periodic input `input`.
    pub fn new(model: RateIndependent, input: &TurningPoints) -> Result<Self, InputError> {
        let n = input.len();
        let mut u = column(n);
        u.extend_from_slice(input.values());
        let mut rho = column(n + 1);
        // The running sum stays in a register (not re-read from the vector each step).
        let mut total = 0.0;
        rho.push(total);
        for (k, &u_k) in u.iter().enumerate() {
            let next = if k + 1 == n { u[0] } else { u[k + 1] };
            total += (next - u_k).abs();
            rho.push(total);
        }
        if !rho[n].is_finite() {
            return Err(InputError::VariationOverflow);
        }
        let r = canonical_start(&u);
        let mut hl = Self {
            model,
            u,
            rho,
            y: {
                let mut y = column(n + 1);
                y.resize(n + 1, 0.0);
                y
            },
            loops: LoopTable::default(),
        };
        let period = Period {
            model,
            u: &hl.u,
            rho: &hl.rho,
            r,
            y_r: hl.periodic_value(r),
        };
        hl.loops = period.loops(&mut hl.y);
        Ok(hl)
    }

    /// Number of turning points (segments) in one period.
    pub fn len(&self) -> usize {
        self.u.len()
    }

    pub fn is_empty(&self) -> bool {
        self.u.is_empty()
    }

    pub fn model(&self) -> RateIndependent {
        self.model
    }

    /// The period `P = rho_u(T)`, the total variation of the input over one period.
    pub fn period(&self) -> f64 {
        self.rho[self.len()]
    }

    /// Turning points `u_k`.
    pub fn turning_points(&self) -> &[f64] {
        &self.u
    }

    /// `rho_k` of the turning points (`k < n`).
    pub fn turning_rho(&self) -> &[f64] {
        &self.rho[..self.len()]
    }

    /// `y°(rho_k)` at the turning points (`k < n`).
    pub fn turning_y(&self) -> &[f64] {
        &self.y[..self.len()]
    }

    /// The loop at the turning points.
    pub fn turning_loop_points(&self) -> Vec<LoopPoint> {
        (0..self.len())
            .map(|k| LoopPoint {
                rho: self.rho[k],
                u: self.u[k],
                y: self.y[k],
            })
            .collect()
    }

    /// `k + 1` around the period (a compare, not an integer division, on the per-loop path).
    #[inline]
    fn next(&self, k: usize) -> usize {
        if k + 1 == self.len() {
            0
        } else {
            k + 1
        }
    }

    /// `s_k`, the direction of segment `k`.
    #[inline]
    pub(crate) fn direction(&self, k: usize) -> f64 {
        let next = self.u[self.next(k)];
        if next > self.u[k] {
            1.0
        } else {
            -1.0
        }
    }

    /// `L_k`, the length of segment `k`.
    #[inline]
    pub(crate) fn segment_length(&self, k: usize) -> f64 {
        (self.u[self.next(k)] - self.u[k]).abs()
    }

    /// `y°` at turning point `first` (eq. 10, the period started there) by the stable forms of
    /// the module docs.
    fn periodic_value(&self, first: usize) -> f64 {
        let n = self.len();
        let a = self.model.a();
        let sigma0 = self.model.sigma0();
        let p = self.period();
        let ap = a * p;
        // Segment `i` of the period started at `first`.
        let segment = |i: usize| {
            if first + i >= n {
                first + i - n
            } else {
                first + i
            }
        };
        if ap > 1.0 {
            // The recursion forgets its start like exp(-a rho): what it carries from before the
            // last stretch of `a rho > 750` is scaled by exp(-750) = 0 in f64, so it starts
            // there (for a long period that is a few segments, not all n).
            let mut from = n;
            let mut tail = 0.0;
            while from > 0 && a * tail <= 750.0 {
                from -= 1;
                tail += self.segment_length(segment(from));
            }
            let mut c = 0.0;
            for i in from..n {
                let k = segment(i);
                c = self.advance(c, k, self.segment_length(k));
            }
            c / one_minus_exp(ap)
        } else {
            // The sum's terms are products of two lengths: with the lengths scaled by a power
            // of two near 1/P they neither underflow (P = 1e-300) nor overflow, and elsewhere
            // the result is bit for bit what it is unscaled.
            let scale = 2f64.powi(-(p.log2().floor().clamp(-1000.0, 1000.0) as i32));
            let mut tail = 0.0; // R_k = P - rho_{k+1}, summed from the end
            let mut sum = 0.0; // scale^2 times the sum of the module docs
            for i in (0..n).rev() {
                let k = segment(i);
                let l = self.segment_length(k);
                let at = a * tail;
                let (ls, ts) = (l * scale, tail * scale);
                sum += self.direction(k) * ls * (ts * phi(at) + ls * h(a * l) * (-at).exp());
                tail += l;
            }
            -sigma0 * sum / (p * scale * phi(ap) * scale)
        }
    }

    /// `y°` a length `l` into segment `k`, from `y_k` there.
    #[inline]
    fn advance(&self, y_k: f64, k: usize, l: f64) -> f64 {
        advance(self.model, y_k, self.direction(k), l)
    }

    /// Every loop as columns, in the order they close (see [`LoopTable`]).
    pub fn loop_table(&self) -> &LoopTable {
        &self.loops
    }

    /// The work `integral y° dpsi` over one period: the energy dissipated per cycle (the stored
    /// energy returns to its start, so it equals the dissipation over the period).
    pub fn work_per_period(&self) -> f64 {
        self.loops.dissipation()[self.loops.major()]
    }

    /// The segment holding `rho` (reduced to `[0, P)`) and the offset into it.
    fn locate(&self, rho: f64) -> (usize, f64) {
        let p = self.period();
        let mut r = rho.rem_euclid(p);
        if r >= p {
            r = 0.0; // rem_euclid can round up to p
        }
        let k = self.rho.partition_point(|&x| x <= r).saturating_sub(1);
        let k = k.min(self.len() - 1);
        (k, (r - self.rho[k]).max(0.0))
    }

    /// The normalized input `psi_u(rho)` (eq. 12), periodic in `rho`; NaN for a non-finite
    /// `rho`.
    pub fn psi_at(&self, rho: f64) -> f64 {
        if !rho.is_finite() {
            return f64::NAN;
        }
        let (k, l) = self.locate(rho);
        self.u[k] + self.direction(k) * l
    }

    /// `y°(rho)`, periodic in `rho`; NaN for a non-finite `rho`.
    pub fn y_at(&self, rho: f64) -> f64 {
        if !rho.is_finite() {
            return f64::NAN;
        }
        let (k, l) = self.locate(rho);
        self.advance(self.y[k], k, l)
    }

    /// `(rho, psi_u(rho), y°(rho))` with `rho` as given (not reduced); NaN for a non-finite
    /// `rho`.
    pub fn point_at(&self, rho: f64) -> LoopPoint {
        if !rho.is_finite() {
            return LoopPoint {
                rho,
                u: f64::NAN,
                y: f64::NAN,
            };
        }
        let (k, l) = self.locate(rho);
        LoopPoint {
            rho,
            u: self.u[k] + self.direction(k) * l,
            y: self.advance(self.y[k], k, l),
        }
    }

    /// `n >= 2` points evenly spaced over one period, both ends included (`rho = 0` and `P`).
    pub fn sample(&self, n: usize) -> Vec<LoopPoint> {
        let n = n.max(2);
        let p = self.period();
        (0..n)
            .map(|i| {
                let rho = if i == n - 1 {
                    p
                } else {
                    p * (i as f64 / (n - 1) as f64)
                };
                self.point_at(rho)
            })
            .collect()
    }

    /// Checks that every value a report would print is finite.
    pub fn check_finite(&self) -> Result<(), LoopError> {
        if !self.y.iter().all(|v| v.is_finite()) {
            return Err(LoopError::Overflow { what: "y°" });
        }
        if !self.work_per_period().is_finite() {
            return Err(LoopError::Overflow {
                what: "the work per period",
            });
        }
        Ok(())
    }
}
