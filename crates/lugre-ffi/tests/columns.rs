//! The column names the C side writes are the core's: the fields of `LugreCycleColumns` and
//! the buffers of `lugre_loop_sample` in the header, and the struct fields the MEX gateway
//! (`matlab/lugre_mex.c`) names its cycles and its sampled curve with
//! (`lugre::CycleColumns::NAMES`, `lugre::LoopPoint::COLUMNS`), and the fields of a run's
//! friction-displacement loop in `LugreFrictionLoop` and the MEX gateway's `loops`
//! (`lugre::dynamics::FrictionLoop::FIELDS`). A column renamed or added in the core and not
//! here fails, naming the place.

use lugre::dynamics::FrictionLoop;
use lugre::{CycleColumns, LoopPoint};

fn read(path: &str) -> String {
    let dir = env!("CARGO_MANIFEST_DIR");
    std::fs::read_to_string(format!("{dir}/{path}")).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// The text of `text` from `start` to the next `end`.
fn between<'a>(text: &'a str, start: &str, end: &str) -> &'a str {
    let from = text.find(start).unwrap_or_else(|| panic!("no '{start}'"));
    let to = from + text[from..].find(end).expect("its end");
    &text[from + start.len()..to]
}

/// The C identifiers declared in `decl` as `type *name;` or `type *name,` / `type *name)`.
fn declared_names(decl: &str) -> Vec<String> {
    decl.split([';', ',', ')'])
        .filter_map(|item| item.rsplit(['*', ' ']).next())
        .map(str::trim)
        .filter(|name| !name.is_empty())
        .map(String::from)
        .collect()
}

/// The strings of a C initializer `{"a", "b", ...}`.
fn strings(init: &str) -> Vec<String> {
    init.split('"')
        .skip(1)
        .step_by(2)
        .map(String::from)
        .collect()
}

#[test]
fn the_headers_columns_are_the_cores() {
    let header = read("include/lugre.h");
    let fields = between(
        &header,
        "typedef struct LugreCycleColumns {",
        "} LugreCycleColumns;",
    );
    assert_eq!(declared_names(fields), CycleColumns::NAMES);
    let sample = between(
        &header,
        "lugre_loop_sample(const struct LugreLoop *hl,",
        ";",
    );
    let names = declared_names(sample);
    assert_eq!(names[0], "n");
    assert_eq!(names[1..], LoopPoint::COLUMNS);
    // The turning points' length stands beside them (as `default_values`, `default_len`).
    let friction_loop = between(
        &header,
        "typedef struct LugreFrictionLoop {",
        "} LugreFrictionLoop;",
    );
    let mut names = declared_names(friction_loop);
    let at = names.iter().position(|n| n == "turning_points");
    let len = at.and_then(|k| names.get(k + 1));
    assert_eq!(
        len.map(String::as_str),
        Some("turning_points_len"),
        "{names:?}"
    );
    names.remove(at.unwrap_or_default() + 1);
    assert_eq!(names, FrictionLoop::FIELDS, "LugreFrictionLoop");
}

#[test]
fn the_mex_gateways_columns_are_the_cores() {
    let mex = read("../../matlab/lugre_mex.c");
    let cycles = between(&mex, "static mxArray *cycles_struct(", "\n}\n");
    let names = between(cycles, "static const char *names[] = {", "};");
    assert_eq!(
        strings(names),
        CycleColumns::NAMES,
        "lugre_mex.c, cycles_struct"
    );
    let curve = between(&mex, "static const char *curve_names[] = {", "};");
    assert_eq!(
        strings(curve),
        LoopPoint::COLUMNS,
        "lugre_mex.c, the loop's curve"
    );
    let loops = between(&mex, "static const char *loop_names[FIELDS] = {", "};");
    assert_eq!(
        strings(loops),
        FrictionLoop::FIELDS,
        "lugre_mex.c, the dynamics' loops"
    );
}
