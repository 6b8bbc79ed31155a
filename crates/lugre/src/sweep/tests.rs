use super::*;
use crate::simulate::Tolerance;
use crate::{HysteresisLoop, LuGre, LuGreParams, TurningPoints};

fn canudas() -> LuGre {
    LuGre::from_params(LuGreParams::canudas_de_wit_1995()).unwrap()
}

fn tol() -> Tolerance {
    Tolerance::new(Request::DEFAULT_TOLERANCE).unwrap()
}

/// The rate-independent loop's dissipation for turning points `offset -+ amplitude`.
fn loop_dissipation(model: &LuGre, amplitude: f64, offset: f64) -> f64 {
    let tp = TurningPoints::new(&[offset - amplitude, offset + amplitude]).unwrap();
    let hl = HysteresisLoop::new(model.rate_independent(), &tp).unwrap();
    hl.loops()[0].energy.dissipation
}

/// At a frequency where the rate effects are below 1e-13 (`sigma1 pi A^2 w` and the Stribeck
/// drop), the energy per cycle is the closed-form loop's (eq. 10) to 1e-12.
#[test]
fn quasi_static_limit_is_the_closed_form_loop() {
    let cases = [
        (canudas(), [1e-6, 1e-5, 1e-4, 1e-3, 1e-2], 1e-13),
        (LuGre::paper(), [0.1, 0.5, 1.0, 3.0, 10.0], 1e-16),
        (
            LuGre::paper().with_sigma0(1e8).unwrap(),
            [1e-9, 1e-8, 1e-7, 1e-3, 1.0],
            1e-16,
        ),
    ];
    for (model, amplitudes, frequency) in cases {
        for a in amplitudes {
            let p = Point::compute(&model, a, frequency, 0.3, tol(), 0).unwrap();
            // The loop's own offset 0: its turning points 0.3 -+ 1e-6 would lose digits.
            let d = loop_dissipation(&model, a, 0.0);
            let rel = (p.dissipation - d) / d;
            assert!(
                rel.abs() < 1e-12,
                "{model:?} A = {a}: {} vs {d} ({rel:e})",
                p.dissipation
            );
            assert!((p.work - d).abs() < 1e-12 * d);
        }
    }
}

/// A model whose symmetry the sweep does not know (closures) takes the whole period and
/// (P3); the symmetric one half a period and (P4): the same numbers.
#[test]
fn half_and_whole_period_agree() {
    let p = LuGreParams::canudas_de_wit_1995();
    let st = crate::Stribeck::new(p.fc, p.fs, p.vs, p.beta).unwrap();
    let general = LuGre::new(
        p.sigma0,
        p.sigma1,
        move |v: f64| crate::VelocityFn::eval(&st, v),
        move |v: f64| 0.4 * v,
    )
    .unwrap();
    assert!(!general.is_symmetric() && canudas().is_symmetric());
    for (a, f) in [(1e-7, 1.0), (1e-5, 10.0), (1e-3, 0.1), (1e-3, 100.0)] {
        let x = Point::compute(&canudas(), a, f, 0.0, tol(), 0).unwrap();
        let y = Point::compute(&general, a, f, 0.0, tol(), 0).unwrap();
        for (name, u, v) in [
            ("dissipation", x.dissipation, y.dissipation),
            ("peak", x.peak_force, y.peak_force),
            ("b1", x.b1, y.b1),
        ] {
            assert!(
                (u - v).abs() < 1e-10 * u.abs(),
                "A {a} f {f} {name}: {u} vs {v}"
            );
        }
    }
}

/// The loop samples close on themselves, integrate (trapezoid, 20001 samples) to the
/// dissipation, reach the peak force, and the offset moves u only.
#[test]
fn loop_samples_are_the_orbit() {
    let m = canudas();
    for (a, f) in [(1e-5, 1.0), (1e-3, 10.0)] {
        let p = Point::compute(&m, a, f, 0.0, tol(), 20001).unwrap();
        let q = Point::compute(&m, a, f, 2.0, tol(), 20001).unwrap();
        let l = p.samples.as_ref().unwrap();
        let n = l.t.len();
        assert_eq!(n, 20001);
        assert!((l.force[0] - l.force[n - 1]).abs() < 1e-9 * p.peak_force);
        let trapezoid: f64 = (1..n)
            .map(|i| 0.5 * (l.force[i] + l.force[i - 1]) * (l.u[i] - l.u[i - 1]))
            .sum();
        assert!(
            (trapezoid - p.dissipation).abs() < 1e-5 * p.dissipation,
            "{trapezoid} vs {}",
            p.dissipation
        );
        let sampled_peak = l.force.iter().fold(0.0f64, |m, f| m.max(f.abs()));
        assert!(sampled_peak <= p.peak_force * (1.0 + 1e-12));
        assert!(sampled_peak > p.peak_force * (1.0 - 1e-4));
        let l2 = q.samples.as_ref().unwrap();
        assert_eq!(l2.force, l.force);
        assert!(l2
            .u
            .iter()
            .zip(&l.u)
            .all(|(x, y)| (x - y - 2.0).abs() < 1e-12));
        assert_eq!(q.dissipation, p.dissipation);
    }
}

/// Stable at sigma0 = 1e8 and at high rates: finite, positive, and the peak force is at
/// least the Coulomb force once the loop slides.
#[test]
fn stiff_and_fast_points() {
    let m = canudas().with_sigma0(1e8).unwrap();
    for (a, f) in [(1e-3, 1e3), (1e-9, 1e3), (1e-6, 1e-3)] {
        let p = Point::compute(&m, a, f, 0.0, tol(), 0).unwrap();
        assert!(p.dissipation > 0.0 && p.peak_force > 0.0, "{p:?}");
        assert!(
            p.stored_energy_change.abs() < 1e-10 * p.dissipation,
            "{p:?}"
        );
    }
}

#[test]
fn piecewise_linear_orbit_is_periodic_and_matches_the_loop() {
    let m = canudas();
    let slow = TurningPoints::new(&[-3e-5, 1e-4]).unwrap();
    let o = periodic_orbit(
        &m,
        &crate::PiecewiseLinear::from_turning_points(&slow, 1e-12).unwrap(),
    )
    .unwrap();
    let d = loop_dissipation(&m, 6.5e-5, 3.5e-5);
    assert!(
        (o.dissipation - d).abs() < 1e-10 * d,
        "{} vs {d}",
        o.dissipation
    );
    assert!(o.contraction < 1.0 && o.contraction > 0.0);
    let tp = TurningPoints::new(&[0.0, 1e-4, 2e-5, 1.5e-4]).unwrap();
    // At a finite speed the orbit repeats: one more period from z* ends at z*.
    let fast = crate::PiecewiseLinear::from_turning_points(&tp, 1e-3).unwrap();
    let o = periodic_orbit(&m, &fast).unwrap();
    let z = &o.trajectory.z;
    assert!((z[z.len() - 1] - o.z0).abs() < 1e-12 * o.z0.abs().max(1e-5));
    let open = crate::PiecewiseLinear::new(vec![0.0, 1.0], vec![0.0, 1.0]).unwrap();
    assert_eq!(
        periodic_orbit(&m, &open).unwrap_err().to_string(),
        "the input is not periodic: it ends at u = 1, not where it starts (u = 0)"
    );
}

#[test]
fn requests_name_the_bad_value() {
    let bad = [
        (
            Request::new(vec![0.0], vec![1.0]),
            "amplitude must be a finite number > 0, got 0",
        ),
        (
            Request::new(vec![-1e-6], vec![1.0]),
            "amplitude must be a finite number > 0, got -1e-6",
        ),
        (
            Request::new(vec![1e-6], vec![f64::NAN]),
            "frequency must be a finite number > 0, got NaN",
        ),
        (
            Request::new(vec![1e-6], vec![0.0]),
            "frequency must be a finite number > 0, got 0",
        ),
        (
            Request::new(vec![], vec![1.0]),
            "the amplitudes list is empty (give numbers separated by commas, or START:STOP:COUNT)",
        ),
    ];
    for (r, want) in bad {
        assert_eq!(r.unwrap_err().to_string(), want);
    }
    let r = Request::new(vec![1e-6; 1000], vec![1.0; 1000]).unwrap();
    let e = r.with_loop_samples(10_000).unwrap_err().to_string();
    assert!(e.starts_with("the grid of 1000000 points (1000 amplitudes x 1000 frequencies) with 10000 loop samples each needs about 240"), "{e}");
    assert!(Request::new(vec![1e-6], vec![1.0])
        .unwrap()
        .with_loop_samples(1)
        .is_err());
    assert!(Request::new(vec![1e-6], vec![1.0])
        .unwrap()
        .with_offset(f64::INFINITY)
        .is_err());
}

#[test]
fn lists_and_ranges() {
    assert_eq!(
        parse_values("amplitudes", "1e-6,1e-5").unwrap(),
        [1e-6, 1e-5]
    );
    let v = parse_values("frequencies", " 0.1 : 100 : 7 ").unwrap();
    assert_eq!(v.len(), 7);
    assert_eq!((v[0], v[6]), (0.1, 100.0));
    for (i, x) in v.iter().enumerate() {
        let want = 0.1 * 10f64.powf(i as f64 / 2.0);
        assert!(
            (x - want).abs() < 4.0 * f64::EPSILON * want,
            "{x} vs {want}"
        );
    }
    assert_eq!(parse_values("amplitudes", "2:1:1").unwrap(), [2.0]);
    for (text, want) in [
        ("1,x", "amplitudes: item 2 is 'x', which is not a number"),
        ("", "the amplitudes list is empty (give numbers separated by commas, or START:STOP:COUNT)"),
        ("0:1:3", "amplitudes: a range is START:STOP:COUNT (log spacing) with START and STOP finite and > 0 and COUNT a whole number from 1 to 10000000, got '0:1:3'"),
        ("1:2:0", "amplitudes: a range is START:STOP:COUNT (log spacing) with START and STOP finite and > 0 and COUNT a whole number from 1 to 10000000, got '1:2:0'"),
        ("1:2", "amplitudes: a range is START:STOP:COUNT (log spacing) with START and STOP finite and > 0 and COUNT a whole number from 1 to 10000000, got '1:2'"),
    ] {
        assert_eq!(parse_values("amplitudes", text).unwrap_err().to_string(), want);
    }
}

/// The grid runs every point, in order, on all cores, with progress.
#[test]
fn grid_in_order_with_progress() {
    let m = canudas();
    let r = Request::new(vec![1e-6, 1e-5, 1e-4], vec![0.1, 1.0, 10.0, 100.0]).unwrap();
    let calls = std::sync::atomic::AtomicUsize::new(0);
    let report = |done: usize, total: usize| {
        assert!(done <= total && total == 12);
        calls.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    };
    let s = r.run(&m, Some(&report)).unwrap();
    assert_eq!(calls.into_inner(), 12);
    for (i, p) in s.points.iter().enumerate() {
        assert_eq!((p.amplitude, p.frequency), r.point(i));
        assert_eq!(
            *p,
            Point::compute(&m, p.amplitude, p.frequency, 0.0, tol(), 0).unwrap()
        );
    }
}
