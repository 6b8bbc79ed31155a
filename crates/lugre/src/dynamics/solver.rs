//! The solver: the dedicated Radau IIA integrator (`integrator.rs`) with error control, landing
//! exactly on every kink of the drive and restarted at every located sign change of the
//! velocity (module docs of [`super`]).
//!
//! Absolute tolerances follow the system's own scales: `atol` on displacements (`x`, `z`, and
//! the integral `q` per second), `atol w0` on the velocity, with the natural frequency
//! `w0 = sqrt(sigma0 / M)` of the mass on its bristles.

use super::integrator::{
    dense, iteration_matrix, next_guess, quadrature, radau_step, radau_step_with, Step, N, NODES,
};
use super::System;
use crate::error::DynamicsError;
use crate::model::VelocityFn;

/// The solver's tolerances: relative `rtol` and absolute `atol` on displacements (in metres;
/// the velocity gets `atol w0`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerances {
    rtol: f64,
    atol: Option<f64>,
}

impl Tolerances {
    /// The default relative tolerance.
    pub const DEFAULT_RTOL: f64 = 1e-8;

    /// `rtol` in `(0, 1)`; `atol` finite and `> 0`, or `None` for `rtol` times the bristle
    /// length `g(0) / sigma0`.
    pub fn new(rtol: f64, atol: Option<f64>) -> Result<Self, DynamicsError> {
        if !(rtol > 0.0 && rtol < 1.0) {
            return Err(DynamicsError::BadTolerance {
                name: "rtol",
                value: rtol,
            });
        }
        if let Some(a) = atol {
            if !(a.is_finite() && a > 0.0) {
                return Err(DynamicsError::BadTolerance {
                    name: "atol",
                    value: a,
                });
            }
        }
        Ok(Self { rtol, atol })
    }

    pub fn rtol(&self) -> f64 {
        self.rtol
    }
}

impl Default for Tolerances {
    fn default() -> Self {
        Self {
            rtol: Self::DEFAULT_RTOL,
            atol: None,
        }
    }
}

/// What happened at an event.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EventKind {
    /// The velocity changed sign (a reversal; the mass sticks or slips through it).
    VelocityZero,
    /// The drive's slope or the set point jumped.
    Kink,
    /// The velocity rose through a watched level ([`System::with_velocity_watch`]).
    VelocityUp,
}

impl EventKind {
    pub fn name(self) -> &'static str {
        match self {
            EventKind::VelocityZero => "velocity_zero",
            EventKind::Kink => "kink",
            EventKind::VelocityUp => "velocity_up",
        }
    }
}

/// An event, located to the integrator's accuracy.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Event {
    pub t: f64,
    pub kind: EventKind,
    /// The position there.
    pub x: f64,
}

/// What the solver did.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Stats {
    pub steps: usize,
    pub rejected: usize,
    pub rhs_evaluations: usize,
    pub jacobians: usize,
    /// Restarts of the integrator (at kinks and velocity sign changes).
    pub restarts: usize,
}

/// A state of the system: where a run starts ([`System::solve_from`]; at rest at `t = 0` by
/// default).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct State {
    pub t: f64,
    pub x: f64,
    pub v: f64,
    /// The bristle deflection.
    pub z: f64,
    /// The PID's integral of `x - x_d` (0 without a PID).
    pub q: f64,
}

/// The motion at the requested times.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Motion {
    pub t: Vec<f64>,
    pub x: Vec<f64>,
    pub v: Vec<f64>,
    pub z: Vec<f64>,
    /// The friction force `F` on the mass.
    pub friction: Vec<f64>,
    /// The driving force `F_d` (just after a jump of the set point).
    pub drive: Vec<f64>,
    pub events: Vec<Event>,
    pub stats: Stats,
    /// The energy balance over the run.
    pub energy: EnergyBalance,
}

/// The energy balance over a run: what the drive put in equals the change of what is stored
/// (kinetic, spring and bristle energy) plus what was dissipated (friction, damper), to the
/// solver's accuracy (each term is integrated by the steps' own quadrature).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct EnergyBalance {
    /// The work of the applied force, the controller and the spring's moving end (a prescribed
    /// velocity: the work done against the friction).
    pub input: f64,
    /// Kinetic + spring + bristle energy at the start and at the end.
    pub stored_start: f64,
    pub stored_end: f64,
    /// Dissipated by the friction (`sigma0^2 |v| z^2 / g + sigma1 z' v + f(v) v`) and the damper.
    pub dissipated: f64,
}

impl EnergyBalance {
    /// `input - (stored_end - stored_start) - dissipated`: 0 up to the integration's error.
    pub fn residual(&self) -> f64 {
        self.input - (self.stored_end - self.stored_start) - self.dissipated
    }
}

/// The largest factor a step may grow by, and the safety factor of the step-size rule.
const MAX_GROWTH: f64 = 3.0;
const SAFETY: f64 = 0.9;
/// The sign of `v` stops being frozen once the ringing amplitude `|v'| / w0` at a sign change
/// is below this fraction of the velocity tolerance (so that stepping over the remaining kinks
/// costs less than the tolerance; above it the kinks of a ringing mass cost accuracy).
const RINGING: f64 = 1e-3;
/// Steps before the solver gives up.
const MAX_STEPS: usize = 10_000_000;

impl<G: VelocityFn, F: VelocityFn> System<G, F> {
    /// The motion from rest over `[0, t_end]`, reported at `times` (strictly increasing, in
    /// `[0, t_end]`), with the sign changes of `v` and the kinks of the drive as events.
    pub fn solve(
        &self,
        t_end: f64,
        times: &[f64],
        tol: Tolerances,
    ) -> Result<Motion, DynamicsError> {
        let start = State {
            v: self.initial_velocity(),
            ..State::default()
        };
        Ok(self.integrate(start, t_end, times, tol, false)?.0)
    }

    /// [`Self::solve`] from the state `start` (its time, position, velocity, deflection and
    /// the PID's integral) instead of rest at `t = 0`: `times` in `[start.t, t_end]`. What a
    /// host that advances the system step by step needs (the FMU of the mass).
    pub fn solve_from(
        &self,
        start: State,
        t_end: f64,
        times: &[f64],
        tol: Tolerances,
    ) -> Result<Motion, DynamicsError> {
        for (name, value) in [
            ("the start time", start.t),
            ("the start position", start.x),
            ("the start velocity", start.v),
            ("the start deflection", start.z),
            ("the start integral", start.q),
        ] {
            if !value.is_finite() {
                return Err(DynamicsError::NotFinite { name, value });
            }
        }
        Ok(self.integrate(start, t_end, times, tol, false)?.0)
    }

    /// [`Self::solve`]; with `to_peak`, it stops at the first local maximum of the friction
    /// force (the sign change of `dF/dt` from + to -, located on the collocation polynomial)
    /// and also returns the state there (`t`, `x`, `F`).
    fn integrate(
        &self,
        start: State,
        t_end: f64,
        times: &[f64],
        tol: Tolerances,
        to_peak: bool,
    ) -> Result<(Motion, Option<Breakaway>), DynamicsError> {
        check_times(start.t, t_end, times)?;
        let m = self.model();
        let w0 = (m.sigma0() / self.mass()).sqrt();
        let length = m.g0() / m.sigma0();
        let atol = tol.atol.unwrap_or(tol.rtol * length);
        let atol = [atol, atol * w0, atol, atol];
        let mut run = Run {
            system: self,
            rtol: tol.rtol,
            atol,
            w0,
            out: Motion::default(),
            times,
            next_time: 0,
            rising: false,
        };
        let kinks: Vec<f64> = self
            .kinks(t_end)
            .into_iter()
            .filter(|&k| k > start.t)
            .collect();
        let mut y = [start.x, start.v, start.z, start.q];
        let mut t = start.t;
        let mut h = (0.01 / w0).min(t_end - t);
        run.report_until(t, &y, 0.0, None);
        run.out.energy.stored_start = self.stored(t, &y);
        let mut rejected = false;
        for bound in kinks.iter().copied().chain(std::iter::once(t_end)) {
            let mut s = self.start_sign(t, &y);
            while t < bound {
                if run.out.stats.steps + run.out.stats.rejected > MAX_STEPS {
                    return Err(DynamicsError::Solver {
                        t,
                        reason: format!("more than {MAX_STEPS} steps"),
                    });
                }
                let last = t + h >= bound;
                let step = if last { bound - t } else { h };
                match run.double_step(t, &y, step, s) {
                    Err(factor) => {
                        run.out.stats.rejected += 1;
                        rejected = true;
                        h = step * factor;
                        if h.is_nan() || h <= f64::EPSILON * t.abs().max(1.0) {
                            return Err(DynamicsError::Solver {
                                t,
                                reason: "the step fell below the resolution of t".into(),
                            });
                        }
                    }
                    Ok((halves, factor)) => {
                        run.out.stats.steps += 1;
                        let end = if last { bound } else { t + step };
                        let crossing = run.crossing(t, step, &halves, s);
                        let kept = crossing.map_or(end, |c| c.0);
                        run.watch(t, step, &halves, kept);
                        if to_peak {
                            if let Some(tp) = run.friction_peak(t, step, &halves, s, kept) {
                                return run.peak_at(t, &y, step, &halves, tp, s);
                            }
                        }
                        match crossing {
                            Some((tc, yc)) => {
                                // v changed sign: the step is kept up to the crossing only,
                                // and the state there is a step of its own (the dense output
                                // is of lower order than the step).
                                let yc = match run.step_to_with(t, &y, tc, s) {
                                    Some((yc, halves_c)) => {
                                        run.account(t, tc - t, &halves_c, s);
                                        yc
                                    }
                                    None => {
                                        run.account_dense(t, step, &halves, tc, s);
                                        yc
                                    }
                                };
                                run.report_until(tc, &yc, s, Some((t, &y, step, &halves)));
                                let (yc, s_next) = run.reversal(tc, yc);
                                (t, y, s) = (tc, yc, s_next);
                            }
                            None => {
                                run.account(t, step, &[halves[0].0, halves[1].0], s);
                                let y_end = halves[1].0.y;
                                run.report_until(end, &y_end, s, Some((t, &y, step, &halves)));
                                (t, y) = (end, y_end);
                            }
                        }
                        check_finite(t, &y)?;
                        // No growth right after a rejection (the usual guard against
                        // alternating accept / reject).
                        let factor = if rejected { factor.min(1.0) } else { factor };
                        rejected = false;
                        h = if last { h.max(step) } else { step * factor };
                    }
                }
            }
            if bound >= t_end {
                run.out.energy.stored_end = self.stored(t, &y);
            }
            if bound < t_end {
                run.out.events.push(Event {
                    t: bound,
                    kind: EventKind::Kink,
                    x: y[0],
                });
                run.out.stats.restarts += 1;
            }
        }
        Ok((run.out, None))
    }

    /// The sign `v` takes from `y`: its own, or from rest that of the acceleration.
    fn start_sign(&self, t: f64, y: &[f64; N]) -> f64 {
        let v = if y[1] != 0.0 {
            y[1]
        } else {
            self.rate(t, y, 0.0)[1]
        };
        if v < 0.0 {
            -1.0
        } else {
            1.0
        }
    }
}

/// Two half steps: `(step, start)` of each.
type Halves = [(Step, [f64; N]); 2];

/// The point where `past` turns true in `[lo, hi]` (false at `lo`, true at `hi`), by
/// bisection to the resolution of `f64`: the smallest `theta` found with `past(theta)`.
fn bisect(past: impl Fn(f64) -> bool, mut lo: f64, mut hi: f64) -> f64 {
    for _ in 0..80 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if past(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}

struct Run<'a, G, F> {
    system: &'a System<G, F>,
    rtol: f64,
    atol: [f64; N],
    w0: f64,
    out: Motion,
    times: &'a [f64],
    next_time: usize,
    /// Whether the friction force has been seen rising (for the first peak).
    rising: bool,
}

impl<G: VelocityFn, F: VelocityFn> Run<'_, G, F> {
    /// A step of `h` checked against two of `h / 2` (kept); `Ok` with the halves and the
    /// factor for the next step, or `Err` with the factor to retry with.
    fn double_step(&mut self, t: f64, y: &[f64; N], h: f64, s: f64) -> Result<(Halves, f64), f64> {
        let f = |t: f64, y: &[f64; N]| self.system.rate(t, y, s);
        let jac = self.jacobian(t, y, s);
        let w = self.weights(y);
        let full = radau_step(&f, &jac, t, y, h, &w);
        // Both halves iterate with the Jacobian at the step's start: one factorization.
        let Some(half) = iteration_matrix(&jac, 0.5 * h) else {
            return Err(0.25);
        };
        let first = radau_step_with(&f, &half, t, y, 0.5 * h, &w, [[0.0; N]; 3]);
        let (Some(full), Some(first)) = (full, first) else {
            return Err(0.25);
        };
        let guess = next_guess(y, &first.stages);
        let Some(second) = radau_step_with(&f, &half, t + 0.5 * h, &first.y, 0.5 * h, &w, guess)
        else {
            return Err(0.25);
        };
        self.out.stats.rhs_evaluations += full.evaluations + first.evaluations + second.evaluations;
        // The two results differ by about (2^5 - 1) times the error of the halves.
        let w_end = self.weights(&second.y);
        let err = (0..N)
            .map(|r| ((second.y[r] - full.y[r]) / (31.0 * w[r].max(w_end[r]))).abs())
            .fold(0.0f64, f64::max);
        let factor = if err == 0.0 {
            MAX_GROWTH
        } else {
            (SAFETY * err.powf(-1.0 / 6.0)).clamp(0.2, MAX_GROWTH)
        };
        if err.is_nan() || err > 1.0 {
            return Err(factor.min(0.9));
        }
        Ok(([(first, *y), (second, first.y)], factor))
    }

    /// The state at `t1` by one step from `(t, y)` (two half steps when one does not converge).
    fn step_to(&mut self, t: f64, y: &[f64; N], t1: f64, s: f64) -> Option<[f64; N]> {
        self.step_to_with(t, y, t1, s).map(|(y, _)| y)
    }

    /// [`Self::step_to`], with its two half steps.
    fn step_to_with(
        &mut self,
        t: f64,
        y: &[f64; N],
        t1: f64,
        s: f64,
    ) -> Option<([f64; N], [Step; 2])> {
        let h = t1 - t;
        let f = |t: f64, y: &[f64; N]| self.system.rate(t, y, s);
        let jac = self.jacobian(t, y, s);
        let w = self.weights(y);
        let first = radau_step(&f, &jac, t, y, 0.5 * h, &w)?;
        let second = radau_step(&f, &jac, t + 0.5 * h, &first.y, 0.5 * h, &w)?;
        self.out.stats.rhs_evaluations += first.evaluations + second.evaluations;
        Some((second.y, [first, second]))
    }

    /// Adds the input and the dissipation over `[t, t_to]` from the collocation polynomials of
    /// a step of `h` from `t` (Gauss-Legendre with three nodes on each half step's part): the
    /// fallback where a step of its own to `t_to` does not converge.
    fn account_dense(&mut self, t: f64, h: f64, halves: &Halves, t_to: f64, s: f64) {
        const NODES3: [f64; 3] = [0.112_701_665_379_258_3, 0.5, 0.887_298_334_620_741_7];
        const WEIGHTS3: [f64; 3] = [5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0];
        for (k, (step, start)) in halves.iter().enumerate() {
            let from = t + 0.5 * h * k as f64;
            let to = (from + 0.5 * h).min(t_to);
            if to <= from {
                continue;
            }
            for (node, weight) in NODES3.iter().zip(WEIGHTS3) {
                let ti = from + node * (to - from);
                let yi = dense(start, &step.stages, (ti - from) / (0.5 * h));
                let [input, dissipated] = self.system.power(ti, &yi, s);
                self.out.energy.input += weight * (to - from) * input;
                self.out.energy.dissipated += weight * (to - from) * dissipated;
            }
        }
    }

    /// Adds the input and the dissipation over two half steps of `[t, t + h]`.
    fn account(&mut self, t: f64, h: f64, halves: &[Step; 2], s: f64) {
        if h <= 0.0 {
            return;
        }
        for (k, half) in halves.iter().enumerate() {
            let t0 = t + 0.5 * h * k as f64;
            let [input, dissipated] =
                quadrature(0.5 * h, t0, &half.stages, |t, y| self.system.power(t, y, s));
            self.out.energy.input += input;
            self.out.energy.dissipated += dissipated;
        }
    }

    /// The error weights `atol + rtol |y|`.
    fn weights(&self, y: &[f64; N]) -> [f64; N] {
        std::array::from_fn(|r| self.atol[r] + self.rtol * y[r].abs())
    }

    /// The Jacobian of the rate by central differences, each step on the component's scale.
    fn jacobian(&mut self, t: f64, y: &[f64; N], s: f64) -> [[f64; N]; N] {
        self.out.stats.jacobians += 1;
        let mut j = [[0.0; N]; N];
        for c in 0..N {
            let h = 1e-6 * (y[c].abs() + self.atol[c] / self.rtol);
            let (mut up, mut down) = (*y, *y);
            up[c] += h;
            down[c] -= h;
            let (fu, fd) = (self.system.rate(t, &up, s), self.system.rate(t, &down, s));
            for r in 0..N {
                j[r][c] = (fu[r] - fd[r]) / (2.0 * h);
            }
        }
        self.out.stats.rhs_evaluations += 2 * N;
        j
    }

    /// The first crossing of `v` against the sign `s` in the step (none when `s = 0`):
    /// bracketed at the collocation nodes of the half steps, then located by bisection on the
    /// collocation polynomial to the resolution of `t`.
    fn crossing(&self, t: f64, h: f64, halves: &Halves, s: f64) -> Option<(f64, [f64; N])> {
        if s == 0.0 {
            return None;
        }
        for (k, (step, start)) in halves.iter().enumerate() {
            let t0 = t + 0.5 * h * k as f64;
            let at = |theta: f64| dense(start, &step.stages, theta);
            let past = |theta: f64| s * at(theta)[1] < 0.0;
            let mut lo = 0.0;
            for &node in &NODES[1..] {
                if past(node) {
                    let hi = bisect(past, lo, node);
                    return Some((t0 + 0.5 * h * hi, at(hi)));
                }
                lo = node;
            }
        }
        None
    }

    /// The upward crossings of the watched velocity levels in the step, up to `t_kept`, as
    /// events (located by bisection on the collocation polynomial).
    fn watch(&mut self, t: f64, h: f64, halves: &Halves, t_kept: f64) {
        let mut found = Vec::new();
        for &level in &self.system.watch {
            for (k, (step, start)) in halves.iter().enumerate() {
                let t0 = t + 0.5 * h * k as f64;
                let at = |theta: f64| dense(start, &step.stages, theta);
                let past = |theta: f64| at(theta)[1] >= level;
                let mut lo = 0.0;
                for &node in &NODES[1..] {
                    if !past(lo) && past(node) {
                        let hi = bisect(past, lo, node);
                        let tc = t0 + 0.5 * h * hi;
                        if tc <= t_kept {
                            found.push((tc, at(hi)[0]));
                        }
                    }
                    lo = node;
                }
            }
        }
        found.sort_by(|a, b| a.0.total_cmp(&b.0));
        for (tc, x) in found {
            self.out.events.push(Event {
                t: tc,
                kind: EventKind::VelocityUp,
                x,
            });
        }
    }

    /// `dF/dt` at the state `y`: `dF/dz z' + dF/dv v'` with the rates of the system (not the
    /// derivative of an interpolant) and the partial derivatives by central differences (`F`
    /// is linear in `z`, smooth in `v` at a frozen sign: no derivative of `g` needed).
    fn friction_rate(&self, t: f64, y: &[f64; N], s: f64) -> f64 {
        let rate = self.system.rate(t, y, s);
        let (v, z) = (y[1], y[2]);
        let force = |v: f64, z: f64| self.system.friction(v, z, s).0;
        let dz = z.abs() + self.atol[2];
        let dv = 1e-6 * (v.abs() + self.atol[1] / self.rtol);
        let by_z = (force(v, z + dz) - force(v, z - dz)) / (2.0 * dz);
        let by_v = (force(v + dv, z) - force(v - dv, z)) / (2.0 * dv);
        by_z * rate[2] + by_v * rate[1]
    }

    /// The first local maximum of the friction force in the step, up to `t_kept`: where
    /// `dF/dt` ([`Self::friction_rate`] on the collocation polynomial) turns from > 0 to <= 0,
    /// bracketed at the nodes of the half steps and located by bisection.
    fn friction_peak(
        &mut self,
        t: f64,
        h: f64,
        halves: &Halves,
        s: f64,
        t_kept: f64,
    ) -> Option<f64> {
        let mut rising = self.rising;
        let found = self.first_peak(t, h, halves, s, &mut rising);
        self.rising = rising;
        found.filter(|&tp| tp <= t_kept)
    }

    fn first_peak(
        &self,
        t: f64,
        h: f64,
        halves: &Halves,
        s: f64,
        rising: &mut bool,
    ) -> Option<f64> {
        for (k, (step, start)) in halves.iter().enumerate() {
            let t0 = t + 0.5 * h * k as f64;
            let slope = |theta: f64| {
                let y = dense(start, &step.stages, theta);
                self.friction_rate(t0 + 0.5 * h * theta, &y, s)
            };
            let past = |theta: f64| slope(theta) <= 0.0;
            let mut lo = 0.0;
            for &node in &NODES {
                let falling = past(node);
                if falling && *rising {
                    let theta = if node == 0.0 {
                        0.0
                    } else {
                        bisect(past, lo, node)
                    };
                    return Some(t0 + 0.5 * h * theta);
                }
                *rising |= !falling;
                lo = node;
            }
        }
        None
    }

    /// The run stopped at the friction peak `tp` inside the step `(t, y, h, halves)`: the state
    /// there by a step of its own (as accurate as the steps), the outputs up to it.
    fn peak_at(
        mut self,
        t: f64,
        y: &[f64; N],
        h: f64,
        halves: &Halves,
        tp: f64,
        s: f64,
    ) -> Result<(Motion, Option<Breakaway>), DynamicsError> {
        let k = usize::from(tp >= t + 0.5 * h);
        let (st, start) = &halves[k];
        let from = t + 0.5 * h * k as f64;
        let exact = |run: &mut Self, tq: f64| -> [f64; N] {
            if tq > from {
                run.step_to(from, start, tq, s)
                    .unwrap_or_else(|| dense(start, &st.stages, (tq - from) / (0.5 * h)))
            } else {
                *start
            }
        };
        // The collocation polynomial locates the peak to its own (lower) order; secant steps
        // on dF/dt at states that are steps of their own bring it to the steps' accuracy.
        let mut tp = tp;
        let mut yp = exact(&mut self, tp);
        let d = 1e-4 * h;
        for _ in 0..3 {
            let g1 = self.friction_rate(tp, &yp, s);
            let y2 = exact(&mut self, tp + d);
            let g2 = self.friction_rate(tp + d, &y2, s);
            let next = tp - g1 * d / (g2 - g1);
            if !(next.is_finite() && next > from && next < t + h) {
                break;
            }
            let moved = (next - tp).abs();
            tp = next;
            yp = exact(&mut self, tp);
            if moved <= 1e-13 * tp.abs() {
                break;
            }
        }
        self.report_until(tp, &yp, s, Some((t, y, h, halves)));
        check_finite(tp, &yp)?;
        let peak = Breakaway {
            t: tp,
            force: self.system.friction(yp[1], yp[2], s).0,
            x: yp[0],
        };
        Ok((self.out, Some(peak)))
    }

    /// At a located sign change: `v = 0` there, an event, and the sign to go on with: that of
    /// the acceleration (at `v = 0` the rate does not depend on the sign), or none once the
    /// mass rings down below the velocity tolerance (its amplitude `|v'| / w0`).
    fn reversal(&mut self, t: f64, mut y: [f64; N]) -> ([f64; N], f64) {
        y[1] = 0.0;
        self.out.events.push(Event {
            t,
            kind: EventKind::VelocityZero,
            x: y[0],
        });
        self.out.stats.restarts += 1;
        let a = self.system.rate(t, &y, 0.0)[1];
        let s = if a.abs() / self.w0 < RINGING * self.atol[1] {
            0.0
        } else if a < 0.0 {
            -1.0
        } else {
            1.0
        };
        (y, s)
    }

    /// Reports the requested times up to `t_to` (inclusive), from the step's dense output, or
    /// at `t_to` itself from `y_to` when no step is given.
    fn report_until(
        &mut self,
        t_to: f64,
        y_to: &[f64; N],
        s: f64,
        step: Option<(f64, &[f64; N], f64, &Halves)>,
    ) {
        while self.next_time < self.times.len() && self.times[self.next_time] <= t_to {
            let ti = self.times[self.next_time];
            let yi = match step {
                Some((t0, _, h, halves)) if ti < t_to => {
                    // A step of its own from the half step's start (as accurate as the
                    // steps); the collocation polynomial if that step does not converge.
                    let k = usize::from(ti >= t0 + 0.5 * h);
                    let (st, start) = &halves[k];
                    let from = t0 + 0.5 * h * k as f64;
                    let theta = (ti - from) / (0.5 * h);
                    self.step_to(from, start, ti, s)
                        .unwrap_or_else(|| dense(start, &st.stages, theta.clamp(0.0, 1.0)))
                }
                _ => *y_to,
            };
            self.system.record(&mut self.out, ti, &yi, s);
            self.next_time += 1;
        }
    }
}

impl<G: VelocityFn, F: VelocityFn> System<G, F> {
    fn record(&self, out: &mut Motion, t: f64, y: &[f64; N], s: f64) {
        let [x, v, z, q] = *y;
        out.t.push(t);
        out.x.push(x);
        out.v.push(v);
        out.z.push(z);
        out.friction.push(self.friction(v, z, s).0);
        out.drive.push(self.drive_force(t, x, v, q));
    }
}

fn check_times(t0: f64, t_end: f64, times: &[f64]) -> Result<(), DynamicsError> {
    if !(t_end.is_finite() && t_end > t0) {
        return Err(DynamicsError::NotPositive {
            name: if t0 == 0.0 { "t_end" } else { "t_end - t0" },
            value: t_end - t0,
        });
    }
    for (index, &value) in times.iter().enumerate() {
        if !(value.is_finite() && (t0..=t_end).contains(&value)) {
            return Err(DynamicsError::TimeOutOfRange {
                index,
                value,
                t0,
                t_end,
            });
        }
        if index > 0 && value <= times[index - 1] {
            return Err(DynamicsError::TimesNotIncreasing {
                index,
                prev: times[index - 1],
                value,
            });
        }
    }
    Ok(())
}

fn check_finite(t: f64, y: &[f64; N]) -> Result<(), DynamicsError> {
    if y.iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(DynamicsError::Overflow { t })
    }
}

/// The break-away under a rising force: where the friction force first peaks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Breakaway {
    pub t: f64,
    /// The friction force there (its first local maximum).
    pub force: f64,
    pub x: f64,
}

impl<G: VelocityFn, F: VelocityFn> System<G, F> {
    /// The first local maximum of the friction force in `(0, t_end)` (the break-away of a
    /// force ramp, Fig. 4 of Canudas de Wit et al.), or `None` if it only rises: located as an
    /// event during one run, which stops there (see [`Self::solve`] for the events).
    pub fn breakaway(
        &self,
        t_end: f64,
        tol: Tolerances,
    ) -> Result<Option<Breakaway>, DynamicsError> {
        let start = State {
            v: self.initial_velocity(),
            ..State::default()
        };
        Ok(self.integrate(start, t_end, &[], tol, true)?.1)
    }
}
