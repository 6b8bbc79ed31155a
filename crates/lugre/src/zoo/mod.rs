//! Rate-independent hysteresis models with Masing behaviour: Maxwell-slip
//! ([`MaxwellSlip`]) and Prandtl-Ishlinskii ([`PrandtlIshlinskii`]), their response to any
//! sequence of turning points and, for a periodic input, the loop and every minor loop with
//! their energies, all exact (`docs/mathematics.md#masing-models-maxwell-slip-and-prandtl-ishlinskii`).
//!
//! # One form for both models
//!
//! Both are weighted sums of **play operators**. The play operator of threshold `r >= 0` maps
//! the input `u` to `p` with `|u - p| <= r`, `p` moving only when the band pushes it:
//!
//! ```text
//! (Z1)  on a segment of the input from u_a up to u_b:    p <- max(p, u_b - r)
//!       on a segment of the input from u_a down to u_b:  p <- min(p, u_b + r)
//! ```
//!
//! exactly, for any monotone segment (the segment map). `z = u - p`, `|z| <= r`, is the stop
//! (elastic-perfectly plastic) operator. A model of the zoo is, with constants `e`, `c_i`:
//!
//! ```text
//! (Z2)  F = e u - sum_i c_i z_i
//! ```
//!
//! Maxwell-slip: `e = 0`, `c_i = -k_i`, `r_i = Delta_i = f_i / k_i` (`F = sum k_i z_i`).
//! Prandtl-Ishlinskii `F = w0 u + sum w_i p_i`: `e = w0 + sum w_i`, `c_i = w_i`.
//!
//! # Energy
//!
//! On a monotone segment `z_i` moves with `u` (`dz = du`) until it reaches `s r_i`, then
//! stays there while `p_i` slips, by the length `|Δp_i|` (the slip of (Z1) equals the move
//! of `p_i`). Hence `∫ z du = Δ(z²/2) + r |Δp|`, and the work `W = ∫ F du` splits into
//!
//! ```text
//! (Z3)  V = e u²/2 - sum_i c_i z_i²/2                  (stored energy)
//! (Z4)  D = W - ΔV = - sum_i c_i r_i |Δp_i|            (dissipation, summed over segments)
//! ```
//!
//! For Maxwell-slip `V = sum k_i z_i²/2` and `D = sum f_i × slip_i >= 0`. For
//! Prandtl-Ishlinskii with nonnegative weights `D <= 0`: a play operator's loop in the
//! `(u, F)` plane runs counterclockwise (the output lags the input), so `W = ∮ F du` is minus
//! the enclosed area. The sign is the model's, not a convention of this module.
//!
//! # Masing behaviour, loops
//!
//! A play operator forgets everything but the extremes not yet wiped out: once the input
//! returns to `u_A` after a reversal at `u_B` (with `u_A` a reversal before it), every `p_i`
//! is back where it was at `A`. So every minor loop closes exactly, and the loops of a periodic
//! input are the rainflow pairs of its turning points (ASTM E1049, three-point rule, a pair
//! closing once `X >= Y`), started at the first global maximum. The periodic state there is
//!
//! ```text
//! (Z5)  p_i = u_max - min(r_i, R / 2),   R = u_max - u_min
//! ```
//!
//! for `r_i < R/2` the descent to the global minimum and the rise back saturate the operator
//! (unique); an operator with `r_i >= R/2` never slips, its offset is not fixed by the input,
//! and (Z5) takes the symmetric one: the state reached from rest (`z = 0`) at the mid-range
//! `(u_max + u_min)/2`. The pairing engine of [`crate::loops`] carries LuGre's relaxation sums;
//! this module has its own small one ([`ZooLoop`]), generic over the model's state ([`Segmental`]).

mod bouc_wen;
mod chunk;
mod elastoplastic;
mod element;
mod engine;
pub mod gms;
mod history;
mod maxwell;
mod prandtl;
mod segment;
mod stepper;
mod table;

pub use bouc_wen::BoucWen;
pub use chunk::{ZooChunkEnergy, ZooChunkState, ZooSpanPart};
pub(crate) use elastoplastic::alpha as elastoplastic_alpha;
pub use elastoplastic::ElastoPlastic;
pub use element::ZooElement;
pub use engine::{ZooLoop, MAX_STATES};
pub use history::{check_held, MAX_HISTORY_SAMPLES};
pub use maxwell::MaxwellSlip;
pub use prandtl::PrandtlIshlinskii;
pub use segment::{Point, Segmental, SingleState, Step};
pub use stepper::ZooStepper;
pub use table::{
    dynamics_model_names, model_names, Domain, Shape, ZooKind, ZooModel, ZooModelSpec,
    ZooParameter, MODELS,
};

use crate::kernel::ArcEnergy;

/// The common form (Z2) of the zoo's models: play operators of thresholds `r_i` and the
/// constants `e`, `c_i`.
#[derive(Debug, Clone, PartialEq)]
pub struct PlayBank {
    r: Vec<f64>,
    c: Vec<f64>,
    /// `-c_i r_i`: the dissipation per unit slip of each operator (Z4).
    loss: Vec<f64>,
    e: f64,
}

/// The state of a [`PlayBank`]: the input `u` and each play operator's output `p_i`.
#[derive(Debug, Clone, PartialEq)]
pub struct MasingState {
    /// The input.
    pub u: f64,
    /// Each play operator's output, `|u - p_i| <= r_i`.
    pub p: Vec<f64>,
}

impl MasingState {
    /// `z_i = u - p_i`, each element's deflection (the stop operators).
    pub fn deflections(&self) -> Vec<f64> {
        self.p.iter().map(|p| self.u - p).collect()
    }
}

impl PlayBank {
    /// Built by the models from validated parameters.
    pub(crate) fn new(r: Vec<f64>, c: Vec<f64>, e: f64) -> Self {
        let loss = r.iter().zip(&c).map(|(r, c)| -c * r).collect();
        Self { r, c, loss, e }
    }

    /// Number of play operators.
    pub fn len(&self) -> usize {
        self.r.len()
    }

    pub fn is_empty(&self) -> bool {
        self.r.is_empty()
    }

    /// The thresholds `r_i`.
    pub fn thresholds(&self) -> &[f64] {
        &self.r
    }

    /// At rest at `u`: every `z_i = 0`.
    pub fn rest(&self, u: f64) -> MasingState {
        MasingState {
            u,
            p: vec![u; self.len()],
        }
    }

    /// The force (Z2) in `state`.
    pub fn force(&self, state: &MasingState) -> f64 {
        let sum: f64 = self
            .c
            .iter()
            .zip(&state.p)
            .map(|(c, p)| c * (state.u - p))
            .sum();
        self.e * state.u - sum
    }

    /// The stored energy (Z3) in `state`.
    pub fn stored_energy(&self, state: &MasingState) -> f64 {
        let sum: f64 = self
            .c
            .iter()
            .zip(&state.p)
            .map(|(c, p)| c * (state.u - p) * (state.u - p))
            .sum();
        0.5 * (self.e * state.u * state.u - sum)
    }

    /// Moves `state` along the monotone segment to `to` (the segment map Z1); returns the
    /// dissipation (Z4) over it.
    #[inline]
    pub fn advance(&self, state: &mut MasingState, to: f64) -> f64 {
        // One loop per direction, without a branch inside: it vectorizes.
        let lanes = state.p.iter_mut().zip(&self.r).zip(&self.loss);
        let d = if to > state.u {
            lanes.fold(0.0, |d, ((p, r), loss)| {
                let old = *p;
                *p = old.max(to - r);
                d + loss * (*p - old)
            })
        } else {
            lanes.fold(0.0, |d, ((p, r), loss)| {
                let old = *p;
                *p = old.min(to + r);
                d + loss * (old - *p)
            })
        };
        state.u = to;
        d
    }

    /// The energy over an arc from `from` to `to` with dissipation `d` along it: the work,
    /// the stored-energy change (Z3) and the force difference, each from differences of the
    /// states (not of the totals), so that a closed arc gives exactly 0 where the states agree.
    pub fn arc(&self, from: &MasingState, to: &MasingState, d: f64) -> ArcEnergy {
        let du = to.u - from.u;
        let su = to.u + from.u;
        let (mut dv, mut df) = (0.0, 0.0);
        for ((c, pa), pb) in self.c.iter().zip(&from.p).zip(&to.p) {
            let dz = du - (pb - pa);
            let sz = (to.u - pb) + (from.u - pa);
            dv += c * dz * sz;
            df += c * dz;
        }
        let stored = 0.5 * (self.e * du * su - dv);
        ArcEnergy {
            work: stored + d,
            stored_energy_change: stored,
            dissipation: d,
            closure_gap: self.e * du - df,
        }
    }

    /// The force at each point of `turning` (monotone segments between them), from `state`
    /// (which ends at the last point), by the segment map (Z1).
    pub fn response(&self, state: &mut MasingState, turning: &[f64]) -> Vec<f64> {
        turning
            .iter()
            .map(|&u| {
                self.advance(state, u);
                self.force(state)
            })
            .collect()
    }

    /// The vertices `(u, F)` of the exact piecewise-linear path from `state` to `to`: the start,
    /// every point where an operator starts to slip, the end. `state` is not changed.
    pub fn path(&self, state: &MasingState, to: f64) -> Vec<(f64, f64)> {
        let up = to > state.u;
        let mut at: Vec<f64> = state
            .p
            .iter()
            .zip(&self.r)
            .map(|(p, r)| if up { p + r } else { p - r })
            .filter(|&b| {
                if up {
                    b > state.u && b < to
                } else {
                    b < state.u && b > to
                }
            })
            .collect();
        at.sort_by(|a, b| if up { a.total_cmp(b) } else { b.total_cmp(a) });
        at.push(to);
        let mut s = state.clone();
        let mut out = vec![(s.u, self.force(&s))];
        for u in at {
            self.advance(&mut s, u);
            out.push((u, self.force(&s)));
        }
        out
    }

    /// The periodic state (Z5) at the global maximum `u_max` of an input of range `range`.
    pub(crate) fn periodic_at_max(&self, u_max: f64, range: f64) -> MasingState {
        MasingState {
            u: u_max,
            p: self.r.iter().map(|r| u_max - r.min(0.5 * range)).collect(),
        }
    }
}

/// Checks element values: finite, and `> 0` (`positive`) or `>= 0`.
pub(crate) fn check_elements(
    name: &'static str,
    values: &[f64],
    positive: bool,
) -> Result<(), crate::error::ZooError> {
    use crate::error::ZooError;
    for (index, &value) in values.iter().enumerate() {
        if !value.is_finite() {
            return Err(ZooError::NotFinite { name, index, value });
        }
        if positive && value <= 0.0 {
            return Err(ZooError::NotPositive { name, index, value });
        }
        if !positive && value < 0.0 {
            return Err(ZooError::Negative { name, index, value });
        }
    }
    Ok(())
}

/// Checks a scalar parameter: finite, and `> 0` (`positive`) or `>= 0`.
pub(crate) fn check_scalar(
    name: &'static str,
    value: f64,
    positive: bool,
) -> Result<f64, crate::error::ZooError> {
    let (ok, condition) = if positive {
        (value > 0.0, "> 0")
    } else {
        (value >= 0.0, ">= 0")
    };
    if value.is_finite() && ok {
        Ok(value)
    } else {
        Err(crate::error::ZooError::Domain {
            name,
            value,
            condition: condition.into(),
        })
    }
}

/// Checks that two element arrays are non-empty and equally long.
pub(crate) fn check_lengths(
    first: (&'static str, usize),
    second: (&'static str, usize),
) -> Result<(), crate::error::ZooError> {
    use crate::error::ZooError;
    if first.1 == 0 {
        return Err(ZooError::Empty { name: first.0 });
    }
    if first.1 != second.1 {
        return Err(ZooError::LengthMismatch {
            first: first.0,
            n_first: first.1,
            second: second.0,
            n_second: second.1,
        });
    }
    Ok(())
}
