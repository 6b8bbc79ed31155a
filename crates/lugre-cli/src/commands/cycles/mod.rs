//! `lugre cycles`: the minor loops of a measured (non-periodic) history. Reversals, ASTM E1049-85
//! rainflow cycles (as the Python package `rainflow` counts them), where each loop closes, and
//! with a model the energy over each loop; a table, JSON, a CSV of the cycles, and a histogram.
//!
//! Everything streams: the file is read row by row into blocks for the counter, cycles are
//! written as they close, and the table keeps only its first rows, so a 10^8-sample file runs
//! in constant memory. JSON lists the reversals before the cycles, and the histogram needs the
//! history's span before the first cycle is binned, so those read the input twice: the first
//! pass validates everything and collects the reversals (in memory, or in a temporary file past
//! `SPOOL_IN_MEMORY`), the second counts. Nothing reaches stdout before the input has been read
//! once without error.
//!
//! Energies are computed with `--energy`, and whenever the model is named (`--x0`, `--model
//! dahl`, or any model parameter): a model flag without energies would be silently ignored.

use anyhow::{anyhow, bail, Context, Result};
use clap::Args;
use lugre::cycles::MAX_SAMPLE;
use lugre::{
    Cycle, CycleCounter, CycleSink, CycleSummary, EnergyCycleCounter, Histogram, Reversal,
};
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

use crate::args::{ModelArgs, ModelChoice, ModelKind, OutputArgs};
use crate::fmt::{exact, num, sig};
use crate::io::atomic::write_atomic;
use crate::io::csv::{Columns, SampleReader};
use crate::io::json::JsonOut;
use crate::io::spool::Spool;
use crate::numbers::{parse_list, Real, Whole};

/// Rows of the cycle table printed before the rest is summarised (all of it is in --json and
/// --csv).
const MAX_TABLE_ROWS: usize = 40;

/// Samples handed to the counter at a time.
const BLOCK: usize = 4096;

/// Reversal JSON kept in memory before it goes to a temporary file.
const SPOOL_IN_MEMORY: usize = 8 << 20;

/// Bins per axis of `--histogram` when `--bins` is not given, and the most allowed (the
/// range x mean matrix has `bins^2` cells).
const DEFAULT_BINS: usize = 10;
const MAX_BINS: usize = 1000;

/// The help of `--csv` for this command.
const CSV_HELP: &str = "Write the cycles to this CSV file, one row per cycle";

#[derive(Args, Debug)]
#[command(
    mut_arg("csv", |a| a.help(CSV_HELP))
)]
pub struct CyclesArgs {
    /// The history from a CSV file: a column 'u' (header 'u' or 't,u', or no header), or the
    /// column --column names; a column 't' is checked as strictly increasing times.
    #[arg(long, value_name = "FILE.csv", help_heading = "Input")]
    pub input: Option<PathBuf>,
    /// The column of FILE.csv holding the history, by its header name (default u); other
    /// columns are ignored.
    #[arg(long, value_name = "NAME", requires = "input", help_heading = "Input")]
    pub column: Option<String>,
    /// The history on the command line, e.g. -2,1,-3,5,-1,3,-4,4,-2.
    #[arg(
        long,
        value_name = "V0,V1,...",
        allow_hyphen_values = true,
        conflicts_with = "input",
        help_heading = "Input"
    )]
    pub values: Option<String>,
    /// Noise gate: ignore reversals smaller than H (in units of u; 0, the default, is no
    /// gate). Every range between consecutive reversals is then >= H.
    #[arg(
        long,
        value_name = "H",
        allow_hyphen_values = true,
        value_parser = Real,
        help_heading = "Counting"
    )]
    pub gate: Option<f64>,
    /// Follow y* (eq. 6) along the history and report each full cycle's work, stored-energy
    /// change, dissipation and closure gap (implied by --x0, --model dahl and any model
    /// parameter; the model defaults to the paper's Examples 2-3).
    #[arg(long, help_heading = "Energy")]
    pub energy: bool,
    /// Initial bristle deflection x(0), with |sigma0 x0| <= g(0): y*(0) = sigma0 x0 (default
    /// 0; for Dahl, x0 = w(0) / rho).
    #[arg(
        long,
        value_name = "X",
        allow_hyphen_values = true,
        value_parser = Real,
        help_heading = "Energy"
    )]
    pub x0: Option<f64>,
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    /// Bin the counts by range, and by range and mean (the rainflow matrix), over the
    /// history's span.
    #[arg(long, help_heading = "Output")]
    pub histogram: bool,
    /// Bins per axis for --histogram (default 10).
    #[arg(
        long,
        value_name = "N",
        allow_hyphen_values = true,
        value_parser = Whole(1),
        requires = "histogram",
        help_heading = "Output"
    )]
    pub bins: Option<usize>,
}

impl CyclesArgs {
    /// Whether the model is wanted (see the module docs).
    fn wants_energy(&self) -> bool {
        let m = &self.model;
        self.energy
            || self.x0.is_some()
            || m.model == ModelKind::Dahl
            || [
                m.sigma0, m.sigma1, m.sigma2, m.fc, m.fs, m.vs, m.beta, m.rho,
            ]
            .iter()
            .any(Option::is_some)
    }
}

/// Where the samples come from.
enum Source<'a> {
    File { path: &'a Path, column: &'a str },
    Values(Vec<f64>),
}

impl Source<'_> {
    /// How errors name the input.
    fn name(&self) -> String {
        match self {
            Source::File { path, .. } => path.display().to_string(),
            Source::Values(_) => "--values".into(),
        }
    }

    /// Streams the samples in blocks to `f`.
    fn each_block(&self, mut f: impl FnMut(&[f64]) -> Result<()>) -> Result<()> {
        match self {
            Source::Values(v) => v.chunks(BLOCK).try_for_each(f),
            Source::File { path, column } => {
                let name = || path.display().to_string();
                let mut reader = SampleReader::open(path, Columns::Named(column))?;
                let mut block = Vec::with_capacity(BLOCK);
                while let Some(s) = reader.next_sample().with_context(name)? {
                    // Finite already (the reader checks).
                    if s.u.abs() > MAX_SAMPLE {
                        bail!(
                            "{}: line {}: u = {} is too large (|u| must be at most {} so that ranges stay finite)",
                            name(),
                            reader.line(),
                            num(s.u),
                            num(MAX_SAMPLE)
                        );
                    }
                    block.push(s.u);
                    if block.len() == BLOCK {
                        f(&block)?;
                        block.clear();
                    }
                }
                if !block.is_empty() {
                    f(&block)?;
                }
                Ok(())
            }
        }
    }
}

/// The counter, with or without energies.
enum Counter {
    Plain(CycleCounter),
    Energy(Box<EnergyCycleCounter>),
}

impl Counter {
    fn push_all(
        &mut self,
        u: &[f64],
        sink: &mut impl CycleSink,
    ) -> Result<(), lugre::HistoryError> {
        match self {
            Counter::Plain(c) => c.push_all(u, sink),
            Counter::Energy(c) => c.push_all(u, sink),
        }
    }

    fn finish(self, sink: &mut impl CycleSink) -> Result<CycleSummary, lugre::HistoryError> {
        match self {
            Counter::Plain(c) => c.finish(sink),
            Counter::Energy(c) => c.finish(sink),
        }
    }
}

/// The model and initial state, when energies are wanted.
struct Energy {
    model: ModelChoice,
    x0: f64,
}

pub fn run(args: &CyclesArgs) -> Result<()> {
    let gate = args.gate.unwrap_or(0.0);
    // Validated here so that a bad flag is reported before any input is read.
    CycleCounter::new(gate).map_err(|e| anyhow!("--gate: {e}"))?;
    let energy = if args.wants_energy() {
        let model = args.model.build()?;
        let x0 = args.x0.unwrap_or(0.0);
        EnergyCycleCounter::new(gate, model.rate_independent(), x0)
            .map_err(|e| anyhow!("--x0: {e}"))?;
        Some(Energy { model, x0 })
    } else {
        None
    };
    let bins = args.bins.unwrap_or(DEFAULT_BINS);
    if args.histogram && !(1..=MAX_BINS).contains(&bins) {
        bail!("--bins must be between 1 and {MAX_BINS}, got {bins}");
    }
    let column = args.column.as_deref().unwrap_or("u");
    let source = match (&args.input, &args.values) {
        (Some(path), None) => Source::File { path, column },
        (None, Some(text)) => {
            let u = parse_list("--values", text)?;
            // Finite already (parse_list checks).
            if let Some(k) = u.iter().position(|v| v.abs() > MAX_SAMPLE) {
                bail!(
                    "--values: item {} is {}, which is too large (|u| must be at most {})",
                    k + 1,
                    num(u[k]),
                    num(MAX_SAMPLE)
                );
            }
            Source::Values(u)
        }
        _ => bail!("no input: give --input FILE.csv or --values V0,V1,..."),
    };
    let source_error = |e: lugre::HistoryError| anyhow!("{}: {e}", source.name());
    let new_counter = || -> Result<Counter> {
        Ok(match &energy {
            Some(e) => Counter::Energy(Box::new(EnergyCycleCounter::new(
                gate,
                e.model.rate_independent(),
                e.x0,
            )?)),
            None => Counter::Plain(CycleCounter::new(gate)?),
        })
    };

    // First pass (JSON, histogram): validate, find the span, collect the reversals. With a
    // model it follows the energies too, so that an overflow there is reported before the
    // second pass streams anything to stdout.
    let first = if args.output.json || args.histogram {
        let mut spool = Spool::new(SPOOL_IN_MEMORY);
        let mut pass = FirstPass {
            json: args.output.json.then(|| JsonOut::new(&mut spool)),
            reversals: 0,
            min: f64::INFINITY,
            max: f64::NEG_INFINITY,
            error: None,
        };
        let mut counter = new_counter()?;
        source.each_block(|block| {
            counter.push_all(block, &mut pass).map_err(source_error)?;
            pass.check()
        })?;
        let summary = counter.finish(&mut pass).map_err(source_error)?;
        pass.check()?;
        check_history(&summary)?;
        if let Some(j) = pass.json.take() {
            j.finish()?;
        }
        let (min, max) = (pass.min, pass.max);
        Some((min, max, spool))
    } else {
        None
    };

    let histogram = match (&first, args.histogram) {
        (Some((min, max, _)), true) => {
            Some(Histogram::new(bins, *min, *max).map_err(|e| anyhow!("--histogram: {e}"))?)
        }
        _ => None,
    };
    let stdout = io::stdout();
    let mut json = if args.output.json {
        let mut j = JsonOut::new(stdout.lock());
        j.raw("{\"reversals\":[")?;
        if let Some((_, _, spool)) = &first {
            spool.replay(|chunk| {
                j.raw(std::str::from_utf8(chunk).context("reversal spool")?)?;
                Ok(())
            })?;
        }
        j.raw("],\"cycles\":[")?;
        Some(j)
    } else {
        None
    };

    // Second pass (or the only one): count, with energies, and report.
    let count = |csv: Option<&mut dyn Write>,
                 json: Option<&mut JsonOut<io::StdoutLock<'static>>>| {
        let mut pass = SecondPass {
            json,
            csv,
            cycles: 0,
            table: Vec::with_capacity(MAX_TABLE_ROWS),
            histogram: histogram.clone(),
            max_range: 0.0,
            error: None,
        };
        if let Some(w) = pass.csv.as_mut() {
            if let Err(e) = w.write_all(CSV_HEADER.as_bytes()) {
                pass.error = Some(e.into());
            }
        }
        let mut counter = new_counter()?;
        source.each_block(|block| {
            counter.push_all(block, &mut pass).map_err(source_error)?;
            pass.check()
        })?;
        let summary = counter.finish(&mut pass).map_err(source_error)?;
        pass.check()?;
        // Before the table is printed and the CSV renamed into place.
        check_history(&summary)?;
        Ok::<_, anyhow::Error>(Report {
            summary,
            table: pass.table,
            histogram: pass.histogram,
            max_range: pass.max_range,
        })
    };
    let report = match &args.output.csv {
        Some(path) => {
            let mut report = None;
            write_atomic(path, |w| {
                report = Some(count(Some(w), json.as_mut())?);
                Ok(())
            })?;
            report.context("the count did not run")?
        }
        None => count(None, json.as_mut())?,
    };

    match json {
        Some(mut j) => {
            report.write_json_tail(&mut j, gate, energy.as_ref())?;
            j.finish()?;
        }
        None => {
            let mut out = BufWriter::with_capacity(1 << 16, stdout.lock());
            report.print_table(&mut out, &source, gate, energy.as_ref())?;
            if let Some(path) = &args.output.csv {
                writeln!(
                    out,
                    "\nWrote the cycles (one row per cycle) to {}",
                    path.display()
                )?;
            }
            out.flush()?;
        }
    }
    Ok(())
}

const CSV_HEADER: &str = "range,mean,count,start,end,closure,closure_position,work,stored_energy_change,dissipation,closure_gap,y_start,y_closure\n";

/// Receives the first pass: reversals (to JSON), the span, and the first I/O error.
struct FirstPass<W: Write> {
    json: Option<JsonOut<W>>,
    reversals: u64,
    min: f64,
    max: f64,
    error: Option<io::Error>,
}

impl<W: Write> FirstPass<W> {
    fn check(&mut self) -> Result<()> {
        match self.error.take() {
            Some(e) => Err(e.into()),
            None => Ok(()),
        }
    }
}

impl<W: Write> CycleSink for FirstPass<W> {
    fn reversal(&mut self, r: Reversal) {
        self.min = self.min.min(r.u);
        self.max = self.max.max(r.u);
        if let (Some(j), None) = (self.json.as_mut(), &self.error) {
            let result = (|| {
                j.raw(if self.reversals == 0 {
                    "{\"index\":"
                } else {
                    ",{\"index\":"
                })?;
                j.int(r.index as usize)?;
                j.field(",\"u\":", r.u)?;
                j.raw("}")
            })();
            if let Err(e) = result {
                self.error = Some(e);
            }
        }
        self.reversals += 1;
    }

    fn cycle(&mut self, _c: Cycle) {}
}

/// Receives the second pass: cycles to JSON and CSV, the table's first rows, the histogram.
struct SecondPass<'a, 'b> {
    json: Option<&'a mut JsonOut<io::StdoutLock<'static>>>,
    csv: Option<&'b mut dyn Write>,
    cycles: u64,
    table: Vec<Cycle>,
    histogram: Option<Histogram>,
    max_range: f64,
    error: Option<anyhow::Error>,
}

impl SecondPass<'_, '_> {
    fn check(&mut self) -> Result<()> {
        match self.error.take() {
            Some(e) => Err(e),
            None => Ok(()),
        }
    }

    fn write(&mut self, c: &Cycle) -> Result<()> {
        if let Some(j) = self.json.as_mut() {
            j.raw(if self.cycles == 0 { "{" } else { ",{" })?;
            j.field("\"range\":", c.range)?;
            j.field(",\"mean\":", c.mean)?;
            j.field(",\"count\":", c.count)?;
            j.raw(",\"start\":")?;
            j.int(c.start as usize)?;
            j.raw(",\"end\":")?;
            j.int(c.end as usize)?;
            j.raw(",\"closure\":")?;
            match c.closure {
                Some(cl) => {
                    j.int(cl.index as usize)?;
                    j.field(",\"closure_position\":", cl.position)?;
                }
                None => j.raw("null,\"closure_position\":null")?,
            }
            match c.energy {
                Some(e) => {
                    j.field(",\"work\":", e.work)?;
                    j.field(",\"stored_energy_change\":", e.stored_energy_change)?;
                    j.field(",\"dissipation\":", e.dissipation)?;
                    j.field(",\"closure_gap\":", e.closure_gap)?;
                    j.field(",\"y_start\":", e.y_start)?;
                    j.field(",\"y_closure\":", e.y_closure)?;
                }
                None => j.raw(
                    ",\"work\":null,\"stored_energy_change\":null,\"dissipation\":null,\"closure_gap\":null,\"y_start\":null,\"y_closure\":null",
                )?,
            }
            j.raw("}")?;
        }
        if let Some(w) = self.csv.as_mut() {
            let opt = |x: Option<f64>| x.map(exact).unwrap_or_default();
            let e = c.energy;
            writeln!(
                w,
                "{},{},{},{},{},{},{},{},{},{},{},{},{}",
                exact(c.range),
                exact(c.mean),
                exact(c.count),
                c.start,
                c.end,
                c.closure.map(|cl| cl.index.to_string()).unwrap_or_default(),
                opt(c.closure.map(|cl| cl.position)),
                opt(e.map(|e| e.work)),
                opt(e.map(|e| e.stored_energy_change)),
                opt(e.map(|e| e.dissipation)),
                opt(e.map(|e| e.closure_gap)),
                opt(e.map(|e| e.y_start)),
                opt(e.map(|e| e.y_closure)),
            )?;
        }
        Ok(())
    }
}

impl CycleSink for SecondPass<'_, '_> {
    fn reversal(&mut self, _r: Reversal) {}

    fn cycle(&mut self, c: Cycle) {
        if self.error.is_none() {
            if let Err(e) = self.write(&c) {
                self.error = Some(e);
            }
        }
        if let Some(h) = self.histogram.as_mut() {
            h.add(&c);
        }
        if self.table.len() < MAX_TABLE_ROWS {
            self.table.push(c);
        }
        self.max_range = self.max_range.max(c.range);
        self.cycles += 1;
    }
}

/// What the second pass leaves for the report.
struct Report {
    summary: CycleSummary,
    table: Vec<Cycle>,
    histogram: Option<Histogram>,
    max_range: f64,
}

impl Report {
    /// Everything after the cycles in `--json` (keys may be added, never renamed).
    fn write_json_tail<W: Write>(
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
                let ri = e.model.rate_independent();
                j.raw(",\"model\":")?;
                j.raw(&e.model.to_json().to_string())?;
                j.field(",\"x0\":", e.x0)?;
                j.field(",\"g0\":", ri.g0())?;
                j.field(",\"a\":", ri.a())?;
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

    fn print_table(
        &self,
        out: &mut impl Write,
        source: &Source,
        gate: f64,
        energy: Option<&Energy>,
    ) -> Result<()> {
        let s = &self.summary;
        let from = match source {
            Source::File { path, column } => format!("{} (column {column})", path.display()),
            Source::Values(_) => "--values".into(),
        };
        writeln!(
            out,
            "History: {} samples from {from}; {} reversals{}",
            s.samples,
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
        if let Some(e) = energy {
            let ri = e.model.rate_independent();
            writeln!(out, "{}", e.model.describe())?;
            writeln!(
                out,
                "g(0) = {}   a = sigma0/g(0) = {}   y*(0) = sigma0 x0 = {}",
                sig(ri.g0(), 10),
                sig(ri.a(), 10),
                sig(ri.sigma0() * e.x0, 10)
            )?;
        }

        writeln!(
            out,
            "\nCycles, in the order they close (closure: first sample back at the start value, and the interpolated position)"
        )?;
        let mut head = format!(
            "{:>6} {:>5} {:>12} {:>12} {:>10} {:>10} {:>10} {:>12}",
            "#", "count", "range", "mean", "start", "end", "closure", "at"
        );
        if energy.is_some() {
            head += &format!(
                " {:>13} {:>13} {:>13} {:>13}",
                "work W", "stored dV", "dissip. D", "gap y_C-y_A"
            );
        }
        writeln!(out, "{head}")?;
        for (i, c) in self.table.iter().enumerate() {
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
                    sig(e.work, 8),
                    sig(e.stored_energy_change, 8),
                    sig(e.dissipation, 8),
                    sig(e.closure_gap, 8)
                );
            } else if energy.is_some() {
                row += &format!(" {:>13} {:>13} {:>13} {:>13}", "-", "-", "-", "-");
            }
            writeln!(out, "{row}")?;
        }
        let total = s.full_cycles + s.half_cycles;
        if total > self.table.len() as u64 {
            writeln!(
                out,
                "{:>6} ... {} more rows: use --json or --csv FILE to get all",
                "",
                total - self.table.len() as u64
            )?;
        }
        if let Some(h) = s.energy {
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

/// The totals along the history are finite (checked before anything is printed).
fn check_history(summary: &CycleSummary) -> Result<()> {
    let Some(h) = summary.energy else {
        return Ok(());
    };
    if [h.work, h.stored_energy_change, h.dissipation, h.y_end]
        .iter()
        .all(|x| x.is_finite())
    {
        Ok(())
    } else {
        bail!("the energies along the history overflow f64 for this model and input (values too large)")
    }
}
