//! The loop and every minor loop with their energies of the models of `lugre::zoo` for
//! periodic inputs of random turning points, in turning points per second: every model of the
//! zoo's table on its defaults through `ZooModel` (target: at least 5 x 10^6 turning points per
//! second each), Maxwell-slip with 100 elements (target: at least 10^6) and Prandtl-Ishlinskii
//! with 100 play operators (one segment map of every element per turning point), Bouc-Wen at
//! n = 1 (closed form) and n = 1.5, 2.5 (tables and Newton): one state, its periodic state by
//! Newton on the period map; the elasto-plastic model, its `z_max` a third of the largest step so
//! that segments stick, slip in the blend and saturate.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use lugre::zoo::{BoucWen, ElastoPlastic, MaxwellSlip, PrandtlIshlinskii, Segmental, ZooLoop};
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
    for spec in lugre::zoo::MODELS {
        let model = lugre::zoo::ZooModel::new(spec.name, &[]).expect("the defaults are valid");
        let mut group = c.benchmark_group(format!("defaults_{}", spec.name));
        group.sample_size(10);
        for n in [1_000, 100_000] {
            // The input's range spans the defaults' break-away displacements (up to a few m).
            let tp = random_turning_points(n, 8.0);
            group.throughput(Throughput::Elements(n as u64));
            group.bench_with_input(BenchmarkId::from_parameter(n), &tp, |b, tp| {
                b.iter(|| black_box(model.loops(black_box(tp)).expect("finite").loops().len()))
            });
        }
        group.finish();
    }
    loops(c, "maxwell_slip_100", maxwell.bank());
    loops(c, "prandtl_ishlinskii_100", prandtl.bank());
    for n in [1.0, 1.5, 2.5] {
        let model = BoucWen::new(0.5, 1.0, 4.0, 0.75, n).expect("valid parameters");
        loops(c, &format!("bouc_wen_n{n}"), &model);
    }
    let elastoplastic = ElastoPlastic::new(1.0, 0.2, 0.3, 0.1).expect("valid parameters");
    loops(c, "elastoplastic", &elastoplastic);
}

/// The loops of `model` for 10^3 and 10^5 random turning points.
fn loops<M: Segmental>(c: &mut Criterion, name: &str, model: &M) {
    let mut group = c.benchmark_group(name);
    group.sample_size(10);
    for n in [1_000, 100_000] {
        let tp = random_turning_points(n, 1.0);
        group.throughput(Throughput::Elements(n as u64));
        group.bench_with_input(BenchmarkId::from_parameter(n), &tp, |b, tp| {
            b.iter(|| {
                let hl = ZooLoop::new(model, black_box(tp)).expect("finite");
                black_box(hl.loops().len())
            })
        });
    }
    group.finish();
}

criterion_group!(benches, zoo);
criterion_main!(benches);
