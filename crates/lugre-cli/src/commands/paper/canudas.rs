//! The second report of `lugre paper`: the experiments of Canudas de Wit, Olsson, Åström and
//! Lischinsky, "A new model for control of systems with friction" (IEEE TAC 40(3), 1995), Figs.
//! 2, 3, 4, 6 and 8, redrawn from `lugre::dynamics` with Table I and a 1 kg mass, with their
//! numbers, in `canudas1995/` (its own `index.html`, linked from the first).

use anyhow::Result;
use lugre::dynamics::{EventKind, Motion, Outcome, Request, Scenario};
use lugre::zoo::{ZooModel, ZooModelSpec, MODELS};
use lugre::{LuGre, LuGreParams};
use std::fmt::Write;

use super::html::{esc, figure, HEAD};
use super::PaperFigure;
use crate::fmt::sig;
use crate::plot::{Curve, Figure, LineStyle, BLACK, PALETTE};

/// The folder of the second report, inside `lugre paper`'s output folder.
pub(crate) const DIR: &str = "canudas1995";

/// A table of numbers shown under a figure: its figure, heading, rows of (quantity, value).
pub(crate) type Numbers = (u32, &'static str, Vec<(String, String)>);

/// The report: its figures and the numbers shown with them.
pub(crate) struct Report {
    pub(crate) figures: Vec<PaperFigure>,
    pub(crate) tables: Vec<Numbers>,
}

fn table1() -> Result<LuGre> {
    Ok(LuGre::from_params(LuGreParams::canudas_de_wit_1995())?)
}

/// A friction of the report: LuGre, or a model of the zoo's table with a finite-rate form
/// ([`ZooModelSpec::finite_rate`]), each on the scenario's Table I (a zoo model's other
/// parameters at their defaults on that scale: elasto-plastic's `zba = Fc / (2 sigma0)` = 5
/// µm). A model added to the table with a finite-rate form is drawn here without code here.
#[derive(Debug, Clone, Copy)]
enum Friction {
    LuGre,
    Zoo(&'static ZooModelSpec),
}

impl Friction {
    /// LuGre first, then the zoo's finite-rate models in the table's order.
    fn all() -> Vec<Friction> {
        std::iter::once(Friction::LuGre)
            .chain(MODELS.iter().filter(|m| m.finite_rate).map(Friction::Zoo))
            .collect()
    }

    fn label(self) -> &'static str {
        match self {
            Friction::LuGre => "LuGre",
            Friction::Zoo(spec) => spec.label,
        }
    }

    /// The suffix of its curves' keys: none for LuGre, `_NAME` for a zoo model.
    fn tag(self) -> String {
        match self {
            Friction::LuGre => String::new(),
            Friction::Zoo(spec) => format!("_{}", spec.name),
        }
    }

    /// What a table's row names after its quantity: nothing for LuGre, `, Label` for a zoo
    /// model.
    fn after(self) -> String {
        match self {
            Friction::LuGre => String::new(),
            Friction::Zoo(spec) => format!(", {}", spec.label),
        }
    }

    /// The line of the `i`-th friction of [`Friction::all`]: LuGre solid, the others dashed,
    /// dotted, dash-dotted in turn.
    fn style(i: usize) -> LineStyle {
        [
            LineStyle::Solid,
            LineStyle::Dashed,
            LineStyle::Dotted,
            LineStyle::DashDot,
        ][i % 4]
    }

    /// The experiment with this friction, Table I and 1 kg, at the solver's default tolerance,
    /// sampled `n + 1` times (with the break-away of a ramp), through the one request every
    /// front end builds.
    fn run(self, sc: Scenario, n: usize) -> Result<Outcome> {
        let r = Request::new()
            .with_scenario(sc)
            .with_samples(n as u64 + 1)?;
        let r = match self {
            Friction::LuGre => r.with_model(table1()?),
            Friction::Zoo(spec) => r.with_zoo(&ZooModel::new(spec.name, &[])?)?,
        };
        Ok(r.build()?.run()?)
    }
}

/// Each friction of [`Friction::all`] with its run of `sc` (`n + 1` samples).
fn runs(sc: Scenario, n: usize) -> Result<Vec<(Friction, Motion)>> {
    Friction::all()
        .into_iter()
        .map(|f| Ok((f, f.run(sc, n)?.motion)))
        .collect()
}

/// The labels of the frictions, `LuGre / Elasto-plastic / ...`.
fn labels() -> String {
    let all: Vec<&str> = Friction::all().iter().map(|f| f.label()).collect();
    all.join(" / ")
}

/// The frictions beside LuGre, for captions: `the Elasto-plastic friction (...)`.
fn others_caption() -> String {
    let others: Vec<String> = Friction::all()
        .iter()
        .filter_map(|f| match f {
            Friction::LuGre => None,
            Friction::Zoo(spec) => Some(format!("{} ({})", spec.label, spec.reference)),
        })
        .collect();
    others.join("; ")
}

fn paper_figure(
    number: u32,
    title: &str,
    caption: String,
    figure: Figure,
    columns: [&'static str; 2],
) -> PaperFigure {
    PaperFigure {
        number,
        title: title.into(),
        caption,
        figure,
        columns,
    }
}

pub(crate) fn build() -> Result<Report> {
    let mut figures = Vec::new();
    let mut tables = Vec::new();

    fig02(&mut figures, &mut tables)?;
    fig03(&mut figures)?;
    fig04(&mut figures, &mut tables)?;
    fig06(&mut figures, &mut tables)?;
    fig08(&mut figures, &mut tables)?;
    Ok(Report { figures, tables })
}

/// Fig. 2: pre-sliding displacement against the applied force.
fn fig02(figures: &mut Vec<PaperFigure>, tables: &mut Vec<Numbers>) -> Result<()> {
    let runs = runs(Scenario::Presliding, 6500)?;
    let mut fig = Figure::new("applied force [N]", "displacement x [µm]")
        .title("Fig. 2: pre-sliding displacement");
    for (i, (f, m)) in runs.iter().enumerate() {
        let points = m.drive.iter().zip(&m.x).map(|(d, x)| (*d, x * 1e6));
        fig = fig.curve(
            Curve::new(points.collect(), Friction::style(i), PALETTE[i])
                .label(f.label())
                .key(format!("x{}", f.tag())),
        );
    }
    figures.push(paper_figure(
        2,
        "pre-sliding displacement",
        format!(
            "Pre-sliding displacement x (µm) against the applied force (N), the force ramped \
             to ±1.425 N (95 % of Fs) with holds at 10-15, 35-40 and 60-65 s; LuGre solid, \
             beside it on the same Table I: {}.",
            others_caption()
        ),
        fig,
        ["force", "x_um"],
    ));
    let at = |m: &Motion, t: f64| {
        m.t.iter()
            .position(|&s| (s - t).abs() < 1e-9)
            .map(|i| sig(m.x[i] * 1e6, 10))
    };
    let mut rows = Vec::new();
    for t in [10.0, 15.0, 40.0, 65.0] {
        let xs: Option<Vec<String>> = runs.iter().map(|(_, m)| at(m, t)).collect();
        if let Some(xs) = xs {
            rows.push((
                format!("x({t} s): {}", labels()),
                format!("{} µm", xs.join(" / ")),
            ));
        }
    }
    tables.push((2, "Pre-sliding", rows));
    Ok(())
}

/// Fig. 3: frictional lag, friction against velocity for three frequencies.
fn fig03(figures: &mut Vec<PaperFigure>) -> Result<()> {
    let mut fig =
        Figure::new("velocity v [mm/s]", "friction F [N]").title("Fig. 3: frictional lag");
    for (i, w) in [1.0, 10.0, 25.0].into_iter().enumerate() {
        for (j, (f, m)) in runs(Scenario::Lag { w }, 3000)?.into_iter().enumerate() {
            // The last of the three periods: the steady loop.
            let start = 2 * m.t.len() / 3;
            let points = (start..m.t.len())
                .map(|k| (m.v[k] * 1e3, m.friction[k]))
                .collect();
            fig = fig.curve(
                Curve::new(points, Friction::style(j), PALETTE[i])
                    .label(format!("ω = {w} rad/s, {}", f.label()))
                    .key(format!("w{w}{}", f.tag())),
            );
        }
    }
    figures.push(paper_figure(
        3,
        "frictional lag",
        format!(
            "Friction against velocity under v = 10⁻³ (cos ωt + 1.5) m/s, ω = 1, 10, 25 rad/s \
             (the third period of each): the loops widen with the frequency. LuGre solid, \
             beside it: {}.",
            others_caption()
        ),
        fig,
        ["v_mm_s", "friction"],
    ));
    Ok(())
}

/// Fig. 4: break-away force against the force rate.
fn fig04(figures: &mut Vec<PaperFigure>, tables: &mut Vec<Numbers>) -> Result<()> {
    let rates = [1.0, 2.0, 3.0, 5.0, 7.0, 10.0, 15.0, 20.0, 25.0, 30.0];
    let mut fig =
        Figure::new("force rate r [N/s]", "break-away force [N]").title("Fig. 4: break-away force");
    let mut rows = Vec::new();
    for (i, f) in Friction::all().into_iter().enumerate() {
        let mut points = Vec::new();
        for rate in rates {
            // The break-away is located by the solver, whatever the samples.
            if let Some(b) = f.run(Scenario::Breakaway { rate }, 1)?.breakaway {
                points.push((rate, b.force));
                rows.push((
                    format!("r = {rate} N/s{}", f.after()),
                    format!("F = {} N at t = {} s", sig(b.force, 10), sig(b.t, 10)),
                ));
            }
        }
        fig = fig.curve(
            Curve::new(points, Friction::style(i), PALETTE[i])
                .label(f.label())
                .key(format!("breakaway{}", f.tag())),
        );
    }
    figures.push(paper_figure(
        4,
        "break-away force",
        format!(
            "Break-away force (the first peak of the friction force under F = r t) against the \
             force rate r, 1 to 30 N/s: the faster the ramp, the lower the break-away force. \
             (Above about 35 N/s the first maximum is a shallow bump just above Fc, no longer a \
             break-away peak.) LuGre solid, beside it: {}.",
            others_caption()
        ),
        fig,
        ["rate", "force"],
    ));
    tables.push((4, "Break-away", rows));
    Ok(())
}

/// Fig. 6: stick-slip.
fn fig06(figures: &mut Vec<PaperFigure>, tables: &mut Vec<Numbers>) -> Result<()> {
    let runs = runs(Scenario::StickSlip, 3000)?;
    let mut fig = Figure::new("time t [s]", "position [m]").title("Fig. 6: stick-slip");
    let mut rows = Vec::new();
    for (i, (f, m)) in runs.iter().enumerate() {
        let x = m.t.iter().zip(&m.x).map(|(t, x)| (*t, *x)).collect();
        fig = fig.curve(
            Curve::new(x, LineStyle::Solid, PALETTE[i])
                .label(format!("mass x, {}", f.label()))
                .key(format!("x{}", f.tag())),
        );
        rows.extend(stick_slip_rows(m, &f.after()));
    }
    let end = runs[0].1.t.iter().map(|t| (*t, 0.1 * t)).collect();
    fig = fig.curve(
        Curve::new(end, LineStyle::Dashed, BLACK)
            .label("free end 0.1 t")
            .key("end"),
    );
    figures.push(paper_figure(
        6,
        "stick-slip",
        format!(
            "Stick-slip: a spring of 2 N/m pulled at 0.1 m/s (dashed: its free end) and the \
             mass's position x, with LuGre friction and beside it: {}.",
            others_caption()
        ),
        fig,
        ["t", "x"],
    ));
    tables.push((6, "Stick-slip", rows));
    Ok(())
}

/// Fig. 8: PID hunting.
fn fig08(figures: &mut Vec<PaperFigure>, tables: &mut Vec<Numbers>) -> Result<()> {
    let runs = runs(Scenario::Pid, 5000)?;
    let mut fig = Figure::new("time t [s]", "position x [m]").title("Fig. 8: hunting");
    let mut rows = Vec::new();
    for (i, (f, m)) in runs.iter().enumerate() {
        let x = m.t.iter().zip(&m.x).map(|(t, x)| (*t, *x)).collect();
        fig = fig.curve(
            Curve::new(x, Friction::style(i), PALETTE[i])
                .label(format!("x, {}", f.label()))
                .key(format!("x{}", f.tag())),
        );
        let late: Vec<String> = m
            .events
            .iter()
            .filter(|e| e.kind == EventKind::VelocityZero && e.t > 50.0)
            .map(|e| format!("{} m at {} s", sig(e.x, 8), sig(e.t, 6)))
            .collect();
        rows.push((
            format!("velocity sign changes after 50 s (stops), {}", f.label()),
            late.join("; "),
        ));
    }
    let xd = vec![(0.0, 1.0), (100.0, 1.0)];
    fig = fig.curve(
        Curve::new(xd, LineStyle::Dashed, BLACK)
            .label("xd")
            .key("xd"),
    );
    figures.push(paper_figure(
        8,
        "PID hunting",
        format!(
            "Position under PID control (Kp = 3, Ki = 4, Kv = 6) towards xd = 1 m (dashed): \
             the integral action and stiction make a limit cycle, the mass parking on either \
             side of xd. LuGre solid, beside it: {}.",
            others_caption()
        ),
        fig,
        ["t", "x"],
    ));
    tables.push((8, "PID hunting", rows));
    Ok(())
}

/// The numbers of a stick-slip run: slip onsets, period, energies (`tag` after each name).
fn stick_slip_rows(m: &Motion, tag: &str) -> Vec<(String, String)> {
    let onsets: Vec<f64> = m
        .events
        .iter()
        .filter(|e| e.kind == EventKind::VelocityUp)
        .map(|e| e.t)
        .collect();
    let mut rows = vec![(
        format!("slip onsets (v rising through 0.1 m/s){tag}"),
        onsets
            .iter()
            .map(|t| format!("{} s", sig(*t, 10)))
            .collect::<Vec<_>>()
            .join(", "),
    )];
    if onsets.len() >= 2 {
        rows.push((
            format!("period{tag}"),
            format!("{} s", sig(onsets[1] - onsets[0], 10)),
        ));
    }
    rows.push((
        format!("energy: drive in / dissipated{tag}"),
        format!(
            "{} J / {} J",
            sig(m.energy.input, 8),
            sig(m.energy.dissipated, 8)
        ),
    ));
    rows
}

/// The report's `index.html`.
pub(crate) fn page(r: &Report) -> String {
    let mut h = String::with_capacity(32 * 1024);
    h.push_str(HEAD);
    let _ = write!(
        h,
        "<h1>Friction in closed loop: the experiments of Canudas de Wit et al. (1995), redrawn</h1>\n\
         <p class=\"lead\">Figures 2, 3, 4, 6 and 8 of C. Canudas de Wit, H. Olsson, K. J. \
         Åström, P. Lischinsky, <i>A new model for control of systems with friction</i>, IEEE \
         TAC 40(3), 1995, recomputed by <code>lugre paper</code> (lugre {}) with the \
         paper's Table I (σ0 = 10⁵ N/m, σ1 = √10⁵ N s/m, σ2 = 0.4 N s/m, Fc = 1 N, Fs = 1.5 N, \
         vs = 10⁻³ m/s) and a 1 kg mass, at the solver's default tolerance (rtol 10⁻⁸). Each \
         experiment is also <code>lugre dynamics --scenario NAME</code>. Every figure shows \
         beside LuGre each friction model of the zoo with a finite-rate form on the same \
         Table I, its other parameters at their defaults on that scale ({}; <code>lugre \
         dynamics --model NAME --scenario NAME</code>). <a href=\"../index.html\">\
         The first report</a>: the figures of Ikhouane, Mañosa, Pujol.</p>\n",
        env!("CARGO_PKG_VERSION"),
        esc(&others_caption())
    );
    figures_with_numbers(&mut h, r);
    h.push_str("</body>\n</html>\n");
    h
}

/// Each figure of `r` followed by the tables of numbers shown with it.
pub(crate) fn figures_with_numbers(h: &mut String, r: &Report) {
    for f in &r.figures {
        figure(h, f);
        for (n, heading, rows) in &r.tables {
            if *n == f.number {
                let _ = write!(h, "<div class=\"numbers\"><h3>{}</h3><table>", esc(heading));
                for (q, v) in rows {
                    let _ = write!(h, "<tr><td>{}</td><td>{}</td></tr>", esc(q), esc(v));
                }
                h.push_str("</table></div>\n");
            }
        }
    }
}
