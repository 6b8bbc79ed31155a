//! The lines of a file and the fields of a line. A line ends at LF, CRLF or CR alone (each
//! counts one line, so that messages name the line an editor shows); a UTF-8 byte-order mark
//! before the first line is dropped; a line longer than [`MAX_LINE`] bytes is refused before it
//! is read whole (a binary file or `/dev/zero` has no line breaks).

use std::io::BufRead;
use std::ops::Range;

use crate::Error;

/// The longest line accepted, in bytes. A row of numbers is a few dozen bytes; without a
/// limit, a file with no line breaks would be read into memory as one line until the memory
/// runs out.
pub const MAX_LINE: usize = 1 << 20;

const BOM: &[u8] = b"\xEF\xBB\xBF";

/// Reads a stream line by line, numbering the lines from 1.
pub(crate) struct Lines<R> {
    inner: R,
    buf: Vec<u8>,
    /// The number of the next line.
    next: u64,
    /// The last line ended with CR: an LF right after it belongs to it.
    after_cr: bool,
    done: bool,
}

impl<R: BufRead> Lines<R> {
    pub(crate) fn new(inner: R) -> Self {
        Self {
            inner,
            buf: Vec::new(),
            next: 1,
            after_cr: false,
            done: false,
        }
    }

    /// The next line (without its end) and its number, or `None` at the end of the stream.
    pub(crate) fn next_line(&mut self) -> Result<Option<(u64, &[u8])>, Error> {
        self.buf.clear();
        if self.done {
            return Ok(None);
        }
        let line = self.next;
        loop {
            let available = match self.inner.fill_buf() {
                Ok(bytes) => bytes,
                Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
                Err(source) => return Err(Error::Io { line, source }),
            };
            if available.is_empty() {
                self.done = true;
                if self.buf.is_empty() {
                    return Ok(None);
                }
                break;
            }
            if std::mem::take(&mut self.after_cr) && available[0] == b'\n' {
                self.inner.consume(1);
                continue;
            }
            match memchr::memchr2(b'\n', b'\r', available) {
                Some(k) => {
                    self.buf.extend_from_slice(&available[..k]);
                    self.after_cr = available[k] == b'\r';
                    self.inner.consume(k + 1);
                    break;
                }
                None => {
                    let n = available.len();
                    self.buf.extend_from_slice(available);
                    self.inner.consume(n);
                }
            }
            if self.buf.len() > MAX_LINE {
                return Err(Error::LineTooLong {
                    line,
                    limit: MAX_LINE,
                });
            }
        }
        if self.buf.len() > MAX_LINE {
            return Err(Error::LineTooLong {
                line,
                limit: MAX_LINE,
            });
        }
        self.next += 1;
        let start = if line == 1 && self.buf.starts_with(BOM) {
            BOM.len()
        } else {
            0
        };
        Ok(Some((line, &self.buf[start..])))
    }
}

/// Whether a line holds nothing to read: blank, or a `#` comment.
pub(crate) fn is_comment_or_blank(line: &[u8]) -> bool {
    let line = line.trim_ascii_start();
    line.is_empty() || line[0] == b'#'
}

/// How the fields of a line are separated: found from the first line that is neither blank nor
/// a comment ([`Delimiter::of`]), or given (`--delimiter`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Delimiter {
    Comma,
    Semicolon,
    Tab,
    /// Runs of spaces or tabs; a run followed by `[` or `(` belongs to the name before it
    /// (`Time [s] Position [mm]` is two fields).
    Spaces,
}

impl Delimiter {
    /// How messages name it: "commas", "semicolons", "tabs", "spaces".
    pub fn describe(self) -> &'static str {
        match self {
            Delimiter::Comma => "commas",
            Delimiter::Semicolon => "semicolons",
            Delimiter::Tab => "tabs",
            Delimiter::Spaces => "spaces",
        }
    }

    /// From a line: tabs if it has a tab, else semicolons if it has one, else commas if it has
    /// one, else runs of spaces if they split it, else commas (a single column).
    pub fn of(line: &[u8]) -> Delimiter {
        let line = line.trim_ascii();
        if line.contains(&b'\t') {
            Delimiter::Tab
        } else if line.contains(&b';') {
            Delimiter::Semicolon
        } else if line.contains(&b',') || split(line, Delimiter::Spaces).len() < 2 {
            Delimiter::Comma
        } else {
            Delimiter::Spaces
        }
    }

    fn byte(self) -> u8 {
        match self {
            Delimiter::Comma => b',',
            Delimiter::Semicolon => b';',
            Delimiter::Tab => b'\t',
            Delimiter::Spaces => b' ',
        }
    }
}

/// The fields of a line, each without the blanks and the double quotes around it (`"Force, N"`
/// is one field).
pub(crate) fn split(line: &[u8], delimiter: Delimiter) -> Vec<&[u8]> {
    let mut ranges = Vec::new();
    split_into(line, delimiter, &mut ranges);
    ranges.into_iter().map(|r| &line[r]).collect()
}

/// [`split`] as ranges of `line`, into `fields` (cleared first): a row costs no allocation.
pub(crate) fn split_into(line: &[u8], delimiter: Delimiter, fields: &mut Vec<Range<usize>>) {
    fields.clear();
    if line.contains(&b'"') {
        return split_quoted(line, delimiter, fields);
    }
    if delimiter == Delimiter::Spaces {
        return split_spaces(line, fields);
    }
    let byte = delimiter.byte();
    let mut start = 0;
    for k in memchr::memchr_iter(byte, line) {
        fields.push(trimmed(line, start..k));
        start = k + 1;
    }
    fields.push(trimmed(line, start..line.len()));
}

/// `range` without the blanks at its ends.
fn trimmed(line: &[u8], range: Range<usize>) -> Range<usize> {
    let field = &line[range.clone()];
    let lead = field.len() - field.trim_ascii_start().len();
    let trail = field.len() - field.trim_ascii_end().len();
    if lead == field.len() {
        return range.start..range.start;
    }
    range.start + lead..range.end - trail
}

fn is_blank(b: u8) -> bool {
    b == b' ' || b == b'\t'
}

/// Runs of blanks as separators, except a run before `[` or `(` (a unit).
fn split_spaces(line: &[u8], fields: &mut Vec<Range<usize>>) {
    let all = trimmed(line, 0..line.len());
    let mut start = all.start;
    let mut k = all.start;
    while k < all.end {
        if !is_blank(line[k]) {
            k += 1;
            continue;
        }
        let end = k;
        // The line is trimmed: a run of blanks inside it ends before its end.
        while is_blank(line[k]) {
            k += 1;
        }
        if line[k] != b'[' && line[k] != b'(' {
            fields.push(start..end);
            start = k;
        }
    }
    fields.push(start..all.end);
}

/// A line with a double quote: fields in quotes may hold the delimiter. A field wholly in
/// quotes loses them; other quotes stay (the text then is not a number, and the message shows
/// it as written).
fn split_quoted(line: &[u8], delimiter: Delimiter, fields: &mut Vec<Range<usize>>) {
    let separator = |b: u8| match delimiter {
        Delimiter::Spaces => is_blank(b),
        d => b == d.byte(),
    };
    // A field wholly in quotes, without them.
    let unquote = |range: Range<usize>| {
        let r = trimmed(line, range);
        let field = &line[r.clone()];
        let quoted = field.len() >= 2
            && field[0] == b'"'
            && field[field.len() - 1] == b'"'
            && !field[1..field.len() - 1].contains(&b'"');
        if quoted {
            r.start + 1..r.end - 1
        } else {
            r
        }
    };
    let mut in_quotes = false;
    let mut start = 0;
    for (k, &b) in line.iter().enumerate() {
        if b == b'"' {
            in_quotes = !in_quotes;
        } else if !in_quotes && separator(b) {
            let blank_run =
                delimiter == Delimiter::Spaces && line[start..k].trim_ascii().is_empty();
            if !blank_run {
                fields.push(unquote(start..k));
            }
            start = k + 1;
        }
    }
    let trailing_blanks = delimiter == Delimiter::Spaces && line[start..].trim_ascii().is_empty();
    if !trailing_blanks || fields.is_empty() {
        fields.push(unquote(start..line.len()));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lines(bytes: &[u8]) -> Vec<(u64, String)> {
        let mut r = Lines::new(bytes);
        let mut out = Vec::new();
        while let Some((n, line)) = r.next_line().unwrap() {
            out.push((n, String::from_utf8(line.to_vec()).unwrap()));
        }
        out
    }

    #[test]
    fn every_line_end_counts_once() {
        let want: Vec<(u64, String)> = ["a", "b", "", "c"]
            .iter()
            .enumerate()
            .map(|(k, s)| (k as u64 + 1, s.to_string()))
            .collect();
        assert_eq!(lines(b"a\nb\n\nc\n"), want);
        assert_eq!(lines(b"a\r\nb\r\n\r\nc\r\n"), want);
        assert_eq!(lines(b"a\rb\r\rc\r"), want);
        assert_eq!(lines(b"a\rb\n\r\nc"), want);
        assert_eq!(lines(b"\xEF\xBB\xBFa\nb\n\nc"), want);
        assert!(lines(b"").is_empty());
        assert_eq!(lines(b"\xEF\xBB\xBF"), vec![(1, String::new())]);
    }

    #[test]
    fn crlf_split_across_reads() {
        // A reader that hands out one byte at a time: CR and LF arrive in different reads.
        let bytes: &[u8] = b"a\r\nb\r\nc";
        let one_by_one = std::io::BufReader::with_capacity(1, bytes);
        let mut r = Lines::new(one_by_one);
        let mut got = Vec::new();
        while let Some((n, line)) = r.next_line().unwrap() {
            got.push((n, line.to_vec()));
        }
        assert_eq!(
            got,
            vec![(1, b"a".to_vec()), (2, b"b".to_vec()), (3, b"c".to_vec())]
        );
    }

    #[test]
    fn a_long_line_is_refused_before_it_is_read_whole() {
        let zeros = std::io::BufReader::new(std::io::Read::take(
            std::io::repeat(0),
            64 * MAX_LINE as u64,
        ));
        let mut r = Lines::new(zeros);
        match r.next_line() {
            Err(Error::LineTooLong { line: 1, limit }) => assert_eq!(limit, MAX_LINE),
            other => panic!("{other:?}"),
        }
        let mut text = vec![b' '; MAX_LINE];
        text.extend_from_slice(b"\n1\n");
        assert_eq!(lines(&text).len(), 2);
    }

    #[test]
    fn delimiters() {
        for (line, want) in [
            (&b"t\tu"[..], Delimiter::Tab),
            (b"t;u", Delimiter::Semicolon),
            (b"t,u", Delimiter::Comma),
            (b"t u", Delimiter::Spaces),
            (b" t   u ", Delimiter::Spaces),
            (b"u", Delimiter::Comma),
            (b"Displacement [um]", Delimiter::Comma),
            (b"Time [s]  Position (mm)", Delimiter::Spaces),
            (b"Time [s]\tPosition [mm]", Delimiter::Tab),
        ] {
            assert_eq!(
                Delimiter::of(line),
                want,
                "{}",
                String::from_utf8_lossy(line)
            );
        }
    }

    #[test]
    fn fields() {
        let s = |line: &[u8], d| -> Vec<String> {
            split(line, d)
                .iter()
                .map(|f| String::from_utf8(f.to_vec()).unwrap())
                .collect()
        };
        assert_eq!(s(b" 0 , 1 ,2", Delimiter::Comma), ["0", "1", "2"]);
        assert_eq!(s(b"0,1,", Delimiter::Comma), ["0", "1", ""]);
        assert_eq!(s(b"  0   1\t 2 ", Delimiter::Spaces), ["0", "1", "2"]);
        assert_eq!(
            s(b"Time [s]  Position (mm) F", Delimiter::Spaces),
            ["Time [s]", "Position (mm)", "F"]
        );
        assert_eq!(
            s(b"\"Force, N\",\"t\",x", Delimiter::Comma),
            ["Force, N", "t", "x"]
        );
        assert_eq!(s(b"\"a b\"  c", Delimiter::Spaces), ["a b", "c"]);
        assert_eq!(s(b" \"a b\"  c  ", Delimiter::Spaces), ["a b", "c"]);
        assert_eq!(s(b"1,\"2", Delimiter::Comma), ["1", "\"2"]);
        assert_eq!(s(b"", Delimiter::Spaces), [""]);
    }
}
