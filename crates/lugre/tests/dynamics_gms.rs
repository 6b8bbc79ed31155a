//! GMS friction (`Request::with_zoo` of the Maxwell-slip model) on the mass against an
//! independent integration: `tests/reference/dynamics/gms_dynamics.py` (scipy's solve_ivp, one
//! state per element, the mode changes as terminal events, Radau and DOP853 at rtol 1e-12;
//! their output pasted below with their agreement).

use lugre::dynamics::{FrictionLoop, Outcome, Request, Scenario};
use lugre::zoo::ZooModel;

/// The Table I scale of the reference: four elements sharing `sigma0 = 1e5` N/m, slip forces
/// `1.5 [1, 3, 5, 7] / 16` N, `Fc = 1` N, `vs = 1e-3` m/s, `beta = 2`, `C = 10` N/s,
/// `sigma1 = sqrt(1e5)`, `sigma2 = 0.4`.
fn table_one() -> ZooModel {
    let k = [2.5e4; 4];
    let f = [1.5 / 16.0, 4.5 / 16.0, 7.5 / 16.0, 10.5 / 16.0];
    let sigma1 = 1e5f64.sqrt();
    ZooModel::new(
        "maxwell-slip",
        &[
            ("stiffness", &k),
            ("slip_force", &f),
            ("fc", &[1.0]),
            ("vs", &[1e-3]),
            ("beta", &[2.0]),
            ("attraction", &[10.0]),
            ("sigma1", &[sigma1]),
            ("sigma2", &[0.4]),
        ],
    )
    .unwrap()
}

fn run(scenario: Scenario, times: Vec<f64>, rtol: f64) -> Outcome {
    let request = Request::new()
        .with_scenario(scenario)
        .with_zoo(&table_one());
    solve(request.unwrap().with_times(times).unwrap(), rtol)
}

/// `request` at rtol `rtol`, run.
fn solve(request: Request, rtol: f64) -> Outcome {
    request
        .with_rtol(rtol)
        .unwrap()
        .build()
        .unwrap()
        .run()
        .unwrap()
}

// stick_slip: x Radau - DOP853 = 1.2e-13 of its largest
// stick_slip: v Radau - DOP853 = 3.1e-13 of its largest
// stick_slip: friction Radau - DOP853 = 1.6e-12 of its largest
const STICK_SLIP_T: &[f64] = &[
    0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 4.5, 5.0, 5.5, 6.0, 6.5, 7.0, 7.5, 8.0, 8.5, 9.0, 9.5,
    10.0,
];
const STICK_SLIP_X: &[f64] = &[
    9.936476983742695e-07,
    1.993627698774261e-06,
    2.993607699174254e-06,
    4.074780325712492e-06,
    5.40807865616641e-06,
    6.741376454622614e-06,
    8.07467423405238e-06,
    9.407972012803398e-06,
    1.0741269791530251e-05,
    1.2486857109672413e-05,
    1.4486779821704874e-05,
    1.6486699921494983e-05,
    1.848661992813893e-05,
    2.2223488606403056e-05,
    2.6223196781621156e-05,
    0.03147184263623526,
    0.16620887830923828,
    0.356715188013985,
    0.5318715741276676,
    0.640066030131164,
];
const STICK_SLIP_V: &[f64] = &[
    1.9999600008000443e-06,
    1.9999600007999837e-06,
    1.999960000799989e-06,
    2.6665991458121803e-06,
    2.6665956938559945e-06,
    2.6665955623184766e-06,
    2.6665955576258696e-06,
    2.666595557458394e-06,
    2.66659555745205e-06,
    3.9998587354982506e-06,
    3.9998406742384e-06,
    3.999840030214941e-06,
    3.999840007250855e-06,
    7.999554974353319e-06,
    7.99936697289194e-06,
    0.16998139385520894,
    0.3490816900519213,
    0.3880279579173445,
    0.29473698110826074,
    0.13372118391621568,
];
const STICK_SLIP_F: &[f64] = &[
    0.0999980127046033,
    0.19999601274460246,
    0.29999401278460164,
    0.39999185051216785,
    0.49998918384359703,
    0.5999865172471233,
    0.6999838506515333,
    0.7999811840559745,
    0.8999785174604171,
    0.9999750264106431,
    1.0999710264448095,
    1.1999670266003162,
    1.2999630267601496,
    1.3999555543405464,
    1.4999475536526379,
    1.07484522527774,
    1.139678848932774,
    1.1552114942775717,
    1.117894794539551,
    1.0534884735806105,
];
// breakaway: x Radau - DOP853 = 1.3e-11 of its largest
// breakaway: v Radau - DOP853 = 8.4e-12 of its largest
// breakaway: friction Radau - DOP853 = 2.1e-12 of its largest
const BREAKAWAY_T: &[f64] = &[
    0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.07, 0.08, 0.09, 0.1, 0.11, 0.12, 0.13, 0.14, 0.15, 0.16,
    0.17, 0.18, 0.19, 0.2,
];
const BREAKAWAY_X: &[f64] = &[
    6.08886432203318e-07,
    1.6981472993735092e-06,
    2.680933839994656e-06,
    3.683669996551816e-06,
    4.966901084241907e-06,
    6.3455159693463495e-06,
    7.662332331064666e-06,
    8.999594663987543e-06,
    1.0332849423453195e-05,
    1.1742854237063305e-05,
    1.387923796564788e-05,
    1.5964504812921013e-05,
    1.790356424268714e-05,
    2.045711269903156e-05,
    2.516452709129322e-05,
    3.653330051321595e-05,
    6.771365496894469e-05,
    0.00013244981406245794,
    0.00024403157886054844,
    0.0004153675438314361,
];
const BREAKAWAY_V: &[f64] = &[
    0.00011420945445145726,
    9.885085276133308e-05,
    9.983481820277187e-05,
    0.00010011081726662528,
    0.00014455447279909694,
    0.00013149567337454,
    0.00013319256528774938,
    0.0001335979972963977,
    0.00013324505148465645,
    0.00017664537780934817,
    0.0002248499259404089,
    0.00019428157563322553,
    0.00019794215080051863,
    0.0003680840966774332,
    0.0006045548323329395,
    0.001893854240153968,
    0.004570965493129795,
    0.008597694761436915,
    0.013933747014136653,
    0.02054273966006437,
];
const BREAKAWAY_F: &[f64] = &[
    0.09705052764129855,
    0.20111365461603117,
    0.29970385945770645,
    0.40006486408043307,
    0.5002777805162585,
    0.6005571376512366,
    0.6997088041029811,
    0.8000870789764715,
    0.8999857806015497,
    0.9880440996096339,
    1.1022266987844793,
    1.2014839261740078,
    1.2988778772625764,
    1.374388242208317,
    1.4349758495437033,
    1.401517629019304,
    1.3640901278459223,
    1.33122705685619,
    1.3021683273434597,
    1.276587194720991,
];

/// Each column within `tol` of its largest value.
fn close(what: &str, got: &[f64], want: &[f64], tol: f64) {
    assert_eq!(got.len(), want.len(), "{what}");
    let scale = want.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let worst = got
        .iter()
        .zip(want)
        .map(|(g, w)| (g - w).abs() / scale)
        .fold(0.0, f64::max);
    assert!(worst <= tol, "{what}: {worst:e} of the largest");
}

/// Stick-slip (Fig. 6): the spring loads the sticking elements for 7.5 s, they slip one by
/// one, the mass breaks away near t = 7.6 s and slides. Within 1e-9 of each column's largest
/// value at rtol 1e-10 (the references agree to 2e-12).
#[test]
fn stick_slip_matches_scipy() {
    let out = run(Scenario::StickSlip, STICK_SLIP_T.to_vec(), 1e-10);
    assert_eq!(out.motion.t, STICK_SLIP_T);
    close("x", &out.motion.x, STICK_SLIP_X, 1e-9);
    close("v", &out.motion.v, STICK_SLIP_V, 1e-9);
    close("friction", &out.motion.friction, STICK_SLIP_F, 1e-9);
    // The slip onset: the spring's end outruns the mass once (v rises through 0.1 m/s).
    assert_eq!(out.slip_onsets().len(), 1, "{:?}", out.motion.events);
    // The energy balance (G7) closes to the integration's accuracy, and the friction
    // dissipates.
    let e = out.motion.energy;
    assert!(e.residual().abs() < 1e-9 * e.input, "{e:?}");
    assert!(e.dissipated > 0.0 && e.dissipated < e.input, "{e:?}");
}

/// Break-away (Fig. 4) under F = 10 t: pre-sliding, then the elements slip and the friction
/// peaks. Within 1e-9 of each column's largest value; the break-away within the samples'
/// bracket.
#[test]
fn breakaway_matches_scipy() {
    let out = run(
        Scenario::Breakaway { rate: 10.0 },
        BREAKAWAY_T.to_vec(),
        1e-10,
    );
    close("x", &out.motion.x, BREAKAWAY_X, 1e-9);
    close("v", &out.motion.v, BREAKAWAY_V, 1e-9);
    close("friction", &out.motion.friction, BREAKAWAY_F, 1e-9);
    let b = out.breakaway.expect("a break-away");
    // The samples' friction peaks at t = 0.15 (1.43498): the peak lies in (0.14, 0.16) and is
    // at least that high.
    assert!(b.t > 0.14 && b.t < 0.16, "{b:?}");
    assert!(b.force >= BREAKAWAY_F[14] - 1e-9 && b.force < 1.5, "{b:?}");
}

/// Stiff elements (sigma0 = 1e8 N/m on a 1 kg mass) are stable: the stick-slip run completes
/// with the pre-sliding displacement 1000 times smaller than at 1e5 and the same break-away
/// force level.
#[test]
fn stiff_elements_are_stable() {
    let k = [2.5e7; 4];
    let f = [1.5 / 16.0, 4.5 / 16.0, 7.5 / 16.0, 10.5 / 16.0];
    let model = ZooModel::new(
        "maxwell-slip",
        &[
            ("stiffness", &k),
            ("slip_force", &f),
            ("vs", &[1e-3]),
            ("beta", &[2.0]),
            ("sigma1", &[1e4]),
        ],
    )
    .unwrap();
    let out = Request::new()
        .with_scenario(Scenario::StickSlip)
        .with_zoo(&model)
        .unwrap()
        .with_samples(31)
        .unwrap()
        .build()
        .unwrap()
        .run()
        .unwrap();
    let peak = out.motion.friction.iter().fold(0.0f64, |m, x| m.max(*x));
    assert!(peak > 1.4 && peak < 1.5, "{peak}");
    assert!(out.motion.x[5].abs() < 1e-7, "{}", out.motion.x[5]);
    assert!(out.motion.stats.steps < 200_000, "{:?}", out.motion.stats);
}

/// A triangle wave of `x` between `-A` and `A` (`A = 1.975e-5` m: every element but the
/// stiffest slips, `2 Delta_i < 2 A`), `k` times slower than 1e-5 m/s: the velocity `±1e-5 / k`
/// with ramps of `0.1 k` s at the reversals, from 0 up to `A` at `2 k` s, down to `-A` at `6 k`
/// s and back to `A` at `10 k` s, the run's end.
fn triangle(k: f64) -> Request {
    let (v0, d) = (1e-5 / k, 0.05 * k);
    let t = [0.0, 2.0, 2.0, 6.0, 6.0, 10.0, 10.0];
    let shift = [0.0, -d, d, -d, d, -d, d];
    let t: Vec<f64> = t.iter().zip(shift).map(|(t, s)| t * k + s).collect();
    let v = vec![v0, v0, -v0, -v0, v0, v0, -v0];
    Request::new()
        .with_zoo(&table_one())
        .unwrap()
        .with_velocity(t, v)
        .unwrap()
        .with_t_end(10.0 * k)
        .unwrap()
        .with_loops(true)
}

/// The one loop of [`triangle`] at rtol `rtol`.
fn triangle_loop(k: f64, rtol: f64) -> FrictionLoop {
    let out = solve(triangle(k).with_samples(2).unwrap(), rtol);
    assert_eq!(out.loops.len(), 1, "{:?}", out.loops);
    let l = out.loops[0].clone();
    assert_eq!(
        [l.t_start, l.t_turn, l.t_close],
        [2.0 * k, 6.0 * k, 10.0 * k]
    );
    l
}

/// A slow loop of GMS friction tends to the Maxwell-slip model's loop on the same turning
/// points, like `O(rate)`. The slow loop by hand: over the range `R = 2 A` the three elements
/// with `2 Delta_i < R` slip, each dissipating `2 f_i (R - 2 Delta_i)`. The rate effect to
/// first order (at constant speed a slipping element's force stays at its level): the damping
/// `(sigma1 / K) K_S v` of the sticking elements and the viscous `sigma2 v`, whose work over
/// the loop is `v0 (sigma1 / K) sum_i k_i 2 min(2 Delta_i, R) + sigma2 v0 2 R`, 9.72e-3 of the
/// slow loop at 1e-5 m/s; measured 9.72e-3, 9.68e-3, 9.63e-3 at k = 1, 4, 16 (the Stribeck
/// curve and the ramps, of higher order).
#[test]
fn gms_loop_tends_to_the_maxwell_slip_loop() {
    let (k_el, f) = (2.5e4, [1.5 / 16.0, 4.5 / 16.0, 7.5 / 16.0, 10.5 / 16.0]);
    let mut excess = Vec::new();
    for k in [1.0, 4.0, 16.0] {
        let l = triangle_loop(k, 1e-10);
        let range = l.turning_points[0] - l.turning_points[1];
        let by_hand: f64 = f
            .iter()
            .map(|fi| 2.0 * fi * (range - 2.0 * fi / k_el).max(0.0))
            .sum();
        let ri = l.rate_independent_work;
        assert!((ri - by_hand).abs() <= 1e-12 * by_hand, "{ri} vs {by_hand}");
        excess.push((l.work - ri) / ri);
    }
    assert!(
        (3.9..4.1).contains(&(excess[0] / excess[1]))
            && (3.9..4.1).contains(&(excess[1] / excess[2])),
        "{excess:?}"
    );
    let (v0, range) = (1e-5, 3.95e-5);
    let sticking: f64 = f
        .iter()
        .map(|fi| 2.0 * k_el * (2.0 * fi / k_el).min(range))
        .sum();
    let first_order = v0 * (1e5f64.sqrt() / 1e5 * sticking + 0.4 * 2.0 * range);
    let slow: f64 = f
        .iter()
        .map(|fi| 2.0 * fi * (range - 2.0 * fi / k_el).max(0.0))
        .sum();
    let predicted = first_order / slow;
    for (e, k) in excess.iter().zip([1.0, 4.0, 16.0]) {
        assert!(
            (e * k / predicted - 1.0).abs() < 0.015,
            "{e:e} at k = {k}, {predicted:e}"
        );
    }
}

/// The loop's energy (L1): the elements' springs `sum F_i^2 / (2 k_i)` come back (every
/// slipping element slipped both ways; the sticking one is back at its deflection), so the
/// stored change is the integration's error; the dissipation is positive and equals the run's
/// own dissipation (G7, the steps' quadrature) between the loop's start and its close, to the
/// trapezoid rule's error on the outputs (5e-7, see `gms_loop_work_matches_scipy`).
#[test]
fn gms_loop_energy_balances() {
    let l = triangle_loop(1.0, 1e-12);
    assert!(l.dissipation > 0.0, "{l:?}");
    assert!(l.bristle_energy_change.abs() < 1e-8 * l.work, "{l:?}");
    assert_eq!(l.work, l.bristle_energy_change + l.dissipation);
    let dissipated = |t_end: f64| {
        let request = triangle(1.0).with_samples(2).unwrap().with_t_end(t_end);
        solve(request.unwrap().with_loops(false), 1e-12)
            .motion
            .energy
            .dissipated
    };
    let d = dissipated(10.0) - dissipated(2.0);
    assert!(
        (l.dissipation - d).abs() < 1e-6 * d,
        "{} vs {d}",
        l.dissipation
    );
}

// gms_loop.py (scipy solve_ivp, rtol 1e-12):
// Radau: work exact 1.7607071725543347e-05, trapezoid on the grid 1.7607062832383582e-05
// Radau - DOP853: exact 2.3e-12, trapezoid 2.6e-12 relative
/// The loop's work against scipy (`tests/reference/dynamics/gms_loop.py`, the elements one
/// state each): within 1e-8 of the trapezoid rule on the same outputs at rtol 1e-12 (the
/// integrations' difference), and within 1e-6 of the exact integral (the trapezoid rule's
/// error on 20000 outputs, 5.1e-7).
#[test]
fn gms_loop_work_matches_scipy() {
    let (trapezoid, exact) = (1.7607062832383582e-05, 1.7607071725543347e-05);
    let l = triangle_loop(1.0, 1e-12);
    assert!((l.work - trapezoid).abs() < 1e-8 * trapezoid, "{}", l.work);
    assert!((l.work - exact).abs() < 1e-6 * exact, "{}", l.work);
}
