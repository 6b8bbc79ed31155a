//! The `lugre` command as a library: argument parsing, CSV and JSON I/O, figures and the
//! commands themselves. The binary (`main.rs`) parses the arguments, runs a command and maps
//! errors to exit statuses; the modules are public so that the fuzz targets (`fuzz/`) can drive
//! the CSV reader and the number-list parser directly.

pub mod args;
pub mod cli;
mod commands;
pub mod fmt;
mod hysteresis;
pub mod io;
pub mod numbers;
pub mod plot;
