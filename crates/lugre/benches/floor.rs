//! Lower bounds on any loop engine: parts of the work `HysteresisLoop::new` does, timed on
//! their own to show where the engine's time goes and what any design must spend (the
//! `loops` bench times the engine itself on the same inputs). Needs the hidden internals:
//! `cargo bench -p lugre --features bench-internals --bench floor`.
//!
//! `pairing`: the rainflow pairing alone, three indices per loop, into a reused
//!   vector (a stack and a branch per step, as the engine does it); `pairing_interleaved`: the
//!   same for four quarters of the period at once, branch-free (residues left unpaired);
//!   `pairing_6_columns`: `pairing` plus writing `y` at every turning point and the least a
//!   loop table holds, six values per loop (start, reversal, end, W, dV, D);
//!   `pairing_12_columns`: the `LoopTable`'s twelve; `pairing_y_12_columns`: plus `y°` by the
//!   closed form, one `relax` per piece (no energies); `piece_arithmetic`: the engine's own
//!   per-piece arithmetic (families, closed forms, double-double sums) into one running sum,
//!   no rainflow. The outputs go to memory already mapped; none of them ties, nests or rotates.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use lugre::floor::relax;
use lugre::{LuGre, RateIndependent};
use std::hint::black_box;

mod common;
use common::random_turning_points;

/// The bottom of every pairing stack: two entries whose range nothing exceeds, so that a pair
/// is always there to test and the stack's length never is.
const SENTINELS: [(u32, f64); 2] = [(0, -1e300), (0, 1e300)];

/// Whether the next point `x` closes the pair `(a, b)` on top of the stack: the four-point rule
/// of `lugre::minor`, without its treatment of ties.
#[inline(always)]
fn closes(a: f64, b: f64, x: f64) -> bool {
    (x - b).abs() >= (b - a).abs()
}

/// The rainflow pairing of `u`, calling `on_loop(start, reversal, end, u_start, u_reversal)`
/// for each pair as it closes.
#[inline(always)]
fn pairing(
    u: &[f64],
    stack: &mut Vec<(u32, f64)>,
    mut on_point: impl FnMut(usize, f64),
    mut on_loop: impl FnMut(u32, u32, usize, f64, f64),
) {
    stack.clear();
    stack.extend(SENTINELS);
    for (p, &x) in u.iter().enumerate() {
        on_point(p, x);
        loop {
            let m = stack.len();
            let ((ja, a), (jb, b)) = (stack[m - 2], stack[m - 1]);
            if !closes(a, b, x) {
                break;
            }
            on_loop(ja, jb, p, a, b);
            stack.truncate(m - 2);
        }
        stack.push((p as u32, x));
    }
}

/// One chunk of a period paired on a stack of its own, one step at a time with no branch on
/// the data: a step pops the top pair (and writes it) or pushes the next point. Chunks in turn
/// (see [`pairing_interleaved`]) keep the processor busy while each step waits on the last.
struct Chunk {
    stack: Vec<(u32, f64)>,
    top: usize,
    next: usize,
    end: usize,
    loops: Vec<(u32, u32, u32)>,
    count: usize,
}

impl Chunk {
    fn new(len: usize) -> Self {
        let stack = vec![(0, 0.0); len + 3];
        let loops = vec![(0, 0, 0); len / 2 + 2];
        Self {
            stack,
            top: 0,
            next: 0,
            end: 0,
            loops,
            count: 0,
        }
    }

    /// Ready to pair `points` (at most the length it was made for).
    fn reset(&mut self, points: std::ops::Range<usize>) {
        self.stack[..2].copy_from_slice(&SENTINELS);
        (self.top, self.next, self.end, self.count) = (2, points.start, points.end, 0);
    }

    #[inline(always)]
    fn step(&mut self, u: &[f64]) {
        let x = u[self.next];
        let ((ja, a), (jb, b)) = (self.stack[self.top - 2], self.stack[self.top - 1]);
        let close = closes(a, b, x);
        self.loops[self.count] = (ja, jb, self.next as u32);
        self.stack[self.top] = (self.next as u32, x);
        self.count += usize::from(close);
        self.top = if close { self.top - 2 } else { self.top + 1 };
        self.next += usize::from(!close);
    }
}

/// The pairing of four quarters of `u` at once (their residues, a few dozen points, are left
/// unpaired), each into its chunk: what a branch-free pairing could gain over [`pairing`]'s
/// mispredicted branches.
fn pairing_interleaved(u: &[f64], chunks: &mut [Chunk; 4]) -> usize {
    let q = u.len() / 4;
    for (i, c) in chunks.iter_mut().enumerate() {
        c.reset(i * q..if i == 3 { u.len() } else { (i + 1) * q });
    }
    let [c0, c1, c2, c3] = chunks;
    while c0.next < c0.end && c1.next < c1.end && c2.next < c2.end && c3.next < c3.end {
        c0.step(u);
        c1.step(u);
        c2.step(u);
        c3.step(u);
    }
    chunks
        .iter_mut()
        .map(|c| {
            while c.next < c.end {
                c.step(u);
            }
            c.count
        })
        .sum()
}

/// An output written with no arithmetic: `y` at every turning point and `COLUMNS` values per
/// loop, into buffers already mapped (`table`: the columns one after the other), so that not
/// even the page faults of a fresh output count.
fn pairing_and_table<const COLUMNS: usize>(
    u: &[f64],
    y_of: impl Fn(f64) -> f64,
    stack: &mut Vec<(u32, f64)>,
    y: &mut [f64],
    table: &mut [f64],
) -> usize {
    let rows = table.len() / COLUMNS;
    let mut row = 0;
    pairing(
        u,
        stack,
        |p, x| y[p] = y_of(x),
        |ja, jb, p, a, b| {
            let values = [f64::from(ja), f64::from(jb), p as f64, a, b, a + b];
            for c in 0..COLUMNS {
                table[c * rows + row] = values[c % 6];
            }
            row += 1;
        },
    );
    row
}

/// `y°` by the closed form from `y = 0` (not the periodic value: the cost is the same).
fn closed_form(model: RateIndependent, u: &[f64]) -> impl Fn(f64) -> f64 {
    let (a, sigma0) = (model.a(), model.sigma0());
    let state = std::cell::Cell::new((u[0], 0.0));
    move |x| {
        let (u_prev, y_prev) = state.get();
        let du = x - u_prev;
        let y = relax(y_prev, a * du.abs(), sigma0 * du);
        state.set((x, y));
        y
    }
}

fn floor(c: &mut Criterion) {
    let paper = LuGre::paper().rate_independent();
    let mut group = c.benchmark_group("floor");
    group.sample_size(10);
    for n in [1_000, 1_000_000] {
        let tp = random_turning_points(n, 1.0);
        let u = tp.values();
        group.throughput(Throughput::Elements(n as u64));
        group.bench_with_input(BenchmarkId::new("pairing", n), u, |b, u| {
            let mut stack = Vec::with_capacity(64);
            let mut rows: Vec<(u32, u32, usize)> = Vec::with_capacity(n / 2 + 1);
            b.iter(|| {
                rows.clear();
                pairing(
                    black_box(u),
                    &mut stack,
                    |_, _| {},
                    |ja, jb, p, _, _| rows.push((ja, jb, p)),
                );
                black_box(rows.len())
            })
        });
        group.bench_with_input(BenchmarkId::new("pairing_interleaved", n), u, |b, u| {
            let mut chunks = [0; 4].map(|_| Chunk::new(n / 4 + 3));
            b.iter(|| pairing_interleaved(black_box(u), &mut chunks))
        });
        let mut stack = Vec::with_capacity(64);
        let (mut y, mut table) = (vec![0.0; n], vec![0.0; 12 * (n / 2 + 1)]);
        // The least any loop engine must write: where each loop starts, turns and ends, and
        // its W, dV and D.
        group.bench_with_input(BenchmarkId::new("pairing_6_columns", n), u, |b, u| {
            b.iter(|| {
                let table = &mut table[..6 * (n / 2 + 1)];
                pairing_and_table::<6>(black_box(u), |x| x, &mut stack, &mut y, table)
            })
        });
        // The `LoopTable`'s width.
        group.bench_with_input(BenchmarkId::new("pairing_12_columns", n), u, |b, u| {
            b.iter(|| pairing_and_table::<12>(black_box(u), |x| x, &mut stack, &mut y, &mut table))
        });
        group.bench_with_input(BenchmarkId::new("pairing_y_12_columns", n), u, |b, u| {
            b.iter(|| {
                let y_of = closed_form(paper, u);
                pairing_and_table::<12>(black_box(u), y_of, &mut stack, &mut y, &mut table)
            })
        });
        // The engine's own per-piece arithmetic (families, closed forms, double-double sums) in
        // one running sum, without the rainflow.
        group.bench_with_input(BenchmarkId::new("piece_arithmetic", n), u, |b, u| {
            b.iter(|| lugre::floor::piece_arithmetic(paper, black_box(u), &mut y))
        });
    }
    group.finish();
}

criterion_group!(benches, floor);
criterion_main!(benches);
