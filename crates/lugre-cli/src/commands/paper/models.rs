//! The third report of `lugre paper`: LuGre next to every model of the core's zoo table
//! (`lugre::zoo::MODELS`, each on its defaults), in `models/`: the paper's Fig. 15 input with
//! each model's minor loop (LuGre's drifts, a Masing model's closes), and, for one input with
//! nested reversals, every loop's closure gap and energies. A model added to the table is in
//! the report without a change here.

use anyhow::Result;
use lugre::zoo::{ZooModel, MODELS};
use lugre::{Loop, LoopKind, TurningPoints};
use std::fmt::Write;

use super::canudas::{figures_with_numbers, Numbers, Report};
use super::html::{esc, HEAD};
use super::PaperFigure;
use crate::fmt::sig;
use crate::hysteresis::Response;
use crate::plot::{Curve, Figure, LineStyle, Marker, Shape, BLACK, BLUE, PALETTE};

/// The folder of the report, inside `lugre paper`'s output folder.
pub(crate) const DIR: &str = "models";

/// The paper's Fig. 15 input (Example 4: turning points 0, 1, 0.5, 1.5) scaled by this
/// factor, onto the scale of the models' defaults (break-away displacements 0.5 to 3.5 m).
const SCALE: f64 = 4.0;

/// Fig. 15's bimodal input, scaled: `u_min1, u_max1, u_min2, u_max2`.
const FIG15: [f64; 4] = [0.0, SCALE, 0.5 * SCALE, 1.5 * SCALE];

/// A periodic input with three nested reversals inside the major loop.
const NESTED: [f64; 8] = [6.0, 0.0, 5.0, 1.0, 4.0, 2.0, 3.0, -1.0];

/// LuGre on the paper's default values (`sigma0 = 1`, `Fs = 2`: the scale of the zoo's
/// defaults), then every model of the zoo on its defaults, each for `input`.
fn responses(input: &[f64]) -> Result<Vec<Response>> {
    let tp = TurningPoints::new(input)?;
    let mut out = vec![Response::lugre(
        super::examples::paper_model(1.0)?.rate_independent(),
        &tp,
    )?];
    for spec in MODELS {
        out.push(Response::zoo(ZooModel::new(spec.name, &[])?, &tp)?);
    }
    Ok(out)
}

pub(crate) fn build() -> Result<Report> {
    let mut figures = Vec::new();
    let mut tables: Vec<Numbers> = Vec::new();
    let mut rows = Vec::new();
    for (i, r) in responses(&FIG15)?.iter().enumerate() {
        let loops = r.loops();
        let minor = loops.iter().find(|l| l.kind == LoopKind::Minor);
        figures.push(fig15_like(i as u32 + 1, r, &loops[0], minor));
        if let Some(m) = minor {
            rows.push((
                format!("{}: minor loop u 4 → 2 → 4", r.label()),
                format!(
                    "closure gap F_C − F_A = {}, work W = {}, dissipation D = {}",
                    sig(m.energy.closure_gap, 6),
                    sig(m.energy.work, 6),
                    sig(m.energy.dissipation, 6)
                ),
            ));
        }
    }
    let last = figures.len() as u32;
    tables.push((last, "The minor loop of Fig. 15's input, every model", rows));
    let nested = responses(&NESTED)?;
    figures.push(overlay(last + 1, &nested));
    tables.push((
        last + 1,
        "Every loop of the nested input, every model",
        nested_rows(&nested),
    ));
    Ok(Report { figures, tables })
}

/// One model's loop for Fig. 15's input: the rest of the loop dashed, the minor loop solid,
/// its start (circle) and its end (square).
fn fig15_like(number: u32, r: &Response, major: &Loop, minor: Option<&Loop>) -> PaperFigure {
    let (_, output) = r.output();
    let mut fig = Figure::new("input u [m]", format!("{output} [N]"))
        .title(format!(
            "{}: the paper's Fig. 15 input (×{SCALE})",
            r.label()
        ))
        .curve(
            Curve::new(
                r.arc(major.start.rho, major.end.rho),
                LineStyle::Dashed,
                BLACK,
            )
            .label("the loop")
            .key("loop"),
        );
    let mut caption = format!(
        "{} on its default values, for the input of the paper's Fig. 15 (Example 4: turning \
         points 0, 1, 0.5, 1.5) scaled by {SCALE} to the scale of the defaults.",
        r.label()
    );
    if let Some(m) = minor {
        fig = fig
            .curve(
                Curve::new(r.arc(m.start.rho, m.end.rho), LineStyle::Solid, BLUE)
                    .label("minor loop")
                    .key("minor")
                    .width(3),
            )
            .marker(Marker {
                label: Some("start (u_A, F_A)".into()),
                at: (m.start.u, m.start.y),
                shape: Shape::Circle,
                color: BLACK,
            })
            .marker(Marker {
                label: Some("end: first return to u_A".into()),
                at: (m.end.u, m.end.y),
                shape: Shape::Square,
                color: BLACK,
            });
        let closes = m.energy.closure_gap.abs() <= 1e-12 * m.start.y.abs().max(1.0);
        let _ = write!(
            caption,
            " The minor loop {}: F_C − F_A = {}.",
            if closes { "closes" } else { "does not close" },
            sig(m.energy.closure_gap, 4)
        );
    }
    PaperFigure {
        number,
        title: format!("{}: Fig. 15's input", r.label()),
        caption,
        figure: fig,
        columns: ["u", "F"],
    }
}

/// Every model's periodic response to the nested input, on one figure.
fn overlay(number: u32, responses: &[Response]) -> PaperFigure {
    let mut fig = Figure::new("input u [m]", "force [N]")
        .title("Every model, one input with nested reversals");
    for (i, r) in responses.iter().enumerate() {
        let key = r.label().to_ascii_lowercase().replace(' ', "-");
        fig = fig.curve(
            Curve::new(
                r.arc(0.0, r.period()),
                LineStyle::Solid,
                PALETTE[i % PALETTE.len()],
            )
            .label(r.label())
            .key(key)
            .width(2),
        );
    }
    PaperFigure {
        number,
        title: "every model, nested reversals".into(),
        caption: format!(
            "One period of the input with turning points {} (three minor loops nested in the \
             major loop), every model on its default values. The table gives each loop's \
             closure gap and energies.",
            NESTED.map(|u| sig(u, 4)).join(", ")
        ),
        figure: fig,
        columns: ["u", "F"],
    }
}

/// A row per loop of each model: the arc and its energies.
fn nested_rows(responses: &[Response]) -> Vec<(String, String)> {
    let mut rows = Vec::new();
    for r in responses {
        for l in r.loops() {
            rows.push((
                format!(
                    "{}: {} loop u {} → {}",
                    r.label(),
                    crate::hysteresis::kind_name(l.kind),
                    sig(l.start.u, 4),
                    sig(l.reversal.u, 4)
                ),
                format!(
                    "gap {}, W = {}, ΔV = {}, D = {}",
                    sig(l.energy.closure_gap, 4),
                    sig(l.energy.work, 6),
                    sig(l.energy.stored_energy_change, 4),
                    sig(l.energy.dissipation, 6)
                ),
            ));
        }
    }
    rows
}

/// The report's `index.html`.
pub(crate) fn page(r: &Report) -> String {
    let mut h = String::with_capacity(32 * 1024);
    h.push_str(HEAD);
    let names: Vec<&str> = MODELS.iter().map(|m| m.label).collect();
    let _ = write!(
        h,
        "<h1>LuGre and the models it is compared with: loops and minor loops</h1>\n\
         <p class=\"lead\">LuGre's minor loops do not close (the paper's Fig. 15); models with \
         Masing behaviour close theirs exactly. Computed by <code>lugre paper</code> (lugre {}) \
         for LuGre and {}, each on its default values (<code>lugre loop --model NAME</code>). \
         A play-operator model's loop runs counterclockwise: its work over a loop is negative. \
         <a href=\"../index.html\">The first report</a>.</p>\n",
        env!("CARGO_PKG_VERSION"),
        esc(&names.join(", "))
    );
    figures_with_numbers(&mut h, r);
    h.push_str("</body>\n</html>\n");
    h
}
