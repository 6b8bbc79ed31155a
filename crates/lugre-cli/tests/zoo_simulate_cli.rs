//! `lugre simulate --model NAME` for every model of the zoo table, with no model-specific
//! code in the CLI: the JSON echoes the model and has LuGre's `t`, `u`, `y`; the force is the
//! core's `ZooModel::simulate` of the same samples; LuGre's own flags are refused by name.

mod common;

use common::{accepts, accepts_json, f, rejects, TempDir};
use lugre::zoo::{ZooModel, MODELS};

fn column(doc: &serde_json::Value, name: &str) -> Vec<f64> {
    doc[name].as_array().unwrap().iter().map(f).collect()
}

#[test]
fn every_model_simulates_turning_points_on_its_defaults() {
    for spec in MODELS {
        let doc = accepts_json(&[
            "simulate",
            "--model",
            spec.name,
            "--turning-points",
            "3,1,2,-3",
            "--speed",
            "0.5",
            "--json",
        ]);
        assert_eq!(doc["model"]["kind"], spec.name);
        for p in spec.parameters {
            assert!(!doc["model"][p.name].is_null(), "{}: {}", spec.name, p.name);
        }
        let (t, u, y) = (column(&doc, "t"), column(&doc, "u"), column(&doc, "y"));
        let want = ZooModel::new(spec.name, &[])
            .unwrap()
            .simulate(&t, &u)
            .unwrap();
        assert_eq!(y, want, "{}", spec.name);
    }
}

#[test]
fn elastoplastic_from_a_record_at_finite_rate() {
    let dir = TempDir::new("zoo-simulate");
    let path = dir.path().join("motion.csv");
    std::fs::write(&path, "t,u\n0,0\n0.5,1\n1,2.5\n2,-1\n2.2,-1.5\n").unwrap();
    let file = path.to_str().unwrap();
    let args = ["simulate", "--model", "elastoplastic", "--sigma1", "2"];
    let doc = accepts_json(&[&args[..], &["--input", file, "--json"]].concat());
    let model = ZooModel::new("elastoplastic", &[("sigma1", &[2.0])]).unwrap();
    let t = [0.0, 0.5, 1.0, 2.0, 2.2];
    let u = [0.0, 1.0, 2.5, -1.0, -1.5];
    assert_eq!(column(&doc, "y"), model.simulate(&t, &u).unwrap());
    assert_eq!(doc["model"]["sigma1"], 2.0);
    // The table and the CSV.
    let csv = dir.path().join("out.csv");
    let table = accepts(
        &[
            &args[..],
            &["--input", file, "--csv", csv.to_str().unwrap()],
        ]
        .concat(),
    );
    assert!(table.contains("Elasto-plastic: sigma0 = 1") && table.contains("from rest"));
    let written = std::fs::read_to_string(&csv).unwrap();
    assert!(written.starts_with("t,u,y\n") && written.lines().count() == 6);
}

#[test]
fn bad_requests_get_one_line() {
    let tp = ["--turning-points", "3,1,2,-3"];
    let zoo = |extra: &[&str]| -> Vec<String> {
        ["simulate", "--model", "bouc-wen"]
            .iter()
            .chain(tp.iter())
            .chain(extra)
            .map(|s| s.to_string())
            .collect()
    };
    let run = |extra: &[&str], want: &str| {
        let args = zoo(extra);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        rejects(&args, want);
    };
    run(
        &["--x0", "0.1"],
        "--x0 is an option of LuGre's and Dahl's simulation; the Bouc-Wen model is simulated",
    );
    run(&["--gamma", "10"], "--gamma is an option of LuGre's");
    run(&["--rho", "-1"], "rho must be a finite number > 0");
    run(
        &["--slip-force", "1"],
        "--slip-force is not a parameter of the Bouc-Wen model",
    );
    let dir = TempDir::new("zoo-simulate-bad");
    let path = dir.path().join("bad.csv");
    std::fs::write(&path, "t,u\n0,0\n1,1\n1,2\n").unwrap();
    rejects(
        &[
            "simulate",
            "--model",
            "elastoplastic",
            "--input",
            path.to_str().unwrap(),
        ],
        "bad.csv",
    );
}
