//! The exact simulation of eq. 5 on sampled data (issue: >= 50 M samples per second per core
//! with the Stribeck g; two exponentials per sample). Throughput is in input samples per
//! second, each giving one output row (t, u, z, z', y); the sizes 10^3 to 10^7 show that the
//! time is linear in the length (the same throughput at every size).
//!
//! The input is a measured-looking displacement: 1 mm sine sweeps with micrometre noise, sampled
//! at 10 kHz, on the Canudas de Wit (1995) parameters (sigma0 = 1e5 N/m: stiff, and the noise
//! keeps reversing the pre-sliding state). The output trajectory is reused, so the timed loop
//! allocates nothing.

use criterion::{
    criterion_group, criterion_main, BenchmarkId, Criterion, SamplingMode, Throughput,
};
use lugre::{Gamma, LuGre, LuGreParams, PiecewiseLinear, Simulator, Trajectory};
use std::hint::black_box;

fn sampled_input(n: usize) -> PiecewiseLinear {
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    let dt = 1e-4;
    let t: Vec<f64> = (0..n).map(|i| i as f64 * dt).collect();
    let u: Vec<f64> = t
        .iter()
        .map(|&t| {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            let noise = ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 2e-6;
            1e-3 * (std::f64::consts::TAU * 0.5 * t).sin() + noise
        })
        .collect();
    PiecewiseLinear::new(t, u).expect("valid input")
}

fn exact(c: &mut Criterion) {
    let model = LuGre::from_params(LuGreParams::canudas_de_wit_1995()).expect("valid");
    let mut group = c.benchmark_group("simulate_exact_sampled");
    group.sample_size(10);
    for n in [1_000, 10_000, 100_000, 1_000_000, 10_000_000] {
        // From 10^6 samples an iteration takes milliseconds to a second: the same number of
        // iterations in each sample rather than a growing one.
        group.sampling_mode(if n >= 1_000_000 {
            SamplingMode::Flat
        } else {
            SamplingMode::Auto
        });
        let input = sampled_input(n);
        let mut out = Trajectory::with_capacity(n);
        for gamma in [Gamma::ONE, Gamma::INFINITE] {
            let sim = Simulator::new(&model, gamma, 0.0).expect("valid");
            group.throughput(Throughput::Elements(n as u64));
            let id = format!("{n}/gamma={}", gamma.value());
            group.bench_with_input(BenchmarkId::from_parameter(id), &input, |b, input| {
                b.iter(|| {
                    out.clear();
                    sim.at_knots(black_box(input), 1, &mut out).expect("finite");
                    black_box(out.y.last().copied())
                })
            });
        }
    }
    group.finish();
}

/// The cubic reading of samples of a smooth motion against the linear one, on 10^5 samples of
/// a 1 mm, 0.5 Hz sine at 10 kHz (Table I): building the interpolant and its subdivision to the
/// tolerance, the exact run on it, the output at the samples (the target: at most 3x
/// the linear reading).
fn cubic_reading(c: &mut Criterion) {
    use lugre::simulate::SmoothSamples;
    let model = LuGre::from_params(LuGreParams::canudas_de_wit_1995()).expect("valid");
    let n = 100_000;
    let t: Vec<f64> = (0..n).map(|i| i as f64 * 1e-4).collect();
    let u: Vec<f64> = t
        .iter()
        .map(|&t| 1e-3 * (std::f64::consts::TAU * 0.5 * t).sin())
        .collect();
    let sim = Simulator::new(&model, Gamma::ONE, 0.0).expect("valid");
    let mut group = c.benchmark_group("simulate_cubic_reading");
    group.sample_size(20);
    group.throughput(Throughput::Elements(n as u64));
    let mut out = Trajectory::with_capacity(n);
    let input = PiecewiseLinear::new(t.clone(), u.clone()).expect("valid");
    group.bench_function("linear", |b| {
        b.iter(|| {
            out.clear();
            sim.at_knots(black_box(&input), 1, &mut out)
                .expect("finite");
            black_box(out.y.last().copied())
        })
    });
    for tol in [1e-6, 1e-9] {
        group.bench_function(format!("cubic/tol={tol:e}"), |b| {
            b.iter(|| {
                out.clear();
                let motion = SmoothSamples::pchip(t.clone(), u.clone(), tol).expect("valid");
                sim.at_samples(&motion, &mut out).expect("finite");
                black_box(out.y.last().copied())
            })
        });
    }
    group.finish();
}

criterion_group!(benches, exact, cubic_reading);
criterion_main!(benches);
