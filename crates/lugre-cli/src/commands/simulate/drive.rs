//! What drives the simulation: periodic turning points, sampled data or a sine, from the
//! input flags.

use anyhow::{anyhow, bail, Result};
use lugre::simulate::{Drive, Request, SmoothSamples};
use lugre::{PiecewiseLinear, Sine};

use super::SimulateArgs;
use crate::args::Interpolate;
use crate::fmt::sig;
use crate::numbers::parse_list;
use lugre_io::{Reader, Role, Rows, Spec};

/// A record's normal force (`--columns N=NAME`) at its times.
pub(super) type Normal = Option<(Vec<f64>, Vec<f64>)>;

/// The input flag given (exactly one), with a description for the summary, and the record's
/// normal force where `--columns` names one.
pub(super) fn build_drive(args: &SimulateArgs) -> Result<(Drive, String, Normal)> {
    let mut given = args.input.given();
    if args.sine.is_some() {
        given.push("--sine");
    }
    if given.len() > 1 {
        bail!("give one input, not {}", given.join(" and "));
    }
    if args.speed.is_some() && (args.input.input.is_some() || args.sine.is_some()) {
        bail!("--speed is the speed of --turning-points or --bimodal: --input and --sine carry their own times");
    }
    if let Some(text) = &args.sine {
        let v = parse_list("--sine", text)?;
        if !(2..=4).contains(&v.len()) {
            bail!(
                "--sine takes A,T[,PHASE[,OFFSET]] (2 to 4 numbers), got {}",
                v.len()
            );
        }
        let sine = Sine::new(
            v[0],
            v[1],
            v.get(2).copied().unwrap_or(0.0),
            v.get(3).copied().unwrap_or(0.0),
        )
        .map_err(|e| anyhow!("--sine: {e}"))?;
        let text = format!(
            "sine u(t) = {} sin(2 pi t / {} + {}) + {}",
            sig(sine.amplitude(), 10),
            sig(sine.period(), 10),
            sig(sine.phase(), 10),
            sig(sine.offset(), 10)
        );
        if args.data.selects(Role::N) {
            bail!("--columns N=...: a normal force is read from the record (--input FILE)");
        }
        return Ok((Drive::Sine(sine), text, None));
    }
    if let Some(path) = &args.input.input {
        return sampled(args, path);
    }
    if args.data.selects(Role::N) {
        bail!("--columns N=...: a normal force is read from the record (--input FILE)");
    }
    if given.is_empty() {
        bail!("no input: give --turning-points U0,U1,..., --bimodal UMIN1,UMIN2,UMAX1,UMAX2, --input FILE.csv (t,u) or --sine A,T[,PHASE[,OFFSET]]");
    }
    let tp = args.input.build()?.turning_points();
    let speed = args.speed.unwrap_or(Request::DEFAULT_SPEED);
    let pl =
        PiecewiseLinear::from_turning_points(&tp, speed).map_err(|e| anyhow!("--speed: {e}"))?;
    let values: Vec<String> = tp.values().iter().map(|&u| sig(u, 10)).collect();
    let at = match args.speed {
        None => "at unit speed (t = rho; --speed V for another)".to_string(),
        Some(v) => format!("at speed {}", sig(v, 10)),
    };
    let text = format!(
        "turning points {} {at}",
        if values.len() > 8 {
            format!("{},... ({} in all)", values[..8].join(","), values.len())
        } else {
            values.join(",")
        }
    );
    Ok((Drive::TurningPoints(pl), text, None))
}

/// A record from a file: displacement `t,u` (linear or cubic reading) or velocity `t,v`
/// (integrated, cubic reading: a header with `v` and no `u`, or `--columns v=NAME`), with the
/// normal force `N` when `--columns` names it; other columns ignored.
fn sampled(args: &SimulateArgs, path: &std::path::Path) -> Result<(Drive, String, Normal)> {
    let options = args.data.options(&[Role::U, Role::V, Role::N])?;
    let reader = Reader::open(path, options.clone())?;
    let motion = reader.motion();
    let velocity = motion == Role::V;
    let mut roles = vec![motion.clone()];
    if options.selects(&Role::N) {
        roles.push(Role::N);
    }
    let spec = Spec::new(roles).require_time().positive(Role::N);
    let mut table = reader
        .rows(&spec)
        .and_then(Rows::collect_table)
        .map_err(|e| e.in_file(path))?;
    let t = table.take(&Role::T).unwrap_or_default();
    let values = table.take(&motion).unwrap_or_default();
    let normal = table.take(&Role::N).map(|n| (t.clone(), n));
    let n = t.len();
    let (t0, t1) = (t[0], t[n - 1]);
    let span = format!("t in [{}, {}]", sig(t0, 10), sig(t1, 10));
    let with_file = |e: lugre::SimulateError| anyhow!("{}: {e}", path.display());
    if velocity || args.interpolate == Interpolate::Cubic {
        let tol = match &args.tol {
            Some(text) => super::parse_scalar("--tol", text)?,
            None => lugre::Tolerance::DEFAULT.value(),
        };
        let (motion, what) = if velocity {
            let m = SmoothSamples::from_velocity(t, values, 0.0, tol).map_err(with_file)?;
            (m, "velocity samples integrated from u = 0")
        } else {
            let m = SmoothSamples::pchip(t, values, tol).map_err(with_file)?;
            (m, "displacement samples")
        };
        let text = format!(
            "{n} {what} from {}, read as a smooth motion (C1 cubic, subdivided to {} knots), {span}",
            path.display(),
            motion.refined().len()
        );
        return Ok((Drive::Smooth(motion), text, normal));
    }
    let pl = PiecewiseLinear::new(t, values).map_err(with_file)?;
    let text = format!(
        "{n} samples from {}, linear between samples, {span}",
        path.display()
    );
    Ok((Drive::Samples(pl), text, normal))
}
