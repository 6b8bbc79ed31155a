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
//! Energies are computed with `--energy`, and whenever a model flag is given (`--x0`,
//! `--preset`, `--model`, or any model parameter): a model flag without energies would be
//! silently ignored. They come from a model the user named (a preset, or the parameters of the
//! slow loop), never from the paper's dimensionless defaults alone.

use anyhow::{anyhow, bail, Context, Result};
use clap::Args;
use lugre::{CycleCounter, CycleSink, CycleSummary, Histogram};
use std::io::{self, BufWriter, Write};
use std::path::PathBuf;

use crate::args::{check_files, ModelArgs, ModelChoice, OutputArgs};
use crate::io::atomic::write_atomic;
use crate::io::json::JsonOut;
use crate::io::spool::Spool;
use crate::numbers::{parse_series, Real, Whole};
use lugre::model::named::Needed;

mod passes;
mod report;
mod source;

use passes::{FirstPass, SecondPass};
use report::Report;
use source::Source;

/// Rows of the cycle table printed before the rest is summarised (all of it is in --json and
/// --csv).
const MAX_TABLE_ROWS: usize = 40;

/// Reversal JSON kept in memory before it goes to a temporary file.
const SPOOL_IN_MEMORY: usize = 8 << 20;

/// Bins per axis of `--histogram` when `--bins` is not given, and the most allowed (the
/// range x mean matrix has `bins^2` cells).
const DEFAULT_BINS: usize = 10;
const MAX_BINS: usize = 1000;

/// The help of `--csv` for this command (the columns are the core's).
fn csv_help() -> String {
    format!(
        "Write the cycles to this CSV file, one row per cycle: {} (empty where a half cycle has no closure or there is no model)",
        lugre::Cycle::COLUMNS.join(",")
    )
}

#[derive(Args, Debug)]
#[command(
    mut_arg("csv", |a| a.help(csv_help()))
)]
pub(crate) struct CyclesArgs {
    /// The history from a data file: its column u (u, x, position or displacement; no header:
    /// u or t,u), or the column --column names; other columns are ignored, a column t is
    /// checked as strictly increasing times.
    #[arg(long, value_name = "FILE.csv", help_heading = "Input")]
    pub(crate) input: Option<PathBuf>,
    /// The column of FILE.csv holding the history, by its header name or a role's usual name
    /// (default u).
    #[arg(long, value_name = "NAME", requires = "input", help_heading = "Input")]
    pub(crate) column: Option<String>,
    #[command(flatten)]
    pub(crate) data: crate::args::DataArgs,
    /// The history on the command line, e.g. -2,1,-3,5,-1,3,-4,4,-2.
    #[arg(
        long,
        value_name = "V0,V1,...",
        allow_hyphen_values = true,
        conflicts_with = "input",
        help_heading = "Input"
    )]
    pub(crate) values: Option<String>,
    /// Noise gate: ignore reversals smaller than H (in units of u; 0, the default, is no
    /// gate). Every range between consecutive reversals is then >= H.
    #[arg(
        long,
        value_name = "H",
        allow_hyphen_values = true,
        value_parser = Real,
        help_heading = "Counting"
    )]
    pub(crate) gate: Option<f64>,
    /// Follow y* (eq. 6) along the history and report each full cycle's work, stored-energy
    /// change, dissipation and closure gap (implied by --x0, --preset, --model and any model
    /// parameter). The model must be named: --preset canudas1995, or --sigma0 and --fs
    /// (LuGre; only they act on the slow loop), or --model dahl --rho --fc.
    #[arg(long, help_heading = "Energy")]
    pub(crate) energy: bool,
    /// Initial bristle deflection x(0), with |sigma0 x0| <= g(0): y*(0) = sigma0 x0 (default
    /// 0; for Dahl, x0 = w(0) / rho).
    #[arg(
        long,
        value_name = "X",
        allow_hyphen_values = true,
        value_parser = Real,
        help_heading = "Energy"
    )]
    pub(crate) x0: Option<f64>,
    #[command(flatten)]
    pub(crate) model: ModelArgs,
    #[command(flatten)]
    pub(crate) output: OutputArgs,
    /// Bin the counts by range, and by range and mean (the rainflow matrix), over the
    /// history's span.
    #[arg(long, help_heading = "Output")]
    pub(crate) histogram: bool,
    /// Bins per axis for --histogram (default 10).
    #[arg(
        long,
        value_name = "N",
        allow_hyphen_values = true,
        value_parser = Whole(1),
        requires = "histogram",
        help_heading = "Output"
    )]
    pub(crate) bins: Option<usize>,
}

impl CyclesArgs {
    /// Whether the model is wanted (see the module docs).
    fn wants_energy(&self) -> bool {
        self.energy || self.x0.is_some() || self.model.names_any()
    }
}

/// The model and initial state, when energies are wanted: LuGre or Dahl from `x0`, or a model
/// of the zoo from rest.
enum Energy {
    Classic { model: ModelChoice, x0: f64 },
    Zoo(lugre::zoo::ZooModel),
}

/// The request, from the flags (all checked before any input is read).
struct Request<'a> {
    gate: f64,
    energy: Option<Energy>,
    /// Bins per axis of the histogram (when one is asked for).
    bins: usize,
    source: Source<'a>,
}

impl Request<'_> {
    /// The counter, with the energies of the model when one is named.
    fn counter(&self) -> Result<CycleCounter, lugre::HistoryError> {
        match &self.energy {
            Some(Energy::Classic { model, x0 }) => {
                CycleCounter::new(self.gate)?.with_energy(Some(model.rate_independent()), *x0)
            }
            _ => CycleCounter::new(self.gate),
        }
    }

    /// A counter's error, naming the input.
    fn source_error(&self, e: lugre::HistoryError) -> anyhow::Error {
        anyhow!("{}: {e}", self.source.name())
    }

    /// Streams the history through a new counter into `sink`; `check` reports the sink's
    /// first error after each block.
    fn count<S: CycleSink>(
        &self,
        sink: &mut S,
        check: impl Fn(&mut S) -> Result<()>,
    ) -> Result<CycleSummary> {
        if let Some(Energy::Zoo(model)) = &self.energy {
            return self.count_zoo(model, sink, check);
        }
        let mut counter = self.counter()?;
        self.source.each_block(|block| {
            counter
                .push_all(block, sink)
                .map_err(|e| self.source_error(e))?;
            check(sink)
        })?;
        let summary = counter.finish(sink).map_err(|e| self.source_error(e))?;
        check(sink)?;
        check_history(&summary)?;
        Ok(summary)
    }
}

impl Request<'_> {
    /// [`Self::count`] with the energies of a model of the zoo: the history in memory, counted,
    /// each full cycle's energy along the model's path from rest, then the reversals and the
    /// cycles passed to `sink`.
    fn count_zoo<S: CycleSink>(
        &self,
        model: &lugre::zoo::ZooModel,
        sink: &mut S,
        check: impl Fn(&mut S) -> Result<()>,
    ) -> Result<CycleSummary> {
        let mut u = Vec::new();
        self.source.each_block(|block| {
            lugre::zoo::check_held(model, u.len() + block.len())
                .map_err(|e| self.source_error(e))?;
            u.extend_from_slice(block);
            Ok(())
        })?;
        let summary = model
            .count_cycles(&u, self.gate, sink)
            .map_err(|e| self.source_error(e))?;
        check(sink)?;
        check_history(&summary)?;
        Ok(summary)
    }
}

/// What the first pass finds: the span of the reversals, and their JSON.
struct FirstPassResult {
    min: f64,
    max: f64,
    reversals: Spool,
}

pub(crate) fn run(args: &CyclesArgs) -> Result<()> {
    check_files(args.input.as_deref(), &args.output, None)?;
    let request = parse(args)?;
    let first = if args.output.json || args.histogram {
        Some(first_pass(&request, args.output.json)?)
    } else {
        None
    };
    let histogram = match (&first, args.histogram) {
        (Some(f), true) => Some(
            Histogram::new(request.bins, f.min, f.max).map_err(|e| anyhow!("--histogram: {e}"))?,
        ),
        _ => None,
    };
    let stdout = io::stdout();
    let mut json = if args.output.json {
        let mut j = JsonOut::new(stdout.lock());
        j.raw("{\"reversals\":[")?;
        if let Some(f) = &first {
            f.reversals.replay(|chunk| {
                j.raw(std::str::from_utf8(chunk).context("reversal spool")?)?;
                Ok(())
            })?;
        }
        j.raw("],\"cycles\":[")?;
        Some(j)
    } else {
        None
    };
    let report = match &args.output.csv {
        Some(path) => {
            let mut report = None;
            write_atomic(path, |w| {
                report = Some(second_pass(&request, histogram, Some(w), json.as_mut())?);
                Ok(())
            })?;
            report.context("the count did not run")?
        }
        None => second_pass(&request, histogram, None, json.as_mut())?,
    };
    match json {
        Some(mut j) => {
            report.write_json_tail(&mut j, request.gate, request.energy.as_ref())?;
            j.finish()?;
        }
        None => {
            let mut out = BufWriter::with_capacity(1 << 16, stdout.lock());
            report.print_table(
                &mut out,
                &request.source,
                request.gate,
                request.energy.as_ref(),
            )?;
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

fn parse(args: &CyclesArgs) -> Result<Request<'_>> {
    let gate = args.gate.unwrap_or(0.0);
    // Validated here so that a bad flag is reported before any input is read.
    let counter = CycleCounter::new(gate).map_err(|e| anyhow!("--gate: {e}"))?;
    let energy = if let Some(model) = args.model.build_zoo()? {
        if args.x0.is_some() {
            let e = lugre::HistoryError::StartsFromRest {
                model: model.spec().label,
            };
            bail!("--x0: {e}");
        }
        Some(Energy::Zoo(model))
    } else if args.wants_energy() {
        // Values given are checked first, then that the model is named.
        let model = args.model.build()?;
        args.model.check_named(Needed::RateIndependent)?;
        let x0 = args.x0.unwrap_or(0.0);
        counter
            .with_energy(model.rate_independent(), x0)
            .map_err(|e| anyhow!("--x0: {e}"))?;
        Some(Energy::Classic { model, x0 })
    } else {
        None
    };
    let bins = args.bins.unwrap_or(DEFAULT_BINS);
    if args.histogram && !(1..=MAX_BINS).contains(&bins) {
        bail!("--bins must be between 1 and {MAX_BINS}, got {bins}");
    }
    let column = args.column.as_deref().unwrap_or("u");
    let source = match (&args.input, &args.values) {
        (Some(path), None) => Source::File {
            path,
            column,
            options: args
                .data
                .options(&[lugre_io::Role::U, lugre_io::Role::of(column)])?,
        },
        (None, Some(text)) => {
            // Judged by the library, as `lugre.cycles` and the C ABI judge the same series.
            let u = parse_series("--values", text)?;
            lugre::cycles::check_history(&u).map_err(|e| anyhow!("--values: {e}"))?;
            Source::Values(u)
        }
        _ => bail!("no input: give --input FILE.csv or --values V0,V1,..."),
    };
    Ok(Request {
        gate,
        energy,
        bins,
        source,
    })
}

/// The first pass (for JSON and the histogram): validates the history, finds its span and
/// collects the reversals. With a model it follows the energies too, so that an overflow there
/// is reported before the second pass streams anything to stdout.
fn first_pass(request: &Request, json: bool) -> Result<FirstPassResult> {
    let mut spool = Spool::new(SPOOL_IN_MEMORY);
    let mut pass = FirstPass::new(json.then(|| JsonOut::new(&mut spool)));
    request.count(&mut pass, FirstPass::check)?;
    let (min, max) = pass.finish()?;
    Ok(FirstPassResult {
        min,
        max,
        reversals: spool,
    })
}

/// The second pass (or the only one): counts, with energies, writes each cycle to the JSON
/// document and the CSV file as it closes, and keeps what the report needs.
fn second_pass(
    request: &Request,
    histogram: Option<Histogram>,
    csv: Option<&mut dyn Write>,
    json: Option<&mut JsonOut<io::StdoutLock<'static>>>,
) -> Result<Report> {
    let mut pass = SecondPass::new(json, csv, histogram);
    // The totals are checked before the table is printed and the CSV renamed into place.
    let summary = request.count(&mut pass, SecondPass::check)?;
    Ok(pass.into_report(summary))
}

/// The totals along the history are finite (checked before anything is printed).
fn check_history(summary: &CycleSummary) -> Result<()> {
    match summary.energy {
        Some(h) => Ok(h.check_finite()?),
        None => Ok(()),
    }
}
