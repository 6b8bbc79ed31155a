//! What `lugre simulate` writes: the JSON document, the CSV, the figure and the table.

use anyhow::Result;
use lugre::Trajectory;
use std::io::Write;

use super::Request;
use crate::fmt::sig;
use crate::io::csv::NumberRows;
use crate::io::json::JsonOut;
use crate::plot::{Curve, Figure, LineStyle, Panels, Units, BLUE};
use lugre::model::named::Needed;
use lugre::simulate::Drive;

/// Rows of the table printed before the rest is summarised (all of it is in --json / --csv).
const TABLE_HEAD: usize = 20;

/// `{"t": [...], "u": [...], "z": [...], "dz": [...], "y": [...]}`.
pub(super) fn write_json<W: Write>(mut j: JsonOut<W>, out: &Trajectory) -> std::io::Result<()> {
    j.raw("{\"t\":")?;
    j.array(&out.t)?;
    j.raw(",\"u\":")?;
    j.array(&out.u)?;
    j.raw(",\"z\":")?;
    j.array(&out.z)?;
    j.raw(",\"dz\":")?;
    j.array(&out.dz)?;
    j.raw(",\"y\":")?;
    j.array(&out.y)?;
    j.raw("}\n")?;
    j.finish()
}

/// Points drawn per panel at most: beyond this, buckets of consecutive samples are reduced to
/// their first, lowest, highest and last points (in order), which keeps every peak and jump a
/// plot can show at its resolution.
const MAX_DRAWN_BUCKETS: usize = 20_000;

/// The response as two panels: y against t, and y against u.
pub(super) fn response_figure(out: &Trajectory, what: &str, units: &Units) -> Panels {
    let keep = envelope_indices(&out.y, MAX_DRAWN_BUCKETS);
    let pick = |x: &[f64]| -> Vec<(f64, f64)> { keep.iter().map(|&i| (x[i], out.y[i])).collect() };
    let time = Figure::new(units.t("time t"), units.force("output y"))
        .title(format!("y against t, {what}"))
        .curve(Curve::new(pick(&out.t), LineStyle::Solid, BLUE));
    let input = Figure::new(units.u("input u"), units.force("output y"))
        .title(format!("y against u, {what}"))
        .curve(Curve::new(pick(&out.u), LineStyle::Solid, BLUE));
    Panels::side_by_side(time, input)
}

/// Indices of the samples to draw: all of them when there are at most `4 buckets`, else per
/// bucket of consecutive samples the first, the lowest, the highest and the last of `y`.
fn envelope_indices(y: &[f64], buckets: usize) -> Vec<usize> {
    let n = y.len();
    if n <= 4 * buckets {
        return (0..n).collect();
    }
    let size = n.div_ceil(buckets);
    let mut keep = Vec::with_capacity(4 * buckets);
    for start in (0..n).step_by(size) {
        let end = (start + size).min(n);
        let (mut lo, mut hi) = (start, start);
        for i in start..end {
            if y[i] < y[lo] {
                lo = i;
            }
            if y[i] > y[hi] {
                hi = i;
            }
        }
        let mut four = [start, lo, hi, end - 1];
        four.sort_unstable();
        for i in four {
            if keep.last() != Some(&i) {
                keep.push(i);
            }
        }
    }
    keep
}

pub(super) fn write_csv(w: &mut dyn Write, out: &Trajectory) -> Result<()> {
    let mut rows = NumberRows::new();
    writeln!(w, "t,u,z,dz,y")?;
    for i in 0..out.len() {
        rows.write(w, &[out.t[i], out.u[i], out.z[i], out.dz[i], out.y[i]])?;
    }
    Ok(())
}

pub(super) fn print_table(w: &mut impl Write, r: &Request, out: &Trajectory) -> Result<()> {
    print_summary(w, r)?;
    let n = out.len();
    if n == 0 {
        return Ok(());
    }
    let (imin, imax) = (0..n).fold((0, 0), |(lo, hi), i| {
        (
            if out.y[i] < out.y[lo] { i } else { lo },
            if out.y[i] > out.y[hi] { i } else { hi },
        )
    });
    writeln!(
        w,
        "{} rows, t from {} to {} (at a kink: the value just after it); y from {} (t = {}) to {} (t = {}); y at the end {}",
        n,
        sig(out.t[0], 10),
        sig(out.t[n - 1], 10),
        sig(out.y[imin], 10),
        sig(out.t[imin], 10),
        sig(out.y[imax], 10),
        sig(out.t[imax], 10),
        sig(out.y[n - 1], 10),
    )?;
    print_rows(
        w,
        &["t", "u", "z", "z'", "y"],
        &[&out.t, &out.u, &out.z, &out.dz, &out.y],
    )
}

/// The header and the first [`TABLE_HEAD`] rows of `columns`, then how many more there are.
pub(super) fn print_rows(
    w: &mut impl Write,
    headers: &[&str],
    columns: &[&Vec<f64>],
) -> Result<()> {
    let line = |cells: Vec<String>| {
        let cells: Vec<String> = cells.iter().map(|c| format!("{c:>16}")).collect();
        cells.join(" ")
    };
    writeln!(
        w,
        "\n{}",
        line(headers.iter().map(|h| h.to_string()).collect())
    )?;
    let n = columns.first().map_or(0, |c| c.len());
    for i in 0..n.min(TABLE_HEAD) {
        writeln!(
            w,
            "{}",
            line(columns.iter().map(|c| sig(c[i], 10)).collect())
        )?;
    }
    if n > TABLE_HEAD {
        writeln!(
            w,
            "{:>16} ... {} more rows: use --json or --csv FILE to get all",
            "",
            n - TABLE_HEAD
        )?;
    }
    Ok(())
}

/// What was written: the CSV's `columns` (`rows` of them) and the figure.
pub(super) fn print_written(
    w: &mut impl Write,
    args: &super::SimulateArgs,
    columns: &str,
    rows: usize,
) -> Result<()> {
    if let Some(path) = &args.output.csv {
        writeln!(w, "\nWrote {columns} ({rows} rows) to {}", path.display())?;
    }
    if let Some(path) = &args.plot.path {
        writeln!(w, "Drew y against t and y against u to {}", path.display())?;
    }
    Ok(())
}

/// The model, the input, gamma, the periods, x0 and (for a sine) the tolerance.
fn print_summary(w: &mut impl Write, r: &Request) -> Result<()> {
    let s = &r.simulation;
    // At gamma = inf the response is y*, which sigma0 and g(0) alone shape.
    let needed = if s.gamma().is_infinite() {
        Needed::RateIndependent
    } else {
        Needed::All
    };
    writeln!(w, "{}", r.choice.describe(needed))?;
    writeln!(w, "Input: {}", r.input)?;
    let what = if s.gamma().is_infinite() {
        "gamma = inf: the rate-independent limit y*_u (eq. 6)".to_string()
    } else {
        format!("gamma = {} (eq. 5)", sig(s.gamma().value(), 10))
    };
    let adaptive = matches!(s.drive(), Drive::Sine(_)) && !s.gamma().is_infinite();
    writeln!(
        w,
        "{what}; period T = {}; {} period{}; x0 = {}{}",
        sig(s.drive().span().1, 10),
        s.periods(),
        if s.periods() == 1 { "" } else { "s" },
        sig(s.x0(), 10),
        if adaptive {
            format!(
                "; adaptive integration to tol = {}",
                sig(s.tolerance().value(), 3)
            )
        } else {
            String::new()
        }
    )?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_drawn_envelope_keeps_every_extreme_in_order() {
        let y: Vec<f64> = (0..100_000)
            .map(|i| ((i as f64) * 0.01).sin() + if i == 54_321 { 5.0 } else { 0.0 })
            .collect();
        let keep = envelope_indices(&y, 1000);
        assert!(keep.len() <= 4000 && keep.len() > 1000);
        assert!(keep.windows(2).all(|w| w[0] < w[1]));
        assert!(keep.contains(&54_321) && keep[0] == 0 && keep[keep.len() - 1] == 99_999);
        assert_eq!(
            envelope_indices(&y[..10], 1000),
            (0..10).collect::<Vec<_>>()
        );
    }
}
