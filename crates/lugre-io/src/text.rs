//! Text from a file, shown in a message: cut short (a cell or a header may run to a megabyte),
//! and the header name closest to a mistyped one.

/// Text from a file, quoted for a message: whole up to 40 characters, else its start, '...'
/// and its length.
///
/// ```
/// assert_eq!(lugre_io::text::quoted("1e999"), "'1e999'");
/// assert_eq!(
///     lugre_io::text::quoted(&"x".repeat(50)),
///     format!("'{}...' (50 characters)", "x".repeat(32))
/// );
/// ```
pub fn quoted(text: &str) -> String {
    match shortened(text) {
        (start, None) => format!("'{start}'"),
        (start, Some(n)) => format!("'{start}...' ({n} characters)"),
    }
}

/// [`quoted`] without the quotes.
pub fn excerpt(text: &str) -> String {
    match shortened(text) {
        (start, None) => start,
        (start, Some(n)) => format!("{start}... ({n} characters)"),
    }
}

/// `text` whole, or its start and its length in characters; control characters escaped.
fn shortened(text: &str) -> (String, Option<usize>) {
    let n = text.chars().count();
    if n <= QUOTE_CHARS {
        (printable(text), None)
    } else {
        let start: String = text.chars().take(QUOTE_CHARS - 8).collect();
        (printable(&start), Some(n))
    }
}

/// `text` with its control characters escaped (`\u{0}`, `\n`): a message stays one line, and
/// a NUL or an escape sequence from a file never reaches a terminal.
pub fn printable(text: &str) -> String {
    text.chars()
        .map(|c| {
            if c.is_control() {
                c.escape_default().to_string()
            } else {
                c.to_string()
            }
        })
        .collect()
}

/// The longest text [`quoted`] and [`excerpt`] show whole.
const QUOTE_CHARS: usize = 40;

/// Of `candidates`, the one closest to `wanted` (edit distance, both already compared as bare
/// names), if one is close: at most half the longer name's length apart.
pub(crate) fn closest<'a>(wanted: &str, candidates: &[&'a str]) -> Option<&'a str> {
    candidates
        .iter()
        .map(|c| (edit_distance(wanted, c), *c))
        .filter(|(d, c)| *d <= (c.len().max(wanted.len()) / 2).max(1))
        .min_by_key(|(d, _)| *d)
        .map(|(_, c)| c)
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quoted_text_is_short() {
        assert_eq!(quoted("1e999"), "'1e999'");
        let forty = "x".repeat(40);
        assert_eq!(quoted(&forty), format!("'{forty}'"));
        let digits = format!("1{}", "0".repeat(400));
        assert_eq!(
            quoted(&digits),
            format!("'1{}...' (401 characters)", "0".repeat(31))
        );
        // Characters, not bytes: never a split UTF-8 sequence.
        assert_eq!(
            quoted(&"µ".repeat(41)),
            format!("'{}...' (41 characters)", "µ".repeat(32))
        );
        assert_eq!(excerpt("t,u"), "t,u");
        assert_eq!(quoted("1\u{0}\u{1b}[2J"), "'1\\u{0}\\u{1b}[2J'");
        assert_eq!(
            excerpt(&"x,".repeat(30)),
            format!("{}... (60 characters)", "x,".repeat(16))
        );
    }

    #[test]
    fn the_closest_name() {
        let names = ["time", "position", "friction"];
        assert_eq!(closest("positon", &names), Some("position"));
        assert_eq!(closest("fricton", &names), Some("friction"));
        assert_eq!(closest("velocity", &names), None);
        assert_eq!(edit_distance("", "abc"), 3);
        assert_eq!(edit_distance("kitten", "sitting"), 3);
    }
}
