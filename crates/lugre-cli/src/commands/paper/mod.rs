//! `lugre paper`: the paper's Figures 3-17 redrawn from the library (SVG and PNG), the data of
//! every curve drawn (CSV), and `index.html`, one self-contained page with every figure, its
//! caption, the numbers of each example's loop (as `lugre loop --json` prints them) and the
//! errata of Theorem A.
//!
//! Everything is computed before anything is written, and every file is written atomically.
//! The figures follow the paper's captions: which curves, which line styles (dashed, dotted,
//! dash-dotted, solid), which markers. Where the paper leaves a choice open (how many periods
//! a time plot shows, which bimodal input Fig. 3 draws), the choice is stated in the caption.

use anyhow::{Context, Result};
use clap::Args;
use lugre::simulate::{merge_times, uniform_times};
use lugre::{
    paper_example_1, Bimodal, Gamma, HysteresisLoop, Loop, LuGre, LuGreParams, PiecewiseLinear,
    Simulator, TheoremA, Tolerance, Trajectory, TurningPoints,
};
use std::io::Write;
use std::path::{Path, PathBuf};

use crate::fmt::{exact, sig};
use crate::hysteresis::{arc_points, kind_name};
use crate::io::atomic::write_atomic;
use crate::plot::{Curve, Figure, LineStyle, Marker, Shape, BLACK, BLUE, GREEN, GREY, ORANGE, RED};

mod html;

#[derive(Args, Debug)]
pub struct PaperArgs {
    /// Directory to write the figures, their data and index.html to (created if missing).
    #[arg(long, value_name = "DIR", default_value = "paper-figures")]
    pub out: PathBuf,
}

/// Output times per period of the time plots (kinks and the instants just before them are
/// added: the output of eq. 5 jumps at a kink when `sigma1 > 0`).
const SAMPLES_PER_PERIOD: usize = 400;

/// A jump at a kink is drawn from the value this fraction of a period before it.
const BEFORE_KINK: f64 = 1e-9;

/// Example 1: samples per period of the sine, and the integrator's tolerance.
const EXAMPLE_1_SAMPLES: usize = 1000;
const EXAMPLE_1_GAMMAS: [f64; 3] = [20.0, 200.0, 2000.0];

/// One redrawn figure.
pub(crate) struct PaperFigure {
    pub number: u32,
    /// What the figure shows, in a few words (for the summary).
    pub title: String,
    /// The paper's caption, then what this redrawing chose where the paper does not say.
    pub caption: String,
    pub figure: Figure,
    /// CSV column names of the x and y coordinates.
    pub columns: [&'static str; 2],
}

impl PaperFigure {
    pub fn stem(&self) -> String {
        format!("fig{:02}", self.number)
    }

    /// `(file name, curve)` of every curve's CSV file.
    pub fn csv_files(&self) -> Vec<(String, &Curve)> {
        self.figure
            .curves
            .iter()
            .enumerate()
            .map(|(i, c)| {
                let key = c.key.clone().unwrap_or_else(|| format!("curve{i}"));
                (format!("{}-{key}.csv", self.stem()), c)
            })
            .collect()
    }
}

/// A periodic input of the paper: plain turning points or a bimodal input (Definition 1).
#[derive(Debug, Clone)]
pub(crate) enum PaperInput {
    TurningPoints(Vec<f64>),
    Bimodal(Bimodal),
}

/// A model and input whose hysteresis loop the page tabulates, as `lugre loop` computes it.
pub(crate) struct LoopExample {
    /// HTML id and short name, e.g. `example3`.
    pub id: &'static str,
    pub title: String,
    pub figures: Vec<u32>,
    pub sigma0: f64,
    pub input: PaperInput,
    pub hl: HysteresisLoop,
    pub loops: Vec<Loop>,
    pub theorem_a: Option<TheoremA>,
    pub note: Option<String>,
}

impl LoopExample {
    fn new(
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
        hl.check_finite()?;
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

    /// The `lugre loop` arguments that print the same numbers (with `--json`).
    pub fn loop_args(&self) -> Vec<String> {
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
fn paper_model(sigma0: f64) -> Result<LuGre> {
    Ok(LuGre::from_params(LuGreParams {
        sigma0,
        ..LuGreParams::default()
    })?)
}

/// Everything `lugre paper` draws and tabulates.
pub(crate) struct Paper {
    pub figures: Vec<PaperFigure>,
    pub examples: Vec<LoopExample>,
}

pub fn run(args: &PaperArgs) -> Result<()> {
    let started = std::time::Instant::now();
    let paper = build()?;
    let dir = &args.out;
    std::fs::create_dir_all(dir).with_context(|| {
        format!(
            "cannot create the output directory '{}' (--out)",
            dir.display()
        )
    })?;
    let written = write_all(&paper, dir)?;
    print_summary(&paper, dir, &written, started.elapsed())
}

/// Computes every figure and table.
pub(crate) fn build() -> Result<Paper> {
    let example2 = LoopExample::new(
        "example2",
        "Example 2: triangle input of period 2 (turning points 0, 1), sigma0 = 1",
        vec![6, 7, 8, 9],
        1.0,
        PaperInput::TurningPoints(vec![0.0, 1.0]),
    )?;
    let example3 = LoopExample::new(
        "example3",
        "Example 3: bimodal input, turning points 0, 1, 0.2, 1.5, sigma0 = 1",
        vec![10, 11, 12, 13],
        1.0,
        PaperInput::Bimodal(Bimodal::new(0.0, 0.2, 1.0, 1.5)?),
    )?;
    let example4 = LoopExample::new(
        "example4",
        "Example 4: bimodal input, turning points 0, 1, 0.5, 1.5, sigma0 = 6",
        vec![14, 15],
        6.0,
        PaperInput::Bimodal(Bimodal::new(0.0, 0.5, 1.0, 1.5)?),
    )?;
    let fig16 = LoopExample::new(
        "fig16",
        "Fig. 16: Example 4 with sigma0 = 1",
        vec![16],
        1.0,
        PaperInput::Bimodal(Bimodal::new(0.0, 0.5, 1.0, 1.5)?),
    )?;
    let mut fig17 = LoopExample::new(
        "fig17",
        "Fig. 17: Example 4 with sigma0 = 1 and umin2 = 0.2",
        vec![17],
        1.0,
        PaperInput::Bimodal(Bimodal::new(0.0, 0.2, 1.0, 1.5)?),
    )?;
    fig17.note = Some(
        "With sigma0 = 1 and umin2 = 0.2 this is Example 3's model and input: the same loop as \
         Fig. 13 and the same numbers as Example 3's table."
            .into(),
    );

    let mut figures = vec![fig03(&example3)?, fig04()?, fig05()?];
    figures.extend(convergence_figures(&example2, 6, 5, 4)?);
    figures.extend(convergence_figures(&example3, 10, 3, 3)?);
    figures.push(fig14(&example4)?);
    for (number, ex) in [(15, &example4), (16, &fig16), (17, &fig17)] {
        figures.push(loop_figure(number, ex)?);
    }
    Ok(Paper {
        figures,
        examples: vec![example2, example3, example4, fig16, fig17],
    })
}

/// The bimodal input of an example (the figures that need one are only built for those).
fn bimodal(ex: &LoopExample) -> Result<Bimodal> {
    match &ex.input {
        PaperInput::Bimodal(b) => Ok(*b),
        PaperInput::TurningPoints(_) => anyhow::bail!("{} has no bimodal input", ex.id),
    }
}

/// Fig. 3: the normalized input psi_u of a bimodal input, with rho_1..rho_5 marked.
fn fig03(ex: &LoopExample) -> Result<PaperFigure> {
    let b = bimodal(ex)?;
    let rho = b.rho();
    let hl = &ex.hl;
    let psi: Vec<(f64, f64)> = rho[..5].iter().map(|&r| (r, hl.psi_at(r))).collect();
    let mut fig = Figure::new("ρ (normalized variable)", "ψᵤ(ρ)")
        .curve(
            Curve::new(psi.clone(), LineStyle::Solid, BLACK)
                .label("ψᵤ(ρ), one period ρ ∈ [0, ρ₄]")
                .key("psi")
                .width(3),
        )
        .curve(
            Curve::new(
                vec![(rho[1], b.umax1), (rho[5], b.umax1)],
                LineStyle::Dotted,
                BLUE,
            )
            .label("level uₘₐₓ,₁: the input returns to it at ρ₅")
            .key("umax1-level"),
        )
        .marker(Marker {
            label: Some("turning points ρ₀ … ρ₄".into()),
            at: psi[0],
            shape: Shape::Circle,
            color: BLACK,
        });
    for &p in &psi[1..] {
        fig = fig.marker(Marker {
            label: None,
            at: p,
            shape: Shape::Circle,
            color: BLACK,
        });
    }
    fig = fig.marker(Marker {
        label: Some("ρ₅ = ρ₂ + uₘₐₓ,₁ − uₘᵢₙ,₂".into()),
        at: (rho[5], b.umax1),
        shape: Shape::Square,
        color: BLUE,
    });
    let names = ["ρ₀", "ρ₁", "ρ₂", "ρ₃", "ρ₄"];
    for (i, &p) in psi.iter().enumerate() {
        // Maxima get their name above, minima below.
        let up = i % 2 == 1;
        fig = fig.note(p, names[i], (0, if up { -24 } else { 24 }));
    }
    fig = fig.note((rho[5], b.umax1), "ρ₅", (24, 12));
    Ok(PaperFigure {
        number: 3,
        title: "ψᵤ(ρ), the normalized input of a bimodal input".into(),
        caption: format!(
            "ψᵤ(ρ) versus ρ: the normalized input (eq. 12) of a bimodal input, piecewise linear \
             with slopes ±1. Drawn for Example 3's turning points uₘᵢₙ,₁ = {}, uₘₐₓ,₁ = {}, \
             uₘᵢₙ,₂ = {}, uₘₐₓ,₂ = {}: ρ₁ = {}, ρ₂ = {}, ρ₃ = {}, ρ₄ = {} (the period), and \
             ρ₅ = {}, where the input first returns to uₘₐₓ,₁ (the end of the minor loop).",
            sig(b.umin1, 6),
            sig(b.umax1, 6),
            sig(b.umin2, 6),
            sig(b.umax2, 6),
            sig(rho[1], 6),
            sig(rho[2], 6),
            sig(rho[3], 6),
            sig(rho[4], 6),
            sig(rho[5], 6),
        ),
        figure: fig.y_range(b.umin1 - 0.2, b.umax2 + 0.25),
        columns: ["rho", "psi_u"],
    })
}

/// Fig. 4: Example 1 (eq. 18), the output-versus-input graph for gamma = 20, 200, 2000.
fn fig04() -> Result<PaperFigure> {
    let styles = [
        (LineStyle::DashDot, GREEN),
        (LineStyle::Dashed, RED),
        (LineStyle::Solid, BLUE),
    ];
    let mut steady = Vec::new();
    let mut transients = Vec::new();
    for (&gamma, &(style, color)) in EXAMPLE_1_GAMMAS.iter().zip(&styles) {
        let ex = paper_example_1(gamma, 1, EXAMPLE_1_SAMPLES, Tolerance::DEFAULT)?;
        let name = format!("gamma{}", sig(gamma, 6));
        let from_rest: Vec<(f64, f64)> = ex.u.iter().copied().zip(ex.y.iter().copied()).collect();
        let periodic: Vec<(f64, f64)> =
            ex.u.iter()
                .copied()
                .zip(ex.y_steady.iter().copied())
                .collect();
        transients
            .push(Curve::new(from_rest, LineStyle::Dotted, GREY).key(format!("transient-{name}")));
        steady.push(
            Curve::new(periodic, style, color)
                .label(format!("steady state, γ = {}", sig(gamma, 6)))
                .key(format!("steady-{name}"))
                .width(if style == LineStyle::Solid { 2 } else { 3 }),
        );
    }
    // Largest gamma first in the legend, as the caption lists them.
    steady.reverse();
    if let Some(first) = transients.first_mut() {
        first.label = Some("transients from rest (first period)".into());
    }
    let mut fig = Figure::new("input uᵧ", "output yᵧ");
    for c in transients.into_iter().chain(steady) {
        fig = fig.curve(c);
    }
    Ok(PaperFigure {
        number: 4,
        title: "Example 1 (eq. 18): yᵧ versus uᵧ for γ = 20, 200, 2000".into(),
        caption: "Output of system (18), yᵧ versus uᵧ = sin(2πt/γ), from x(0) = y(0) = 0. \
                  Dotted: transient; solid: steady state for γ = 2000; dashed: steady state for \
                  γ = 200; dash-dotted: steady state for γ = 20. The transient drawn is the \
                  response from rest over the first period; the steady state is the periodic \
                  solution (the fixed point of the period map). As γ grows the steady state \
                  tends to the Dahl hysteresis loop."
            .into(),
        figure: fig,
        columns: ["u", "y"],
    })
}

/// Fig. 5: the Stribeck function g of Examples 2-4.
fn fig05() -> Result<PaperFigure> {
    let model = paper_model(1.0)?;
    let p = model.params();
    let n = 800;
    let (lo, hi) = (-4.0, 4.0);
    let g: Vec<(f64, f64)> = (0..=n)
        .map(|i| {
            let v = lo + (hi - lo) * (i as f64 / n as f64);
            (v, model.g(v))
        })
        .collect();
    let fig = Figure::new("v", "g(v)")
        .curve(
            Curve::new(g, LineStyle::Solid, BLACK)
                .label("g(v) = Fc + (Fs − Fc) exp(−|v/vs|^β)")
                .key("g")
                .width(3),
        )
        .curve(
            Curve::new(vec![(lo, p.fc), (hi, p.fc)], LineStyle::Dashed, BLUE)
                .label("Coulomb force Fc (|v| → ∞)")
                .key("Fc"),
        )
        .marker(Marker {
            label: Some("g(0) = Fs, the stiction force".into()),
            at: (0.0, model.g0()),
            shape: Shape::Circle,
            color: RED,
        })
        .y_range(0.0, 2.6);
    Ok(PaperFigure {
        number: 5,
        title: "the Stribeck function g(v)".into(),
        caption: format!(
            "The macrodamping friction function g(v) versus v: the Stribeck curve with \
             Fc = {}, Fs = {}, vs = {}, β = {}. Only g(0) = Fs enters the hysteresis loop.",
            sig(p.fc, 6),
            sig(p.fs, 6),
            sig(p.vs, 6),
            sig(p.beta, 6)
        ),
        figure: fig,
        columns: ["v", "g"],
    })
}

/// Output times over `periods` periods: a uniform grid, every kink, and the instant just
/// before each kink (so that jumps of the output draw as vertical steps); the run ends just
/// before its end.
fn plot_times(pl: &PiecewiseLinear, periods: u32) -> Vec<f64> {
    let start = pl.times()[0];
    let period = pl.period();
    let knots = pl.knot_times(periods);
    let before: Vec<f64> = knots
        .iter()
        .filter(|&&t| t > start)
        .map(|&t| t - BEFORE_KINK * period)
        .collect();
    let mut times = merge_times(
        &merge_times(
            &uniform_times(start, period, periods, SAMPLES_PER_PERIOD),
            &knots,
        ),
        &before,
    );
    // The run's end is a kink too, where the simulator reports the value just after it (the
    // next period's): a jump drawn at the right edge of the plot, into a period not shown.
    times.pop();
    times
}

fn simulate(
    model: &LuGre,
    pl: &PiecewiseLinear,
    periods: u32,
    gamma: Gamma,
    times: &[f64],
) -> Result<Trajectory> {
    let mut out = Trajectory::with_capacity(times.len());
    Simulator::new(model, gamma, 0.0)?.at_times(pl, periods, times, &mut out, &mut |_| {})?;
    Ok(out)
}

/// `(rho, y°(rho))` over one period: a uniform grid and the turning points.
fn loop_in_time(hl: &HysteresisLoop) -> Vec<(f64, f64)> {
    let p = hl.period();
    let mut rhos = uniform_times(0.0, p, 1, SAMPLES_PER_PERIOD);
    rhos = merge_times(&rhos, hl.turning_rho());
    rhos.iter().map(|&r| (r, hl.y_at(r))).collect()
}

/// The four figures of Examples 2 and 3 (Figs. 6-9 and 10-13): the input, y_gamma for
/// gamma = 1, 10, 100 with y*_u, the periods y*_{u,k} converging to y°, and the convergence
/// in the (u, y) plane. The input is at unit speed, so t = rho.
fn convergence_figures(
    ex: &LoopExample,
    first: u32,
    periods: u32,
    k_count: u32,
) -> Result<Vec<PaperFigure>> {
    let model = paper_model(ex.sigma0)?;
    let tp = match &ex.input {
        PaperInput::TurningPoints(u) => TurningPoints::new(u)?,
        PaperInput::Bimodal(b) => b.turning_points(),
    };
    let pl = PiecewiseLinear::from_turning_points(&tp, 1.0)?;
    let period = pl.period();
    let times = plot_times(&pl, periods);
    let star = simulate(&model, &pl, periods, Gamma::INFINITE, &times)?;
    let turning: Vec<String> = tp.values().iter().map(|&u| sig(u, 6)).collect();
    let turning = turning.join(", ");
    let example = if first == 6 { "Example 2" } else { "Example 3" };
    let span = sig(periods as f64 * period, 6);

    // The input: its knots, whose values repeat every period (the last knot of a period is
    // the next one's first, listed once).
    let values = pl.values();
    let input: Vec<(f64, f64)> = pl
        .knot_times(periods)
        .iter()
        .enumerate()
        .map(|(i, &t)| (t, values[i % (values.len() - 1)]))
        .collect();
    let fig_input = PaperFigure {
        number: first,
        title: format!("{example}: the input u(t)"),
        caption: format!(
            "u(t) versus t: {example}'s input, turning points {turning} at unit speed (so \
             ψᵤ = u and ρ = t), period T = {}; {periods} periods shown.",
            sig(period, 6)
        ),
        figure: Figure::new("t", "u(t)")
            .curve(Curve::new(input, LineStyle::Solid, BLACK).key("u").width(3)),
        columns: ["t", "u"],
    };

    // y*_u, then y_gamma for gamma = 1, 10, 100 on top of it (gamma = 100 is within a line's
    // width of y*_u: drawn first, y*_u would hide it).
    let mut fig = Figure::new("t", "yᵧ(t), y⋆ᵤ(t)").curve(
        Curve::new(pairs(&star.t, &star.y), LineStyle::Solid, BLACK)
            .label("y⋆ᵤ(t) (γ → ∞, eqs. 6-7)")
            .key("y-star"),
    );
    for (gamma, style, color) in [
        (1.0, LineStyle::Dashed, BLUE),
        (10.0, LineStyle::DashDot, RED),
        (100.0, LineStyle::Dotted, GREEN),
    ] {
        let y = simulate(&model, &pl, periods, Gamma::new(gamma)?, &times)?;
        fig = fig.curve(
            Curve::new(pairs(&y.t, &y.y), style, color)
                .label(format!("yᵧ(t), γ = {}", sig(gamma, 6)))
                .key(format!("y-gamma{}", sig(gamma, 6)))
                .width(if style == LineStyle::Dotted { 3 } else { 2 }),
        );
    }
    let fig_gamma = PaperFigure {
        number: first + 1,
        title: format!("{example}: yᵧ(t) for γ = 1, 10, 100 and y⋆ᵤ(t)"),
        caption: format!(
            "yᵧ(t) versus t ({example}: σ0 = σ1 = 1, Fc = 1, Fs = 2, vs = 1, β = 1, x0 = 0). \
             Dashed γ = 1, dash-dotted γ = 10, dotted γ = 100; solid y⋆ᵤ(t) versus t. As γ \
             grows yᵧ converges to y⋆ᵤ. Computed exactly (eq. 5 is linear on each segment of \
             the input), not by a numerical ODE solver; t ∈ [0, {span}]. The vertical steps \
             are the jumps of σ1 x′/γ where u′ changes sign."
        ),
        figure: fig,
        columns: ["t", "y"],
    };

    // y° first, under the y*_{u,k} that converge onto it.
    let mut fig = Figure::new("t ∈ [0, T]", "y⋆ᵤ,ₖ(t), y°ᵤ(t)").curve(
        Curve::new(loop_in_time(&ex.hl), LineStyle::Solid, BLACK)
            .label("y°ᵤ(t), the periodic steady state")
            .key("y-circ")
            .width(3),
    );
    let k_colors = [BLUE, RED, GREEN, ORANGE];
    let mut k_curves = Vec::new();
    for k in 0..k_count {
        let shift = f64::from(k) * period;
        let range = star.range_between(shift, shift + period);
        let pts: Vec<(f64, f64)> = range.map(|i| (star.t[i] - shift, star.y[i])).collect();
        let pts_u: Vec<(f64, f64)> = star
            .range_between(shift, shift + period)
            .map(|i| (star.u[i], star.y[i]))
            .collect();
        let color = k_colors[k as usize % k_colors.len()];
        fig = fig.curve(
            Curve::new(pts, LineStyle::Dashed, color)
                .label(format!("y⋆ᵤ,ₖ(t), k = {k}"))
                .key(format!("y-star-k{k}")),
        );
        k_curves.push((k, pts_u, color));
    }
    let fig_k = PaperFigure {
        number: first + 2,
        title: format!(
            "{example}: y⋆ᵤ,ₖ(t), k = 0..{}, converging to y°ᵤ(t)",
            k_count - 1
        ),
        caption: format!(
            "Convergence of the functions y⋆ᵤ,ₖ(t) = y⋆ᵤ(t + kT) to y°ᵤ. Dashed y⋆ᵤ,ₖ(t) versus \
             t for k = {}; solid y°ᵤ(t) versus t (eqs. 8 and 10). The distance shrinks by \
             exp(−aT) = {} per period (a = σ0/g(0) = {}).",
            (0..k_count)
                .map(|k| k.to_string())
                .collect::<Vec<_>>()
                .join(", "),
            sig((-ex.hl.model().a() * period).exp(), 4),
            sig(ex.hl.model().a(), 6)
        ),
        figure: fig,
        columns: ["t", "y"],
    };

    // The (u, y) plane.
    let loop_curve = Curve::new(
        arc_points(&ex.hl, 0.0, ex.hl.period()),
        LineStyle::Solid,
        BLACK,
    )
    .label("hysteresis loop G°ᵤ")
    .key("loop")
    .width(3);
    let fig_plane = if first == 6 {
        // Fig. 9: G*_u (the whole simulated response) dotted, the loop solid.
        let fig = Figure::new("u", "y⋆ᵤ, y°ᵤ").curve(loop_curve).curve(
            Curve::new(pairs(&star.u, &star.y), LineStyle::Dotted, BLUE)
                .label("G⋆ᵤ = {(u(t), y⋆ᵤ(t)), t ≥ 0}")
                .key("G-star")
                .width(3),
        );
        PaperFigure {
            number: first + 3,
            title: format!("{example}: G⋆ᵤ converging to the hysteresis loop G°ᵤ"),
            caption: format!(
                "Convergence of the output-versus-input graph G⋆ᵤ to the hysteresis loop G°ᵤ. \
                 Dotted G⋆ᵤ (from x0 = 0, t ∈ [0, {span}]); solid G°ᵤ."
            ),
            figure: fig,
            columns: ["u", "y"],
        }
    } else {
        // Fig. 13: the graphs (u, y*_{u,k}) for each k, and the loop.
        let styles = [LineStyle::Dashed, LineStyle::DashDot, LineStyle::Dotted];
        let mut fig = Figure::new("u", "y⋆ᵤ,ₖ, y°ᵤ").curve(loop_curve);
        for (k, pts, color) in k_curves {
            let style = styles[k as usize % styles.len()];
            fig = fig.curve(
                Curve::new(pts, style, color)
                    .label(format!("(u(t), y⋆ᵤ,ₖ(t)), k = {k}"))
                    .key(format!("graph-k{k}"))
                    .width(if style == LineStyle::Dotted { 3 } else { 2 }),
            );
        }
        PaperFigure {
            number: first + 3,
            title: format!(
                "{example}: (u, y⋆ᵤ,ₖ), k = 0..{}, converging to the loop",
                k_count - 1
            ),
            caption: format!(
                "Convergence of the graphs {{(u(t), y⋆ᵤ,ₖ(t)), t ∈ [0, ρ₄]}} to the hysteresis \
                 loop {{(u(t), y°ᵤ(t)), t ∈ [0, ρ₄]}} (solid). k = 0 dashed, k = 1 dash-dotted, \
                 k = 2 dotted; the minor loop is the small lobe between u = {} and u = {}.",
                sig(bimodal(ex)?.umin2, 6),
                sig(bimodal(ex)?.umax1, 6)
            ),
            figure: fig,
            columns: ["u", "y"],
        }
    };
    Ok(vec![fig_input, fig_gamma, fig_k, fig_plane])
}

fn pairs(x: &[f64], y: &[f64]) -> Vec<(f64, f64)> {
    x.iter().copied().zip(y.iter().copied()).collect()
}

/// Fig. 14: Example 4's input over one period, t_1..t_5 marked.
fn fig14(ex: &LoopExample) -> Result<PaperFigure> {
    let b = bimodal(ex)?;
    let rho = b.rho();
    let u: Vec<(f64, f64)> = rho[..5].iter().map(|&r| (r, ex.hl.psi_at(r))).collect();
    let mut fig = Figure::new("t", "u(t)")
        .curve(
            Curve::new(u.clone(), LineStyle::Solid, BLACK)
                .label("u(t), one period")
                .key("u")
                .width(3),
        )
        .marker(Marker {
            label: Some("t₁: start of the minor loop".into()),
            at: (rho[1], b.umax1),
            shape: Shape::Circle,
            color: BLUE,
        })
        .marker(Marker {
            label: Some("t₅: first return to u(t₁)".into()),
            at: (rho[5], b.umax1),
            shape: Shape::Square,
            color: RED,
        });
    let names = ["t₀", "t₁", "t₂", "t₃", "t₄"];
    for (i, &p) in u.iter().enumerate() {
        let up = i % 2 == 1;
        fig = fig.note(p, names[i], (0, if up { -24 } else { 24 }));
    }
    fig = fig.note((rho[5], b.umax1), "t₅", (24, 12));
    Ok(PaperFigure {
        number: 14,
        title: "Example 4: the input u(t), t₁ … t₅ marked".into(),
        caption: format!(
            "u(t) versus t: Example 4's input (eq. 12, a normalized input, so tᵢ = ρᵢ) with \
             uₘᵢₙ,₁ = {}, uₘᵢₙ,₂ = {}, uₘₐₓ,₁ = {}, uₘₐₓ,₂ = {}: t₁ = {}, t₂ = {}, t₃ = {}, \
             t₄ = {}, t₅ = {}.",
            sig(b.umin1, 6),
            sig(b.umin2, 6),
            sig(b.umax1, 6),
            sig(b.umax2, 6),
            sig(rho[1], 6),
            sig(rho[2], 6),
            sig(rho[3], 6),
            sig(rho[4], 6),
            sig(rho[5], 6),
        ),
        figure: fig.y_range(b.umin1 - 0.2, b.umax2 + 0.25),
        columns: ["t", "u"],
    })
}

/// Figs. 15-17: the hysteresis loop with its minor loop solid, an open circle at t_1 and a
/// square at t_5.
fn loop_figure(number: u32, ex: &LoopExample) -> Result<PaperFigure> {
    let b = bimodal(ex)?;
    let hl = &ex.hl;
    let rho = b.rho();
    let p = hl.period();
    let at = |r: f64| {
        let pt = hl.point_at(r);
        (pt.u, pt.y)
    };
    let fig = Figure::new("u", "y°")
        .curve(
            Curve::new(arc_points(hl, rho[5], rho[1] + p), LineStyle::Dashed, BLACK)
                .label("rest of the hysteresis loop G°ᵤ")
                .key("major-rest"),
        )
        .curve(
            Curve::new(arc_points(hl, rho[1], rho[5]), LineStyle::Solid, BLUE)
                .label("minor loop, ρ ∈ [ρ₁, ρ₅]")
                .key("minor")
                .width(3),
        )
        .marker(Marker {
            label: Some("(u(t₁), y°(t₁))".into()),
            at: at(rho[1]),
            shape: Shape::Circle,
            color: BLACK,
        })
        .marker(Marker {
            label: Some("(u(t₅), y°(t₅))".into()),
            at: at(rho[5]),
            shape: Shape::Square,
            color: BLACK,
        });
    let head = match number {
        15 => format!(
            "Hysteresis loop G°ᵤ (Example 4, σ0 = {}). The marker open circle corresponds to \
             the point (u(t₁), y°(t₁)) whilst the marker rectangle corresponds to the point \
             (u(t₅), y°(t₅)). The minor loop is plotted in solid line.",
            sig(ex.sigma0, 6)
        ),
        16 => format!(
            "Hysteresis loop G°ᵤ for σ0 = {} (minor loop in solid line). With this soft \
             stiffness the minor loop's two branches nearly coincide: the shape of the minor \
             loop depends greatly on σ0.",
            sig(ex.sigma0, 6)
        ),
        _ => format!(
            "Hysteresis loop G°ᵤ for σ0 = {} and uₘᵢₙ,₂ = {} (minor loop in solid line).",
            sig(ex.sigma0, 6),
            sig(b.umin2, 6)
        ),
    };
    let y1 = hl.y_at(rho[1]);
    let y5 = hl.y_at(rho[5]);
    let minor_work = ex
        .loops
        .iter()
        .find(|l| l.kind == lugre::LoopKind::Minor)
        .map_or(0.0, |l| l.work);
    Ok(PaperFigure {
        number,
        title: format!(
            "the hysteresis loop and its minor loop, σ0 = {}, uₘᵢₙ,₂ = {}",
            sig(ex.sigma0, 6),
            sig(b.umin2, 6)
        ),
        caption: format!(
            "{head} The rest of the loop is dashed. The minor loop does not close: \
             y°(t₁) = {}, y°(t₅) = {}; the work over it is W = {} (the table below). Computed \
             from the stable form of eqs. 13-16.",
            sig(y1, 6),
            sig(y5, 6),
            sig(minor_work, 4)
        ),
        figure: fig,
        columns: ["u", "y"],
    })
}

/// Writes every file; returns their names in the order written.
fn write_all(paper: &Paper, dir: &Path) -> Result<Vec<String>> {
    let mut written = Vec::new();
    for f in &paper.figures {
        for ext in ["svg", "png"] {
            let name = format!("{}.{ext}", f.stem());
            f.figure.save(&dir.join(&name))?;
            written.push(name);
        }
        for (name, curve) in f.csv_files() {
            write_atomic(&dir.join(&name), |w| {
                writeln!(w, "{},{}", f.columns[0], f.columns[1])?;
                for &(x, y) in &curve.points {
                    writeln!(w, "{},{}", exact(x), exact(y))?;
                }
                Ok(())
            })?;
            written.push(name);
        }
    }
    let html = html::page(paper);
    write_atomic(&dir.join("index.html"), |w| {
        Ok(w.write_all(html.as_bytes())?)
    })?;
    written.push("index.html".into());
    Ok(written)
}

fn print_summary(
    paper: &Paper,
    dir: &Path,
    written: &[String],
    elapsed: std::time::Duration,
) -> Result<()> {
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    let csv = written.iter().filter(|n| n.ends_with(".csv")).count();
    let (first, last) = match (paper.figures.first(), paper.figures.last()) {
        (Some(a), Some(b)) => (a.stem(), b.stem()),
        _ => (String::new(), String::new()),
    };
    writeln!(
        out,
        "Wrote {} files to {} in {:.2} s:",
        written.len(),
        dir.display(),
        elapsed.as_secs_f64()
    )?;
    writeln!(
        out,
        "  {first}..{last}.svg and .png  {} figures of the paper, redrawn",
        paper.figures.len()
    )?;
    writeln!(
        out,
        "  figNN-CURVE.csv            {csv} CSV files, the points of every curve drawn"
    )?;
    writeln!(
        out,
        "  index.html                 every figure with its caption, the loop tables, Theorem A's errata"
    )?;
    writeln!(out)?;
    for f in &paper.figures {
        writeln!(
            out,
            "  {}  {} ({} curve{})",
            f.stem(),
            f.title,
            f.figure.curves.len(),
            if f.figure.curves.len() == 1 { "" } else { "s" }
        )?;
    }
    writeln!(
        out,
        "\nHysteresis loops y° (rate-independent limit); the command shown prints the same \
         numbers with --json:"
    )?;
    for ex in &paper.examples {
        writeln!(out, "  {}", ex.title)?;
        writeln!(out, "    lugre {}", ex.loop_args().join(" "))?;
        let mut line = format!("    y°(0) = {}", sig(ex.hl.turning_y()[0], 10));
        if let Some(ta) = &ex.theorem_a {
            line += &format!(
                ", rho_5 = {}, minor loop [rho_1, rho_5] = [{}, {}]",
                sig(ta.rho[5], 10),
                sig(ta.minor_loop[0], 10),
                sig(ta.minor_loop[1], 10)
            );
        }
        writeln!(out, "{line}")?;
        for l in &ex.loops {
            writeln!(
                out,
                "    {} loop, rho in [{}, {}]: work W = {}, stored dV = {}, dissipated D = {}",
                kind_name(l.kind),
                sig(l.start.rho, 6),
                sig(l.end.rho, 6),
                sig(l.work, 10),
                sig(l.stored_energy_change, 10),
                sig(l.dissipation, 10)
            )?;
        }
    }
    writeln!(
        out,
        "\nOpen {} in a browser (it needs no network).",
        dir.join("index.html").display()
    )?;
    out.flush()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_character_drawn_is_in_the_embedded_font() {
        use ab_glyph::Font;
        let font = ab_glyph::FontRef::try_from_slice(dejavu::sans::regular()).unwrap();
        let paper = build().unwrap();
        for f in &paper.figures {
            let fig = &f.figure;
            let texts = fig
                .curves
                .iter()
                .filter_map(|c| c.label.as_deref())
                .chain(fig.markers.iter().filter_map(|m| m.label.as_deref()))
                .chain(fig.notes.iter().map(|n| n.text.as_str()))
                .chain(fig.title.as_deref())
                .chain([fig.x_label.as_str(), fig.y_label.as_str()]);
            for text in texts {
                for c in text.chars() {
                    assert!(
                        font.glyph_id(c).0 != 0,
                        "Fig. {}: '{c}' (U+{:04X}) in '{text}' has no glyph",
                        f.number,
                        c as u32
                    );
                }
            }
        }
    }

    #[test]
    fn plot_times_bracket_every_kink_and_stop_before_the_end() {
        let tp = TurningPoints::new(&[0.0, 1.0, 0.2, 1.5]).unwrap();
        let pl = PiecewiseLinear::from_turning_points(&tp, 1.0).unwrap();
        let times = plot_times(&pl, 3);
        assert!(times.windows(2).all(|w| w[0] < w[1]));
        let (start, end) = pl.span(3);
        assert_eq!(times[0], start);
        assert!(*times.last().unwrap() < end);
        for &k in &pl.knot_times(3)[1..] {
            let before = k - BEFORE_KINK * pl.period();
            assert!(times.contains(&before), "{k}");
        }
    }

    #[test]
    fn the_loop_examples_are_the_papers() {
        let paper = build().unwrap();
        let ids: Vec<&str> = paper.examples.iter().map(|e| e.id).collect();
        assert_eq!(ids, ["example2", "example3", "example4", "fig16", "fig17"]);
        let numbers: Vec<u32> = paper.figures.iter().map(|f| f.number).collect();
        assert_eq!(numbers, (3..=17).collect::<Vec<_>>());
        // Example 3 (paper §4.3): rho_1..rho_4 = 1, 1.8, 3.1, 4.6 and the minor loop [1, 2.6].
        let ta = paper.examples[1].theorem_a.unwrap();
        for (a, b) in ta.rho.iter().zip([0.0, 1.0, 1.8, 3.1, 4.6, 2.6]) {
            assert!((a - b).abs() < 1e-15, "{:?}", ta.rho);
        }
        // Fig. 17 is Example 3's model and input.
        assert_eq!(paper.examples[4].loop_args(), paper.examples[1].loop_args());
    }
}
