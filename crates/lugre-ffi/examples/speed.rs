//! What the C ABI costs on top of the core: 10^6-sample calls of the exact simulation and of the
//! rainflow count, timed through the core's Rust API and through the C entry points (the
//! same calls a C, Julia or MEX caller makes), best of 7.
//!
//!     cargo run --release -p lugre-ffi --example speed
//!
//! `matlab/tests/speed_lugre.m` times the same two calls through the MEX functions.

use lugre_c::*;
use lugre_test_support::timing::{best_of, random_walk};
use std::hint::black_box;
use std::ptr;

const N: usize = 1_000_000;

fn main() {
    // A random walk in displacement (Table I scale: micrometres), 1 ms apart.
    let u = random_walk(N, 1e-6);
    let t: Vec<f64> = (0..N).map(|i| i as f64 * 1e-3).collect();
    // The walk for matlab/tests/speed_lugre.m (the same samples through the MEX functions).
    let path = std::env::temp_dir().join("lugre-speed-walk.f64");
    let bytes: Vec<u8> = u.iter().flat_map(|v| v.to_le_bytes()).collect();
    std::fs::write(&path, bytes).unwrap();
    // The parameters as a caller has them: known at run time only (black_box keeps the compiler
    // from folding Table I into the Rust calls, e.g. beta = 2 into a square).
    let params = black_box(lugre::LuGreParams::canudas_de_wit_1995());
    let model = lugre::LuGre::from_params(params).unwrap();

    let core_simulate = best_of(7, || {
        let input = lugre::PiecewiseLinear::new(t.clone(), u.clone()).unwrap();
        let mut out = lugre::Trajectory::with_capacity(N);
        lugre::Simulator::new(&model, lugre::Gamma::ONE, 0.0)
            .unwrap()
            .at_knots(&input, 1, &mut out)
            .unwrap();
        black_box(out.y[N - 1]);
    });
    let core_cycles = best_of(7, || {
        let mut columns = lugre::CycleColumns::new().with_reversals(false);
        let mut counter = lugre::CycleCounter::new(0.0).unwrap();
        counter.push_all(&u, &mut columns).unwrap();
        counter.finish(&mut columns).unwrap();
        black_box(columns.len());
    });

    let c_params: LugreParams = params;
    let mut m = ptr::null_mut();
    assert_eq!(lugre_model_new(&c_params, &mut m), LugreStatus::Ok);
    let (mut z, mut f) = (vec![0.0; N], vec![0.0; N]);
    let abi_simulate = best_of(7, || {
        let s = lugre_simulate(
            m,
            t.as_ptr(),
            u.as_ptr(),
            N,
            0.0,
            z.as_mut_ptr(),
            f.as_mut_ptr(),
        );
        assert_eq!(s, LugreStatus::Ok);
        black_box(f[N - 1]);
    });
    let abi_cycles = best_of(7, || {
        let mut c = ptr::null_mut();
        let s = lugre_cycles_new(u.as_ptr(), N, 0.0, ptr::null(), 0.0, &mut c);
        assert_eq!(s, LugreStatus::Ok);
        let mut n = 0;
        lugre_cycles_len(c, &mut n);
        let mut range = vec![0.0; n];
        let cols = LugreCycleColumns {
            range: range.as_mut_ptr(),
            mean: ptr::null_mut(),
            count: ptr::null_mut(),
            start: ptr::null_mut(),
            end: ptr::null_mut(),
            closure: ptr::null_mut(),
            closure_position: ptr::null_mut(),
            work: ptr::null_mut(),
            stored_energy_change: ptr::null_mut(),
            dissipation: ptr::null_mut(),
            closure_gap: ptr::null_mut(),
        };
        assert_eq!(lugre_cycles_columns(c, &cols, n), LugreStatus::Ok);
        lugre_cycles_free(c);
        black_box(range.len());
    });
    lugre_model_free(m);
    println!("10^6 samples (also in {}), best of 7:", path.display());
    println!(
        "simulate: core {:.2} ms, C ABI {:.2} ms ({:.2}x)",
        core_simulate * 1e3,
        abi_simulate * 1e3,
        abi_simulate / core_simulate
    );
    println!(
        "cycles:   core {:.2} ms, C ABI {:.2} ms ({:.2}x)",
        core_cycles * 1e3,
        abi_cycles * 1e3,
        abi_cycles / core_cycles
    );
}
