//! Rainflow counting of a measured history (issue: >= 100 M samples/s per core on a random
//! walk), with reversals, cycles and closures, and the same with y* and energies. Throughput
//! is in samples per second.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use lugre::{Cycle, CycleCounter, CycleSink, EnergyCycleCounter, LuGre, Reversal};
use std::hint::black_box;

const SAMPLES: usize = 10_000_000;

/// A random walk with uniform steps in [-0.5, 0.5) from a fixed LCG (about one reversal every
/// 2 samples, the worst case for the counter).
fn random_walk(n: usize) -> Vec<f64> {
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut u = 0.0;
    (0..n)
        .map(|_| {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            u += (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
            u
        })
        .collect()
}

/// Consumes everything the counter reports, as a caller writing it out would read it.
#[derive(Default)]
struct Checksum {
    reversals: u64,
    sum: f64,
}

impl CycleSink for Checksum {
    #[inline]
    fn reversal(&mut self, r: Reversal) {
        self.reversals += r.index & 1;
    }
    #[inline]
    fn cycle(&mut self, c: Cycle) {
        self.sum += c.range * c.count + c.closure.map_or(0.0, |cl| cl.position);
    }
}

fn cycles(c: &mut Criterion) {
    let u = random_walk(SAMPLES);
    let mut group = c.benchmark_group("cycles_random_walk");
    group.sample_size(10);
    group.throughput(Throughput::Elements(SAMPLES as u64));
    // Blocks of 4096 samples, as `lugre cycles` feeds the counter while it reads a file.
    group.bench_function("count", |b| {
        b.iter(|| {
            let mut sink = Checksum::default();
            let mut counter = CycleCounter::new(0.0).expect("valid gate");
            for block in black_box(&u).chunks(4096) {
                counter.push_all(block, &mut sink).expect("finite");
            }
            let s = counter.finish(&mut sink).expect("long enough");
            black_box((s, sink.sum, sink.reversals))
        })
    });
    // One sample at a time.
    group.bench_function("count_per_sample", |b| {
        b.iter(|| {
            let mut sink = Checksum::default();
            let mut counter = CycleCounter::new(0.0).expect("valid gate");
            for &x in black_box(&u) {
                counter.push(x, &mut sink).expect("finite");
            }
            let s = counter.finish(&mut sink).expect("long enough");
            black_box((s, sink.sum, sink.reversals))
        })
    });
    let model = LuGre::paper().rate_independent();
    group.bench_function("count_with_energy", |b| {
        b.iter(|| {
            let mut sink = Checksum::default();
            let mut counter = EnergyCycleCounter::new(0.0, model, 0.0).expect("valid");
            for block in black_box(&u).chunks(4096) {
                counter.push_all(block, &mut sink).expect("finite");
            }
            let s = counter.finish(&mut sink).expect("long enough");
            black_box((s, sink.sum, sink.reversals))
        })
    });
    group.finish();
}

criterion_group!(benches, cycles);
criterion_main!(benches);
