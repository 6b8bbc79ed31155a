//! Theorem A: the hysteresis loop and the minor loop of a bimodal input (Definition 1).
//!
//! The statement's printed formulas have two errata (the proof's eqs. 13-16 are right): the
//! sign in front of `g(0)[...]` is `+` on increasing segments (`i = 0, 2`) and `-` on decreasing
//! ones (`i = 1, 3`); and `psi_u`, `y°` are functions of `rho`, not of `t`. Its formula for
//! `y°(0)` multiplies `exp(a rho_i)` terms and overflows once `a rho_4 > ~709`; the values here
//! come from the stable recursion of [`crate::loops`], which equals eq. 13 wherever both
//! are finite.

use super::HysteresisLoop;
use crate::input::Bimodal;

/// `rho_0..rho_5` of Theorem A, `y°` there, and the minor-loop arc `[rho_1, rho_5]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TheoremA {
    pub rho: [f64; 6],
    pub y: [f64; 6],
    pub minor_loop: [f64; 2],
}

impl TheoremA {
    /// Theorem A's quantities for the bimodal input `b` on the loop `hl` built from it.
    pub fn new(b: &Bimodal, hl: &HysteresisLoop) -> Self {
        let rho = b.rho();
        let y = rho.map(|r| hl.y_at(r));
        Self {
            rho,
            y,
            minor_loop: [rho[1], rho[5]],
        }
    }
}
