//! The hysteresis loop, every minor loop and their energies for periodic inputs of 10^3 to 10^7
//! random turning points (issue 8: 10^6, and linear scaling from 10^3 to 10^7). Throughput is
//! in turning points per second; equal throughput across sizes means linear scaling.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use lugre::{HysteresisLoop, LuGre, TurningPoints};
use std::hint::black_box;

/// Alternating random steps in [0.01, 1): every point is a reversal. A fixed LCG keeps runs
/// comparable.
fn random_turning_points(n: usize) -> TurningPoints {
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut u = 0.0;
    let values: Vec<f64> = (0..n)
        .map(|i| {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            let r = (state >> 11) as f64 / (1u64 << 53) as f64;
            let step = 0.01 + 0.99 * r;
            u += if i % 2 == 0 { step } else { -step };
            u
        })
        .collect();
    TurningPoints::new(&values).expect("valid input")
}

fn loops(c: &mut Criterion) {
    let model = LuGre::paper().rate_independent();
    let mut group = c.benchmark_group("loop_and_minor_loops");
    group.sample_size(10);
    for n in [1_000, 10_000, 100_000, 1_000_000, 10_000_000] {
        let tp = random_turning_points(n);
        group.throughput(Throughput::Elements(n as u64));
        group.bench_with_input(BenchmarkId::from_parameter(n), &tp, |b, tp| {
            b.iter(|| {
                let hl = HysteresisLoop::new(model, black_box(tp)).expect("finite");
                black_box(hl.loops())
            })
        });
    }
    group.finish();
}

criterion_group!(benches, loops);
criterion_main!(benches);
