//! Typed errors, one enum per domain. Every variant carries the offending value so that a
//! front end (CLI, Python) can print one clear line.

use thiserror::Error;

/// `x` as every message of this crate and its front ends shows a number: the shortest text
/// that parses back to exactly `x`, plain from 1e-5 to 1e16 (`0.25`, `-3`, `123456`) and in
/// exponent notation beyond (`1e299`, `-2.5e-300` rather than hundreds of digits; no `+`).
///
/// ```
/// use lugre::error::num;
/// assert_eq!(num(0.25), "0.25");
/// assert_eq!(num(-3.0), "-3");
/// assert_eq!(num(1e299), "1e299");
/// assert_eq!(num(-2.5e-300), "-2.5e-300");
/// ```
pub fn num(x: f64) -> String {
    if x == 0.0 || !x.is_finite() || (1e-5..1e16).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// `x` as [`num`] shows it, or words where it is not a finite number.
fn shown(x: f64) -> String {
    if x.is_finite() {
        num(x)
    } else {
        "a value that is not a finite number".into()
    }
}

/// The residual RMS of a best point, in words where it is not a number.
fn rms_text(rms: f64) -> String {
    if rms.is_finite() {
        format!("residual RMS {}", num(rms))
    } else {
        "where the model could not be evaluated".into()
    }
}

/// A field of a dynamics request (`lugre::dynamics::Request`), as the user gives it: what
/// its errors name, each front end spelling it its own way ([`DynamicsError::render`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Field {
    Scenario,
    Model,
    Mass,
    Damping,
    Force,
    ForceRate,
    Input,
    Spring,
    Pull,
    End,
    Pid,
    Setpoint,
    Velocity,
    TEnd,
    Times,
    Samples,
    Rtol,
    Atol,
    Loops,
}

impl Field {
    /// Every field, in the order of the table in the module docs.
    pub const ALL: [Field; 19] = [
        Field::Scenario,
        Field::Model,
        Field::Mass,
        Field::Damping,
        Field::Force,
        Field::ForceRate,
        Field::Input,
        Field::Spring,
        Field::Pull,
        Field::End,
        Field::Pid,
        Field::Setpoint,
        Field::Velocity,
        Field::TEnd,
        Field::Times,
        Field::Samples,
        Field::Rtol,
        Field::Atol,
        Field::Loops,
    ];

    /// The field called `name` ([`Self::name`]).
    pub fn from_name(name: &str) -> Option<Field> {
        Self::ALL.into_iter().find(|f| f.name() == name)
    }

    /// The field's name: the Python keyword and the MEX struct field.
    pub fn name(self) -> &'static str {
        match self {
            Field::Scenario => "scenario",
            Field::Model => "model",
            Field::Mass => "mass",
            Field::Damping => "damping",
            Field::Force => "force",
            Field::ForceRate => "force_rate",
            Field::Input => "input",
            Field::Spring => "spring",
            Field::Pull => "pull",
            Field::End => "end",
            Field::Pid => "pid",
            Field::Setpoint => "setpoint",
            Field::Velocity => "velocity",
            Field::TEnd => "t_end",
            Field::Times => "times",
            Field::Samples => "samples",
            Field::Rtol => "rtol",
            Field::Atol => "atol",
            Field::Loops => "loops",
        }
    }
}

impl std::fmt::Display for Field {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// An invalid model parameter.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum ModelError {
    #[error("unknown preset '{name}' (presets: {})", .known.join(", "))]
    UnknownPreset {
        name: String,
        /// The presets there are.
        known: &'static [&'static str],
    },
    #[error("{name} must be a finite number, got {value}", value = num(*.value))]
    NotFinite { name: &'static str, value: f64 },
    #[error("{name} must be > 0, got {value}", value = num(*.value))]
    NotPositive { name: &'static str, value: f64 },
    /// A parameter whose reciprocal the model uses, below the smallest number whose
    /// reciprocal is finite.
    #[error("{name} must be >= {min} (1 / {name} overflows below it), got {value}", min = num(*.min), value = num(*.value))]
    TooSmall {
        name: &'static str,
        value: f64,
        min: f64,
    },
    #[error("{name} must be >= 0, got {value}", value = num(*.value))]
    Negative { name: &'static str, value: f64 },
    #[error("g(0) must be finite and > 0, got {value}", value = num(*.value))]
    BadG0 { value: f64 },
    #[error("f(0) must be 0, got {value}", value = num(*.value))]
    BadF0 { value: f64 },
    #[error("a = sigma0 / g(0) = {sigma0} / {g0} is not a finite positive number", sigma0 = num(*.sigma0), g0 = num(*.g0))]
    BadRatio { sigma0: f64, g0: f64 },
}

/// A series of numbers that cannot be used as data, with one wording for every front end:
/// shared by inputs ([`InputError`]), histories ([`HistoryError`]), fits ([`FitError`]) and
/// the output times of simulations ([`SimulateError`], [`DynamicsError`]), which nest it. The
/// checks are in [`crate::input`].
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum DataError {
    #[error("{what}[{index}] must be a finite number, got {value}", value = num(*.value))]
    NotFinite {
        what: &'static str,
        index: u64,
        value: f64,
    },
    /// `what` names the series: `times` (of data), `output times`.
    #[error("{what} must be strictly increasing: t[{index}] = {value} after t[{prev_index}] = {prev}", prev_index = index - 1, value = num(*.value), prev = num(*.prev))]
    TimesNotIncreasing {
        what: &'static str,
        index: u64,
        prev: f64,
        value: f64,
    },
    #[error("output time t[{index}] = {value} is outside the run [{start}, {end}]", value = num(*.value), start = num(*.start), end = num(*.end))]
    TimeOutOfRange {
        index: u64,
        value: f64,
        start: f64,
        end: f64,
    },
}

/// A normal force that cannot scale a model per newton ([`crate::model::normal`]); `index`
/// is 0-based, each front end naming the sample its own way.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum NormalForceError {
    #[error("the normal force N must be > 0, got {value}", value = num(*.value))]
    NotPositive { index: usize, value: f64 },
    #[error("{normal} normal forces for {samples} samples: one normal force per sample")]
    Length { normal: usize, samples: usize },
}

/// An invalid input signal.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum InputError {
    #[error(transparent)]
    Data(#[from] DataError),
    #[error("the input is empty")]
    Empty,
    #[error("a periodic input needs at least 2 distinct values, got {distinct}")]
    TooFewDistinct { distinct: usize },
    #[error("bimodal input breaks Definition 1: {inequality} fails ({detail})")]
    Definition1 {
        inequality: &'static str,
        detail: String,
    },
    #[error("t and u have different lengths ({t} and {u})")]
    LengthMismatch { t: usize, u: usize },
    #[error("the input's total variation over one period overflows f64 (values too far apart)")]
    VariationOverflow,
}

/// A hysteresis loop that cannot be computed: an invalid input, or a result that cannot be
/// represented (it overflows f64).
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum LoopError {
    #[error("{what} overflows f64 for this model and input")]
    Overflow { what: &'static str },
    /// An option of LuGre's and Dahl's simulation (an initial state, gamma, periods, output
    /// times, a sine, ...) given with a model of the zoo, which is simulated from rest at the
    /// input's own samples ([`crate::zoo::ZooModel::simulate`]); `option` as the front end
    /// spells it (`--x0`, `x0`).
    #[error("{option} is an option of LuGre's and Dahl's simulation; the {model} model is simulated from rest at the input's own samples")]
    SimulateOption { option: String, model: &'static str },
    /// A model without a finite-rate form asked to step at finite rate
    /// ([`crate::zoo::ZooModel::stepper`]).
    #[error("the {model} model has no finite-rate form: it is rate-independent, stepped by its exact segment map")]
    RateIndependent { model: &'static str },
    #[error(transparent)]
    Input(#[from] InputError),
    /// The finite-rate model's LuGre parts (`sigma0, sigma1, sigma2, fc, fs, vs, beta`).
    #[error(transparent)]
    Model(#[from] ModelError),
}

/// A count of loop samples out of range ([`crate::HysteresisLoop::try_sample`]). Each front end
/// names the count its own way (`--samples`, `n`): [`SamplesError::render`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum SamplesError {
    /// Fewer than two points: a period has two ends.
    #[error("{}", self.render("n"))]
    TooFew { n: u64 },
    /// More points than [`crate::loops::MAX_SAMPLES`].
    #[error("{}", self.render("n"))]
    TooMany { n: u64, limit: u64 },
}

impl SamplesError {
    /// The message with the count called `name`.
    pub fn render(&self, name: &str) -> String {
        match self {
            SamplesError::TooFew { n } => {
                format!("{name} must be at least 2 (both ends of the period), got {n}")
            }
            SamplesError::TooMany { n, limit } => {
                format!("{name} must be at most {limit} (memory for the points), got {n}")
            }
        }
    }
}

/// An invalid measured history or counting option ([`crate::cycles`]).
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum HistoryError {
    #[error("the history is empty (no samples)")]
    Empty,
    #[error("a history needs at least 2 samples, got {samples}")]
    TooShort { samples: u64 },
    /// A sample that is not a finite number (`DataError::NotFinite` of `u`).
    #[error(transparent)]
    Data(#[from] DataError),
    #[error("u[{index}] = {value} is too large: |u| must be at most {limit} so that ranges and means stay finite", value = num(*.value), limit = num(f64::MAX / 2.0))]
    TooLarge { index: u64, value: f64 },
    #[error("the gate must be a finite number >= 0, got {value}", value = num(*.value))]
    BadGate { value: f64 },
    #[error("x0 must satisfy |sigma0 x0| <= g(0) (the bristle deflection the model can hold), got x0 = {x0} with sigma0 = {sigma0}, g(0) = {g0}", x0 = num(*.x0), sigma0 = num(*.sigma0), g0 = num(*.g0))]
    BadInitialState { x0: f64, sigma0: f64, g0: f64 },
    #[error("the model must be given before the first sample (the counter has taken {samples})")]
    EnergyAfterStart { samples: u64 },
    #[error("the energies of the cycle closing at u[{index}] overflow f64 (values too large)")]
    EnergyOverflow { index: u64 },
    #[error(
        "the energies along the history overflow f64 for this model and input (values too large)"
    )]
    TotalsOverflow,
    /// An initial state given for a model of the zoo, which starts from rest at `u[0]`.
    #[error(
        "x0 is the initial bristle state of LuGre and Dahl; the {model} model starts from rest"
    )]
    StartsFromRest { model: &'static str },
    /// A history too long for the energies of a model of the zoo (held in memory:
    /// [`crate::zoo::MAX_HISTORY_SAMPLES`]).
    #[error("more than {limit} samples; the energies of the {model} model hold the history in memory (count the cycles without a model, or split the history)")]
    HeldTooLong { limit: usize, model: &'static str },
    #[error("a histogram needs at least 1 bin, got {bins}")]
    NoBins { bins: usize },
    #[error("histogram bounds must be finite with min <= max, got [{min}, {max}]", min = num(*.min), max = num(*.max))]
    BadBounds { min: f64, max: f64 },
    #[error("the chunk starting at u[{start}] is empty: every chunk needs at least 1 sample")]
    EmptyChunk { start: u64 },
    #[error("a chunk of {samples} samples from u[{offset}] runs past u[{last}], the last index a history can have (indices are int64)", last = i64::MAX)]
    IndexOverflow { offset: u64, samples: u64 },
    #[error("the chunk starts at u[0]: there is no sample before it, got {value}", value = num(*.value))]
    PrevBeforeStart { value: f64 },
    #[error("{name} must be a finite number with |{name}| <= g(0) = {g0} (a state y* can hold), got {value}", value = num(*.value), g0 = num(*.g0))]
    BadEntryState {
        name: &'static str,
        value: f64,
        g0: f64,
    },
    #[error("bounds[{index}] = ({upper}, {lower}) must be finite numbers (states y* a chunk can end at)", upper = num(*.upper), lower = num(*.lower))]
    BadStateBounds {
        index: usize,
        upper: f64,
        lower: f64,
    },
    #[error("chunks are not adjacent: the left one ends at u[{left_end}], the right one starts at u[{right_start}]")]
    NotAdjacent { left_end: u64, right_start: u64 },
    #[error("the chunks merged cover u[{start}..={end}], not the whole history from u[0]")]
    NotWhole { start: u64, end: u64 },
    #[error("the closure of the cycle turning at u[{end}] was not found in the chunks given (the summaries and the samples do not belong to one history)")]
    ClosureNotFound { end: u64 },
    #[error("a chunk summary cannot be read from these bytes ({why})")]
    BadSummary { why: &'static str },
    #[error("{name} is not a state of the {model} model ({count} numbers, each finite: the input and the model's state)")]
    NotAZooState {
        name: &'static str,
        model: &'static str,
        count: usize,
    },
}

/// A parameter-identification request that cannot be carried out, or whose answer the data do
/// not determine ([`crate::fit`]).
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum FitError {
    #[error("the data columns have different lengths: {what} has {got} values, u has {u}")]
    LengthMismatch {
        what: &'static str,
        got: usize,
        u: usize,
    },
    #[error(transparent)]
    Data(#[from] DataError),
    #[error("too few samples: {samples} for {parameters} free parameter(s); the fit needs at least {needed}")]
    TooFewSamples {
        samples: usize,
        parameters: usize,
        needed: usize,
    },
    #[error("the input u has no reversal (it only rises or only falls, or is constant): the {fit} fit needs at least one turning point inside the data")]
    NoReversal { fit: &'static str },
    #[error("the force F is 0 at every sample: there is nothing to fit")]
    ZeroForce,
    #[error("unknown parameter '{name}' for the {model} model (its parameters: {known})", known = .known.join(", "))]
    UnknownParameter {
        name: String,
        model: &'static str,
        known: &'static [&'static str],
    },
    #[error("{name} does not enter the slow loop: the rate-independent limit depends only on sigma0 and g(0) = Fs (Dahl: rho and Fc), so {name} cannot be identified from quasi-static data (use a full fit of rate-dependent data)")]
    NotInSlowLoop { name: &'static str },
    #[error(
        "{name} cannot be fitted by the full fit (it has no derivative for it): give its value"
    )]
    NotInFullFit { name: &'static str },
    #[error("{name} does not enter the slow loop of the {model} model (it depends on {slow}): it cannot be identified from quasi-static data; give its value instead")]
    NotInZooSlowLoop {
        name: &'static str,
        model: &'static str,
        slow: String,
    },
    /// A full fit of a model of the zoo without a finite-rate form.
    #[error("--fit full: the {model} model has no finite-rate form (the models of the zoo with one: {takes}); fit its slow loop (--fit slow)")]
    NoFiniteRate {
        model: &'static str,
        /// The models of the zoo with a finite-rate form, comma-separated.
        takes: String,
    },
    #[error("x0 = {x0}: the full fit of the {model} model runs from rest at the first sample (its state is not a number to give); leave x0 out")]
    ZooFromRest { model: &'static str, x0: f64 },
    #[error("the number of elements must be from 1 to {most}, got {count}")]
    BadElements { count: usize, most: usize },
    #[error("the {model} model has no elements: its parameters are scalars ({known}), so there is no element count or threshold to give")]
    NoElements { model: &'static str, known: String },
    #[error(transparent)]
    Zoo(#[from] ZooError),
    #[error("{name} is both fixed and freed")]
    FixedAndFree { name: &'static str },
    #[error("nothing to fit: every parameter of the {fit} fit is fixed")]
    NothingToFit { fit: &'static str },
    #[error(
        "{name} is held in the {fit} fit but has no value: give it (e.g. {example}) or fit it too"
    )]
    NotGiven {
        name: &'static str,
        fit: &'static str,
        example: &'static str,
    },
    #[error("the bounds of {name} must satisfy 0 <= lo < hi (hi may be inf), got [{lo}, {hi}]", lo = num(*.lo), hi = num(*.hi))]
    BadBounds {
        name: &'static str,
        lo: f64,
        hi: f64,
    },
    #[error("the bounds [{lo}, {hi}] of {name} exclude its start value {start} (it must lie strictly inside)", lo = num(*.lo), hi = num(*.hi), start = num(*.start))]
    StartOutsideBounds {
        name: &'static str,
        start: f64,
        lo: f64,
        hi: f64,
    },
    #[error("the start value of {name} must be a finite number > 0, got {value}", value = num(*.value))]
    BadStart { name: &'static str, value: f64 },
    #[error("the number of starts must be from 1 to {most}, got {starts}")]
    BadStarts { starts: usize, most: usize },
    #[error("x0 must be a finite number, got {value}", value = num(*.value))]
    BadX0 { value: f64 },
    #[error("the gate must be a finite number >= 0 (in the units of u), got {value}", value = num(*.value))]
    BadGate { value: f64 },
    #[error("{} cannot be identified from this data: {}", names_of(.parameters), reasons(.parameters))]
    Unidentifiable { parameters: Vec<Unidentified> },
    #[error("the model could not be evaluated at any of the {starts} starts (every start value gave a non-finite response): give start values for the parameters")]
    NoStart { starts: usize },
    #[error("the fit did not converge ({reason}); best point found: {} ({})", list(.best), rms_text(*.rms))]
    NotConverged {
        reason: String,
        best: Vec<(&'static str, f64)>,
        rms: f64,
    },
    #[error(transparent)]
    Model(#[from] ModelError),
    #[error(transparent)]
    Simulate(#[from] SimulateError),
    #[error("the {fit} fit identifies the LuGre model (its Stribeck curve and bristles); the {family} model has neither: use the LuGre model")]
    NotForFamily {
        fit: &'static str,
        family: &'static str,
    },
    #[error("{name} does not enter the steady-state friction F_ss(v) = g(v) sgn(v) + sigma2 v, so constant-velocity runs cannot determine it (sigma0 and sigma1 come from a presliding test)")]
    NotInSteadyState { name: &'static str },
    #[error("the steady-state point {index} has velocity {value}: each point needs a finite, nonzero velocity (the curve jumps at v = 0)", value = num(*.value))]
    BadSteadyVelocity { index: usize, value: f64 },
    #[error("the steady-state point {index} has force {value}: each point needs a finite force", value = num(*.value))]
    BadSteadyForce { index: usize, value: f64 },
    #[error("the steady-state point {index} has standard error {value}: it must be a finite number > 0", value = num(*.value))]
    BadSteadyError { index: usize, value: f64 },
    #[error("{plateaus} constant-velocity points for {parameters} free parameter(s): the Stribeck fit needs at least {needed}; add runs at more velocities or fix parameters")]
    TooFewPlateaus {
        plateaus: usize,
        parameters: usize,
        needed: usize,
    },
    #[error("the constant-velocity runs are at only {speeds} distinct speed(s) ({list}) for {parameters} free parameter(s): the steady-state curve needs runs at {parameters} speeds or more (a sine's record has runs only at its peak speed); run constant-velocity tests over a range of speeds, or fix parameters", list = .list.join(", "))]
    TooFewSpeeds {
        speeds: usize,
        parameters: usize,
        /// The speeds, rounded for the message.
        list: Vec<String>,
    },
    #[error("the table of constant-velocity runs has {v} velocities and {f} forces: give one steady force per velocity")]
    SteadyTableLengths { v: usize, f: usize },
    #[error("the record has no constant-velocity run: the velocity never stays constant (within its noise) over {min_run} samples or more in its {samples} samples; record runs at constant velocities, or give a table v,F of their steady forces")]
    NoPlateau { samples: usize, min_run: usize },
    #[error("the constant-velocity runs are too short: the longest has {longest} samples and each needs at least {needed} once its transient is dropped; sample faster or run each velocity longer")]
    TooFewPlateauSamples { longest: usize, needed: usize },
    #[error("the noise is larger than the signal: {what} varies by {noise} (standard deviation) against a level of {signal}; average more samples or reduce the noise", noise = num(*.noise), signal = num(*.signal))]
    NoiseAboveSignal {
        what: &'static str,
        noise: f64,
        signal: f64,
    },
    #[error("the presliding test breaks away: its force reaches {peak} (within three noise deviations of {limit}, 0.9 Fs with Fs = {fs}); test with smaller displacements, well below break-away", peak = num(*.peak), limit = num(*.limit), fs = num(*.fs))]
    BreaksAway { peak: f64, limit: f64, fs: f64 },
    #[error("the presliding test slides: it travels {travel} between two reversals, where its stiffness would pass twice Fs after {limit}; test with smaller displacements, well below break-away", travel = num(*.travel), limit = num(*.limit))]
    Slides { travel: f64, limit: f64 },
    #[error("{stage} stage: {error}")]
    InStage {
        stage: &'static str,
        error: Box<FitError>,
    },
}

/// An invalid simulation request, or a result that cannot be represented.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum SimulateError {
    #[error("gamma must be > 0 (a positive number or inf), got {value}", value = num(*.value))]
    BadGamma { value: f64 },
    #[error("the number of periods must be at least 1, got {value}")]
    BadPeriods { value: u32 },
    #[error("the run would produce {rows} output rows (more than {limit}): ask for fewer periods or samples per period, or give the output times")]
    TooManyRows { rows: u64, limit: usize },
    #[error("periods must be at most {limit} for a sine (the adaptive integrator steps through each), got {periods}")]
    TooManyPeriods { periods: u32, limit: u64 },
    #[error("periods must be at most {most} for this input ({per_period} pieces a period, at most {limit} pieces a run), got {periods}", most = .limit / .per_period.max(&1))]
    TooMuchWork {
        periods: u32,
        per_period: u64,
        limit: u64,
    },
    #[error("the output samples per period must be at least 1, got 0")]
    BadSamplesPerPeriod,
    #[error("a sine has no knots: ask for output times or samples per period")]
    NoKnots,
    #[error("x0 must be a finite number, got {value}", value = num(*.value))]
    BadX0 { value: f64 },
    #[error("x0 = {x0} cannot be represented: sigma0 * x0 = {sigma0} * {x0} overflows f64", x0 = num(*.x0), sigma0 = num(*.sigma0))]
    X0Overflow { x0: f64, sigma0: f64 },
    #[error("the tolerance must be a number in [1e-14, 1), got {value}", value = num(*.value))]
    BadTolerance { value: f64 },
    #[error("the sine's {name} must be {requirement}, got {value}", value = num(*.value))]
    BadSine {
        name: &'static str,
        requirement: &'static str,
        value: f64,
    },
    #[error("the speed must be a finite number > 0, got {value}", value = num(*.value))]
    BadSpeed { value: f64 },
    #[error("a sampled input needs at least 2 samples, got {count}")]
    TooFewSamples { count: usize },
    #[error(
        "to repeat the input over {periods} periods it must end where it starts, \
         but u[0] = {first} and u[{last_index}] = {last}",
        first = num(*.first),
        last = num(*.last)
    )]
    NotClosed {
        periods: u32,
        first: f64,
        last_index: usize,
        last: f64,
    },
    /// Output times that are not finite, not increasing or outside the run.
    #[error(transparent)]
    Data(#[from] DataError),
    #[error("{what} overflows f64 at t = {t}", t = num(*.t))]
    Overflow { what: &'static str, t: f64 },
    #[error(
        "the adaptive integrator cannot meet the tolerance {tol} near t = {t} \
         (its step fell below the resolution of t)",
        tol = num(*.tol),
        t = num(*.t)
    )]
    StepUnderflow { t: f64, tol: f64 },
    #[error("a record read as a smooth motion runs once: the periods must be 1, got {periods}")]
    SmoothPeriods { periods: u32 },
    #[error("the cubic reading would need more than {limit} knots: loosen its tolerance")]
    TooManyKnots { limit: usize },
    #[error("the step must be a finite number >= 0, got {value}", value = num(*.value))]
    BadStep { value: f64 },
    #[error("the displacement must be a finite number, got {value}", value = num(*.value))]
    BadDisplacement { value: f64 },
    #[error(
        "the displacement cannot move in a zero step (from {from} to {to}): give the step its duration",
        from = num(*.from),
        to = num(*.to)
    )]
    JumpInZeroStep { from: f64, to: f64 },
    #[error(
        "the step {step} from t = {t} takes the time past the largest finite number",
        step = num(*.step),
        t = num(*.t)
    )]
    TimeOverflow { t: f64, step: f64 },
    #[error(transparent)]
    Input(#[from] InputError),
}

/// An invalid sweep request ([`crate::sweep`]), or a point that cannot be computed.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum SweepError {
    #[error("{what} must be a finite number > 0, got {value}", value = num(*.value))]
    NotPositive { what: &'static str, value: f64 },
    #[error("the offset must be a finite number, got {value}", value = num(*.value))]
    BadOffset { value: f64 },
    #[error("the {what} list is empty (give numbers separated by commas, or START:STOP:COUNT)")]
    EmptyList { what: &'static str },
    #[error("{what}: item {position} is '{item}', which is not a number")]
    NotANumber {
        what: &'static str,
        position: usize,
        item: String,
    },
    #[error("{what}: a range is START:STOP:COUNT (log spacing) with START and STOP finite and > 0 and COUNT a whole number from 1 to {most}, got '{text}'")]
    BadRange {
        what: &'static str,
        text: String,
        most: usize,
    },
    #[error("the loop samples must be 0 (no loop) or at least 2, got {value}")]
    BadLoopSamples { value: usize },
    #[error("the grid of {points} points ({amplitudes} amplitudes x {frequencies} frequencies) with {samples} loop samples each needs about {megabytes} MB, more than the limit of {limit_mb} MB: ask for fewer points or loop samples", megabytes = .bytes / 1_000_000, limit_mb = .limit / 1_000_000)]
    TooLarge {
        amplitudes: usize,
        frequencies: usize,
        points: u64,
        samples: usize,
        bytes: u64,
        limit: u64,
    },
    #[error("the input is not periodic: it ends at u = {last}, not where it starts (u = {first})", first = num(*.first), last = num(*.last))]
    NotPeriodic { first: f64, last: f64 },
    #[error("at amplitude {amplitude}, frequency {frequency}: {reason}", amplitude = num(*.amplitude), frequency = num(*.frequency))]
    AtPoint {
        amplitude: f64,
        frequency: f64,
        reason: SimulateError,
    },
    #[error("at amplitude {amplitude}, frequency {frequency}: the force or the energy per cycle overflows f64 (values too large for this model)", amplitude = num(*.amplitude), frequency = num(*.frequency))]
    Overflow { amplitude: f64, frequency: f64 },
    #[error(transparent)]
    Simulate(#[from] SimulateError),
}

/// An invalid closed-loop system or request, or a run that cannot be completed
/// ([`crate::dynamics`]).
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum DynamicsError {
    #[error("{name} must be a finite number > 0, got {value}", value = num(*.value))]
    NotPositive { name: &'static str, value: f64 },
    #[error("{name} must be a finite number >= 0, got {value}", value = num(*.value))]
    Negative { name: &'static str, value: f64 },
    #[error("{name} must be a finite number, got {value}", value = num(*.value))]
    NotFinite { name: &'static str, value: f64 },
    #[error("{what} needs as many times as values (at least one), got {times} times and {values} values")]
    BadProfile {
        what: &'static str,
        times: usize,
        values: usize,
    },
    #[error("{what}: point {index} is not a pair of finite numbers")]
    ProfileNotFinite { what: &'static str, index: usize },
    #[error("{what}: times must be strictly increasing, t = {value} follows t = {prev} (point {index})", value = num(*.value), prev = num(*.prev))]
    ProfileTimes {
        what: &'static str,
        index: usize,
        prev: f64,
        value: f64,
    },
    #[error("the tolerance {name} must be a number in (0, 1) (atol: > 0), got {value}", value = num(*.value))]
    BadTolerance { name: &'static str, value: f64 },
    /// The elasto-plastic break-away displacement outside `[0, min(Fc, Fs) / sigma0)`.
    #[error("zba must be a finite number >= 0 and < min(Fc, Fs) / sigma0 = {limit} (the break-away displacement below every steady-state deflection), got {value}", value = num(*.value), limit = num(*.limit))]
    BadBreakaway { value: f64, limit: f64 },
    /// Output times that are not finite, not increasing or outside the run.
    #[error(transparent)]
    Data(#[from] DataError),
    #[error("the motion overflows f64 near t = {t}", t = num(*.t))]
    Overflow { t: f64 },
    #[error("the integrator failed near t = {t}: {reason}", t = num(*.t))]
    Solver { t: f64, reason: String },
    #[error("{}", self.render(|f| f.name().to_string()))]
    Conflict {
        first: Field,
        second: Field,
        why: &'static str,
    },
    #[error("{}", self.render(|f| f.name().to_string()))]
    Needs {
        field: Field,
        /// One of these must be given too.
        needs: &'static [Field],
        why: &'static str,
    },
    #[error("{}", self.render(|f| f.name().to_string()))]
    BadValue {
        field: Field,
        rule: &'static str,
        value: f64,
    },
    #[error("{}", self.render(|f| f.name().to_string()))]
    Count {
        field: Field,
        value: u64,
        least: u64,
        most: u64,
    },
    #[error("{}", self.render(|f| f.name().to_string()))]
    NotNumbers { field: Field },
    #[error("{}", self.render(|f| f.name().to_string()))]
    NotPoints { field: Field },
    #[error("{}", self.render(|f| f.name().to_string()))]
    NoModel,
    /// A model of the zoo without a finite-rate form ([`crate::zoo::ZooModelSpec::finite_rate`]).
    #[error("model {model}: the dynamics take {takes} (the other models of the zoo have no finite-rate form here)")]
    NoFiniteRate {
        model: &'static str,
        /// The models the dynamics take (`crate::zoo::dynamics_model_names`).
        takes: String,
    },
    #[error("{}", self.render(|f| f.name().to_string()))]
    NoDrive,
    #[error("{}", self.render(|f| f.name().to_string()))]
    NoEnd { why: &'static str },
    #[error("unknown scenario '{name}' (scenarios: {})", .known.join(", "))]
    UnknownScenario {
        name: String,
        /// The scenarios there are.
        known: &'static [&'static str],
    },
    #[error(transparent)]
    Model(#[from] ModelError),
    /// A zoo model's values together, e.g. a scenario's `Fc` under a named `zba`.
    #[error(transparent)]
    Zoo(#[from] ZooError),
}

impl DynamicsError {
    /// The message with each request field spelled by `spell` (the command line's flags, the
    /// Python keywords): one wording for every front end. Other errors: their message.
    pub fn render(&self, spell: impl Fn(Field) -> String) -> String {
        match self {
            DynamicsError::Conflict { first, second, why } => format!(
                "give {} or {}, not both: {why}",
                spell(*first),
                spell(*second)
            ),
            DynamicsError::Needs { field, needs, why } => format!(
                "{} needs {} ({why})",
                spell(*field),
                needs.iter().map(|f| spell(*f)).collect::<Vec<_>>().join(" or ")
            ),
            DynamicsError::BadValue { field, rule, value } => {
                format!("{} must be {rule}, got {}", spell(*field), num(*value))
            }
            DynamicsError::Count {
                field,
                value,
                least,
                most,
            } if least == most => format!(
                "{} takes {least} number{}, got {value}",
                spell(*field),
                if *least == 1 { "" } else { "s" }
            ),
            DynamicsError::Count {
                field,
                value,
                least,
                most,
            } => format!(
                "{} must be a whole number from {least} to {most}, got {value}",
                spell(*field)
            ),
            DynamicsError::NotNumbers { field } => format!(
                "{} is not given as numbers (it takes points (t, value), a name or a model)",
                spell(*field)
            ),
            DynamicsError::NotPoints { field } => format!(
                "{} is not given as points (t, value): it takes numbers",
                spell(*field)
            ),
            DynamicsError::NoModel => format!(
                "name the friction model ({} or its parameters): forces of a physical system are not computed from the dimensionless defaults",
                spell(Field::Model)
            ),
            DynamicsError::NoDrive => format!(
                "no drive: give {}",
                [
                    Field::Scenario,
                    Field::Force,
                    Field::ForceRate,
                    Field::Input,
                    Field::Spring,
                    Field::Pid,
                    Field::Velocity
                ]
                .map(&spell)
                .iter()
                .fold(Vec::<&String>::new(), |mut seen, name| {
                    // A front end may spell two fields alike (Python's `force` takes both a
                    // profile and a measured history).
                    if !seen.contains(&name) {
                        seen.push(name);
                    }
                    seen
                })
                .iter()
                .map(|s| s.as_str())
                .collect::<Vec<_>>()
                .join(", ")
            ),
            DynamicsError::NoEnd { why } => {
                format!("give {} (the end of the run, s): {why}", spell(Field::TEnd))
            }
            // A profile of a request is named by its field.
            DynamicsError::BadProfile { what, .. }
            | DynamicsError::ProfileNotFinite { what, .. }
            | DynamicsError::ProfileTimes { what, .. } => {
                let text = self.to_string();
                match Field::from_name(what) {
                    Some(field) => text.replacen(what, &spell(field), 1),
                    None => text,
                }
            }
            other => other.to_string(),
        }
    }
}

/// A parameter the data do not determine, and why ([`crate::fit`] module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Unidentified {
    pub name: &'static str,
    /// Where the fit left it.
    pub value: f64,
    pub why: Why,
}

/// Why a parameter cannot be identified.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Why {
    /// Its column of the Jacobian, times its value, is negligible against the force
    /// (`sensitivity = |p J_p| / |F|`): it does not act on the output, or the fit drove it to 0.
    NoEffect { sensitivity: f64 },
    /// Its effect is nearly a combination of the others' (`condition` of the scaled normal
    /// matrix above `limit`).
    Collinear { condition: f64, limit: f64 },
    /// Its 95 % confidence interval reaches 0: `t se >= |value|`
    /// (`relative_half_width = t se / |value|`).
    WideInterval {
        stderr: f64,
        relative_half_width: f64,
    },
}

fn names_of(p: &[Unidentified]) -> String {
    p.iter().map(|u| u.name).collect::<Vec<_>>().join(", ")
}

fn reasons(p: &[Unidentified]) -> String {
    p.iter()
        .map(|u| {
            // A positive parameter the fit drove to its bound 0 (to a few hundred binades
            // below any scale of the problem): say so, rather than print a denormal.
            if matches!(u.why, Why::NoEffect { .. }) && u.value.abs() < AT_ZERO {
                format!("{} is at its bound 0 (fix it at 0)", u.name)
            } else {
                format!("{} = {:.4e} {}", u.name, u.value, why(&u.why))
            }
        })
        .collect::<Vec<_>>()
        .join("; ")
}

/// Below this a fitted parameter is at its bound 0.
const AT_ZERO: f64 = 1e-100;

/// Why a parameter is not identified, in words: every number in it is finite (an exactly
/// singular problem has an infinite condition number, which is said rather than printed).
fn why(why: &Why) -> String {
    match *why {
        Why::NoEffect { sensitivity } if sensitivity.is_finite() => format!(
            "has no effect on the output (relative sensitivity {sensitivity:.1e})"
        ),
        Why::NoEffect { .. } => "has no effect on the output".into(),
        Why::Collinear { condition, limit } if condition.is_finite() => format!(
            "acts nearly as a combination of the others (condition number {condition:.2e} of the scaled normal matrix, limit {limit:.0e})"
        ),
        Why::Collinear { .. } => "acts as an exact combination of the others: the parameters cannot be identified from these data (the problem is singular)".into(),
        Why::WideInterval {
            stderr,
            relative_half_width,
        } if stderr.is_finite() && relative_half_width.is_finite() => format!(
            "with standard error {stderr:.2e}: its 95 % interval reaches 0 (half-width {relative_half_width:.3}x the value)"
        ),
        Why::WideInterval { stderr, .. } if stderr.is_finite() => format!(
            "with standard error {stderr:.2e}: its 95 % interval reaches 0 (the estimate is 0)"
        ),
        Why::WideInterval { .. } => {
            "has no finite standard error: it cannot be identified from these data (the problem is singular)".into()
        }
    }
}

fn list(best: &[(&'static str, f64)]) -> String {
    best.iter()
        .map(|(n, v)| format!("{n} = {}", num(*v)))
        .collect::<Vec<_>>()
        .join(", ")
}

/// An invalid parameter of a model of [`crate::zoo`] (Maxwell-slip, Prandtl-Ishlinskii,
/// Bouc-Wen, elasto-plastic), or a loop of one that cannot be computed. Element parameters are
/// named with their index, scalar ones with their condition.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum ZooError {
    #[error("{name} needs at least one element, got none")]
    Empty { name: &'static str },
    #[error("{first} and {second} have different lengths ({n_first} and {n_second})")]
    LengthMismatch {
        first: &'static str,
        n_first: usize,
        second: &'static str,
        n_second: usize,
    },
    #[error("{name}[{index}] must be a finite number, got {value}", value = num(*.value))]
    NotFinite {
        name: &'static str,
        index: usize,
        value: f64,
    },
    #[error("{name}[{index}] must be > 0, got {value}", value = num(*.value))]
    NotPositive {
        name: &'static str,
        index: usize,
        value: f64,
    },
    #[error("{name}[{index}] must be >= 0, got {value}", value = num(*.value))]
    Negative {
        name: &'static str,
        index: usize,
        value: f64,
    },
    /// The initial-loading curve's slope `w0 + sum of the weights of thresholds <= r` is not
    /// positive on the stretch starting at threshold `r`.
    #[error("the initial-loading slope w0 + sum of weights with threshold <= {threshold} is {slope}; it must be > 0 (weights sorted by threshold)", threshold = num(*.threshold), slope = num(*.slope))]
    NotIncreasing { threshold: f64, slope: f64 },
    #[error("unknown model '{name}' (the models: {known})")]
    UnknownModel { name: String, known: String },
    #[error("the {model} model has no parameter '{name}' (its parameters: {known})")]
    UnknownParameter {
        model: &'static str,
        name: String,
        known: String,
    },
    #[error("{name} takes one value, got {count}")]
    NotScalar { name: &'static str, count: usize },
    /// A scalar parameter of a model outside its domain: `condition` says the domain and why
    /// (a value that is not finite is said in words).
    #[error("{name} must be {condition}, got {}", shown(*.value))]
    Domain {
        name: &'static str,
        value: f64,
        condition: String,
    },
    #[error("{elements} elements x {turning_points} turning points exceed the {limit} element states a loop may hold")]
    TooLarge {
        elements: usize,
        turning_points: usize,
        limit: usize,
    },
    #[error("{what} overflows f64 for this model and input")]
    Overflow { what: &'static str },
    /// An option of LuGre's and Dahl's simulation (an initial state, gamma, periods, output
    /// times, a sine, ...) given with a model of the zoo, which is simulated from rest at the
    /// input's own samples ([`crate::zoo::ZooModel::simulate`]); `option` as the front end
    /// spells it (`--x0`, `x0`).
    #[error("{option} is an option of LuGre's and Dahl's simulation; the {model} model is simulated from rest at the input's own samples")]
    SimulateOption { option: String, model: &'static str },
    /// A model without a finite-rate form asked to step at finite rate
    /// ([`crate::zoo::ZooModel::stepper`]).
    #[error("the {model} model has no finite-rate form: it is rate-independent, stepped by its exact segment map")]
    RateIndependent { model: &'static str },
    #[error(transparent)]
    Input(#[from] InputError),
    /// The finite-rate model's LuGre parts (`sigma0, sigma1, sigma2, fc, fs, vs, beta`).
    #[error(transparent)]
    Model(#[from] ModelError),
}

/// Any error of the library.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum Error {
    #[error(transparent)]
    Model(#[from] ModelError),
    #[error(transparent)]
    Input(#[from] InputError),
    #[error(transparent)]
    Loop(#[from] LoopError),
    #[error(transparent)]
    Samples(#[from] SamplesError),
    #[error(transparent)]
    History(#[from] HistoryError),
    #[error(transparent)]
    Simulate(#[from] SimulateError),
    #[error(transparent)]
    Fit(#[from] FitError),
    #[error(transparent)]
    Dynamics(#[from] DynamicsError),
    #[error(transparent)]
    Sweep(#[from] SweepError),
    #[error(transparent)]
    Zoo(#[from] ZooError),
}

#[cfg(test)]
mod tests {
    use super::*;

    fn message(why: Why) -> String {
        FitError::Unidentifiable {
            parameters: vec![Unidentified {
                name: "sigma1",
                value: 0.5,
                why,
            }],
        }
        .to_string()
    }

    /// Not a word "inf" or "NaN" in any reason, whatever the statistics are.
    fn finite_words(text: &str) -> bool {
        !text
            .split(|c: char| !c.is_ascii_alphanumeric())
            .any(|w| ["nan", "inf", "infinity"].contains(&w.to_ascii_lowercase().as_str()))
    }

    #[test]
    fn numbers_in_messages() {
        assert_eq!(num(0.0), "0");
        assert_eq!(num(-0.001), "-0.001");
        assert_eq!(num(123456.0), "123456");
        assert_eq!(num(1e299), "1e299");
        assert_eq!(num(-2.5e-300), "-2.5e-300");
        assert_eq!(num(0.1 + 0.2), "0.30000000000000004");
        for x in [1e299, 1.0 / 3.0, -7e-6, 1e16, 9.999e15] {
            assert_eq!(num(x).parse::<f64>().unwrap(), x);
        }
    }

    #[test]
    fn a_singular_problem_is_said_in_words() {
        let finite = message(Why::Collinear {
            condition: 3.5e12,
            limit: 1e10,
        });
        assert!(finite.contains("condition number 3.50e12"), "{finite}");
        for condition in [f64::INFINITY, f64::NAN] {
            let e = message(Why::Collinear {
                condition,
                limit: 1e10,
            });
            assert!(finite_words(&e), "{e}");
            assert!(e.contains("(the problem is singular)"), "{e}");
            assert!(e.starts_with("sigma1 cannot be identified from this data: sigma1 = 5.0000e-1 acts as an exact combination"), "{e}");
        }
        for (stderr, relative_half_width) in [
            (f64::INFINITY, f64::INFINITY),
            (f64::NAN, f64::NAN),
            (0.1, f64::NAN),
            (0.1, f64::INFINITY),
        ] {
            let e = message(Why::WideInterval {
                stderr,
                relative_half_width,
            });
            assert!(finite_words(&e), "{e}");
        }
        let e = message(Why::NoEffect {
            sensitivity: f64::NAN,
        });
        assert!(
            finite_words(&e) && e.ends_with("has no effect on the output"),
            "{e}"
        );
        let e = message(Why::WideInterval {
            stderr: 0.25,
            relative_half_width: 2.0,
        });
        assert!(
            e.ends_with(
                "standard error 2.50e-1: its 95 % interval reaches 0 (half-width 2.000x the value)"
            ),
            "{e}"
        );
    }

    /// A parameter driven to its bound is said to be there, not printed as a denormal; a fit
    /// with no start to stand on says so without an infinite residual.
    #[test]
    fn a_bound_and_a_fit_without_a_start_in_words() {
        let e = FitError::Unidentifiable {
            parameters: vec![Unidentified {
                name: "sigma2",
                value: 3.0e-314,
                why: Why::NoEffect {
                    sensitivity: 1.7e-315,
                },
            }],
        }
        .to_string();
        assert_eq!(
            e,
            "sigma2 cannot be identified from this data: sigma2 is at its bound 0 (fix it at 0)"
        );
        let e = FitError::NoStart { starts: 4 }.to_string();
        assert!(finite_words(&e) && e.contains("any of the 4 starts"), "{e}");
    }
}
