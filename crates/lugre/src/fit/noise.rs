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
//! a pentadiagonal system `(I + lambda D2^T D2) x = u` solved by banded `L D L^T` in `O(n)`.
//! Its response to a sine of `w` radians a sample is `1 / (1 + lambda (2 sin(w / 2))^4)`: the
//! motion (0.5 Hz at 1 kHz) passes unchanged to `1e-5`, the noise is averaged over about
//! `L = lambda^(1/4)` samples (the equivalent kernel, Silverman 1984, is
//! `exp(-|j| / (sqrt 2 L)) sin(|j| / (sqrt 2 L) + pi / 4) / (2 L)`). Smooth reversals (a sine)
//! are kept; a kink (a triangle wave's reversal) is rounded over that many samples.
//!
//! **Ends.** (N2)'s minimiser meets the natural conditions `x'' = x''' = 0` at both ends of the
//! record: a record cut from a longer motion does not, and the reading is biased there by
//! `O(x''' L^3)` in position and `O(x'' L + x''' L^2)` in velocity (the servo-axis record
//! starts at full speed: its first velocity came out 0.25 % low at `lambda = 7e4`, and its first
//! sample, `F_0 = (sigma1 + sigma2) v_0` from `z = 0`, carries most of what the record says about
//! `sigma1`, which came out +0.25 % high, a third of its standard error, in every record). The
//! end conditions are therefore taken from the data: with `p` the least-squares cubic through
//! the `W = round(7.775 L)` samples at an end (the reach of the equivalent kernel, its second
//! zero at `sqrt(2) 7 pi / 4 = 7.775`),
//!
//! ```text
//! (I + lambda D2^T D2) x = u + lambda c       c = the end rows of D2^T D2 p:
//! c_0 = D2p_0,   c_1 = -2 D2p_0 + D2p_1,      D2p_j = p_j - 2 p_{j+1} + p_{j+2}        (N3)
//! ```
//!
//! (the same at the other end, counted from it), which reproduces a cubic exactly, ends
//! included (`D2^T D2 p = c` for a cubic `p`). The reading stays linear in the samples, so
//! (S3) draws its error through the same map. An end keeps the natural conditions where its
//! cubic does not fit the samples to 1.5 times the noise (a kink, a stop) or where `W < 16`.
//!
//! **lambda.** Mallows' `C_L` (the unbiased estimate of the mean squared error of the reading),
//! with the noise `s_hat` of (N1):
//!
//! ```text
//! lambda = argmin ||u - x(lambda)||^2 + 2 s_hat^2 tr S(lambda)
//! tr S(lambda) ~ sum_k 1 / (1 + lambda (2 - 2 cos(pi k / n))^2)                          (N4)
//! ```
//!
//! (`S` the smoother; the trace from the eigenvalues of the squared path Laplacian, which
//! differs from `D2^T D2` at the two ends only: an error of order 1 in a trace of order
//! `n / (2 sqrt(2) L)`); a pass over `log10 lambda` in `[-3, 12]` at steps of 0.5, then a
//! golden-section search. The discrepancy principle `||u - x||^2 = n s_hat^2` used before sets
//! `lambda` where the residual, nearly flat in `lambda` for a smooth motion
//! (`s^2 (n - 2 tr S + tr S^2)`), meets a target that the 2.5 % error of `s_hat` moves: over
//! 200 servo-axis records it ranged from 70 to 6e5, and the records smoothed least carried the
//! most velocity noise. `C_L` has a sharp minimum: 5.4e4 to 7.7e4 over the same records.
//! An errors-in-variables weighting of the residuals (variance `s_F^2 + (dF/du)^2 s_u^2`) was
//! not used: it weighs the samples, but the bias comes from the noise in the velocity, which
//! no weighting removes.
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
                 spline, lambda {lambda:.3e} by Mallows' C_L for the position noise)"
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

/// `(I + lambda D2^T D2) x = b` (N2's system), written into `x`; `work` holds the
/// factorisation (3 n values).
fn solve_banded(b: &[f64], lambda: f64, x: &mut [f64], work: &mut Vec<f64>) {
    let n = b.len();
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
        let mut v = b[i];
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

/// The span of each end's cubic (N3), in units of `lambda^(1/4)`: the reach of the smoother's
/// equivalent kernel, whose second zero lies at `sqrt(2) 7 pi / 4 = 7.775` of them.
const END_SPAN: f64 = 7.775;

/// The fewest samples an end's cubic (N3) is fitted to.
const END_MIN_SAMPLES: usize = 16;

/// An end's cubic whose residual RMS exceeds this many noise levels does not describe the end
/// (a kink, a stop): the natural conditions are kept there.
const END_MISFIT: f64 = 1.5;

/// The smoother of a record: (N2) with `lambda`, and at each end the number of samples whose
/// cubic sets the end conditions (N3), or `None` where the natural conditions are kept. A
/// linear map of the samples: the same smoother applies to draws of the noise (S3).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Smoother {
    pub lambda: f64,
    ends: [Option<usize>; 2],
}

impl Smoother {
    /// (N2)-(N3) at `lambda` for samples `u` with noise `sigma`: an end gets the conditions of
    /// its cubic where it has [`END_MIN_SAMPLES`] samples or more (at most half the record)
    /// and the cubic fits them to [`END_MISFIT`] times the noise.
    pub(crate) fn for_record(u: &[f64], lambda: f64, sigma: f64) -> Self {
        let n = u.len();
        let w = (END_SPAN * lambda.powf(0.25)).round().min((n / 2) as f64) as usize;
        let end = |reversed: bool| -> Option<usize> {
            if w < END_MIN_SAMPLES {
                return None;
            }
            let fit = end_cubic(u, w, reversed);
            (fit.rms <= END_MISFIT * sigma).then_some(w)
        };
        Self {
            lambda,
            ends: [end(false), end(true)],
        }
    }

    /// `x = (I + lambda D2^T D2)^-1 (u + lambda c)` (N3), written into `x`.
    pub(crate) fn apply(&self, u: &[f64], x: &mut [f64], work: &mut Vec<f64>) {
        let mut b = u.to_vec();
        let n = u.len();
        for (k, w) in self.ends.iter().enumerate() {
            if let Some(w) = *w {
                let [c0, c1] = end_cubic(u, w, k == 1).conditions;
                let (i0, i1) = if k == 0 { (0, 1) } else { (n - 1, n - 2) };
                b[i0] += self.lambda * c0;
                b[i1] += self.lambda * c1;
            }
        }
        solve_banded(&b, self.lambda, x, work);
    }
}

/// The least-squares cubic through the first `w` samples (the last `w`, `reversed`): its
/// residual RMS, and the terms of (N3) at that end, the end rows of `D2^T D2 p`:
/// `[D2p_0, -2 D2p_0 + D2p_1]` with `D2p_j = p_j - 2 p_{j+1} + p_{j+2}` counted from the end.
struct EndCubic {
    rms: f64,
    conditions: [f64; 2],
}

fn end_cubic(u: &[f64], w: usize, reversed: bool) -> EndCubic {
    let at = |k: usize| if reversed { u[u.len() - 1 - k] } else { u[k] };
    // Monomials of s = k / (w - 1) on [0, 1], about the window's first value (no cancellation
    // against a large offset).
    let origin = at(0);
    let basis = |k: usize| {
        let s = k as f64 / (w - 1) as f64;
        nalgebra::Vector4::new(1.0, s, s * s, s * s * s)
    };
    let mut normal = nalgebra::Matrix4::zeros();
    let mut rhs = nalgebra::Vector4::zeros();
    for k in 0..w {
        let b = basis(k);
        normal += b * b.transpose();
        rhs += b * (at(k) - origin);
    }
    let Some(a) = normal.cholesky().map(|c| c.solve(&rhs)) else {
        return EndCubic {
            rms: f64::INFINITY,
            conditions: [0.0; 2],
        };
    };
    let p = |k: usize| basis(k).dot(&a);
    let rss: f64 = (0..w).map(|k| (at(k) - origin - p(k)).powi(2)).sum();
    let d0 = p(0) - 2.0 * p(1) + p(2);
    let d1 = p(1) - 2.0 * p(2) + p(3);
    EndCubic {
        rms: (rss / (w - 4) as f64).sqrt(),
        conditions: [d0, -2.0 * d0 + d1],
    }
}

/// The range of `log10 lambda` searched, and the step of the first, coarse pass.
const LOG_LAMBDA: (f64, f64) = (-3.0, 12.0);
const LOG_LAMBDA_STEP: f64 = 0.5;

/// (N2)-(N3) with `lambda` set by Mallows' `C_L` (N4) for noise `sigma`: the smoothed samples
/// and `lambda`. `None` when there is nothing to smooth (`sigma = 0`, fewer than 5 samples, or
/// the least smoothing searched, `lambda = 1e-3`, is best: the samples are the motion).
pub fn smooth_displacement(u: &[f64], sigma: f64) -> Option<(Vec<f64>, f64)> {
    smooth(u, sigma).map(|(x, s)| (x, s.lambda))
}

/// [`smooth_displacement`] with the smoother it used.
pub(crate) fn smooth(u: &[f64], sigma: f64) -> Option<(Vec<f64>, Smoother)> {
    let n = u.len();
    if !(sigma > 0.0 && sigma.is_finite()) || n < 5 {
        return None;
    }
    // The eigenvalues of D2^T D2, approximated by those of the squared path Laplacian (N4).
    let eigen: Vec<f64> = (0..n)
        .map(|k| {
            let c = 2.0 - 2.0 * (std::f64::consts::PI * k as f64 / n as f64).cos();
            c * c
        })
        .collect();
    let mut x = vec![0.0; n];
    let mut work = Vec::new();
    let mut risk = |log_lambda: f64, x: &mut [f64]| {
        let lambda = 10f64.powf(log_lambda);
        let smoother = Smoother::for_record(u, lambda, sigma);
        smoother.apply(u, x, &mut work);
        let rss: f64 = u.iter().zip(x.iter()).map(|(a, b)| (a - b) * (a - b)).sum();
        let trace: f64 = eigen.iter().map(|e| 1.0 / (1.0 + lambda * e)).sum();
        (rss + 2.0 * sigma * sigma * trace, smoother)
    };
    // A coarse pass over the range, then golden-section search in the best point's bracket.
    let (lo, hi) = LOG_LAMBDA;
    let steps = ((hi - lo) / LOG_LAMBDA_STEP).round() as usize;
    let grid = |k: usize| lo + (hi - lo) * k as f64 / steps as f64;
    let best = (0..=steps)
        .map(|k| (k, risk(grid(k), &mut x).0))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map_or(0, |(k, _)| k);
    if best == 0 {
        return None;
    }
    let (mut a, mut b) = (grid(best - 1), grid((best + 1).min(steps)));
    const GOLDEN: f64 = 0.618_033_988_749_894_8;
    let (mut c, mut d) = (b - GOLDEN * (b - a), a + GOLDEN * (b - a));
    let (mut fc, mut fd) = (risk(c, &mut x).0, risk(d, &mut x).0);
    // 40 steps shrink the bracket (one decade) to 5e-9 of a decade.
    for _ in 0..40 {
        if fc <= fd {
            (b, d, fd) = (d, c, fc);
            c = b - GOLDEN * (b - a);
            fc = risk(c, &mut x).0;
        } else {
            (a, c, fc) = (c, d, fd);
            d = a + GOLDEN * (b - a);
            fd = risk(d, &mut x).0;
        }
    }
    let (_, smoother) = risk(0.5 * (a + b), &mut x);
    Some((x, smoother))
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

/// The noise of a full fit's record and the displacement the fit runs on: smoothed (N2)-(N3)
/// where the samples are equally spaced and noisy, with the smoother used.
pub(crate) fn prepare_full(
    t: &[f64],
    u: &[f64],
    f: &[f64],
) -> (Option<(Vec<f64>, Smoother)>, NoiseLevels) {
    let mut levels = levels(u, f, PositionHandling::AsGiven);
    if !evenly_spaced(t) {
        levels.handling = PositionHandling::Uneven;
        return (None, levels);
    }
    let smoothed = smooth(u, levels.position);
    if let Some((_, s)) = &smoothed {
        levels.handling = PositionHandling::Smoothed { lambda: s.lambda };
    }
    (smoothed, levels)
}

/// Draws of the smoothing's error for (S3), `fit/stats.rs`.
pub const INPUT_DRAWS: usize = 64;

/// The model's response to [`INPUT_DRAWS`] draws of the error of a smoothed displacement `u`
/// (noise `sigma`, smoother `smoother`): the smoother is linear, so its error on white noise
/// `e` is the smoothed noise `S e`; `model_at` gives the output for a reading of the input.
/// The draws come from a generator seeded by the record: the same record gives the same
/// intervals.
pub(crate) fn input_effects(
    u: &[f64],
    sigma: f64,
    smoother: &Smoother,
    mut model_at: impl FnMut(&[f64]) -> Option<Vec<f64>>,
) -> Vec<Vec<f64>> {
    let Some(base) = model_at(u) else {
        return Vec::new();
    };
    let n = u.len();
    let mut normal = Normal(record_seed(u));
    let (mut e, mut s, mut uk, mut work) = (vec![0.0; n], vec![0.0; n], vec![0.0; n], Vec::new());
    let mut out = Vec::with_capacity(INPUT_DRAWS);
    for _ in 0..INPUT_DRAWS {
        e.iter_mut().for_each(|x| *x = sigma * normal.next());
        smoother.apply(&e, &mut s, &mut work);
        for i in 0..n {
            uk[i] = u[i] + s[i];
        }
        if let Some(y) = model_at(&uk) {
            out.push(y.iter().zip(&base).map(|(a, b)| a - b).collect());
        }
    }
    out
}

/// The draws' seed from the record itself (FNV-1a over the samples' 64-bit words): the same record
/// gives the same draws, different records independent ones, so that the draws' own error
/// averages out over records instead of repeating in each (S3).
fn record_seed(u: &[f64]) -> u64 {
    u.iter().fold(0xcbf2_9ce4_8422_2325, |h, x| {
        (h ^ x.to_bits()).wrapping_mul(0x0000_0100_0000_01b3)
    })
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
        solve_banded(&u, lambda, &mut x, &mut Vec::new());
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
    fn smoothing_minimises_the_risk_and_keeps_the_ends() {
        // A cosine sampled from its apex: curved at both ends.
        let n = 4001;
        let e = gauss(n, 3);
        let clean: Vec<f64> = (0..n)
            .map(|i| 5.0 * (i as f64 * 1e-3 * std::f64::consts::PI).cos())
            .collect();
        let sigma = 5e-4;
        let u: Vec<f64> = clean.iter().zip(&e).map(|(c, e)| c + sigma * e).collect();
        let (x, lambda) = smooth_displacement(&u, sigma).unwrap();
        // (N4) at its minimum: a quarter of a decade either way is worse.
        let eigen: Vec<f64> = (0..n)
            .map(|k| (2.0 - 2.0 * (std::f64::consts::PI * k as f64 / n as f64).cos()).powi(2))
            .collect();
        let risk = |l: f64| {
            let mut y = vec![0.0; n];
            Smoother::for_record(&u, l, sigma).apply(&u, &mut y, &mut Vec::new());
            let rss: f64 = u.iter().zip(&y).map(|(a, b)| (a - b) * (a - b)).sum();
            rss + 2.0 * sigma * sigma * eigen.iter().map(|e| 1.0 / (1.0 + l * e)).sum::<f64>()
        };
        let at = risk(lambda);
        assert!(
            at < risk(lambda * 1.78) && at < risk(lambda / 1.78),
            "{lambda}"
        );
        // The smoothed motion is far nearer the truth than the samples.
        let rms = |a: &[f64]| {
            (a.iter()
                .zip(&clean)
                .map(|(a, b)| (a - b).powi(2))
                .sum::<f64>()
                / n as f64)
                .sqrt()
        };
        let err = rms(&x);
        assert!(err < 0.3 * sigma, "{err}");
        // The ends (N3): the first step within 5 of its standard errors (about 1e-5 here, by
        // simulation) of the truth; with the natural conditions 0.5 % of the motion off.
        let mut natural = vec![0.0; n];
        solve_banded(&u, lambda, &mut natural, &mut Vec::new());
        let first_step = |x: &[f64]| (x[1] - x[0]) - (clean[1] - clean[0]);
        assert!(first_step(&x).abs() < 5e-5, "{}", first_step(&x));
        assert!(
            first_step(&natural).abs() > 5e-4,
            "{}",
            first_step(&natural)
        );
        assert!(smooth_displacement(&u, 0.0).is_none());
    }

    #[test]
    fn the_end_conditions_reproduce_a_cubic() {
        let u: Vec<f64> = (0..200)
            .map(|i| {
                let s = i as f64 * 0.01;
                1.0 + 2.0 * s - 3.0 * s * s + 0.5 * s * s * s
            })
            .collect();
        let smoother = Smoother::for_record(&u, 1e3, 1e-9);
        assert!(smoother.ends.iter().all(Option::is_some), "{smoother:?}");
        let mut x = vec![0.0; u.len()];
        smoother.apply(&u, &mut x, &mut Vec::new());
        let off = x
            .iter()
            .zip(&u)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(off < 1e-10, "{off}");
        // The natural conditions bend a cubic at its ends.
        solve_banded(&u, 1e3, &mut x, &mut Vec::new());
        let off = x
            .iter()
            .zip(&u)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(off > 1e-4, "{off}");
        // An end that is no cubic (a stop, then a ramp) keeps the natural conditions.
        let kinked: Vec<f64> = (0..200).map(|i| (i as f64 - 20.0).max(0.0)).collect();
        let smoother = Smoother::for_record(&kinked, 1e3, 1e-3);
        assert_eq!(smoother.ends, [None, Some(44)]);
    }

    #[test]
    fn spacing() {
        assert!(evenly_spaced(&[0.0, 0.001, 0.002, 0.003]));
        assert!(!evenly_spaced(&[0.0, 0.001, 0.0025, 0.003]));
    }
}
