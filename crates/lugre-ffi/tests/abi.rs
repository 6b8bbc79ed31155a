//! The C entry points called as C would: results, error codes, messages, and bad input.

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
    assert_eq!(last_error(), "u[2] = inf is not a finite number");
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
