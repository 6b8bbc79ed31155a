//! Parts of the loop engine ([`crate::LoopTable`]) that the `floor` benchmark times on their
//! own, to show where the engine's time goes. Not for use: only with the feature
//! `bench-internals`, hidden from the documentation and free to change.

use crate::kernel::arc::Sums;
use crate::kernel::numerics::{PhiBlock, BLOCK};
use crate::kernel::piece::step;
use crate::model::RateIndependent;

/// The kernel's exact relaxation step, for the benchmark's closed-form floor.
pub use crate::kernel::relax::relax;

/// The engine's per-piece arithmetic over the pieces of `u` (`y` from 0 written to `y`, as
/// far as it reaches): the same blocks of families, closed forms and double-double sums as the
/// loop engine's, into one running sum, with no rainflow, no loop and no output. Returns the
/// total dissipation, so that nothing can be optimised away.
pub fn piece_arithmetic(model: RateIndependent, u: &[f64], y: &mut [f64]) -> f64 {
    #[cfg(target_arch = "x86_64")]
    {
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU has the features the function is compiled for.
            return unsafe { piece_arithmetic_avx2(model, u, y) };
        }
    }
    piece_arithmetic_portable(model, u, y)
}

/// Compiled for AVX2 like the engine's pass.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn piece_arithmetic_avx2(model: RateIndependent, u: &[f64], y: &mut [f64]) -> f64 {
    piece_arithmetic_portable(model, u, y)
}

#[inline(always)]
fn piece_arithmetic_portable(model: RateIndependent, u: &[f64], y: &mut [f64]) -> f64 {
    let model = model.relaxation();
    let (mut z, mut family) = ([0.0; BLOCK], PhiBlock::default());
    let (mut sums, mut y_prev) = (Sums::default(), 0.0);
    for first in (1..u.len()).step_by(BLOCK) {
        let pieces = first..(first + BLOCK).min(u.len());
        for (z, k) in z.iter_mut().zip(pieces.clone()) {
            *z = model.a() * (u[k] - u[k - 1]).abs();
        }
        family.fill(&z);
        for (i, k) in pieces.enumerate() {
            let (s, l) = step(u[k - 1], u[k]);
            let (piece, terms) = Sums::with_piece(model, y_prev, s, l, &family.get(i));
            sums = sums + terms;
            y_prev = piece.y_end;
            if let Some(y) = y.get_mut(k) {
                *y = y_prev;
            }
        }
    }
    sums.dissipation()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::piece::{advance, piece};
    use crate::LuGre;
    use lugre_test_support::prec::{rel_diff, CLOSED_FORM};

    /// Across several blocks, each piece gets its own family: `y` agrees with the scalar
    /// closed form (`advance`, through `relax`: another path) and the dissipation with the
    /// pieces summed one by one.
    #[test]
    fn piece_arithmetic_is_the_pieces_in_order() {
        let model = LuGre::paper().rate_independent();
        let u: Vec<f64> = (0..3 * BLOCK + 5)
            .map(|k| (k as f64 * 0.7).sin() * (1.0 + (k % 5) as f64))
            .collect();
        let mut y = vec![0.0; u.len()];
        let total = piece_arithmetic(model, &u, &mut y);
        let (mut y_k, mut d) = (0.0, 0.0);
        for k in 1..u.len() {
            let (s, l) = step(u[k - 1], u[k]);
            d += piece(model.relaxation(), y_k, s, l).dissipation;
            y_k = advance(model.relaxation(), y_k, s, l);
            // On the scale of `y`, `g0`: near a zero crossing a relative test would measure
            // the cancellation of `y_k e + s sigma0 c`, not the code.
            let scale = model.g0();
            assert!(
                (y[k] - y_k).abs() <= CLOSED_FORM * scale,
                "k = {k}: {} vs {y_k}",
                y[k]
            );
        }
        assert!(rel_diff(total, d) <= CLOSED_FORM, "{total} vs {d}");
    }
}
