//! One point of a sweep: the orbit's quadratures turned into energies, the first harmonic and
//! the describing function (module docs, eq. P5-P6).

use super::orbit::{LoopSamples, SineOrbit};
use super::COLUMNS;
use crate::error::SweepError;
use crate::model::{LuGre, VelocityFn};
use crate::simulate::Tolerance;
use std::f64::consts::PI;

/// The periodic steady state under `u = offset + A sin(2 pi f t)`: energies over one period,
/// the peak force and the first harmonic of the force. Units: those of the model
/// (displacement m, force N, energy J with SI parameters); the phase in radians.
#[derive(Debug, Clone, PartialEq)]
pub struct Point {
    /// `A`.
    pub amplitude: f64,
    /// `f` (Hz).
    pub frequency: f64,
    /// Energy dissipated per cycle `D` (eq. P5), `>= 0`.
    pub dissipation: f64,
    /// Work done on the friction over the period, `W = integral F du`, computed as
    /// `D + Delta V` (eq. P5: the elastic part `sigma0 z z'` integrates in closed form).
    pub work: f64,
    /// Change of the energy stored in the bristles over the period, `Delta V` (0 on the orbit:
    /// what is left is the integration's error).
    pub stored_energy_change: f64,
    /// `max |F|` over the period.
    pub peak_force: f64,
    /// Equivalent stiffness `k_eq = b1 / A`.
    pub stiffness: f64,
    /// Equivalent viscous damping `c_eq = a1 / (A w)`, `w = 2 pi f`.
    pub damping: f64,
    /// Describing-function gain `|b1 + i a1| / A`.
    pub gain: f64,
    /// Describing-function phase `atan2(a1, b1)` (radians; > 0: the force leads `u`).
    pub phase: f64,
    /// The force's first Fourier coefficient on `cos(w t)`, `W / (pi A)` (eq. P6).
    pub a1: f64,
    /// The force's first Fourier coefficient on `sin(w t)`.
    pub b1: f64,
    /// The loop `(t, u, F)` over one period, when asked for.
    pub samples: Option<LoopSamples>,
}

impl Point {
    /// The steady state for one sine, to the integrator's tolerance `tol`, with the loop at
    /// `loop_samples` times (0: none).
    pub fn compute<G: VelocityFn, F: VelocityFn>(
        model: &LuGre<G, F>,
        amplitude: f64,
        frequency: f64,
        offset: f64,
        tol: Tolerance,
        loop_samples: usize,
    ) -> Result<Point, SweepError> {
        let orbit = SineOrbit::new(model, amplitude, frequency, offset, tol).map_err(|reason| {
            SweepError::AtPoint {
                amplitude,
                frequency,
                reason,
            }
        })?;
        let s = orbit.sums;
        let k = orbit.copies();
        let period = orbit.sine().period();
        let w = orbit.sine().omega();
        let dissipation = k * s.dissipation;
        let stored = 0.5 * model.sigma0() * (s.z_end - s.z_start) * (s.z_end + s.z_start);
        // W = D + Delta V (P5, the elastic work sigma0 z z' integrated in closed form) and
        // a1 = W / (pi A) (P6): no cancellation of the elastic part at small amplitudes.
        let work = dissipation + stored;
        let (a1, b1) = (work / (PI * amplitude), k * 2.0 / period * s.sin);
        let point = Point {
            amplitude,
            frequency,
            dissipation,
            work,
            stored_energy_change: stored,
            peak_force: s.peak,
            stiffness: b1 / amplitude,
            damping: a1 / (amplitude * w),
            gain: a1.hypot(b1) / amplitude,
            phase: a1.atan2(b1),
            a1,
            b1,
            samples: (loop_samples >= 2).then(|| orbit.samples(loop_samples)),
        };
        point.check()?;
        Ok(point)
    }

    /// The numbers in the order of [`COLUMNS`].
    pub fn values(&self) -> [f64; COLUMNS.len()] {
        [
            self.amplitude,
            self.frequency,
            self.dissipation,
            self.work,
            self.stored_energy_change,
            self.peak_force,
            self.stiffness,
            self.damping,
            self.gain,
            self.phase,
            self.a1,
            self.b1,
        ]
    }

    /// No number of the point is NaN or infinite (a model whose forces overflow).
    fn check(&self) -> Result<(), SweepError> {
        let finite_loop = self
            .samples
            .as_ref()
            .is_none_or(|l| l.force.iter().all(|f| f.is_finite()));
        if self.values().iter().all(|v| v.is_finite()) && finite_loop {
            Ok(())
        } else {
            Err(SweepError::Overflow {
                amplitude: self.amplitude,
                frequency: self.frequency,
            })
        }
    }
}
