//! Closed-loop friction dynamics: a mass driven by forces, a spring and a controller, with
//! LuGre (or Dahl) friction, or the elasto-plastic friction of Dupont et al. (2002)
//! ([`FrictionLaw`], (D1)-(D2)), or GMS friction (the Maxwell-slip model at finite rate, an
//! event-driven run of its own: `gms.rs`, (G6)), solved to a stated accuracy with the instants
//! where the velocity changes sign located as events.
//!
//! ```text
//! M x'' = F_d(t, x, x', q) - F                 x(0) = x'(0) = 0, z(0) = 0, q(0) = 0
//! z'    = v - sigma0 |v| z / g(v)              v = x'
//! F     = sigma0 z + sigma1 z' + f(v)          (the friction force on the mass)
//! F_d   = P(t) + k (x_e(t) - x) - c v - Kv v - Kp (x - x_d(t)) - Ki q,       q' = x - x_d(t)
//! ```
//!
//! with an applied force `P` (a piecewise-linear profile or a ramp `r t`), an optional linear
//! spring `k` to a free end moving along `x_e(t)` (a constant speed or a profile), a linear
//! damper `c`, and an optional PID controller on position (gains `Kp, Ki, Kv`, set point `x_d`
//! piecewise constant). In SI units: `M` in kg, forces in N, `k` in N/m, `c` and `Kv` in N s/m,
//! `Kp` in N/m, `Ki` in N/(m s). A **rotational** reading is the same equations with the
//! inertia `J` (kg m^2) for `M`, angles (rad) for `x`, torques (N m) for forces, and `sigma0`
//! in N m/rad, `vs` in rad/s.
//!
//! **Non-smooth points.** `|v|` makes the right-hand side only Lipschitz at `v = 0`, and the
//! drive's slope jumps at its kinks. Both are handled exactly: the integration stops at every
//! kink, and between kinks it runs with the sign of `v` frozen (`|v| -> s v`, a smooth
//! extension) until `v` crosses 0, which is located as an event on the integrator's dense
//! output; it then restarts with the other sign. Where the mass rings down to rest (a stuck
//! mass under a constant force) the crossings never end; once the ringing amplitude, estimated
//! from `|v'|` at a crossing over the natural frequency `sqrt(sigma0 / M)`, is below the
//! velocity tolerance, the sign is no longer frozen until the next kink (the kinks of the
//! ringing are then below the tolerance).
//!
//! **The integrator** (`integrator.rs`) is Radau IIA of order 5 written for this small system
//! in Hairer & Wanner's form (radau5): L-stable (stable at any `sigma0 / M`), simplified Newton
//! on the transformed stage equations, the embedded error estimate held to the tolerances,
//! Gustafsson's step-size controller, the collocation polynomial as dense output for locating
//! sign changes, and a step of its own to each output time and located event
//! (`docs/mathematics.md`, "The integrator"). The `differential-equations` crate's Radau5,
//! tried first, failed here ("step size became too small" on the PID experiment at `rtol`
//! 1e-7 and 1e-8, in a sliding phase, with or without the sign splitting); its figures are in
//! BENCHMARKS.md. Accuracy against an independent scipy reference: `tests/dynamics.rs`.

mod gms;
mod integrator;
mod loops;
mod profile;
mod request;
mod scenario;
mod solver;
mod stepper;

pub use crate::error::Field;
pub use loops::FrictionLoop;
pub use profile::{Profile, Steps};
pub use request::{Outcome, Plan, Request};
pub use scenario::{Scenario, Setup};
pub use stepper::MassStepper;

pub use solver::{Breakaway, EnergyBalance, Event, EventKind, Motion, State, Stats, Tolerances};

use crate::error::DynamicsError;
use crate::model::{LuGre, Stribeck, VelocityFn, Viscous};

/// A prescribed velocity (the mass then follows it whatever the forces: the
/// displacement-driven case, for comparison with `lugre simulate`).
#[derive(Debug, Clone, PartialEq)]
pub enum Velocity {
    /// A piecewise-linear profile `v(t)`.
    Profile(Profile),
    /// `v(t) = mean + amplitude cos(w t)` (Fig. 3 of Canudas de Wit et al. 1995:
    /// `1e-3 (cos w t + 1.5)`).
    Harmonic { mean: f64, amplitude: f64, w: f64 },
}

impl Velocity {
    /// `(v(t), v'(t))`.
    fn at(&self, t: f64) -> (f64, f64) {
        match self {
            Velocity::Profile(p) => p.value_and_slope(t),
            Velocity::Harmonic { mean, amplitude, w } => {
                let (s, c) = (w * t).sin_cos();
                (mean + amplitude * c, -amplitude * w * s)
            }
        }
    }

    /// The instants in `(0, t_end)` where `v` changes sign or its slope jumps.
    fn breakpoints(&self, t_end: f64) -> Vec<f64> {
        let mut out = Vec::new();
        match self {
            Velocity::Profile(p) => {
                out.extend_from_slice(p.kinks());
                // Zeros inside the linear pieces.
                let k = p.kinks();
                for w in k.windows(2) {
                    let (a, b) = (p.value(w[0]), p.value(w[1]));
                    if a * b < 0.0 {
                        out.push(w[0] + (w[1] - w[0]) * a / (a - b));
                    }
                }
            }
            Velocity::Harmonic { mean, amplitude, w } => {
                // cos(w t) = -mean / amplitude.
                let c = -mean / amplitude;
                if c.abs() < 1.0 && *w > 0.0 {
                    let phase = c.acos();
                    let period = std::f64::consts::TAU / w;
                    let mut base = 0.0;
                    while base < t_end {
                        for t in [base + phase / w, base + period - phase / w] {
                            out.push(t);
                        }
                        base += period;
                    }
                }
            }
        }
        out.retain(|&t| t > 0.0 && t < t_end);
        out
    }
}

/// A PID controller on position: `u = -Kv v - Kp (x - x_d) - Ki integral (x - x_d)`.
#[derive(Debug, Clone, PartialEq)]
pub struct Pid {
    pub kp: f64,
    pub ki: f64,
    pub kv: f64,
    pub setpoint: Steps,
}

/// The friction law of the bristle state: LuGre's (Dahl's as its special case) or the
/// elasto-plastic model of Dupont et al. (2002), both on the [`LuGre`] model's `sigma0`,
/// `sigma1`, `g` and `f`. With `w = sgn(v) z` and `z_ss = g(v) / sigma0`:
///
/// ```text
/// (D1)  LuGre            z' = v (1 - w / z_ss)             = v - sigma0 |v| z / g(v)
/// (D2)  elasto-plastic   z' = v (1 - alpha(w) w / z_ss)    alpha: 0 for w <= zba, the sine
///                                                          blend up to z_ss, 1 beyond
/// ```
///
/// and `F = sigma0 z + sigma1 z' + f(v)` for both. (D2) is affine in `v` at a frozen sign but
/// not in `z`: the blend is `C^1` in `z` at `|z| = zba` and `|z| = z_ss` (the error control
/// copes: `tests/dynamics_elastoplastic.rs` against scipy).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub enum FrictionLaw {
    /// (D1).
    #[default]
    LuGre,
    /// (D2) with the break-away displacement `zba` (m), `0 <= zba < min(Fc, Fs) / sigma0`.
    ElastoPlastic { zba: f64 },
}

impl FrictionLaw {
    /// The name reports echo: `lugre` or `elastoplastic` (the zoo table's).
    pub fn name(&self) -> &'static str {
        match self {
            FrictionLaw::LuGre => "lugre",
            FrictionLaw::ElastoPlastic { .. } => "elastoplastic",
        }
    }

    /// Whether the rate is affine in `z` at a frozen sign (the Jacobian's `z` column may then
    /// be a difference over a whole scale).
    fn affine_in_z(&self) -> bool {
        matches!(self, FrictionLaw::LuGre)
    }
}

/// The one-degree-of-freedom system.
#[derive(Debug, Clone)]
pub struct System<G = Stribeck, F = Viscous> {
    model: LuGre<G, F>,
    law: FrictionLaw,
    mass: f64,
    damping: f64,
    force: Option<Profile>,
    spring: Option<(f64, Profile)>,
    pid: Option<Pid>,
    velocity: Option<Velocity>,
    /// Velocity levels whose upward crossings are reported as events.
    watch: Vec<f64>,
}

impl<G: VelocityFn, F: VelocityFn> System<G, F> {
    /// A mass `M > 0` with the friction `model`, nothing driving it yet.
    pub fn new(model: LuGre<G, F>, mass: f64) -> Result<Self, DynamicsError> {
        positive("the mass", mass)?;
        Ok(Self {
            model,
            law: FrictionLaw::LuGre,
            mass,
            damping: 0.0,
            force: None,
            spring: None,
            pid: None,
            velocity: None,
            watch: Vec::new(),
        })
    }

    /// An applied force `P(t)` (a profile, or [`Profile::ramp`]).
    pub fn with_force(mut self, force: Profile) -> Self {
        self.force = Some(force);
        self
    }

    /// A linear spring `k >= 0` from the mass to a free end at `x_e(t)`.
    pub fn with_spring(mut self, k: f64, end: Profile) -> Result<Self, DynamicsError> {
        non_negative("the spring stiffness", k)?;
        self.spring = Some((k, end));
        Ok(self)
    }

    /// A linear damper `c >= 0` to the ground.
    pub fn with_damping(mut self, c: f64) -> Result<Self, DynamicsError> {
        non_negative("the damping", c)?;
        self.damping = c;
        Ok(self)
    }

    /// A PID controller on position (gains finite).
    pub fn with_pid(mut self, pid: Pid) -> Result<Self, DynamicsError> {
        for (name, value) in [("Kp", pid.kp), ("Ki", pid.ki), ("Kv", pid.kv)] {
            if !value.is_finite() {
                return Err(DynamicsError::NotFinite { name, value });
            }
        }
        self.pid = Some(pid);
        Ok(self)
    }

    /// A prescribed velocity: the mass follows it (the forces are then only reported, the
    /// drive as the force `M v' + F` that makes the mass follow it).
    pub fn with_velocity(mut self, velocity: Velocity) -> Result<Self, DynamicsError> {
        if let Velocity::Harmonic { mean, amplitude, w } = velocity {
            for (name, value) in [
                ("the mean velocity", mean),
                ("the amplitude", amplitude),
                ("w", w),
            ] {
                if !value.is_finite() {
                    return Err(DynamicsError::NotFinite { name, value });
                }
            }
        }
        self.velocity = Some(velocity);
        Ok(self)
    }

    /// Reports every upward crossing of the velocity `level` as an event
    /// ([`EventKind::VelocityUp`]): with a spring pulled at speed `V`, `v = V` rising is where
    /// the spring force peaks, the slip onset.
    pub fn with_velocity_watch(mut self, level: f64) -> Result<Self, DynamicsError> {
        if !level.is_finite() {
            return Err(DynamicsError::NotFinite {
                name: "the watched velocity",
                value: level,
            });
        }
        self.watch.push(level);
        Ok(self)
    }

    /// Whether the velocity is prescribed (the mass follows it).
    pub(crate) fn prescribed(&self) -> bool {
        self.velocity.is_some()
    }

    /// The linear damper `c` to the ground.
    pub(crate) fn damping(&self) -> f64 {
        self.damping
    }

    /// The velocity levels whose upward crossings are events.
    pub(crate) fn watched(&self) -> &[f64] {
        &self.watch
    }

    /// The friction law ([`FrictionLaw::LuGre`] unless [`System::with_elastoplastic`]).
    pub fn law(&self) -> FrictionLaw {
        self.law
    }

    pub fn model(&self) -> &LuGre<G, F> {
        &self.model
    }

    pub fn mass(&self) -> f64 {
        self.mass
    }

    /// The times in `(0, t_end)` where the drive's slope or the set point jumps.
    pub(crate) fn kinks(&self, t_end: f64) -> Vec<f64> {
        let mut k: Vec<f64> = self
            .force
            .iter()
            .chain(self.spring.iter().map(|(_, end)| end))
            .flat_map(|p| p.kinks().iter().copied())
            .chain(
                self.pid
                    .iter()
                    .flat_map(|p| p.setpoint.steps().iter().copied()),
            )
            .chain(self.velocity.iter().flat_map(|v| v.breakpoints(t_end)))
            .filter(|&t| t > 0.0 && t < t_end)
            .collect();
        k.sort_by(f64::total_cmp);
        k.dedup();
        k
    }

    /// The driving force `F_d` at `t` in state `(x, v, q)`.
    pub fn drive_force(&self, t: f64, x: f64, v: f64, q: f64) -> f64 {
        let mut f = -self.damping * v;
        if let Some(p) = &self.force {
            f += p.value(t);
        }
        if let Some((k, end)) = &self.spring {
            f += k * (end.value(t) - x);
        }
        if let Some(pid) = &self.pid {
            f -= pid.kv * v + pid.kp * (x - pid.setpoint.value(t)) + pid.ki * q;
        }
        f
    }

    /// The force that drives the mass at `t` in state `(x, v, q)` with the friction
    /// `friction`: [`Self::drive_force`], or with a prescribed velocity the force that makes
    /// the mass follow it, `M v' + F`.
    pub(crate) fn applied(&self, t: f64, x: f64, v: f64, q: f64, friction: f64) -> f64 {
        match &self.velocity {
            Some(velocity) => self.mass * velocity.at(t).1 + friction,
            None => self.drive_force(t, x, v, q),
        }
    }

    /// `v(0)`: the prescribed velocity's, else at rest.
    pub(crate) fn initial_velocity(&self) -> f64 {
        self.velocity.as_ref().map_or(0.0, |v| v.at(0.0).0)
    }

    /// The set point's deviation `x - x_d(t)` (the integral state's rate), 0 without a PID.
    pub(crate) fn deviation(&self, t: f64, x: f64) -> f64 {
        self.pid.as_ref().map_or(0.0, |p| x - p.setpoint.value(t))
    }

    /// The friction force and `z'` in state `(v, z)`, with `|v|` taken as `s v` (`s = +-1`), or
    /// as `|v|` when `s = 0`.
    #[inline]
    pub(crate) fn friction(&self, v: f64, z: f64, s: f64) -> (f64, f64) {
        let m = &self.model;
        let dz = match self.law {
            FrictionLaw::LuGre => {
                let speed = if s == 0.0 { v.abs() } else { s * v };
                v - m.sigma0() * speed * z / m.g(v)
            }
            FrictionLaw::ElastoPlastic { zba } => {
                let (slip, _) = self.slip(v, z, s, zba);
                v - slip
            }
        };
        (m.sigma0() * z + m.sigma1() * dz + m.f(v), dz)
    }

    /// (D2)'s slip rate `v alpha(w) w / z_ss` (what `z'` lacks of `v`) and the friction power
    /// it dissipates in the bristles, `sigma0 alpha w^2 |v| / z_ss`, with `|v| = s v`.
    #[inline]
    fn slip(&self, v: f64, z: f64, s: f64, zba: f64) -> (f64, f64) {
        let m = &self.model;
        let sign = if s == 0.0 { v.signum() } else { s };
        let (w, speed) = (sign * z, sign * v);
        let z_ss = m.g(v) / m.sigma0();
        let a = crate::zoo::elastoplastic_alpha(w, zba, z_ss);
        let ratio = a * w / z_ss;
        (v * ratio, m.sigma0() * ratio * w * speed)
    }

    /// The power put in by the drive and the power dissipated, in state `y` with the sign `s`
    /// (see [`EnergyBalance`]).
    pub(crate) fn power(&self, t: f64, y: &[f64; 4], s: f64) -> [f64; 2] {
        let m = &self.model;
        let [x, state_v, z, q] = *y;
        let (v, dv) = match &self.velocity {
            Some(velocity) => velocity.at(t),
            None => (state_v, 0.0),
        };
        let (friction, dz) = self.friction(v, z, s);
        let bristles = match self.law {
            FrictionLaw::LuGre => {
                let speed = if s == 0.0 { v.abs() } else { s * v };
                m.sigma0() * m.sigma0() * speed * z * z / m.g(v)
            }
            FrictionLaw::ElastoPlastic { zba } => self.slip(v, z, s, zba).1,
        };
        let dissipated_friction = bristles + m.sigma1() * dz * v + m.f(v) * v;
        if self.velocity.is_some() {
            return [(self.mass * dv + friction) * v, dissipated_friction];
        }
        let mut input = 0.0;
        if let Some(p) = &self.force {
            input += p.value(t) * v;
        }
        if let Some(pid) = &self.pid {
            input -= (pid.kv * v + pid.kp * (x - pid.setpoint.value(t)) + pid.ki * q) * v;
        }
        if let Some((k, end)) = &self.spring {
            let (xe, ve) = end.value_and_slope(t);
            input += k * (xe - x) * ve;
        }
        [input, dissipated_friction + self.damping * v * v]
    }

    /// The energy stored: kinetic, in the spring and in the bristles (a prescribed velocity:
    /// kinetic and the bristles).
    pub(crate) fn stored(&self, t: f64, y: &[f64; 4]) -> f64 {
        let [x, v, z, _] = *y;
        let bristles = 0.5 * self.model.sigma0() * z * z;
        if let Some(velocity) = &self.velocity {
            let v = velocity.at(t).0;
            return 0.5 * self.mass * v * v + bristles;
        }
        let spring = self
            .spring
            .as_ref()
            .map_or(0.0, |(k, end)| 0.5 * k * (end.value(t) - x).powi(2));
        0.5 * self.mass * v * v + spring + bristles
    }

    /// The state's rate `(x', v', z', q')` with the sign `s` (see [`Self::friction`]).
    #[inline]
    pub(crate) fn rate(&self, t: f64, y: &[f64; 4], s: f64) -> [f64; 4] {
        if let Some(velocity) = &self.velocity {
            // Kinematic: v is the prescribed one (the state's v follows it exactly).
            let (v, dv) = velocity.at(t);
            let (_, dz) = self.friction(v, y[2], s);
            return [v, dv, dz, 0.0];
        }
        let [x, v, z, q] = *y;
        let (friction, dz) = self.friction(v, z, s);
        let a = (self.drive_force(t, x, v, q) - friction) / self.mass;
        [v, a, dz, self.deviation(t, x)]
    }
}

impl System<Stribeck, Viscous> {
    /// The elasto-plastic friction law (D2) with break-away displacement `zba` on this
    /// system's model (its `sigma0`, `sigma1`, Stribeck `g` and viscous `f`).
    ///
    /// # Errors
    /// [`DynamicsError::BadBreakaway`] unless `0 <= zba < min(Fc, Fs) / sigma0` (below every
    /// steady-state deflection `g(v) / sigma0`: Dupont et al.'s condition for stiction).
    pub fn with_elastoplastic(mut self, zba: f64) -> Result<Self, DynamicsError> {
        let p = self.model.params();
        let limit = p.fc.min(p.fs) / p.sigma0;
        if !(zba.is_finite() && zba >= 0.0 && zba < limit) {
            return Err(DynamicsError::BadBreakaway { value: zba, limit });
        }
        self.law = FrictionLaw::ElastoPlastic { zba };
        Ok(self)
    }
}

fn positive(name: &'static str, value: f64) -> Result<f64, DynamicsError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(DynamicsError::NotPositive { name, value })
    }
}

fn non_negative(name: &'static str, value: f64) -> Result<f64, DynamicsError> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(DynamicsError::Negative { name, value })
    }
}
