//! The elasto-plastic friction of Dupont et al. (2002) at finite rate as the friction of the
//! closed-loop dynamics (`FrictionLaw::ElastoPlastic`, `lugre::dynamics` (D2)): against an
//! independent scipy reference on two experiments of Canudas de Wit et al. (1995), and its
//! hallmark beside LuGre's: no drift under a force below break-away.

// The pasted reference times are multiples of pi / 40 as the script printed them.
#![allow(clippy::approx_constant)]

use lugre::dynamics::{FrictionLaw, Request, Scenario};
use lugre::{LuGre, LuGreParams};

/// The accuracy asked of the solver at rtol 1e-11, relative to each quantity's scale (`Fs /
/// sigma0` for `z`, `Fs` for `F`, 1 m for `x`, 0.1 m/s for `v`); the references' own error is
/// far below (Radau and DOP853 agree to 1e-13 of those scales).
const TOL: f64 = 1e-10;

/// The break-away displacement of the reference runs (half of Fc / sigma0 of Table I).
const ZBA: f64 = 0.5e-5;

fn table1() -> LuGre {
    LuGre::from_params(LuGreParams::canudas_de_wit_1995()).expect("Table I is valid")
}

/// `(t, z, F)` of the frictional lag (Fig. 3, w = 10 rad/s), elasto-plastic with zba = 0.5e-5 m,
/// every eighth of a period over three (after t = 0): made by
/// `python crates/lugre/tests/reference/dynamics/elastoplastic_dynamics.py` (scipy 1.17.1; Radau
/// at rtol 1e-12, split at the blend's kinks; DOP853 at rtol 1e-12 agrees to 2.4e-14).
const LAG: &[(f64, f64, f64)] = &[
    (
        0.07853981633974483,
        1.0033742448132217e-05,
        1.0045765120553185,
    ),
    (
        0.15707963267948966,
        1.0440624679739199e-05,
        1.0488377441108616,
    ),
    (
        0.23561944901923448,
        1.2296997707253166e-05,
        1.2387232120383562,
    ),
    (
        0.3141592653589793,
        1.3713314635064698e-05,
        1.3737465811049336,
    ),
    (
        0.39269908169872414,
        1.3095202256834627e-05,
        1.301350708002112,
    ),
    (
        0.47123889803846897,
        1.066875706368631e-05,
        1.0610880229612756,
    ),
    (
        0.5497787143782138,
        1.0045048240604382e-05,
        1.0049195986765151,
    ),
    (
        0.6283185307179586,
        1.0009731495332657e-05,
        1.001966892314262,
    ),
    (
        0.7068583470577035,
        1.0033742459219946e-05,
        1.0045765123863029,
    ),
    (
        0.7853981633974483,
        1.0440624679739195e-05,
        1.0488377441108612,
    ),
    (
        0.8639379797371931,
        1.2296997707253168e-05,
        1.2387232120383562,
    ),
    (0.9424777960769379, 1.37133146350647e-05, 1.3737465811049339),
    (
        1.0210176124166828,
        1.3095202256834625e-05,
        1.3013507080021118,
    ),
    (
        1.0995574287564276,
        1.0668757063686306e-05,
        1.0610880229612754,
    ),
    (
        1.1780972450961724,
        1.0045048240604385e-05,
        1.0049195986765154,
    ),
    (
        1.2566370614359172,
        1.0009731495332655e-05,
        1.0019668923142617,
    ),
    (
        1.335176877775662,
        1.0033742459219947e-05,
        1.0045765123863029,
    ),
    (
        1.413716694115407,
        1.0440624679739195e-05,
        1.0488377441108612,
    ),
    (
        1.4922565104551517,
        1.2296997707253185e-05,
        1.2387232120383576,
    ),
    (
        1.5707963267948966,
        1.3713314635064698e-05,
        1.3737465811049336,
    ),
    (
        1.6493361431346414,
        1.309520225683463e-05,
        1.3013507080021125,
    ),
    (
        1.7278759594743862,
        1.0668757063686308e-05,
        1.0610880229612756,
    ),
    (
        1.806415775814131,
        1.0045048240604383e-05,
        1.0049195986765154,
    ),
    (
        1.8849555921538759,
        1.0009731495332655e-05,
        1.0019668923142617,
    ),
];

/// `got` within [`TOL`] of the quantity's `scale` of `want`.
fn near(what: &str, t: f64, got: f64, want: f64, scale: f64) {
    let err = (got - want).abs() / scale;
    assert!(
        err <= TOL,
        "t = {t}: {what} = {got} vs {want} ({err:e} of {scale})"
    );
}

#[test]
fn lag_against_scipy() {
    let period = std::f64::consts::TAU / 10.0;
    let times: Vec<f64> = (0..25).map(|k| k as f64 * period / 8.0).collect();
    let plan = Request::new()
        .with_scenario(Scenario::Lag { w: 10.0 })
        .with_elastoplastic(ZBA)
        .with_times(times)
        .unwrap()
        .with_rtol(1e-11)
        .unwrap()
        .build()
        .unwrap();
    assert_eq!(plan.system.law(), FrictionLaw::ElastoPlastic { zba: ZBA });
    let m = plan.motion().unwrap();
    assert_eq!(m.t.len(), LAG.len() + 1);
    for (i, &(t, z, f)) in LAG.iter().enumerate() {
        let i = i + 1;
        assert_eq!(m.t[i], t);
        near("z", t, m.z[i], z, 1.5e-5);
        near("F", t, m.friction[i], f, 1.5);
    }
}

/// The position at the end of each of `cycles` force cycles 0 -> `peak` -> 0 N (each 2 s, then a
/// 2 s hold at 0 N for the mass to come to rest), Table I and 1 kg, with the friction law
/// elasto-plastic (`zba`) or LuGre (`None`).
fn rest_positions(zba: Option<f64>, peak: f64, cycles: usize) -> Vec<f64> {
    let mut t = vec![0.0];
    let mut f = vec![0.0];
    for k in 0..cycles {
        let t0 = 4.0 * k as f64;
        t.extend([t0 + 1.0, t0 + 2.0, t0 + 4.0]);
        f.extend([peak, 0.0, 0.0]);
    }
    let t_end = *t.last().unwrap();
    let times: Vec<f64> = (1..=cycles).map(|k| 4.0 * k as f64).collect();
    let mut r = Request::new()
        .with_model(table1())
        .with_force(t, f)
        .unwrap()
        .with_t_end(t_end)
        .unwrap()
        .with_times(times)
        .unwrap();
    if let Some(zba) = zba {
        r = r.with_elastoplastic(zba);
    }
    r.build().unwrap().motion().unwrap().x
}

/// Dupont et al.'s point: under a force that cycles below break-away the elasto-plastic mass
/// comes back to where it started (its deflection is elastic: `z' = v` while `|z| <= zba`, so
/// `x - z` stays 0 and at rest under no force `z = 0`), where LuGre's creeps a little further
/// every cycle (its `z' = v - sigma0 |v| z / g` slips at any deflection).
#[test]
fn no_drift_below_breakaway_where_lugre_creeps() {
    // Peak 0.8 N, below sigma0 zba = 0.9 N (and below Fc = 1 N).
    let (zba, peak, cycles) = (0.9e-5, 0.8, 4);
    let ep = rest_positions(Some(zba), peak, cycles);
    let lugre = rest_positions(None, peak, cycles);
    println!("elasto-plastic {ep:?}\nLuGre {lugre:?}");
    // Back at 0 within the solver's displacement tolerance (rtol 1e-8 times Fs / sigma0).
    for x in &ep {
        assert!(x.abs() <= 1e-12, "elasto-plastic drifted to {x} m");
    }
    // LuGre: at rest away from 0, further each cycle by about the same step.
    let steps: Vec<f64> = lugre.windows(2).map(|w| w[1] - w[0]).collect();
    assert!(lugre[0] > 1e-8, "LuGre's first cycle left {} m", lugre[0]);
    for s in &steps {
        assert!(*s > 0.1 * lugre[0], "LuGre's drift per cycle {s} m");
    }
}
