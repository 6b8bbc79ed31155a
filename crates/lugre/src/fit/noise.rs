//! Noise in the record: the levels of the position and force noise estimated from the samples
//! themselves, and the smoothing of a noisy displacement before the full fit.
//!
//! **Levels.** For white noise `e_i` of variance `s^2` the `k`-th difference
//! `D^k e_i = sum_j (-1)^j C(k, j) e_{i+k-j}` has variance `C(2k, k) s^2` (the sum of the
//! squared binomial coefficients). The `k`-th difference of a smooth signal sampled at step `h`
//! is `h^k x^(k)`, which at 1 kHz is far below any noise (a 5 mm, 0.5 Hz sine: `1.5e-4` um for
//! `k = 3`); a reversal of a triangle wave or a force jump makes a few large differences, which
//! the median ignores. So, with `k = 3`,
//!
//! ```text
//! s_hat = median_i |D^3 x_i| / (Phi^-1(3/4) sqrt(C(6, 3)))      Phi^-1(3/4) = 0.6744897...    (N1)
//! ```
//!
//! (the median of `|N(0, s^2)|` is `Phi^-1(3/4) s`), consistent for Gaussian noise. A reading
//! rounded to a step `q` (an encoder's resolution) adds the rounding error, uniform on
//! `(-q/2, q/2)`, of variance `q^2 / 12` where the noise spans several steps or the motion
//! sweeps across them (Sheppard): `s_hat` then estimates `sqrt(s^2 + q^2 / 12)`, which is the
//! error the fit meets, so no correction is made. A record with no noise at all, rounded to `q`
//! while it stands still, has `D^3 x = 0` there: `s_hat` is then below `q / sqrt(12)`.
//! Without noise (simulated data) `s_hat` is the rounding of the arithmetic.
//!
//! **Smoothing** (the full fit of a displacement record). At `sigma0 = 1e6` N/m half a
//! micrometre of position noise is half a newton of force, and the velocity `du / dt` of
//! consecutive samples carries `sqrt(2) s / h` of noise (0.7 mm/s at 1 kHz, a sixth of a
//! typical `vs`): the fit, which treats the input as exact, is biased (attenuation of `sigma1`,
//! a wrong Stribeck curve) and its intervals miss. The displacement is therefore read as the
//! smooth motion nearest the samples: the discrete smoothing spline (Whittaker-Henderson of
//! order 2) minimising
//!
//! ```text
//! sum_i (x_i - u_i)^2 + lambda sum_i (x_{i-1} - 2 x_i + x_{i+1})^2                         (N2)
//! ```
//!
//! a pentadiagonal system `(I + lambda D2^T D2) x = u` solved by banded `L D L^T` in `O(n)`;
//! `lambda` is set by the discrepancy principle, `sum (x_i - u_i)^2 = n s_hat^2` (bisection on
//! `log lambda`; the residual sum grows with `lambda`). Its response to a sine of `w` radians a
//! sample is `1 / (1 + lambda (2 sin(w / 2))^4)`: the motion (0.5 Hz at 1 kHz) passes
//! unchanged to `1e-4`, the noise is averaged over about `lambda^(1/4)` samples. Smooth
//! reversals (a sine) are kept; a kink (a triangle wave's reversal) is rounded over that many
//! samples, as far as the noise allows. Measured on the servo-axis record (200
//! records, BENCHMARKS.md) this removes the bias; an errors-in-variables weighting of the
//! residuals (variance `s_F^2 + (dF/du)^2 s_u^2`) was not used: it weighs the samples, but
//! the bias comes from the noise in the velocity, which no weighting removes.
//!
//! The samples must be equally spaced in time (within `1e-6` relative): the penalty (N2)
//! counts samples, not seconds. An unevenly sampled record is fitted as given, and the report
//! says so.

/// The order of the differences in (N1).
pub const DIFFERENCE_ORDER: usize = 3;

/// `Phi^-1(3/4)`, the median of `|N(0, 1)|` (mpmath `sqrt(2) erfinv(1/2)`).
const MAD_NORMAL: f64 = 0.674_489_750_196_081_7;

/// `C(2k, k)` for `k = DIFFERENCE_ORDER`.
const DIFFERENCE_VARIANCE: f64 = 20.0;

/// The relative spread of the time steps up to which a record counts as equally spaced.
pub const EVEN_SPACING: f64 = 1e-6;

/// The noise estimated in a record, and what the fit did with it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NoiseLevels {
    /// Standard deviation of the position noise (N1), in the units of `u`.
    pub position: f64,
    /// Standard deviation of the force noise (N1), in the units of `F`.
    pub force: f64,
    /// How the position noise was taken into account.
    pub handling: PositionHandling,
}

/// What the fit did with the position noise.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PositionHandling {
    /// The displacement was smoothed (N2) with this `lambda` before the fit.
    Smoothed { lambda: f64 },
    /// Not smoothed: none asked for, or none needed (no noise found).
    AsGiven,
    /// Not smoothed because the samples are not equally spaced in time.
    Uneven,
    /// The slow fit: the noise sets the gate on its reversals, in the units of `u`.
    Gate { gate: f64 },
}

impl PositionHandling {
    /// In words, for reports.
    pub fn describe(&self) -> String {
        match *self {
            PositionHandling::Smoothed { lambda } => format!(
                "the displacement was read as the smooth motion nearest the samples (smoothing \
                 spline, lambda {lambda:.3e}, residual equal to the position noise)"
            ),
            PositionHandling::AsGiven => "the displacement was used as given".to_string(),
            PositionHandling::Uneven => "the displacement was used as given (the samples are \
                 not equally spaced in time, which the smoothing needs)"
                .to_string(),
            PositionHandling::Gate { gate } => {
                format!("reversals smaller than the gate {gate:.3e} (in units of u) were ignored")
            }
        }
    }

    /// A short key for machine-readable reports.
    pub fn key(&self) -> &'static str {
        match self {
            PositionHandling::Smoothed { .. } => "smoothed",
            PositionHandling::AsGiven => "as_given",
            PositionHandling::Uneven => "uneven",
            PositionHandling::Gate { .. } => "gate",
        }
    }
}

/// (N1): the standard deviation of white noise on the samples `x` (NaN entries skipped:
/// differences across them are not formed). 0 for fewer than `DIFFERENCE_ORDER + 1` samples.
pub fn noise_level(x: &[f64]) -> f64 {
    difference_noise(x, DIFFERENCE_ORDER)
}

/// (N1) with differences of order `k` (1 to 3): `median |D^k x| / (Phi^-1(3/4) sqrt(C(2k, k)))`.
/// The second differences serve where the signal's own third differences are not small (a
/// velocity computed from the samples, a force that reverses: [`super::plateaus`],
/// [`super::presliding`]).
pub(crate) fn difference_noise(x: &[f64], k: usize) -> f64 {
    // Binomial coefficients of D^k and C(2k, k), the variance of D^k of unit white noise.
    let (coefficients, variance): (&[f64], f64) = match k {
        1 => (&[-1.0, 1.0], 2.0),
        2 => (&[1.0, -2.0, 1.0], 6.0),
        _ => (&[-1.0, 3.0, -3.0, 1.0], DIFFERENCE_VARIANCE),
    };
    let mut d: Vec<f64> = x
        .windows(coefficients.len())
        .map(|w| {
            w.iter()
                .zip(coefficients)
                .map(|(x, c)| c * x)
                .sum::<f64>()
                .abs()
        })
        .filter(|d| !d.is_nan())
        .collect();
    match super::slow::median(&mut d) {
        Some(m) => m / (MAD_NORMAL * variance.sqrt()),
        None => 0.0,
    }
}

/// Whether the times are equally spaced (within [`EVEN_SPACING`] relative).
pub fn evenly_spaced(t: &[f64]) -> bool {
    if t.len() < 3 {
        return true;
    }
    let h = (t[t.len() - 1] - t[0]) / (t.len() - 1) as f64;
    t.windows(2)
        .all(|w| ((w[1] - w[0]) - h).abs() <= EVEN_SPACING * h.abs())
}

/// (N2) at a given `lambda`, written into `x`; `work` holds the factorisation (5 n values).
fn smooth_with(u: &[f64], lambda: f64, x: &mut [f64], work: &mut Vec<f64>) {
    let n = u.len();
    // The bands of A = I + lambda D2^T D2: diagonal a, first and second off-diagonals b, c.
    let diag = |i: usize| -> f64 {
        let core = if i == 0 || i == n - 1 {
            1.0
        } else if i == 1 || i == n - 2 {
            5.0
        } else {
            6.0
        };
        1.0 + lambda * core
    };
    let off1 = |i: usize| -> f64 {
        // A[i, i+1].
        if i == 0 || i + 2 == n {
            -2.0 * lambda
        } else {
            -4.0 * lambda
        }
    };
    let off2 = lambda;
    // L D L^T with unit lower-triangular L of bandwidth 2: l1[i] = L[i, i-1], l2[i] = L[i, i-2].
    work.clear();
    work.resize(3 * n, 0.0);
    let (d, rest) = work.split_at_mut(n);
    let (l1, l2) = rest.split_at_mut(n);
    for i in 0..n {
        if i >= 2 {
            l2[i] = off2 / d[i - 2];
        }
        if i >= 1 {
            let mut v = off1(i - 1);
            if i >= 2 {
                v -= l2[i] * d[i - 2] * l1[i - 1];
            }
            l1[i] = v / d[i - 1];
        }
        let mut di = diag(i);
        if i >= 1 {
            di -= l1[i] * l1[i] * d[i - 1];
        }
        if i >= 2 {
            di -= l2[i] * l2[i] * d[i - 2];
        }
        d[i] = di;
    }
    // Forward (L y = u), diagonal, backward (L^T x = y / d).
    for i in 0..n {
        let mut v = u[i];
        if i >= 1 {
            v -= l1[i] * x[i - 1];
        }
        if i >= 2 {
            v -= l2[i] * x[i - 2];
        }
        x[i] = v;
    }
    for i in 0..n {
        x[i] /= d[i];
    }
    for i in (0..n).rev() {
        let mut v = x[i];
        if i + 1 < n {
            v -= l1[i + 1] * x[i + 1];
        }
        if i + 2 < n {
            v -= l2[i + 2] * x[i + 2];
        }
        x[i] = v;
    }
}

/// The range of `log10 lambda` searched.
const LOG_LAMBDA: (f64, f64) = (-3.0, 12.0);

/// (N2) with `lambda` set by the discrepancy principle for noise `sigma`: the smoothed samples
/// and `lambda`. `None` when there is nothing to smooth (`sigma = 0`, fewer than 5 samples, or
/// even `lambda = 1e-3` moves the samples by more than the noise).
pub fn smooth_displacement(u: &[f64], sigma: f64) -> Option<(Vec<f64>, f64)> {
    let n = u.len();
    if !(sigma > 0.0 && sigma.is_finite()) || n < 5 {
        return None;
    }
    let target = n as f64 * sigma * sigma;
    let mut x = vec![0.0; n];
    let mut work = Vec::new();
    let mut rss = |log_lambda: f64, x: &mut [f64]| {
        smooth_with(u, 10f64.powf(log_lambda), x, &mut work);
        u.iter()
            .zip(x.iter())
            .map(|(a, b)| (a - b) * (a - b))
            .sum::<f64>()
    };
    let (mut lo, mut hi) = LOG_LAMBDA;
    if rss(lo, &mut x) > target {
        // Even the lightest smoothing moves the samples by more than the noise (noise at the
        // rounding of the arithmetic, a kinked motion): the samples are the motion.
        return None;
    }
    if rss(hi, &mut x) <= target {
        return Some((x, 10f64.powf(hi)));
    }
    // 40 halvings of 15 decades: lambda to 1e-11 relative.
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        if rss(mid, &mut x) > target {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    rss(lo, &mut x);
    Some((x, 10f64.powf(lo)))
}

/// The noise levels (N1) of the position `u` and the force `f` (NaN where no force was
/// measured), with what the fit does with them.
pub(crate) fn levels(u: &[f64], f: &[f64], handling: PositionHandling) -> NoiseLevels {
    NoiseLevels {
        position: noise_level(u),
        force: noise_level(f),
        handling,
    }
}

/// The noise of a full fit's record and the displacement the fit runs on: smoothed (N2) where
/// the samples are equally spaced and noisy.
pub(crate) fn prepare_full(t: &[f64], u: &[f64], f: &[f64]) -> (Option<Vec<f64>>, NoiseLevels) {
    let mut levels = levels(u, f, PositionHandling::AsGiven);
    if !evenly_spaced(t) {
        levels.handling = PositionHandling::Uneven;
        return (None, levels);
    }
    match smooth_displacement(u, levels.position) {
        Some((x, lambda)) => {
            levels.handling = PositionHandling::Smoothed { lambda };
            (Some(x), levels)
        }
        None => (None, levels),
    }
}

/// Draws of the smoothing's error for (S3), `fit/stats.rs`.
pub const INPUT_DRAWS: usize = 64;

/// The model's response to [`INPUT_DRAWS`] draws of the error of a smoothed displacement `u`
/// (noise `sigma`, smoothing `lambda`): the smoother is linear, so its error on white noise
/// `e` is the smoothed noise `S e`; `model_at` gives the output for a reading of the input.
/// The draws come from a fixed generator: the same record gives the same intervals.
pub(crate) fn input_effects(
    u: &[f64],
    sigma: f64,
    lambda: f64,
    mut model_at: impl FnMut(&[f64]) -> Option<Vec<f64>>,
) -> Vec<Vec<f64>> {
    let Some(base) = model_at(u) else {
        return Vec::new();
    };
    let n = u.len();
    let mut normal = Normal(0x05ee_d0f0_015e);
    let (mut e, mut s, mut uk, mut work) = (vec![0.0; n], vec![0.0; n], vec![0.0; n], Vec::new());
    let mut out = Vec::with_capacity(INPUT_DRAWS);
    for _ in 0..INPUT_DRAWS {
        e.iter_mut().for_each(|x| *x = sigma * normal.next());
        smooth_with(&e, lambda, &mut s, &mut work);
        for i in 0..n {
            uk[i] = u[i] + s[i];
        }
        if let Some(y) = model_at(&uk) {
            out.push(y.iter().zip(&base).map(|(a, b)| a - b).collect());
        }
    }
    out
}

/// Standard normal deviates: Box-Muller on a 64-bit LCG (Knuth's MMIX constants).
struct Normal(u64);

impl Normal {
    fn unit(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        // In (0, 1): the logarithm below is finite.
        ((self.0 >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }

    fn next(&mut self) -> f64 {
        let r = (-2.0 * self.unit().ln()).sqrt();
        r * (std::f64::consts::TAU * self.unit()).cos()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn gauss(n: usize, seed: u64) -> Vec<f64> {
        let mut g = Normal(seed);
        (0..n).map(|_| g.next()).collect()
    }

    #[test]
    fn the_level_of_white_noise_on_a_smooth_signal() {
        let e = gauss(20_000, 7);
        let x: Vec<f64> = (0..e.len())
            .map(|i| 5.0 * (i as f64 * 1e-3 * std::f64::consts::PI).sin() + 0.01 * e[i])
            .collect();
        // The median of 20 000 has a relative standard error of about 1.1 %: 4 of them.
        let s = noise_level(&x);
        assert!((s / 0.01 - 1.0).abs() < 0.045, "{s}");
        // Rounded to q = 0.01: sqrt(s^2 + q^2 / 12).
        let q = 0.01;
        let r: Vec<f64> = x.iter().map(|v| (v / q).round() * q).collect();
        let want = (0.01f64.powi(2) + q * q / 12.0).sqrt();
        let s = noise_level(&r);
        assert!((s / want - 1.0).abs() < 0.045, "{s} vs {want}");
        // A triangle wave's kinks do not count.
        let tri: Vec<f64> = (0..2000)
            .map(|i| (((i % 200) as f64) - 100.0).abs() + 1e-3 * e[i])
            .collect();
        let s = noise_level(&tri);
        assert!((s / 1e-3 - 1.0).abs() < 0.1, "{s}");
        assert_eq!(noise_level(&[1.0, 2.0]), 0.0);
    }

    #[test]
    fn the_smoother_solves_its_system() {
        // (I + lambda D2^T D2) x = u checked by multiplying back.
        let u: Vec<f64> = (0..9)
            .map(|i| (i as f64).powi(2) * 0.3 - (i as f64))
            .collect();
        let lambda = 2.5;
        let mut x = vec![0.0; u.len()];
        smooth_with(&u, lambda, &mut x, &mut Vec::new());
        let n = u.len();
        let mut dx = vec![0.0; n - 2];
        for i in 0..n - 2 {
            dx[i] = x[i] - 2.0 * x[i + 1] + x[i + 2];
        }
        for i in 0..n {
            let mut back = x[i];
            for (j, d) in dx.iter().enumerate() {
                let c = match i as isize - j as isize {
                    0 | 2 => 1.0,
                    1 => -2.0,
                    _ => 0.0,
                };
                back += lambda * c * d;
            }
            assert!((back - u[i]).abs() < 1e-12, "{i}: {back} vs {}", u[i]);
        }
    }

    #[test]
    fn smoothing_leaves_the_noise_as_residual() {
        let e = gauss(4001, 3);
        let clean: Vec<f64> = (0..4001)
            .map(|i| 5.0 * (i as f64 * 1e-3 * std::f64::consts::PI).sin())
            .collect();
        let u: Vec<f64> = clean.iter().zip(&e).map(|(c, e)| c + 5e-4 * e).collect();
        let (x, lambda) = smooth_displacement(&u, 5e-4).unwrap();
        let rss: f64 = u.iter().zip(&x).map(|(a, b)| (a - b) * (a - b)).sum();
        assert!((rss / (4001.0 * 25e-8) - 1.0).abs() < 1e-6, "{rss}");
        assert!(lambda > 1.0, "{lambda}");
        // The smoothed motion is far nearer the truth than the samples.
        let err = (x
            .iter()
            .zip(&clean)
            .map(|(a, b)| (a - b).powi(2))
            .sum::<f64>()
            / 4001.0)
            .sqrt();
        assert!(err < 1.5e-4, "{err}");
        assert!(smooth_displacement(&u, 0.0).is_none());
    }

    #[test]
    fn spacing() {
        assert!(evenly_spaced(&[0.0, 0.001, 0.002, 0.003]));
        assert!(!evenly_spaced(&[0.0, 0.001, 0.0025, 0.003]));
    }
}
