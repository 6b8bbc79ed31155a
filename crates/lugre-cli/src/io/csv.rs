//! Writing the CSV files the commands produce ([`NumberRows`]). Data files are read by the
//! `lugre-io` crate, the reader every front end shares.

use std::io::Write;

/// Writes rows of finite numbers, each in its shortest round-trip form (as
/// [`crate::fmt::exact`] writes it) without an allocation per number: a CSV file may have 10^8
/// of them.
pub(crate) struct NumberRows {
    buf: zmij::Buffer,
}

impl NumberRows {
    pub(crate) fn new() -> Self {
        Self {
            buf: zmij::Buffer::new(),
        }
    }

    /// One row: the numbers separated by commas, then a line break.
    pub(crate) fn write(&mut self, w: &mut dyn Write, row: &[f64]) -> std::io::Result<()> {
        for (i, &x) in row.iter().enumerate() {
            let s = self.buf.format_finite(x);
            w.write_all(s.strip_suffix(".0").unwrap_or(s).as_bytes())?;
            w.write_all(if i + 1 == row.len() { b"\n" } else { b"," })?;
        }
        Ok(())
    }
}
