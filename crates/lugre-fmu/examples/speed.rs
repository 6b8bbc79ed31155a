//! What the FMI layer costs: 10^6 co-simulation steps of the friction element (Table I, a
//! random walk in displacement, 1 ms steps) through `fmi3SetFloat64` + `fmi3DoStep` +
//! `fmi3GetFloat64` (what a host's C-level loop calls) against `FrictionElement::step` from
//! Rust, best of 7, two ways:
//!
//! * **open loop**: the displacements known in advance (consecutive steps are independent
//!   until the state, so the processor overlaps one step's `g(v)` and exponential with the
//!   previous step's);
//! * **closed loop**: each step's displacement depends on the force the last step returned
//!   (`x_k + 1e-30 F_{k-1}`, numerically the same walk), as when a host closes a loop around
//!   the element: no overlap, in either path.
//!
//!     cargo run --release -p lugre-fmu --example speed

use lugre_fmu::*;
use lugre_test_support::timing::{best_of, random_walk};
use std::hint::black_box;

const N: usize = 1_000_000;
const H: f64 = 1e-3;
/// How much of the last force feeds into the next displacement in the closed loop: enough to
/// make a data dependency, too little to change a bit of the walk.
const FEEDBACK: f64 = 1e-30;

fn main() {
    let xs = random_walk(N + 1, 1e-6);
    // The parameters as a host has them: known at run time only (black_box keeps the compiler
    // from folding Table I into the Rust loop, e.g. beta = 2 into a square).
    let model =
        lugre::LuGre::from_params(black_box(lugre::LuGreParams::canudas_de_wit_1995())).unwrap();
    // The closed loop's feedback term, left out of the open loop's code altogether.
    let feed = |closed: bool, f: f64| if closed { FEEDBACK * f } else { 0.0 };
    let rust = |closed: bool| {
        best_of(7, || {
            let mut e = lugre::simulate::FrictionElement::new(model.clone(), 0.0).unwrap();
            let (mut sum, mut f) = (0.0, 0.0);
            for x in &xs[1..] {
                f = e.step(*x + feed(closed, f), H).unwrap().y;
                sum += f;
            }
            black_box(sum);
        })
    };
    let token = std::ffi::CString::new(FRICTION_TOKEN).unwrap();
    let fmu = |closed: bool| {
        best_of(7, || {
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
                let shift = feed(closed, f[0]);
                let values = [xs[k] + shift, (xs[k + 1] - xs[k]) / H];
                fmi3SetFloat64(i, inputs.as_ptr(), 2, values.as_ptr(), 2);
                let status =
                    fmi3DoStep(i, k as f64 * H, H, false, &mut a, &mut b, &mut c, &mut last);
                assert_eq!(status, Status::Ok);
                fmi3GetFloat64(i, output.as_ptr(), 1, f.as_mut_ptr(), 1);
                sum += f[0];
            }
            fmi3FreeInstance(i);
            black_box(sum);
        })
    };
    for (name, closed) in [("open loop", false), ("closed loop", true)] {
        let (r, f) = (rust(closed), fmu(closed));
        println!(
            "10^6 co-simulation steps, {name}, best of 7: Rust FrictionElement::step {:.1} ms, FMI calls {:.1} ms ({:.2}x)",
            r * 1e3,
            f * 1e3,
            f / r
        );
    }
}
