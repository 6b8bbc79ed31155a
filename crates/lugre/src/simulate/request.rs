//! [`Request`]: what to simulate and where to sample it, with the one set of defaults that the
//! command line (`lugre simulate`) and the Python package (`model.simulate`) both fill in.

use super::inputs::{PiecewiseLinear, Sine};
use super::smooth::SmoothSamples;
use super::{merge_times, uniform_times, Gamma, SimulateError, Simulator, Tolerance, Trajectory};
use crate::model::{LuGre, VelocityFn};

/// Sample times and input values `(t, u)`.
pub type Samples = (Vec<f64>, Vec<f64>);

/// The input of a simulation.
#[derive(Debug, Clone, PartialEq)]
pub enum Drive {
    /// A periodic input given by its turning points, run at unit speed (solved exactly).
    TurningPoints(PiecewiseLinear),
    /// Samples `(t, u)`, linear between samples (solved exactly).
    Samples(PiecewiseLinear),
    /// A sine (the adaptive integrator).
    Sine(Sine),
    /// Samples of a smooth motion, read as their C1 cubic interpolant (run once, exactly on
    /// its subdivision; [`super::smooth`]).
    Smooth(SmoothSamples),
}

impl Drive {
    /// The samples `(t, u)` a model of the zoo is simulated at (`ZooModel::simulate`): turning
    /// points at [`Request::DEFAULT_SAMPLES_PER_PERIOD`] evenly spaced times of the period and
    /// at every turning point, as LuGre's default output, or `per_period` where given; a
    /// record at its own samples, or at `per_period` evenly spaced times and its samples. The
    /// motion is the input's lines either way. `None` for a sine or a smooth reading (the zoo
    /// takes piecewise-linear inputs).
    ///
    /// # Errors
    /// [`SimulateError::TooManyRows`] beyond [`Request::MAX_ROWS`] samples, before allocating.
    pub fn zoo_samples(&self, per_period: Option<usize>) -> Result<Option<Samples>, SimulateError> {
        let pl = match self {
            Drive::TurningPoints(pl) | Drive::Samples(pl) => pl,
            Drive::Sine(_) | Drive::Smooth(_) => return Ok(None),
        };
        let per_period = match self {
            Drive::TurningPoints(_) => {
                Some(per_period.unwrap_or(Request::DEFAULT_SAMPLES_PER_PERIOD))
            }
            _ => per_period,
        };
        let Some(n) = per_period else {
            return Ok(Some((pl.times().to_vec(), pl.values().to_vec())));
        };
        match n.checked_add(pl.len()) {
            Some(rows) if rows <= Request::MAX_ROWS => Ok(Some(pl.resampled(n))),
            rows => Err(SimulateError::TooManyRows {
                rows: rows.map_or(u64::MAX, |r| r as u64),
                limit: Request::MAX_ROWS,
            }),
        }
    }

    /// The start and the period of the input.
    pub fn span(&self) -> (f64, f64) {
        match self {
            Drive::TurningPoints(pl) | Drive::Samples(pl) => (pl.times()[0], pl.period()),
            Drive::Sine(s) => (0.0, s.period()),
            Drive::Smooth(s) => (s.refined().times()[0], s.refined().period()),
        }
    }
}

/// Where the response is sampled.
#[derive(Debug, Clone, PartialEq)]
pub enum Output {
    /// The default for the input: samples at their knots; turning points at
    /// [`Request::DEFAULT_SAMPLES_PER_PERIOD`] evenly spaced times per period and at every
    /// turning point (so the corners and the `sigma1` jumps there show); a sine at
    /// [`Request::DEFAULT_SAMPLES_PER_PERIOD`] evenly spaced times per period.
    Default,
    /// At the input's knots (piecewise-linear inputs only).
    Knots,
    /// At these times.
    Times(Vec<f64>),
    /// At `n` evenly spaced times per period, both ends included.
    PerPeriod(usize),
}

/// A simulation of eq. 5: the input, `gamma`, the number of periods, `x0`, the adaptive
/// integrator's tolerance and the output times, each with its default (`gamma = 1`, one
/// period, `x0 = 0`, [`Tolerance::DEFAULT`], [`Output::Default`]).
///
/// ```
/// use lugre::simulate::{Drive, Request};
/// use lugre::{LuGre, PiecewiseLinear, TurningPoints};
///
/// let tp = TurningPoints::new(&[0.0, 1.0, 0.2, 1.5]).unwrap();
/// let input = Drive::TurningPoints(PiecewiseLinear::from_turning_points(&tp, 1.0).unwrap());
/// let r = Request::new(input).with_periods(3).unwrap();
/// let y = r.run(&LuGre::paper(), None).unwrap();
/// assert_eq!(y.len(), 3 * 200 + 1 + 3 * 3); // 200 per period, plus the corners
/// assert!(y.len() <= r.rows().unwrap());
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Request {
    drive: Drive,
    gamma: Gamma,
    periods: u32,
    x0: f64,
    tol: Tolerance,
    output: Output,
}

impl Request {
    /// The speed of turning points by default: 1, so that time is the normalized variable
    /// `rho` (the paper's Examples 2-4). A physical model wants its own (`--speed`).
    pub const DEFAULT_SPEED: f64 = 1.0;
    /// Output samples per period by default (turning points and sines).
    pub const DEFAULT_SAMPLES_PER_PERIOD: usize = 200;
    /// The most pieces of a piecewise-linear input a run walks (periods times pieces per
    /// period): about ten seconds of the exact solution on one core.
    pub const MAX_PIECES: u64 = 1_000_000_000;
    /// The most output rows a run may produce (five columns of 8 bytes: 2 GB).
    pub const MAX_ROWS: usize = 50_000_000;
    /// The most periods of a sine a run integrates (the adaptive integrator takes tens of
    /// steps a period).
    pub const MAX_SINE_PERIODS: u64 = 1_000_000;

    /// The defaults for `drive`.
    pub fn new(drive: Drive) -> Self {
        Self {
            drive,
            gamma: Gamma::ONE,
            periods: 1,
            x0: 0.0,
            tol: Tolerance::DEFAULT,
            output: Output::Default,
        }
    }

    pub fn with_gamma(mut self, gamma: Gamma) -> Self {
        self.gamma = gamma;
        self
    }

    /// At least 1.
    pub fn with_periods(mut self, periods: u32) -> Result<Self, SimulateError> {
        if periods < 1 {
            return Err(SimulateError::BadPeriods { value: periods });
        }
        self.periods = periods;
        Ok(self)
    }

    /// The initial bristle deflection (checked against the model by [`Self::run`]).
    pub fn with_x0(mut self, x0: f64) -> Self {
        self.x0 = x0;
        self
    }

    pub fn with_tolerance(mut self, tol: Tolerance) -> Self {
        self.tol = tol;
        self
    }

    /// Where to sample; [`Output::Knots`] needs a piecewise-linear input and
    /// [`Output::PerPeriod`] at least one sample per period.
    pub fn with_output(mut self, output: Output) -> Result<Self, SimulateError> {
        match (&output, &self.drive) {
            (Output::Knots, Drive::Sine(_)) => return Err(SimulateError::NoKnots),
            (Output::PerPeriod(0), _) => return Err(SimulateError::BadSamplesPerPeriod),
            _ => {}
        }
        self.output = output;
        Ok(self)
    }

    pub fn drive(&self) -> &Drive {
        &self.drive
    }
    pub fn gamma(&self) -> Gamma {
        self.gamma
    }
    pub fn periods(&self) -> u32 {
        self.periods
    }
    pub fn x0(&self) -> f64 {
        self.x0
    }
    pub fn tolerance(&self) -> Tolerance {
        self.tol
    }
    pub fn output(&self) -> &Output {
        &self.output
    }

    /// The number of output samples, found before anything is allocated so that front ends
    /// can check it against what they can hold; `None` if it does not fit in a `usize`. For
    /// the default grid of turning points it is a bound (`periods (200 + turning points)`;
    /// times where the grid meets a turning point are one sample).
    pub fn rows(&self) -> Option<usize> {
        let k = self.periods as usize;
        match (&self.output, &self.drive) {
            (Output::Times(t), _) => Some(t.len()),
            (Output::PerPeriod(n), _) => k.checked_mul(*n)?.checked_add(1),
            (Output::Knots | Output::Default, Drive::Samples(pl))
            | (Output::Knots, Drive::TurningPoints(pl)) => {
                (pl.len() - 1).checked_mul(k)?.checked_add(1)
            }
            (Output::Default, Drive::TurningPoints(pl)) => {
                k.checked_mul(Self::DEFAULT_SAMPLES_PER_PERIOD + pl.len())
            }
            (Output::Default, Drive::Sine(_)) => k
                .checked_mul(Self::DEFAULT_SAMPLES_PER_PERIOD)?
                .checked_add(1),
            (Output::Knots | Output::Default, Drive::Smooth(s)) => Some(s.samples().0.len()),
            (Output::Knots, Drive::Sine(_)) => None,
        }
    }

    /// The output times, `None` for the input's knots.
    pub fn times(&self) -> Option<Vec<f64>> {
        let (start, period) = self.drive.span();
        match (&self.output, &self.drive) {
            (Output::Times(t), _) => Some(t.clone()),
            (Output::PerPeriod(n), _) => Some(uniform_times(start, period, self.periods, *n)),
            (Output::Knots, _) | (Output::Default, Drive::Samples(_) | Drive::Smooth(_)) => None,
            (Output::Default, _) => self.default_times(),
        }
    }

    fn default_times(&self) -> Option<Vec<f64>> {
        let (start, period) = self.drive.span();
        let n = Self::DEFAULT_SAMPLES_PER_PERIOD;
        let uniform = uniform_times(start, period, self.periods, n);
        match &self.drive {
            Drive::TurningPoints(pl) => Some(merge_times(&uniform, &pl.knot_times(self.periods))),
            Drive::Sine(_) => Some(uniform),
            Drive::Samples(_) | Drive::Smooth(_) => None,
        }
    }

    /// Checks that the run is work a machine can do: at most [`Self::MAX_ROWS`] output rows
    /// (before anything is allocated); a piecewise-linear input walks at most
    /// [`Self::MAX_PIECES`] pieces (periods times pieces per period), a sine runs at most
    /// [`Self::MAX_SINE_PERIODS`] periods. [`Self::run_on`] checks it first.
    ///
    /// # Errors
    /// [`SimulateError::TooManyRows`], [`SimulateError::TooMuchWork`] and
    /// [`SimulateError::TooManyPeriods`] naming the count and the limit.
    pub fn check_work(&self) -> Result<(), SimulateError> {
        match self.rows() {
            Some(rows) if rows <= Self::MAX_ROWS => {}
            rows => {
                return Err(SimulateError::TooManyRows {
                    rows: rows.map_or(u64::MAX, |r| r as u64),
                    limit: Self::MAX_ROWS,
                })
            }
        }
        let periods = u64::from(self.periods);
        let (pieces, limit) = match &self.drive {
            Drive::TurningPoints(pl) | Drive::Samples(pl) => {
                (pl.len().saturating_sub(1) as u64, Self::MAX_PIECES)
            }
            Drive::Smooth(s) => (s.refined().len().saturating_sub(1) as u64, Self::MAX_PIECES),
            Drive::Sine(_) if periods > Self::MAX_SINE_PERIODS => {
                return Err(SimulateError::TooManyPeriods {
                    periods: self.periods,
                    limit: Self::MAX_SINE_PERIODS,
                })
            }
            Drive::Sine(_) => return Ok(()),
        };
        if periods.saturating_mul(pieces) > limit {
            return Err(SimulateError::TooMuchWork {
                periods: self.periods,
                per_period: pieces,
                limit,
            });
        }
        Ok(())
    }

    /// The simulator it runs on (`x0` checked against the model).
    pub fn simulator<'m, G: VelocityFn, F: VelocityFn>(
        &self,
        model: &'m LuGre<G, F>,
    ) -> Result<Simulator<'m, G, F>, SimulateError> {
        Simulator::new(model, self.gamma, self.x0)
    }

    /// Runs it for `model`, reporting the fraction done to `progress` now and then if given.
    pub fn run<G: VelocityFn, F: VelocityFn>(
        &self,
        model: &LuGre<G, F>,
        progress: Option<&mut dyn FnMut(f64)>,
    ) -> Result<Trajectory, SimulateError> {
        self.run_on(&self.simulator(model)?, progress)
    }

    /// Runs it on `sim` (from [`Self::simulator`]).
    pub fn run_on<G: VelocityFn, F: VelocityFn>(
        &self,
        sim: &Simulator<'_, G, F>,
        progress: Option<&mut dyn FnMut(f64)>,
    ) -> Result<Trajectory, SimulateError> {
        self.check_work()?;
        let mut none = |_: f64| {};
        let progress = progress.unwrap_or(&mut none);
        let mut out = Trajectory::default();
        let times = self.times();
        if let Drive::Smooth(s) = &self.drive {
            if self.periods != 1 {
                return Err(SimulateError::SmoothPeriods {
                    periods: self.periods,
                });
            }
            if times.is_none() {
                sim.at_samples(s, &mut out)?;
                return Ok(out);
            }
        }
        let mut sim = sim.with_progress(progress);
        match (&self.drive, &times) {
            (Drive::Smooth(s), t) => sim.at_times(
                s.refined(),
                self.periods,
                t.as_deref().unwrap_or_default(),
                &mut out,
            )?,
            (Drive::TurningPoints(pl) | Drive::Samples(pl), None) => {
                sim.at_knots(pl, self.periods, &mut out)?
            }
            (Drive::TurningPoints(pl) | Drive::Samples(pl), Some(t)) => {
                sim.at_times(pl, self.periods, t, &mut out)?
            }
            (Drive::Sine(s), t) => sim.sine(
                s,
                self.periods,
                t.as_deref().unwrap_or_default(),
                self.tol,
                &mut out,
            )?,
        }
        Ok(out)
    }
}
