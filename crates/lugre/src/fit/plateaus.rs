//! The steady parts of a constant-velocity record: the points of the Stribeck fit
//! ([`super::fit_stribeck`]) from a record `(t, u, F)` (or `(t, v, F)`) of runs at constant
//! velocities, found without help.
//!
//! 1. **Velocity.** Between samples, `v_i = (u_{i+1} - u_i) / (t_{i+1} - t_i)` (a velocity
//!    record gives it at each sample). Its noise is estimated robustly from the second
//!    differences, which are noise alone on a run and hardly see a smooth change:
//!    `s_v = median |v_{i+1} - 2 v_i + v_{i-1}| / (Phi^-1(3/4) sqrt(6))` (P1, the estimator (N1) of
//!    [`super::noise`] at order 2).
//! 2. **Runs.** A run is a stretch of consecutive samples whose velocity stays within
//!    `4 s_v + 0.1 % |v|` of the stretch's mean (P2); runs of at least
//!    [`MIN_RUN`] samples that move (`|v| > 4 s_v`) are the candidate plateaus. Ramps between
//!    runs, whose velocity changes from sample to sample, form no run.
//! 3. **Steady part.** The start of a run is the transient of the friction towards its steady
//!    value. While the mean force of the first quarter of what is left differs from that of the
//!    last half by more than three standard errors of the difference,
//!    `3 s_F sqrt(1/n_q + 1/n_h)` with `s_F` the standard deviation over the last half, the
//!    first quarter is dropped (P3). A run whose steady part keeps fewer than [`MIN_STEADY`]
//!    samples is skipped (and counted).
//! 4. **Point.** The steady part's velocity is the least-squares slope of `u` against `t` (a
//!    velocity record: the mean `v`), its force the mean `F`, with the standard error
//!    `s_F / sqrt(n)` (independent noise assumed) (P4).

use crate::error::FitError;
use crate::input::{check_finite, check_increasing};

use super::noise::difference_noise;
use super::stribeck::SteadyPoint;

/// The fewest samples a run must have to be a candidate plateau.
pub const MIN_RUN: usize = 10;
/// The fewest samples the steady part of a plateau must keep.
pub const MIN_STEADY: usize = 10;
/// Runs at least this long, if none is long enough, make the record's runs "too short"
/// rather than absent.
const SHORT_RUN: usize = 5;
/// The relative tolerance on a run's velocity (P2), besides its noise.
const RELATIVE_TOLERANCE: f64 = 1e-3;
/// Standard deviations of the velocity's noise within which it counts as constant (P2).
const NOISE_WIDTH: f64 = 4.0;

/// The steady part of one constant-velocity run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Plateau {
    /// The run: its first sample and one past its last.
    pub run: (usize, usize),
    /// The steady part (P3): its first sample and one past its last.
    pub steady: (usize, usize),
    /// The velocity (P4).
    pub v: f64,
    /// The mean force over the steady part.
    pub f: f64,
    /// The standard deviation of the force over the steady part.
    pub f_sd: f64,
    /// The standard error of the mean force, `f_sd / sqrt(n)`.
    pub stderr: f64,
}

impl Plateau {
    /// The point of the Stribeck fit.
    pub fn point(&self) -> SteadyPoint {
        SteadyPoint {
            v: self.v,
            f: self.f,
            stderr: Some(self.stderr),
        }
    }
}

/// The plateaus of a record and what was set aside.
#[derive(Debug, Clone, PartialEq)]
pub struct Plateaus {
    pub plateaus: Vec<Plateau>,
    /// Runs skipped because their steady part kept fewer than [`MIN_STEADY`] samples.
    pub skipped: usize,
    /// The velocity's noise `s_v` (P1).
    pub velocity_noise: f64,
}

impl Plateaus {
    /// The points of the Stribeck fit, one a plateau.
    pub fn points(&self) -> Vec<SteadyPoint> {
        self.plateaus.iter().map(Plateau::point).collect()
    }
}

/// Which motion the record gives.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Motion {
    /// The displacement `u` at each sample.
    Displacement,
    /// The velocity `v` at each sample.
    Velocity,
}

/// The plateaus of a record `(t, motion, F)` (see the module docs).
pub fn find_plateaus(
    t: &[f64],
    motion: &[f64],
    f: &[f64],
    kind: Motion,
) -> Result<Plateaus, FitError> {
    let name = match kind {
        Motion::Displacement => "u",
        Motion::Velocity => "v",
    };
    super::check_columns(&[(name, motion), ("t", t), ("F", f)])?;
    check_increasing(t)?;
    check_finite("t", t)?;
    if t.len() < MIN_RUN {
        return Err(FitError::NoPlateau {
            samples: t.len(),
            min_run: MIN_RUN,
        });
    }
    // The velocity of each sample: on the interval after it (the last: before it).
    let v: Vec<f64> = match kind {
        Motion::Velocity => motion.to_vec(),
        Motion::Displacement => {
            let mut v: Vec<f64> = (0..t.len() - 1)
                .map(|i| (motion[i + 1] - motion[i]) / (t[i + 1] - t[i]))
                .collect();
            v.push(v[v.len() - 1]);
            v
        }
    };
    let noise = difference_noise(&v, 2);
    let mut plateaus = Vec::new();
    let (mut skipped, mut longest) = (0, 0);
    for (a, b) in runs(&v, noise) {
        let moving = (v[a..b].iter().sum::<f64>() / (b - a) as f64).abs() > NOISE_WIDTH * noise;
        if !moving {
            continue;
        }
        longest = longest.max(b - a);
        if b - a < MIN_RUN {
            continue;
        }
        match steady_part(f, a, b) {
            Some(c) => plateaus.push(plateau(t, motion, f, kind, (a, b), c)),
            None => skipped += 1,
        }
    }
    if plateaus.is_empty() {
        // Runs of a few samples are constant-velocity runs cut short; shorter ones are a
        // smooth motion's.
        return Err(if longest >= SHORT_RUN {
            FitError::TooFewPlateauSamples {
                longest,
                needed: MIN_RUN.max(MIN_STEADY),
            }
        } else {
            FitError::NoPlateau {
                samples: t.len(),
                min_run: MIN_RUN,
            }
        });
    }
    check_signal(&plateaus)?;
    Ok(Plateaus {
        plateaus,
        skipped,
        velocity_noise: noise,
    })
}

/// (P2): the stretches `[a, b)` of constant velocity.
fn runs(v: &[f64], noise: f64) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut a = 0;
    let mut sum = v[0];
    for (i, &vi) in v.iter().enumerate().skip(1) {
        let mean = sum / (i - a) as f64;
        if (vi - mean).abs() <= NOISE_WIDTH * noise + RELATIVE_TOLERANCE * mean.abs() {
            sum += vi;
        } else {
            out.push((a, i));
            a = i;
            sum = vi;
        }
    }
    out.push((a, v.len()));
    out
}

/// Mean and standard deviation (`n - 1` in the denominator) of `x`.
fn mean_sd(x: &[f64]) -> (f64, f64) {
    let n = x.len() as f64;
    let m = x.iter().sum::<f64>() / n;
    let ss: f64 = x.iter().map(|y| (y - m) * (y - m)).sum();
    (m, (ss / (n - 1.0).max(1.0)).sqrt())
}

/// (P3): the first sample of the steady part of run `[a, b)`, or `None` when fewer than
/// [`MIN_STEADY`] samples would be left. The run's first sample ends the ramp: never steady.
fn steady_part(f: &[f64], a: usize, b: usize) -> Option<usize> {
    let mut c = a + 1;
    loop {
        let n = b - c;
        if n < MIN_STEADY {
            return None;
        }
        let (q, h) = (n / 4, n / 2);
        let (head, _) = mean_sd(&f[c..c + q.max(1)]);
        let (tail, sd) = mean_sd(&f[b - h..b]);
        let limit = 3.0 * sd * (1.0 / q.max(1) as f64 + 1.0 / h as f64).sqrt();
        if (head - tail).abs() <= limit {
            return Some(c);
        }
        c += q.max(1);
    }
}

/// (P4): the point of run `[a, b)` with steady part from `c`.
fn plateau(
    t: &[f64],
    motion: &[f64],
    f: &[f64],
    kind: Motion,
    (a, b): (usize, usize),
    c: usize,
) -> Plateau {
    let (mean_f, sd) = mean_sd(&f[c..b]);
    let n = (b - c) as f64;
    let v = match kind {
        Motion::Velocity => mean_sd(&motion[c..b]).0,
        Motion::Displacement => {
            let (mt, _) = mean_sd(&t[c..b]);
            let (mu, _) = mean_sd(&motion[c..b]);
            let (mut stu, mut stt) = (0.0, 0.0);
            for i in c..b {
                stu += (t[i] - mt) * (motion[i] - mu);
                stt += (t[i] - mt) * (t[i] - mt);
            }
            stu / stt
        }
    };
    Plateau {
        run: (a, b),
        steady: (c, b),
        v,
        f: mean_f,
        f_sd: sd,
        // A noise-free record would give 0, which no weight can use: a floor at the force's
        // rounding.
        stderr: (sd / n.sqrt()).max(f64::EPSILON * mean_f.abs()),
    }
}

/// Noise larger than the signal: the median force noise of the plateaus at least their median
/// `|F|`.
fn check_signal(plateaus: &[Plateau]) -> Result<(), FitError> {
    let median = |mut x: Vec<f64>| {
        x.sort_by(f64::total_cmp);
        x[x.len() / 2]
    };
    let noise = median(plateaus.iter().map(|p| p.f_sd).collect());
    let signal = median(plateaus.iter().map(|p| p.f.abs()).collect());
    if noise >= signal {
        return Err(FitError::NoiseAboveSignal {
            what: "the plateaus' force",
            noise,
            signal,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A record of runs at the velocities `speeds`, `per_run` samples each at `dt`, with
    /// instantaneous velocity changes and a force that relaxes to `1 + 0.1 |v|` (times the
    /// sign) with time constant `tau` in samples, plus a deterministic wiggle of amplitude
    /// `noise`.
    fn record(
        speeds: &[f64],
        per_run: usize,
        tau: f64,
        noise: f64,
    ) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        let dt = 0.01;
        let (mut t, mut u, mut f) = (Vec::new(), Vec::new(), Vec::new());
        let (mut x, mut force) = (0.0, 0.0);
        for &v in speeds {
            let target = v.signum() * (1.0 + 0.1 * v.abs());
            for _ in 0..per_run {
                let i = t.len();
                t.push(i as f64 * dt);
                u.push(x);
                x += v * dt;
                force = target + (force - target) * (-1.0 / tau).exp();
                f.push(force + noise * ((i as f64) * 2.399).sin());
            }
        }
        (t, u, f)
    }

    #[test]
    fn finds_each_run_and_its_steady_force() {
        let speeds = [0.1, -0.1, 1.0, -1.0, 3.0];
        let (t, u, f) = record(&speeds, 100, 5.0, 1e-3);
        let p = find_plateaus(&t, &u, &f, Motion::Displacement).unwrap();
        assert_eq!(p.plateaus.len(), speeds.len(), "{p:?}");
        for (q, &v) in p.plateaus.iter().zip(&speeds) {
            assert!((q.v - v).abs() < 1e-9 * v.abs(), "{q:?}");
            let want = v.signum() * (1.0 + 0.1 * v.abs());
            assert!(
                (q.f - want).abs() < 4.0 * q.stderr + 1e-4,
                "{q:?} vs {want}"
            );
            // The transient (5 samples' time constant) is dropped.
            assert!(q.steady.0 > q.run.0 + 10, "{q:?}");
        }
    }

    #[test]
    fn a_record_without_plateaus_is_refused() {
        let t: Vec<f64> = (0..200).map(|i| f64::from(i) * 0.01).collect();
        let u: Vec<f64> = t.iter().map(|t| (5.0 * t).sin()).collect();
        let f: Vec<f64> = u.iter().map(|u| u * 0.5).collect();
        let e = find_plateaus(&t, &u, &f, Motion::Displacement).unwrap_err();
        assert!(
            matches!(
                e,
                FitError::NoPlateau { .. } | FitError::TooFewPlateauSamples { .. }
            ),
            "{e}"
        );
        let (t, u, f) = record(&[0.1, -0.1, 1.0], 6, 1.0, 1e-3);
        let e = find_plateaus(&t, &u, &f, Motion::Displacement).unwrap_err();
        assert!(matches!(e, FitError::TooFewPlateauSamples { .. }), "{e}");
        assert!(e.to_string().contains("samples"), "{e}");
        let (t, u, f) = record(&[0.1, -0.1, 1.0], 100, 1.0, 5.0);
        let e = find_plateaus(&t, &u, &f, Motion::Displacement).unwrap_err();
        assert!(matches!(e, FitError::NoiseAboveSignal { .. }), "{e}");
    }
}
