//! The `cargo bench -p lugre` workloads (loops, cycles, simulate, dynamics, fit) as one program
//! that runs one case a given number of times, so that the work of a case can be counted in
//! instructions (`valgrind --tool=cachegrind`), which the load of a shared machine does not
//! change, at two commits. Inputs and calls are those of `crates/lugre/benches/*.rs`.
//!
//!     bench/instructions.sh BEFORE AFTER     # builds this at both commits, counts every case
//!
//! Usage: `workloads CASE ITERATIONS` (0 iterations: the inputs only, to subtract).
//!
//! The inputs are restated here rather than shared with the benches: this file must build
//! against older commits too, where they live inside the bench files.

use lugre::dynamics::{Scenario, Tolerances};
use lugre::fit::{fit_full, fit_full_smooth, fit_slow, Family, FitSpec, FullOptions};
use lugre::simulate::{merge_times, uniform_times, SmoothSamples};
use lugre::{
    Cycle, CycleColumns, CycleCounter, CycleSink, Gamma, HysteresisLoop, LuGre, LuGreParams,
    PiecewiseLinear, Reversal, Simulator, Trajectory, TurningPoints,
};
use std::hint::black_box;

/// The counter with energies (`CycleCounter::with_energy`; `EnergyCycleCounter` before
/// 603662e: `bench/instructions.sh` rewrites this line for such commits).
macro_rules! energy_counter {
    ($m:expr) => {
        CycleCounter::new(0.0).and_then(|c| c.with_energy($m, 0.0))
    };
}

fn lcg(state: &mut u64) -> f64 {
    *state = state
        .wrapping_mul(6_364_136_223_846_793_005)
        .wrapping_add(1_442_695_040_888_963_407);
    (*state >> 11) as f64 / (1u64 << 53) as f64
}

/// benches/common: alternating random steps in [0.01, 1) times `scale`.
fn random_turning_points(n: usize, scale: f64) -> TurningPoints {
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut u = 0.0;
    let values: Vec<f64> = (0..n)
        .map(|i| {
            let step = scale * (0.01 + 0.99 * lcg(&mut state));
            u += if i % 2 == 0 { step } else { -step };
            u
        })
        .collect();
    TurningPoints::new(&values).expect("valid input")
}

/// benches/cycles: a random walk with uniform steps in [-0.5, 0.5).
fn random_walk(n: usize) -> Vec<f64> {
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut u = 0.0;
    (0..n)
        .map(|_| {
            u += lcg(&mut state) - 0.5;
            u
        })
        .collect()
}

#[derive(Default)]
struct Checksum {
    reversals: u64,
    sum: f64,
}

impl CycleSink for Checksum {
    fn reversal(&mut self, r: Reversal) {
        self.reversals += r.index & 1;
    }
    fn cycle(&mut self, c: Cycle) {
        self.sum += c.range * c.count + c.closure.map_or(0.0, |cl| cl.position);
    }
}

/// benches/simulate: 1 mm sine sweeps with micrometre noise at 10 kHz.
fn sampled_input(n: usize) -> PiecewiseLinear {
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    let t: Vec<f64> = (0..n).map(|i| i as f64 * 1e-4).collect();
    let u: Vec<f64> = t
        .iter()
        .map(|&t| {
            let noise = (lcg(&mut state) - 0.5) * 2e-6;
            1e-3 * (std::f64::consts::TAU * 0.5 * t).sin() + noise
        })
        .collect();
    PiecewiseLinear::new(t, u).expect("valid input")
}

fn noisy(f: &[f64], level: f64, mut state: u64) -> Vec<f64> {
    let rms = (f.iter().map(|v| v * v).sum::<f64>() / f.len() as f64).sqrt();
    f.iter()
        .map(|v| {
            let r = (-2.0 * (1.0 - lcg(&mut state)).ln()).sqrt();
            v + level * rms * r * (std::f64::consts::TAU * lcg(&mut state)).cos()
        })
        .collect()
}

fn slow_data(n: usize) -> (Vec<f64>, Vec<f64>) {
    let model = LuGre::paper().with_sigma0(6.0).expect("valid");
    let tp = TurningPoints::new(&[0.0, 1.0, 0.5, 1.5]).expect("valid");
    let input = PiecewiseLinear::from_turning_points(&tp, 1.0).expect("valid");
    let p = input.period();
    let times = merge_times(&uniform_times(0.0, p, 5, n / 2), &input.knot_times(5));
    let mut out = Trajectory::default();
    Simulator::new(&model, Gamma::INFINITE, 0.0)
        .expect("valid")
        .at_times(&input, 5, &times, &mut out)
        .expect("finite");
    let from = out.range_between(3.0 * p, f64::INFINITY).start;
    (out.u[from..].to_vec(), noisy(&out.y[from..], 0.01, 1))
}

fn full_data(n: usize) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let model = LuGre::from_params(LuGreParams::canudas_de_wit_1995()).expect("valid");
    let speeds = [1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 1e-1];
    let per_sweep = n / (2 * speeds.len());
    let (amp, mut t, mut u) = (1e-3, vec![0.0], vec![-1e-3]);
    for &v in &speeds {
        for target in [amp, -amp] {
            let (t0, u0) = (t[t.len() - 1], u[u.len() - 1]);
            let dur = f64::abs(target - u0) / v;
            for j in 1..=per_sweep {
                let x = j as f64 / per_sweep as f64;
                t.push(t0 + dur * x);
                u.push(u0 + (target - u0) * x);
            }
        }
    }
    let input = PiecewiseLinear::new(t.clone(), u.clone()).expect("valid");
    let mut out = Trajectory::default();
    Simulator::new(&model, Gamma::ONE, 0.0)
        .expect("valid")
        .at_knots(&input, 1, &mut out)
        .expect("finite");
    let f = noisy(&out.y, 0.01, 2);
    (t, u, f)
}

fn sine_data(n: usize) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let t: Vec<f64> = (0..n).map(|i| 8.0 * i as f64 / (n - 1) as f64).collect();
    let u: Vec<f64> = t
        .iter()
        .map(|&t| 6.0 * (std::f64::consts::TAU * t / 4.0).sin())
        .collect();
    let input = PiecewiseLinear::new(t.clone(), u.clone()).expect("valid");
    let mut out = Trajectory::default();
    Simulator::new(&LuGre::paper(), Gamma::ONE, 0.0)
        .expect("valid")
        .at_knots(&input, 1, &mut out)
        .expect("finite");
    let f = noisy(&out.y, 0.01, 3);
    (t, u, f)
}

fn dynamics_run(sc: Scenario) -> f64 {
    let model = LuGre::from_params(LuGreParams::canudas_de_wit_1995()).expect("valid");
    let setup = sc.setup(model, 1.0).expect("valid");
    let t = setup.t_end;
    setup
        .system
        .solve(t, &[t], Tolerances::default())
        .unwrap()
        .x[0]
}

fn breakaway() -> f64 {
    [1.0, 2.0, 5.0, 10.0, 20.0, 50.0]
        .iter()
        .map(|&rate| {
            let model = LuGre::from_params(LuGreParams::canudas_de_wit_1995()).expect("valid");
            let setup = Scenario::Breakaway { rate }
                .setup(model, 1.0)
                .expect("valid");
            let b = setup.system.breakaway(setup.t_end, Tolerances::default());
            b.unwrap().expect("a peak").force
        })
        .sum()
}

/// Runs `body` `k` times.
fn repeat<T>(k: usize, mut body: impl FnMut() -> T) {
    for _ in 0..k {
        black_box(body());
    }
}

fn loops(case: &str, k: usize) {
    let paper = LuGre::paper().rate_independent();
    let stiff = LuGre::from_params(LuGreParams {
        sigma0: 1e5,
        sigma1: 316.2,
        fc: 1.0,
        fs: 1.5,
        vs: 1e-3,
        ..LuGreParams::default()
    })
    .expect("valid")
    .rate_independent();
    let (model, scale, records) = match case {
        "loops/loop_and_minor_loops" => (paper, 1.0, false),
        "loops/stiff" => (stiff, 1e-3, false),
        _ => (paper, 1.0, true),
    };
    let tp = random_turning_points(1_000_000, scale);
    repeat(k, || {
        let hl = HysteresisLoop::new(model, black_box(&tp)).expect("finite");
        if records {
            hl.loops().len()
        } else {
            hl.loop_table().len()
        }
    });
}

fn cycles(case: &str, k: usize) {
    let u = random_walk(1_000_000);
    let model = LuGre::paper().rate_independent();
    match case {
        "cycles/count" => repeat(k, || {
            let mut sink = Checksum::default();
            let mut counter = CycleCounter::new(0.0).expect("valid gate");
            for block in black_box(&u).chunks(4096) {
                counter.push_all(block, &mut sink).expect("finite");
            }
            (
                counter.finish(&mut sink).expect("long"),
                sink.sum,
                sink.reversals,
            )
        }),
        "cycles/count_per_sample" => repeat(k, || {
            let mut sink = Checksum::default();
            let mut counter = CycleCounter::new(0.0).expect("valid gate");
            for &x in black_box(&u) {
                counter.push(x, &mut sink).expect("finite");
            }
            (
                counter.finish(&mut sink).expect("long"),
                sink.sum,
                sink.reversals,
            )
        }),
        "cycles/count_into_columns" => repeat(k, || {
            let mut columns = CycleColumns::new();
            let mut counter = CycleCounter::new(0.0).expect("valid gate");
            counter
                .push_all(black_box(&u), &mut columns)
                .expect("finite");
            (
                counter.finish(&mut columns).expect("long"),
                columns.range.len(),
            )
        }),
        _ => repeat(k, || {
            let mut sink = Checksum::default();
            let mut counter = energy_counter!(model).expect("valid");
            for block in black_box(&u).chunks(4096) {
                counter.push_all(block, &mut sink).expect("finite");
            }
            (
                counter.finish(&mut sink).expect("long"),
                sink.sum,
                sink.reversals,
            )
        }),
    }
}

fn simulate(case: &str, k: usize) {
    let model = LuGre::from_params(LuGreParams::canudas_de_wit_1995()).expect("valid");
    if case == "simulate/cubic_1e-9" {
        let n = 100_000;
        let t: Vec<f64> = (0..n).map(|i| i as f64 * 1e-4).collect();
        let u: Vec<f64> = t
            .iter()
            .map(|&t| 1e-3 * (std::f64::consts::TAU * 0.5 * t).sin())
            .collect();
        let sim = Simulator::new(&model, Gamma::ONE, 0.0).expect("valid");
        let mut out = Trajectory::with_capacity(n);
        return repeat(k, || {
            out.clear();
            let motion = SmoothSamples::pchip(t.clone(), u.clone(), 1e-9).expect("valid");
            sim.at_samples(&motion, &mut out).expect("finite");
            out.y.last().copied()
        });
    }
    let gamma = if case == "simulate/exact_gamma_1" {
        Gamma::ONE
    } else {
        Gamma::INFINITE
    };
    let input = sampled_input(1_000_000);
    let mut out = Trajectory::with_capacity(1_000_000);
    let sim = Simulator::new(&model, gamma, 0.0).expect("valid");
    repeat(k, || {
        out.clear();
        sim.at_knots(black_box(&input), 1, &mut out)
            .expect("finite");
        out.y.last().copied()
    });
}

fn dynamics(case: &str, k: usize) {
    match case {
        "dynamics/presliding" => repeat(k, || dynamics_run(Scenario::Presliding)),
        "dynamics/breakaway_6_rates" => repeat(k, breakaway),
        "dynamics/stick_slip" => repeat(k, || dynamics_run(Scenario::StickSlip)),
        "dynamics/pid" => repeat(k, || dynamics_run(Scenario::Pid)),
        _ => repeat(k, || dynamics_run(Scenario::Lag { w: 10.0 })),
    }
}

fn fit(case: &str, k: usize) {
    match case {
        "fit/slow" => {
            let (u, f) = slow_data(100_000);
            let spec = FitSpec::new(Family::LuGre);
            repeat(k, || fit_slow(black_box(&spec), &u, &f).expect("fits"));
        }
        "fit/full" => {
            let (t, u, f) = full_data(100_000);
            let spec = FitSpec::new(Family::LuGre).set("beta", 2.0).expect("known");
            repeat(k, || {
                fit_full(&spec, &t, &u, &f, FullOptions::default()).expect("fits")
            });
        }
        _ => {
            let (t, u, f) = sine_data(100_000);
            let spec = FitSpec::new(Family::LuGre)
                .set("sigma2", 0.0)
                .and_then(|s| s.fix("sigma2"))
                .and_then(|s| s.set("beta", 1.0))
                .expect("known");
            repeat(k, || {
                let motion = SmoothSamples::pchip(t.clone(), u.clone(), 1e-9).expect("valid");
                fit_full_smooth(&spec, &motion, &f, FullOptions::default()).expect("fits")
            });
        }
    }
}

/// Every case, in the order `bench/instructions.sh` reports them.
const CASES: [&str; 18] = [
    "loops/loop_and_minor_loops",
    "loops/stiff",
    "loops/as_records",
    "cycles/count",
    "cycles/count_per_sample",
    "cycles/count_into_columns",
    "cycles/count_with_energy",
    "simulate/exact_gamma_1",
    "simulate/exact_gamma_inf",
    "simulate/cubic_1e-9",
    "dynamics/presliding",
    "dynamics/breakaway_6_rates",
    "dynamics/stick_slip",
    "dynamics/pid",
    "dynamics/lag",
    "fit/slow",
    "fit/full",
    "fit/full_cubic",
];

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let case = args.get(1).map(String::as_str).unwrap_or("list");
    if !CASES.contains(&case) {
        CASES.iter().for_each(|c| println!("{c}"));
        return;
    }
    let k: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(1);
    match case.split('/').next() {
        Some("loops") => loops(case, k),
        Some("cycles") => cycles(case, k),
        Some("simulate") => simulate(case, k),
        Some("dynamics") => dynamics(case, k),
        _ => fit(case, k),
    }
}
