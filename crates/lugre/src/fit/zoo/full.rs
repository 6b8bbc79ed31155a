//! The full fit of a model of the zoo with a finite-rate form ([`crate::zoo::ZooModelSpec::finite_rate`]:
//! GMS, the elasto-plastic model) to a rate-dependent `(t, u, F)` record
//! (`docs/mathematics.md#full-fit-of-the-zoos-finite-rate-models`).
//!
//! The response is the model's path from rest at `u_0` along the input linear between the
//! samples, at its rate ([`crate::zoo::ZooModel::simulate`]: exact per interval), and
//!
//! ```text
//! (ZF4)  q^ = argmin_q  sum_i (y_i(t, u; q) - F_i)^2,     lo_j < q_j < hi_j
//! ```
//!
//! over every parameter of the table (the slow loop's and the finite rate's), with the slow
//! fit's bounds, maps, iteration, central differences (ZF2, relative step `6e-6`; ZF2' where a
//! switch from sticking to slipping crosses a sample inside the step) and
//! statistics. An element model's thresholds are held as there (ZF3, on the record's range).
//!
//! Starts. The slow loop's parameters start as in the slow fit, from the record's initial
//! slope after its reversals `s0` and its plateau `g0` (the LuGre full fit's slow-end force,
//! [`super::super::full::data_start`]); an element model's weights are the linear
//! least-squares solution for the rate-independent path (exact for a record slow enough).
//! The finite rate's `fc`, `vs`, `sigma1`, `sigma2` are the LuGre full fit's data starts
//! (`fc <= g0`), `beta` its given value or the table's; the elasto-plastic `zba = 0.3 fc / s0`
//! (inside its constraint `zba < fc / sigma0`), and GMS's attraction `C = s0 |v|_med` (a
//! slipping element then settles over a travel `g / s0`, as LuGre's bristle does). Further
//! starts multiply `sigma0` (or `C`) and `vs` by 4 or 1/4 as the LuGre full fit does; the best
//! end point wins.
//!
//! Steps. GMS's output jumps where an element's switch from sticking to slipping crosses a
//! sample, so the sum of squares steps, and an iteration can stop at a step's edge. Each start's
//! end is probed beside it (each free parameter moved by `1e-3` and `1e-2` of its value either
//! way, and the Gauss-Newton step of its piece), and the iteration restarted from a point lower
//! by more than a hundredth of the noise variance, at most 4 times (ZF6); a lower point still
//! found then is reported ([`FitWarning::NotMinimum`]), not a minimum.
//!
//! The displacement is used as given (its noise level is measured and reported, not smoothed:
//! the models' switching between sticking and slipping follows the samples); the model starts
//! from rest, so a start state other than rest (`x0`) is refused.

use super::super::full::{data_start as lugre_start, has_reversal, segments, Exact};
use super::super::lm::{minimize, Outcome, Space};
use super::super::noise::{levels, PositionHandling};
use super::super::{
    check_columns, check_count, FitError, FitKind, FitWarning, FullOptions, FULL_CONFIG,
    START_FACTORS,
};
use super::{
    conclude, data_start, given_and_bounds, initial_slope, lay_out, linear_start, End, Output,
    Response, ZooFitReport, ZooFitSpec, STEP,
};
use crate::fit::spec::Family;
use crate::input::check_increasing;
use crate::model::Parameter;
use crate::zoo::MODELS;

/// The full fit (ZF4) of `spec`'s model to `(t_i, u_i, F_i)` from rest (module docs).
///
/// # Errors
/// [`FitError::NoFiniteRate`] for a model without a finite-rate form,
/// [`FitError::ZooFromRest`] for a start state given, the LuGre full fit's for the record and
/// the starts, and the slow zoo fit's ([`super::fit_zoo`]) for the request.
pub fn fit_zoo_full(
    spec: &ZooFitSpec,
    t: &[f64],
    u: &[f64],
    f: &[f64],
    options: FullOptions<'_>,
) -> Result<ZooFitReport, FitError> {
    let model = spec.model();
    spec.check_finite_rate()?;
    let FullOptions {
        x0,
        starts,
        noise: _,
        mut progress,
    } = options;
    check_request(model.name, x0, starts, (t, u, f))?;
    let noise = levels(u, f, PositionHandling::AsGiven);
    let (layout, free, mut values) = lay_out(spec, u, FitKind::Full)?;
    check_count(u.len(), free.len())?;
    let (given, bounds) = given_and_bounds(spec, &layout, &free, &values);
    let out = Output {
        layout: &layout,
        response: Response::Path {
            t: t.to_vec(),
            u: u.to_vec(),
            rate: true,
        },
        free: free.clone(),
        bounds: bounds.clone(),
        step: STEP,
    };
    rate_start(&out, t, u, f, &given, &mut values)?;
    let (start, outcome, lower) = best_start(out, f, (&values, &given), starts, &mut progress)?;
    let end = End {
        kind: FitKind::Full,
        layout: &layout,
        free: &free,
        bounds: &bounds,
        starts: (starts, &start),
        turning_points: segments(u).len() + 1,
        levels: noise,
    };
    let rss = outcome.rss;
    let mut report = conclude(end, outcome, f)?;
    if let Some(lower) = lower {
        report.warnings.push(FitWarning::NotMinimum { rss, lower });
    }
    Ok(report)
}

/// One start's end: its free values at the start, the iteration's end, and the sum of squares
/// of a lower point still found beside the end ([`escape_steps`]).
type StartEnd = (Vec<f64>, Outcome, Option<f64>);

/// The best end of `starts` iterations, each from `values` with the free ones not `given`
/// scaled by a start's factors ([`spread_start`]); its evaluations the sum over all starts.
fn best_start(
    mut out: Output<'_>,
    f: &[f64],
    (values, given): (&[f64], &[bool]),
    starts: usize,
    progress: &mut Option<&mut dyn FnMut(&super::super::FitProgress)>,
) -> Result<StartEnd, FitError> {
    let (free, bounds) = (out.free.clone(), out.bounds.clone());
    let mut best: Option<StartEnd> = None;
    let mut evaluations = 0;
    for n in 0..starts {
        let v = spread_start(&out, values, given, n);
        let start: Vec<f64> = free.iter().map(|&i| v[i]).collect();
        let space = Space {
            values: &v,
            free: &free,
            bounds: &bounds,
        };
        let mut report = |evaluations: usize, rms: f64| {
            if let Some(p) = progress.as_mut() {
                p(&super::super::FitProgress {
                    start: n + 1,
                    starts,
                    evaluations,
                    rms,
                })
            }
        };
        let (back, outcome) = minimize(out, f, space, &start, FULL_CONFIG, &mut report);
        let (back, outcome, lower) = escape_steps(back, f, outcome, &mut report);
        out = back;
        evaluations += outcome.evaluations;
        if outcome.rss.is_finite() && best.as_ref().is_none_or(|(_, b, _)| outcome.rss < b.rss) {
            best = Some((start, outcome, lower));
        }
    }
    let Some((start, mut outcome, lower)) = best else {
        return Err(FitError::NoStart { starts });
    };
    outcome.evaluations = evaluations;
    Ok((start, outcome, lower))
}

/// The values of start `n`: the free ones not `given` scaled by the factors of
/// [`START_FACTORS`] (cycled, each round's by a higher power), pulled inside their bounds.
fn spread_start(out: &Output<'_>, values: &[f64], given: &[bool], n: usize) -> Vec<f64> {
    let (k0, kv) = START_FACTORS[n % START_FACTORS.len()];
    let spread = 1.0 + (n / START_FACTORS.len()) as f64;
    let mut v = values.to_vec();
    for (c, &i) in out.free.iter().enumerate() {
        if !given[c] {
            let k = start_factor(out.layout.slots[i].parameter, (k0, kv));
            v[i] = out.bounds[c].pull_inside(v[i] * k.powf(spread));
        }
    }
    v
}

/// Restarts of one start's iteration from a lower point beside its end (ZF6), at most this
/// many: the sum of squares steps where an element's switch crosses a sample, and the
/// iteration stops at such a step's edge when the piece beyond it is lower only past the step.
const ESCAPES: usize = 4;

/// The relative steps of the probes (ZF6) along each free parameter: past the edge of a step
/// (the iteration stops within its tolerance `1e-8` of it), within the piece beyond it (a
/// standard error is `1e-3` to `1e-2` of the value on a record with noise 1 % of the force).
const PROBES: [f64; 2] = [1e-3, 1e-2];

/// The iteration's end `outcome`, or the end of its restarts from lower points beside it
/// (ZF6, at most [`ESCAPES`]); with the sum of squares of a lower point still found beside
/// the end when the restarts ran out.
fn escape_steps<'a>(
    mut out: Output<'a>,
    f: &[f64],
    mut outcome: Outcome,
    report: &mut dyn FnMut(usize, f64),
) -> (Output<'a>, Outcome, Option<f64>) {
    for restart in 0..=ESCAPES {
        let (found, probes) = lower_beside(&out, f, &outcome);
        outcome.evaluations += probes;
        let Some((values, rss)) = found else {
            return (out, outcome, None);
        };
        if restart == ESCAPES {
            return (out, outcome, Some(rss));
        }
        let start: Vec<f64> = out.free.iter().map(|&i| values[i]).collect();
        let bounds = out.bounds.clone();
        let free = out.free.clone();
        let space = Space {
            values: &values,
            free: &free,
            bounds: &bounds,
        };
        let (back, next) = minimize(out, f, space, &start, FULL_CONFIG, report);
        out = back;
        let evaluations = outcome.evaluations + next.evaluations;
        if next.rss < outcome.rss {
            outcome = next;
        }
        outcome.evaluations = evaluations;
    }
    (out, outcome, None)
}

/// The lowest of the points beside `outcome`'s end (ZF6): each free parameter moved by the
/// relative steps [`PROBES`] either way, and the Gauss-Newton step of the piece the end lies
/// on, whole, halved and quartered; with its sum of squares if below the end's, and the number
/// of points evaluated.
fn lower_beside(
    out: &Output<'_>,
    f: &[f64],
    outcome: &Outcome,
) -> (Option<(Vec<f64>, f64)>, usize) {
    let q = &outcome.values;
    let mut points: Vec<Vec<f64>> = Vec::new();
    for &i in &out.free {
        for step in PROBES.iter().flat_map(|&s| [s, -s]) {
            let mut v = q.clone();
            v[i] *= 1.0 + step;
            points.push(v);
        }
    }
    if let Some(delta) = gauss_newton_step(outcome, f) {
        for scale in [1.0, 0.5, 0.25] {
            let mut v = q.clone();
            for (c, &i) in out.free.iter().enumerate() {
                v[i] += scale * delta[c];
            }
            points.push(v);
        }
    }
    let inside = |v: &Vec<f64>| {
        out.free
            .iter()
            .zip(&out.bounds)
            .all(|(&i, b)| b.contains(v[i]))
    };
    // The noise variance the end's residuals estimate (m - p degrees of freedom).
    let noise = outcome.rss / (f.len() - out.free.len()).max(1) as f64;
    let mut best: Option<(Vec<f64>, f64)> = None;
    let mut evaluated = 0;
    for v in points.into_iter().filter(inside) {
        evaluated += 1;
        let Some(y) = out.y(&v) else { continue };
        let rss: f64 = y.iter().zip(f).map(|(y, f)| (y - f) * (y - f)).sum();
        // Lower by more than a step that moves no interval.
        if rss < outcome.rss - LOWER * noise && best.as_ref().is_none_or(|(_, b)| rss < *b) {
            best = Some((v, rss));
        }
    }
    (best, evaluated)
}

/// A point beside the end is lower when its sum of squares is below the end's by more than
/// this fraction of the noise variance: a hundredth of the unit of the likelihood ratio the
/// intervals are drawn in (their half-width is `1.96^2 = 3.84` units), so the iteration does
/// not chase steps that move no interval.
const LOWER: f64 = 1e-2;

/// The Gauss-Newton step `J d = F - y` of the piece the end lies on, in the free parameters
/// (least squares by the SVD: rank-deficient columns get no step).
fn gauss_newton_step(outcome: &Outcome, f: &[f64]) -> Option<Vec<f64>> {
    let r = nalgebra::DVector::from_iterator(f.len(), f.iter().zip(&outcome.y).map(|(f, y)| f - y));
    let svd = outcome.jac.clone().svd(true, true);
    let d = svd.solve(&r, 1e-10 * svd.singular_values.max()).ok()?;
    d.iter()
        .all(|x| x.is_finite())
        .then(|| d.iter().copied().collect())
}

/// The checks of a full fit's request and record `(t, u, F)` before anything is fitted.
fn check_request(
    model: &'static str,
    x0: f64,
    starts: usize,
    (t, u, f): (&[f64], &[f64], &[f64]),
) -> Result<(), FitError> {
    if x0 != 0.0 {
        return Err(FitError::ZooFromRest { model, x0 });
    }
    if starts == 0 || starts > FullOptions::MAX_STARTS {
        return Err(FitError::BadStarts {
            starts,
            most: FullOptions::MAX_STARTS,
        });
    }
    check_columns(&[("u", u), ("t", t), ("F", f)])?;
    check_increasing(t)?;
    if !has_reversal(u) {
        return Err(FitError::NoReversal { fit: "full" });
    }
    if f.iter().all(|&v| v == 0.0) {
        return Err(FitError::ZeroForce);
    }
    Ok(())
}

/// The factor of a start (`START_FACTORS`' pair `(k0, kv)`) on `parameter`: the stiffness or
/// the attraction by `k0`, the Stribeck velocity by `kv`, the others kept.
fn start_factor(parameter: &str, (k0, kv): (f64, f64)) -> f64 {
    match parameter {
        "sigma0" | "attraction" => k0,
        "vs" => kv,
        _ => 1.0,
    }
}

impl ZooFitSpec {
    /// Whether the model has the finite-rate form [`fit_zoo_full`] needs: a front end asks
    /// before it reads a record.
    ///
    /// # Errors
    /// [`FitError::NoFiniteRate`] naming the models of the zoo that have one.
    pub fn check_finite_rate(&self) -> Result<(), FitError> {
        let model = self.model();
        if model.finite_rate {
            return Ok(());
        }
        let names: Vec<&str> = MODELS
            .iter()
            .filter(|m| m.finite_rate)
            .map(|m| m.name)
            .collect();
        Err(FitError::NoFiniteRate {
            model: model.name,
            takes: names.join(", "),
        })
    }
}

/// Start values of the free slots not given (module docs), pulled inside their bounds.
fn rate_start(
    out: &Output<'_>,
    t: &[f64],
    u: &[f64],
    f: &[f64],
    given: &[bool],
    values: &mut [f64],
) -> Result<(), FitError> {
    let layout = out.layout;
    let weight = layout.elements.as_ref().map(|(e, _)| e.weight);
    if let Some(weight) = weight {
        weights_start(out, weight, (t, u, f), given, values)?;
    }
    let data = RateData::of(t, u, f);
    for (c, &i) in out.free.iter().enumerate() {
        let name = layout.slots[i].parameter;
        if given[c] || Some(name) == weight {
            continue;
        }
        if let Some(x) = data.start(name) {
            values[i] = out.bounds[c].pull_inside(x);
        }
    }
    for (c, &i) in out.free.iter().enumerate() {
        values[i] = out.bounds[c].pull_inside(values[i]);
    }
    Ok(())
}

/// An element model's free weights `weight` alone, on the rate-independent path (linear in
/// them: [`linear_start`]).
fn weights_start(
    out: &Output<'_>,
    weight: &str,
    (t, u, f): (&[f64], &[f64], &[f64]),
    given: &[bool],
    values: &mut [f64],
) -> Result<(), FitError> {
    let layout = out.layout;
    let weights: Vec<usize> = (0..out.free.len())
        .filter(|&c| layout.slots[out.free[c]].parameter == weight)
        .collect();
    let mut linear = Output {
        layout,
        response: Response::Path {
            t: t.to_vec(),
            u: u.to_vec(),
            rate: false,
        },
        free: weights.iter().map(|&c| out.free[c]).collect(),
        bounds: weights.iter().map(|&c| out.bounds[c]).collect(),
        step: super::LINEAR_STEP,
    };
    let given_w: Vec<bool> = weights.iter().map(|&c| given[c]).collect();
    linear_start(&mut linear, f, &given_w, values)
}

/// What the record gives the finite rate's starts (module docs): the LuGre full fit's data
/// starts, the plateau `g0`, the initial slope `s0`, `fc <= g0`, and the median speed.
struct RateData {
    lugre: Vec<f64>,
    g0: f64,
    s0: f64,
    fc: f64,
    speed: f64,
}

impl RateData {
    fn of(t: &[f64], u: &[f64], f: &[f64]) -> Self {
        let ex = Exact::new(Family::LuGre, Vec::new(), t, u, 0.0);
        let current: Vec<f64> = Parameter::LUGRE.iter().map(|p| p.default_value()).collect();
        let lugre = lugre_start(Family::LuGre, &ex, u, f, &current);
        let of = |name: &str| Self::named(&lugre, name);
        let g0 = of("fs").unwrap_or(1.0);
        let reversals: Vec<usize> = segments(u).iter().map(|s| s.0).collect();
        let s0 = initial_slope(u, f, &reversals)
            .or(of("sigma0"))
            .unwrap_or(1.0);
        let fc = of("fc").map_or(g0, |fc| fc.min(g0));
        let mut speeds: Vec<f64> = (0..u.len() - 1).map(|i| ex.speed(i)).collect();
        let speed = super::super::slow::median(&mut speeds).unwrap_or(1.0);
        Self {
            lugre,
            g0,
            s0,
            fc,
            speed,
        }
    }

    /// The LuGre parameter `name`'s value in `lugre` (LuGre's order).
    fn named(lugre: &[f64], name: &str) -> Option<f64> {
        let i = Parameter::LUGRE.iter().position(|p| p.name() == name);
        i.map(|i| lugre[i])
    }

    /// The start of the parameter `name` (module docs), if the data give one.
    fn start(&self, name: &str) -> Option<f64> {
        match name {
            "fc" => Some(self.fc),
            "zba" => Some(0.3 * self.fc / self.s0),
            "attraction" => Some(self.s0 * self.speed),
            "sigma1" | "sigma2" | "vs" => Self::named(&self.lugre, name),
            _ => data_start(name, self.s0, self.g0),
        }
    }
}
