//! Reading a series from CSV: header `t,u`, or a single column `u`; the header is optional.
//! A UTF-8 byte-order mark, `#` comments, blank lines, CRLF line ends and spaces around values
//! are accepted. Every problem is reported with the file's line number.

use anyhow::{bail, Context, Result};
use std::path::Path;

/// A sampled series: optional times (strictly increasing) and values, all finite.
#[derive(Debug, Clone)]
pub struct Series {
    pub t: Option<Vec<f64>>,
    pub u: Vec<f64>,
}

pub fn read_series(path: &Path) -> Result<Series> {
    let bytes = std::fs::read(path).with_context(|| format!("cannot read '{}'", path.display()))?;
    parse_series(&bytes).with_context(|| path.display().to_string())
}

pub fn parse_series(bytes: &[u8]) -> Result<Series> {
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .comment(Some(b'#'))
        .trim(csv::Trim::All)
        .from_reader(bytes);
    let mut width: Option<usize> = None;
    let mut t: Vec<f64> = Vec::new();
    let mut u: Vec<f64> = Vec::new();
    let mut record = csv::ByteRecord::new();
    loop {
        let more = reader.read_byte_record(&mut record);
        let line = record.position().map_or(0, |p| p.line());
        match more {
            Ok(false) => break,
            Ok(true) => {}
            Err(e) => bail!("line {line}: {e}"),
        }
        if record.iter().all(|f| f.is_empty()) {
            continue; // a blank line (or only separators)
        }
        let fields: Vec<&str> = record
            .iter()
            .map(std::str::from_utf8)
            .collect::<Result<_, _>>()
            .map_err(|_| anyhow::anyhow!("line {line}: not valid UTF-8 text"))?;
        let w = match width {
            Some(w) => w,
            None => {
                let w = columns(&fields, line)?;
                width = Some(w);
                if fields.iter().any(|f| f.parse::<f64>().is_err()) {
                    continue; // the header, checked by `columns`
                }
                w
            }
        };
        if fields.len() != w {
            let names = if w == 2 {
                "2 values (t,u)"
            } else {
                "1 value (u)"
            };
            bail!("line {line}: expected {names}, found {}", fields.len());
        }
        let values: Vec<f64> = fields
            .iter()
            .zip(if w == 2 {
                ["t", "u"].as_slice()
            } else {
                ["u"].as_slice()
            })
            .map(|(f, name)| number(f, name, line))
            .collect::<Result<_>>()?;
        if w == 2 {
            if let Some(&prev) = t.last() {
                if values[0] <= prev {
                    bail!(
                        "line {line}: times must be strictly increasing, t = {} follows t = {prev}",
                        values[0]
                    );
                }
            }
            t.push(values[0]);
            u.push(values[1]);
        } else {
            u.push(values[0]);
        }
    }
    if u.is_empty() {
        bail!("no data rows");
    }
    Ok(Series {
        t: (width == Some(2)).then_some(t),
        u,
    })
}

/// The number of columns, from the first row: a header `t,u` or `u`, or numbers.
fn columns(fields: &[&str], line: u64) -> Result<usize> {
    let numeric = fields.iter().all(|f| f.parse::<f64>().is_ok());
    if numeric {
        return match fields.len() {
            1 | 2 => Ok(fields.len()),
            n => bail!("line {line}: expected 1 column (u) or 2 columns (t,u), found {n}"),
        };
    }
    let names: Vec<String> = fields.iter().map(|f| f.to_ascii_lowercase()).collect();
    match names
        .iter()
        .map(String::as_str)
        .collect::<Vec<_>>()
        .as_slice()
    {
        ["t", "u"] => Ok(2),
        ["u"] => Ok(1),
        _ => bail!(
            "line {line}: unexpected header '{}': expected 't,u' or 'u'",
            fields.join(",")
        ),
    }
}

fn number(field: &str, name: &str, line: u64) -> Result<f64> {
    if field.is_empty() {
        bail!("line {line}: empty value for {name}");
    }
    match field.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(_) => bail!("line {line}: {name} = '{field}' is not a finite number"),
        Err(_) => bail!("line {line}: {name} = '{field}' is not a number"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
}
