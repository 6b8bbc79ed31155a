//! The hysteresis loop, every minor loop and their energies for periodic inputs of 10^3 to 10^7
//! random turning points (the target is set at 10^6, with linear scaling from 10^3 to 10^7).
//! Throughput is in turning points per second; equal throughput across sizes means linear
//! scaling.
//!
//! * `loop_and_minor_loops`: `HysteresisLoop::new`, which computes `y°` at every turning point
//!   and every loop with its energies and nesting (the `LoopTable`), for the paper's model
//!   (`a = 1/2`: pieces of `a l < 1/2`, the series path);
//! * `stiff`: the same for a realistic stiffness (`sigma0 = 1e5`, `g0 = 1.5`, steps of 0.01 to
//!   1 mm: `a l` from 7 to 700, the exponential path);
//! * `as_records`: `new` plus `loops()`, the same loops as `Vec<Loop>` ordered by start;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use lugre::{HysteresisLoop, LuGre, LuGreParams};
use std::hint::black_box;

mod common;
use common::random_turning_points;

fn loops(c: &mut Criterion) {
    let paper = LuGre::paper().rate_independent();
    let stiff = LuGre::from_params(LuGreParams {
        sigma0: 1e5,
        sigma1: 316.2,
        fc: 1.0,
        fs: 1.5,
        vs: 1e-3,
        ..LuGreParams::default()
    })
    .expect("valid parameters")
    .rate_independent();
    let sizes = [1_000, 10_000, 100_000, 1_000_000, 10_000_000];
    for (name, model, scale, records) in [
        ("loop_and_minor_loops", paper, 1.0, false),
        ("stiff", stiff, 1e-3, false),
        ("as_records", paper, 1.0, true),
    ] {
        let mut group = c.benchmark_group(name);
        group.sample_size(10);
        for n in sizes {
            if name != "loop_and_minor_loops" && !(n == 1_000 || n == 1_000_000) {
                continue;
            }
            let tp = random_turning_points(n, scale);
            group.throughput(Throughput::Elements(n as u64));
            group.bench_with_input(BenchmarkId::from_parameter(n), &tp, |b, tp| {
                b.iter(|| {
                    let hl = HysteresisLoop::new(model, black_box(tp)).expect("finite");
                    if records {
                        black_box(hl.loops().len())
                    } else {
                        black_box(hl.loop_table().len())
                    }
                })
            });
        }
        group.finish();
    }
}

criterion_group!(benches, loops);
criterion_main!(benches);
