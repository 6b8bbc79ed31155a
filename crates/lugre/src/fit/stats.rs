//! Uncertainty at the optimum and the identifiability check.
//!
//! With `m` samples, `p` free parameters, the residual sum of squares `RSS` and the Jacobian
//! `J` (`m x p`, derivatives of the model output with respect to the parameters themselves, not
//! the optimizer's variables) at the optimum, the linearised covariance is
//!
//! ```text
//! s^2 = RSS / (m - p)          Cov = s^2 (J^T J)^-1          se_j = sqrt(Cov_jj)      (S1)
//! CI95_j = p_j -+ t_{0.975, m-p} se_j                                                 (S2)
//! ```
//!
//! with Student's t quantile on `m - p` degrees of freedom (for `m - p >= 30` it is within 5 %
//! of the normal 1.96, for 10^3 samples within 0.2 %). `(J^T J)^-1` is computed from the
//! correlation form `R = D^-1 J^T J D^-1`, `D = diag(|J_j|)`, by its eigen-decomposition: the
//! scaling makes the result independent of the parameters' units, and the eigenvalues give the
//! condition number used below.
//!
//! Where the residuals are correlated (a Ljung-Box test), the covariance is the Newey-West
//! sandwich (C2) instead ([`super::covariance`]). Where the input itself carries an error (a
//! smoothed displacement, [`super::noise`]), the estimates move with it too: with `dy_k` the
//! model's response to the `k`-th of `K` draws of the input's error (the fitted parameters
//! held),
//!
//! ```text
//! Cov += 1/(K-1) sum_k (d_k - d) (d_k - d)^T     d_k = (J^T J)^-1 J^T dy_k,  d = mean d_k   (S3)
//! ```
//!
//! the linearised covariance of the least-squares estimate under that error.
//!
//! **Degrees of freedom.** Each variance is an estimate with its own degrees of freedom: `m - p`
//! for (S1), `nu_C` of (C4) for the sandwich (few where a few samples carry a parameter, e.g.
//! `sigma1` on a record that starts at full speed from `z = 0`, whose first sample alone is
//! `(sigma1 + sigma2) v`), `K - 1` for (S3). The interval of parameter `j` uses Student's t on
//! the Welch-Satterthwaite degrees of freedom of the sum `V = V_F + V_u`:
//!
//! ```text
//! nu_j = V^2 / (V_F^2 / nu_F + V_u^2 / (K - 1))        CI95_j = p_j -+ t_{0.975, nu_j} se_j   (S4)
//! ```
//!
//! (Satterthwaite 1946; with the sandwich this is the Bell-McCaffrey correction that Imbens and
//! Kolesar 2016 recommend with HC2 residuals, C3).
//!
//! A parameter is reported as not identifiable (an error, not a number) when
//! * its column of `J` is zero relative to the force: it has no effect on the output
//!   (`|p_j J_j| <= 1e-12 |F|`), e.g. `vs` when `Fs = Fc`;
//! * `cond(R) > 1e10`: some combination of parameters leaves the output unchanged to within
//!   `1e-5` of its effect, so `(J^T J)^-1` keeps too few digits to mean anything; the parameters
//!   with a weight of at least 0.2 in that combination (the eigenvector of the smallest
//!   eigenvalue) are named;
//! * its 95 % interval reaches 0: `t se_j >= |p_j|`, with `t = t_{0.975, m-p}` and `se_j` from
//!   the model-based covariance (S1) + (S3), the information in the data at the estimated noise.
//!   The data then cannot tell the parameter from 0 nor from twice its value: e.g. `sigma1`
//!   from quasi-static data, whose effect `sigma1 z'` is far below the noise. (The sandwich
//!   measures how far the residuals are from the model's noise, not what the data determine:
//!   where it widens an interval to 0, the interval is reported, clipped at the bound.)
//!
//! A parameter at one of its bounds (see [`super::FitReport`]; e.g. `sigma2 = 0` on data without
//! viscous friction) is exempt from the first and third tests: its effect vanishes with its
//! value, and its interval reaches the bound. Its standard error is that of (S1), the
//! curvature of the sum of squares at the bound.
//!
//! Parameters without effect, and collinear ones, are set aside (as if fixed) and the rest is
//! analysed again, so that one error names every parameter the data do not determine.

use super::covariance::{self, Covariance};
use crate::error::{FitError, Unidentified, Why};
use nalgebra::{DMatrix, SymmetricEigen};

/// A column this small relative to the data (`|p_j J_j| / |F|`) is no effect at all.
pub(crate) const NO_EFFECT: f64 = 1e-12;

/// Largest condition number of the scaled normal matrix accepted.
pub(crate) const CONDITION_LIMIT: f64 = 1e10;

/// Weight in the near-null combination above which a parameter is named as collinear.
const COLLINEAR_WEIGHT: f64 = 0.2;

/// The uncertainty of the estimates.
#[derive(Debug, Clone)]
pub(crate) struct Uncertainty {
    pub stderr: Vec<f64>,
    /// `t_{0.975, m-p}` (S2).
    pub t: f64,
    /// Each estimate's degrees of freedom (S4) and its interval's factor `t_{0.975, nu}`.
    pub estimate_dof: Vec<f64>,
    pub estimate_t: Vec<f64>,
    /// Correlation matrix of the estimates.
    pub correlation: Vec<Vec<f64>>,
    /// Condition number of the scaled normal matrix `R`.
    pub condition: f64,
    /// Which covariance the standard errors come from.
    pub method: Covariance,
}

/// (S1)-(S2) and the identifiability check. `jac` is `m x p` (column-major, one column per free
/// parameter, in `names` order), `values` the estimates, `data_norm` `|F|`. Every parameter
/// that fails a test is named in one error: those without effect first (the rest is then
/// analysed without them), then collinear ones, else those whose interval reaches 0.
pub(crate) fn uncertainty(
    jac: &DMatrix<f64>,
    names: &[&'static str],
    values: &[f64],
    at_bound: &[bool],
    residuals: &[f64],
    data_norm: f64,
    input_effects: &[Vec<f64>],
) -> Result<Uncertainty, FitError> {
    let rss: f64 = residuals.iter().map(|r| r * r).sum();
    let (m, p) = jac.shape();
    let dof = (m - p) as f64;
    let normal = jac.tr_mul(jac);
    let scale: Vec<f64> = (0..p).map(|j| normal[(j, j)].sqrt()).collect();
    let mut problems = Vec::new();
    let mut kept = Vec::new();
    for j in 0..p {
        let sensitivity = scale[j] * values[j].abs() / data_norm;
        // At its bound 0 a parameter's effect `p J_p` vanishes with `p`, not with `J_p`: it is
        // reported at its bound, not as without effect.
        if sensitivity > NO_EFFECT || (at_bound[j] && scale[j] > 0.0) {
            kept.push(j);
        } else {
            problems.push(Unidentified {
                name: names[j],
                value: values[j],
                why: Why::NoEffect { sensitivity },
            });
        }
    }
    // Collinear parameters are named and set aside until the rest is well-conditioned.
    let (eig, condition) = loop {
        let q = kept.len();
        if q == 0 {
            return Err(FitError::Unidentifiable {
                parameters: problems,
            });
        }
        let r = DMatrix::from_fn(q, q, |a, b| {
            let (i, j) = (kept[a], kept[b]);
            normal[(i, j)] / (scale[i] * scale[j])
        });
        let eig = SymmetricEigen::new(r);
        let (mut lo, mut hi) = (0, 0);
        for k in 0..q {
            if eig.eigenvalues[k] < eig.eigenvalues[lo] {
                lo = k;
            }
            if eig.eigenvalues[k] > eig.eigenvalues[hi] {
                hi = k;
            }
        }
        let condition = if eig.eigenvalues[lo] > 0.0 {
            eig.eigenvalues[hi] / eig.eigenvalues[lo]
        } else {
            f64::INFINITY
        };
        if condition <= CONDITION_LIMIT {
            break (eig, condition);
        }
        // A unit vector has a component of at least 1/sqrt(q) >= 0.378 > COLLINEAR_WEIGHT
        // (q <= 7): every pass sets at least one parameter aside.
        let v = eig.eigenvectors.column(lo);
        let weights: Vec<f64> = v.iter().map(|w| w.abs()).collect();
        for a in (0..q).filter(|&a| weights[a] >= COLLINEAR_WEIGHT) {
            problems.push(Unidentified {
                name: names[kept[a]],
                value: values[kept[a]],
                why: Why::Collinear {
                    condition,
                    limit: CONDITION_LIMIT,
                },
            });
        }
        let mut a = 0;
        kept.retain(|_| {
            a += 1;
            weights[a - 1] < COLLINEAR_WEIGHT
        });
    };
    let q = kept.len();
    // R^-1 = V diag(1/lambda) V^T; (J^T J)^-1 = D^-1 R^-1 D^-1.
    let inv_r = DMatrix::from_fn(q, q, |a, b| {
        (0..q)
            .map(|k| eig.eigenvectors[(a, k)] * eig.eigenvectors[(b, k)] / eig.eigenvalues[k])
            .sum::<f64>()
    });
    let s2 = rss / dof;
    let t = t_quantile_975(dof);
    // (S1), or (C2) where the residuals are correlated: the covariance of the scaled
    // parameters, and the degrees of freedom of each variance.
    let (cov, method, force_dof) =
        match covariance::newey_west(jac, &kept, &scale, &inv_r, residuals, data_norm) {
            Some((cov, lags, dof)) => (cov, Covariance::NeweyWest { lags }, dof),
            None => (inv_r.clone() * s2, Covariance::Classical, vec![dof; q]),
        };
    let input = input_covariance(jac, &kept, &scale, &inv_r, input_effects);
    // (S4): each variance's degrees of freedom, and its interval's t factor.
    let input_dof = input_effects.len().saturating_sub(1) as f64;
    let estimate_dof: Vec<f64> = (0..q)
        .map(|a| satterthwaite(cov[(a, a)], force_dof[a], input[(a, a)], input_dof))
        .collect();
    let estimate_t: Vec<f64> = estimate_dof.iter().map(|&d| t_quantile_975(d)).collect();
    // The identifiability test reads the information in the data, the model-based covariance
    // (S1) + (S3) with t_{m-p}; the residual-based sandwich (C2), with its few degrees of
    // freedom where a few samples carry a parameter, widens the reported interval only.
    let model_stderr: Vec<f64> = (0..q)
        .map(|a| (s2 * inv_r[(a, a)] + input[(a, a)]).sqrt() / scale[kept[a]])
        .collect();
    let cov = cov + input;
    let stderr: Vec<f64> = (0..q)
        .map(|a| cov[(a, a)].sqrt() / scale[kept[a]])
        .collect();
    for a in 0..q {
        let j = kept[a];
        let relative_half_width = t * model_stderr[a] / values[j].abs();
        // NaN (a zero estimate) counts as unidentifiable too; an estimate at its bound has an
        // interval that reaches the bound.
        if !at_bound[j] && (relative_half_width.is_nan() || relative_half_width >= 1.0) {
            problems.push(Unidentified {
                name: names[j],
                value: values[j],
                why: Why::WideInterval {
                    stderr: model_stderr[a],
                    relative_half_width,
                },
            });
        }
    }
    if !problems.is_empty() {
        // In the family's order.
        problems.sort_by_key(|u| names.iter().position(|n| *n == u.name));
        return Err(FitError::Unidentifiable {
            parameters: problems,
        });
    }
    let correlation = (0..q)
        .map(|a| {
            (0..q)
                .map(|b| cov[(a, b)] / (cov[(a, a)] * cov[(b, b)]).sqrt())
                .collect()
        })
        .collect();
    Ok(Uncertainty {
        stderr,
        t,
        estimate_dof,
        estimate_t,
        correlation,
        condition,
        method,
    })
}

/// (S3) in the scaled variables: the covariance of the estimates that the input's own error
/// causes, from the model's responses `dy_k` to draws of it (none: 0).
fn input_covariance(
    jac: &DMatrix<f64>,
    kept: &[usize],
    scale: &[f64],
    inv_r: &DMatrix<f64>,
    input_effects: &[Vec<f64>],
) -> DMatrix<f64> {
    let q = kept.len();
    let mut cov = DMatrix::zeros(q, q);
    let mut mean = nalgebra::DVector::zeros(q);
    let ds: Vec<nalgebra::DVector<f64>> = input_effects
        .iter()
        .map(|dy| {
            let g = nalgebra::DVector::from_iterator(
                q,
                kept.iter().map(|&j| {
                    jac.column(j)
                        .iter()
                        .zip(dy)
                        .map(|(a, b)| a * b)
                        .sum::<f64>()
                        / scale[j]
                }),
            );
            inv_r * g
        })
        .collect();
    if ds.len() < 2 {
        return cov;
    }
    let k = ds.len() as f64;
    for d in &ds {
        mean += d / k;
    }
    for d in &ds {
        let c = d - &mean;
        cov += &c * c.transpose() / (k - 1.0);
    }
    cov
}

/// (S4): the degrees of freedom of the variance `force + input`, the first estimated with
/// `force_dof` degrees of freedom, the second with `input_dof` (Welch-Satterthwaite); `force_dof`
/// alone without an input share.
fn satterthwaite(force: f64, force_dof: f64, input: f64, input_dof: f64) -> f64 {
    if !(input > 0.0 && input_dof > 0.0) {
        return force_dof;
    }
    let total = force + input;
    total * total / (force * force / force_dof + input * input / input_dof)
}

/// The 97.5 % quantile of Student's t distribution with `dof >= 1` degrees of freedom (the
/// half-width factor of a two-sided 95 % interval): exact for 1 and 2 degrees of freedom,
/// between them interpolated (within 3 %, never below), else Hill's approximation (G. W. Hill, "Algorithm 396: Student's t-quantiles", CACM 13, 1970),
/// within 2e-6 relative for every `dof` (checked against mpmath below); 1.96 (the normal
/// quantile) in the limit.
pub(crate) fn t_quantile_975(dof: f64) -> f64 {
    // Two-sided tail probability.
    const P: f64 = 0.05;
    // The standard normal's 2.5 % quantile (lower tail), mpmath.
    const Z: f64 = -1.959_963_984_540_054_2;
    if dof.is_nan() || dof < 1.0 {
        return f64::NAN;
    }
    if dof.is_infinite() {
        return -Z;
    }
    if dof == 1.0 {
        // Cauchy: cot(pi P / 2).
        return 1.0 / (std::f64::consts::FRAC_PI_2 * P).tan();
    }
    if dof <= 2.0 {
        let t1 = 1.0 / (std::f64::consts::FRAC_PI_2 * P).tan();
        let t2 = (2.0 / (P * (2.0 - P)) - 2.0).sqrt();
        // Between 1 and 2 (an effective dof, S4): log t linear in 1 / dof between the exact
        // ends, high by at most 3 % (Hill's formula is not meant for dof < 2).
        let x = (1.0 / dof - 1.0) / (0.5 - 1.0);
        return (t1.ln() + x * (t2.ln() - t1.ln())).exp();
    }
    let n = dof;
    let a = 1.0 / (n - 0.5);
    let b = 48.0 / (a * a);
    let mut c = ((20700.0 * a / b - 98.0) * a - 16.0) * a + 96.36;
    let d = ((94.5 / (b + c) - 3.0) / b + 1.0) * (a * std::f64::consts::FRAC_PI_2).sqrt() * n;
    let y = (d * P).powf(2.0 / n);
    let y = if y > 0.05 + a {
        // Asymptotic inverse expansion about the normal quantile.
        let x = Z;
        let yy = x * x;
        if n < 5.0 {
            c += 0.3 * (n - 4.5) * (x + 0.6);
        }
        c += (((0.05 * d * x - 5.0) * x - 7.0) * x - 2.0) * x + b;
        let w = (((((0.4 * yy + 6.3) * yy + 36.0) * yy + 94.5) / c - yy - 3.0) / b + 1.0) * x;
        (a * w * w).exp_m1()
    } else {
        ((1.0 / (((n + 6.0) / (n * y) - 0.089 * d - 0.822) * (n + 2.0) * 3.0) + 0.5 / (n + 4.0))
            * y
            - 1.0)
            * (n + 1.0)
            / (n + 2.0)
            + 1.0 / y
    };
    (n * y).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn t_quantiles_against_mpmath() {
        // mpmath: the root of 0.5 I_{nu/(nu+t^2)}(nu/2, 1/2) = 0.025, 20 digits.
        let reference = [
            (1.0, 12.706204736174704646),
            (2.0, 4.3026527297494638523),
            (3.0, 3.1824463052837095927),
            (4.0, 2.7764451051977943578),
            (5.0, 2.5705818356363155147),
            (7.0, 2.3646242515927853417),
            (10.0, 2.2281388519862747484),
            (30.0, 2.04227245630123831),
            (100.0, 1.9839715185235522866),
            (1000.0, 1.962339080826408485),
            (100000.0, 1.9599877075346096386),
        ];
        for (dof, want) in reference {
            let got = t_quantile_975(dof);
            assert!(
                ((got - want) / want).abs() < 2e-6,
                "dof {dof}: {got} vs {want}"
            );
        }
        // Fractional degrees of freedom (S4): scipy.stats.t.ppf(0.975, dof). Below 2, Hill's
        // approximation is high by up to 3 % (a wider interval).
        for (dof, want, tol) in [
            (1.01, 12.412738499102536, 0.03),
            (1.05, 11.361907668693245, 0.03),
            (1.1, 10.2768012862812, 0.03),
            (1.2, 8.648826510748867, 0.03),
            (1.3, 7.500529325562029, 0.03),
            (1.5, 6.016663104427929, 0.03),
            (1.7, 5.1188389882530565, 0.03),
            (1.9, 4.527118077100328, 0.03),
            (1.99, 4.323438865678835, 0.03),
            (2.5, 3.5746548420036817, 2e-5),
            (3.7, 2.8675207071911895, 2e-5),
            (12.4, 2.171043117662886, 2e-5),
            (150.5, 1.9758519492008906, 2e-5),
        ] {
            let got = t_quantile_975(dof);
            assert!(
                got >= want * (1.0 - 2e-6) && (got - want) / want < tol,
                "dof {dof}: {got} vs {want}"
            );
        }
        assert_eq!(t_quantile_975(f64::INFINITY), 1.959_963_984_540_054_2);
        assert!(t_quantile_975(0.5).is_nan());
    }

    /// Ten residuals with RSS = 8 and no serial correlation to speak of.
    const WHITE_8: [f64; 10] = {
        let a = 0.894_427_190_999_916; // sqrt(0.8)
        [a, -a, -a, a, a, -a, a, -a, -a, a]
    };

    #[test]
    fn straight_line_statistics() {
        // y = p0 + p1 x: the textbook covariance s^2 (X^T X)^-1.
        let x: Vec<f64> = (0..10).map(f64::from).collect();
        let jac = DMatrix::from_fn(10, 2, |i, j| if j == 0 { 1.0 } else { x[i] });
        let u = uncertainty(
            &jac,
            &["p0", "p1"],
            &[10.0, 2.0],
            &[false; 2],
            &WHITE_8,
            100.0,
            &[],
        )
        .unwrap();
        let s2: f64 = 8.0 / 8.0;
        // (X^T X)^-1 for x = 0..9: [[sum x^2, -sum x], [-sum x, n]] / (n sum x^2 - (sum x)^2).
        let det: f64 = 10.0 * 285.0 - 45.0 * 45.0;
        assert!((u.stderr[0] - (s2 * 285.0 / det).sqrt()).abs() < 1e-14);
        assert!((u.stderr[1] - (s2 * 10.0 / det).sqrt()).abs() < 1e-14);
        let corr = -45.0 / (285.0f64 * 10.0).sqrt();
        assert!((u.correlation[0][1] - corr).abs() < 1e-14);
    }

    #[test]
    fn unidentifiable_columns_are_named() {
        let jac = DMatrix::from_fn(10, 2, |i, j| if j == 0 { 1.0 + i as f64 } else { 0.0 });
        let why = |e: FitError| match e {
            FitError::Unidentifiable { parameters } => parameters
                .into_iter()
                .map(|u| (u.name, std::mem::discriminant(&u.why)))
                .collect::<Vec<_>>(),
            other => panic!("{other}"),
        };
        let no_effect = std::mem::discriminant(&Why::NoEffect { sensitivity: 0.0 });
        let collinear = std::mem::discriminant(&Why::Collinear {
            condition: 0.0,
            limit: 0.0,
        });
        let wide = std::mem::discriminant(&Why::WideInterval {
            stderr: 0.0,
            relative_half_width: 0.0,
        });
        let refused = |jac: &DMatrix<f64>, values: [f64; 2]| {
            uncertainty(jac, &["a", "b"], &values, &[false; 2], &[1.0; 10], 1.0, &[]).unwrap_err()
        };
        let e = refused(&jac, [1.0, 1.0]);
        assert!(e.to_string().starts_with("b cannot be identified"), "{e}");
        assert_eq!(why(e), vec![("b", no_effect)]);
        let jac = DMatrix::from_fn(10, 2, |i, _| 1.0 + i as f64);
        let e = refused(&jac, [1.0, 1.0]);
        assert!(
            e.to_string().starts_with("a, b cannot be identified"),
            "{e}"
        );
        assert_eq!(why(e.clone()), vec![("a", collinear), ("b", collinear)]);
        // Equal columns: the scaled normal matrix is exactly singular, its condition number
        // infinite; the message says so in words.
        match &e {
            FitError::Unidentifiable { parameters } => assert!(
                matches!(parameters[0].why, Why::Collinear { condition, .. } if condition == f64::INFINITY),
                "{e}"
            ),
            other => panic!("{other}"),
        }
        let text = e.to_string();
        assert!(text.contains("(the problem is singular)"), "{text}");
        assert!(!text.contains("inf"), "{text}");
        // A parameter driven to 0, and another that noise swamps: both named.
        let jac = DMatrix::from_fn(10, 2, |i, j| if j == 0 { 1e-3 } else { i as f64 });
        let e = refused(&jac, [1.0, 0.0]);
        assert_eq!(why(e), vec![("a", wide), ("b", no_effect)]);
    }
}
