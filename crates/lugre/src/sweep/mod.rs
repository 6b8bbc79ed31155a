//! Amplitude and frequency sweeps: the **periodic steady state** of the LuGre model under a
//! periodic input, found directly as the fixed point of the period map, with the energy
//! dissipated per cycle, the peak force, the equivalent stiffness and viscous damping and the
//! describing function (`docs/mathematics.md`, "Periodic steady state and sweeps").
//!
//! **The period map is affine.** For a given input `u(t)` the state equation (eq. 1)
//!
//! ```text
//! z' = -r(t) z + u'(t)          r(t) = sigma0 |u'(t)| / g(u'(t)) >= 0           (P1)
//! ```
//!
//! is linear in `z`, so the state after one period `T` is an affine function of the state at
//! its start:
//!
//! ```text
//! z(T) = Phi z(0) + c           Phi = exp(-R),  R = integral_0^T r dt            (P2)
//! ```
//!
//! with `c` the state reached from `z(0) = 0`. Over a period the input moves by its total
//! variation `V` (`4 A` for a sine of amplitude `A`) and `g <= g_max`, so
//! `R >= sigma0 V / g_max > 0` and `Phi <= exp(-sigma0 V / g_max) < 1`: the map is a
//! contraction, and its one fixed point, the periodic orbit, is
//!
//! ```text
//! z* = c / (1 - Phi)            1 - Phi = -expm1(-R)                             (P3)
//! ```
//!
//! found from **one period of integration** (the response from 0 and `R`), never by
//! simulating the transient away (which takes `~ 1 / R` periods; `R` is small for small
//! amplitudes). `1 - Phi` is computed as `-expm1(-R)`: no exponential of a positive number and
//! no cancellation when `R` is small.
//!
//! **Half a period suffices for a symmetric model** (`g` even, `f` odd, as the Stribeck and
//! viscous functions are: [`crate::LuGre::is_symmetric`]) under a sine: then `-z(t)` answers
//! `-u`, the orbit satisfies `z*(t + T/2) = -z*(t)`, and the half-period map
//! `z(T/2) = Phi_h z(0) + c_h` gives
//!
//! ```text
//! z*(0) = -c_h / (1 + Phi_h)                                                     (P4)
//! ```
//!
//! whose denominator lies in `[1, 2]`: well conditioned however small `R` is.
//!
//! **Sines** (`u = offset + A sin(2 pi f t)`) are integrated by the adaptive Radau IIA method
//! of [`crate::simulate`] (L-stable, so stable at any `sigma0`), from the reversal at
//! `t = T/4`; each step's stage values are affine in its start (`Z = z G + K`, the stage system
//! is linear), so the orbit is **replayed** from `z*` without evaluating `g` again, and the
//! energies and harmonics are Radau quadratures on the stages (order 5, like the state):
//!
//! ```text
//! work         W = integral_0^T F u' dt                                        (P5)
//! dissipation  D = integral_0^T [sigma0 r z^2 + sigma1 z' u' + f(u') u'] dt = W - Delta V
//! stored       V = sigma0 z^2 / 2,  Delta V = V(T) - V(0) = 0 on the orbit
//! harmonic     a1 = (2/T) integral F cos(w t) dt,  b1 = (2/T) integral F sin(w t) dt
//! ```
//!
//! `D` is integrated from its own rate (`F u' - V'`), each of whose terms is small where the
//! dissipation is: no cancellation of the elastic work `sigma0 z u'` at small amplitudes; the
//! step control holds this quadrature to the tolerance as well as `z` (in a stiff sliding
//! stretch `z` barely moves while `|u'|` does). `W` is then `D + Delta V` exactly (the elastic
//! part `sigma0 z z'` integrates in closed form). The first harmonic `F1 = b1 sin(w t) + a1 cos(w t) = k_eq u1 + c_eq u1'` (with
//! `u1 = A sin(w t)`) gives the equivalent stiffness `k_eq = b1 / A` and viscous damping
//! `c_eq = a1 / (A w)`, and the describing function `N = (b1 + i a1) / A`: gain `|N|`, phase
//! `atan2(a1, b1)` (radians; > 0: the force leads). Since `u' = A w cos(w t)`,
//!
//! ```text
//! W = integral F u' dt = A w (T/2) a1 = pi A a1                                    (P6)
//! ```
//!
//! for any period, and on the orbit `D = W`: the first harmonic carries all the energy, and
//! `a1` is computed as `W / (pi A)`.
//!
//! As the frequency goes to 0 the orbit tends to the rate-independent hysteresis loop `y°` of
//! [`crate::HysteresisLoop`] (eq. 10) and `D` to its dissipation.
//!
//! **Piecewise-linear periodic inputs** ([`periodic_orbit`]) use the exact solver of
//! [`crate::simulate`]: `c` from one period from 0 and `R = sum sigma0 |du_i| / g(v_i)`.
//!
//! ```
//! use lugre::sweep::Request;
//! use lugre::{LuGre, LuGreParams};
//!
//! let model = LuGre::from_params(LuGreParams::canudas_de_wit_1995()).unwrap();
//! let request = Request::new(vec![1e-6, 1e-5], vec![0.1, 1.0]).unwrap();
//! let sweep = request.run(&model, None).unwrap();
//! assert_eq!(sweep.points.len(), 4);
//! for p in &sweep.points {
//!     assert!(p.dissipation > 0.0 && p.phase > 0.0 && p.phase < 1.6);
//!     // Small amplitudes: the bristles' stiffness sigma0 = 1e5 N/m.
//!     assert!((p.stiffness / 1e5 - 1.0).abs() < 0.2);
//! }
//! ```

mod grid;
mod harmonics;
mod orbit;
mod periodic;

pub use grid::{parse_values, Request, Sweep};
pub use harmonics::Point;
pub use orbit::LoopSamples;
pub use periodic::{periodic_orbit, PeriodicOrbit};

pub use crate::error::SweepError;

/// The names of a point's numbers, in the order of [`Point::values`]: the CSV header, the JSON
/// keys and the Python columns.
pub const COLUMNS: [&str; 12] = [
    "amplitude",
    "frequency",
    "dissipation",
    "work",
    "stored_energy_change",
    "peak_force",
    "stiffness",
    "damping",
    "gain",
    "phase",
    "a1",
    "b1",
];

#[cfg(test)]
mod tests;
