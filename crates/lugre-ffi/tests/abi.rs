//! The C entry points called as C would: results, error codes, messages, and bad input.

use lugre::model::Parameter;
use lugre_c::*;
use std::ffi::CStr;
use std::ptr;

fn last_error() -> String {
    unsafe { CStr::from_ptr(lugre_last_error()) }
        .to_string_lossy()
        .into_owned()
}

fn table1() -> *mut LugreModel {
    let mut p = LugreParams::default();
    assert_eq!(lugre_params_canudas1995(&mut p), LugreStatus::Ok);
    let mut m = ptr::null_mut();
    assert_eq!(lugre_model_new(&p, &mut m), LugreStatus::Ok);
    m
}

#[test]
fn invalid_parameters_are_an_error_with_the_cores_message() {
    let p = LugreParams {
        sigma0: f64::NAN,
        ..LugreParams::default()
    };
    let mut m = ptr::null_mut();
    assert_eq!(lugre_model_new(&p, &mut m), LugreStatus::InvalidArgument);
    assert!(m.is_null());
    assert!(
        last_error().starts_with("sigma0 must be"),
        "{}",
        last_error()
    );
    assert_eq!(
        lugre_model_new(ptr::null(), &mut m),
        LugreStatus::NullPointer
    );
    assert_eq!(last_error(), "params is NULL");
    assert_eq!(
        lugre_model_new_dahl(-1.0, 1.0, &mut m),
        LugreStatus::InvalidArgument
    );
}

#[test]
fn non_finite_inputs_and_short_buffers_are_refused() {
    let m = table1();
    let mut hl = ptr::null_mut();
    let u = [0.0, 1e-5, f64::INFINITY];
    assert_eq!(
        lugre_loop_new(m, u.as_ptr(), 3, &mut hl),
        LugreStatus::InvalidArgument
    );
    assert_eq!(last_error(), "u[2] must be a finite number, got inf");
    let u = [0.0, 1e-5, 5e-6];
    assert_eq!(lugre_loop_new(m, u.as_ptr(), 3, &mut hl), LugreStatus::Ok);
    let mut len = 0;
    assert_eq!(lugre_loop_turning_len(hl, &mut len), LugreStatus::Ok);
    assert_eq!(len, 2, "5e-6 is on the way back to 0: not a turning point");
    let mut y = [0.0; 1];
    assert_eq!(
        lugre_loop_turning(hl, ptr::null_mut(), ptr::null_mut(), y.as_mut_ptr(), 1),
        LugreStatus::BufferTooSmall
    );
    assert_eq!(y, [0.0; 1], "nothing written on failure");
    assert_eq!(
        last_error(),
        "the output buffers hold 1, the result has 2 values"
    );
    lugre_loop_free(hl);
    // A step that jumps in zero time, a NaN step: errors, the element unchanged.
    let mut e = ptr::null_mut();
    assert_eq!(lugre_element_new(m, 0.0, &mut e), LugreStatus::Ok);
    let mut f = 0.0;
    assert_eq!(lugre_element_step(e, 1e-6, 1e-3, &mut f), LugreStatus::Ok);
    let before = f;
    assert_eq!(
        lugre_element_step(e, 2e-6, 0.0, &mut f),
        LugreStatus::InvalidArgument
    );
    assert_eq!(
        lugre_element_step(e, f64::NAN, 1e-3, &mut f),
        LugreStatus::InvalidArgument
    );
    assert_eq!(f, before);
    let mut now = 0.0;
    assert_eq!(
        lugre_element_state(
            e,
            ptr::null_mut(),
            ptr::null_mut(),
            ptr::null_mut(),
            &mut now
        ),
        LugreStatus::Ok
    );
    assert_eq!(now, before);
    lugre_element_free(e);
    lugre_element_free(ptr::null_mut()); // NULL is fine
    lugre_model_free(m);
}

#[test]
fn cycles_simulate_and_dynamics_through_the_abi() {
    let h = [-2.0, 1.0, -3.0, 5.0, -1.0, 3.0, -4.0, 4.0, -2.0];
    let mut c = ptr::null_mut();
    assert_eq!(
        lugre_cycles_new(h.as_ptr(), 9, 0.0, ptr::null(), 0.0, &mut c),
        LugreStatus::Ok
    );
    let mut n = 0;
    assert_eq!(lugre_cycles_len(c, &mut n), LugreStatus::Ok);
    let (mut range, mut count, mut closure, mut pos) = ([0.0; 7], [0.0; 7], [0i64; 7], [9.0; 7]);
    let cols = LugreCycleColumns {
        range: range.as_mut_ptr(),
        mean: ptr::null_mut(),
        count: count.as_mut_ptr(),
        start: ptr::null_mut(),
        end: ptr::null_mut(),
        closure: closure.as_mut_ptr(),
        closure_position: pos.as_mut_ptr(),
        work: ptr::null_mut(),
        stored_energy_change: ptr::null_mut(),
        dissipation: ptr::null_mut(),
        closure_gap: ptr::null_mut(),
    };
    assert_eq!(lugre_cycles_columns(c, &cols, 7), LugreStatus::Ok);
    assert_eq!(
        (n, range, count),
        (
            7,
            [3.0, 4.0, 4.0, 8.0, 9.0, 8.0, 6.0],
            [0.5, 0.5, 1.0, 0.5, 0.5, 0.5, 0.5]
        )
    );
    assert_eq!(closure[2], 6);
    assert_eq!(pos[2], 5.0 + 4.0 / 7.0);
    assert!(
        pos.iter().all(|p| p.is_finite()),
        "no NaN for half cycles: {pos:?}"
    );
    lugre_cycles_free(c);

    // The library's messages, word for word those of `lugre cycles --values` and
    // `lugre.cycles` on the same series.
    for (u, message) in [
        (
            &[0.0, f64::NAN, 1.0][..],
            "u[1] must be a finite number, got NaN",
        ),
        (&[1.0][..], "a history needs at least 2 samples, got 1"),
    ] {
        let mut c = ptr::null_mut();
        assert_eq!(
            lugre_cycles_new(u.as_ptr(), u.len(), 0.0, ptr::null(), 0.0, &mut c),
            LugreStatus::InvalidArgument
        );
        assert_eq!(last_error(), message);
        assert!(c.is_null());
    }

    let m = table1();
    // An open record (it does not end where it starts): the last value is the last segment's.
    let (t, x) = ([0.0, 1e-2, 2e-2], [0.0, 1e-5, 2e-6]);
    let (mut z, mut f) = ([0.0; 3], [0.0; 3]);
    assert_eq!(
        lugre_simulate(
            m,
            t.as_ptr(),
            x.as_ptr(),
            3,
            0.0,
            z.as_mut_ptr(),
            f.as_mut_ptr()
        ),
        LugreStatus::Ok
    );
    assert!(z[1] > 0.0 && f[2] < 0.0, "{z:?} {f:?}");
    lugre_model_free(m);

    let times = [10.0, 20.0, 30.0];
    let mut xs = [0.0; 3];
    let mut positions = |name: &CStr| {
        let null = ptr::null_mut();
        let x = xs.as_mut_ptr();
        lugre_dynamics_scenario(name.as_ptr(), 0.0, times.as_ptr(), 3, x, null, null, null)
    };
    assert_eq!(positions(c"stick-slip"), LugreStatus::Ok);
    assert_eq!(positions(c"nope"), LugreStatus::InvalidArgument);
    // The reference (scipy Radau 1e-12; crates/lugre/tests/reference/dynamics): x(30) = 2.545101...
    assert!((xs[2] - 2.5451019).abs() < 1e-6, "{xs:?}");
    assert!(last_error().starts_with("unknown scenario 'nope'"));
}

#[test]
fn loop_sample_checks_its_count_and_is_the_cores_sample() {
    let m = table1();
    let mut hl = ptr::null_mut();
    let u = [0.0, 1e-5, 5e-6, 1.5e-5];
    assert_eq!(lugre_loop_new(m, u.as_ptr(), 4, &mut hl), LugreStatus::Ok);
    // Buffers sized for n = 0 and 1 (the core would make 2 points): refused, nothing written.
    let mut y = [7.0; 1];
    for n in [0, 1] {
        let status = lugre_loop_sample(hl, n, ptr::null_mut(), ptr::null_mut(), y.as_mut_ptr());
        assert_eq!(status, LugreStatus::InvalidArgument);
        assert_eq!(
            last_error(),
            format!("n must be at least 2 (both ends of the period), got {n}")
        );
    }
    assert_eq!(y, [7.0]);
    assert_eq!(
        lugre_loop_sample(
            hl,
            usize::MAX / 8,
            ptr::null_mut(),
            ptr::null_mut(),
            ptr::null_mut()
        ),
        LugreStatus::InvalidArgument
    );
    assert!(
        last_error().starts_with("n must be at most 10000000 (memory for the points), got "),
        "{}",
        last_error()
    );
    let (mut rho, mut uu, mut yy) = ([0.0; 5], [0.0; 5], [0.0; 5]);
    let status = lugre_loop_sample(hl, 5, rho.as_mut_ptr(), uu.as_mut_ptr(), yy.as_mut_ptr());
    assert_eq!(status, LugreStatus::Ok);
    let model = lugre::LuGre::from_params(lugre::LuGreParams::canudas_de_wit_1995()).unwrap();
    let tp = lugre::TurningPoints::new(&u).unwrap();
    let core = lugre::HysteresisLoop::new(model.rate_independent(), &tp).unwrap();
    let want = core.sample(5);
    assert_eq!(rho.to_vec(), want.iter().map(|p| p.rho).collect::<Vec<_>>());
    assert_eq!(uu.to_vec(), want.iter().map(|p| p.u).collect::<Vec<_>>());
    assert_eq!(yy.to_vec(), want.iter().map(|p| p.y).collect::<Vec<_>>());
    let (mut work, mut period) = (0.0, 0.0);
    assert_eq!(
        lugre_loop_summary(hl, &mut work, &mut period),
        LugreStatus::Ok
    );
    assert_eq!((work, period), (core.work_per_period(), core.period()));
    lugre_loop_free(hl);
    lugre_model_free(m);
}

#[test]
fn an_element_step_past_the_largest_time_is_refused() {
    let m = table1();
    let mut e = ptr::null_mut();
    assert_eq!(lugre_element_new(m, 0.0, &mut e), LugreStatus::Ok);
    assert_eq!(
        lugre_element_step(e, 0.0, 1.7e308, ptr::null_mut()),
        LugreStatus::Ok
    );
    assert_eq!(
        lugre_element_step(e, 0.0, 1.7e308, ptr::null_mut()),
        LugreStatus::InvalidArgument
    );
    assert_eq!(
        last_error(),
        "the step 1.7e308 from t = 1.7e308 takes the time past the largest finite number"
    );
    let mut t = 0.0;
    let null = ptr::null_mut();
    assert_eq!(
        lugre_element_state(e, &mut t, null, null, null),
        LugreStatus::Ok
    );
    assert_eq!(t, 1.7e308);
    lugre_element_free(e);
    lugre_model_free(m);
}

/// The struct's fields are the table's parameters in its order: the header (written from the
/// table) and the Rust struct (the core's `#[repr(C)]` `LuGreParams`) agree on every place.
#[test]
fn the_params_struct_holds_each_parameter_at_its_place_in_the_table() {
    const N: usize = Parameter::LUGRE.len();
    for (i, p) in Parameter::LUGRE.into_iter().enumerate() {
        let mut s = LugreParams::default();
        s.set(p, 1234.5);
        // SAFETY: LugreParams is N doubles (asserted at build time by the library).
        let doubles: [f64; N] = unsafe { std::mem::transmute(s) };
        let at: Vec<usize> = (0..N).filter(|&k| doubles[k] == 1234.5).collect();
        assert_eq!(at, [i], "{p}");
    }
}

/// The work per period of a loop of `m` (and frees `m`): a model's fingerprint.
fn loop_work(m: *mut LugreModel) -> f64 {
    let u = [0.0, 1.0, 0.5, 1.5];
    let mut hl = ptr::null_mut();
    assert_eq!(lugre_loop_new(m, u.as_ptr(), 4, &mut hl), LugreStatus::Ok);
    let (mut work, mut period) = (0.0, 0.0);
    assert_eq!(
        lugre_loop_summary(hl, &mut work, &mut period),
        LugreStatus::Ok
    );
    lugre_loop_free(hl);
    lugre_model_free(m);
    work
}

/// A model of either family from its parameters by name, the others at the table's defaults.
#[test]
fn a_model_from_named_parameters() {
    let names = [c"RHO".as_ptr(), c"fc".as_ptr()];
    let values = [2.0, 0.5];
    let (mut m, mut want) = (ptr::null_mut(), ptr::null_mut());
    assert_eq!(
        lugre_model_new_named(
            LUGRE_FAMILY_DAHL,
            2,
            names.as_ptr(),
            values.as_ptr(),
            &mut m
        ),
        LugreStatus::Ok
    );
    assert_eq!(lugre_model_new_dahl(2.0, 0.5, &mut want), LugreStatus::Ok);
    assert_eq!(loop_work(m), loop_work(want));
    // Nothing named: every parameter at the table's default.
    assert_eq!(
        lugre_model_new_named(LUGRE_FAMILY_LUGRE, 0, ptr::null(), ptr::null(), &mut m),
        LugreStatus::Ok
    );
    assert_eq!(
        lugre_model_new(&LugreParams::default(), &mut want),
        LugreStatus::Ok
    );
    assert_eq!(loop_work(m), loop_work(want));
    let mut none = ptr::null_mut();
    assert_eq!(
        lugre_model_new_named(
            LUGRE_FAMILY_DAHL,
            1,
            [c"sigma0".as_ptr()].as_ptr(),
            [1.0].as_ptr(),
            &mut none
        ),
        LugreStatus::InvalidArgument
    );
    assert_eq!(
        last_error(),
        format!(
            "unknown parameter 'sigma0' for the Dahl model (its parameters: {})",
            lugre::fit::Family::Dahl.parameters().join(", ")
        )
    );
    let twice = [c"fc".as_ptr(), c"Fc".as_ptr()];
    assert_eq!(
        lugre_model_new_named(
            LUGRE_FAMILY_DAHL,
            2,
            twice.as_ptr(),
            values.as_ptr(),
            &mut none
        ),
        LugreStatus::InvalidArgument
    );
    assert_eq!(last_error(), "names[1] gives fc a second time");
    assert_eq!(
        lugre_model_new_named(
            LUGRE_FAMILY_DAHL,
            1,
            names.as_ptr(),
            [0.0].as_ptr(),
            &mut none
        ),
        LugreStatus::InvalidArgument
    );
    assert_eq!(last_error(), "rho must be > 0, got 0");
    assert_eq!(
        lugre_model_new_named(
            LUGRE_FAMILY_DAHL,
            1,
            ptr::null(),
            values.as_ptr(),
            &mut none
        ),
        LugreStatus::NullPointer
    );
    assert_eq!(last_error(), "names is NULL");
    assert_eq!(
        lugre_model_new_named(7, 0, ptr::null(), ptr::null(), &mut none),
        LugreStatus::InvalidArgument
    );
    assert!(none.is_null());
}

#[test]
fn parameters_by_name() {
    let mut p = LugreParams::default();
    assert_eq!(
        lugre_params_set(&mut p, c" FS ".as_ptr(), 3.0),
        LugreStatus::Ok
    );
    assert_eq!(p.fs, 3.0);
    assert_eq!(
        lugre_params_set(&mut p, c"rho".as_ptr(), 3.0),
        LugreStatus::InvalidArgument
    );
    assert_eq!(
        last_error(),
        format!(
            "unknown parameter 'rho' for the LuGre model (its parameters: {})",
            lugre::fit::Family::LuGre.parameters().join(", ")
        )
    );
    let mut name = ptr::null();
    let names = |family: i32, count: usize| -> Vec<String> {
        (0..count)
            .map(|i| {
                let mut name = ptr::null();
                assert_eq!(lugre_parameter_name(family, i, &mut name), LugreStatus::Ok);
                unsafe { CStr::from_ptr(name) }
                    .to_str()
                    .unwrap()
                    .to_string()
            })
            .collect()
    };
    let core =
        |ps: &[Parameter]| -> Vec<String> { ps.iter().map(|p| p.name().to_string()).collect() };
    assert_eq!(
        names(LUGRE_FAMILY_LUGRE, Parameter::LUGRE.len()),
        core(&Parameter::LUGRE)
    );
    assert_eq!(
        names(LUGRE_FAMILY_DAHL, Parameter::DAHL.len()),
        core(&Parameter::DAHL)
    );
    assert_eq!(
        lugre_parameter_name(LUGRE_FAMILY_DAHL, Parameter::DAHL.len(), &mut name),
        LugreStatus::InvalidArgument
    );
    assert_eq!(last_error(), "index must be below 2, got 2");
    assert_eq!(
        lugre_parameter_name(5, 0, &mut name),
        LugreStatus::InvalidArgument
    );
    assert!(last_error().starts_with("family must be LUGRE_FAMILY_LUGRE (0)"));
}

/// Samples of the paper's Example 4 loop (sigma0 = 6, fs = 2), every 1/160 of rho, with a
/// small deterministic ripple so that the standard errors are not 0.
fn example4_record() -> (Vec<f64>, Vec<f64>) {
    let model = lugre::LuGre::paper().with_sigma0(6.0).unwrap();
    let tp = lugre::TurningPoints::new(&[0.0, 1.0, 0.5, 1.5]).unwrap();
    let hl = lugre::HysteresisLoop::new(model.rate_independent(), &tp).unwrap();
    let points = hl.sample(401);
    let u = points.iter().map(|p| p.u).collect();
    let f = points
        .iter()
        .enumerate()
        .map(|(i, p)| p.y + 1e-3 * ((i * 7919 % 13) as f64 - 6.0))
        .collect();
    (u, f)
}

fn zero_result() -> LugreFitResult {
    LugreFitResult {
        family: -1,
        parameters: 0,
        value: [0.0; LUGRE_MAX_PARAMETERS],
        fitted: [0; LUGRE_MAX_PARAMETERS],
        std_error: [0.0; LUGRE_MAX_PARAMETERS],
        ci95_lo: [0.0; LUGRE_MAX_PARAMETERS],
        ci95_hi: [0.0; LUGRE_MAX_PARAMETERS],
        at_bound: [0; LUGRE_MAX_PARAMETERS],
        rms: 0.0,
        samples: 0,
        dof: 0,
        t_quantile: 0.0,
        condition_number: 0.0,
        iterations: 0,
        evaluations: 0,
        starts: 0,
        converged: 0,
        turning_points: 0,
    }
}

#[test]
fn the_slow_fit_is_the_cores() {
    let (u, f) = example4_record();
    let n = u.len();
    let mut r = zero_result();
    let mut curve = vec![0.0; n];
    let status = lugre_fit_slow(
        u.as_ptr(),
        f.as_ptr(),
        n,
        ptr::null(),
        &mut r,
        curve.as_mut_ptr(),
    );
    assert_eq!(status, LugreStatus::Ok, "{}", last_error());
    let spec = lugre::FitSpec::new(lugre::fit::Family::LuGre);
    let core = lugre::fit_slow(&spec, &u, &f).unwrap();
    let s0 = core.estimate("sigma0").unwrap();
    let fs = core.estimate("fs").unwrap();
    assert_eq!(
        (r.family, r.parameters),
        (LUGRE_FAMILY_LUGRE, Parameter::LUGRE.len())
    );
    // The slow fit's: sigma0 and fs.
    let slow = Parameter::LUGRE.map(|p| i32::from(Parameter::LUGRE_RATE_INDEPENDENT.contains(&p)));
    assert_eq!(r.fitted[..r.parameters], slow);
    assert_eq!((r.value[0], r.std_error[0]), (s0.value, s0.stderr));
    assert_eq!((r.value[4], r.std_error[4]), (fs.value, fs.stderr));
    assert_eq!([r.ci95_lo[0], r.ci95_hi[0]], s0.ci95);
    assert!(r.std_error[0] > 0.0 && (r.value[0] - 6.0).abs() < 10.0 * r.std_error[0]);
    // The parameters the loop does not depend on keep the model's values (the defaults).
    assert_eq!((r.value[1], r.std_error[1], r.ci95_lo[1]), (1.0, 0.0, 1.0));
    assert_eq!(
        (r.rms, r.samples, r.dof, r.converged),
        (core.rms, n, core.dof, 1)
    );
    assert_eq!(r.turning_points, core.turning_points.unwrap());
    assert_eq!(curve, core.fitted);

    // Dahl, with its values from a model; fc held at 2.
    let mut dahl = ptr::null_mut();
    assert_eq!(lugre_model_new_dahl(1.0, 2.0, &mut dahl), LugreStatus::Ok);
    let mut o = LugreFitOptions {
        family: 7,
        model: ptr::null(),
        fix: ptr::null(),
        free: ptr::null(),
        x0: 1.0,
        starts: 0,
    };
    assert_eq!(lugre_fit_options_default(&mut o), LugreStatus::Ok);
    assert_eq!(
        (o.model, o.fix, o.x0, o.starts),
        (ptr::null(), ptr::null(), 0.0, 0)
    );
    assert_eq!(o.family, LUGRE_FAMILY_LUGRE);
    o.model = dahl;
    let null = ptr::null_mut();
    let status = lugre_fit_slow(u.as_ptr(), f.as_ptr(), n, &o, &mut r, null);
    assert_eq!(status, LugreStatus::InvalidArgument);
    assert_eq!(
        last_error(),
        "options.model is a Dahl model, options.family says LuGre"
    );
    o.family = LUGRE_FAMILY_DAHL;
    o.fix = c"fc".as_ptr();
    assert_eq!(
        lugre_fit_slow(u.as_ptr(), f.as_ptr(), n, &o, &mut r, null),
        LugreStatus::Ok
    );
    assert_eq!(
        (r.family, &r.fitted[..r.parameters]),
        (LUGRE_FAMILY_DAHL, &[1, 0][..])
    );
    assert_eq!(r.value[1], 2.0);
    let spec = lugre::FitSpec::dahl(1.0, 2.0).fix("fc").unwrap();
    assert_eq!(
        r.value[0],
        lugre::fit_slow(&spec, &u, &f).unwrap().estimates[0].value
    );

    // Bad requests: the message names the option or the sample, nothing is written.
    let before = r;
    o.fix = c"fc, nope".as_ptr();
    assert_eq!(
        lugre_fit_slow(u.as_ptr(), f.as_ptr(), n, &o, &mut r, null),
        LugreStatus::InvalidArgument
    );
    assert!(
        last_error().starts_with("options.fix: "),
        "{}",
        last_error()
    );
    assert!(last_error().contains("nope"), "{}", last_error());
    o.fix = c"fc,".as_ptr();
    assert_eq!(
        lugre_fit_slow(u.as_ptr(), f.as_ptr(), n, &o, &mut r, null),
        LugreStatus::InvalidArgument
    );
    assert_eq!(last_error(), "options.fix has an empty name in 'fc,'");
    o.fix = ptr::null();
    o.family = 9;
    let status = lugre_fit_slow(u.as_ptr(), f.as_ptr(), n, &o, &mut r, null);
    assert_eq!(status, LugreStatus::InvalidArgument);
    assert!(last_error().starts_with("options.family must be LUGRE_FAMILY_LUGRE (0)"));
    o.family = LUGRE_FAMILY_DAHL;
    o.x0 = 0.5;
    assert_eq!(
        lugre_fit_slow(u.as_ptr(), f.as_ptr(), n, &o, &mut r, null),
        LugreStatus::InvalidArgument
    );
    assert_eq!(
        last_error(),
        "options.x0 applies to the full fit (lugre_fit), not the slow fit"
    );
    let mut g = f.clone();
    g[3] = f64::NAN;
    assert_eq!(
        lugre_fit_slow(u.as_ptr(), g.as_ptr(), n, ptr::null(), &mut r, null),
        LugreStatus::InvalidArgument
    );
    assert_eq!(last_error(), "f[3] must be a finite number, got NaN");
    assert_eq!(r, before);
    lugre_model_free(dahl);
}

#[test]
fn the_full_fit_is_the_cores() {
    // Sweeps of +-6 at three speeds of the paper's model; sigma2 = 0 and beta = 1 held.
    let model = lugre::LuGre::paper();
    let (mut t, mut u) = (vec![0.0], vec![-6.0_f64]);
    for speed in [0.1, 1.0, 10.0] {
        for target in [6.0, -6.0] {
            let (t0, u0) = (*t.last().unwrap(), *u.last().unwrap());
            for j in 1..=60 {
                let x = f64::from(j) / 60.0;
                t.push(t0 + (target - u0).abs() / speed * x);
                u.push(u0 + (target - u0) * x);
            }
        }
    }
    let input = lugre::PiecewiseLinear::new(t.clone(), u.clone()).unwrap();
    let mut sim = lugre::Trajectory::default();
    lugre::Simulator::new(&model, lugre::Gamma::ONE, 0.0)
        .unwrap()
        .at_knots(&input, 1, &mut sim)
        .unwrap();
    let mut f: Vec<f64> = sim
        .y
        .iter()
        .enumerate()
        .map(|(i, y)| y + 1e-3 * ((i * 7919 % 13) as f64 - 6.0))
        .collect();
    f[5] = f64::NAN; // no force measured there
    let n = t.len();
    let mut p = LugreParams::default();
    assert_eq!(lugre_params_default(&mut p), LugreStatus::Ok);
    let mut m = ptr::null_mut();
    assert_eq!(lugre_model_new(&p, &mut m), LugreStatus::Ok);
    let o = LugreFitOptions {
        family: LUGRE_FAMILY_LUGRE,
        model: m,
        fix: c"sigma2,beta".as_ptr(),
        free: ptr::null(),
        x0: 0.0,
        starts: 2,
    };
    let mut r = zero_result();
    let mut curve = vec![0.0; n];
    let status = lugre_fit(
        t.as_ptr(),
        u.as_ptr(),
        f.as_ptr(),
        n,
        &o,
        &mut r,
        curve.as_mut_ptr(),
    );
    assert_eq!(status, LugreStatus::Ok, "{}", last_error());
    let spec = lugre::FitSpec::lugre(lugre::LuGreParams::default())
        .fix("sigma2")
        .unwrap()
        .fix("beta")
        .unwrap();
    let options = lugre::fit::FullOptions::default().with_starts(2);
    let core = lugre::fit_full(&spec, &t, &u, &f, options).unwrap();
    // The parameters the core fitted (all it can but the two fixed), each at its place.
    for name in ["sigma0", "sigma1", "fc", "fs", "vs"] {
        assert!(core.estimate(name).is_some(), "{name}");
    }
    let fitted = Parameter::LUGRE.map(|p| i32::from(core.estimate(p.name()).is_some()));
    assert_eq!(r.fitted[..r.parameters], fitted);
    for (j, p) in Parameter::LUGRE.into_iter().enumerate() {
        if let Some(e) = core.estimate(p.name()) {
            assert_eq!((r.value[j], r.std_error[j]), (e.value, e.stderr), "{p}");
        }
    }
    assert_eq!((r.starts, r.samples, r.turning_points), (2, n - 1, 0));
    assert_eq!(curve, core.fitted);
    let mut bad = f.clone();
    bad[0] = f64::INFINITY;
    let null = ptr::null_mut();
    assert_eq!(
        lugre_fit(t.as_ptr(), u.as_ptr(), bad.as_ptr(), n, &o, &mut r, null),
        LugreStatus::InvalidArgument
    );
    lugre_model_free(m);
}

/// A dynamics request through the C ABI is the core's: the same motion to the last bit, and a
/// request the core refuses is refused with its message, the request left as it was.
#[test]
fn a_dynamics_request_is_the_cores() {
    use lugre::dynamics::{Request, Scenario};
    let mut d = ptr::null_mut();
    assert_eq!(lugre_dynamics_new(&mut d), LugreStatus::Ok);
    assert_eq!(
        lugre_dynamics_set_scenario(d, c"breakaway".as_ptr()),
        LugreStatus::Ok
    );
    let (rate, samples) = (4.0, 7.0);
    assert_eq!(
        lugre_dynamics_set(d, c"force_rate".as_ptr(), &rate, 1),
        LugreStatus::Ok
    );
    assert_eq!(
        lugre_dynamics_set(d, c"samples".as_ptr(), &samples, 1),
        LugreStatus::Ok
    );
    // Refused, naming both fields; the request keeps its samples.
    let times = [0.0, 0.1];
    assert_eq!(
        lugre_dynamics_set(d, c"times".as_ptr(), times.as_ptr(), 2),
        LugreStatus::InvalidArgument
    );
    assert_eq!(
        last_error(),
        "give samples or times, not both: they set the same thing"
    );
    let half = 0.5;
    assert_eq!(
        lugre_dynamics_set(d, c"samples".as_ptr(), &half, 1),
        LugreStatus::InvalidArgument
    );
    assert_eq!(
        last_error(),
        "samples must be a whole number from 2 to 10000000, got 0.5"
    );
    let mut m = ptr::null_mut();
    assert_eq!(lugre_dynamics_run(d, &mut m), LugreStatus::Ok);
    let want = Request::new()
        .with_scenario(Scenario::Breakaway { rate: 10.0 })
        .with_force_rate(4.0)
        .unwrap()
        .with_samples(7)
        .unwrap()
        .build()
        .unwrap()
        .run()
        .unwrap();
    let mut n = 0;
    assert_eq!(lugre_motion_len(m, &mut n), LugreStatus::Ok);
    assert_eq!(n, 7);
    let mut cols = vec![[0.0; 7]; 6];
    let [t, x, v, z, f, drive] = &mut cols[..] else {
        unreachable!()
    };
    assert_eq!(
        lugre_motion_columns(
            m,
            7,
            t.as_mut_ptr(),
            x.as_mut_ptr(),
            v.as_mut_ptr(),
            z.as_mut_ptr(),
            f.as_mut_ptr(),
            drive.as_mut_ptr()
        ),
        LugreStatus::Ok
    );
    for (got, column) in cols.iter().zip(want.motion.columns()) {
        assert_eq!(&got[..], column);
    }
    let mut s = LugreMotionSummary::default();
    assert_eq!(lugre_motion_summary(m, &mut s), LugreStatus::Ok);
    let b = want.breakaway.unwrap();
    assert_eq!((s.t_end, s.has_breakaway, s.breakaway_t), (0.5, 1, b.t));
    lugre_motion_free(m);
    lugre_dynamics_free(d);
}

#[test]
fn sweep_through_the_abi_is_the_cores() {
    let m = table1();
    let (a, f) = ([1e-6, 1e-4], [0.1, 10.0]);
    let mut table = vec![0.0; 4 * LUGRE_SWEEP_COLUMNS];
    let status = lugre_sweep(
        m,
        a.as_ptr(),
        2,
        f.as_ptr(),
        2,
        0.0,
        0.0,
        table.as_mut_ptr(),
        4,
    );
    assert_eq!(status, LugreStatus::Ok, "{}", last_error());
    let model = lugre::LuGre::from_params(lugre::LuGreParams::canudas_de_wit_1995()).unwrap();
    let core = lugre::sweep::Request::new(a.to_vec(), f.to_vec())
        .unwrap()
        .run(&model, None)
        .unwrap();
    let want: Vec<f64> = core.points.iter().flat_map(|p| p.values()).collect();
    assert_eq!(table, want);
    for (i, name) in lugre::sweep::COLUMNS.iter().enumerate() {
        assert_eq!(
            unsafe { CStr::from_ptr(lugre_sweep_column(i)) }.to_str(),
            Ok(*name)
        );
    }
    assert!(lugre_sweep_column(LUGRE_SWEEP_COLUMNS).is_null());
    let zero = [0.0];
    let status = lugre_sweep(
        m,
        zero.as_ptr(),
        1,
        f.as_ptr(),
        2,
        0.0,
        0.0,
        table.as_mut_ptr(),
        4,
    );
    assert_eq!(status, LugreStatus::InvalidArgument);
    assert_eq!(
        last_error(),
        "amplitudes: amplitude must be a finite number > 0, got 0"
    );
    let status = lugre_sweep(
        m,
        a.as_ptr(),
        2,
        f.as_ptr(),
        2,
        0.0,
        0.0,
        table.as_mut_ptr(),
        3,
    );
    assert_eq!(status, LugreStatus::BufferTooSmall);
    let status = lugre_sweep(
        m,
        a.as_ptr(),
        2,
        f.as_ptr(),
        2,
        0.0,
        1e-20,
        table.as_mut_ptr(),
        4,
    );
    assert_eq!(status, LugreStatus::InvalidArgument);
    assert!(
        last_error().starts_with("tol: the tolerance must be"),
        "{}",
        last_error()
    );
    lugre_model_free(m);
}
