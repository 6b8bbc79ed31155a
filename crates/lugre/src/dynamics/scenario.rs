//! The experiments of Canudas de Wit, Olsson, Åström, Lischinsky (IEEE TAC 40(3), 1995) as
//! systems ready to solve: one definition for the command line, the Python package and the
//! tests.

use super::{Pid, Profile, Steps, System, Velocity};
use crate::error::DynamicsError;
use crate::model::{LuGre, Stribeck, Viscous};

/// One of the 1995 experiments.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Scenario {
    /// Fig. 2: pre-sliding under a force ramped to +-95 % of Fs (1.425 N) with holds, 65 s.
    Presliding,
    /// Fig. 4: break-away under `F = r t` (N/s), until `2 / r` s.
    Breakaway { rate: f64 },
    /// Fig. 6: stick-slip, a spring of 2 N/m pulled at 0.1 m/s, 30 s.
    StickSlip,
    /// Fig. 3: frictional lag under `v = 1e-3 (cos w t + 1.5)` m/s, three periods.
    Lag { w: f64 },
    /// Fig. 8: hunting under PID (`Kp = 3`, `Ki = 4`, `Kv = 6`) towards `xd = 1` m, 100 s.
    Pid,
}

/// A scenario's system and run.
#[derive(Debug, Clone)]
pub struct Setup {
    pub system: System<Stribeck, Viscous>,
    pub t_end: f64,
    /// The force rate of a ramp (its break-away is the headline).
    pub rate: Option<f64>,
    /// The pull speed of a spring (its upward crossings are the slip onsets).
    pub pull: Option<f64>,
    /// What it is, in one line.
    pub description: &'static str,
}

impl Scenario {
    /// The names the command line and Python take.
    pub const NAMES: [&'static str; 5] = ["presliding", "breakaway", "stick-slip", "lag", "pid"];

    /// The scenario called `name` (`rate` for the break-away, default 10 N/s; `w` for the lag,
    /// default 10 rad/s).
    pub fn from_name(name: &str, rate: Option<f64>, w: Option<f64>) -> Option<Self> {
        Some(match name {
            "presliding" => Scenario::Presliding,
            "breakaway" => Scenario::Breakaway {
                rate: rate.unwrap_or(10.0),
            },
            "stick-slip" => Scenario::StickSlip,
            "lag" => Scenario::Lag {
                w: w.unwrap_or(10.0),
            },
            "pid" => Scenario::Pid,
            _ => return None,
        })
    }

    /// The system for `model` and `mass` (the paper: Table I, 1 kg).
    pub fn setup(self, model: LuGre, mass: f64) -> Result<Setup, DynamicsError> {
        let system = System::new(model, mass)?;
        Ok(match self {
            Scenario::Presliding => {
                let t = vec![0.0, 10.0, 15.0, 35.0, 40.0, 60.0, 65.0];
                let f = vec![0.0, 1.425, 1.425, -1.425, -1.425, 1.425, 1.425];
                Setup {
                    system: system.with_force(Profile::new("the force profile", t, f)?),
                    t_end: 65.0,
                    rate: None,
                    pull: None,
                    description: "pre-sliding (Fig. 2): force to +-1.425 N with holds",
                }
            }
            Scenario::Breakaway { rate } => {
                if !(rate.is_finite() && rate > 0.0) {
                    return Err(DynamicsError::NotPositive {
                        name: "the force rate",
                        value: rate,
                    });
                }
                Setup {
                    system: system.with_force(Profile::ramp(0.0, rate)?),
                    t_end: 2.0 / rate,
                    rate: Some(rate),
                    pull: None,
                    description: "break-away (Fig. 4): force ramp F = r t",
                }
            }
            Scenario::StickSlip => Setup {
                system: system
                    .with_spring(2.0, Profile::ramp(0.0, 0.1)?)?
                    .with_velocity_watch(0.1)?,
                t_end: 30.0,
                rate: None,
                pull: Some(0.1),
                description: "stick-slip (Fig. 6): spring k = 2 N/m pulled at 0.1 m/s",
            },
            Scenario::Lag { w } => {
                if !(w.is_finite() && w > 0.0) {
                    return Err(DynamicsError::NotPositive {
                        name: "w",
                        value: w,
                    });
                }
                Setup {
                    system: system.with_velocity(Velocity::Harmonic {
                        mean: 1.5e-3,
                        amplitude: 1e-3,
                        w,
                    })?,
                    t_end: 3.0 * std::f64::consts::TAU / w,
                    rate: None,
                    pull: None,
                    description: "frictional lag (Fig. 3): v = 1e-3 (cos w t + 1.5) m/s",
                }
            }
            Scenario::Pid => Setup {
                system: system.with_pid(Pid {
                    kp: 3.0,
                    ki: 4.0,
                    kv: 6.0,
                    setpoint: Steps::constant(1.0)?,
                })?,
                t_end: 100.0,
                rate: None,
                pull: None,
                description: "PID hunting (Fig. 8): Kp = 3, Ki = 4, Kv = 6, xd = 1 m",
            },
        })
    }
}
