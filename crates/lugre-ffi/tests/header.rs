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

/// The fields of `LugreParams` in the header with the comment above each:
/// `(name, comment)`.
fn params_fields(header: &str) -> Vec<(String, String)> {
    let start = header
        .find("typedef struct LugreParams {")
        .expect("LugreParams");
    let end = start + header[start..].find("} LugreParams;").expect("its end");
    let mut comment = String::new();
    let mut fields = Vec::new();
    for line in header[start..end].lines().skip(1).map(str::trim) {
        if let Some(c) = line.strip_prefix("// ") {
            comment = c.to_string();
        } else if let Some(name) = line.strip_prefix("double ") {
            fields.push((name.trim_end_matches(';').to_string(), comment.clone()));
        }
    }
    fields
}

/// The C parameter struct is the core's table: the same names in the same order, each
/// commented with the core's description, domain and unit.
#[test]
fn the_parameter_struct_is_the_cores_table() {
    let dir = env!("CARGO_MANIFEST_DIR");
    let header = std::fs::read_to_string(format!("{dir}/include/lugre.h")).unwrap();
    let want: Vec<(String, String)> = lugre::model::Parameter::LUGRE
        .iter()
        .map(|p| {
            let comment = format!(
                "{} ({}), unit {}",
                p.description(),
                p.domain().condition(),
                p.unit()
            );
            (p.name().to_string(), comment)
        })
        .collect();
    assert_eq!(params_fields(&header), want);
}
