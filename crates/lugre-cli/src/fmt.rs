//! Numbers for people (tables) and for machines (JSON, CSV: shortest round-trip repr).

/// `x` with up to `digits` significant digits, plain notation for moderate magnitudes.
pub fn sig(x: f64, digits: usize) -> String {
    if x == 0.0 {
        return "0".into();
    }
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

/// The shortest string that parses back to exactly `x` (as serde_json prints numbers).
pub fn exact(x: f64) -> String {
    let mut buf = zmij::Buffer::new();
    let s = buf.format(x);
    s.strip_suffix(".0").unwrap_or(s).to_string()
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
    }

    #[test]
    fn exact_round_trips() {
        for x in [0.1, 1.0 / 3.0, 1e-300, -2.5, 1e21] {
            assert_eq!(exact(x).parse::<f64>().unwrap(), x);
        }
        assert_eq!(exact(2.0), "2");
    }
}
