//! The dynamics request (`lugre::dynamics::Request`): a scenario is a preset that the fields
//! given on top of it replace, two fields that cannot hold together are one error naming both,
//! counts are bounded before anything is allocated, and the end of the run follows the rules
//! of the module docs. Every front end builds this request, so these are the answers the CLI,
//! Python, the C ABI and the MEX function give.

use lugre::dynamics::{Field, Request, Scenario};
use lugre::{DynamicsError, LuGre, LuGreParams};

fn table1() -> LuGre {
    LuGre::from_params(LuGreParams::canudas_de_wit_1995()).unwrap()
}

fn err(r: Result<Request, DynamicsError>) -> String {
    match r.and_then(|r| r.build().map(|_| ())) {
        Ok(()) => panic!("expected an error"),
        Err(e) => e.to_string(),
    }
}

/// New gains on the PID experiment keep its set point (1 m): the mass moves towards it. (The
/// set point was silently dropped to 0 before: x stayed 0 for the whole run.)
#[test]
fn gains_on_the_pid_scenario_keep_its_set_point() {
    for gains in [[3.0, 8.0, 6.0], [3.0, 4.0, 6.0]] {
        let plan = Request::new()
            .with_scenario(Scenario::Pid)
            .with_pid(gains[0], gains[1], gains[2])
            .unwrap()
            .with_t_end(40.0)
            .unwrap()
            .build()
            .unwrap();
        let out = plan.run().unwrap();
        let x = *out.motion.x.last().unwrap();
        // Hunting: the mass overshoots and sticks around the set point, within 0.15 m of it.
        assert!((x - 1.0).abs() < 0.15, "{gains:?}: x(40) = {x}");
        assert!(
            plan.description.contains("xd = 1 m"),
            "{}",
            plan.description
        );
    }
    // A set point on top of the scenario replaces its set point.
    let out = Request::new()
        .with_scenario(Scenario::Pid)
        .with_setpoint(2.0)
        .unwrap()
        .with_t_end(60.0)
        .unwrap()
        .build()
        .unwrap()
        .run()
        .unwrap();
    let x = *out.motion.x.last().unwrap();
    assert!((x - 2.0).abs() < 0.15, "x(60) = {x}");
}

#[test]
fn the_scenario_and_its_setup_are_one_definition() {
    let setup = Scenario::Pid.setup(table1(), 1.0).unwrap();
    let plan = Request::new().with_scenario(Scenario::Pid).build().unwrap();
    assert_eq!(setup.t_end, plan.t_end);
    assert_eq!(setup.description, plan.description);
    let a = setup
        .system
        .solve(10.0, &[5.0, 10.0], Default::default())
        .unwrap();
    let b = plan
        .system
        .solve(10.0, &[5.0, 10.0], Default::default())
        .unwrap();
    assert_eq!(a.x, b.x);
}

/// A force rate on the break-away replaces its ramp, and its end `2 N / r` follows.
#[test]
fn a_rate_on_the_breakaway_moves_its_end() {
    let plan = Request::new()
        .with_scenario(Scenario::Breakaway { rate: 10.0 })
        .with_force_rate(4.0)
        .unwrap()
        .build()
        .unwrap();
    assert_eq!(plan.t_end, 0.5);
    assert_eq!(plan.rate, Some(4.0));
}

#[test]
fn fields_that_cannot_hold_together() {
    let r = || Request::new().with_model(table1());
    let cases: Vec<(Result<Request, DynamicsError>, &str)> = vec![
        (
            r().with_force_rate(10.0)
                .and_then(|r| r.with_force(vec![0.0], vec![1.0])),
            "give force_rate or force, not both",
        ),
        (
            r().with_force(vec![0.0], vec![1.0])
                .and_then(|r| r.with_input("d.csv", vec![0.0, 1.0], vec![0.0, 1.0])),
            "give force or input, not both",
        ),
        (
            r().with_times(vec![0.0, 1.0])
                .and_then(|r| r.with_samples(10)),
            "give times or samples, not both",
        ),
        (
            r().with_spring(2.0)
                .and_then(|r| r.with_pull(0.1))
                .and_then(|r| r.with_end(vec![0.0], vec![1.0])),
            "give pull or end, not both",
        ),
        (
            r().with_force_rate(1.0)
                .and_then(|r| r.with_velocity(vec![0.0], vec![1e-3]))
                .and_then(|r| r.with_t_end(1.0)),
            "give force_rate or velocity, not both",
        ),
        (
            Ok(Request::new().with_scenario(Scenario::Presliding))
                .and_then(|r| r.with_setpoint(1.0)),
            "setpoint needs pid",
        ),
        (
            r().with_pull(0.1).and_then(|r| r.with_t_end(1.0)),
            "pull needs spring",
        ),
        (
            r().with_spring(1.0).and_then(|r| r.with_t_end(1.0)),
            "spring needs pull or end",
        ),
        (
            Request::new()
                .with_force_rate(1.0)
                .and_then(|r| r.with_t_end(1.0)),
            "name the friction model",
        ),
        (
            r().with_t_end(1.0),
            "no drive: give scenario, force, force_rate, input",
        ),
        (
            r().with_force_rate(1.0),
            "give t_end (the end of the run, s)",
        ),
    ];
    for (request, want) in cases {
        let got = err(request);
        assert!(
            got.starts_with(want),
            "{got:?} does not start with {want:?}"
        );
    }
}

#[test]
fn a_prescribed_velocity_on_the_lag_scenario_replaces_its_velocity_and_a_drive_its_velocity() {
    let plan = Request::new()
        .with_scenario(Scenario::Lag { w: 10.0 })
        .with_velocity(vec![0.0, 1.0], vec![1e-3, 1e-3])
        .unwrap()
        .build()
        .unwrap();
    assert!(plan.description.contains("prescribed velocity profile"));
    let plan = Request::new()
        .with_scenario(Scenario::Lag { w: 10.0 })
        .with_force_rate(1.0)
        .unwrap()
        .build()
        .unwrap();
    assert_eq!(plan.rate, Some(1.0));
}

/// Counts are checked before anything is allocated, naming the field and the limit.
#[test]
fn counts_are_bounded() {
    let e = Request::new().with_samples(1_000_000_000_000).unwrap_err();
    assert_eq!(
        e.to_string(),
        "samples must be a whole number from 2 to 10000000, got 1000000000000"
    );
    assert!(matches!(
        Request::new().with_samples(u64::MAX).unwrap_err(),
        DynamicsError::Count {
            field: Field::Samples,
            ..
        }
    ));
    assert!(Request::new().with_samples(1).is_err());
    assert!(Request::new().with_times(Vec::new()).is_err());
}

/// Output times past the scenario's end extend the run to the last of them (the lag
/// experiment ends at 3 periods, 1.885 s; times to 2 s asked for a run to 2 s); the user's
/// `t_end` wins and times beyond it are an error.
#[test]
fn the_end_of_the_run() {
    let times: Vec<f64> = (0..5).map(|i| 0.5 * i as f64).collect();
    let plan = Request::new()
        .with_scenario(Scenario::Lag { w: 10.0 })
        .with_times(times.clone())
        .unwrap()
        .build()
        .unwrap();
    assert_eq!(plan.t_end, 2.0);
    assert_eq!(plan.run().unwrap().motion.t, times);
    let e = Request::new()
        .with_scenario(Scenario::Lag { w: 10.0 })
        .with_times(times)
        .unwrap()
        .with_t_end(1.0)
        .unwrap()
        .build()
        .unwrap()
        .run()
        .unwrap_err();
    assert!(e.to_string().contains("outside the run"), "{e}");
    // A measured force history runs to its last time.
    let plan = Request::new()
        .with_model(table1())
        .with_input("f.csv", vec![0.0, 0.5, 2.5], vec![0.0, 1.0, 1.0])
        .unwrap()
        .build()
        .unwrap();
    assert_eq!(plan.t_end, 2.5);
    assert_eq!(plan.description, "applied force from f.csv");
}

/// With a prescribed velocity the drive is the force `M v' + F` that makes the mass follow
/// it (it was reported as 0 while the energy balance counted its work), and the balance holds
/// with the kinetic energy stored.
#[test]
fn the_drive_of_a_prescribed_velocity() {
    let mass = 2.0;
    let plan = Request::new()
        .with_model(table1())
        .with_mass(mass)
        .unwrap()
        .with_velocity(vec![0.0, 1.0, 2.0], vec![0.0, 2e-3, 2e-3])
        .unwrap()
        .with_t_end(2.0)
        .unwrap()
        .with_samples(201)
        .unwrap()
        .build()
        .unwrap();
    let m = plan.run().unwrap().motion;
    for i in 1..m.t.len() {
        // The slope just after a knot (the profile's convention).
        let dv = if m.t[i] < 1.0 { 2e-3 } else { 0.0 };
        let want = mass * dv + m.friction[i];
        assert!(
            (m.drive[i] - want).abs() <= 1e-12 * want.abs().max(1.0),
            "t = {}: drive {} vs M v' + F = {want}",
            m.t[i],
            m.drive[i]
        );
    }
    let e = m.energy;
    assert!(e.input > 0.0);
    assert!(e.residual().abs() < 1e-9 * e.input, "{e:?}");
    assert!(
        (e.stored_end - (0.5 * mass * 4e-6 + 0.5 * 1e5 * m.z.last().unwrap().powi(2))).abs()
            < 1e-12
    );
}

/// Every message spells the fields its front end's way.
#[test]
fn messages_spell_the_fields_per_front_end() {
    let e = Request::new()
        .with_force_rate(10.0)
        .unwrap()
        .with_force(vec![0.0], vec![1.0])
        .unwrap_err();
    let flags = e.render(|f| format!("--{}", f.name().replace('_', "-")));
    assert_eq!(
        flags,
        "give --force-rate or --force, not both: they set the same thing"
    );
    assert_eq!(
        e.to_string(),
        "give force_rate or force, not both: they set the same thing"
    );
    for f in Field::ALL {
        assert!(
            !f.name().is_empty() && f.name().chars().all(|c| c.is_ascii_lowercase() || c == '_')
        );
    }
}

/// The pre-sliding scenario reports its loops by default; `with_loops(false)` turns them off.
#[test]
fn loops_default_per_scenario() {
    let on = Request::new()
        .with_scenario(Scenario::Presliding)
        .build()
        .unwrap();
    assert!(on.loops);
    let off = Request::new()
        .with_scenario(Scenario::Presliding)
        .with_loops(false)
        .build()
        .unwrap();
    assert!(!off.loops);
    let pid = Request::new().with_scenario(Scenario::Pid).build().unwrap();
    assert!(!pid.loops);
}

/// A zoo model as the friction on a scenario: the parameters its maker named are kept, the
/// others are the scenario's (Table I), and an unnamed `zba` is `fc / (2 sigma0)` at that
/// scale; without a scenario the model is taken as built. Every front end passes a
/// `ZooModel` here, so they all run the same friction for the same named values.
#[test]
fn a_zoo_model_on_a_scenario_takes_the_unnamed_parameters_from_table_i() {
    use lugre::dynamics::FrictionLaw;
    use lugre::zoo::ZooModel;
    let plan = |zoo: &ZooModel, scenario: Option<Scenario>| {
        let mut r = Request::new();
        if let Some(s) = scenario {
            r = r.with_scenario(s);
        } else {
            r = r.with_force_rate(1.0).unwrap().with_t_end(1.0).unwrap();
        }
        r.with_zoo(zoo).unwrap().build().unwrap()
    };
    let only_zba = ZooModel::new("elastoplastic", &[("zba", &[4e-6])]).unwrap();
    let p = plan(&only_zba, Some(Scenario::Breakaway { rate: 10.0 }));
    assert_eq!(p.system.model().params(), table1().params());
    assert_eq!(p.system.law(), FrictionLaw::ElastoPlastic { zba: 4e-6 });

    let nothing = ZooModel::new("elastoplastic", &[]).unwrap();
    let p = plan(&nothing, Some(Scenario::StickSlip));
    assert_eq!(p.system.model().params(), table1().params());
    assert_eq!(p.system.law(), FrictionLaw::ElastoPlastic { zba: 0.5e-5 });

    // A named value wins over Table I; zba still follows the resolved fc / sigma0.
    let fc = ZooModel::new("elastoplastic", &[("fc", &[1.2]), ("fs", &[1.4])]).unwrap();
    let p = plan(&fc, Some(Scenario::StickSlip));
    let q = p.system.model().params();
    assert_eq!((q.sigma0, q.fc, q.fs, q.vs), (1e5, 1.2, 1.4, 1e-3));
    assert_eq!(
        p.system.law(),
        FrictionLaw::ElastoPlastic {
            zba: 0.5 * 1.2 / 1e5
        }
    );

    // No scenario: the model as built, the table's defaults included.
    let p = plan(&nothing, None);
    let q = p.system.model().params();
    assert_eq!((q.sigma0, q.fc, q.fs), (1.0, 1.0, 2.0));
    assert_eq!(p.system.law(), FrictionLaw::ElastoPlastic { zba: 0.5 });
}

/// The table's `finite_rate` is what the dynamics take: every model with it is accepted as a
/// friction, every other one refused with the message listing the ones there are.
#[test]
fn the_dynamics_take_the_models_with_a_finite_rate_form() {
    use lugre::zoo::{dynamics_model_names, ZooModel, MODELS};
    for spec in MODELS {
        let model = ZooModel::new(spec.name, &[]).unwrap();
        let r = Request::new().with_zoo(&model);
        assert_eq!(r.is_ok(), spec.finite_rate, "{}", spec.name);
        if let Err(e) = r {
            let names = dynamics_model_names();
            assert!(names.starts_with("lugre, dahl") && names.contains(" or "));
            assert!(e.to_string().contains(&names), "{e}");
        }
    }
}
