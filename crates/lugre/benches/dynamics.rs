//! The closed-loop experiments of Canudas de Wit et al. (1995) at the solver's default tolerance
//! (`rtol = 1e-8`): pre-sliding (Fig. 2, 65 s), the break-away located at the six force rates of
//! the reference (Fig. 4), stick-slip (Fig. 6, 30 s), PID hunting (Fig. 8, 100 s), frictional lag
//! (Fig. 3, w = 10 rad/s, three periods), and the five together (the target: under
//! 20 ms on one core).

use criterion::{criterion_group, criterion_main, Criterion};
use lugre::dynamics::{Scenario, Tolerances};
use lugre::{LuGre, LuGreParams};
use std::hint::black_box;

fn run(sc: Scenario) -> f64 {
    let model = LuGre::from_params(LuGreParams::canudas_de_wit_1995()).expect("valid");
    let setup = sc.setup(model, 1.0).expect("valid");
    let t = setup.t_end;
    setup
        .system
        .solve(t, &[t], Tolerances::default())
        .unwrap()
        .x[0]
}

fn presliding() -> f64 {
    run(Scenario::Presliding)
}

/// The experiment is the break-away itself: the first friction peak located at each rate.
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

fn stick_slip() -> f64 {
    run(Scenario::StickSlip)
}

fn pid() -> f64 {
    run(Scenario::Pid)
}

fn lag() -> f64 {
    run(Scenario::Lag { w: 10.0 })
}

fn dynamics(c: &mut Criterion) {
    let mut group = c.benchmark_group("dynamics");
    group.sample_size(20);
    group.bench_function("presliding", |b| b.iter(|| black_box(presliding())));
    group.bench_function("breakaway_6_rates", |b| b.iter(|| black_box(breakaway())));
    group.bench_function("stick_slip", |b| b.iter(|| black_box(stick_slip())));
    group.bench_function("pid", |b| b.iter(|| black_box(pid())));
    group.bench_function("lag", |b| b.iter(|| black_box(lag())));
    group.bench_function("all_five", |b| {
        b.iter(|| black_box(presliding() + breakaway() + stick_slip() + pid() + lag()))
    });
    group.finish();
}

criterion_group!(benches, dynamics);
criterion_main!(benches);
