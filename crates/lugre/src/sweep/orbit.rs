//! The periodic orbit under a sine (module docs, eq. P1-P5): one adaptive pass from `z = 0`
//! records every step's affine stage map, the fixed point follows from (P3) or (P4), and a
//! replay from it gives the quadratures.

use crate::kernel::radau::{A, C};
use crate::model::{LuGre, VelocityFn};
use crate::simulate::adaptive::{radau_step, solve3, stage_system, Integrator, Stages};
use crate::simulate::{SimulateError, Sine, Tolerance};

/// The Radau IIA weights (the last row of `A`: the method is stiffly accurate).
const B: [f64; 3] = A[2];

/// Golden-section iterations locating the peak force: the bracket (three steps) shrinks by
/// `0.618^60 ~ 3e-13`, and the peak, a smooth maximum, errs by the square of that.
const PEAK_ITERATIONS: usize = 60;

/// One step of the period map: its start and length, the coefficients at its stages
/// (`r`, `v = u'`), and the stage values from a start `z`: `Z = z G + K` (the stage system of
/// `stage_system` is linear in `z`).
#[derive(Debug, Clone, Copy)]
struct Step {
    t: f64,
    h: f64,
    r: [f64; 3],
    v: [f64; 3],
    g: [f64; 3],
    k: [f64; 3],
    /// `1 - G_3`, the step's decay, solved for directly (no cancellation; full periods only).
    d: f64,
}

/// The quadratures of one replay (eq. P5), over the stretch integrated.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Sums {
    pub dissipation: f64,
    pub sin: f64,
    /// The orbit's state at the stretch's start and end.
    pub z_start: f64,
    pub z_end: f64,
    /// The largest `|F|` found and where.
    pub peak: f64,
    pub peak_t: f64,
}

/// The steady-state loop sampled at evenly spaced times over one period, both ends
/// included (`t = j T / (n - 1)`).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LoopSamples {
    pub t: Vec<f64>,
    pub u: Vec<f64>,
    pub force: Vec<f64>,
}

/// `(r, u')` at `t` (eq. P1).
#[inline]
fn coefficients<G: VelocityFn, F: VelocityFn>(
    model: &LuGre<G, F>,
    sine: &Sine,
    t: f64,
) -> (f64, f64) {
    let v = sine.du(t);
    (model.sigma0() * v.abs() / model.g(v), v)
}

/// The orbit under one sine.
pub(super) struct SineOrbit<'m, G, F> {
    model: &'m LuGre<G, F>,
    sine: Sine,
    /// The stretch integrated: from the top reversal `T/4`, half a period (symmetric model)
    /// or a whole one.
    t0: f64,
    span: f64,
    symmetric: bool,
    steps: Vec<Step>,
    /// The orbit's state at each step's start.
    starts: Vec<f64>,
    pub sums: Sums,
}

impl<'m, G: VelocityFn, F: VelocityFn> SineOrbit<'m, G, F> {
    /// The orbit for `u = offset + amplitude sin(2 pi frequency t)` to tolerance `tol`.
    pub fn new(
        model: &'m LuGre<G, F>,
        amplitude: f64,
        frequency: f64,
        offset: f64,
        tol: Tolerance,
    ) -> Result<Self, SimulateError> {
        let sine = Sine::new(amplitude, 1.0 / frequency, 0.0, offset)?;
        let period = sine.period();
        let symmetric = model.is_symmetric();
        let mut orbit = Self {
            model,
            sine,
            t0: 0.25 * period,
            span: if symmetric { 0.5 * period } else { period },
            symmetric,
            steps: Vec::with_capacity(512),
            starts: Vec::new(),
            sums: Sums::default(),
        };
        let c = orbit.record(tol)?;
        let z0 = orbit.fixed_point(c);
        orbit.replay(z0);
        orbit.refine_peak();
        Ok(orbit)
    }

    #[inline]
    fn coefficients(&self, t: f64) -> (f64, f64) {
        coefficients(self.model, &self.sine, t)
    }

    /// The adaptive pass from `z = 0` over the stretch, stopping at the bottom reversal;
    /// returns `c` of (P2) and keeps every step's stage map.
    fn record(&mut self, tol: Tolerance) -> Result<f64, SimulateError> {
        let (model, sine) = (self.model, self.sine);
        let ode = |t: f64| coefficients(model, &sine, t);
        // z lives on the scale of the smaller of the stroke and the bristle's reach g0/sigma0.
        let scale = self
            .sine
            .amplitude()
            .min(self.model.g0() / self.model.sigma0());
        let mut integrator = Integrator::new(tol, scale);
        // The steps also hold the dissipation's quadrature (P5) on the orbit's way from 0.
        let (sigma0, sigma1) = (model.sigma0(), model.sigma1());
        let rate = |_t: f64, z: f64, r: f64, v: f64| {
            sigma0 * r * z * z + sigma1 * (v - r * z) * v + model.f(v) * v
        };
        // Its size: g0 A w in sliding, times (sigma0 A / g0)^2 in the elastic regime.
        let (a, g0) = (sine.amplitude(), model.g0());
        let rate_scale = g0 * a * sine.omega() * (sigma0 * a / g0).min(1.0).powi(2);
        let mut steps = std::mem::take(&mut self.steps);
        let full = !self.symmetric;
        let mut keep = |t: f64, h: f64, _z: f64, s: &Stages| {
            let (m, haq) = stage_system(h, &s.r, &s.q);
            let d = if full {
                let hr: [f64; 3] =
                    std::array::from_fn(|i| (0..3).map(|j| h * A[i][j] * s.r[j]).sum());
                solve3(m, hr)[2]
            } else {
                0.0
            };
            steps.push(Step {
                t,
                h,
                r: s.r,
                v: s.q,
                g: solve3(m, [1.0; 3]),
                k: solve3(m, haq),
                d,
            });
        };
        let half = self.t0 + 0.5 * self.sine.period();
        let mut z = integrator.advance_observed(
            &ode,
            self.t0,
            0.0,
            half,
            (&rate, rate_scale),
            &mut keep,
        )?;
        if full {
            z = integrator.advance_observed(
                &ode,
                half,
                z,
                self.t0 + self.span,
                (&rate, rate_scale),
                &mut keep,
            )?;
        }
        self.steps = steps;
        if !z.is_finite() {
            return Err(SimulateError::Overflow {
                what: "the state z",
                t: self.t0 + self.span,
            });
        }
        Ok(z)
    }

    /// The orbit's state at the stretch's start: (P4) for a symmetric model, (P3) else, with
    /// the discrete map's own `Phi` (the product of the steps' `G_3`), so that the replay
    /// closes on itself to rounding.
    fn fixed_point(&self, c: f64) -> f64 {
        if self.symmetric {
            let phi: f64 = self.steps.iter().map(|s| s.g[2]).product();
            -c / (1.0 + phi)
        } else {
            // ln Phi = sum ln(1 - d_i); 1 - Phi = -expm1(ln Phi).
            let log_phi: f64 = self.steps.iter().map(|s| (-s.d).ln_1p()).sum();
            c / -log_phi.exp_m1()
        }
    }

    /// The force at `t` for state `z` and slope `v` (eq. 1).
    #[inline]
    fn force(&self, z: f64, r: f64, v: f64) -> f64 {
        let m = self.model;
        m.sigma0() * z + m.sigma1() * (v - r * z) + m.f(v)
    }

    /// Walks the orbit from `z0`, summing the quadratures (P5) on the stages.
    fn replay(&mut self, z0: f64) {
        let (sigma0, sigma1) = (self.model.sigma0(), self.model.sigma1());
        let w = self.sine.omega();
        let mut s = Sums {
            z_start: z0,
            peak: (sigma0 * z0).abs(),
            peak_t: self.t0,
            ..Sums::default()
        };
        self.starts.clear();
        self.starts.reserve(self.steps.len());
        let mut z = z0;
        for step in &self.steps {
            self.starts.push(z);
            let mut sums = [0.0; 2];
            for j in 0..3 {
                let (zj, r, v) = (z * step.g[j] + step.k[j], step.r[j], step.v[j]);
                let tj = step.t + C[j] * step.h;
                let force = self.force(zj, r, v);
                let rates = [
                    sigma0 * r * zj * zj + sigma1 * (v - r * zj) * v + self.model.f(v) * v,
                    force * (w * tj).sin(),
                ];
                for (sum, rate) in sums.iter_mut().zip(rates) {
                    *sum += B[j] * rate;
                }
                if force.abs() > s.peak {
                    (s.peak, s.peak_t) = (force.abs(), tj);
                }
            }
            s.dissipation += step.h * sums[0];
            s.sin += step.h * sums[1];
            z = z * step.g[2] + step.k[2];
        }
        s.z_end = z;
        self.sums = s;
    }

    /// The state on the orbit at `t` in the stretch: one Radau step from the start of the
    /// recorded step that holds `t` (shorter than that step, so at least as accurate).
    fn z_at(&self, t: f64) -> f64 {
        let i = self.steps.partition_point(|s| s.t <= t).saturating_sub(1);
        let (start, z) = (self.steps[i].t, self.starts[i]);
        let h = t - start;
        if h <= 0.0 {
            return z;
        }
        radau_step(&|t: f64| self.coefficients(t), start, z, h)
    }

    /// The force on the orbit at `t` in the stretch.
    fn force_at(&self, t: f64) -> f64 {
        let (r, v) = self.coefficients(t);
        self.force(self.z_at(t), r, v)
    }

    /// Locates the peak `|F|` between the neighbours of the step where the stages found it,
    /// by golden section.
    fn refine_peak(&mut self) {
        if self.steps.is_empty() {
            return;
        }
        let i = self
            .steps
            .partition_point(|s| s.t <= self.sums.peak_t)
            .saturating_sub(1);
        let lo = self.steps[i.saturating_sub(1)].t;
        let last = &self.steps[(i + 1).min(self.steps.len() - 1)];
        let hi = (last.t + last.h).min(self.t0 + self.span);
        let phi = 0.5 * (5f64.sqrt() - 1.0);
        let (mut a, mut b) = (lo, hi);
        let mut x1 = b - phi * (b - a);
        let mut x2 = a + phi * (b - a);
        let (mut f1, mut f2) = (self.force_at(x1).abs(), self.force_at(x2).abs());
        for _ in 0..PEAK_ITERATIONS {
            if f1 >= f2 {
                (b, x2, f2) = (x2, x1, f1);
                x1 = b - phi * (b - a);
                f1 = self.force_at(x1).abs();
            } else {
                (a, x1, f1) = (x1, x2, f2);
                x2 = a + phi * (b - a);
                f2 = self.force_at(x2).abs();
            }
        }
        let (best, t) = if f1 >= f2 { (f1, x1) } else { (f2, x2) };
        if best > self.sums.peak {
            (self.sums.peak, self.sums.peak_t) = (best, t);
        }
    }

    /// The loop at `n >= 2` evenly spaced times over a period from `t = 0`, both ends
    /// included; for a symmetric model the second half is the first with `u - offset` and `F`
    /// of the opposite sign.
    pub fn samples(&self, n: usize) -> LoopSamples {
        let period = self.sine.period();
        let mut out = LoopSamples {
            t: Vec::with_capacity(n),
            u: Vec::with_capacity(n),
            force: Vec::with_capacity(n),
        };
        for j in 0..n {
            let t = if j + 1 == n {
                period
            } else {
                period * (j as f64 / (n - 1) as f64)
            };
            // Into the stretch [t0, t0 + span): a whole period back, or half of one with the
            // sign flipped.
            let mut tau = t - self.t0;
            if tau < 0.0 {
                tau += period;
            }
            let (tau, sign) = if tau >= self.span {
                (tau - self.span, -1.0)
            } else {
                (tau, 1.0)
            };
            let force = sign * self.force_at(self.t0 + tau.min(self.span));
            out.t.push(t);
            out.u.push(self.sine.u(t));
            out.force.push(force);
        }
        out
    }

    /// How many times the sums over the stretch count in a period.
    pub fn copies(&self) -> f64 {
        if self.symmetric {
            2.0
        } else {
            1.0
        }
    }

    pub fn sine(&self) -> &Sine {
        &self.sine
    }
}
