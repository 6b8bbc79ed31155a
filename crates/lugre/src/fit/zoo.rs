//! The slow-loop fit of a model of the zoo ([`crate::zoo::MODELS`]) to a measured `(u, F)`
//! record: one or more periods of a slow periodic test, read as the LuGre slow fit reads it
//! (the record closes from its last sample to its first; its reversals estimated between the
//! samples, [`super::slow`]), generic over the model table
//! (`docs/mathematics.md#slow-loop-fit-of-the-zoos-models`).
//!
//! Sample `i` lies at `rho_i` on the periodic input of the record's turning points; the model
//! `M(q)` with parameters `q` gives the exact periodic response `y(rho_i; q)` there
//! ([`crate::zoo::ZooModel::points`]: the segment maps from the periodic state), and
//!
//! ```text
//! (ZF1)  q^ = argmin_q  sum_i (y(rho_i; q) - F_i)^2,     lo_j < q_j < hi_j
//! ```
//!
//! with the bounds of each parameter's domain in the table (`> 0`, `>= 0`: `(0, inf)`;
//! `[lo, hi]`: `(lo, hi)`), built into the variables by the log and logistic maps of the LuGre
//! fit, by its Levenberg-Marquardt iteration. The derivatives are central differences,
//!
//! ```text
//! (ZF2)  dy/dq_j = (y(q + h e_j) - y(q - h e_j)) / (2 h),     h = 6e-6 |q_j|
//! ```
//!
//! (one-sided where a bound is nearer than `h`): error `O(h^2) ~ 4e-11` relative, far below any
//! standard error. A sample whose output jumps inside the step (GMS: an element's switch from
//! sticking to slipping crossing the sample's instant) takes the one-sided difference that does
//! not cross the jump (ZF2', `central_across_jumps`): the central one would be the jump over
//! `2 h`, and the parameter's standard error near 0. The Masing models' output is linear in the weights: there `h = |q_j| / 2`,
//! and (ZF2) is exact, with no rounding of a small step in it.
//!
//! **Element models** (Maxwell-slip, Prandtl-Ishlinskii). As in the laboratory, each element's
//! threshold (the slip displacement `Delta_i = f_i / k_i`, the play threshold `r_i`) is held on
//! a grid spanning the record's amplitude `A = (u_max - u_min) / 2`, or given,
//!
//! ```text
//! (ZF3)  r_i = A (2 i + 1) / (2 N),     i = 0 .. N - 1
//! ```
//!
//! (no threshold 0: a play of threshold 0 is the input itself, collinear with `w0`). The
//! output is then linear in the weights `w = (k_i)` or `(w0, w_i)`, `y = J w` (Z2): the start
//! is the linear least-squares solution of `J w = F` (exact for noise-free data), each weight
//! pulled inside `(0, inf)` (the fit keeps weights positive: the loading curve then rises, and
//! the inverse a compensator needs exists), and (ZF1) with log maps refines it and gives the
//! intervals. An element whose threshold reaches `A` never slips in the periodic loop: its
//! weight has no effect (Prandtl-Ishlinskii) or only that of a spring, and the fit names it
//! as not identifiable.
//!
//! **Single-state models** (Bouc-Wen, elasto-plastic). (ZF1) on their scalars, started from
//! the data: the loop's initial slope `s0` and plateau `g0` ([`SlowLoop::data_start`]) give
//! Bouc-Wen's `kw = g0`, `rho = s0 / g0`, `kx = s0 / 100`, `sigma = 1`, `n = 2`, and the
//! elasto-plastic `sigma0 = s0`, `fs = g0`, `zba = 0.3 fs / sigma0`. A parameter that does
//! not enter the slow loop (elasto-plastic: `fc`, `sigma1`, `sigma2`, `vs`, `beta`) is held
//! and refused if freed ([`FitError::NotInZooSlowLoop`]); the loop is evaluated with
//! `fc = fs`, which meets the model's constraint `zba < fc / sigma0` wherever the loop itself
//! is defined (`zba < fs / sigma0`).
//!
//! A start given ([`ZooFitSpec::set`], a front end's model object) is used as it is, except on
//! the edge of its domain (Bouc-Wen's default `kx = 0`, `n = 1`), where the maps have no
//! variable: that parameter starts from the data.
//!
//! Standard errors, intervals, identifiability, at-bound reports and lack-of-fit warnings are
//! the LuGre fit's (S1-S4, C1-C4): one set of rules for every model.

use super::covariance::{lack_of_fit, SerialCorrelation};
use super::lm::{minimize, Evaluator, Outcome, Space};
use super::slow::SlowLoop;
use super::spec::{Bounds, FitKind};
use super::{
    assess, bound_warnings, check_columns, check_count, slow_gate, Covariance, Estimate, FitError,
    FitWarning, FreeEnd, NoiseLevels, SlowOptions, SLOW_CONFIG,
};
use crate::error::ZooError;
use crate::input::TurningPoints;
use crate::zoo::{Domain, Shape, ZooModel, ZooModelSpec};
use nalgebra::DMatrix;

mod full;
pub use full::fit_zoo_full;

/// Elements an element model's fit has unless told otherwise.
pub const DEFAULT_ELEMENTS: usize = 4;
/// The most elements a fit takes.
pub const MAX_ELEMENTS: usize = 64;

/// The relative step of the central differences (ZF2): `eps^(1/3)`.
const STEP: f64 = 6e-6;
/// The relative step for an element model, whose output is linear in every number the fit
/// moves: the difference is then exact for any step, and a large one keeps rounding out of it
/// (a weight without effect then shows a column of exact zeros).
const LINEAR_STEP: f64 = 0.5;

/// How an element model's elements enter the fit: the weight parameter, and the threshold.
#[derive(Debug, Clone, Copy)]
struct Elements {
    weight: &'static str,
    threshold: Threshold,
}

#[derive(Debug, Clone, Copy)]
enum Threshold {
    /// The threshold is a parameter itself (Prandtl-Ishlinskii's `thresholds`).
    Parameter(&'static str),
    /// The parameter named is weight × threshold (Maxwell-slip's `slip_force = k Delta`).
    Product(&'static str),
}

impl Elements {
    /// Whether the parameter `name` is the elements' weight or threshold.
    fn holds(&self, name: &str) -> bool {
        self.weight == name
            || matches!(self.threshold, Threshold::Parameter(t) | Threshold::Product(t) if t == name)
    }
}

/// What a model needs of the fit beyond its table entry.
fn elements_of(model: &ZooModelSpec) -> Option<Elements> {
    match model.name {
        "maxwell-slip" => Some(Elements {
            weight: "stiffness",
            threshold: Threshold::Product("slip_force"),
        }),
        "prandtl-ishlinskii" => Some(Elements {
            weight: "weights",
            threshold: Threshold::Parameter("thresholds"),
        }),
        _ => None,
    }
}

/// The parameters of `model` its slow loop does not depend on (the table's
/// [`crate::zoo::ZooParameter::slow_loop`]).
fn outside_slow_loop(model: &ZooModelSpec) -> Vec<&'static str> {
    let outside = model.parameters.iter().filter(|p| !p.slow_loop);
    outside.map(|p| p.name).collect()
}

/// The start of a single-state model's parameter from the loop's initial slope `s0` and
/// plateau `g0` (module docs).
fn data_start(name: &str, s0: f64, g0: f64) -> Option<f64> {
    Some(match name {
        "kx" => 0.01 * s0,
        "kw" | "fs" => g0,
        // The slope after a reversal from w = 1 is kx + 2 sigma kw rho (B2).
        "rho" => 0.5 * s0 / g0,
        "sigma" => 1.0,
        "n" => 2.0,
        "sigma0" => s0,
        "zba" => 0.3 * g0 / s0,
        _ => return None,
    })
}

/// The request: the model, values (held parameters keep them, free ones start there), which
/// parameters are held or freed, and an element model's elements.
#[derive(Debug, Clone, PartialEq)]
pub struct ZooFitSpec {
    model: &'static ZooModelSpec,
    values: Vec<(&'static str, Vec<f64>)>,
    fixed: Vec<&'static str>,
    freed: Vec<&'static str>,
    elements: Option<usize>,
    thresholds: Option<Vec<f64>>,
}

impl ZooFitSpec {
    /// The fit of the model `name` of the table; every parameter of its slow loop free.
    ///
    /// # Errors
    /// [`ZooError::UnknownModel`] naming the models.
    pub fn new(name: &str) -> Result<Self, FitError> {
        let model = ZooModelSpec::find(name).ok_or_else(|| ZooError::UnknownModel {
            name: name.trim().to_string(),
            known: crate::zoo::model_names(),
        })?;
        Ok(Self {
            model,
            values: Vec::new(),
            fixed: Vec::new(),
            freed: Vec::new(),
            elements: None,
            thresholds: None,
        })
    }

    /// The model's entry in the table.
    pub fn model(&self) -> &'static ZooModelSpec {
        self.model
    }

    fn parameter(&self, name: &str) -> Result<&'static str, FitError> {
        let p = self
            .model
            .parameter(name)
            .ok_or_else(|| ZooError::UnknownParameter {
                model: self.model.name,
                name: name.trim().to_string(),
                known: self.model.parameter_names(),
            })?;
        Ok(p.name)
    }

    /// The value(s) of `name`: kept if it is held, the start if it is free (an element
    /// model's weights: one per element).
    pub fn set(mut self, name: &str, values: &[f64]) -> Result<Self, FitError> {
        let name = self.parameter(name)?;
        self.values.retain(|(n, _)| *n != name);
        self.values.push((name, values.to_vec()));
        Ok(self)
    }

    /// Holds `name` at its value (given with [`Self::set`], else the table's default).
    pub fn fix(mut self, name: &str) -> Result<Self, FitError> {
        let name = self.parameter(name)?;
        self.fixed.push(name);
        Ok(self)
    }

    /// Fits `name`: refused at the fit for a parameter outside the slow loop.
    pub fn free(mut self, name: &str) -> Result<Self, FitError> {
        let name = self.parameter(name)?;
        self.freed.push(name);
        Ok(self)
    }

    /// The number of elements of an element model (default [`DEFAULT_ELEMENTS`], or the
    /// count of the thresholds given).
    pub fn with_elements(mut self, count: usize) -> Self {
        self.elements = Some(count);
        self
    }

    /// The element thresholds (`Delta_i`, `r_i`), held, instead of the grid (ZF3).
    pub fn with_thresholds(mut self, thresholds: &[f64]) -> Self {
        self.thresholds = Some(thresholds.to_vec());
        self
    }

    fn given(&self, name: &str) -> Option<&[f64]> {
        self.values
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, v)| v.as_slice())
    }
}

/// One number of the fit: a scalar parameter or one element's weight.
#[derive(Debug, Clone, Copy)]
struct Slot {
    /// The name in reports: `kw`, `stiffness[2]`.
    name: &'static str,
    parameter: &'static str,
}

/// The fit's numbers and how they make a model.
#[derive(Debug, Clone)]
struct Layout {
    model: &'static ZooModelSpec,
    elements: Option<(Elements, Vec<f64>)>,
    slots: Vec<Slot>,
    /// The values of the parameters the slots do not hold.
    rest: Vec<(&'static str, Vec<f64>)>,
    /// The slow-loop fit's layout: `fc` follows `fs` (module docs).
    slow: bool,
}

/// `param[i]` as a name that lives as long as the program (at most [`MAX_ELEMENTS`] per
/// element parameter of the table are ever made).
fn element_name(param: &'static str, i: usize) -> &'static str {
    use std::collections::HashMap;
    use std::sync::{Mutex, OnceLock};
    static NAMES: OnceLock<Mutex<HashMap<(&'static str, usize), &'static str>>> = OnceLock::new();
    let mut names = NAMES
        .get_or_init(Default::default)
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    names
        .entry((param, i))
        .or_insert_with(|| Box::leak(format!("{param}[{i}]").into_boxed_str()))
}

impl Layout {
    /// The model for the slot values `v`.
    fn build(&self, v: &[f64]) -> Result<ZooModel, ZooError> {
        let mut given: Vec<(&str, Vec<f64>)> = self.rest.clone();
        if let Some((e, thresholds)) = &self.elements {
            let n = thresholds.len();
            let w = &v[v.len() - n..];
            given.push((e.weight, w.to_vec()));
            given.push(match e.threshold {
                Threshold::Parameter(p) => (p, thresholds.clone()),
                Threshold::Product(p) => {
                    (p, w.iter().zip(thresholds).map(|(w, r)| w * r).collect())
                }
            });
        }
        let scalars = v.len() - self.elements.as_ref().map_or(0, |(_, t)| t.len());
        for (s, &x) in self.slots[..scalars].iter().zip(v) {
            given.push((s.parameter, vec![x]));
        }
        // fc does not enter the slow loop: held at fs there (module docs).
        if self.slow && outside_slow_loop(self.model).contains(&"fc") {
            let fs = given
                .iter()
                .find(|(n, _)| *n == "fs")
                .map(|(_, v)| v.clone());
            if let Some(fs) = fs {
                given.push(("fc", fs));
            }
        }
        let refs: Vec<(&str, &[f64])> = given.iter().map(|(n, v)| (*n, v.as_slice())).collect();
        ZooModel::new(self.model.name, &refs)
    }

    /// The bounds of slot `s`, from its domain (`>= 0` and a finite domain of weights: `(0, inf)`).
    fn bounds(&self, s: &Slot) -> Bounds {
        match self.model.parameter(s.parameter).map(|p| p.domain) {
            Some(Domain::Closed(lo, hi)) => Bounds { lo, hi },
            _ => Bounds::POSITIVE,
        }
    }
}

/// What the model's output is matched with.
#[derive(Debug, Clone)]
enum Response {
    /// The periodic loop at the samples' places (ZF1).
    Loop { tp: TurningPoints, rhos: Vec<f64> },
    /// The path from rest along the samples: at their rate (ZF4), or (`rate` false) the
    /// rate-independent path, the start's linear solve for an element model's weights.
    Path {
        t: Vec<f64>,
        u: Vec<f64>,
        rate: bool,
    },
}

/// The model evaluated on the record ([`Response`]), with (ZF2).
struct Output<'a> {
    layout: &'a Layout,
    response: Response,
    free: Vec<usize>,
    bounds: Vec<Bounds>,
    /// [`STEP`] or [`LINEAR_STEP`].
    step: f64,
}

impl Output<'_> {
    fn y(&self, v: &[f64]) -> Option<Vec<f64>> {
        let model = self.layout.build(v).ok()?;
        let y: Vec<f64> = match &self.response {
            Response::Loop { tp, rhos } => {
                let hl = model.loops(tp).ok()?;
                model.points(&hl, rhos).iter().map(|p| p.y).collect()
            }
            Response::Path { t, u, rate: true } => model.simulate(t, u).ok()?,
            Response::Path { u, .. } => model.exact_path(u).ok()?,
        };
        y.iter().all(|x| x.is_finite()).then_some(y)
    }
}

impl Evaluator for Output<'_> {
    fn evaluate(&mut self, values: &[f64], y: &mut [f64], jac: &mut DMatrix<f64>) -> bool {
        let Some(y0) = self.y(values) else {
            return false;
        };
        y.copy_from_slice(&y0);
        let mut v = values.to_vec();
        for (c, &i) in self.free.iter().enumerate() {
            let (p, b) = (values[i], self.bounds[c]);
            let h = self.step * p.abs().max(f64::MIN_POSITIVE);
            let (up, down) = (p + h < b.hi, p - h > b.lo);
            let mut at = |x: f64| {
                v[i] = x;
                let out = self.y(&v);
                v[i] = p;
                out
            };
            let column: Option<Vec<f64>> = match (up, down) {
                (true, true) => at(p + h)
                    .zip(at(p - h))
                    .map(|(a, b)| central_across_jumps(&y0, &a, &b, h)),
                (true, false) => {
                    at(p + h).map(|a| a.iter().zip(&y0).map(|(a, b)| (a - b) / h).collect())
                }
                _ => at(p - h).map(|b| y0.iter().zip(&b).map(|(a, b)| (a - b) / h).collect()),
            };
            let Some(column) = column else {
                return false;
            };
            for (r, d) in column.into_iter().enumerate() {
                jac[(r, c)] = d;
            }
        }
        true
    }
}

/// A sample's second difference above this fraction of the largest output is a jump of the
/// output inside the step, not curvature: a smooth output's is `h^2 q^2 y''`, about `4e-11`
/// of the force at the step `6e-6` (rounding `1e-15`), while GMS's force jumps by
/// `sigma1 k_i |v| / K` where a switch from sticking to slipping crosses a sample (ZF2').
const JUMP: f64 = 1e-8;

/// The column (ZF2) from `y(q + h)` (`up`) and `y(q - h)` (`down`) about `y0 = y(q)`: the
/// central difference at each sample, except where the sample's output jumps inside
/// `[q - h, q + h]`; there the one-sided difference that does not cross the jump (the smaller:
/// the other is the jump over `h`), the derivative of the piece `q` lies on (ZF2').
fn central_across_jumps(y0: &[f64], up: &[f64], down: &[f64], h: f64) -> Vec<f64> {
    let scale = y0.iter().fold(0.0f64, |m, y| m.max(y.abs()));
    let jumps = |y: f64, a: f64, b: f64| (a - 2.0 * y + b).abs() > JUMP * scale;
    let one_sided = |y: f64, a: f64, b: f64| {
        let (forward, backward) = ((a - y) / h, (y - b) / h);
        if forward.abs() <= backward.abs() {
            forward
        } else {
            backward
        }
    };
    y0.iter()
        .zip(up.iter().zip(down))
        .map(|(&y, (&a, &b))| match jumps(y, a, b) {
            true => one_sided(y, a, b),
            false => (a - b) / (2.0 * h),
        })
        .collect()
}

/// The result of a zoo model's fit: the LuGre fit's report with the model.
#[derive(Debug, Clone, PartialEq)]
pub struct ZooFitReport {
    /// [`FitKind::Slow`] ([`fit_zoo`]) or [`FitKind::Full`] ([`fit_zoo_full`]).
    pub kind: FitKind,
    /// The fitted model (every parameter by name: [`ZooModel::named`]).
    pub model: ZooModel,
    /// The fitted numbers: scalars by name, element weights as `name[i]`.
    pub estimates: Vec<Estimate>,
    /// The parameters held, with their values (an element model's thresholds among them).
    pub fixed: Vec<(&'static str, Vec<f64>)>,
    /// Residual RMS `sqrt(RSS / m)`.
    pub rms: f64,
    pub samples: usize,
    /// Degrees of freedom `m - p`.
    pub dof: usize,
    /// The factor of the 95 % intervals, `t_{0.975, m-p}`.
    pub t_quantile: f64,
    pub condition_number: f64,
    pub correlation: Vec<Vec<f64>>,
    pub iterations: usize,
    pub evaluations: usize,
    /// The starts the fit ran from (the slow fit: 1).
    pub starts: usize,
    pub converged: bool,
    pub termination: String,
    /// Turning points of the record.
    pub turning_points: usize,
    /// The model's response at every sample: periodic (slow), from rest at its rate (full).
    pub fitted: Vec<f64>,
    pub noise: NoiseLevels,
    pub warnings: Vec<FitWarning>,
    pub covariance: Covariance,
    pub serial: SerialCorrelation,
}

impl ZooFitReport {
    pub fn estimate(&self, name: &str) -> Option<&Estimate> {
        self.estimates.iter().find(|e| e.name == name)
    }

    /// The sum of squared residuals.
    pub fn rss(&self) -> f64 {
        self.rms * self.rms * self.samples as f64
    }

    /// The view the front ends show, as for the LuGre fit.
    pub fn summary(&self) -> super::FitSummary<'_> {
        super::FitSummary {
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
            turning_points: (self.kind == FitKind::Slow).then_some(self.turning_points),
            noise: Some(&self.noise),
            warnings: &self.warnings,
            covariance: self.covariance,
            serial: &self.serial,
            fitted: &self.fitted,
        }
    }
}

/// The slow-loop fit (ZF1) of `spec`'s model to `(u_i, F_i)`: one or more periods of a slow
/// periodic test. See the module docs.
///
/// # Errors
/// The LuGre slow fit's ([`super::fit_slow_with`]), and [`FitError::NotInZooSlowLoop`],
/// [`FitError::BadElements`], [`FitError::NoElements`], [`FitError::Zoo`] for a value outside
/// its domain.
pub fn fit_zoo(
    spec: &ZooFitSpec,
    u: &[f64],
    f: &[f64],
    options: SlowOptions,
) -> Result<ZooFitReport, FitError> {
    check_columns(&[("u", u), ("F", f)])?;
    let (gate, levels) = slow_gate(u, f, options)?;
    let sl = SlowLoop::placement(u, gate)?;
    let tp = sl.turning_points().clone();
    let (layout, free, mut values) = lay_out(spec, tp.values(), FitKind::Slow)?;
    check_count(u.len(), free.len())?;
    let (given, bounds) = given_and_bounds(spec, &layout, &free, &values);
    let turning_points = tp.len();
    let mut out = Output {
        layout: &layout,
        response: Response::Loop {
            tp,
            rhos: sl.sample_rho(),
        },
        free: free.clone(),
        bounds: bounds.clone(),
        step: if layout.elements.is_some() {
            LINEAR_STEP
        } else {
            STEP
        },
    };
    start(&mut out, &sl, u, f, &given, &mut values)?;
    for (j, &i) in free.iter().enumerate() {
        values[i] = bounds[j].pull_inside(values[i]);
    }
    let start_values: Vec<f64> = free.iter().map(|&i| values[i]).collect();
    let space = Space {
        values: &values,
        free: &free,
        bounds: &bounds,
    };
    let (_, outcome) = minimize(out, f, space, &start_values, SLOW_CONFIG, &mut |_, _| {});
    if !outcome.rss.is_finite() {
        return Err(FitError::NoStart { starts: 1 });
    }
    let end = End {
        kind: FitKind::Slow,
        layout: &layout,
        free: &free,
        bounds: &bounds,
        starts: (1, &start_values),
        turning_points,
        levels,
    };
    conclude(end, outcome, f)
}

/// Which values were given as starts (and lie inside their domains), and each free slot's
/// bounds.
fn given_and_bounds(
    spec: &ZooFitSpec,
    layout: &Layout,
    free: &[usize],
    values: &[f64],
) -> (Vec<bool>, Vec<Bounds>) {
    let bounds: Vec<Bounds> = free
        .iter()
        .map(|&i| layout.bounds(&layout.slots[i]))
        .collect();
    // A start given on the edge of its domain (a model's kx = 0, n = 1) starts from the data
    // instead: the log and logistic maps have no variable there.
    let given = free
        .iter()
        .zip(&bounds)
        .map(|(&i, b)| spec.given(layout.slots[i].parameter).is_some() && b.contains(values[i]))
        .collect();
    (given, bounds)
}

/// A fit's end: what it fitted, and how it began.
struct End<'a> {
    kind: FitKind,
    layout: &'a Layout,
    free: &'a [usize],
    bounds: &'a [Bounds],
    /// The number of starts, and the free values of the first.
    starts: (usize, &'a [f64]),
    turning_points: usize,
    levels: NoiseLevels,
}

/// The report of the fit that ended at `outcome`: statistics, identifiability, warnings.
fn conclude(end: End<'_>, outcome: Outcome, f: &[f64]) -> Result<ZooFitReport, FitError> {
    let End {
        kind,
        layout,
        free,
        bounds,
        starts: (starts, start_values),
        turning_points,
        levels,
    } = end;
    let model = layout.build(&outcome.values)?;
    let fitted = outcome.y.clone();
    let names: Vec<&'static str> = free.iter().map(|&i| layout.slots[i].name).collect();
    let est: Vec<f64> = free.iter().map(|&i| outcome.values[i]).collect();
    let residuals: Vec<f64> = f.iter().zip(&fitted).map(|(f, y)| f - y).collect();
    let data_norm = f.iter().map(|v| v * v).sum::<f64>().sqrt();
    let free_end = FreeEnd {
        names: &names,
        values: &est,
        starts: start_values,
        bounds,
    };
    let (estimates, unc) = assess(&outcome, free_end, &residuals, data_norm, &[])?;
    let converged = outcome.converged();
    let m = f.len();
    let rms = (residuals.iter().map(|r| r * r).sum::<f64>() / m as f64).sqrt();
    let f_rms = data_norm / (m as f64).sqrt();
    let mut warnings = bound_warnings(&estimates, bounds);
    warnings.extend(lack_of_fit(
        &residuals,
        rms,
        f_rms,
        Some(levels.force),
        kind == FitKind::Slow,
    ));
    let fixed = held(layout, free, &outcome.values);
    Ok(ZooFitReport {
        kind,
        model,
        estimates,
        fixed,
        rms,
        samples: m,
        dof: m - free.len(),
        t_quantile: unc.t,
        condition_number: unc.condition,
        correlation: unc.correlation,
        iterations: outcome.iterations,
        evaluations: outcome.evaluations,
        starts,
        converged,
        termination: outcome.reason(),
        turning_points,
        fitted,
        noise: levels,
        warnings,
        covariance: unc.method,
        serial: SerialCorrelation::of(&residuals),
    })
}

/// The held parameters with their values: scalar slots not free, and the thresholds.
fn held(layout: &Layout, free: &[usize], values: &[f64]) -> Vec<(&'static str, Vec<f64>)> {
    let mut out: Vec<(&'static str, Vec<f64>)> = (0..layout.slots.len())
        .filter(|i| !free.contains(i))
        .map(|i| (layout.slots[i].name, vec![values[i]]))
        .collect();
    if let Some((e, t)) = &layout.elements {
        let name = match e.threshold {
            Threshold::Parameter(p) => p,
            Threshold::Product(_) => "slip_displacement",
        };
        out.push((name, t.clone()));
    }
    out
}

/// The slots, the free ones, and every slot's value (given, or the table's default).
fn lay_out(
    spec: &ZooFitSpec,
    turning: &[f64],
    kind: FitKind,
) -> Result<(Layout, Vec<usize>, Vec<f64>), FitError> {
    let model = spec.model;
    // The full fit has every parameter of the table in its response.
    let slow = kind == FitKind::Slow;
    let outside = if slow {
        outside_slow_loop(model)
    } else {
        Vec::new()
    };
    check_freed(spec, &outside)?;
    let elements = elements_for(spec, turning)?;
    let (mut slots, mut values, rest) = scalar_slots(spec, elements.as_ref(), &outside)?;
    if let Some((e, t)) = &elements {
        push_weights(spec, e, t.len(), &mut slots, &mut values);
    }
    let free: Vec<usize> = (0..slots.len())
        .filter(|&i| !spec.fixed.contains(&slots[i].parameter))
        .collect();
    if free.is_empty() {
        return Err(FitError::NothingToFit { fit: kind.label() });
    }
    let layout = Layout {
        model,
        elements,
        slots,
        rest,
        slow,
    };
    // A held value outside its domain is named now, not found unevaluable in the fit.
    layout.build(&values)?;
    Ok((layout, free, values))
}

/// Refuses a parameter both held and freed, or freed though `outside` the fit's response.
fn check_freed(spec: &ZooFitSpec, outside: &[&'static str]) -> Result<(), FitError> {
    for &name in &spec.freed {
        if spec.fixed.contains(&name) {
            return Err(FitError::FixedAndFree { name });
        }
        if outside.contains(&name) {
            return Err(FitError::NotInZooSlowLoop {
                name,
                model: spec.model.name,
                slow: slow_names(spec.model),
            });
        }
    }
    Ok(())
}

/// An element model's elements with their thresholds; elements asked of another model refused.
fn elements_for(
    spec: &ZooFitSpec,
    turning: &[f64],
) -> Result<Option<(Elements, Vec<f64>)>, FitError> {
    let model = spec.model;
    match elements_of(model) {
        Some(e) => Ok(Some((e, thresholds(spec, e, turning)?))),
        None if spec.elements.is_some() || spec.thresholds.is_some() => Err(FitError::NoElements {
            model: model.name,
            known: model.parameter_names(),
        }),
        None => Ok(None),
    }
}

/// The scalar slots with their values (given, or the table's default), and the values of the
/// parameters neither a scalar slot nor the elements' (an array, or `outside` the response).
type Scalars = (Vec<Slot>, Vec<f64>, Vec<(&'static str, Vec<f64>)>);

/// The slots of the scalars the fit moves (module docs), in the table's order.
fn scalar_slots(
    spec: &ZooFitSpec,
    elements: Option<&(Elements, Vec<f64>)>,
    outside: &[&'static str],
) -> Result<Scalars, FitError> {
    let (mut slots, mut values, mut rest) = (Vec::new(), Vec::new(), Vec::new());
    for p in spec.model.parameters {
        let value = spec
            .given(p.name)
            .map_or_else(|| p.default.to_vec(), <[f64]>::to_vec);
        // The weights and thresholds are the elements' slots and held values.
        if elements.is_some_and(|(e, _)| e.holds(p.name)) {
            continue;
        }
        if p.shape != Shape::Scalar || outside.contains(&p.name) {
            rest.push((p.name, value));
            continue;
        }
        if value.len() != 1 {
            return Err(ZooError::NotScalar {
                name: p.name,
                count: value.len(),
            }
            .into());
        }
        slots.push(Slot {
            name: p.name,
            parameter: p.name,
        });
        values.push(value[0]);
    }
    Ok((slots, values, rest))
}

/// One slot per element for its weight, started at the weight given (else 1).
fn push_weights(
    spec: &ZooFitSpec,
    e: &Elements,
    count: usize,
    slots: &mut Vec<Slot>,
    values: &mut Vec<f64>,
) {
    let given = spec.given(e.weight);
    for i in 0..count {
        slots.push(Slot {
            name: element_name(e.weight, i),
            parameter: e.weight,
        });
        values.push(given.and_then(|g| g.get(i).copied()).unwrap_or(1.0));
    }
}

/// The slow loop's parameters of `model`, comma-separated (for the refusal).
fn slow_names(model: &ZooModelSpec) -> String {
    let outside = outside_slow_loop(model);
    let names: Vec<&str> = model
        .parameters
        .iter()
        .map(|p| p.name)
        .filter(|n| !outside.contains(n))
        .collect();
    names.join(", ")
}

/// The thresholds given ([`ZooFitSpec::with_thresholds`], else a model's own: Prandtl-Ishlinskii's
/// `thresholds`, Maxwell-slip's `slip_force / stiffness` when both are given), or the grid (ZF3)
/// on the turning points' amplitude.
fn thresholds(spec: &ZooFitSpec, e: Elements, turning: &[f64]) -> Result<Vec<f64>, FitError> {
    let own = match e.threshold {
        Threshold::Parameter(p) => spec.given(p).map(<[f64]>::to_vec),
        Threshold::Product(p) => spec
            .given(p)
            .zip(spec.given(e.weight))
            .filter(|(f, k)| f.len() == k.len())
            .map(|(f, k)| f.iter().zip(k).map(|(f, k)| f / k).collect()),
    };
    let spec = &ZooFitSpec {
        thresholds: spec.thresholds.clone().or(own),
        ..spec.clone()
    };
    if let Some(t) = &spec.thresholds {
        let count = spec.elements.unwrap_or(t.len());
        if count != t.len() {
            return Err(FitError::BadElements {
                count,
                most: MAX_ELEMENTS,
            });
        }
        let name = match e.threshold {
            Threshold::Parameter(p) => p,
            Threshold::Product(_) => "thresholds",
        };
        crate::zoo::check_elements(name, t, matches!(e.threshold, Threshold::Product(_)))?;
    }
    let n = spec
        .thresholds
        .as_ref()
        .map_or(spec.elements.unwrap_or(DEFAULT_ELEMENTS), Vec::len);
    if n == 0 || n > MAX_ELEMENTS {
        return Err(FitError::BadElements {
            count: n,
            most: MAX_ELEMENTS,
        });
    }
    if let Some(t) = &spec.thresholds {
        return Ok(t.clone());
    }
    let (lo, hi) = turning
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    let amplitude = 0.5 * (hi - lo);
    Ok((0..n)
        .map(|i| amplitude * (2 * i + 1) as f64 / (2 * n) as f64)
        .collect())
}

/// Start values for the free slots not given: linear least squares for an element model's
/// weights, the data's slope and plateau for a single-state model (module docs).
fn start(
    out: &mut Output<'_>,
    sl: &SlowLoop,
    u: &[f64],
    f: &[f64],
    given: &[bool],
    values: &mut [f64],
) -> Result<(), FitError> {
    let free = out.free.clone();
    if out.layout.elements.is_some() {
        return linear_start(out, f, given, values);
    }
    let (relaxing, g0) = sl.data_start(f)?;
    let s0 = initial_slope(u, f, sl.reversal_samples()).unwrap_or(relaxing);
    for (c, &i) in free.iter().enumerate() {
        if given[c] {
            continue;
        }
        if let Some(x) = data_start(out.layout.slots[i].parameter, s0, g0) {
            values[i] = out.bounds[c].pull_inside(x);
        }
    }
    Ok(())
}

/// An element model's weights without a given start: the linear least-squares solution of
/// `J w = F` less the held part (the output is linear and homogeneous in the weights), each
/// pulled inside `(0, inf)`.
fn linear_start(
    out: &mut Output<'_>,
    f: &[f64],
    given: &[bool],
    values: &mut [f64],
) -> Result<(), FitError> {
    let free = out.free.clone();
    // y = J w exactly (linear and homogeneous in the weights): solve J w = F - held part.
    let mut y = vec![0.0; f.len()];
    let mut jac = DMatrix::zeros(f.len(), free.len());
    if !out.evaluate(values, &mut y, &mut jac) {
        return Err(FitError::NoStart { starts: 1 });
    }
    let w0: Vec<f64> = free.iter().map(|&i| values[i]).collect();
    let held = nalgebra::DVector::from_iterator(
        f.len(),
        (0..f.len())
            .map(|r| f[r] - y[r] + (0..free.len()).map(|c| jac[(r, c)] * w0[c]).sum::<f64>()),
    );
    let solved = jac.svd(true, true).solve(&held, 1e-12);
    let largest = solved.as_ref().map_or(0.0, |w| w.amax());
    for (c, &i) in free.iter().enumerate() {
        if given[c] {
            continue;
        }
        let w = solved.as_ref().map_or(1.0, |w| w[c]);
        values[i] = out.bounds[c].pull_inside(w.max(1e-3 * largest));
    }
    Ok(())
}

/// The travel after a reversal over which [`initial_slope`] measures the slope, as a fraction
/// of the record's range.
const SLOPE_TRAVEL: f64 = 0.05;

/// The median over the reversals of the least-squares slope of `F` against `u` over the first
/// [`SLOPE_TRAVEL`] of the range after each (at least 3 samples): the loop's initial slope,
/// which an elastic stretch (elasto-plastic) or a fast relaxation both show. `None` if no
/// reversal has enough samples there.
fn initial_slope(u: &[f64], f: &[f64], reversals: &[usize]) -> Option<f64> {
    let (lo, hi) = u
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    let reach = SLOPE_TRAVEL * (hi - lo);
    let mut slopes: Vec<f64> = reversals
        .iter()
        .filter_map(|&r| {
            let run: Vec<usize> = (r..u.len())
                .take_while(|&j| (u[j] - u[r]).abs() <= reach)
                .collect();
            (run.len() >= 3).then(|| {
                let m = run.len() as f64;
                let (mu, mf) = run
                    .iter()
                    .fold((0.0, 0.0), |(a, b), &j| (a + u[j] / m, b + f[j] / m));
                let (sxy, sxx) = run.iter().fold((0.0, 0.0), |(a, b), &j| {
                    (a + (u[j] - mu) * (f[j] - mf), b + (u[j] - mu) * (u[j] - mu))
                });
                sxy / sxx
            })
        })
        .filter(|s| s.is_finite() && *s > 0.0)
        .collect();
    super::slow::median(&mut slopes)
}

#[cfg(test)]
mod tests {
    use super::central_across_jumps;

    /// Two samples of `y(q)`: `3 q^2` (smooth: the central difference, exact for a
    /// quadratic, `6 q`) and `2 q` plus a unit step at `q = 1 + h / 3` (a switch inside the
    /// step: the piece `q = 1` lies on has the derivative 2, where the central difference would
    /// give `2 + 1 / (2 h)`); at `q = 1`, `h = 6e-6` (the fit's step), by hand.
    #[test]
    fn a_jump_inside_the_step_is_not_differenced() {
        let (q, h) = (1.0f64, 6e-6);
        let y = |q: f64| {
            [
                3.0 * q * q,
                2.0 * q + f64::from(u8::from(q > 1.0 + h / 3.0)),
            ]
        };
        let column = central_across_jumps(&y(q), &y(q + h), &y(q - h), h);
        assert!((column[0] - 6.0).abs() < 1e-9, "{column:?}");
        assert!((column[1] - 2.0).abs() < 1e-9, "{column:?}");
        // The step below q: the backward difference crosses it, the forward one is kept.
        let y = |q: f64| {
            [
                3.0 * q * q,
                2.0 * q + f64::from(u8::from(q > 1.0 - h / 3.0)),
            ]
        };
        let column = central_across_jumps(&y(q), &y(q + h), &y(q - h), h);
        assert!((column[1] - 2.0).abs() < 1e-9, "{column:?}");
    }
}
