//! The staged identification of friction labs (Canudas de Wit et al. 1995; Olsson et al.
//! 1998): the three experiments in turn, each determining its parameters with the earlier
//! ones held.
//!
//! 1. **Stribeck** ([`super::fit_stribeck`]): `Fc, Fs, vs, sigma2` (and `beta` if freed) from
//!    the steady-state friction of constant-velocity runs;
//! 2. **presliding** ([`super::fit_presliding`]): `sigma0`, `sigma1` from a presliding test,
//!    with the Stribeck curve of stage 1 held;
//! 3. optionally a **full fit** ([`super::fit_full_smooth`]) of a rate-dependent record (read
//!    as a smooth motion), every parameter free (`beta` as in stage 1) and started from stages
//!    1 and 2; a parameter the record cannot determine (e.g. `sigma2` from slow motion) is held
//!    at its earlier value and the fit run again. The estimates and intervals of the
//!    parameters it fitted are then this fit's.
//!
//! Parameters the spec fixes stay fixed throughout.

use super::{
    fit_full_smooth, fit_presliding, fit_stribeck, Estimate, FitKind, FitReport, FitSpec,
    FullOptions, SteadyPoint,
};
use crate::error::FitError;
use crate::simulate::SmoothSamples;

/// The result of a staged identification.
#[derive(Debug, Clone, PartialEq)]
pub struct StagedReport {
    pub stribeck: FitReport,
    pub presliding: FitReport,
    pub full: Option<FitReport>,
    /// Every fitted parameter's final estimate with the stage that determined it
    /// ([`FitKind::Stribeck`], [`FitKind::Presliding`] or, after a full fit, [`FitKind::Full`]),
    /// in the family's order.
    pub estimates: Vec<(Estimate, FitKind)>,
    /// The parameters held throughout.
    pub fixed: Vec<(&'static str, f64)>,
}

/// A stage's error, naming the stage.
fn in_stage(stage: FitKind) -> impl Fn(FitError) -> FitError {
    move |e| FitError::InStage {
        stage: stage.label(),
        error: Box::new(e),
    }
}

/// The staged identification (module docs): the Stribeck fit of `points`, the presliding fit
/// of `presliding = (t, u, F)`, and, if given, the full fit of `full = (motion, F)` (a smooth
/// motion's samples, [`SmoothSamples`]).
pub fn fit_staged(
    spec: &FitSpec,
    points: &[SteadyPoint],
    presliding: (&[f64], &[f64], &[f64]),
    full: Option<(&SmoothSamples, &[f64])>,
) -> Result<StagedReport, FitError> {
    let stribeck = fit_stribeck(spec, points).map_err(in_stage(FitKind::Stribeck))?;
    let mut held = spec.clone();
    for e in &stribeck.estimates {
        held = held.set(e.name, e.value)?;
    }
    let (t, u, f) = presliding;
    let pre = fit_presliding(&held, t, u, f).map_err(in_stage(FitKind::Presliding))?;
    let full = match full {
        None => None,
        Some((motion, f)) => {
            let mut started = held;
            for e in &pre.estimates {
                started = started.set(e.name, e.value)?;
            }
            Some(final_fit(started, motion, f).map_err(in_stage(FitKind::Full))?)
        }
    };
    let order = spec.family().parameters();
    // The earlier stages' estimates, replaced by the full fit's where it fitted them.
    let mut estimates: Vec<(Estimate, FitKind)> = stribeck
        .estimates
        .iter()
        .map(|e| (e.clone(), FitKind::Stribeck))
        .chain(
            pre.estimates
                .iter()
                .map(|e| (e.clone(), FitKind::Presliding)),
        )
        .collect();
    for e in full.iter().flat_map(|r| &r.estimates) {
        if let Some(slot) = estimates.iter_mut().find(|(o, _)| o.name == e.name) {
            *slot = (e.clone(), FitKind::Full);
        }
    }
    estimates.sort_by_key(|(e, _)| order.iter().position(|n| *n == e.name));
    let fixed = order
        .iter()
        .filter(|n| !estimates.iter().any(|(e, _)| e.name == **n))
        .map(|&n| (n, spec.value(n).unwrap_or_default()))
        .collect();
    Ok(StagedReport {
        stribeck,
        presliding: pre,
        full,
        estimates,
        fixed,
    })
}

/// The final full fit from the earlier stages' values; parameters the record cannot determine
/// (its error names them) are held at those values and the fit run again.
fn final_fit(mut spec: FitSpec, motion: &SmoothSamples, f: &[f64]) -> Result<FitReport, FitError> {
    loop {
        match fit_full_smooth(&spec, motion, f, FullOptions::default().with_starts(1)) {
            Err(FitError::Unidentifiable { parameters }) => {
                let before = spec.clone();
                for p in &parameters {
                    spec = spec.fix(p.name)?;
                }
                if spec == before || spec.resolve(FitKind::Full).is_err() {
                    return Err(FitError::Unidentifiable { parameters });
                }
            }
            other => return other,
        }
    }
}
