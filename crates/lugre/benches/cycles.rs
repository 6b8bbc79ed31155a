//! Rainflow counting of a measured history (issue: >= 100 M samples/s per core on a random
//! walk), with reversals, cycles and closures, and the same with y* and energies. Throughput
//! is in samples per second; the lengths 10^3 to 10^7 show that the time is linear in the
//! length (the same throughput at every size).

use criterion::{
    criterion_group, criterion_main, BenchmarkId, Criterion, SamplingMode, Throughput,
};
use lugre::{Cycle, CycleColumns, CycleCounter, CycleSink, LuGre, Reversal};
use std::hint::black_box;

/// The history lengths: the walk's first `n` samples.
const SIZES: [usize; 5] = [1_000, 10_000, 100_000, 1_000_000, 10_000_000];

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
    let walk = random_walk(SIZES[SIZES.len() - 1]);
    let model = LuGre::paper().rate_independent();
    let mut group = c.benchmark_group("cycles_random_walk");
    group.sample_size(10);
    for n in SIZES {
        let u = &walk[..n];
        group.throughput(Throughput::Elements(n as u64));
        // From 10^6 samples an iteration takes milliseconds: the same number of iterations in
        // each sample rather than a growing one.
        group.sampling_mode(if n >= 1_000_000 {
            SamplingMode::Flat
        } else {
            SamplingMode::Auto
        });
        // Blocks of 4096 samples, as `lugre cycles` feeds the counter while it reads a file.
        group.bench_with_input(BenchmarkId::new("count", n), u, |b, u| {
            b.iter(|| {
                let mut sink = Checksum::default();
                let mut counter = CycleCounter::new(0.0).expect("valid gate");
                for block in black_box(u).chunks(4096) {
                    counter.push_all(block, &mut sink).expect("finite");
                }
                let s = counter.finish(&mut sink).expect("long enough");
                black_box((s, sink.sum, sink.reversals))
            })
        });
        // One sample at a time.
        group.bench_with_input(BenchmarkId::new("count_per_sample", n), u, |b, u| {
            b.iter(|| {
                let mut sink = Checksum::default();
                let mut counter = CycleCounter::new(0.0).expect("valid gate");
                for &x in black_box(u) {
                    counter.push(x, &mut sink).expect("finite");
                }
                let s = counter.finish(&mut sink).expect("long enough");
                black_box((s, sink.sum, sink.reversals))
            })
        });
        // Into columns (what the Python binding does): every reversal, cycle and closure kept
        // in memory, the columns' memory reused from one iteration to the next (the time of
        // counting and writing, not of getting fresh memory); then the cycle table alone.
        for (name, keep) in [
            ("count_into_columns", true),
            ("count_into_columns_table", false),
        ] {
            let mut columns = CycleColumns::new().with_reversals(keep).with_closures(keep);
            group.bench_with_input(BenchmarkId::new(name, n), u, |b, u| {
                b.iter(|| {
                    columns.clear();
                    let mut counter = CycleCounter::new(0.0).expect("valid gate");
                    counter
                        .push_all(black_box(u), &mut columns)
                        .expect("finite");
                    let s = counter.finish(&mut columns).expect("long enough");
                    black_box((s, columns.range.len()))
                })
            });
        }
        group.bench_with_input(BenchmarkId::new("count_with_energy", n), u, |b, u| {
            b.iter(|| {
                let mut sink = Checksum::default();
                let mut counter = CycleCounter::new(0.0)
                    .and_then(|c| c.with_energy(model, 0.0))
                    .expect("valid");
                for block in black_box(u).chunks(4096) {
                    counter.push_all(block, &mut sink).expect("finite");
                }
                let s = counter.finish(&mut sink).expect("long enough");
                black_box((s, sink.sum, sink.reversals))
            })
        });
    }
    group.finish();
}

/// The chunked count (issue: a chunk counted at >= 90 % of the single pass's samples/s; a merge
/// in O(size of the residues)): one chunk of 10^7 samples by `count_chunk` against the single
/// pass into the same columns (closures, no reversals, fresh columns each time, as both
/// return them), the 63 merges of 64 chunks' summaries, and the energy pass of a chunk
/// against the single pass with energies.
fn chunked(c: &mut Criterion) {
    use lugre::cycles::chunk::{count_chunk, count_chunk_energy, merge, ArcSpan};
    let n = SIZES[SIZES.len() - 1];
    let walk = random_walk(n);
    let mut group = c.benchmark_group("cycles_chunked");
    group.sample_size(10);
    group.sampling_mode(SamplingMode::Flat);
    group.throughput(Throughput::Elements(n as u64));
    group.bench_function(BenchmarkId::new("single_pass_table", n), |b| {
        b.iter(|| {
            // Reserved up front as `lugre.cycles` and `count_chunk` do.
            let mut columns = CycleColumns::new().with_reversals(false);
            columns.reserve_for_samples(n);
            let mut counter = CycleCounter::new(0.0).expect("valid gate");
            counter
                .push_all(black_box(&walk), &mut columns)
                .expect("finite");
            let s = counter.finish(&mut columns).expect("long enough");
            black_box((s, columns.range.len()))
        })
    });
    group.bench_function(BenchmarkId::new("count_chunk", n), |b| {
        b.iter(|| {
            let (s, rows) = count_chunk(black_box(&walk), 1 << 40).expect("finite");
            black_box((s.residue().len(), rows.range.len()))
        })
    });
    let leaves: Vec<_> = walk
        .chunks(n / 64)
        .enumerate()
        .map(|(k, u)| count_chunk(u, (k * (n / 64)) as u64).expect("finite").0)
        .collect();
    group.throughput(Throughput::Elements(leaves.len() as u64 - 1));
    group.bench_function(BenchmarkId::new("merge_64_leaves", n), |b| {
        b.iter(|| {
            let mut acc = leaves[0].clone();
            let mut open = 0;
            for leaf in &leaves[1..] {
                let (m, o) = merge(&acc, leaf).expect("adjacent");
                acc = m;
                open += o.len();
            }
            black_box((acc.residue().len(), open))
        })
    });
    // With energies: the chunk's count from its entry state with the parts of 16 arcs that
    // span chunks (a 10^7-sample chunk of a random walk has about 10), against the single
    // pass with energies into the same columns.
    let model = LuGre::paper().rate_independent();
    let spans: Vec<ArcSpan> = (0..16)
        .map(|k| ArcSpan {
            id: k,
            from: (k % 2 == 0).then_some((1 << 40) + (k * n / 16) as u64),
            to: None,
        })
        .collect();
    group.throughput(Throughput::Elements(n as u64));
    group.bench_function(BenchmarkId::new("single_pass_energy_table", n), |b| {
        b.iter(|| {
            let mut columns = CycleColumns::new().with_reversals(false).with_energy(true);
            columns.reserve_for_samples(n);
            let mut counter = CycleCounter::new(0.0)
                .and_then(|c| c.with_energy(model, 0.0))
                .expect("valid");
            counter
                .push_all(black_box(&walk), &mut columns)
                .expect("finite");
            let s = counter.finish(&mut columns).expect("long enough");
            black_box((s, columns.range.len()))
        })
    });
    group.bench_function(BenchmarkId::new("count_chunk_energy", n), |b| {
        b.iter(|| {
            let (rows, pass) =
                count_chunk_energy(black_box(&walk), 1 << 40, Some(0.0), 0.0, model, &spans)
                    .expect("finite");
            black_box((rows.range.len(), pass.y_last))
        })
    });
    group.finish();
}

criterion_group!(benches, cycles, chunked);
criterion_main!(benches);
