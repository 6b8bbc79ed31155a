//! The reader's errors ([`Error`]), one variant per mistake, each carrying the line, the column
//! and the value concerned; its `Display` is the one-line message every front end shows (the
//! CLI after the file's name, Python in a `ValueError`). [`FileError`] adds the file's path.

use std::path::PathBuf;

use lugre::error::num;
use thiserror::Error;

use crate::{Delimiter, Role};

/// Something that cannot be read. Lines are numbered from 1 as an editor shows them (comment
/// and blank lines counted; CRLF is one line end). Columns are named as the file's header
/// names them, or by their role (`u`, `F`, ...) in a file without one.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum Error {
    // --- the options (`--columns`, `--scale`), before any line is read ---
    #[error("{option}: '{item}' is not {form}")]
    NotAPair {
        option: &'static str,
        item: String,
        /// `ROLE=COLUMN` or `ROLE=FACTOR`.
        form: &'static str,
    },
    #[error("{option}: {role} is given twice ({first} and {second})")]
    RoleTwice {
        option: &'static str,
        role: String,
        first: String,
        second: String,
    },
    #[error("{option} {role}=0: columns are numbered from 1")]
    ColumnZero { option: &'static str, role: String },
    #[error("{option} {role}={value}: not a number")]
    FactorNotANumber {
        option: &'static str,
        role: String,
        value: String,
    },
    #[error("{option} {role}={value}: a factor must be a finite number other than 0")]
    BadFactor {
        option: &'static str,
        role: String,
        value: String,
    },
    #[error("{option}: unknown column role '{role}' (this command reads {reads})")]
    UnknownRole {
        option: &'static str,
        role: String,
        /// The roles that are read, as "t, u, F".
        reads: String,
    },

    // --- the header (or the first row of a file without one): where each column is ---
    #[error("line {line}: {option} {role}={index}: the file has {width} column{s} (numbered from 1)", s = plural(*.width))]
    IndexOutOfRange {
        line: u64,
        option: &'static str,
        role: String,
        index: usize,
        width: usize,
    },
    #[error("line {line}: {option} {role}={name}: the file has no header line (number the columns instead, from 1)")]
    NameWithoutHeader {
        line: u64,
        option: &'static str,
        role: String,
        name: String,
    },
    #[error("line {line}: {option} {item}: no such column in the header {header}{hint} (fields separated by {sep})",
        hint = closest.as_ref().map(|c| format!(" (did you mean '{c}'?)")).unwrap_or_default(),
        sep = delimiter.describe())]
    NoSuchName {
        line: u64,
        option: &'static str,
        /// The choice as given: `u=Positon`.
        item: String,
        /// The header as written, quoted and cut short.
        header: String,
        /// The header field closest to the name, if one is close.
        closest: Option<String>,
        delimiter: Delimiter,
    },
    #[error("line {line}: {option} {role}={name}: the header {header} has more than one column of that name (number the column instead, from 1)")]
    NameTwice {
        line: u64,
        option: &'static str,
        role: String,
        name: String,
        header: String,
    },
    #[error("line {line}: no column {role}{names} in the header {header} (fields separated by {sep}){hint}",
        names = match role.names_in_words() { n if n.is_empty() => n, n => format!(" ({n})") },
        sep = delimiter.describe(),
        hint = closest.as_ref().map(|c| format!("; did you mean '{c}'?")).unwrap_or_else(|| format!("; name it with {option} {}=NAME", role.name())))]
    MissingColumn {
        line: u64,
        role: Role,
        header: String,
        /// For a column asked for by a name of its own: the header field closest to it.
        closest: Option<String>,
        delimiter: Delimiter,
        option: &'static str,
    },
    #[error("line {line}: the header has two columns for {role}: '{first}' (column {first_index}) and '{second}' (column {second_index}); say which with {option} {role}=NUMBER")]
    DuplicateColumn {
        line: u64,
        role: String,
        first: String,
        first_index: usize,
        second: String,
        second_index: usize,
        option: &'static str,
    },
    #[error("line {line}: column {column}{name} would be read as both {first} and {second}: give each its own column with {option}",
        name = name.as_ref().map(|n| format!(" ('{n}')")).unwrap_or_default())]
    ColumnInTwoRoles {
        line: u64,
        /// 1-based.
        column: usize,
        name: Option<String>,
        first: String,
        second: String,
        option: &'static str,
    },
    #[error("line {line}: expected {expected}, found {found} (fields separated by {sep})", sep = delimiter.describe())]
    FirstRowWidth {
        line: u64,
        /// "2 columns (u,F) or 3 columns (t,u,F)".
        expected: String,
        found: usize,
        delimiter: Delimiter,
    },
    #[error("line {line}: the file has no header line: give every column's number with {option}")]
    NoHeaderSelect { line: u64, option: &'static str },
    #[error("line {line}: no header line, so no column {role} (a file without a header has the columns {columns})")]
    NoHeaderNamed {
        line: u64,
        role: String,
        /// "u or t,u".
        columns: String,
    },

    // --- the rows ---
    #[error("line {line}: expected {expected} value{s} ({columns}), found {found} (fields separated by {sep})",
        s = plural(*.expected), sep = delimiter.describe())]
    RowWidth {
        line: u64,
        expected: usize,
        /// The header as written, or the roles of a file without one ("t,u").
        columns: String,
        found: usize,
        delimiter: Delimiter,
    },
    #[error("line {line}: not valid UTF-8 text")]
    Utf8 { line: u64 },
    #[error("line {line}: empty value for {column}")]
    EmptyValue { line: u64, column: String },
    #[error("line {line}: {column} = {value} is not a number")]
    NotANumber {
        line: u64,
        column: String,
        /// The field as written, quoted and cut short.
        value: String,
    },
    /// The core's words for a value that is not finite (`u[1] must be a finite number, got
    /// NaN`), at the file's line.
    #[error("line {line}: {column} must be a finite number, got {value}", value = num(*.value))]
    NotFinite {
        line: u64,
        column: String,
        value: f64,
    },
    #[error("line {line}: {column} = {value} times the {option} factor {factor} is not a finite number", value = num(*.value), factor = num(*.factor))]
    ScaledNotFinite {
        line: u64,
        column: String,
        value: f64,
        factor: f64,
        option: &'static str,
    },
    #[error("line {line}: {column} must be > 0, got {value}", value = num(*.value))]
    NotPositive {
        line: u64,
        column: String,
        value: f64,
    },
    #[error("line {line}: times must be strictly increasing, t = {value} follows t = {prev}", value = num(*.value), prev = num(*.prev))]
    TimesNotIncreasing { line: u64, prev: f64, value: f64 },
    #[error("line {line}: a line is longer than {limit} bytes (not a CSV file of numbers?)")]
    LineTooLong { line: u64, limit: usize },
    #[error("line {line}: {source}")]
    Io {
        line: u64,
        #[source]
        source: std::io::Error,
    },
    #[error("no data rows")]
    NoData,
    #[error("cannot read the file: {source}")]
    Open {
        #[source]
        source: std::io::Error,
    },
}

fn plural(n: usize) -> &'static str {
    if n == 1 {
        ""
    } else {
        "s"
    }
}

impl Error {
    /// The line the error is on, if it is on one.
    pub fn line(&self) -> Option<u64> {
        use Error::*;
        match self {
            IndexOutOfRange { line, .. }
            | NameWithoutHeader { line, .. }
            | NoSuchName { line, .. }
            | NameTwice { line, .. }
            | MissingColumn { line, .. }
            | DuplicateColumn { line, .. }
            | ColumnInTwoRoles { line, .. }
            | FirstRowWidth { line, .. }
            | NoHeaderSelect { line, .. }
            | NoHeaderNamed { line, .. }
            | RowWidth { line, .. }
            | Utf8 { line }
            | EmptyValue { line, .. }
            | NotANumber { line, .. }
            | NotFinite { line, .. }
            | ScaledNotFinite { line, .. }
            | NotPositive { line, .. }
            | TimesNotIncreasing { line, .. }
            | LineTooLong { line, .. }
            | Io { line, .. } => Some(*line),
            NotAPair { .. }
            | RoleTwice { .. }
            | ColumnZero { .. }
            | FactorNotANumber { .. }
            | BadFactor { .. }
            | UnknownRole { .. }
            | NoData
            | Open { .. } => None,
        }
    }

    /// The error of a file: the same message after its path.
    pub fn in_file(self, path: impl Into<PathBuf>) -> FileError {
        FileError {
            path: path.into(),
            error: Box::new(self),
        }
    }
}

/// An [`enum@Error`] in a file: `path: message`.
#[derive(Debug, Error)]
#[error("{}: {error}", path.display())]
pub struct FileError {
    pub path: PathBuf,
    /// Not a `source`: the message already holds it (a chain printer would show it twice).
    pub error: Box<Error>,
}
