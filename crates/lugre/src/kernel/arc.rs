//! Energies over a loop's arc, shared by periodic loops ([`crate::loops`]) and measured
//! histories ([`crate::cycles`]): the work `W = integral y dpsi`, the stored-energy change
//! `dV = (y_C^2 - y_A^2) / (2 sigma0)` and the dissipation `D = (1/g0) integral y^2 drho`,
//! over an arc from `A` to `C` on which the input returns to its start (`u_C = u_A`).
//!
//! `W = dV + D` exactly, and `W` can be computed two ways whose rounding differs by orders of
//! magnitude depending on the loop:
//!
//! * directly, as `integral (y - y_A) dpsi` (equal to `W` because `integral dpsi = 0`): per
//!   piece `s (y_k - y_A) c + (1 - s y_A / g0) e` with
//!   `(c, e) = (l phi(a l), sigma0 l^2 h(a l))`.
//!   Its terms are at most about `sigma0 L min(L, 2/a)` over an arc of length `L`: accurate for
//!   loops narrower than `1/a` far from `y = 0`, where `D ~ |dV| >> W`;
//! * as `dV + D`: its terms are `|dV|` and `D`: accurate in the elastic regime (`a L << 1`
//!   near `y = 0`), where the direct terms `O(sigma0 L^2)` cancel down to `W = O(a sigma0 L^3)`.
//!
//! [`arc_energy`] returns the one with the smaller rounding bound. The closure gap
//! `y_C - y_A` is `O(a)` on arcs shorter than `1/a`, so it is not taken as a difference there:
//! on a piece `y_end - y_k = s sigma0 l - a (y_k c + s e)`, and the first terms add up
//! to `sigma0 (u_C - u_A) = 0`, leaving `gap = -a (sum y_k c + sum s e)`.

use super::numerics::{DoubleDouble, PhiFamily};
use super::piece::{piece, piece_with, Piece};
use super::Relaxation;

/// Running sums over pieces of an arc, in double-double, one lane per sum (`hi + lo` in each):
/// laid out as two arrays so that adding two sums is a few vector instructions. `y_k c` is
/// formed exactly, so `s1 - y_A s2` is `sum s (y_k - y_A) c` up to one rounding of a small
/// number.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
#[repr(C, align(64))]
pub(crate) struct Sums {
    hi: [f64; LANES],
    lo: [f64; LANES],
}

pub(crate) const LANES: usize = 8;
/// `sum s y_k c`
const S1: usize = 0;
/// `sum s c`
const S2: usize = 1;
/// `sum e`
const S3: usize = 2;
/// `sum s e`
const S4: usize = 3;
/// `sum y_k c`
const S5: usize = 4;
/// `sum l`, the arc's length in rho.
const LENGTH: usize = 5;
/// The dissipation `sum (1/g0) integral y^2 drho`.
const D: usize = 6;

impl Sums {
    /// The sums over one piece `p` of direction `s` and length `l` that starts at `y`.
    #[inline(always)]
    pub fn piece(y: f64, s: f64, l: f64, p: &Piece) -> Self {
        let yc = DoubleDouble::product(y, p.c);
        Self {
            hi: [
                s * yc.hi,
                s * p.c,
                p.e,
                s * p.e,
                yc.hi,
                l,
                p.dissipation,
                0.0,
            ],
            lo: [s * yc.lo, 0.0, 0.0, 0.0, yc.lo, 0.0, 0.0, 0.0],
        }
    }

    /// The piece of direction `s` and length `l` from `y`, its family `f` already evaluated (in
    /// blocks), and its sums.
    #[inline(always)]
    pub fn with_piece(model: Relaxation, y: f64, s: f64, l: f64, f: &PhiFamily) -> (Piece, Self) {
        let p = piece_with(model, y, s, l, f);
        (p, Self::piece(y, s, l, &p))
    }

    /// Adds the piece of direction `s` and length `l` starting at `y`; returns its work
    /// `integral y dpsi`, its dissipation and `y` at its end.
    #[inline]
    pub fn add_piece(
        &mut self,
        model: Relaxation,
        y: f64,
        s: f64,
        l: f64,
    ) -> (DoubleDouble, f64, f64) {
        let (terms, w, d, y_end) = Self::piece_terms(model, y, s, l);
        *self = *self + terms;
        (w, d, y_end)
    }

    /// The sums of the piece of direction `s` and length `l` starting at `y`, its work
    /// `integral y dpsi`, its dissipation and `y` at its end.
    #[inline]
    pub fn piece_terms(
        model: Relaxation,
        y: f64,
        s: f64,
        l: f64,
    ) -> (Self, DoubleDouble, f64, f64) {
        let p = piece(model, y, s, l);
        let terms = Self::piece(y, s, l, &p);
        (
            terms,
            terms.lane_dd(S1).add_f64(p.e),
            p.dissipation,
            p.y_end,
        )
    }

    #[inline(always)]
    fn lane_dd(&self, i: usize) -> DoubleDouble {
        DoubleDouble {
            hi: self.hi[i],
            lo: self.lo[i],
        }
    }

    /// Lane `i` rounded to f64. A sum that overflowed stays infinite (its trailing part, the
    /// error of an infinite sum, is NaN).
    #[inline]
    fn lane(&self, i: usize) -> f64 {
        let hi = self.hi[i];
        if hi.is_finite() {
            hi + self.lo[i]
        } else {
            hi
        }
    }

    /// The lanes as one array (leading parts, then trailing parts), to send between processes.
    pub fn to_array(self) -> [f64; 2 * LANES] {
        let mut a = [0.0; 2 * LANES];
        a[..LANES].copy_from_slice(&self.hi);
        a[LANES..].copy_from_slice(&self.lo);
        a
    }

    /// [`to_array`](Self::to_array)'s output back.
    pub fn from_array(a: &[f64; 2 * LANES]) -> Self {
        let mut s = Self::default();
        s.hi.copy_from_slice(&a[..LANES]);
        s.lo.copy_from_slice(&a[LANES..]);
        s
    }

    /// The dissipation over the pieces added (never < 0; an overflow stays visible as inf).
    pub fn dissipation(&self) -> f64 {
        let d = self.lane(D);
        if d < 0.0 {
            0.0
        } else {
            d
        }
    }
}

impl std::ops::Add for Sums {
    type Output = Self;
    /// Lane by lane: the exact sum of the leading parts (two-sum) with its rounding error added
    /// to the trailing parts, not renormalized. The leading part then depends on the leading
    /// parts only (one addition of latency, where a renormalized double-double chains about
    /// ten), which is what the loop engine waits on; the trailing part
    /// collects the errors, so `hi + lo` keeps about `k eps^2` relative error after `k`
    /// additions.
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        let mut r = Self::default();
        for i in 0..LANES {
            let (s, e) = DoubleDouble::two_sum(self.hi[i], o.hi[i]);
            r.hi[i] = s;
            r.lo[i] = (self.lo[i] + o.lo[i]) + e;
        }
        r
    }
}

impl std::ops::Neg for Sums {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self {
            hi: self.hi.map(|x| -x),
            lo: self.lo.map(|x| -x),
        }
    }
}

impl std::ops::Sub for Sums {
    type Output = Self;
    #[inline]
    fn sub(self, o: Self) -> Self {
        self + (-o)
    }
}

/// The energies over an arc from `A` to `C` on which the input returns to its start
/// (`u_C = u_A`): a periodic input's loop ([`crate::Loop`]) or a measured history's full cycle
/// ([`crate::CycleEnergy`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArcEnergy {
    /// `W = integral y dpsi` over the arc, nested loops included.
    pub work: f64,
    /// `dV = (y_C^2 - y_A^2) / (2 sigma0)`, the change of the energy stored in the bristles.
    pub stored_energy_change: f64,
    /// `D = W - dV = (1/g0) integral y^2 drho >= 0`.
    pub dissipation: f64,
    /// `y_C - y_A`: loops do not close in general (paper Fig. 15).
    pub closure_gap: f64,
}

/// `y_C - y_A` over an arc of length `length` on which the input returns to its start, from
/// the sums `y_k c` and `s e` over it (see the module docs), or as the plain difference on
/// arcs longer than `1/a`, where the gap is not small and the difference is exact enough.
#[inline]
pub(crate) fn closure_gap(
    model: Relaxation,
    length: f64,
    sum_yc: f64,
    sum_se: f64,
    y_a: f64,
    y_c: f64,
) -> f64 {
    if model.a() * length > 1.0 {
        y_c - y_a
    } else {
        -model.a() * (sum_yc + sum_se)
    }
}

/// `dV` from the gap and the two end values.
#[inline]
pub(crate) fn stored_energy_change(model: Relaxation, gap: f64, y_a: f64, y_c: f64) -> f64 {
    // `gap / sigma0` first: a length, where `gap (y_c + y_a)` is a force squared and overflows
    // (forces above 1e154) or underflows (below 1e-154) where dV itself is representable.
    gap / model.sigma0() * (0.5 * (y_c + y_a))
}

/// Whether the direct form of `W` rounds less than `dV + D` on an arc of length `length`
/// (module docs): its terms are at most `sigma0 L min(L, 2/a)`, those of the identity
/// `|dV| + D`.
#[inline]
pub(crate) fn direct_work_is_better(
    model: Relaxation,
    length: f64,
    stored_energy_change: f64,
    dissipation: f64,
) -> bool {
    let direct_bound = model.sigma0() * length * length.min(2.0 / model.a());
    direct_bound < stored_energy_change.abs() + dissipation
}

/// `W` from whichever of its two forms rounds less, given `dV`, `D`, the arc's length and,
/// when the pieces were summed, the direct form `integral (y - y_A) dpsi`.
#[inline]
pub(crate) fn best_work(
    model: Relaxation,
    length: f64,
    direct: Option<f64>,
    stored_energy_change: f64,
    dissipation: f64,
) -> f64 {
    match direct {
        Some(w) if direct_work_is_better(model, length, stored_energy_change, dissipation) => w,
        _ => stored_energy_change + dissipation,
    }
}

/// Every energy of an arc from `A` (where `y = y_a`) to `C` (`y = y_c`) whose pieces were
/// summed into `sums`.
#[inline(always)]
pub(crate) fn arc_energy(model: Relaxation, sums: &Sums, y_a: f64, y_c: f64) -> ArcEnergy {
    let length = sums.lane(LENGTH);
    let gap = closure_gap(model, length, sums.lane(S5), sums.lane(S4), y_a, y_c);
    let dv = stored_energy_change(model, gap, y_a, y_c);
    let d = sums.dissipation();
    let direct =
        sums.lane(S1) - y_a * sums.lane(S2) + sums.lane(S3) - y_a / model.g0() * sums.lane(S4);
    ArcEnergy {
        work: best_work(model, length, Some(direct), dv, d),
        stored_energy_change: dv,
        dissipation: d,
        closure_gap: gap,
    }
}
