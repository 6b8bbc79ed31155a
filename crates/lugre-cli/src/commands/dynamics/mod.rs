//! `lugre dynamics`: a mass with LuGre friction driven by a force, a spring, a controller or a
//! prescribed velocity (`lugre::dynamics`), with the 1995 experiments of Canudas de Wit et al.
//! as named scenarios. Everything is computed and checked before anything is written.

use anyhow::{anyhow, bail, Result};
use clap::Args;
use lugre::dynamics::{
    EventKind, Field, FrictionLaw, FrictionLoop, Motion, Outcome, Plan, Request, Scenario,
};
use lugre::fit::Family;
use lugre::model::Parameter;
use lugre::zoo::{ZooKind, ZooModel};
use lugre::{DynamicsError, LuGre};
use std::io::Write;

use crate::args::{model_line, ModelArgs, OutputArgs, PlotArgs};
use crate::fmt::{quoted, sig};
use crate::io::atomic::write_atomic;
use crate::io::csv::NumberRows;
use crate::io::json::JsonOut;
use crate::numbers::{parse_list, parse_number};
use crate::plot::{Curve, Figure, LineStyle, Panels, BLUE};
use lugre::model::named::Needed;
use lugre_io::Role;

/// Rows of the table printed (all of them are in --json / --csv).
const TABLE_HEAD: usize = 12;

/// `--scenario`'s help: the core's names of the 1995 experiments, each with its description
/// (the name is checked by the core, which words an unknown one as every front end does).
fn scenario_help() -> String {
    let names: Vec<String> = Scenario::NAMES
        .iter()
        .filter_map(|n| Some(format!("{n}: {}", Scenario::named(n).ok()?.description())))
        .collect();
    format!(
        "One of the 1995 experiments, a preset: Table I, a 1 kg mass, its drive and its end; every \
flag given on top of it replaces that part (--pid 3,8,6 on pid keeps its set point). {}",
        names.join("; ")
    )
}

#[derive(Args, Debug)]
#[command(mut_arg("csv", |a| a.help("Write t,x,v,z,friction,drive to this CSV file (with a \
prescribed velocity, drive is the force M v' + F that makes the mass follow it)")))]
#[command(mut_arg("plot", |a| a.help("Draw x, v and the friction against t, and the friction \
against x (SVG or PNG)")))]
pub(crate) struct DynamicsArgs {
    #[command(flatten)]
    pub(crate) model: ModelArgs,
    #[arg(long, value_name = "NAME", help = scenario_help(), help_heading = "System")]
    pub(crate) scenario: Option<String>,
    /// Mass M > 0 [kg] (a rotational system: the inertia [kg m^2]).
    #[arg(long, allow_hyphen_values = true, help_heading = "System")]
    pub(crate) mass: Option<f64>,
    /// Linear spring k >= 0 [N/m] from the mass to a free end (--pull or --end-profile).
    #[arg(long, allow_hyphen_values = true, help_heading = "System")]
    pub(crate) spring: Option<f64>,
    /// The spring's free end moves at this constant speed [m/s] from 0.
    #[arg(long, allow_hyphen_values = true, help_heading = "System")]
    pub(crate) pull: Option<f64>,
    /// The spring's free end along T:Y,... [s:m], linear in between, held after.
    #[arg(
        long,
        value_name = "T:Y,...",
        allow_hyphen_values = true,
        help_heading = "System"
    )]
    pub(crate) end_profile: Option<String>,
    /// Linear damper c >= 0 [N s/m] to the ground.
    #[arg(long, allow_hyphen_values = true, help_heading = "System")]
    pub(crate) damping: Option<f64>,
    /// Applied force along T:F,... [s:N], linear in between, held after.
    #[arg(
        long,
        value_name = "T:F,...",
        allow_hyphen_values = true,
        help_heading = "Drive"
    )]
    pub(crate) force_profile: Option<String>,
    /// Applied force F = R t [N/s]; the break-away (first peak of the friction) is reported.
    #[arg(
        long,
        value_name = "R",
        allow_hyphen_values = true,
        help_heading = "Drive"
    )]
    pub(crate) force_rate: Option<f64>,
    /// Applied force from a CSV file with a header naming the columns `t` [s] and `F` [N]
    /// (others ignored): a measured force history, linear between rows, held after; the run
    /// ends at its last time unless --t-end is given.
    #[arg(long, value_name = "FILE.csv", help_heading = "Drive")]
    pub(crate) input: Option<std::path::PathBuf>,
    #[command(flatten)]
    pub(crate) data: crate::args::DataArgs,
    /// PID gains KP,KI,KV on position: u = -KV v - KP (x - xd) - KI integral(x - xd).
    #[arg(
        long,
        value_name = "KP,KI,KV",
        allow_hyphen_values = true,
        help_heading = "Drive"
    )]
    pub(crate) pid: Option<String>,
    /// The PID's set point xd [m] (default 0), or T:XD,... stepping at those times.
    #[arg(
        long,
        value_name = "XD|T:XD,...",
        allow_hyphen_values = true,
        help_heading = "Drive"
    )]
    pub(crate) setpoint: Option<String>,
    /// Prescribed velocity along T:V,... [s:m/s] (the mass follows it; forces are reported).
    #[arg(
        long,
        value_name = "T:V,...",
        allow_hyphen_values = true,
        help_heading = "Drive"
    )]
    pub(crate) velocity_profile: Option<String>,
    /// End of the run [s].
    #[arg(long, allow_hyphen_values = true, help_heading = "Run")]
    pub(crate) t_end: Option<f64>,
    /// Output at these times (strictly increasing, in [0, t_end]).
    #[arg(
        long,
        value_name = "T1,T2,...",
        allow_hyphen_values = true,
        help_heading = "Run"
    )]
    pub(crate) times: Option<String>,
    /// N >= 2 evenly spaced output times over [0, t_end] (default 1001, at most 10^7).
    #[arg(
        long,
        value_name = "N",
        allow_hyphen_values = true,
        help_heading = "Run"
    )]
    pub(crate) samples: Option<String>,
    /// Report the friction-displacement loops of x(t): each closed loop (a rainflow cycle of
    /// x) with the work of the friction over it, the change of the energy stored in the
    /// friction (the bristles', or GMS's elements') and the dissipation, beside the
    /// rate-independent loop of `lugre loop` on the same turning points, of the same model
    /// (on by default for --scenario presliding).
    #[arg(long, help_heading = "Run")]
    pub(crate) loops: bool,
    /// Relative tolerance in (0, 1) (default 1e-8).
    #[arg(long, allow_hyphen_values = true, help_heading = "Run")]
    pub(crate) rtol: Option<f64>,
    /// Absolute tolerance on displacements [m] (default rtol g(0)/sigma0; velocities get it
    /// times sqrt(sigma0 / M)).
    #[arg(long, allow_hyphen_values = true, help_heading = "Run")]
    pub(crate) atol: Option<f64>,
    #[command(flatten)]
    pub(crate) output: OutputArgs,
    #[command(flatten)]
    pub(crate) plot: PlotArgs,
}

/// A problem with the flags: the request's (its message spelled with the flags) or another.
enum Bad {
    Request(DynamicsError),
    Other(anyhow::Error),
}

impl From<DynamicsError> for Bad {
    fn from(e: DynamicsError) -> Self {
        Bad::Request(e)
    }
}

impl From<anyhow::Error> for Bad {
    fn from(e: anyhow::Error) -> Self {
        Bad::Other(e)
    }
}

impl From<Bad> for anyhow::Error {
    fn from(b: Bad) -> Self {
        match b {
            Bad::Request(e) => anyhow!(e.render(flag)),
            Bad::Other(e) => e,
        }
    }
}

pub(crate) fn run(args: &DynamicsArgs) -> Result<()> {
    crate::args::check_files(args.input.as_deref(), &args.output, Some(&args.plot))?;
    let plan = parse(args).and_then(|r| Ok(r.build()?))?;
    if let Some(path) = &args.plot.path {
        crate::plot::check_path(path)?;
    }
    let outcome = plan.run().map_err(|e| match e {
        lugre::Error::Dynamics(d) => anyhow!(d.render(flag)),
        other => anyhow!(other),
    })?;
    report(args, &plan, &outcome)
}

/// The command line's spelling of a request field.
pub(crate) fn flag(field: Field) -> String {
    let name = match field {
        Field::Model => "preset",
        Field::Force => "force-profile",
        Field::End => "end-profile",
        Field::Velocity => "velocity-profile",
        other => return format!("--{}", other.name().replace('_', "-")),
    };
    format!("--{name}")
}

/// The flags as a core request: every flag given sets its field, over the scenario's.
fn parse(args: &DynamicsArgs) -> Result<Request, Bad> {
    let mut r = Request::new();
    if let Some(name) = &args.scenario {
        r = r.with_scenario(Scenario::named(name)?);
    }
    // A model of the zoo (`--model elastoplastic`): the core refuses one without a finite-rate
    // form and, on a scenario, takes the parameters not given from Table I.
    if let Some(zoo) = args.model.build_zoo()? {
        r = r.with_zoo(&zoo)?;
    } else if let Some(model) = named_model(&args.model)? {
        r = r.with_model(model);
    }
    if let Some(m) = args.mass {
        r = r.with_mass(m)?;
    }
    if let Some(c) = args.damping {
        r = r.with_damping(c)?;
    }
    if let Some(rate) = args.force_rate {
        r = r.with_force_rate(rate)?;
    }
    if let Some(text) = &args.force_profile {
        let (t, f) = pairs(Field::Force, text)?;
        r = r.with_force(t, f)?;
    }
    if let Some(path) = &args.input {
        let (t, f) = read_force(args, path)?;
        r = r.with_input(&path.display().to_string(), t, f)?;
    }
    if let Some(k) = args.spring {
        r = r.with_spring(k)?;
    }
    if let Some(v) = args.pull {
        r = r.with_pull(v)?;
    }
    if let Some(text) = &args.end_profile {
        let (t, y) = pairs(Field::End, text)?;
        r = r.with_end(t, y)?;
    }
    // Lists of numbers go to the core as they are: it counts them (`--pid takes 3 numbers`).
    if let Some(text) = &args.pid {
        r = r.with_numbers(Field::Pid, &numbers(Field::Pid, text)?)?;
    }
    if let Some(text) = &args.setpoint {
        r = if text.contains(':') {
            let (t, x) = pairs(Field::Setpoint, text)?;
            r.with_setpoint_steps(t, x)?
        } else {
            r.with_numbers(Field::Setpoint, &numbers(Field::Setpoint, text)?)?
        };
    }
    if let Some(text) = &args.velocity_profile {
        let (t, v) = pairs(Field::Velocity, text)?;
        r = r.with_velocity(t, v)?;
    }
    if let Some(t) = args.t_end {
        r = r.with_t_end(t)?;
    }
    if let Some(text) = &args.times {
        r = r.with_times(numbers(Field::Times, text)?)?;
    }
    if let Some(text) = &args.samples {
        r = match text.trim().parse::<u64>() {
            Ok(n) => r.with_samples(n)?,
            // Not a count (negative, fractional): the core's words for what a count must be.
            Err(_) => {
                let x = text.trim().parse::<f64>().map_err(|_| {
                    anyhow!(
                        "{} expects a number, got {}",
                        flag(Field::Samples),
                        quoted(text)
                    )
                })?;
                r.with_numbers(Field::Samples, &[x])?
            }
        };
    }
    if let Some(rtol) = args.rtol {
        r = r.with_rtol(rtol)?;
    }
    if let Some(atol) = args.atol {
        r = r.with_atol(atol)?;
    }
    if args.loops {
        r = r.with_loops(true);
    }
    Ok(r)
}

/// The model the flags name (a preset, or every parameter whose default is not neutral), or
/// none (a scenario's Table I then, else the request's error); flags that name only part of a
/// model are an error naming what is missing.
fn named_model(m: &ModelArgs) -> Result<Option<LuGre>> {
    if !m.names_any() {
        return Ok(None);
    }
    // Values given are checked first, then that the model is named.
    let model = m.build()?.lugre();
    m.check_named(Needed::All)?;
    Ok(Some(model))
}

/// The model as JSON: `kind` (`lugre` or the zoo's `elastoplastic`) and each parameter by name.
fn model_json(r: &Plan) -> serde_json::Value {
    if let Some(ms) = &r.gms {
        return crate::zoo_args::zoo_json(&ZooModel::from(ZooKind::MaxwellSlip(ms.clone())));
    }
    let p = r.system.model().params();
    let mut j = serde_json::json!({ "kind": r.system.law().name() });
    for (q, v) in p.named() {
        j[q.name()] = v.into();
    }
    if let FrictionLaw::ElastoPlastic { zba } = r.system.law() {
        j["zba"] = zba.into();
    }
    j
}

/// The model of the run in one line: the one the flags name, else the scenario's (Table I).
fn model_text(m: &ModelArgs, r: &Plan) -> Result<String> {
    if let Some(ms) = &r.gms {
        let line = crate::zoo_args::zoo_line(&ZooModel::from(ZooKind::MaxwellSlip(ms.clone())));
        return Ok(format!("GMS ({line})"));
    }
    if let FrictionLaw::ElastoPlastic { zba } = r.system.law() {
        let values: Vec<String> = r
            .system
            .model()
            .params()
            .named()
            .iter()
            .map(|(p, v)| format!("{} = {}", p.name(), sig(*v, 10)))
            .chain(std::iter::once(format!("zba = {}", sig(zba, 10))))
            .collect();
        return Ok(format!("Elasto-plastic: {}", values.join(", ")));
    }
    if m.names_any() {
        return Ok(m.build()?.describe(Needed::All));
    }
    let values: Vec<_> = r
        .system
        .model()
        .params()
        .named()
        .iter()
        .map(|&(p, v)| (p, v, false))
        .collect();
    Ok(model_line(
        Family::LuGre.label(),
        Some("the scenario's, Table I"),
        &values,
        &Parameter::LUGRE,
    ))
}

/// The times and forces of the `--input` file.
fn read_force(args: &DynamicsArgs, path: &std::path::Path) -> Result<(Vec<f64>, Vec<f64>)> {
    // The times and the force F (force, friction, y), other columns ignored. A file that
    // `lugre dynamics --csv` wrote holds the applied force as `drive` and the friction as
    // `friction`: its drive is the force applied (unless `--columns F=...` says otherwise).
    let mut options = args.data.options(&[Role::F])?;
    if !options.selects(&Role::F) && has_drive_column(path, options.clone()) {
        options = options.select(Role::F, lugre_io::Selector::Name(Motion::DRIVE.into()))?;
    }
    let spec = lugre_io::Spec::new([Role::F]).require_time();
    let mut table = lugre_io::read_file(path, &spec, options)?;
    let (t, f) = (table.take(&Role::T), table.take(&Role::F));
    Ok((t.unwrap_or_default(), f.unwrap_or_default()))
}

/// Whether the file's header has the column `lugre dynamics --csv` writes the applied force to
/// (a header the reader cannot read is the real read's to report).
fn has_drive_column(path: &std::path::Path, options: lugre_io::ReadOptions) -> bool {
    lugre_io::Reader::open(path, options).is_ok_and(|r| {
        r.header()
            .is_some_and(|h| h.iter().any(|f| f.name.eq_ignore_ascii_case(Motion::DRIVE)))
    })
}

/// The numbers of a list flag.
fn numbers(field: Field, text: &str) -> Result<Vec<f64>> {
    parse_list(&flag(field), text)
}

/// `T:V,T:V,...` as two columns.
fn pairs(field: Field, text: &str) -> Result<(Vec<f64>, Vec<f64>)> {
    let mut t = Vec::new();
    let mut v = Vec::new();
    for (i, item) in text.split(',').enumerate() {
        let Some((a, b)) = item.split_once(':') else {
            bail!("{}: item {} is not T:VALUE", flag(field), i + 1);
        };
        t.push(parse_number(&flag(field), i + 1, a)?);
        v.push(parse_number(&flag(field), i + 1, b)?);
    }
    Ok((t, v))
}

fn report(args: &DynamicsArgs, r: &Plan, o: &Outcome) -> Result<()> {
    let m = &o.motion;
    if let Some(path) = &args.output.csv {
        write_atomic(path, |w| {
            writeln!(w, "{}", Motion::COLUMNS.join(","))?;
            let columns = m.columns();
            let mut rows = NumberRows::new();
            for i in 0..m.t.len() {
                rows.write(w, &columns.map(|c| c[i]))?;
            }
            Ok(())
        })?;
    }
    if let Some(path) = &args.plot.path {
        figure(m).save(path)?;
    }
    let stdout = std::io::stdout();
    if args.output.json {
        write_json(JsonOut::new(stdout.lock()), r, o)?;
        return Ok(());
    }
    let mut w = std::io::BufWriter::new(stdout.lock());
    writeln!(w, "{}", r.description)?;
    writeln!(w, "{}", model_text(&args.model, r)?)?;
    write_summary(&mut w, r, o)?;
    if r.loops {
        write_loops(&mut w, &o.loops)?;
    }
    write_table(&mut w, m)?;
    w.flush()?;
    Ok(())
}

/// The energy balance in one line.
fn write_energy(w: &mut impl Write, e: &lugre::dynamics::EnergyBalance) -> std::io::Result<()> {
    writeln!(
        w,
        "energy: the drive put in {} J; stored {} -> {} J; dissipated {} J (balance off by {} J)",
        sig(e.input, 8),
        sig(e.stored_start, 6),
        sig(e.stored_end, 6),
        sig(e.dissipated, 8),
        sig(e.residual(), 2)
    )?;
    Ok(())
}

/// The run in a few lines: its cost, the break-away, the slip onsets, the energy balance.
fn write_summary(w: &mut impl Write, r: &Plan, o: &Outcome) -> std::io::Result<()> {
    let m = &o.motion;
    writeln!(
        w,
        "mass {} kg, run 0..{} s, rtol {}; {} steps ({} rejected), {} events",
        sig(r.system.mass(), 6),
        sig(r.t_end, 6),
        sig(r.tol.rtol(), 3),
        m.stats.steps,
        m.stats.rejected,
        m.events.len()
    )?;
    if let Some(b) = &o.breakaway {
        writeln!(
            w,
            "break-away (first peak of the friction): t = {} s, F = {} N, x = {} m",
            sig(b.t, 10),
            sig(b.force, 10),
            sig(b.x, 10)
        )?;
    }
    if let Some(v) = r.pull {
        write_slip_onsets(w, v, &o.slip_onsets())?;
    }
    write_energy(w, &m.energy)?;
    let reversals = m
        .events
        .iter()
        .filter(|e| e.kind == EventKind::VelocityZero)
        .count();
    writeln!(w, "velocity sign changes: {reversals}")
}

/// The slip onsets of a pulled spring (pulled at `v`) and the periods between them.
fn write_slip_onsets(w: &mut impl Write, v: f64, onsets: &[f64]) -> std::io::Result<()> {
    let times: Vec<String> = onsets.iter().map(|t| sig(*t, 10)).collect();
    writeln!(
        w,
        "slip onsets (v rising through {} m/s, the spring force's peaks): {}",
        sig(v, 6),
        times.join(", ")
    )?;
    if onsets.len() >= 2 {
        let periods: Vec<String> = onsets.windows(2).map(|p| sig(p[1] - p[0], 10)).collect();
        writeln!(w, "period: {} s", periods.join(", "))?;
    }
    Ok(())
}

/// About [`TABLE_HEAD`] rows of the motion, the last always among them.
fn write_table(w: &mut impl Write, m: &Motion) -> std::io::Result<()> {
    let [t, x, v, z, friction, drive] = Motion::COLUMNS;
    writeln!(
        w,
        "\n{t:>12} {x:>16} {v:>14} {z:>14} {friction:>12} {drive:>12}"
    )?;
    let n = m.t.len();
    let step = (n / TABLE_HEAD).max(1);
    let last = n.saturating_sub(1);
    let rows = (0..n)
        .step_by(step)
        .filter(|&i| i != last)
        .chain((n > 0).then_some(last));
    for i in rows {
        writeln!(
            w,
            "{:>12} {:>16} {:>14} {:>14} {:>12} {:>12}",
            sig(m.t[i], 6),
            sig(m.x[i], 9),
            sig(m.v[i], 6),
            sig(m.z[i], 6),
            sig(m.friction[i], 7),
            sig(m.drive[i], 7)
        )?;
    }
    writeln!(w, "({n} samples; all of them with --json or --csv)")
}

fn write_json<W: Write>(mut j: JsonOut<W>, r: &Plan, o: &Outcome) -> std::io::Result<()> {
    let m = &o.motion;
    for (i, (key, xs)) in Motion::COLUMNS.iter().zip(m.columns()).enumerate() {
        j.raw(if i == 0 { "{\"" } else { ",\"" })?;
        j.raw(key)?;
        j.raw("\":")?;
        j.array(xs)?;
    }
    j.raw(",\"events\":[")?;
    for (i, e) in m.events.iter().enumerate() {
        j.raw(if i == 0 { "{\"t\":" } else { ",{\"t\":" })?;
        j.num(e.t)?;
        j.raw(&format!(",\"kind\":\"{}\"", e.kind.name()))?;
        j.field(",\"x\":", e.x)?;
        j.raw("}")?;
    }
    j.raw("]")?;
    j.raw(",\"model\":")?;
    j.raw(&model_json(r).to_string())?;
    let s = m.stats;
    j.raw(&format!(
        ",\"stats\":{{\"steps\":{},\"rejected\":{},\"rhs_evaluations\":{},\"jacobians\":{},\"restarts\":{}}}",
        s.steps, s.rejected, s.rhs_evaluations, s.jacobians, s.restarts
    ))?;
    let e = m.energy;
    j.field(",\"energy\":{\"input\":", e.input)?;
    j.field(",\"stored_start\":", e.stored_start)?;
    j.field(",\"stored_end\":", e.stored_end)?;
    j.field(",\"dissipated\":", e.dissipated)?;
    j.raw("}")?;
    if let Some(b) = &o.breakaway {
        j.field(",\"breakaway\":{\"t\":", b.t)?;
        j.field(",\"force\":", b.force)?;
        j.field(",\"x\":", b.x)?;
        j.raw("}")?;
    }
    if r.pull.is_some() {
        let onsets = o.slip_onsets();
        j.raw(",\"slip_onsets\":")?;
        j.array(&onsets)?;
        if onsets.len() >= 2 {
            j.field(
                ",\"period\":",
                onsets[onsets.len() - 1] - onsets[onsets.len() - 2],
            )?;
        }
    }
    if r.loops {
        j.raw(",\"loops\":[")?;
        for (i, l) in o.loops.iter().enumerate() {
            j.raw(if i == 0 { "{" } else { ",{" })?;
            j.field("\"t_start\":", l.t_start)?;
            j.field(",\"t_turn\":", l.t_turn)?;
            j.field(",\"t_close\":", l.t_close)?;
            j.raw(",\"turning_points\":")?;
            j.array(&l.turning_points)?;
            j.field(",\"work\":", l.work)?;
            j.field(",\"bristle_energy_change\":", l.bristle_energy_change)?;
            j.field(",\"dissipation\":", l.dissipation)?;
            j.field(",\"rate_independent_work\":", l.rate_independent_work)?;
            j.raw("}")?;
        }
        j.raw("]")?;
    }
    j.raw("}\n")?;
    j.finish()
}

/// The loops' lines of the summary.
fn write_loops(w: &mut impl Write, loops: &[FrictionLoop]) -> std::io::Result<()> {
    if loops.is_empty() {
        return writeln!(w, "friction-displacement loops: none closed");
    }
    writeln!(
        w,
        "friction-displacement loops (closed where x returns; work = stored energy change + dissipated; lugre loop: the rate-independent loop on the same turning points):"
    )?;
    for l in loops {
        let points: Vec<String> = l.turning_points.iter().map(|x| sig(*x, 7)).collect();
        writeln!(
            w,
            "  {} -> {} -> {} s, x through {} m: work {} J = {} + dissipated {} J; lugre loop {} J ({} relative)",
            sig(l.t_start, 6),
            sig(l.t_turn, 6),
            sig(l.t_close, 6),
            points.join(", "),
            sig(l.work, 7),
            sig(l.bristle_energy_change, 3),
            sig(l.dissipation, 7),
            sig(l.rate_independent_work, 7),
            sig((l.work - l.rate_independent_work) / l.rate_independent_work, 2)
        )?;
    }
    Ok(())
}

/// x, v and the friction against t, and the friction against x, in a 2 x 2 grid.
fn figure(m: &Motion) -> Panels {
    let against_t =
        |y: &[f64]| -> Vec<(f64, f64)> { m.t.iter().copied().zip(y.iter().copied()).collect() };
    let panel = |label: &str, title: &str, points: Vec<(f64, f64)>, x_label: &str| {
        Figure::new(x_label, label)
            .title(title)
            .curve(Curve::new(points, LineStyle::Solid, BLUE))
    };
    let t = "time t [s]";
    Panels {
        title: None,
        panels: vec![
            panel(
                "position x [m]",
                "position against time",
                against_t(&m.x),
                t,
            ),
            panel(
                "velocity v [m/s]",
                "velocity against time",
                against_t(&m.v),
                t,
            ),
            panel(
                "friction F [N]",
                "friction against time",
                against_t(&m.friction),
                t,
            ),
            panel(
                "friction F [N]",
                "friction against position",
                m.x.iter()
                    .copied()
                    .zip(m.friction.iter().copied())
                    .collect(),
                "position x [m]",
            ),
        ],
        cols: 2,
        size: (1600, 1200),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every field of the core's request has its flag: a field added to the core without a
    /// flag, or a flag renamed, fails here.
    #[test]
    fn every_request_field_has_its_flag() {
        let cmd = DynamicsArgs::augment_args(clap::Command::new("dynamics"));
        let longs: Vec<String> = cmd
            .get_arguments()
            .filter_map(|a| a.get_long().map(|l| format!("--{l}")))
            .collect();
        for field in Field::ALL {
            assert!(
                longs.contains(&flag(field)),
                "{field}: no flag {}",
                flag(field)
            );
        }
    }
}
