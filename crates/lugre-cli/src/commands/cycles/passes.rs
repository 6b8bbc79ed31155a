//! The two passes over the history, as sinks of the counter: the first collects the reversals
//! (for JSON) and the span (for the histogram); the second writes the cycles as they close.

use anyhow::Result;
use lugre::cycles::Cell;
use lugre::{Cycle, CycleSink, CycleSummary, Histogram, Reversal};
use std::io::{self, Write};

use super::report::Report;
use super::MAX_TABLE_ROWS;
use crate::fmt::exact;
use crate::io::json::JsonOut;

/// Receives the first pass: reversals (to JSON), the span, and the first I/O error.
pub(super) struct FirstPass<W: Write> {
    json: Option<JsonOut<W>>,
    reversals: u64,
    min: f64,
    max: f64,
    error: Option<io::Error>,
}

impl<W: Write> FirstPass<W> {
    /// A first pass that writes the reversals' JSON to `json`, if given.
    pub(super) fn new(json: Option<JsonOut<W>>) -> Self {
        Self {
            json,
            reversals: 0,
            min: f64::INFINITY,
            max: f64::NEG_INFINITY,
            error: None,
        }
    }

    /// Flushes the reversals' JSON; returns the span of the reversals.
    pub(super) fn finish(mut self) -> Result<(f64, f64)> {
        if let Some(j) = self.json.take() {
            j.finish()?;
        }
        Ok((self.min, self.max))
    }

    pub(super) fn check(&mut self) -> Result<()> {
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
pub(super) struct SecondPass<'a, 'b> {
    json: Option<&'a mut JsonOut<io::StdoutLock<'static>>>,
    csv: Option<&'b mut dyn Write>,
    cycles: u64,
    table: Vec<Cycle>,
    histogram: Option<Histogram>,
    max_range: f64,
    error: Option<anyhow::Error>,
}

impl<'a, 'b> SecondPass<'a, 'b> {
    /// A second pass that writes the cycles to `json` and `csv` (after its header), if given,
    /// and bins them in `histogram`.
    pub(super) fn new(
        json: Option<&'a mut JsonOut<io::StdoutLock<'static>>>,
        csv: Option<&'b mut dyn Write>,
        histogram: Option<Histogram>,
    ) -> Self {
        let mut pass = Self {
            json,
            csv,
            cycles: 0,
            table: Vec::with_capacity(MAX_TABLE_ROWS),
            histogram,
            max_range: 0.0,
            error: None,
        };
        if let Some(w) = pass.csv.as_mut() {
            if let Err(e) = writeln!(w, "{}", Cycle::COLUMNS.join(",")) {
                pass.error = Some(e.into());
            }
        }
        pass
    }

    /// What the report needs, with the counter's summary.
    pub(super) fn into_report(self, summary: CycleSummary) -> Report {
        Report {
            summary,
            table: self.table,
            histogram: self.histogram,
            max_range: self.max_range,
        }
    }

    pub(super) fn check(&mut self) -> Result<()> {
        match self.error.take() {
            Some(e) => Err(e),
            None => Ok(()),
        }
    }

    /// Cycle `c` to JSON (an object keyed by [`Cycle::COLUMNS`], `null` where a cell is
    /// missing) and CSV (a row of them, empty where missing).
    fn write(&mut self, c: &Cycle) -> Result<()> {
        let row = c.row();
        if let Some(j) = self.json.as_mut() {
            if self.cycles > 0 {
                j.raw(",")?;
            }
            for (k, (name, cell)) in Cycle::COLUMNS.iter().zip(row).enumerate() {
                j.key(k == 0, name);
                match cell {
                    Cell::Number(x) => j.num(x)?,
                    Cell::Index(i) => j.int(i as usize)?,
                    Cell::Missing => j.raw("null")?,
                }
            }
            j.raw("}")?;
        }
        if let Some(w) = self.csv.as_mut() {
            for (k, cell) in row.into_iter().enumerate() {
                let sep = if k == 0 { "" } else { "," };
                match cell {
                    Cell::Number(x) => write!(w, "{sep}{}", exact(x))?,
                    Cell::Index(i) => write!(w, "{sep}{i}")?,
                    Cell::Missing => w.write_all(sep.as_bytes())?,
                }
            }
            writeln!(w)?;
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
