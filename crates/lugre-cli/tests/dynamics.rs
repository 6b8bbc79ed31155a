//! `lugre dynamics` through the real binary: the scenarios' headline numbers against the
//! independent reference (`crates/lugre/tests/reference/dynamics/`), the JSON document, files,
//! and bad input.

mod common;
use common::{accepts, accepts_json, f, rejects};

/// The slip onsets of the reference (scipy Radau at rtol 1e-12; README there), s.
const SLIP_ONSETS: [f64; 4] = [
    7.645395363948738,
    14.008115185014645,
    20.370835006080426,
    26.73355482714638,
];
const PERIOD: f64 = 6.362719821065907;

#[test]
fn stick_slip_prints_the_slip_onsets_and_the_period() {
    let out = accepts(&["dynamics", "--scenario", "stick-slip"]);
    assert!(out.contains("slip onsets"), "{out}");
    assert!(out.contains("period:"), "{out}");
    let j = accepts_json(&["dynamics", "--scenario", "stick-slip", "--json"]);
    let onsets: Vec<f64> = j["slip_onsets"].as_array().unwrap().iter().map(f).collect();
    assert_eq!(onsets.len(), 4);
    for (got, want) in onsets.iter().zip(SLIP_ONSETS) {
        assert!((got - want).abs() / PERIOD < 1e-6, "{got} vs {want}");
    }
    assert!((f(&j["period"]) - PERIOD).abs() / PERIOD < 1e-6);
    for key in ["t", "x", "v", "z", "friction", "drive", "events", "stats"] {
        assert!(j.get(key).is_some(), "{key}");
    }
    assert_eq!(j["t"].as_array().unwrap().len(), 1001);
    assert!(j["events"][0]["kind"].is_string());
}

#[test]
fn breakaway_under_a_force_ramp() {
    // Reference at r = 5 N/s: t = 0.2696877519509, F = 1.313208595797, x = 3.4265831633e-5.
    let j = accepts_json(&[
        "dynamics",
        "--scenario",
        "breakaway",
        "--force-rate",
        "5",
        "--json",
    ]);
    let b = &j["breakaway"];
    assert!((f(&b["t"]) - 0.2696877519509).abs() / 0.27 < 1e-6, "{b}");
    assert!((f(&b["force"]) - 1.313208595797).abs() / 1.5 < 1e-6, "{b}");
    assert!((f(&b["x"]) - 3.4265831633e-5).abs() / 3.4e-5 < 1e-6, "{b}");
}

#[test]
fn a_system_from_flags() {
    // The stick-slip scenario spelled out: the same slip onsets.
    let j = accepts_json(&[
        "dynamics",
        "--preset",
        "canudas1995",
        "--mass",
        "1",
        "--spring",
        "2",
        "--pull",
        "0.1",
        "--t-end",
        "30",
        "--samples",
        "11",
        "--json",
    ]);
    let onsets: Vec<f64> = j["slip_onsets"].as_array().unwrap().iter().map(f).collect();
    assert!((onsets[0] - SLIP_ONSETS[0]).abs() < 1e-5, "{onsets:?}");
    assert_eq!(j["t"].as_array().unwrap().len(), 11);
    // A PID with a stepping set point and a force profile run.
    accepts(&[
        "dynamics",
        "--preset",
        "canudas1995",
        "--pid",
        "3,4,6",
        "--setpoint",
        "0:1,20:0",
        "--t-end",
        "40",
    ]);
    accepts(&[
        "dynamics",
        "--preset",
        "canudas1995",
        "--force-profile",
        "0:0,10:1.425,15:1.425",
        "--t-end",
        "15",
        "--times",
        "5,10,15",
    ]);
}

#[test]
fn csv_and_plot_files() {
    let dir = std::env::temp_dir().join(format!("lugre-dynamics-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (csv, png) = (dir.join("m.csv"), dir.join("m.png"));
    accepts(&[
        "dynamics",
        "--scenario",
        "pid",
        "--samples",
        "51",
        "--csv",
        csv.to_str().unwrap(),
        "--plot",
        png.to_str().unwrap(),
    ]);
    let text = std::fs::read_to_string(&csv).unwrap();
    assert!(text.starts_with("t,x,v,z,friction,drive\n"));
    assert_eq!(text.lines().count(), 52);
    assert!(std::fs::metadata(&png).unwrap().len() > 1000);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_force_history_from_a_file_is_the_same_drive_as_its_profile() {
    let dir = std::env::temp_dir().join(format!("lugre-dynamics-input-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (good, no_f, no_t) = (dir.join("f.csv"), dir.join("u.csv"), dir.join("nt.csv"));
    // Columns in any order, one ignored; the run ends at the last time.
    std::fs::write(&good, "F,note,t\n0,a,0\n1.425,b,10\n1.425,c,15\n").unwrap();
    std::fs::write(&no_f, "t,u\n0,1\n").unwrap();
    std::fs::write(&no_t, "F\n0\n1\n").unwrap();
    let common = [
        "dynamics",
        "--preset",
        "canudas1995",
        "--times",
        "5,10,15",
        "--json",
    ];
    let from_file = accepts_json(&[&common[..], &["--input", good.to_str().unwrap()]].concat());
    let from_profile = accepts_json(
        &[
            &common[..],
            &["--force-profile", "0:0,10:1.425,15:1.425", "--t-end", "15"],
        ]
        .concat(),
    );
    assert_eq!(from_file, from_profile);
    rejects(
        &["dynamics", "--input", no_f.to_str().unwrap()],
        "no column F (F, force, friction or y) in the header 't,u'",
    );
    rejects(
        &[
            "dynamics",
            "--input",
            no_t.to_str().unwrap(),
            "--t-end",
            "1",
        ],
        "line 1: no column t (t or time) in the header 'F'",
    );
    rejects(
        &[
            "dynamics",
            "--input",
            good.to_str().unwrap(),
            "--force-profile",
            "0:0,1:1",
        ],
        "not both",
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_input_is_one_line() {
    rejects(&["dynamics", "--t-end", "1"], "no drive");
    rejects(
        &["dynamics", "--scenario", "pid", "--mass", "0"],
        "--mass must be a finite number > 0",
    );
    rejects(&["dynamics", "--scenario", "pid", "--mass", "-2"], "--mass");
    rejects(
        &["dynamics", "--force-rate", "1"],
        "name the friction model (--preset",
    );
    rejects(
        &["dynamics", "--force-rate", "1", "--preset", "canudas1995"],
        "give --t-end",
    );
    rejects(
        &[
            "dynamics",
            "--force-rate",
            "1",
            "--fs",
            "1.5",
            "--t-end",
            "1",
        ],
        "give --sigma0, --sigma1, --fc, --vs, --beta too, or --preset canudas1995",
    );
    rejects(
        &[
            "dynamics",
            "--preset",
            "canudas1995",
            "--force-rate",
            "1",
            "--t-end",
            "-1",
        ],
        "--t-end must be",
    );
    rejects(
        &[
            "dynamics",
            "--preset",
            "canudas1995",
            "--spring",
            "2",
            "--t-end",
            "1",
        ],
        "--spring needs --pull or --end-profile",
    );
    rejects(
        &["dynamics", "--spring", "-2", "--pull", "1", "--t-end", "1"],
        "--spring must be a finite number >= 0, got -2",
    );
    rejects(
        &["dynamics", "--scenario", "stick-slip", "--damping", "-1"],
        "--damping must be a finite number >= 0, got -1",
    );
    rejects(&["dynamics", "--pid", "3,nan,6", "--t-end", "1"], "--pid");
    rejects(
        &[
            "dynamics",
            "--scenario",
            "pid",
            "--force-profile",
            "0:0,1:1,1:2",
            "--t-end",
            "2",
        ],
        "--force-profile: times must be strictly increasing",
    );
    rejects(
        &["dynamics", "--scenario", "pid", "--rtol", "2"],
        "--rtol must be a number in (0, 1), got 2",
    );
    rejects(
        &[
            "dynamics",
            "--scenario",
            "pid",
            "--times",
            "1,200",
            "--t-end",
            "100",
        ],
        "outside the run",
    );
    rejects(
        &[
            "dynamics",
            "--scenario",
            "pid",
            "--times",
            "1",
            "--samples",
            "3",
        ],
        "not both",
    );
    rejects(
        &["dynamics", "--model", "dahl", "--preset", "canudas1995"],
        "--preset",
    );
}

/// The pre-sliding scenario reports its friction-displacement loop: x from the first hold's
/// reversal down to the second's and back. Its rate-independent twin against the closed form
/// of a two-point loop worked by hand (ascending branch `y = g0 - (g0 + Y) exp(-a rho)` from
/// `-Y` to `Y = g0 tanh(a L / 2)`, the descending one its mirror):
/// `W = 2 (g0 L - (g0 + Y)(1 - exp(-a L)) / a)`, `a = sigma0 / g0`, `L` the loop's span. The
/// dynamic loop's work differs from it by the rate effect of the 0.1425 N/s ramps (1.26e-3,
/// falling like the rate: `crates/lugre/tests/dynamics.rs`).
#[test]
fn presliding_reports_its_friction_displacement_loop() {
    let out = accepts(&["dynamics", "--scenario", "presliding"]);
    assert!(out.contains("friction-displacement loops"), "{out}");
    assert!(out.contains("lugre loop"), "{out}");
    let j = accepts_json(&["dynamics", "--scenario", "presliding", "--json"]);
    let (l, tp) = the_one_loop(&j);
    // Table I: sigma0 = 1e5 N/m, g0 = Fs = 1.5 N.
    let (g0, a) = (1.5, 1e5 / 1.5);
    let span = (tp[0] - tp[1]).abs();
    let y = g0 * (0.5 * a * span).tanh();
    let closed_form = 2.0 * (g0 * span + (g0 + y) * (-a * span).exp_m1() / a);
    let ri = f(&l["rate_independent_work"]);
    assert!(
        (ri - closed_form).abs() <= 1e-12 * closed_form,
        "{ri} vs {closed_form}"
    );
    // The turning points: the holds' displacements (reference x_max 4.5311842e-5 m at the end
    // of a hold, plus the ringing of ~1e-11 m; x_min -1.00174e-5 m).
    assert!(
        (tp[0] - 4.53118e-5).abs() < 1e-10 && (tp[1] + 1.00174e-5).abs() < 1e-10,
        "{tp:?}"
    );
    let (w, dv, d) = (
        f(&l["work"]),
        f(&l["bristle_energy_change"]),
        f(&l["dissipation"]),
    );
    assert!(d > 0.0 && (w - dv - d).abs() <= 1e-15 * w);
    let rate_effect = (w - ri) / ri;
    assert!((1.1e-3..1.4e-3).contains(&rate_effect), "{rate_effect:e}");
    assert!(f(&l["t_start"]) < f(&l["t_turn"]) && f(&l["t_turn"]) < f(&l["t_close"]));
    // Asked for on another run: the stick-slip's x only grows, no loop closes.
    let j = accepts_json(&["dynamics", "--scenario", "stick-slip", "--loops", "--json"]);
    assert!(j["loops"].as_array().unwrap().is_empty());
}

/// `--loops` with GMS friction (`--model maxwell-slip`, the pre-sliding scenario on Table I's
/// scale): the loop of x between the holds, its work split into the elements' stored energy
/// change and the dissipation, beside the Maxwell-slip model's slow loop on the same turning
/// points, worked by hand: over the range `R` each element with `2 f_i / k_i < R` slips both
/// ways, dissipating `2 f_i (R - 2 f_i / k_i)`. The dynamic loop's work is within 0.3 % of it
/// (the rate effect of the ramps, 0.15 %: `crates/lugre/tests/dynamics_gms.rs` shows it fall
/// like the rate).
#[test]
fn gms_friction_reports_its_friction_displacement_loop() {
    let j = accepts_json(&[
        "dynamics",
        "--model",
        "maxwell-slip",
        "--scenario",
        "presliding",
        "--loops",
        "--samples",
        "3",
        "--json",
    ]);
    let (l, tp) = the_one_loop(&j);
    let range = tp[0] - tp[1];
    let by_hand: f64 = [1.0, 3.0, 5.0, 7.0]
        .iter()
        .map(|n| {
            let (fi, ki) = (1.5 * n / 16.0, 2.5e4);
            2.0 * fi * (range - 2.0 * fi / ki).max(0.0)
        })
        .sum();
    let ri = f(&l["rate_independent_work"]);
    assert!((ri - by_hand).abs() <= 1e-12 * by_hand, "{ri} vs {by_hand}");
    let (w, dv, d) = (
        f(&l["work"]),
        f(&l["bristle_energy_change"]),
        f(&l["dissipation"]),
    );
    assert!(d > 0.0 && (w - dv - d).abs() <= 1e-15 * w, "{l}");
    assert!(dv.abs() < 1e-4 * w, "{l}");
    assert!(w > ri && (w - ri) < 3e-3 * ri, "{w} vs {ri}");
    // The summary says it too.
    let out = accepts(&[
        "dynamics",
        "--model",
        "maxwell-slip",
        "--scenario",
        "presliding",
    ]);
    assert!(out.contains("friction-displacement loops (closed"), "{out}");
}

/// The reproductions of the one-request issue: the PID experiment with new gains keeps its set
/// point; two applied forces, a list for one set point and an unbounded sample count are one
/// line naming the flags.
#[test]
fn flags_on_a_scenario_replace_its_fields() {
    for gains in ["3,8,6", "3,4,6"] {
        let j = accepts_json(&[
            "dynamics",
            "--scenario",
            "pid",
            "--pid",
            gains,
            "--t-end",
            "40",
            "--samples",
            "5",
            "--json",
        ]);
        let x = f(j["x"].as_array().unwrap().last().unwrap());
        assert!((x - 1.0).abs() < 0.15, "--pid {gains}: x(40) = {x}");
    }
    let j = accepts_json(&[
        "dynamics",
        "--scenario",
        "pid",
        "--setpoint",
        "2",
        "--t-end",
        "60",
        "--samples",
        "3",
        "--json",
    ]);
    let x = f(j["x"].as_array().unwrap().last().unwrap());
    assert!((x - 2.0).abs() < 0.15, "--setpoint 2: x(60) = {x}");
    rejects(
        &[
            "dynamics",
            "--preset",
            "canudas1995",
            "--force-rate",
            "10",
            "--force-profile",
            "0:1",
            "--t-end",
            "1",
        ],
        "give --force-rate or --force-profile, not both",
    );
    rejects(
        &["dynamics", "--scenario", "pid", "--setpoint", "1,2"],
        "--setpoint takes 1 number, got 2",
    );
    rejects(
        &[
            "dynamics",
            "--scenario",
            "pid",
            "--samples",
            "1000000000000",
        ],
        "--samples must be a whole number from 2 to 10000000, got 1000000000000",
    );
    rejects(
        &["dynamics", "--scenario", "presliding", "--setpoint", "1"],
        "--setpoint needs --pid",
    );
    // The lag experiment ends at 1.885 s; output times to 2 s run it to 2 s.
    let j = accepts_json(&[
        "dynamics",
        "--scenario",
        "lag",
        "--times",
        "0,0.5,1,1.5,2",
        "--json",
    ]);
    assert_eq!(j["t"].as_array().unwrap().len(), 5);
    // A prescribed velocity's drive is M v' + F, not 0.
    let j = accepts_json(&["dynamics", "--scenario", "lag", "--samples", "11", "--json"]);
    let drive: Vec<f64> = j["drive"].as_array().unwrap().iter().map(f).collect();
    assert!(drive.iter().all(|d| *d > 0.5), "{drive:?}");
}

/// `--model elastoplastic` through the zoo's flags: on a scenario over Table I, the positions
/// of the core's scipy reference (`crates/lugre/tests/reference/dynamics/elastoplastic_dynamics.py`,
/// Radau at rtol 1e-12: x at 8, 10 and 15 s of stick-slip with zba = 5e-6 m), the model echoed
/// by name, and the refusals in one line.
#[test]
fn elastoplastic_friction_from_the_zoo_flags() {
    // The stick-slip run sampled at the reference's times, with `zba` flags or none.
    let stick_slip = |zba: &[&str]| {
        let head = ["dynamics", "--model", "elastoplastic", "--scenario"];
        let tail = ["stick-slip", "--times", "0,8,10,15", "--rtol", "1e-11"];
        let args: Vec<&str> = head.iter().chain(&tail).chain(zba).copied().collect();
        let j = accepts_json(&[args.as_slice(), &["--json"]].concat());
        let x: Vec<f64> = j["x"].as_array().unwrap().iter().map(f).collect();
        (j, x)
    };
    let (j, x) = stick_slip(&["--zba", "5e-6"]);
    let want = [
        0.0,
        0.0721748171072542,
        0.6281298925070146,
        0.9142700510848314,
    ];
    for (got, want) in x.iter().zip(want) {
        assert!((got - want).abs() <= 1e-9, "{got} vs {want}");
    }
    let m = &j["model"];
    assert_eq!(m["kind"], "elastoplastic");
    assert_eq!(f(&m["zba"]), 5e-6);
    assert_eq!(f(&m["sigma0"]), 1e5);
    assert_eq!(f(&m["vs"]), 1e-3);
    // LuGre's runs name their law too.
    let j = accepts_json(&["dynamics", "--scenario", "lag", "--samples", "2", "--json"]);
    assert_eq!(j["model"]["kind"], "lugre");
    // Table I with zba not given: Fc / (2 sigma0) = 5e-6 m, the run above to the last bit.
    let (j, x2) = stick_slip(&[]);
    assert_eq!(f(&j["model"]["zba"]), 5e-6);
    assert_eq!(x, x2);
    // A zba given at or above Fc / sigma0 of Table I.
    rejects(
        &[
            "dynamics",
            "--model",
            "elastoplastic",
            "--scenario",
            "stick-slip",
            "--zba",
            "1e-5",
        ],
        "zba must be >= 0 and < fc / sigma0 = 0.00001",
    );
    rejects(
        &[
            "dynamics",
            "--model",
            "bouc-wen",
            "--scenario",
            "stick-slip",
        ],
        &format!(
            "model bouc-wen: the dynamics take {}",
            lugre::zoo::dynamics_model_names()
        ),
    );
    rejects(
        &["dynamics", "--scenario", "stick-slip", "--zba", "1e-6"],
        "--zba is a parameter of --model elastoplastic",
    );
}

/// `--model maxwell-slip` (GMS friction): on a scenario the elements take Table I's scale and
/// the scalars Table I's values; the positions are the core's scipy reference
/// (`crates/lugre/tests/reference/dynamics/gms_dynamics.py`, Radau at rtol 1e-12: x at 5, 8
/// and 10 s of stick-slip); the model is echoed by name with its elements; the energy balance
/// closes; flags given replace the scale.
#[test]
fn gms_friction_from_the_zoo_flags() {
    let j = accepts_json(&[
        "dynamics",
        "--model",
        "maxwell-slip",
        "--scenario",
        "stick-slip",
        "--times",
        "0,5,8,10",
        "--rtol",
        "1e-10",
        "--json",
    ]);
    let x: Vec<f64> = j["x"].as_array().unwrap().iter().map(f).collect();
    let want = [
        0.0,
        1.2486857109672413e-05,
        0.03147184263623526,
        0.640066030131164,
    ];
    for (got, want) in x.iter().zip(want) {
        assert!((got - want).abs() <= 1e-9, "{got} vs {want}");
    }
    let m = &j["model"];
    assert_eq!(m["kind"], "maxwell-slip");
    let k: Vec<f64> = m["stiffness"].as_array().unwrap().iter().map(f).collect();
    assert_eq!(k, [2.5e4; 4]);
    assert_eq!(f(&m["slip_force"][3]), 1.5 * 7.0 / 16.0);
    assert_eq!(f(&m["vs"]), 1e-3);
    assert_eq!(f(&m["attraction"]), 10.0);
    let e = &j["energy"];
    let residual =
        f(&e["input"]) - (f(&e["stored_end"]) - f(&e["stored_start"])) - f(&e["dissipated"]);
    assert!(residual.abs() < 1e-8 * f(&e["input"]), "{e}");
    // Elements given replace the scale; a parameter the model does not have is named.
    let j = accepts_json(&[
        "dynamics",
        "--model",
        "maxwell-slip",
        "--scenario",
        "breakaway",
        "--stiffness",
        "1e5",
        "--slip-force",
        "1.5",
        "--samples",
        "2",
        "--json",
    ]);
    assert_eq!(f(&j["model"]["stiffness"][0]), 1e5);
    assert!(f(&j["breakaway"]["force"]) > 1.0, "{}", j["breakaway"]);
    rejects(
        &[
            "dynamics",
            "--model",
            "maxwell-slip",
            "--scenario",
            "lag",
            "--zba",
            "1e-6",
        ],
        "--zba is not a parameter of the Maxwell-slip model",
    );
}

/// The run's one friction loop in `j` (checked to be the only one) and its two turning points.
fn the_one_loop(j: &serde_json::Value) -> (&serde_json::Value, Vec<f64>) {
    let loops = j["loops"].as_array().unwrap();
    assert_eq!(loops.len(), 1, "{loops:?}");
    let l = &loops[0];
    let tp: Vec<f64> = l["turning_points"]
        .as_array()
        .unwrap()
        .iter()
        .map(f)
        .collect();
    assert_eq!(tp.len(), 2);
    (l, tp)
}
