//! The solver: the dedicated Radau IIA integrator (`integrator.rs`) with radau5's error and
//! step-size control (Hairer & Wanner, Solving ODEs II, IV.8), landing
//! exactly on every kink of the drive and restarted at every located sign change of the
//! velocity (module docs of [`super`]).
//!
//! Absolute tolerances follow the system's own scales: `atol` on displacements (`x`, `z`, and
//! the integral `q` per second), `atol w0` on the velocity, with the natural frequency
//! `w0 = sqrt(sigma0 / M)` of the mass on its bristles.

use super::integrator::{
    dense, error_estimate, guess, quadrature, solve_stages, Factors, Newton, Step, N, NIT, NODES,
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

    /// The absolute tolerance on displacements given, if any.
    pub fn atol(&self) -> Option<f64> {
        self.atol
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
    /// The driving force `F_d` (just after a jump of the set point); with a prescribed
    /// velocity, the force that makes the mass follow it, `M v' + F`.
    pub drive: Vec<f64>,
    pub events: Vec<Event>,
    pub stats: Stats,
    /// The energy balance over the run.
    pub energy: EnergyBalance,
}

impl Motion {
    /// The names of the sampled columns, in the order of the CSV files, the JSON and the
    /// Python result: `t, x, v, z, friction, drive`.
    pub const COLUMNS: [&'static str; 6] = ["t", "x", "v", "z", "friction", Self::DRIVE];

    /// The column of the force applied to the mass (a file with it drives a next run).
    pub const DRIVE: &'static str = "drive";

    /// The sampled columns, in the order of [`Self::COLUMNS`].
    pub fn columns(&self) -> [&[f64]; 6] {
        [
            &self.t,
            &self.x,
            &self.v,
            &self.z,
            &self.friction,
            &self.drive,
        ]
    }
}

/// The energy balance over a run: what the drive put in equals the change of what is stored
/// (kinetic, spring and bristle energy) plus what was dissipated (friction, damper), to the
/// solver's accuracy (each term is integrated by the steps' own quadrature).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct EnergyBalance {
    /// The work of the applied force, the controller and the spring's moving end (a prescribed
    /// velocity: the work of the force `M v' + F` that makes the mass follow it).
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

/// The step-size rule (radau5's defaults): safety factor, the bounds of `h_new / h`, and the
/// band of `h_new / h` in which the step size and its factorization are kept.
const SAFETY: f64 = 0.9;
const MIN_FACTOR: f64 = 0.2;
const MAX_FACTOR: f64 = 8.0;
const KEEP: std::ops::RangeInclusive<f64> = 1.0..=1.2;
/// Newton contraction below which the Jacobian is kept for the next step.
const REUSE_JACOBIAN: f64 = 1e-3;
/// The sign of `v` stops being frozen once the ringing amplitude `|v'| / w0` at a sign change
/// is below this fraction of the velocity tolerance (so that stepping over the remaining kinks
/// costs less than the tolerance; above it the kinks of a ringing mass cost accuracy).
const RINGING: f64 = 1e-3;
/// A sign change located within this fraction of a step from its start is taken for the
/// polynomial not resolving the step's start (see `integrate`), and the step is retried shorter.
const MIN_PROGRESS: f64 = 1e-6;
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
    ///
    /// The drive's kinks split `[start.t, t_end]` into segments, each integrated with a fresh
    /// start ("Non-smooth points" in `docs/mathematics.md`): the frozen sign of `v` from the
    /// segment's start, then Radau IIA steps ([`Run::step`]) to the segment's end.
    fn integrate(
        &self,
        start: State,
        t_end: f64,
        times: &[f64],
        tol: Tolerances,
        to_peak: bool,
    ) -> Result<(Motion, Option<Breakaway>), DynamicsError> {
        check_times(start.t, t_end, times)?;
        let mut run = Run::new(self, tol, times);
        let kinks: Vec<f64> = self
            .kinks(t_end)
            .into_iter()
            .filter(|&k| k > start.t)
            .collect();
        let mut p = Position {
            t: start.t,
            y: [start.x, start.v, start.z, start.q],
            s: 0.0,
            h: (0.01 / run.w0).min(t_end - start.t),
        };
        run.report_until(p.t, &p.y, 0.0, None);
        run.out.energy.stored_start = self.stored(p.t, &p.y);
        for bound in kinks.iter().copied().chain(std::iter::once(t_end)) {
            p.s = self.start_sign(p.t, &p.y);
            run.restart(p.t, &p.y, p.s);
            while p.t < bound {
                if let Some((piece, tp)) = run.step(&mut p, bound, to_peak)? {
                    return run.peak_at(&piece, tp, p.s);
                }
            }
            run.segment_end(&p, bound, t_end);
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

/// An accepted step: from `(t, y0)` over `h`, with the Jacobian it was solved with.
#[derive(Debug, Clone, Copy)]
struct Piece {
    t: f64,
    h: f64,
    y0: [f64; N],
    step: Step<N>,
    jac: [[f64; N]; N],
}

impl Piece {
    /// The collocation polynomial at `theta` of the step.
    fn at(&self, theta: f64) -> [f64; N] {
        dense(&self.y0, &self.step.stages, theta)
    }

    fn time(&self, theta: f64) -> f64 {
        self.t + self.h * theta
    }
}

/// The integrator's state between steps (radau5's): the Jacobian and its factorization while
/// they are reused, Newton's convergence factor, the rate at the step's start, the last
/// accepted step (Newton's starting point) and the predictive controller's memory.
struct Control {
    jac: Option<[[f64; N]; N]>,
    /// Whether `jac` was computed for the current step (not reused).
    fresh: bool,
    factors: Option<Factors<N>>,
    newton: Newton,
    f0: [f64; N],
    first: bool,
    reject: bool,
    previous: Option<Piece>,
    /// Gustafsson's controller: the last accepted step's size and error.
    accepted: Option<(f64, f64)>,
}

impl Control {
    fn new(rtol: f64) -> Self {
        Self {
            jac: None,
            fresh: false,
            factors: None,
            newton: Newton {
                faccon: 1.0,
                tol: (10.0 * f64::EPSILON / rtol).max(0.03f64.min(rtol.sqrt())),
                lenient: false,
            },
            f0: [0.0; N],
            first: true,
            reject: false,
            previous: None,
            accepted: None,
        }
    }
}

/// The point where `past` turns true in `[lo, hi]` (false at `lo`, true at `hi`), by
/// bisection to the resolution of `f64`: the smallest `theta` found with `past(theta)`.
pub(super) fn bisect(past: impl Fn(f64) -> bool, mut lo: f64, mut hi: f64) -> f64 {
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
    /// The tolerances the error estimate is held to (see `integrate`).
    rtol: f64,
    atol: [f64; N],
    w0: f64,
    out: Motion,
    times: &'a [f64],
    next_time: usize,
    /// Whether the friction force has been seen rising (for the first peak).
    rising: bool,
    control: Control,
}

/// Where the integration stands: the time, the state `(x, v, z, q)`, the frozen sign `s` of
/// `v` (0: not frozen) and the size of the next step.
struct Position {
    t: f64,
    y: [f64; N],
    s: f64,
    h: f64,
}

impl<'a, G: VelocityFn, F: VelocityFn> Run<'a, G, F> {
    /// A run of `system` reporting at `times`, with the error weights `atol + rtol |y|` of
    /// `tol` on the system's scales (module docs): `atol` on `x`, `z`, `q`, `atol w0` on `v`.
    fn new(system: &'a System<G, F>, tol: Tolerances, times: &'a [f64]) -> Self {
        let m = system.model();
        let w0 = (m.sigma0() / system.mass()).sqrt();
        let length = m.g0() / m.sigma0();
        let atol = tol.atol.unwrap_or(tol.rtol * length);
        // The embedded error estimate is held to the tolerances as given. radau5 holds it to
        // 0.1 rtol^(2/3), aiming at a global error of about rtol at moderate tolerances; against
        // the references that let the error reach 1000x rtol at rtol 1e-11 (BENCHMARKS.md). As
        // given, the estimate (of order 4 for a method of order 5) is conservative and the
        // global error stays within 3x rtol on every experiment.
        let rtol = tol.rtol;
        Self {
            system,
            rtol,
            atol: [atol, atol * w0, atol, atol],
            w0,
            out: Motion::default(),
            times,
            next_time: 0,
            rising: false,
            control: Control::new(rtol),
        }
    }
}

impl<G: VelocityFn, F: VelocityFn> Run<'_, G, F> {
    /// One step from `p` towards `bound` (landing on it exactly): attempted under the error
    /// control ([`Self::attempt`]: the embedded estimate, eq. (8.19)-(8.20) of Hairer & Wanner
    /// IV.8, and the step-size rule of "The integrator" in `docs/mathematics.md`), cut at a sign
    /// change of `v` ([`Self::locate`]), its events and outputs recorded ([`Self::output`]), and
    /// `p` moved to its end (a reversal there restarts the integrator); a rejected step only
    /// changes `p.h`. With `to_peak`, `Some` with the accepted step and the friction peak in
    /// it, where the run stops: the step is boxed, as a result the size of a step, copied out
    /// of every step, cost 0.8 % of the experiments' instructions.
    fn step(
        &mut self,
        p: &mut Position,
        bound: f64,
        to_peak: bool,
    ) -> Result<Option<(Box<Piece>, f64)>, DynamicsError> {
        if self.out.stats.steps + self.out.stats.rejected > MAX_STEPS {
            return Err(DynamicsError::Solver {
                t: p.t,
                reason: format!("more than {MAX_STEPS} steps"),
            });
        }
        let last = p.t + p.h >= bound;
        let step = if last { bound - p.t } else { p.h };
        let (first, h_new) = match self.attempt(p.t, &p.y, step, p.s) {
            Ok(accepted) => accepted,
            Err(h_new) => return self.rejected(p, h_new).map(|()| None),
        };
        let Some((piece, crossing)) = self.locate(p, first, step) else {
            return Ok(None);
        };
        self.out.stats.steps += 1;
        let end = match crossing {
            Some(tc) => tc,
            None if last => bound,
            None => p.t + step,
        };
        self.watch(&piece, end);
        if to_peak {
            if let Some(tp) = self.friction_peak(&piece, p.s, end) {
                return Ok(Some((Box::new(piece), tp)));
            }
        }
        self.output(&piece, end, p.s)?;
        let y_end = piece.step.y;
        if crossing.is_some() {
            // At the crossing: v = 0, an event, and the sign to go on with.
            let (yc, s_next) = self.reversal(end, y_end);
            (p.t, p.y, p.s) = (end, yc, s_next);
            self.restart(p.t, &p.y, p.s);
            p.h = h_new;
        } else {
            (p.t, p.y) = (end, y_end);
            self.accepted(piece, p.s);
            // A step cut short to land on the bound leaves the size as it was.
            p.h = if last { p.h.max(h_new) } else { h_new };
        }
        Ok(None)
    }

    /// A step rejected by the error control or Newton: the run goes on with `h_new`, unless
    /// that fell below the resolution of `t`.
    fn rejected(&mut self, p: &mut Position, h_new: f64) -> Result<(), DynamicsError> {
        self.out.stats.rejected += 1;
        p.h = h_new;
        if h_new.is_nan() || h_new <= f64::EPSILON * p.t.abs().max(1.0) {
            return Err(DynamicsError::Solver {
                t: p.t,
                reason: "the step fell below the resolution of t".into(),
            });
        }
        Ok(())
    }

    /// Event location ("Non-smooth points" in `docs/mathematics.md`): the step `first` of size
    /// `step` from `p`, as it is or, where `v` crosses 0 against the frozen sign inside it, redone
    /// to the crossing (returned with it). `None`: the step is rejected and `p.h` is the size
    /// to retry with.
    #[inline]
    fn locate(
        &mut self,
        p: &mut Position,
        first: Piece,
        step: f64,
    ) -> Option<(Piece, Option<f64>)> {
        let Some(tc) = self.crossing(&first, p.s) else {
            return Some((first, None));
        };
        if tc - p.t <= MIN_PROGRESS * step {
            // v leaves a sign change (or a kink) in the direction of its acceleration: a sign
            // change at the very start of a step is the collocation polynomial not resolving
            // the start of a step this long (far longer than the mass's period): shorter.
            self.out.stats.rejected += 1;
            p.h = self.retry(0.1 * step);
            return None;
        }
        // Past the crossing the frozen sign is not the motion, and the step's error estimate
        // covered that part too: the step is redone to the crossing under its own error
        // control (rejected, the run goes on with shorter steps and finds the crossing again).
        match self.attempt(p.t, &p.y, tc - p.t, p.s) {
            Ok((to_crossing, _)) => Some((to_crossing, Some(tc))),
            Err(h_retry) => {
                self.out.stats.rejected += 1;
                p.h = h_retry;
                None
            }
        }
    }

    /// The outputs of the accepted `piece` up to `end`: the energy over it (its own
    /// quadrature, "Energy balance" in `docs/mathematics.md`), the requested times in it (steps
    /// of their own), and its end state checked finite.
    fn output(&mut self, piece: &Piece, end: f64, s: f64) -> Result<(), DynamicsError> {
        self.account(piece, s);
        let y_end = piece.step.y;
        self.report_until(end, &y_end, s, Some(piece));
        check_finite(end, &y_end)
    }

    /// At the end `bound` of a segment: the run's end (the stored energy, the times within
    /// rounding past it), or a kink (an event and a restart).
    fn segment_end(&mut self, p: &Position, bound: f64, t_end: f64) {
        if bound >= t_end {
            self.out.energy.stored_end = self.system.stored(p.t, &p.y);
            // Times within rounding past the end (`check_output_times`): the end's state.
            self.report_until(f64::INFINITY, &p.y, p.s, None);
        }
        if bound < t_end {
            self.out.events.push(Event {
                t: bound,
                kind: EventKind::Kink,
                x: p.y[0],
            });
            self.out.stats.restarts += 1;
        }
    }
    /// A fresh start at `(t, y)` with the sign `s` (the run's start, a kink, a reversal):
    /// nothing of the previous steps carries over but the step size.
    fn restart(&mut self, t: f64, y: &[f64; N], s: f64) {
        let c = &mut self.control;
        c.jac = None;
        c.factors = None;
        c.first = true;
        c.reject = false;
        c.previous = None;
        c.accepted = None;
        // |v| not split (s = 0): the right-hand side has a kink at v = 0, where Newton's
        // contraction is erratic; it iterates on while the increments do not grow.
        c.newton.lenient = s == 0.0;
        c.f0 = self.system.rate(t, y, s);
        self.out.stats.rhs_evaluations += 1;
    }

    /// After an accepted step (not cut short): the rate at its end, and the step kept as
    /// Newton's starting point.
    fn accepted(&mut self, piece: Piece, s: f64) {
        self.control.f0 = self.system.rate(piece.t + piece.h, &piece.step.y, s);
        self.out.stats.rhs_evaluations += 1;
        self.control.previous = Some(piece);
    }

    /// One Radau IIA step of `h` from `(t, y)` with its embedded error estimate: `Ok` with the
    /// step and the size of the next, or `Err` with the size to retry with (radau5's rules:
    /// the Jacobian kept while Newton contracts fast, the factorization while the size stays,
    /// Gustafsson's predictive controller).
    fn attempt(&mut self, t: f64, y: &[f64; N], h: f64, s: f64) -> Result<(Piece, f64), f64> {
        let jac = match self.control.jac {
            Some(jac) => jac,
            None => {
                let jac = self.jacobian(t, y, s);
                self.control.jac = Some(jac);
                self.control.fresh = true;
                jac
            }
        };
        if self.control.factors.as_ref().is_none_or(|f| f.h() != h) {
            self.control.factors = Factors::new(&jac, h);
        }
        let Some(factors) = self.control.factors.as_ref() else {
            return Err(self.retry(0.5 * h));
        };
        let f = |t: f64, y: &[f64; N]| self.system.rate(t, y, s);
        let scal = self.weights(y);
        let guess = match &self.control.previous {
            Some(p) if !self.control.first => guess(&p.y0, &p.step.stages, 1.0, h / p.h),
            _ => [[0.0; N]; 3],
        };
        let step = solve_stages(&f, factors, t, y, &scal, guess, &mut self.control.newton);
        let step = match step {
            Ok(step) => step,
            Err(q) => {
                self.out.stats.rhs_evaluations += 3 * NIT;
                return Err(self.retry(h * q));
            }
        };
        let refine = self.control.first || self.control.reject;
        let f_start = |y: &[f64; N]| f(t, y);
        let (err, extra) =
            error_estimate(f_start, factors, y, &self.control.f0, &step, &scal, refine);
        self.out.stats.rhs_evaluations += step.evaluations + extra;
        let fac = SAFETY.min(SAFETY * (1 + 2 * NIT) as f64 / (step.iterations + 2 * NIT) as f64);
        let quot = |q: f64| q.clamp(1.0 / MAX_FACTOR, 1.0 / MIN_FACTOR);
        let mut q = quot(err.sqrt().sqrt() / fac);
        if err.is_nan() || err >= 1.0 {
            let h_new = if self.control.first { 0.1 * h } else { h / q };
            return Err(self.retry(h_new));
        }
        if let Some((h_acc, err_acc)) = self.control.accepted {
            q = q.max(quot(
                (h_acc / h) * (err * err / err_acc).sqrt().sqrt() / SAFETY,
            ));
        }
        self.control.accepted = Some((h, err.max(1e-2)));
        let mut h_new = h / q;
        if self.control.reject {
            h_new = h_new.min(h);
        }
        self.control.first = false;
        self.control.reject = false;
        self.control.fresh = false;
        if step.theta > REUSE_JACOBIAN {
            self.control.jac = None;
        } else if KEEP.contains(&(h_new / h)) {
            h_new = h;
        }
        let piece = Piece {
            t,
            h,
            y0: *y,
            step,
            jac,
        };
        Ok((piece, h_new))
    }

    /// A rejected step: retry with `h_new`, with a fresh Jacobian unless this one was.
    fn retry(&mut self, h_new: f64) -> f64 {
        self.control.reject = true;
        if !self.control.fresh {
            self.control.jac = None;
        }
        h_new
    }

    /// The state at `tq` inside `piece`: by a step of its own from the piece's start (as
    /// accurate as the step; the collocation polynomial is of lower order between its nodes),
    /// or the polynomial where Newton does not converge for that step.
    fn state_at(&mut self, piece: &Piece, tq: f64, s: f64) -> [f64; N] {
        self.step_to(piece, tq, s)
            .unwrap_or_else(|| piece.at(((tq - piece.t) / piece.h).clamp(0.0, 1.0)))
    }

    /// [`Self::state_at`]'s step of its own, Newton starting from the piece's collocation
    /// polynomial; `None` at the piece's start or if Newton does not converge.
    fn step_to(&mut self, piece: &Piece, tq: f64, s: f64) -> Option<[f64; N]> {
        let h = tq - piece.t;
        if h <= 0.0 {
            return None;
        }
        let factors = Factors::new(&piece.jac, h)?;
        let f = |t: f64, y: &[f64; N]| self.system.rate(t, y, s);
        let scal = self.weights(&piece.y0);
        let start = guess(&piece.y0, &piece.step.stages, 0.0, h / piece.h);
        let mut newton = self.control.newton;
        let step =
            solve_stages(&f, &factors, piece.t, &piece.y0, &scal, start, &mut newton).ok()?;
        self.out.stats.rhs_evaluations += step.evaluations;
        Some(step.y)
    }

    /// Adds the input and the dissipation over an accepted step (its own quadrature).
    fn account(&mut self, piece: &Piece, s: f64) {
        let [input, dissipated] = quadrature(piece.h, piece.t, &piece.step.stages, |t, y| {
            self.system.power(t, y, s)
        });
        self.out.energy.input += input;
        self.out.energy.dissipated += dissipated;
    }

    /// The error weights `atol + rtol |y|`.
    fn weights(&self, y: &[f64; N]) -> [f64; N] {
        std::array::from_fn(|r| self.atol[r] + self.rtol * y[r].abs())
    }

    /// The Jacobian of the rate at `(t, y)` (whose rate is `control.f0`). The rate is affine in
    /// `x`, `z` and `q` (the drive is linear in `x` and `q`, the bristle equation and the
    /// friction force linear in `z` at a frozen sign), so those columns are forward
    /// differences over a whole scale of the component, exact up to rounding; the `v` column
    /// (through `g(v)` and `f(v)`) is a central difference.
    ///
    /// With the sign not frozen (`s = 0`, a mass at rest within the tolerance) it is the
    /// Jacobian on the side of `v`'s own sign: a creeping mass stays on its side, and the
    /// average of the two sides (what a difference across `v = 0` gives) slows Newton to a
    /// crawl there.
    fn jacobian(&mut self, t: f64, y: &[f64; N], s: f64) -> [[f64; N]; N] {
        self.out.stats.jacobians += 1;
        let s = if s == 0.0 && y[1] != 0.0 {
            y[1].signum()
        } else {
            s
        };
        let f0 = self.control.f0;
        let mut j = [[0.0; N]; N];
        for c in 0..N {
            let scale = y[c].abs() + self.atol[c] / self.rtol;
            let mut up = *y;
            if c == 1 {
                let d = 1e-6 * scale;
                let mut down = *y;
                up[c] += d;
                down[c] -= d;
                let (fu, fd) = (self.system.rate(t, &up, s), self.system.rate(t, &down, s));
                for r in 0..N {
                    j[r][c] = (fu[r] - fd[r]) / (2.0 * d);
                }
                self.out.stats.rhs_evaluations += 2;
            } else {
                // A law not affine in z (the elasto-plastic blend): a forward difference small
                // against the scale of z.
                up[c] += if c == 2 && !self.system.law.affine_in_z() {
                    1e-7 * scale
                } else {
                    scale
                };
                let d = up[c] - y[c];
                let fu = self.system.rate(t, &up, s);
                for r in 0..N {
                    j[r][c] = (fu[r] - f0[r]) / d;
                }
                self.out.stats.rhs_evaluations += 1;
            }
        }
        j
    }

    /// The first crossing of `v` against the sign `s` in the step (none when `s = 0`):
    /// bracketed at the collocation nodes, then located by bisection on the collocation
    /// polynomial to the resolution of `t`.
    fn crossing(&self, piece: &Piece, s: f64) -> Option<f64> {
        if s == 0.0 {
            return None;
        }
        let past = |theta: f64| s * piece.at(theta)[1] < 0.0;
        let mut lo = 0.0;
        for &node in &NODES[1..] {
            if past(node) {
                return Some(piece.time(bisect(past, lo, node)));
            }
            lo = node;
        }
        None
    }

    /// The upward crossings of the watched velocity levels in the step, up to `t_kept`, as
    /// events (located by bisection on the collocation polynomial).
    fn watch(&mut self, piece: &Piece, t_kept: f64) {
        let mut found = Vec::new();
        for &level in &self.system.watch {
            let past = |theta: f64| piece.at(theta)[1] >= level;
            let mut lo = 0.0;
            for &node in &NODES[1..] {
                if !past(lo) && past(node) {
                    let hi = bisect(past, lo, node);
                    let tc = piece.time(hi);
                    if tc <= t_kept {
                        found.push((tc, piece.at(hi)[0]));
                    }
                }
                lo = node;
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
        let dz = if self.system.law.affine_in_z() {
            z.abs() + self.atol[2]
        } else {
            1e-6 * (z.abs() + self.atol[2] / self.rtol)
        };
        let dv = 1e-6 * (v.abs() + self.atol[1] / self.rtol);
        let by_z = (force(v, z + dz) - force(v, z - dz)) / (2.0 * dz);
        let by_v = (force(v + dv, z) - force(v - dv, z)) / (2.0 * dv);
        by_z * rate[2] + by_v * rate[1]
    }

    /// The first local maximum of the friction force in the step, up to `t_kept`: where
    /// `dF/dt` ([`Self::friction_rate`] on the collocation polynomial) turns from > 0 to <= 0,
    /// bracketed at the nodes and located by bisection.
    fn friction_peak(&mut self, piece: &Piece, s: f64, t_kept: f64) -> Option<f64> {
        let slope = |theta: f64| self.friction_rate(piece.time(theta), &piece.at(theta), s);
        let past = |theta: f64| slope(theta) <= 0.0;
        let mut rising = self.rising;
        let mut lo = 0.0;
        let mut found = None;
        for &node in &NODES {
            let falling = past(node);
            if falling && rising {
                let theta = if node == 0.0 {
                    0.0
                } else {
                    bisect(past, lo, node)
                };
                found = Some(piece.time(theta)).filter(|&tp| tp <= t_kept);
                break;
            }
            rising |= !falling;
            lo = node;
        }
        self.rising = rising;
        found
    }

    /// The run stopped at the friction peak `tp` inside `piece`: the state there by a step of
    /// its own (as accurate as the steps), the outputs up to it.
    fn peak_at(
        mut self,
        piece: &Piece,
        tp: f64,
        s: f64,
    ) -> Result<(Motion, Option<Breakaway>), DynamicsError> {
        // The collocation polynomial locates the peak to its own (lower) order; secant steps
        // on dF/dt at states that are steps of their own bring it to the steps' accuracy.
        let mut tp = tp;
        let mut yp = self.state_at(piece, tp, s);
        let d = 1e-4 * piece.h;
        for _ in 0..3 {
            let g1 = self.friction_rate(tp, &yp, s);
            let y2 = self.state_at(piece, tp + d, s);
            let g2 = self.friction_rate(tp + d, &y2, s);
            let next = tp - g1 * d / (g2 - g1);
            if !(next.is_finite() && next > piece.t && next < piece.time(1.0)) {
                break;
            }
            let moved = (next - tp).abs();
            tp = next;
            yp = self.state_at(piece, tp, s);
            if moved <= 1e-13 * tp.abs() {
                break;
            }
        }
        self.report_until(tp, &yp, s, Some(piece));
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

    /// Reports the requested times up to `t_to` (inclusive): inside `piece` by a step of its
    /// own from the piece's start (the collocation polynomial if that step does not
    /// converge), at `t_to` itself from `y_to`.
    fn report_until(&mut self, t_to: f64, y_to: &[f64; N], s: f64, piece: Option<&Piece>) {
        while self.next_time < self.times.len() && self.times[self.next_time] <= t_to {
            let ti = self.times[self.next_time];
            let yi = match piece {
                Some(p) if ti < t_to => self.state_at(p, ti, s),
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
        let friction = self.friction(v, z, s).0;
        out.friction.push(friction);
        out.drive.push(self.applied(t, x, v, q, friction));
    }
}

fn check_times(t0: f64, t_end: f64, times: &[f64]) -> Result<(), DynamicsError> {
    if !(t_end.is_finite() && t_end > t0) {
        return Err(DynamicsError::NotPositive {
            name: if t0 == 0.0 { "t_end" } else { "t_end - t0" },
            value: t_end - t0,
        });
    }
    Ok(crate::input::check_output_times(times, t0, t_end)?)
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
