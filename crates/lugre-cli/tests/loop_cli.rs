//! `lugre loop` run as a user would: the real binary, its stdout, stderr and exit status.

mod common;

use common::{lugre, rejects};

fn json(args: &[&str]) -> serde_json::Value {
    let out = lugre(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("valid JSON")
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().expect("a number")
}

// The paper's Example 4 (sigma0 = 6, g(0) = 2; turning points 0, 1, 0.5, 1.5). References:
// the paper's eqs. 13-16 literally, and eq. 8's integrals by quadrature, in mpmath at 40 digits:
//   a = 3; y0 = g0 e^{-a r4}/(1-e^{-a r4}) (2e^{a r1} - 2e^{a r2} + 2e^{a r3} - e^{a r4} - 1), ...
//   W = quad(y psi', [1, 1.5, 2]), D = quad(y^2, [1, 1.5, 2]) / g0
const EX4_Y: [f64; 4] = [
    -1.9573070266459944,
    1.8029772845117475,
    -1.151441069466053,
    1.8430989880171994,
];
const EX4_Y_RHO5: f64 = 1.2968184494717006;
const EX4_MINOR_W: f64 = 0.1991073756948153;
const EX4_MINOR_D: f64 = 0.32985645882607939;
const EX4_MINOR_DV: f64 = -0.1307490831312641;
const EX4_WORK_PER_PERIOD: f64 = 3.4967837542393372;
const TOL: f64 = lugre_test_support::prec::LOOP;

#[test]
fn example_4_json_matches_the_paper() {
    let j = json(&[
        "loop",
        "--sigma0",
        "6",
        "--bimodal",
        "0,0.5,1,1.5",
        "--json",
    ]);
    assert_eq!(f(&j["g0"]), 2.0);
    assert_eq!(f(&j["a"]), 3.0);
    assert_eq!(f(&j["period"]), 4.0);
    let tp = j["turning_points"].as_array().unwrap();
    for (k, want) in EX4_Y.iter().enumerate() {
        assert!(rel(f(&tp[k]["y"]), *want) < TOL, "y_{k}");
    }
    assert_eq!(
        tp.iter().map(|p| f(&p["u"])).collect::<Vec<_>>(),
        [0.0, 1.0, 0.5, 1.5]
    );
    let ta = &j["theorem_a"];
    let rho: Vec<f64> = ta["rho"].as_array().unwrap().iter().map(f).collect();
    assert_eq!(rho, [0.0, 1.0, 1.5, 2.5, 4.0, 2.0]);
    assert_eq!(ta["minor_loop"], serde_json::json!([1.0, 2.0]));
    assert!(rel(f(&ta["y"][5]), EX4_Y_RHO5) < TOL);

    let loops = j["loops"].as_array().unwrap();
    assert_eq!(loops.len(), 2);
    assert_eq!(loops[0]["kind"], "major");
    assert_eq!(loops[0]["parent"], serde_json::Value::Null);
    assert_eq!(loops[0]["depth"], 0);
    let minor = &loops[1];
    assert_eq!(minor["kind"], "minor");
    assert_eq!(f(&minor["start"]["rho"]), 1.0);
    assert_eq!(f(&minor["reversal"]["rho"]), 1.5);
    assert_eq!(f(&minor["end"]["rho"]), 2.0);
    assert_eq!(minor["parent"], 0);
    assert_eq!(minor["depth"], 1);
    assert!(rel(f(&minor["work"]), EX4_MINOR_W) < TOL);
    assert!(rel(f(&minor["dissipation"]), EX4_MINOR_D) < TOL);
    assert!(rel(f(&minor["stored_energy_change"]), EX4_MINOR_DV) < TOL);
    assert!(rel(f(&minor["closure_gap"]), EX4_Y_RHO5 - EX4_Y[1]) < TOL);
    assert!(rel(f(&j["work_per_period"]), EX4_WORK_PER_PERIOD) < TOL);
    assert!(rel(f(&loops[0]["work"]), EX4_WORK_PER_PERIOD) < TOL);
    assert!(j.get("points").is_none());
}

#[test]
fn example_4_table_names_the_minor_loop() {
    let out = lugre(&["loop", "--sigma0", "6", "--bimodal", "0,0.5,1,1.5"]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("minor loop: rho in [rho_1, rho_5] = [1, 2]"),
        "{text}"
    );
    assert!(text.contains("Work per period"), "{text}");
    assert!(text.contains("minor"), "{text}");
}

#[test]
fn negative_turning_points_with_and_without_equals() {
    let a = json(&["loop", "--turning-points", "-1,1,-0.5,0.5", "--json"]);
    let b = json(&["loop", "--turning-points=-1,1,-0.5,0.5", "--json"]);
    assert_eq!(a, b);
    assert_eq!(f(&a["turning_points"][0]["u"]), -1.0);
    assert_eq!(a["loops"].as_array().unwrap().len(), 2);
}

#[test]
fn points_at_and_samples_are_periodic() {
    let j = json(&[
        "loop",
        "--sigma0",
        "6",
        "--bimodal",
        "0,0.5,1,1.5",
        "--at",
        "-4,0,2,4,8",
        "--json",
    ]);
    let p = j["points"].as_array().unwrap();
    assert_eq!(p.len(), 5);
    for i in [0, 3, 4] {
        assert_eq!(f(&p[i]["y"]), f(&p[1]["y"]), "y°(rho + kP) = y°(rho)");
        assert_eq!(f(&p[i]["u"]), 0.0);
    }
    assert_eq!(f(&p[0]["rho"]), -4.0, "rho as given");
    assert!(rel(f(&p[2]["y"]), EX4_Y_RHO5) < TOL);
    let j = json(&[
        "loop",
        "--bimodal",
        "0,0.2,1,1.5",
        "--samples",
        "5",
        "--json",
    ]);
    let rho: Vec<f64> = j["points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| f(&p["rho"]))
        .collect();
    assert_eq!(rho, [0.0, 1.15, 2.3, 3.4499999999999997, 4.6]);
}

#[test]
fn csv_output_round_trips() {
    let dir = std::env::temp_dir().join(format!("lugre-loop-csv-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("curve.csv");
    let j = json(&[
        "loop",
        "--sigma0",
        "6",
        "--bimodal",
        "0,0.5,1,1.5",
        "--samples",
        "9",
        "--json",
        "--csv",
        path.to_str().unwrap(),
    ]);
    let text = std::fs::read_to_string(&path).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("rho,u,y"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 9);
    for (row, p) in rows.iter().zip(j["points"].as_array().unwrap()) {
        assert_eq!(row, &vec![f(&p["rho"]), f(&p["u"]), f(&p["y"])]);
    }
    let leftovers: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().contains(".tmp"))
        .collect();
    assert!(leftovers.is_empty(), "no temporary file is left behind");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn csv_input_gives_the_same_loop_as_its_turning_points() {
    let dir = std::env::temp_dir().join(format!("lugre-loop-in-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let with_t = dir.join("tu.csv");
    // A sampled period of Example 3's input, with non-reversal samples in between.
    std::fs::write(
        &with_t,
        "t,u\n0,0\n0.5,0.5\n1,1\n1.4,0.6\n1.8,0.2\n2.5,0.9\n3.1,1.5\n4,0.6\n4.6,0\n",
    )
    .unwrap();
    let only_u = dir.join("u.csv");
    std::fs::write(
        &only_u,
        "\u{feff}# one period\r\n0\r\n1\r\n0.2\r\n1.5\r\n\r\n",
    )
    .unwrap();
    let a = json(&["loop", "--input", with_t.to_str().unwrap(), "--json"]);
    let b = json(&["loop", "--input", only_u.to_str().unwrap(), "--json"]);
    let c = json(&["loop", "--turning-points", "0,1,0.2,1.5", "--json"]);
    assert_eq!(a, c);
    assert_eq!(b, c);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn dahl_model() {
    // Dahl (rho, Fc) is LuGre with sigma0 = rho Fc and g = Fc: the same loop.
    let d = json(&[
        "loop",
        "--model",
        "dahl",
        "--rho",
        "2",
        "--fc",
        "0.5",
        "--turning-points",
        "-1,1",
        "--json",
    ]);
    let l = json(&[
        "loop",
        "--sigma0",
        "1",
        "--fs",
        "0.5",
        "--fc",
        "0.5",
        "--turning-points",
        "-1,1",
        "--json",
    ]);
    assert_eq!(d["model"]["kind"], "dahl");
    assert_eq!(d["loops"], l["loops"]);
    // Symmetric triangle between -A and A: y°(-A) = -Fc tanh(rho A) (by hand from the
    // recursion: y1 = Fc + (y0 - Fc) e^{-2 rho A}, y0 = -y1).
    let y0 = f(&d["turning_points"][0]["y"]);
    assert!(rel(y0, -0.5 * 2.0f64.tanh()) < TOL);
}

#[test]
fn bad_inputs_are_one_line_and_status_2() {
    rejects(&["loop", "--bogus"], "unexpected argument '--bogus'");
    rejects(&["loop"], "no input");
    rejects(
        &["loop", "--turning-points", "0,nan,1"],
        "item 2 must be a finite number, got NaN",
    );
    rejects(&["loop", "--turning-points", "0,1,x"], "item 3 is 'x'");
    rejects(
        &["loop", "--turning-points", "1,1,1"],
        "at least 2 distinct values",
    );
    rejects(&["loop", "--turning-points", ""], "empty list");
    rejects(&["loop", "--bimodal", "0.3,0.2,1,1.5"], "umin1 <= umin2");
    rejects(&["loop", "--bimodal", "0,1,1,1.5"], "umin2 < umax1");
    rejects(&["loop", "--bimodal", "0,0.2,2,1.5"], "umax1 <= umax2");
    rejects(
        &["loop", "--bimodal", "0,0,1,1"],
        "umin1 != umin2 or umax1 != umax2",
    );
    rejects(&["loop", "--bimodal", "0,1,2"], "takes 4 numbers");
    rejects(
        &["loop", "--sigma0", "0", "--turning-points", "0,1"],
        "sigma0 must be > 0",
    );
    rejects(
        &["loop", "--fs", "-2", "--turning-points", "0,1"],
        "fs must be > 0",
    );
    rejects(
        &["loop", "--sigma1", "nan", "--turning-points", "0,1"],
        "sigma1 must be a finite number, got NaN",
    );
    rejects(
        &["loop", "--rho", "2", "--turning-points", "0,1"],
        "--rho is the Dahl model's parameter",
    );
    rejects(
        &[
            "loop",
            "--model",
            "dahl",
            "--sigma0",
            "2",
            "--turning-points",
            "0,1",
        ],
        "--sigma0 is a LuGre parameter",
    );
    rejects(
        &[
            "loop",
            "--turning-points",
            "0,1",
            "--bimodal",
            "0,0.2,1,1.5",
        ],
        "give one input",
    );
    rejects(
        &["loop", "--turning-points", "0,1", "--samples", "1"],
        "--samples must be at least 2 (both ends of the period), got 1",
    );
    rejects(
        &["loop", "--input", "/nonexistent/x.csv"],
        "/nonexistent/x.csv: cannot read the file: No such file or directory",
    );
    rejects(
        &[
            "loop",
            "--turning-points",
            "0,1",
            "--csv",
            "/nonexistent/dir/out.csv",
        ],
        "cannot write '/nonexistent/dir/out.csv'",
    );
}

#[test]
fn csv_errors_name_the_line() {
    let dir = std::env::temp_dir().join(format!("lugre-loop-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let cases = [
        (
            "t,u\n0,0\n1,1\n1,0\n",
            "line 4: times must be strictly increasing",
        ),
        ("t,u\n0,0\n1\n", "line 3: expected 2 values"),
        ("a,b\n0,0\n", "line 1: no column u"),
        (
            "# c\r\n\r\nu,u\r\n0,0\r\n",
            "line 3: the header has two columns for u",
        ),
        (
            "u\n0\n1e400\n",
            "line 3: u must be a finite number, got inf",
        ),
        ("u\n", "no data rows"),
        ("u\n5\n5\n", "at least 2 distinct values"),
    ];
    for (i, (text, want)) in cases.iter().enumerate() {
        let path = dir.join(format!("bad{i}.csv"));
        std::fs::write(&path, text).unwrap();
        rejects(&["loop", "--input", path.to_str().unwrap()], want);
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn extreme_stiffness_stays_finite_and_saturated() {
    // a P = 1e12 * 2.3: the paper's printed formula overflows; the loop saturates at +-g0.
    let j = json(&[
        "loop",
        "--sigma0",
        "1e12",
        "--bimodal",
        "0,0.2,1,1.5",
        "--json",
    ]);
    for p in j["turning_points"].as_array().unwrap() {
        let y = f(&p["y"]);
        assert!(y.abs() <= 2.0 && y.abs() > 2.0 * (1.0 - 1e-12), "{y}");
    }
    // a P = 2.3e-12: elastic regime, y° ~ sigma0 (u - mean over rho).
    let j = json(&[
        "loop",
        "--sigma0",
        "1e-12",
        "--bimodal",
        "0,0.2,1,1.5",
        "--json",
    ]);
    assert!(f(&j["work_per_period"]) > 0.0);
    assert!(f(&j["turning_points"][0]["y"]).is_finite());
}

#[test]
fn help_and_version_succeed() {
    let out = lugre(&["--help"]);
    assert!(out.status.success());
    assert!(String::from_utf8_lossy(&out.stdout).contains("loop"));
    let out = lugre(&["loop", "--help"]);
    assert!(String::from_utf8_lossy(&out.stdout).contains("--turning-points"));
    assert!(lugre(&["--version"]).status.success());
}

#[test]
fn plots_are_written_as_png_and_svg() {
    let dir = std::env::temp_dir().join(format!("lugre-loop-plot-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let png = dir.join("ex4.png");
    let svg = dir.join("ex4.svg");
    for path in [&png, &svg] {
        let out = lugre(&[
            "loop",
            "--sigma0",
            "6",
            "--bimodal",
            "0,0.5,1,1.5",
            "--plot",
            path.to_str().unwrap(),
        ]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    // IHDR: width and height, big-endian, right after the chunk header.
    let width = u32::from_be_bytes(bytes[16..20].try_into().unwrap());
    let height = u32::from_be_bytes(bytes[20..24].try_into().unwrap());
    assert_eq!((width, height), (1000, 700));
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.trim_start().starts_with("<svg") && text.trim_end().ends_with("</svg>"));
    for label in ["input u", "friction force y°", "minor loop, rho in [1, 2]"] {
        assert!(text.contains(label), "{label}");
    }
    rejects(
        &[
            "loop",
            "--turning-points",
            "0,1",
            "--plot",
            dir.join("x.pdf").to_str().unwrap(),
        ],
        "must end in .svg or .png",
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
