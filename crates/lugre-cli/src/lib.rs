//! The `lugre` command as a library: argument parsing, CSV and JSON I/O, figures and the
//! commands themselves. The binary (`main.rs`) parses the arguments, runs a command and maps
//! errors to exit statuses; the modules are public so that the fuzz targets (`fuzz/`) can drive
//! the CSV reader and the number-list parser directly.

pub mod args;
pub mod cli;
pub mod cycles_cmd;
pub mod fit_cmd;
pub mod fmt;
pub mod io;
pub mod loop_cmd;
pub mod numbers;
pub mod paper;
mod paper_html;
pub mod plot;
pub mod simulate_cmd;
