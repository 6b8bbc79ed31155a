//! The models of the core's zoo table (`lugre::zoo::MODELS`) through `lugre loop`, with no
//! model-specific code in the CLI: each is a `--model` value listed in `--help`, runs on its
//! defaults alone, echoes every parameter by name in its JSON, takes its parameters from flags
//! generated from the table, and gives the core's loops (compared with the library's own
//! result for the same request); bad requests get one line.

mod common;

use common::{accepts, accepts_json, f, rejects};
use lugre::zoo::{Shape, ZooModel, MODELS};
use lugre::TurningPoints;

const TURNING: &str = "3,1,2,-3,-1,-2";

#[test]
fn every_model_of_the_table_is_listed_and_runs_on_its_defaults() {
    let help = accepts(&["loop", "--help"]);
    let input = TurningPoints::new(&[3.0, 1.0, 2.0, -3.0, -1.0, -2.0]).unwrap();
    for spec in MODELS {
        assert!(help.contains(spec.name), "--help lists {}", spec.name);
        let doc = accepts_json(&[
            "loop",
            "--model",
            spec.name,
            "--turning-points",
            TURNING,
            "--json",
        ]);
        assert_eq!(doc["model"]["kind"], spec.name);
        for p in spec.parameters {
            let echoed = &doc["model"][p.name];
            let values: Vec<f64> = match p.shape {
                Shape::Scalar => vec![f(echoed)],
                Shape::Elements => echoed.as_array().unwrap().iter().map(f).collect(),
            };
            assert_eq!(values, p.default, "{}: {}", spec.name, p.name);
        }
        let want = ZooModel::new(spec.name, &[])
            .unwrap()
            .loops(&input)
            .unwrap();
        let loops = doc["loops"].as_array().unwrap();
        assert_eq!(loops.len(), want.loops().len());
        for (got, want) in loops.iter().zip(want.loops()) {
            for (key, value) in [
                ("work", want.energy.work),
                ("stored_energy_change", want.energy.stored_energy_change),
                ("dissipation", want.energy.dissipation),
                ("closure_gap", want.energy.closure_gap),
            ] {
                assert_eq!(f(&got[key]), value, "{}: {key}", spec.name);
            }
        }
    }
}

#[test]
fn the_parameters_come_from_flags_generated_from_the_table() {
    let doc = accepts_json(&[
        "loop",
        "--model",
        "maxwell-slip",
        "--stiffness",
        "1,2",
        "--slip-force",
        "1,0.5",
        "--turning-points",
        TURNING,
        "--json",
        "--samples",
        "5",
    ]);
    assert_eq!(doc["model"]["stiffness"], serde_json::json!([1.0, 2.0]));
    // Both elements slip on the major loop: F(3) = 1 + 0.5.
    assert_eq!(f(&doc["turning_points"][0]["y"]), 1.5);
    assert_eq!(doc["points"].as_array().unwrap().len(), 5);
    let doc = accepts_json(&[
        "loop",
        "--model",
        "prandtl-ishlinskii",
        "--linear-weight",
        "2",
        "--thresholds",
        "0.5",
        "--weights",
        "1",
        "--turning-points",
        "1,-1",
        "--json",
    ]);
    // F = 2 u + p, p(1) = 0.5 on the periodic loop: 2.5; the loop runs counterclockwise.
    assert_eq!(f(&doc["turning_points"][0]["y"]), 2.5);
    assert!(f(&doc["work_per_period"]) < 0.0);
}

#[test]
fn bad_requests_of_the_zoo_get_one_line() {
    rejects(
        &["loop", "--model", "maxwell-slip", "--sigma0", "1", "--turning-points", TURNING],
        "--sigma0 is not a parameter of the Maxwell-slip model (its parameters: --stiffness, --slip-force, --fc, --vs, --beta, --attraction, --sigma1, --sigma2)",
    );
    rejects(
        &["loop", "--stiffness", "1", "--turning-points", TURNING],
        "--stiffness is a parameter of --model maxwell-slip: add that --model",
    );
    rejects(
        &[
            "loop",
            "--model",
            "maxwell-slip",
            "--stiffness",
            "1,-2",
            "--slip-force",
            "1,1",
            "--turning-points",
            TURNING,
        ],
        "stiffness[1] must be > 0, got -2",
    );
    rejects(
        &[
            "loop",
            "--model",
            "maxwell-slip",
            "--preset",
            "canudas1995",
            "--turning-points",
            TURNING,
        ],
        "--preset is a LuGre parameter set; the Maxwell-slip model takes --stiffness, --slip-force",
    );
    rejects(
        &[
            "loop",
            "--model",
            "prandtl-ishlinskii",
            "--linear-weight",
            "1,2",
            "--turning-points",
            TURNING,
        ],
        "linear_weight takes one value, got 2",
    );
    rejects(
        &["simulate", "--model", "maxwell-slip", "--sine", "1,1"],
        "--sine is an option of LuGre's and Dahl's simulation; the Maxwell-slip model is simulated from rest at the input's own samples",
    );
    rejects(
        &["loop", "--model", "bouc", "--turning-points", TURNING],
        "bouc",
    );
}

#[test]
fn cycles_of_a_history_along_every_model_of_the_table() {
    let values = [0.0, 4.0, 1.0, 3.0, -4.0, -1.0, -3.0, 4.0, 0.0];
    let text = "0,4,1,3,-4,-1,-3,4,0";
    for spec in MODELS {
        let doc = accepts_json(&["cycles", "--model", spec.name, "--values", text, "--json"]);
        assert_eq!(doc["model"]["kind"], spec.name);
        let mut history = lugre::cycles::count_cycles(&values, 0.0).unwrap();
        let model = ZooModel::new(spec.name, &[]).unwrap();
        let totals = model.cycle_energies(&values, &mut history.cycles);
        assert_eq!(f(&doc["history"]["work"]), totals.work, "{}", spec.name);
        assert_eq!(f(&doc["history"]["dissipation"]), totals.dissipation);
        let full: Vec<&lugre::Cycle> = history.cycles.iter().filter(|c| c.is_full()).collect();
        let got: Vec<&serde_json::Value> = doc["cycles"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|c| f(&c["count"]) == 1.0)
            .collect();
        assert_eq!(got.len(), full.len());
        for (g, c) in got.iter().zip(&full) {
            let e = c.energy.unwrap();
            assert_eq!(f(&g["work"]), e.arc.work, "{}", spec.name);
            assert_eq!(f(&g["closure_gap"]), e.arc.closure_gap);
        }
    }
    rejects(
        &["cycles", "--model", "maxwell-slip", "--x0", "1", "--values", text],
        "--x0: x0 is the initial bristle state of LuGre and Dahl; the Maxwell-slip model starts from rest",
    );
}

/// The README's claim: Bouc-Wen with sigma = 1, n = 1, kx = 0 is the Dahl model (rho, Fc = kw),
/// whose loop LuGre's engine computes: the same numbers to 1e-14.
#[test]
fn bouc_wen_at_sigma_one_is_the_dahl_model() {
    let tp = "4,1,3,-4";
    let bw = accepts_json(&[
        "loop",
        "--model",
        "bouc-wen",
        "--sigma",
        "1",
        "--turning-points",
        tp,
        "--json",
    ]);
    let dahl = accepts_json(&[
        "loop",
        "--model",
        "dahl",
        "--rho",
        "0.5",
        "--fc",
        "2",
        "--turning-points",
        tp,
        "--json",
    ]);
    let close = |a: &serde_json::Value, b: &serde_json::Value| {
        assert!(
            (f(a) - f(b)).abs() <= 1e-14 * f(b).abs().max(1.0),
            "{a} vs {b}"
        );
    };
    for (a, b) in bw["turning_points"]
        .as_array()
        .unwrap()
        .iter()
        .zip(dahl["turning_points"].as_array().unwrap())
    {
        close(&a["y"], &b["y"]);
    }
    for (a, b) in bw["loops"]
        .as_array()
        .unwrap()
        .iter()
        .zip(dahl["loops"].as_array().unwrap())
    {
        for key in ["work", "stored_energy_change", "dissipation", "closure_gap"] {
            close(&a[key], &b[key]);
        }
    }
}

/// Every parameter of every model of the table has a flag in `--help` whose help gives the
/// model and the default (its own flag, or the LuGre/Dahl flag of the same name with "also").
#[test]
fn every_parameter_of_the_table_is_a_flag_with_its_default() {
    let help = accepts(&["loop", "--help"]);
    for spec in MODELS {
        for p in spec.parameters {
            let flag = format!("--{} ", p.name.replace('_', "-"));
            let line = help
                .lines()
                .find(|l| l.trim_start().starts_with(&flag))
                .unwrap_or_else(|| panic!("{flag}in --help"));
            let default: Vec<String> = p
                .default
                .iter()
                .map(|v| format!("{}", (v * 1e10).round() / 1e10))
                .collect();
            let own = format!("({}; default {})", spec.label, default.join(","));
            // A flag several models share lists them after "also", `; `-separated.
            let shared = format!("{}, default {}", spec.label, default.join(","));
            let also = line.split_once("also ").map_or("", |(_, rest)| rest);
            let listed = also.split("; ").any(|m| m.starts_with(&shared));
            assert!(line.contains(&own) || listed, "{line}");
        }
    }
}
