//! The data-file reader of every lugre front end (the `lugre` command, the Python package's
//! `lugre.read` and `lugre.dask`): one set of rules, one set of messages.
//!
//! # What a file may hold
//!
//! * **Fields** separated by commas, semicolons, tabs or runs of spaces, whichever the first
//!   line that is neither blank nor a comment uses ([`Delimiter::of`]: a tab, else a
//!   semicolon, else a comma, else runs of spaces), or as given ([`ReadOptions::with_delimiter`]).
//!   Blanks around a field and double quotes around it are dropped (`"Force, N"` is one field).
//!   With runs of spaces, a unit in brackets belongs to the name before it (`Time [s]`).
//! * **Lines** ending in LF, CRLF or CR; a UTF-8 byte-order mark at the start; `#` comments,
//!   blank lines and lines of separators only, anywhere. Lines are numbered as an editor shows
//!   them, comments and blank lines included. A line is at most [`MAX_LINE`] bytes.
//! * **A header** (optional): the first line that is not a comment, if any of its fields is not
//!   a number. Its fields name the columns in any order, case-insensitively, each with an
//!   optional unit in brackets or parentheses at its end (`Time [s]`, `position (mm)`), which
//!   is kept ([`ColumnInfo::unit`]). Each [`Role`] has its usual names ([`Role::names`]):
//!   `t`/`time`; `u`/`x`/`position`/`displacement`; `v`/`velocity`; `F`/`force`/`friction`/`y`;
//!   `N`/`normal`/`normal force`/`load`. Columns a command does not read are ignored, whatever
//!   they hold; two columns of a role it reads are refused (say which with `--columns`).
//! * **No header**: the columns a command needs, in its order, after `t` if there is one more
//!   (`u` or `t,u`; `u,F` or `t,u,F`), or as numbered by `--columns`.
//! * **Values**: finite numbers (Rust's `f64` syntax: `1e-3`, `-2.5`, `inf` and `nan` refused
//!   as not finite); times strictly increasing. A role may allow missing values
//!   ([`Spec::allow_missing`]: empty or `NaN`, read as NaN).
//!
//! `--columns ROLE=NAME|NUMBER,...` chooses a role's column by header name (unit ignored) or
//! 1-based number; `--scale ROLE=FACTOR,...` multiplies a role's values as read ([`ReadOptions`]).
//! A role given twice, a column given two roles, a factor of 0 or not finite are refused.
//!
//! # Use
//!
//! [`Reader::new`] reads to the header; [`Reader::rows`] places the columns of a [`Spec`] and
//! streams the rows ([`Rows::next_row`]: a history larger than memory is read in constant
//! memory) or collects them ([`Rows::collect_table`]); [`read`] and [`read_file`] do both.
//!
//! ```
//! use lugre_io::{read, ReadOptions, Role, Spec};
//! let text = "# a lab file\nTime [s];Position [mm];Friction [uN];Note\n0;1.5;-2;a\n0.5;2.5;-3;b\n";
//! let options = ReadOptions::default().parse_scale("u=1e-3").unwrap();
//! let mut table = read(text.as_bytes(), &Spec::new([Role::U, Role::F]), options).unwrap();
//! assert_eq!(table.get(&Role::U).unwrap().info.unit.as_deref(), Some("mm"));
//! assert_eq!(table.take(&Role::T), Some(vec![0.0, 0.5]));
//! assert_eq!(table.take(&Role::U), Some(vec![1.5e-3, 2.5e-3]));
//! let e = read("u,u,F\n0,1,2\n".as_bytes(), &Spec::new([Role::U]), ReadOptions::default());
//! assert_eq!(
//!     e.unwrap_err().to_string(),
//!     "line 1: the header has two columns for u: 'u' (column 1) and 'u' (column 2); \
//!      say which with --columns u=NUMBER"
//! );
//! ```

mod error;
mod lines;
mod options;
mod reader;
mod role;
pub mod text;

pub use error::{Error, FileError};
pub use lines::{Delimiter, MAX_LINE};
pub use options::{Labels, ReadOptions, Selector};
pub use reader::{Column, ColumnInfo, Reader, Row, Rows, Spec, Table};
pub use role::{Field, Role};

use std::io::Read;
use std::path::Path;

/// Every row of `inner` that `spec` asks for (at least one).
pub fn read<R: Read>(inner: R, spec: &Spec, options: ReadOptions) -> Result<Table, Error> {
    Reader::new(inner, options)?.rows(spec)?.collect_table()
}

/// [`read`] of the file at `path`; errors name it.
pub fn read_file(path: &Path, spec: &Spec, options: ReadOptions) -> Result<Table, FileError> {
    Reader::open(path, options)?
        .rows(spec)
        .and_then(Rows::collect_table)
        .map_err(|e| e.in_file(path))
}
