//! What `lugre cycles` prints after the count: the rest of the JSON document, or the table (and
//! the histogram).

use anyhow::Result;
use lugre::{Cycle, CycleSummary, Histogram};
use std::io::Write;

use super::source::Source;
use super::Energy;
use crate::fmt::sig;
use crate::io::json::JsonOut;
use lugre::model::named::Needed;

/// What the second pass leaves for the report.
pub(super) struct Report {
    pub(super) summary: CycleSummary,
    pub(super) table: Vec<Cycle>,
    pub(super) histogram: Option<Histogram>,
    pub(super) max_range: f64,
}

impl Report {
    /// Everything after the cycles in `--json` (keys may be added, never renamed).
    pub(super) fn write_json_tail<W: Write>(
        &self,
        j: &mut JsonOut<W>,
        gate: f64,
        energy: Option<&Energy>,
    ) -> Result<()> {
        let s = &self.summary;
        j.raw("],\"samples\":")?;
        j.int(s.samples as usize)?;
        j.raw(",\"reversal_count\":")?;
        j.int(s.reversals as usize)?;
        j.raw(",\"full_cycles\":")?;
        j.int(s.full_cycles as usize)?;
        j.raw(",\"half_cycles\":")?;
        j.int(s.half_cycles as usize)?;
        j.field(",\"gate\":", gate)?;
        match (energy, s.energy) {
            (Some(e), Some(h)) => {
                j.raw(",\"model\":")?;
                match e {
                    Energy::Classic { model, x0 } => {
                        let ri = model.rate_independent();
                        j.raw(&model.to_json().to_string())?;
                        j.field(",\"x0\":", *x0)?;
                        j.field(",\"g0\":", ri.g0())?;
                        j.field(",\"a\":", ri.a())?;
                    }
                    Energy::Zoo(model) => {
                        j.raw(&crate::zoo_args::zoo_json(model).to_string())?;
                        j.raw(",\"x0\":null,\"g0\":null,\"a\":null")?;
                    }
                }
                j.field(",\"history\":{\"y_start\":", h.y_start)?;
                j.field(",\"y_end\":", h.y_end)?;
                j.field(",\"work\":", h.work)?;
                j.field(",\"stored_energy_change\":", h.stored_energy_change)?;
                j.field(",\"dissipation\":", h.dissipation)?;
                j.raw("}")?;
            }
            _ => j.raw(",\"model\":null,\"x0\":null,\"g0\":null,\"a\":null,\"history\":null")?,
        }
        if let Some(h) = &self.histogram {
            j.raw(",\"histogram\":{\"bins\":")?;
            j.int(h.bins())?;
            j.raw(",\"range_edges\":")?;
            j.array(&h.range_edges())?;
            j.raw(",\"mean_edges\":")?;
            j.array(&h.mean_edges())?;
            j.raw(",\"range_counts\":")?;
            j.array(h.range_counts())?;
            j.raw(",\"range_mean_counts\":[")?;
            for r in 0..h.bins() {
                if r > 0 {
                    j.raw(",")?;
                }
                j.array(h.range_row(r))?;
            }
            j.raw("]}")?;
        }
        j.raw("}\n")?;
        Ok(())
    }

    pub(super) fn print_table(
        &self,
        out: &mut impl Write,
        source: &Source,
        gate: f64,
        energy: Option<&Energy>,
    ) -> Result<()> {
        self.print_summary(out, source, gate, energy)?;
        self.print_cycles(out, energy.is_some())?;
        if let Some(h) = self.summary.energy {
            writeln!(
                out,
                "\nAlong the whole history: work W = {}, stored dV = {}, dissipation D = {}; y* at the end = {}",
                sig(h.work, 10),
                sig(h.stored_energy_change, 10),
                sig(h.dissipation, 10),
                sig(h.y_end, 10)
            )?;
        }
        if let Some(h) = &self.histogram {
            print_histogram(out, h)?;
        }
        Ok(())
    }

    /// The history, the count, and the model.
    fn print_summary(
        &self,
        out: &mut impl Write,
        source: &Source,
        gate: f64,
        energy: Option<&Energy>,
    ) -> Result<()> {
        let s = &self.summary;
        writeln!(
            out,
            "History: {} samples from {}; {} reversals{}",
            s.samples,
            source.describe(),
            s.reversals,
            if gate > 0.0 {
                format!(" (gate {})", sig(gate, 10))
            } else {
                String::new()
            }
        )?;
        writeln!(
            out,
            "Rainflow (ASTM E1049-85, three-point method): {} full {}, {} half {}; largest range {}",
            s.full_cycles,
            if s.full_cycles == 1 { "cycle" } else { "cycles" },
            s.half_cycles,
            if s.half_cycles == 1 { "cycle" } else { "cycles" },
            sig(self.max_range, 10)
        )?;
        match energy {
            Some(Energy::Classic { model, x0 }) => {
                let ri = model.rate_independent();
                writeln!(out, "{}", model.describe(Needed::RateIndependent))?;
                writeln!(
                    out,
                    "g(0) = {}   a = sigma0/g(0) = {}   y*(0) = sigma0 x0 = {}",
                    sig(ri.g0(), 10),
                    sig(ri.a(), 10),
                    sig(ri.sigma0() * x0, 10)
                )?;
            }
            Some(Energy::Zoo(model)) => {
                writeln!(out, "{}; from rest", crate::zoo_args::zoo_line(model))?;
            }
            None => {}
        }
        Ok(())
    }

    /// The table's first rows of cycles (with energy columns when energies are followed).
    fn print_cycles(&self, out: &mut impl Write, with_energy: bool) -> Result<()> {
        writeln!(
            out,
            "\nCycles, in the order they close (closure: first sample back at the start value, and the interpolated position)"
        )?;
        let mut head = format!(
            "{:>6} {:>5} {:>12} {:>12} {:>10} {:>10} {:>10} {:>12}",
            "#", "count", "range", "mean", "start", "end", "closure", "at"
        );
        if with_energy {
            head += &format!(
                " {:>13} {:>13} {:>13} {:>13}",
                "work W", "stored dV", "dissip. D", "gap y_C-y_A"
            );
        }
        writeln!(out, "{head}")?;
        for (i, c) in self.table.iter().enumerate() {
            writeln!(out, "{}", cycle_row(i, c, with_energy))?;
        }
        let s = &self.summary;
        let total = s.full_cycles + s.half_cycles;
        if total > self.table.len() as u64 {
            writeln!(
                out,
                "{:>6} ... {} more rows: use --json or --csv FILE to get all",
                "",
                total - self.table.len() as u64
            )?;
        }
        Ok(())
    }
}

/// Row `i` of the table: cycle `c`.
fn cycle_row(i: usize, c: &Cycle, with_energy: bool) -> String {
    let (closure, at) = match c.closure {
        Some(cl) => (cl.index.to_string(), sig(cl.position, 9)),
        None => ("-".into(), "-".into()),
    };
    let mut row = format!(
        "{:>6} {:>5} {:>12} {:>12} {:>10} {:>10} {:>10} {:>12}",
        i,
        if c.is_full() { "1" } else { "0.5" },
        sig(c.range, 8),
        sig(c.mean, 8),
        c.start,
        c.end,
        closure,
        at
    );
    if let Some(e) = c.energy {
        row += &format!(
            " {:>13} {:>13} {:>13} {:>13}",
            sig(e.arc.work, 8),
            sig(e.arc.stored_energy_change, 8),
            sig(e.arc.dissipation, 8),
            sig(e.arc.closure_gap, 8)
        );
    } else if with_energy {
        row += &format!(" {:>13} {:>13} {:>13} {:>13}", "-", "-", "-", "-");
    }
    row
}

fn print_histogram(out: &mut impl Write, h: &Histogram) -> Result<()> {
    let re = h.range_edges();
    let me = h.mean_edges();
    writeln!(
        out,
        "\nCounts by range ({} bins, closed on the left, the last on both sides)",
        h.bins()
    )?;
    writeln!(out, "{:>14} {:>14} {:>12}", "range from", "to", "count")?;
    for (k, count) in h.range_counts().iter().enumerate() {
        writeln!(
            out,
            "{:>14} {:>14} {:>12}",
            sig(re[k], 8),
            sig(re[k + 1], 8),
            sig(*count, 12)
        )?;
    }
    writeln!(
        out,
        "\nCounts by range (rows) and mean (columns, bins from {} to {})",
        sig(me[0], 8),
        sig(me[h.bins()], 8)
    )?;
    let mut head = format!("{:>14}", "range \\ mean");
    // Each bin is labelled by its lower edge.
    for edge in &me[..h.bins()] {
        head += &format!(" {:>10}", sig(*edge, 6));
    }
    writeln!(out, "{head}")?;
    for (r, edge) in re[..h.bins()].iter().enumerate() {
        let mut row = format!("{:>14}", sig(*edge, 8));
        for x in h.range_row(r) {
            row += &format!(" {:>10}", sig(*x, 8));
        }
        writeln!(out, "{row}")?;
    }
    writeln!(out, "total count {}", sig(h.total(), 12))?;
    Ok(())
}
