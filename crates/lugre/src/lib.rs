//! # lugre
//!
//! The hysteresis loop and every minor loop of the LuGre and Dahl friction models for any
//! periodic input, exact and stable at any stiffness, after Ikhouane, Mañosa and Pujol,
//! "Minor loops of the Dahl and LuGre models".
//!
//! ```
//! use lugre::{Bimodal, HysteresisLoop, LuGre};
//!
//! // The paper's Example 4: sigma0 = 6, turning points 0, 1, 0.5, 1.5.
//! let model = LuGre::paper().with_sigma0(6.0).unwrap();
//! let input = Bimodal::new(0.0, 0.5, 1.0, 1.5).unwrap();
//! let hl = HysteresisLoop::new(model.rate_independent(), &input.turning_points()).unwrap();
//! let loops = hl.loops();
//! assert_eq!(loops.len(), 2); // the major loop and one minor loop
//! assert_eq!([loops[1].start.rho, loops[1].end.rho], [1.0, 2.0]); // [rho_1, rho_5]
//! assert!(loops.iter().all(|l| l.dissipation >= 0.0));
//! ```
//!
//! The core is pure computation: no file or terminal I/O.

pub mod cycles;
pub mod error;
pub mod fit;
#[cfg(feature = "bench-internals")]
#[doc(hidden)]
pub mod floor;
pub mod input;
mod kernel;
pub mod loops;
mod memory;
pub mod model;
pub mod simulate;

pub use cycles::{
    count_cycles, count_cycles_with_energy, Closure, Cycle, CycleColumns, CycleCounter,
    CycleEnergy, CycleSink, CycleSummary, EnergyCycleCounter, Histogram, History, HistoryEnergy,
    Reversal,
};
pub use error::{
    DataError, Error, FitError, HistoryError, InputError, LoopError, ModelError, SimulateError,
};
pub use fit::{fit_full, fit_slow, Estimate, FitReport, FitSpec};
pub use input::{Bimodal, TurningPoints};
pub use kernel::ArcEnergy;
pub use loops::{HysteresisLoop, Loop, LoopKind, LoopPoint, LoopTable, TheoremA};
pub use model::{Dahl, LuGre, LuGreParams, RateIndependent, Stribeck, VelocityFn, Viscous};
pub use simulate::{
    paper_example_1, Example1, Gamma, PiecewiseLinear, Sample, Simulator, Sine, Tolerance,
    Trajectory,
};
