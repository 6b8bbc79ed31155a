//! Loops as records ([`Loop`]), ordered by where they start: the same loops as the
//! [`LoopTable`](super::LoopTable) the engine writes, for callers that want one value per loop.

use super::{HysteresisLoop, LoopPoint};
use crate::kernel::ArcEnergy;

/// Whether a loop is the major loop (the whole period) or a minor loop.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LoopKind {
    Major,
    Minor,
}

/// One loop of the hysteresis curve, with the energy over its arc.
#[derive(Debug, Clone, PartialEq)]
pub struct Loop {
    pub kind: LoopKind,
    /// Where the arc starts (`rho_A`, in `[0, P)`).
    pub start: LoopPoint,
    /// The reversal the loop turns at (`rho_B`).
    pub reversal: LoopPoint,
    /// Where the input first returns to `u_A` (`rho_C`; may exceed `P` when the arc wraps).
    pub end: LoopPoint,
    /// Work, stored-energy change, dissipation and closure gap over the arc.
    pub energy: ArcEnergy,
    /// Index of the smallest loop whose arc contains this one (`None` for the major loop).
    pub parent: Option<usize>,
    /// 0 for the major loop, parent's depth + 1 otherwise.
    pub depth: usize,
}

/// All loops of `hl`: `[0]` is the major loop, then the minor loops ordered by where their
/// arcs start (so a parent comes before its children). The same loops as
/// [`HysteresisLoop::loop_table`], as records.
pub(super) fn minor_loops(hl: &HysteresisLoop) -> Vec<Loop> {
    let table = hl.loop_table();
    let (u, rho, y) = (hl.turning_points(), hl.turning_rho(), hl.turning_y());
    let major = table.major();
    let (order, place) = table.rows_by_start();
    let turning = |k: usize, rho: f64| LoopPoint {
        rho,
        u: u[k],
        y: y[k],
    };
    order
        .iter()
        .map(|&row| {
            let (a, b) = (table.start()[row], table.reversal()[row]);
            Loop {
                kind: if row == major {
                    LoopKind::Major
                } else {
                    LoopKind::Minor
                },
                start: turning(a, rho[a]),
                reversal: turning(b, table.reversal_rho()[row]),
                end: LoopPoint {
                    rho: table.end_rho()[row],
                    u: table.end_u()[row],
                    y: table.end_y()[row],
                },
                energy: ArcEnergy {
                    work: table.work()[row],
                    stored_energy_change: table.stored_energy_change()[row],
                    dissipation: table.dissipation()[row],
                    closure_gap: table.closure_gap()[row],
                },
                parent: table.parent(row).map(|p| place[p]),
                depth: table.depth()[row],
            }
        })
        .collect()
}
