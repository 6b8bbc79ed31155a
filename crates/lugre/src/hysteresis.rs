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
//! Energy over a piece of length `l` from `y_k` (the identity `W = dV + D` follows from
//! `dy/drho = a (s g0 - y)`):
//!
//! ```text
//! W = integral y dpsi        = sigma0 l^2 h(z) + s y_k l phi(z)                        z = a l
//! D = (1/g0) integral y^2 drho = a y_k^2 l phi(2z) / sigma0 + 2 s y_k l (phi(z) - phi(2z))
//!                              + sigma0 l^2 q(z) / z
//! dV = (y_end^2 - y_k^2) / (2 sigma0)
//! ```

use crate::error::{InputError, LoopError};
use crate::input::TurningPoints;
use crate::model::RateIndependent;
use crate::numerics::{h, one_minus_exp, phi, phi_minus_phi2, q_over_z, DoubleDouble};

/// Loops whose arcs span at most this many segments get their work integrated directly
/// (relative to their start value); longer ones use prefix sums.
const DIRECT_WORK_MAX_SEGMENTS: usize = 64;

/// A point of the loop: the normalized variable, the input and the output there.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct LoopPoint {
    pub rho: f64,
    pub u: f64,
    pub y: f64,
}

/// A place on the periodic normalized input: `offset` along segment `k` in period `wraps`
/// (so `rho = rho_k + wraps P + offset`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Position {
    pub k: usize,
    pub wraps: u32,
    pub offset: f64,
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
    /// Work `integral y dpsi` from `rho = 0` to `rho_k`, `k = 0..=n`.
    work: Vec<DoubleDouble>,
    /// Dissipation `(1/g0) integral y^2 drho` from `rho = 0` to `rho_k`, `k = 0..=n`.
    dissipation: Vec<DoubleDouble>,
}

impl HysteresisLoop {
    /// The loop of `model` for the periodic input `input`.
    pub fn new(model: RateIndependent, input: &TurningPoints) -> Result<Self, InputError> {
        let u = input.values().to_vec();
        let n = u.len();
        let mut rho = Vec::with_capacity(n + 1);
        rho.push(0.0);
        for k in 0..n {
            rho.push(rho[k] + (u[(k + 1) % n] - u[k]).abs());
        }
        if !rho[n].is_finite() {
            return Err(InputError::VariationOverflow);
        }
        let mut hl = Self {
            model,
            u,
            rho,
            y: Vec::new(),
            work: Vec::new(),
            dissipation: Vec::new(),
        };
        hl.y = hl.turning_point_values();
        hl.accumulate_energy();
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

    /// `s_k`, the direction of segment `k`.
    #[inline]
    pub(crate) fn direction(&self, k: usize) -> f64 {
        let next = self.u[(k + 1) % self.len()];
        if next > self.u[k] {
            1.0
        } else {
            -1.0
        }
    }

    /// `L_k`, the length of segment `k`.
    #[inline]
    pub(crate) fn segment_length(&self, k: usize) -> f64 {
        (self.u[(k + 1) % self.len()] - self.u[k]).abs()
    }

    /// `y°(0)` (eq. 10) by the stable forms of the module docs, then `y°` at every turning point.
    fn turning_point_values(&self) -> Vec<f64> {
        let n = self.len();
        let a = self.model.a();
        let sigma0 = self.model.sigma0();
        let p = self.period();
        let ap = a * p;
        let y0 = if ap > 1.0 {
            let mut c = 0.0;
            for k in 0..n {
                c = self.advance(c, k, self.segment_length(k));
            }
            c / one_minus_exp(ap)
        } else {
            let mut tail = 0.0; // R_k = P - rho_{k+1}, summed from the end
            let mut sum = 0.0;
            for k in (0..n).rev() {
                let l = self.segment_length(k);
                let at = a * tail;
                sum += self.direction(k) * l * (tail * phi(at) + l * h(a * l) * (-at).exp());
                tail += l;
            }
            -sigma0 * sum / (p * phi(ap))
        };
        let mut y = Vec::with_capacity(n + 1);
        y.push(y0);
        for k in 0..n - 1 {
            y.push(self.advance(y[k], k, self.segment_length(k)));
        }
        y.push(y0);
        y
    }

    /// `y°` a length `l` into segment `k`, from `y_k` there.
    #[inline]
    fn advance(&self, y_k: f64, k: usize, l: f64) -> f64 {
        let z = self.model.a() * l;
        y_k * (-z).exp() + self.direction(k) * self.model.sigma0() * l * phi(z)
    }

    /// Work `integral y dpsi` over the first `l` of segment `k`.
    #[inline]
    fn piece_work(&self, k: usize, l: f64) -> f64 {
        let z = self.model.a() * l;
        self.model.sigma0() * l * l * h(z) + self.direction(k) * self.y[k] * l * phi(z)
    }

    /// Dissipation `(1/g0) integral y^2 drho` over the first `l` of segment `k` (never < 0).
    #[inline]
    fn piece_dissipation(&self, k: usize, l: f64) -> f64 {
        if l == 0.0 {
            return 0.0;
        }
        let (a, sigma0, y_k) = (self.model.a(), self.model.sigma0(), self.y[k]);
        let z = a * l;
        let d = a * y_k * y_k * l * phi(2.0 * z) / sigma0
            + 2.0 * self.direction(k) * y_k * l * phi_minus_phi2(z)
            + sigma0 * l * l * q_over_z(z);
        d.max(0.0)
    }

    fn accumulate_energy(&mut self) {
        let n = self.len();
        let mut w = DoubleDouble::ZERO;
        let mut d = DoubleDouble::ZERO;
        self.work = Vec::with_capacity(n + 1);
        self.dissipation = Vec::with_capacity(n + 1);
        self.work.push(w);
        self.dissipation.push(d);
        for k in 0..n {
            let l = self.segment_length(k);
            w = w.add_f64(self.piece_work(k, l));
            d = d.add_f64(self.piece_dissipation(k, l));
            self.work.push(w);
            self.dissipation.push(d);
        }
    }

    /// The work `integral y° dpsi` over one period: the energy dissipated per cycle.
    pub fn work_per_period(&self) -> f64 {
        self.work[self.len()].to_f64()
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

    /// The normalized input `psi_u(rho)` (eq. 12), periodic in `rho`.
    pub fn psi_at(&self, rho: f64) -> f64 {
        let (k, l) = self.locate(rho);
        self.u[k] + self.direction(k) * l
    }

    /// `y°(rho)`, periodic in `rho`.
    pub fn y_at(&self, rho: f64) -> f64 {
        let (k, l) = self.locate(rho);
        self.advance(self.y[k], k, l)
    }

    /// `(rho, psi_u(rho), y°(rho))` with `rho` as given (not reduced).
    pub fn point_at(&self, rho: f64) -> LoopPoint {
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

    pub(crate) fn position_rho(&self, pos: Position) -> f64 {
        self.rho[pos.k] + f64::from(pos.wraps) * self.period() + pos.offset
    }

    pub(crate) fn position_point(&self, pos: Position) -> LoopPoint {
        LoopPoint {
            rho: self.position_rho(pos),
            u: self.u[pos.k] + self.direction(pos.k) * pos.offset,
            y: self.advance(self.y[pos.k], pos.k, pos.offset),
        }
    }

    fn cumulative(&self, table: &[DoubleDouble], pos: Position, piece: f64) -> DoubleDouble {
        let mut acc = table[pos.k].add_f64(piece);
        for _ in 0..pos.wraps {
            acc = acc + table[self.len()];
        }
        acc
    }

    /// Work and dissipation from `from` to `to` (`to` not before `from`). `y_ref` is `y°` at
    /// `from`.
    ///
    /// Dissipation terms are all positive, so prefix sums are exact to rounding. Work terms
    /// `+-y l` cancel over a small loop; since `u` returns to its start over a loop's arc,
    /// `W = integral (y - y_ref) dpsi`, whose terms are small: short arcs are integrated that
    /// way, segment by segment, and long arcs (large loops, large `W`) from the prefix sums.
    pub(crate) fn energy_between(&self, from: Position, to: Position, y_ref: f64) -> (f64, f64) {
        let d = self.cumulative(
            &self.dissipation,
            to,
            self.piece_dissipation(to.k, to.offset),
        ) - self.cumulative(
            &self.dissipation,
            from,
            self.piece_dissipation(from.k, from.offset),
        );
        let n = self.len();
        let span = (to.wraps as usize * n + to.k) - (from.wraps as usize * n + from.k);
        let w = if span <= DIRECT_WORK_MAX_SEGMENTS {
            self.work_relative(from, span, to.offset, y_ref)
        } else {
            (self.cumulative(&self.work, to, self.piece_work(to.k, to.offset))
                - self.cumulative(&self.work, from, self.piece_work(from.k, from.offset)))
            .to_f64()
        };
        (w, d.to_f64().max(0.0))
    }

    /// `integral (y - y_ref) dpsi` from `from` over `span` segment boundaries to offset
    /// `end_offset` of the last segment.
    fn work_relative(&self, from: Position, span: usize, end_offset: f64, y_ref: f64) -> f64 {
        let (a, sigma0) = (self.model.a(), self.model.sigma0());
        let mut total = DoubleDouble::ZERO;
        let mut k = from.k;
        let mut offset = from.offset;
        for step in 0..=span {
            let stop = if step == span {
                end_offset
            } else {
                self.segment_length(k)
            };
            let l = stop - offset;
            if l > 0.0 {
                let s = self.direction(k);
                let y0 = self.advance(self.y[k], k, offset);
                let z = a * l;
                // s (y0 - y_ref) l phi(z) + a (g0 - s y_ref) l^2 h(z)
                let piece = s * (y0 - y_ref) * l * phi(z) + (sigma0 - s * a * y_ref) * l * l * h(z);
                total = total.add_f64(piece);
            }
            k = (k + 1) % self.len();
            offset = 0.0;
        }
        total.to_f64()
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
