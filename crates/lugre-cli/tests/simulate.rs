//! `lugre simulate` run as a user would: the real binary, its stdout, stderr, files and exit
//! status.

use std::path::PathBuf;

mod common;
use common::{lugre, rejects};

fn json(args: &[&str]) -> serde_json::Value {
    let out = lugre(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        out.stderr.is_empty(),
        "no progress bar when stderr is not a terminal"
    );
    serde_json::from_slice(&out.stdout).expect("valid JSON")
}

/// A column of the `--json` document.
fn column(doc: &serde_json::Value, key: &str) -> Vec<f64> {
    doc[key]
        .as_array()
        .unwrap_or_else(|| panic!("{key} is an array"))
        .iter()
        .map(|v| v.as_f64().expect("a number"))
        .collect()
}

/// A scratch directory of its own for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("lugre-simulate-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

// The paper's Example 3 at gamma = 10 from x0 = 0 over 3 periods: y just after each kink.
// mpmath, mp.dps = 50, the direct form of the exact solution on each unit-speed segment:
//   g = lambda v: 1 + exp(-abs(v)); z = 0; t = 0
//   for each segment (a, b) of 0 -> 1 -> 0.2 -> 1.5 -> 0, 3 times:
//       v = sign(b - a); k = 1 / g(v / 10); y = z + (v - k z) / 10   (sigma0 = sigma1 = 1)
//       z = v / k + (z - v / k) exp(-k |b - a|)
//   and at the end y with the first segment's slope (the input is periodic).
const EXAMPLE_3: [(f64, f64); 13] = [
    (0.0, 0.1),
    (1.0, 0.63715394063321472),
    (1.8, -0.034602270613191062),
    (3.1, 0.72471111272116768),
    (4.6, -0.50840590306539242),
    (5.6, 0.27724067433796044),
    (6.4, -0.27108607506828681),
    (7.7, 0.6052003081914327),
    (9.2, -0.56278272526372316),
    (10.2, 0.24507310398804884),
    (11.0, -0.29222202677889575),
    (12.3, 0.59451892305701796),
    (13.8, -0.56764270242287158),
];

#[test]
fn example_3_json_reproduces_the_exact_solution() {
    let doc = json(&[
        "simulate",
        "--gamma",
        "10",
        "--periods",
        "3",
        "--bimodal",
        "0,0.2,1,1.5",
        "--json",
    ]);
    let keys: Vec<&String> = doc.as_object().unwrap().keys().collect();
    assert_eq!(keys.len(), 5, "{keys:?}");
    let (t, u, y) = (column(&doc, "t"), column(&doc, "u"), column(&doc, "y"));
    for key in ["u", "z", "dz", "y"] {
        assert_eq!(column(&doc, key).len(), t.len(), "{key}");
    }
    // 200 samples per period and the turning points.
    assert_eq!(t.len(), 3 * 200 + 1 + 9);
    assert!(t.windows(2).all(|w| w[0] < w[1]));
    for (tk, yk) in EXAMPLE_3 {
        let i = t
            .iter()
            .position(|&x| (x - tk).abs() < 1e-12)
            .unwrap_or_else(|| panic!("t = {tk} is an output time"));
        assert!(
            (y[i] - yk).abs() <= lugre_test_support::prec::EXACT_SIMULATION * 2.0,
            "y({tk}) = {} vs {yk}",
            y[i]
        );
    }
    // u is the unit-speed input through the turning points: 1 at t = 1, 1.5 at t = 3.1 + 4.6,
    // and 0.92 on the grid at t = 4.6 * 40 / 200 = 0.92.
    let at = |tk: f64| t.iter().position(|&x| (x - tk).abs() < 1e-12).unwrap();
    assert!((u[at(1.0)] - 1.0).abs() < 1e-12);
    assert!((u[at(7.7)] - 1.5).abs() < 1e-12);
    assert!((u[at(0.92)] - 0.92).abs() < 1e-12);
}

#[test]
fn rate_independent_limit_decays_onto_the_loop() {
    // gamma = inf: y*_u. At the turning points of 0 <-> 1 (a = sigma0 / g(0) = 1/2, P = 2),
    // y* - y° = (sigma0 x0 - y°(0)) exp(-a rho), y° from `lugre loop`.
    let lp = json(&["loop", "--turning-points", "0,1", "--json"]);
    let y_loop: Vec<f64> = lp["turning_points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["y"].as_f64().unwrap())
        .collect();
    let x0 = 0.4;
    let doc = json(&[
        "simulate",
        "--gamma",
        "inf",
        "--turning-points",
        "0,1",
        "--periods",
        "3",
        "--x0",
        "0.4",
        "--times",
        "0,1,2,3,4,5,6",
        "--json",
    ]);
    let y = column(&doc, "y");
    for (k, &yk) in y.iter().enumerate() {
        let want = (x0 - y_loop[0]) * (-0.5 * k as f64).exp();
        let got = yk - y_loop[k % 2];
        assert!(
            (got - want).abs() < 1e-13 * 2.0,
            "rho = {k}: {got} vs {want}"
        );
    }
}

#[test]
fn dahl_model_and_initial_state() {
    // Dahl (rho = 2, Fc = 0.5) from w(0) = -0.5 (x0 = w(0) / rho = -0.25), up 0.5:
    // y = Fc (1 + (w0 - 1) exp(-rho 0.5)), at any gamma.
    let want = 0.5 * (1.0 + (-0.5 - 1.0) * (-1.0f64).exp());
    for gamma in ["1", "3", "inf"] {
        let doc = json(&[
            "simulate",
            "--model",
            "dahl",
            "--rho",
            "2",
            "--fc",
            "0.5",
            "--turning-points",
            "0,1",
            "--x0",
            "-0.25",
            "--gamma",
            gamma,
            "--times",
            "0.5",
            "--json",
        ]);
        let y = column(&doc, "y")[0];
        assert!((y - want).abs() < 1e-15, "gamma {gamma}: {y} vs {want}");
    }
}

#[test]
fn sampled_input_from_csv_and_csv_output() {
    let dir = scratch("csv");
    let input = dir.join("u.csv");
    std::fs::write(&input, "t,u\n0,0\n0.5,2e-6\n1.5,-1e-6\n2,0\n").unwrap();
    let output = dir.join("out.csv");
    let args = [
        "simulate",
        "--input",
        input.to_str().unwrap(),
        "--sigma0",
        "1e5",
        "--periods",
        "2",
        "--csv",
        output.to_str().unwrap(),
    ];
    let out = lugre(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("4 samples from"), "{text}");
    assert!(text.contains("7 rows"), "{text}");
    // The CSV: the header and one row per sample over two periods, the same numbers as --json.
    let csv = std::fs::read_to_string(&output).unwrap();
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some("t,u,z,dz,y"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    let mut json_args = args[..7].to_vec();
    json_args.push("--json");
    let doc = json(&json_args);
    assert_eq!(rows.len(), 7);
    for (j, key) in ["t", "u", "z", "dz", "y"].iter().enumerate() {
        let col = column(&doc, key);
        for (i, row) in rows.iter().enumerate() {
            assert_eq!(row[j], col[i], "{key}[{i}]");
        }
    }
    assert_eq!(column(&doc, "t"), vec![0.0, 0.5, 1.5, 2.0, 2.5, 3.5, 4.0]);
    // Nothing else was left in the directory (the write is atomic).
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names, ["out.csv", "u.csv"]);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn sine_input() {
    let doc = json(&[
        "simulate",
        "--sine",
        "1,4,0,0.5",
        "--gamma",
        "10",
        "--periods",
        "2",
        "--samples-per-period",
        "50",
        "--json",
    ]);
    let (t, u, y) = (column(&doc, "t"), column(&doc, "u"), column(&doc, "y"));
    assert_eq!(t.len(), 101);
    assert_eq!(t[100], 8.0);
    for i in 0..t.len() {
        let want = (std::f64::consts::TAU * t[i] / 4.0).sin() + 0.5;
        assert!((u[i] - want).abs() < 1e-15);
        assert!(y[i].abs() < 2.0 + 0.2, "|y| <= g(0) plus the sigma1 term");
    }
}

#[test]
fn human_output_is_a_summary_and_the_head_of_the_table() {
    let out = lugre(&[
        "simulate",
        "--gamma",
        "10",
        "--periods",
        "3",
        "--bimodal",
        "0,0.2,1,1.5",
    ]);
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    for want in [
        "LuGre: sigma0 = 1",
        "turning points 0,1,0.2,1.5",
        "gamma = 10 (eq. 5)",
        "3 periods",
        "610 rows",
        "just after",
        "590 more rows",
    ] {
        assert!(text.contains(want), "wanted '{want}' in\n{text}");
    }
    let out = lugre(&["simulate", "--gamma", "inf", "--turning-points", "0,1"]);
    assert!(String::from_utf8_lossy(&out.stdout).contains("rate-independent limit"));
}

#[test]
fn bad_requests_are_one_line_and_exit_2() {
    let dir = scratch("bad");
    let write = |name: &str, text: &str| {
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        p.to_str().unwrap().to_string()
    };
    let empty = write("empty.csv", "t,u\n");
    let backwards = write("back.csv", "t,u\n0,0\n1,1\n1,2\n");
    let u_only = write("u.csv", "u\n0\n1\n0\n");
    let open = write("open.csv", "t,u\n0,0\n1,1\n");
    let bimodal = ["--bimodal", "0,0.2,1,1.5"];
    let with = |extra: &[&str]| -> Vec<String> {
        let mut v = vec!["simulate".to_string()];
        v.extend(extra.iter().map(|s| s.to_string()));
        v
    };
    let cases: Vec<(Vec<String>, &str)> = vec![
        (
            with(&[&["--gamma", "0"][..], &bimodal].concat()),
            "gamma must be > 0",
        ),
        (
            with(&[&["--gamma", "-1"][..], &bimodal].concat()),
            "gamma must be > 0",
        ),
        (
            with(&[&["--gamma", "nan"][..], &bimodal].concat()),
            "--gamma must be a number > 0 or 'inf'",
        ),
        (
            with(&[&["--periods", "0"][..], &bimodal].concat()),
            "--periods must be at least 1",
        ),
        (
            with(&[&["--periods", "1.5"][..], &bimodal].concat()),
            "--periods must be a whole number",
        ),
        (
            with(&[&["--x0", "inf"][..], &bimodal].concat()),
            "--x0 must be a finite number",
        ),
        (
            with(&[&["--x0", "1e305", "--sigma0", "1e5"][..], &bimodal].concat()),
            "cannot be represented",
        ),
        (
            with(&[&["--times", "1,0.5"][..], &bimodal].concat()),
            "strictly increasing",
        ),
        (
            with(&[&["--times", "0,20"][..], &bimodal].concat()),
            "outside the run",
        ),
        (
            with(&[&["--times", "0,nan"][..], &bimodal].concat()),
            "--times: item 2 must be a finite number, got NaN",
        ),
        (
            with(&[&["--samples-per-period", "0"][..], &bimodal].concat()),
            "--samples-per-period must be a whole number >= 1, got 0",
        ),
        (
            with(&[&["--times", "1", "--samples-per-period", "3"][..], &bimodal].concat()),
            "not both",
        ),
        (with(&["--input", &empty]), "no data rows"),
        (with(&["--input", &backwards]), "strictly increasing"),
        (
            with(&["--input", &u_only]),
            "line 1: no column t (t or time) in the header 'u'",
        ),
        (
            with(&["--input", &open, "--periods", "2"]),
            "must end where it starts",
        ),
        (with(&[]), "no input"),
        (
            with(&["--sine", "1,2", "--turning-points", "0,1"]),
            "give one input",
        ),
        (
            with(&["--sine", "0,1"]),
            "amplitude must be a finite number > 0",
        ),
        (with(&["--sine", "1"]), "A,T[,PHASE[,OFFSET]]"),
        (with(&["--sine", "1,2", "--tol", "0"]), "tolerance"),
        (
            with(&[&["--sigma0", "-1"][..], &bimodal].concat()),
            "sigma0",
        ),
    ];
    for (args, want) in &cases {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        rejects(&args, want);
    }
    // An error writes no CSV.
    let csv = dir.join("never.csv");
    rejects(
        &[
            "simulate",
            "--gamma",
            "0",
            "--bimodal",
            "0,0.2,1,1.5",
            "--csv",
            csv.to_str().unwrap(),
        ],
        "gamma",
    );
    assert!(!csv.exists());
    let _ = std::fs::remove_dir_all(&dir);
}

/// Samples of a sine read as a smooth motion (`--interpolate cubic`) against the adaptive
/// solution of the sine itself (`--sine`) at the same times: far closer than the linear
/// reading; a velocity record (header `t,velocity`) is integrated and read the same way.
#[test]
fn samples_of_a_smooth_motion_read_as_cubic() {
    let dir = common::TempDir::new("simulate-cubic");
    let (a, period, n) = (1e-5, 0.05, 200usize);
    let w = std::f64::consts::TAU / period;
    let t: Vec<f64> = (0..=n).map(|k| period * k as f64 / n as f64).collect();
    let mut disp = String::from("t,u\n");
    let mut vel = String::from("Time [s],Velocity [m/s]\n");
    for &t in &t {
        disp.push_str(&format!("{t:?},{:?}\n", a * (w * t + 0.3).sin()));
        vel.push_str(&format!("{t:?},{:?}\n", a * w * (w * t + 0.3).cos()));
    }
    let (disp, vel) = (dir.file("disp.csv", disp), dir.file("vel.csv", vel));
    let times: Vec<String> = t[..n].iter().map(|t| format!("{t:?}")).collect();
    let model = ["--preset", "canudas1995"];
    let run = |extra: &[&str]| -> Vec<f64> {
        let mut args = vec!["simulate"];
        args.extend(model);
        args.extend(extra);
        args.push("--json");
        let j = json(&args);
        j["y"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect()
    };
    let reference = run(&[
        "--sine",
        &format!("{a:?},{period:?},0.3"),
        "--times",
        &times.join(","),
    ]);
    // The mean error over the samples (at the few samples next to a reversal both readings
    // are first order: simulate::smooth's docs).
    let mean = |y: &[f64]| {
        y.iter()
            .zip(&reference)
            .map(|(a, b)| (a - b).abs())
            .sum::<f64>()
            / n as f64
    };
    let linear = mean(&run(&["--input", &disp])[..n]);
    let cubic = mean(&run(&["--input", &disp, "--interpolate", "cubic"])[..n]);
    assert!(cubic < 0.1 * linear, "cubic {cubic:e} vs linear {linear:e}");
    // The velocity record: integrated from u = 0 (the sine starts at a sin(0.3)).
    let velocity = run(&["--input", &vel]);
    assert_eq!(velocity.len(), n + 1);
    assert!(velocity.iter().all(|y| y.is_finite()));
    rejects(
        &[
            "simulate",
            "--input",
            &disp,
            "--interpolate",
            "cubic",
            "--periods",
            "2",
        ],
        "runs once",
    );
}

/// `--columns N=NAME`: the model is the friction coefficient's (parameters per newton) and
/// `y = N(t)` times it. On the lab file (a constant 5 N) it is the force model with sigma0,
/// sigma1, Fc and Fs five times larger, to rounding; a varying `N` scales `y` sample by
/// sample; `N <= 0` is refused, naming the row.
#[test]
fn a_normal_force_column_scales_the_friction_coefficient() {
    let lab = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/data/lab-slow-loop.tsv"
    );
    let common = [
        "simulate", "--input", lab, "--vs", "1e-3", "--beta", "2", "--json",
    ];
    let run = |extra: &[&str]| -> Vec<f64> {
        let args: Vec<&str> = common.iter().chain(extra).copied().collect();
        column(&json(&args), "y")
    };
    let force = run(&[
        "--columns",
        "u=Position",
        "--scale",
        "u=1e-3",
        "--sigma0",
        "1e5",
        "--sigma1",
        "316",
        "--fc",
        "1",
        "--fs",
        "1.5",
    ]);
    let per_newton = run(&[
        "--columns",
        "u=Position,N=Normal",
        "--scale",
        "u=1e-3,N=1e-6",
        "--sigma0",
        "2e4",
        "--sigma1",
        "63.2",
        "--fc",
        "0.2",
        "--fs",
        "0.3",
    ]);
    assert_eq!(force.len(), per_newton.len());
    for (a, b) in force.iter().zip(&per_newton) {
        assert!((a - b).abs() <= 1e-12 * (1.0 + a.abs()), "{a} vs {b}");
    }
    let dir = scratch("normal");
    let file = dir.join("load.csv");
    std::fs::write(&file, "t,u,N\n0,0,1\n1,1,2\n2,0,4\n").unwrap();
    let f = file.to_str().unwrap();
    let unit = column(
        &json(&["simulate", "--input", f, "--columns", "u=u", "--json"]),
        "y",
    );
    let scaled = column(
        &json(&[
            "simulate",
            "--input",
            f,
            "--columns",
            "N=N",
            "--times",
            "0,1,1.5,2",
            "--json",
        ]),
        "y",
    );
    let at = column(
        &json(&[
            "simulate",
            "--input",
            f,
            "--columns",
            "u=u",
            "--times",
            "0,1,1.5,2",
            "--json",
        ]),
        "y",
    );
    for ((s, a), n) in scaled.iter().zip(&at).zip([1.0, 2.0, 3.0, 4.0]) {
        assert!(
            (s - n * a).abs() <= 1e-14 * (1.0 + a.abs()),
            "{s} vs {n} x {a}"
        );
    }
    assert_eq!(unit.len(), 3);
    std::fs::write(&file, "t,u,N\n0,0,1\n1,1,0\n2,0,4\n").unwrap();
    rejects(
        &["simulate", "--input", f, "--columns", "N=N"],
        "line 3: N must be > 0, got 0",
    );
    rejects(
        &["simulate", "--sine", "1,1", "--columns", "N=2"],
        "a normal force is read from the record",
    );
}
