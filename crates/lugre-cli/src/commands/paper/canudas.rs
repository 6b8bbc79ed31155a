//! The second report of `lugre paper`: the experiments of Canudas de Wit, Olsson, Åström and
//! Lischinsky, "A new model for control of systems with friction" (IEEE TAC 40(3), 1995), Figs.
//! 2, 3, 4, 6 and 8, redrawn from `lugre::dynamics` with Table I and a 1 kg mass, with their
//! numbers, in `canudas1995/` (its own `index.html`, linked from the first).

use anyhow::Result;
use lugre::dynamics::{EventKind, Motion, Request, Scenario, Tolerances};
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

/// The elasto-plastic friction's break-away displacement beside LuGre's: half of `Fc / sigma0`
/// of Table I (purely elastic up to 0.5 N).
const ZBA: f64 = 5e-6;

/// The experiment's setup with Table I, 1 kg, and the elasto-plastic law (`zba`) or LuGre's.
fn setup(sc: Scenario, zba: Option<f64>) -> Result<lugre::dynamics::Setup> {
    let r = Request::new().with_scenario(sc).with_model(table1()?);
    let r = match zba {
        Some(zba) => r.with_elastoplastic(zba),
        None => r,
    };
    Ok(r.build()?)
}

/// The experiment's run at the solver's default tolerance, sampled `n + 1` times.
fn run(sc: Scenario, n: usize) -> Result<(lugre::dynamics::Motion, lugre::dynamics::Setup)> {
    run_law(sc, n, None)
}

/// [`run`] with the elasto-plastic law (`zba`) or LuGre's.
fn run_law(
    sc: Scenario,
    n: usize,
    zba: Option<f64>,
) -> Result<(lugre::dynamics::Motion, lugre::dynamics::Setup)> {
    let setup = setup(sc, zba)?;
    let times = lugre::simulate::uniform_times(0.0, setup.t_end, 1, n);
    let m = setup
        .system
        .solve(setup.t_end, &times, Tolerances::default())?;
    Ok((m, setup))
}

/// The experiment with GMS friction on Table I's scale
/// ([`lugre::zoo::gms::on_lugre_scale`]), sampled `n + 1` times (with the break-away of a
/// ramp).
fn run_gms(sc: Scenario, n: usize) -> Result<lugre::dynamics::Outcome> {
    let gms = lugre::zoo::gms::on_lugre_scale(&LuGreParams::canudas_de_wit_1995())?;
    let plan = Request::new()
        .with_scenario(sc)
        .with_zoo(&lugre::zoo::ZooModel::MaxwellSlip(gms))?
        .with_samples(n as u64 + 1)?
        .build()?;
    Ok(plan.run()?)
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
    let (m, _) = run(Scenario::Presliding, 6500)?;
    let (ep, _) = run_law(Scenario::Presliding, 6500, Some(ZBA))?;
    let gms = run_gms(Scenario::Presliding, 6500)?.motion;
    let force_x = |m: &Motion| -> Vec<(f64, f64)> {
        m.drive
            .iter()
            .zip(&m.x)
            .map(|(f, x)| (*f, x * 1e6))
            .collect()
    };
    let points = force_x(&m);
    figures.push(paper_figure(
        2,
        "pre-sliding displacement",
        "Pre-sliding displacement x (µm) against the applied force (N), the force ramped to \
         ±1.425 N (95 % of Fs) with holds at 10-15, 35-40 and 60-65 s; dashed: the \
         elasto-plastic friction of Dupont et al. (2002) on the same Table I with zba = 5 µm \
         (purely elastic up to 0.5 N); dotted: GMS friction (Al-Bender et al. 2005) with four \
         elements on Table I's scale (Σ k_i = σ0, Σ f_i = Fs), whose minor loops close."
            .into(),
        Figure::new("applied force [N]", "displacement x [µm]")
            .title("Fig. 2: pre-sliding displacement")
            .curve(
                Curve::new(points, LineStyle::Solid, PALETTE[0])
                    .label("LuGre")
                    .key("x"),
            )
            .curve(
                Curve::new(force_x(&ep), LineStyle::Dashed, PALETTE[1])
                    .label("elasto-plastic")
                    .key("x_elastoplastic"),
            )
            .curve(
                Curve::new(force_x(&gms), LineStyle::Dotted, PALETTE[2])
                    .label("GMS")
                    .key("x_gms"),
            ),
        ["force", "x_um"],
    ));
    let at = |m: &Motion, t: f64| {
        m.t.iter()
            .position(|&s| (s - t).abs() < 1e-9)
            .map(|i| m.x[i])
    };
    let mut rows = Vec::new();
    for t in [10.0, 15.0, 40.0, 65.0] {
        if let (Some(x), Some(x_ep), Some(x_gms)) = (at(&m, t), at(&ep, t), at(&gms, t)) {
            rows.push((
                format!("x({t} s): LuGre / elasto-plastic / GMS"),
                format!(
                    "{} / {} / {} µm",
                    sig(x * 1e6, 10),
                    sig(x_ep * 1e6, 10),
                    sig(x_gms * 1e6, 10)
                ),
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
        let (m, _) = run(Scenario::Lag { w }, 3000)?;
        // The last of the three periods: the steady loop.
        let start = 2 * m.t.len() / 3;
        let points = (start..m.t.len())
            .map(|k| (m.v[k] * 1e3, m.friction[k]))
            .collect();
        fig = fig.curve(
            Curve::new(points, LineStyle::Solid, PALETTE[i])
                .label(format!("ω = {w} rad/s"))
                .key(format!("w{w}")),
        );
    }
    figures.push(paper_figure(
        3,
        "frictional lag",
        "Friction against velocity under v = 10⁻³ (cos ωt + 1.5) m/s, ω = 1, 10, 25 rad/s (the \
         third period of each): the loops widen with the frequency."
            .into(),
        fig,
        ["v_mm_s", "friction"],
    ));
    Ok(())
}

/// Fig. 4: break-away force against the force rate.
fn fig04(figures: &mut Vec<PaperFigure>, tables: &mut Vec<Numbers>) -> Result<()> {
    let rates = [1.0, 2.0, 3.0, 5.0, 7.0, 10.0, 15.0, 20.0, 25.0, 30.0];
    let mut points = Vec::new();
    let mut points_ep = Vec::new();
    let mut points_gms = Vec::new();
    let mut rows = Vec::new();
    for rate in rates {
        let breakaway = |zba| -> Result<_> {
            let setup = setup(Scenario::Breakaway { rate }, zba)?;
            Ok(setup.system.breakaway(setup.t_end, Tolerances::default())?)
        };
        if let Some(b) = breakaway(None)? {
            points.push((rate, b.force));
            rows.push((
                format!("r = {rate} N/s"),
                format!("F = {} N at t = {} s", sig(b.force, 10), sig(b.t, 10)),
            ));
        }
        if let Some(b) = breakaway(Some(ZBA))? {
            points_ep.push((rate, b.force));
            rows.push((
                format!("r = {rate} N/s, elasto-plastic"),
                format!("F = {} N at t = {} s", sig(b.force, 10), sig(b.t, 10)),
            ));
        }
        if let Some(b) = run_gms(Scenario::Breakaway { rate }, 1)?.breakaway {
            points_gms.push((rate, b.force));
            rows.push((
                format!("r = {rate} N/s, GMS"),
                format!("F = {} N at t = {} s", sig(b.force, 10), sig(b.t, 10)),
            ));
        }
    }
    figures.push(paper_figure(
        4,
        "break-away force",
        "Break-away force (the first peak of the friction force under F = r t) against the force \
         rate r, 1 to 30 N/s: the faster the ramp, the lower the break-away force. (Above about \
         35 N/s the first maximum is a shallow bump just above Fc, no longer a break-away peak.) \
         Dashed: the elasto-plastic friction (zba = 5 µm); dotted: GMS on Table I's scale \
         (attraction C = 10 N/s)."
            .into(),
        Figure::new("force rate r [N/s]", "break-away force [N]")
            .title("Fig. 4: break-away force")
            .curve(
                Curve::new(points, LineStyle::Solid, PALETTE[0])
                    .label("LuGre")
                    .key("breakaway"),
            )
            .curve(
                Curve::new(points_ep, LineStyle::Dashed, PALETTE[1])
                    .label("elasto-plastic")
                    .key("breakaway_elastoplastic"),
            )
            .curve(
                Curve::new(points_gms, LineStyle::Dotted, PALETTE[2])
                    .label("GMS")
                    .key("breakaway_gms"),
            ),
        ["rate", "force"],
    ));
    tables.push((4, "Break-away", rows));
    Ok(())
}

/// Fig. 6: stick-slip.
fn fig06(figures: &mut Vec<PaperFigure>, tables: &mut Vec<Numbers>) -> Result<()> {
    let (m, _) = run(Scenario::StickSlip, 3000)?;
    let (ep, _) = run_law(Scenario::StickSlip, 3000, Some(ZBA))?;
    let gms = run_gms(Scenario::StickSlip, 3000)?.motion;
    let x_gms = gms.t.iter().zip(&gms.x).map(|(t, x)| (*t, *x)).collect();
    let x = m.t.iter().zip(&m.x).map(|(t, x)| (*t, *x)).collect();
    let x_ep = ep.t.iter().zip(&ep.x).map(|(t, x)| (*t, *x)).collect();
    let end = m.t.iter().map(|t| (*t, 0.1 * t)).collect();
    figures.push(paper_figure(
        6,
        "stick-slip",
        "Stick-slip: a spring of 2 N/m pulled at 0.1 m/s (dashed: its free end) and the mass's \
         position x, with LuGre friction, with the elasto-plastic friction (zba = 5 µm) and \
         with GMS friction on Table I's scale."
            .into(),
        Figure::new("time t [s]", "position [m]")
            .title("Fig. 6: stick-slip")
            .curve(
                Curve::new(x, LineStyle::Solid, PALETTE[0])
                    .label("mass x, LuGre")
                    .key("x"),
            )
            .curve(
                Curve::new(x_ep, LineStyle::Solid, PALETTE[1])
                    .label("mass x, elasto-plastic")
                    .key("x_elastoplastic"),
            )
            .curve(
                Curve::new(x_gms, LineStyle::Solid, PALETTE[2])
                    .label("mass x, GMS")
                    .key("x_gms"),
            )
            .curve(
                Curve::new(end, LineStyle::Dashed, BLACK)
                    .label("free end 0.1 t")
                    .key("end"),
            ),
        ["t", "x"],
    ));
    let mut rows = stick_slip_rows(&m, "");
    rows.extend(stick_slip_rows(&ep, ", elasto-plastic"));
    rows.extend(stick_slip_rows(&gms, ", GMS"));
    tables.push((6, "Stick-slip", rows));
    Ok(())
}

/// Fig. 8: PID hunting.
fn fig08(figures: &mut Vec<PaperFigure>, tables: &mut Vec<Numbers>) -> Result<()> {
    let (m, _) = run(Scenario::Pid, 5000)?;
    let x = m.t.iter().zip(&m.x).map(|(t, x)| (*t, *x)).collect();
    let xd = vec![(0.0, 1.0), (100.0, 1.0)];
    figures.push(paper_figure(
        8,
        "PID hunting",
        "Position under PID control (Kp = 3, Ki = 4, Kv = 6) towards xd = 1 m (dashed): the \
         integral action and stiction make a limit cycle, the mass parking on either side of xd."
            .into(),
        Figure::new("time t [s]", "position x [m]")
            .title("Fig. 8: hunting")
            .curve(
                Curve::new(x, LineStyle::Solid, PALETTE[0])
                    .label("x")
                    .key("x"),
            )
            .curve(
                Curve::new(xd, LineStyle::Dashed, BLACK)
                    .label("xd")
                    .key("xd"),
            ),
        ["t", "x"],
    ));
    let stops: Vec<(f64, f64)> = m
        .events
        .iter()
        .filter(|e| e.kind == EventKind::VelocityZero)
        .map(|e| (e.t, e.x))
        .collect();
    let late: Vec<String> = stops
        .iter()
        .filter(|(t, _)| *t > 50.0)
        .map(|(t, x)| format!("{} m at {} s", sig(*x, 8), sig(*t, 6)))
        .collect();
    tables.push((
        8,
        "PID hunting",
        vec![(
            "velocity sign changes after 50 s (stops)".into(),
            late.join("; "),
        )],
    ));
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
         experiment is also <code>lugre dynamics --scenario NAME</code>. Figs. 2, 4 and 6 show \
         beside LuGre the elasto-plastic friction of Dupont, Hayward, Armstrong and Altpeter \
         (IEEE TAC 47(5), 2002) on the same Table I with zba = 5 µm (<code>lugre dynamics \
         --model elastoplastic --zba 5e-6 --scenario NAME</code>) and GMS friction \
         (Al-Bender, Lampaert and Swevers, IEEE TAC 50(11), 2005) with four elements on Table \
         I's scale (<code>lugre dynamics --model maxwell-slip --scenario NAME</code>). <a href=\"../index.html\">\
         The first report</a>: the figures of Ikhouane, Mañosa, Pujol.</p>\n",
        env!("CARGO_PKG_VERSION")
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
