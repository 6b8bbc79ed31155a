//! Every command reads every data file that holds the columns it needs (the `lugre-io` reader):
//! a file one command writes reads back into the next where that makes sense, the usual lab
//! headers with units are read as they stand, and the mistakes `--columns`, `--scale`, `--fix`
//! and a header can hold are one line each.
//!
//! What reads back: `loop --csv` (`rho,u,y`: `rho` is the loop's parameter, not a time, so it
//! is ignored; `y`, the model's output, is the force `F`) into `fit` (the slow fit: it needs no
//! times), `loop --input` and `cycles`; `simulate --csv` (`t,u,z,dz,y`) into `simulate
//! --input`, `fit` and `cycles`; `dynamics --csv` (`t,x,v,z,friction,drive`: `x` the
//! displacement, `friction` the force) into `simulate --input` and `cycles`, and into
//! `dynamics --input` (`drive` the force applied).

mod common;
use common::{accepts, accepts_json, f, rejects, TempDir};

/// The column `name` of a CSV file the commands wrote.
fn column(path: &str, name: &str) -> Vec<f64> {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let k = header.iter().position(|h| *h == name).unwrap();
    lines
        .map(|l| l.split(',').nth(k).unwrap().parse().unwrap())
        .collect()
}

#[test]
fn a_loop_file_is_fitted_and_counted() {
    let dir = TempDir::new("data-files-loop");
    let csv = dir.join("loop.csv");
    // The loop's model, given to every command that computes one.
    fn with_model<'a>(args: &[&'a str]) -> Vec<&'a str> {
        [args, &["--sigma0", "3", "--fs", "1.5"]].concat()
    }
    accepts(&with_model(&[
        "loop",
        "--turning-points=-1,2",
        "--csv",
        &csv,
    ]));
    // The slow fit of the slow loop finds the loop's own parameters.
    let fit = accepts_json(&["fit", "--input", &csv, "--json"]);
    for (name, want) in [("sigma0", 3.0), ("fs", 1.5)] {
        let got = f(&fit["parameters"][name]["value"]);
        assert!((got - want).abs() <= 1e-9 * want, "{name}: {got}");
    }
    // rho is not a time: the full fit, which needs times, says so.
    rejects(
        &["fit", "--fit", "full", "--input", &csv],
        "a full fit needs the samples' times",
    );
    // loop --input reads its u (one period): the same loop as its turning points.
    let again = accepts_json(&with_model(&["loop", "--input", &csv, "--json"]));
    let direct = accepts_json(&with_model(&["loop", "--turning-points=-1,2", "--json"]));
    assert_eq!(again["turning_points"], direct["turning_points"]);
    // cycles counts its u.
    let c = accepts_json(&["cycles", "--input", &csv, "--json"]);
    assert_eq!(c["samples"], column(&csv, "u").len());
}

#[test]
fn a_simulated_record_drives_the_simulation_again() {
    let dir = TempDir::new("data-files-simulate");
    let (first, second) = (dir.join("first.csv"), dir.join("second.csv"));
    accepts(&[
        "simulate",
        "--turning-points",
        "0,1",
        "--periods",
        "2",
        "--csv",
        &first,
    ]);
    // t,u read (z, dz, y ignored): the same input, the same output.
    accepts(&["simulate", "--input", &first, "--csv", &second]);
    let (y1, y2) = (column(&first, "y"), column(&second, "y"));
    assert_eq!(y1.len(), y2.len());
    for (a, b) in y1.iter().zip(&y2) {
        assert!((a - b).abs() <= 1e-12 * (1.0 + a.abs()), "{a} vs {b}");
    }
    // y is the force: fit reads u,y with its times.
    let fit = accepts_json(&["fit", "--input", &first, "--json"]);
    assert_eq!(fit["samples"], y1.len());
    accepts(&["cycles", "--input", &first]);
}

#[test]
fn a_dynamics_run_is_a_record() {
    let dir = TempDir::new("data-files-dynamics");
    let csv = dir.join("run.csv");
    accepts(&["dynamics", "--scenario", "stick-slip", "--csv", &csv]);
    let x = column(&csv, "x");
    // x is the displacement (v beside it does not make it a velocity record).
    let c = accepts_json(&["cycles", "--input", &csv, "--json"]);
    assert_eq!(c["samples"], x.len());
    let s = accepts_json(&[
        "simulate",
        "--input",
        &csv,
        "--preset",
        "canudas1995",
        "--json",
    ]);
    assert_eq!(s["t"].as_array().unwrap().len(), x.len());
}

/// A `dynamics --csv` file drives `dynamics --input` with its `drive` column, the force applied:
/// the same run again (its `friction` column, also a force by name, is the result, not the
/// drive, unless `--columns F=friction` says so).
#[test]
fn a_dynamics_run_drives_the_dynamics_again() {
    let dir = TempDir::new("data-files-dynamics-again");
    let (first, second) = (dir.join("first.csv"), dir.join("second.csv"));
    accepts(&[
        "dynamics",
        "--scenario",
        "breakaway",
        "--samples",
        "6",
        "--csv",
        &first,
    ]);
    let times: Vec<String> = column(&first, "t").iter().map(|t| t.to_string()).collect();
    let times = times.join(",");
    let again = |extra: &[&str], out: &str| {
        let args = [
            &["dynamics", "--preset", "canudas1995", "--input", &first][..],
            &["--times", &times, "--csv", out][..],
            extra,
        ]
        .concat();
        accepts(&args);
    };
    again(&[], &second);
    assert_eq!(column(&second, "drive"), column(&first, "drive"));
    for (a, b) in column(&first, "friction")
        .iter()
        .zip(column(&second, "friction"))
    {
        assert!((a - b).abs() <= 1e-6 * (1.0 + a.abs()), "{a} vs {b}");
    }
    let third = dir.join("third.csv");
    again(&["--columns", "F=friction"], &third);
    assert_eq!(column(&third, "drive"), column(&first, "friction"));
}

/// `dynamics --input` with the usual names and units, tab-separated (it said "no column 'F'"):
/// the same run as from the plain `t,F` file.
#[test]
fn a_force_history_with_units() {
    let dir = TempDir::new("data-files-force");
    let rows = [("0", "0"), ("10", "1.425"), ("15", "1.425")];
    let file = |name: &str, head: &str, sep: &str| {
        let body: String = rows.iter().map(|(t, f)| format!("{t}{sep}{f}\n")).collect();
        dir.file(name, format!("{head}\n{body}"))
    };
    let units = file("force.tsv", "# applied force\ntime [s]\tforce [N]", "\t");
    let plain = file("force.csv", "t,F", ",");
    let run = |path: &str| {
        accepts_json(&[
            "dynamics",
            "--preset",
            "canudas1995",
            "--times",
            "5,10,15",
            "--input",
            path,
            "--json",
        ])
    };
    assert_eq!(run(&units), run(&plain));
}

#[test]
fn ambiguous_choices_are_refused() {
    let dir = TempDir::new("data-files-mistakes");
    let path = dir.file("lab.csv", "t,u,F\n0,0,0\n1,1,1\n2,0,0\n");
    for (args, want) in [
        (
            vec!["--columns", "t=2,u=2"],
            "line 1: column 2 ('u') would be read as both t and u: give each its own column with --columns",
        ),
        (
            vec!["--columns", "u=1,u=2"],
            "--columns: u is given twice (u=1 and u=2)",
        ),
        (
            vec!["--columns", "u=2,position=3"],
            "--columns: u is given twice (u=2 and u=3)",
        ),
        (
            vec!["--scale", "u=2,u=3"],
            "--scale: u is given twice (u=2 and u=3)",
        ),
    ] {
        for cmd in ["fit", "simulate", "cycles"] {
            rejects(&[&[cmd, "--input", &path][..], &args[..]].concat(), want);
        }
    }
    for (args, want) in [
        (
            ["--columns", "u=2,F=2"],
            "line 1: column 2 ('u') would be read as both u and F",
        ),
        (
            ["--fix", "fs=1,fs=2"],
            "--fix: 'fs' is given twice ('fs=1' and 'fs=2')",
        ),
        (
            ["--free", "sigma0,sigma0"],
            "--free: 'sigma0' is given twice",
        ),
        (
            ["--bounds", "sigma0=1:2,sigma0=3:4"],
            "--bounds: 'sigma0' is given twice",
        ),
    ] {
        rejects(&[&["fit", "--input", &path][..], &args[..]].concat(), want);
    }
    let twice = dir.file("twice.csv", "u,u,F\n0,0,0\n1,1,1\n");
    for cmd in ["fit", "cycles", "loop"] {
        rejects(
            &[cmd, "--input", &twice],
            "line 1: the header has two columns for u: 'u' (column 1) and 'u' (column 2)",
        );
    }
    // Said which: read.
    let c = accepts_json(&["cycles", "--input", &twice, "--columns", "u=2", "--json"]);
    assert_eq!(c["samples"], 2);
}
