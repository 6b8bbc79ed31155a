//! The command line's dependency rules, checked on its source (`lugre_test_support::layout`):
//!
//! * only `cli.rs` names the commands (it parses and dispatches);
//! * the commands do not import each other; what two of them share lives in `args`, `io`,
//!   `plot`, `hysteresis`, `fmt` or `numbers`;
//! * those shared modules import neither `cli` nor `commands`;
//! * no two modules import each other, directly or through others.

use lugre_test_support::layout::{cycles, module_graph, submodule_graph, Graph};
use std::path::{Path, PathBuf};

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

fn violations(top: &Graph, commands: &Graph) -> Vec<String> {
    let mut out = Vec::new();
    for (m, deps) in top {
        if m != "cli" && deps.contains("commands") {
            out.push(format!(
                "only cli.rs names the commands, but {m} imports commands"
            ));
        }
        if m != "commands" && deps.contains("cli") {
            out.push(format!("{m} must not import cli"));
        }
    }
    if top.get("commands").is_some_and(|d| d.contains("cli")) {
        out.push("commands must not import cli".into());
    }
    for (c, deps) in commands {
        for d in deps {
            out.push(format!("command {c} must not import command {d}"));
        }
    }
    for c in cycles(top) {
        out.push(format!(
            "modules import each other in a circle: {}",
            c.join(" <-> ")
        ));
    }
    out
}

#[test]
fn the_dependency_rules_hold() {
    let (top, commands) = (module_graph(&src()), submodule_graph(&src(), "commands"));
    assert!(commands.len() >= 5, "the commands: {commands:?}");
    let v = violations(&top, &commands);
    assert!(v.is_empty(), "{}\n{top:#?}\n{commands:#?}", v.join("\n"));
}

/// The rules catch each kind of violation: the old `paper -> loop` import and the old
/// `cli <-> *_cmd` circle put back.
#[test]
fn the_rules_catch_what_was_there_before() {
    let (top, commands) = (module_graph(&src()), submodule_graph(&src(), "commands"));
    let mut c = commands.clone();
    c.get_mut("paper").unwrap().insert("loops".into());
    assert!(violations(&top, &c).contains(&"command paper must not import command loops".into()));
    let mut t = top.clone();
    t.get_mut("args").unwrap().insert("commands".into());
    let v = violations(&t, &commands);
    assert!(
        v.iter()
            .any(|l| l.starts_with("only cli.rs names the commands")),
        "{v:?}"
    );
    assert!(v.iter().any(|l| l.contains("circle")), "{v:?}");
}
