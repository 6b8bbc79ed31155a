//! The GMS model at finite rate (`MaxwellSlip::simulate`, `crates/lugre/src/zoo/gms.rs`)
//! against an independent integration of the published equations: scipy's solve_ivp by Radau
//! and by DOP853 at rtol 1e-12, the stick-to-slip transitions located as events
//! (`tests/reference/gms_reference.py`, its output pasted below; the two integrators agree to
//! the figure in each case's comment). The exact simulation matches them within 1e-12 of the
//! largest force.

use lugre::zoo::{MaxwellSlip, ZooKind, ZooModel};

// defaults: Radau - DOP853 = 1.9e-15 of max |F|
const DEFAULTS_T: &[f64] = &[0.0, 1.0, 2.5, 3.0, 4.0, 4.5, 6.0, 7.0, 8.0];
const DEFAULTS_U: &[f64] = &[0.0, 1.2, 3.0, 3.0, 1.0, 1.5, -2.0, -1.0, -1.3];
const DEFAULTS_F: &[f64] = &[
    0.0,
    1.5252985529780503,
    1.3011942119122022,
    1.3011942119122022,
    -1.3079381618750008,
    1.1920618381249988,
    -1.096971967864405,
    0.5570812452003352,
    -0.792918754799665,
];

// table1: Radau - DOP853 = 1.5e-14 of max |F|
const TABLE1_T: &[f64] = &[0.0, 0.001, 0.003, 0.004, 0.006, 0.01, 0.012, 0.02];
const TABLE1_U: &[f64] = &[0.0, 2e-06, 1e-05, 1.2e-05, 5e-06, -1e-05, -1e-05, -8e-06];
const TABLE1_F: &[f64] = &[
    0.0,
    0.8331999999999999,
    0.9810400168802762,
    0.8510624251544311,
    -0.6253316928161889,
    -0.9572252551670041,
    -0.6000002810809442,
    -0.32085028108094393,
];

// random: Radau - DOP853 = 3.6e-14 of max |F|
const RANDOM_T: &[f64] = &[
    0.0,
    1.7333010847678838,
    3.526108402106238,
    5.104383749909855,
    5.362341231499535,
    5.652700740690417,
    6.445647802725568,
    8.222454602148574,
    10.134037720731268,
    11.292738690352474,
    12.905973418622303,
    13.698778909740192,
    15.371328850164597,
    17.04146469970389,
    17.372362530059995,
    19.305002313727073,
    20.123676613698468,
    20.64316954460286,
    21.778722181445406,
    23.09855349969086,
    23.32877477174677,
    23.796386042743936,
    24.615699418402155,
    25.215006594438087,
    26.500565434271238,
    26.854616048092467,
    28.377299459310258,
    29.43863991797845,
    30.16748981253015,
    32.11311272455733,
    34.08641088489198,
];
const RANDOM_U: &[f64] = &[
    0.0,
    1.601563866525499,
    3.444808064973993,
    1.787885597808497,
    1.1418606991805116,
    -0.2812969978480018,
    -0.38149427726303076,
    1.3543523249670826,
    1.4575674236272835,
    3.234467734919242,
    3.92121504228983,
    2.450798318253629,
    4.314603417241217,
    4.922484860486107,
    5.161256615097777,
    3.93188706958053,
    5.38709284281143,
    6.825691864854184,
    8.083699808249781,
    6.351589260101111,
    7.104992199420635,
    8.955147846385334,
    9.37967583819897,
    9.507393046780342,
    11.489569540513251,
    13.235438861223786,
    14.696702076508856,
    16.623752515633644,
    16.298726820004436,
    15.522652812397759,
    14.302316151210102,
];
const RANDOM_F: &[f64] = &[
    0.0,
    1.3735127381874461,
    1.2919279062458802,
    -0.7520470917821149,
    -1.205660137651661,
    -1.5685088432222636,
    -1.9036826496833346,
    0.466813411834486,
    0.06632974958218651,
    1.1296811658171535,
    1.5185639031314784,
    -0.967628359392247,
    1.2272894388569549,
    1.889640363311362,
    1.5679324824536434,
    0.1187191785823705,
    1.0116876936705805,
    1.1476469176885304,
    1.2386210718803963,
    -0.9218418113858613,
    2.206109053081908,
    1.3913220339899657,
    1.7489250395619373,
    1.9346103040200573,
    1.0329058188505016,
    1.5517401467002818,
    1.3523831739129042,
    1.0100712009063175,
    0.018366322650703454,
    -0.552730867970006,
    -1.336122864605694,
];

/// The Maxwell-slip model of the table with `k`, `f` and the GMS parameters `rate`
/// (`fc, vs, beta, attraction, sigma1, sigma2`).
fn gms(k: &[f64], f: &[f64], rate: [f64; 6]) -> MaxwellSlip {
    let names = ["fc", "vs", "beta", "attraction", "sigma1", "sigma2"];
    let mut given: Vec<(&str, &[f64])> = vec![("stiffness", k), ("slip_force", f)];
    for (name, value) in names.iter().zip(&rate) {
        given.push((name, std::slice::from_ref(value)));
    }
    match ZooModel::new("maxwell-slip", &given).unwrap().kind() {
        ZooKind::MaxwellSlip(m) => m.clone(),
        other => panic!("{other:?}"),
    }
}

fn check(model: &MaxwellSlip, t: &[f64], u: &[f64], want: &[f64]) {
    let got = model.simulate(t, u).unwrap();
    let scale = want.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    for (j, (g, w)) in got.iter().zip(want).enumerate() {
        assert!(
            (g - w).abs() <= 1e-12 * scale,
            "sample {j}: {g} against {w}"
        );
    }
    assert_eq!(got.len(), want.len());
}

const DEFAULT_K: &[f64] = &[0.25, 0.25, 0.25, 0.25];
const DEFAULT_F: &[f64] = &[0.125, 0.375, 0.625, 0.875];

#[test]
fn the_defaults_match_scipy() {
    let model = ZooModel::new("maxwell-slip", &[]).unwrap();
    let ZooKind::MaxwellSlip(m) = model.kind() else {
        unreachable!()
    };
    check(m, DEFAULTS_T, DEFAULTS_U, DEFAULTS_F);
}

#[test]
fn table_one_scale_matches_scipy() {
    let m = gms(
        &[4e4, 3e4, 2e4, 1e4],
        &[0.15, 0.3, 0.45, 0.6],
        [1.0, 1e-3, 2.0, 50.0, 316.2, 0.4],
    );
    check(&m, TABLE1_T, TABLE1_U, TABLE1_F);
}

#[test]
fn thirty_random_segments_match_scipy() {
    let m = gms(DEFAULT_K, DEFAULT_F, [0.6, 1.0, 2.0, 3.0, 0.5, 0.2]);
    check(&m, RANDOM_T, RANDOM_U, RANDOM_F);
}

/// As `v -> 0` GMS is Maxwell-slip: at 1e-9 m/s every slip level is `f_i` within
/// `(1 - fc / F_s) 1e-9` and the damping adds `sigma1 v`, so the forces at the turning points
/// are the exact segment map's (`MaxwellSlip::response`) within 1e-8.
#[test]
fn the_slow_limit_is_maxwell_slip() {
    let m = gms(DEFAULT_K, DEFAULT_F, [1.0, 1.0, 1.0, 10.0, 1.0, 0.0]);
    let turning: [f64; 6] = [3.0, -1.0, 2.0, 0.5, 1.5, -4.0];
    let mut t = vec![0.0];
    let mut u: Vec<f64> = vec![0.0];
    for &x in &turning {
        t.push(t.last().unwrap() + (x - u.last().unwrap()).abs() * 1e9);
        u.push(x);
    }
    let slow = m.simulate(&t, &u).unwrap();
    let exact = m.response(0.0, &turning);
    for (s, e) in slow[1..].iter().zip(&exact) {
        assert!((s - e).abs() < 1e-8, "{s} against {e}");
    }
}

#[test]
fn bad_motions_are_named() {
    let m = gms(DEFAULT_K, DEFAULT_F, [1.0, 1.0, 1.0, 10.0, 1.0, 0.0]);
    let e = m.simulate(&[0.0, 1.0, 1.0], &[0.0, 1.0, 2.0]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "t must be > t[1] = 1 (times increasing), got 1"
    );
    let e = m.simulate(&[0.0, 1.0], &[0.0]).unwrap_err();
    assert_eq!(e.to_string(), "t and u have different lengths (2 and 1)");
    let e = m.simulate(&[0.0, 1.0], &[0.0, f64::NAN]).unwrap_err();
    assert!(
        e.to_string().starts_with("u must be a finite number"),
        "{e}"
    );
    let e = ZooModel::new("maxwell-slip", &[("attraction", &[0.0])]).unwrap_err();
    assert_eq!(e.to_string(), "attraction must be > 0, got 0");
}
