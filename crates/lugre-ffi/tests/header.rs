//! The checked-in header `include/lugre.h` is what cbindgen makes of `src/lib.rs` today, with
//! the parameters written from the core's table ([`lugre::model::Parameter`]): the struct
//! `LugreParams` (the core's `#[repr(C)]` `LuGreParams`, which cbindgen does not see) and
//! `LUGRE_MAX_PARAMETERS` (a constant computed from the table, which cbindgen cannot write).
//! A parameter added to the table is in the header after
//! `LUGRE_BLESS=1 cargo test -p lugre-ffi --test header`, which rewrites it.

use lugre::model::Parameter;

/// The comment of a parameter's field: the core's description, domain and unit.
fn field_comment(p: Parameter) -> String {
    format!(
        "{} ({}), unit {}",
        p.description(),
        p.domain().condition(),
        p.unit()
    )
}

/// The header's part that comes from the core's table.
fn from_the_table() -> String {
    let max = lugre_c::LUGRE_MAX_PARAMETERS;
    let mut out = format!(
        "// The most parameters a family has (LuGre's {}): the length of the fit's arrays.\n\
         #define LUGRE_MAX_PARAMETERS {max}\n\n\
         // The parameters of a LuGre model (SI units; see lugre_params_default), in the order of\n\
         // the core's table (lugre_parameter_name); lugre_params_set sets one by name.\n\
         typedef struct LugreParams {{\n",
        Parameter::LUGRE.len()
    );
    for p in Parameter::LUGRE {
        out += &format!("  // {}\n  double {};\n", field_comment(p), p.name());
    }
    out + "} LugreParams;"
}

#[test]
fn the_checked_in_header_is_up_to_date() {
    let dir = env!("CARGO_MANIFEST_DIR");
    let mut config =
        cbindgen::Config::from_file(format!("{dir}/cbindgen.toml")).expect("cbindgen.toml");
    config.after_includes = Some(format!("\n{}", from_the_table()));
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
    let want: Vec<(String, String)> = Parameter::LUGRE
        .iter()
        .map(|&p| (p.name().to_string(), field_comment(p)))
        .collect();
    assert_eq!(params_fields(&header), want);
}
