//! The crate's dependency rules, checked on its source (`lugre_test_support::layout`): they keep
//! the layout readable as it grows (see the map of the crate in `lib.rs`).
//!
//! * `kernel` and `error` are leaves: they import nothing of the crate;
//! * the engines — `loops`, `cycles`, `simulate`, `fit`, `dynamics` — do not import each other, except
//!   `fit`, which builds on `loops` (the slow loop) and `simulate` (the full fit), and `dynamics`,
//!   whose friction-displacement loops are the rainflow cycles (`cycles`) of a run beside the
//!   rate-independent loop (`loops`), sampled at `simulate`'s evenly spaced times, and
//!   `sweep`, whose periodic orbits are integrated by `simulate`'s solvers;
//! * no two modules import each other, directly or through others.

use lugre_test_support::layout::{cycles, module_graph, Graph};
use std::path::Path;

fn graph() -> Graph {
    module_graph(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src"))
}

/// The rules' violations in `g`, one line each.
fn violations(g: &Graph) -> Vec<String> {
    let mut out = Vec::new();
    for leaf in ["kernel", "error"] {
        match g.get(leaf) {
            None => out.push(format!("module {leaf} is missing")),
            Some(deps) if !deps.is_empty() => out.push(format!(
                "{leaf} must import nothing of the crate, imports {deps:?}"
            )),
            Some(_) => {}
        }
    }
    let engines = ["loops", "cycles", "simulate", "fit", "dynamics", "sweep"];
    let allowed = [
        ("sweep", "simulate"),
        ("fit", "loops"),
        ("fit", "simulate"),
        ("dynamics", "loops"),
        ("dynamics", "cycles"),
        ("dynamics", "simulate"),
    ];
    for from in engines {
        for to in engines {
            let imports = g.get(from).is_some_and(|d| d.contains(to));
            if from != to && imports && !allowed.contains(&(from, to)) {
                out.push(format!("{from} must not import {to}"));
            }
        }
    }
    for c in cycles(g) {
        out.push(format!(
            "modules import each other in a circle: {}",
            c.join(" <-> ")
        ));
    }
    out
}

#[test]
fn the_dependency_rules_hold() {
    let g = graph();
    let v = violations(&g);
    assert!(v.is_empty(), "{}\nthe graph: {g:#?}", v.join("\n"));
}

/// The rules catch each kind of violation (so the test above can fail): today's graph with one
/// of the old cycles put back.
#[test]
fn the_rules_catch_a_cycle_put_back() {
    let mut g = graph();
    // The old `hysteresis -> loop_table -> arc_energy -> hysteresis`: the kernel importing the
    // loops.
    g.get_mut("kernel").unwrap().insert("loops".into());
    let v = violations(&g);
    assert!(
        v.iter()
            .any(|l| l.starts_with("kernel must import nothing")),
        "{v:?}"
    );
    assert!(v.iter().any(|l| l.contains("circle")), "{v:?}");
    // The old `error <-> simulate`.
    let mut g = graph();
    g.get_mut("error").unwrap().insert("simulate".into());
    assert!(violations(&g)
        .iter()
        .any(|l| l.starts_with("error must import nothing")));
    // An engine importing another.
    let mut g = graph();
    g.get_mut("simulate").unwrap().insert("loops".into());
    assert!(violations(&g).contains(&"simulate must not import loops".to_string()));
}
