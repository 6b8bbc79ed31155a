//! The Maxwell-slip model (Al-Bender, Lampaert and Swevers, "The generalized Maxwell-slip
//! model: a novel model for friction simulation and compensation", IEEE Trans. Automatic
//! Control 50(11), 2005, the rate-independent part of GMS; Lampaert, Al-Bender and Swevers,
//! "A generalized Maxwell-slip friction model appropriate for control purposes", 2003).
//!
//! `N` elasto-plastic elements in parallel, all driven by the displacement `u` (m). Element `i`
//! has stiffness `k_i > 0` (N/m) and slip force `f_i > 0` (N), so break-away displacement
//! `Delta_i = f_i / k_i` (m); its state is its deflection `z_i` (m):
//!
//! ```text
//! (M1)  |k_i z_i| <= f_i,   dz_i/du = 1 while |z_i| < Delta_i or the motion unloads it,
//!                           0 while it slips (z_i = ±Delta_i in the direction of motion)
//! (M2)  F = sum_i k_i z_i                                     [N]
//! (M3)  V = sum_i k_i z_i² / 2,  D = sum_i f_i × slip_i       [J]
//! ```
//!
//! On a monotone segment of `u` the map is exact and piecewise linear: each `z_i` moves with
//! `u` until it saturates at `±Delta_i` (the segment map Z1 of [`crate::zoo`], with `z = u - p`
//! and threshold `Delta_i`). The initial-loading curve from rest is
//! `F(u) = sum_i k_i min(u, Delta_i)`, increasing, slope `sum k_i` at 0.
//!
//! At finite rate the elements are GMS's ([`super::gms`]): the slip level follows the
//! Stribeck curve and a slipping element relaxes to it at a finite rate; the model carries
//! those parameters ([`MaxwellSlip::with_rate`]) and its slow limit is (M1)-(M3).

use super::gms::{Gms, GmsRate};
use super::{check_elements, check_lengths, MasingState, PlayBank, ZooLoop};
use crate::error::ZooError;
use crate::input::TurningPoints;

/// The Maxwell-slip model: validated element stiffnesses and slip forces.
#[derive(Debug, Clone, PartialEq)]
pub struct MaxwellSlip {
    stiffness: Vec<f64>,
    slip_force: Vec<f64>,
    bank: PlayBank,
    /// The elements at finite rate (GMS).
    gms: Gms,
}

impl MaxwellSlip {
    /// Elements of stiffness `stiffness[i]` (N/m) and slip force `slip_force[i]` (N).
    ///
    /// # Errors
    /// [`ZooError::Empty`] without elements, [`ZooError::LengthMismatch`] for arrays of
    /// different lengths, [`ZooError::NotFinite`] / [`ZooError::NotPositive`] naming the
    /// element, [`ZooError::Overflow`] when a break-away displacement `f_i / k_i` overflows.
    pub fn new(stiffness: &[f64], slip_force: &[f64]) -> Result<Self, ZooError> {
        check_lengths(
            ("stiffness", stiffness.len()),
            ("slip_force", slip_force.len()),
        )?;
        check_elements("stiffness", stiffness, true)?;
        check_elements("slip_force", slip_force, true)?;
        let delta: Vec<f64> = stiffness
            .iter()
            .zip(slip_force)
            .map(|(k, f)| f / k)
            .collect();
        if !delta.iter().all(|d| d.is_finite()) {
            return Err(ZooError::Overflow {
                what: "a break-away displacement slip_force / stiffness",
            });
        }
        let c = stiffness.iter().map(|k| -k).collect();
        Ok(Self {
            stiffness: stiffness.to_vec(),
            slip_force: slip_force.to_vec(),
            bank: PlayBank::new(delta, c, 0.0),
            gms: Gms::new(stiffness, slip_force, GmsRate::default())?,
        })
    }

    /// The finite-rate (GMS) parameters `rate` (the slow loop does not use them).
    ///
    /// # Errors
    /// [`ZooError::Domain`] naming the parameter: `fc, vs, beta, attraction > 0`,
    /// `sigma1, sigma2 >= 0`.
    pub fn with_rate(mut self, rate: GmsRate) -> Result<Self, ZooError> {
        self.gms = Gms::new(&self.stiffness, &self.slip_force, rate)?;
        Ok(self)
    }

    /// The finite-rate (GMS) parameters.
    pub fn rate(&self) -> GmsRate {
        self.gms.rate()
    }

    /// The model at finite rate (GMS).
    pub fn gms(&self) -> &Gms {
        &self.gms
    }

    /// The GMS friction force at each time `t[j]` of the motion `u(t)`, linear between the
    /// samples, from rest at `t[0]`: exact ([`Gms::simulate`]).
    ///
    /// ```
    /// use lugre::zoo::MaxwellSlip;
    /// let model = MaxwellSlip::new(&[1.0, 1.0], &[0.5, 1.5])?;
    /// // Slowly to u = 3 (both elements slip at their levels, near 0.5 + 1.5), back to 1.
    /// let f = model.simulate(&[0.0, 3e6, 5e6], &[0.0, 3.0, 1.0])?;
    /// assert!((f[1] - 2.0).abs() < 1e-5 && (f[2] + 1.0).abs() < 1e-5);
    /// # Ok::<(), lugre::Error>(())
    /// ```
    ///
    /// # Errors
    /// See [`Gms::simulate`].
    pub fn simulate(&self, t: &[f64], u: &[f64]) -> Result<Vec<f64>, ZooError> {
        self.gms.simulate(t, u)
    }

    pub fn stiffness(&self) -> &[f64] {
        &self.stiffness
    }

    pub fn slip_force(&self) -> &[f64] {
        &self.slip_force
    }

    /// The break-away displacements `Delta_i = f_i / k_i`.
    pub fn break_away(&self) -> &[f64] {
        self.bank.thresholds()
    }

    /// The model in the common form (Z2) of [`crate::zoo`].
    pub fn bank(&self) -> &PlayBank {
        &self.bank
    }

    /// The force at each turning point, from rest (every `z_i = 0`) at `u0`.
    pub fn response(&self, u0: f64, turning: &[f64]) -> Vec<f64> {
        self.bank.response(&mut self.bank.rest(u0), turning)
    }

    /// The element deflections `z_i` of `state`.
    pub fn deflections(&self, state: &MasingState) -> Vec<f64> {
        state.deflections()
    }

    /// The loop and every minor loop for the periodic input `input`.
    ///
    /// # Errors
    /// See [`ZooLoop::new`].
    pub fn loops(&self, input: &TurningPoints) -> Result<ZooLoop, ZooError> {
        ZooLoop::new(&self.bank, input)
    }
}
