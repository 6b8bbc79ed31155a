//! The presliding fit: `sigma0` and `sigma1` from a presliding test, the lab's second and third
//! LuGre experiments (Canudas de Wit et al. 1995; Olsson et al. 1998): small displacement
//! reversals, `(t, u, F)` from rest (`z = 0`), that stay below break-away.
//!
//! Below break-away `|sigma0 z| << g(v)`, so `z` follows the displacement from the last
//! reversal and the force is a damped spring:
//!
//! ```text
//! F ~ F_r + sigma0 (u - u_r) + (sigma1 + sigma2) v                                      (R1)
//! ```
//!
//! The initial slope of the force-displacement curve after a reversal is `sigma0`; the force's
//! lead on the displacement (the presliding loop's width, `(sigma1 + sigma2) omega / sigma0`
//! at angular frequency `omega`) is the damping. The lab's estimates are (R1) by linear least
//! squares, `F_i = a + k u_i + c v_i` with `v_i` the central difference, `sigma0 = k` and
//! `sigma1 = c - sigma2` (R2). (R1) neglects the bristles' softening `1 - sigma0 |z| / g`, a
//! bias of the order of `sigma0 |u - u_r| / g`; so (R2) only starts the exact fit: the full fit
//! of eq. 1 ([`super::fit_full_smooth`]: the samples read as a smooth motion, the C1 cubic
//! through them) with `sigma0`, `sigma1` free and the Stribeck curve (`Fc, Fs, vs, beta,
//! sigma2`) held at its values (from the Stribeck fit, or given).
//!
//! A test that breaks away is refused ([`FitError::BreaksAway`]): its force reaches
//! `0.9 Fs` (three noise deviations below its peak), or the spring (R2), or the fitted
//! `sigma0`, would exceed twice `Fs` over the travel between two reversals, which only sliding
//! allows (a sliding test's flat force can make (R2) soft; the exact fit is not fooled).

use super::noise::difference_noise;
use super::spec::index_of;
use super::{
    check_columns, fit_full_smooth, full, FitKind, FitReport, FitSpec, FullOptions,
    CUBIC_READING_TOL,
};
use crate::error::FitError;
use crate::input::check_increasing;
use crate::model::Parameter;
use crate::simulate::SmoothSamples;

/// The force's peak, less three noise deviations, may reach this fraction of `Fs`.
pub const BREAKAWAY_FRACTION: f64 = 0.9;

const SIGMA0: usize = index_of(&Parameter::LUGRE, Parameter::Sigma0);
const SIGMA1: usize = index_of(&Parameter::LUGRE, Parameter::Sigma1);
const SIGMA2: usize = index_of(&Parameter::LUGRE, Parameter::Sigma2);
const FS: usize = index_of(&Parameter::LUGRE, Parameter::Fs);

/// The presliding fit of `sigma0`, `sigma1` (others freed with [`FitSpec::free`] are fitted
/// too) to a presliding test `(t, u, F)` from rest; the Stribeck curve is held at the spec's
/// values. See the module docs.
pub fn fit_presliding(
    spec: &FitSpec,
    t: &[f64],
    u: &[f64],
    f: &[f64],
) -> Result<FitReport, FitError> {
    check_columns(&[("u", u), ("t", t), ("F", f)])?;
    check_increasing(t)?;
    let resolved = spec.resolve(FitKind::Presliding)?;
    super::check_count(u.len(), resolved.free.len())?;
    if !full::has_reversal(u) {
        return Err(FitError::NoReversal { fit: "presliding" });
    }
    check_signal(u, f)?;
    let (k, c) = lab_estimates(t, u, f);
    check_breakaway(u, f, k, resolved.values[FS])?;
    let sigma1 = c - resolved.values[SIGMA2];
    // A damping the linear model cannot see (c <= sigma2) starts sigma1 at a small fraction
    // of sigma0 times the sampling interval.
    let dt = (t[t.len() - 1] - t[0]) / (t.len() - 1) as f64;
    let starts = [
        (SIGMA0, k),
        (SIGMA1, if sigma1 > 0.0 { sigma1 } else { 0.1 * k * dt }),
    ];
    let held = spec.holding_all_but(&resolved.free, &starts);
    // The test's motion is smooth (a sampled sine, say): read as the C1 cubic through the
    // samples, the velocity in the damping term is the motion's at each sample, not the chord
    // to the next one (half a sample ahead, a bias of sigma1 of order omega dt).
    let motion = SmoothSamples::pchip(t.to_vec(), u.to_vec(), CUBIC_READING_TOL)?;
    let mut report = fit_full_smooth(&held, &motion, f, FullOptions::default().with_starts(1))?;
    // A sliding test can fool (R2) (the force is flat while it slides, so the spring looks
    // soft) but not the exact fit: its sigma0 over the travel shows the sliding.
    check_travel(u, report.lugre_params(&held).sigma0, resolved.values[FS])?;
    report.kind = FitKind::Presliding;
    Ok(report)
}

/// (R2): the spring `k` and damping `c` of `F = a + k u + c v` by least squares.
fn lab_estimates(t: &[f64], u: &[f64], f: &[f64]) -> (f64, f64) {
    let n = u.len();
    let v: Vec<f64> = (0..n)
        .map(|i| {
            let (a, b) = (i.saturating_sub(1), (i + 1).min(n - 1));
            (u[b] - u[a]) / (t[b] - t[a])
        })
        .collect();
    // Centred columns: the intercept drops out of the 2 x 2 normal equations.
    let mean = |x: &[f64]| x.iter().sum::<f64>() / n as f64;
    let (mu, mv, mf) = (mean(u), mean(&v), mean(f));
    let (mut suu, mut suv, mut svv, mut suf, mut svf) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for i in 0..n {
        let (x, y, z) = (u[i] - mu, v[i] - mv, f[i] - mf);
        suu += x * x;
        suv += x * y;
        svv += y * y;
        suf += x * z;
        svf += y * z;
    }
    let det = suu * svv - suv * suv;
    ((suf * svv - svf * suv) / det, (svf * suu - suf * suv) / det)
}

/// Noise larger than the signal, in the force or in the displacement.
fn check_signal(u: &[f64], f: &[f64]) -> Result<(), FitError> {
    for (what, x) in [
        ("the presliding force", f),
        ("the presliding displacement", u),
    ] {
        let noise = difference_noise(x, 2);
        let (lo, hi) = x
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &y| {
                (l.min(y), h.max(y))
            });
        let signal = 0.5 * (hi - lo);
        if noise >= signal {
            return Err(FitError::NoiseAboveSignal {
                what,
                noise,
                signal,
            });
        }
    }
    Ok(())
}

/// Refuses a test that breaks away (module docs); `k` is the spring of (R2).
fn check_breakaway(u: &[f64], f: &[f64], k: f64, fs: f64) -> Result<(), FitError> {
    let noise = difference_noise(f, 2);
    let peak = f.iter().fold(0.0f64, |m, y| m.max(y.abs()));
    if peak - 3.0 * noise >= BREAKAWAY_FRACTION * fs {
        return Err(FitError::BreaksAway {
            peak,
            limit: BREAKAWAY_FRACTION * fs,
            fs,
        });
    }
    check_travel(u, k, fs)
}

/// Refuses a test whose travel between two reversals, on a bristle spring `k`, would exceed
/// twice `Fs`: only sliding goes that far.
fn check_travel(u: &[f64], k: f64, fs: f64) -> Result<(), FitError> {
    let travel = full::segments(u)
        .iter()
        .map(|&(a, b)| (u[b] - u[a]).abs())
        .fold(0.0, f64::max);
    if k > 0.0 && k * travel > 2.0 * fs {
        return Err(FitError::Slides {
            travel,
            limit: 2.0 * fs / k,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fit::Family;
    use crate::{Gamma, LuGre, LuGreParams, PiecewiseLinear, Simulator, Trajectory};

    /// canudas1995 with its Stribeck curve given, as after the Stribeck fit.
    fn spec() -> FitSpec {
        let p = LuGreParams::canudas_de_wit_1995();
        let mut s = FitSpec::new(Family::LuGre);
        for (name, v) in [
            ("sigma2", p.sigma2),
            ("fc", p.fc),
            ("fs", p.fs),
            ("vs", p.vs),
            ("beta", p.beta),
        ] {
            s = s.set(name, v).unwrap();
        }
        s
    }

    /// A 20 Hz sine of amplitude `a` (1000 samples over 0.5 s) through the core's simulator:
    /// this checks the fit's plumbing on its own model; the independent check is the CLI test
    /// on `examples/data/lab-presliding.csv`.
    fn test_record(a: f64) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        let t: Vec<f64> = (0..1000).map(|i| f64::from(i) * 5e-4).collect();
        let u: Vec<f64> = t
            .iter()
            .map(|t| a * (std::f64::consts::TAU * 20.0 * t).sin())
            .collect();
        let model = LuGre::from_params(LuGreParams::canudas_de_wit_1995()).unwrap();
        let input = PiecewiseLinear::new(t.clone(), u.clone()).unwrap();
        let mut out = Trajectory::with_capacity(t.len());
        Simulator::new(&model, Gamma::ONE, 0.0)
            .unwrap()
            .at_knots(&input, 1, &mut out)
            .unwrap();
        (t, u, out.y)
    }

    #[test]
    fn recovers_sigma0_and_sigma1() {
        let (t, u, f) = test_record(2e-6);
        let r = fit_presliding(&spec(), &t, &u, &f).unwrap();
        let s0 = r.estimate("sigma0").unwrap().value;
        let s1 = r.estimate("sigma1").unwrap().value;
        // The record is the piecewise-linear motion's response, the fit reads the samples as
        // the smooth cubic through them: the two motions' responses differ by about 1 %.
        assert!((s0 / 1e5 - 1.0).abs() < 0.02, "{s0}");
        assert!((s1 / 1e5f64.sqrt() - 1.0).abs() < 0.02, "{s1}");
        assert_eq!(r.kind, FitKind::Presliding);
        // The lab's linear estimates are close, not exact.
        let (k, _) = lab_estimates(&t, &u, &f);
        assert!((k / 1e5 - 1.0).abs() < 0.2, "{k}");
    }

    #[test]
    fn a_test_that_breaks_away_is_refused() {
        let (t, u, f) = test_record(1e-4);
        let e = fit_presliding(&spec(), &t, &u, &f).unwrap_err();
        assert!(matches!(e, FitError::BreaksAway { .. }), "{e}");
        assert!(e.to_string().contains("breaks away"), "{e}");
        let held = FitSpec::new(Family::LuGre);
        let e = fit_presliding(&held, &t, &u, &f).unwrap_err();
        assert!(
            matches!(
                e,
                FitError::NotGiven {
                    fit: "presliding",
                    ..
                }
            ),
            "{e}"
        );
    }
}
