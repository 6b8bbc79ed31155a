//! `lugre dynamics`: a mass with LuGre friction driven by a force, a spring, a controller or a
//! prescribed velocity (`lugre::dynamics`), with the 1995 experiments of Canudas de Wit et al.
//! as named scenarios. Everything is computed and checked before anything is written.

use anyhow::{anyhow, bail, Result};
use clap::{Args, ValueEnum};
use lugre::dynamics::{
    Breakaway, EventKind, Motion, Pid, Profile, Steps, System, Tolerances, Velocity,
};
use lugre::simulate::uniform_times;
use lugre::LuGre;
use std::io::Write;

use crate::args::{ModelArgs, OutputArgs, PlotArgs, Preset};
use crate::fmt::sig;
use crate::io::atomic::write_atomic;
use crate::io::csv::NumberRows;
use crate::io::json::JsonOut;
use crate::numbers::{parse_list, Whole};
use crate::plot::{Curve, Figure, LineStyle, Panels, BLUE};
use lugre_io::Role;

mod loops;
use loops::{friction_loops, FrictionLoop};

/// Output samples over the run when neither `--times` nor `--samples` is given.
const DEFAULT_SAMPLES: usize = 1001;
/// Rows of the table printed (all of them are in --json / --csv).
const TABLE_HEAD: usize = 12;

/// The experiments of Canudas de Wit, Olsson, Åström, Lischinsky (IEEE TAC 40(3), 1995), with
/// Table I and a 1 kg mass unless the flags say otherwise.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Scenario {
    /// Fig. 2: pre-sliding displacement under a force ramped to +-95 % of Fs, with holds;
    /// its friction-displacement loop.
    #[value(alias = "pre-sliding")]
    Presliding,
    /// Fig. 4: break-away under F = r t (r from --force-rate, default 10 N/s).
    Breakaway,
    /// Fig. 6: stick-slip, a spring k = 2 N/m pulled at 0.1 m/s.
    StickSlip,
    /// Fig. 3: frictional lag under v = 1e-3 (cos w t + 1.5), w = 10 rad/s.
    Lag,
    /// Fig. 8: hunting under PID (Kp = 3, Ki = 4, Kv = 6) towards xd = 1.
    Pid,
}

#[derive(Args, Debug)]
#[command(mut_arg("csv", |a| a.help("Write t,x,v,z,friction,drive to this CSV file")))]
#[command(mut_arg("plot", |a| a.help("Draw x, v and the friction against t, and the friction \
against x (SVG or PNG)")))]
pub(crate) struct DynamicsArgs {
    #[command(flatten)]
    pub(crate) model: ModelArgs,
    /// One of the 1995 experiments (Table I and a 1 kg mass unless given).
    #[arg(long, value_enum, help_heading = "System")]
    pub(crate) scenario: Option<Scenario>,
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
    /// N >= 2 evenly spaced output times over [0, t_end] (default 1001).
    #[arg(long, value_parser = Whole(2), help_heading = "Run")]
    pub(crate) samples: Option<usize>,
    /// Report the friction-displacement loops of x(t): each closed loop (a rainflow cycle of
    /// x) with the work of the friction over it, the bristle energy change and the
    /// dissipation, beside the rate-independent loop of `lugre loop` on the same turning
    /// points (on by default for --scenario presliding).
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

/// The request: the system, the run and what to report.
struct Request {
    system: System,
    description: String,
    t_end: f64,
    times: Vec<f64>,
    tol: Tolerances,
    /// The force rate, when the drive is a ramp (the break-away is located).
    rate: Option<f64>,
    /// The pull speed, when a spring is pulled (slip onsets are its upward crossings).
    pull: Option<f64>,
    /// Whether the friction-displacement loops are reported.
    loops: bool,
}

struct Outcome {
    motion: Motion,
    breakaway: Option<Breakaway>,
    loops: Vec<FrictionLoop>,
}

pub(crate) fn run(args: &DynamicsArgs) -> Result<()> {
    let request = parse(args)?;
    let outcome = compute(&request)?;
    report(args, &request, &outcome)
}

fn parse(args: &DynamicsArgs) -> Result<Request> {
    let scenario = args.scenario;
    let mut model_args = args.model.clone();
    if scenario.is_some() && model_args.preset.is_none() {
        model_args.preset = Some(Preset::Canudas1995);
    }
    let model: LuGre = model_args.build()?.lugre();
    let mass = args.mass.unwrap_or(1.0);
    let mut description = Vec::new();
    let mut t_end = args.t_end;
    let mut pull = args.pull;
    // The drive's force ramp, and whether it still has to be added to the system.
    let (mut system, ramp) = match scenario {
        Some(sc) => {
            let core = match sc {
                Scenario::Presliding => lugre::dynamics::Scenario::Presliding,
                Scenario::Breakaway => lugre::dynamics::Scenario::Breakaway {
                    rate: args.force_rate.unwrap_or(10.0),
                },
                Scenario::StickSlip => lugre::dynamics::Scenario::StickSlip,
                Scenario::Lag => lugre::dynamics::Scenario::Lag { w: 10.0 },
                Scenario::Pid => lugre::dynamics::Scenario::Pid,
            };
            let setup = core.setup(model, mass)?;
            description.push(setup.description.to_string());
            t_end = t_end.or(Some(setup.t_end));
            pull = pull.or(setup.pull);
            (setup.system, setup.rate.map(|r| (r, false)))
        }
        None => (
            System::new(model, mass)?,
            args.force_rate.map(|r| (r, true)),
        ),
    };
    let rate = ramp.map(|(r, _)| r);
    if let Some((r, true)) = ramp {
        system = system.with_force(Profile::ramp(0.0, r)?);
        description.push(format!("force ramp F = {} t N", sig(r, 6)));
    }
    if let Some(text) = &args.force_profile {
        let (t, f) = pairs("--force-profile", text)?;
        system = system.with_force(Profile::new("--force-profile", t, f)?);
        description.push("applied force profile".into());
    }
    if let Some(path) = &args.input {
        if args.force_profile.is_some() {
            bail!("give --force-profile or --input, not both");
        }
        // The times and the force F (force, friction, y), other columns ignored.
        let options = args.data.options(&[Role::F])?;
        let spec = lugre_io::Spec::new([Role::F]).require_time();
        let mut table = lugre_io::read_file(path, &spec, options)?;
        let (t, f) = (table.take(&Role::T), table.take(&Role::F));
        let (t, f) = (t.unwrap_or_default(), f.unwrap_or_default());
        // A measured history runs to its last sample unless told otherwise.
        t_end = t_end.or(t.last().copied());
        system = system.with_force(Profile::new("--input", t, f)?);
        description.push(format!("applied force from {}", path.display()));
    }
    if let Some(k) = args.spring {
        let end = match (pull, &args.end_profile) {
            (Some(_), Some(_)) => bail!("give --pull or --end-profile, not both"),
            (Some(v), None) => Profile::ramp(0.0, v)?,
            (None, Some(text)) => {
                let (t, y) = pairs("--end-profile", text)?;
                Profile::new("--end-profile", t, y)?
            }
            (None, None) => bail!("--spring needs --pull V or --end-profile T:Y,..."),
        };
        system = system.with_spring(k, end)?;
        description.push(format!("spring k = {} N/m", sig(k, 6)));
    } else if args.end_profile.is_some() || (args.pull.is_some() && scenario.is_none()) {
        bail!("--pull and --end-profile move the free end of a --spring K");
    }
    if let Some(c) = args.damping {
        system = system.with_damping(c)?;
    }
    if let Some(text) = &args.pid {
        let g = parse_list("--pid", text)?;
        if g.len() != 3 {
            bail!("--pid takes 3 numbers KP,KI,KV, got {}", g.len());
        }
        let setpoint = match &args.setpoint {
            None => Steps::constant(0.0)?,
            Some(text) if !text.contains(':') => {
                Steps::constant(parse_list("--setpoint", text)?[0])?
            }
            Some(text) => {
                let (t, x) = pairs("--setpoint", text)?;
                Steps::new(t, x)?
            }
        };
        system = system.with_pid(Pid {
            kp: g[0],
            ki: g[1],
            kv: g[2],
            setpoint,
        })?;
        description.push(format!("PID Kp = {}, Ki = {}, Kv = {}", g[0], g[1], g[2]));
    } else if args.setpoint.is_some() {
        bail!("--setpoint is the set point of a --pid controller");
    }
    if let Some(text) = &args.velocity_profile {
        let (t, v) = pairs("--velocity-profile", text)?;
        system =
            system.with_velocity(Velocity::Profile(Profile::new("--velocity-profile", t, v)?))?;
        description.push("prescribed velocity profile".into());
    }
    if let (Some(v), None) = (pull, scenario) {
        system = system.with_velocity_watch(v)?;
    }
    if description.is_empty() {
        bail!("no drive: give --scenario, --force-profile, --input, --force-rate, --spring with --pull, --pid or --velocity-profile");
    }
    let t_end = t_end.ok_or_else(|| anyhow!("give --t-end T (the end of the run, s)"))?;
    if !(t_end.is_finite() && t_end > 0.0) {
        bail!("--t-end must be a finite number > 0, got {}", sig(t_end, 6));
    }
    let tol = Tolerances::new(args.rtol.unwrap_or(Tolerances::DEFAULT_RTOL), args.atol)?;
    if args.times.is_some() && args.samples.is_some() {
        bail!("give --times or --samples, not both");
    }
    let times = match (&args.times, args.samples) {
        (Some(text), _) => parse_list("--times", text)?,
        (None, n) => uniform_times(0.0, t_end, 1, n.unwrap_or(DEFAULT_SAMPLES) - 1),
    };
    if let Some(path) = &args.plot.path {
        crate::plot::check_path(path)?;
    }
    Ok(Request {
        system,
        description: description.join("; "),
        t_end,
        times,
        tol,
        rate,
        pull,
        loops: args.loops || scenario == Some(Scenario::Presliding),
    })
}

/// `T:V,T:V,...` as two columns.
fn pairs(flag: &str, text: &str) -> Result<(Vec<f64>, Vec<f64>)> {
    let mut t = Vec::new();
    let mut v = Vec::new();
    for (i, item) in text.split(',').enumerate() {
        let Some((a, b)) = item.split_once(':') else {
            bail!("{flag}: item {} is not T:VALUE", i + 1);
        };
        t.push(parse_list(flag, a.trim())?[0]);
        v.push(parse_list(flag, b.trim())?[0]);
    }
    Ok((t, v))
}

fn compute(r: &Request) -> Result<Outcome> {
    let motion = r.system.solve(r.t_end, &r.times, r.tol)?;
    let breakaway = match r.rate {
        Some(_) => r.system.breakaway(r.t_end, r.tol)?,
        None => None,
    };
    let loops = if r.loops {
        friction_loops(&r.system, r.t_end, r.tol)?
    } else {
        Vec::new()
    };
    Ok(Outcome {
        motion,
        breakaway,
        loops,
    })
}

fn report(args: &DynamicsArgs, r: &Request, o: &Outcome) -> Result<()> {
    let m = &o.motion;
    if let Some(path) = &args.output.csv {
        write_atomic(path, |w| {
            writeln!(w, "t,x,v,z,friction,drive")?;
            let mut rows = NumberRows::new();
            for i in 0..m.t.len() {
                rows.write(
                    w,
                    &[m.t[i], m.x[i], m.v[i], m.z[i], m.friction[i], m.drive[i]],
                )?;
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
        let onsets: Vec<f64> = ups(m);
        writeln!(
            w,
            "slip onsets (v rising through {} m/s, the spring force's peaks): {}",
            sig(v, 6),
            onsets
                .iter()
                .map(|t| sig(*t, 10))
                .collect::<Vec<_>>()
                .join(", ")
        )?;
        if onsets.len() >= 2 {
            let periods: Vec<String> = onsets.windows(2).map(|p| sig(p[1] - p[0], 10)).collect();
            writeln!(w, "period: {} s", periods.join(", "))?;
        }
    }
    let e = m.energy;
    writeln!(
        w,
        "energy: the drive put in {} J; stored {} -> {} J; dissipated {} J (balance off by {} J)",
        sig(e.input, 8),
        sig(e.stored_start, 6),
        sig(e.stored_end, 6),
        sig(e.dissipated, 8),
        sig(e.residual(), 2)
    )?;
    let reversals = m
        .events
        .iter()
        .filter(|e| e.kind == EventKind::VelocityZero)
        .count();
    writeln!(w, "velocity sign changes: {reversals}")?;
    if r.loops {
        write_loops(&mut w, &o.loops)?;
    }
    writeln!(
        w,
        "\n{:>12} {:>16} {:>14} {:>14} {:>12} {:>12}",
        "t", "x", "v", "z", "friction", "drive"
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
    writeln!(w, "({n} samples; all of them with --json or --csv)")?;
    w.flush()?;
    Ok(())
}

/// The times of the upward crossings of the watched velocity.
fn ups(m: &Motion) -> Vec<f64> {
    m.events
        .iter()
        .filter(|e| e.kind == EventKind::VelocityUp)
        .map(|e| e.t)
        .collect()
}

fn write_json<W: Write>(mut j: JsonOut<W>, r: &Request, o: &Outcome) -> std::io::Result<()> {
    let m = &o.motion;
    for (i, (key, xs)) in [
        ("t", &m.t),
        ("x", &m.x),
        ("v", &m.v),
        ("z", &m.z),
        ("friction", &m.friction),
        ("drive", &m.drive),
    ]
    .iter()
    .enumerate()
    {
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
        let onsets = ups(m);
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
        "friction-displacement loops (closed where x returns; work = bristle energy change + dissipated; lugre loop: the rate-independent loop on the same turning points):"
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
