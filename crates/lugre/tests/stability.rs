//! Stability at any stiffness: `a P` from ~1e-12 to ~1e12, and the realistic case
//! `sigma0 = 1e5 N/m`, `Fs = 1.5 N`, 1 cm of travel, where the paper's eq. 13 overflows f64.
//!
//! References: the paper's eqs. 13-16 evaluated literally in mpmath at 120 digits (checked
//! against 60 digits to 1e-25), energies by mp.quad; `tests/reference/make_reference.py`,
//! `SWEEP_EXAMPLE3`, `SWEEP_DYADIC`, `realistic` in `tests/common/reference_values.rs`.
//!
//! Tolerance: `prec::LOOP` relative to the loop's scale `max |y°|` (values cross zero). Near a
//! reversal at high stiffness `y°` changes by `~2 g0` over `1/a` of `rho`, so an error of one
//! ulp in `rho_k` moves `y°` by `~2 a ulp(rho_k)` relative: probes inside those boundary layers
//! are placed only after turning points whose `rho_k` is exact in f64 (all of them for the
//! dyadic input, `rho_0 = 0` and `rho_1 = 1` for Example 3's).

mod common;

use common::reference_values::{
    realistic, SweepCase, SWEEP_DYADIC, SWEEP_DYADIC_BIMODAL, SWEEP_DYADIC_G0, SWEEP_EXAMPLE3,
    SWEEP_EXAMPLE3_BIMODAL, SWEEP_EXAMPLE3_G0,
};
use common::{
    assert_close, assert_rel, check_loop_invariants, loop_invariant_violations,
    periodicity_residual,
};
use lugre::{Bimodal, HysteresisLoop, LuGre, LuGreParams, RateIndependent, TheoremA};
use lugre_test_support::prec::{FEW_ULPS, IDENTITY, LOOP};

fn bimodal_loop(sigma0: f64, g0: f64, b: [f64; 4]) -> (Bimodal, HysteresisLoop) {
    let b = Bimodal::new(b[0], b[1], b[2], b[3]).unwrap();
    let model = RateIndependent::new(sigma0, g0).unwrap();
    let hl = HysteresisLoop::new(model, &b.turning_points()).unwrap();
    (b, hl)
}

/// `y°` over the sweep: at the turning points and `rho_5` (against the exact `rho_k`) and at the
/// probes (against that f64 `rho`), relative to the loop's scale.
fn sweep_y(name: &str, g0: f64, bimodal: [f64; 4], cases: &[SweepCase]) {
    let mut a_p = Vec::new();
    for &(sigma0, scale, turning, points, _) in cases {
        let (b, hl) = bimodal_loop(sigma0, g0, bimodal);
        a_p.push(hl.model().a() * hl.period());

        let what = |w: &str| {
            format!(
                "{name}, sigma0 = {sigma0:e} (a P = {:e}): {w}",
                a_p[a_p.len() - 1]
            )
        };
        for (k, (&got, &want)) in hl.turning_y().iter().zip(&turning[..4]).enumerate() {
            assert!(
                got.abs() <= g0,
                "{}",
                what(&format!("|y(rho_{k})| = {got} > g0"))
            );
            assert_close(&what(&format!("y(rho_{k})")), got, want, scale, LOOP);
        }
        let loops = hl.loops();
        assert_eq!(loops.len(), 2, "{}", what("number of loops"));
        let minor = &loops[1];
        assert_eq!(
            [minor.start.rho, minor.end.rho],
            TheoremA::new(&b, &hl).minor_loop
        );
        assert_close(
            &what("minor y_A = y(rho_1)"),
            minor.start.y,
            turning[1],
            scale,
            LOOP,
        );
        assert_close(
            &what("minor y_B = y(rho_2)"),
            minor.reversal.y,
            turning[2],
            scale,
            LOOP,
        );
        assert_close(
            &what("minor y_C = y(rho_5)"),
            minor.end.y,
            turning[4],
            scale,
            LOOP,
        );
        for &(rho, want) in points {
            let got = hl.y_at(rho);
            assert!(
                got.is_finite() && got.abs() <= g0,
                "{}",
                what(&format!("y({rho}) = {got}"))
            );
            assert_close(&what(&format!("y({rho})")), got, want, scale, LOOP);
        }
        let r = periodicity_residual(&hl);
        assert!(
            r <= IDENTITY,
            "{}",
            what(&format!("periodicity residual {r:e}"))
        );
    }
    // the sweep spans a P = 1e-12 .. 1e12 and both sides of the two-formula switch at a P = 1
    let lo = a_p.iter().cloned().fold(f64::INFINITY, f64::min);
    let hi = a_p.iter().cloned().fold(0.0, f64::max);
    assert!(lo <= 1e-12 && hi >= 1e12, "{name}: a P in [{lo:e}, {hi:e}]");
    assert!(a_p.iter().any(|&x| (0.98..1.0).contains(&x)));
    assert!(a_p.iter().any(|&x| (1.0..1.02).contains(&x)));
}

/// Energies over the sweep against mp.quad: `W`, `D` of the major loop and, where given, `W`,
/// `D`, `dV` of the minor loop, relative to their own size (`dV` relative to the stored
/// energies it is the difference of); then every per-loop invariant, `W = dV + D` included.
/// Collects every failure, so that one run shows the whole range of stiffness where it fails.
fn sweep_energies(name: &str, g0: f64, bimodal: [f64; 4], cases: &[SweepCase]) {
    let mut failures = Vec::new();
    for &(sigma0, _, _, _, energies) in cases {
        let (_, hl) = bimodal_loop(sigma0, g0, bimodal);
        let a_p = hl.model().a() * hl.period();
        let loops = hl.loops();
        let (major, minor) = (&loops[0], &loops[1]);
        let mut check = |what: &str, got: f64, want: f64, scale: f64| {
            let err = (got - want).abs() / want.abs().max(scale);
            if err.is_nan() || err > LOOP {
                failures.push(format!(
                    "sigma0 = {sigma0:e} (a P = {a_p:.3e}): {what} = {got:e}, reference {want:e}, \
                     relative error {err:.2e}"
                ));
            }
        };
        check("major W", major.energy.work, energies[0], 0.0);
        check("work_per_period", hl.work_per_period(), energies[0], 0.0);
        check("major D", major.energy.dissipation, energies[1], 0.0);
        if energies.len() == 5 {
            let stored = (minor.start.y.powi(2) + minor.end.y.powi(2)) / (2.0 * sigma0);
            check("minor W", minor.energy.work, energies[2], 0.0);
            check("minor D", minor.energy.dissipation, energies[3], 0.0);
            check(
                "minor dV",
                minor.energy.stored_energy_change,
                energies[4],
                stored,
            );
        }
        for v in loop_invariant_violations(&hl, &loops, IDENTITY) {
            failures.push(format!("sigma0 = {sigma0:e} (a P = {a_p:.3e}): {v}"));
        }
    }
    assert!(failures.is_empty(), "{name}:\n{}", failures.join("\n"));
}

#[test]
fn y_matches_eq_13_for_a_p_from_1e_minus_12_to_1e12_example3_input() {
    sweep_y(
        "Example 3 input",
        SWEEP_EXAMPLE3_G0,
        SWEEP_EXAMPLE3_BIMODAL,
        SWEEP_EXAMPLE3,
    );
}

#[test]
fn y_matches_eq_13_for_a_p_from_1e_minus_12_to_1e12_dyadic_input() {
    sweep_y(
        "dyadic input",
        SWEEP_DYADIC_G0,
        SWEEP_DYADIC_BIMODAL,
        SWEEP_DYADIC,
    );
}

#[test]
fn energies_match_quadrature_for_a_p_from_1e_minus_12_to_1e12_example3_input() {
    sweep_energies(
        "Example 3 input",
        SWEEP_EXAMPLE3_G0,
        SWEEP_EXAMPLE3_BIMODAL,
        SWEEP_EXAMPLE3,
    );
}

#[test]
fn energies_match_quadrature_for_a_p_from_1e_minus_12_to_1e12_dyadic_input() {
    sweep_energies(
        "dyadic input",
        SWEEP_DYADIC_G0,
        SWEEP_DYADIC_BIMODAL,
        SWEEP_DYADIC,
    );
}

#[test]
fn realistic_stiffness_where_eq_13_overflows_f64() {
    let params = LuGreParams::canudas_de_wit_1995();
    assert_eq!(
        (params.sigma0, params.fs),
        (realistic::SIGMA0, realistic::G0)
    );
    let model = LuGre::from_params(params).unwrap();
    assert_eq!(model.g0(), realistic::G0);
    let [umin1, umin2, umax1, umax2] = realistic::BIMODAL;
    let b = Bimodal::new(umin1, umin2, umax1, umax2).unwrap();
    let hl = HysteresisLoop::new(model.rate_independent(), &b.turning_points()).unwrap();

    // The paper's eq. 13 in f64 is not an option here: e^(a rho_4) overflows.
    let (a, rho) = (model.rate_independent().a(), b.rho());
    let e = |r: f64| (a * r).exp();
    let eq13_y0 = realistic::G0 * (-a * rho[4]).exp() / (1.0 - (-a * rho[4]).exp())
        * (2.0 * e(rho[1]) - 2.0 * e(rho[2]) + 2.0 * e(rho[3]) - e(rho[4]) - 1.0);
    assert!(!eq13_y0.is_finite(), "eq. 13 in f64 gave {eq13_y0}");

    for k in 0..4 {
        let got = hl.turning_y()[k];
        assert_close(
            &format!("realistic y(rho_{k})"),
            got,
            realistic::TURNING[k],
            realistic::SCALE,
            LOOP,
        );
    }
    for &(rho, want) in realistic::POINTS {
        let got = hl.y_at(rho);
        assert!(got.abs() <= realistic::G0);
        assert_close(
            &format!("realistic y({rho})"),
            got,
            want,
            realistic::SCALE,
            LOOP,
        );
    }
    let loops = hl.loops();
    assert_eq!(loops.len(), 2);
    let (major, minor) = (&loops[0], &loops[1]);
    assert_rel(
        "realistic major W",
        major.energy.work,
        realistic::MAJOR_W,
        LOOP,
    );
    assert_rel(
        "realistic major D",
        major.energy.dissipation,
        realistic::MAJOR_D,
        LOOP,
    );
    assert_rel(
        "realistic W per period",
        hl.work_per_period(),
        realistic::MAJOR_W,
        LOOP,
    );
    assert_eq!([minor.start.rho, minor.end.rho], [rho[1], rho[5]]);
    assert_close(
        "realistic minor y_C",
        minor.end.y,
        realistic::TURNING[4],
        realistic::SCALE,
        LOOP,
    );
    assert_rel(
        "realistic minor W",
        minor.energy.work,
        realistic::MINOR_W,
        LOOP,
    );
    assert_rel(
        "realistic minor D",
        minor.energy.dissipation,
        realistic::MINOR_D,
        LOOP,
    );
    // dV = (y_C^2 - y_A^2) / (2 sigma0) with y_A, y_C both within e^-500 of g0: pure rounding
    // (the reference is ~1e-230); it must be no more than an ulp of y^2 / sigma0.
    assert!(
        (minor.energy.stored_energy_change - realistic::MINOR_DV).abs()
            <= FEW_ULPS * realistic::G0 * realistic::G0 / realistic::SIGMA0,
        "realistic minor dV = {:e}, reference {:e}",
        minor.energy.stored_energy_change,
        realistic::MINOR_DV
    );
    check_loop_invariants(&hl, &loops, IDENTITY);
}

/// `|y°| < g0` holds exactly (eqs. 13-16: `y°` relaxes towards `+-g0` and never reaches it); in
/// f64 the correctly rounded value can be `g0` itself once `g0 - |y°|` is below half an ulp, but
/// never more. Regression: the first version exceeded it by an ulp, e.g. `sigma0 = 1e3`, `g0 = 1.5`, triangle `0 -> 1`:
/// `y_at(0.058) = 1.5000000000000002` (exact: `1.5 - 4.8e-17`, which rounds to 1.5), and 406 of
/// 1001 evenly spaced samples exceed `g0` by an ulp.
#[test]
fn y_never_exceeds_g0() {
    let mut bad = Vec::new();
    let mut total = 0usize;
    let mut check = |what: &str, hl: &HysteresisLoop| {
        let g0 = hl.model().g0();
        let mut points = hl.sample(1001);
        points.extend(hl.turning_loop_points());
        for l in hl.loops() {
            points.extend([l.start, l.reversal, l.end]);
        }
        for pt in points {
            total += 1;
            if pt.y.is_nan() || pt.y.abs() > g0 {
                bad.push(format!("{what}: y({}) = {:?}, g0 = {g0:?}", pt.rho, pt.y));
            }
        }
    };
    check(
        "sigma0 = 1e3, g0 = 1.5, triangle 0 -> 1",
        &common::loop_of(1e3, 1.5, &[0.0, 1.0]),
    );
    let mut rng = common::Lcg(0x5eed_0006);
    for i in 0..200 {
        let u = common::random_turning_points(&mut rng, 8);
        let (sigma0, g0) = (rng.log_uniform(-3.0, 6.0), rng.log_uniform(-1.0, 1.0));
        check(
            &format!("random {i} (sigma0 = {sigma0:e}, u = {u:?})"),
            &common::loop_of(sigma0, g0, &u),
        );
    }
    assert!(
        bad.is_empty(),
        "{} of {total} values of y° exceed g0, e.g.\n{}",
        bad.len(),
        bad[..bad.len().min(5)].join("\n")
    );
}

/// A minor loop 1e-6 wide near saturation (a = 0.5): `D ~ -dV ~ 1e-6` while `W ~ 5e-13`, so
/// `W = dV + D` would keep only ~4 digits; the direct form `integral (y - y_A) dpsi` keeps
/// about 10, which is all the rounding of the y° values themselves allows (`W` is 1e-7 of
/// `y delta`). Reference: mpmath at 40 digits, the loop's arc [rho_A, rho_C] located exactly
/// and `integral y dpsi` summed in closed form per piece (y° from the exact fixed point).
#[test]
fn narrow_loop_near_saturation_keeps_its_work() {
    let model = LuGre::paper().rate_independent();
    let tp = lugre::TurningPoints::new(&[-0.5, 2.0, 1.999999, 2.5]).unwrap();
    let loops = HysteresisLoop::new(model, &tp).unwrap().loops();
    assert_eq!(loops.len(), 2);
    let w = loops[1].energy.work;
    let reference = -5.315213545291311e-13;
    // Tolerance: the loop's condition, max|y°| delta / |W| ~ 4e6, times a few ulps.
    assert!(
        ((w - reference) / reference).abs() < 1e-9,
        "W = {w:e}, mpmath {reference:e}"
    );
    assert!(loops[1].energy.dissipation > 0.0);
}

/// The ends of the f64 range, where the robustness catalogue (`lugre-cli/tests/catalogue.rs`)
/// found wrong answers or needless errors: each value here is exact in closed form.
#[test]
fn the_ends_of_the_f64_range() {
    // A period of 4e-308: the sum behind y°(0) multiplies two lengths, which underflowed to 0
    // (y° came out as 0 and 2e-308). Elastic: y° = sigma0 (u - mean) = +-1e-308 to rounding.
    let hl = common::loop_of(1.0, 2.0, &[-1e-308, 1e-308]);
    assert_eq!(hl.turning_y(), &[-1e-308, 1e-308]);
    // sigma0 u overflows (1e600) but the loop is saturated: y° = +-g0 and W = 4 g0 A (this
    // was "y° overflows f64"; then, with sigma0 l guarded alone, W = 0).
    let hl = common::loop_of(1e300, 2.0, &[0.0, 1e300]);
    assert_eq!(hl.turning_y(), &[-2.0, 2.0]);
    assert_eq!(hl.work_per_period(), 4e300);
    let loops = hl.loops();
    assert_eq!(
        (loops[0].energy.work, loops[0].energy.dissipation),
        (4e300, 4e300)
    );
    // a l overflows for every piece (a = 5e307): W = 4 g0 (A - 1/a) = 4.
    assert_eq!(
        common::loop_of(1e308, 2.0, &[0.0, 1.0]).work_per_period(),
        4.0
    );
    // u ~ 1e300 with sigma0 ~ 1e-300: every energy is ~ g0 u and fits, but the piece's
    // l^2 h(a l) overflows (the energies came out as "overflow"). u -> lambda u,
    // sigma0 -> sigma0 / lambda leaves y° as it is and multiplies each energy by lambda (the
    // property tests' scaling law; lambda a power of two, so the inputs scale exactly).
    let lambda = 2f64.powi(996);
    let u = [0.0, 1.0, 0.2, 1.5];
    let big: Vec<f64> = u.iter().map(|x| x * lambda).collect();
    let (h1, h2) = (
        common::loop_of(1.0, 2.0, &u),
        common::loop_of(1.0 / lambda, 2.0, &big),
    );
    for (y1, y2) in h1.turning_y().iter().zip(h2.turning_y()) {
        assert!((y1 - y2).abs() <= LOOP * 2.0, "{y1:e} vs {y2:e}");
    }
    for (a, b) in h1.loops().iter().zip(&h2.loops()) {
        for (x, y) in [
            (a.energy.work, b.energy.work),
            (a.energy.stored_energy_change, b.energy.stored_energy_change),
            (a.energy.dissipation, b.energy.dissipation),
        ] {
            assert!(
                (x * lambda - y).abs() <= IDENTITY * y.abs(),
                "{x:e} * 2^996 vs {y:e}"
            );
        }
        assert!((a.energy.closure_gap - b.energy.closure_gap).abs() <= LOOP * 2.0);
    }
    // Forces at the ends of the range: sigma0 and g0 -> lambda (sigma0, g0) leaves a and the
    // loops' places as they are and multiplies y° and every energy by lambda, exactly for a
    // power of two. y^2 and gap (y_A + y_C) over- and underflowed there (D = 0, dV = -0; found
    // by comparing the streaming engine with the one before it), and the exact product y c
    // gave NaN past 1e300.
    let u = [0.0, 1.0, 0.2, 1.5, 0.7, 0.9, 0.3, 2.0];
    let h1 = common::loop_of(0.75, 2.0, &u);
    for lambda in [2f64.powi(-1000), 2f64.powi(990), 2f64.powi(1020)] {
        let h2 = common::loop_of(0.75 * lambda, 2.0 * lambda, &u);
        for (y1, y2) in h1.turning_y().iter().zip(h2.turning_y()) {
            assert!(
                (y1 * lambda - y2).abs() <= LOOP * 2.0 * lambda,
                "{y1:e} vs {y2:e}"
            );
        }
        for (a, b) in h1.loops().iter().zip(&h2.loops()) {
            let scale = a.energy.stored_energy_change.abs() + a.energy.dissipation;
            for (x, y) in [
                (a.energy.work, b.energy.work),
                (a.energy.stored_energy_change, b.energy.stored_energy_change),
                (a.energy.dissipation, b.energy.dissipation),
                (a.energy.closure_gap, b.energy.closure_gap),
            ] {
                assert!(y.is_finite(), "{y:e} at lambda = {lambda:e}");
                assert!(
                    (x * lambda - y).abs() <= 1e-12 * scale.max(x.abs()) * lambda,
                    "{x:e} * {lambda:e} vs {y:e}"
                );
            }
        }
    }
    // Fs far below Fc: g(0) = Fs exactly, where Fc + (Fs - Fc) exp(0) rounds to 0.
    let m = LuGre::from_params(LuGreParams {
        fs: 1e-300,
        ..LuGreParams::default()
    })
    .unwrap();
    assert_eq!(m.g0(), 1e-300);
    assert!(m.g(1e-20) > 1e-300 && m.g(1e-20) < 2e-20, "{}", m.g(1e-20));
    assert_eq!(m.g(1e3), 1.0);
    // A subnormal vs: 1 / vs overflows, and g(0) would be 0 * inf = NaN.
    let e = LuGre::from_params(LuGreParams {
        vs: 4e-309,
        ..LuGreParams::default()
    })
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        "vs must be >= 5.56268464626801e-309 (1 / vs overflows below it), got 4e-309"
    );
    // The bound is the last number whose reciprocal is finite (from Python: the smallest
    // double x with 1/x < inf, by stepping with math.nextafter from 1/sys.float_info.max).
    let min = 5.56268464626801e-309_f64;
    assert!((1.0 / min).is_finite() && (1.0 / min.next_down()).is_infinite());
    let ok = LuGre::from_params(LuGreParams {
        vs: min,
        ..LuGreParams::default()
    });
    assert!(ok.is_ok(), "{ok:?}");
    assert!(LuGre::from_params(LuGreParams {
        vs: min.next_down(),
        ..LuGreParams::default()
    })
    .is_err());
    // Messages show extreme values in exponent notation, not as 300 digits.
    let e = LuGre::paper().with_sigma0(-1e-300).unwrap_err();
    assert_eq!(e.to_string(), "sigma0 must be > 0, got -1e-300");
    let e = RateIndependent::new(1e-300, 1e300).unwrap_err();
    assert_eq!(
        e.to_string(),
        "a = sigma0 / g(0) = 1e-300 / 1e300 is not a finite positive number"
    );
}
