//! The periodic orbit under a periodic piecewise-linear input (module docs, eq. P2-P3), by
//! the exact solver: one period from `z = 0` gives `c` and `R = sum c_i`, then `z*`.

use super::SweepError;
use crate::model::{LuGre, VelocityFn};
use crate::simulate::{Gamma, PiecewiseLinear, Simulator, Trajectory};

/// The periodic steady state under a periodic piecewise-linear input: the orbit's state at
/// the input's first knot, the energies over one period, the peak force and the orbit itself.
#[derive(Debug, Clone, PartialEq)]
pub struct PeriodicOrbit {
    /// `z*` at the first knot (eq. P3).
    pub z0: f64,
    /// `Phi = exp(-R)`, the contraction factor of the period map.
    pub contraction: f64,
    /// Work done on the friction over the period, `integral F du`.
    pub work: f64,
    /// Change of the stored energy `sigma0 z^2 / 2` over the period (0 on the orbit, to
    /// rounding).
    pub stored_energy_change: f64,
    /// Energy dissipated over the period, `work - stored_energy_change`.
    pub dissipation: f64,
    /// `max |F|` over the period (at a knot: on a segment `F` is monotone).
    pub peak_force: f64,
    /// One period of the orbit at the input's knots (at a kink: the value just after it).
    pub trajectory: Trajectory,
}

/// The periodic orbit of `model` (eq. 1, `gamma = 1`) under `input` repeated: its period is
/// `T = t_last - t_first` and it must end where it starts.
///
/// ```
/// use lugre::sweep::periodic_orbit;
/// use lugre::{HysteresisLoop, LuGre, PiecewiseLinear, TurningPoints};
///
/// // Turning points 0, 1 at a speed where sigma1 and the Stribeck drop act below 1e-13: the
/// // orbit is the hysteresis loop y°.
/// let model = LuGre::paper();
/// let tp = TurningPoints::new(&[0.0, 1.0]).unwrap();
/// let input = PiecewiseLinear::from_turning_points(&tp, 1e-14).unwrap();
/// let orbit = periodic_orbit(&model, &input).unwrap();
/// let hl = HysteresisLoop::new(model.rate_independent(), &tp).unwrap();
/// let d = hl.loops()[0].energy.dissipation;
/// assert!((orbit.dissipation - d).abs() < 1e-12 * d);
/// ```
pub fn periodic_orbit<G: VelocityFn, F: VelocityFn>(
    model: &LuGre<G, F>,
    input: &PiecewiseLinear,
) -> Result<PeriodicOrbit, SweepError> {
    if !input.is_closed() {
        let u = input.values();
        return Err(SweepError::NotPeriodic {
            first: u[0],
            last: u[u.len() - 1],
        });
    }
    let from_zero = Simulator::new(model, Gamma::ONE, 0.0)?;
    let (c, exponent, _) = walk(&from_zero, input, 0.0);
    // (P3): z* = c / (1 - Phi), 1 - Phi = -expm1(-R).
    let one_minus_phi = -(-exponent).exp_m1();
    let z0 = if one_minus_phi > 0.0 {
        c / one_minus_phi
    } else {
        // The input does not move: every state is periodic; the one from rest is kept.
        0.0
    };
    let sim = Simulator::new(model, Gamma::ONE, z0)?;
    let (z_end, _, sums) = walk(&sim, input, z0);
    let mut trajectory = Trajectory::default();
    sim.at_knots(input, 1, &mut trajectory)?;
    let stored = 0.5 * model.sigma0() * (z_end - z0) * (z_end + z0);
    let orbit = PeriodicOrbit {
        z0,
        contraction: (-exponent).exp(),
        work: sums.0,
        stored_energy_change: stored,
        dissipation: sums.0 - stored,
        peak_force: sums.1,
        trajectory,
    };
    if !(orbit.work.is_finite() && orbit.peak_force.is_finite()) {
        return Err(crate::error::SimulateError::Overflow {
            what: "the force",
            t: input.times()[0],
        }
        .into());
    }
    Ok(orbit)
}

/// One period walked from `z`: the end state, `R`, and (work, peak `|F|`).
fn walk<G: VelocityFn, F: VelocityFn>(
    sim: &Simulator<'_, G, F>,
    input: &PiecewiseLinear,
    mut z: f64,
) -> (f64, f64, (f64, f64)) {
    let (t, u) = (input.times(), input.values());
    let (mut exponent, mut work, mut peak) = (0.0, 0.0, 0.0f64);
    for i in 0..t.len() - 1 {
        let s = sim.walk_segment(z, u[i + 1] - u[i], t[i + 1] - t[i]);
        z = s.z_end;
        exponent += s.exponent;
        work += s.work;
        peak = peak.max(s.y_start.abs()).max(s.y_end.abs());
    }
    (z, exponent, (work, peak))
}
