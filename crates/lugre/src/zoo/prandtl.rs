//! The Prandtl-Ishlinskii model with play (backlash) operators (Brokate and Sprekels,
//! "Hysteresis and Phase Transitions", Springer 1996, ch. 2; Kuhnen, "Modeling, identification
//! and compensation of complex hysteretic nonlinearities: a modified Prandtl-Ishlinskii
//! approach", European J. Control 9(4), 2003).
//!
//! Input `u` (any unit, e.g. V or m), output `F` (any unit), thresholds `r_i >= 0` [unit
//! of `u`], weights `w_i` [unit of `F` per unit of `u`], `w0` the weight of the linear part
//! (the operator of threshold 0):
//!
//! ```text
//! (P1)  F = w0 u + sum_i w_i p_i,   p_i = P_{r_i}[u]   (the play operator, Z1 of crate::zoo)
//! (P2)  V = W u²/2 - sum_i w_i z_i²/2,   z_i = u - p_i,   W = w0 + sum_i w_i
//! (P3)  D = - sum_i w_i r_i × slip_i
//! ```
//!
//! Constraint. From rest at 0 the initial-loading curve is `F(u) = w0 u + sum w_i (u - r_i)_+`,
//! piecewise linear with slope `w0 + sum_{r_i < u} w_i` between consecutive thresholds. It is
//! strictly increasing (so the model is invertible and every loop branch is increasing, the
//! condition of Kuhnen's inverse) exactly when
//!
//! ```text
//! (P4)  w0 > 0  and  w0 + sum_{r_i <= r} w_i > 0  for every threshold r,
//! ```
//!
//! which is what [`PrandtlIshlinskii::new`] checks. Negative weights past the first threshold
//! are allowed (they model saturation). With nonnegative weights `D <= 0`: the play loops run
//! counterclockwise in the `(u, F)` plane, and the work per loop is minus the enclosed area.

use super::{check_elements, check_lengths, check_scalar, PlayBank, ZooLoop};
use crate::error::ZooError;
use crate::input::TurningPoints;

/// The Prandtl-Ishlinskii model: validated thresholds and weights.
#[derive(Debug, Clone, PartialEq)]
pub struct PrandtlIshlinskii {
    linear_weight: f64,
    weights: Vec<f64>,
    bank: PlayBank,
}

impl PrandtlIshlinskii {
    /// `F = linear_weight u + sum weights[i] P_{thresholds[i]}[u]`.
    ///
    /// # Errors
    /// [`ZooError::Empty`] without operators, [`ZooError::LengthMismatch`],
    /// [`ZooError::NotFinite`] / [`ZooError::Negative`] (thresholds) naming the element,
    /// [`ZooError::Domain`] for `linear_weight` not finite and positive,
    /// [`ZooError::NotIncreasing`] when (P4) fails.
    pub fn new(linear_weight: f64, thresholds: &[f64], weights: &[f64]) -> Result<Self, ZooError> {
        check_lengths(("thresholds", thresholds.len()), ("weights", weights.len()))?;
        check_scalar("linear_weight", linear_weight, true)?;
        check_elements("thresholds", thresholds, false)?;
        check_elements("weights", weights, false).or_else(|e| match e {
            ZooError::Negative { .. } => Ok(()),
            e => Err(e),
        })?;
        check_loading(linear_weight, thresholds, weights)?;
        let total = weights.iter().sum::<f64>() + linear_weight;
        if !total.is_finite() {
            return Err(ZooError::Overflow {
                what: "the sum of the weights",
            });
        }
        Ok(Self {
            linear_weight,
            weights: weights.to_vec(),
            bank: PlayBank::new(thresholds.to_vec(), weights.to_vec(), total),
        })
    }

    pub fn linear_weight(&self) -> f64 {
        self.linear_weight
    }

    pub fn thresholds(&self) -> &[f64] {
        self.bank.thresholds()
    }

    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// The model in the common form (Z2) of [`crate::zoo`].
    pub fn bank(&self) -> &PlayBank {
        &self.bank
    }

    /// The output at each turning point, from rest (every `p_i = u0`) at `u0`.
    pub fn response(&self, u0: f64, turning: &[f64]) -> Vec<f64> {
        self.bank.response(&mut self.bank.rest(u0), turning)
    }

    /// The loop and every minor loop for the periodic input `input`.
    ///
    /// # Errors
    /// See [`ZooLoop::new`].
    pub fn loops(&self, input: &TurningPoints) -> Result<ZooLoop, ZooError> {
        ZooLoop::new(&self.bank, input)
    }
}

/// (P4): the slope of the initial-loading curve is positive from 0 and past every threshold.
fn check_loading(w0: f64, r: &[f64], w: &[f64]) -> Result<(), ZooError> {
    if w0 <= 0.0 {
        return Err(ZooError::NotIncreasing {
            threshold: 0.0,
            slope: w0,
        });
    }
    let mut order: Vec<usize> = (0..r.len()).collect();
    order.sort_by(|&a, &b| r[a].total_cmp(&r[b]));
    let mut slope = w0;
    for (i, &k) in order.iter().enumerate() {
        slope += w[k];
        // Equal thresholds act together: check after the last of them.
        let last = order.get(i + 1).is_none_or(|&next| r[next] != r[k]);
        if last && slope <= 0.0 {
            return Err(ZooError::NotIncreasing {
                threshold: r[k],
                slope,
            });
        }
    }
    Ok(())
}
