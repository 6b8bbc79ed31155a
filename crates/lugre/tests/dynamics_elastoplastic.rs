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
/// far below (Radau and DOP853 agree to 1e-11 of those scales). Observed: lag within 1e-12,
/// stick-slip within 3e-11 (the velocity near the second slip onset).
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
        1.0033742459219946e-05,
        1.0045765123863029,
    ),
    (
        1.413716694115407,
        1.0440624679739197e-05,
        1.0488377441108614,
    ),
    (
        1.4922565104551517,
        1.2296997707253181e-05,
        1.2387232120383571,
    ),
    (
        1.5707963267948966,
        1.3713314635064695e-05,
        1.3737465811049334,
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

/// `(t, x, v, z, F)` of stick-slip (Fig. 6) each second over 20 s (two slips and a re-stick),
/// elasto-plastic, zba = 0.5e-5 m: the same script (DOP853 agrees to 1.2e-12).
const STICK_SLIP: &[(f64, f64, f64, f64, f64)] = &[
    (
        1.0,
        1.9936276987742615e-06,
        1.9999600007999808e-06,
        1.9936276987742615e-06,
        0.1999960127446025,
    ),
    (
        2.0,
        3.993587699574246e-06,
        1.999960000799979e-06,
        3.993587699574246e-06,
        0.3999920128246009,
    ),
    (
        3.0,
        5.9966387649746434e-06,
        2.019451831071366e-06,
        5.9935467178962085e-06,
        0.5999879215542477,
    ),
    (
        4.0,
        8.10242525724366e-06,
        2.24560813595215e-06,
        7.993500475957655e-06,
        0.7999833851570869,
    ),
    (
        5.0,
        1.0655958103569274e-05,
        2.9958281985812914e-06,
        9.993438213725404e-06,
        0.9999774503448009,
    ),
    (
        6.0,
        1.4621150033221994e-05,
        5.4653878069405185e-06,
        1.199331561033951e-05,
        1.1999661390709415,
    ),
    (
        7.0,
        2.518725168033281e-05,
        2.2169828905602866e-05,
        1.3992547637425993e-05,
        1.399895160891746,
    ),
    (
        8.0,
        0.0721748171072542,
        0.246741361591077,
        1e-05,
        1.0986965446364307,
    ),
    (
        9.0,
        0.411692568904372,
        0.3430454801074255,
        1e-05,
        1.1372181920429703,
    ),
    (
        10.0,
        0.6281298925070146,
        0.06927944239923156,
        1e-05,
        1.0277117769596926,
    ),
    (
        11.0,
        0.6371594792331482,
        2.6191298178698987e-06,
        9.250467372803676e-06,
        0.9256802200693433,
    ),
    (
        12.0,
        0.6371627179534314,
        4.15405338382413e-06,
        1.1250378145001337e-05,
        1.1256718906832117,
    ),
    (
        13.0,
        0.6371692987876052,
        1.1005145091790015e-05,
        1.3250085045027654e-05,
        1.3256451419705964,
    ),
    (
        14.0,
        0.6455309286748868,
        0.08945508134597259,
        1e-05,
        1.035782032538389,
    ),
    (
        15.0,
        0.9142700510848314,
        0.3699963831665153,
        1e-05,
        1.1479985532666062,
    ),
    (
        16.0,
        1.218875710707281,
        0.18221242026867238,
        1e-05,
        1.072884968107469,
    ),
    (
        17.0,
        1.2743084174908585,
        2.3680178352150426e-06,
        8.507492317546044e-06,
        0.8513826169291668,
    ),
    (
        18.0,
        1.274311194064422,
        3.365992752996066e-06,
        1.0507421711894246e-05,
        1.0513759434716885,
    ),
    (
        19.0,
        1.274315925715674,
        6.953224726976354e-06,
        1.2507257866382775e-05,
        1.2513609278662077,
    ),
    (
        20.0,
        1.274333520437084,
        5.240309553100043e-05,
        1.4504342423085257e-05,
        1.4510801160630962,
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

/// The scenario with the elasto-plastic law (`zba = ZBA`) at rtol 1e-11, output at `times`.
fn elastoplastic_run(scenario: Scenario, times: Vec<f64>) -> lugre::dynamics::Plan {
    Request::new()
        .with_scenario(scenario)
        .with_elastoplastic(ZBA)
        .with_times(times)
        .unwrap()
        .with_rtol(1e-11)
        .unwrap()
        .build()
        .unwrap()
}

#[test]
fn lag_against_scipy() {
    let period = std::f64::consts::TAU / 10.0;
    let times: Vec<f64> = (0..25).map(|k| k as f64 * period / 8.0).collect();
    let plan = elastoplastic_run(Scenario::Lag { w: 10.0 }, times);
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

#[test]
fn stick_slip_against_scipy() {
    let times: Vec<f64> = (0..21).map(f64::from).collect();
    let plan = elastoplastic_run(Scenario::StickSlip, times);
    let m = plan.motion().unwrap();
    assert_eq!(m.t.len(), STICK_SLIP.len() + 1);
    for (i, &(t, x, v, z, f)) in STICK_SLIP.iter().enumerate() {
        let i = i + 1;
        assert_eq!(m.t[i], t);
        near("x", t, m.x[i], x, 1.0);
        near("v", t, m.v[i], v, 0.1);
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
