//! The number-list parser of the list flags (`--turning-points 0,1,...`) on arbitrary text: no
//! panic; a list it accepts has one finite number per comma-separated item, which its shortest
//! representation reads back exactly; every error names the flag.
#![no_main]

use libfuzzer_sys::fuzz_target;
use lugre_cli::fuzzing::{exact, parse_list, parse_number};

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    match parse_list("--x", &text) {
        Ok(v) => {
            assert_eq!(v.len(), text.trim().split(',').count());
            for (i, x) in v.iter().enumerate() {
                assert!(x.is_finite());
                let back = parse_number("--x", i + 1, &exact(*x)).unwrap();
                assert_eq!(back.to_bits(), x.to_bits(), "{x} round-trips");
            }
        }
        Err(e) => assert!(e.to_string().starts_with("--x: "), "{e}"),
    }
});
