//! The hysteresis loop `y°` of the LuGre and Dahl models (paper eqs. 8-10) for any periodic
//! input, by the stable closed form (`docs/mathematics.md#the-stable-closed-form`).
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
//! Summing `W`'s own closed form `sigma0 l^2 h(z) + s y_k l phi(z)` piece by piece cancels
//! where its terms are `O(sigma0 l^2)` (the elastic energy that comes back) while `W` is
//! `O(a sigma0 P^3)` (small `a P`), whereas `D`'s terms are all positive; `dV + D` cancels in
//! turn on loops much narrower than `1/a` far from `y = 0`. Each loop's `W` is taken from the
//! form whose rounding bound is smaller (the kernel's `best_work`). Per piece:
//!
//! ```text
//! D over a piece = a y_k^2 l phi(2z) / sigma0 + 2 s y_k l (phi(z) - phi(2z)) + sigma0 l^2 q(z)/z
//! ```
//!
//! with `z = a l` and `q(z) = 1 - 2 phi(z) + phi(2z)`. `dV` needs the closure gap
//! `y_end - y_start`, which is `O(a)` on loops shorter than `1/a`; it is computed without
//! taking the difference of the two values (`kernel::arc`). The sums over every loop's
//! arc are carried on the rainflow stack in one pass over the period ([`crate::LoopTable`]),
//! which also writes `y°` at the turning points: each piece is evaluated once.

mod engine;
mod records;
mod table;
mod theorem_a;

pub use records::{Loop, LoopKind};
pub use table::LoopTable;
pub use theorem_a::TheoremA;

use crate::error::{InputError, LoopError, SamplesError};
use crate::input::TurningPoints;
use crate::kernel::numerics::{h, one_minus_exp, phi};
use crate::kernel::piece::advance;
use crate::memory::column;
use crate::model::RateIndependent;
use engine::{canonical_start, Period};

/// The most points a loop is sampled at on request (24 bytes each in memory, more as text).
pub const MAX_SAMPLES: usize = 10_000_000;

/// Checks a requested number of loop samples: `2 <= n <= MAX_SAMPLES`.
///
/// # Errors
/// [`SamplesError`] naming `n`.
pub fn check_samples(n: usize) -> Result<(), SamplesError> {
    if n < 2 {
        return Err(SamplesError::TooFew { n: n as u64 });
    }
    if n > MAX_SAMPLES {
        return Err(SamplesError::TooMany {
            n: n as u64,
            limit: MAX_SAMPLES as u64,
        });
    }
    Ok(())
}

/// A point of the loop: the normalized variable, the input and the output there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoopPoint {
    pub rho: f64,
    pub u: f64,
    pub y: f64,
}

impl LoopPoint {
    /// The columns of a sampled loop, in order: `lugre loop --csv`, the MEX gateway's curve,
    /// Python's `HysteresisLoop.sample` (`rho, u, y = hl.sample(n)`).
    pub const COLUMNS: [&'static str; 3] = ["rho", "u", "y"];

    /// The point's values in the order of [`Self::COLUMNS`].
    pub fn values(&self) -> [f64; 3] {
        [self.rho, self.u, self.y]
    }
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
    /// The loop of `model` for the periodic input `input`, with every loop and its energies.
    /// An error if the input's variation, `y°` or the work per period overflows f64: a loop
    /// that is returned holds finite numbers only.
    pub fn new(model: RateIndependent, input: &TurningPoints) -> Result<Self, LoopError> {
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
            return Err(InputError::VariationOverflow.into());
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
            model: model.relaxation(),
            u: &hl.u,
            rho: &hl.rho,
            r,
            y_r: hl.periodic_value(r),
        };
        hl.loops = period.loops(&mut hl.y);
        hl.check_finite()?;
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
        advance(self.model.relaxation(), y_k, self.direction(k), l)
    }

    /// The major loop and every minor loop as records, ordered by where their arcs start: `[0]`
    /// is the major loop, and a parent comes before its children. The same loops as
    /// [`loop_table`](Self::loop_table).
    pub fn loops(&self) -> Vec<Loop> {
        records::minor_loops(self)
    }

    /// `|y°(0) - sigma0 x0| exp(-a P k)`: the distance `sup_t |y*_{u,k}(t) - y°(t)|` between
    /// the k-th period of the rate-independent response from `x0` and the hysteresis loop, for
    /// an input whose period starts at the loop's first turning point (as
    /// [`crate::PiecewiseLinear::from_turning_points`] builds it). Both obey eq. 8's recursion,
    /// so the difference is exactly `(sigma0 x0 - y°(0)) exp(-a rho_u(t))`, largest at the
    /// start of each period.
    pub fn transient_amplitude(&self, x0: f64, k: u32) -> f64 {
        let m = self.model();
        let gap = (self.turning_y()[0] - m.sigma0() * x0).abs();
        // exp(-a P k) as a power keeps the exponent's rounding from growing with k.
        gap * (-m.a() * self.period())
            .exp()
            .powi(k.min(i32::MAX as u32) as i32)
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

    /// `n` points evenly spaced over one period, both ends included (`rho = 0` and `P`), with
    /// `n` checked first: every front end asks through here, so they refuse the same counts.
    ///
    /// # Errors
    /// [`SamplesError::TooFew`] for `n < 2`, [`SamplesError::TooMany`] above [`MAX_SAMPLES`].
    pub fn try_sample(&self, n: usize) -> Result<Vec<LoopPoint>, SamplesError> {
        check_samples(n)?;
        Ok(self.sample(n))
    }

    /// `n >= 2` points evenly spaced over one period, both ends included (`rho = 0` and `P`);
    /// `n < 2` gives the two ends.
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
    fn check_finite(&self) -> Result<(), LoopError> {
        // Branch-free over the exponent bits (all ones: inf or NaN), so that the pass
        // vectorizes: it runs on every loop `new` returns.
        const EXPONENT: u64 = 0x7ff0_0000_0000_0000;
        let not_finite = |v: &f64| v.to_bits() & EXPONENT == EXPONENT;
        if self.y.iter().fold(false, |any, v| any | not_finite(v)) {
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
