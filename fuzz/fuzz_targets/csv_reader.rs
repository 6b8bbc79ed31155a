//! The data-file reader (`lugre_io`) on arbitrary bytes, for a series `u`, a column asked for by
//! a name of its own, a record `u,F` and a record with required times: no panic; every row it
//! returns has as many values as the columns it placed, all finite, and, when the file has
//! times, strictly increasing finite times; every error names a line.
#![no_main]

use libfuzzer_sys::fuzz_target;
use lugre_io::{ReadOptions, Reader, Role, Spec};

fuzz_target!(|data: &[u8]| {
    let Some((&mode, bytes)) = data.split_first() else {
        return;
    };
    let spec = match mode % 5 {
        0 => Spec::new([Role::U]),
        1 => Spec::new([Role::of("strain")]),
        2 => Spec::new([Role::F]).require_time(),
        3 => Spec::new([Role::U, Role::F]).allow_missing(Role::F),
        _ => Spec::new([Role::U]).optional(Role::N).positive(Role::N),
    };
    let names_a_line = |e: lugre_io::Error| {
        assert!(e.line().is_some(), "an error names its line: {e}");
        assert!(e.to_string().starts_with("line "), "{e}");
    };
    let reader = match Reader::new(bytes, ReadOptions::default()) {
        Ok(r) => r,
        Err(e) => return names_a_line(e),
    };
    let mut rows = match reader.rows(&spec) {
        Ok(r) => r,
        Err(e) => return names_a_line(e),
    };
    let width = rows.columns().len();
    let timed = rows.time().is_some();
    let mut prev_t: Option<f64> = None;
    loop {
        match rows.next_row() {
            Ok(Some(row)) => {
                assert_eq!(row.values.len(), width, "{row:?}");
                let missing_f = mode % 5 == 3;
                assert!(
                    row.values.iter().all(|v| v.is_finite() || missing_f),
                    "{row:?}"
                );
                assert_eq!(row.t.is_some(), timed);
                if let Some(t) = row.t {
                    assert!(t.is_finite());
                    if let Some(p) = prev_t {
                        assert!(t > p, "times increase: {p} then {t}");
                    }
                    prev_t = Some(t);
                }
            }
            Ok(None) => break,
            Err(e) => return names_a_line(e),
        }
    }
});
