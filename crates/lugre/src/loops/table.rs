//! [`LoopTable`]: every loop of a periodic input as columns, in the order the loops close.

use crate::kernel::ArcEnergy;
use crate::memory::Columns;

/// All loops of a periodic input as columns, one row per loop, in the order the loops close:
/// each loop after every loop nested in it, the major loop last (see the engine for the
/// pairing rule and [`crate::HysteresisLoop::loops`] for the same loops as records ordered by
/// where they start).
///
/// Start and reversal are turning points, given by their index `k` into
/// [`HysteresisLoop::turning_points`](crate::HysteresisLoop::turning_points) (the loop's `u`
/// and `y°` there are that array's and
/// [`turning_y`](crate::HysteresisLoop::turning_y)'s); the start's `rho` is in `[0, P)`, the
/// reversal's and the end's may exceed `P` when the arc wraps round the period.
///
/// ```
/// use lugre::{HysteresisLoop, LuGre, TurningPoints};
///
/// // The ASTM E1049 history as one period: three minor loops and the major loop.
/// let u = [-2.0, 1.0, -3.0, 5.0, -1.0, 3.0, -4.0, 4.0];
/// let model = LuGre::paper().rate_independent();
/// let hl = HysteresisLoop::new(model, &TurningPoints::new(&u).unwrap()).unwrap();
/// let t = hl.loop_table();
/// assert_eq!(t.len(), 4);
/// assert_eq!(t.major(), 3); // closes last
/// let u_a: Vec<f64> = t.start().iter().map(|&k| u[k]).collect();
/// assert_eq!(u_a, [-1.0, -2.0, 4.0, 5.0]);
/// assert!(t.dissipation().iter().all(|&d| d > 0.0));
/// assert_eq!(t.parent(1), Some(2)); // (-2, 1) lies inside (4, -3)
/// assert_eq!(hl.work_per_period(), t.work()[t.major()]);
/// ```
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LoopTable {
    len: usize,
    /// Turning points in the period.
    turning_points: usize,
    /// [`START`], [`REVERSAL`], [`PARENT`], [`DEPTH`].
    indices: Columns<usize>,
    /// [`REVERSAL_RHO`] to [`CLOSURE_GAP`].
    reals: Columns<f64>,
}

/// No row: the major loop's parent.
pub(super) const NONE: usize = usize::MAX;

const START: usize = 0;
const REVERSAL: usize = 1;
const PARENT: usize = 2;
const DEPTH: usize = 3;
const REVERSAL_RHO: usize = 0;
const END_RHO: usize = 1;
const END_U: usize = 2;
const END_Y: usize = 3;
const WORK: usize = 4;
const STORED_ENERGY_CHANGE: usize = 5;
const DISSIPATION: usize = 6;
const CLOSURE_GAP: usize = 7;

impl LoopTable {
    /// Number of loops, the major loop included.
    pub fn len(&self) -> usize {
        self.len
    }

    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The row of the major loop (the last one).
    pub fn major(&self) -> usize {
        self.len - 1
    }

    fn index(&self, i: usize) -> &[usize] {
        &self.indices.column(i)[..self.len]
    }

    fn real(&self, i: usize) -> &[f64] {
        &self.reals.column(i)[..self.len]
    }

    /// Index `k` of the turning point each loop starts at (`rho_A = rho_k`, `u_A = u_k`).
    pub fn start(&self) -> &[usize] {
        self.index(START)
    }

    /// Index `k` of the turning point each loop turns at.
    pub fn reversal(&self) -> &[usize] {
        self.index(REVERSAL)
    }

    /// `rho_B` of each loop's reversal (`rho_k`, plus `P` when the arc wrapped before it).
    pub fn reversal_rho(&self) -> &[f64] {
        self.real(REVERSAL_RHO)
    }

    /// `rho_C`, where the input first returns to `u_A`.
    pub fn end_rho(&self) -> &[f64] {
        self.real(END_RHO)
    }

    /// `u` at the end (`u_A` up to the rounding of `u_k + s offset`).
    pub fn end_u(&self) -> &[f64] {
        self.real(END_U)
    }

    /// `y°(rho_C)`.
    pub fn end_y(&self) -> &[f64] {
        self.real(END_Y)
    }

    /// `W = integral y° dpsi` over each arc, nested loops included.
    pub fn work(&self) -> &[f64] {
        self.real(WORK)
    }

    /// `dV = (y_C^2 - y_A^2) / (2 sigma0)`.
    pub fn stored_energy_change(&self) -> &[f64] {
        self.real(STORED_ENERGY_CHANGE)
    }

    /// `D = W - dV >= 0`.
    pub fn dissipation(&self) -> &[f64] {
        self.real(DISSIPATION)
    }

    /// `y_C - y_A`.
    pub fn closure_gap(&self) -> &[f64] {
        self.real(CLOSURE_GAP)
    }

    /// Row of the smallest loop containing each one (always a later row); `None` for the major
    /// loop.
    pub fn parent(&self, row: usize) -> Option<usize> {
        let p = self.index(PARENT)[row];
        (p != NONE).then_some(p)
    }

    /// 0 for the major loop, the parent's depth + 1 otherwise.
    pub fn depth(&self) -> &[usize] {
        self.index(DEPTH)
    }

    /// The rows in the order of [`crate::HysteresisLoop::loops`] (the major loop, then the
    /// minor loops by where their arcs start in the major loop's period), and the place of
    /// each row in that order (to renumber parents). A counting sort: each turning point starts
    /// at most one minor loop.
    pub fn rows_by_start(&self) -> (Vec<usize>, Vec<usize>) {
        if self.is_empty() {
            return (Vec::new(), Vec::new());
        }
        let (n, major) = (self.turning_points, self.major());
        let r = self.start()[major];
        let mut by_start = vec![NONE; n];
        for (row, &k) in self.start()[..major].iter().enumerate() {
            by_start[if k >= r { k - r } else { k + n - r }] = row;
        }
        let order: Vec<usize> = std::iter::once(major)
            .chain(by_start.into_iter().filter(|&row| row != NONE))
            .collect();
        let mut place = vec![0; self.len];
        for (i, &row) in order.iter().enumerate() {
            place[row] = i;
        }
        (order, place)
    }

    /// Room for the loops of a period of `n` turning points (at most `n / 2 + 1`).
    pub(super) fn for_turning_points(n: usize) -> Self {
        let rows = n / 2 + 1;
        Self {
            len: 0,
            turning_points: n,
            indices: Columns::zeroed(4, rows),
            reals: Columns::zeroed(8, rows),
        }
    }

    /// The loop in row `row` (its parent entry was made when it closed, the engine's `adopt`).
    #[inline]
    pub(super) fn set(
        &mut self,
        row: usize,
        (start, reversal): (usize, usize),
        reversal_rho: f64,
        end: (f64, f64, f64),
        energy: ArcEnergy,
    ) {
        self.indices.column_mut(START)[row] = start;
        self.indices.column_mut(REVERSAL)[row] = reversal;
        let reals = [
            (REVERSAL_RHO, reversal_rho),
            (END_RHO, end.0),
            (END_U, end.1),
            (END_Y, end.2),
            (WORK, energy.work),
            (STORED_ENERGY_CHANGE, energy.stored_energy_change),
            (DISSIPATION, energy.dissipation),
            (CLOSURE_GAP, energy.closure_gap),
        ];
        for (column, value) in reals {
            self.reals.column_mut(column)[row] = value;
        }
        self.len = self.len.max(row + 1);
    }

    /// The parent column, filled by the engine as loops close.
    #[inline(always)]
    pub(super) fn parents_mut(&mut self) -> &mut [usize] {
        self.indices.column_mut(PARENT)
    }

    /// Depths from the parents: a parent is always a later row, so one backward pass.
    pub(super) fn fill_depths(&mut self) {
        for i in (0..self.len).rev() {
            let p = self.index(PARENT)[i];
            if p != NONE {
                let d = self.index(DEPTH)[p] + 1;
                self.indices.column_mut(DEPTH)[i] = d;
            }
        }
    }
}
