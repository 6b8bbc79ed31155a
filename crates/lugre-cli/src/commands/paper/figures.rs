//! The figures drawn from the examples' inputs and loops: Figs. 3-5 and 14-17.

use anyhow::Result;
use lugre::{paper_example_1, LoopKind, Tolerance};

use super::examples::{paper_model, LoopExample};
use crate::fmt::sig;
use crate::hysteresis::arc_points;
use crate::plot::{Curve, Figure, LineStyle, Marker, Shape, BLACK, BLUE, GREEN, GREY, RED};

/// Example 1: samples per period of the sine, and the integrator's tolerance.
const EXAMPLE_1_SAMPLES: usize = 1000;
const EXAMPLE_1_GAMMAS: [f64; 3] = [20.0, 200.0, 2000.0];

/// One redrawn figure.
pub(crate) struct PaperFigure {
    pub(crate) number: u32,
    /// What the figure shows, in a few words (for the summary).
    pub(crate) title: String,
    /// The paper's caption, then what this redrawing chose where the paper does not say.
    pub(crate) caption: String,
    pub(crate) figure: Figure,
    /// CSV column names of the x and y coordinates.
    pub(crate) columns: [&'static str; 2],
}

impl PaperFigure {
    pub(crate) fn stem(&self) -> String {
        format!("fig{:02}", self.number)
    }

    /// `(file name, curve)` of every curve's CSV file.
    pub(crate) fn csv_files(&self) -> Vec<(String, &Curve)> {
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

/// Fig. 3: the normalized input psi_u of a bimodal input, with rho_1..rho_5 marked.
pub(super) fn fig03(ex: &LoopExample) -> Result<PaperFigure> {
    let b = ex.bimodal()?;
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
    let fig = name_turning_points(
        fig,
        &psi,
        ["ρ₀", "ρ₁", "ρ₂", "ρ₃", "ρ₄"],
        "ρ₅",
        rho[5],
        b.umax1,
    );
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

/// `fig` with the turning points of one period of a bimodal input named (`names[i]` at
/// `points[i]`; maxima get their name above, minima below), and the return to u_max,1 at
/// (`rho5`, `umax1`) named `fifth`.
fn name_turning_points(
    mut fig: Figure,
    points: &[(f64, f64)],
    names: [&str; 5],
    fifth: &str,
    rho5: f64,
    umax1: f64,
) -> Figure {
    for (i, &p) in points.iter().enumerate() {
        let up = i % 2 == 1;
        fig = fig.note(p, names[i], (0, if up { -24 } else { 24 }));
    }
    fig.note((rho5, umax1), fifth, (24, 12))
}

/// Fig. 4: Example 1 (eq. 18), the output-versus-input graph for gamma = 20, 200, 2000.
pub(super) fn fig04() -> Result<PaperFigure> {
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
pub(super) fn fig05() -> Result<PaperFigure> {
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

/// Fig. 14: Example 4's input over one period, t_1..t_5 marked.
pub(super) fn fig14(ex: &LoopExample) -> Result<PaperFigure> {
    let b = ex.bimodal()?;
    let rho = b.rho();
    let u: Vec<(f64, f64)> = rho[..5].iter().map(|&r| (r, ex.hl.psi_at(r))).collect();
    let fig = Figure::new("t", "u(t)")
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
    let fig = name_turning_points(
        fig,
        &u,
        ["t₀", "t₁", "t₂", "t₃", "t₄"],
        "t₅",
        rho[5],
        b.umax1,
    );
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
pub(super) fn loop_figure(number: u32, ex: &LoopExample) -> Result<PaperFigure> {
    let b = ex.bimodal()?;
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
    let head = loop_caption_head(number, ex, b.umin2);
    let y1 = hl.y_at(rho[1]);
    let y5 = hl.y_at(rho[5]);
    let minor_work = ex
        .loops
        .iter()
        .find(|l| l.kind == LoopKind::Minor)
        .map_or(0.0, |l| l.energy.work);
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

/// The start of the caption of Fig. `number` (15, 16 or 17), as the paper words it.
fn loop_caption_head(number: u32, ex: &LoopExample, umin2: f64) -> String {
    match number {
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
            sig(umin2, 6)
        ),
    }
}
