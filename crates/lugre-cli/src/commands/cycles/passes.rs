//! The two passes over the history, as sinks of the counter: the first collects the reversals
//! (for JSON) and the span (for the histogram); the second writes the cycles as they close.

use anyhow::Result;
use lugre::{Cycle, CycleSink, CycleSummary, Histogram, Reversal};
use std::io::{self, Write};

use super::report::Report;
use super::MAX_TABLE_ROWS;
use crate::fmt::exact;
use crate::io::json::JsonOut;

const CSV_HEADER: &str = "range,mean,count,start,end,closure,closure_position,work,stored_energy_change,dissipation,closure_gap,y_start,y_closure\n";

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
            if let Err(e) = w.write_all(CSV_HEADER.as_bytes()) {
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
                    j.field(",\"work\":", e.arc.work)?;
                    j.field(",\"stored_energy_change\":", e.arc.stored_energy_change)?;
                    j.field(",\"dissipation\":", e.arc.dissipation)?;
                    j.field(",\"closure_gap\":", e.arc.closure_gap)?;
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
                opt(e.map(|e| e.arc.work)),
                opt(e.map(|e| e.arc.stored_energy_change)),
                opt(e.map(|e| e.arc.dissipation)),
                opt(e.map(|e| e.arc.closure_gap)),
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
