//! Comma-separated number lists as given on the command line (`--turning-points 0,-1,2.5`).

use anyhow::{bail, Result};

/// Parses `a,b,c` into finite numbers, naming the flag and the offending item.
pub fn parse_list(flag: &str, text: &str) -> Result<Vec<f64>> {
    let text = text.trim();
    if text.is_empty() {
        bail!("{flag}: empty list (expected numbers separated by commas)");
    }
    text.split(',')
        .enumerate()
        .map(|(i, item)| parse_number(flag, i + 1, item))
        .collect()
}

/// One finite number; `position` is 1-based for messages.
pub fn parse_number(flag: &str, position: usize, item: &str) -> Result<f64> {
    let item = item.trim();
    if item.is_empty() {
        bail!("{flag}: item {position} is empty");
    }
    match item.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(_) => bail!("{flag}: item {position} is '{item}', which is not a finite number"),
        Err(_) => bail!("{flag}: item {position} is '{item}', which is not a number"),
    }
}

/// The value of a numeric flag that takes values starting with '-' (`--fc -inf`, clap's
/// `allow_hyphen_values`): a flag in its place (`--fc --json`, the value left out) is named as
/// one, not read as a bad number.
pub fn flag_value<T>(text: &str) -> Result<T, String>
where
    T: std::str::FromStr,
    T::Err: std::fmt::Display,
{
    if text.len() > 2 && text.starts_with("--") {
        return Err("expected a value, found a flag".into());
    }
    text.parse::<T>().map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lists() {
        assert_eq!(
            parse_list("--x", "0, -1,2.5e-3").unwrap(),
            vec![0.0, -1.0, 2.5e-3]
        );
        for bad in ["", "1,,2", "1,nan", "1,inf", "1,abc", "1,"] {
            let e = parse_list("--x", bad).unwrap_err().to_string();
            assert!(e.starts_with("--x:"), "{bad}: {e}");
        }
    }

    #[test]
    fn flag_values() {
        assert_eq!(flag_value::<f64>("-inf"), Ok(f64::NEG_INFINITY));
        assert_eq!(flag_value::<f64>("-0.5"), Ok(-0.5));
        assert!(flag_value::<usize>("-1").is_err());
        assert_eq!(
            flag_value::<f64>("--json"),
            Err("expected a value, found a flag".to_string())
        );
        assert!(flag_value::<f64>("--").is_err());
    }
}
