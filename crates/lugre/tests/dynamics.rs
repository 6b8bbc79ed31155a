//! The closed-loop system (`lugre::dynamics`) against the independent references of
//! `tests/reference/dynamics/` (scipy Radau, LSODA and DOP853 agreeing to ~1e-10; the command
//! that made them, the definitions and the estimated errors are in its README.md and in
//! `reference.json`), the experiments of Canudas de Wit et al. (1995) with their Table I.

use lugre::dynamics::{EventKind, Motion, Profile, Scenario, System, Tolerances};
use lugre::{LuGre, LuGreParams};
use serde_json::Value;

/// The relative accuracy the solver must reach at its default tolerance (rtol 1e-8), and at
/// rtol 1e-11 (the targets: 1e-6 and 1e-9); relative to the quantity's natural scale.
const AT_DEFAULT: f64 = 1e-6;
const AT_1E_11: f64 = 1e-9;

fn reference() -> Value {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/reference/dynamics/reference.json"
    );
    serde_json::from_str(&std::fs::read_to_string(path).expect("reference.json")).expect("JSON")
}

fn table1() -> LuGre {
    LuGre::from_params(LuGreParams::canudas_de_wit_1995()).expect("Table I is valid")
}

fn samples(r: &Value, experiment: &str) -> Vec<(f64, f64)> {
    r[experiment]["values"]["samples"]
        .as_array()
        .expect("samples")
        .iter()
        .map(|s| (s["t"].as_f64().unwrap(), s["x"].as_f64().unwrap()))
        .collect()
}

/// The largest `|x - x_ref| / scale` over the samples.
fn worst(m: &Motion, want: &[(f64, f64)], scale: f64) -> f64 {
    m.x.iter()
        .zip(want)
        .map(|(x, (_, w))| (x - w).abs() / scale)
        .fold(0.0, f64::max)
}

/// The scenarios' systems (`Scenario::setup`, Table I, 1 kg).
fn scenario(sc: Scenario) -> System {
    sc.setup(table1(), 1.0).expect("a valid scenario").system
}

/// Fig. 2: a force ramped to +-95 % of Fs with holds.
fn presliding() -> System {
    scenario(Scenario::Presliding)
}

/// Fig. 6: a spring k = 2 N/m whose free end moves at 0.1 m/s.
fn stick_slip() -> System {
    scenario(Scenario::StickSlip)
}

/// Fig. 8: PID with Kp = 3, Ki = 4, Kv = 6 towards xd = 1.
fn pid() -> System {
    scenario(Scenario::Pid)
}

#[test]
fn presliding_displacements() {
    let r = reference();
    let want = samples(&r, "presliding");
    let times: Vec<f64> = want.iter().map(|s| s.0).collect();
    // The displacement's scale: the largest, 4.5e-5 m.
    let scale = r["presliding"]["values"]["x_max"].as_f64().unwrap();
    for (rtol, bound) in [(Tolerances::DEFAULT_RTOL, AT_DEFAULT), (1e-11, AT_1E_11)] {
        let m = presliding()
            .solve(65.0, &times, Tolerances::new(rtol, None).unwrap())
            .unwrap();
        let e = worst(&m, &want, scale);
        assert!(e <= bound, "rtol {rtol:e}: {e:e}");
    }
}

#[test]
fn stick_slip_positions_and_stick_onsets() {
    let r = reference();
    let want = samples(&r, "stickslip");
    let times: Vec<f64> = want.iter().map(|s| s.0).collect();
    let onsets: Vec<f64> = r["stickslip"]["values"]["stick_onsets"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["t"].as_f64().unwrap())
        .collect();
    for (rtol, bound) in [(Tolerances::DEFAULT_RTOL, AT_DEFAULT), (1e-11, AT_1E_11)] {
        let m = stick_slip()
            .solve(30.0, &times, Tolerances::new(rtol, None).unwrap())
            .unwrap();
        let e = worst(&m, &want, 1.0);
        assert!(e <= bound, "rtol {rtol:e}: x {e:e}");
        // A stick onset is the first v = 0 after a slip: the first of each cluster of located
        // sign changes (the mass rings down after it).
        let zeros: Vec<f64> = m
            .events
            .iter()
            .filter(|e| e.kind == EventKind::VelocityZero)
            .map(|e| e.t)
            .collect();
        let firsts: Vec<f64> = zeros
            .iter()
            .enumerate()
            .filter(|&(i, &t)| i == 0 || t - zeros[i - 1] > 1.0)
            .map(|(_, &t)| t)
            .collect();
        assert_eq!(firsts.len(), onsets.len(), "{zeros:?}");
        for (got, want) in firsts.iter().zip(&onsets) {
            // Relative to the period (6.36 s).
            assert!(
                (got - want).abs() / 6.36 <= bound,
                "rtol {rtol:e}: {got} vs {want}"
            );
        }
    }
}

#[test]
fn pid_hunting_positions() {
    let r = reference();
    let want = samples(&r, "pid");
    let times: Vec<f64> = want.iter().map(|s| s.0).collect();
    for (rtol, bound) in [(Tolerances::DEFAULT_RTOL, AT_DEFAULT), (1e-11, AT_1E_11)] {
        let m = pid()
            .solve(100.0, &times, Tolerances::new(rtol, None).unwrap())
            .unwrap();
        let e = worst(&m, &want, 1.0);
        assert!(e <= bound, "rtol {rtol:e}: {e:e}");
    }
}

#[test]
fn breakaway_states_at_the_reference_instants() {
    let r = reference();
    for case in r["breakaway"]["values"]["rates"].as_array().unwrap() {
        let (rate, t) = (case["rate"].as_f64().unwrap(), case["t"].as_f64().unwrap());
        let system = System::new(table1(), 1.0)
            .unwrap()
            .with_force(Profile::ramp(0.0, rate).unwrap());
        let m = system.solve(t, &[t], Tolerances::default()).unwrap();
        let (f, x) = (case["F"].as_f64().unwrap(), case["x"].as_f64().unwrap());
        assert!(
            (m.friction[0] - f).abs() / 1.5 <= AT_DEFAULT,
            "r = {rate}: F {}",
            m.friction[0]
        );
        assert!(
            (m.x[0] - x).abs() / x <= AT_DEFAULT,
            "r = {rate}: x {}",
            m.x[0]
        );
    }
}

/// Fig. 3: frictional lag under the prescribed velocity `1e-3 (cos w t + 1.5)`.
#[test]
fn frictional_lag() {
    let r = reference();
    for case in r["lag"]["values"]["w"].as_array().unwrap() {
        let w = case["w"].as_f64().unwrap();
        let want: Vec<(f64, f64, f64)> = case["samples"]
            .as_array()
            .unwrap()
            .iter()
            .map(|s| {
                let g = |k: &str| s[k].as_f64().unwrap();
                (g("t"), g("z"), g("F"))
            })
            .collect();
        let times: Vec<f64> = want.iter().map(|s| s.0).collect();
        for (rtol, bound) in [(Tolerances::DEFAULT_RTOL, AT_DEFAULT), (1e-11, AT_1E_11)] {
            let system = scenario(Scenario::Lag { w });
            let t_end = *times.last().unwrap();
            let m = system
                .solve(t_end, &times, Tolerances::new(rtol, None).unwrap())
                .unwrap();
            for (i, (t, z, f)) in want.iter().enumerate() {
                // Scales: Fs and the bristle length Fs / sigma0.
                let (ez, ef) = ((m.z[i] - z).abs() / 1.5e-5, (m.friction[i] - f).abs() / 1.5);
                assert!(
                    ez <= bound && ef <= bound,
                    "w {w}, t {t}, rtol {rtol:e}: z {ez:e}, F {ef:e}"
                );
            }
        }
    }
}

/// Fig. 4: the break-away (first local maximum of the friction force) located, for the rates
/// where it is a sharp peak (above ~35 N/s it is a shallow bump just above Fc: the reference's
/// README).
#[test]
fn breakaway_located() {
    let r = reference();
    for case in r["breakaway"]["values"]["rates"].as_array().unwrap() {
        let rate = case["rate"].as_f64().unwrap();
        if rate > 30.0 {
            continue;
        }
        let system = scenario(Scenario::Breakaway { rate });
        for (rtol, bound) in [(Tolerances::DEFAULT_RTOL, AT_DEFAULT), (1e-11, AT_1E_11)] {
            let b = system
                .breakaway(2.0 / rate, Tolerances::new(rtol, None).unwrap())
                .unwrap()
                .expect("a peak");
            let g = |k: &str| case[k].as_f64().unwrap();
            assert!(
                (b.t - g("t")).abs() / g("t") <= bound,
                "r = {rate}, rtol {rtol:e}: t {} vs {}",
                b.t,
                g("t")
            );
            assert!(
                (b.force - g("F")).abs() / 1.5 <= bound,
                "r = {rate}, rtol {rtol:e}: F {}",
                b.force
            );
            assert!(
                (b.x - g("x")).abs() / g("x") <= bound,
                "r = {rate}, rtol {rtol:e}: x {}",
                b.x
            );
        }
    }
}

/// Fig. 6: the slip onsets (the spring force peaks: `v` rising through the pull speed) and the
/// period.
#[test]
fn stick_slip_onsets_and_period() {
    let r = reference();
    let want: Vec<f64> = r["stickslip"]["values"]["slip_onsets"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["t"].as_f64().unwrap())
        .collect();
    let m = stick_slip()
        .solve(30.0, &[], Tolerances::default())
        .unwrap();
    let got: Vec<f64> = m
        .events
        .iter()
        .filter(|e| e.kind == EventKind::VelocityUp)
        .map(|e| e.t)
        .collect();
    assert_eq!(got.len(), want.len(), "{got:?}");
    for (g, w) in got.iter().zip(&want) {
        assert!((g - w).abs() / 6.36 <= AT_DEFAULT, "{g} vs {w}");
    }
    let period = r["stickslip"]["values"]["periods"][0].as_f64().unwrap();
    assert!(((got[1] - got[0]) - period).abs() / period <= AT_DEFAULT);
}

/// The energy balance: the drive's work = the change of kinetic + spring + bristle energy + what
/// the friction and the damper dissipated, to the tolerance, in every scenario.
#[test]
fn energy_balance() {
    for sc in [
        Scenario::Presliding,
        Scenario::Breakaway { rate: 10.0 },
        Scenario::StickSlip,
        Scenario::Lag { w: 10.0 },
        Scenario::Pid,
    ] {
        let setup = sc.setup(table1(), 1.0).unwrap();
        for rtol in [1e-6, Tolerances::DEFAULT_RTOL] {
            let e = setup
                .system
                .solve(setup.t_end, &[], Tolerances::new(rtol, None).unwrap())
                .unwrap()
                .energy;
            let scale = e.input.abs().max(e.dissipated);
            assert!(e.dissipated > 0.0 && scale > 0.0, "{sc:?}: {e:?}");
            assert!(
                e.residual().abs() <= 10.0 * rtol * scale,
                "{sc:?} rtol {rtol:e}: {e:?}"
            );
        }
    }
}

/// Minor loops under force input: the pre-sliding history x(t) is a displacement history, and
/// for slow force ramps its friction-displacement loop tends to the rate-independent loop of
/// `lugre loop` on the same turning points (x at the ends of the holds): the work over the
/// closed cycle from the first hold's end (x max) through the second (x min) back, by the
/// trapezoid rule on 20000 outputs, against `HysteresisLoop::work_per_period`. The difference
/// falls like 1/k when the ramps are k times slower (measured: 1.26e-3, 3.1e-4, 7.8e-5).
#[test]
fn presliding_loop_tends_to_the_rate_independent_loop() {
    let model = table1();
    let mut differences = Vec::new();
    for k in [1.0, 4.0, 16.0] {
        let t: Vec<f64> = [0.0, 10.0, 15.0, 35.0, 40.0, 60.0, 65.0]
            .iter()
            .map(|x| x * k)
            .collect();
        let f = vec![0.0, 1.425, 1.425, -1.425, -1.425, 1.425, 1.425];
        let system = System::new(model.clone(), 1.0)
            .unwrap()
            .with_force(Profile::new("the force", t, f).unwrap());
        let n = 20_000;
        let (a, b) = (15.0 * k, 65.0 * k);
        let times: Vec<f64> = (0..=n).map(|i| a + (b - a) * i as f64 / n as f64).collect();
        let m = system.solve(b, &times, Tolerances::default()).unwrap();
        let work: f64 = (1..m.x.len())
            .map(|i| 0.5 * (m.friction[i] + m.friction[i - 1]) * (m.x[i] - m.x[i - 1]))
            .sum();
        let x_min = m.x.iter().copied().fold(f64::INFINITY, f64::min);
        let tp = lugre::TurningPoints::new(&[m.x[0], x_min]).unwrap();
        let hl = lugre::HysteresisLoop::new(model.rate_independent(), &tp).unwrap();
        differences.push((work - hl.work_per_period()).abs() / hl.work_per_period());
    }
    assert!(
        differences[0] > 3.0 * differences[1] && differences[1] > 3.0 * differences[2],
        "{differences:?}"
    );
    assert!(differences[2] < 1e-4, "{differences:?}");
}

/// The global error shrinks with the tolerance (stick-slip, positions at 10, 20, 30 s).
#[test]
fn the_error_follows_the_tolerance() {
    let r = reference();
    let want = samples(&r, "stickslip");
    let times: Vec<f64> = want.iter().map(|s| s.0).collect();
    let errors: Vec<f64> = [1e-6, 1e-8, 1e-10]
        .iter()
        .map(|&rtol| {
            let m = stick_slip()
                .solve(30.0, &times, Tolerances::new(rtol, None).unwrap())
                .unwrap();
            worst(&m, &want, 1.0)
        })
        .collect();
    assert!(
        errors[0] > 10.0 * errors[1] && errors[1] > 10.0 * errors[2],
        "{errors:?}"
    );
    for (e, rtol) in errors.iter().zip([1e-6, 1e-8, 1e-10]) {
        assert!(*e <= 30.0 * rtol, "{e:e} at rtol {rtol:e}");
    }
}

/// Under a constant force below Fs the mass sticks: its displacement stays at the pre-sliding
/// level whatever the output spacing (from 1 ms to the whole run in one output).
#[test]
fn stiction_holds_at_any_output_spacing() {
    let hold = |spacing: f64| {
        let n = (20.0 / spacing).round() as usize;
        let times: Vec<f64> = (1..=n).map(|i| i as f64 * 20.0 / n as f64).collect();
        let system = System::new(table1(), 1.0)
            .unwrap()
            .with_force(Profile::new("the force", vec![0.0, 1.0], vec![0.0, 1.4]).unwrap());
        let m = system.solve(20.0, &times, Tolerances::default()).unwrap();
        m.x.iter().fold(0.0f64, |a, x| a.max(x.abs()))
    };
    for spacing in [1e-3, 0.1, 5.0, 20.0] {
        let x = hold(spacing);
        // 1.4 N on the bristles alone is 1.4e-5 m; a slip would be metres.
        assert!(x < 5e-5, "spacing {spacing}: |x| reached {x:e}");
    }
}

#[test]
fn bad_systems_and_requests_are_errors() {
    use lugre::DynamicsError;
    assert!(matches!(
        System::new(table1(), 0.0),
        Err(DynamicsError::NotPositive { .. })
    ));
    let e = stick_slip().with_damping(-1.0).unwrap_err().to_string();
    assert_eq!(e, "the damping must be a finite number >= 0, got -1");
    let e = Profile::new("the force profile", vec![0.0, 1.0, 1.0], vec![0.0; 3]).unwrap_err();
    assert!(e.to_string().contains("strictly increasing"), "{e}");
    assert!(Tolerances::new(0.0, None).is_err() && Tolerances::new(1e-8, Some(f64::NAN)).is_err());
    let e = stick_slip()
        .solve(-1.0, &[], Tolerances::default())
        .unwrap_err();
    assert_eq!(e.to_string(), "t_end must be a finite number > 0, got -1");
    let e = stick_slip()
        .solve(1.0, &[0.5, 2.0], Tolerances::default())
        .unwrap_err();
    assert!(e.to_string().contains("outside the run"), "{e}");
    // The one rule of output times (`lugre::input::check_output_times`, as for simulate): a
    // time within rounding past the end is the end, reported with the end's state.
    let past = 1.0 + f64::EPSILON;
    let end = stick_slip()
        .solve(1.0, &[0.5, 1.0], Tolerances::default())
        .unwrap();
    let beyond = stick_slip()
        .solve(1.0, &[0.5, past], Tolerances::default())
        .unwrap();
    assert_eq!(beyond.t, [0.5, past]);
    assert_eq!(beyond.x, end.x);
}

/// The cross-check with a well-kept stiff solver: the `differential-equations` crate's Radau5
/// (the right-hand side written out here, `|v|` unsplit, rtol 1e-10) on stick-slip, where it
/// runs (on the PID experiment it stops with "step size became too small" at rtol 1e-7 and
/// 1e-8: BENCHMARKS.md). They agree to the crate's accuracy, 1e-6 m.
#[test]
fn agrees_with_the_differential_equations_crate() {
    use differential_equations::prelude::{ImplicitRungeKutta, IVP, ODE};
    struct StickSlip;
    impl ODE<f64, [f64; 3]> for StickSlip {
        fn diff(&self, t: f64, y: &[f64; 3], dy: &mut [f64; 3]) {
            // Scaled: x and z in units of 1e-5 m, v in units of 1e-5 * 316 m/s.
            let (lx, lv) = (1e-5, 1e-5 * 1e5f64.sqrt());
            let (x, v, z) = (y[0] * lx, y[1] * lv, y[2] * lx);
            let (s0, s1, s2) = (1e5, 1e5f64.sqrt(), 0.4);
            let g = 1.0 + 0.5 * (-(v / 1e-3) * (v / 1e-3)).exp();
            let dz = v - s0 * v.abs() * z / g;
            let f = s0 * z + s1 * dz + s2 * v;
            let a = 2.0 * (0.1 * t - x) - f;
            *dy = [v / lx, a / lv, dz / lx];
        }
    }
    let times = [10.0, 20.0, 30.0];
    let sol = IVP::ode(&StickSlip, 0.0, 30.0, [0.0; 3])
        .t_eval(times)
        .method(ImplicitRungeKutta::radau5().rtol(1e-10).atol(1e-10))
        .solve()
        .expect("Radau5 runs on stick-slip");
    let ours = stick_slip()
        .solve(30.0, &times, Tolerances::new(1e-10, None).unwrap())
        .unwrap();
    for (i, t) in times.iter().enumerate() {
        let k = sol
            .t
            .iter()
            .position(|s| (s - t).abs() < 1e-9)
            .expect("the time");
        let theirs = sol.y[k][0] * 1e-5;
        // The crate steps over the kinks of |v| (no events): it lands 6.4e-7 m off at 30 s,
        // where this solver is within 2e-10 m of the scipy reference.
        assert!(
            (ours.x[i] - theirs).abs() < 2e-6,
            "t = {t}: {} vs {theirs}",
            ours.x[i]
        );
    }
}

/// A run continued from a state it passed through ([`System::solve_from`]) is the same run: the
/// stick-slip experiment stopped at 10 s (mid-slip: 0.068 m/s) and restarted from its state there
/// agrees with the reference at 20 and 30 s as the one run does.
#[test]
fn a_run_continued_from_a_state_is_the_same_run() {
    let r = reference();
    let want = samples(&r, "stickslip");
    let system = stick_slip();
    let tol = Tolerances::default();
    let first = system.solve(10.0, &[10.0], tol).unwrap();
    let start = lugre::dynamics::State {
        t: 10.0,
        x: first.x[0],
        v: first.v[0],
        z: first.z[0],
        q: 0.0,
    };
    let rest = system
        .solve_from(start, 30.0, &[10.0, 20.0, 30.0], tol)
        .unwrap();
    assert_eq!(rest.x[0], first.x[0]);
    assert!(
        worst(&rest, &want, 1.0) <= AT_DEFAULT,
        "{:e}",
        worst(&rest, &want, 1.0)
    );
    let e = system
        .solve_from(start, 5.0, &[], tol)
        .unwrap_err()
        .to_string();
    assert_eq!(e, "t_end - t0 must be a finite number > 0, got -5");
}

/// Stable at any stiffness: Table I with `sigma0` from 1e5 to 1e8 N/m (and `sigma1` keeping the
/// paper's damping ratio, `sqrt(sigma0)` for 1 kg, scaled with the mass) on masses from a gram
/// to a tonne. A force held at 90 % of `Fc` sticks (below `Fc` there is no steady sliding,
/// `g(v) + sigma2 v >= Fc`; between `Fc` and `Fs` a light mass can break away under the ramp,
/// as the integrators agree); the displacement stays within twice the bristles' reach
/// `Fs / sigma0` (a tonne on 1e5 N/m overshoots its static deflection under the ramp)),
/// a force ramped to `2 Fs` slides (well past the bristles), and the energy balance closes to
/// the tolerance.
#[test]
fn stable_at_any_stiffness_and_mass() {
    for sigma0 in [1e5, 1e6, 1e7, 1e8] {
        for mass in [1e-3, 1.0, 1e3] {
            let p = LuGreParams {
                sigma0,
                sigma1: (sigma0 * mass).sqrt(),
                ..LuGreParams::canudas_de_wit_1995()
            };
            let model = LuGre::from_params(p).unwrap();
            let (fs, reach) = (p.fs, p.fs / sigma0);
            let held = Profile::new("the force", vec![0.0, 1.0], vec![0.0, 0.9 * p.fc]).unwrap();
            let system = System::new(model.clone(), mass).unwrap().with_force(held);
            let m = system
                .solve(10.0, &[0.5, 1.0, 10.0], Tolerances::default())
                .unwrap_or_else(|e| panic!("sigma0 {sigma0:e}, M {mass}: {e}"));
            let x = m.x.iter().fold(0.0f64, |a, x| a.max(x.abs()));
            assert!(
                x < 2.0 * reach,
                "sigma0 {sigma0:e}, M {mass}: stuck at 0.9 Fc moved {x:e} (reach {reach:e})"
            );
            let e = m.energy;
            assert!(
                e.residual().abs() <= 1e-6 * e.input.abs().max(e.dissipated),
                "sigma0 {sigma0:e}, M {mass}: {e:?}"
            );
            // Past stiction: a ramp to 2 Fs over 1 s, then 1 s more: it slides.
            let ramp = Profile::new("the force", vec![0.0, 1.0], vec![0.0, 2.0 * fs]).unwrap();
            let m = System::new(model, mass)
                .unwrap()
                .with_force(ramp)
                .solve(2.0, &[2.0], Tolerances::default())
                .unwrap_or_else(|e| panic!("sigma0 {sigma0:e}, M {mass}, sliding: {e}"));
            // Well past the bristles' reach (a tonne under 3 N: about 1.5 mm in the 2 s).
            assert!(
                m.x[0] > 10.0 * reach,
                "sigma0 {sigma0:e}, M {mass}: under 2 Fs it moved only {:e}",
                m.x[0]
            );
            let e = m.energy;
            assert!(
                e.residual().abs() <= 1e-6 * e.input.abs().max(e.dissipated),
                "sigma0 {sigma0:e}, M {mass}, sliding: {e:?}"
            );
        }
    }
}
