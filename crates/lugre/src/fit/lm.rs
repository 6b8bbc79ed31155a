//! The bridge to the `levenberg-marquardt` crate (MINPACK's LMDER: trust region, pivoted QR,
//! scaled variables): the least-squares problem in the optimizer's unconstrained variables
//! `theta` ([`Transform`]), with the model output and its exact derivatives from an
//! [`Evaluator`] computed in one pass per trial point and kept for the Jacobian.

use super::spec::{Bounds, Transform};
use levenberg_marquardt::{LeastSquaresProblem, LevenbergMarquardt, TerminationReason};
use nalgebra::{DMatrix, DVector, Dyn, Owned};

/// A model evaluated at every sample, with derivatives.
pub(crate) trait Evaluator {
    /// Writes the model output at every sample into `y` and, in column `j` of `jac`, its
    /// derivative with respect to the `j`-th free parameter itself (not `theta`), for the
    /// family's parameter vector `values`. Returns `false` when `values` is not a valid model
    /// or a derivative is not finite (the optimizer then treats the point as infinitely bad;
    /// a non-finite output shows in the sum of squares).
    fn evaluate(&mut self, values: &[f64], y: &mut [f64], jac: &mut DMatrix<f64>) -> bool;
}

/// Stopping rules and the evaluation budget.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Config {
    /// Relative change of the parameters (in the scaled variables) below which the iteration
    /// has converged: far below any standard error.
    pub xtol: f64,
    /// Relative reduction of the sum of squares below which it has converged.
    pub ftol: f64,
    /// Largest cosine between the residual and a Jacobian column at convergence.
    pub gtol: f64,
    /// At most `patience * (p + 1)` evaluations.
    pub patience: usize,
}

/// Progress of one start: evaluations so far and the best residual RMS.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitProgress {
    /// The start being run, from 1.
    pub start: usize,
    pub starts: usize,
    pub evaluations: usize,
    pub rms: f64,
}

/// The result of one Levenberg-Marquardt run.
pub(crate) struct Outcome {
    /// The family's parameter vector at the best point.
    pub values: Vec<f64>,
    /// The model output there.
    pub y: Vec<f64>,
    /// Its derivatives with respect to the free parameters.
    pub jac: DMatrix<f64>,
    pub rss: f64,
    pub termination: TerminationReason,
    /// Jacobian evaluations: the iterations of the trust-region method.
    pub iterations: usize,
    pub evaluations: usize,
}

impl Outcome {
    /// Converged, or stopped because no further progress was possible at machine precision.
    pub fn converged(&self) -> bool {
        self.termination.was_successful()
            || matches!(
                self.termination,
                TerminationReason::NoImprovementPossible(_)
            )
    }

    pub fn reason(&self) -> String {
        match &self.termination {
            TerminationReason::LostPatience => format!(
                "it stopped after {} model evaluations without meeting the tolerances",
                self.evaluations
            ),
            TerminationReason::Numerical(what) => {
                format!("the iteration met a non-finite number ({what})")
            }
            TerminationReason::User(_) => "the model could not be evaluated".to_string(),
            TerminationReason::Converged { ftol, xtol } => match (ftol, xtol) {
                (true, true) => "converged (sum of squares and parameters)".to_string(),
                (true, false) => "converged (sum of squares)".to_string(),
                _ => "converged (parameters)".to_string(),
            },
            TerminationReason::Orthogonal => {
                "converged (residuals orthogonal to the Jacobian)".to_string()
            }
            TerminationReason::ResidualsZero => "converged (residuals zero)".to_string(),
            TerminationReason::NoImprovementPossible(what) => {
                format!("converged (no improvement possible at machine precision: {what})")
            }
            other => format!("{other:?}"),
        }
    }
}

/// A residual this large stands for an invalid parameter point: finite, so that the
/// trust-region step is simply rejected and shrunk.
const INVALID: f64 = 1e100;

/// The parameter space the iteration moves in: every parameter's value (held ones keep it,
/// free ones start there), the indices of the free ones and their bounds (one per free one).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Space<'a> {
    pub values: &'a [f64],
    pub free: &'a [usize],
    pub bounds: &'a [Bounds],
}

impl Space<'_> {
    /// The maps of the free parameters, `theta = 1` at `start`.
    fn transforms(&self, start: &[f64]) -> Vec<Transform> {
        self.bounds
            .iter()
            .zip(start)
            .map(|(&b, &p)| Transform::new(b, p))
            .collect()
    }
}

struct Problem<'a, E> {
    eval: E,
    data: &'a [f64],
    resolved: Space<'a>,
    transforms: Vec<Transform>,
    values: Vec<f64>,
    theta: DVector<f64>,
    y: Vec<f64>,
    residuals: DVector<f64>,
    /// Derivatives with respect to the parameters themselves.
    jac: DMatrix<f64>,
    valid: bool,
    rss: f64,
    best: Option<(f64, DVector<f64>)>,
    evaluations: usize,
    iterations: std::cell::Cell<usize>,
    progress: &'a mut dyn FnMut(usize, f64),
}

impl<E: Evaluator> Problem<'_, E> {
    fn values_at(&self, theta: &DVector<f64>) -> Vec<f64> {
        let mut values = self.resolved.values.to_vec();
        for (j, &i) in self.resolved.free.iter().enumerate() {
            values[i] = self.transforms[j].to_p(theta[j]);
        }
        values
    }
}

impl<E: Evaluator> LeastSquaresProblem<f64, Dyn, Dyn> for Problem<'_, E> {
    type ResidualStorage = Owned<f64, Dyn>;
    type JacobianStorage = Owned<f64, Dyn, Dyn>;
    type ParameterStorage = Owned<f64, Dyn>;

    fn set_params(&mut self, theta: &DVector<f64>) {
        self.theta.copy_from(theta);
        self.values = self.values_at(theta);
        let free_ok = self
            .resolved
            .free
            .iter()
            .all(|&i| self.values[i].is_finite() && self.values[i] > 0.0);
        self.valid = free_ok && self.eval.evaluate(&self.values, &mut self.y, &mut self.jac);
        if self.valid {
            // Four partial sums: the additions then overlap instead of queueing on one.
            let mut acc = [0.0; 4];
            let r = self.residuals.as_mut_slice();
            for ((r, y), f) in r
                .chunks_mut(4)
                .zip(self.y.chunks(4))
                .zip(self.data.chunks(4))
            {
                for j in 0..r.len() {
                    r[j] = y[j] - f[j];
                    acc[j] += r[j] * r[j];
                }
            }
            let rss = (acc[0] + acc[1]) + (acc[2] + acc[3]);
            self.valid = rss.is_finite();
            self.rss = rss;
        }
        if !self.valid {
            self.residuals.fill(INVALID);
            self.rss = f64::INFINITY;
        }
        self.evaluations += 1;
        if self.valid && self.best.as_ref().is_none_or(|(b, _)| self.rss < *b) {
            self.best = Some((self.rss, self.theta.clone()));
        }
        let best_rms = self
            .best
            .as_ref()
            .map_or(f64::INFINITY, |(b, _)| (b / self.data.len() as f64).sqrt());
        (self.progress)(self.evaluations, best_rms);
    }

    fn params(&self) -> DVector<f64> {
        self.theta.clone()
    }

    fn residuals(&self) -> Option<DVector<f64>> {
        Some(self.residuals.clone())
    }

    fn jacobian(&self) -> Option<DMatrix<f64>> {
        if !self.valid {
            // Never asked for at a rejected point; an invalid start ends the run.
            return None;
        }
        self.iterations.set(self.iterations.get() + 1);
        let mut j = self.jac.clone();
        for (c, &i) in self.resolved.free.iter().enumerate() {
            let slope = self.transforms[c].slope(self.values[i]);
            j.column_mut(c).scale_mut(slope);
        }
        Some(j)
    }
}

/// Runs Levenberg-Marquardt from the free values `start`, and returns the best point visited
/// with its output and derivatives. `progress` gets the evaluation count and best RMS.
pub(crate) fn minimize<E: Evaluator>(
    eval: E,
    data: &[f64],
    resolved: Space<'_>,
    start: &[f64],
    config: Config,
    progress: &mut dyn FnMut(usize, f64),
) -> (E, Outcome) {
    let m = data.len();
    let p = resolved.free.len();
    let transforms = resolved.transforms(start);
    let theta = DVector::from_iterator(p, (0..p).map(|j| transforms[j].to_theta(start[j])));
    let mut problem = Problem {
        eval,
        data,
        resolved,
        transforms,
        values: resolved.values.to_vec(),
        theta: theta.clone(),
        y: vec![0.0; m],
        residuals: DVector::zeros(m),
        jac: DMatrix::zeros(m, p),
        valid: false,
        rss: f64::INFINITY,
        best: None,
        evaluations: 0,
        iterations: std::cell::Cell::new(0),
        progress,
    };
    problem.set_params(&theta);
    let lm = LevenbergMarquardt::new()
        .with_xtol(config.xtol)
        .with_ftol(config.ftol)
        .with_gtol(config.gtol)
        .with_patience(config.patience);
    let (mut problem, report) = lm.minimize(problem);
    // The crate leaves the problem at its last accepted point, except after some failures:
    // go back to the best point seen, which is the one reported.
    if let Some((best_rss, best)) = problem.best.clone() {
        if problem.theta != best || !problem.valid || problem.rss != best_rss {
            problem.set_params(&best);
        }
    }
    let outcome = Outcome {
        values: problem.values.clone(),
        y: std::mem::take(&mut problem.y),
        jac: std::mem::replace(&mut problem.jac, DMatrix::zeros(0, 0)),
        rss: problem.rss,
        termination: report.termination,
        iterations: problem.iterations.get(),
        evaluations: problem.evaluations,
    };
    (problem.eval, outcome)
}
