//! The reader: [`Reader::new`] reads up to the header (or the first row of a file without one)
//! and finds the delimiter; [`Reader::rows`] places the columns a [`Spec`] asks for and streams
//! the rows ([`Rows::next_row`]), or collects them ([`Rows::collect_table`]).

use std::fs::File;
use std::io::{BufReader, Read};
use std::ops::Range;
use std::path::Path;

use crate::lines::{is_comment_or_blank, split, split_into, Lines};
use crate::role::Field;
use crate::text::{closest, excerpt, quoted};
use crate::{Delimiter, Error, FileError, ReadOptions, Role, Selector};

/// What a command reads: value columns it needs (in the order it gets them), value columns it
/// reads when the file has them, and the time `t` (read when the file has it, or required).
#[derive(Debug, Clone, PartialEq)]
pub struct Spec {
    values: Vec<Role>,
    optional: Vec<Role>,
    time_required: bool,
    missing: Vec<Role>,
    positive: Vec<Role>,
}

impl Spec {
    /// The value columns a command needs, in the order it gets them; `t` is read when the file
    /// has it. A file without a header holds exactly these, after `t` if it has one more
    /// column.
    pub fn new(values: impl IntoIterator<Item = Role>) -> Spec {
        Spec {
            values: values.into_iter().collect(),
            optional: Vec::new(),
            time_required: false,
            missing: Vec::new(),
            positive: Vec::new(),
        }
    }

    /// Also `role`, after the needed ones, where the header has it or the options name it.
    pub fn optional(mut self, role: Role) -> Spec {
        self.optional.push(role);
        self
    }

    /// The file must have times.
    pub fn require_time(mut self) -> Spec {
        self.time_required = true;
        self
    }

    /// A value of `role` may be missing (an empty field or `NaN`): read as NaN.
    pub fn allow_missing(mut self, role: Role) -> Spec {
        self.missing.push(role);
        self
    }

    /// Every value of `role` must be > 0 (a normal force).
    pub fn positive(mut self, role: Role) -> Spec {
        self.positive.push(role);
        self
    }

    /// Every role read: `t`, then the values, then the optional ones.
    fn roles(&self) -> Vec<Role> {
        std::iter::once(Role::T)
            .chain(self.values.iter().cloned())
            .chain(self.optional.iter().cloned())
            .collect()
    }
}

/// A column as the file names it.
#[derive(Debug, Clone, PartialEq)]
pub struct ColumnInfo {
    pub role: Role,
    /// The header field as written (`Position [mm]`); none in a file without a header.
    pub name: Option<String>,
    /// The unit in the header (`mm`), if it gives one. Values are as read, times `--scale`.
    pub unit: Option<String>,
    /// Its position in a row, from 0.
    pub index: usize,
}

/// A column and every value read from it.
#[derive(Debug, Clone, PartialEq)]
pub struct Column {
    pub info: ColumnInfo,
    pub values: Vec<f64>,
}

/// Every row of a file: the times, if read, and the value columns in the [`Spec`]'s order
/// (the needed ones, then the optional ones the file has).
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    pub t: Option<Column>,
    pub columns: Vec<Column>,
}

impl Table {
    /// The column of `role`, if read.
    pub fn get(&self, role: &Role) -> Option<&Column> {
        std::iter::once(&self.t)
            .flatten()
            .chain(&self.columns)
            .find(|c| c.info.role == *role)
    }

    /// The values of `role`, if read.
    pub fn take(&mut self, role: &Role) -> Option<Vec<f64>> {
        if *role == Role::T {
            return self.t.take().map(|c| c.values);
        }
        let k = self.columns.iter().position(|c| c.info.role == *role)?;
        Some(self.columns.remove(k).values)
    }
}

/// One row: its time (if times are read) and its values, in the order of [`Rows::columns`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Row<'a> {
    pub t: Option<f64>,
    pub values: &'a [f64],
}

/// The header line: its number and fields.
#[derive(Debug, Clone)]
struct Header {
    line: u64,
    fields: Vec<Field>,
}

impl Header {
    /// The header as written, for messages (quoted, cut short).
    fn quoted(&self) -> String {
        quoted(&self.joined())
    }

    fn joined(&self) -> String {
        let texts: Vec<&str> = self.fields.iter().map(|f| f.text.as_str()).collect();
        texts.join(",")
    }
}

/// A file, read up to its header or its first row.
pub struct Reader<R> {
    lines: Lines<BufReader<R>>,
    options: ReadOptions,
    delimiter: Delimiter,
    header: Option<Header>,
    /// The first row of a file without a header: its line, text and number of fields.
    first_row: Option<(u64, Vec<u8>, usize)>,
}

impl Reader<File> {
    /// Opens `path`; as [`Reader::new`].
    pub fn open(path: &Path, options: ReadOptions) -> Result<Self, FileError> {
        let file = File::open(path).map_err(|source| Error::Open { source }.in_file(path))?;
        Reader::new(file, options).map_err(|e| e.in_file(path))
    }
}

impl<R: Read> Reader<R> {
    /// Reads `inner` up to its first line that is neither blank nor a `#` comment: a header
    /// if any of its fields is not a number, else the first row. The delimiter is found from
    /// that line unless the options give it.
    pub fn new(inner: R, options: ReadOptions) -> Result<Self, Error> {
        let mut lines = Lines::new(BufReader::with_capacity(1 << 16, inner));
        let mut delimiter = options.delimiter().unwrap_or(Delimiter::Comma);
        let (mut header, mut first_row) = (None, None);
        while let Some((line, text)) = lines.next_line()? {
            if is_comment_or_blank(text) {
                continue;
            }
            delimiter = options.delimiter().unwrap_or_else(|| Delimiter::of(text));
            let fields = split(text, delimiter);
            if fields.iter().all(|f| f.is_empty()) {
                continue; // only separators
            }
            let fields: Vec<&str> = fields
                .into_iter()
                .map(std::str::from_utf8)
                .collect::<Result<_, _>>()
                .map_err(|_| Error::Utf8 { line })?;
            if fields
                .iter()
                .any(|f| !f.is_empty() && f.parse::<f64>().is_err())
            {
                header = Some(Header {
                    line,
                    fields: fields.into_iter().map(Field::parse).collect(),
                });
            } else {
                first_row = Some((line, text.to_vec(), fields.len()));
            }
            break;
        }
        Ok(Reader {
            lines,
            options,
            delimiter,
            header,
            first_row,
        })
    }

    /// The header's fields (none for a file without a header, or without any row).
    pub fn header(&self) -> Option<&[Field]> {
        self.header.as_ref().map(|h| h.fields.as_slice())
    }

    /// The number of fields of the header, or of the first row of a file without one (0 for
    /// a file without either).
    pub fn width(&self) -> usize {
        match (&self.header, &self.first_row) {
            (Some(h), _) => h.fields.len(),
            (None, Some((_, _, width))) => *width,
            (None, None) => 0,
        }
    }

    /// The delimiter found (or given).
    pub fn delimiter(&self) -> Delimiter {
        self.delimiter
    }

    /// Whether the header has a column of `role`.
    pub fn header_has(&self, role: &Role) -> bool {
        self.header()
            .is_some_and(|h| h.iter().any(|f| f.role == *role))
    }

    /// The motion a record holds: [`Role::V`] (a velocity record) where the options choose a
    /// `v` column, or the header has `v` and no `u` and the options choose no `u`; else
    /// [`Role::U`].
    pub fn motion(&self) -> Role {
        let o = &self.options;
        let velocity = o.selects(&Role::V)
            || (!o.selects(&Role::U) && self.header_has(&Role::V) && !self.header_has(&Role::U));
        if velocity {
            Role::V
        } else {
            Role::U
        }
    }

    /// Places the columns `spec` asks for and returns the rows. Refused: a role of the options
    /// that `spec` does not read, a column it needs that the file does not have, a role two
    /// header columns hold (unless the options say which), one column in two roles.
    pub fn rows(self, spec: &Spec) -> Result<Rows<R>, Error> {
        self.options.check_roles(&spec.roles())?;
        let layout = match (&self.header, &self.first_row) {
            (None, None) => None,
            (header, first) => {
                let line = match (header, first) {
                    (Some(h), _) => h.line,
                    (None, Some((line, _, _))) => *line,
                    (None, None) => unreachable!("matched above"),
                };
                let width = self.width();
                let locator = Locator {
                    header: header.as_ref(),
                    width,
                    line,
                    options: &self.options,
                    delimiter: self.delimiter,
                };
                Some(locator.layout(spec)?)
            }
        };
        Ok(Rows {
            lines: self.lines,
            delimiter: self.delimiter,
            layout,
            pending: self.first_row.map(|(line, text, _)| (line, text)),
            parser: Parser {
                ranges: Vec::new(),
                values: Vec::new(),
                t: None,
                prev_t: None,
                scale: self.options.labels().scale,
            },
            line: 0,
        })
    }
}

/// Where a column is and how its values are read.
#[derive(Debug, Clone)]
struct Slot {
    info: ColumnInfo,
    /// How messages name it: its header field, or its role in a file without a header.
    label: String,
    factor: f64,
    missing_ok: bool,
    positive: bool,
}

/// Where the columns read are.
#[derive(Debug, Clone)]
struct Layout {
    width: usize,
    /// The columns, for messages: the header as written, or the roles read ("t,u").
    listing: String,
    t: Option<Slot>,
    values: Vec<Slot>,
}

/// Finds the columns from the header (or the first row's width) and the options.
struct Locator<'a> {
    header: Option<&'a Header>,
    width: usize,
    /// The header's line, or the first row's.
    line: u64,
    options: &'a ReadOptions,
    delimiter: Delimiter,
}

impl Locator<'_> {
    fn layout(&self, spec: &Spec) -> Result<Layout, Error> {
        let (t, values) = if self.header.is_none() && !self.options.selects_any() {
            self.by_position(spec)?
        } else {
            let t = self.locate(&Role::T, spec.time_required)?;
            let mut values = Vec::new();
            for role in &spec.values {
                if let Some(k) = self.locate(role, true)? {
                    values.push((role.clone(), k));
                }
            }
            for role in &spec.optional {
                if let Some(k) = self.locate(role, false)? {
                    values.push((role.clone(), k));
                }
            }
            (t, values)
        };
        let mut placed: Vec<(Role, usize)> = t.map(|k| (Role::T, k)).into_iter().collect();
        placed.extend(values.iter().cloned());
        self.check_one_role_per_column(&placed)?;
        let slot = |role: &Role, index: usize| self.slot(spec, role, index);
        let listing = match self.header {
            Some(h) => excerpt(&h.joined()),
            None => {
                let mut by_index = placed.clone();
                by_index.sort_by_key(|(_, k)| *k);
                let names: Vec<&str> = by_index.iter().map(|(r, _)| r.name()).collect();
                names.join(",")
            }
        };
        Ok(Layout {
            width: self.width,
            listing,
            t: t.map(|k| slot(&Role::T, k)),
            values: values.iter().map(|(r, k)| slot(r, *k)).collect(),
        })
    }

    fn slot(&self, spec: &Spec, role: &Role, index: usize) -> Slot {
        let field = self.header.map(|h| &h.fields[index]);
        Slot {
            info: ColumnInfo {
                role: role.clone(),
                name: field.map(|f| f.text.clone()),
                unit: field.and_then(|f| f.unit.clone()),
                index,
            },
            label: field.map_or_else(|| role.name().to_string(), |f| f.text.clone()),
            factor: self.options.factor(role),
            missing_ok: spec.missing.contains(role),
            positive: spec.positive.contains(role),
        }
    }

    /// A file without a header and without `--columns`: the needed columns in order, after
    /// `t` if there is one more.
    #[allow(clippy::type_complexity)]
    fn by_position(&self, spec: &Spec) -> Result<(Option<usize>, Vec<(Role, usize)>), Error> {
        let listed: Vec<&str> = spec.values.iter().map(Role::name).collect();
        let listed = listed.join(",");
        let k = spec.values.len();
        if let Some(named) = spec.values.iter().find(|r| matches!(r, Role::Named(_))) {
            return Err(Error::NoHeaderNamed {
                line: self.line,
                role: named.to_string(),
                columns: "u or t,u".into(),
            });
        }
        let first = if self.width == k + 1 {
            1
        } else if self.width == k && !spec.time_required {
            0
        } else {
            let with_t = format!("{} columns (t,{listed})", k + 1);
            return Err(Error::FirstRowWidth {
                line: self.line,
                expected: if spec.time_required {
                    with_t
                } else {
                    let s = if k == 1 { "" } else { "s" };
                    format!("{k} column{s} ({listed}) or {with_t}")
                },
                found: self.width,
                delimiter: self.delimiter,
            });
        };
        let values = spec.values.iter().cloned().zip(first..).collect();
        Ok(((first == 1).then_some(0), values))
    }

    /// The column of `role`: as the options choose it, else the header's column of that role.
    fn locate(&self, role: &Role, required: bool) -> Result<Option<usize>, Error> {
        let labels = self.options.labels();
        let option = labels.columns;
        let line = self.line;
        match (self.options.selector(role), self.header) {
            (Some(Selector::Index(i)), _) => {
                if *i > self.width {
                    return Err(Error::IndexOutOfRange {
                        line,
                        option,
                        role: role.name().into(),
                        index: *i,
                        width: self.width,
                    });
                }
                Ok(Some(i - 1))
            }
            (Some(Selector::Name(name)), None) => Err(Error::NameWithoutHeader {
                line,
                option,
                role: role.name().into(),
                name: name.clone(),
            }),
            (Some(Selector::Name(name)), Some(h)) => {
                let wanted = crate::role::split_unit(name).0.to_lowercase();
                let matching: Vec<usize> = (0..h.fields.len())
                    .filter(|&k| h.fields[k].bare() == wanted)
                    .collect();
                match matching[..] {
                    [k] => Ok(Some(k)),
                    [] => Err(Error::NoSuchName {
                        line,
                        option,
                        item: format!("{}={name}", role.name()),
                        header: h.quoted(),
                        closest: self.closest(&wanted),
                        delimiter: self.delimiter,
                    }),
                    _ => Err(Error::NameTwice {
                        line,
                        option,
                        role: role.name().into(),
                        name: name.clone(),
                        header: h.quoted(),
                    }),
                }
            }
            (None, Some(h)) => {
                let matching: Vec<usize> = (0..h.fields.len())
                    .filter(|&k| h.fields[k].role == *role)
                    .collect();
                match matching[..] {
                    [k] => Ok(Some(k)),
                    [] if !required => Ok(None),
                    [] => Err(Error::MissingColumn {
                        line,
                        role: role.clone(),
                        header: h.quoted(),
                        closest: match role {
                            Role::Named(name) => self.closest(&name.to_lowercase()),
                            _ => None,
                        },
                        delimiter: self.delimiter,
                        option,
                    }),
                    [a, b, ..] => Err(Error::DuplicateColumn {
                        line,
                        role: role.name().into(),
                        first: h.fields[a].text.clone(),
                        first_index: a + 1,
                        second: h.fields[b].text.clone(),
                        second_index: b + 1,
                        option,
                    }),
                }
            }
            (None, None) if required => Err(Error::NoHeaderSelect { line, option }),
            (None, None) => Ok(None),
        }
    }

    /// The header field closest to `wanted` (a bare name), as written.
    fn closest(&self, wanted: &str) -> Option<String> {
        let h = self.header?;
        let bare: Vec<String> = h.fields.iter().map(Field::bare).collect();
        let names: Vec<&str> = bare.iter().map(String::as_str).collect();
        let found = closest(wanted, &names)?;
        let k = names.iter().position(|n| *n == found)?;
        Some(h.fields[k].text.clone())
    }

    /// Refuses a column placed in two roles; two the options chose are named first (the
    /// user's own contradiction), then one chosen and one found by its header name.
    fn check_one_role_per_column(&self, placed: &[(Role, usize)]) -> Result<(), Error> {
        let chosen = |r: &Role| usize::from(self.options.selects(r));
        let mut pairs: Vec<(&Role, &Role, usize)> = Vec::new();
        for (i, (first, k)) in placed.iter().enumerate() {
            for (second, j) in &placed[i + 1..] {
                if j == k {
                    pairs.push((first, second, *k));
                }
            }
        }
        pairs.sort_by_key(|(a, b, _)| 2 - chosen(a) - chosen(b));
        match pairs.first() {
            Some((first, second, k)) => Err(Error::ColumnInTwoRoles {
                line: self.line,
                column: k + 1,
                name: self.header.map(|h| h.fields[*k].text.clone()),
                first: first.name().into(),
                second: second.name().into(),
                option: self.options.labels().columns,
            }),
            None => Ok(()),
        }
    }
}

/// The rows of a file, streamed.
pub struct Rows<R> {
    lines: Lines<BufReader<R>>,
    delimiter: Delimiter,
    /// None for a file without any row (nor header).
    layout: Option<Layout>,
    /// The first row of a file without a header, read by [`Reader::new`].
    pending: Option<(u64, Vec<u8>)>,
    parser: Parser,
    line: u64,
}

impl<R: Read> Rows<R> {
    /// The value columns, in the order of [`Row::values`].
    pub fn columns(&self) -> Vec<ColumnInfo> {
        self.layout
            .iter()
            .flat_map(|l| &l.values)
            .map(|s| s.info.clone())
            .collect()
    }

    /// The time column, if read.
    pub fn time(&self) -> Option<&ColumnInfo> {
        self.layout.as_ref()?.t.as_ref().map(|s| &s.info)
    }

    /// The line of the last row read.
    pub fn line(&self) -> u64 {
        self.line
    }

    /// The next row, or `None` at the end of the file. Blank lines, lines of separators only
    /// and `#` comments are skipped.
    pub fn next_row(&mut self) -> Result<Option<Row<'_>>, Error> {
        let Some(layout) = &self.layout else {
            return Ok(None);
        };
        if let Some((line, text)) = self.pending.take() {
            self.line = line;
            self.parser.parse(layout, &text, self.delimiter, line)?;
            return Ok(Some(self.parser.row()));
        }
        while let Some((line, text)) = self.lines.next_line()? {
            self.line = line;
            if is_comment_or_blank(text) {
                continue;
            }
            if self.parser.parse(layout, text, self.delimiter, line)? {
                return Ok(Some(self.parser.row()));
            }
        }
        Ok(None)
    }

    /// Every row (at least one).
    pub fn collect_table(mut self) -> Result<Table, Error> {
        let n = self.layout.as_ref().map_or(0, |l| l.values.len());
        let (mut t, mut values, mut rows) = (Vec::new(), vec![Vec::new(); n], 0usize);
        while let Some(row) = self.next_row()? {
            rows += 1;
            t.extend(row.t);
            for (column, &v) in values.iter_mut().zip(row.values) {
                column.push(v);
            }
        }
        let Some(layout) = self.layout.filter(|_| rows > 0) else {
            return Err(Error::NoData);
        };
        Ok(Table {
            t: layout.t.map(|s| Column {
                info: s.info,
                values: t,
            }),
            columns: layout
                .values
                .into_iter()
                .zip(values)
                .map(|(s, values)| Column {
                    info: s.info,
                    values,
                })
                .collect(),
        })
    }
}

/// Reads the fields of a row into numbers.
struct Parser {
    ranges: Vec<Range<usize>>,
    values: Vec<f64>,
    t: Option<f64>,
    prev_t: Option<f64>,
    /// How messages name `--scale`.
    scale: &'static str,
}

impl Parser {
    /// Reads `text` (line `line`); false for a line of separators only.
    fn parse(
        &mut self,
        layout: &Layout,
        text: &[u8],
        delimiter: Delimiter,
        line: u64,
    ) -> Result<bool, Error> {
        split_into(text, delimiter, &mut self.ranges);
        if self.ranges.iter().all(|r| r.is_empty()) {
            return Ok(false);
        }
        if self.ranges.len() != layout.width {
            return Err(Error::RowWidth {
                line,
                expected: layout.width,
                columns: layout.listing.clone(),
                found: self.ranges.len(),
                delimiter,
            });
        }
        self.t = match &layout.t {
            Some(slot) => {
                let t = self.value(slot, text, line)?;
                if let Some(prev) = self.prev_t.filter(|&p| t <= p) {
                    return Err(Error::TimesNotIncreasing {
                        line,
                        prev,
                        value: t,
                    });
                }
                self.prev_t = Some(t);
                Some(t)
            }
            None => None,
        };
        self.values.clear();
        for slot in &layout.values {
            let v = self.value(slot, text, line)?;
            self.values.push(v);
        }
        Ok(true)
    }

    fn row(&self) -> Row<'_> {
        Row {
            t: self.t,
            values: &self.values,
        }
    }

    /// The value of `slot` in `text`, times its factor.
    fn value(&self, slot: &Slot, text: &[u8], line: u64) -> Result<f64, Error> {
        let field = &text[self.ranges[slot.info.index].clone()];
        if slot.missing_ok && (field.is_empty() || field.eq_ignore_ascii_case(b"nan")) {
            return Ok(f64::NAN);
        }
        let column = || slot.label.clone();
        let Ok(field) = std::str::from_utf8(field) else {
            return Err(Error::Utf8 { line });
        };
        if field.is_empty() {
            return Err(Error::EmptyValue {
                line,
                column: column(),
            });
        }
        let v = match field.parse::<f64>() {
            Ok(v) if v.is_finite() => v,
            Ok(value) => {
                return Err(Error::NotFinite {
                    line,
                    column: column(),
                    value,
                })
            }
            Err(_) => {
                return Err(Error::NotANumber {
                    line,
                    column: column(),
                    value: quoted(field),
                })
            }
        };
        let scaled = v * slot.factor;
        if !scaled.is_finite() {
            return Err(Error::ScaledNotFinite {
                line,
                column: column(),
                value: v,
                factor: slot.factor,
                option: self.scale,
            });
        }
        if slot.positive && scaled <= 0.0 {
            return Err(Error::NotPositive {
                line,
                column: column(),
                value: scaled,
            });
        }
        Ok(scaled)
    }
}
