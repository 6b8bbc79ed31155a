//! Every command line of the README's text blocks runs as written and prints what the README
//! shows: `$ cargo run --release -- ARGS` and `$ lugre ARGS` lines are run with this build's
//! binary (the same program) from the repository's root, and the lines after each are matched
//! against its output (stdout, then stderr). In the README's output, a line `...` stands for any
//! number of lines, and `[...]` or `{...}` inside a line for any text. A command whose input
//! files the README only describes (`data.csv`, `d.csv`) runs on the file the README describes,
//! made in a scratch folder.

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

/// The README's commands with their shown output.
fn examples(readme: &str) -> Vec<(usize, String, Vec<String>)> {
    let mut out: Vec<(usize, String, Vec<String>)> = Vec::new();
    let mut in_text = false;
    // Whether the lines go to the last command (a block's end ends its output).
    let mut open = false;
    for (i, line) in readme.lines().enumerate() {
        if line.starts_with("```") {
            in_text = line == "```text";
            open = false;
            continue;
        }
        if !in_text {
            continue;
        }
        let command = line
            .strip_prefix("$ cargo run --release -- ")
            .or_else(|| line.strip_prefix("$ lugre "));
        match command {
            Some(c) => {
                // A trailing `# comment` is the README's, not the command's.
                let c = c.split("  #").next().unwrap_or(c).trim();
                out.push((i + 1, c.to_string(), Vec::new()));
                open = true;
            }
            None if open => {
                if let Some(last) = out.last_mut() {
                    last.2.push(line.trim_end().to_string());
                }
            }
            None => {}
        }
    }
    out
}

/// Splits a command line at blanks, keeping 'quoted' and "quoted" words together.
fn words(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut word = String::new();
    let mut quote = None;
    let mut any = false;
    for c in line.chars() {
        match (quote, c) {
            (Some(q), c) if c == q => quote = None,
            (None, '\'' | '"') => {
                quote = Some(c);
                any = true;
            }
            (None, c) if c.is_whitespace() => {
                if any {
                    out.push(std::mem::take(&mut word));
                    any = false;
                }
            }
            (_, c) => {
                word.push(c);
                any = true;
            }
        }
    }
    if any {
        out.push(word);
    }
    out
}

/// Whether `got` matches the README's `want` line (`[...]` and `{...}` stand for any text).
fn line_matches(want: &str, got: &str) -> bool {
    let parts: Vec<&str> = want.split("[...]").flat_map(|p| p.split("{...}")).collect();
    if parts.len() == 1 {
        return want == got;
    }
    let mut rest = got;
    for (k, part) in parts.iter().enumerate() {
        let found = if k == 0 {
            rest.starts_with(part).then_some(0)
        } else if k == parts.len() - 1 {
            rest.ends_with(part).then(|| rest.len() - part.len())
        } else {
            rest.find(part)
        };
        match found {
            Some(at) => rest = &rest[at + part.len()..],
            None => return false,
        }
    }
    true
}

/// Whether the output lines `got` match `want`, where a `...` line skips any lines.
fn matches(want: &[String], got: &[&str]) -> bool {
    match want.split_first() {
        None => got.is_empty(),
        Some((w, rest)) if w == "..." => (0..=got.len()).any(|k| matches(rest, &got[k..])),
        Some((w, rest)) => got
            .split_first()
            .is_some_and(|(g, more)| line_matches(w, g) && matches(rest, more)),
    }
}

/// The files the README's commands read but only describes, made in `dir`.
fn scratch_inputs(dir: &Path) {
    // "$ lugre fit --input data.csv  # ... here Example 4's loop": 2001 samples of the loop.
    let hl = lugre::HysteresisLoop::new(
        lugre::LuGre::paper()
            .with_sigma0(6.0)
            .unwrap()
            .rate_independent(),
        &lugre::TurningPoints::new(&[0.0, 1.0, 0.5, 1.5]).unwrap(),
    )
    .unwrap();
    let mut fit = String::from("u,F\n");
    for p in hl.sample(2001) {
        fit.push_str(&format!("{:?},{:?}\n", p.u, p.y));
    }
    std::fs::write(dir.join("fit-data.csv"), fit).unwrap();
    // "$ lugre cycles --input data.csv": line 4 repeats the time of line 3.
    std::fs::write(dir.join("data.csv"), "t,u\n0,0\n1,1\n1,2\n").unwrap();
    std::fs::write(dir.join("d.csv"), "u,F\n0,0\n1,1\n0,0\n").unwrap();
}

#[test]
fn every_readme_command_prints_what_the_readme_shows() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    let dir = common::TempDir::new("readme");
    scratch_inputs(dir.path());
    let mut failures = Vec::new();
    let all = examples(&readme);
    assert!(all.len() >= 15, "{} commands found", all.len());
    for (line, command, want) in &all {
        let mut args = words(command);
        // The described files: the fit example reads Example 4's loop, the others their own.
        let mut cwd = root.clone();
        if args.iter().any(|a| a == "data.csv" || a == "d.csv") {
            cwd = dir.path().to_path_buf();
            if args[0] == "fit" && args.iter().any(|a| a == "data.csv") {
                for a in args.iter_mut().filter(|a| *a == "data.csv") {
                    *a = "fit-data.csv".into();
                }
            }
        }
        let out = Command::new(env!("CARGO_BIN_EXE_lugre"))
            .args(&args)
            .current_dir(&cwd)
            .output()
            .unwrap();
        let text = String::from_utf8_lossy(&out.stdout).into_owned()
            + &String::from_utf8_lossy(&out.stderr);
        let text = text.replace("fit-data.csv", "data.csv");
        let got: Vec<&str> = text
            .lines()
            .map(str::trim_end)
            .filter(|l| !l.is_empty())
            .collect();
        let mut want: Vec<String> = want.iter().filter(|l| !l.is_empty()).cloned().collect();
        // A one-line JSON document the README breaks over lines for reading.
        if got.len() == 1 && want.len() > 1 && want[0].starts_with('{') {
            want = vec![want.iter().map(|l| l.trim_start()).collect::<String>()];
        }
        if !matches(&want, &got) {
            failures.push(format!(
                "README line {line}: lugre {command}\n--- README ---\n{}\n--- printed ---\n{}",
                want.join("\n"),
                got.join("\n")
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}

#[test]
fn the_matcher_can_fail() {
    let want = |s: &[&str]| s.iter().map(|l| l.to_string()).collect::<Vec<_>>();
    assert!(matches(&want(&["a", "...", "d"]), &["a", "b", "c", "d"]));
    assert!(!matches(&want(&["a", "...", "d"]), &["a", "b", "c"]));
    assert!(!matches(&want(&["a", "b"]), &["a", "c"]));
    assert!(line_matches(
        "{\"t\":[...],\"x\":1}",
        "{\"t\":[1,2],\"x\":1}"
    ));
    assert!(!line_matches(
        "{\"t\":[...],\"x\":1}",
        "{\"t\":[1,2],\"x\":2}"
    ));
    assert_eq!(words("a 'b c' \"d\""), ["a", "b c", "d"]);
}
