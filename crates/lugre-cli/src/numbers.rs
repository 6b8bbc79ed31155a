//! Comma-separated number lists as given on the command line (`--turning-points 0,-1,2.5`).

use anyhow::{bail, Result};
use clap::builder::TypedValueParser;
use clap::error::{Error, ErrorKind};
use clap::{Arg, Command};
use std::ffi::OsStr;

use crate::fmt::quoted;

/// Parses `a,b,c` into finite numbers, naming the flag and the offending item.
pub fn parse_list(flag: &str, text: &str) -> Result<Vec<f64>> {
    items(flag, text)?
        .map(|(i, item)| parse_number(flag, i + 1, item))
        .collect()
}

/// Parses `a,b,c` into numbers, `nan` and `inf` included: a series the library judges as a
/// whole (`lugre cycles --values`), so that a value that is not finite gets the library's
/// message, the one the Python package and the C ABI give for the same series.
pub(crate) fn parse_series(flag: &str, text: &str) -> Result<Vec<f64>> {
    items(flag, text)?
        .map(|(i, item)| number(flag, i + 1, item))
        .collect()
}

/// The items of a comma-separated list, numbered from 0.
fn items<'a>(flag: &str, text: &'a str) -> Result<impl Iterator<Item = (usize, &'a str)> + 'a> {
    let text = text.trim();
    if text.is_empty() {
        bail!("{flag}: empty list (expected numbers separated by commas)");
    }
    Ok(text.split(',').enumerate())
}

/// One finite number; `position` is 1-based for messages, and the item is quoted short (a
/// list may run to megabytes).
pub fn parse_number(flag: &str, position: usize, item: &str) -> Result<f64> {
    match number(flag, position, item)? {
        v if v.is_finite() => Ok(v),
        _ => bail!(
            "{flag}: item {position} is {}, which is not a finite number",
            quoted(item.trim())
        ),
    }
}

/// One number, finite or not (see [`parse_number`]).
fn number(flag: &str, position: usize, item: &str) -> Result<f64> {
    let item = item.trim();
    if item.is_empty() {
        bail!("{flag}: item {position} is empty");
    }
    match item.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        // The core's words for a value that is not finite (`u[1] must be a finite number, got
        // NaN` in Python and C), the item counted from 1 as a list on the command line is.
        Ok(v) => bail!(
            "{flag}: item {position} must be a finite number, got {}",
            lugre::error::num(v)
        ),
        Err(_) => bail!(
            "{flag}: item {position} is {}, which is not a number",
            quoted(item)
        ),
    }
}

/// The value parser of a flag that takes one finite number (`--fc`, `--gate`): values starting
/// with '-' are numbers (`--fc -0.5`, with clap's `allow_hyphen_values`), and anything else is
/// named with the flag in one sentence: `--fc expects a number, got '--'`. The model or the
/// command judges the number itself (finite, positive, in range, ...).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Real;

/// The value parser of a flag that takes a whole number of at least `.0` (`--bins`):
/// `--bins must be a whole number >= 1, got -1`. With `0` it checks the syntax only and the
/// core judges the count (`--samples`: `HysteresisLoop::try_sample`).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Whole(pub usize);

impl TypedValueParser for Real {
    type Value = f64;

    fn parse_ref(&self, _: &Command, arg: Option<&Arg>, value: &OsStr) -> Result<f64, Error> {
        let flag = flag_name(arg);
        let text = value.to_string_lossy();
        // `inf` and `nan` written as such go through: the model or the command rejects them
        // with the same message as the library and the Python package ("fs must be a finite
        // number, got NaN"). A number too large for f64 is named here, as the user wrote it.
        match text.trim().parse::<f64>() {
            Ok(v) if v.is_finite() || !text.trim().bytes().any(|b| b.is_ascii_digit()) => Ok(v),
            Ok(_) => Err(invalid(format!(
                "{flag} expects a finite number, {}",
                got(&text)
            ))),
            Err(_) => Err(invalid(format!("{flag} expects a number, {}", got(&text)))),
        }
    }
}

impl TypedValueParser for Whole {
    type Value = usize;

    fn parse_ref(&self, _: &Command, arg: Option<&Arg>, value: &OsStr) -> Result<usize, Error> {
        let flag = flag_name(arg);
        let text = value.to_string_lossy();
        match text.trim().parse::<usize>() {
            Ok(n) if n >= self.0 && !is_flag(&text) => Ok(n),
            _ => {
                // A whole number out of range is shown as such; anything else quoted.
                let got = match text.trim().parse::<i128>() {
                    Ok(n) => format!("got {n}"),
                    Err(_) => got(&text),
                };
                let floor = match self.0 {
                    0 => String::new(),
                    min => format!(" >= {min}"),
                };
                Err(invalid(format!(
                    "{flag} must be a whole number{floor}, {got}"
                )))
            }
        }
    }
}

/// A flag in the value's place (`--fc --json`: the value left out), not `--` alone nor a
/// negative number.
fn is_flag(text: &str) -> bool {
    text.len() > 2 && text.starts_with("--")
}

/// `got '<text>'`, short, or the flag found where the value belongs.
fn got(text: &str) -> String {
    if is_flag(text) {
        format!("got the flag {} (the value is missing)", quoted(text))
    } else {
        format!("got {}", quoted(text))
    }
}

/// `--name` of the flag being parsed.
fn flag_name(arg: Option<&Arg>) -> String {
    match arg.and_then(Arg::get_long) {
        Some(long) => format!("--{long}"),
        None => "the value".into(),
    }
}

/// A clap error that prints as `message` alone.
fn invalid(message: String) -> Error {
    Error::raw(ErrorKind::ValueValidation, message)
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

    fn real(text: &str) -> Result<f64, String> {
        let arg = Arg::new("fc").long("fc");
        Real.parse_ref(&Command::new("t"), Some(&arg), OsStr::new(text))
            .map_err(|e| e.to_string())
    }

    fn whole(min: usize, text: &str) -> Result<usize, String> {
        let arg = Arg::new("samples").long("samples");
        Whole(min)
            .parse_ref(&Command::new("t"), Some(&arg), OsStr::new(text))
            .map_err(|e| e.to_string())
    }

    #[test]
    fn flag_values() {
        assert_eq!(real("-0.5"), Ok(-0.5));
        assert_eq!(real(" 2 "), Ok(2.0));
        let e = real("--").unwrap_err();
        assert!(e.contains("--fc expects a number, got '--'"), "{e}");
        let e = real("--json").unwrap_err();
        assert!(
            e.contains("--fc expects a number, got the flag '--json' (the value is missing)"),
            "{e}"
        );
        // Non-finite values are the model's or the command's to reject (same message as the
        // library's).
        assert_eq!(real("-inf"), Ok(f64::NEG_INFINITY));
        assert!(real("NaN").unwrap().is_nan());
        let e = real("1e999").unwrap_err();
        assert!(
            e.contains("--fc expects a finite number, got '1e999'"),
            "{e}"
        );
        let e = real(&"x".repeat(100_000)).unwrap_err();
        assert!(e.contains("(100000 characters)") && e.len() < 200, "{e}");
        assert_eq!(whole(2, "2"), Ok(2));
        for (min, text, want) in [
            (2, "-1", "--samples must be a whole number >= 2, got -1"),
            (2, "1", "--samples must be a whole number >= 2, got 1"),
            (1, "2.5", "--samples must be a whole number >= 1, got '2.5'"),
            (0, "-1", "--samples must be a whole number, got -1"),
            (1, "--json", "got the flag '--json' (the value is missing)"),
        ] {
            let e = whole(min, text).unwrap_err();
            assert!(e.contains(want), "{e}");
        }
    }
}
