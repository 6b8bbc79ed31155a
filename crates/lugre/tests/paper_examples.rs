//! The paper's Examples 3 and 4 (and Fig. 16's variant) against independent references:
//! the paper's eqs. 13-16 evaluated literally and eqs. 8/10 integrated by quadrature, both in
//! mpmath at 50 digits (`tests/reference/make_reference.py`, values in
//! `tests/common/reference_values.rs`, modules `example3`, `example4`, `fig16`).
//!
//! Models: the paper's LuGre model (§4.2: Stribeck `g` with `Fc = 1`, `Fs = 2`, so
//! `g(0) = 2`), `sigma0 = 1` (Example 3, Fig. 16) or `6` (Example 4).

mod common;

use common::reference_values::{example3, example4, fig16};
use common::{assert_close, assert_rel, check_loop_invariants, periodicity_residual};
use lugre::{Bimodal, HysteresisLoop, LoopKind, LuGre, TheoremA};
use lugre_test_support::prec::{FEW_ULPS, IDENTITY, LOOP};

/// One example's reference values (see `make_reference.py`).
struct Example {
    name: &'static str,
    sigma0: f64,
    g0: f64,
    bimodal: [f64; 4],
    rho: [f64; 6],
    y_eq13: [f64; 6],
    y_quad: [f64; 6],
    interior: &'static [(f64, f64, f64)],
    major_w: f64,
    major_d: f64,
    minor_w: f64,
    minor_d: f64,
    minor_dv: f64,
    minor_gap: f64,
}

macro_rules! example {
    ($m:ident) => {
        Example {
            name: stringify!($m),
            sigma0: $m::SIGMA0,
            g0: $m::G0,
            bimodal: $m::BIMODAL,
            rho: $m::RHO,
            y_eq13: $m::Y_EQ13,
            y_quad: $m::Y_QUAD,
            interior: &$m::INTERIOR,
            major_w: $m::MAJOR_W,
            major_d: $m::MAJOR_D,
            minor_w: $m::MINOR_W,
            minor_d: $m::MINOR_D,
            minor_dv: $m::MINOR_DV,
            minor_gap: $m::MINOR_GAP,
        }
    };
}

fn examples() -> [Example; 3] {
    [example!(example3), example!(example4), example!(fig16)]
}

/// The paper's model with this example's `sigma0`, the bimodal input, and its loop.
fn build(ex: &Example) -> (Bimodal, HysteresisLoop) {
    let model = LuGre::paper().with_sigma0(ex.sigma0).unwrap();
    assert_eq!(model.g0(), ex.g0, "g(0) = Fs of the paper's Stribeck curve");
    let [umin1, umin2, umax1, umax2] = ex.bimodal;
    let b = Bimodal::new(umin1, umin2, umax1, umax2).unwrap();
    let hl = HysteresisLoop::new(model.rate_independent(), &b.turning_points()).unwrap();
    (b, hl)
}

#[test]
fn y_at_the_turning_points_matches_eqs_13_16_and_quadrature() {
    for ex in examples() {
        let (_, hl) = build(&ex);
        assert_eq!(
            hl.turning_points(),
            &[ex.bimodal[0], ex.bimodal[2], ex.bimodal[1], ex.bimodal[3]]
        );
        for k in 0..4 {
            let got = hl.turning_y()[k];
            assert_rel(
                &format!("{} y(rho_{k}) vs eq. 13-16", ex.name),
                got,
                ex.y_eq13[k],
                LOOP,
            );
            assert_rel(
                &format!("{} y(rho_{k}) vs eq. 8 quad", ex.name),
                got,
                ex.y_quad[k],
                LOOP,
            );
        }
    }
}

#[test]
fn y_at_interior_points_matches_eqs_13_16_and_quadrature() {
    for ex in examples() {
        let (_, hl) = build(&ex);
        for &(rho, y13, yq) in ex.interior {
            let got = hl.y_at(rho);
            assert_rel(
                &format!("{} y({rho}) vs eq. 13-16", ex.name),
                got,
                y13,
                LOOP,
            );
            assert_rel(
                &format!("{} y({rho}) vs eq. 8 quad", ex.name),
                got,
                yq,
                LOOP,
            );
            // the same through point_at, with the input there
            let pt = hl.point_at(rho);
            assert_eq!((pt.rho, pt.y), (rho, got));
        }
    }
}

#[test]
fn theorem_a_quantities() {
    for ex in examples() {
        let (b, hl) = build(&ex);
        let t = TheoremA::new(&b, &hl);
        for k in 0..6 {
            // rho_k are sums of a few f64 differences: within a couple of ulps of the exact sum
            assert_close(
                &format!("{} rho_{k}", ex.name),
                t.rho[k],
                ex.rho[k],
                1.0,
                FEW_ULPS,
            );
            assert_rel(
                &format!("{} Theorem A y(rho_{k})", ex.name),
                t.y[k],
                ex.y_eq13[k],
                LOOP,
            );
        }
        assert_eq!(t.rho, b.rho());
        assert_eq!(t.minor_loop, [t.rho[1], t.rho[5]]);
        // y(rho_4) = y(P) = y(0): the loop closes
        assert_eq!(t.y[4], t.y[0]);
    }
    // Paper §4.3: rho_1..rho_4 = 1, 1.8, 3.1, 4.6 for Example 3; §4.4 / Fig. 15: Example 4's
    // minor loop is t in [t_1, t_5] = [1, 2].
    let (b, hl) = build(&example!(example4));
    assert_eq!(TheoremA::new(&b, &hl).minor_loop, [1.0, 2.0]);
    assert_eq!(b.rho(), [0.0, 1.0, 1.5, 2.5, 4.0, 2.0]);
}

#[test]
fn the_loops_of_the_examples_and_their_energies() {
    for ex in examples() {
        let (b, hl) = build(&ex);
        let rho = b.rho();
        let loops = hl.loops();
        assert_eq!(loops.len(), 2, "{}: {loops:#?}", ex.name);
        let (major, minor) = (&loops[0], &loops[1]);
        assert_eq!(major.kind, LoopKind::Major);
        assert_eq!(minor.kind, LoopKind::Minor);

        // Major loop: starts at the global maximum umax2 (rho_3), turns at umin1 (rho_4 = P).
        assert_eq!(major.start.rho, rho[3]);
        assert_eq!(major.start.u, ex.bimodal[3]);
        assert_eq!(major.reversal.rho, rho[4]);
        assert_eq!(major.reversal.u, ex.bimodal[0]);
        assert_rel(
            &format!("{} major y_A", ex.name),
            major.start.y,
            ex.y_eq13[3],
            LOOP,
        );
        assert_rel(
            &format!("{} major y_B", ex.name),
            major.reversal.y,
            ex.y_eq13[0],
            LOOP,
        );
        assert_rel(
            &format!("{} major W", ex.name),
            major.energy.work,
            ex.major_w,
            LOOP,
        );
        assert_rel(
            &format!("{} major D", ex.name),
            major.energy.dissipation,
            ex.major_d,
            LOOP,
        );
        assert_eq!(major.energy.closure_gap, 0.0);
        assert_rel(
            &format!("{} W per period", ex.name),
            hl.work_per_period(),
            ex.major_w,
            LOOP,
        );

        // Minor loop: Theorem A (b), the arc [rho_1, rho_5], turning at rho_2.
        assert_eq!(
            [minor.start.rho, minor.reversal.rho, minor.end.rho],
            [rho[1], rho[2], rho[5]]
        );
        assert_eq!(
            [minor.start.u, minor.reversal.u],
            [ex.bimodal[2], ex.bimodal[1]]
        );
        assert_close(
            &format!("{} u_C", ex.name),
            minor.end.u,
            ex.bimodal[2],
            1.0,
            FEW_ULPS,
        );
        assert_rel(
            &format!("{} minor y_A", ex.name),
            minor.start.y,
            ex.y_eq13[1],
            LOOP,
        );
        assert_rel(
            &format!("{} minor y_B", ex.name),
            minor.reversal.y,
            ex.y_eq13[2],
            LOOP,
        );
        assert_rel(
            &format!("{} minor y_C", ex.name),
            minor.end.y,
            ex.y_eq13[5],
            LOOP,
        );
        assert_rel(
            &format!("{} minor W", ex.name),
            minor.energy.work,
            ex.minor_w,
            LOOP,
        );
        assert_rel(
            &format!("{} minor D", ex.name),
            minor.energy.dissipation,
            ex.minor_d,
            LOOP,
        );
        assert_rel(
            &format!("{} minor dV", ex.name),
            minor.energy.stored_energy_change,
            ex.minor_dv,
            LOOP,
        );
        assert_rel(
            &format!("{} minor gap", ex.name),
            minor.energy.closure_gap,
            ex.minor_gap,
            LOOP,
        );
        assert_eq!(minor.parent, Some(0));
        assert_eq!(minor.depth, 1);

        check_loop_invariants(&hl, &loops, IDENTITY);
    }
}

#[test]
fn periodic_and_bounded() {
    for ex in examples() {
        let (_, hl) = build(&ex);
        let p = hl.period();
        assert_close(&format!("{} period", ex.name), p, ex.rho[4], 1.0, FEW_ULPS);
        // Running eqs. 13-16 over one period from the crate's y°(0) comes back to it.
        let r = periodicity_residual(&hl);
        assert!(r <= IDENTITY, "{}: periodicity residual {r:e}", ex.name);
        assert_eq!(hl.y_at(p), hl.y_at(0.0));
        // continuity at the period: just below P the loop is within a·ulp of y°(0)
        let below = hl.y_at(p * (1.0 - f64::EPSILON));
        assert_close("y just below P", below, hl.y_at(0.0), ex.g0, LOOP);
        // |y°| < g0 strictly at these stiffnesses
        for pt in hl.sample(1001) {
            assert!(
                pt.y.abs() < ex.g0,
                "{}: |y({})| = {} >= g0",
                ex.name,
                pt.rho,
                pt.y
            );
        }
    }
}
