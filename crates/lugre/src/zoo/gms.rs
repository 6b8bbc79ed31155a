//! The Generalized Maxwell-slip (GMS) model of Al-Bender, Lampaert and Swevers (IEEE Trans.
//! Automatic Control 50(11), 2005): the Maxwell-slip elements of [`super::MaxwellSlip`] with a
//! rate-dependent slip level and a slipping phase of their own, at finite rate
//! (`docs/mathematics.md#generalized-maxwell-slip-gms-at-finite-rate`).
//!
//! Element `i` carries the force `F_i = k_i z_i` (N); `F_s = sum_j f_j` is the static force and
//! `s(v) = sgn(v) g(v)` the Stribeck curve `g(v) = fc + (F_s - fc) exp(-|v / vs|^beta)`, so that
//! the element's slip level is `alpha_i s(v)` with `alpha_i = f_i / F_s` (`sum alpha_i = 1`):
//!
//! ```text
//! (G1)  sticking:  dF_i/dt = k_i v                     until s F_i reaches alpha_i g(v)
//! (G2)  slipping:  dF_i/dt = sgn(v) C (alpha_i - F_i / s(v))
//!                          = lambda(v) (alpha_i s(v) - F_i),   lambda = C / g(v)   [1/s]
//!                                                      until v reverses or stops
//! (G3)  F = sum_i F_i + (sigma1 / K) sum_i dF_i/dt + sigma2 v,      K = sum_i k_i
//! ```
//!
//! with `s = sgn(v)`, the attraction `C` (N/s) and the micro-damping of element `i`,
//! `sigma_i = sigma1 k_i / K` (so that `sum sigma_i dz_i/dt = sigma1 v` while every element
//! sticks, LuGre's `sigma1`). As `v -> 0`, `alpha_i g(v) -> f_i` and a slipping element sits
//! at its level: the model is Maxwell-slip with slip forces `f_i`, its slow loop.
//!
//! On an interval of constant `v` (a piecewise-linear motion `u(t)`) each element is exact:
//! sticking, `F_i` is linear in `t`, and reaches its level `s alpha_i g(v)` at
//! `tau = (alpha_i g - s F_i) / (k_i |v|)`; slipping, (G2) has constant coefficients:
//!
//! ```text
//! (G4)  F_i(t0 + h) = F_i + (s alpha_i g - F_i) (1 - exp(-lambda h))
//! ```
//!
//! (`1 - exp(-x)` by `kernel::relax::decay`, no cancellation); an element that starts
//! to slip at its level stays on it exactly. The time integral of each piece is closed too, so
//! the work `integral F v dt` over an interval is exact (G8 of `docs/mathematics.md`).

use super::check_scalar;
use crate::error::ZooError;
use crate::model::{Parameter, Stribeck, VelocityFn};

/// The attraction `C` (N/s) when none is given: with the table's static force of 2 N, a
/// slipping element settles to its level at the rate `C / g(0) = 5` per second.
pub const DEFAULT_ATTRACTION: f64 = 10.0;

/// The table's default Maxwell-slip elements with their proportions kept, scaled to the total
/// stiffness `sigma0` (N/m) and the static force `fs` (N): `(stiffness, slip_force)`. GMS on
/// the scale of a LuGre parameter set (the 1995 experiments: Table I's `sigma0 = 1e5`,
/// `Fs = 1.5`).
pub fn elements_on_scale(sigma0: f64, fs: f64) -> (Vec<f64>, Vec<f64>) {
    let scaled = |name: &str, total: f64| -> Vec<f64> {
        let spec = &super::MODELS[0];
        let default = spec.parameter(name).map_or(&[][..], |p| p.default);
        let sum: f64 = default.iter().sum();
        default.iter().map(|x| x * total / sum).collect()
    };
    (scaled("stiffness", sigma0), scaled("slip_force", fs))
}

/// The parameters GMS adds to the Maxwell-slip elements (the slow loop does not use them):
/// the Coulomb force `fc` (N), Stribeck velocity `vs` (m/s) and exponent `beta`, the
/// attraction `attraction` (`C`, N/s), the micro-damping `sigma1` and the viscous coefficient
/// `sigma2` (N s/m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GmsRate {
    pub fc: f64,
    pub vs: f64,
    pub beta: f64,
    pub attraction: f64,
    pub sigma1: f64,
    pub sigma2: f64,
}

impl Default for GmsRate {
    /// LuGre's defaults for `fc, vs, beta, sigma1, sigma2` ([`Parameter::default_value`]) and
    /// [`DEFAULT_ATTRACTION`].
    fn default() -> Self {
        Self {
            fc: Parameter::Fc.default_value(),
            vs: Parameter::Vs.default_value(),
            beta: Parameter::Beta.default_value(),
            attraction: DEFAULT_ATTRACTION,
            sigma1: Parameter::Sigma1.default_value(),
            sigma2: Parameter::Sigma2.default_value(),
        }
    }
}

impl GmsRate {
    /// The values in the table's order: `fc, vs, beta, attraction, sigma1, sigma2`.
    pub fn values(&self) -> [f64; 6] {
        [
            self.fc,
            self.vs,
            self.beta,
            self.attraction,
            self.sigma1,
            self.sigma2,
        ]
    }

    /// Checked: `fc, vs, beta, attraction > 0`, `sigma1, sigma2 >= 0`, all finite.
    ///
    /// # Errors
    /// [`ZooError::Domain`] naming the parameter and its value.
    pub fn checked(self) -> Result<Self, ZooError> {
        for (name, value) in [
            ("fc", self.fc),
            ("vs", self.vs),
            ("beta", self.beta),
            ("attraction", self.attraction),
        ] {
            check_scalar(name, value, true)?;
        }
        check_scalar("sigma1", self.sigma1, false)?;
        check_scalar("sigma2", self.sigma2, false)?;
        Ok(self)
    }
}

/// The GMS elements: stiffnesses, slip forces and the finite-rate parameters, with the
/// Stribeck curve `g` of (G1) built once.
#[derive(Debug, Clone, PartialEq)]
pub struct Gms {
    k: Vec<f64>,
    /// `alpha_i = f_i / F_s`.
    alpha: Vec<f64>,
    /// `sigma1 / K`.
    damping: f64,
    g: Stribeck,
    rate: GmsRate,
}

/// The state of the GMS elements: each force `F_i` and whether it slips (`+1`, `-1`: in that
/// direction) or sticks (`0`).
#[derive(Debug, Clone, PartialEq)]
pub struct GmsState {
    pub force: Vec<f64>,
    pub slip: Vec<f64>,
}

impl Gms {
    /// From validated elements (`k_i, f_i > 0`) and `rate`.
    ///
    /// # Errors
    /// `rate`'s checks; [`ZooError::Domain`] for a `vs` whose reciprocal overflows;
    /// [`ZooError::Overflow`] where `sum k_i` or `sum f_i` does.
    pub(crate) fn new(k: &[f64], f: &[f64], rate: GmsRate) -> Result<Self, ZooError> {
        let rate = rate.checked()?;
        let (stiffness, fs): (f64, f64) = (k.iter().sum(), f.iter().sum());
        if !(stiffness.is_finite() && fs.is_finite()) {
            return Err(ZooError::Overflow {
                what: "the sum of the stiffnesses or of the slip forces",
            });
        }
        let g = Stribeck::new(rate.fc, fs, rate.vs, rate.beta).map_err(|_| ZooError::Domain {
            name: "vs",
            value: rate.vs,
            condition: "large enough for 1 / vs to be finite".into(),
        })?;
        Ok(Self {
            k: k.to_vec(),
            alpha: f.iter().map(|fi| fi / fs).collect(),
            damping: rate.sigma1 / stiffness,
            g,
            rate,
        })
    }

    /// The finite-rate parameters.
    pub fn rate(&self) -> GmsRate {
        self.rate
    }

    /// The element stiffnesses `k_i`.
    pub fn stiffness(&self) -> &[f64] {
        &self.k
    }

    /// The element weights `alpha_i = f_i / F_s`.
    pub fn weights(&self) -> &[f64] {
        &self.alpha
    }

    /// `sigma1 / K`: the damping of (G3) per unit of `sum_i dF_i/dt`.
    pub fn damping(&self) -> f64 {
        self.damping
    }

    /// The Stribeck curve `g(v) = |s(v)|` of (G1).
    pub fn g(&self, v: f64) -> f64 {
        self.g.eval(v)
    }

    /// At rest: every force 0, every element sticking.
    pub fn rest(&self) -> GmsState {
        GmsState {
            force: vec![0.0; self.k.len()],
            slip: vec![0.0; self.k.len()],
        }
    }

    /// Moves `state` over `h >= 0` seconds at the constant velocity `v` by (G1), (G2), (G4),
    /// each stick-slip transition at its exact instant; returns `sum_i dF_i/dt` at the end and
    /// the time integral of `sum_i F_i` over the interval, each piece in closed form (G8 of
    /// `docs/mathematics.md`).
    pub fn advance(&self, state: &mut GmsState, v: f64, h: f64) -> (f64, f64) {
        if v == 0.0 {
            // At rest every element sticks (a slipping one stops with the motion), F constant.
            state.slip.iter_mut().for_each(|m| *m = 0.0);
            return (0.0, state.force.iter().sum::<f64>() * h);
        }
        let s = v.signum();
        let g = self.g(v);
        let lambda = self.rate.attraction / g;
        let (mut rate, mut integral) = (0.0, 0.0);
        let elements = state.force.iter_mut().zip(state.slip.iter_mut());
        for ((f, m), (k, a)) in elements.zip(self.k.iter().zip(&self.alpha)) {
            let level = a * g;
            if *m != s {
                // Sticking (or slipping the other way, which the reversal ends).
                *m = 0.0;
                let gap = level - s * *f;
                let tau = gap / (k * v.abs());
                if tau >= h {
                    // Sticking: F_i linear in t.
                    integral += h * (*f + 0.5 * k * v * h);
                    *f += k * v * h;
                    rate += k * v;
                    continue;
                }
                *m = s;
                if gap > 0.0 {
                    // Reaches its level inside the interval and slips on it from there.
                    integral += 0.5 * tau * (*f + s * level) + s * level * (h - tau);
                    *f = s * level;
                    continue;
                }
            }
            let target = s * level;
            let (_, one_minus_e) = crate::kernel::relax::decay(lambda * h);
            // Slipping: the integral of (G4).
            integral += target * h + (*f - target) * one_minus_e / lambda;
            *f += (target - *f) * one_minus_e;
            rate += lambda * (target - *f);
        }
        (rate, integral)
    }

    /// The stored energy of `state`: `sum_i F_i^2 / (2 k_i)` (G7).
    pub fn stored_energy(&self, state: &GmsState) -> f64 {
        let terms = state.force.iter().zip(&self.k);
        terms.map(|(f, k)| 0.5 * f * f / k).sum()
    }

    /// The friction force (G3) of `state` moving at `v` with `sum_i dF_i/dt = rate`.
    pub fn force(&self, state: &GmsState, v: f64, rate: f64) -> f64 {
        state.force.iter().sum::<f64>() + self.damping * rate + self.rate.sigma2 * v
    }

    /// The friction force at each time `t[j]` of the motion `u(t)` linear between the samples,
    /// from rest at `t[0]` (0 there): at `t[j]`, `j > 0`, the force at the end of the interval
    /// `[t[j-1], t[j]]` (its left limit: with `sigma1` or `sigma2 > 0` the force jumps where
    /// `v` does).
    ///
    /// # Errors
    /// [`ZooError::LengthMismatch`] / [`ZooError::Empty`] for the arrays,
    /// [`ZooError::Domain`] for a sample that is not finite or a time not after the one
    /// before, [`ZooError::Overflow`] where the force overflows.
    pub fn simulate(&self, t: &[f64], u: &[f64]) -> Result<Vec<f64>, ZooError> {
        super::check_lengths(("t", t.len()), ("u", u.len()))?;
        check_samples(t, u)?;
        let mut state = self.rest();
        let mut out = Vec::with_capacity(t.len());
        out.push(0.0);
        for j in 1..t.len() {
            let h = t[j] - t[j - 1];
            let v = (u[j] - u[j - 1]) / h;
            let (rate, _) = self.advance(&mut state, v, h);
            let force = self.force(&state, v, rate);
            if !force.is_finite() {
                return Err(ZooError::Overflow { what: "the force" });
            }
            out.push(force);
        }
        Ok(out)
    }
}

/// Every sample finite, the times increasing, the velocities finite.
fn check_samples(t: &[f64], u: &[f64]) -> Result<(), ZooError> {
    let bad = |name, value, condition: String| ZooError::Domain {
        name,
        value,
        condition,
    };
    for (name, x) in [("t", t), ("u", u)] {
        if let Some(&value) = x.iter().find(|x| !x.is_finite()) {
            return Err(bad(name, value, "a finite number".into()));
        }
    }
    for j in 1..t.len() {
        if t[j] <= t[j - 1] {
            let condition = format!("> t[{}] = {} (times increasing)", j - 1, t[j - 1]);
            return Err(bad("t", t[j], condition));
        }
        let v = (u[j] - u[j - 1]) / (t[j] - t[j - 1]);
        if !v.is_finite() {
            let condition = "a finite velocity (u[j] - u[j-1]) / (t[j] - t[j-1])".into();
            return Err(bad("u", u[j], condition));
        }
    }
    Ok(())
}
