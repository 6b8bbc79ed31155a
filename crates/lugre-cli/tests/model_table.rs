//! The model's flags and the model's line in every text output, against the core's table
//! (`lugre::model::Parameter`): every parameter is a flag of every command that takes a model,
//! under "Model", with its symbol, domain, unit, model and default in its help, and its value
//! read back by name; every text output names the model and marks the defaults. And the
//! columns of cycles and loops (`lugre::Cycle::COLUMNS`, `lugre::LoopPoint::COLUMNS`) are those
//! `--csv` and `--json` write.

mod common;

use common::{lugre, rejects};
use lugre::model::Parameter;
use lugre::{Cycle, LoopPoint};

/// The commands that take the model's flags.
const COMMANDS: [&str; 5] = ["loop", "cycles", "simulate", "fit", "dynamics"];

fn stdout(args: &[&str]) -> String {
    let out = lugre(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// The help of `--flag` in `text` (a `--help` page): from its line up to the next flag or
/// blank line, on one line.
fn flag_help(text: &str, flag: &str) -> Option<String> {
    let mut lines = text.lines().skip_while(|l| {
        !l.trim_start()
            .strip_prefix(flag)
            .is_some_and(|rest| rest.starts_with(' '))
    });
    let first = lines.next()?;
    let rest = lines.take_while(|l| !l.trim().is_empty() && !l.trim_start().starts_with("--"));
    Some(
        std::iter::once(first)
            .chain(rest)
            .map(str::trim)
            .collect::<Vec<_>>()
            .join(" "),
    )
}

/// `x` as the help and the model's line print it.
fn shown(x: f64) -> String {
    format!("{x}")
}

#[test]
fn every_parameter_of_the_table_is_a_flag_with_its_unit_default_and_domain() {
    for command in COMMANDS {
        let help = stdout(&[command, "--help"]);
        let model = help
            .find("\nModel:\n")
            .unwrap_or_else(|| panic!("lugre {command} --help: no heading Model"));
        let mut at = model;
        for p in Parameter::ALL {
            let flag = format!("--{}", p.name());
            let line = flag_help(&help[model..], &flag)
                .unwrap_or_else(|| panic!("lugre {command} --help: no {flag} under Model"));
            // In the table's order, under the heading.
            let here = help[model..].find(&format!("{flag} <")).unwrap() + model;
            assert!(
                here > at,
                "lugre {command}: {flag} out of the table's order"
            );
            at = here;
            let mut want = vec![
                format!("{} {}", p.symbol(), p.domain().condition()),
                format!("default {})", shown(p.default_value())),
            ];
            if p.unit() != "1" {
                want.push(format!("[{}]", p.unit()));
            }
            for w in want {
                assert!(
                    line.contains(&w),
                    "lugre {command} {flag}: wanted '{w}' in '{line}'"
                );
            }
            let desc = p.description();
            assert!(
                line.to_lowercase().contains(&desc.to_lowercase()),
                "lugre {command} {flag}: wanted '{desc}' in '{line}'"
            );
        }
    }
}

/// A value for `p` that is not its default and lies in its domain.
fn other_value(p: Parameter) -> f64 {
    p.default_value() + 0.75
}

#[test]
fn every_flag_is_read_back_by_name() {
    for (model, parameters) in [("lugre", &Parameter::LUGRE[..]), ("dahl", &Parameter::DAHL)] {
        for &p in parameters {
            let value = shown(other_value(p));
            let flag = format!("--{}", p.name());
            let text = stdout(&[
                "loop",
                "--model",
                model,
                &flag,
                &value,
                "--turning-points",
                "0,1",
                "--json",
            ]);
            let j: serde_json::Value = serde_json::from_str(&text).unwrap();
            assert_eq!(j["model"]["kind"], model);
            for &q in parameters {
                let want = if q == p {
                    other_value(q)
                } else {
                    q.default_value()
                };
                assert_eq!(j["model"][q.name()], want, "{model} {flag}: {}", q.name());
            }
        }
    }
    // A flag of the other model is refused, naming it.
    rejects(
        &[
            "loop",
            "--model",
            "dahl",
            "--beta",
            "2",
            "--turning-points",
            "0,1",
        ],
        "--beta is a LuGre parameter; the Dahl model takes --rho and --fc",
    );
}

/// The first line of `lugre loop` with `flags`.
fn loop_model_line(flags: &[&str]) -> String {
    let mut args = vec!["loop", "--turning-points", "0,1"];
    args.extend_from_slice(flags);
    stdout(&args).lines().next().unwrap().to_string()
}

#[test]
fn the_model_line_marks_the_defaults_and_says_which_parameters_act() {
    // Nothing given: every value is the table's default, marked.
    let line = loop_model_line(&[]);
    assert!(line.starts_with("LuGre: "), "{line}");
    for p in Parameter::LUGRE {
        let want = format!("{} = {}*", p.symbol(), shown(p.default_value()));
        assert!(line.contains(&want), "wanted '{want}' in {line}");
    }
    assert!(line.contains("(* default)"), "{line}");
    // The slow loop: sigma0 and g(0) = Fs alone act.
    let acting: Vec<&str> = Parameter::LUGRE_RATE_INDEPENDENT
        .iter()
        .map(|p| p.symbol())
        .collect();
    assert!(
        line.ends_with(&format!(
            "; only {} act on the rate-independent loop",
            acting.join(" and ")
        )),
        "{line}"
    );
    // A value given is not marked; the others still are.
    let line = loop_model_line(&["--sigma0", "1e5", "--fs", "1.5"]);
    assert!(
        line.contains("sigma0 = 100000,") && line.contains("Fs = 1.5,"),
        "{line}"
    );
    assert!(line.contains("sigma1 = 1*"), "{line}");
    // A preset gives every value: nothing is a default.
    let line = loop_model_line(&["--preset", "canudas1995"]);
    assert!(
        line.starts_with("LuGre (preset canudas1995): sigma0 = 100000,"),
        "{line}"
    );
    assert!(!line.contains('*'), "{line}");
    // Dahl: both parameters act on the loop.
    let line = loop_model_line(&["--model", "dahl", "--rho", "3"]);
    assert!(
        line.starts_with("Dahl: rho = 3, Fc = 1* (* default)"),
        "{line}"
    );
    assert!(!line.contains("only"), "{line}");
}

#[test]
fn every_text_output_names_its_model() {
    // simulate at a finite rate: every parameter acts.
    let text = stdout(&["simulate", "--turning-points", "0,1", "--sigma0", "6"]);
    let line = text.lines().next().unwrap();
    assert!(line.starts_with("LuGre: sigma0 = 6, sigma1 = 1*"), "{line}");
    assert!(!line.contains("only"), "{line}");
    // ... and at gamma = inf only those of y*.
    let text = stdout(&["simulate", "--turning-points", "0,1", "--gamma", "inf"]);
    assert!(
        text.lines()
            .next()
            .unwrap()
            .contains("; only sigma0 and Fs act"),
        "{text}"
    );
    // cycles with energies.
    let dir = std::env::temp_dir().join(format!("lugre-model-table-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("h.csv");
    std::fs::write(&path, "u\n0\n1\n-1\n2\n-2\n0\n").unwrap();
    let input = path.to_str().unwrap();
    let text = stdout(&["cycles", "--input", input, "--sigma0", "1e5", "--fs", "1.5"]);
    // sigma0 and Fs as given, every other parameter of the table at its default, marked.
    let values: Vec<String> = Parameter::LUGRE
        .iter()
        .map(|&p| match p {
            Parameter::Sigma0 => "sigma0 = 100000".to_string(),
            Parameter::Fs => "Fs = 1.5".to_string(),
            p => format!("{} = {}*", p.symbol(), shown(p.default_value())),
        })
        .collect();
    let want = format!(
        "\nLuGre: {} (* default); only sigma0 and Fs act on the rate-independent loop\n",
        values.join(", ")
    );
    assert!(text.contains(&want), "wanted {want} in {text}");
    std::fs::remove_dir_all(&dir).unwrap();
    // dynamics: the scenario's model, or the one the flags name.
    let text = stdout(&["dynamics", "--scenario", "breakaway"]);
    assert!(
        text.contains("\nLuGre (the scenario's, Table I): sigma0 = 100000, "),
        "{text}"
    );
    let text = stdout(&[
        "dynamics",
        "--scenario",
        "breakaway",
        "--preset",
        "canudas1995",
        "--fs",
        "2",
    ]);
    assert!(
        text.contains("\nLuGre (preset canudas1995): sigma0 = 100000,"),
        "{text}"
    );
    assert!(text.contains(", Fs = 2, "), "{text}");
}

#[test]
fn the_columns_of_cycles_and_loops_are_the_cores() {
    let dir = std::env::temp_dir().join(format!("lugre-columns-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let history = dir.join("h.csv");
    std::fs::write(&history, "u\n-2\n1\n-3\n5\n-1\n3\n-4\n4\n-2\n").unwrap();
    let cycles_csv = dir.join("cycles.csv");
    let loop_csv = dir.join("loop.csv");
    let text = stdout(&[
        "cycles",
        "--input",
        history.to_str().unwrap(),
        "--preset",
        "canudas1995",
        "--csv",
        cycles_csv.to_str().unwrap(),
        "--json",
    ]);
    let csv = std::fs::read_to_string(&cycles_csv).unwrap();
    assert_eq!(csv.lines().next(), Some(Cycle::COLUMNS.join(",").as_str()));
    // Every row has a cell for every column; the full cycle (-1, 3) has all of them.
    for row in csv.lines().skip(1) {
        assert_eq!(row.split(',').count(), Cycle::COLUMNS.len(), "{row}");
    }
    assert!(
        csv.lines()
            .skip(1)
            .any(|r| r.split(',').all(|c| !c.is_empty())),
        "{csv}"
    );
    let j: serde_json::Value = serde_json::from_str(&text).unwrap();
    for c in j["cycles"].as_array().unwrap() {
        let mut keys: Vec<&str> = c.as_object().unwrap().keys().map(|k| k.as_str()).collect();
        let mut want = Cycle::COLUMNS.to_vec();
        keys.sort_unstable();
        want.sort_unstable();
        assert_eq!(keys, want);
    }
    // In the columns' order in the text itself.
    let first = &text[text.find("\"cycles\":[{").unwrap()..];
    let at: Vec<usize> = Cycle::COLUMNS
        .iter()
        .map(|name| first.find(&format!("\"{name}\":")).unwrap())
        .collect();
    assert!(at.windows(2).all(|w| w[0] < w[1]), "{at:?}");
    stdout(&[
        "loop",
        "--turning-points",
        "0,1",
        "--csv",
        loop_csv.to_str().unwrap(),
    ]);
    let csv = std::fs::read_to_string(&loop_csv).unwrap();
    assert_eq!(
        csv.lines().next(),
        Some(LoopPoint::COLUMNS.join(",").as_str())
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
