//! What `lugre loop` and `lugre paper` both take from a hysteresis loop: the points of an arc,
//! to draw it, and the name of a loop's kind.

use lugre::{HysteresisLoop, LoopKind, LoopPoint};

/// `major` or `minor`, as the tables and the JSON documents name a loop's kind.
pub(crate) fn kind_name(kind: LoopKind) -> &'static str {
    match kind {
        LoopKind::Major => "major",
        LoopKind::Minor => "minor",
    }
}

/// Points per drawn arc (plus the turning points inside it, when there are not too many).
const POINTS_PER_ARC: usize = 600;

/// `(u, y°)` along the arc `[rho0, rho1]` of `hl`: evenly spaced points and the turning
/// points inside.
pub(crate) fn arc_points(hl: &HysteresisLoop, rho0: f64, rho1: f64) -> Vec<(f64, f64)> {
    arc_of(
        |rhos| rhos.iter().map(|&r| hl.point_at(r)).collect(),
        hl.period(),
        hl.turning_rho(),
        rho0,
        rho1,
    )
}

/// `(u, y)` along the arc `[rho0, rho1]` of any periodic response (`points` gives it at a list
/// of rho, `period` and `turning` its period and its turning points' rho).
pub(crate) fn arc_of(
    points: impl Fn(&[f64]) -> Vec<LoopPoint>,
    period: f64,
    turning: &[f64],
    rho0: f64,
    rho1: f64,
) -> Vec<(f64, f64)> {
    let mut rhos: Vec<f64> = (0..=POINTS_PER_ARC)
        .map(|i| rho0 + (rho1 - rho0) * (i as f64 / POINTS_PER_ARC as f64))
        .collect();
    if turning.len() <= 20 * POINTS_PER_ARC {
        for shift in [0.0, period, 2.0 * period] {
            rhos.extend(
                turning
                    .iter()
                    .map(|r| r + shift)
                    .filter(|r| *r > rho0 && *r < rho1),
            );
        }
    }
    rhos.sort_by(f64::total_cmp);
    points(&rhos).iter().map(|pt| (pt.u, pt.y)).collect()
}
