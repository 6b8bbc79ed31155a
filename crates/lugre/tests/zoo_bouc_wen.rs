//! The Bouc-Wen model of `lugre::zoo`: at `n = 1`, `sigma = 1`, `kx = 0` it is the Dahl model,
//! whose loops LuGre's engine computes independently (1e-12); its parameter domains.

use lugre::zoo::{BoucWen, SingleState, ZooLoop};
use lugre::{HysteresisLoop, RateIndependent, TurningPoints, ZooError};

mod common;
use common::{random_turning_points, Lcg};

#[test]
fn at_n_1_sigma_1_without_kx_its_loops_are_lugres_dahl_loops() {
    let mut rng = Lcg(28);
    for (rho, kw, scale) in [(1.7, 0.8, 0.05), (40.0, 2.5, 1.0), (0.3, 1.0, 10.0)] {
        let model = BoucWen::new(0.0, kw, rho, 1.0, 1.0).unwrap();
        let dahl = RateIndependent::new(rho * kw, kw).unwrap();
        for _ in 0..4 {
            let u: Vec<f64> = random_turning_points(&mut rng, 30)
                .iter()
                .map(|x| x * scale)
                .collect();
            let input = TurningPoints::new(&u).unwrap();
            let mine = ZooLoop::new(&model, &input).unwrap();
            let theirs = HysteresisLoop::new(dahl, &input).unwrap();
            for (a, b) in mine.turning_force().iter().zip(theirs.turning_y()) {
                assert!((a - b).abs() <= 1e-12 * kw, "force {a} vs {b}");
            }
            let theirs = theirs.loops();
            assert_eq!(mine.loops().len(), theirs.len());
            // Energies of a loop are O(kw x its input range).
            let energy = kw * u.iter().fold(0.0f64, |m, x| m.max(x.abs())).max(1.0 / rho);
            for (a, b) in mine.loops().iter().zip(&theirs) {
                for (x, y) in [
                    (a.energy.work, b.energy.work),
                    (a.energy.dissipation, b.energy.dissipation),
                    (a.energy.stored_energy_change, b.energy.stored_energy_change),
                    (a.energy.closure_gap, b.energy.closure_gap),
                ] {
                    assert!((x - y).abs() <= 1e-12 * energy, "energy {x} vs {y}");
                }
            }
        }
    }
}

#[test]
fn each_parameter_outside_its_domain_is_named_with_its_value() {
    let cases = [
        (BoucWen::new(-1.0, 1.0, 1.0, 1.0, 1.0), "kx must be a finite number >= 0 (N/m), got -1"),
        (BoucWen::new(1.0, 0.0, 1.0, 1.0, 1.0), "kw must be a finite number > 0 (N), got 0"),
        (
            BoucWen::new(1.0, 1.0, f64::INFINITY, 1.0, 1.0),
            "rho must be a finite number > 0 (1/m; A > 0 in the classical form), got inf",
        ),
        (
            BoucWen::new(1.0, 1.0, 1.0, 0.25, 1.0),
            "sigma must be a finite number >= 1/2 (beta >= gamma: bounded output and nonnegative dissipation), got 0.25",
        ),
        (
            BoucWen::new(1.0, 1.0, 1.0, 1.0, 0.5),
            "n must be a finite number in [1, 100] (n >= 1: a unique solution; n <= 100: the segment map to 1e-13), got 0.5",
        ),
    ];
    for (result, message) in cases {
        let e = result.unwrap_err();
        assert!(matches!(e, ZooError::Domain { .. }), "{e:?}");
        assert_eq!(e.to_string(), message);
    }
    assert!(BoucWen::new(1.0, 1.0, 1.0, f64::MAX, 1.0).is_err());
    assert!(BoucWen::new(0.0, 1.0, 1.0, 0.5, 1.0).is_ok());
}

#[test]
fn the_state_stays_in_its_bounds_and_dissipation_is_nonnegative() {
    let mut rng = Lcg(7);
    for n in [1.0, 1.5, 2.0, 3.0, 7.5] {
        for sigma in [0.5, 0.8, 1.0, 4.0] {
            let m = BoucWen::new(0.3, 1.2, 2.0, sigma, n).unwrap();
            let (mut u, mut w) = (0.0, 0.0);
            for _ in 0..200 {
                let to = rng.range(-3.0, 3.0);
                let (next, d) = m.segment(u, w, to);
                assert!(
                    (-1.0..=1.0).contains(&next) && d >= 0.0,
                    "{n} {sigma}: {next} {d}"
                );
                (u, w) = (to, next);
            }
        }
    }
}
