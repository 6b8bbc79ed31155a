//! The numerical kernel: closed forms on one piece and their sums, shared by every engine.
//!
//! A true leaf: it imports nothing of the crate and takes numbers, not model types, so
//! [`crate::model`], [`crate::loops`], [`crate::cycles`], [`crate::simulate`] and [`crate::fit`]
//! all build on it without depending on each other. What it holds:
//!
//! * `relax`: one step of `w' = -r w + q` exactly (`relax`, `relax_toward`, `decay`), eq. 8 on
//!   a piece of the normalized input and eq. 5 on a segment of a piecewise-linear input;
//! * `numerics`: `phi`, `h`, `q` and their family at one argument from a single exponential,
//!   blocks of them for the vectorized passes, and double-double arithmetic;
//! * `piece`: `y°` at the end of a piece of the loop, its dissipation and the two terms of its
//!   work (eq. 8 integrated);
//! * `arc`: the sums of pieces over an arc and the energies of the arc ([`ArcEnergy`]);
//! * `radau`: the Radau IIA tableau of the two stiff integrators (`simulate`, `dynamics`).
//!
//! The mathematics is in `docs/mathematics.md` (`#the-stable-closed-form`,
//! `#the-energy-identity-and-the-dissipation-series`).
//!
//! **Inlining rule.** The loop engine is compiled twice, portable and AVX2, chosen at run time
//! ([`crate::loops`]). A helper it calls that is not inlined is compiled once, without AVX2,
//! and the AVX2 copy calls it: the lane sums and the blocks of the series lose their vector
//! forms, silently (the results stay bit-identical, only slower). A plain `#[inline]` is a hint
//! the optimiser may decline in a function as large as the engine's pass, so every helper on
//! that path — here and in the engine — is `#[inline(always)]`. A contributor adding one must
//! do the same; `cargo bench -p lugre --bench loops` shows the difference.

pub(crate) mod arc;
pub(crate) mod numerics;
pub(crate) mod piece;
pub(crate) mod radau;
pub(crate) mod relax;

pub use arc::ArcEnergy;

/// The numbers the rate-independent closed forms take: `sigma0`, `g0 = g(0)` and
/// `a = sigma0 / g0` (kept: every piece of every loop needs it, and a division is slow).
/// Built from a validated [`crate::RateIndependent`]; the kernel does not validate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Relaxation {
    sigma0: f64,
    g0: f64,
    a: f64,
}

impl Relaxation {
    /// From `sigma0` and `g0` (the caller has checked that both and their ratio are finite and
    /// positive).
    #[inline]
    pub(crate) fn new(sigma0: f64, g0: f64) -> Self {
        Self {
            sigma0,
            g0,
            a: sigma0 / g0,
        }
    }

    #[inline(always)]
    pub(crate) fn sigma0(&self) -> f64 {
        self.sigma0
    }

    #[inline(always)]
    pub(crate) fn g0(&self) -> f64 {
        self.g0
    }

    #[inline(always)]
    pub(crate) fn a(&self) -> f64 {
        self.a
    }
}
