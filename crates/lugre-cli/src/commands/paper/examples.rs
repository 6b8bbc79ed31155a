//! The examples whose hysteresis loops the page tabulates, computed as `lugre loop` computes
//! them.

use anyhow::Result;
use lugre::{Bimodal, HysteresisLoop, Loop, LuGre, LuGreParams, TheoremA, TurningPoints};

use crate::fmt::exact;

/// A periodic input of the paper: plain turning points or a bimodal input (Definition 1).
#[derive(Debug, Clone)]
pub(crate) enum PaperInput {
    TurningPoints(Vec<f64>),
    Bimodal(Bimodal),
}

/// A model and input whose hysteresis loop the page tabulates, as `lugre loop` computes it.
pub(crate) struct LoopExample {
    /// HTML id and short name, e.g. `example3`.
    pub(crate) id: &'static str,
    pub(crate) title: String,
    pub(crate) figures: Vec<u32>,
    pub(crate) sigma0: f64,
    pub(crate) input: PaperInput,
    pub(crate) hl: HysteresisLoop,
    pub(crate) loops: Vec<Loop>,
    pub(crate) theorem_a: Option<TheoremA>,
    pub(crate) note: Option<String>,
}

impl LoopExample {
    pub(crate) fn new(
        id: &'static str,
        title: impl Into<String>,
        figures: Vec<u32>,
        sigma0: f64,
        input: PaperInput,
    ) -> Result<Self> {
        let model = paper_model(sigma0)?;
        let (tp, bimodal) = match &input {
            PaperInput::TurningPoints(u) => (TurningPoints::new(u)?, None),
            PaperInput::Bimodal(b) => (b.turning_points(), Some(*b)),
        };
        // The same calls as `lugre loop` (`commands::loops`), so the numbers are the same.
        let hl = HysteresisLoop::new(model.rate_independent(), &tp)?;
        let loops = hl.loops();
        let theorem_a = bimodal.map(|b| TheoremA::new(&b, &hl));
        Ok(Self {
            id,
            title: title.into(),
            figures,
            sigma0,
            input,
            hl,
            loops,
            theorem_a,
            note: None,
        })
    }

    /// The bimodal input (the figures that need one are only built for the examples that have
    /// one).
    pub(crate) fn bimodal(&self) -> Result<Bimodal> {
        match &self.input {
            PaperInput::Bimodal(b) => Ok(*b),
            PaperInput::TurningPoints(_) => anyhow::bail!("{} has no bimodal input", self.id),
        }
    }

    /// The `lugre loop` arguments that print the same numbers (with `--json`).
    pub(crate) fn loop_args(&self) -> Vec<String> {
        let mut args = vec!["loop".to_string()];
        match &self.input {
            PaperInput::TurningPoints(u) => {
                args.push("--turning-points".into());
                args.push(u.iter().map(|&v| exact(v)).collect::<Vec<_>>().join(","));
            }
            PaperInput::Bimodal(b) => {
                args.push("--bimodal".into());
                args.push(
                    [b.umin1, b.umin2, b.umax1, b.umax2]
                        .iter()
                        .map(|&v| exact(v))
                        .collect::<Vec<_>>()
                        .join(","),
                );
            }
        }
        args.push("--sigma0".into());
        args.push(exact(self.sigma0));
        args
    }
}

/// The paper's LuGre model (Section 4.2: sigma1 = 1, Fc = 1, Fs = 2, vs = 1, beta = 1, f = 0)
/// with stiffness `sigma0`.
pub(super) fn paper_model(sigma0: f64) -> Result<LuGre> {
    Ok(LuGre::from_params(LuGreParams {
        sigma0,
        ..LuGreParams::default()
    })?)
}
