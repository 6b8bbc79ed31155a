//! `lugre sweep --plot`: the figures papers show of a sweep, in one image of five panels:
//!
//! 1. the steady-state loops `(u, F)` of several amplitudes at one frequency, overlaid, coloured
//!    dark to light by amplitude (a sequential scale that survives grey-scale printing);
//! 2. the same loops as friction against velocity `(u', F)`;
//! 3. the energy dissipated per cycle against the amplitude (log-log), one curve per frequency;
//! 4. the describing function's gain against the amplitude (log-log), one curve per frequency;
//! 5. its phase (degrees) against the amplitude, one curve per frequency.
//!
//! Axis labels carry the units of `--units u=UNIT,F=UNIT` (a preset's are SI: m and N); the
//! energy's unit is the product of the two ([`Units`]).

use anyhow::Result;
use lugre::sweep::{self, Point, Sweep};
use lugre::LuGre;

use crate::plot::{scale_color, Curve, Figure, LineStyle, Marker, Panels, Shape, Units};

/// At most this many loops are overlaid (evenly chosen among the amplitudes, both ends kept).
const MAX_LOOPS: usize = 8;
/// At most this many frequencies get a curve of their own in the summary panels.
const MAX_CURVES: usize = 8;
/// Samples of each loop drawn, when `--loops` did not ask for them.
const LOOP_SAMPLES: usize = 401;

/// The five panels of a computed sweep.
pub(super) fn figure(
    model: &LuGre,
    r: &sweep::Request,
    s: &Sweep,
    units: &Units,
) -> Result<Panels> {
    let (loops, velocity) = loop_figures(model, r, s, units)?;
    let mut panels = Panels::side_by_side(loops, velocity);
    panels.panels.extend(summary_figures(r, s, units));
    panels.cols = 3;
    panels.size = (2100, 1300);
    Ok(panels)
}

/// Indices of at most `most` of `n` items, evenly spread, first and last included.
fn spread(n: usize, most: usize) -> Vec<usize> {
    if n <= most {
        return (0..n).collect();
    }
    let mut picked: Vec<usize> = (0..most)
        .map(|k| ((k * (n - 1)) as f64 / (most - 1) as f64).round() as usize)
        .collect();
    picked.dedup();
    picked
}

/// The loops of the amplitudes drawn, at the first frequency: `(u, F)` and `(u', F)`.
fn loop_figures(
    model: &LuGre,
    r: &sweep::Request,
    s: &Sweep,
    units: &Units,
) -> Result<(Figure, Figure)> {
    let f0 = r.frequencies()[0];
    let title = format!("steady-state loops at f = {} Hz", crate::fmt::sig(f0, 4));
    let mut loops = Figure::new(units.u("input u"), units.force("friction F")).title(&title);
    let mut velocity = Figure::new(units.velocity("velocity u'"), units.force("friction F"))
        .title("friction against velocity");
    let picked = spread(r.amplitudes().len(), MAX_LOOPS);
    let w = 2.0 * std::f64::consts::PI * f0;
    for (k, &i) in picked.iter().enumerate() {
        let amplitude = r.amplitudes()[i];
        let samples = loop_of(model, r, s, i)?;
        let color = scale_color(k, picked.len());
        let label = format!("A = {}", crate::fmt::sig(amplitude, 4));
        let uf: Vec<(f64, f64)> = samples
            .u
            .iter()
            .copied()
            .zip(samples.force.iter().copied())
            .collect();
        // u = offset + A sin(w t): u' = A w cos(w t), exactly.
        let vf: Vec<(f64, f64)> = samples
            .t
            .iter()
            .zip(&samples.force)
            .map(|(&t, &f)| (amplitude * w * (w * t).cos(), f))
            .collect();
        loops = loops.curve(Curve::new(uf, LineStyle::Solid, color).label(label.clone()));
        velocity = velocity.curve(Curve::new(vf, LineStyle::Solid, color).label(label));
    }
    Ok((loops, velocity))
}

/// The loop at amplitude `i` and the first frequency: the sweep's own when `--loops` asked for
/// it, else computed here.
fn loop_of(
    model: &LuGre,
    r: &sweep::Request,
    s: &Sweep,
    i: usize,
) -> Result<lugre::sweep::LoopSamples> {
    let index = i * r.frequencies().len();
    if let Some(samples) = s.points.get(index).and_then(|p| p.samples.clone()) {
        return Ok(samples);
    }
    let (amplitude, frequency) = r.point(index);
    let point = Point::compute(
        model,
        amplitude,
        frequency,
        r.offset(),
        r.tolerance(),
        LOOP_SAMPLES,
    )?;
    Ok(point.samples.unwrap_or_default())
}

/// Energy per cycle, gain and phase against the amplitude, one curve per frequency drawn.
fn summary_figures(r: &sweep::Request, s: &Sweep, units: &Units) -> [Figure; 3] {
    let mut energy = Figure::new(units.u("amplitude A"), units.energy("energy per cycle"))
        .title("energy dissipated per cycle")
        .log_x()
        .log_y();
    let mut gain = Figure::new(units.u("amplitude A"), units.stiffness("gain |N|"))
        .title("describing function: gain")
        .log_x()
        .log_y();
    let mut phase = Figure::new(units.u("amplitude A"), "phase [deg]")
        .title("describing function: phase (> 0: F leads u)")
        .log_x();
    let nf = r.frequencies().len();
    let picked = spread(nf, MAX_CURVES);
    for (k, &j) in picked.iter().enumerate() {
        let color = scale_color(k, picked.len());
        let label = format!("f = {} Hz", crate::fmt::sig(r.frequencies()[j], 4));
        let column = |value: fn(&Point) -> f64| -> Vec<(f64, f64)> {
            s.points
                .iter()
                .skip(j)
                .step_by(nf)
                .map(|p| (p.amplitude, value(p)))
                .collect()
        };
        let add = |fig: Figure, points: Vec<(f64, f64)>| -> Figure {
            let markers: Vec<Marker> = points
                .iter()
                .map(|&at| Marker {
                    label: None,
                    at,
                    shape: Shape::Circle,
                    color,
                })
                .collect();
            let mut fig =
                fig.curve(Curve::new(points, LineStyle::Solid, color).label(label.clone()));
            for m in markers {
                fig = fig.marker(m);
            }
            fig
        };
        energy = add(energy, column(|p| p.dissipation));
        gain = add(gain, column(|p| p.gain));
        phase = add(phase, column(|p| p.phase.to_degrees()));
    }
    [energy, gain, phase]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_loops_drawn_are_spread_over_the_amplitudes() {
        assert_eq!(spread(3, 8), [0, 1, 2]);
        assert_eq!(spread(50, 5), [0, 12, 25, 37, 49]);
        assert_eq!(spread(9, 2), [0, 8]);
    }
}
