//! The Stribeck fit: `Fc, Fs, vs, sigma2` (and `beta` if freed) from the steady-state friction
//! of constant-velocity runs, the lab's first LuGre experiment (Canudas de Wit et al. 1995;
//! Olsson et al. 1998).
//!
//! At a constant velocity `v` the state of eq. 1 settles at `z = sgn(v) g(v) / sigma0` and the
//! friction force at
//!
//! ```text
//! F_ss(v) = g(v) sgn(v) + sigma2 v        g(v) = Fc + (Fs - Fc) E,  E = exp(-|v / vs|^beta)  (T1)
//! ```
//!
//! which depends on neither `sigma0` nor `sigma1`. With `r = |v| / vs` and `s = sgn(v)` the
//! derivatives are
//!
//! ```text
//! dF/dsigma2 = v    dF/dFc = s (1 - E)    dF/dFs = s E                                      (T2)
//! dF/dvs = s (Fs - Fc) E beta r^beta / vs    dF/dbeta = -s (Fs - Fc) E r^beta ln r
//! ```
//!
//! Each point `(v_k, F_k)` is one run's velocity and mean steady force, with its standard error
//! `e_k` when known (from [`super::plateaus`]): the fit then minimises `sum ((F_ss(v_k) - F_k) /
//! e_k)^2` (weighted least squares), else the plain sum of squares. The covariance is (S1) of
//! the weighted problem, `s^2 (J_w^T J_w)^-1` with `s^2` from the weighted residuals: a common
//! factor in the `e_k` cancels, so only their ratios matter.
//!
//! Start values from the points (`a = |v|`, `y = s F`): a straight line through the faster half
//! gives `Fc` (intercept) and `sigma2` (slope), the slowest three points `Fs`, and `vs` is the
//! slowest speed at which `y - sigma2 a - Fc` has fallen below `(Fs - Fc) / e`; further starts
//! scale `vs` by 4 and 1/4, and the best end point wins.

use super::lm::{minimize, Evaluator};
use super::spec::index_of;
use super::{report, FitKind, FitReport, FitSpec, FULL_CONFIG};
use crate::error::FitError;
use crate::model::{LuGreParams, Parameter};
use nalgebra::DMatrix;

/// One point of the steady-state curve: a constant-velocity run's velocity, its mean friction
/// force and, when known, the standard error of that mean.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyPoint {
    pub v: f64,
    pub f: f64,
    /// The standard error of `f` (`None`: every point weighs the same).
    pub stderr: Option<f64>,
}

/// The steady-state friction force (T1) of the LuGre parameters `p` at velocity `v`.
pub fn steady_force(p: &LuGreParams, v: f64) -> f64 {
    if v == 0.0 {
        // sgn(0) = 0: the curve has a jump there.
        return 0.0;
    }
    // The argument of exp is never positive.
    let e = (-(v / p.vs).abs().powf(p.beta)).exp();
    (p.fc + (p.fs - p.fc) * e) * v.signum() + p.sigma2 * v
}

/// The points of a table of constant-velocity runs, one velocity and steady force a run (no
/// standard errors: every point weighs the same).
pub fn table_points(v: &[f64], f: &[f64]) -> Result<Vec<SteadyPoint>, FitError> {
    if v.len() != f.len() {
        return Err(FitError::SteadyTableLengths {
            v: v.len(),
            f: f.len(),
        });
    }
    Ok(v.iter()
        .zip(f)
        .map(|(&v, &f)| SteadyPoint { v, f, stderr: None })
        .collect())
}

/// Indices of the LuGre parameters in the family's vector (the table's order).
const SIGMA2: usize = index_of(&Parameter::LUGRE, Parameter::Sigma2);
const FC: usize = index_of(&Parameter::LUGRE, Parameter::Fc);
const FS: usize = index_of(&Parameter::LUGRE, Parameter::Fs);
const VS: usize = index_of(&Parameter::LUGRE, Parameter::Vs);
const BETA: usize = index_of(&Parameter::LUGRE, Parameter::Beta);

/// The steady-state curve at the points, weighted, with the derivatives (T2).
struct Curve {
    v: Vec<f64>,
    /// `1 / e_k` (1 without standard errors).
    w: Vec<f64>,
    free: Vec<usize>,
}

impl Evaluator for Curve {
    fn evaluate(&mut self, values: &[f64], y: &mut [f64], jac: &mut DMatrix<f64>) -> bool {
        let (sigma2, fc, fs, vs, beta) = (
            values[SIGMA2],
            values[FC],
            values[FS],
            values[VS],
            values[BETA],
        );
        if !(vs > 0.0 && beta > 0.0) {
            return false;
        }
        for (k, (&v, &w)) in self.v.iter().zip(&self.w).enumerate() {
            let s = v.signum();
            let r = (v / vs).abs();
            let rb = r.powf(beta);
            let e = (-rb).exp();
            y[k] = w * ((fc + (fs - fc) * e) * s + sigma2 * v);
            for (j, &i) in self.free.iter().enumerate() {
                let d = match i {
                    SIGMA2 => v,
                    FC => s * (1.0 - e),
                    FS => s * e,
                    VS => s * (fs - fc) * e * beta * rb / vs,
                    BETA => -s * (fs - fc) * e * rb * r.ln(),
                    _ => 0.0,
                };
                jac[(k, j)] = w * d;
            }
        }
        jac.iter().all(|d| d.is_finite())
    }
}

/// Checks the points: finite, nonzero velocities, positive standard errors.
fn check_points(points: &[SteadyPoint]) -> Result<(), FitError> {
    for (index, p) in points.iter().enumerate() {
        if !p.v.is_finite() || p.v == 0.0 {
            return Err(FitError::BadSteadyVelocity { index, value: p.v });
        }
        if !p.f.is_finite() {
            return Err(FitError::BadSteadyForce { index, value: p.f });
        }
        if let Some(e) = p.stderr {
            if !(e.is_finite() && e > 0.0) {
                return Err(FitError::BadSteadyError { index, value: e });
            }
        }
    }
    Ok(())
}

/// Two runs' speeds within this ratio are one speed of the curve (runs of one test at one
/// set speed, or the two signs of it, differ by their noise only).
const SAME_SPEED: f64 = 1.05;

/// The distinct speeds `|v|` of the points, ascending: the curve's parameters are only
/// identified by runs at as many speeds.
fn distinct_speeds(points: &[SteadyPoint]) -> Vec<f64> {
    let mut a: Vec<f64> = points.iter().map(|p| p.v.abs()).collect();
    a.sort_by(f64::total_cmp);
    let mut out: Vec<f64> = Vec::new();
    for s in a {
        match out.last() {
            Some(&last) if s <= last * SAME_SPEED => {}
            _ => out.push(s),
        }
    }
    out
}

/// The Stribeck fit of `Fc, Fs, vs, sigma2` (and `beta` if freed; `sigma0`, `sigma1` do not
/// enter (T1)) to steady-state points, weighted by their standard errors when every point has
/// one. See the module docs.
pub fn fit_stribeck(spec: &FitSpec, points: &[SteadyPoint]) -> Result<FitReport, FitError> {
    check_points(points)?;
    let mut resolved = spec.resolve(FitKind::Stribeck)?;
    let needed = resolved.free.len() + 1;
    if points.len() < needed {
        return Err(FitError::TooFewPlateaus {
            plateaus: points.len(),
            parameters: resolved.free.len(),
            needed,
        });
    }
    let speeds = distinct_speeds(points);
    if speeds.len() < resolved.free.len() {
        return Err(FitError::TooFewSpeeds {
            speeds: speeds.len(),
            parameters: resolved.free.len(),
            list: speeds.iter().map(|s| format!("{s:.3e}")).collect(),
        });
    }
    let weighted = points.iter().all(|p| p.stderr.is_some());
    let w: Vec<f64> = points
        .iter()
        .map(|p| p.stderr.filter(|_| weighted).map_or(1.0, |e| 1.0 / e))
        .collect();
    let v: Vec<f64> = points.iter().map(|p| p.v).collect();
    let data: Vec<f64> = points.iter().zip(&w).map(|(p, w)| p.f * w).collect();
    resolved.fill_starts(&data_start(&resolved.values, points));
    let mut curve = Curve {
        v,
        w,
        free: resolved.free.clone(),
    };
    let base = resolved.values.clone();
    let vs_column = resolved.free.iter().position(|&i| i == VS);
    let mut best = None;
    let mut evaluations = 0;
    const VS_FACTORS: [f64; 3] = [1.0, 0.25, 4.0];
    for k in VS_FACTORS {
        let mut run = resolved.clone();
        run.values = base.clone();
        if let Some(c) = vs_column.filter(|&c| !resolved.given[c]) {
            run.values[VS] = resolved.bounds[c].pull_inside(base[VS] * k);
        }
        let start = run.free_values();
        let (back, outcome) = minimize(
            curve,
            &data,
            run.space(),
            &start,
            FULL_CONFIG,
            &mut |_, _| {},
        );
        curve = back;
        evaluations += outcome.evaluations;
        if outcome.rss.is_finite()
            && best
                .as_ref()
                .is_none_or(|b: &super::lm::Outcome| outcome.rss < b.rss)
        {
            best = Some(outcome);
        }
    }
    let Some(mut outcome) = best else {
        return Err(FitError::NoStart {
            starts: VS_FACTORS.len(),
        });
    };
    outcome.evaluations = evaluations;
    let weighted_fit = outcome.y.clone();
    let values = outcome.values.clone();
    let mut r = report(
        FitKind::Stribeck,
        &resolved,
        outcome,
        weighted_fit,
        &data,
        VS_FACTORS.len(),
        &[],
    )?;
    // The curve and its RMS in force units (the statistics above are the weighted problem's).
    let p = resolved.lugre(&values);
    r.fitted = points.iter().map(|q| steady_force(&p, q.v)).collect();
    let rss: f64 = points
        .iter()
        .zip(&r.fitted)
        .map(|(q, y)| (q.f - y) * (q.f - y))
        .sum();
    r.rms = (rss / points.len() as f64).sqrt();
    Ok(r)
}

/// Start values from the points (see the module docs), in the family's vector `values`.
fn data_start(values: &[f64], points: &[SteadyPoint]) -> Vec<f64> {
    let mut ay: Vec<(f64, f64)> = points
        .iter()
        .map(|p| (p.v.abs(), p.f * p.v.signum()))
        .collect();
    ay.sort_by(|a, b| a.0.total_cmp(&b.0));
    let n = ay.len();
    let fast = &ay[n / 2..];
    let (intercept, slope) = line(fast);
    let mean_fast = fast.iter().map(|p| p.1).sum::<f64>() / fast.len() as f64;
    let sigma2 = if slope > 0.0 {
        slope
    } else {
        // A small positive viscous start: the parameter is positive.
        1e-3 * mean_fast.abs() / ay[n - 1].0
    };
    let fc = if intercept > 0.0 {
        intercept
    } else {
        mean_fast.abs().max(f64::MIN_POSITIVE)
    };
    let slow = &ay[..n.min(3)];
    let fs = slow
        .iter()
        .map(|(a, y)| y - sigma2 * a)
        .fold(f64::NEG_INFINITY, f64::max);
    let fs = if fs > 1.001 * fc { fs } else { 1.05 * fc };
    let threshold = (fs - fc) * (-1.0f64).exp();
    let vs = ay
        .iter()
        .find(|(a, y)| y - sigma2 * a - fc < threshold)
        .map_or(ay[n / 2].0, |p| p.0);
    let mut out = values.to_vec();
    out[SIGMA2] = sigma2;
    out[FC] = fc;
    out[FS] = fs;
    out[VS] = vs;
    out
}

/// Least-squares line `y = a + b x` through the points (`b = 0` when `x` does not vary).
fn line(points: &[(f64, f64)]) -> (f64, f64) {
    let n = points.len() as f64;
    let mx = points.iter().map(|p| p.0).sum::<f64>() / n;
    let my = points.iter().map(|p| p.1).sum::<f64>() / n;
    let sxx: f64 = points.iter().map(|p| (p.0 - mx) * (p.0 - mx)).sum();
    let sxy: f64 = points.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let b = if sxx > 0.0 { sxy / sxx } else { 0.0 };
    (my - b * mx, b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fit::Family;

    /// canudas1995's values ([`LuGreParams::canudas_de_wit_1995`]).
    fn truth() -> LuGreParams {
        LuGreParams::canudas_de_wit_1995()
    }

    /// (T1) written out separately from the code under test.
    fn f_ss(v: f64) -> f64 {
        let (fc, fs, vs, sigma2) = (1.0, 1.5, 1e-3, 0.4);
        let g = fc + (fs - fc) * (-(v / vs) * (v / vs)).exp();
        if v > 0.0 {
            g + sigma2 * v
        } else {
            -g + sigma2 * v
        }
    }

    /// 25 speeds a sign, log-spaced over four decades (1e-4 to 1 m/s).
    fn speeds() -> Vec<f64> {
        let a: Vec<f64> = (0..25)
            .map(|k| 10f64.powf(-4.0 + 4.0 * f64::from(k) / 24.0))
            .collect();
        a.iter().map(|&a| -a).chain(a.iter().copied()).collect()
    }

    /// A small independent generator of standard normal numbers: a 64-bit LCG (Knuth's MMIX
    /// constants) and the Box-Muller transform.
    struct Normal(u64);

    impl Normal {
        fn uniform(&mut self) -> f64 {
            self.0 = self
                .0
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((self.0 >> 11) as f64 + 0.5) / (1u64 << 53) as f64
        }

        fn next(&mut self) -> f64 {
            let (u1, u2) = (self.uniform(), self.uniform());
            (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
        }
    }

    fn spec() -> FitSpec {
        FitSpec::new(Family::LuGre).set("beta", 2.0).unwrap()
    }

    /// Points with noise of standard deviation `rel |F_ss|` (their standard errors known).
    fn noisy(rng: &mut Normal, rel: f64) -> Vec<SteadyPoint> {
        speeds()
            .into_iter()
            .map(|v| {
                let e = rel * f_ss(v).abs();
                SteadyPoint {
                    v,
                    f: f_ss(v) + e * rng.next(),
                    stderr: Some(e),
                }
            })
            .collect()
    }

    #[test]
    fn the_curve_is_t1() {
        for v in speeds() {
            assert!((steady_force(&truth(), v) - f_ss(v)).abs() < 1e-14 * f_ss(v).abs());
        }
        assert_eq!(steady_force(&truth(), 0.0), 0.0);
    }

    #[test]
    fn noise_free_points_give_the_truth() {
        let points: Vec<SteadyPoint> = speeds()
            .into_iter()
            .map(|v| SteadyPoint {
                v,
                f: f_ss(v),
                stderr: None,
            })
            .collect();
        let r = fit_stribeck(&spec(), &points).unwrap();
        for (name, want) in [("sigma2", 0.4), ("fc", 1.0), ("fs", 1.5), ("vs", 1e-3)] {
            let got = r.estimate(name).unwrap().value;
            assert!(((got - want) / want).abs() < 1e-7, "{name}: {got}");
        }
        assert_eq!(r.fixed, vec![("beta", 2.0)]);
        assert!(r.rms < 1e-9, "{}", r.rms);
    }

    #[test]
    fn beta_freed_is_fitted() {
        let mut rng = Normal(7);
        let points = noisy(&mut rng, 1e-3);
        let r = fit_stribeck(&spec().free("beta").unwrap(), &points).unwrap();
        let beta = r.estimate("beta").unwrap();
        assert!(beta.ci95[0] < 2.0 && 2.0 < beta.ci95[1], "{beta:?}");
    }

    /// The target: runs whose force samples carry 1 % noise, each point the mean of 100 steady
    /// samples (so 0.1 % on the mean), 50 records; every estimate of `Fc, Fs, vs, sigma2`
    /// within 2 % of the truth and the 95 % intervals covering it in at least 45 of 50 records
    /// (90 %) for each. (With 1 % on each point itself `vs` has a standard error of about 2 %.)
    #[test]
    fn monte_carlo_recovery_and_coverage() {
        const PER_RUN: f64 = 100.0;
        let mut rng = Normal(20240926);
        let truth = [("sigma2", 0.4), ("fc", 1.0), ("fs", 1.5), ("vs", 1e-3)];
        let mut covered = [0usize; 4];
        let records = 50;
        for _ in 0..records {
            let r = fit_stribeck(&spec(), &noisy(&mut rng, 0.01 / PER_RUN.sqrt())).unwrap();
            assert!(r.converged);
            for (k, (name, want)) in truth.iter().enumerate() {
                let e = r.estimate(name).unwrap();
                assert!(((e.value - want) / want).abs() < 0.02, "{name}: {e:?}");
                if e.ci95[0] <= *want && *want <= e.ci95[1] {
                    covered[k] += 1;
                }
            }
        }
        eprintln!("coverage of the 95 % intervals in {records} records: {covered:?}");
        for (k, (name, _)) in truth.iter().enumerate() {
            assert!(covered[k] >= 45, "{name}: {} of {records}", covered[k]);
        }
    }

    #[test]
    fn bad_requests_are_named() {
        let mut points = noisy(&mut Normal(1), 0.01);
        let e = fit_stribeck(&spec(), &points[..4]).unwrap_err();
        assert_eq!(
            e,
            FitError::TooFewPlateaus {
                plateaus: 4,
                parameters: 4,
                needed: 5
            }
        );
        assert!(e.to_string().contains("4 constant-velocity"), "{e}");
        points[3].v = 0.0;
        assert_eq!(
            fit_stribeck(&spec(), &points).unwrap_err(),
            FitError::BadSteadyVelocity {
                index: 3,
                value: 0.0
            }
        );
        let e = fit_stribeck(
            &spec().free("sigma0").unwrap(),
            &noisy(&mut Normal(1), 0.01),
        )
        .unwrap_err();
        assert_eq!(e, FitError::NotInSteadyState { name: "sigma0" });
        let e =
            fit_stribeck(&FitSpec::new(Family::Dahl), &noisy(&mut Normal(1), 0.01)).unwrap_err();
        assert!(matches!(e, FitError::NotForFamily { .. }), "{e}");
        let r = spec().resolve(FitKind::Stribeck).unwrap();
        assert_eq!(r.free, vec![SIGMA2, FC, FS, VS]);
        let e = table_points(&[1.0, -1.0], &[1.0]).unwrap_err();
        assert_eq!(e, FitError::SteadyTableLengths { v: 2, f: 1 });
        assert!(e.to_string().contains("2 velocities and 1 forces"), "{e}");
        let p = table_points(&[1.0], &[2.0]).unwrap();
        assert_eq!(
            p,
            vec![SteadyPoint {
                v: 1.0,
                f: 2.0,
                stderr: None
            }]
        );
    }

    #[test]
    fn runs_at_too_few_speeds_are_said_to_be_so() {
        // A sine's record: runs at its peak speed only, both signs, a little spread.
        let points: Vec<SteadyPoint> = [3.77e-3, -3.77e-3, 3.79e-3, -3.76e-3, 3.78e-3, -3.8e-3]
            .iter()
            .map(|&v| SteadyPoint {
                v,
                f: f_ss(v),
                stderr: Some(1e-3),
            })
            .collect();
        let e = fit_stribeck(&spec(), &points).unwrap_err();
        assert!(
            matches!(
                e,
                FitError::TooFewSpeeds {
                    speeds: 1,
                    parameters: 4,
                    ..
                }
            ),
            "{e}"
        );
        assert!(e.to_string().starts_with("the constant-velocity runs are at only 1 distinct speed(s) (3.760e-3) for 4 free parameter(s)"), "{e}");
        assert_eq!(distinct_speeds(&points).len(), 1);
        let all: Vec<SteadyPoint> = speeds()
            .into_iter()
            .map(|v| SteadyPoint {
                v,
                f: f_ss(v),
                stderr: None,
            })
            .collect();
        assert_eq!(distinct_speeds(&all).len(), 25);
    }
}
