//! `lugre loop`: the hysteresis loop y° (eqs. 8-10), Theorem A for bimodal inputs, every minor
//! loop with its energies, as a table, JSON or CSV.

use anyhow::{anyhow, bail, Result};
use clap::Args;
use lugre::model::named::Needed;
use lugre::{HysteresisLoop, Loop, LoopPoint, TheoremA};
use std::io::Write;

use crate::args::{
    check_files, ModelArgs, ModelChoice, OutputArgs, PeriodicInput, PeriodicInputArgs, PlotArgs,
};
use crate::fmt::{exact, sig};
use crate::hysteresis::{kind_name, Response};
use crate::io::atomic::write_atomic;
use crate::io::json::JsonOut;
use crate::numbers::{parse_list, Whole};
use crate::plot::{Curve, Figure, LineStyle, Marker, Shape, Units, BLACK, PALETTE};
use crate::zoo_args::{zoo_json, zoo_line};
use lugre::zoo::ZooModel;

/// Rows of a table printed before the rest is summarised (all of it is in --json / --csv).
const MAX_TABLE_ROWS: usize = 40;

/// Samples written by `--csv` when neither `--samples` nor `--at` is given.
const DEFAULT_CSV_SAMPLES: usize = 1001;

/// The help of `--csv` for this command (the columns are the core's).
fn csv_help() -> String {
    format!(
        "Write the sampled curve (columns {}) to this CSV file ({DEFAULT_CSV_SAMPLES} samples unless --samples or --at is given)",
        LoopPoint::COLUMNS.join(",")
    )
}
/// The help of `--plot` for this command.
const PLOT_HELP: &str =
    "Draw the loop in the (u, y°) plane, the minor loops solid with their start \
    (circle) and end (square) marked, to an SVG or PNG file";

#[derive(Args, Debug)]
#[command(
    mut_arg("csv", |a| a.help(csv_help())),
    mut_arg("plot", |a| a.help(PLOT_HELP))
)]
pub(crate) struct LoopArgs {
    #[command(flatten)]
    pub(crate) model: ModelArgs,
    #[command(flatten)]
    pub(crate) input: PeriodicInputArgs,
    /// Evaluate the loop at these rho (any real numbers; the loop is periodic).
    #[arg(
        long,
        value_name = "R1,R2,...",
        allow_hyphen_values = true,
        help_heading = "Output"
    )]
    pub(crate) at: Option<String>,
    /// N >= 2 evenly spaced points over one period, rho = 0 and rho = P included.
    #[arg(
        long,
        value_name = "N",
        allow_hyphen_values = true,
        value_parser = Whole(0),
        help_heading = "Output"
    )]
    pub(crate) samples: Option<usize>,
    #[command(flatten)]
    pub(crate) output: OutputArgs,
    #[command(flatten)]
    pub(crate) plot: PlotArgs,
}

/// The request, from the flags (all checked before anything is computed).
struct Request {
    model: Chosen,
    input: PeriodicInput,
    /// The rhos of `--at`.
    at: Option<Vec<f64>>,
    samples: Option<usize>,
}

/// The model: LuGre or Dahl (their loop depends on `sigma0` and `g(0)` alone), or a model of
/// the zoo.
enum Chosen {
    Classic(ModelChoice),
    Zoo(Box<ZooModel>),
}

/// What `lugre loop` computes, every number finite: the loop, its loops, Theorem A for a
/// bimodal input, and the points asked for (`--at`, `--samples`).
struct Outcome {
    hl: Response,
    loops: Vec<Loop>,
    theorem_a: Option<TheoremA>,
    points: Option<Vec<LoopPoint>>,
}

pub(crate) fn run(args: &LoopArgs) -> Result<()> {
    check_files(args.input.input.as_deref(), &args.output, Some(&args.plot))?;
    let request = parse(args)?;
    let outcome = compute(&request)?;
    report(args, &request.model, &outcome)
}

fn parse(args: &LoopArgs) -> Result<Request> {
    let model = match args.model.build_zoo()? {
        Some(z) => Chosen::Zoo(Box::new(z)),
        None => Chosen::Classic(args.model.build()?),
    };
    let input = args.input.build()?;
    let at = match &args.at {
        Some(text) => Some(parse_list("--at", text)?),
        None => None,
    };
    if let Some(n) = args.samples {
        lugre::loops::check_samples(n).map_err(|e| anyhow!(e.render("--samples")))?;
    }
    Ok(Request {
        model,
        input,
        at,
        samples: args.samples,
    })
}

fn compute(request: &Request) -> Result<Outcome> {
    let turning = request.input.turning_points();
    let (hl, loops, theorem_a) = match &request.model {
        Chosen::Classic(model) => {
            let hl = HysteresisLoop::new(model.rate_independent(), &turning)?;
            let theorem_a = match &request.input {
                PeriodicInput::Bimodal(b) => Some(TheoremA::new(b, &hl)),
                _ => None,
            };
            (Response::LuGre(hl.clone()), hl.loops(), theorem_a)
        }
        Chosen::Zoo(model) => {
            let zl = model.loops(&turning)?;
            let loops = zl.loops().to_vec();
            (
                Response::Zoo(Box::new(((**model).clone(), zl))),
                loops,
                None,
            )
        }
    };
    check_loops_finite(&loops)?;
    let points: Option<Vec<LoopPoint>> = match (&request.at, request.samples) {
        (Some(rhos), _) => Some(hl.points(rhos)),
        (None, Some(n)) => Some(hl.sample(n)),
        (None, None) => None,
    };
    if let Some(p) = &points {
        if p.iter().any(|p| !p.y.is_finite() || !p.u.is_finite()) {
            bail!("a requested point overflows f64 (rho too large?)");
        }
    }
    Ok(Outcome {
        hl,
        loops,
        theorem_a,
        points,
    })
}

/// Writes the CSV and the figure asked for, then prints the JSON document or the table.
fn report(args: &LoopArgs, model: &Chosen, outcome: &Outcome) -> Result<()> {
    if let Some(path) = &args.output.csv {
        write_atomic(path, |w| outcome.write_csv(w))?;
    }
    if let Some(path) = &args.plot.path {
        // The loop reads its file's columns as they are (no --scale).
        let units = Units::for_figure(
            args.input.input.as_deref(),
            &lugre_io::ReadOptions::default(),
            args.model.preset.is_some(),
            args.plot.units.as_deref(),
        )?;
        loop_figure(&outcome.hl, &outcome.loops, &units, model).save(path)?;
    }

    let stdout = std::io::stdout();
    if args.output.json {
        outcome.write_json(model, JsonOut::new(stdout.lock()))?;
    } else {
        let mut out = std::io::BufWriter::with_capacity(1 << 16, stdout.lock());
        let line = match model {
            Chosen::Classic(m) => m.describe(Needed::RateIndependent),
            Chosen::Zoo(m) => zoo_line(m),
        };
        outcome.print_table(&mut out, &line)?;
        if let Some(path) = &args.output.csv {
            writeln!(
                out,
                "\nWrote the sampled curve ({}) to {}",
                LoopPoint::COLUMNS.join(","),
                path.display()
            )?;
        }
        if let Some(path) = &args.plot.path {
            writeln!(out, "Drew the loop to {}", path.display())?;
        }
        out.flush()?;
    }
    Ok(())
}

fn check_loops_finite(loops: &[Loop]) -> Result<()> {
    let finite = |p: &LoopPoint| p.rho.is_finite() && p.u.is_finite() && p.y.is_finite();
    for l in loops {
        let ok = finite(&l.start)
            && finite(&l.reversal)
            && finite(&l.end)
            && l.energy.work.is_finite()
            && l.energy.stored_energy_change.is_finite()
            && l.energy.dissipation.is_finite();
        if !ok {
            bail!("the loop energies overflow f64 for this model and input (values too large)");
        }
    }
    Ok(())
}

impl Outcome {
    /// `rho,u,y` at the points asked for, else at [`DEFAULT_CSV_SAMPLES`] points.
    fn write_csv(&self, w: &mut dyn Write) -> Result<()> {
        let sampled;
        let points = match &self.points {
            Some(p) => p,
            None => {
                sampled = self.hl.sample(DEFAULT_CSV_SAMPLES);
                &sampled
            }
        };
        writeln!(w, "{}", LoopPoint::COLUMNS.join(","))?;
        for p in points {
            let [rho, u, y] = p.values().map(exact);
            writeln!(w, "{rho},{u},{y}")?;
        }
        Ok(())
    }

    /// Everything `lugre loop --json` prints (the documented schema; keys may be added, never
    /// renamed).
    fn write_json<W: Write>(&self, model: &Chosen, mut j: JsonOut<W>) -> std::io::Result<()> {
        let hl = &self.hl;
        j.raw("{\"model\":")?;
        match model {
            Chosen::Classic(m) => j.raw(&m.to_json().to_string())?,
            Chosen::Zoo(m) => j.raw(&zoo_json(m).to_string())?,
        }
        if let Response::LuGre(hl) = hl {
            j.field(",\"g0\":", hl.model().g0())?;
            j.field(",\"a\":", hl.model().a())?;
        }
        j.field(",\"period\":", hl.period())?;
        j.raw(",\"turning_points\":")?;
        j.points(&hl.turning_points())?;
        if let Some(ta) = &self.theorem_a {
            j.raw(",\"theorem_a\":{\"rho\":")?;
            j.array(&ta.rho)?;
            j.raw(",\"y\":")?;
            j.array(&ta.y)?;
            j.raw(",\"minor_loop\":")?;
            j.array(&ta.minor_loop)?;
            j.raw("}")?;
        }
        j.raw(",\"loops\":[")?;
        for (i, l) in self.loops.iter().enumerate() {
            j.raw(if i == 0 { "{" } else { ",{" })?;
            write_loop_json(&mut j, l)?;
            j.raw("}")?;
        }
        j.raw("]")?;
        j.field(",\"work_per_period\":", hl.work_per_period())?;
        if let Some(points) = &self.points {
            j.raw(",\"points\":")?;
            j.points(points)?;
        }
        j.raw("}\n")?;
        j.finish()
    }

    fn print_table(&self, out: &mut impl Write, model: &str) -> Result<()> {
        let hl = &self.hl;
        writeln!(out, "{model}")?;
        if let Response::LuGre(hl) = hl {
            let m = hl.model();
            write!(
                out,
                "g(0) = {}   a = sigma0/g(0) = {}   ",
                sig(m.g0(), 10),
                sig(m.a(), 10)
            )?;
        }
        writeln!(
            out,
            "period P = {} (total variation of u per period)",
            sig(hl.period(), 10)
        )?;

        let (y, _) = hl.output();
        writeln!(out, "\nHysteresis loop {y} at the turning points")?;
        writeln!(out, "{:>6} {:>16} {:>16} {:>18}", "k", "rho", "u", y)?;
        let tp = hl.turning_points();
        for (k, p) in tp.iter().enumerate().take(MAX_TABLE_ROWS) {
            writeln!(
                out,
                "{:>6} {:>16} {:>16} {:>18}",
                k,
                sig(p.rho, 10),
                sig(p.u, 10),
                sig(p.y, 12)
            )?;
        }
        more(out, tp.len())?;
        if let Some(ta) = &self.theorem_a {
            print_theorem_a(out, ta)?;
        }
        print_loops(out, &self.loops)?;
        writeln!(
            out,
            "\nWork per period (energy dissipated per cycle): {}",
            sig(hl.work_per_period(), 12)
        )?;
        if hl.work_per_period() < 0.0 {
            writeln!(
                out,
                "(negative: the loop runs counterclockwise in the (u, {y}) plane, the output lagging the input as a play operator's does; its area is the magnitude)"
            )?;
        }
        if let Some(points) = &self.points {
            print_points(out, points)?;
        }
        Ok(())
    }
}

/// The fields of one loop in the JSON document, from `"kind"` to `"depth"`.
fn write_loop_json<W: Write>(j: &mut JsonOut<W>, l: &Loop) -> std::io::Result<()> {
    j.raw("\"kind\":\"")?;
    j.raw(kind_name(l.kind))?;
    j.raw("\",\"start\":")?;
    j.point(&l.start)?;
    j.raw(",\"reversal\":")?;
    j.point(&l.reversal)?;
    j.raw(",\"end\":")?;
    j.point(&l.end)?;
    j.field(",\"work\":", l.energy.work)?;
    j.field(",\"stored_energy_change\":", l.energy.stored_energy_change)?;
    j.field(",\"dissipation\":", l.energy.dissipation)?;
    j.field(",\"closure_gap\":", l.energy.closure_gap)?;
    j.raw(",\"parent\":")?;
    match l.parent {
        Some(p) => j.int(p)?,
        None => j.raw("null")?,
    }
    j.raw(",\"depth\":")?;
    j.int(l.depth)
}

fn print_theorem_a(out: &mut impl Write, ta: &TheoremA) -> Result<()> {
    writeln!(out, "\nTheorem A (bimodal input)")?;
    writeln!(out, "{:>6} {:>16} {:>18}", "i", "rho_i", "y°(rho_i)")?;
    for i in 0..6 {
        writeln!(
            out,
            "{:>6} {:>16} {:>18}",
            i,
            sig(ta.rho[i], 10),
            sig(ta.y[i], 12)
        )?;
    }
    writeln!(
        out,
        "minor loop: rho in [rho_1, rho_5] = [{}, {}]",
        sig(ta.minor_loop[0], 10),
        sig(ta.minor_loop[1], 10)
    )?;
    Ok(())
}

fn print_loops(out: &mut impl Write, loops: &[Loop]) -> Result<()> {
    writeln!(
        out,
        "\nLoops (arc from rho_A through the reversal rho_B to the first return rho_C; energies over the arc)"
    )?;
    writeln!(
        out,
        "{:>5} {:>5} {:>6} {:>6} {:>11} {:>11} {:>11} {:>11} {:>11} {:>13} {:>13} {:>13} {:>13}",
        "#",
        "kind",
        "depth",
        "parent",
        "rho_A",
        "rho_B",
        "rho_C",
        "u_A",
        "u_B",
        "work W",
        "stored dV",
        "dissip. D",
        "gap y_C-y_A"
    )?;
    for (i, l) in loops.iter().enumerate().take(MAX_TABLE_ROWS) {
        writeln!(
            out,
            "{:>5} {:>5} {:>6} {:>6} {:>11} {:>11} {:>11} {:>11} {:>11} {:>13} {:>13} {:>13} {:>13}",
            i,
            kind_name(l.kind),
            l.depth,
            l.parent.map_or("-".to_string(), |p| p.to_string()),
            sig(l.start.rho, 8),
            sig(l.reversal.rho, 8),
            sig(l.end.rho, 8),
            sig(l.start.u, 8),
            sig(l.reversal.u, 8),
            sig(l.energy.work, 8),
            sig(l.energy.stored_energy_change, 8),
            sig(l.energy.dissipation, 8),
            sig(l.energy.closure_gap, 8),
        )?;
    }
    more(out, loops.len())
}

fn print_points(out: &mut impl Write, points: &[LoopPoint]) -> Result<()> {
    writeln!(out, "\nPoints")?;
    writeln!(out, "{:>16} {:>16} {:>18}", "rho", "u", "y°")?;
    for p in points.iter().take(MAX_TABLE_ROWS) {
        writeln!(
            out,
            "{:>16} {:>16} {:>18}",
            sig(p.rho, 10),
            sig(p.u, 10),
            sig(p.y, 12)
        )?;
    }
    more(out, points.len())
}

fn more(out: &mut impl Write, n: usize) -> Result<()> {
    if n > MAX_TABLE_ROWS {
        writeln!(
            out,
            "{:>6} ... {} more rows: use --json (or --csv for the curve) to get all",
            "",
            n - MAX_TABLE_ROWS
        )?;
    }
    Ok(())
}

/// Minor loops drawn in colour (the largest by input range); the others are part of the
/// drawn major loop all the same.
const MAX_DRAWN_MINOR_LOOPS: usize = 10;

/// The loop in the (u, y°) plane as the paper's Fig. 15 draws it.
fn loop_figure(hl: &Response, loops: &[Loop], units: &Units, model: &Chosen) -> Figure {
    let major = &loops[0];
    let mut minors: Vec<&Loop> = loops[1..].iter().collect();
    minors.sort_by(|p, q| {
        let range = |l: &Loop| (l.reversal.u - l.start.u).abs();
        range(q).total_cmp(&range(p))
    });
    let drawn = minors.len().min(MAX_DRAWN_MINOR_LOOPS);
    let title = match model {
        Chosen::Classic(_) => "Hysteresis loop".to_string(),
        Chosen::Zoo(m) => format!("Hysteresis loop, {} model", m.spec().label),
    };
    let (_, output) = hl.output();
    let mut fig = Figure::new(units.u("input u"), units.force(output)).title(title.clone());
    fig = fig.curve(
        Curve::new(
            hl.arc(major.start.rho, major.end.rho),
            if drawn > 0 {
                LineStyle::Dashed
            } else {
                LineStyle::Solid
            },
            BLACK,
        )
        .label(format!("hysteresis loop {}", hl.output().0))
        .width(2),
    );
    for (i, l) in minors.iter().take(drawn).enumerate() {
        let label = format!(
            "minor loop, rho in [{}, {}]",
            sig(l.start.rho, 4),
            sig(l.end.rho, 4)
        );
        fig = fig.curve(
            Curve::new(
                hl.arc(l.start.rho, l.end.rho),
                // Colours repeat after five loops: the line style changes then, so every drawn
                // loop stays distinguishable, in grey scale too.
                [LineStyle::Solid, LineStyle::DashDot, LineStyle::Dotted][(i / PALETTE.len()) % 3],
                PALETTE[i % PALETTE.len()],
            )
            .label(label)
            .width(3),
        );
    }
    for (i, l) in minors.iter().take(drawn).enumerate() {
        let first = i == 0;
        fig = fig
            .marker(Marker {
                label: first.then(|| "start of a minor loop (rho_A)".to_string()),
                at: (l.start.u, l.start.y),
                shape: Shape::Circle,
                color: BLACK,
            })
            .marker(Marker {
                label: first.then(|| "end: first return to u_A (rho_C)".to_string()),
                at: (l.end.u, l.end.y),
                shape: Shape::Square,
                color: BLACK,
            });
    }
    if minors.len() > drawn {
        fig.title = Some(format!(
            "{title} ({drawn} largest of {} minor loops in colour)",
            minors.len()
        ));
    }
    fig
}
