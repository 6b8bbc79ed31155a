//! What drives the simulation: periodic turning points, sampled data or a sine, from the
//! input flags.

use anyhow::{anyhow, bail, Result};
use lugre::model::normal;
use lugre::simulate::{Drive, Request, SmoothSamples};
use lugre::{PiecewiseLinear, Sine};

use super::SimulateArgs;
use crate::args::{normal_force_error, Interpolate};
use crate::fmt::sig;
use crate::numbers::parse_list;

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
        if args.data.selects(normal::COLUMN) {
            bail!("--columns N=...: a normal force is read from the record (--input FILE)");
        }
        return Ok((Drive::Sine(sine), text, None));
    }
    if let Some(path) = &args.input.input {
        return sampled(args, path);
    }
    if args.data.selects(normal::COLUMN) {
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
/// (integrated, cubic reading).
fn sampled(args: &SimulateArgs, path: &std::path::Path) -> Result<(Drive, String, Normal)> {
    use crate::io::csv::{read_table_with, Columns};
    let velocity = args.data.selects("v") || crate::io::csv::is_velocity_record(path);
    let (columns, role) = match (velocity, args.data.selects(normal::COLUMN)) {
        (true, false) => (Columns::Named("v"), "v"),
        (true, true) => (Columns::VelocityN, "v"),
        (false, false) => (Columns::Series, "u"),
        (false, true) => (Columns::SeriesN, "u"),
    };
    let table = read_table_with(path, columns, args.data.options(&[role, normal::COLUMN])?)?;
    let Some(t) = table.t else {
        bail!(
            "{}: simulate needs the samples' times: a column 't' (or --columns t=NAME)",
            path.display()
        );
    };
    let mut columns = table.columns.into_iter();
    let values = columns.next().unwrap_or_default();
    let normal = match columns.next() {
        Some(n) => {
            normal::check(&n).map_err(|e| normal_force_error(path, e))?;
            Some((t.clone(), n))
        }
        None => None,
    };
    let n = t.len();
    let (t0, t1) = (t[0], t[n - 1]);
    let span = format!("t in [{}, {}]", sig(t0, 10), sig(t1, 10));
    let with_file = |e: lugre::SimulateError| anyhow!("{}: {e}", path.display());
    if velocity || args.interpolate == Interpolate::Cubic {
        let tol = super::parse_scalar("--tol", &args.tol)?;
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
