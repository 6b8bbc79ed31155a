//! The loop and every minor loop with their energies of the Masing models of `lugre::zoo` for
//! periodic inputs of random turning points, in turning points per second: Maxwell-slip with
//! 100 elements (target: at least 10^6 turning points per second) and Prandtl-Ishlinskii with
//! 100 play operators. The work per turning point is one segment map of every element.
//! The elasto-plastic model (target: at least 5 x 10^6 turning points per second), its
//! `z_max` a third of the largest step so that segments stick, slip in the blend and saturate.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use lugre::zoo::{ElastoPlastic, MaxwellSlip, PrandtlIshlinskii, Segmental};
use std::hint::black_box;

mod common;
use common::random_turning_points;

fn zoo(c: &mut Criterion) {
    let elements = 100;
    // Break-away displacements and thresholds spread over the input's range (0 to 1).
    let k: Vec<f64> = (0..elements).map(|i| 1.0 + i as f64).collect();
    let f: Vec<f64> = (0..elements)
        .map(|i| k[i] * 0.5 * (i + 1) as f64 / elements as f64)
        .collect();
    let maxwell = MaxwellSlip::new(&k, &f).expect("valid parameters");
    let r: Vec<f64> = (0..elements)
        .map(|i| 0.5 * i as f64 / elements as f64)
        .collect();
    let w: Vec<f64> = (0..elements).map(|i| 1.0 / (1 + i) as f64).collect();
    let prandtl = PrandtlIshlinskii::new(1.0, &r, &w).expect("valid parameters");
    bench_loops(c, "maxwell_slip_100", maxwell.bank());
    bench_loops(c, "prandtl_ishlinskii_100", prandtl.bank());
    let elastoplastic = ElastoPlastic::new(1.0, 0.2, 0.3, 0.1).expect("valid parameters");
    bench_loops(c, "elastoplastic", &elastoplastic);
}

/// The loops of `model` for 10^3 and 10^5 random turning points.
fn bench_loops<M: Segmental>(c: &mut Criterion, name: &str, model: &M) {
    let mut group = c.benchmark_group(name);
    group.sample_size(10);
    for n in [1_000, 100_000] {
        let tp = random_turning_points(n, 1.0);
        group.throughput(Throughput::Elements(n as u64));
        group.bench_with_input(BenchmarkId::from_parameter(n), &tp, |b, tp| {
            b.iter(|| {
                let hl = lugre::zoo::ZooLoop::new(model, black_box(tp)).expect("finite");
                black_box(hl.loops().len())
            })
        });
    }
    group.finish();
}

criterion_group!(benches, zoo);
criterion_main!(benches);
