//! Numbers for people (tables), for machines (JSON, CSV: shortest round-trip repr) and for
//! messages ([`num`], the core's formatter, so that the CLI's messages and the library's print
//! a number the same way), and text quoted in messages ([`quoted`], [`excerpt`], from the
//! reader).

/// A number in a message: shortest round-trip, exponent form beyond 1e-5..1e16 (`1e299`).
pub(crate) use lugre::error::num;

/// `x` with up to `digits` significant digits, plain notation for moderate magnitudes. Never
/// more digits than `x`'s shortest round-trip form has: a subnormal typed as `1e-320` is
/// stored as 9.99988867...e-321 (it has fewer bits), and prints as `1e-320`, as typed.
pub(crate) fn sig(x: f64, digits: usize) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let digits = digits.min(shortest_digits(x));
    let exp = x.abs().log10().floor() as i32;
    if (-4..9).contains(&exp) {
        let decimals = (digits as i32 - 1 - exp).max(0) as usize;
        let s = format!("{x:.decimals$}");
        let s = if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        };
        if s == "-0" {
            "0".into()
        } else {
            s
        }
    } else {
        let s = format!("{:.*e}", digits - 1, x);
        match s.split_once('e') {
            Some((m, e)) => {
                let m = if m.contains('.') {
                    m.trim_end_matches('0').trim_end_matches('.')
                } else {
                    m
                };
                format!("{m}e{e}")
            }
            None => s,
        }
    }
}

/// The number of significant digits of the shortest string that parses back to `x` (finite,
/// not 0).
fn shortest_digits(x: f64) -> usize {
    let s = format!("{:e}", x.abs());
    let mantissa = s.split_once('e').map_or(s.as_str(), |(m, _)| m);
    mantissa.chars().filter(char::is_ascii_digit).count().max(1)
}

/// The shortest string that parses back to exactly `x` (as serde_json prints numbers).
pub fn exact(x: f64) -> String {
    let mut buf = zmij::Buffer::new();
    let s = buf.format(x);
    s.strip_suffix(".0").unwrap_or(s).to_string()
}

/// Text from a file, quoted for a message, cut short (the reader's, so that every message
/// shows file text the same way).
pub(crate) use lugre_io::text::{excerpt, quoted};

/// A message written elsewhere (clap's, which quote the command line whole: `unexpected
/// argument '...' found`) with every '-quoted text cut short as `quoted` cuts it.
pub fn shorten_quoted(message: &str) -> String {
    let parts: Vec<&str> = message.split('\'').collect();
    let mut out = String::with_capacity(message.len().min(1024));
    for (i, part) in parts.iter().enumerate() {
        if i % 2 == 0 {
            out.push_str(part);
        } else if i + 1 < parts.len() {
            out.push_str(&quoted(part));
        } else {
            // An unpaired quote: the rest as it is.
            out.push('\'');
            out.push_str(part);
        }
    }
    out
}

/// `text` with its first letter upper case (a description opening a help line).
pub(crate) fn capitalized(text: &str) -> String {
    let mut chars = text.chars();
    chars
        .next()
        .map(|c| c.to_ascii_uppercase())
        .into_iter()
        .chain(chars)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn significant_digits() {
        assert_eq!(sig(0.0, 10), "0");
        assert_eq!(sig(1.5, 10), "1.5");
        assert_eq!(sig(-0.123456789012, 6), "-0.123457");
        assert_eq!(sig(1e-12, 6), "1e-12");
        assert_eq!(sig(123456.0, 10), "123456");
        assert_eq!(sig(2.5e12, 4), "2.5e12");
        // Subnormals print as typed, not as their stored value's ten digits.
        assert_eq!(sig(1e-320, 10), "1e-320");
        assert_eq!(sig(-4.5e-310, 10), "-4.5e-310");
        assert_eq!(sig(5e-324, 10), "5e-324");
        assert_eq!(sig(0.1 + 0.2, 10), "0.3");
        assert_eq!(sig(1.0 / 3.0, 4), "0.3333");
    }

    #[test]
    fn exact_round_trips() {
        for x in [0.1, 1.0 / 3.0, 1e-300, -2.5, 1e21] {
            assert_eq!(exact(x).parse::<f64>().unwrap(), x);
        }
        assert_eq!(exact(2.0), "2");
    }

    #[test]
    fn quoted_messages_are_short() {
        let long = "x".repeat(1000);
        assert_eq!(
            shorten_quoted(&format!("unexpected argument '{long}' found; 'a' b")),
            format!(
                "unexpected argument '{}...' (1000 characters) found; 'a' b",
                "x".repeat(32)
            )
        );
        assert_eq!(shorten_quoted("it's"), "it's");
        assert_eq!(shorten_quoted("no quotes"), "no quotes");
    }
}
