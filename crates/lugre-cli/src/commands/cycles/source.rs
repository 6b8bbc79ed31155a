//! Where the samples come from (a CSV file, streamed, or `--values`).

use anyhow::{bail, Result};
use lugre::cycles::MAX_SAMPLE;
use std::path::Path;

use crate::fmt::num;
use lugre_io::{ReadOptions, Reader, Role, Spec};

/// Samples handed to the counter at a time.
const BLOCK: usize = 4096;

/// Where the samples come from.
pub(super) enum Source<'a> {
    File {
        path: &'a Path,
        column: &'a str,
        /// `--columns` and `--scale`.
        options: ReadOptions,
    },
    Values(Vec<f64>),
}

impl Source<'_> {
    /// How errors name the input.
    pub(super) fn name(&self) -> String {
        match self {
            Source::File { path, .. } => path.display().to_string(),
            Source::Values(_) => "--values".into(),
        }
    }

    /// How the table names the input.
    pub(super) fn describe(&self) -> String {
        match self {
            Source::File { path, column, .. } => format!("{} (column {column})", path.display()),
            Source::Values(_) => "--values".into(),
        }
    }

    /// Streams the samples in blocks to `f`.
    pub(super) fn each_block(&self, mut f: impl FnMut(&[f64]) -> Result<()>) -> Result<()> {
        match self {
            Source::Values(v) => v.chunks(BLOCK).try_for_each(f),
            Source::File {
                path,
                column,
                options,
            } => {
                let name = || path.display().to_string();
                // The column and `t` where the file has one (times are checked, not used).
                let spec = Spec::new([Role::of(column)]);
                let mut rows = Reader::open(path, options.clone())?
                    .rows(&spec)
                    .map_err(|e| e.in_file(*path))?;
                let mut block = Vec::with_capacity(BLOCK);
                while let Some(row) = rows.next_row().map_err(|e| e.in_file(*path))? {
                    let u = row.values[0];
                    // Finite already (the reader checks).
                    if u.abs() > MAX_SAMPLE {
                        bail!(
                            "{}: line {}: u = {} is too large (|u| must be at most {} so that ranges stay finite)",
                            name(),
                            rows.line(),
                            num(u),
                            num(MAX_SAMPLE)
                        );
                    }
                    block.push(u);
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
