//! The periodic orbit's energy per cycle against an independent computation: scipy's Radau
//! (rtol = 1e-12; DOP853 at the same tolerance agreeing to a few 1e-13 where the problem is
//! not stiff) simulating the LuGre model from z = 0 period after period until the state and
//! the period's energy change by less than 1e-13 (at most 1000 periods), the energy integrated
//! as extra states. Made once by
//!
//!     python3 crates/lugre/tests/reference/sweep_reference.py
//!
//! (scipy 1.17.1); the comments give each case's W/D - 1 on the scipy side, the periods it took
//! and the DOP853 check. Rates from quasi-static to far above the Stribeck velocity, sigma0
//! from 1 to 1e8.

use lugre::sweep::{Point, Request};
use lugre::{LuGre, LuGreParams, Tolerance};

/// (label, sigma0, amplitude, frequency, dissipation per cycle).
const REFERENCE: [(&str, f64, f64, f64, f64); 13] = [
    // W/D-1 = 8.9e-16, 31 periods, DOP853 rel 8.1e-14
    ("paper", 1.0, 0.5, 0.001, 0.08619349143246198),
    // W/D-1 = -5.6e-16, 28 periods, DOP853 rel 2.2e-13
    ("paper", 1.0, 0.5, 0.1, 0.567714294430417),
    // W/D-1 = -2.4e-15, 6 periods, DOP853 rel 2.1e-13
    ("paper", 1.0, 2.0, 1.0, 37.82221503492882),
    // W/D-1 = 2.2e-16, 4 periods, DOP853 rel 4.5e-14
    (
        "paper sigma0=1e4",
        10000.0,
        0.001,
        0.1,
        0.006398948037033396,
    ),
    // W/D-1 = -1.3e-15, 3 periods
    (
        "paper sigma0=1e8",
        100000000.0,
        1e-06,
        1.0,
        7.839980526105862e-06,
    ),
    // W/D-1 = 0.0e+00, 3 periods
    (
        "paper sigma0=1e8",
        100000000.0,
        0.001,
        0.01,
        0.007999642613260192,
    ),
    // W/D-1 = 1.1e-14, 109 periods
    ("canudas1995", 100000.0, 1e-06, 0.1, 9.49707493048814e-09),
    // W/D-1 = 1.3e-15, 13 periods
    ("canudas1995", 100000.0, 1e-05, 1.0, 8.088172455054045e-06),
    // W/D-1 = 0.0e+00, 4 periods
    ("canudas1995", 100000.0, 0.0001, 0.1, 0.0005100868895343459),
    // W/D-1 = 8.9e-16, 3 periods
    ("canudas1995", 100000.0, 0.0001, 10.0, 0.00039087800651627),
    // W/D-1 = 4.7e-15, 3 periods
    ("canudas1995", 100000.0, 0.001, 1.0, 0.003983164031008943),
    // W/D-1 = 6.7e-16, 3 periods
    ("canudas1995", 100000.0, 0.001, 100.0, 0.00574196292291288),
    // W/D-1 = -3.6e-15, 3 periods
    (
        "canudas1995 sigma0=1e8",
        100000000.0,
        0.0001,
        1.0,
        0.0005548026057689032,
    ),
];

/// The agreement required: 1e-10 relative (the two computations agree to about 1e-13).
const REL: f64 = 1e-10;

fn model(label: &str, sigma0: f64) -> LuGre {
    let base = if label.starts_with("paper") {
        LuGreParams::default()
    } else {
        LuGreParams::canudas_de_wit_1995()
    };
    LuGre::from_params(LuGreParams { sigma0, ..base }).expect("valid")
}

#[test]
fn energy_per_cycle_matches_scipy_to_1e_10() {
    let tol = Tolerance::new(Request::DEFAULT_TOLERANCE).unwrap();
    let mut worst: f64 = 0.0;
    for (label, sigma0, a, f, want) in REFERENCE {
        let p = Point::compute(&model(label, sigma0), a, f, 0.0, tol, 0).unwrap();
        let rel = (p.dissipation / want - 1.0).abs();
        worst = worst.max(rel);
        assert!(
            rel < REL,
            "{label} A = {a}, f = {f}: {} vs {want} ({rel:e})",
            p.dissipation
        );
        // The work is the same number on the orbit.
        assert!((p.work / want - 1.0).abs() < REL);
    }
    println!("worst relative difference {worst:e}");
}
