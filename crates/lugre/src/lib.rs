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
//! assert!(loops.iter().all(|l| l.energy.dissipation >= 0.0));
//! ```
//!
//! The core is pure computation: no file or terminal I/O. The mathematics behind every module
//! is in `docs/mathematics.md` (equation numbers are the paper's).
//!
//! # Map of the crate
//!
//! | where | what | API shape |
//! |---|---|---|
//! | [`model`] | LuGre and Dahl (eq. 1), `g` and `f`, the rate-independent pair `(sigma0, g(0))` | validated `new()`, `with_*` builders that validate |
//! | [`input`] | turning points, the bimodal input of Definition 1, the shared data checks | validated `new()` |
//! | `kernel` (private) | the stable closed form on one piece (eq. 8), `phi`/`h`/`q`, double-double sums, energies of an arc ([`ArcEnergy`]) | functions of numbers; a leaf that imports nothing of the crate |
//! | [`loops`] | the periodic input (§3-4): [`HysteresisLoop`] — `y°` by **the recursion** with exponents `<= 0` and the periodic value `y°(0)` (eq. 10); **the pairing** of every loop (rainflow with the tie rule, one pass, `loops/engine.rs`); **the energies** of each loop; [`LoopTable`] (columns) and [`Loop`] (records); **Theorem A** ([`TheoremA`]) | `new()` computes everything once; accessors borrow |
//! | [`cycles`] | measured histories: streaming rainflow (ASTM E1049), closures, energies along `y*` | push-based counters into a [`CycleSink`]; one-call [`count_cycles`] |
//! | [`simulate`] | **simulation** at finite rates (eq. 5): exact for piecewise-linear inputs, adaptive Radau IIA for sines, the paper's Example 1 | a [`Simulator`] run into a [`Trajectory`] |
//! | [`sweep`] | **periodic steady states** under sines (and periodic piecewise-linear inputs): the fixed point of the affine period map, energy per cycle, peak force, equivalent stiffness and damping, describing function; grids of amplitudes and frequencies on all cores | a [`sweep::Request`] (the front ends' one set of defaults and checks) run into a [`sweep::Sweep`] of [`sweep::Point`]s |
//! | [`dynamics`] | a mass driven by forces, a spring and a PID controller with LuGre friction (Canudas de Wit et al. 1995): a dedicated Radau IIA with located sign changes of the velocity | a [`dynamics::Request`] (every front end's one set of defaults and checks; the 1995 experiments as presets) built into a validated [`dynamics::System`] and solved into a [`dynamics::Motion`] |
//! | [`fit`] | **fitting**: identification from the slow loop or the full record, with standard errors and identifiability checks | [`fit_slow`]/[`fit_full`] from a [`FitSpec`] |
//! | [`zoo`] | rate-independent models with Masing behaviour: Maxwell-slip, Prandtl-Ishlinskii (play operators); the exact segment map, the response to turning points, every loop with its energies ([`zoo::ZooLoop`]) | validated `new()`; `loops()` computes everything once |
//! | [`error`] | every error enum (a leaf); messages name the offending value | `thiserror`, `#[non_exhaustive]` |
//!
//! Dependencies run one way: `kernel` and `error` import nothing of the crate; `model`,
//! `input` build on them; the engines `loops`, `cycles`, `simulate`, `dynamics` and `fit` do
//! not import each other, except `fit`, which uses `loops` and `simulate`, `dynamics`, whose
//! friction loops use `cycles`, `loops` and `simulate`, and `sweep`, which integrates with
//! `simulate`'s solvers (checked by `tests/layout.rs`).

pub mod cycles;
pub mod dynamics;
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
pub mod sweep;
pub mod zoo;

pub use cycles::{
    count_cycles, count_cycles_with_energy, Closure, Cycle, CycleColumns, CycleCounter,
    CycleEnergy, CycleSink, CycleSummary, Histogram, History, HistoryEnergy, Reversal,
};
pub use error::{
    DataError, DynamicsError, Error, FitError, HistoryError, InputError, LoopError, ModelError,
    SamplesError, SimulateError, SweepError, ZooError,
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

/// The README's Rust example, compiled and run as a doctest (`cargo test --doc`), so that it
/// cannot drift from the API.
#[cfg(doctest)]
#[doc = include_str!("../../../README.md")]
struct ReadmeDoctests;
