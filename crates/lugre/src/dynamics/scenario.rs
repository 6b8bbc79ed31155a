//! The experiments of Canudas de Wit, Olsson, Åström, Lischinsky (IEEE TAC 40(3), 1995) as
//! systems ready to solve: one definition for the command line, the Python package and the
//! tests.

use super::{Plan, Profile, Request, Steps, Velocity};
use crate::error::DynamicsError;
use crate::model::{LuGre, LuGreParams};

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

/// A scenario's system and run: the plan of a request that names only the scenario, a model
/// and a mass.
pub type Setup = Plan;

impl Scenario {
    /// The names the command line and Python take.
    pub const NAMES: [&'static str; 5] = ["presliding", "breakaway", "stick-slip", "lag", "pid"];

    /// Other spellings accepted for a name: `(alias, name)`.
    pub const ALIASES: [(&'static str, &'static str); 1] = [("pre-sliding", "presliding")];

    /// The scenario called `name` (or one of its [`Self::ALIASES`]) with its default rate or
    /// `w`.
    ///
    /// # Errors
    /// [`DynamicsError::UnknownScenario`] naming it and the scenarios there are.
    pub fn named(name: &str) -> Result<Self, DynamicsError> {
        Self::from_name(name, None, None).ok_or_else(|| DynamicsError::UnknownScenario {
            name: name.to_string(),
            known: &Self::NAMES,
        })
    }

    /// The scenario called `name` (`rate` for the break-away, default 10 N/s; `w` for the lag,
    /// default 10 rad/s).
    pub fn from_name(name: &str, rate: Option<f64>, w: Option<f64>) -> Option<Self> {
        let name = Self::ALIASES
            .iter()
            .find(|(alias, _)| *alias == name)
            .map_or(name, |(_, to)| *to);
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

    /// What it is, in one line.
    pub fn description(self) -> &'static str {
        match self {
            Scenario::Presliding => "pre-sliding (Fig. 2): force to +-1.425 N with holds",
            Scenario::Breakaway { .. } => "break-away (Fig. 4): force ramp F = r t",
            Scenario::StickSlip => "stick-slip (Fig. 6): spring k = 2 N/m pulled at 0.1 m/s",
            Scenario::Lag { .. } => "frictional lag (Fig. 3): v = 1e-3 (cos w t + 1.5) m/s",
            Scenario::Pid => "PID hunting (Fig. 8): Kp = 3, Ki = 4, Kv = 6, xd = 1 m",
        }
    }

    /// The scenario as a request's preset: Table I, its drive and its end (the one definition
    /// of the experiments; [`Request::with_scenario`]).
    pub(super) fn preset(self) -> Result<Request, DynamicsError> {
        let table1 = LuGre::from_params(LuGreParams::canudas_de_wit_1995())?;
        let r = Request::new().preset_model(table1);
        Ok(match self {
            Scenario::Presliding => {
                let t = vec![0.0, 10.0, 15.0, 35.0, 40.0, 60.0, 65.0];
                let f = vec![0.0, 1.425, 1.425, -1.425, -1.425, 1.425, 1.425];
                r.preset_force(Profile::new("the force profile", t, f)?)
                    .preset_run(65.0, true)
            }
            Scenario::Breakaway { rate } => {
                if !(rate.is_finite() && rate > 0.0) {
                    return Err(DynamicsError::NotPositive {
                        name: "the force rate",
                        value: rate,
                    });
                }
                r.preset_ramp(rate).preset_run(2.0 / rate, false)
            }
            Scenario::StickSlip => r.preset_spring(2.0, 0.1).preset_run(30.0, false),
            Scenario::Lag { w } => {
                if !(w.is_finite() && w > 0.0) {
                    return Err(DynamicsError::NotPositive {
                        name: "w",
                        value: w,
                    });
                }
                r.preset_velocity(Velocity::Harmonic {
                    mean: 1.5e-3,
                    amplitude: 1e-3,
                    w,
                })
                .preset_run(3.0 * std::f64::consts::TAU / w, false)
            }
            Scenario::Pid => r
                .preset_pid([3.0, 4.0, 6.0], Steps::constant(1.0)?)
                .preset_run(100.0, false),
        })
    }

    /// The system for `model` and `mass` (the paper: Table I, 1 kg).
    ///
    /// # Errors
    /// A mass that is not a finite number > 0, a rate or `w` that is not.
    pub fn setup(self, model: LuGre, mass: f64) -> Result<Setup, DynamicsError> {
        Request::new()
            .with_scenario(self)
            .with_model(model)
            .with_mass(mass)?
            .build()
    }
}
