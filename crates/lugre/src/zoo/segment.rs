//! What a model of the zoo provides to the loop engine ([`Segmental`]): an exact map of its
//! state along a monotone segment of the input, the force and the energies of an arc, and its
//! periodic state at the global maximum of a periodic input.
//!
//! Single-state models (Bouc-Wen, elasto-plastic) implement the smaller [`SingleState`]: a
//! state `z` with `dz/du = h_s(z)` on a segment of direction `s` (the Duhem form). Their periodic
//! state is the fixed point of the period map `T` (the state after one period from `z` at the
//! global maximum):
//!
//! ```text
//! (S1)  T(z*) = z*,     T'(z) = prod_k h_s(z_(k+1)) / h_s(z_k)     (separable segments)
//! ```
//!
//! `T` is non-decreasing and maps the model's bounded range of states into itself, so
//! `g(z) = T(z) - z` changes sign on that range: Newton's step with the exact derivative (S1),
//! kept inside a bracket that bisection shrinks when the step leaves it. When `g` vanishes on a
//! whole interval (an input too small to make the model slip everywhere), the state reached
//! from rest (`z = 0`) at the mid-range is taken, as for the Masing models (Z5).

use super::{MasingState, PlayBank};
use crate::kernel::ArcEnergy;

/// A model whose state moves along a monotone segment of the input by an exact map.
pub trait Segmental {
    /// The state: the input and the model's internal variables.
    type State: Clone + std::fmt::Debug;

    /// What every map of a segment from one state in one direction shares, whichever point
    /// of the segment it ends at (Bouc-Wen: where the state lies on the segment's exact
    /// relation (B8)); `()` when a map has nothing to share.
    type Start: Copy + Default + std::fmt::Debug;

    /// How many numbers one state holds (for the memory check of a loop's stack).
    fn state_len(&self) -> usize;

    /// The input of `state`.
    fn input(state: &Self::State) -> f64;

    /// The force (or output) in `state`.
    fn force(&self, state: &Self::State) -> f64;

    /// Moves `state` along the monotone segment to `to`; returns the dissipation over it.
    fn advance(&self, state: &mut Self::State, to: f64) -> f64;

    /// The shared start of the segments from `state` in the direction of `to`.
    fn start(&self, _state: &Self::State, _to: f64) -> Self::Start {
        Self::Start::default()
    }

    /// [`Segmental::advance`] given `start`, [`Segmental::start`] of `state` toward `to`.
    fn advance_from(&self, _start: &Self::Start, state: &mut Self::State, to: f64) -> f64 {
        self.advance(state, to)
    }

    /// Work, stored-energy change, dissipation `d` and force difference over an arc.
    fn arc(&self, from: &Self::State, to: &Self::State, d: f64) -> ArcEnergy;

    /// The periodic state at the global maximum `u[r]` of the periodic input `u` (turning
    /// points, the period running `u[r], u[r+1], ...` and wrapping), whose minimum is `min`.
    fn periodic_start(&self, u: &[f64], r: usize, min: f64) -> Self::State;

    /// [`Segmental::periodic_start`], and in `trail` the states, segment dissipations and
    /// segment starts the solver met on its last walk over the period (`trail[j - 1]` at
    /// rotated index `j`, after the segment from `j - 1`); the
    /// returned index is the first `j` from which they are the periodic ones to rounding (the
    /// walk's dependence on where it started contracted below the solver's tolerance), so the
    /// loop engine reuses them instead of mapping those segments again. By default no walk:
    /// the index is past the period (`u.len() + 1`).
    fn periodic_trail(
        &self,
        u: &[f64],
        r: usize,
        min: f64,
        trail: &mut Vec<Step<Self::State, Self::Start>>,
    ) -> (Self::State, usize) {
        trail.clear();
        (self.periodic_start(u, r, min), u.len() + 1)
    }

    /// At rest at input `u` (every element unloaded, `z = 0`).
    fn rest(&self, u: f64) -> Self::State;

    /// `dst = src` without allocating where the state allows it.
    fn assign(dst: &mut Self::State, src: &Self::State) {
        dst.clone_from(src);
    }

    /// The state's numbers, the input first (what a chunked count sends between processes).
    fn values(state: &Self::State) -> Vec<f64>;

    /// The state of [`Segmental::values`]' numbers; `None` unless they are as many as a state
    /// of this model holds, and finite.
    fn state_of_values(&self, values: &[f64]) -> Option<Self::State>;
}

/// One segment of a walk over the period: the state it ends in, its dissipation, and the
/// shared start ([`Segmental::Start`]) of the segment, which any part of it reuses.
#[derive(Debug, Clone)]
pub struct Step<S, P> {
    /// The state at the segment's end.
    pub state: S,
    /// The dissipation over the segment.
    pub d: f64,
    /// The segment's shared start.
    pub start: P,
}

impl Segmental for PlayBank {
    type State = MasingState;
    type Start = ();

    fn state_len(&self) -> usize {
        self.len()
    }

    #[inline]
    fn input(state: &MasingState) -> f64 {
        state.u
    }

    #[inline]
    fn force(&self, state: &MasingState) -> f64 {
        PlayBank::force(self, state)
    }

    #[inline]
    fn advance(&self, state: &mut MasingState, to: f64) -> f64 {
        PlayBank::advance(self, state, to)
    }

    fn arc(&self, from: &MasingState, to: &MasingState, d: f64) -> ArcEnergy {
        PlayBank::arc(self, from, to, d)
    }

    fn rest(&self, u: f64) -> MasingState {
        PlayBank::rest(self, u)
    }

    fn periodic_start(&self, u: &[f64], r: usize, min: f64) -> MasingState {
        self.periodic_at_max(u[r], u[r] - min)
    }

    #[inline]
    fn assign(dst: &mut MasingState, src: &MasingState) {
        dst.u = src.u;
        dst.p.copy_from_slice(&src.p);
    }

    fn values(state: &MasingState) -> Vec<f64> {
        std::iter::once(state.u)
            .chain(state.p.iter().copied())
            .collect()
    }

    fn state_of_values(&self, values: &[f64]) -> Option<MasingState> {
        let (&u, p) = values.split_first()?;
        (p.len() == self.len() && values.iter().all(|x| x.is_finite()))
            .then(|| MasingState { u, p: p.to_vec() })
    }
}

/// A rate-independent model with one state `z`, `dz/du = h_s(z)` on a segment of direction `s`.
pub trait SingleState {
    /// The force at input `u` and state `z`.
    fn force(&self, u: f64, z: f64) -> f64;

    /// The stored energy at `(u, z)`.
    fn stored_energy(&self, u: f64, z: f64) -> f64;

    /// What the segments from `z_a` in one direction share ([`Segmental::Start`]).
    type Start: Copy + Default + std::fmt::Debug;

    /// The shared start of the segments from `z_a` moving up (`up`) or down.
    fn start(&self, z_a: f64, up: bool) -> Self::Start;

    /// The state at `u_b` after the monotone segment from `(u_a, z_a)`, and the dissipation
    /// along it (`>= 0`), both exact (closed form, or a root or quadrature to 1e-13 relative),
    /// given `start`, [`SingleState::start`] of `z_a` in the segment's direction.
    fn segment_from(&self, start: &Self::Start, u_a: f64, z_a: f64, u_b: f64) -> (f64, f64);

    /// [`SingleState::segment_from`] with its start.
    #[inline]
    fn segment(&self, u_a: f64, z_a: f64, u_b: f64) -> (f64, f64) {
        self.segment_from(&self.start(z_a, u_b > u_a), u_a, z_a, u_b)
    }

    /// `h_s(z) = dz/du` moving up (`up`) or down: the derivative (S1) of the period map. It
    /// does not increase in the direction of motion (`h_+` non-increasing in `z`, `h_-`
    /// non-decreasing): the state is drawn toward its bound.
    fn slope(&self, z: f64, up: bool) -> f64;

    /// The range `[lo, hi]` the state stays in once inside it.
    fn bounds(&self) -> (f64, f64);
}

/// The state of a [`SingleState`] model: the input and `z`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Point {
    /// The input.
    pub u: f64,
    /// The model's state.
    pub z: f64,
}

impl<T: SingleState> Segmental for T {
    type State = Point;
    type Start = T::Start;

    fn state_len(&self) -> usize {
        2
    }

    #[inline]
    fn input(state: &Point) -> f64 {
        state.u
    }

    #[inline]
    fn force(&self, state: &Point) -> f64 {
        SingleState::force(self, state.u, state.z)
    }

    #[inline]
    fn advance(&self, state: &mut Point, to: f64) -> f64 {
        let (z, d) = self.segment(state.u, state.z, to);
        *state = Point { u: to, z };
        d
    }

    #[inline]
    fn start(&self, state: &Point, to: f64) -> T::Start {
        SingleState::start(self, state.z, to > state.u)
    }

    #[inline]
    fn advance_from(&self, start: &T::Start, state: &mut Point, to: f64) -> f64 {
        let (z, d) = self.segment_from(start, state.u, state.z, to);
        *state = Point { u: to, z };
        d
    }

    fn arc(&self, from: &Point, to: &Point, d: f64) -> ArcEnergy {
        let stored = self.stored_energy(to.u, to.z) - self.stored_energy(from.u, from.z);
        ArcEnergy {
            work: stored + d,
            stored_energy_change: stored,
            dissipation: d,
            closure_gap: SingleState::force(self, to.u, to.z)
                - SingleState::force(self, from.u, from.z),
        }
    }

    fn rest(&self, u: f64) -> Point {
        Point { u, z: 0.0 }
    }

    fn values(state: &Point) -> Vec<f64> {
        vec![state.u, state.z]
    }

    fn state_of_values(&self, values: &[f64]) -> Option<Point> {
        match *values {
            [u, z] if u.is_finite() && z.is_finite() => Some(Point { u, z }),
            _ => None,
        }
    }

    fn periodic_start(&self, u: &[f64], r: usize, min: f64) -> Point {
        Point {
            u: u[r],
            z: fixed_point(self, u, r, min, None).0,
        }
    }

    fn periodic_trail(
        &self,
        u: &[f64],
        r: usize,
        min: f64,
        trail: &mut Vec<Step<Point, T::Start>>,
    ) -> (Point, usize) {
        let (z, first) = fixed_point(self, u, r, min, Some(trail));
        (Point { u: u[r], z }, first)
    }
}

/// Iterations of the periodic-state solver; each halves the bracket at least once in two.
const MAX_ITERATIONS: usize = 200;
/// A derivative of the period map below this is -1 when 1 is taken from it: `2^-60`.
const NEGLIGIBLE: f64 = 1.0 / (1u64 << 60) as f64;

/// `T(z) - z`, `T'(z)` (S1) for the period of `u` started at `u[r]`, and the first rotated
/// index from which the walk from `z` stays within `tolerance` of the walk from any state within
/// `width` of `z` (its derivative times `width` below `tolerance`; `n + 1` if never), with the
/// walk's states and dissipations in `trail` when given.
fn period_map<T: SingleState>(
    model: &T,
    (u, r, z): (&[f64], usize, f64),
    (width, tolerance): (f64, f64),
    mut trail: Option<&mut Vec<Step<Point, T::Start>>>,
) -> (f64, f64, usize) {
    let n = u.len();
    let (mut at, mut state, mut derivative, mut first) = (u[r], z, 1.0, n + 1);
    if let Some(t) = trail.as_deref_mut() {
        t.clear();
    }
    for j in 1..=n {
        let to = u[(r + j) % n];
        let start = model.start(state, to > at);
        let (after_z, d) = model.segment_from(&start, at, state, to);
        // `h_s` does not increase along a segment (the state moves toward its bound), so the
        // derivative never grows: once below `NEGLIGIBLE` it stays below, `T' - 1` is -1 to
        // the last bit whatever its value, and the slopes are skipped.
        if derivative >= NEGLIGIBLE {
            let up = to > at;
            let before = model.slope(state, up);
            let after = model.slope(after_z, up);
            // At a saturated state (h = 0) the map no longer depends on where it started.
            derivative *= if before != 0.0 { after / before } else { 0.0 };
        }
        if first > n && derivative * width <= tolerance {
            first = j;
        }
        if let Some(t) = trail.as_deref_mut() {
            t.push(Step {
                state: Point { u: to, z: after_z },
                d,
                start,
            });
        }
        (at, state) = (to, after_z);
    }
    (state - z, derivative - 1.0, first)
}

/// The periodic state (S1) at `u[r]`: safeguarded Newton on the model's bounds; with `trail`,
/// the last walk's states and the first index where they are the periodic ones (see
/// [`Segmental::periodic_trail`]).
fn fixed_point<T: SingleState>(
    model: &T,
    u: &[f64],
    r: usize,
    min: f64,
    mut trail: Option<&mut Vec<Step<Point, T::Start>>>,
) -> (f64, usize) {
    let n = u.len();
    let (mut lo, mut hi) = model.bounds();
    let rest = model.segment(0.5 * (u[r] + min), 0.0, u[r]).0.clamp(lo, hi);
    let tolerance = 4.0 * f64::EPSILON * lo.abs().max(hi.abs());
    let mut z = rest;
    for _ in 0..MAX_ITERATIONS {
        // The fixed point lies in [lo, hi]: the walk from it is within `hi - lo` of this one.
        let (g, dg, first) =
            period_map(model, (u, r, z), (hi - lo, tolerance), trail.as_deref_mut());
        if g.abs() <= tolerance {
            // The walk started at the periodic state itself.
            return (z, 1);
        }
        // A strong contraction (|T'| small, a long or large input): T(z) is within |T'| |g|
        // of the fixed point, so one pass over the period suffices.
        if (dg + 1.0).abs() * g.abs() <= tolerance {
            return ((z + g).clamp(lo, hi), first);
        }
        // g is non-increasing: a positive value lies left of the roots.
        if g > 0.0 {
            lo = z;
        } else {
            hi = z;
        }
        if hi - lo <= tolerance {
            return (z, 1);
        }
        let newton = z - g / dg;
        z = if dg < 0.0 && newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
    }
    (z, n + 1)
}
