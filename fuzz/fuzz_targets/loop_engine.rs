//! The periodic-loop engine (`HysteresisLoop`, `minor_loops`, Theorem A) on arbitrary f64
//! sequences and model parameters: no panic, and what a report would print obeys the
//! invariants the CLI relies on.
#![no_main]

use libfuzzer_sys::fuzz_target;
use lugre::{Bimodal, HysteresisLoop, LoopKind, RateIndependent, TheoremA, TurningPoints};

fuzz_target!(|data: &[u8]| {
    let v = lugre_fuzz::values(data);
    if v.len() < 4 {
        return;
    }
    let Ok(model) = RateIndependent::new(v[0], v[1]) else {
        return;
    };
    let u = &v[2..];
    let bimodal = (u.len() == 4)
        .then(|| Bimodal::new(u[0], u[1], u[2], u[3]).ok())
        .flatten();
    let tp = match &bimodal {
        Some(b) => b.turning_points(),
        None => match TurningPoints::new(u) {
            Ok(tp) => tp,
            Err(_) => return,
        },
    };
    let n = tp.len();
    assert!(n >= 2 && n % 2 == 0, "turning points alternate: {n}");
    let Ok(hl) = HysteresisLoop::new(model, &tp) else {
        return;
    };
    let g0 = model.g0();
    for &rho in &[0.0, -1.5, 1e300, f64::NAN, hl.period() * 0.37] {
        let p = hl.point_at(rho);
        assert!(
            p.y.is_nan() || p.y.abs() <= g0,
            "|y°| <= g0 at {rho}: {p:?}"
        );
    }
    let _ = hl.sample(7);
    // `new` returned: y° and the work per period are finite.
    for &y in hl.turning_y() {
        assert!(y.abs() <= g0, "|y°| <= g0: {y} vs {g0}");
    }
    let loops = hl.loops();
    // Rainflow pairs every turning point of a repeating history: n / 2 loops.
    assert_eq!(loops.len(), n / 2, "one loop per pair of turning points");
    assert_eq!(loops[0].kind, LoopKind::Major);
    assert_eq!((loops[0].parent, loops[0].depth), (None, 0));
    for (i, l) in loops.iter().enumerate().skip(1) {
        assert_eq!(l.kind, LoopKind::Minor);
        let p = l.parent.expect("a minor loop has a parent");
        assert!(p < i, "a parent comes first");
        assert_eq!(l.depth, loops[p].depth + 1);
    }
    let finite = loops.iter().all(|l| {
        [l.energy.work, l.energy.stored_energy_change, l.energy.dissipation, l.energy.closure_gap]
            .iter()
            .all(|x| x.is_finite())
            && [l.start, l.reversal, l.end]
                .iter()
                .all(|p| p.rho.is_finite() && p.u.is_finite() && p.y.is_finite())
    });
    if finite {
        for l in &loops {
            assert!(l.energy.dissipation >= 0.0, "D >= 0: {l:?}");
            assert!(
                l.start.rho <= l.reversal.rho && l.reversal.rho <= l.end.rho,
                "{l:?}"
            );
            assert!(l.start.y.abs() <= g0 && l.end.y.abs() <= g0, "{l:?}");
        }
    }
    if let Some(b) = &bimodal {
        let ta = TheoremA::new(b, &hl);
        assert!(ta.y.iter().all(|y| y.abs() <= g0), "{ta:?}");
    }
});
