//! Reading sampled data from CSV: the value columns a command wants (`u`, or `u,F` for
//! `lugre fit`), each row optionally led by a time `t`. Fields are separated by tabs,
//! semicolons, commas or runs of spaces, whichever the first line that is not a comment uses
//! ([`Delimiter`]). A header is optional; it names the columns in any order (case-insensitive,
//! a unit suffix in brackets or parentheses ignored: `Time [s]`), by their letters or their
//! usual names (`time`; `x`, `position`, `displacement`; `force`, `friction`). A UTF-8 byte-order mark, `#` comments, blank lines,
//! CRLF (or CR) line ends and spaces around values are accepted; a line longer than a megabyte
//! is refused. Every problem is reported with the file's line number.
//!
//! [`SampleReader`] streams the file one row at a time (a measured history may not fit in
//! memory); [`read_series`] and [`read_table`] collect it. All share the per-row parsing and
//! validation. With a column name (`lugre cycles --column NAME`), any header naming that column
//! is accepted, a column `t` is read as times, and other columns are ignored.
//!
//! [`NumberRows`] writes the rows of the CSV files the commands produce.

use anyhow::{bail, Context, Result};
use std::io::{Read, Write};
use std::path::Path;

use crate::fmt::{excerpt, num, quoted};

/// A sampled series: optional times (strictly increasing) and values, all finite.
#[derive(Debug, Clone)]
pub(crate) struct Series {
    pub(crate) t: Option<Vec<f64>>,
    pub(crate) u: Vec<f64>,
}

/// Every row of a file: optional times (strictly increasing) and each value column (all
/// finite), in the order of [`Columns`].
#[derive(Debug, Clone)]
pub(crate) struct Table {
    pub(crate) t: Option<Vec<f64>>,
    pub(crate) columns: Vec<Vec<f64>>,
}

/// Which columns a file holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Columns<'a> {
    /// `u` or `t,u`.
    Series,
    /// `u,F` or `t,u,F` (`lugre fit`).
    Record,
    /// `t,v,F`: a velocity record (`lugre fit`).
    VelocityRecord,
    /// [`Columns::Record`] and [`Columns::VelocityRecord`] with a normal force `N`.
    RecordN,
    VelocityRecordN,
    /// `t,u,N` and `t,v,N`: a sampled input with a normal force (`lugre simulate`; the columns
    /// are always named with `--columns`).
    SeriesN,
    VelocityN,
    /// The column of this name in any header (a file without a header has the columns `u` or
    /// `t,u`).
    Named(&'a str),
}

/// Where a role's column is: by its header name (units ignored) or its 1-based position.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Selector {
    Name(String),
    Index(usize),
}

/// What `--columns` and `--scale` say: the column of each role (`t`, `u`, `f`, ...), and a
/// factor for the values of each role as read (unit and sign conversions).
#[derive(Debug, Clone, Default, PartialEq)]
pub(crate) struct ReadOptions {
    pub(crate) select: Vec<(String, Selector)>,
    pub(crate) scale: Vec<(String, f64)>,
    /// A role whose value may be missing (an empty field or `NaN`): read as NaN (`lugre fit`'s
    /// input-only rows, where no force was measured).
    pub(crate) optional: Option<String>,
    /// `--delimiter`: instead of the one found from the first line.
    pub(crate) delimiter: Option<Delimiter>,
}

impl ReadOptions {
    fn selector(&self, role: &str) -> Option<&Selector> {
        self.select
            .iter()
            .find(|(r, _)| r.eq_ignore_ascii_case(role))
            .map(|(_, s)| s)
    }

    fn factor(&self, role: &str) -> f64 {
        self.scale
            .iter()
            .find(|(r, _)| r.eq_ignore_ascii_case(role))
            .map_or(1.0, |(_, f)| *f)
    }
}

impl Columns<'_> {
    /// The value columns' names (without a header, or in the order they are returned).
    fn names(self) -> &'static [&'static str] {
        match self {
            Columns::Series | Columns::Named(_) => &["u"],
            Columns::Record => &["u", "F"],
            Columns::VelocityRecord => &["v", "F"],
            Columns::RecordN => &["u", "F", "N"],
            Columns::VelocityRecordN => &["v", "F", "N"],
            Columns::SeriesN => &["u", "N"],
            Columns::VelocityN => &["v", "N"],
        }
    }
}

impl From<Table> for Series {
    /// The first value column (the only one of [`Columns::Series`] and [`Columns::Named`]).
    fn from(Table { t, columns }: Table) -> Self {
        Series {
            t,
            u: columns.into_iter().next().unwrap_or_default(),
        }
    }
}

pub(crate) fn read_series(path: &Path) -> Result<Series> {
    read_table(path, Columns::Series).map(Series::from)
}

/// Whether the header of `path` names a velocity column (`v`, `velocity`, units ignored) and
/// no displacement: a velocity record. False for a file that cannot be read (the reader then
/// says why).
pub(crate) fn is_velocity_record(path: &Path) -> bool {
    let roles = header_roles(path);
    roles.iter().any(|r| r == "v") && !roles.iter().any(|r| r == "u")
}

/// The roles of the header of `path` (none for a file that cannot be read or has no header:
/// the reader then says why).
fn header_roles(path: &Path) -> Vec<String> {
    let Ok(file) = std::fs::File::open(path) else {
        return Vec::new();
    };
    let mut head = Vec::new();
    if file.take(SNIFF as u64).read_to_end(&mut head).is_err() {
        return Vec::new();
    }
    let delimiter = Delimiter::of(&head);
    let text = String::from_utf8_lossy(&head);
    let Some(line) = text
        .lines()
        .map(str::trim)
        .find(|l| !l.is_empty() && !l.starts_with('#'))
    else {
        return Vec::new();
    };
    let split: Vec<&str> = match delimiter {
        Delimiter::Spaces => line.split_whitespace().collect(),
        d => line.split(char::from(d.byte())).collect(),
    };
    split.iter().map(|f| role(f)).collect()
}

/// Reads every row of `path` (at least one).
pub(crate) fn read_table(path: &Path, columns: Columns) -> Result<Table> {
    read_table_with(path, columns, ReadOptions::default())
}

/// [`read_table`] with `--columns` and `--scale`.
pub(crate) fn read_table_with(
    path: &Path,
    columns: Columns,
    options: ReadOptions,
) -> Result<Table> {
    collect(SampleReader::open(path, columns)?.with_options(options))
        .with_context(|| path.display().to_string())
}

fn collect<R: Read>(mut reader: SampleReader<'_, R>) -> Result<Table> {
    let mut t: Vec<f64> = Vec::new();
    let mut columns: Vec<Vec<f64>> = Vec::new();
    while let Some(row) = reader.next_row()? {
        if let Some(ts) = row.t {
            t.push(ts);
        }
        columns.resize_with(row.values.len(), Vec::new);
        for (column, &v) in columns.iter_mut().zip(row.values) {
            column.push(v);
        }
    }
    if columns.is_empty() {
        bail!("no data rows");
    }
    Ok(Table {
        t: reader.has_time().then_some(t),
        columns,
    })
}

/// One row of a single-value file: its time (if the file has times) and value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    pub t: Option<f64>,
    pub u: f64,
}

/// One row: its time (if the file has times) and values, in the order of [`Columns`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Row<'a> {
    pub t: Option<f64>,
    pub values: &'a [f64],
}

/// Where the values are, from the first row.
#[derive(Debug, Clone)]
struct Layout {
    width: usize,
    t: Option<usize>,
    /// The value columns' positions and names (for messages), in the order returned.
    values: Vec<(usize, String)>,
    /// The columns, for messages (`t,u`).
    header: String,
}

/// Streams the rows of a CSV file.
pub struct SampleReader<'c, R: Read> {
    reader: csv::Reader<Sniffed<LineLimit<SkipBom<R>>>>,
    delimiter: Delimiter,
    options: ReadOptions,
    /// The factor of `t` and of each value column (from `--scale`).
    factors: (f64, Vec<f64>),
    record: csv::ByteRecord,
    columns: Columns<'c>,
    layout: Option<Layout>,
    values: Vec<f64>,
    prev_t: Option<f64>,
    line: u64,
}

impl<'c> SampleReader<'c, std::fs::File> {
    /// Opens `path`; `columns` as in [`SampleReader::new`].
    pub fn open(path: &Path, columns: Columns<'c>) -> Result<Self> {
        let file = std::fs::File::open(path)
            .with_context(|| format!("cannot read '{}'", path.display()))?;
        Ok(Self::new(file, columns))
    }
}

impl<'c, R: Read> SampleReader<'c, R> {
    /// A reader of the `columns` of `inner`.
    pub fn new(inner: R, columns: Columns<'c>) -> Self {
        let (sniffed, delimiter) = Sniffed::new(LineLimit::new(SkipBom::new(inner)));
        let reader = csv_reader(sniffed, delimiter);
        Self {
            reader,
            delimiter,
            options: ReadOptions::default(),
            factors: (1.0, Vec::new()),
            record: csv::ByteRecord::new(),
            columns,
            layout: None,
            values: Vec::new(),
            prev_t: None,
            line: 0,
        }
    }

    /// The columns chosen by `--columns`, the factors of `--scale` and the delimiter of
    /// `--delimiter` (before any row is read).
    pub(crate) fn with_options(mut self, options: ReadOptions) -> Self {
        if let Some(delimiter) = options.delimiter {
            let mut sniffed = self.reader.into_inner();
            sniffed.spaces = delimiter == Delimiter::Spaces;
            self.reader = csv_reader(sniffed, delimiter);
            self.delimiter = delimiter;
        }
        self.options = options;
        self
    }

    /// Whether the rows have times (known once the first row is read).
    pub fn has_time(&self) -> bool {
        self.layout.as_ref().is_some_and(|l| l.t.is_some())
    }

    /// The line of the last row read.
    pub fn line(&self) -> u64 {
        self.line
    }

    /// The next row of a single-value file ([`Columns::Series`] or [`Columns::Named`]), or
    /// `None` at the end of the file.
    pub fn next_sample(&mut self) -> Result<Option<Sample>> {
        Ok(self.next_row()?.map(|row| Sample {
            t: row.t,
            u: row.values.first().copied().unwrap_or_default(),
        }))
    }

    /// The next row, or `None` at the end of the file.
    pub fn next_row(&mut self) -> Result<Option<Row<'_>>> {
        loop {
            let more = self.reader.read_byte_record(&mut self.record);
            self.line = self.record.position().map_or(0, |p| p.line());
            let line = self.line;
            match more {
                Ok(false) => return Ok(None),
                Ok(true) => {}
                Err(e) => bail!("line {line}: {e}"),
            }
            if self.record.iter().all(|f| f.is_empty()) {
                continue; // a blank line (or only separators)
            }
            if self.layout.is_none() {
                let fields = utf8_fields(&self.record, line)?;
                let (first, is_header) = layout(&fields, self.columns, &self.options, line)
                    .map_err(|e| {
                        anyhow::anyhow!("{e} (fields separated by {})", self.delimiter.describe())
                    })?;
                let factor_of = |name: &str| self.options.factor(&role(name));
                self.factors = (
                    self.options.factor("t"),
                    first.values.iter().map(|(_, n)| factor_of(n)).collect(),
                );
                self.layout = Some(first);
                if is_header {
                    continue;
                }
            }
            let Some(layout) = &self.layout else {
                continue; // set just above
            };
            if self.record.len() != layout.width {
                let w = layout.width;
                let values = if w == 1 { "value" } else { "values" };
                bail!(
                    "line {line}: expected {w} {values} ({}), found {} (fields separated by {})",
                    layout.header,
                    self.record.len(),
                    self.delimiter.describe()
                );
            }
            let t = match layout.t {
                Some(k) => {
                    let t = number(&self.record[k], "t", line)? * self.factors.0;
                    if let Some(prev) = self.prev_t {
                        if t <= prev {
                            bail!(
                                "line {line}: times must be strictly increasing, t = {} follows t = {}",
                                num(t),
                                num(prev)
                            );
                        }
                    }
                    self.prev_t = Some(t);
                    Some(t)
                }
                None => None,
            };
            self.values.clear();
            for ((k, name), factor) in layout.values.iter().zip(&self.factors.1) {
                let field = &self.record[*k];
                let missing = field.is_empty() || field.eq_ignore_ascii_case(b"nan");
                let optional = self.options.optional.as_deref() == Some(role(name).as_str());
                if missing && optional {
                    self.values.push(f64::NAN);
                    continue;
                }
                self.values.push(number(field, name, line)? * factor);
            }
            return Ok(Some(Row {
                t,
                values: &self.values,
            }));
        }
    }
}

fn csv_reader<R: Read>(inner: R, delimiter: Delimiter) -> csv::Reader<R> {
    csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .comment(Some(b'#'))
        .trim(csv::Trim::All)
        .delimiter(delimiter.byte())
        .buffer_capacity(1 << 16)
        .from_reader(inner)
}

fn utf8_fields(record: &csv::ByteRecord, line: u64) -> Result<Vec<&str>> {
    record
        .iter()
        .map(std::str::from_utf8)
        .collect::<Result<_, _>>()
        .map_err(|_| anyhow::anyhow!("line {line}: not valid UTF-8 text"))
}

/// The layout from the first row (a header, or numbers), and whether that row is a header.
fn layout(
    fields: &[&str],
    columns: Columns,
    options: &ReadOptions,
    line: u64,
) -> Result<(Layout, bool)> {
    let is_header = !fields.iter().all(|f| f.parse::<f64>().is_ok());
    if !options.select.is_empty() {
        return Ok((
            selected_layout(fields, columns, options, is_header, line)?,
            is_header,
        ));
    }
    if !is_header {
        return Ok((layout_without_header(fields.len(), columns, line)?, false));
    }
    let layout = match columns {
        Columns::Named(name) => named_column(fields, name, line)?,
        _ => header_layout(fields, columns, line)?,
    };
    Ok((layout, true))
}

/// The layout `--columns` gives: each role at its named or numbered column (the roles it does
/// not name where the header, or the order without one, puts them); other columns ignored.
fn selected_layout(
    fields: &[&str],
    columns: Columns,
    options: &ReadOptions,
    is_header: bool,
    line: u64,
) -> Result<Layout> {
    let header = fields.join(",");
    let bare: Vec<String> = fields.iter().map(|f| bare_name(f)).collect();
    let locate = |role_name: &str, required: bool| -> Result<Option<usize>> {
        match options.selector(role_name) {
            Some(Selector::Index(i)) => {
                if *i == 0 || *i > fields.len() {
                    bail!(
                        "line {line}: --columns {role_name}={i}: the file has {} columns (numbered from 1)",
                        fields.len()
                    );
                }
                Ok(Some(i - 1))
            }
            Some(Selector::Name(name)) => {
                if !is_header {
                    bail!("line {line}: --columns {role_name}={name}: the file has no header line (number the columns instead, from 1)");
                }
                let wanted = bare_name(name);
                match bare.iter().position(|b| *b == wanted) {
                    Some(k) => Ok(Some(k)),
                    None => bail!(
                        "line {line}: --columns {role_name}={name}: no such column in the header {}{}",
                        quoted(&header),
                        closest(name, fields)
                            .map(|c| format!(" (did you mean '{c}'?)"))
                            .unwrap_or_default()
                    ),
                }
            }
            None if is_header => {
                let k = fields.iter().position(|f| {
                    role(f).eq_ignore_ascii_case(role_name) || bare_name(f) == bare_name(role_name)
                });
                match (k, required) {
                    (None, true) => bail!(
                        "line {line}: no column for {role_name} in the header {}: name it with --columns {role_name}=NAME",
                        quoted(&header)
                    ),
                    (k, _) => Ok(k),
                }
            }
            None if required => bail!(
                "line {line}: the file has no header line: give every column's number with --columns"
            ),
            None => Ok(None),
        }
    };
    let t = locate("t", false)?;
    let roles: Vec<&str> = match columns {
        Columns::Named(name) => vec![name],
        _ => columns.names().to_vec(),
    };
    let mut values = Vec::new();
    for name in &roles {
        let k = locate(name, true)?.unwrap_or_default();
        values.push((k, name.to_string()));
    }
    let mut listed: Vec<&str> = t.map(|_| "t").into_iter().collect();
    listed.extend(&roles);
    Ok(Layout {
        width: fields.len(),
        t,
        values,
        header: if is_header {
            excerpt(&header)
        } else {
            listed.join(",")
        },
    })
}

/// The header field closest to `name` (by edit distance on the bare names), if any is close.
fn closest<'a>(name: &str, fields: &[&'a str]) -> Option<&'a str> {
    let wanted = bare_name(name);
    fields
        .iter()
        .map(|f| (edit_distance(&wanted, &bare_name(f)), *f))
        .filter(|(d, f)| *d <= (bare_name(f).len().max(wanted.len()) / 2).max(1))
        .min_by_key(|(d, _)| *d)
        .map(|(_, f)| f)
}

fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let next = (prev + usize::from(ca != *cb))
                .min(row[j] + 1)
                .min(row[j + 1] + 1);
            prev = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}

/// The layout of a file whose first row is numbers (`n` of them): the values in order, after
/// the time if there is one more column.
fn layout_without_header(n: usize, columns: Columns, line: u64) -> Result<Layout> {
    let wanted = columns.names();
    let listed = wanted.join(",");
    if let Columns::Named(name) = columns {
        if !name.eq_ignore_ascii_case("u") {
            bail!("line {line}: no header line, so no column '{name}' (a file without a header has the columns u or t,u)");
        }
    }
    let k = wanted.len();
    if n != k && n != k + 1 {
        let s = if k == 1 { "" } else { "s" };
        bail!(
            "line {line}: expected {k} column{s} ({listed}) or {} columns (t,{listed}), found {n}",
            k + 1
        );
    }
    let t = (n == k + 1).then_some(0);
    let first = usize::from(t.is_some());
    Ok(Layout {
        width: n,
        t,
        values: (first..)
            .zip(wanted)
            .map(|(k, name)| (k, name.to_string()))
            .collect(),
        header: if t.is_some() {
            format!("t,{listed}")
        } else {
            listed
        },
    })
}

/// A header field as a name: lower case, without a unit suffix in brackets or parentheses
/// (`Time [s]` and `time(s)` are `time`).
fn bare_name(field: &str) -> String {
    let mut name = field.trim();
    if let Some(stripped) = name.strip_suffix(']').or_else(|| name.strip_suffix(')')) {
        let open = if name.ends_with(']') { '[' } else { '(' };
        if let Some(k) = stripped.rfind(open) {
            name = stripped[..k].trim_end();
        }
    }
    name.to_lowercase()
}

/// The role a header name plays: the canonical column (`t`, `u`, `f`) for its usual names, or
/// the name itself.
fn role(field: &str) -> String {
    let name = bare_name(field);
    let canonical = match name.as_str() {
        "t" | "time" => "t",
        "u" | "x" | "position" | "displacement" => "u",
        "f" | "force" | "friction" => "f",
        "v" | "velocity" => "v",
        "n" | "normal" | "normal force" | "load" => "n",
        other => other,
    };
    canonical.to_string()
}

/// The layout of the column `name` in the header `fields` (and of `t`, if there is one).
fn named_column(fields: &[&str], name: &str, line: u64) -> Result<Layout> {
    let names: Vec<String> = fields.iter().map(|f| bare_name(f)).collect();
    let header = fields.join(",");
    let wanted = bare_name(name);
    let find = |n: &str| names.iter().position(|x| *x == n);
    // By its name; a velocity also by its usual name (`velocity` for `v`).
    let by_role = || {
        (wanted == "v")
            .then(|| fields.iter().position(|f| role(f) == "v"))
            .flatten()
    };
    let Some(u) = find(&wanted).or_else(by_role) else {
        bail!(
            "line {line}: no column '{name}' in the header {}",
            quoted(&header)
        );
    };
    if names.iter().filter(|x| **x == wanted).count() > 1 {
        bail!(
            "line {line}: the header {} names '{name}' more than once",
            quoted(&header)
        );
    }
    let t = fields
        .iter()
        .position(|f| role(f) == "t")
        .filter(|&k| k != u);
    Ok(Layout {
        width: fields.len(),
        t,
        values: vec![(u, fields[u].to_string())],
        header: excerpt(&header),
    })
}

/// The layout of a header naming exactly the value columns, and perhaps `t`, each once, in
/// any order.
fn header_layout(fields: &[&str], columns: Columns, line: u64) -> Result<Layout> {
    let wanted = columns.names();
    let listed = wanted.join(",");
    let names: Vec<String> = fields.iter().map(|f| role(f)).collect();
    let find = |n: &str| names.iter().position(|x| x.eq_ignore_ascii_case(n));
    let t = find("t");
    let values: Option<Vec<(usize, String)>> = wanted
        .iter()
        .map(|&name| find(name).map(|k| (k, name.to_string())))
        .collect();
    let distinct = {
        let mut sorted = names.clone();
        sorted.sort();
        sorted.dedup();
        sorted.len() == names.len()
    };
    match values {
        Some(values) if distinct && names.len() == wanted.len() + usize::from(t.is_some()) => {
            let header = if t.is_some() {
                format!("t,{listed}")
            } else {
                listed
            };
            Ok(Layout {
                width: names.len(),
                t,
                values,
                header,
            })
        }
        _ => bail!(
            "line {line}: unexpected header {}: expected '{listed}' or 't,{listed}'",
            quoted(&fields.join(","))
        ),
    }
}

fn number(field: &[u8], name: &str, line: u64) -> Result<f64> {
    let Ok(field) = std::str::from_utf8(field) else {
        bail!("line {line}: not valid UTF-8 text");
    };
    if field.is_empty() {
        bail!("line {line}: empty value for {name}");
    }
    match field.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(_) => bail!(
            "line {line}: {name} = {} is not a finite number",
            quoted(field)
        ),
        Err(_) => bail!("line {line}: {name} = {} is not a number", quoted(field)),
    }
}

/// The longest line accepted, in bytes. A row of numbers is a few dozen bytes; without a
/// limit, a file with no line breaks (a binary file, `/dev/zero`) would be read into memory
/// as one record until the memory runs out.
const MAX_LINE: usize = 1 << 20;

/// Fails the stream once a line grows longer than [`MAX_LINE`].
struct LineLimit<R> {
    inner: R,
    /// Bytes since the last line break.
    since_break: usize,
}

impl<R> LineLimit<R> {
    fn new(inner: R) -> Self {
        Self {
            inner,
            since_break: 0,
        }
    }
}

impl<R: Read> Read for LineLimit<R> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let n = self.inner.read(buf)?;
        // `\r` alone ends a line too (the CSV reader takes old Mac files).
        self.since_break = match buf[..n].iter().rposition(|&b| b == b'\n' || b == b'\r') {
            Some(k) => n - 1 - k,
            None => self.since_break + n,
        };
        if self.since_break > MAX_LINE {
            return Err(std::io::Error::new(
                std::io::ErrorKind::InvalidData,
                format!("a line is longer than {MAX_LINE} bytes (not a CSV file of numbers?)"),
            ));
        }
        Ok(n)
    }
}

/// How the fields of a line are separated, from the first data line (or header) of a file:
/// tabs if it has a tab, else semicolons if it has one, else commas if it has one, else runs
/// of spaces.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Delimiter {
    Comma,
    Semicolon,
    Tab,
    Spaces,
}

impl Delimiter {
    /// The byte the CSV reader splits on (runs of spaces are rewritten to commas first).
    fn byte(self) -> u8 {
        match self {
            Delimiter::Comma | Delimiter::Spaces => b',',
            Delimiter::Semicolon => b';',
            Delimiter::Tab => b'\t',
        }
    }

    fn describe(self) -> &'static str {
        match self {
            Delimiter::Comma => "commas",
            Delimiter::Semicolon => "semicolons",
            Delimiter::Tab => "tabs",
            Delimiter::Spaces => "spaces",
        }
    }

    /// From the first line that is neither blank nor a comment.
    fn of(head: &[u8]) -> Self {
        let line = head
            .split(|&b| b == b'\n' || b == b'\r')
            .map(|l| l.trim_ascii())
            .find(|l| !l.is_empty() && !l.starts_with(b"#"))
            .unwrap_or_default();
        if line.contains(&b'\t') {
            Delimiter::Tab
        } else if line.contains(&b';') {
            Delimiter::Semicolon
        } else if line.contains(&b',') || !line.contains(&b' ') {
            Delimiter::Comma
        } else {
            Delimiter::Spaces
        }
    }
}

/// How much of a file is read ahead to find its delimiter.
const SNIFF: usize = 1 << 16;

/// A stream whose head has been read to find the delimiter; with [`Delimiter::Spaces`], each
/// run of blanks inside a line becomes one comma and blanks at the ends of lines are dropped.
struct Sniffed<R> {
    inner: R,
    head: Vec<u8>,
    pos: usize,
    /// An error met while reading the head, handed out on the first read.
    error: Option<std::io::Error>,
    spaces: bool,
    /// In spaces mode: at the start of a line, and whether a run of blanks awaits its comma.
    line_start: bool,
    pending: bool,
}

impl<R: Read> Sniffed<R> {
    fn new(mut inner: R) -> (Self, Delimiter) {
        let mut head = vec![0; SNIFF];
        let mut len = 0;
        let mut error = None;
        while len < SNIFF {
            match inner.read(&mut head[len..]) {
                Ok(0) => break,
                Ok(n) => len += n,
                Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
                Err(e) => {
                    error = Some(e);
                    break;
                }
            }
        }
        head.truncate(len);
        let delimiter = Delimiter::of(&head);
        let sniffed = Self {
            inner,
            head,
            pos: 0,
            error,
            spaces: delimiter == Delimiter::Spaces,
            line_start: true,
            pending: false,
        };
        (sniffed, delimiter)
    }

    /// Rewrites `buf[..n]` in place (never longer: one comma stands for a run of blanks).
    fn collapse(&mut self, buf: &mut [u8], n: usize) -> usize {
        let mut out = 0;
        for k in 0..n {
            let b = buf[k];
            match b {
                b'\n' | b'\r' => {
                    (self.line_start, self.pending) = (true, false);
                    buf[out] = b;
                    out += 1;
                }
                b' ' | b'\t' => self.pending |= !self.line_start,
                _ => {
                    if self.pending {
                        buf[out] = b',';
                        out += 1;
                        self.pending = false;
                    }
                    self.line_start = false;
                    buf[out] = b;
                    out += 1;
                }
            }
        }
        out
    }
}

impl<R: Read> Read for Sniffed<R> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        loop {
            let n = if self.pos < self.head.len() {
                let n = (self.head.len() - self.pos).min(buf.len());
                buf[..n].copy_from_slice(&self.head[self.pos..self.pos + n]);
                self.pos += n;
                n
            } else if let Some(e) = self.error.take() {
                return Err(e);
            } else {
                self.inner.read(buf)?
            };
            if !self.spaces || n == 0 {
                return Ok(n);
            }
            let kept = self.collapse(buf, n);
            // A chunk of blanks only yields nothing: read on rather than signal the end.
            if kept > 0 {
                return Ok(kept);
            }
        }
    }
}

/// Drops a UTF-8 byte-order mark at the start of a stream.
struct SkipBom<R> {
    inner: R,
    /// Bytes read ahead to look for the mark and not yet handed out.
    head: [u8; 3],
    head_len: usize,
    started: bool,
}

impl<R: Read> SkipBom<R> {
    fn new(inner: R) -> Self {
        Self {
            inner,
            head: [0; 3],
            head_len: 0,
            started: false,
        }
    }
}

impl<R: Read> Read for SkipBom<R> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        if !self.started {
            self.started = true;
            while self.head_len < 3 {
                let n = self.inner.read(&mut self.head[self.head_len..])?;
                if n == 0 {
                    break;
                }
                self.head_len += n;
            }
            if self.head[..self.head_len] == *b"\xEF\xBB\xBF" {
                self.head_len = 0;
            }
        }
        if self.head_len > 0 {
            let n = self.head_len.min(buf.len());
            buf[..n].copy_from_slice(&self.head[..n]);
            self.head.copy_within(n..self.head_len, 0);
            self.head_len -= n;
            return Ok(n);
        }
        self.inner.read(buf)
    }
}

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

#[cfg(test)]
mod tests {
    use super::*;

    fn parse_series(bytes: &[u8]) -> Result<Series> {
        collect(SampleReader::new(bytes, Columns::Series)).map(Series::from)
    }

    /// Lab files: tabs, semicolons or runs of spaces between fields, headers with units and
    /// the usual names.
    #[test]
    fn finds_the_delimiter_and_reads_headers_with_units() {
        let tab = b"Time [s]\tPosition [mm]\tFriction [uN]\n0\t1.5\t-2\n0.5\t2.5\t-3\n";
        let t = parse_record(tab).unwrap();
        assert_eq!(t.t.unwrap(), vec![0.0, 0.5]);
        assert_eq!(t.columns, vec![vec![1.5, 2.5], vec![-2.0, -3.0]]);
        let semi = b"# a comment; with a semicolon\ntime(s);x;force\n0;1;2\n1;3;4\n";
        assert_eq!(parse_record(semi).unwrap().columns[1], vec![2.0, 4.0]);
        let spaces = b"  t   u    F\n 0  1   2  \n\n1 3 4\n";
        let t = parse_record(spaces).unwrap();
        assert_eq!(
            (t.t.unwrap(), t.columns),
            (vec![0.0, 1.0], vec![vec![1.0, 3.0], vec![2.0, 4.0]])
        );
        // Numbers only, space-separated: t,u.
        let s = parse_series(b"0 1\n1 2\n").unwrap();
        assert_eq!((s.t.unwrap(), s.u), (vec![0.0, 1.0], vec![1.0, 2.0]));
        // A named column matches its unit-suffixed header.
        let mut r = SampleReader::new(
            &b"Time [s]\tPosition [mm]\n0\t5\n"[..],
            Columns::Named("position"),
        );
        assert_eq!(
            r.next_sample().unwrap().unwrap(),
            Sample {
                t: Some(0.0),
                u: 5.0
            }
        );
        // Messages say how the fields were split.
        let e = parse_record(b"t\tu\tF\n0\t1\n").unwrap_err().to_string();
        assert_eq!(
            e,
            "line 2: expected 3 values (t,u,F), found 2 (fields separated by tabs)"
        );
        let e = parse_record(b"Time;Value\n0;1\n").unwrap_err().to_string();
        assert!(e.ends_with("(fields separated by semicolons)"), "{e}");
        // --delimiter overrides what the first line suggests.
        let forced = |bytes: &'static [u8], d: Delimiter| {
            let options = ReadOptions {
                delimiter: Some(d),
                ..ReadOptions::default()
            };
            collect(SampleReader::new(bytes, Columns::Record).with_options(options))
        };
        let t = forced(b"t u F\n0 1 2\n", Delimiter::Spaces).unwrap();
        assert_eq!(t.columns, vec![vec![1.0], vec![2.0]]);
        let e = forced(b"t\tu\tF\n0\t1\t2\n", Delimiter::Comma)
            .unwrap_err()
            .to_string();
        assert!(e.ends_with("(fields separated by commas)"), "{e}");
    }

    #[test]
    fn accepts_the_usual_shapes() {
        let s = parse_series(b"\xEF\xBB\xBFt,u\r\n# comment\r\n0, 0\r\n1,1\r\n\r\n2,0.5\r\n\n")
            .unwrap();
        assert_eq!(s.t.unwrap(), vec![0.0, 1.0, 2.0]);
        assert_eq!(s.u, vec![0.0, 1.0, 0.5]);
        let s = parse_series(b"u\n1\n-2\n").unwrap();
        assert!(s.t.is_none());
        assert_eq!(s.u, vec![1.0, -2.0]);
        let s = parse_series(b"0,1\n1,2\n").unwrap();
        assert_eq!(s.u, vec![1.0, 2.0]);
        // A mark alone, or a file shorter than one.
        assert!(parse_series(b"\xEF\xBB\xBF").is_err());
        assert_eq!(parse_series(b"7").unwrap().u, vec![7.0]);
    }

    #[test]
    fn a_file_without_line_breaks_is_refused_early() {
        // As /dev/zero would be, without reading it all into one record.
        let zeros = std::io::repeat(0).take(64 * MAX_LINE as u64);
        let mut r = SampleReader::new(zeros, Columns::Series);
        let e = r.next_sample().unwrap_err().to_string();
        assert!(e.contains("a line is longer than 1048576 bytes"), "{e}");
        // A long line just under the limit is read.
        let mut text = vec![b' '; MAX_LINE - 10];
        text.extend_from_slice(b"1\n2\n");
        assert_eq!(parse_series(&text).unwrap().u, vec![1.0, 2.0]);
        // Lines ended by CR alone are lines: a long file of them is read.
        let text = "0.5\r".repeat(MAX_LINE);
        assert_eq!(parse_series(text.as_bytes()).unwrap().u.len(), MAX_LINE);
    }

    #[test]
    fn names_the_line() {
        let cases: [(&[u8], &str); 8] = [
            (b"t,u\n0,1\n1\n", "line 3: expected 2 values"),
            (b"t,u\n0,1\n1,2,3\n", "line 3: expected 2 values"),
            (b"x,y\n0,1\n", "line 1: unexpected header"),
            (
                b"t,u\n0,1\n0,2\n",
                "line 3: times must be strictly increasing",
            ),
            (b"t,u\n0,nan\n", "line 2: u = 'nan' is not a finite number"),
            (b"t,u\n0,abc\n", "line 2: u = 'abc' is not a number"),
            (b"t,u\n0,\xff\n", "line 2: not valid UTF-8"),
            (b"t,u\n", "no data rows"),
        ];
        for (input, want) in cases {
            let e = parse_series(input).unwrap_err().to_string();
            assert!(e.contains(want), "{e} (wanted {want})");
        }
    }

    fn parse_record(bytes: &[u8]) -> Result<Table> {
        collect(SampleReader::new(bytes, Columns::Record))
    }

    #[test]
    fn records_in_the_usual_shapes() {
        let r = parse_record(b"\xEF\xBB\xBFu,F\r\n# c\r\n0,1\r\n\r\n1, 2\r\n").unwrap();
        assert!(r.t.is_none());
        assert_eq!(r.columns, vec![vec![0.0, 1.0], vec![1.0, 2.0]]);
        let r = parse_record(b"0,1,2\n1,2,3\n").unwrap();
        assert_eq!(r.t.unwrap(), vec![0.0, 1.0]);
        assert_eq!(r.columns, vec![vec![1.0, 2.0], vec![2.0, 3.0]]);
        // Named columns in any order, any case.
        let r = parse_record(b"F,t,U\n5,0,1\n6,1,2\n").unwrap();
        assert_eq!(r.t.unwrap(), vec![0.0, 1.0]);
        assert_eq!(r.columns, vec![vec![1.0, 2.0], vec![5.0, 6.0]]);
        let r = parse_record(b"f,u\n5,1\n").unwrap();
        assert_eq!((r.t, r.columns), (None, vec![vec![1.0], vec![5.0]]));
        // A series header in any order too.
        let s = parse_series(b"u,t\n5,0\n6,1\n").unwrap();
        assert_eq!((s.t.unwrap(), s.u), (vec![0.0, 1.0], vec![5.0, 6.0]));
    }

    #[test]
    fn record_errors_name_the_line() {
        let cases: [(&[u8], &str); 14] = [
            (b"u,F\n0,1\n1\n", "line 3: expected 2 values (u,F), found 1"),
            (
                b"F,t,u\n0,1,2\n1,2\n",
                "line 3: expected 3 values (t,u,F), found 2",
            ),
            (
                b"x,y\n0,1\n",
                "line 1: unexpected header 'x,y': expected 'u,F' or 't,u,F'",
            ),
            (b"u,F,F\n0,1,2\n", "line 1: unexpected header 'u,F,F'"),
            (b"u,F,x\n0,1,2\n", "line 1: unexpected header 'u,F,x'"),
            (b"t,u,F,t\n0,1,2,3\n", "line 1: unexpected header"),
            (b"u\n0\n", "line 1: unexpected header 'u'"),
            (
                b"t,u,F\n0,1,2\n0,1,2\n",
                "line 3: times must be strictly increasing, t = 0 follows t = 0",
            ),
            // Times as the shortest text that reads back, never hundreds of digits.
            (
                b"t,u,F\n1e300,1,2\n1e299,1,2\n",
                "line 3: times must be strictly increasing, t = 1e299 follows t = 1e300",
            ),
            (b"u,F\n0,nan\n", "line 2: F = 'nan' is not a finite number"),
            (b"u,F\n0,abc\n", "line 2: F = 'abc' is not a number"),
            (
                b"1,2,3,4\n",
                "line 1: expected 2 columns (u,F) or 3 columns (t,u,F), found 4",
            ),
            (
                b"1\n",
                "line 1: expected 2 columns (u,F) or 3 columns (t,u,F), found 1",
            ),
            (b"u,F\n", "no data rows"),
        ];
        for (input, want) in cases {
            let e = match parse_record(input) {
                Ok(_) => panic!("{want}: accepted"),
                Err(e) => e.to_string(),
            };
            assert!(e.contains(want), "{e} (wanted {want})");
        }
        let e = parse_series(b"1,2,3\n").unwrap_err().to_string();
        assert!(
            e.contains("line 1: expected 1 column (u) or 2 columns (t,u), found 3"),
            "{e}"
        );
        let e = parse_series(b"t,u,u\n").unwrap_err().to_string();
        assert!(
            e.contains("line 1: unexpected header 't,u,u': expected 'u' or 't,u'"),
            "{e}"
        );
    }

    fn named(bytes: &[u8], column: &str) -> Result<Vec<Sample>> {
        let mut r = SampleReader::new(bytes, Columns::Named(column));
        let mut out = Vec::new();
        while let Some(s) = r.next_sample()? {
            out.push(s);
        }
        Ok(out)
    }

    #[test]
    fn a_named_column() {
        let rows = named(b"t,force,U\n0,9,1\n1,x,2\n", "u").unwrap();
        assert_eq!(
            rows,
            vec![
                Sample {
                    t: Some(0.0),
                    u: 1.0
                },
                Sample {
                    t: Some(1.0),
                    u: 2.0
                }
            ]
        );
        assert_eq!(named(b"x\n3\n", "x").unwrap()[0].t, None);
        assert_eq!(named(b"1\n2\n", "u").unwrap().len(), 2);
        for (input, column, want) in [
            (
                &b"t,u\n0,1\n"[..],
                "x",
                "line 1: no column 'x' in the header 't,u'",
            ),
            (b"1,2\n", "x", "line 1: no header line, so no column 'x'"),
            (b"u,u\n1,2\n", "u", "names 'u' more than once"),
            (
                b"t,x\n0,1\n1\n",
                "x",
                "line 3: expected 2 values (t,x), found 1",
            ),
            (
                b"t,x\n0,1\n0,2\n",
                "x",
                "line 3: times must be strictly increasing",
            ),
            (
                b"t,x\n0,inf\n",
                "x",
                "line 2: x = 'inf' is not a finite number",
            ),
        ] {
            let e = named(input, column).unwrap_err().to_string();
            assert!(e.contains(want), "{e} (wanted {want})");
        }
    }
}
