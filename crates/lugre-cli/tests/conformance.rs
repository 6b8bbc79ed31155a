//! The conformance table (`tests/conformance/cases.json`, format in its README) through the
//! command line and the C ABI: every case that names `cli` runs the built `lugre` with its
//! `cli` arguments, every case that names `c` builds the same request through `lugre_c`'s
//! functions from its `fields`; an accepted case's numbers must be the CLI's `--json` to the
//! last bit (`same`) and pass its `checks`, a refused one must be refused with the message of
//! `error`, spelled as each front end spells it. Python and the FMUs run the same table in
//! `tests/conformance/test_conformance.py`, Octave's MEX functions in
//! `tests/conformance/conformance.m`.

#[path = "conformance/c_abi.rs"]
mod c_abi;
mod common;
#[path = "conformance/table.rs"]
mod table;

use std::io::Write;
use std::process::Command;

use serde_json::Value;
use table::{Case, Failure, Outcome};

/// The CLI's answer: its JSON document on stdout, or the message of its one line on stderr.
fn run_cli(case: &Case, dir: &std::path::Path) -> Outcome {
    let args = case.cli_args(dir);
    let out = Command::new(env!("CARGO_BIN_EXE_lugre"))
        .args(&args)
        .output()
        .expect("the binary runs");
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    match out.status.code() {
        Some(0) => {
            assert!(stderr.is_empty(), "{}: stderr {stderr}", case.id);
            let text = String::from_utf8(out.stdout).expect("UTF-8");
            if text.trim().is_empty() {
                // A command that writes files only (the output-policy cases).
                return Ok(Value::Null);
            }
            // Not JSON: the table's command line lacks --json (shown as the text it printed).
            Ok(serde_json::from_str(&text).unwrap_or(Value::String(text)))
        }
        Some(2) => {
            let lines: Vec<&str> = stderr.lines().collect();
            assert_eq!(lines.len(), 1, "{}: one line on stderr: {stderr}", case.id);
            assert!(out.stdout.is_empty(), "{}: nothing on stdout", case.id);
            let message = lines[0]
                .strip_prefix("lugre: error: ")
                .unwrap_or_else(|| panic!("{}: not 'lugre: error: ': {stderr}", case.id));
            Err(Failure::new("value", message))
        }
        other => panic!("{}: exit status {other:?}: {stderr}", case.id),
    }
}

#[test]
fn every_case_through_the_cli_and_the_c_abi() {
    let cases = table::load();
    assert!(cases.len() >= 60, "{} cases", cases.len());
    let mut ran = [0usize; 2];
    let mut failed = Vec::new();
    for case in &cases {
        let dir = common::TempDir::new(&format!("conformance-{}", case.id));
        let cli = case.applies("cli").then(|| run_cli(case, dir.path()));
        if let Some(got) = &cli {
            ran[0] += 1;
            failed.extend(case.judge("cli", got, None, dir.path()));
        }
        if case.applies("c") {
            ran[1] += 1;
            let got = c_abi::run(case);
            failed.extend(case.judge("c", &got, cli.as_ref(), dir.path()));
        }
    }
    // Straight to stderr, past the test harness's capture: the count shows in every run.
    let _ = writeln!(
        std::io::stderr(),
        "conformance: {} cases through the CLI, {} through the C ABI ({} in the table)",
        ran[0],
        ran[1],
        cases.len()
    );
    assert!(
        failed.is_empty(),
        "{} failed:\n{}",
        failed.len(),
        failed.join("\n")
    );
}

/// The set `friction_loops` compares every field of a run's loops
/// (`lugre::dynamics::FrictionLoop::FIELDS`): a field the core adds or renames fails here
/// until the table, and so every front end, has it.
#[test]
fn the_friction_loop_set_is_every_field_of_the_cores_loops() {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/conformance/cases.json");
    let table: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let set = table["sets"]["friction_loops"].as_array().expect("the set");
    let fields: Vec<&str> = set
        .iter()
        .filter_map(Value::as_str)
        .filter_map(|p| p.strip_prefix("loops[]."))
        .map(|p| p.trim_end_matches("[]"))
        .collect();
    assert_eq!(fields, lugre::dynamics::FrictionLoop::FIELDS);
}
