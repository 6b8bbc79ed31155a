//! The exact solution of eq. 5 for piecewise-linear inputs
//! (`docs/mathematics.md#piecewise-linear-inputs-in-closed-form`).
//!
//! On a segment from knot `(t_i, u_i)` to `(t_{i+1}, u_{i+1})` the input's slope is the
//! constant `v = du / dt` (`du = u_{i+1} - u_i`, `dt = t_{i+1} - t_i`) and eq. 5 is linear with
//! constant coefficients:
//!
//! ```text
//! k     = sigma0 |v| / g(v / gamma)                      z_inf = v / k = sign(v) g(v / gamma) / sigma0
//! z(t)  = z_inf + (z_i - z_inf) exp(-k (t - t_i))
//!       = z_i exp(-c) + du' phi(c)                       c = k (t - t_i),  du' = v (t - t_i)
//! z'(t) = v - k z(t)
//! y     = sigma0 z + (sigma1 / gamma) z' + f(v / gamma)
//! ```
//!
//! The second form of `z` (`relax`, shared with the hysteresis loop) has no exponential of a
//! positive argument, never divides by `k` (a segment where `u` stands still, `k = 0`, is exact
//! too) and does not cancel (`1 - exp(-c)` is computed as such, see `decay`). Over a whole
//! segment `c = sigma0 |du| / g(v / gamma)` depends on `dt` only through `g`, so in the
//! rate-independent limit the recursion is exactly eq. 8's. The per-sample loop uses the
//! equivalent `relax_toward` form `z_i exp(-c) + z_inf (1 - exp(-c))`, which keeps a division
//! off its critical path. Per segment this costs one `g` (one exponential for the Stribeck
//! curve), one exponential in `decay`, and four divisions: nothing is allocated, nothing is
//! limited by stiffness, and the error is a few roundings per segment for any `sigma0 / g`.
//!

use super::inputs::{PiecewiseLinear, Sine};
use super::{check_output_times, Gamma, Sample, SimulateError, Tolerance, Trajectory};
use crate::kernel::relax::relax_toward;
use crate::model::{LuGre, Stribeck, VelocityFn, Viscous};

/// Samples between two calls of the progress callback.
const PROGRESS_EVERY: usize = 1 << 16;

/// Rows written per block (between checks and progress reports).
const CHUNK: usize = 256;

/// Eq. 5 for one model, slowness and initial state, driven by any input.
#[derive(Debug, Clone)]
pub struct Simulator<'m, G = Stribeck, F = Viscous> {
    pub(super) model: &'m LuGre<G, F>,
    gamma: Gamma,
    x0: f64,
    sigma0: f64,
    /// `1 / sigma0`.
    inv_sigma0: f64,
    /// `1 / gamma` (0 in the limit).
    pub(super) inv_gamma: f64,
    /// `sigma1 / gamma` (0 in the limit).
    sigma1_over_gamma: f64,
}

/// What [`Simulator::walk_segment`] gives.
#[derive(Debug, Clone, Copy)]
pub(crate) struct SegmentWalk {
    pub z_end: f64,
    pub exponent: f64,
    pub work: f64,
    pub y_start: f64,
    pub y_end: f64,
}

/// Eq. 5's coefficients on one segment of a piecewise-linear input.
#[derive(Debug, Clone, Copy)]
struct Segment {
    /// `v = du / dt`.
    v: f64,
    /// `k = sigma0 |v| / g(v / gamma)`.
    k: f64,
    /// `c = k dt = sigma0 |du| / g(v / gamma)`, the decay over the whole segment.
    c: f64,
    /// `z_inf = v / k = sign(du) g(v / gamma) / sigma0`, the state relaxed to.
    z_inf: f64,
    /// `f(v / gamma)`.
    f: f64,
}

impl<'m, G: VelocityFn, F: VelocityFn> Simulator<'m, G, F> {
    /// Validated: `x0` finite and `sigma0 x0` representable (`y(0)` must be).
    pub fn new(model: &'m LuGre<G, F>, gamma: Gamma, x0: f64) -> Result<Self, SimulateError> {
        if !x0.is_finite() {
            return Err(SimulateError::BadX0 { value: x0 });
        }
        let sigma0 = model.sigma0();
        if !(sigma0 * x0).is_finite() {
            return Err(SimulateError::X0Overflow { x0, sigma0 });
        }
        Ok(Self {
            model,
            gamma,
            x0,
            sigma0,
            inv_sigma0: 1.0 / sigma0,
            inv_gamma: gamma.inverse(),
            sigma1_over_gamma: model.sigma1() * gamma.inverse(),
        })
    }

    pub fn model(&self) -> &LuGre<G, F> {
        self.model
    }

    /// The same runs, reporting the fraction of each run done to `progress` now and then
    /// (opt-in: the plain methods report nothing).
    ///
    /// ```
    /// use lugre::{Gamma, LuGre, PiecewiseLinear, Simulator, Trajectory};
    /// let model = LuGre::paper();
    /// let input = PiecewiseLinear::new(vec![0.0, 1.0, 2.0], vec![0.0, 1.0, 0.0]).unwrap();
    /// let mut last = 0.0;
    /// let mut report = |done: f64| last = done;
    /// let mut out = Trajectory::default();
    /// Simulator::new(&model, Gamma::ONE, 0.0)
    ///     .unwrap()
    ///     .with_progress(&mut report)
    ///     .at_knots(&input, 2, &mut out)
    ///     .unwrap();
    /// assert_eq!(out.len(), 5);
    /// ```
    pub fn with_progress<'s, 'p>(
        &'s self,
        progress: &'p mut dyn FnMut(f64),
    ) -> Observed<'s, 'p, 'm, G, F> {
        Observed {
            simulator: self,
            progress,
        }
    }
    pub fn gamma(&self) -> Gamma {
        self.gamma
    }
    pub fn x0(&self) -> f64 {
        self.x0
    }

    #[inline(always)]
    fn segment(&self, du: f64, dt: f64) -> Segment {
        let v = du / dt;
        let w = v * self.inv_gamma;
        let g = self.model.g(w);
        // One division per sample for both sigma0 / g and g / sigma0.
        let sigma0_over_g = self.sigma0 * (1.0 / g);
        Segment {
            v,
            k: sigma0_over_g * v.abs(),
            c: sigma0_over_g * du.abs(),
            z_inf: (g * self.inv_sigma0).copysign(du),
            f: self.model.f(w),
        }
    }

    /// The output at state `z` on a segment (the value just after a kink at its start).
    #[inline(always)]
    fn sample(&self, seg: &Segment, t: f64, u: f64, z: f64) -> Sample {
        let dz = seg.v - seg.k * z;
        Sample {
            t,
            u,
            z,
            dz,
            y: self.sigma0 * z + self.sigma1_over_gamma * dz + seg.f,
        }
    }

    /// From state `z`, the input moving by `du` over `dt > 0` at a constant speed: the sample
    /// at the step's end, with the step's slope (the value just before a kink there).
    #[inline(always)]
    pub(super) fn advance(&self, z: f64, t_end: f64, u_end: f64, du: f64, dt: f64) -> Sample {
        let seg = self.segment(du, dt);
        let z = relax_toward(z, seg.c, seg.z_inf);
        self.sample(&seg, t_end, u_end, z)
    }

    /// One segment of a piecewise-linear input walked exactly from state `z` (the input
    /// moving by `du` over `dt > 0`): the state at its end, the decay exponent
    /// `c = sigma0 |du| / g(v / gamma)` (the segment's share of `R` in the sweep's eq. S2), the
    /// work `integral y u' dt` over it, and the output just after its start and just before its
    /// end. The work is `sigma0 du zbar + (sigma1 / gamma) v (z_end - z) + f du`, with the mean
    /// state `zbar = z_inf + (z - z_inf) phi(c)`: `integral z' dt = z_end - z` exactly, so the
    /// stiff `k z` term never appears.
    pub(crate) fn walk_segment(&self, z: f64, du: f64, dt: f64) -> SegmentWalk {
        let seg = self.segment(du, dt);
        let (e, one_minus_e) = crate::kernel::relax::decay(seg.c);
        let z_end = z * e + seg.z_inf * one_minus_e;
        let phi = if seg.c > 0.0 {
            one_minus_e / seg.c
        } else {
            1.0
        };
        let zbar = seg.z_inf + (z - seg.z_inf) * phi;
        let work =
            self.sigma0 * du * zbar + self.sigma1_over_gamma * seg.v * (z_end - z) + seg.f * du;
        SegmentWalk {
            z_end,
            exponent: seg.c,
            work,
            y_start: self.sample(&seg, 0.0, 0.0, z).y,
            y_end: self.sample(&seg, 0.0, 0.0, z_end).y,
        }
    }

    /// The response to a smooth motion at its samples (the cubic reading,
    /// [`super::smooth`]): the exact solution on the subdivided interpolant, output with the
    /// interpolant's velocity at each sample. Appended to `out`.
    pub fn at_samples(
        &self,
        motion: &super::SmoothSamples,
        out: &mut Trajectory,
    ) -> Result<(), SimulateError> {
        // Only z is needed at the knots (the output is taken with the samples' velocities):
        // the recursion alone, without writing the rows of every refined knot.
        let (rt, ru) = (motion.refined().times(), motion.refined().values());
        let (t, x, v) = motion.samples();
        out.reserve(t.len());
        let base = out.len();
        let knots = motion.sample_knots();
        let mut z = self.x0;
        let mut next = 0;
        for k in 0..rt.len() {
            if knots.get(next) == Some(&k) {
                out.push(self.sample_at_slope(t[next], x[next], v[next], z));
                next += 1;
            }
            if k + 1 < rt.len() {
                let seg = self.segment(ru[k + 1] - ru[k], rt[k + 1] - rt[k]);
                z = relax_toward(z, seg.c, seg.z_inf);
            }
        }
        out.check_finite(base)
    }

    /// The output where the input's slope is `v` (smooth inputs: no kink).
    #[inline]
    pub(super) fn sample_at_slope(&self, t: f64, u: f64, v: f64, z: f64) -> Sample {
        let seg = self.segment(v, 1.0);
        self.sample(&seg, t, u, z)
    }

    /// Eq. 5's rate `sigma0 |v| / g(v / gamma)` at slope `v`.
    #[inline]
    pub(super) fn rate(&self, v: f64) -> f64 {
        self.sigma0 * v.abs() / self.model.g(v * self.inv_gamma)
    }

    /// The response at every knot of `input` over `periods` periods, appended to `out`
    /// (`(len - 1) periods + 1` samples). The fast path for sampled data: per sample one `g`,
    /// one exponential, no allocation beyond `out`'s growth.
    ///
    /// [`with_progress`](Self::with_progress) reports the fraction of the run done now and
    /// then.
    pub fn at_knots(
        &self,
        input: &PiecewiseLinear,
        periods: u32,
        out: &mut Trajectory,
    ) -> Result<(), SimulateError> {
        self.observed_at_knots(input, periods, out, &mut |_| {})
    }

    pub(super) fn observed_at_knots(
        &self,
        input: &PiecewiseLinear,
        periods: u32,
        out: &mut Trajectory,
        progress: &mut dyn FnMut(f64),
    ) -> Result<(), SimulateError> {
        input.check_periods(periods)?;
        let (t, u) = (input.times(), input.values());
        let n = t.len();
        out.reserve((n - 1) * periods as usize + 1);
        let total = (n - 1) as f64 * f64::from(periods);
        let mut z = self.x0;
        for p in 0..periods {
            let shift = f64::from(p) * input.period();
            let mut i = 0;
            while i < n - 1 {
                let stop = (i + CHUNK).min(n - 1);
                let base = out.len();
                // Non-zero (NaN) once any of z, z', y is not finite: one check per block, made
                // while the rows are in L1 rather than in a second pass over the output.
                let mut bad = 0.0;
                for i in i..stop {
                    let seg = self.segment(u[i + 1] - u[i], t[i + 1] - t[i]);
                    // `+ 0.0` in the first period leaves the user's times exact.
                    let s = self.sample(&seg, t[i] + shift, u[i], z);
                    bad += (s.z + s.dz + s.y) * 0.0;
                    // Pushed into reserved capacity: no zero-filling pass before the writes.
                    out.push(s);
                    z = relax_toward(z, seg.c, seg.z_inf);
                }
                if bad != 0.0 {
                    out.check_finite(base)?;
                }
                i = stop;
                if i % PROGRESS_EVERY < CHUNK {
                    progress(((n - 1) as f64 * f64::from(p) + i as f64) / total);
                }
            }
        }
        let last = self.end_segment(input);
        out.push(self.sample(&last, input.knot_time(n - 1, periods - 1), u[n - 1], z));
        out.check_finite(out.len() - 1)
    }

    /// The segment whose slope applies at the input's end: the next period's first for a
    /// closed input, the last one otherwise.
    fn end_segment(&self, input: &PiecewiseLinear) -> Segment {
        let (t, u) = (input.times(), input.values());
        let n = t.len();
        if input.is_closed() {
            self.segment(u[1] - u[0], t[1] - t[0])
        } else {
            self.segment(u[n - 1] - u[n - 2], t[n - 1] - t[n - 2])
        }
    }

    /// The response at the given times (strictly increasing, inside
    /// [`PiecewiseLinear::span`]), appended to `out`. A time on a knot gets the value just
    /// after the kink. Between knots `z` is evaluated from the segment's start, so no error
    /// accumulates within a segment.
    pub fn at_times(
        &self,
        input: &PiecewiseLinear,
        periods: u32,
        times: &[f64],
        out: &mut Trajectory,
    ) -> Result<(), SimulateError> {
        self.observed_at_times(input, periods, times, out, &mut |_| {})
    }

    pub(super) fn observed_at_times(
        &self,
        input: &PiecewiseLinear,
        periods: u32,
        times: &[f64],
        out: &mut Trajectory,
        progress: &mut dyn FnMut(f64),
    ) -> Result<(), SimulateError> {
        input.check_periods(periods)?;
        let (start, end) = input.span(periods);
        check_output_times(times, start, end)?;
        let first = out.len();
        out.reserve(times.len());
        let (t, u) = (input.times(), input.values());
        let n = t.len();
        let mut z = self.x0;
        let mut j = 0;
        let mut since_progress = 0;
        'periods: for p in 0..periods {
            for i in 0..n - 1 {
                if j == times.len() {
                    break 'periods;
                }
                let seg = self.segment(u[i + 1] - u[i], t[i + 1] - t[i]);
                let t_i = input.knot_time(i, p);
                let final_segment = p == periods - 1 && i == n - 2;
                // Segment i of period p is [t_i, t_next); the last period's end belongs to the
                // last segment (it is the end of the run).
                let t_next = if i + 1 < n - 1 {
                    input.knot_time(i + 1, p)
                } else if !final_segment {
                    input.knot_time(0, p + 1)
                } else {
                    f64::INFINITY
                };
                let t_end = input.knot_time(n - 1, periods - 1);
                while j < times.len() && times[j] < t_next {
                    let tau = times[j];
                    let s = if final_segment && tau >= t_end {
                        // The end of the input: exact end state, slope as at the end.
                        let z_end = relax_toward(z, seg.c, seg.z_inf);
                        self.sample(&self.end_segment(input), tau, u[n - 1], z_end)
                    } else {
                        let e = tau - t_i;
                        let zt = relax_toward(z, seg.k * e, seg.z_inf);
                        self.sample(&seg, tau, u[i] + seg.v * e, zt)
                    };
                    out.push(s);
                    j += 1;
                    since_progress += 1;
                }
                z = relax_toward(z, seg.c, seg.z_inf);
                since_progress += 1;
                if since_progress >= PROGRESS_EVERY {
                    since_progress = 0;
                    progress(((t_next.min(end) - start) / (end - start)).clamp(0.0, 1.0));
                }
            }
        }
        out.check_finite(first)
    }
}

/// A [`Simulator`] whose runs report their progress ([`Simulator::with_progress`]).
pub struct Observed<'s, 'p, 'm, G = Stribeck, F = Viscous> {
    simulator: &'s Simulator<'m, G, F>,
    progress: &'p mut dyn FnMut(f64),
}

impl<G: VelocityFn, F: VelocityFn> Observed<'_, '_, '_, G, F> {
    /// [`Simulator::at_knots`], reporting progress.
    pub fn at_knots(
        &mut self,
        input: &PiecewiseLinear,
        periods: u32,
        out: &mut Trajectory,
    ) -> Result<(), SimulateError> {
        self.simulator
            .observed_at_knots(input, periods, out, self.progress)
    }

    /// [`Simulator::at_times`], reporting progress.
    pub fn at_times(
        &mut self,
        input: &PiecewiseLinear,
        periods: u32,
        times: &[f64],
        out: &mut Trajectory,
    ) -> Result<(), SimulateError> {
        self.simulator
            .observed_at_times(input, periods, times, out, self.progress)
    }

    /// [`Simulator::sine`], reporting progress.
    pub fn sine(
        &mut self,
        input: &Sine,
        periods: u32,
        times: &[f64],
        tol: Tolerance,
        out: &mut Trajectory,
    ) -> Result<(), SimulateError> {
        self.simulator
            .observed_sine(input, periods, times, tol, out, self.progress)
    }
}
