//! What `lugre loop` and `lugre paper` both take from a hysteresis loop: the points of an arc,
//! to draw it, and the name of a loop's kind.

use lugre::zoo::{ZooLoop, ZooModel};
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

/// The periodic response of `lugre loop` and `lugre paper`: LuGre's closed forms, or a model
/// of the zoo with its loop.
pub(crate) enum Response {
    LuGre(HysteresisLoop),
    Zoo(Box<(ZooModel, ZooLoop)>),
}

impl Response {
    pub(crate) fn period(&self) -> f64 {
        match self {
            Response::LuGre(hl) => hl.period(),
            Response::Zoo(z) => z.1.period(),
        }
    }

    pub(crate) fn turning_points(&self) -> Vec<LoopPoint> {
        match self {
            Response::LuGre(hl) => hl.turning_loop_points(),
            Response::Zoo(z) => {
                let hl = &z.1;
                (0..hl.len())
                    .map(|k| LoopPoint {
                        rho: hl.turning_rho()[k],
                        u: hl.turning_points()[k],
                        y: hl.turning_force()[k],
                    })
                    .collect()
            }
        }
    }

    pub(crate) fn work_per_period(&self) -> f64 {
        match self {
            Response::LuGre(hl) => hl.work_per_period(),
            Response::Zoo(z) => z.1.work_per_period(),
        }
    }

    /// The response at `rhos`.
    pub(crate) fn points(&self, rhos: &[f64]) -> Vec<LoopPoint> {
        match self {
            Response::LuGre(hl) => rhos.iter().map(|&r| hl.point_at(r)).collect(),
            Response::Zoo(z) => z.0.points(&z.1, rhos),
        }
    }

    /// `n >= 2` points evenly spaced over one period, both ends included.
    pub(crate) fn sample(&self, n: usize) -> Vec<LoopPoint> {
        match self {
            Response::LuGre(hl) => hl.sample(n),
            Response::Zoo(z) => z.0.sample(&z.1, n).unwrap_or_default(),
        }
    }

    /// The curve over `[rho0, rho1]`, through every turning point on it (for figures).
    pub(crate) fn arc(&self, rho0: f64, rho1: f64) -> Vec<(f64, f64)> {
        arc_of(
            |r| self.points(r),
            self.period(),
            &self.turning_rho(),
            rho0,
            rho1,
        )
    }

    /// The output's symbol and name: LuGre's loop `y°`, a model of the zoo's force `F`.
    pub(crate) fn output(&self) -> (&'static str, &'static str) {
        match self {
            Response::LuGre(_) => ("y°", "friction force y°"),
            Response::Zoo(_) => ("F", "force F"),
        }
    }

    pub(crate) fn turning_rho(&self) -> Vec<f64> {
        match self {
            Response::LuGre(hl) => hl.turning_rho().to_vec(),
            Response::Zoo(z) => z.1.turning_rho().to_vec(),
        }
    }
}

impl Response {
    /// LuGre's loop of `model` (its rate-independent part) for `input`.
    pub(crate) fn lugre(
        model: lugre::RateIndependent,
        input: &lugre::TurningPoints,
    ) -> anyhow::Result<Self> {
        Ok(Response::LuGre(HysteresisLoop::new(model, input)?))
    }

    /// The loop of a model of the zoo for `input`.
    pub(crate) fn zoo(model: ZooModel, input: &lugre::TurningPoints) -> anyhow::Result<Self> {
        let hl = model.loops(input)?;
        Ok(Response::Zoo(Box::new((model, hl))))
    }

    /// The major loop (`[0]`) and every minor loop.
    pub(crate) fn loops(&self) -> Vec<lugre::Loop> {
        match self {
            Response::LuGre(hl) => hl.loops(),
            Response::Zoo(z) => z.1.loops().to_vec(),
        }
    }

    /// The model's name in reports.
    pub(crate) fn label(&self) -> &'static str {
        match self {
            Response::LuGre(_) => "LuGre",
            Response::Zoo(z) => z.0.spec().label,
        }
    }
}
