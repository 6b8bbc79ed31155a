//! The CSV reader (`lugre_cli::fuzzing::SampleReader`) on arbitrary bytes, for a series (with
//! and without a named column) and a `u,F` record: no panic; every row it returns has as many
//! values as the columns asked for, all finite, and, when the file has times, strictly
//! increasing finite times; every error names a line.
#![no_main]

use libfuzzer_sys::fuzz_target;
use lugre_cli::fuzzing::{Columns, SampleReader};

fuzz_target!(|data: &[u8]| {
    let Some((&mode, bytes)) = data.split_first() else {
        return;
    };
    let (columns, width) = match mode % 5 {
        0 => (Columns::Series, 1),
        1 => (Columns::Named("u"), 1),
        2 => (Columns::Named("force"), 1),
        3 => (Columns::Named("t"), 1),
        _ => (Columns::Record, 2),
    };
    let mut reader = SampleReader::new(bytes, columns);
    let mut prev_t: Option<f64> = None;
    loop {
        match reader.next_row() {
            Ok(Some(s)) => {
                assert_eq!(s.values.len(), width, "{s:?}");
                assert!(s.values.iter().all(|v| v.is_finite()), "{s:?}");
                let t = s.t;
                assert_eq!(t.is_some(), reader.has_time());
                if let Some(t) = t {
                    assert!(t.is_finite());
                    if let Some(p) = prev_t {
                        assert!(t > p, "times increase: {p} then {t}");
                    }
                    prev_t = Some(t);
                }
            }
            Ok(None) => break,
            Err(e) => {
                let msg = format!("{e:#}");
                assert!(msg.starts_with("line "), "an error names its line: {msg}");
                break;
            }
        }
    }
});
