//! The elasto-plastic friction model of Dupont, Hayward, Armstrong and Altpeter ("Single state
//! elastoplastic friction models", IEEE Trans. Automatic Control 47(5), 2002), its
//! rate-independent part: the loop and every minor loop with their energies, exact
//! (`docs/mathematics.md#elasto-plastic-dupont-et-al-2002`).
//!
//! # The model
//!
//! Displacement `u` (m), bristle deflection `z` (m), `sigma0` (N/m), Coulomb and static forces
//! `fc <= fs` (N), break-away displacement `zba` (m), LuGre's Stribeck curve `g` (`g(0) = fs`):
//!
//! ```text
//! (E1)  z' = u' (1 - alpha(z, u') z / z_ss(u')),   F = sigma0 z + sigma1 z' + sigma2 u',
//!       z_ss(v) = sgn(v) g(v) / sigma0
//! (E2)  alpha = 0                               |z| <= zba  or  sgn(z) != sgn(u')
//!       alpha = (1 + sin(pi (|z| - (|z_ss| + zba)/2) / (|z_ss| - zba))) / 2
//!                                               zba < |z| < |z_ss|
//!       alpha = 1                               |z| >= |z_ss|
//! ```
//!
//! with `0 <= zba < fc / sigma0 <= |z_ss(v)|` for every `v`, so that the deflection sticks
//! (`alpha = 0`, purely elastic) in the band `|z| <= zba`. The slow (rate-independent) limit,
//! `v -> 0`: `z_max = fs / sigma0`, and with `w = s z` on a segment of direction `s = sgn(du)`,
//! `theta = (w - zba) / (z_max - zba)`:
//!
//! ```text
//! (E3)  F = sigma0 z,    dw/d|u| = h(w) = 1 - alpha(w) w / z_max,
//!       alpha(w) = 0 (w <= zba),  sin^2(pi theta / 2) (zba < w < z_max),  1 (w >= z_max)
//! (E4)  V = sigma0 z^2 / 2,   D = W - ΔV = sigma0 ∫ alpha w^2 / z_max |du|  >= 0
//! ```
//!
//! (the sine blend of (E2) is `sin^2(pi theta / 2)`). The state stays in `[-z_max, z_max]`.
//!
//! # The segment map
//!
//! In units of `z_max` (`e = (z_max - w) / z_max`, `delta = 1 - zba / z_max`, `x = 1 - e`,
//! `S = sin^2(pi e / (2 delta))`, `h = e + x S`, `l = |du| / z_max`), a monotone segment is
//!
//! 1. an elastic stretch `w <- w + |du|` while `w <= zba` (closed form, no dissipation);
//! 2. the blend, `de/dl = -h(e)`, never reaching `e = 0` (`h ≈ e` there: the approach to `z_max`
//!    is exponential). With `tau(e) = ∫_e^delta de'/h` and `y = exp(-tau)` in `(0, 1]`:
//!
//! ```text
//! (E5)  tau(e) = ln(delta / e) + R(e),   R(e) = ∫_e^delta (1/h - 1/e') de'   (analytic)
//! (E6)  e = y phi(y),   phi analytic on [0, 1],   y_b = y_a exp(-l)
//! (E7)  D / (sigma0 z_max^2) = Φ(e_b) - Φ(e_a),       Φ(e) = ∫_e^delta alpha x^2 / h de'
//!                          = l - (G(e_b) - G(e_a)),   G(e) = ∫_e^(delta/2) (1 - alpha x^2) / h de'
//! ```
//!
//! the first form where both ends have `e >= delta/2`, the second (no log singularity, no
//! cancellation with `l`) deeper in, both summed across `e = delta/2`;
//! 3. above `z_max` (only from a state outside the bounds), `alpha = 1` and the exponential
//!    approach `w = z_max + (w_a - z_max) e^(-l)` in closed form.
//!
//! No closed form exists for the blend: `R`, `Φ`, `G` (1-D quadratures of analytic integrands)
//! and `phi` (the root of (E5) for given `y`, by a safeguarded Newton in `ln e`) are built
//! once in [`ElastoPlastic::new`] as piecewise Chebyshev series of degree 16-17, each piece
//! refined until its last two coefficients are below `5e-15` of its largest, in pairs on
//! shared pieces: `(R, Φ)` and `(R, G)` in `e`, and `(phi, Φ or G)` in `y`. A segment in the
//! blend then costs one `exp` and one or two evaluations (one pair each). Error bound: `z`
//! within 1e-13 `z_max`, the dissipation within 1e-13 `sigma0 z_max (z_max + |du|)` per
//! segment (the tables' `5e-15` and the rounding of `y`; checked against Simpson's rule on the
//! integrals to 1e-14 of those scales, and against scipy's Radau and DOP853 at rtol 1e-12 in
//! `tests/zoo_elastoplastic.rs` to the integrators' own accuracy, 7e-13 `z_max` and 6e-12
//! relative in the dissipation at worst).

pub(super) mod chebyshev;
mod rate;

use super::{SingleState, ZooLoop};
use crate::error::{num, ZooError};
use crate::input::TurningPoints;
use chebyshev::Table;

/// `alpha` of (E2) for the deflection `w` in the direction of motion (`w = sgn(v) z`: `w < 0`
/// is a deflection against the motion), the break-away displacement `zba` and the steady-state
/// deflection `z_ss > zba`: 0 up to `zba`, the sine blend `sin^2(pi theta / 2)` with
/// `theta = (w - zba) / (z_ss - zba)`, 1 from `z_ss` on. The one blend of the slow loop
/// (`z_ss = z_max`) and of the finite-rate dynamics (`z_ss = g(v) / sigma0`). It is `C^1` in
/// `w` (its slope vanishes at both ends), not `C^2`.
#[inline]
pub fn alpha(w: f64, zba: f64, z_ss: f64) -> f64 {
    if w <= zba {
        0.0
    } else if w >= z_ss {
        1.0
    } else {
        let half = 0.5 * std::f64::consts::PI * (w - zba) / (z_ss - zba);
        half.sin().powi(2)
    }
}

/// The elasto-plastic model's rate-independent part: validated parameters and the tables of
/// its blend, with the rate-dependent parameters its finite-rate form adds.
#[derive(Debug, Clone, PartialEq)]
pub struct ElastoPlastic {
    sigma0: f64,
    fc: f64,
    fs: f64,
    zba: f64,
    z_max: f64,
    blend: Blend,
    rate: Rate,
}

/// The parameters of (E1) that the slow loop does not use: micro-damping `sigma1` (N s/m),
/// viscous `sigma2` (N s/m), Stribeck velocity `vs` (m/s) and exponent `beta`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Rate {
    sigma1: f64,
    sigma2: f64,
    vs: f64,
    beta: f64,
}

impl Default for Rate {
    /// LuGre's defaults ([`crate::model::Parameter::default_value`]).
    fn default() -> Self {
        use crate::model::Parameter;
        Self {
            sigma1: Parameter::Sigma1.default_value(),
            sigma2: Parameter::Sigma2.default_value(),
            vs: Parameter::Vs.default_value(),
            beta: Parameter::Beta.default_value(),
        }
    }
}

/// The blend's integrands in units of its steady deflection (`z_max` of the slow loop,
/// `z_ss(v)` at finite rate): `delta = 1 - zba / z_max`, `a = pi / (2 delta)`, no tables
/// (cheap to build for each velocity).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Shape {
    delta: f64,
    /// `pi / (2 delta)`.
    a: f64,
}

/// The blend in units of `z_max`: `delta = 1 - zba / z_max` and the tables (E5)-(E7), each
/// pair of functions on shared pieces (one evaluation gives both).
#[derive(Debug, Clone, PartialEq)]
struct Blend {
    shape: Shape,
    /// `(R, Φ)` of `e` on `[delta/2, delta]` (the start of the blend).
    early: Table<2>,
    /// `(R, G)` of `e` on `[0, delta/2]`.
    deep: Table<2>,
    /// `(phi, Φ(e(y)))` for `y >= y_split`, `(phi, G(e(y)))` below, on `[0, 1]`.
    by_y: Table<2>,
    /// `y` at `e = delta/2`, `tau` there, `Φ` there.
    y_split: f64,
    tau_split: f64,
    phi_split: f64,
}

impl ElastoPlastic {
    /// The model with stiffness `sigma0` (N/m), Coulomb force `fc` (N), static force `fs` (N)
    /// and break-away displacement `zba` (m).
    ///
    /// # Errors
    /// [`ZooError::Domain`] naming the parameter, its value and the condition: each
    /// finite, `sigma0 > 0`, `fc > 0`, `fs >= fc`, `0 <= zba < fc / sigma0` (the break-away
    /// displacement below every steady-state deflection `g(v) / sigma0`, Dupont et al.'s
    /// condition for stiction); [`ZooError::Overflow`] when `fs / sigma0` overflows.
    ///
    /// ```
    /// use lugre::zoo::ElastoPlastic;
    /// use lugre::TurningPoints;
    /// let model = ElastoPlastic::new(1e5, 1.0, 1.5, 5e-6)?;
    /// // Inside the break-away band (range below 2 zba): stiction, a closed elastic loop.
    /// let small = model.loops(&TurningPoints::new(&[4e-6, -4e-6])?)?;
    /// assert_eq!(small.loops()[0].energy.dissipation, 0.0);
    /// // Beyond it the bristles slip in the blend and the loop dissipates.
    /// let large = model.loops(&TurningPoints::new(&[1e-4, -1e-4])?)?;
    /// assert!(large.work_per_period() > 0.0);
    /// # Ok::<(), lugre::Error>(())
    /// ```
    /// The break-away displacement where none is given, as a fraction of `fc / sigma0` (the
    /// deflection at the Coulomb force), so that it fits any scale: the zoo table's default
    /// (`0.5` m at `fc = 1` N, `sigma0 = 1` N/m), and `5e-6` m on Table I's.
    pub const DEFAULT_ZBA_FRACTION: f64 = 0.5;

    pub fn new(sigma0: f64, fc: f64, fs: f64, zba: f64) -> Result<Self, ZooError> {
        let out = |name, value, condition: String| ZooError::Domain {
            name,
            value,
            condition,
        };
        for (name, value) in [("sigma0", sigma0), ("fc", fc), ("fs", fs), ("zba", zba)] {
            if !value.is_finite() {
                return Err(out(name, value, "a finite number".into()));
            }
        }
        if sigma0 <= 0.0 {
            return Err(out("sigma0", sigma0, "> 0".into()));
        }
        if fc <= 0.0 {
            return Err(out("fc", fc, "> 0".into()));
        }
        if fs < fc {
            return Err(out("fs", fs, format!(">= fc = {}", num(fc))));
        }
        let z_max = fs / sigma0;
        if !z_max.is_finite() {
            return Err(ZooError::Overflow {
                what: "z_max = fs / sigma0",
            });
        }
        let limit = fc / sigma0;
        let delta = 1.0 - zba / z_max;
        if !(zba >= 0.0 && zba < limit && delta > 0.0) {
            let condition = format!(
                ">= 0 and < fc / sigma0 = {} (the break-away displacement below every steady-state deflection)",
                num(limit)
            );
            return Err(out("zba", zba, condition));
        }
        Ok(Self {
            sigma0,
            fc,
            fs,
            zba,
            z_max,
            blend: Blend::new(delta),
            rate: Rate::default(),
        })
    }

    /// The stiffness `sigma0` (N/m).
    pub fn sigma0(&self) -> f64 {
        self.sigma0
    }

    /// The Coulomb force `fc` (N) (only in the domain of `zba` here: the slow limit slides at `fs`).
    pub fn fc(&self) -> f64 {
        self.fc
    }

    /// The static force `fs` (N), `g(0)`.
    pub fn fs(&self) -> f64 {
        self.fs
    }

    /// The break-away displacement `zba` (m).
    pub fn zba(&self) -> f64 {
        self.zba
    }

    /// `z_max = fs / sigma0`, the deflection of steady sliding in the slow limit.
    pub fn z_max(&self) -> f64 {
        self.z_max
    }

    /// `alpha(w)` of (E3) for the deflection `w` in the direction of motion.
    pub fn alpha(&self, w: f64) -> f64 {
        alpha(w, self.zba, self.z_max)
    }

    /// The rate-dependent parameters `(sigma1, sigma2, vs, beta)` (the slow loop ignores
    /// them): what `lugre dynamics` needs beside `sigma0, fc, fs, zba`.
    ///
    /// # Errors
    /// [`ZooError::Domain`] naming the parameter: `sigma1, sigma2 >= 0`, `vs, beta > 0`.
    pub fn with_rate(
        mut self,
        sigma1: f64,
        sigma2: f64,
        vs: f64,
        beta: f64,
    ) -> Result<Self, ZooError> {
        for (name, value, positive) in [
            ("sigma1", sigma1, false),
            ("sigma2", sigma2, false),
            ("vs", vs, true),
            ("beta", beta, true),
        ] {
            let ok = value.is_finite() && (value > 0.0 || (!positive && value == 0.0));
            if !ok {
                let condition = if positive { "> 0" } else { ">= 0" };
                return Err(ZooError::Domain {
                    name,
                    value,
                    condition: condition.into(),
                });
            }
        }
        self.rate = Rate {
            sigma1,
            sigma2,
            vs,
            beta,
        };
        Ok(self)
    }

    /// The rate-dependent parameters `(sigma1, sigma2, vs, beta)`.
    pub fn rate(&self) -> [f64; 4] {
        let r = self.rate;
        [r.sigma1, r.sigma2, r.vs, r.beta]
    }

    /// The finite-rate model's LuGre parts: `sigma0, sigma1`, the Stribeck curve
    /// `g(v) = fc + (fs - fc) exp(-|v / vs|^beta)` (`z_ss = g / sigma0`) and `f(v) = sigma2 v`.
    pub fn lugre_params(&self) -> crate::model::LuGreParams {
        crate::model::LuGreParams {
            sigma0: self.sigma0,
            sigma1: self.rate.sigma1,
            sigma2: self.rate.sigma2,
            fc: self.fc,
            fs: self.fs,
            vs: self.rate.vs,
            beta: self.rate.beta,
        }
    }

    /// The force at each turning point, from rest (`z = 0`) at `u0`.
    pub fn response(&self, u0: f64, turning: &[f64]) -> Vec<f64> {
        let (mut u, mut z) = (u0, 0.0);
        turning
            .iter()
            .map(|&to| {
                z = self.segment(u, z, to).0;
                u = to;
                self.sigma0 * z
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

    /// Above `z_max` (`alpha = 1`): `w - z_max` decays as `e^(-|du| / z_max)`; the new `w`
    /// and the dissipation `sigma0 ∫ w^2 / z_max |du|`.
    fn above(&self, w: f64, length: f64) -> (f64, f64) {
        let c = w - self.z_max;
        let l = length / self.z_max;
        let d = self.z_max * length
            + 2.0 * c * self.z_max * -(-l).exp_m1()
            + 0.5 * c * c * -(-2.0 * l).exp_m1();
        (self.z_max + c * (-l).exp(), self.sigma0 * d)
    }
}

impl SingleState for ElastoPlastic {
    type Start = ();

    #[inline]
    fn start(&self, _z_a: f64, _up: bool) {}

    #[inline]
    fn force(&self, _u: f64, z: f64) -> f64 {
        self.sigma0 * z
    }

    #[inline]
    fn stored_energy(&self, _u: f64, z: f64) -> f64 {
        0.5 * self.sigma0 * z * z
    }

    /// Its legs share nothing worth keeping: the map is a few operations and one table.
    #[inline]
    fn segment_from(&self, _start: &(), u_a: f64, z_a: f64, u_b: f64) -> (f64, f64) {
        let du = u_b - u_a;
        let s = if du >= 0.0 { 1.0 } else { -1.0 };
        let w = s * z_a;
        match Leg::of(w, du.abs(), self.zba, self.z_max, self.blend.shape.delta) {
            Leg::Elastic(w_b) => (s * w_b, 0.0),
            Leg::Above => {
                let (w_b, d) = self.above(w, du.abs());
                (s * w_b, d)
            }
            Leg::Blend { e_a, l } => {
                let (e_b, d) = self.blend.advance(e_a, l);
                let scale = self.sigma0 * self.z_max * self.z_max;
                (s * (self.z_max - self.z_max * e_b), scale * d)
            }
        }
    }

    fn slope(&self, z: f64, up: bool) -> f64 {
        let w = if up { z } else { -z };
        if w <= self.zba {
            1.0
        } else if w >= self.z_max {
            1.0 - w / self.z_max
        } else {
            self.blend.h((self.z_max - w) / self.z_max)
        }
    }

    fn bounds(&self) -> (f64, f64) {
        (-self.z_max, self.z_max)
    }
}

impl Blend {
    /// Initial breaks toward `delta` for `Φ`: relative accuracy where `Φ ~ (delta - e)^3`.
    const GRADED: i32 = 24;

    fn new(delta: f64) -> Self {
        let shape = Shape::new(delta);
        let split = 0.5 * delta;
        let mut blend = Self {
            shape,
            early: Table::fit(&|_| [0.0; 2], &[split, delta]),
            deep: Table::fit(&|_| [0.0; 2], &[0.0, split]),
            by_y: Table::fit(&|_| [0.0; 2], &[0.0, 1.0]),
            y_split: 0.0,
            tau_split: 0.0,
            phi_split: 0.0,
        };
        let mut breaks: Vec<f64> = (0..Self::GRADED)
            .map(|k| delta - split * 0.5f64.powi(k))
            .collect();
        breaks.push(delta);
        blend.early = Table::integral(
            &|e| [blend.r(e), blend.dissipation_density(e)],
            &breaks,
            [0.0; 2],
        );
        let [r_split, phi_split] = blend.early.eval(split);
        blend.deep = Table::integral(&|e| [blend.r(e), blend.g(e)], &[0.0, split], [r_split, 0.0]);
        blend.y_split = 0.5 * (-r_split).exp();
        blend.tau_split = std::f64::consts::LN_2 + r_split;
        blend.phi_split = phi_split;
        // Graded toward y = 1 too: Φ(e(y)) ~ (1 - y)^3 there.
        let mut breaks = vec![0.0];
        breaks.extend((0..Self::GRADED).map(|k| 1.0 - (1.0 - blend.y_split) * 0.5f64.powi(k)));
        breaks.push(1.0);
        blend.by_y = Table::fit(
            &|y| {
                let e = blend.root(y);
                let early = y >= blend.y_split;
                let [r, d] = blend.at_e(e, early);
                [delta * r.exp(), d]
            },
            &breaks,
        );
        blend
    }

    /// `(R, Φ)` (`early`) or `(R, G)` at `e`.
    #[inline]
    fn at_e(&self, e: f64, early: bool) -> [f64; 2] {
        if early {
            self.early.eval(e)
        } else {
            self.deep.eval(e)
        }
    }

    /// `R(e)`.
    fn big_r(&self, e: f64) -> f64 {
        self.at_e(e, e >= 0.5 * self.shape.delta)[0]
    }

    fn parts(&self, e: f64) -> (f64, f64, f64) {
        self.shape.parts(e)
    }

    fn h(&self, e: f64) -> f64 {
        self.shape.h(e)
    }

    fn r(&self, e: f64) -> f64 {
        self.shape.r(e)
    }

    /// `(1 - alpha x^2) / h = (2 - e + x^2 S/e) / (1 + x S/e)`, the integrand of `G` (E7).
    fn g(&self, e: f64) -> f64 {
        let (x, s_e, _) = self.parts(e);
        (2.0 - e + x * x * s_e) / (1.0 + x * s_e)
    }

    /// `alpha x^2 / h`, the integrand of `Φ` (E7).
    fn dissipation_density(&self, e: f64) -> f64 {
        let (x, s_e, _) = self.parts(e);
        // alpha = sin^2(pi theta / 2) from delta - e, not 1 - S: relative accuracy near zba.
        let alpha = sin_quarter(self.shape.a * (self.shape.delta - e)).powi(2);
        alpha * x * x / (e * (1.0 + x * s_e))
    }

    /// `e` with `ln(e / delta) - R(e) = ln y` (E5, E6): safeguarded Newton in `ln e` on the
    /// bracket `ln y + ln delta + [R(0), 0]` (`R` is increasing and `<= 0`); the derivative is
    /// `e / h(e)`, in `(0, 1]`.
    fn root(&self, y: f64) -> f64 {
        let target = y.ln() + self.shape.delta.ln();
        let (mut lo, mut hi) = (target + self.big_r(0.0), target);
        let mut l = hi;
        for _ in 0..200 {
            let e = l.exp();
            let f = l - target - self.big_r(e);
            if f > 0.0 {
                hi = l;
            } else {
                lo = l;
            }
            let newton = l - f * self.h(e) / e;
            let next = if (lo..=hi).contains(&newton) {
                newton
            } else {
                0.5 * (lo + hi)
            };
            let tolerance = 2.0 * f64::EPSILON * l.abs().max(1.0);
            let done = (next - l).abs() <= tolerance || hi - lo <= tolerance;
            l = next;
            if done {
                break;
            }
        }
        l.exp()
    }

    /// From `e_a` over the length `l` (units of `z_max`): `e_b` and the dissipation (E7) in
    /// units of `sigma0 z_max^2`.
    #[inline]
    fn advance(&self, e_a: f64, l: f64) -> (f64, f64) {
        let split = 0.5 * self.shape.delta;
        let early_a = e_a >= split;
        // At the start of the blend R = Φ = 0.
        let [r_a, d_a] = if e_a >= self.shape.delta {
            [0.0; 2]
        } else {
            self.at_e(e_a, early_a)
        };
        let y_b = e_a / self.shape.delta * (-r_a - l).exp();
        let [phi, d_b] = self.by_y.eval(y_b);
        let e_b = (y_b * phi).min(e_a);
        let early_b = y_b >= self.y_split;
        let d = if early_b && early_a {
            d_b - d_a
        } else if early_b {
            // Both ends at the split, on either side by rounding: G at e_b instead.
            l - (self.deep.eval(e_b)[1] - d_a)
        } else if !early_a {
            l - (d_b - d_a)
        } else {
            let tau_a = if e_a >= self.shape.delta {
                0.0
            } else {
                (self.shape.delta / e_a).ln() + r_a
            };
            (self.phi_split - d_a) + (l - (self.tau_split - tau_a)) - d_b
        };
        (e_b, d.max(0.0))
    }
}

/// Where a monotone stretch of length `length` from `w` (the deflection in the direction of
/// motion) runs, for the break-away `zba` and the steady deflection `z_ss` (`z_max` of the
/// slow loop, `g(v) / sigma0` at finite rate; `delta = 1 - zba / z_ss`): (E3)'s three parts.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Leg {
    /// In the elastic band the whole way: `w + length` at its end.
    Elastic(f64),
    /// From above `z_ss` (`alpha = 1`, only from a state outside the bounds).
    Above,
    /// Into or in the blend: from `e_a` over the length `l` in units of `z_ss` (the elastic
    /// part before it removed).
    Blend { e_a: f64, l: f64 },
}

impl Leg {
    fn of(w: f64, length: f64, zba: f64, z_ss: f64, delta: f64) -> Self {
        if w + length <= zba || length == 0.0 {
            return Leg::Elastic(w + length);
        }
        if w >= z_ss {
            return Leg::Above;
        }
        let (e_a, rest) = if w <= zba {
            (delta, length - (zba - w))
        } else {
            (((z_ss - w) / z_ss).min(delta), length)
        };
        Leg::Blend {
            e_a,
            l: rest / z_ss,
        }
    }
}

impl Shape {
    fn new(delta: f64) -> Self {
        Self {
            delta,
            a: 0.5 * std::f64::consts::PI / delta,
        }
    }

    /// `(x, S / e, sin(a e) / e)` at `e` (the last two finite at `e = 0`).
    #[inline]
    fn parts(&self, e: f64) -> (f64, f64, f64) {
        let sn = sin_quarter(self.a * e);
        let sinc = if e > 0.0 { sn / e } else { self.a };
        (1.0 - e, sn * sinc, sinc)
    }

    /// `h(e) = e + x S`, the slope `dw/d|u|`.
    fn h(&self, e: f64) -> f64 {
        let (x, s_e, _) = self.parts(e);
        e * (1.0 + x * s_e)
    }

    /// `1/h - 1/e = -x (S/e^2) / (1 + x S/e)`, the integrand of `R` (E5).
    fn r(&self, e: f64) -> f64 {
        let (x, s_e, sinc) = self.parts(e);
        -x * sinc * sinc / (1.0 + x * s_e)
    }
}

/// `sin x` for `x` in `[0, pi/2]`: its Taylor series to `x^19` (the next term is below
/// `2.6e-16`), cheaper than the library's argument reduction on the slope's hot path.
#[inline]
fn sin_quarter(x: f64) -> f64 {
    const C: [f64; 9] = [
        -0.16666666666666666,
        0.008333333333333333,
        -0.0001984126984126984,
        2.7557319223985893e-06,
        -2.505210838544172e-08,
        1.6059043836821613e-10,
        -7.647163731819816e-13,
        2.8114572543455206e-15,
        -8.22063524662433e-18,
    ];
    let x2 = x * x;
    let p = C.iter().rev().fold(0.0, |acc, c| acc * x2 + c);
    x + x * x2 * p
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `∫_lo^hi f de` by composite Simpson on `n` (even) intervals in `ln e` (the integrands
    /// grow as `1/e`).
    fn simpson(f: impl Fn(f64) -> f64, lo: f64, hi: f64, n: usize) -> f64 {
        let (a, b) = (lo.ln(), hi.ln());
        let g = |s: f64| f(s.exp()) * s.exp();
        let h = (b - a) / n as f64;
        let inner: f64 = (1..n)
            .map(|k| g(a + k as f64 * h) * if k % 2 == 1 { 4.0 } else { 2.0 })
            .sum();
        (g(a) + inner + g(b)) * h / 3.0
    }

    #[test]
    fn the_tables_follow_the_flow() {
        // The length to reach e_b (1/h integrated) and the dissipation (alpha x^2 / h),
        // both by Simpson's rule on the table's e_b: the tables' state and energy.
        for delta in [1.0, 0.6, 0.2, 0.05] {
            let blend = Blend::new(delta);
            for l in [0.01, 0.1, 0.5, 1.0, 3.0] {
                let (e, d) = blend.advance(delta, l);
                let tau = simpson(|e| 1.0 / blend.h(e), e, delta, 40_000);
                let dissipated = simpson(|e| blend.dissipation_density(e), e, delta, 40_000);
                assert!((tau - l).abs() * blend.h(e) <= 1e-14, "{delta} {l}: {tau}");
                assert!(
                    (d - dissipated).abs() <= 1e-14 * (1.0 + l),
                    "{delta} {l}: {d} {dissipated}"
                );
            }
        }
    }

    #[test]
    fn the_inverse_table_inverts_the_forward_one() {
        for delta in [1.0, 0.3, 0.01] {
            let blend = Blend::new(delta);
            for k in 1..200 {
                let e = delta * (k as f64 / 200.0).powi(3);
                let y = e / delta * (-blend.big_r(e)).exp();
                let back = y * blend.by_y.eval(y)[0];
                assert!((back - e).abs() <= 1e-13 * delta, "{delta} {e} {back}");
            }
        }
    }

    #[test]
    fn a_blend_narrow_against_z_max_is_as_accurate() {
        // zba close to z_max (delta small): the integrands vary on the scale delta^2 near
        // e = 0; the tables refine there.
        for delta in [1e-2, 1e-4, 1e-6] {
            let blend = Blend::new(delta);
            for l in [1e-4, 1e-2, 1.0] {
                let (e, _) = blend.advance(delta, l);
                let tau = simpson(|e| 1.0 / blend.h(e), e, delta, 100_000);
                assert!((tau - l).abs() * blend.h(e) <= 1e-15, "{delta} {l}: {tau}");
            }
        }
    }

    #[test]
    fn the_quarter_sine_is_the_sine() {
        for k in 0..=1000 {
            let x = 0.5 * std::f64::consts::PI * k as f64 / 1000.0;
            assert!(
                (sin_quarter(x) - x.sin()).abs() <= 2.3e-16 * x.sin().max(1e-300),
                "{x}"
            );
        }
    }
}
