//! The closed-loop experiments of Canudas de Wit et al. (1995) at the solver's default tolerance
//! (`rtol = 1e-8`): pre-sliding (Fig. 2, 65 s), break-away at the six force rates of the
//! reference (Fig. 4), stick-slip (Fig. 6, 30 s) and PID hunting (Fig. 8, 100 s), and the four
//! together (the target: all five experiments in under 20 ms on one core; the frictional
//! lag, Fig. 3, is not in the library yet).

use criterion::{criterion_group, criterion_main, Criterion};
use lugre::dynamics::{Pid, Profile, Steps, System, Tolerances};
use lugre::{LuGre, LuGreParams};
use std::hint::black_box;

fn table1() -> LuGre {
    LuGre::from_params(LuGreParams::canudas_de_wit_1995()).expect("valid")
}

fn presliding() -> f64 {
    let t = vec![0.0, 10.0, 15.0, 35.0, 40.0, 60.0, 65.0];
    let f = vec![0.0, 1.425, 1.425, -1.425, -1.425, 1.425, 1.425];
    let s = System::new(table1(), 1.0)
        .unwrap()
        .with_force(Profile::new("f", t, f).unwrap());
    s.solve(65.0, &[65.0], Tolerances::default()).unwrap().x[0]
}

fn breakaway() -> f64 {
    [1.0, 2.0, 5.0, 10.0, 20.0, 50.0]
        .iter()
        .map(|&r| {
            let s = System::new(table1(), 1.0)
                .unwrap()
                .with_force(Profile::ramp(0.0, r).unwrap());
            // Past the break-away (at 1.44 s for r = 1, earlier for faster ramps).
            let t_end = 2.0 / r;
            s.solve(t_end, &[t_end], Tolerances::default()).unwrap().x[0]
        })
        .sum()
}

fn stick_slip() -> f64 {
    let s = System::new(table1(), 1.0)
        .unwrap()
        .with_spring(2.0, Profile::ramp(0.0, 0.1).unwrap())
        .unwrap();
    s.solve(30.0, &[30.0], Tolerances::default()).unwrap().x[0]
}

fn pid() -> f64 {
    let pid = Pid {
        kp: 3.0,
        ki: 4.0,
        kv: 6.0,
        setpoint: Steps::constant(1.0).unwrap(),
    };
    let s = System::new(table1(), 1.0).unwrap().with_pid(pid).unwrap();
    s.solve(100.0, &[100.0], Tolerances::default()).unwrap().x[0]
}

fn dynamics(c: &mut Criterion) {
    let mut group = c.benchmark_group("dynamics");
    group.sample_size(20);
    group.bench_function("presliding", |b| b.iter(|| black_box(presliding())));
    group.bench_function("breakaway_6_rates", |b| b.iter(|| black_box(breakaway())));
    group.bench_function("stick_slip", |b| b.iter(|| black_box(stick_slip())));
    group.bench_function("pid", |b| b.iter(|| black_box(pid())));
    group.bench_function("all_four", |b| {
        b.iter(|| black_box(presliding() + breakaway() + stick_slip() + pid()))
    });
    group.finish();
}

criterion_group!(benches, dynamics);
criterion_main!(benches);
