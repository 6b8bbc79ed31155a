//! The Dahl model (`w' = rho (u' - |u'| w)`, `y = Fc w`) as the LuGre model with
//! `sigma0 = rho Fc`, `g0 = Fc`, against closed forms worked out by hand for a symmetric
//! triangle `-A -> A -> -A` (derivation in `tests/reference/make_reference.py`, section 7,
//! where they are also checked against quadrature of eqs. 8 and 10; values in `DAHL` of
//! `tests/common/reference_values.rs`, evaluated in mpmath at 50 digits):
//!
//! * `y°(-A) = -Fc tanh(rho A)`, `y°(A) = Fc tanh(rho A)`;
//! * on the rising branch, `l` after `-A`: `y° = Fc (1 - (1 + tanh(rho A)) e^(-rho l))`;
//! * work per period `W = 4 Fc (A - tanh(rho A) / rho)`.

mod common;

use common::reference_values::DAHL;
use common::{assert_close, assert_rel, check_loop_invariants};
use lugre::{Dahl, HysteresisLoop, LuGre, RateIndependent, TurningPoints};
use lugre_test_support::prec::{FEW_ULPS, IDENTITY, LOOP};

fn triangle(a: f64) -> TurningPoints {
    TurningPoints::new(&[-a, a]).unwrap()
}

#[test]
fn dahl_symmetric_triangle_matches_the_closed_form() {
    for &(rho, fc, amp, y_bottom, work, rising) in DAHL {
        let what = |w: &str| format!("Dahl rho = {rho}, Fc = {fc}, A = {amp}: {w}");
        let model = Dahl::new(rho, fc).unwrap().rate_independent();
        let hl = HysteresisLoop::new(model, &triangle(amp)).unwrap();
        assert_eq!(hl.turning_points(), &[-amp, amp]);
        assert_rel(&what("y(-A)"), hl.turning_y()[0], y_bottom, LOOP);
        assert_rel(&what("y(A)"), hl.turning_y()[1], -y_bottom, LOOP);
        for &(l, y) in rising {
            assert_close(&what(&format!("y({l} after -A)")), hl.y_at(l), y, fc, LOOP);
            // the falling branch is the rising one mirrored: y(2A + l) = -y(l)
            assert_close(
                &what(&format!("y({l} after A)")),
                hl.y_at(2.0 * amp + l),
                -y,
                fc,
                LOOP,
            );
        }
        let loops = hl.loops();
        assert_eq!(loops.len(), 1, "{}", what("a triangle has no minor loop"));
        // D = (1/g0) int y°^2 drho = W for the closed major loop
        assert_rel(&what("major D"), loops[0].energy.dissipation, work, LOOP);
        check_loop_invariants(&hl, &loops, IDENTITY);
    }
}

/// Regression: at `rho A = 2e-6` (`a P = 8e-6`) the first version's `W` lost relative accuracy
/// like `1e-16 / (a P)` (got 3.2000000014e-11, closed form 3.1999999999949e-11); `W` now comes
/// from the form that rounds less (`kernel/arc.rs`).
#[test]
fn dahl_work_per_period_matches_the_closed_form() {
    for &(rho, fc, amp, _, work, _) in DAHL {
        let what = |w: &str| format!("Dahl rho = {rho}, Fc = {fc}, A = {amp}: {w}");
        let hl = HysteresisLoop::new(
            Dahl::new(rho, fc).unwrap().rate_independent(),
            &triangle(amp),
        )
        .unwrap();
        assert_rel(&what("W per period"), hl.work_per_period(), work, LOOP);
        assert_rel(&what("major W"), hl.loops()[0].energy.work, work, LOOP);
    }
}

#[test]
fn dahl_is_lugre_with_sigma0_rho_fc_and_g0_fc() {
    let inputs: [&[f64]; 3] = [
        &[-1.0, 1.0],
        &[0.0, 1.0, 0.2, 1.5],
        &[
            10.0, 0.0, 8.0, 1.0, 5.0, 3.0, 9.0, 2.0, 7.0, 4.0, 6.0, 4.5, 8.5, 3.5,
        ],
    ];
    for (rho, fc) in [(1.0, 1.0), (2.5, 0.8), (1e4, 1.2), (3e-7, 40.0)] {
        let dahl = Dahl::new(rho, fc).unwrap();
        // the same model three ways: Dahl, LuGre with constant g = Fc (and sigma1, f anything),
        // and the rate-independent pair directly
        let via_lugre = LuGre::new(rho * fc, 0.7, move |_v: f64| fc, |v: f64| 0.3 * v)
            .unwrap()
            .rate_independent();
        let direct = RateIndependent::new(rho * fc, fc).unwrap();
        assert_eq!(dahl.rate_independent(), direct);
        assert_eq!(via_lugre, direct);
        assert_rel("a = rho", dahl.rate_independent().a(), rho, FEW_ULPS);
        for u in inputs {
            let tp = TurningPoints::new(u).unwrap();
            let from_dahl = HysteresisLoop::new(dahl.rate_independent(), &tp).unwrap();
            let from_lugre = HysteresisLoop::new(via_lugre, &tp).unwrap();
            assert_eq!(from_dahl.turning_y(), from_lugre.turning_y());
            assert_eq!(from_dahl.loops(), from_lugre.loops());
        }
    }
}

#[test]
fn lugre_triangle_from_zero_has_y0_minus_g0_tanh_half_al() {
    // The triangle 0 -> L -> 0 is the Dahl triangle shifted: y°(0) = -g0 tanh(a L / 2), worked
    // by hand as above (A = L / 2, rho = a). Here in f64 with std's tanh (correctly rounded to
    // within an ulp or so).
    for (sigma0, g0, l) in [
        (1.0, 2.0, 1.0),
        (6.0, 2.0, 1.5),
        (1e5, 1.5, 0.01),
        (1e-3, 2.0, 0.5),
    ] {
        let hl = common::loop_of(sigma0, g0, &[0.0, l]);
        let a: f64 = sigma0 / g0;
        let want = -g0 * (a * l / 2.0).tanh();
        assert_rel(
            &format!("sigma0 = {sigma0}, L = {l}: y(0)"),
            hl.turning_y()[0],
            want,
            LOOP,
        );
        assert_rel(
            &format!("sigma0 = {sigma0}, L = {l}: y(L)"),
            hl.turning_y()[1],
            -want,
            LOOP,
        );
    }
}
