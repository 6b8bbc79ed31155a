//! Parameter identification: the LuGre and Dahl parameters from measured `(u, F)` or
//! `(t, u, F)` data, with standard errors and 95 % confidence intervals.
//!
//! **Slow fit** ([`fit_slow`]). In the rate-independent limit the response to a periodic input
//! is the hysteresis loop `y°` (eqs. 8-10), which depends only on `sigma0` and `g(0)` (`= Fs`
//! for the Stribeck curve; Dahl: `rho` and `Fc`) and on the input's turning points. So one or
//! more periods of a slow periodic test determine those two directly: nonlinear least squares
//! of `y°(rho_i)` against the measured `F_i`, with the turning points taken from the data (its
//! reversal samples: sample the reversals themselves, a missed one biases the loop) and `rho_i`
//! the variation of `u` up to sample `i` (eq. 7). On segment `k` of the normalized input, from
//! turning point `u_k` where `y° = y_k` (from [`crate::HysteresisLoop`]), in direction `s_k`,
//! with `a = sigma0 / g0` and `l_i = |u_i - u_k|`,
//!
//! ```text
//! y°(rho_i) = y_k e_i + s_k g0 (1 - e_i)          e_i = exp(-a l_i)                  (F1)
//! ```
//!
//! and its derivatives are closed forms too (eqs. F2-F4 in `fit/slow.rs`: the loop is
//! proportional to `g0` at fixed `a`, and `dy°/da` obeys a periodic linear recursion): one
//! exponential per sample and evaluation, no allocation per sample. Records of more than
//! 32768 samples are fitted first on about 8192 of them (every k-th sample and every turning
//! point), then on all from there, which then takes two or three iterations.
//!
//! **Full fit** ([`fit_full`]). From rate-dependent `(t, u, F)` data: `sigma0, sigma1, sigma2,
//! Fc, Fs, vs` (and `beta` if freed) on the exact simulation of eq. 1 for `u` linear between
//! samples ([`crate::simulate`]), from the initial state `x0` (given, not fitted), with exact
//! forward sensitivities of the simulation's recursion (eqs. X1-X4 in `fit/full.rs`) and
//! several starts (the first from the data; the best end point wins).
//!
//! **Noise** ([`noise`], eqs. N1-N4). Both fits estimate the position and force noise from
//! the record's third differences and report them ([`FitReport::noise`]); the full fit reads
//! an equally spaced noisy displacement as the smooth motion nearest the samples (a smoothing
//! spline with end conditions from the data, its smoothing chosen by Mallows' `C_L` for the
//! position noise), since the least-squares fit treats the input as exact. [`Noise::Off`]
//! takes the samples as given.
//!
//! Both minimise `sum_i (y_i(p) - F_i)^2` with the `levenberg-marquardt` crate (MINPACK's
//! trust-region method). Bounds `lo < p < hi` (default `0 < p < inf`: every parameter is
//! positive) are built into the variables it moves: `p = lo + exp(theta)` (the
//! log-parametrisation), or a logistic map for a finite upper bound. Start values come from
//! the data (force plateaus, the relaxation after reversals, the steady sliding force against
//! speed, linear least squares for `sigma1` and `sigma2`), so no guess is needed; a value given
//! with [`FitSpec::set`] is used instead. A parameter whose true value is 0 (e.g. `sigma2` in
//! the paper's examples) goes to its bound: it is reported *at its bound* ([`Estimate::at_bound`],
//! a warning in [`FitReport::warnings`]) with an interval that reaches the bound, and the other
//! estimates are given as they are with it held there; the same for a user's bound the data
//! push against (`vs` bounded below its true value). Fix it at 0 to fit without it.
//!
//! **Uncertainty** (eqs. S1-S2 in `fit/stats.rs`): the linearised covariance
//! `s^2 (J^T J)^-1` at the optimum, `s^2 = RSS / (m - p)`, and 95 % intervals
//! `p -+ t_{0.975, m-p} se` with Student's t quantile on `m - p` degrees of freedom
//! (`stats::t_quantile_975`; 1.96 for large samples). They assume independent errors of equal
//! variance on `F` and a correct model, and are symmetric in the parameter itself. On
//! synthetic data with 1 % noise they cover the truth at their nominal rate (the ignored test
//! `intervals_cover_the_truth_at_their_nominal_rate`). Where the residuals are correlated the
//! covariance is the Newey-West sandwich with leverage-scaled residuals (C1-C4 in
//! `fit/covariance.rs`), a smoothed displacement adds its own share (S3), and each interval
//! then uses Student's t on its estimate's effective degrees of freedom ([`Estimate::dof`],
//! S4).
//!
//! **Identifiability.** A parameter the data cannot determine is an error naming it and why
//! ([`FitError::Unidentifiable`], [`Why`]), not a number: it has no effect on the output
//! (`|p J_p| <= 1e-12 |F|`, e.g. `vs` when `Fs = Fc`, or a parameter the fit drove to 0), its
//! effect is nearly a combination of others' (condition number of the scaled `J^T J` above
//! `1e10`), or its 95 % interval reaches 0 (e.g. `sigma1` from quasi-static data). Every such
//! parameter is named at once. Asking a slow fit for anything but the loop's two parameters is
//! refused outright ([`FitError::NotInSlowLoop`]).
//!
//! **Convergence.** The iteration stops when a step changes the parameters by less than `1e-8`
//! relatively, or the sum of squares by less than `1e-10`: far below any standard error. A run
//! that exhausts its evaluations at a finite, identifiable point returns it with
//! [`FitReport::converged`] `= false` (the CLI warns and exits 0); a run that fails
//! numerically is [`FitError::NotConverged`], which carries the best point found.
//!
//! ```
//! use lugre::fit::{fit_slow, FitSpec};
//! use lugre::{Bimodal, HysteresisLoop, LuGre};
//!
//! // Noise-free samples of the paper's Example 4 loop (sigma0 = 6, g(0) = Fs = 2), every
//! // 0.01 of rho: the turning points (rho = 0, 1, 1.5, 2.5) are among them.
//! let model = LuGre::paper().with_sigma0(6.0).unwrap();
//! let input = Bimodal::new(0.0, 0.5, 1.0, 1.5).unwrap();
//! let hl = HysteresisLoop::new(model.rate_independent(), &input.turning_points()).unwrap();
//! let points = hl.sample(401);
//! let u: Vec<f64> = points.iter().map(|p| p.u).collect();
//! let f: Vec<f64> = points.iter().map(|p| p.y).collect();
//!
//! let report = fit_slow(&FitSpec::new(lugre::fit::Family::LuGre), &u, &f).unwrap();
//! let sigma0 = report.estimate("sigma0").unwrap();
//! assert!((sigma0.value - 6.0).abs() < 1e-9);
//! assert!((report.estimate("fs").unwrap().value - 2.0).abs() < 1e-9);
//! assert!(report.rms < 1e-12);
//! ```

mod covariance;
mod full;
mod lm;
pub mod noise;
mod plateaus;
mod presliding;
mod slow;
mod spec;
mod staged;
mod stats;
mod stribeck;
mod zoo;

pub use crate::error::{FitError, Unidentified, Why};
pub use covariance::{Covariance, FitWarning, SerialCorrelation, MISFIT_RATIO, STRUCTURED_RHO};
pub use lm::FitProgress;
pub use noise::{NoiseLevels, PositionHandling};
pub use plateaus::{find_plateaus, Motion, Plateau, Plateaus, MIN_RUN, MIN_STEADY};
pub use presliding::{fit_presliding, BREAKAWAY_FRACTION};
pub use spec::{Bounds, Family, FitKind, FitSpec};
pub use staged::{fit_staged, StagedReport};
pub use stribeck::{fit_stribeck, steady_force, table_points, SteadyPoint};
pub use zoo::{fit_zoo, fit_zoo_full, ZooFitReport, ZooFitSpec, DEFAULT_ELEMENTS, MAX_ELEMENTS};

use crate::input::{check_finite, check_increasing};
use crate::model::LuGreParams;
use crate::simulate::{Gamma, PiecewiseLinear, Simulator, SmoothSamples, Trajectory};
use lm::{minimize, Config, Evaluator, Outcome};
use spec::Resolved;

/// One fitted parameter.
#[derive(Debug, Clone, PartialEq)]
pub struct Estimate {
    pub name: &'static str,
    pub value: f64,
    /// Standard error (S1; C2-C3 where the residuals are correlated; plus S3 for a smoothed
    /// displacement).
    pub stderr: f64,
    /// The degrees of freedom of the standard error (S4): `m - p` for (S1) alone, fewer where a
    /// few samples or a few draws carry its estimate.
    pub dof: f64,
    /// The 95 % confidence interval, `value -+ t_{0.975, dof} stderr` (S2, S4).
    pub ci95: [f64; 2],
    /// The estimate sits on one of its bounds (the interval then means little).
    pub at_bound: bool,
}

/// The result of a fit.
#[derive(Debug, Clone, PartialEq)]
pub struct FitReport {
    pub kind: FitKind,
    pub family: Family,
    /// The fitted parameters, in the family's order.
    pub estimates: Vec<Estimate>,
    /// The parameters held at their given values (slow fit: only those of the loop).
    pub fixed: Vec<(&'static str, f64)>,
    /// Residual RMS `sqrt(RSS / m)`.
    pub rms: f64,
    pub samples: usize,
    /// Degrees of freedom `m - p`.
    pub dof: usize,
    /// The factor of the 95 % intervals, `t_{0.975, m-p}`.
    pub t_quantile: f64,
    /// Condition number of the scaled normal matrix (see the module docs).
    pub condition_number: f64,
    /// Correlation matrix of the estimates.
    pub correlation: Vec<Vec<f64>>,
    /// Trust-region iterations of the winning start.
    pub iterations: usize,
    /// Model evaluations over all starts.
    pub evaluations: usize,
    pub starts: usize,
    pub converged: bool,
    pub termination: String,
    /// Turning points of the whole record (slow fit; two periods of a four-turning-point input
    /// have 8).
    pub turning_points: Option<usize>,
    /// The model's output at every sample: `y°(rho_i)` from [`crate::HysteresisLoop`] (slow fit)
    /// or the exact simulation from [`Simulator`] (full fit).
    pub fitted: Vec<f64>,
    /// The noise levels estimated in the record and how the fit used them (with [`Noise::Off`]
    /// they are estimated and reported, and not used).
    pub noise: Option<NoiseLevels>,
    /// Why the estimates or their intervals may not be trusted (empty: no reason found); each
    /// says it in words (`Display`).
    pub warnings: Vec<FitWarning>,
    /// Which covariance the standard errors come from (C1-C2).
    pub covariance: Covariance,
    /// The residuals' serial correlation (C1).
    pub serial: SerialCorrelation,
}

impl FitReport {
    pub fn estimate(&self, name: &str) -> Option<&Estimate> {
        self.estimates.iter().find(|e| e.name == name)
    }

    /// `F_i - fitted_i` (NaN where no force was measured).
    pub fn residuals(&self, f: &[f64]) -> Vec<f64> {
        f.iter().zip(&self.fitted).map(|(f, y)| f - y).collect()
    }

    /// The value of every parameter of the fit (estimates and fixed), in the family's order.
    pub fn values(&self) -> Vec<(&'static str, f64)> {
        let mut v: Vec<(&'static str, f64)> = self
            .estimates
            .iter()
            .map(|e| (e.name, e.value))
            .chain(self.fixed.iter().copied())
            .collect();
        let order = self.family.parameters();
        v.sort_by_key(|(n, _)| order.iter().position(|o| o == n));
        v
    }
}

/// What every fit reports beyond its parameters' names and values, as one view over a
/// [`FitReport`] or a [`ZooFitReport`], for the front ends to show alike.
#[derive(Debug, Clone, Copy)]
pub struct FitSummary<'a> {
    pub estimates: &'a [Estimate],
    pub rms: f64,
    pub samples: usize,
    pub dof: usize,
    pub t_quantile: f64,
    pub condition_number: f64,
    pub correlation: &'a [Vec<f64>],
    pub iterations: usize,
    pub evaluations: usize,
    pub starts: usize,
    pub converged: bool,
    pub termination: &'a str,
    pub turning_points: Option<usize>,
    pub noise: Option<&'a NoiseLevels>,
    pub warnings: &'a [FitWarning],
    pub covariance: Covariance,
    pub serial: &'a SerialCorrelation,
    pub fitted: &'a [f64],
}

impl FitReport {
    /// The view the front ends show.
    pub fn summary(&self) -> FitSummary<'_> {
        FitSummary {
            estimates: &self.estimates,
            rms: self.rms,
            samples: self.samples,
            dof: self.dof,
            t_quantile: self.t_quantile,
            condition_number: self.condition_number,
            correlation: &self.correlation,
            iterations: self.iterations,
            evaluations: self.evaluations,
            starts: self.starts,
            converged: self.converged,
            termination: &self.termination,
            turning_points: self.turning_points,
            noise: self.noise.as_ref(),
            warnings: &self.warnings,
            covariance: self.covariance,
            serial: &self.serial,
            fitted: &self.fitted,
        }
    }
}

/// Options of the full fit: the defaults, changed with `with_*` (checked when the fit starts).
///
/// ```
/// use lugre::fit::FullOptions;
/// let mut evaluations = 0;
/// let mut count = |_: &lugre::fit::FitProgress| evaluations += 1;
/// let options = FullOptions::default().with_starts(5).with_progress(&mut count);
/// assert_eq!((options.x0(), options.starts()), (0.0, 5));
/// ```
pub struct FullOptions<'p> {
    x0: f64,
    starts: usize,
    noise: Noise,
    progress: Option<&'p mut dyn FnMut(&FitProgress)>,
}

impl Default for FullOptions<'_> {
    fn default() -> Self {
        Self {
            x0: 0.0,
            starts: Self::DEFAULT_STARTS,
            noise: Noise::Auto,
            progress: None,
        }
    }
}

/// Whether a fit estimates the record's noise and takes it into account ([`noise`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Noise {
    /// Estimate the position and force noise (N1); the full fit reads a noisy displacement as
    /// the smooth motion nearest the samples (N2), the slow fit gates its reversals.
    #[default]
    Auto,
    /// Use the samples as given.
    Off,
}

impl Noise {
    /// The names the front ends take.
    pub const NAMES: [&'static str; 2] = ["auto", "off"];

    /// `"auto"` or `"off"` (case-insensitive).
    pub fn from_name(name: &str) -> Option<Self> {
        match name.trim().to_ascii_lowercase().as_str() {
            "auto" => Some(Noise::Auto),
            "off" => Some(Noise::Off),
            _ => None,
        }
    }
}

impl std::fmt::Debug for FullOptions<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("FullOptions")
            .field("x0", &self.x0)
            .field("starts", &self.starts)
            .field("noise", &self.noise)
            .field("progress", &self.progress.is_some())
            .finish()
    }
}

impl<'p> FullOptions<'p> {
    /// Starts tried by default.
    pub const DEFAULT_STARTS: usize = 3;
    /// The most starts a fit tries: past the table of seven scalings each round spreads
    /// `sigma0` and `vs` by another factor of 4, and 64 starts reach factors of 4^10.
    pub const MAX_STARTS: usize = 64;

    /// The initial bristle deflection `x(0)` (Dahl: `w(0) / rho`), not fitted (default 0).
    pub fn with_x0(mut self, x0: f64) -> Self {
        self.x0 = x0;
        self
    }

    /// Starts tried: the first from the data, then `sigma0` and `vs` scaled by 4 or 1/4
    /// (default [`Self::DEFAULT_STARTS`], at least 1).
    pub fn with_starts(mut self, starts: usize) -> Self {
        self.starts = starts;
        self
    }

    /// Whether the record's noise is estimated and taken into account (default
    /// [`Noise::Auto`]).
    pub fn with_noise(mut self, noise: Noise) -> Self {
        self.noise = noise;
        self
    }

    /// Called after every model evaluation with the fit's progress (default: nothing).
    pub fn with_progress(mut self, progress: &'p mut dyn FnMut(&FitProgress)) -> Self {
        self.progress = Some(progress);
        self
    }

    pub fn x0(&self) -> f64 {
        self.x0
    }

    pub fn starts(&self) -> usize {
        self.starts
    }

    pub fn noise(&self) -> Noise {
        self.noise
    }
}

/// The fit needs at least this many samples, and twice as many as free parameters.
pub(crate) const MIN_SAMPLES: usize = 10;

/// A slow fit of more samples than this first iterates on about [`COARSE_SAMPLES`] of them.
const COARSE_ABOVE: usize = 32_768;
const COARSE_SAMPLES: usize = 8_192;

const SLOW_CONFIG: Config = Config {
    xtol: 1e-8,
    ftol: 1e-10,
    gtol: 1e-12,
    patience: 50,
};

/// The full fits' starts: (stiffness factor, `vs` factor) on the data's start, cycled.
const START_FACTORS: [(f64, f64); 7] = [
    (1.0, 1.0),
    (4.0, 0.25),
    (0.25, 4.0),
    (4.0, 4.0),
    (0.25, 0.25),
    (4.0, 1.0),
    (0.25, 1.0),
];

const FULL_CONFIG: Config = Config {
    xtol: 1e-8,
    ftol: 1e-10,
    gtol: 1e-12,
    patience: 40,
};

/// Checks the columns: equal lengths, finite values.
fn check_columns(columns: &[(&'static str, &[f64])]) -> Result<(), FitError> {
    let u = columns[0].1.len();
    for &(what, c) in columns {
        if c.len() != u {
            return Err(FitError::LengthMismatch {
                what,
                got: c.len(),
                u,
            });
        }
        check_finite(what, c)?;
    }
    Ok(())
}

fn check_count(samples: usize, parameters: usize) -> Result<(), FitError> {
    let needed = MIN_SAMPLES.max(2 * parameters);
    if samples < needed {
        return Err(FitError::TooFewSamples {
            samples,
            parameters,
            needed,
        });
    }
    Ok(())
}

/// The slow-loop fit of `sigma0` and `g(0) = Fs` (Dahl: `rho`, `Fc`) to samples `(u_i, F_i)` of
/// one or more periods of a slow periodic test (the record closes from its last sample to its
/// first; trim a start-up transient first). See the module docs.
pub fn fit_slow(spec: &FitSpec, u: &[f64], f: &[f64]) -> Result<FitReport, FitError> {
    fit_slow_with(spec, u, f, SlowOptions::default())
}

/// Options of the slow fit: the defaults, changed with `with_*` (checked when the fit starts).
///
/// ```
/// use lugre::fit::{Noise, SlowOptions};
/// let options = SlowOptions::default().with_gate(1e-7);
/// assert_eq!((options.gate(), options.noise()), (Some(1e-7), Noise::Auto));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SlowOptions {
    gate: Option<f64>,
    noise: Noise,
}

impl SlowOptions {
    /// The default gate in standard deviations of the estimated position noise (N1): white
    /// noise comes back from its running extreme by 8 of them about once in 10^15 samples.
    pub const GATE_NOISE_SIGMAS: f64 = 8.0;

    /// The default gate at most, as a fraction of the record's range: a coarsely sampled
    /// record's jagged differences look like noise to (N1), and a larger gate would remove the
    /// loops the test is made of.
    pub const GATE_RANGE: f64 = 0.05;

    /// The noise gate on the reversals, in the units of `u` (finite, `>= 0`; 0: every turn of
    /// the samples is a reversal). Default: [`Self::GATE_NOISE_SIGMAS`] times the estimated
    /// position noise, at most [`Self::GATE_RANGE`] of the record's range ([`Noise::Auto`]),
    /// or 0 ([`Noise::Off`]).
    pub fn with_gate(mut self, gate: f64) -> Self {
        self.gate = Some(gate);
        self
    }

    /// Whether the record's noise is estimated (and sets the default gate).
    pub fn with_noise(mut self, noise: Noise) -> Self {
        self.noise = noise;
        self
    }

    /// The gate given, if any.
    pub fn gate(&self) -> Option<f64> {
        self.gate
    }

    pub fn noise(&self) -> Noise {
        self.noise
    }
}

/// [`fit_slow`] with options: the noise gate on the reversals and the noise handling.
pub fn fit_slow_with(
    spec: &FitSpec,
    u: &[f64],
    f: &[f64],
    options: SlowOptions,
) -> Result<FitReport, FitError> {
    check_columns(&[("u", u), ("F", f)])?;
    let mut resolved = spec.resolve(FitKind::Slow)?;
    check_count(u.len(), resolved.free.len())?;
    let (gate, levels) = slow_gate(u, f, options)?;
    let sl = slow::SlowLoop::new(resolved.family, resolved.free.clone(), u, None, gate)?;
    let mut coarse_iterations = 0;
    let mut coarse_evaluations = 0;
    if u.len() > COARSE_ABOVE {
        // Iterate on a thinned record first (every k-th sample and every turning point):
        // the full record then only has to confirm the optimum, in two or three steps.
        let idx = sl.thinned(COARSE_SAMPLES);
        let (su, sf): (Vec<f64>, Vec<f64>) = idx.iter().map(|&i| (u[i], f[i])).unzip();
        // The reversals as estimated on the full record (the thinned one has the same).
        let turning = sl.turning_points().values().to_vec();
        let sub = slow::SlowLoop::new(
            resolved.family,
            resolved.free.clone(),
            &su,
            Some(&turning),
            gate,
        )?;
        slow_start(&mut resolved, &sub, &sf)?;
        let (_, coarse) = minimize(
            sub,
            &sf,
            resolved.space(),
            &resolved.free_values(),
            SLOW_CONFIG,
            &mut |_, _| {},
        );
        coarse_iterations = coarse.iterations;
        coarse_evaluations = coarse.evaluations;
        if coarse.rss.is_finite() {
            for (j, &i) in resolved.free.iter().enumerate() {
                resolved.values[i] = resolved.bounds[j].pull_inside(coarse.values[i]);
            }
        }
    } else {
        slow_start(&mut resolved, &sl, f)?;
    }
    let (sl, mut outcome) = minimize(
        sl,
        f,
        resolved.space(),
        &resolved.free_values(),
        SLOW_CONFIG,
        &mut |_, _| {},
    );
    outcome.iterations += coarse_iterations;
    outcome.evaluations += coarse_evaluations;
    // The fitted curve: (F1) with the turning-point values of the core's loop, which equals
    // `HysteresisLoop::y_at` at the samples' rho to a few roundings (unit-tested).
    let fitted = outcome.y.clone();
    let mut report = report(FitKind::Slow, &resolved, outcome, fitted, f, 1, &[])?;
    report.turning_points = Some(sl.turning_points().len());
    report.noise = Some(levels);
    report.check_fit(f);
    Ok(report)
}

/// The noise levels of a slow record and the gate on its reversals ([`SlowOptions`]); the
/// gate given, if any, checked.
fn slow_gate(u: &[f64], f: &[f64], options: SlowOptions) -> Result<(f64, NoiseLevels), FitError> {
    if let Some(g) = options.gate {
        if !(g.is_finite() && g >= 0.0) {
            return Err(FitError::BadGate { value: g });
        }
    }
    let mut levels = noise::levels(u, f, PositionHandling::AsGiven);
    let gate = match (options.gate, options.noise) {
        (Some(g), _) => g,
        (None, Noise::Auto) => {
            let (lo, hi) = u
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                    (a.min(x), b.max(x))
                });
            (SlowOptions::GATE_NOISE_SIGMAS * levels.position)
                .min(SlowOptions::GATE_RANGE * (hi - lo))
        }
        (None, Noise::Off) => 0.0,
    };
    if options.gate.is_some() || options.noise == Noise::Auto {
        levels.handling = PositionHandling::Gate { gate };
    }
    Ok((gate, levels))
}

/// Start values from the data for the free parameters without a given start.
fn slow_start(resolved: &mut Resolved, sl: &slow::SlowLoop, f: &[f64]) -> Result<(), FitError> {
    let (sigma0, g0) = sl.data_start(f)?;
    let mut start = resolved.values.clone();
    match resolved.family {
        Family::LuGre => {
            start[0] = sigma0;
            start[4] = g0;
        }
        Family::Dahl => {
            start[0] = sigma0 / g0;
            start[1] = g0;
        }
    }
    resolved.fill_starts(&start);
    Ok(())
}

/// The chord tolerance of the cubic reading's subdivision in a fit, relative to the record's
/// range (`lugre fit --interpolate cubic`, `lugre.fit(..., interpolate="cubic")`).
pub const CUBIC_READING_TOL: f64 = 1e-9;

/// [`fit_full`] on a smooth reading of sampled data (`motion`: the C1 cubic through
/// displacement samples, or integrated velocity samples, [`SmoothSamples`]): the subdivided
/// motion drives the simulation, its added knots are input-only rows, and the residual is taken
/// at the samples (`f`: one force per sample of `motion`, `NaN` for an input-only sample).
/// `fitted` holds the fit at the samples.
pub fn fit_full_smooth(
    spec: &FitSpec,
    motion: &SmoothSamples,
    f: &[f64],
    options: FullOptions<'_>,
) -> Result<FitReport, FitError> {
    let knots = motion.sample_knots();
    if f.len() != knots.len() {
        return Err(FitError::LengthMismatch {
            what: "F",
            got: f.len(),
            u: knots.len(),
        });
    }
    let (rt, ru) = (motion.refined().times(), motion.refined().values());
    let mut rf = vec![f64::NAN; rt.len()];
    for (&k, &fk) in knots.iter().zip(f) {
        rf[k] = fk;
    }
    // The cubic reading takes the samples as exact: the noise is only reported.
    let mut report = fit_full(spec, rt, ru, &rf, options.with_noise(Noise::Off))?;
    report.fitted = knots.iter().map(|&k| report.fitted[k]).collect();
    let levels = noise::levels(motion.samples().1, f, PositionHandling::AsGiven);
    report.noise = Some(levels);
    report.check_fit(f);
    Ok(report)
}

/// The full fit to rate-dependent samples `(t_i, u_i, F_i)` on the exact simulation from
/// `options.x0()`; the options' progress observer, if any, is called after every model
/// evaluation.
pub fn fit_full(
    spec: &FitSpec,
    t: &[f64],
    u: &[f64],
    f: &[f64],
    options: FullOptions<'_>,
) -> Result<FitReport, FitError> {
    let (x0, starts, noise) = (options.x0, options.starts, options.noise);
    check_full_input(t, u, f, x0, starts)?;
    // The noise, and the displacement the fit runs on (smoothed where it is noisy).
    let (smoothed, levels) = match noise {
        Noise::Auto => noise::prepare_full(t, u, f),
        Noise::Off => (None, noise::levels(u, f, PositionHandling::AsGiven)),
    };
    let (smoothed, smoother) = smoothed.unzip();
    let u = smoothed.as_deref().unwrap_or(u);
    let measured = Measured::new(t, u, f);
    let mut resolved = spec.resolve(FitKind::Full)?;
    measured.check(u, resolved.free.len())?;
    let start = measured.data_start(&resolved, x0);
    let ex = full_evaluator(&resolved, t, u, x0, smoothed.is_some(), &measured);
    resolved.fill_starts(&start);
    let (mut ex, outcome) = best_start(ex, &resolved, &measured.f, starts, options.progress)?;
    let fitted = if smoothed.is_some() {
        // (X5) is the fit's own output, not the simulator's at the knots.
        own_output(&mut ex.inner, &outcome.values, u.len(), resolved.free.len())
    } else {
        simulated_output(&resolved, &outcome.values, t, u, x0)?
    };
    // A smoothed record: the estimates move with the smoothing's error too (S3).
    let input_effects = match &smoother {
        Some(smoother) => {
            let model_at = output_at(resolved.family, &outcome.values, t, x0);
            noise::input_effects(u, levels.position, smoother, model_at)
                .iter()
                .map(|dy| measured.pick(dy))
                .collect()
        }
        None => Vec::new(),
    };
    let fitted_m = measured.pick(&fitted);
    let mut r = report(
        FitKind::Full,
        &resolved,
        outcome,
        fitted_m,
        &measured.f,
        starts,
        &input_effects,
    )?;
    // The fitted curve at every row, measured or not.
    r.fitted = fitted;
    r.noise = Some(levels);
    r.check_fit(f);
    Ok(r)
}

/// The full fit's columns (equal lengths, finite; a force may be NaN, a row without a
/// measured force), strictly increasing times, a finite `x0` and `1..=MAX_STARTS` starts.
fn check_full_input(
    t: &[f64],
    u: &[f64],
    f: &[f64],
    x0: f64,
    starts: usize,
) -> Result<(), FitError> {
    check_columns(&[("u", u), ("t", t)])?;
    // NaN marks a row without a measured force: the input there still drives the model.
    check_columns(&[
        ("u", u),
        (
            "F",
            &f.iter()
                .map(|v| if v.is_nan() { 0.0 } else { *v })
                .collect::<Vec<_>>(),
        ),
    ])?;
    check_increasing(t)?;
    if !x0.is_finite() {
        return Err(FitError::BadX0 { value: x0 });
    }
    if starts == 0 || starts > FullOptions::MAX_STARTS {
        return Err(FitError::BadStarts {
            starts,
            most: FullOptions::MAX_STARTS,
        });
    }
    Ok(())
}

/// The rows of a full fit's record with a measured force (NaN marks a row without one), and
/// the samples there: the residual is taken at these rows, every row drives the model.
struct Measured {
    rows: Vec<usize>,
    t: Vec<f64>,
    u: Vec<f64>,
    f: Vec<f64>,
}

impl Measured {
    fn new(t: &[f64], u: &[f64], f: &[f64]) -> Self {
        let rows: Vec<usize> = (0..f.len()).filter(|&i| !f[i].is_nan()).collect();
        let (t, u, f) = (pick(&rows, t), pick(&rows, u), pick(&rows, f));
        Self { rows, t, u, f }
    }

    /// The values of a column at the measured rows.
    fn pick(&self, xs: &[f64]) -> Vec<f64> {
        pick(&self.rows, xs)
    }

    /// Enough measured rows for the `free` parameters, a reversal in the input `u` (every
    /// row), and a force that is not zero throughout.
    fn check(&self, u: &[f64], free: usize) -> Result<(), FitError> {
        check_count(self.rows.len(), free)?;
        if !full::has_reversal(u) {
            return Err(FitError::NoReversal { fit: "full" });
        }
        if self.f.iter().all(|&v| v == 0.0) {
            return Err(FitError::ZeroForce);
        }
        Ok(())
    }

    /// The starting values from the measured rows alone (their speeds between measured rows).
    fn data_start(&self, resolved: &Resolved, x0: f64) -> Vec<f64> {
        let family = resolved.family;
        let ex = full::Exact::new(family, resolved.free.clone(), &self.t, &self.u, x0);
        full::data_start(family, &ex, &self.u, &self.f, &resolved.values)
    }
}

fn pick(rows: &[usize], xs: &[f64]) -> Vec<f64> {
    rows.iter().map(|&i| xs[i]).collect()
}

/// The exact simulation over every row of `(t, u)` from `x0`, its output at the measured rows.
fn full_evaluator(
    resolved: &Resolved,
    t: &[f64],
    u: &[f64],
    x0: f64,
    smoothed: bool,
    measured: &Measured,
) -> full::Rows<full::Exact> {
    let mut exact = full::Exact::new(resolved.family, resolved.free.clone(), t, u, x0);
    if smoothed {
        // A smooth motion: each sample output with its own velocity (X5).
        exact = exact.with_central_output(t, u);
    }
    full::Rows::new(exact, measured.rows.clone(), t.len())
}

/// The full fit from `starts` start points (the data's, then the stiffness and `vs` scaled by
/// [`START_FACTORS`], cycled): the evaluator back and the best end point, with the
/// evaluations of every start.
fn best_start(
    mut ex: full::Rows<full::Exact>,
    resolved: &Resolved,
    f: &[f64],
    starts: usize,
    mut progress: Option<&mut dyn FnMut(&FitProgress)>,
) -> Result<(full::Rows<full::Exact>, Outcome), FitError> {
    let mut best: Option<Outcome> = None;
    let mut evaluations = 0;
    for (n, &factors) in START_FACTORS.iter().cycle().take(starts).enumerate() {
        let mut run = resolved.clone();
        run.values = start_point(resolved, n, factors);
        full::solve_linear(&ex, resolved, &mut run.values, f);
        let free_start = run.free_values();
        let mut report = |evaluations: usize, rms: f64| {
            if let Some(f) = progress.as_mut() {
                f(&FitProgress {
                    start: n + 1,
                    starts,
                    evaluations,
                    rms,
                })
            }
        };
        let (back, outcome) = minimize(ex, f, run.space(), &free_start, FULL_CONFIG, &mut report);
        ex = back;
        evaluations += outcome.evaluations;
        if outcome.rss.is_finite() && best.as_ref().is_none_or(|b| outcome.rss < b.rss) {
            best = Some(outcome);
        }
    }
    let Some(mut outcome) = best else {
        return Err(FitError::NoStart { starts });
    };
    outcome.evaluations = evaluations;
    Ok((ex, outcome))
}

/// The `n`-th start point: the data's start with sigma0 scaled by `k0` and (LuGre) vs by `kv`,
/// where their starts were not given, inside their bounds.
fn start_point(resolved: &Resolved, n: usize, (k0, kv): (f64, f64)) -> Vec<f64> {
    let mut values = resolved.values.clone();
    let mut scale = |i: usize, k: f64| {
        if let Some(c) = resolved.free.iter().position(|&j| j == i) {
            if !resolved.given[c] {
                values[i] = resolved.bounds[c].pull_inside(values[i] * k);
            }
        }
    };
    // Cycling past the table (more than 7 starts) spreads further.
    let spread = 1.0 + (n / START_FACTORS.len()) as f64;
    scale(0, k0.powf(spread));
    if resolved.family == Family::LuGre {
        scale(5, kv.powf(spread));
    }
    values
}

/// The fit's own output at the `n` rows at `values`, from the evaluator the fit ran on (of
/// `free` free parameters).
fn own_output(ex: &mut full::Exact, values: &[f64], n: usize, free: usize) -> Vec<f64> {
    let mut y = vec![0.0; n];
    let mut jac = nalgebra::DMatrix::zeros(n, free);
    ex.evaluate(values, &mut y, &mut jac);
    y
}

/// The fitted model's output at every row: the simulator's at the knots of the piecewise-linear
/// input through `(t, u)` from `x0`.
fn simulated_output(
    resolved: &Resolved,
    values: &[f64],
    t: &[f64],
    u: &[f64],
    x0: f64,
) -> Result<Vec<f64>, FitError> {
    let model = crate::LuGre::from_params(resolved.lugre(values))?;
    let input = PiecewiseLinear::new(t.to_vec(), u.to_vec())?;
    let mut out = Trajectory::with_capacity(u.len());
    Simulator::new(&model, Gamma::ONE, x0)?.at_knots(&input, 1, &mut out)?;
    Ok(out.y)
}

/// The fitted model's output (alone, no derivatives) for another reading `uk` of the input at
/// the times `t` (each sample with its own velocity, X5); `None` where the simulation fails.
fn output_at<'a>(
    family: Family,
    values: &'a [f64],
    t: &'a [f64],
    x0: f64,
) -> impl Fn(&[f64]) -> Option<Vec<f64>> + 'a {
    move |uk: &[f64]| {
        let mut e = full::Exact::new(family, Vec::new(), t, uk, x0).with_central_output(t, uk);
        let mut y = vec![0.0; uk.len()];
        let mut none = nalgebra::DMatrix::zeros(uk.len(), 0);
        e.evaluate(values, &mut y, &mut none).then_some(y)
    }
}

fn not_converged(resolved: &Resolved, outcome: &Outcome, m: usize) -> FitError {
    FitError::NotConverged {
        reason: outcome.reason(),
        best: resolved
            .free
            .iter()
            .map(|&i| (resolved.family.parameters()[i], outcome.values[i]))
            .collect(),
        rms: (outcome.rss / m as f64).sqrt(),
    }
}

/// Statistics, identifiability and the report (`input_effects`: the model's responses to draws
/// of the input's error, eq. S3).
fn report(
    kind: FitKind,
    resolved: &Resolved,
    outcome: Outcome,
    fitted: Vec<f64>,
    f: &[f64],
    starts: usize,
    input_effects: &[Vec<f64>],
) -> Result<FitReport, FitError> {
    let m = f.len();
    if !outcome.rss.is_finite() {
        return Err(not_converged(resolved, &outcome, m));
    }
    let names = resolved.names();
    let values = resolved.free_values_of(&outcome.values);
    let data_norm = f.iter().map(|v| v * v).sum::<f64>().sqrt();
    let residuals: Vec<f64> = f.iter().zip(&fitted).map(|(f, y)| f - y).collect();
    let rss: f64 = residuals.iter().map(|r| r * r).sum();
    let start_values = resolved.free_values();
    let free = FreeEnd {
        names: &names,
        values: &values,
        starts: &start_values,
        bounds: &resolved.bounds,
    };
    let (estimates, unc) = assess(&outcome, free, &residuals, data_norm, input_effects)?;
    let converged = outcome.converged();
    let relevant: Vec<usize> = (0..resolved.family.parameters().len())
        .filter(|&i| kind.uses(resolved.family, i))
        .collect();
    let fixed = relevant
        .into_iter()
        .filter(|i| !resolved.free.contains(i))
        .map(|i| (resolved.family.parameters()[i], resolved.values[i]))
        .collect();
    let warnings = bound_warnings(&estimates, &resolved.bounds);
    Ok(FitReport {
        kind,
        family: resolved.family,
        estimates,
        fixed,
        rms: (rss / m as f64).sqrt(),
        samples: m,
        dof: m - names.len(),
        t_quantile: unc.t,
        condition_number: unc.condition,
        correlation: unc.correlation,
        iterations: outcome.iterations,
        evaluations: outcome.evaluations,
        starts,
        converged,
        termination: outcome.reason(),
        turning_points: None,
        fitted,
        noise: None,
        warnings,
        covariance: unc.method,
        serial: SerialCorrelation::of(&residuals),
    })
}

/// The free parameters of a fit at its end: names, values, starts and bounds.
struct FreeEnd<'a> {
    names: &'a [&'static str],
    values: &'a [f64],
    starts: &'a [f64],
    bounds: &'a [Bounds],
}

/// The estimates of the free parameters with their standard errors, intervals (S1-S4) and
/// at-bound flags, and the statistics they come from (`residuals = F - y`, `data_norm = |F|`).
/// A run that stopped for any reason but its evaluation budget is [`FitError::NotConverged`]; a
/// parameter the data do not determine is [`FitError::Unidentifiable`].
fn assess(
    outcome: &Outcome,
    free: FreeEnd<'_>,
    residuals: &[f64],
    data_norm: f64,
    input_effects: &[Vec<f64>],
) -> Result<(Vec<Estimate>, stats::Uncertainty), FitError> {
    let FreeEnd {
        names,
        values,
        starts: start_values,
        bounds,
    } = free;
    let at_bound: Vec<bool> = (0..names.len())
        .map(|j| bounds[j].reached(values[j], start_values[j]))
        .collect();
    let unc = stats::uncertainty(
        &outcome.jac,
        names,
        values,
        &at_bound,
        residuals,
        data_norm,
        input_effects,
    )?;
    if !outcome.converged()
        && !matches!(
            outcome.termination,
            levenberg_marquardt::TerminationReason::LostPatience
        )
    {
        return Err(FitError::NotConverged {
            reason: outcome.reason(),
            best: names.iter().copied().zip(values.iter().copied()).collect(),
            rms: (outcome.rss / residuals.len() as f64).sqrt(),
        });
    }
    let estimates: Vec<Estimate> = (0..names.len())
        .map(|j| {
            let half = unc.estimate_t[j] * unc.stderr[j];
            let b = bounds[j];
            let mut ci95 = [b.clamp(values[j] - half), b.clamp(values[j] + half)];
            if at_bound[j] {
                // The interval of an estimate at its bound reaches the bound.
                match bound_of(values[j], b) {
                    x if x == b.lo => ci95[0] = b.lo,
                    _ => ci95[1] = b.hi,
                }
            }
            Estimate {
                name: names[j],
                value: values[j],
                stderr: unc.stderr[j],
                dof: unc.estimate_dof[j],
                ci95,
                at_bound: at_bound[j],
            }
        })
        .collect();
    Ok((estimates, unc))
}

impl FitReport {
    /// Adds the lack-of-fit warnings (C1-C2 module docs) for the measured forces `f` (the rows
    /// fitted), once the noise levels are known.
    fn check_fit(&mut self, f: &[f64]) {
        let r: Vec<f64> = f
            .iter()
            .zip(&self.fitted)
            .filter(|(f, _)| !f.is_nan())
            .map(|(f, y)| f - y)
            .collect();
        let force_noise = self.noise.map(|n| n.force);
        let slow = self.kind == FitKind::Slow;
        // Checked again on another reading of the rows: the new check replaces the old.
        self.warnings
            .retain(|w| matches!(w, FitWarning::AtBound { .. }));
        let f_rms = (f.iter().filter(|f| !f.is_nan()).map(|f| f * f).sum::<f64>()
            / r.len().max(1) as f64)
            .sqrt();
        self.warnings.extend(covariance::lack_of_fit(
            &r,
            self.rms,
            f_rms,
            force_noise,
            slow,
        ));
    }
}

/// The bound nearer `value`.
fn bound_of(value: f64, b: Bounds) -> f64 {
    if b.hi.is_finite() && (value - b.hi).abs() < (value - b.lo).abs() {
        b.hi
    } else {
        b.lo
    }
}

/// Each estimate at its bound.
fn bound_warnings(estimates: &[Estimate], bounds: &[Bounds]) -> Vec<FitWarning> {
    estimates
        .iter()
        .zip(bounds)
        .filter(|(e, _)| e.at_bound)
        .map(|(e, b)| FitWarning::AtBound {
            name: e.name,
            bound: bound_of(e.value, *b),
        })
        .collect()
}

impl FitReport {
    /// The fitted model as LuGre parameters (fixed ones at their values; for a slow fit the
    /// parameters the loop does not depend on are those of `spec`).
    pub fn lugre_params(&self, spec: &FitSpec) -> LuGreParams {
        let names = self.family.parameters();
        let mut v: Vec<f64> = names.iter().map(|n| spec.value(n).unwrap_or(0.0)).collect();
        for e in &self.estimates {
            if let Some(i) = names.iter().position(|n| *n == e.name) {
                v[i] = e.value;
            }
        }
        spec::lugre_params(self.family, &v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::DMatrix;

    /// `y = fc exp(-rho x)`: a two-parameter model to drive the optimizer's edge cases.
    struct Decay {
        x: Vec<f64>,
        valid: bool,
    }

    impl Evaluator for Decay {
        fn evaluate(&mut self, v: &[f64], y: &mut [f64], jac: &mut DMatrix<f64>) -> bool {
            for (i, &x) in self.x.iter().enumerate() {
                let e = (-v[0] * x).exp();
                y[i] = v[1] * e;
                jac[(i, 0)] = -x * v[1] * e;
                jac[(i, 1)] = e;
            }
            self.valid
        }
    }

    fn problem(valid: bool) -> (Decay, Vec<f64>, Resolved) {
        let x: Vec<f64> = (0..50).map(|i| f64::from(i) * 0.1).collect();
        // The truth (rho, fc) = (2, 0.8) and a deterministic wiggle as noise.
        let f = x
            .iter()
            .enumerate()
            .map(|(i, &x)| 0.8 * (-2.0 * x).exp() + 0.01 * (i as f64 * 1.7).sin())
            .collect();
        let resolved = FitSpec::new(Family::Dahl).resolve(FitKind::Full).unwrap();
        (Decay { x, valid }, f, resolved)
    }

    #[test]
    fn out_of_evaluations_at_a_usable_point_is_reported_unconverged() {
        let (eval, f, resolved) = problem(true);
        let config = Config {
            patience: 1,
            ..FULL_CONFIG
        };
        let (_, outcome) = minimize(
            eval,
            &f,
            resolved.space(),
            &[1.0, 1.0],
            config,
            &mut |_, _| {},
        );
        assert!(!outcome.converged());
        let fitted = outcome.y.clone();
        let r = report(FitKind::Full, &resolved, outcome, fitted, &f, 1, &[]).unwrap();
        assert!(!r.converged);
        assert!(
            r.termination.contains("without meeting the tolerances"),
            "{}",
            r.termination
        );
    }

    #[test]
    fn a_model_that_cannot_be_evaluated_is_not_converged() {
        let (eval, f, resolved) = problem(false);
        let (_, outcome) = minimize(
            eval,
            &f,
            resolved.space(),
            &[1.0, 1.0],
            FULL_CONFIG,
            &mut |_, _| {},
        );
        let fitted = outcome.y.clone();
        let e = report(FitKind::Full, &resolved, outcome, fitted, &f, 1, &[]).unwrap_err();
        assert!(matches!(e, FitError::NotConverged { .. }), "{e}");
        assert!(e.to_string().starts_with("the fit did not converge"), "{e}");
    }

    #[test]
    fn converges_on_a_plain_problem() {
        let (eval, f, resolved) = problem(true);
        let (_, outcome) = minimize(
            eval,
            &f,
            resolved.space(),
            &[1.0, 1.0],
            FULL_CONFIG,
            &mut |_, _| {},
        );
        assert!(outcome.converged());
        let fitted = outcome.y.clone();
        let r = report(FitKind::Full, &resolved, outcome, fitted, &f, 1, &[]).unwrap();
        assert!((r.estimates[0].value - 2.0).abs() < 0.05, "{r:?}");
        assert!((r.estimates[1].value - 0.8).abs() < 0.02, "{r:?}");
    }
}
