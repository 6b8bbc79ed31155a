//! The steady-state sweep (issue: a 50 x 50 grid, amplitudes over four decades and
//! frequencies over three, on the Canudas de Wit et al. (1995) Table I parameters, in under
//! 1 s on two cores). Each point is the fixed point of the period map plus one replay with the
//! quadratures (`lugre::sweep`); the grid runs on every core the machine has.

use criterion::{criterion_group, criterion_main, Criterion, SamplingMode};
use lugre::sweep::{parse_values, Point, Request};
use lugre::{LuGre, LuGreParams, Tolerance};
use std::hint::black_box;

fn grid(c: &mut Criterion) {
    let model = LuGre::from_params(LuGreParams::canudas_de_wit_1995()).expect("valid");
    let amplitudes = parse_values("amplitudes", "1e-7:1e-3:50").expect("valid");
    let frequencies = parse_values("frequencies", "0.1:100:50").expect("valid");
    let request = Request::new(amplitudes, frequencies).expect("valid");
    let mut group = c.benchmark_group("sweep");
    group.sample_size(10);
    group.sampling_mode(SamplingMode::Flat);
    group.bench_function("grid_50x50_canudas1995_all_cores", |b| {
        b.iter(|| black_box(request.run(&model, None).expect("finite")))
    });
    // One point on one core, the unit the grid is made of.
    let tol = Tolerance::new(Request::DEFAULT_TOLERANCE).expect("valid");
    group.sampling_mode(SamplingMode::Auto);
    group.bench_function("point_1e-5m_1Hz", |b| {
        b.iter(|| black_box(Point::compute(&model, 1e-5, 1.0, 0.0, tol, 0).expect("finite")))
    });
    group.finish();
}

criterion_group!(benches, grid);
criterion_main!(benches);
