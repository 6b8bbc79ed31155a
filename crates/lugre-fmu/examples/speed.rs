//! What the FMI layer costs: 10^6 co-simulation steps of the friction element (Table I, a
//! random walk in displacement, 1 ms steps) through `fmi3SetFloat64` + `fmi3DoStep` +
//! `fmi3GetFloat64` (what a host's C-level loop calls) against `FrictionElement::step` from
//! Rust, best of 7.
//!
//!     cargo run --release -p lugre-fmu --example speed

use lugre_fmu::*;
use lugre_test_support::timing::{best_of, random_walk};
use std::hint::black_box;

const N: usize = 1_000_000;
const H: f64 = 1e-3;

fn main() {
    let xs = random_walk(N + 1, 1e-6);
    // The parameters as a host has them: known at run time only (black_box keeps the compiler
    // from folding Table I into the Rust loop, e.g. beta = 2 into a square).
    let model =
        lugre::LuGre::from_params(black_box(lugre::LuGreParams::canudas_de_wit_1995())).unwrap();
    let rust = best_of(7, || {
        let mut e = lugre::simulate::FrictionElement::new(model.clone(), 0.0).unwrap();
        let mut sum = 0.0;
        for x in &xs[1..] {
            sum += e.step(*x, H).unwrap().y;
        }
        black_box(sum);
    });
    let token = std::ffi::CString::new(FRICTION_TOKEN).unwrap();
    let fmu = best_of(7, || {
        let i = fmi3InstantiateCoSimulation(
            c"speed".as_ptr(),
            token.as_ptr(),
            std::ptr::null(),
            false,
            false,
            false,
            false,
            std::ptr::null(),
            0,
            std::ptr::null_mut(),
            None,
            std::ptr::null(),
        );
        fmi3EnterInitializationMode(i, false, 0.0, 0.0, false, 0.0);
        fmi3ExitInitializationMode(i);
        let (inputs, output) = ([friction::vr::X, friction::vr::V], [friction::vr::F]);
        let mut sum = 0.0;
        let mut f = [0.0];
        let (mut a, mut b, mut c, mut last) = (false, false, false, 0.0);
        for k in 0..N {
            let values = [xs[k], (xs[k + 1] - xs[k]) / H];
            fmi3SetFloat64(i, inputs.as_ptr(), 2, values.as_ptr(), 2);
            let status = fmi3DoStep(i, k as f64 * H, H, false, &mut a, &mut b, &mut c, &mut last);
            assert_eq!(status, Status::Ok);
            fmi3GetFloat64(i, output.as_ptr(), 1, f.as_mut_ptr(), 1);
            sum += f[0];
        }
        fmi3FreeInstance(i);
        black_box(sum);
    });
    println!(
        "10^6 co-simulation steps, best of 7: Rust FrictionElement::step {:.1} ms, FMI calls {:.1} ms ({:.2}x)",
        rust * 1e3,
        fmu * 1e3,
        fmu / rust
    );
}
