//! Fits of records as labs make them: noise in the position and the force, quantised
//! positions, parameters at their bounds.
//!
//! The servo-axis record comes from an independent computation: scipy's Radau at
//! rtol 1e-10 (`reference/servo_axis.py clean`, committed as `reference/servo_axis_clean.csv`:
//! t [s], u [mm], F [N], noise-free), to which the tests add their own noise (Box-Muller on a
//! fixed LCG) at the levels: 0.5 um on the position, rounded to 0.1 um, 0.2 N on the
//! force. Truth: sigma0 = 1e6 N/m, sigma1 = 1500, sigma2 = 40 N s/m, Fc = 15 N, Fs = 22 N,
//! vs = 4 mm/s, beta = 2.

mod common;

use common::{Gauss, Lcg};
use lugre::fit::{fit_full, Family, FitReport, FitSpec, FullOptions, Noise, PositionHandling};
use lugre::{Gamma, LuGre, PiecewiseLinear, Simulator, Trajectory};

/// The true values of the servo axis (SI units).
const SERVO: [(&str, f64); 5] = [
    ("sigma0", 1e6),
    ("sigma1", 1500.0),
    ("fc", 15.0),
    ("fs", 22.0),
    ("vs", 4e-3),
];

/// The noise-free servo-axis samples `(t, u [m], F)`.
fn servo_clean() -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let text = include_str!("reference/servo_axis_clean.csv");
    let (mut t, mut u, mut f) = (Vec::new(), Vec::new(), Vec::new());
    for line in text.lines().skip(1) {
        let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        t.push(v[0]);
        u.push(v[1] * 1e-3);
        f.push(v[2]);
    }
    (t, u, f)
}

/// The record with `position` of noise (m) rounded to `step` (m; 0: not rounded) and `force`
/// of noise (N).
fn servo_noisy(seed: u64, position: f64, step: f64, force: f64) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let (t, u, f) = servo_clean();
    let mut g = Gauss(Lcg(seed));
    let u = u
        .iter()
        .map(|&x| {
            let x = x + position * g.next();
            if step > 0.0 {
                (x / step).round() * step
            } else {
                x
            }
        })
        .collect();
    let f = f.iter().map(|&x| x + force * g.next()).collect();
    (t, u, f)
}

/// The request: `--fit full --beta 2 --fix sigma2=40`.
fn servo_spec() -> FitSpec {
    FitSpec::new(Family::LuGre)
        .set("beta", 2.0)
        .unwrap()
        .set("sigma2", 40.0)
        .unwrap()
        .fix("sigma2")
        .unwrap()
}

fn value(r: &FitReport, name: &str) -> f64 {
    r.estimate(name).unwrap().value
}

#[test]
fn the_servo_axis_record_is_fitted_through_its_noise() {
    let (t, u, f) = servo_noisy(11, 0.5e-6, 0.1e-6, 0.2);
    let r = fit_full(&servo_spec(), &t, &u, &f, FullOptions::default()).unwrap();
    let noise = r.noise.unwrap();
    // sqrt(0.5^2 + 0.1^2 / 12) um = 0.5008 um and 0.2 N, each to the median's ~4 % (2 sigma).
    assert!((noise.position / 0.5008e-6 - 1.0).abs() < 0.06, "{noise:?}");
    assert!((noise.force / 0.2 - 1.0).abs() < 0.06, "{noise:?}");
    assert!(matches!(noise.handling, PositionHandling::Smoothed { .. }));
    for (name, want) in SERVO {
        let got = value(&r, name);
        assert!((got / want - 1.0).abs() < 0.02, "{name}: {got} vs {want}");
    }
    // As given, the fit is confidently wrong: sigma0 13 % low, Fs 18 % high.
    let off = fit_full(
        &servo_spec(),
        &t,
        &u,
        &f,
        FullOptions::default().with_noise(Noise::Off),
    )
    .unwrap();
    assert_eq!(off.noise.unwrap().handling, PositionHandling::AsGiven);
    // ... and says its intervals cannot be trusted.
    assert!(
        off.warnings
            .iter()
            .any(|w| w.to_string().starts_with("the intervals cannot be trusted")),
        "{:?}",
        off.warnings
    );
    assert!(value(&off, "sigma0") < 0.9e6, "{off:?}");
    assert!(value(&off, "fs") > 24.0, "{off:?}");
}

#[test]
fn a_parameter_at_its_bound_is_reported_there_with_the_others() {
    // The paper's model has no viscous friction (sigma2 = 0): fitted free on noise-free data,
    // sigma2 goes to its bound 0, and the others are still estimated.
    let model = LuGre::paper();
    let mut t = vec![0.0];
    let mut u = vec![-6.0];
    for v in [0.1, 0.3, 1.0, 3.0, 10.0] {
        for target in [6.0, -6.0] {
            let (t0, u0): (f64, f64) = (t[t.len() - 1], u[u.len() - 1]);
            for j in 1..=300 {
                let x = f64::from(j) / 300.0;
                t.push(t0 + (target - u0).abs() / v * x);
                u.push(u0 + (target - u0) * x);
            }
        }
    }
    let input = PiecewiseLinear::new(t.clone(), u.clone()).unwrap();
    let mut out = Trajectory::default();
    Simulator::new(&model, Gamma::ONE, 0.0)
        .unwrap()
        .at_knots(&input, 1, &mut out)
        .unwrap();
    let spec = FitSpec::new(Family::LuGre).set("beta", 1.0).unwrap();
    let r = fit_full(&spec, &t, &u, &out.y, FullOptions::default()).unwrap();
    let s2 = r.estimate("sigma2").unwrap();
    assert!(s2.at_bound && s2.value < 1e-6, "{s2:?}");
    assert!(s2.ci95[0] == 0.0 && s2.ci95[1].is_finite(), "{s2:?}");
    assert!(
        r.warnings
            .iter()
            .any(|w| w.to_string().starts_with("sigma2 is at its bound 0")),
        "{:?}",
        r.warnings
    );
    for (name, want) in [
        ("sigma0", 1.0),
        ("sigma1", 1.0),
        ("fc", 1.0),
        ("fs", 2.0),
        ("vs", 1.0),
    ] {
        let got = value(&r, name);
        assert!((got / want - 1.0).abs() < 1e-3, "{name}: {got} vs {want}");
        assert!(!r.estimate(name).unwrap().at_bound);
    }
}

#[test]
fn a_parameter_at_a_user_bound_is_reported_there() {
    // vs = 4 mm/s held below 2 mm/s: vs ends at its bound, nothing is blamed on sigma2.
    let (t, u, f) = servo_noisy(12, 0.5e-6, 0.1e-6, 0.2);
    let spec = FitSpec::new(Family::LuGre)
        .set("beta", 2.0)
        .unwrap()
        .bounds("vs", 0.0, 0.002)
        .unwrap();
    let r = fit_full(&spec, &t, &u, &f, FullOptions::default()).unwrap();
    let vs = r.estimate("vs").unwrap();
    assert!(
        vs.at_bound && (vs.value / 0.002 - 1.0).abs() < 1e-5,
        "{vs:?}"
    );
    assert!(vs.ci95[1] == 0.002 && vs.stderr.is_finite(), "{vs:?}");
    assert!(
        r.warnings
            .iter()
            .any(|w| w.to_string().starts_with("vs is at its bound 0.002")),
        "{:?}",
        r.warnings
    );
    assert_eq!(r.estimates.len(), 6);
}

/// The reduced Monte Carlo: `RECORDS` servo-axis records, each fitted with the
/// noise handling; the 95 % intervals must cover the truth in at least 90 % of the records for
/// every fitted parameter, and the mean estimates be within 2 % of the truth. (The full count,
/// 200 records from the generator's own noise: `scripts/servo_axis_monte_carlo.py`, numbers in
/// BENCHMARKS.md: coverage 0.92 to 0.96 for every parameter on seeds 1-200 and on 201-400.)
/// Seeds 1000-1023 of this file's generator: 24, 23, 22, 24, 23 of 24 covered (sigma0,
/// sigma1, Fc, Fs, vs), mean errors below 2e-4.
#[test]
fn servo_axis_monte_carlo() {
    const RECORDS: u64 = 24;
    let mut covered = [0usize; 5];
    let mut mean = [0.0f64; 5];
    for seed in 0..RECORDS {
        let (t, u, f) = servo_noisy(1000 + seed, 0.5e-6, 0.1e-6, 0.2);
        let r = fit_full(&servo_spec(), &t, &u, &f, FullOptions::default()).unwrap();
        for (k, (name, want)) in SERVO.iter().enumerate() {
            let e = r.estimate(name).unwrap();
            covered[k] += usize::from(e.ci95[0] <= *want && *want <= e.ci95[1]);
            mean[k] += e.value / RECORDS as f64;
        }
    }
    for (k, (name, want)) in SERVO.iter().enumerate() {
        let coverage = covered[k] as f64 / RECORDS as f64;
        assert!(coverage >= 0.9, "{name}: coverage {coverage}");
        let bias = mean[k] / want - 1.0;
        assert!(bias.abs() < 0.02, "{name}: mean error {bias}");
    }
}
