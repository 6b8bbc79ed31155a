//! The checked-in header `include/lugre.h` is what cbindgen makes of `src/lib.rs` today.
//! `LUGRE_BLESS=1 cargo test -p lugre-ffi --test header` rewrites it.

#[test]
fn the_checked_in_header_is_up_to_date() {
    let dir = env!("CARGO_MANIFEST_DIR");
    let config =
        cbindgen::Config::from_file(format!("{dir}/cbindgen.toml")).expect("cbindgen.toml");
    let mut made = Vec::new();
    cbindgen::Builder::new()
        .with_crate(dir)
        .with_config(config)
        .generate()
        .expect("cbindgen parses src/lib.rs")
        .write(&mut made);
    let path = format!("{dir}/include/lugre.h");
    if std::env::var_os("LUGRE_BLESS").is_some() {
        std::fs::write(&path, &made).expect("write include/lugre.h");
    }
    let have = std::fs::read(&path).unwrap_or_default();
    assert!(
        have == made,
        "include/lugre.h is out of date: run LUGRE_BLESS=1 cargo test -p lugre-ffi --test header"
    );
}
