//! The slow-loop fit of a model of the zoo through the C ABI (core `lugre::fit::fit_zoo`, the
//! engine of `lugre fit --model NAME`), and the full fit of one with a finite-rate form
//! (`lugre::fit::fit_zoo_full`, `lugre fit --model NAME --fit full`: [`lugre_zoo_fit_full`]): the result is a handle whose estimates are read one by
//! one by index (an element model has as many as it has elements), with the fitted model as a
//! [`LugreZoo`].
//!
//! ```c
//! LugreZooFit *fit;
//! double fitted[1100];
//! lugre_zoo_fit("bouc-wen", NULL, u, f, 1100, 0, NULL, NULL, &fit, fitted);
//! LugreZooFitSummary s; lugre_zoo_fit_summary(fit, &s);
//! for (size_t i = 0; i < s.estimates; i++) {
//!     LugreZooEstimate e; lugre_zoo_fit_estimate(fit, i, &e);   /* e.name, e.value, ... */
//! }
//! lugre_zoo_fit_free(fit);
//! ```

use std::ffi::{c_char, CString};

use lugre::fit::{fit_zoo, fit_zoo_full, FullOptions, SlowOptions, ZooFitReport, ZooFitSpec};

use super::{fail, free, guard, handle, handle_mut, input, names, output, set_out, text};
use super::{LugreStatus, LugreZoo};

/// A zoo model's fit: its report and the estimates' names as C strings.
pub struct LugreZooFit {
    report: ZooFitReport,
    names: Vec<CString>,
}

/// One fitted number of a zoo model's fit (`name` lives as long as the fit).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct LugreZooEstimate {
    /// The parameter's name, an element's weight as `stiffness[i]` or `weights[i]`.
    pub name: *const c_char,
    pub value: f64,
    pub std_error: f64,
    /// The degrees of freedom of its interval's t.
    pub dof: f64,
    /// Its 95 % confidence interval.
    pub ci95_lo: f64,
    pub ci95_hi: f64,
    /// 1 where the estimate sits on one of its bounds.
    pub at_bound: i32,
}

/// A zoo model's fit's statistics (as `lugre fit --model NAME --json`).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct LugreZooFitSummary {
    /// How many estimates [`lugre_zoo_fit_estimate`] reads.
    pub estimates: usize,
    pub rms: f64,
    pub samples: usize,
    pub dof: usize,
    pub t_quantile: f64,
    pub condition_number: f64,
    pub iterations: usize,
    pub evaluations: usize,
    /// 0: the fit ran out of evaluations at a usable point, reported.
    pub converged: i32,
    pub turning_points: usize,
    /// The noise estimated in the record (standard deviations of the position and the force).
    pub noise_position: f64,
    pub noise_force: f64,
    /// The starts the fit ran from (the slow fit: 1).
    pub starts: usize,
    /// 1 for the full fit ([`lugre_zoo_fit_full`]), 0 for the slow one.
    pub full: i32,
}

/// The slow-loop fit of the zoo's model `model` (as `lugre fit --model NAME`) to `n` samples
/// `(u, f)` of one or more periods of a slow periodic test. `start` (NULL: none) is a model of
/// the same name whose values are the start values and the held ones (an element model's
/// thresholds its own); `elements` (0: the default, 4) the number of elements of an element
/// model on the grid spanning the record's amplitude; `fix` and `free` comma-separated names
/// (NULL or "": none). The fit goes to `out` (freed by [`lugre_zoo_fit_free`]), the fitted force
/// at every sample to `fitted` (`n` values; NULL skips it).
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn lugre_zoo_fit(
    model: *const c_char,
    start: *const LugreZoo,
    u: *const f64,
    f: *const f64,
    n: usize,
    elements: usize,
    fix: *const c_char,
    free_names: *const c_char,
    out: *mut *mut LugreZooFit,
    fitted: *mut f64,
) -> LugreStatus {
    guard(|| {
        let spec = request(model, start, elements, fix, free_names)?;
        let (u, f) = (input(u, n, "u")?, input(f, n, "f")?);
        let report = fit_zoo(&spec, u, f, SlowOptions::default())?;
        finish(report, out, fitted)
    })
}

/// The full fit of the zoo's model `model` with a finite-rate form (as `lugre fit --model NAME
/// --fit full`: GMS as "maxwell-slip", "elastoplastic") to `n` samples `(t, u, f)` of a
/// rate-dependent record, on the model's exact path from rest at the record's rate, from
/// `starts` start points (0: the default, 3); the other arguments as [`lugre_zoo_fit`]'s. A
/// model without a finite-rate form is `LUGRE_STATUS_INVALID_ARGUMENT` with the core's message.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn lugre_zoo_fit_full(
    model: *const c_char,
    start: *const LugreZoo,
    t: *const f64,
    u: *const f64,
    f: *const f64,
    n: usize,
    elements: usize,
    starts: usize,
    fix: *const c_char,
    free_names: *const c_char,
    out: *mut *mut LugreZooFit,
    fitted: *mut f64,
) -> LugreStatus {
    guard(|| {
        let spec = request(model, start, elements, fix, free_names)?;
        spec.check_finite_rate()?;
        let (t, u, f) = (input(t, n, "t")?, input(u, n, "u")?, input(f, n, "f")?);
        let starts = if starts == 0 {
            FullOptions::DEFAULT_STARTS
        } else {
            starts
        };
        let options = FullOptions::default().with_starts(starts);
        let report = fit_zoo_full(&spec, t, u, f, options)?;
        finish(report, out, fitted)
    })
}

/// The request of [`lugre_zoo_fit`] and [`lugre_zoo_fit_full`] from their arguments.
fn request(
    model: *const c_char,
    start: *const LugreZoo,
    elements: usize,
    fix: *const c_char,
    free_names: *const c_char,
) -> Result<ZooFitSpec, super::Failure> {
    let name =
        text(model, "model")?.ok_or_else(|| fail(LugreStatus::NullPointer, "model is NULL"))?;
    let mut spec = ZooFitSpec::new(&name)?;
    // SAFETY: NULL or a handle made by this library.
    if let Some(s) = unsafe { start.as_ref() } {
        if s.model.spec().name != spec.model().name {
            return Err(fail(
                LugreStatus::InvalidArgument,
                format!(
                    "start is a {} model, model says {}",
                    s.model.spec().name,
                    spec.model().name
                ),
            ));
        }
        for (p, v) in s.model.named() {
            spec = spec.set(p, &v)?;
        }
    }
    for p in names(fix, "fix")? {
        spec = spec
            .fix(&p)
            .map_err(|e| fail(LugreStatus::InvalidArgument, format!("fix: {e}")))?;
    }
    for p in names(free_names, "free")? {
        spec = spec
            .free(&p)
            .map_err(|e| fail(LugreStatus::InvalidArgument, format!("free: {e}")))?;
    }
    if elements != 0 {
        spec = spec.with_elements(elements);
    }
    Ok(spec)
}

/// The fitted force to `fitted` and the fit to `out`.
fn finish(
    report: ZooFitReport,
    out: *mut *mut LugreZooFit,
    fitted: *mut f64,
) -> Result<(), super::Failure> {
    let names = report
        .estimates
        .iter()
        .map(|e| CString::new(e.name).unwrap_or_default())
        .collect();
    output(fitted, &report.fitted);
    set_out(out, LugreZooFit { report, names })
}

/// The fit's statistics.
#[no_mangle]
pub extern "C" fn lugre_zoo_fit_summary(
    fit: *const LugreZooFit,
    out: *mut LugreZooFitSummary,
) -> LugreStatus {
    guard(|| {
        let r = &handle(fit, "fit")?.report;
        *handle_mut(out, "out")? = LugreZooFitSummary {
            estimates: r.estimates.len(),
            rms: r.rms,
            samples: r.samples,
            dof: r.dof,
            t_quantile: r.t_quantile,
            condition_number: r.condition_number,
            iterations: r.iterations,
            evaluations: r.evaluations,
            converged: i32::from(r.converged),
            turning_points: r.turning_points,
            noise_position: r.noise.position,
            noise_force: r.noise.force,
            starts: r.starts,
            full: i32::from(r.kind == lugre::fit::FitKind::Full),
        };
        Ok(())
    })
}

/// Estimate `index` (below [`LugreZooFitSummary::estimates`]).
#[no_mangle]
pub extern "C" fn lugre_zoo_fit_estimate(
    fit: *const LugreZooFit,
    index: usize,
    out: *mut LugreZooEstimate,
) -> LugreStatus {
    guard(|| {
        let fit = handle(fit, "fit")?;
        let e = fit.report.estimates.get(index).ok_or_else(|| {
            fail(
                LugreStatus::InvalidArgument,
                format!(
                    "index must be below {}, got {index}",
                    fit.report.estimates.len()
                ),
            )
        })?;
        *handle_mut(out, "out")? = LugreZooEstimate {
            name: fit.names[index].as_ptr(),
            value: e.value,
            std_error: e.stderr,
            dof: e.dof,
            ci95_lo: e.ci95[0],
            ci95_hi: e.ci95[1],
            at_bound: i32::from(e.at_bound),
        };
        Ok(())
    })
}

/// The fitted model as a new [`LugreZoo`] (freed by `lugre_zoo_free`; its values by
/// `lugre_zoo_value`).
#[no_mangle]
pub extern "C" fn lugre_zoo_fit_model(
    fit: *const LugreZooFit,
    out: *mut *mut LugreZoo,
) -> LugreStatus {
    guard(|| {
        let model = handle(fit, "fit")?.report.model.clone();
        set_out(out, LugreZoo { model })
    })
}

#[no_mangle]
pub extern "C" fn lugre_zoo_fit_free(fit: *mut LugreZooFit) {
    free(fit)
}
