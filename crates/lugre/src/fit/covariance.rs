//! Covariance that holds when the residuals are correlated, and the lack-of-fit checks.
//!
//! The linearised covariance (S1) assumes independent residuals of equal variance. A record
//! whose displacement was smoothed ([`super::noise`]), or a model that does not follow the data
//! to their noise, leaves residuals correlated from sample to sample, and (S1) then understates
//! the uncertainty. A Ljung-Box test on the residuals `r_i` chooses:
//!
//! ```text
//! rho_l = sum_i r_i r_{i+l} / sum_i r_i^2
//! Q     = m (m + 2) sum_{l=1..K} rho_l^2 / (m - l)           K = min(10, m / 5)           (C1)
//! ```
//!
//! `Q` is `chi^2_K` for independent residuals; above its 95 % point (Wilson-Hilferty:
//! `K (1 - 2/(9K) + 1.6449 sqrt(2/(9K)))^3`, within 1 % for `K >= 2`) the covariance is the
//! sandwich with the Newey-West (Bartlett-kernel) estimate of the scores' long-run covariance,
//! `s_i = J_i r~_i` (`J_i` the row of the Jacobian):
//!
//! ```text
//! M   = sum_i s_i s_i^T + sum_{l=1..L} (1 - l/(L+1)) sum_i (s_i s_{i+l}^T + s_{i+l} s_i^T)
//! Cov = (J^T J)^-1 M (J^T J)^-1                                                           (C2)
//! ```
//!
//! with Andrews' (1991) plug-in bandwidth for an AR(1) fitted to the residuals:
//! `L = floor(1.1447 (alpha m)^(1/3))`, `alpha = 4 rho_1^2 / (1 - rho_1^2)^2` (`rho_1` capped
//! at 0.97), at least 1 and at most `m / 4`. Otherwise (S1) stands.
//!
//! **Leverage.** A residual is shorter than its error where the sample pulls the fit towards
//! itself: `E r_i^2 = s^2 (1 - h_i)` for independent errors, with the leverage
//! `h_i = J_i (J^T J)^-1 J_i^T`. The servo-axis record, which starts at full speed from
//! `z = 0`, has `h_0 = 0.4` to `0.8`: its first sample nearly alone sets `sigma1`, and the
//! sandwich with the raw residuals (and the factor `m / (m - p)` used before) gave `sigma1`
//! standard errors from a quarter to 1.3 times the right one. The residuals are therefore
//! scaled as in MacKinnon and White's HC2 (unbiased for independent errors of equal variance):
//!
//! ```text
//! r~_i = r_i / sqrt(1 - min(h_i, 0.99))                                                    (C3)
//! ```
//!
//! **Degrees of freedom.** Even unbiased, a variance that a few residuals estimate is itself
//! uncertain. With `c_i = (J^T J)^-1 J_i^T` the weights of the estimates on the samples,
//! `V_j = sum_i sum_k w_{i-k} c_ij c_kj r~_i r~_k` is a quadratic form in the errors; for
//! independent errors of equal variance its mean and variance give (Satterthwaite) the
//! effective degrees of freedom
//!
//! ```text
//! nu_j = (sum_i c_ij^2)^2 / sum_i sum_{|l|<=L} w_l^2 c_ij^2 c_{i+l,j}^2     (w_0 = 1)      (C4)
//! ```
//!
//! between 1 (one sample carries the parameter) and `m / (1 + 2 sum_l w_l^2)` (all samples
//! alike); the interval uses them (S4 in `fit/stats.rs`).
//!
//! **Lack of fit.** Where the force noise `s_F` was estimated ([`super::noise`], eq. N1), a
//! residual RMS above `1.3 s_F` says the model does not fit the data to their noise; a lag-1
//! autocorrelation above 0.5 says the residuals are structured. Either is reported in words
//! ([`FitWarning`]): the intervals then count a systematic misfit as if it were noise. Residuals
//! below `1e-10` of the force (an exact fit of noise-free data, to rounding) are neither tested
//! nor warned about: rounding is correlated, but it is no misfit.

use nalgebra::DMatrix;

/// Lags of the Ljung-Box statistic (C1), at most.
const LJUNG_BOX_LAGS: usize = 10;

/// The largest leverage used in (C3): a sample that alone determines a parameter (`h_i = 1`)
/// has a residual of 0 whatever its noise, and no correction recovers it.
const MAX_LEVERAGE: f64 = 0.99;

/// The largest lag-1 autocorrelation used in the bandwidth rule.
const RHO_CAP: f64 = 0.97;

/// A residual RMS above this many force-noise standard deviations is a misfit.
pub const MISFIT_RATIO: f64 = 1.3;

/// A lag-1 autocorrelation of the residuals above this is structure, not noise.
pub const STRUCTURED_RHO: f64 = 0.5;

/// Residuals below this fraction of the force (RMS, relative) are the rounding of an exact
/// fit (noise-free data): correlated, as rounding is, but no sign of a misfit.
pub const EXACT_FIT: f64 = 1e-10;

/// Which covariance the standard errors come from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Covariance {
    /// (S1): the residuals look independent.
    Classical,
    /// (C2) with `lags` Bartlett lags: the residuals are correlated.
    NeweyWest { lags: usize },
}

impl Covariance {
    /// A short key for machine-readable reports.
    pub fn key(&self) -> &'static str {
        match self {
            Covariance::Classical => "classical",
            Covariance::NeweyWest { .. } => "newey-west",
        }
    }

    /// In words, for reports.
    pub fn describe(&self) -> String {
        match self {
            Covariance::Classical => {
                "s^2 (J^T J)^-1 (the residuals pass the Ljung-Box test for independence)".into()
            }
            Covariance::NeweyWest { lags } => format!(
                "the Newey-West sandwich with {lags} lags (the residuals are correlated: \
                 Ljung-Box test)"
            ),
        }
    }
}

/// The residuals' serial correlation: lag-1 autocorrelation, Ljung-Box `Q` (C1) and its 95 %
/// point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SerialCorrelation {
    pub lag1: f64,
    pub ljung_box: f64,
    pub critical: f64,
    pub lags: usize,
}

impl SerialCorrelation {
    /// (C1) on the residuals `r` (at least 10 of them).
    pub fn of(r: &[f64]) -> Self {
        let m = r.len();
        let lags = LJUNG_BOX_LAGS.min(m / 5).max(1);
        let q: f64 = (1..=lags)
            .map(|l| autocorrelation(r, l).powi(2) / (m - l) as f64)
            .sum::<f64>()
            * (m * (m + 2)) as f64;
        Self {
            lag1: autocorrelation(r, 1),
            ljung_box: q,
            critical: chi2_95(lags as f64),
            lags,
        }
    }

    /// Whether the residuals are correlated (the test rejects independence at 5 %).
    pub fn correlated(&self) -> bool {
        self.ljung_box > self.critical
    }

    /// Andrews' AR(1) plug-in bandwidth for the Bartlett kernel.
    fn bandwidth(&self, m: usize) -> usize {
        let rho = self.lag1.clamp(-RHO_CAP, RHO_CAP);
        let alpha = 4.0 * rho * rho / (1.0 - rho * rho).powi(2);
        let l = (1.1447 * (alpha * m as f64).cbrt()).floor() as usize;
        l.clamp(1, (m / 4).max(1))
    }
}

/// `rho_l` of (C1); 0 for residuals that are all 0.
fn autocorrelation(r: &[f64], lag: usize) -> f64 {
    let c0: f64 = r.iter().map(|x| x * x).sum();
    if c0 == 0.0 || lag >= r.len() {
        return 0.0;
    }
    r.iter().zip(&r[lag..]).map(|(a, b)| a * b).sum::<f64>() / c0
}

/// The 95 % point of `chi^2_k` (Wilson-Hilferty).
fn chi2_95(k: f64) -> f64 {
    const Z95: f64 = 1.644_853_626_951_472_2;
    let c = 2.0 / (9.0 * k);
    k * (1.0 - c + Z95 * c.sqrt()).powi(3)
}

/// (C2)-(C3) in the scaled variables of `stats` (columns of `J` divided by `scale`, `inv_r`
/// the inverse of the scaled normal matrix, both for the `kept` columns): the covariance of the
/// scaled parameters, the lags used and each parameter's effective degrees of freedom (C4);
/// `None` when the residuals look independent.
pub(crate) fn newey_west(
    jac: &DMatrix<f64>,
    kept: &[usize],
    scale: &[f64],
    inv_r: &DMatrix<f64>,
    r: &[f64],
    data_norm: f64,
) -> Option<(DMatrix<f64>, usize, Vec<f64>)> {
    let m = r.len();
    let serial = SerialCorrelation::of(r);
    let rss: f64 = r.iter().map(|x| x * x).sum();
    if !serial.correlated() || rss.sqrt() <= EXACT_FIT * data_norm {
        return None;
    }
    let lags = serial.bandwidth(m);
    let q = kept.len();
    // Per row: the weights c_i = (J^T J)^-1 J_i^T of the estimates on the sample, and the
    // scores with the residual divided by sqrt(1 - h_i), h_i = J_i c_i (C3).
    let mut c = vec![0.0; m * q];
    let mut s = vec![0.0; m * q];
    for i in 0..m {
        let row = nalgebra::DVector::from_iterator(q, kept.iter().map(|&j| jac[(i, j)] / scale[j]));
        let weights = inv_r * &row;
        let leverage = row.dot(&weights);
        let ri = r[i] / (1.0 - leverage.min(MAX_LEVERAGE)).sqrt();
        for a in 0..q {
            c[i * q + a] = weights[a];
            s[i * q + a] = row[a] * ri;
        }
    }
    let bartlett = |l: usize| 1.0 - l as f64 / (lags + 1) as f64;
    let mut meat = DMatrix::zeros(q, q);
    for l in 0..=lags {
        let w = bartlett(l);
        for i in 0..m - l {
            let (a, b) = (&s[i * q..(i + 1) * q], &s[(i + l) * q..(i + l + 1) * q]);
            for x in 0..q {
                for y in 0..q {
                    let v = a[x] * b[y];
                    meat[(x, y)] += if l == 0 { v } else { w * (v + a[y] * b[x]) };
                }
            }
        }
    }
    let cov = inv_r * meat * inv_r;
    // (C4): (sum_i c_i^2)^2 / sum_i sum_|l|<=L w_l^2 c_i^2 c_{i+l}^2, per parameter.
    let dof = (0..q)
        .map(|a| {
            let c2 = |i: usize| c[i * q + a] * c[i * q + a];
            let total: f64 = (0..m).map(c2).sum();
            let spread: f64 = (0..=lags)
                .map(|l| {
                    let w = bartlett(l);
                    let pairs: f64 = (0..m - l).map(|i| c2(i) * c2(i + l)).sum();
                    if l == 0 {
                        pairs
                    } else {
                        2.0 * w * w * pairs
                    }
                })
                .sum();
            if spread > 0.0 {
                total * total / spread
            } else {
                (m - q) as f64
            }
        })
        .collect();
    Some((cov, lags, dof))
}

/// Why the estimates or their intervals may not be trusted.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum FitWarning {
    /// The estimate sits at `bound`, one of its bounds.
    AtBound { name: &'static str, bound: f64 },
    /// The residual RMS is `ratio` times the force noise estimated in the record.
    Misfit {
        rms: f64,
        force_noise: f64,
        ratio: f64,
        /// A slow fit (whose model ignores the rate).
        slow: bool,
    },
    /// The residuals are structured (lag-1 autocorrelation above 0.5).
    Structured { lag1: f64, slow: bool },
    /// The iteration ended at a sum of squares `rss`, and a point beside its end has the
    /// lower `lower`: not a minimum (a sum of squares that steps, docs/mathematics.md (ZF6)).
    NotMinimum { rss: f64, lower: f64 },
}

impl std::fmt::Display for FitWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let slow_hint = |slow: bool| {
            if slow {
                "; if the test was not quasi-static (the force depends on the speed: damping, \
                 the Stribeck effect), use the full fit on t,u,F data"
            } else {
                ""
            }
        };
        match *self {
            FitWarning::AtBound { name, bound } => write!(
                f,
                "{name} is at its bound {} (the data push it there: its interval reaches the \
                 bound, and the other estimates are those with {name} held at it; {})",
                crate::error::num(bound),
                if bound == 0.0 {
                    "fix it at 0 if that is what it is"
                } else {
                    "widen its bounds if they were a guess"
                }
            ),
            FitWarning::Misfit {
                rms,
                force_noise,
                ratio,
                slow,
            } => write!(
                f,
                "the intervals cannot be trusted: the residual RMS {rms:.3e} is {ratio:.1} times \
                 the force noise {force_noise:.3e} estimated in the record, so the model does not \
                 follow the data to their noise and the intervals count a systematic misfit as \
                 noise (a wrong model, a parameter held at a wrong value){}",
                slow_hint(slow)
            ),
            FitWarning::Structured { lag1, slow } => write!(
                f,
                "the intervals cannot be trusted: the residuals are structured (lag-1 \
                 autocorrelation {lag1:.2}), not noise: the model misses part of the data{}",
                slow_hint(slow)
            ),
            FitWarning::NotMinimum { rss, lower } => write!(
                f,
                "the estimates and intervals cannot be trusted: the fit ended at a sum of \
                 squares {rss:.6e}, and a point beside its end has {lower:.6e}: not a minimum \
                 (the model's output jumps where a switch between sticking and slipping \
                 crosses a sample, and the iteration stopped at such a step); run more starts"
            ),
        }
    }
}

/// The lack-of-fit warnings (module docs) for residuals `r` with RMS `rms`, given the force
/// noise estimated in the record (if it was).
pub(crate) fn lack_of_fit(
    r: &[f64],
    rms: f64,
    f_rms: f64,
    force_noise: Option<f64>,
    slow: bool,
) -> Vec<FitWarning> {
    let mut out = Vec::new();
    if rms <= EXACT_FIT * f_rms {
        return out;
    }
    if let Some(s) = force_noise.filter(|s| *s > 0.0) {
        let ratio = rms / s;
        if ratio > MISFIT_RATIO {
            out.push(FitWarning::Misfit {
                rms,
                force_noise: s,
                ratio,
                slow,
            });
        }
    }
    let lag1 = autocorrelation(r, 1);
    if lag1 > STRUCTURED_RHO {
        out.push(FitWarning::Structured { lag1, slow });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chi2_points() {
        // scipy.stats.chi2.ppf(0.95, k): 10 -> 18.307038, 5 -> 11.070498, 2 -> 5.991465.
        for (k, want) in [(10.0, 18.307038), (5.0, 11.070498), (2.0, 5.991465)] {
            assert!(
                (chi2_95(k) / want - 1.0).abs() < 0.01,
                "{k}: {}",
                chi2_95(k)
            );
        }
    }

    #[test]
    fn white_and_correlated_residuals() {
        // Uniform deviates of an LCG (independent), then a smooth sequence.
        let mut state = 5u64;
        let white: Vec<f64> = (0..2000)
            .map(|_| {
                state = state
                    .wrapping_mul(6_364_136_223_846_793_005)
                    .wrapping_add(1_442_695_040_888_963_407);
                (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
            })
            .collect();
        let sc = SerialCorrelation::of(&white);
        assert!(!sc.correlated(), "{sc:?}");
        let smooth: Vec<f64> = (0..2000).map(|i| (i as f64 * 0.05).sin()).collect();
        let sc = SerialCorrelation::of(&smooth);
        assert!(sc.correlated() && sc.lag1 > 0.9, "{sc:?}");
        assert!(sc.bandwidth(2000) > 10);
        let w = lack_of_fit(&smooth, 0.7, 1.0, Some(0.1), true);
        assert_eq!(w.len(), 2);
        let text = w[0].to_string();
        assert!(text.contains("7.0 times the force noise"), "{text}");
        assert!(text.contains("use the full fit"), "{text}");
    }

    #[test]
    fn the_sandwich_of_white_residuals_is_the_classical_covariance() {
        // One column of ones: (J^T J)^-1 = 1/m; the scaled sandwich with white residuals of
        // variance 1 is about m / (m - 1) * sum r^2 / m.
        let m = 400;
        let r: Vec<f64> = (0..m)
            .map(|i| if i % 2 == 0 { 1.0 } else { -1.0 })
            .collect();
        let jac = DMatrix::from_element(m, 1, 1.0);
        let scale = [(m as f64).sqrt()];
        let inv_r = DMatrix::from_element(1, 1, 1.0);
        // Alternating residuals are correlated (rho_1 = -1): Newey-West with the capped rho.
        let (cov, lags, dof) = newey_west(&jac, &[0], &scale, &inv_r, &r, 1.0).unwrap();
        // Equal weights c_i = 1/m on every sample: (C4) is m^2 / (m + 2 sum_l w_l^2 (m - l)).
        let pairs: f64 = (1..=lags)
            .map(|l| (1.0 - l as f64 / (lags + 1) as f64).powi(2) * (m - l) as f64)
            .sum();
        let want = (m * m) as f64 / (m as f64 + 2.0 * pairs);
        assert!((dof[0] / want - 1.0).abs() < 1e-12, "{dof:?} vs {want}");
        assert!(lags >= 1);
        // Bartlett weights shrink the alternating sum towards 0, never below.
        assert!(cov[(0, 0)] >= 0.0 && cov[(0, 0)] < 1.0, "{cov}");
    }
}
