//! The normalized Bouc-Wen model (Ikhouane and Rodellar, "Systems with Hysteresis", Wiley
//! 2007, ch. 2; Ikhouane, Mañosa and Rodellar, "Dynamic properties of the hysteretic Bouc-Wen
//! model", Systems & Control Letters 56, 2007), its exact segment map and energies
//! (`docs/mathematics.md#bouc-wen`).
//!
//! Input `u` (m), output `F` (N), state `w` (1), parameters `kx` (N/m), `kw` (N), `rho` (1/m),
//! `sigma` (1), `n` (1):
//!
//! ```text
//! (B1)  F = kx u + kw w
//! (B2)  w' = rho (u' - sigma |u'| |w|^(n-1) w + (sigma - 1) u' |w|^n)
//! ```
//!
//! The classical form `z' = A u' - beta |u'| |z|^(n-1) z - gamma u' |z|^n`,
//! `F = alpha k u + (1 - alpha) k z` maps onto it by `z0 = (A / (beta + gamma))^(1/n)`,
//! `w = z / z0`, `rho = A / z0`, `sigma = beta / (beta + gamma)`, `kx = alpha k`,
//! `kw = (1 - alpha) k z0`.
//!
//! # Domains
//!
//! `rho > 0`, `sigma >= 1/2`, `n >= 1` are the class of Ikhouane, Mañosa and Rodellar that is
//! bounded-input bounded-output for every initial state (`A > 0`, `beta + gamma > 0`,
//! `beta >= gamma`; `n >= 1` makes (B2) Lipschitz, so its solution unique); `sigma >= 1/2` is
//! also exactly what makes the dissipation (B5) nonnegative. `kw > 0`, `kx >= 0` (`kx = 0`:
//! no elastic part, the Dahl model when `n = 1`, `sigma = 1`). The state stays in
//! `[-1, 1]` ([`SingleState::bounds`]).
//!
//! # Segment map
//!
//! On a monotone segment of direction `s = ±1` let `v = s w` and `tau = rho s (u - u_a) >= 0`:
//!
//! ```text
//! (B3)  dv/dtau = h(v) = 1 - v^n            (v >= 0)
//!                      = 1 + c |v|^n        (v < 0),      c = 2 sigma - 1 >= 0
//! ```
//!
//! `v` rises to 1 without reaching it. With `V` the stored energy, the work `W = ∫ F du`
//! splits into
//!
//! ```text
//! (B4)  V = kx u²/2 + kw w²/(2 rho)
//! (B5)  D = W - ΔV = (kw / rho) ∫ phi(v) dtau,   phi = v^(n+1) (v >= 0), c |v|^(n+1) (v < 0)
//! ```
//!
//! (`w dw/rho = w h du` on the segment, and `w - w h(w) = phi`.) For `n = 1` the map is in
//! closed form, `t = -v` on the negative part, `K(t) = ∫_0^t c s²/(1 + c s) ds`:
//!
//! ```text
//! (B6)  v < 0:  1 + c t = (1 + c t_a) e^(-c tau),  reaching 0 at tau_0 = ln(1 + c t_a) / c,
//!               D rho / kw = K(t_a) - K(t_b),  K(t) = (ln(1 + c t) - c t + (c t)²/2) / c²
//! (B7)  v >= 0: 1 - v = (1 - v_a) e^(-tau),
//!               D rho / kw = tau - 2 (1 - v_a)(1 - e^(-tau)) + (1 - v_a)² (1 - e^(-2 tau)) / 2
//! ```
//!
//! each through `expm1`/`ln_1p` (no exponential of a growing argument).
//!
//! # Any n >= 1
//!
//! The segment's exact relation between `tau` and `v`, and the dissipation, are integrals of
//! known functions of `v`:
//!
//! ```text
//! (B8)  tau = T(v_b) - T(v_a),   T' = 1 / h,     D rho / kw = E(v_b) - E(v_a),   E' = phi / h
//! ```
//!
//! On the negative part (`t = -v`), `T_-(t) = ∫_0^t ds / (1 + c s^n)` and
//! `E_-(t) = ∫_0^t c s^(n+1) / (1 + c s^n) ds` are bounded; on the positive part `T` and `E`
//! grow like `-ln(1 - v) / n`, so with `e = 1 - v`, `x = -ln e`:
//!
//! ```text
//! (B9)  T(v) = x / n + R(e),   E(v) = T(v) + Q(e),
//!       R' = -(n e - P_n(e)) / (n e P_n(e)),   Q' = P_(n+1)(e) / P_n(e),   P_m = 1 - (1 - e)^m
//! ```
//!
//! with `R`, `Q` bounded and analytic in `e` near 0. Near `v = 0`, where `|v|^n` is not smooth,
//! each function is its power series in `y = c t^n` or `y = v^n`, used while `y <= 1/8`
//! (a geometric series of ratio 1/8: 21 terms, coefficients precomputed, reach 1e-18):
//!
//! ```text
//! (B10) T_-(t) = t sum_k (-y)^k / (kn + 1),   E_-(t) = t² y sum_k (-y)^k / ((k+1) n + 2)
//!       T(v) = v sum_k y^k / (kn + 1),        Q = -v - v sum_(k>=1) y^k (1/(kn + 1) - v/(kn + 2))
//! ```
//!
//! and elsewhere piecewise Chebyshev antiderivatives of the integrands, built in
//! [`BoucWen::new`] ([`table`]): their dropped coefficients are below `1e-15 n`, so `T`, `E`,
//! `R`, `Q` carry an absolute error of at most ~`1e-15 n` (the integrands are O(1) on ranges of
//! length <= 1). At run time their values are the elasto-plastic model's degree-16 pieces fitted
//! to them (half the evaluation time), within `5e-15` of their largest value more. Two
//! quantities need a root: `v_b` from (B8) on the negative part, Newton in `t` on
//! `T_-` (concave: started left of the root from the bound `t_b >= t_a - tau (1 + c t_a^n)`,
//! its iterates rise monotonically), and on the positive part Newton in `x` on
//! `x/n + R(e^(-x))` (concave, slope `e / P_n(e)` in `[1/n, 1]`, started at `x_a`):
//!
//! ```text
//! (B11) the root to 1e-14 relative in x (1e-15 in t), so |Δw| <= 1e-14 + the tables' error;
//!       |ΔD| <= (kw / rho) (4 eps tau + 4e-15)
//! ```
//!
//! On the positive part that root is tabulated once per model (no Newton at run time): with
//! `s = T^n` below `v0` and `Y = e^(-n (T - T(v0)))` above,
//!
//! ```text
//! (B12) v = T g(s),  E = T^(n+2) k(s)          (T <= T(v0))
//!       1 - v = (1 - v0) Y phi(Y),  E = T + Q   (T > T(v0))
//! ```
//!
//! `g`, `k`, `phi` analytic, piecewise Chebyshev of degree 16 to `5e-15` of their largest
//! coefficient (the elasto-plastic model's tables), built from the Newton roots above: a positive
//! segment is `T_b = T(v_a) + tau`, one `powf` or `exp` and one table pair, within `1.6e-15` of
//! the roots in `v` and `6.2e-15 (1 + tau)` in `D rho / kw` (checked on 3600 segments,
//! `n` in `[1 + 1e-9, 100]`); the bound (B11) holds with `5e-15` added to `|Δw|`.
//! The dissipation on the positive part is `E(T_b) - E(T_a)` (no quadrature at run
//! time).
//!
//! The negative part's root is tabulated the same way: `t_b` and `E_-(t_b)` are functions of
//! `T_b = T_-(t_a) - tau` alone, with `s = c T_-^n` below `t0` (`c t0^n = 1/8`) and `T_-` itself
//! above:
//!
//! ```text
//! (B13) t = T_- g(s),  E_- = T_-² s k(s)        (T_- <= T_-(t0))
//!       t, E_- piecewise in T_-                  (T_-(t0) < T_- <= T_-(1), c <= 1e4)
//! ```
//!
//! (`g`, `k` analytic in `s` by the implicit function theorem on (B10); above `t0` the slope
//! `dt/dT_- = 1 + c t^n` is at most `1 + c`, the pieces grading toward `T_-(1)`), built from
//! Newton's roots: a negative segment is one forward table pair, one `powf` or none, and one
//! table pair. Against Newton (`the_negative_inverse_follows_newton`, 201 segments for each of
//! nine `n` and seven `c` in `[1e-3, 1e4]`): `|Δt| <= 2.1e-15 (1 + T_- (1 + c t^n))` (an
//! error `δ` in `T_-`, which both carry, moves `t` by `δ (1 + c t^n)`: the map's own
//! conditioning) and `|ΔE_-| <= 7.3e-15`. For `c > 1e4` (`sigma > 5000`) the root above `t0`
//! stays Newton's. With the tables (`c <= 7`, `sigma <= 4`, covers the published fits):
//!
//! ```text
//! (B14) |Δw| <= 5e-14 + 1e-15 n,   |ΔD| <= (kw / rho) (4 eps tau + 4e-15 n + 1e-14 (1 + tau))
//! ```
//!
//! and for larger `c` the first term grows with the conditioning, to at most `5e-15 (1 + c)`. Its absolute error is a few rounding units of `kw |Δu|` (relative to the segment's
//! work scale, not to `D`, which vanishes at the rate `tau^3` on a short segment from `w = 0`).

mod table;

use super::elastoplastic::chebyshev::Table;
use super::{SingleState, ZooLoop};
use crate::error::ZooError;
use crate::input::TurningPoints;
use table::Antiderivatives;

/// The largest `n` accepted: `|v|^n` carries `n` rounding units, so the tables (B10) hold
/// `T`, `E` to `1e-15 n` (1e-13 at this bound); beyond it the model is the elastic-perfectly
/// plastic limit in all but name.
pub const MAX_EXPONENT: f64 = 100.0;

/// The normalized Bouc-Wen model (B1-B2) with validated parameters.
#[derive(Debug, Clone, PartialEq)]
pub struct BoucWen {
    kx: f64,
    kw: f64,
    rho: f64,
    sigma: f64,
    n: f64,
    shape: Shape,
}

/// How the segment map is evaluated: closed form (B6-B7) or the tables (B8-B13).
#[derive(Debug, Clone, PartialEq)]
enum Shape {
    Linear { c: f64 },
    General(Box<General>),
}

impl BoucWen {
    /// `F = kx u + kw w`, `w' = rho (u' - sigma |u'| |w|^(n-1) w + (sigma - 1) u' |w|^n)`.
    ///
    /// # Errors
    /// [`ZooError::Domain`] naming the first parameter outside its domain: `kx` finite `>= 0`,
    /// `kw` finite `> 0`, `rho` finite `> 0`, `sigma` finite `>= 1/2` (with `2 sigma - 1`
    /// finite), `n` finite in `[1, MAX_EXPONENT]`.
    pub fn new(kx: f64, kw: f64, rho: f64, sigma: f64, n: f64) -> Result<Self, ZooError> {
        check(
            "kx",
            kx,
            kx.is_finite() && kx >= 0.0,
            "a finite number >= 0 (N/m)",
        )?;
        check(
            "kw",
            kw,
            kw.is_finite() && kw > 0.0,
            "a finite number > 0 (N)",
        )?;
        check(
            "rho",
            rho,
            rho.is_finite() && rho > 0.0,
            "a finite number > 0 (1/m; A > 0 in the classical form)",
        )?;
        check(
            "sigma",
            sigma,
            sigma.is_finite() && sigma >= 0.5 && (2.0 * sigma - 1.0).is_finite(),
            "a finite number >= 1/2 (beta >= gamma: bounded output and nonnegative dissipation)",
        )?;
        check(
            "n",
            n,
            n.is_finite() && (1.0..=MAX_EXPONENT).contains(&n),
            "a finite number in [1, 100] (n >= 1: a unique solution; n <= 100: the segment map to 1e-13)",
        )?;
        let c = 2.0 * sigma - 1.0;
        let shape = if n == 1.0 {
            Shape::Linear { c }
        } else {
            Shape::General(Box::new(General::new(n, c).ok_or(ZooError::Overflow {
                what: "the tables of the segment map",
            })?))
        };
        Ok(Self {
            kx,
            kw,
            rho,
            sigma,
            n,
            shape,
        })
    }

    /// The elastic stiffness `kx` (N/m).
    pub fn kx(&self) -> f64 {
        self.kx
    }

    /// The hysteretic force scale `kw` (N).
    pub fn kw(&self) -> f64 {
        self.kw
    }

    /// The rate `rho` (1/m) at which `w` approaches ±1.
    pub fn rho(&self) -> f64 {
        self.rho
    }

    /// The shape parameter `sigma` (1).
    pub fn sigma(&self) -> f64 {
        self.sigma
    }

    /// The exponent `n` (1).
    pub fn n(&self) -> f64 {
        self.n
    }

    /// The force at each turning point, from `w = w0` at `u0` (`w0` clamped to `[-1, 1]`).
    pub fn response(&self, u0: f64, w0: f64, turning: &[f64]) -> Vec<f64> {
        let (mut u, mut w) = (u0, w0.clamp(-1.0, 1.0));
        turning
            .iter()
            .map(|&to| {
                (w, _) = self.segment(u, w, to);
                u = to;
                SingleState::force(self, u, w)
            })
            .collect()
    }

    /// The loop and every minor loop for the periodic input `input`.
    ///
    /// # Errors
    /// See [`ZooLoop::new`].
    pub fn loops(&self, input: &TurningPoints) -> Result<ZooLoop, ZooError> {
        ZooLoop::new(self, input)
    }

    /// `|v|^n`.
    #[inline]
    fn power(&self, x: f64) -> f64 {
        if self.n == 1.0 {
            x.abs()
        } else {
            x.abs().powf(self.n)
        }
    }
}

/// `Ok` when `ok`, else the domain error of `name`.
fn check(
    name: &'static str,
    value: f64,
    ok: bool,
    condition: &'static str,
) -> Result<(), ZooError> {
    if ok {
        Ok(())
    } else {
        Err(ZooError::Domain {
            name,
            value,
            condition: condition.into(),
        })
    }
}

impl SingleState for BoucWen {
    #[inline]
    fn force(&self, u: f64, w: f64) -> f64 {
        self.kx * u + self.kw * w
    }

    #[inline]
    fn stored_energy(&self, u: f64, w: f64) -> f64 {
        0.5 * (self.kx * u * u + self.kw * w * w / self.rho)
    }

    type Start = SegmentStart;

    /// Where `v_a = s w_a` lies on the segment's relation (B6) or (B8).
    #[inline]
    fn start(&self, w_a: f64, up: bool) -> SegmentStart {
        let v = direct(w_a, if up { 1.0 } else { -1.0 });
        match &self.shape {
            Shape::Linear { c } => linear_start(*c, v),
            Shape::General(g) => g.start(v),
        }
    }

    /// The state at `u_b` and the dissipation (B5), by (B6-B7) for `n = 1` and (B8-B13)
    /// otherwise.
    #[inline]
    fn segment_from(&self, start: &SegmentStart, u_a: f64, w_a: f64, u_b: f64) -> (f64, f64) {
        if u_b == u_a || u_b.is_nan() || u_a.is_nan() {
            return (w_a, 0.0);
        }
        let s = if u_b > u_a { 1.0 } else { -1.0 };
        let tau = self.rho * (u_b - u_a).abs();
        let v_a = direct(w_a, s);
        let (v_b, d) = match &self.shape {
            Shape::Linear { c } => linear(*c, v_a, start, tau),
            Shape::General(g) => g.segment(v_a, start, tau),
        };
        (s * v_b, (self.kw / self.rho * d).max(0.0))
    }

    /// `rho h(s w)` (B3).
    #[inline]
    fn slope(&self, w: f64, up: bool) -> f64 {
        let v = if up { w } else { -w };
        let c = 2.0 * self.sigma - 1.0;
        let h = if v >= 0.0 {
            1.0 - self.power(v)
        } else {
            1.0 + c * self.power(v)
        };
        self.rho * h
    }

    fn bounds(&self) -> (f64, f64) {
        (-1.0, 1.0)
    }
}

/// `K(t) = ∫_0^t c s²/(1 + c s) ds` (B6) as `c t³ g(c t)`, `g(x) = (ln(1+x) - x + x²/2)/x³`,
/// given `l = ln(1 + c t)`: the series `1/3 - x/4 + x²/5 - ...` below `x = 1/4` (where the
/// closed form cancels).
fn dahl_loss(c: f64, t: f64, l: f64) -> f64 {
    let x = c * t;
    let g = if x < 0.25 {
        let (mut sum, mut power) = (0.0, 1.0f64);
        for k in 3..40 {
            sum += power / f64::from(k);
            power *= -x;
            if power.abs() < 1e-17 {
                break;
            }
        }
        sum
    } else {
        (l - x + 0.5 * x * x) / (x * x * x)
    };
    c * t * t * t * g
}

/// `v = s w` on a segment of direction `s`, `w` outside `[-1, 1]` taken at the nearest bound.
#[inline]
fn direct(w: f64, s: f64) -> f64 {
    (s * w).clamp(-1.0, 1.0)
}

/// Where a segment from `v = s w_a` starts on its exact relation, what every segment from
/// there in that direction shares (two numbers, as the periodic solver keeps one per
/// segment): `at` is `T_-(t_a)` for `v < 0` and `T(v)` for `0 < v < 1` (B8), or for `n = 1`
/// `ln(1 + c t_a)` (B6); `loss` is `E_-(t_a)`, `E(v)` or `K(t_a)`; zeros where unused.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct SegmentStart {
    at: f64,
    loss: f64,
}

/// [`SegmentStart`] for `n = 1` (B6): one `ln_1p` on the negative part.
#[inline]
fn linear_start(c: f64, v: f64) -> SegmentStart {
    if v >= 0.0 {
        return SegmentStart::default();
    }
    let t = -v;
    let log = (c * t).ln_1p();
    SegmentStart {
        at: log,
        loss: dahl_loss(c, t, log),
    }
}

/// The segment map for `n = 1` (B6-B7): `v_b` and `D rho / kw` from `start` after `tau`. One
/// `expm1` on the negative part, one on the positive part: on the
/// negative part `ln(1 + c t_b) = ln(1 + c t_a) - c tau` and `e^(-c tau) = 1 + expm1(-c tau)`
/// (absolute errors of a few rounding units of `t_a`, the bound (B11) of `w`); on the positive
/// part `1 - e^(-2 tau) = m (2 - m)`, `m = 1 - e^(-tau)`.
#[inline]
fn linear(c: f64, v_a: f64, start: &SegmentStart, tau: f64) -> (f64, f64) {
    let (mut v, mut tau, mut d) = (v_a, tau, 0.0);
    if v < 0.0 {
        let t = -v;
        let (x, l, loss_a) = (c * t, start.at, start.loss);
        let reach = if x == 0.0 { t } else { t * (l / x) };
        if tau < reach {
            let (ct, m) = (c * tau, (-c * tau).exp_m1());
            // (1 - e^(-c tau)) / c, tau at c = 0.
            let ratio = if ct == 0.0 { tau } else { tau * (-m / ct) };
            let t_b = (t + t * m - ratio).max(0.0);
            return (-t_b, loss_a - dahl_loss(c, t_b, (l - ct).max(0.0)));
        }
        d = loss_a;
        tau -= reach;
        v = 0.0;
    }
    let e_a = 1.0 - v;
    let m1 = -(-tau).exp_m1();
    let m2 = m1 * (2.0 - m1);
    let v_b = (v + e_a * m1).min(1.0);
    (v_b, d + tau - 2.0 * e_a * m1 + 0.5 * e_a * e_a * m2)
}

/// The tables of (B8-B10) for one `(n, c)`.
#[derive(Debug, Clone, PartialEq)]
struct General {
    n: f64,
    c: f64,
    /// The negative part's series (B10) holds on `t <= t0`, the table on `[t0, 1]`.
    t0: f64,
    neg: Option<Table<2>>,
    /// `(T_-, E_-)` at `t0`.
    neg_at_t0: (f64, f64),
    series: Series,
    /// The positive part's series holds on `v <= v0`, the table in `e` on `[0, 1 - v0]`.
    v0: f64,
    pos: Table<2>,
    /// The inverse (B12): `T(v0)`, and `(g, k)` of `s = T^n` on `[0, T(v0)^n]`.
    t0_pos: f64,
    near: Table<2>,
    /// `(phi, Q)` of `Y = e^(-n (T - T(v0)))` on `[0, 1]`.
    far: Table<2>,
    /// The negative part's inverse (B13): `(g, k)` of `s = c T_-^n` on `[0, c T_-(t0)^n]`.
    neg_near: Table<2>,
    /// `(t, E_-)` of `T_-` on `[T_-(t0), T_-(1)]`; `None` when `t0 = 1` or `c > NEG_TABLE_C`
    /// (Newton (B11) there).
    neg_far: Option<Table<2>>,
}

/// The largest `c = 2 sigma - 1` for which the negative part's inverse above the series
/// (`t` in `[t0, 1]`) is tabulated: its slope `dt/dT_- = 1 + c t^n` grows to `1 + c`, so the
/// pieces grade toward `T_-(1)` in about `log2 c` halvings; beyond this bound (`sigma > 5000`,
/// far outside published fits) the root stays Newton's.
const NEG_TABLE_C: f64 = 1e4;

/// `P_m(e) = 1 - (1 - e)^m`, accurate for small `e`.
#[inline]
fn complement(m: f64, e: f64) -> f64 {
    -(m * (-e).ln_1p()).exp_m1()
}

/// `n e - P_n(e) >= 0`: its binomial series `sum_(k>=2) C(n,k) (-e)^k` below `e = 1/4` (where
/// the difference cancels), the difference above.
fn bernoulli_gap(n: f64, e: f64) -> f64 {
    if e > 0.25 {
        return n * e - complement(n, e);
    }
    let mut term = 0.5 * n * (n - 1.0) * e * e;
    let mut sum = 0.0;
    let mut k = 2.0;
    while term != 0.0 && k < 400.0 {
        sum += term;
        if term.abs() <= 1e-18 * sum.abs() {
            break;
        }
        term *= -(n - k) / (k + 1.0) * e;
        k += 1.0;
    }
    sum
}

/// `offset + F(x)` of the antiderivatives on `[a, b]` as the elasto-plastic model's piecewise
/// Chebyshev series of degree 16 (their values analytic there): evaluated in half the time of
/// the degree-32 panels, within `5e-15` of their largest value.
fn values(integral: &Antiderivatives, offset: (f64, f64), a: f64, b: f64) -> Table<2> {
    Table::fit(
        &|x: f64| {
            let (f1, f2) = integral.eval_both(x);
            [offset.0 + f1, offset.1 + f2]
        },
        &[a, b],
    )
}

/// Terms of the series (B10): `y <= 1/8`, so the dropped terms are below `8^-21 < 1e-18`.
const SERIES: usize = 21;

/// The coefficients of (B10): `1/(kn + 1)`, `1/((k+1) n + 2)`, `1/(kn + 2)`.
#[derive(Debug, Clone, PartialEq)]
struct Series {
    a: [f64; SERIES],
    b: [f64; SERIES],
    d: [f64; SERIES],
}

impl Series {
    fn new(n: f64) -> Self {
        let k = |k: usize| k as f64;
        Self {
            a: std::array::from_fn(|i| 1.0 / (k(i) * n + 1.0)),
            b: std::array::from_fn(|i| 1.0 / ((k(i) + 1.0) * n + 2.0)),
            d: std::array::from_fn(|i| 1.0 / (k(i) * n + 2.0)),
        }
    }

    /// `(T_-(t), E_-(t))`, `y = c t^n <= 1/8`.
    #[inline]
    fn negative(&self, t: f64, y: f64) -> (f64, f64) {
        let (mut time, mut loss) = (0.0, 0.0);
        for k in (0..SERIES).rev() {
            time = time * -y + self.a[k];
            loss = loss * -y + self.b[k];
        }
        (t * time, t * t * y * loss)
    }

    /// `T(v) = v sum_k y^k / (kn + 1)` (B10), `y = v^n <= 1/8`.
    #[inline]
    fn time(&self, v: f64, y: f64) -> f64 {
        let mut time = 0.0;
        for k in (0..SERIES).rev() {
            time = time * y + self.a[k];
        }
        v * time
    }

    /// `E(v) = v² y sum_k y^k / ((k+1) n + 2)` (B12), `y = v^n <= 1/8`.
    #[inline]
    fn loss(&self, v: f64, y: f64) -> f64 {
        let mut loss = 0.0;
        for k in (0..SERIES).rev() {
            loss = loss * y + self.b[k];
        }
        v * v * y * loss
    }

    /// `(R, Q)` at `v`, `y = v^n <= 1/8`.
    #[inline]
    fn positive(&self, n: f64, v: f64, y: f64) -> (f64, f64) {
        let (mut time, mut q) = (0.0, 0.0);
        for k in (1..SERIES).rev() {
            time = time * y + self.a[k];
            q = q * y + (self.a[k] - v * self.d[k]);
        }
        (v * (1.0 + y * time) + (-v).ln_1p() / n, -v - v * y * q)
    }
}

impl General {
    /// The tables for exponent `n` and `c = 2 sigma - 1`; `None` when one needs too many panels.
    fn new(n: f64, c: f64) -> Option<Self> {
        // |s|^n carries n rounding units: the integrands' noise, and so the tables' error.
        let tolerance = 1e-15 * n;
        let t0 = if c <= 0.125 {
            1.0
        } else {
            (0.125 / c).powf(1.0 / n)
        };
        let neg = if t0 < 1.0 {
            let f = |s: f64| {
                let y = c * s.powf(n);
                [1.0 / (1.0 + y), s * y / (1.0 + y)]
            };
            let integral = Antiderivatives::new(&f, t0, 1.0, tolerance)?;
            let at_t0 = Series::new(n).negative(t0, c * t0.powf(n));
            Some(values(&integral, at_t0, t0, 1.0))
        } else {
            None
        };
        let v0 = 0.125f64.powf(1.0 / n);
        let e1 = 1.0 - v0;
        let f = |e: f64| {
            let p = complement(n, e);
            [
                -bernoulli_gap(n, e) / (n * e * p),
                complement(n + 1.0, e) / p,
            ]
        };
        let integral = Antiderivatives::new(&f, 0.0, e1, tolerance)?;
        let series = Series::new(n);
        let (r1, q1) = series.positive(n, v0, v0.powf(n));
        let (f1, f2) = integral.eval_both(e1);
        let pos = values(&integral, (r1 - f1, q1 - f2), 0.0, e1);
        let mut out = Self {
            n,
            c,
            t0,
            neg,
            neg_at_t0: series.negative(t0, c * t0.powf(n)),
            series,
            v0,
            pos,
            t0_pos: 0.0,
            near: Table::fit(&|_| [0.0; 2], &[0.0, 1.0]),
            far: Table::fit(&|_| [0.0; 2], &[0.0, 1.0]),
            neg_near: Table::fit(&|_| [0.0; 2], &[0.0, 1.0]),
            neg_far: None,
        };
        out.t0_pos = out.forward(v0).0;
        out.near = out.near_table();
        out.far = out.far_table();
        if c > 0.0 {
            out.neg_near = out.neg_near_table();
        }
        if t0 < 1.0 && c <= NEG_TABLE_C {
            out.neg_far = Some(out.neg_far_table());
        }
        Some(out)
    }

    /// `(g, k)` of (B13) on `[0, c T_-(t0)^n]`, from the roots of (B8) by Newton (B11).
    fn neg_near_table(&self) -> Table<2> {
        let (n, c) = (self.n, self.c);
        Table::fit(
            &|s: f64| {
                let time = (s / c).powf(1.0 / n);
                if time == 0.0 {
                    return [1.0, self.series.b[0]];
                }
                let t = self.neg_root(self.t0, time);
                [t / time, self.neg(t).1 / (time * time * s)]
            },
            &[0.0, c * self.neg_at_t0.0.powf(n)],
        )
    }

    /// `(t, E_-)` of (B13) on `[T_-(t0), T_-(1)]`, from the roots of (B8) by Newton (B11).
    fn neg_far_table(&self) -> Table<2> {
        Table::fit(
            &|time: f64| {
                let t = self.neg_root(1.0, time);
                [t, self.neg(t).1]
            },
            &[self.neg_at_t0.0, self.neg(1.0).0],
        )
    }

    /// `(g, k)` of (B12) on `[0, T(v0)^n]`, from the roots of (B8) by Newton (B11).
    fn near_table(&self) -> Table<2> {
        let (n, top) = (self.n, self.t0_pos.powf(self.n));
        Table::fit(
            &|s: f64| {
                let time = s.powf(1.0 / n);
                if time == 0.0 {
                    return [1.0, self.series.b[0]];
                }
                let v = self.positive_newton(0.0, time).0;
                [v / time, self.series.loss(v, v.powf(n)) / (time * time * s)]
            },
            &[0.0, top],
        )
    }

    /// `(phi, Q)` of (B12) on `[0, 1]`, from the roots of (B8) by Newton (B11).
    fn far_table(&self) -> Table<2> {
        let e1 = 1.0 - self.v0;
        Table::fit(
            &|y: f64| {
                let tau = -y.ln() / self.n;
                let v = self.positive_newton(self.v0, tau).0;
                let e = 1.0 - v;
                [e / (e1 * y), self.pos(v, e).1]
            },
            &[0.0, 1.0],
        )
    }

    /// `(T(v), E(v))` of (B8) on the positive part, `0 <= v < 1`.
    #[inline]
    fn forward(&self, v: f64) -> (f64, f64) {
        if v <= self.v0 {
            let y = v.powf(self.n);
            let time = self.series.time(v, y);
            (time, self.series.loss(v, y))
        } else {
            let e = 1.0 - v;
            let (r, q) = self.pos(v, e);
            let time = -e.ln() / self.n + r;
            (time, time + q)
        }
    }

    /// `(v, E(v))` at `T(v) = time >= 0` (B12): one table pair and a `powf` or an `exp`.
    #[inline]
    fn inverse(&self, time: f64) -> (f64, f64) {
        if time <= self.t0_pos {
            let s = time.powf(self.n);
            let [g, k] = self.near.eval(s);
            (time * g, time * time * s * k)
        } else {
            let y = (-self.n * (time - self.t0_pos)).exp();
            let [phi, q] = self.far.eval(y);
            let e = (1.0 - self.v0) * y * phi;
            (1.0 - e, time + q)
        }
    }

    /// `(T_-(t), E_-(t))`.
    #[inline]
    fn neg(&self, t: f64) -> (f64, f64) {
        match &self.neg {
            Some(table) if t > self.t0 => {
                let [time, loss] = table.eval(t);
                (time, loss)
            }
            _ => self.series.negative(t, self.c * t.powf(self.n)),
        }
    }

    /// `T_-(t)` alone.
    #[inline]
    fn neg_time(&self, t: f64) -> f64 {
        self.neg(t).0
    }

    /// `(R, Q)` at `v = 1 - e`.
    #[inline]
    fn pos(&self, v: f64, e: f64) -> (f64, f64) {
        if v <= self.v0 {
            self.series.positive(self.n, v, v.powf(self.n))
        } else {
            let [r, q] = self.pos.eval(e);
            (r, q)
        }
    }

    /// `R` at `v = 1 - e`.
    #[inline]
    fn pos_r(&self, v: f64, e: f64) -> f64 {
        self.pos(v, e).0
    }

    /// [`SegmentStart`] at `v` (B8): one forward table pair, or a series.
    #[inline]
    fn start(&self, v: f64) -> SegmentStart {
        let (time, loss) = if v < 0.0 {
            self.neg(-v)
        } else if v > 0.0 && v < 1.0 {
            self.forward(v)
        } else {
            (0.0, 0.0)
        };
        SegmentStart { at: time, loss }
    }

    /// `v_b` and `D rho / kw` from `v_a` at `start` after `tau` (B8-B13).
    fn segment(&self, v_a: f64, start: &SegmentStart, tau: f64) -> (f64, f64) {
        let (time, loss) = (start.at, start.loss);
        if v_a >= 0.0 {
            return self.positive_from(v_a, (time, loss), tau);
        }
        let t_a = -v_a;
        if tau >= time {
            let (v, d) = self.positive_from(0.0, (0.0, 0.0), tau - time);
            return (v, loss + d);
        }
        let (t, loss_b) = self.neg_inverse(t_a, time - tau);
        (-t.min(t_a), loss - loss_b)
    }

    /// `(t, E_-(t))` at `T_-(t) = time`, `0 <= time < T_-(t_a)` (B13): one `powf` and one table
    /// pair below `T_-(t0)`, one table pair above (Newton there when `c > NEG_TABLE_C`).
    #[inline]
    fn neg_inverse(&self, t_a: f64, time: f64) -> (f64, f64) {
        if time <= self.neg_at_t0.0 {
            if self.c == 0.0 {
                return (time, 0.0);
            }
            let s = self.c * time.powf(self.n);
            let [g, k] = self.neg_near.eval(s);
            (time * g, time * time * s * k)
        } else if let Some(table) = &self.neg_far {
            let [t, loss] = table.eval(time);
            (t, loss)
        } else {
            let t = self.neg_root(t_a, time);
            (t, self.neg(t).1)
        }
    }

    /// The root `t` of `T_-(t) = target` in `[0, t_a]`, `target <= T_-(t_a)`, by Newton (B11).
    fn neg_root(&self, t_a: f64, target: f64) -> f64 {
        // Two lower bounds: T_-(t) <= t, and T_-' >= 1 / (1 + c t_a^n) on [t, t_a].
        let bound = t_a - (self.neg_time(t_a) - target) * (1.0 + self.c * t_a.powf(self.n));
        let mut t = bound.max(target).clamp(0.0, t_a);
        for _ in 0..60 {
            // Newton on the concave T_-: from the left, the iterates rise to the root.
            let slope = 1.0 + self.c * t.powf(self.n);
            let step = (target - self.neg_time(t)) * slope;
            t = (t + step).clamp(0.0, t_a);
            if step <= 1e-15 * slope {
                break;
            }
        }
        t
    }

    /// The positive part (B12): `v_b` and `D rho / kw` from `v_a >= 0` after `tau`.
    #[cfg(test)]
    fn positive(&self, v_a: f64, tau: f64) -> (f64, f64) {
        let start = self.start(v_a);
        self.positive_from(v_a, (start.at, start.loss), tau)
    }

    /// The positive part (B12) from `v_a >= 0` at `(T(v_a), E(v_a))` after `tau`.
    #[inline]
    fn positive_from(&self, v_a: f64, (time, loss): (f64, f64), tau: f64) -> (f64, f64) {
        if v_a >= 1.0 {
            return (1.0, tau);
        }
        let (v_b, loss_b) = self.inverse(time + tau);
        (v_b.max(v_a).min(1.0), loss_b - loss)
    }

    /// The positive part by Newton (B9, B11): `v_b` and `D rho / kw` from `v_a >= 0` after
    /// `tau` (the tables (B12) are built from it).
    fn positive_newton(&self, v_a: f64, tau: f64) -> (f64, f64) {
        if v_a >= 1.0 {
            return (1.0, tau);
        }
        let e_a = 1.0 - v_a;
        let x_a = -(-v_a).ln_1p();
        let (r_a, q_a) = self.pos(v_a, e_a);
        let target = x_a / self.n + r_a + tau;
        let (mut x, mut e, mut v, mut residual) = (x_a, e_a, v_a, -tau);
        for _ in 0..60 {
            // Newton on the concave x/n + R(e^-x): from x_a, the iterates rise to the root.
            let slope = if e > 0.0 {
                e / complement(self.n, e)
            } else {
                1.0 / self.n
            };
            let step = -residual / slope;
            x += step;
            e = (-x).exp();
            v = -(-x).exp_m1();
            if step <= 1e-14 * x.max(1.0) {
                break;
            }
            residual = x / self.n + self.pos_r(v, e) - target;
        }
        (v, tau + self.pos(v, e).1 - q_a)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Exponents over the domain, from just above the closed form to the largest.
    const EXPONENTS: [f64; 9] = [
        1.0 + 1e-9,
        1.1,
        1.5,
        2.0,
        2.5,
        3.7,
        10.0,
        25.0,
        MAX_EXPONENT,
    ];

    #[test]
    fn the_tables_give_the_closed_form_at_n_1() {
        for sigma in [0.5, 0.75, 1.0, 3.0, 40.0] {
            let c = 2.0 * sigma - 1.0;
            let g = General::new(1.0, c).unwrap();
            for v_a in [-1.0, -0.7, -0.2, -1e-9, 0.0, 0.3, 0.9, 1.0 - 1e-12, 1.0] {
                for tau in [1e-6, 0.01, 0.3, 1.0, 2.5, 7.0, 40.0] {
                    let (v1, d1) = linear(c, v_a, &linear_start(c, v_a), tau);
                    let (v2, d2) = g.segment(v_a, &g.start(v_a), tau);
                    assert!(
                        (v1 - v2).abs() < 2e-14,
                        "{sigma} {v_a} {tau}: v {v1} vs {v2}"
                    );
                    let scale = tau + 1.0;
                    assert!(
                        (d1 - d2).abs() < 1e-14 * scale,
                        "{sigma} {v_a} {tau}: d {d1} vs {d2}"
                    );
                }
            }
        }
    }

    #[test]
    fn the_inverse_tables_follow_newton() {
        // (B12) against the Newton roots (B11) it is built from, off its nodes; the worst
        // deviations (printed with --nocapture) stand in the bound of the module docs.
        let (mut worst_v, mut worst_d) = (0.0f64, 0.0f64);
        for n in EXPONENTS {
            let g = General::new(n, 0.5).unwrap();
            for i in 0..=400 {
                let v_a = if i % 2 == 0 {
                    0.0
                } else {
                    (i as f64 / 401.0).powi(2)
                };
                let tau = 10f64.powf(-6.0 + 7.0 * ((i * 37) % 401) as f64 / 400.0);
                let (v1, d1) = g.positive_newton(v_a, tau);
                let (v2, d2) = g.positive(v_a, tau);
                worst_v = worst_v.max((v1 - v2).abs());
                worst_d = worst_d.max((d1 - d2).abs() / (1.0 + tau));
            }
        }
        println!("worst |dv| {worst_v:e}, |dD| / (1 + tau) {worst_d:e}");
        assert!(worst_v <= 1e-14 && worst_d <= 1e-14, "{worst_v} {worst_d}");
    }

    #[test]
    fn the_negative_inverse_follows_newton() {
        // (B13) against the Newton roots (B11) it is built from, off its nodes, over `n` and
        // `c` up to NEG_TABLE_C; the worst deviations (printed with --nocapture) stand in the
        // bound of the module docs. Both carry the forward table's rounding times the slope.
        let (mut worst_t, mut worst_d) = (0.0f64, 0.0f64);
        for n in EXPONENTS {
            for c in [1e-3, 0.125, 0.5, 1.0, 7.0, 100.0, NEG_TABLE_C] {
                let g = General::new(n, c).unwrap();
                for i in 0..=200 {
                    let t_a = if i % 3 == 0 {
                        1.0
                    } else {
                        (i as f64 / 201.0).sqrt()
                    };
                    let top = g.neg_time(t_a);
                    let time = top * ((i * 37) % 201) as f64 / 201.0;
                    let t1 = g.neg_root(t_a, time);
                    let (t2, d2) = g.neg_inverse(t_a, time);
                    // A rounding unit of T_- moves t by eps T_- (1 + c t^n): the conditioning.
                    let scale = 1.0 + time * (1.0 + c * t1.powf(n));
                    worst_t = worst_t.max((t1 - t2.min(t_a)).abs() / scale);
                    worst_d = worst_d.max((g.neg(t1).1 - d2).abs());
                }
            }
        }
        println!("worst |dt| / (1 + T_- (1 + c t^n)) {worst_t:e}, |dE_-| {worst_d:e}");
        assert!(worst_t <= 1e-14 && worst_d <= 1e-14, "{worst_t} {worst_d}");
    }

    #[test]
    fn the_tables_build_over_the_domain() {
        for n in [1.0 + 1e-9, 1.5, 2.0, 3.7, 25.0, MAX_EXPONENT] {
            for c in [0.0, 1.0, 1e3, 1e300] {
                let g = General::new(n, c).unwrap_or_else(|| panic!("n {n} c {c}"));
                let (v, d) = g.segment(-1.0, &g.start(-1.0), 3.0);
                assert!(
                    v.is_finite() && d.is_finite() && v > 0.0,
                    "{n} {c}: {v} {d}"
                );
            }
        }
    }
}
