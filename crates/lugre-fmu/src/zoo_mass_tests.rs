//! The mass FMUs of the zoo's finite-rate models: their descriptions (`fmu/mass/NAME.xml`) are
//! the core's table, the references name what the code serves, and through the FMI functions
//! a run is `lugre dynamics --model NAME`'s and a bad parameter is `fmi3Error` naming it.

use lugre::dynamics::Request;
use lugre::zoo::{ZooModel, ZooModelSpec, MODELS};

use crate::tests::{co_simulation, last_logged, SERIAL};
use crate::zoo_mass::{self, vr, ZooMass};
use crate::zoo_tests::{check_names, check_written};
use crate::*;

fn finite_rate() -> Vec<&'static ZooModelSpec> {
    MODELS.iter().filter(|m| m.finite_rate).collect()
}

#[test]
fn the_mass_model_descriptions_are_written_from_the_table() {
    let specs = finite_rate();
    assert!(specs.len() >= 2);
    check_written("mass", &specs, zoo_mass::model_description);
}

#[test]
fn the_mass_descriptions_name_what_the_code_serves() {
    for spec in finite_rate() {
        let xml = zoo_mass::model_description(spec).unwrap();
        let seen = check_names(&xml, &ZooMass::new(spec), spec.name);
        assert!(seen >= 9 + spec.parameters.len(), "{}: {seen}", spec.name);
        let token = zoo_mass::token(spec);
        assert_eq!(
            zoo_mass::model_of(token.as_bytes()).map(|m| m.name),
            Some(spec.name)
        );
    }
    // No mass FMU for a model without a finite-rate form.
    let slow = MODELS.iter().find(|m| !m.finite_rate).unwrap();
    assert!(zoo_mass::model_of(zoo_mass::token(slow).as_bytes()).is_none());
}

/// An instance of the mass FMU of `spec`, initialized with `set` (value reference, value).
fn initialized(spec: &ZooModelSpec, set: &[(u32, f64)]) -> (Instance, Status) {
    let token = std::ffi::CString::new(zoo_mass::token(spec)).unwrap();
    let cs = co_simulation(&token);
    assert!(!cs.is_null());
    for (r, v) in set {
        assert_eq!(
            fmi3SetFloat64(cs, [*r].as_ptr(), 1, [*v].as_ptr(), 1),
            Status::Ok
        );
    }
    assert_eq!(
        fmi3EnterInitializationMode(cs, false, 0.0, 0.0, false, 0.0),
        Status::Ok
    );
    (cs, fmi3ExitInitializationMode(cs))
}

fn get(cs: Instance, refs: &[u32]) -> Vec<f64> {
    let mut out = vec![0.0; refs.len()];
    let status = fmi3GetFloat64(cs, refs.as_ptr(), refs.len(), out.as_mut_ptr(), out.len());
    assert_eq!(status, Status::Ok);
    out
}

/// A force ramp `F = 1.5 t` over 2 s in 1 ms communication steps (force and its rate set at
/// each): the position, velocity and friction at 2 s are `lugre dynamics --model NAME
/// --force-profile 0:0,2:3`'s to the tolerance.
#[test]
fn a_ramp_in_small_steps_is_the_dynamics_run() {
    let _serial = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    for spec in finite_rate() {
        let (cs, status) = initialized(spec, &[]);
        assert_eq!(status, Status::Ok, "{}", last_logged());
        let (h, n) = (1e-3, 2000);
        let (mut a, mut b, mut c, mut t) = (false, false, false, 0.0);
        for k in 0..n {
            let t0 = k as f64 * h;
            let refs = [vr::FORCE, vr::DFORCE];
            let status = fmi3SetFloat64(cs, refs.as_ptr(), 2, [1.5 * t0, 1.5].as_ptr(), 2);
            assert_eq!(status, Status::Ok);
            let status = fmi3DoStep(cs, t0, h, false, &mut a, &mut b, &mut c, &mut t);
            assert_eq!(status, Status::Ok, "{}", last_logged());
        }
        let got = get(cs, &[vr::X, vr::V, vr::FRICTION]);
        fmi3FreeInstance(cs);
        let run = Request::new()
            .with_zoo(&ZooModel::new(spec.name, &[]).unwrap())
            .unwrap()
            .with_force(vec![0.0, 2.0], vec![0.0, 3.0])
            .unwrap()
            .with_t_end(2.0)
            .unwrap()
            .with_times(vec![2.0])
            .unwrap()
            .build()
            .unwrap()
            .motion()
            .unwrap();
        assert!(run.x[0] > 0.01, "{}: it slid", spec.name);
        let want = [run.x[0], run.v[0], run.friction[0]];
        for (g, w) in got.iter().zip(want) {
            // rtol 1e-8 on both sides, over 2000 restarts: within 1e-7 of the scale (3 N,
            // and x, v of order 1).
            assert!(
                (g - w).abs() < 1e-7 * w.abs().max(1.0),
                "{}: {got:?} {want:?}",
                spec.name
            );
        }
    }
}

/// A parameter outside its domain and a bad mass: `fmi3Error` at the end of initialization,
/// the message naming the parameter and its value; model exchange refused.
#[test]
fn bad_parameters_are_errors_naming_them() {
    let _serial = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    for spec in finite_rate() {
        let first = crate::vr::PARAMETERS;
        let p = &spec.parameters[0];
        let n = p.default.len();
        let token = std::ffi::CString::new(zoo_mass::token(spec)).unwrap();
        let cs = co_simulation(&token);
        let bad = vec![-2.5; n];
        assert_eq!(
            fmi3SetFloat64(cs, [first].as_ptr(), 1, bad.as_ptr(), n),
            Status::Ok
        );
        assert_eq!(
            fmi3EnterInitializationMode(cs, false, 0.0, 0.0, false, 0.0),
            Status::Ok
        );
        assert_eq!(fmi3ExitInitializationMode(cs), Status::Error);
        let message = last_logged();
        assert!(
            message.contains(p.name) && message.contains("-2.5"),
            "{}: {message}",
            spec.name
        );
        fmi3FreeInstance(cs);

        let (cs, status) = initialized(spec, &[(vr::M, -3.0)]);
        assert_eq!(status, Status::Error);
        assert_eq!(
            last_logged(),
            "the mass must be a finite number > 0, got -3"
        );
        fmi3FreeInstance(cs);

        let (cs, status) = initialized(spec, &[]);
        assert_eq!(status, Status::Ok);
        assert_eq!(
            fmi3SetFloat64(cs, [vr::M].as_ptr(), 1, [2.0].as_ptr(), 1),
            Status::Error
        );
        assert_eq!(
            last_logged(),
            "m is a fixed parameter: set it before the end of initialization"
        );
        fmi3FreeInstance(cs);

        let me = fmi3InstantiateModelExchange(
            c"m".as_ptr(),
            token.as_ptr(),
            std::ptr::null(),
            false,
            false,
            std::ptr::null_mut(),
            Some(crate::tests::collect),
        );
        assert!(me.is_null());
        assert!(last_logged().contains("co-simulation only"));
    }
}

/// The start `x0`, `v0` with the friction at rest: the outputs before any step.
#[test]
fn the_run_starts_at_x0_and_v0() {
    let _serial = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    for spec in finite_rate() {
        let (cs, status) = initialized(spec, &[(vr::X0, 0.5), (vr::V0, 0.0)]);
        assert_eq!(status, Status::Ok);
        assert_eq!(get(cs, &[vr::X, vr::V, vr::FRICTION]), [0.5, 0.0, 0.0]);
        fmi3FreeInstance(cs);
    }
}
