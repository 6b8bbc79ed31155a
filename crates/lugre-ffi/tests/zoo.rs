//! The zoo's models through the C ABI, every model of the core's table in turn (none named
//! here but in example data): the table as C reads it, models on their defaults and on given
//! arrays with the core's numbers to the last bit through the `lugre_loop_*` accessors, and
//! every kind of bad input refused with the core's message.

use std::ffi::{c_char, CStr, CString};
use std::ptr;

use lugre::zoo::{Shape, ZooModel, MODELS};
use lugre_c::*;

fn last_error() -> String {
    unsafe { CStr::from_ptr(lugre_last_error()) }
        .to_string_lossy()
        .into_owned()
}

fn c_str(p: *const c_char) -> String {
    assert!(!p.is_null());
    unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned()
}

/// `lugre_zoo_new` with `given` by name.
fn zoo(model: &str, given: &[(&str, &[f64])]) -> Result<*mut LugreZoo, (LugreStatus, String)> {
    let model = CString::new(model).unwrap();
    let names: Vec<CString> = given
        .iter()
        .map(|(n, _)| CString::new(*n).unwrap())
        .collect();
    let name_ptrs: Vec<*const c_char> = names.iter().map(|n| n.as_ptr()).collect();
    let values: Vec<*const f64> = given.iter().map(|(_, v)| v.as_ptr()).collect();
    let lens: Vec<usize> = given.iter().map(|(_, v)| v.len()).collect();
    let mut out = ptr::null_mut();
    let s = lugre_zoo_new(
        model.as_ptr(),
        given.len(),
        name_ptrs.as_ptr(),
        values.as_ptr(),
        lens.as_ptr(),
        &mut out,
    );
    if s == LugreStatus::Ok {
        Ok(out)
    } else {
        assert!(out.is_null(), "nothing written on failure");
        Err((s, last_error()))
    }
}

/// What the accessors give: turning points (u, rho, y), summary, every loop's numbers and a
/// sample of 5 points, as bits.
fn read_loop(hl: *const LugreLoop) -> Vec<u64> {
    let mut n = 0;
    assert_eq!(lugre_loop_turning_len(hl, &mut n), LugreStatus::Ok);
    let (mut u, mut rho, mut y) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let s = lugre_loop_turning(hl, u.as_mut_ptr(), rho.as_mut_ptr(), y.as_mut_ptr(), n);
    assert_eq!(s, LugreStatus::Ok);
    let (mut work, mut period) = (0.0, 0.0);
    assert_eq!(
        lugre_loop_summary(hl, &mut work, &mut period),
        LugreStatus::Ok
    );
    let mut k = 0;
    assert_eq!(lugre_loop_table_len(hl, &mut k), LugreStatus::Ok);
    let mut c: Vec<Vec<f64>> = (0..4).map(|_| vec![0.0; k]).collect();
    let mut parent = vec![0i64; k];
    let columns = LugreLoopColumns {
        kind: ptr::null_mut(),
        start_rho: ptr::null_mut(),
        start_u: ptr::null_mut(),
        start_y: ptr::null_mut(),
        reversal_rho: ptr::null_mut(),
        reversal_u: ptr::null_mut(),
        reversal_y: ptr::null_mut(),
        end_rho: ptr::null_mut(),
        end_u: ptr::null_mut(),
        end_y: c[0].as_mut_ptr(),
        work: c[1].as_mut_ptr(),
        stored_energy_change: c[2].as_mut_ptr(),
        dissipation: c[3].as_mut_ptr(),
        closure_gap: ptr::null_mut(),
        parent: parent.as_mut_ptr(),
        depth: ptr::null_mut(),
    };
    assert_eq!(lugre_loop_table(hl, &columns, k), LugreStatus::Ok);
    let (mut sr, mut sy) = (vec![0.0; 5], vec![0.0; 5]);
    let s = lugre_loop_sample(hl, 5, sr.as_mut_ptr(), ptr::null_mut(), sy.as_mut_ptr());
    assert_eq!(s, LugreStatus::Ok);
    let mut all = [u, rho, y, vec![work, period], sr, sy].concat();
    all.extend(c.concat());
    all.extend(parent.iter().map(|&p| p as f64));
    all.into_iter().map(f64::to_bits).collect()
}

/// The core's numbers in the order of [`read_loop`].
fn core_numbers(m: &ZooModel, u: &[f64]) -> Vec<u64> {
    let zl = m.loops(&lugre::TurningPoints::new(u).unwrap()).unwrap();
    let sample = m.sample(&zl, 5).unwrap();
    let loops = zl.loops();
    let mut all = [
        zl.turning_points().to_vec(),
        zl.turning_rho().to_vec(),
        zl.turning_force().to_vec(),
        vec![zl.work_per_period(), zl.period()],
        sample.iter().map(|p| p.rho).collect(),
        sample.iter().map(|p| p.y).collect(),
    ]
    .concat();
    for f in [
        |l: &lugre::Loop| l.end.y,
        |l: &lugre::Loop| l.energy.work,
        |l: &lugre::Loop| l.energy.stored_energy_change,
        |l: &lugre::Loop| l.energy.dissipation,
    ] {
        all.extend(loops.iter().map(f));
    }
    all.extend(loops.iter().map(|l| l.parent.map_or(-1.0, |p| p as f64)));
    all.into_iter().map(f64::to_bits).collect()
}

const INPUT: [f64; 6] = [3.0, 1.0, 2.0, -3.0, 0.5, -1.0];

#[test]
fn the_table_as_c_reads_it() {
    let mut listed = Vec::new();
    while let Some(p) = Some(lugre_zoo_model_name(listed.len())).filter(|p| !p.is_null()) {
        listed.push(c_str(p));
    }
    let want: Vec<&str> = MODELS.iter().map(|m| m.name).collect();
    assert_eq!(listed, want);
    for spec in &MODELS {
        let name = CString::new(spec.name.to_uppercase()).unwrap();
        let mut info = std::mem::MaybeUninit::<LugreZooModelInfo>::uninit();
        assert_eq!(
            lugre_zoo_model_info(name.as_ptr(), info.as_mut_ptr()),
            LugreStatus::Ok
        );
        let info = unsafe { info.assume_init() };
        assert_eq!(c_str(info.name), spec.name);
        assert_eq!(c_str(info.label), spec.label);
        assert_eq!(c_str(info.equations), spec.equations);
        assert_eq!(c_str(info.reference), spec.reference);
        assert_eq!(info.parameters, spec.parameters.len());
        assert_eq!(info.closes_minor_loops, i32::from(spec.closes_minor_loops));
        assert_eq!(info.finite_rate, i32::from(spec.finite_rate));
        for (i, p) in spec.parameters.iter().enumerate() {
            let mut q = std::mem::MaybeUninit::<LugreZooParameter>::uninit();
            let s = lugre_zoo_parameter(name.as_ptr(), i, q.as_mut_ptr());
            assert_eq!(s, LugreStatus::Ok);
            let q = unsafe { q.assume_init() };
            assert_eq!(
                [
                    c_str(q.name),
                    c_str(q.unit),
                    c_str(q.description),
                    c_str(q.domain)
                ],
                [p.name, p.unit, p.description, &p.domain.text()]
            );
            let shape = match p.shape {
                Shape::Scalar => LUGRE_ZOO_SCALAR,
                Shape::Elements => LUGRE_ZOO_ELEMENTS,
            };
            assert_eq!(q.shape, shape);
            let d = unsafe { std::slice::from_raw_parts(q.default_values, q.default_len) };
            assert_eq!(d, p.default);
            assert_eq!(q.slow_loop, i32::from(p.slow_loop));
        }
        let mut q = std::mem::MaybeUninit::<LugreZooParameter>::uninit();
        let past = spec.parameters.len();
        let s = lugre_zoo_parameter(name.as_ptr(), past, q.as_mut_ptr());
        assert_eq!(s, LugreStatus::InvalidArgument);
        assert_eq!(
            last_error(),
            format!("index must be below {past}, got {past}")
        );
    }
}

#[test]
fn every_model_on_its_defaults_and_given_arrays_is_the_cores() {
    for spec in &MODELS {
        // The defaults, and the defaults given by name: the same bits as the core's.
        let core = ZooModel::new(spec.name, &[]).unwrap();
        let given: Vec<(&str, &[f64])> = spec
            .parameters
            .iter()
            .map(|p| (p.name, p.default))
            .collect();
        // Element arrays of another length: each default element doubled in count.
        let twice: Vec<(&str, Vec<f64>)> = spec
            .parameters
            .iter()
            .map(|p| match p.shape {
                Shape::Scalar => (p.name, p.default.to_vec()),
                Shape::Elements => (p.name, [p.default, p.default].concat()),
            })
            .collect();
        let twice: Vec<(&str, &[f64])> = twice.iter().map(|(n, v)| (*n, v.as_slice())).collect();
        for (c_given, core_given) in [
            (&[][..], &[][..]),
            (&given[..], &given[..]),
            (&twice[..], &twice[..]),
        ] {
            let m = zoo(spec.name, c_given).unwrap();
            let core_m = ZooModel::new(spec.name, core_given).unwrap();
            let mut hl = ptr::null_mut();
            let s = lugre_zoo_loop_new(m, INPUT.as_ptr(), INPUT.len(), &mut hl);
            assert_eq!(s, LugreStatus::Ok, "{}: {}", spec.name, last_error());
            assert_eq!(
                read_loop(hl),
                core_numbers(&core_m, &INPUT),
                "{}",
                spec.name
            );
            // The echo: every parameter's values in the table's order.
            for (i, (_, values)) in core_m.named().iter().enumerate() {
                let mut len = 0;
                let mut out = vec![0.0; values.len()];
                let s = lugre_zoo_value(m, i, out.as_mut_ptr(), out.len(), &mut len);
                assert_eq!(s, LugreStatus::Ok);
                assert_eq!((len, &out), (values.len(), values));
            }
            lugre_loop_free(hl);
            lugre_zoo_free(m);
        }
        assert_eq!(
            core_numbers(&core, &INPUT),
            core_numbers(&ZooModel::new(spec.name, &given).unwrap(), &INPUT)
        );
    }
}

#[test]
fn bad_input_is_refused_with_the_cores_message() {
    for spec in &MODELS {
        let p = &spec.parameters[0];
        // An element (or the scalar) outside its domain: the core's message, by the C name.
        let bad = [f64::NAN];
        let core = ZooModel::new(spec.name, &[(p.name, &bad)])
            .unwrap_err()
            .to_string();
        assert_eq!(
            zoo(spec.name, &[(p.name, &bad)]).unwrap_err(),
            (LugreStatus::InvalidArgument, core)
        );
        // An unknown parameter, and one given twice.
        let core = ZooModel::new(spec.name, &[("stiffnes", &[1.0])])
            .unwrap_err()
            .to_string();
        assert_eq!(zoo(spec.name, &[("stiffnes", &[1.0])]).unwrap_err().1, core);
        assert!(core.contains(&spec.parameter_names()), "{core}");
        let twice = zoo(spec.name, &[(p.name, p.default), (p.name, p.default)]).unwrap_err();
        assert_eq!(twice.1, format!("names[1] gives {} a second time", p.name));
        // The loop's input: a NaN turning point.
        let m = zoo(spec.name, &[]).unwrap();
        let mut hl = ptr::null_mut();
        let u = [0.0, 1.0, f64::NAN];
        assert_eq!(
            lugre_zoo_loop_new(m, u.as_ptr(), 3, &mut hl),
            LugreStatus::InvalidArgument
        );
        assert_eq!(last_error(), "u[2] must be a finite number, got NaN");
        assert_eq!(
            lugre_zoo_loop_new(m, u.as_ptr(), 2, ptr::null_mut()),
            LugreStatus::NullPointer
        );
        let mut len = 0;
        assert_eq!(
            lugre_zoo_value(m, 99, ptr::null_mut(), 0, &mut len),
            LugreStatus::InvalidArgument
        );
        let mut one = [0.0];
        let s = lugre_zoo_value(m, 0, one.as_mut_ptr(), 0, &mut len);
        assert_eq!(s, LugreStatus::BufferTooSmall);
        lugre_zoo_free(m);
    }
    let unknown = ZooModel::new("coulomb", &[]).unwrap_err().to_string();
    assert_eq!(zoo("coulomb", &[]).unwrap_err().1, unknown);
    let mut info = std::mem::MaybeUninit::<LugreZooModelInfo>::uninit();
    let name = CString::new("coulomb").unwrap();
    assert_eq!(
        lugre_zoo_model_info(name.as_ptr(), info.as_mut_ptr()),
        LugreStatus::InvalidArgument
    );
    assert_eq!(last_error(), unknown);
    assert!(lugre_zoo_model_name(MODELS.len()).is_null());
}

#[test]
fn null_pointers_are_refused_by_name() {
    let mut out = ptr::null_mut();
    let model = CString::new(MODELS[0].name).unwrap();
    let parameter = CString::new(MODELS[0].parameters[0].name).unwrap();
    type Call<'a> = Box<dyn Fn() -> LugreStatus + 'a>;
    let out_p: *mut *mut LugreZoo = &mut out;
    let cases: [(Call, &str); 4] = [
        (
            Box::new(|| {
                lugre_zoo_new(ptr::null(), 0, ptr::null(), ptr::null(), ptr::null(), out_p)
            }),
            "model is NULL",
        ),
        (
            Box::new(|| {
                lugre_zoo_new(
                    model.as_ptr(),
                    1,
                    ptr::null(),
                    ptr::null(),
                    ptr::null(),
                    out_p,
                )
            }),
            "names is NULL",
        ),
        (
            Box::new(|| lugre_zoo_loop_new(ptr::null(), ptr::null(), 0, ptr::null_mut())),
            "zoo is NULL",
        ),
        (
            Box::new(|| lugre_zoo_value(ptr::null(), 0, ptr::null_mut(), 0, ptr::null_mut())),
            "zoo is NULL",
        ),
    ];
    for (call, message) in cases {
        assert_eq!(call(), LugreStatus::NullPointer);
        assert_eq!(last_error(), message);
    }
    let names = [parameter.as_ptr()];
    let values = [ptr::null::<f64>()];
    let lens = [2usize];
    let s = lugre_zoo_new(
        model.as_ptr(),
        1,
        names.as_ptr(),
        values.as_ptr(),
        lens.as_ptr(),
        &mut out,
    );
    assert_eq!(
        (s, last_error()),
        (LugreStatus::NullPointer, "values[0] is NULL".into())
    );
    lugre_zoo_free(ptr::null_mut());
}

/// `lugre_zoo_cycles_new` through `lugre_cycles_columns`: every model of the table on its
/// defaults gives the core's count and energies (`ZooModel::count_cycles`) to the last bit,
/// with and without a gate; bad input is refused with the core's message.
#[test]
fn cycles_of_a_history_are_the_cores() {
    let h = [0.0, 4.0, 1.0, 3.0, -4.0, -1.0, -3.0, 4.0, 0.0];
    for spec in MODELS {
        let z = zoo(spec.name, &[]).unwrap();
        let model = ZooModel::new(spec.name, &[]).unwrap();
        for gate in [0.0, 2.5] {
            let mut cy = ptr::null_mut();
            let s = lugre_zoo_cycles_new(z, h.as_ptr(), h.len(), gate, ptr::null(), &mut cy);
            assert_eq!(s, LugreStatus::Ok, "{}", last_error());
            let mut n = 0;
            assert_eq!(lugre_cycles_len(cy, &mut n), LugreStatus::Ok);
            // The columns compared; the others are skipped (NULL).
            let mut d: Vec<Vec<f64>> = (0..6).map(|_| vec![0.0; n]).collect();
            let mut start = vec![0i64; n];
            let columns = LugreCycleColumns {
                range: d[0].as_mut_ptr(),
                mean: ptr::null_mut(),
                count: d[1].as_mut_ptr(),
                start: start.as_mut_ptr(),
                end: ptr::null_mut(),
                closure: ptr::null_mut(),
                closure_position: ptr::null_mut(),
                work: d[2].as_mut_ptr(),
                stored_energy_change: d[3].as_mut_ptr(),
                dissipation: d[4].as_mut_ptr(),
                closure_gap: d[5].as_mut_ptr(),
            };
            assert_eq!(lugre_cycles_columns(cy, &columns, n), LugreStatus::Ok);
            lugre_cycles_free(cy);
            let mut want = lugre::cycles::Collect::default();
            model.count_cycles(&h, gate, &mut want).unwrap();
            assert_eq!(n, want.cycles.len());
            for (k, c) in want.cycles.iter().enumerate() {
                assert_eq!(
                    (d[0][k], d[1][k], start[k]),
                    (c.range, c.count, c.start as i64)
                );
                // C's 0 where the core has none (half cycles).
                let e = c.energy.map_or([0.0; 4], |e| {
                    let a = e.arc;
                    [a.work, a.stored_energy_change, a.dissipation, a.closure_gap]
                });
                let got = [d[2][k], d[3][k], d[4][k], d[5][k]];
                assert_eq!(got.map(f64::to_bits), e.map(f64::to_bits), "{}", spec.name);
            }
        }
        let mut cy = ptr::null_mut();
        let bad = [0.0, f64::NAN];
        let s = lugre_zoo_cycles_new(z, bad.as_ptr(), 2, 0.0, ptr::null(), &mut cy);
        assert_eq!(s, LugreStatus::InvalidArgument);
        assert_eq!(last_error(), "u[1] must be a finite number, got NaN");
        let s = lugre_zoo_cycles_new(z, h.as_ptr(), h.len(), -1.0, ptr::null(), &mut cy);
        assert_eq!(s, LugreStatus::InvalidArgument);
        assert_eq!(
            last_error(),
            "the gate must be a finite number >= 0, got -1"
        );
        assert!(cy.is_null(), "nothing written on failure");
        let s = lugre_zoo_cycles_new(z, h.as_ptr(), h.len(), 0.0, &0.0, &mut cy);
        assert_eq!(s, LugreStatus::InvalidArgument);
        assert_eq!(
            last_error(),
            format!(
                "x0 is the initial bristle state of LuGre and Dahl; the {} model starts from rest",
                spec.label
            )
        );
        let s = lugre_zoo_cycles_new(ptr::null(), h.as_ptr(), 2, 0.0, ptr::null(), &mut cy);
        assert_eq!(
            (s, last_error().as_str()),
            (LugreStatus::NullPointer, "zoo is NULL")
        );
        lugre_zoo_free(z);
    }
}

#[test]
fn simulate_is_the_cores_and_starts_from_rest() {
    // Reversals at unequal rates: the elasto-plastic model's rate terms differ per interval.
    let t = [0.0, 0.5, 1.0, 2.0, 2.2, 3.7];
    let u = [0.0, 1.0, 2.5, -1.0, -1.5, 0.25];
    for spec in MODELS {
        let z = zoo(spec.name, &[]).unwrap();
        let want = ZooModel::new(spec.name, &[])
            .unwrap()
            .simulate(&t, &u)
            .unwrap();
        let mut force = vec![f64::NAN; t.len()];
        let s = lugre_zoo_simulate(
            z,
            t.as_ptr(),
            u.as_ptr(),
            t.len(),
            ptr::null(),
            force.as_mut_ptr(),
        );
        assert_eq!(s, LugreStatus::Ok, "{}", last_error());
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&force), bits(&want), "{}", spec.name);
        // Refusals write nothing: an initial state, times not increasing, a NULL handle.
        let mut untouched = [7.0; 6];
        let s = lugre_zoo_simulate(z, t.as_ptr(), u.as_ptr(), 6, &0.0, untouched.as_mut_ptr());
        assert_eq!(s, LugreStatus::InvalidArgument);
        assert_eq!(
            last_error(),
            format!(
                "z0 is an option of LuGre's and Dahl's simulation; the {} model is simulated from rest at the input's own samples",
                spec.label
            )
        );
        let back = [0.0, 1.0, 1.0];
        let s = lugre_zoo_simulate(
            z,
            back.as_ptr(),
            u.as_ptr(),
            3,
            ptr::null(),
            untouched.as_mut_ptr(),
        );
        assert_eq!(s, LugreStatus::InvalidArgument);
        assert!(
            last_error().contains("t[2] = 1 after t[1] = 1"),
            "{}",
            last_error()
        );
        assert_eq!(untouched, [7.0; 6]);
        let s = lugre_zoo_simulate(
            ptr::null(),
            t.as_ptr(),
            u.as_ptr(),
            6,
            ptr::null(),
            untouched.as_mut_ptr(),
        );
        assert_eq!(
            (s, last_error().as_str()),
            (LugreStatus::NullPointer, "zoo is NULL")
        );
        lugre_zoo_free(z);
    }
}

/// `lugre_zoo_fit_full` on a record `t,u,F` of the generator (`zoo_full_fit_reference.py` in
/// the core's tests: the elasto-plastic model integrated by scipy's Radau at rtol 1e-12): the
/// core's `fit_zoo_full` to the last bit, the generator's values to 1e-8 (the core's test's
/// tolerance), and a model without a finite-rate form refused with the core's message.
#[test]
fn the_full_fit_is_the_cores() {
    let text = include_str!("../../lugre/tests/reference/zoo_fit/elastoplastic-full.csv");
    let rows: Vec<Vec<f64>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    let column = |k: usize| -> Vec<f64> { rows.iter().map(|r| r[k]).collect() };
    let (t, u, f) = (column(0), column(1), column(2));
    let n = t.len();
    let call = |model: &str, fit: &mut *mut LugreZooFit, fitted: *mut f64| {
        let name = CString::new(model).unwrap();
        let (elements, starts) = (0, 1);
        lugre_zoo_fit_full(
            name.as_ptr(),
            ptr::null(),
            t.as_ptr(),
            u.as_ptr(),
            f.as_ptr(),
            n,
            elements,
            starts,
            ptr::null(),
            ptr::null(),
            fit,
            fitted,
        )
    };
    let mut fit = ptr::null_mut();
    let mut fitted = vec![0.0; n];
    let s = call("elastoplastic", &mut fit, fitted.as_mut_ptr());
    assert_eq!(s, LugreStatus::Ok, "{}", last_error());
    let spec = lugre::fit::ZooFitSpec::new("elastoplastic").unwrap();
    let options = lugre::fit::FullOptions::default().with_starts(1);
    let core = lugre::fit::fit_zoo_full(&spec, &t, &u, &f, options).unwrap();
    let mut summary = LugreZooFitSummary::default();
    assert_eq!(lugre_zoo_fit_summary(fit, &mut summary), LugreStatus::Ok);
    assert_eq!(summary.estimates, core.estimates.len());
    assert_eq!(summary.rms.to_bits(), core.rms.to_bits());
    assert_eq!((summary.starts, summary.full), (1, 1));
    let truth = [2.0, 1.0, 1.5, 0.3, 0.5, 0.2, 0.5, 2.0];
    for (i, (c, want)) in core.estimates.iter().zip(truth).enumerate() {
        let mut e = std::mem::MaybeUninit::<LugreZooEstimate>::uninit();
        assert_eq!(
            lugre_zoo_fit_estimate(fit, i, e.as_mut_ptr()),
            LugreStatus::Ok
        );
        let e = unsafe { e.assume_init() };
        assert_eq!(c_str(e.name), c.name);
        assert_eq!(e.value.to_bits(), c.value.to_bits(), "{}", c.name);
        assert_eq!(e.std_error.to_bits(), c.stderr.to_bits(), "{}", c.name);
        assert!(
            (e.value / want - 1.0).abs() < 1e-8,
            "{}: {}",
            c.name,
            e.value
        );
    }
    let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    assert_eq!(bits(&fitted), bits(&core.fitted));
    lugre_zoo_fit_free(fit);

    let mut fit = ptr::null_mut();
    let s = call("bouc-wen", &mut fit, ptr::null_mut());
    assert_eq!(s, LugreStatus::InvalidArgument);
    assert!(fit.is_null());
    let spec = lugre::fit::ZooFitSpec::new("bouc-wen").unwrap();
    assert_eq!(
        last_error(),
        spec.check_finite_rate().unwrap_err().to_string()
    );
}
