//! The hysteresis loop, every minor loop and their energies for periodic inputs of 10^3 to 10^7
//! random turning points (issue 8: 10^6, and linear scaling from 10^3 to 10^7). Throughput is
//! in turning points per second; equal throughput across sizes means linear scaling.
//!
//! * `loop_and_minor_loops`: `HysteresisLoop::new`, which computes `y°` at every turning point
//!   and every loop with its energies and nesting (the `LoopTable`), for the paper's model
//!   (`a = 1/2`: pieces of `a l < 1/2`, the series path);
//! * `stiff`: the same for a realistic stiffness (`sigma0 = 1e5`, `g0 = 1.5`, steps of 0.01 to
//!   1 mm: `a l` from 7 to 700, the exponential path);
//! * `as_records`: `new` plus `loops()`, the same loops as `Vec<Loop>` ordered by start;
//! * `floor`: what any engine must at least do for the same input, with none of the
//!   arithmetic of the loops: `pairing` (the rainflow pairing alone, three indices per loop,
//!   into a reused vector), `pairing_6_columns` (plus writing `y` at every turning point and
//!   the least a loop table holds, six values per loop: start, reversal, end, W, dV, D),
//!   `pairing_12_columns` (the `LoopTable`'s twelve) and `pairing_y_12_columns` (plus `y°` by
//!   the closed form, one `relax` per piece, still no energies), all into memory already
//!   mapped. Lower bounds on the time of `loop_and_minor_loops`: they skip the rotation to the
//!   maximum, ties, parents and depths, every energy, and the page faults of a fresh output.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use lugre::hysteresis::relax;
use lugre::{HysteresisLoop, LuGre, LuGreParams, RateIndependent, TurningPoints};
use std::hint::black_box;

/// Alternating random steps in [0.01, 1) times `scale`: every point is a reversal. A fixed LCG
/// keeps runs comparable.
fn random_turning_points(n: usize, scale: f64) -> TurningPoints {
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut u = 0.0;
    let values: Vec<f64> = (0..n)
        .map(|i| {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            let r = (state >> 11) as f64 / (1u64 << 53) as f64;
            let step = scale * (0.01 + 0.99 * r);
            u += if i % 2 == 0 { step } else { -step };
            u
        })
        .collect();
    TurningPoints::new(&values).expect("valid input")
}

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

/// The rainflow pairing of `u` (the four-point rule of `lugre::minor`, without its treatment of
/// ties), calling `on_loop(start, reversal, end)` for each pair as it closes. Two sentinel
/// entries at the bottom of the stack, whose range nothing exceeds, spare the length test.
#[inline(always)]
fn pairing(
    u: &[f64],
    stack: &mut Vec<(u32, f64)>,
    mut on_point: impl FnMut(usize, f64),
    mut on_loop: impl FnMut(u32, u32, usize, f64, f64),
) {
    stack.clear();
    stack.extend([(0, -1e300), (0, 1e300)]);
    for (p, &x) in u.iter().enumerate() {
        on_point(p, x);
        loop {
            let m = stack.len();
            let ((ja, a), (jb, b)) = (stack[m - 2], stack[m - 1]);
            if (x - b).abs() < (b - a).abs() {
                break;
            }
            on_loop(ja, jb, p, a, b);
            stack.truncate(m - 2);
        }
        stack.push((p as u32, x));
    }
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
    }
    group.finish();
}

criterion_group!(benches, loops, floor);
criterion_main!(benches);
