//! What drives the simulation: periodic turning points, sampled data or a sine, from the
//! input flags.

use anyhow::{anyhow, bail, Result};
use lugre::simulate::Drive;
use lugre::{PiecewiseLinear, Sine};

use super::SimulateArgs;
use crate::fmt::sig;
use crate::numbers::parse_list;

/// The input flag given (exactly one), with a description for the summary.
pub(super) fn build_drive(args: &SimulateArgs) -> Result<(Drive, String)> {
    let mut given = args.input.given();
    if args.sine.is_some() {
        given.push("--sine");
    }
    if given.len() > 1 {
        bail!("give one input, not {}", given.join(" and "));
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
        return Ok((Drive::Sine(sine), text));
    }
    if let Some(path) = &args.input.input {
        let options = args.data.options(&["u"])?;
        let series: crate::io::csv::Series =
            crate::io::csv::read_table_with(path, crate::io::csv::Columns::Series, options)?.into();
        let Some(t) = series.t else {
            bail!(
                "{}: simulate needs the samples' times: a header 't,u' and two columns (a single column 'u' has no time)",
                path.display()
            );
        };
        let n = t.len();
        let pl =
            PiecewiseLinear::new(t, series.u).map_err(|e| anyhow!("{}: {e}", path.display()))?;
        let text = format!(
            "{} samples from {}, linear between samples, t in [{}, {}]",
            n,
            path.display(),
            sig(pl.times()[0], 10),
            sig(pl.times()[n - 1], 10)
        );
        return Ok((Drive::Samples(pl), text));
    }
    if given.is_empty() {
        bail!("no input: give --turning-points U0,U1,..., --bimodal UMIN1,UMIN2,UMAX1,UMAX2, --input FILE.csv (t,u) or --sine A,T[,PHASE[,OFFSET]]");
    }
    let tp = args.input.build()?.turning_points();
    let pl = PiecewiseLinear::from_turning_points(&tp, 1.0)?;
    let values: Vec<String> = tp.values().iter().map(|&u| sig(u, 10)).collect();
    let text = format!(
        "turning points {} at unit speed (t = rho)",
        if values.len() > 8 {
            format!("{},... ({} in all)", values[..8].join(","), values.len())
        } else {
            values.join(",")
        }
    );
    Ok((Drive::TurningPoints(pl), text))
}
