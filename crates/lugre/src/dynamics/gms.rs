//! GMS friction (the Maxwell-slip model at finite rate, [`crate::zoo::gms`], (G1)-(G3)) on the
//! mass of [`super::System`], event-driven (`docs/mathematics.md`, "GMS as the friction of the
//! dynamics").
//!
//! Between events every element keeps its mode. With the sticking set `S` (forces `F_i0` and
//! position `x0` at the last event, `K_S = sum_S k_i`) and the slipping set `P` (all slipping in
//! the direction `s_P` of the motion they started in, `A = sum_P alpha_i`):
//!
//! ```text
//! (G6)  sum_S F_i = sum_S F_i0 + K_S (x - x0)                    (algebraic in x)
//!       G = sum_P F_i,      G' = lambda(v) (A s_P g(v) - G)      (one state for all of P)
//!       F_i = (alpha_i / A) G + w_i E,  E' = -lambda(v) E,  E(t0) = 1,  w_i = F_i0 - alpha_i G0 / A
//!       M v' = F_d - F,     F = sum_S F_i + G + (sigma1 / K) (K_S v + G') + sigma2 v
//! ```
//!
//! (`w_i' = -lambda w_i` for `w_i = F_i - (alpha_i / A) G`, from (G2)), so the state is
//! `(x, v, q, G, E)` whatever the number of elements, and smooth between events: the Radau IIA
//! integrator of the LuGre system (`integrator.rs`, L-stable: any `K / M`) steps it. The events,
//! each located by bisection on the collocation polynomial and then reached by a step of its
//! own, change the modes: a sticking element slips once `sgn(v) F_i` reaches `alpha_i g(v)`
//! (`v != 0`), and every slipping element sticks once `v` reverses (`s_P v <= 0`: an event
//! [`EventKind::VelocityZero`]). While every element sticks the rate does not depend on the
//! sign of `v`, so a mass ringing at rest costs no events.
//!
//! The energy balance: the drive's work, the energy stored (kinetic, spring, `sum F_i^2 /
//! (2 k_i)` in the elements) and the dissipation, whose friction part is
//!
//! ```text
//! (G7)  F v - d/dt sum_i F_i^2 / (2 k_i) = sum_P F_i (v - F_i' / k_i) + (sigma1 / K) v sum_i F_i' + sigma2 v^2
//! ```
//!
//! (a sticking element stores all its work), each integrated by the steps' own quadrature.

use super::integrator::{dense, error_estimate, guess, quadrature, solve_stages, Factors, Newton};
use super::loops::{loop_times, LoopTrace};
use super::solver::bisect;
use super::{Breakaway, Event, EventKind, Motion, System, Tolerances};
use crate::error::DynamicsError;
use crate::zoo::gms::Gms;

/// `(x, v, q, G, E)`.
const D: usize = 5;
type Y = [f64; D];

/// Points per step where the events' conditions are looked at before bisecting.
const LOOKS: usize = 8;
/// Steps before the solver gives up.
const MAX_STEPS: usize = 10_000_000;

/// The elements' modes and forces at the last event: what (G6) is relative to.
#[derive(Debug, Clone)]
struct Modes {
    x0: f64,
    f0: Vec<f64>,
    /// 0 sticking, else the direction of slipping.
    slip: Vec<f64>,
    /// `w_i` of (G6) of each slipping element.
    w0: Vec<f64>,
    stick_force: f64,
    stick_k: f64,
    dir: f64,
    a: f64,
}

impl Modes {
    /// Modes `slip` at position `x` with element forces `f0`; and `G` there.
    fn new(gms: &Gms, x: f64, f0: Vec<f64>, slip: Vec<f64>) -> (Self, f64) {
        let (k, alpha) = (gms.stiffness(), gms.weights());
        let (mut stick_force, mut stick_k, mut a, mut g, mut dir) = (0.0, 0.0, 0.0, 0.0, 0.0);
        for i in 0..f0.len() {
            if slip[i] == 0.0 {
                stick_force += f0[i];
                stick_k += k[i];
            } else {
                (a, g, dir) = (a + alpha[i], g + f0[i], slip[i]);
            }
        }
        let w0 = (0..f0.len())
            .map(|i| {
                if slip[i] == 0.0 {
                    0.0
                } else {
                    f0[i] - alpha[i] * g / a
                }
            })
            .collect();
        let modes = Self {
            x0: x,
            f0,
            slip,
            w0,
            stick_force,
            stick_k,
            dir,
            a,
        };
        (modes, g)
    }

    /// Each element's force in state `y` (G6).
    fn forces(&self, gms: &Gms, y: &Y) -> Vec<f64> {
        let (k, alpha) = (gms.stiffness(), gms.weights());
        (0..self.f0.len())
            .map(|i| {
                if self.slip[i] == 0.0 {
                    self.f0[i] + k[i] * (y[0] - self.x0)
                } else {
                    alpha[i] / self.a * y[3] + self.w0[i] * y[4]
                }
            })
            .collect()
    }
}

/// The full state of a mass with GMS friction between events: time, position, velocity,
/// each element's force and mode (0 sticking, else the direction it slips in).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct GmsState {
    pub t: f64,
    pub x: f64,
    pub v: f64,
    pub forces: Vec<f64>,
    pub slip: Vec<f64>,
}

impl GmsState {
    /// At `(t, x, v)` with every one of `n` elements sticking at force 0.
    pub(crate) fn at_rest(n: usize, t: f64, x: f64, v: f64) -> Self {
        Self {
            t,
            x,
            v,
            forces: vec![0.0; n],
            slip: vec![0.0; n],
        }
    }
}

/// One run of the system with GMS friction.
pub(crate) struct GmsRun<'a> {
    system: &'a System,
    gms: &'a Gms,
    modes: Modes,
    rtol: f64,
    atol: Y,
    newton_tol: f64,
    out: Motion,
    /// Whether the first peak of the friction is still looked for.
    find_peak: bool,
    breakaway: Option<Breakaway>,
    /// The energy stored in the elements at each output, `sum F_i^2 / (2 k_i)` (L2).
    energy_out: Vec<f64>,
}

impl<'a> GmsRun<'a> {
    /// A run from rest (every element sticking at force 0).
    pub(crate) fn new(system: &'a System, gms: &'a Gms, tol: Tolerances, peak: bool) -> Self {
        let n = gms.stiffness().len();
        let (modes, _) = Modes::new(gms, 0.0, vec![0.0; n], vec![0.0; n]);
        let stiffness: f64 = gms.stiffness().iter().sum();
        let fs = gms.g(0.0);
        let rtol = tol.rtol();
        let atol_x = tol.atol().unwrap_or(rtol * fs / stiffness);
        let w0 = (stiffness / system.mass()).sqrt();
        let rtol_n = 0.1 * rtol.powf(2.0 / 3.0);
        Self {
            system,
            gms,
            modes,
            rtol,
            atol: [atol_x, atol_x * w0, atol_x, atol_x * stiffness, rtol],
            newton_tol: (10.0 * f64::EPSILON / rtol_n).max(0.03f64.min(rtol_n.sqrt())),
            out: Motion::default(),
            find_peak: peak,
            breakaway: None,
            energy_out: Vec::new(),
        }
    }

    /// The rate of (G6) and the friction force in state `y` at `t`.
    fn rate(&self, t: f64, y: &Y) -> (Y, f64) {
        let (m, g) = (&self.modes, self.gms);
        let [x, v, q, big_g, e] = *y;
        let gv = g.g(v);
        let lambda = g.rate().attraction / gv;
        let (dg, de) = if m.dir == 0.0 {
            (0.0, 0.0)
        } else {
            (lambda * (m.a * m.dir * gv - big_g), -lambda * e)
        };
        let stick = m.stick_force + m.stick_k * (x - m.x0);
        let friction = stick + big_g + g.damping() * (m.stick_k * v + dg) + g.rate().sigma2 * v;
        let applied = self.system.applied(t, x, v, q, friction);
        let dv = (applied - friction) / self.system.mass();
        ([v, dv, self.system.deviation(t, x), dg, de], friction)
    }

    /// Whether an event has happened by state `y`: a reversal of the slipping elements, or a
    /// sticking element at its slip level.
    fn event(&self, y: &Y) -> bool {
        let v = y[1];
        if self.modes.dir != 0.0 && self.modes.dir * v <= 0.0 {
            return true;
        }
        v != 0.0 && self.onsets(y).next().is_some()
    }

    /// The sticking elements at or beyond their slip level in state `y` (moving at `v != 0`).
    fn onsets<'b>(&'b self, y: &'b Y) -> impl Iterator<Item = usize> + 'b {
        let s = y[1].signum();
        let level = self.gms.g(y[1]);
        let forces = self.modes.forces(self.gms, y);
        let alpha = self.gms.weights();
        (0..forces.len())
            .filter(move |&i| self.modes.slip[i] == 0.0 && alpha[i] * level - s * forces[i] <= 0.0)
    }

    /// The modes after the event at state `y` (`at`: the state where it was located, whose
    /// onsets switch); returns the state to go on from (`G` recomputed, `E = 1`).
    fn switch(&mut self, t: f64, y: &Y, at: &Y) -> Y {
        let mut slip = self.modes.slip.clone();
        if self.modes.dir != 0.0 && self.modes.dir * at[1] <= 0.0 {
            slip.iter_mut().for_each(|m| *m = 0.0);
            let kind = EventKind::VelocityZero;
            self.out.events.push(Event { t, kind, x: y[0] });
        }
        if at[1] != 0.0 {
            let onsets: Vec<usize> = self.onsets(at).collect();
            for i in onsets {
                slip[i] = at[1].signum();
            }
        }
        let forces = self.modes.forces(self.gms, y);
        let (modes, g) = Modes::new(self.gms, y[0], forces, slip);
        self.modes = modes;
        self.out.stats.restarts += 1;
        [y[0], y[1], y[2], g, 1.0]
    }

    /// The Jacobian of the rate at `(t, y)` by forward differences.
    fn jacobian(&mut self, t: f64, y: &Y, f0: &Y) -> [[f64; D]; D] {
        let mut j = [[0.0; D]; D];
        for c in 0..D {
            let delta = 1e-7 * y[c].abs().max(self.atol[c] / self.rtol);
            let mut yc = *y;
            yc[c] += delta;
            let fc = self.rate(t, &yc).0;
            for r in 0..D {
                j[r][c] = (fc[r] - f0[r]) / delta;
            }
        }
        self.out.stats.jacobians += 1;
        self.out.stats.rhs_evaluations += D;
        j
    }

    fn weights(&self, y: &Y) -> Y {
        std::array::from_fn(|r| self.atol[r] + self.rtol * y[r].abs())
    }

    /// One Radau step of size `h` from `(t, y)`: the stage values and the scaled error, or the
    /// factor to retry with.
    fn step(
        &mut self,
        t: f64,
        y: &Y,
        h: f64,
        guess0: [[f64; D]; 3],
    ) -> Result<([[f64; D]; 3], f64), f64> {
        let f0 = self.rate(t, y).0;
        let jac = self.jacobian(t, y, &f0);
        let factors = Factors::new(&jac, h).ok_or(0.5)?;
        let scal = self.weights(y);
        let mut newton = Newton {
            faccon: 1.0,
            tol: self.newton_tol,
            lenient: true,
        };
        let f = |t: f64, y: &Y| self.rate(t, y).0;
        let step = solve_stages(&f, &factors, t, y, &scal, guess0, &mut newton)?;
        let f_start = |y: &Y| f(t, y);
        let (err, extra) = error_estimate(f_start, &factors, y, &f0, &step, &scal, true);
        self.out.stats.rhs_evaluations += step.evaluations + extra + 1;
        Ok((step.stages, err))
    }

    /// The friction force in the state `start` (its modes and element forces).
    pub(crate) fn friction_at(&mut self, start: &GmsState) -> f64 {
        let y = self.load(start);
        self.rate(start.t, &y).1
    }

    /// Takes the modes and element forces of `start` as the last event's (a restart: the
    /// same motion as going on); returns `(x, v, q, G, E)` there.
    fn load(&mut self, start: &GmsState) -> Y {
        let (modes, g) = Modes::new(self.gms, start.x, start.forces.clone(), start.slip.clone());
        self.modes = modes;
        [start.x, start.v, 0.0, g, 1.0]
    }

    /// From `start` to `t_end` (> `start.t`) through the drive's kinks and the events on
    /// the way (located as [`Self::solve`] locates them); returns the state at `t_end` and
    /// the friction force there.
    pub(crate) fn run_from(
        mut self,
        start: &GmsState,
        t_end: f64,
    ) -> Result<(GmsState, f64), DynamicsError> {
        let mut y = self.load(start);
        let mut t = start.t;
        let w0 = (self.gms.stiffness().iter().sum::<f64>() / self.system.mass()).sqrt();
        let mut h = (0.1 * self.rtol.powf(0.25) / w0).min(t_end - t);
        let t0 = t;
        let kinks = self.system.kinks(t_end);
        for stop in kinks.into_iter().filter(|&k| k > t0).chain([t_end]) {
            (t, y, h) = self.advance(t, y, stop, h)?;
        }
        let friction = self.rate(t, &y).1;
        let state = GmsState {
            t,
            x: y[0],
            v: y[1],
            forces: self.modes.forces(self.gms, &y),
            slip: self.modes.slip.clone(),
        };
        Ok((state, friction))
    }

    /// The motion over `[0, t_end]` at `times` (increasing, in `[0, t_end]`), stopping at each
    /// output time and each kink of the drive.
    pub(crate) fn solve(
        self,
        t_end: f64,
        times: &[f64],
    ) -> Result<(Motion, Option<Breakaway>), DynamicsError> {
        let run = self.integrate(t_end, times)?;
        Ok((run.out, run.breakaway))
    }

    /// The outputs over `[0, t_end]` the friction loops are taken from
    /// ([`super::loops::LoopTrace`]: the stored energy is the elements').
    pub(crate) fn trace(self, t_end: f64) -> Result<LoopTrace, DynamicsError> {
        let run = self.integrate(t_end, &loop_times(t_end))?;
        let m = run.out;
        Ok(LoopTrace {
            t: m.t,
            x: m.x,
            friction: m.friction,
            stored: run.energy_out,
        })
    }

    /// [`Self::solve`]'s run, the outputs kept in `self`.
    fn integrate(mut self, t_end: f64, times: &[f64]) -> Result<Self, DynamicsError> {
        let mut stops: Vec<f64> = self.system.kinks(t_end);
        let kinks = stops.clone();
        stops.extend(times.iter().copied().filter(|&t| t > 0.0 && t <= t_end));
        stops.push(t_end);
        stops.sort_by(f64::total_cmp);
        stops.dedup();
        let mut y: Y = [0.0, self.system.initial_velocity(), 0.0, 0.0, 1.0];
        let mut t = 0.0;
        self.out.energy.stored_start = self.stored(t, &y);
        if times.first() == Some(&0.0) {
            self.record(t, &y);
        }
        let w0 = (self.gms.stiffness().iter().sum::<f64>() / self.system.mass()).sqrt();
        let mut h = (0.1 * self.rtol.powf(0.25) / w0).min(t_end);
        for stop in stops {
            (t, y, h) = self.advance(t, y, stop, h)?;
            if kinks.contains(&stop) {
                let kind = EventKind::Kink;
                self.out.events.push(Event { t, kind, x: y[0] });
            }
            if times.binary_search_by(|x| x.total_cmp(&stop)).is_ok() {
                self.record(t, &y);
            }
        }
        self.out.energy.stored_end = self.stored(t, &y);
        Ok(self)
    }

    /// Integrates from `(t, y)` to exactly `stop`, through the events on the way.
    fn advance(
        &mut self,
        mut t: f64,
        mut y: Y,
        stop: f64,
        mut h: f64,
    ) -> Result<(f64, Y, f64), DynamicsError> {
        let mut guess0 = [[0.0; D]; 3];
        while t < stop {
            if self.out.stats.steps + self.out.stats.rejected > MAX_STEPS {
                let reason = format!("more than {MAX_STEPS} steps");
                return Err(DynamicsError::Solver { t, reason });
            }
            let last = h >= stop - t;
            let hs = if last { stop - t } else { h };
            let (stages, err) = match self.step(t, &y, hs, guess0) {
                Ok(s) => s,
                Err(q) => {
                    self.out.stats.rejected += 1;
                    h = hs * q;
                    guess0 = [[0.0; D]; 3];
                    continue;
                }
            };
            let factor = (0.9 * err.powf(-0.25)).clamp(0.2, 8.0);
            if err > 1.0 {
                self.out.stats.rejected += 1;
                h = hs * factor;
                guess0 = [[0.0; D]; 3];
                continue;
            }
            self.out.stats.steps += 1;
            let t_stop = if last { stop } else { t + hs };
            let (t1, y1, event) = self.land(t, &y, hs, &stages, t_stop);
            check_finite(t1, &y1)?;
            guess0 = if event {
                [[0.0; D]; 3]
            } else {
                guess(&y, &stages, 1.0, factor)
            };
            (t, y) = (t1, y1);
            h = if event { hs } else { hs * factor };
        }
        Ok((t, y, h))
    }

    /// Where an accepted step from `(t, y)` of size `h` ends: at the first event inside it
    /// (located on the collocation polynomial, then reached by a step of its own, and the
    /// modes switched there), else at its end `t_end`; the watched crossings and the peak are
    /// looked for up to there, in the modes of the step.
    fn land(
        &mut self,
        t: f64,
        y: &Y,
        h: f64,
        stages: &[[f64; D]; 3],
        t_end: f64,
    ) -> (f64, Y, bool) {
        let at = |theta: f64| dense(y, stages, theta);
        let first = (1..=LOOKS).find(|&k| self.event(&at(k as f64 / LOOKS as f64)));
        let Some(k) = first else {
            self.watch(t, y, stages, h, t_end);
            self.account(t, h, stages);
            return (t_end, stages[2], false);
        };
        let lo = (k - 1) as f64 / LOOKS as f64;
        let theta = bisect(|th| self.event(&at(th)), lo, k as f64 / LOOKS as f64);
        let located = at(theta);
        let te = t + theta * h;
        self.watch(t, y, stages, h, te);
        // The event's state by a step of its own (the polynomial is of lower order inside).
        let event_stages = match self.step(t, y, theta * h, [[0.0; D]; 3]) {
            Ok((s, _)) => s,
            Err(_) => std::array::from_fn(|i| at(crate::kernel::radau::C[i] * theta)),
        };
        self.account(t, theta * h, &event_stages);
        let y_event = event_stages[2];
        let next = self.switch(te, &y_event, &located);
        (te, next, true)
    }

    /// Upward crossings of the watched velocities and the first peak of the friction within
    /// the step from `(t, y)` of size `h`, up to `t_kept`.
    fn watch(&mut self, t: f64, y: &Y, stages: &[[f64; D]; 3], h: f64, t_kept: f64) {
        let theta_end = ((t_kept - t) / h).min(1.0);
        let at = |theta: f64| dense(y, stages, theta * theta_end);
        for &level in self.system.watched() {
            let (v0, v1) = (y[1], at(1.0)[1]);
            if v0 < level && v1 >= level {
                let th = bisect(|th| at(th)[1] >= level, 0.0, 1.0);
                let kind = EventKind::VelocityUp;
                let te = t + th * theta_end * h;
                self.out.events.push(Event {
                    t: te,
                    kind,
                    x: at(th)[0],
                });
            }
        }
        if self.find_peak {
            self.peak(t, y, stages, h, theta_end);
        }
    }

    /// The first local maximum of the friction inside the step (its samples compared within
    /// the step: a jump of the damping term at an event is not a peak).
    fn peak(&mut self, t: f64, y: &Y, stages: &[[f64; D]; 3], h: f64, theta_end: f64) {
        let at = |theta: f64| dense(y, stages, theta * theta_end);
        let friction = |th: f64| self.rate(t + th * theta_end * h, &at(th)).1;
        let mut prev = friction(0.0);
        for k in 1..=LOOKS {
            let th = k as f64 / LOOKS as f64;
            let f = friction(th);
            if f < prev {
                let lo = (k as f64 - 2.0).max(0.0) / LOOKS as f64;
                let top = golden(&friction, lo, th);
                self.breakaway = Some(Breakaway {
                    t: t + top * theta_end * h,
                    force: friction(top),
                    x: at(top)[0],
                });
                self.find_peak = false;
                return;
            }
            prev = f;
        }
    }

    /// The power put in by the drive and the power dissipated by the friction and the damper
    /// in state `y` at `t` (G7): the friction's is `F v - d/dt sum F_i^2 / (2 k_i)`, 0 for a
    /// sticking element (`F_i' = k_i v`).
    fn power(&self, t: f64, y: &Y) -> [f64; 2] {
        let [x, v, q, _, _] = *y;
        let friction = self.rate(t, y).1;
        let input = if self.system.prescribed() {
            self.system.applied(t, x, v, q, friction) * v
        } else {
            self.system.power(t, &[x, v, 0.0, q], 0.0)[0]
        };
        let (k, alpha) = (self.gms.stiffness(), self.gms.weights());
        let g = self.gms.g(v);
        let lambda = self.gms.rate().attraction / g;
        let forces = self.modes.forces(self.gms, y);
        let elastic: f64 = (0..forces.len())
            .filter(|&i| self.modes.slip[i] != 0.0)
            .map(|i| forces[i] * lambda * (alpha[i] * self.modes.dir * g - forces[i]) / k[i])
            .sum();
        let sticking: f64 = (0..forces.len())
            .filter(|&i| self.modes.slip[i] == 0.0)
            .map(|i| forces[i] * v)
            .sum();
        let damper = self.system.damping() * v * v;
        [input, friction * v - elastic - sticking + damper]
    }

    /// The energy stored in state `y` at `t`: kinetic, in the spring, in the elements.
    fn stored(&self, t: f64, y: &Y) -> f64 {
        let [x, v, q, _, _] = *y;
        let elements = self.element_energy(&self.modes.forces(self.gms, y));
        self.system.stored(t, &[x, v, 0.0, q]) + elements
    }

    /// The energy in the elements' springs with forces `forces`, `sum F_i^2 / (2 k_i)`.
    fn element_energy(&self, forces: &[f64]) -> f64 {
        forces
            .iter()
            .zip(self.gms.stiffness())
            .map(|(f, k)| 0.5 * f * f / k)
            .sum()
    }

    /// Adds the input and the dissipation over the step from `t` of size `h` with `stages`.
    fn account(&mut self, t: f64, h: f64, stages: &[[f64; D]; 3]) {
        let [input, dissipated] = quadrature(h, t, stages, |t, y| self.power(t, y));
        self.out.energy.input += input;
        self.out.energy.dissipated += dissipated;
    }

    /// Appends the state at `t` to the output.
    fn record(&mut self, t: f64, y: &Y) {
        let (_, friction) = self.rate(t, y);
        let stiffness: f64 = self.gms.stiffness().iter().sum();
        let element_forces = self.modes.forces(self.gms, y);
        let energy = self.element_energy(&element_forces);
        self.energy_out.push(energy);
        let forces: f64 = element_forces.iter().sum();
        let o = &mut self.out;
        o.t.push(t);
        o.x.push(y[0]);
        o.v.push(y[1]);
        o.z.push(forces / stiffness);
        o.friction.push(friction);
        o.drive
            .push(self.system.applied(t, y[0], y[1], y[2], friction));
    }
}

/// The maximum of `f` on `[lo, hi]` by golden-section search.
fn golden(f: &impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    let r = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..100 {
        let (a, b) = (hi - r * (hi - lo), lo + r * (hi - lo));
        if f(a) < f(b) {
            lo = a;
        } else {
            hi = b;
        }
    }
    0.5 * (lo + hi)
}

fn check_finite(t: f64, y: &Y) -> Result<(), DynamicsError> {
    if y.iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(DynamicsError::Overflow { t })
    }
}
