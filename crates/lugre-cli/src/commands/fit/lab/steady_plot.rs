//! The Stribeck fit's figure: friction against velocity, both signs, the points with their
//! error bars (two standard errors each way) and the fitted steady-state curve; beside it the
//! same against `|v|` on a log axis, where the Stribeck drop below `vs` shows.

use lugre::fit::{steady_force, FitReport, FitSpec};

use super::Steady;
use crate::fmt::sig;
use crate::plot::{Curve, Figure, LineStyle, Marker, Panels, Shape, BLACK, BLUE, RED};

/// Points of each branch of the fitted curve.
const CURVE_POINTS: usize = 400;

pub(super) fn figure(steady: &Steady, r: &FitReport, spec: &FitSpec) -> Panels {
    let p = r.lugre_params(spec);
    let points = &steady.points;
    let (lo, hi) = points.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), q| {
        (lo.min(q.v.abs()), hi.max(q.v.abs()))
    });
    // Log-spaced speeds from the slowest to the fastest run.
    let speeds: Vec<f64> = (0..CURVE_POINTS)
        .map(|k| lo * (hi / lo).powf(k as f64 / (CURVE_POINTS - 1) as f64))
        .collect();
    let branch = |sign: f64, log: bool| -> Vec<(f64, f64)> {
        speeds
            .iter()
            .map(|&a| {
                let f = steady_force(&p, sign * a);
                if log {
                    (a, sign * f)
                } else {
                    (sign * a, f)
                }
            })
            .collect()
    };
    let title = format!(
        "Stribeck fit: Fc {}, Fs {}, vs {}, sigma2 {}",
        sig(p.fc, 4),
        sig(p.fs, 4),
        sig(p.vs, 4),
        sig(p.sigma2, 4)
    );
    let mut linear = Figure::new("velocity v", "steady friction force F").title(title);
    let mut log = Figure::new("speed |v|", "sgn(v) F")
        .title(format!("against |v| (residual RMS {})", sig(r.rms, 3)))
        .log_x();
    for sign in [1.0, -1.0] {
        let lin = Curve::new(branch(sign, false), LineStyle::Solid, RED);
        linear = linear.curve(if sign > 0.0 { lin.label("fit") } else { lin });
        let (color, label) = if sign > 0.0 {
            (RED, "fit, v > 0")
        } else {
            (BLACK, "fit, v < 0")
        };
        let style = if sign > 0.0 {
            LineStyle::Solid
        } else {
            LineStyle::Dashed
        };
        let lg = Curve::new(branch(sign, true), style, color).label(label);
        log = log.curve(lg);
    }
    for (k, q) in points.iter().enumerate() {
        let bar = 2.0 * q.stderr.unwrap_or(0.0);
        let (x_log, y_log) = (q.v.abs(), q.f * q.v.signum());
        let color = if q.v > 0.0 { BLUE } else { BLACK };
        if bar > 0.0 {
            linear = linear.curve(
                Curve::new(
                    vec![(q.v, q.f - bar), (q.v, q.f + bar)],
                    LineStyle::Solid,
                    BLUE,
                )
                .width(1),
            );
            log = log.curve(
                Curve::new(
                    vec![(x_log, y_log - bar), (x_log, y_log + bar)],
                    LineStyle::Solid,
                    color,
                )
                .width(1),
            );
        }
        let first_of_sign = points[..k].iter().all(|o| o.v.signum() != q.v.signum());
        linear = linear.marker(Marker {
            label: (k == 0).then(|| "data (bars: 2 standard errors)".to_string()),
            at: (q.v, q.f),
            shape: Shape::Circle,
            color: BLUE,
        });
        log = log.marker(Marker {
            label: first_of_sign.then(|| {
                if q.v > 0.0 {
                    "data, v > 0"
                } else {
                    "data, v < 0"
                }
                .to_string()
            }),
            at: (x_log, y_log),
            shape: if q.v > 0.0 {
                Shape::Circle
            } else {
                Shape::Square
            },
            color,
        });
    }
    Panels::side_by_side(linear, log)
}
