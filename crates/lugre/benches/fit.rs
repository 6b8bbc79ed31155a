//! Parameter identification (issue: the slow fit of a 10^5-point loop in under 10 ms, the full
//! fit of 10^5 samples in under 2 s, release, one core).
//!
//! Data: the project's simulator plus 1 % Gaussian noise (fixed seed). Slow: the paper's
//! Example 4 loop (sigma0 = 6, Fs = 2, minor loop included), two periods of 5 * 10^4 samples.
//! Full: the Canudas de Wit (1995) parameters, sweeps of +-1 mm at seven speeds from 0.1 mm/s to
//! 0.1 m/s, 10^5 samples, all six parameters free (beta = 2 fixed), three starts. Full on the
//! cubic reading (issue: 10^5 samples under 1 s): the paper's model, two periods of a sine of
//! amplitude 6 sampled 10^5 times, sigma2 = 0 and beta = 1 held, the interpolant and its
//! subdivision (tolerance 1e-9 of the range, as `lugre fit --interpolate cubic`) built inside.

use criterion::{criterion_group, criterion_main, Criterion};
use lugre::fit::{fit_full, fit_full_smooth, fit_slow, Family, FitSpec, FullOptions};
use lugre::simulate::SmoothSamples;
use lugre::simulate::{merge_times, uniform_times};
use lugre::{Gamma, LuGre, LuGreParams, PiecewiseLinear, Simulator, Trajectory, TurningPoints};
use std::hint::black_box;
use std::time::Duration;

/// Adds Gaussian noise of standard deviation `level * rms(f)` (Box-Muller on an LCG).
fn noisy(f: &[f64], level: f64, mut state: u64) -> Vec<f64> {
    let mut unit = move || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let rms = (f.iter().map(|v| v * v).sum::<f64>() / f.len() as f64).sqrt();
    f.iter()
        .map(|v| {
            let r = (-2.0 * (1.0 - unit()).ln()).sqrt();
            v + level * rms * r * (std::f64::consts::TAU * unit()).cos()
        })
        .collect()
}

fn slow_data(n: usize) -> (Vec<f64>, Vec<f64>) {
    let model = LuGre::paper().with_sigma0(6.0).expect("valid");
    let tp = TurningPoints::new(&[0.0, 1.0, 0.5, 1.5]).expect("valid");
    let input = PiecewiseLinear::from_turning_points(&tp, 1.0).expect("valid");
    let p = input.period();
    // 3 periods of transient (exp(-3 a P) = exp(-36)), then 2 measured ones.
    let times = merge_times(&uniform_times(0.0, p, 5, n / 2), &input.knot_times(5));
    let mut out = Trajectory::default();
    Simulator::new(&model, Gamma::INFINITE, 0.0)
        .expect("valid")
        .at_times(&input, 5, &times, &mut out)
        .expect("finite");
    let from = out.range_between(3.0 * p, f64::INFINITY).start;
    let u = out.u[from..].to_vec();
    let f = noisy(&out.y[from..], 0.01, 1);
    (u, f)
}

fn full_data(n: usize) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let p = LuGreParams::canudas_de_wit_1995();
    let model = LuGre::from_params(p).expect("valid");
    let speeds = [1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 1e-1];
    let per_sweep = n / (2 * speeds.len());
    let (amp, mut t, mut u) = (1e-3, vec![0.0], vec![-1e-3]);
    for &v in &speeds {
        for target in [amp, -amp] {
            let (t0, u0) = (t[t.len() - 1], u[u.len() - 1]);
            let dur = f64::abs(target - u0) / v;
            for j in 1..=per_sweep {
                let x = j as f64 / per_sweep as f64;
                t.push(t0 + dur * x);
                u.push(u0 + (target - u0) * x);
            }
        }
    }
    let input = PiecewiseLinear::new(t.clone(), u.clone()).expect("valid");
    let mut out = Trajectory::default();
    Simulator::new(&model, Gamma::ONE, 0.0)
        .expect("valid")
        .at_knots(&input, 1, &mut out)
        .expect("finite");
    let f = noisy(&out.y, 0.01, 2);
    (t, u, f)
}

/// Two periods of `6 sin(2 pi t / 4)` sampled `n` times, the paper's model's force (from the
/// dense samples) plus 1 % noise.
fn sine_data(n: usize) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let t: Vec<f64> = (0..n).map(|i| 8.0 * i as f64 / (n - 1) as f64).collect();
    let u: Vec<f64> = t
        .iter()
        .map(|&t| 6.0 * (std::f64::consts::TAU * t / 4.0).sin())
        .collect();
    let input = PiecewiseLinear::new(t.clone(), u.clone()).expect("valid");
    let mut out = Trajectory::default();
    Simulator::new(&LuGre::paper(), Gamma::ONE, 0.0)
        .expect("valid")
        .at_knots(&input, 1, &mut out)
        .expect("finite");
    let f = noisy(&out.y, 0.01, 3);
    (t, u, f)
}

fn fit(c: &mut Criterion) {
    let mut group = c.benchmark_group("fit");
    let (u, f) = slow_data(100_000);
    let spec = FitSpec::new(Family::LuGre);
    group.sample_size(50);
    group.measurement_time(Duration::from_secs(10));
    group.bench_function(format!("slow/{}", u.len()), |b| {
        b.iter(|| fit_slow(black_box(&spec), black_box(&u), black_box(&f)).expect("fits"))
    });
    let (t, u, f) = full_data(100_000);
    let spec = FitSpec::new(Family::LuGre).set("beta", 2.0).expect("known");
    group.sample_size(10);
    group.measurement_time(Duration::from_secs(20));
    group.bench_function(format!("full/{}", u.len()), |b| {
        b.iter(|| fit_full(black_box(&spec), &t, &u, &f, FullOptions::default()).expect("fits"))
    });
    let (t, u, f) = sine_data(100_000);
    let spec = FitSpec::new(Family::LuGre)
        .set("sigma2", 0.0)
        .and_then(|s| s.fix("sigma2"))
        .and_then(|s| s.set("beta", 1.0))
        .expect("known");
    group.bench_function(format!("full_cubic/{}", u.len()), |b| {
        b.iter(|| {
            let motion = SmoothSamples::pchip(t.clone(), u.clone(), 1e-9).expect("valid");
            fit_full_smooth(black_box(&spec), &motion, &f, FullOptions::default()).expect("fits")
        })
    });
    group.finish();
}

criterion_group!(benches, fit);
criterion_main!(benches);
