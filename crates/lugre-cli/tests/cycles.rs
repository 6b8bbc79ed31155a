//! `lugre cycles` run as a user would: the real binary, its stdout, stderr, files and exit
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
    serde_json::from_slice(&out.stdout).expect("valid JSON")
}

/// A file in a fresh directory under the target's temporary directory.
fn temp_file(name: &str, contents: &[u8]) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!(
        "cycles-{}-{}",
        std::process::id(),
        name.replace('.', "-")
    ));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, contents).unwrap();
    path
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().expect("a number")
}

/// `(range, mean, count, start, end)` of every cycle in a `--json` document.
fn rows(j: &serde_json::Value) -> Vec<(f64, f64, f64, u64, u64)> {
    j["cycles"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| {
            (
                f(&c["range"]),
                f(&c["mean"]),
                f(&c["count"]),
                c["start"].as_u64().unwrap(),
                c["end"].as_u64().unwrap(),
            )
        })
        .collect()
}

const ASTM: &str = "-2,1,-3,5,-1,3,-4,4,-2";

#[test]
fn astm_example_row_by_row() {
    // ASTM E1049-85 §5.4.4 (Table 4: range 3: 0.5, 4: 1.5, 6: 0.5, 8: 1.0, 9: 0.5), in the
    // order rainflow 3.2.0 yields it:
    //   list(rainflow.extract_cycles([-2, 1, -3, 5, -1, 3, -4, 4, -2]))
    let j = json(&["cycles", "--values", ASTM, "--json"]);
    assert_eq!(
        rows(&j),
        vec![
            (3.0, -0.5, 0.5, 0, 1),
            (4.0, -1.0, 0.5, 1, 2),
            (4.0, 1.0, 1.0, 4, 5),
            (8.0, 1.0, 0.5, 2, 3),
            (9.0, 0.5, 0.5, 3, 6),
            (8.0, 0.0, 0.5, 6, 7),
            (6.0, 1.0, 0.5, 7, 8),
        ]
    );
    let reversals: Vec<(u64, f64)> = j["reversals"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| (r["index"].as_u64().unwrap(), f(&r["u"])))
        .collect();
    assert_eq!(reversals.len(), 9);
    assert_eq!(reversals[3], (3, 5.0));
    // The full cycle (-1, 3) closes 4/7 of the way from sample 5 (u = 3) to 6 (u = -4).
    let full = &j["cycles"][2];
    assert_eq!(full["closure"], 6);
    assert_eq!(f(&full["closure_position"]), 5.0 + 4.0 / 7.0);
    assert_eq!(full["work"], serde_json::Value::Null);
    assert_eq!(j["cycles"][0]["closure"], serde_json::Value::Null);
    assert_eq!(
        (
            j["samples"].as_u64(),
            j["full_cycles"].as_u64(),
            j["half_cycles"].as_u64()
        ),
        (Some(9), Some(1), Some(6))
    );
    assert_eq!(j["model"], serde_json::Value::Null);

    let out = lugre(&["cycles", "--values", ASTM]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("1 full cycle, 6 half cycles; largest range 9"),
        "{text}"
    );
}

#[test]
fn hand_checked_nesting_and_closure() {
    // 0 -> 1 -> 0.2 -> 0.8 -> 0.5 -> 1.5 -> -0.3: (0.8, 0.5) nests in (1, 0.2); both close on
    // the rise from 0.5 to 1.5, at 0.8 (4 + 0.3) and at 1 (4 + 0.5). The rest is residue.
    let j = json(&["cycles", "--values", "0,1,0.2,0.8,0.5,1.5,-0.3", "--json"]);
    let full: Vec<&serde_json::Value> = j["cycles"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|c| f(&c["count"]) == 1.0)
        .collect();
    assert_eq!(full.len(), 2);
    assert_eq!(
        (full[0]["start"].as_u64(), full[0]["end"].as_u64()),
        (Some(3), Some(4))
    );
    assert_eq!(full[0]["closure"], 5);
    assert!((f(&full[0]["closure_position"]) - 4.3).abs() < 1e-14);
    assert_eq!(
        (full[1]["start"].as_u64(), full[1]["end"].as_u64()),
        (Some(1), Some(2))
    );
    assert_eq!(full[1]["closure"], 5);
    assert_eq!(f(&full[1]["closure_position"]), 4.5);
}

/// A random walk with plateaus (fixed LCG), as CSV text with header `t,u`.
fn random_walk(n: usize) -> (Vec<f64>, String) {
    let mut state: u64 = 0x2545_F491_4F6C_DD1D;
    let mut x = 0.0;
    let mut u = Vec::with_capacity(n);
    let mut text = String::from("t,u\n");
    for k in 0..n {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        let r = (state >> 11) as f64 / (1u64 << 53) as f64;
        if r > 0.15 {
            x += r - 0.575;
        }
        u.push(x);
        text += &format!("{},{x:?}\n", k as f64 * 1e-3);
    }
    (u, text)
}

#[test]
fn streaming_a_file_gives_the_cycles_of_the_whole_array() {
    let (u, text) = random_walk(30_000);
    let path = temp_file("walk.csv", text.as_bytes());
    let csv_out = path.with_file_name("cycles.csv");
    let j = json(&[
        "cycles",
        "--input",
        path.to_str().unwrap(),
        "--json",
        "--csv",
        csv_out.to_str().unwrap(),
    ]);
    let whole = lugre::count_cycles(&u, 0.0).unwrap();
    let want: Vec<(f64, f64, f64, u64, u64)> = whole
        .cycles
        .iter()
        .map(|c| (c.range, c.mean, c.count, c.start, c.end))
        .collect();
    assert_eq!(rows(&j), want);
    let closures: Vec<Option<u64>> = j["cycles"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["closure"].as_u64())
        .collect();
    let want_closures: Vec<Option<u64>> = whole
        .cycles
        .iter()
        .map(|c| c.closure.map(|cl| cl.index))
        .collect();
    assert_eq!(closures, want_closures);
    assert_eq!(
        j["reversals"].as_array().unwrap().len(),
        whole.reversals.len()
    );

    // The CSV file: a header and one row per cycle, the same numbers.
    let table = std::fs::read_to_string(&csv_out).unwrap();
    let mut lines = table.lines();
    assert_eq!(
        lines.next(),
        Some("range,mean,count,start,end,closure,closure_position,work,stored_energy_change,dissipation,closure_gap,y_start,y_closure")
    );
    let body: Vec<&str> = lines.collect();
    assert_eq!(body.len(), want.len());
    for (line, c) in body.iter().zip(&whole.cycles) {
        let fields: Vec<&str> = line.split(',').collect();
        assert_eq!(fields.len(), 13);
        assert_eq!(fields[0].parse::<f64>().unwrap(), c.range);
        assert_eq!(fields[3].parse::<u64>().unwrap(), c.start);
        assert_eq!(fields[5].parse::<u64>().ok(), c.closure.map(|cl| cl.index));
        assert!(fields[7].is_empty());
    }

    // The table: one pass, the same counts.
    let out = lugre(&["cycles", "--input", path.to_str().unwrap()]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains(&format!(
            "{} full cycles, {} half cycles",
            whole.summary.full_cycles, whole.summary.half_cycles
        )),
        "{text}"
    );
    assert!(
        text.contains("more rows: use --json or --csv FILE"),
        "{text}"
    );
}

#[test]
fn several_periods_agree_with_lugre_loop() {
    // Paper Example 4 (sigma0 = 6, g(0) = 2, turning points 0, 1, 0.5, 1.5) for 6 periods,
    // sampled 10 times per unit of travel. y* approaches y° like |y*(0) - y°(0)| exp(-a rho)
    // (a = 3, period P = 4): at the minor loop of period k (rho >= 4 k + 1) within
    // 2 exp(-3 (4k + 1)), 4e-12 for k = 2 and 2e-17 for k = 3. From the fourth period on, the
    // minor cycle (1, 0.5) is lugre loop's minor loop [rho_1, rho_5].
    let tp = [0.0, 1.0, 0.5, 1.5];
    let mut text = String::from("u\n0\n");
    for _ in 0..6 {
        for k in 0..4 {
            let (a, b): (f64, f64) = (tp[k], tp[(k + 1) % 4]);
            let n = ((b - a).abs() * 10.0).round() as usize;
            for j in 1..=n {
                text += &format!("{:?}\n", a + (b - a) * (j as f64 / n as f64));
            }
        }
    }
    let path = temp_file("periods.csv", text.as_bytes());
    let j = json(&[
        "cycles",
        "--fs",
        "2",
        "--input",
        path.to_str().unwrap(),
        "--sigma0",
        "6",
        "--json",
    ]);
    assert_eq!(f(&j["g0"]), 2.0);
    assert_eq!(f(&j["x0"]), 0.0);
    let l = json(&[
        "loop",
        "--sigma0",
        "6",
        "--turning-points",
        "0,1,0.5,1.5",
        "--json",
    ]);
    let minor = &l["loops"][1];
    assert_eq!(minor["kind"], "minor");
    let cycles: Vec<&serde_json::Value> = j["cycles"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|c| f(&c["count"]) == 1.0 && f(&c["range"]) == 0.5)
        .collect();
    assert_eq!(cycles.len(), 6);
    let scale = 2.0 * f(&l["period"]);
    let tol = lugre_test_support::prec::CYCLE_ENERGY * scale;
    for c in &cycles[3..] {
        for (key, want) in [
            ("work", &minor["work"]),
            ("stored_energy_change", &minor["stored_energy_change"]),
            ("dissipation", &minor["dissipation"]),
            ("closure_gap", &minor["closure_gap"]),
            ("y_start", &minor["start"]["y"]),
            ("y_closure", &minor["end"]["y"]),
        ] {
            assert!(
                (f(&c[key]) - f(want)).abs() < tol,
                "{key}: {} vs {}",
                c[key],
                want
            );
        }
        // The arc closes where the input is back at 1, halfway from 0.5 to 1.5.
        let pos = f(&c["closure_position"]);
        assert_eq!(pos.fract(), 0.0);
    }
}

#[test]
fn gate_column_and_histogram() {
    let text = b"# bench test\nt,force,disp\n0,9,0\n1,9,1\n2,9,0.9\n3,9,1\n4,9,0.95\n5,9,2\n6,9,1.2\n7,9,1.25\n8,9,0\n";
    let path = temp_file("gate.csv", text);
    let p = path.to_str().unwrap();
    let all = json(&["cycles", "--input", p, "--column", "disp", "--json"]);
    assert_eq!(all["reversals"].as_array().unwrap().len(), 9);
    let gated = json(&[
        "cycles", "--input", p, "--column", "disp", "--gate", "0.5", "--json",
    ]);
    let r: Vec<u64> = gated["reversals"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["index"].as_u64().unwrap())
        .collect();
    assert_eq!(r, vec![0, 5, 8]);
    assert_eq!(f(&gated["gate"]), 0.5);

    let h = json(&[
        "cycles",
        "--values",
        ASTM,
        "--histogram",
        "--bins",
        "3",
        "--json",
    ]);
    let hist = &h["histogram"];
    assert_eq!(hist["bins"], 3);
    let edges: Vec<f64> = hist["range_edges"]
        .as_array()
        .unwrap()
        .iter()
        .map(f)
        .collect();
    assert_eq!(edges, vec![0.0, 3.0, 6.0, 9.0]);
    let counts: Vec<f64> = hist["range_counts"]
        .as_array()
        .unwrap()
        .iter()
        .map(f)
        .collect();
    assert_eq!(counts, vec![0.0, 2.0, 2.0]);
    let matrix_total: f64 = hist["range_mean_counts"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|row| row.as_array().unwrap().iter().map(f))
        .sum();
    assert_eq!(matrix_total, 4.0);
    let out = lugre(&["cycles", "--values", ASTM, "--histogram", "--bins", "3"]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("Counts by range (rows) and mean"), "{text}");
}

#[test]
fn energy_along_the_history() {
    // Dahl (rho = 2, Fc = 1: sigma0 = 2, g0 = 1) from w(0) = 0.5 (x0 = 0.25); each cycle's
    // W = dV + D with D >= 0, and the history's own totals add up.
    let j = json(&[
        "cycles",
        "--fc",
        "1",
        "--values",
        "0,1,0.2,0.8,0.5,1.5,-0.3,0.6,0.1,1.2",
        "--model",
        "dahl",
        "--rho",
        "2",
        "--x0",
        "0.25",
        "--json",
    ]);
    assert_eq!(j["model"]["kind"], "dahl");
    assert_eq!(f(&j["history"]["y_start"]), 0.5);
    let mut full = 0;
    for c in j["cycles"].as_array().unwrap() {
        if f(&c["count"]) == 1.0 {
            full += 1;
            let (w, dv, d) = (
                f(&c["work"]),
                f(&c["stored_energy_change"]),
                f(&c["dissipation"]),
            );
            assert!(d >= 0.0);
            assert!((w - dv - d).abs() < 1e-13, "{c}");
        } else {
            assert_eq!(c["work"], serde_json::Value::Null);
        }
    }
    assert!(full >= 2);
    let h = &j["history"];
    assert!((f(&h["work"]) - f(&h["stored_energy_change"]) - f(&h["dissipation"])).abs() < 1e-12);
    // Any model flag asks for energies; without one there are none.
    let k = json(&[
        "cycles", "--sigma0", "1", "--values", ASTM, "--fs", "3", "--json",
    ]);
    assert_eq!(f(&k["g0"]), 3.0);
    assert!(k["cycles"][2]["work"].is_number());
}

#[test]
fn bad_input_is_one_line_and_status_2() {
    let p = |name: &str, text: &[u8]| temp_file(name, text).to_str().unwrap().to_string();
    let malformed = p("malformed.csv", b"u\n1\n2\nabc\n3\n");
    rejects(
        &["cycles", "--input", &malformed, "--json"],
        "line 4: u = 'abc' is not a number",
    );
    rejects(&["cycles", "--input", &malformed], "line 4");
    let wide = p("wide.csv", b"t,u\n0,1\n1,2,3\n");
    rejects(
        &["cycles", "--input", &wide],
        "line 3: expected 2 values (t,u), found 3",
    );
    let nocol = p("nocol.csv", b"t,w\n0,1\n1,2\n");
    rejects(
        &["cycles", "--input", &nocol],
        "line 1: no column u (u, x, position or displacement) in the header 't,w'",
    );
    rejects(
        &["cycles", "--input", &nocol, "--column", "force"],
        "line 1: no column F (F, force, friction or y) in the header 't,w'",
    );
    rejects(
        &["cycles", "--input", &nocol, "--column", "strain"],
        "line 1: no column 'strain' in the header 't,w'",
    );
    let twice = p("twice.csv", b"t,u,u\n0,1,1\n1,2,2\n");
    rejects(
        &["cycles", "--input", &twice],
        "line 1: the header has two columns for u: 'u' (column 2) and 'u' (column 3); say which with --columns u=NUMBER",
    );
    let nan = p("nan.csv", b"u\n1\nnan\n");
    rejects(
        &["cycles", "--input", &nan],
        "line 3: u must be a finite number, got NaN",
    );
    let inf = p("inf.csv", b"1\n-inf\n");
    rejects(&["cycles", "--input", &inf, "--histogram"], "line 2");
    let huge = p("huge.csv", b"1\n1e308\n");
    rejects(
        &["cycles", "--input", &huge],
        "line 2: u = 1e308 is too large",
    );
    let times = p("times.csv", b"t,u\n0,1\n0,2\n");
    rejects(
        &["cycles", "--input", &times],
        "times must be strictly increasing",
    );
    let empty = p("empty.csv", b"u\n");
    rejects(&["cycles", "--input", &empty], "the history is empty");
    let single = p("single.csv", b"u\n4\n");
    rejects(
        &["cycles", "--input", &single, "--json"],
        "a history needs at least 2 samples, got 1",
    );
    rejects(&["cycles", "--values", "3"], "at least 2 samples");
    // The library's words, as `lugre.cycles` and the C ABI give them for the same series, the
    // item counted from 1 as a list on the command line is.
    rejects(
        &["cycles", "--values", "1,nan,2"],
        "--values: item 2 must be a finite number, got NaN",
    );
    rejects(
        &["cycles", "--values", "1,1e308"],
        "--values: u[1] = 1e308 is too large",
    );
    rejects(
        &["cycles", "--values", "3"],
        "--values: a history needs at least 2 samples, got 1",
    );
    rejects(&["cycles", "--input", "/nonexistent/x.csv"], "cannot read");
    rejects(&["cycles"], "no input");
    rejects(&["cycles", "--values", ASTM, "--gate", "-1"], "--gate");
    rejects(&["cycles", "--values", ASTM, "--gate", "nan"], "--gate");
    rejects(
        &[
            "cycles", "--sigma0", "1", "--fs", "2", "--values", ASTM, "--x0", "5",
        ],
        "x0 must satisfy |sigma0 x0| <= g(0)",
    );
    rejects(
        &["cycles", "--fs", "2", "--values", ASTM, "--sigma0", "-1"],
        "sigma0",
    );
    rejects(
        &["cycles", "--values", ASTM, "--histogram", "--bins", "0"],
        "--bins must be a whole number >= 1, got 0",
    );
    rejects(
        &["cycles", "--values", ASTM, "--input", &empty],
        "cannot be used with",
    );
}

/// A lab's tab-separated file with units in its header: the delimiter is found, `Time [s]` is
/// the time column and `--column position` names `Position [mm]`.
#[test]
fn a_tab_separated_lab_file() {
    let dir = common::TempDir::new("cycles-tab");
    let text = "Time [s]\tNormal [uN]\tPosition [mm]\n0\t5\t-2\n1\t5\t1\n2\t5\t-3\n3\t5\t5\n4\t5\t-1\n5\t5\t3\n6\t5\t-4\n7\t5\t4\n8\t5\t-2\n";
    let path = dir.file("lab.tsv", text);
    let j = json(&["cycles", "--input", &path, "--column", "Position", "--json"]);
    let want = json(&["cycles", "--values=-2,1,-3,5,-1,3,-4,4,-2", "--json"]);
    assert_eq!(j["cycles"], want["cycles"]);
    let e = rejects(
        &["cycles", "--input", &path, "--column", "Friction"],
        "no column F (F, force, friction or y) in the header 'Time [s],Normal [uN],Position [mm]'",
    );
    assert!(e.contains("fields separated by tabs"), "{e}");
    // Without --column: Position is u by its usual name.
    let j = json(&["cycles", "--input", &path, "--json"]);
    assert_eq!(j["cycles"], want["cycles"]);
}

/// The files other commands write and the usual lab headers are histories too: `cycles`
/// reads their displacement column whatever else they hold.
#[test]
fn histories_from_other_commands_and_lab_headers() {
    let dir = common::TempDir::new("cycles-headers");
    let u = [-2.0, 1.0, -3.0, 5.0, -1.0, 3.0, -4.0, 4.0, -2.0];
    let want = json(&["cycles", "--values=-2,1,-3,5,-1,3,-4,4,-2", "--json"]);
    let rows = |f: &dyn Fn(usize, f64) -> String| -> String {
        u.iter().enumerate().map(|(k, &v)| f(k, v)).collect()
    };
    for (name, text) in [
        // Said "no column 'u'" before.
        (
            "lab.csv",
            format!(
                "Time [s],Displacement [um]\n{}",
                rows(&|k, v| format!("{k},{v}\n"))
            ),
        ),
        (
            "loop.csv",
            format!("rho,u,y\n{}", rows(&|k, v| format!("{k},{v},0.5\n"))),
        ),
        (
            "dynamics.csv",
            format!(
                "t,x,v,z,friction,drive\n{}",
                rows(&|k, v| format!("{k},{v},1,2,3,4\n"))
            ),
        ),
        (
            "crlf-comments.csv",
            format!(
                "# run 3\r\n\r\nt;x\r\n{}",
                rows(&|k, v| format!("{k};{v}\r\n"))
            ),
        ),
    ] {
        let path = dir.file(name, text);
        let j = json(&["cycles", "--input", &path, "--json"]);
        assert_eq!(j["cycles"], want["cycles"], "{name}");
    }
}
