//! `lugre fit --fit stribeck|presliding|staged` run as a user would: the real binary on the
//! example data of `examples/data/` (written by `examples/data/make_lab_experiments.py`, an
//! independent generator: scipy's Radau at rtol 1e-10 on the LuGre model with the parameters
//! of Canudas de Wit et al. (1995)), its stdout, stderr, files and exit status.

use std::path::PathBuf;

mod common;
use common::{accepts, accepts_json, f, rejects, TempDir};

/// The truth of the example data (the preset `canudas1995`).
const TRUTH: [(&str, f64); 7] = [
    ("sigma0", 1e5),
    ("sigma1", 316.227_766_016_837_94),
    ("sigma2", 0.4),
    ("fc", 1.0),
    ("fs", 1.5),
    ("vs", 1e-3),
    ("beta", 2.0),
];

fn data(name: &str) -> String {
    let p: PathBuf = [
        env!("CARGO_MANIFEST_DIR"),
        "..",
        "..",
        "examples",
        "data",
        name,
    ]
    .iter()
    .collect();
    p.to_str().expect("UTF-8 path").to_string()
}

fn truth(name: &str) -> f64 {
    TRUTH
        .iter()
        .find(|(n, _)| *n == name)
        .expect("a parameter")
        .1
}

/// Each named estimate within `rel` of the truth, and its 95 % interval covering the truth.
#[track_caller]
fn recovers(doc: &serde_json::Value, names: &[&str], rel: f64) {
    for &name in names {
        let p = &doc["parameters"][name];
        let (value, lo, hi) = (f(&p["value"]), f(&p["ci95"][0]), f(&p["ci95"][1]));
        let want = truth(name);
        assert!(
            ((value - want) / want).abs() < rel,
            "{name}: {value} vs {want}"
        );
        assert!(
            lo <= want && want <= hi,
            "{name}: [{lo}, {hi}] misses {want}"
        );
    }
}

#[test]
fn stribeck_from_a_table_recovers_the_curve() {
    let table = data("lab-stribeck-table.csv");
    let doc = accepts_json(&[
        "fit", "--fit", "stribeck", "--input", &table, "--beta", "2", "--json",
    ]);
    assert_eq!(doc["fit"], "stribeck");
    recovers(&doc, &["fc", "fs", "vs", "sigma2"], 0.02);
    assert_eq!(doc["points"].as_array().map(Vec::len), Some(48));
    assert_eq!(f(&doc["fixed"]["beta"]), 2.0);
    // The table: each parameter with its interval.
    let text = accepts(&["fit", "--fit", "stribeck", "--input", &table, "--beta", "2"]);
    assert!(text.contains("Stribeck fit"), "{text}");
    assert!(text.contains("95 % confidence interval"), "{text}");
}

#[test]
fn stribeck_writes_its_points_and_figure() {
    let dir = TempDir::new("fit-lab-files");
    let (csv, svg, png) = (dir.join("p.csv"), dir.join("s.svg"), dir.join("s.png"));
    let table = data("lab-stribeck-table.csv");
    for plot in [&svg, &png] {
        accepts(&[
            "fit", "--fit", "stribeck", "--input", &table, "--beta", "2", "--csv", &csv, "--plot",
            plot,
        ]);
    }
    let text = std::fs::read_to_string(&csv).expect("the CSV");
    assert!(text.starts_with("v,F,stderr,fit,residual\n"), "{text}");
    assert_eq!(text.lines().count(), 49);
    assert!(std::fs::read_to_string(&svg)
        .expect("svg")
        .contains("speed |v|"));
    assert!(std::fs::read(&png).expect("png").starts_with(b"\x89PNG"));
}

#[test]
fn stribeck_bad_input_is_one_line() {
    let dir = TempDir::new("fit-lab-bad");
    let few = dir.file("few.csv", "v,F\n0.001,1.2\n-0.001,-1.2\n0.01,1.01\n");
    rejects(
        &["fit", "--fit", "stribeck", "--input", &few, "--beta", "2"],
        "3 constant-velocity points for 4 free parameter(s): the Stribeck fit needs at least 5",
    );
    let zero = dir.file(
        "zero.csv",
        "v,F\n0,1.2\n-0.001,-1.2\n0.01,1.01\n0.1,1.05\n1,1.4\n",
    );
    rejects(
        &["fit", "--fit", "stribeck", "--input", &zero, "--beta", "2"],
        "velocity 0",
    );
    let table = data("lab-stribeck-table.csv");
    rejects(
        &[
            "fit", "--fit", "stribeck", "--input", &table, "--beta", "2", "--free", "sigma0",
        ],
        "sigma0 does not enter the steady-state friction",
    );
    rejects(
        &[
            "fit", "--fit", "stribeck", "--input", &table, "--beta", "2", "--x0", "0",
        ],
        "--x0 applies to the full fit",
    );
    rejects(
        &["fit", "--fit", "stribeck", "--input", &table],
        "beta is held in the stribeck fit but has no value",
    );
}

#[test]
fn stribeck_from_a_record_finds_the_runs() {
    let record = data("lab-stribeck.csv");
    let doc = accepts_json(&[
        "fit", "--fit", "stribeck", "--input", &record, "--beta", "2", "--json",
    ]);
    recovers(&doc, &["fc", "fs", "vs", "sigma2"], 0.02);
    let runs = doc["plateaus"]["runs"].as_array().expect("the runs");
    assert_eq!(runs.len(), 48, "24 speeds, both signs");
    // The slowest run's transient (about 1 s of its 3 s) is dropped.
    assert!(f(&runs[0]["t_start"]) > 0.5, "{}", runs[0]);
    for r in runs {
        assert!(f(&r["samples"]) >= 10.0, "{r}");
    }
}

#[test]
fn records_without_usable_runs_are_one_line() {
    let dir = TempDir::new("fit-lab-records");
    // A sine: the velocity never stays constant (near its extremes, for a few samples: the
    // line says the runs are too short, or that there are none).
    let mut sine = String::from("t,u,F\n");
    for i in 0..400 {
        let t = f64::from(i) * 0.01;
        sine.push_str(&format!(
            "{t},{},{}\n",
            (3.0 * t).sin() * 1e-3,
            (3.0 * t).cos()
        ));
    }
    let sine = dir.file("sine.csv", sine);
    rejects(
        &["fit", "--fit", "stribeck", "--input", &sine, "--beta", "2"],
        "constant-velocity run",
    );
    // The lab's sine record: runs at its peak speed only.
    let lab_sine = data("lab-sine.csv");
    rejects(
        &[
            "fit", "--fit", "stribeck", "--input", &lab_sine, "--beta", "2",
        ],
        "distinct speed(s)",
    );
    // Runs of 6 samples.
    let short = runs(6, 0.0);
    let short = dir.file("short.csv", short);
    rejects(
        &["fit", "--fit", "stribeck", "--input", &short, "--beta", "2"],
        "the constant-velocity runs are too short",
    );
    // Noise of 3 N on a 1 N force.
    let noisy = runs(50, 3.0);
    let noisy = dir.file("noisy.csv", noisy);
    rejects(
        &["fit", "--fit", "stribeck", "--input", &noisy, "--beta", "2"],
        "the noise is larger than the signal",
    );
}

/// A record `t,u,F` of runs at +-1, 2, 4 mm/s, `per_run` samples each at 100 Hz, with a force
/// of sgn(v) N plus a deterministic wiggle of amplitude `wiggle`.
fn runs(per_run: usize, wiggle: f64) -> String {
    let mut text = String::from("t,u,F\n");
    let (mut u, mut k) = (0.0, 0);
    for v in [1e-3f64, -1e-3, 2e-3, -2e-3, 4e-3, -4e-3] {
        for _ in 0..per_run {
            let w = wiggle * (f64::from(k) * 2.399).sin();
            text.push_str(&format!("{},{u},{}\n", f64::from(k) * 0.01, v.signum() + w));
            u += v * 0.01;
            k += 1;
        }
    }
    text
}

/// The Stribeck curve of the example data, held in the presliding fit.
const CURVE: [&str; 10] = [
    "--fc", "1", "--fs", "1.5", "--vs", "1e-3", "--beta", "2", "--sigma2", "0.4",
];

#[test]
fn presliding_recovers_sigma0_and_sigma1() {
    let test = data("lab-presliding.csv");
    let mut args = vec!["fit", "--fit", "presliding", "--input", &test, "--json"];
    args.extend(CURVE);
    let doc = accepts_json(&args);
    assert_eq!(doc["fit"], "presliding");
    recovers(&doc, &["sigma0", "sigma1"], 0.02);
    assert_eq!(f(&doc["fixed"]["fs"]), 1.5);
}

#[test]
fn presliding_bad_input_is_one_line() {
    // The constant-velocity record slides.
    let record = data("lab-stribeck.csv");
    let mut args = vec!["fit", "--fit", "presliding", "--input", &record];
    args.extend(CURVE);
    rejects(&args, "the presliding test breaks away");
    // The Stribeck curve must be given (or come from the Stribeck fit: --fit staged).
    let test = data("lab-presliding.csv");
    rejects(
        &["fit", "--fit", "presliding", "--input", &test],
        "is held in the presliding fit but has no value",
    );
    // A sine of 1 mm slides far beyond the presliding range (its force stays below 0.9 Fs
    // and the linear spring is soft: the exact fit's sigma0 shows it).
    let sine = data("lab-sine.csv");
    let mut args = vec!["fit", "--fit", "presliding", "--input", &sine];
    args.extend(CURVE);
    rejects(&args, "the presliding test slides");
    let dir = TempDir::new("fit-lab-presliding");
    let untimed = dir.file("u.csv", "u,F\n0,0\n1e-6,0.1\n0,0\n-1e-6,-0.1\n");
    let mut args = vec!["fit", "--fit", "presliding", "--input", &untimed];
    args.extend(CURVE);
    rejects(&args, "needs the samples' times");
}

#[test]
fn staged_runs_the_three_experiments() {
    let (stribeck, presliding) = (data("lab-stribeck.csv"), data("lab-presliding.csv"));
    let base = [
        "fit",
        "--fit",
        "staged",
        "--stribeck",
        &stribeck,
        "--presliding",
        &presliding,
        "--beta",
        "2",
        "--json",
    ];
    let doc = accepts_json(&base);
    assert_eq!(doc["fit"], "staged");
    recovers(
        &doc,
        &["sigma0", "sigma1", "fc", "fs", "vs", "sigma2"],
        0.02,
    );
    assert_eq!(doc["parameters"]["sigma0"]["stage"], "presliding");
    assert_eq!(doc["parameters"]["fs"]["stage"], "stribeck");
    // With the final full fit: the record cannot determine sigma2 (its speeds are low), which
    // stays the Stribeck stage's.
    let sine = data("lab-sine.csv");
    let doc = accepts_json(&[&base[..], &["--input", &sine]].concat());
    assert_eq!(doc["parameters"]["fs"]["stage"], "full");
    assert_eq!(doc["parameters"]["sigma2"]["stage"], "stribeck");
    for name in ["sigma0", "sigma1", "fc", "fs", "vs"] {
        let value = f(&doc["parameters"][name]["value"]);
        assert!(
            ((value - truth(name)) / truth(name)).abs() < 0.02,
            "{name}: {value}"
        );
    }
    rejects(
        &[
            "fit",
            "--fit",
            "staged",
            "--stribeck",
            &stribeck,
            "--beta",
            "2",
        ],
        "--fit staged needs --stribeck FILE",
    );
    rejects(
        &[
            "fit",
            "--fit",
            "staged",
            "--stribeck",
            &presliding,
            "--presliding",
            &presliding,
            "--beta",
            "2",
        ],
        "lab-presliding.csv: the constant-velocity runs are too short",
    );
    rejects(
        &[
            "fit",
            "--fit",
            "full",
            "--stribeck",
            &stribeck,
            "--input",
            &sine,
        ],
        "--stribeck gives a record of the staged fit",
    );
}
