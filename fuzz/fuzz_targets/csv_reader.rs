//! The CSV reader (`lugre_cli::csv_in::SampleReader`) on arbitrary bytes, with and without a
//! named column: no panic; every row it returns has finite values and, when the file has
//! times, strictly increasing finite times; every error names a line or the file's emptiness.
#![no_main]

use libfuzzer_sys::fuzz_target;
use lugre_cli::csv_in::SampleReader;

fuzz_target!(|data: &[u8]| {
    let Some((&mode, bytes)) = data.split_first() else {
        return;
    };
    let column = match mode % 4 {
        0 => None,
        1 => Some("u"),
        2 => Some("force"),
        _ => Some("t"),
    };
    let mut reader = SampleReader::new(bytes, column);
    let mut prev_t: Option<f64> = None;
    loop {
        match reader.next_sample() {
            Ok(Some(s)) => {
                assert!(s.u.is_finite(), "{s:?}");
                assert_eq!(s.t.is_some(), reader.has_time());
                if let Some(t) = s.t {
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
