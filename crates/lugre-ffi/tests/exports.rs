//! Every function `include/lugre.h` declares is called from C by `tests/c/every_export.c`,
//! which checks what each returns: this test lists the header's functions, fails if the
//! program does not call one of them (a function added to the ABI must be added there too),
//! then compiles and runs it.

mod common;

/// The functions the header declares (a declaration starts a line with its return type).
fn declared(header: &str) -> Vec<String> {
    header
        .lines()
        .filter(|l| !l.starts_with(' ') && !l.starts_with("//") && !l.starts_with('#'))
        .filter_map(|l| {
            let open = l.find('(')?;
            let name = l[..open].rsplit([' ', '*']).next()?;
            name.starts_with("lugre_").then(|| name.to_string())
        })
        .collect()
}

/// The program's text without its comments.
fn code(c: &str) -> String {
    let mut out = String::new();
    let mut rest = c;
    while let Some(start) = rest.find("/*") {
        out.push_str(&rest[..start]);
        rest = rest[start..]
            .find("*/")
            .map_or("", |end| &rest[start + end + 2..]);
    }
    out.push_str(rest);
    out
}

/// The declared functions `program` does not call.
fn uncalled(header: &str, program: &str) -> Vec<String> {
    let code = code(program);
    declared(header)
        .into_iter()
        .filter(|name| !code.contains(&format!("{name}(")))
        .collect()
}

#[test]
fn every_exported_function_is_called_from_c() {
    let root = common::root();
    let header = std::fs::read_to_string(root.join("crates/lugre-ffi/include/lugre.h")).unwrap();
    let source = root.join("crates/lugre-ffi/tests/c/every_export.c");
    let program = std::fs::read_to_string(&source).unwrap();
    assert!(declared(&header).len() >= 31, "{:?}", declared(&header));
    assert_eq!(uncalled(&header, &program), [""; 0]);

    let version = format!("-DLUGRE_EXPECTED_VERSION=\"{}\"", env!("CARGO_PKG_VERSION"));
    let out = common::compile_and_run(&source, &[version]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success() && text == "ok\n", "{text}");
}

#[test]
fn a_function_only_named_in_a_comment_is_not_called() {
    let header = "LugreStatus lugre_new_thing(double x);\nconst char *lugre_version(void);\n";
    let program = "/* lugre_new_thing(1) */ int main(void) { lugre_version(); }";
    assert_eq!(uncalled(header, program), ["lugre_new_thing"]);
}
