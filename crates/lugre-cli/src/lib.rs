//! The `lugre` command as a library. The binary (`main.rs`) parses the arguments into a
//! [`Cli`], runs it and maps errors to exit statuses; everything else is private to the crate,
//! except the parser the fuzz targets (`fuzz/`) drive directly, in [`fuzzing`].
//!
//! Modules: `cli` (the parser and the dispatch to the commands), `args` (the flags several
//! commands share), `commands` (one module per command), `io` (CSV and JSON out, atomic files,
//! the spool, progress; data files are read by the `lugre-io` crate), `plot` (figures), `hysteresis` (what `loop` and `paper` both
//! draw), `fmt` and `numbers` (numbers out and in).
#![warn(unreachable_pub)]

mod args;
mod cli;
mod commands;
mod fmt;
mod hysteresis;
mod io;
mod numbers;
mod plot;
mod zoo_args;

pub use cli::Cli;
pub use fmt::shorten_quoted;

/// What the fuzz targets drive: the parser of number lists (the data-file reader is the
/// `lugre-io` crate's). Not an API.
#[doc(hidden)]
pub mod fuzzing {
    pub use crate::fmt::exact;
    pub use crate::numbers::{parse_list, parse_number};
}
