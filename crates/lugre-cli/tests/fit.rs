//! `lugre fit` run as a user would: the real binary on CSV files made by the project's own
//! simulator plus 1 % Gaussian noise (fixed seed), its stdout, stderr, files and exit status.

use lugre::simulate::{merge_times, uniform_times};
use lugre::{Gamma, LuGre, LuGreParams, PiecewiseLinear, Simulator, Trajectory, TurningPoints};
use std::path::{Path, PathBuf};

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
        "no progress bar or warning: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("valid JSON")
}

/// A scratch directory of its own for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("lugre-fit-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

/// `n` standard normal deviates (Box-Muller on an LCG).
fn gauss(n: usize, mut state: u64) -> Vec<f64> {
    let mut unit = move || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..n)
        .map(|_| {
            let r = (-2.0 * (1.0 - unit()).ln()).sqrt();
            r * (std::f64::consts::TAU * unit()).cos()
        })
        .collect()
}

/// Adds Gaussian noise of standard deviation 1 % of the RMS of `f`.
fn noisy(f: &[f64], state: u64) -> Vec<f64> {
    let rms = (f.iter().map(|v| v * v).sum::<f64>() / f.len() as f64).sqrt();
    f.iter()
        .zip(gauss(f.len(), state))
        .map(|(v, e)| v + 0.01 * rms * e)
        .collect()
}

/// The servo-axis record (`t,u,F`, u in mm): the noise-free samples of the
/// independent generator (crates/lugre/tests/reference/servo_axis.py, scipy Radau) with 0.5 um
/// of position noise rounded to 0.1 um and 0.2 N of force noise.
fn servo_file(dir: &Path) -> PathBuf {
    let text = include_str!("../../lugre/tests/reference/servo_axis_clean.csv");
    let rows: Vec<Vec<f64>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    let e = gauss(2 * rows.len(), 31);
    let t: Vec<f64> = rows.iter().map(|r| r[0]).collect();
    let u: Vec<f64> = (0..rows.len())
        .map(|i| ((rows[i][1] + 5e-4 * e[2 * i]) / 1e-4).round() * 1e-4)
        .collect();
    let f: Vec<f64> = (0..rows.len())
        .map(|i| rows[i][2] + 0.2 * e[2 * i + 1])
        .collect();
    let path = dir.join("servo.csv");
    write_csv(&path, "t,u,F", &[&t, &u, &f]);
    path
}

/// Writes the columns with a header.
fn write_csv(path: &Path, header: &str, columns: &[&[f64]]) {
    let mut text = format!("{header}\n");
    for i in 0..columns[0].len() {
        let row: Vec<String> = columns.iter().map(|c| format!("{:?}", c[i])).collect();
        text.push_str(&row.join(","));
        text.push('\n');
    }
    std::fs::write(path, text).expect("write the data");
}

/// Two periods of the slow loop (gamma = inf, after a decayed transient) with noise: `u,F`.
fn slow_file(dir: &Path, model: &LuGre, turning: &[f64]) -> PathBuf {
    let tp = TurningPoints::new(turning).unwrap();
    let input = PiecewiseLinear::from_turning_points(&tp, 1.0).unwrap();
    let p = input.period();
    let times = merge_times(&uniform_times(0.0, p, 6, 500), &input.knot_times(6));
    let mut out = Trajectory::default();
    Simulator::new(model, Gamma::INFINITE, 0.0)
        .unwrap()
        .at_times(&input, 6, &times, &mut out)
        .unwrap();
    let from = out.range_between(4.0 * p, f64::INFINITY).start;
    let f = noisy(&out.y[from..], 11);
    let path = dir.join("slow.csv");
    write_csv(&path, "u,F", &[&out.u[from..], &f]);
    path
}

/// Triangles between -amp and amp at each speed (two sweeps each), the exact simulation of
/// eq. 1 from x0 = 0, with noise: `t,u,F`.
fn rate_file(dir: &Path, name: &str, model: &LuGre, amp: f64, speeds: &[f64]) -> PathBuf {
    let (mut t, mut u) = (vec![0.0], vec![-amp]);
    for &v in speeds {
        for target in [amp, -amp] {
            let (t0, u0) = (t[t.len() - 1], u[u.len() - 1]);
            let dur = f64::abs(target - u0) / v;
            for j in 1..=300 {
                let x = f64::from(j) / 300.0;
                t.push(t0 + dur * x);
                u.push(u0 + (target - u0) * x);
            }
        }
    }
    let input = PiecewiseLinear::new(t.clone(), u.clone()).unwrap();
    let mut out = Trajectory::default();
    Simulator::new(model, Gamma::ONE, 0.0)
        .unwrap()
        .at_knots(&input, 1, &mut out)
        .unwrap();
    let f = noisy(&out.y, 12);
    let path = dir.join(name);
    write_csv(&path, "t,u,F", &[&t, &u, &f]);
    path
}

/// The estimate of `name` within `tol` of `want`, and `want` inside its interval.
#[track_caller]
fn recovered(doc: &serde_json::Value, name: &str, want: f64, tol: f64) {
    let p = &doc["parameters"][name];
    let value = p["value"]
        .as_f64()
        .unwrap_or_else(|| panic!("{name}: {doc}"));
    let ci = [
        p["ci95"][0].as_f64().unwrap(),
        p["ci95"][1].as_f64().unwrap(),
    ];
    assert!(
        ((value - want) / want).abs() <= tol,
        "{name}: {value} vs {want}"
    );
    assert!(
        ci[0] <= want && want <= ci[1],
        "{name}: {want} outside {ci:?}"
    );
    assert!(p["stderr"].as_f64().unwrap() > 0.0);
}

#[test]
fn slow_fit_json_has_the_documented_shape_and_recovers_example_4() {
    let dir = scratch("slow-json");
    let file = slow_file(
        &dir,
        &LuGre::paper().with_sigma0(6.0).unwrap(),
        &[0.0, 1.0, 0.5, 1.5],
    );
    let f = file.to_str().unwrap();
    let doc = json(&["fit", "--input", f, "--json"]);
    recovered(&doc, "sigma0", 6.0, 0.02);
    recovered(&doc, "fs", 2.0, 0.02);
    let params = doc["parameters"].as_object().unwrap();
    assert_eq!(params.len(), 2);
    for p in params.values() {
        for key in ["value", "stderr", "ci95"] {
            assert!(p.get(key).is_some(), "{key} in {p}");
        }
        assert_eq!(p["ci95"].as_array().unwrap().len(), 2);
    }
    assert!(doc["rms"].as_f64().unwrap() > 0.0);
    assert!(doc["iterations"].as_u64().unwrap() >= 1);
    assert_eq!(doc["fit"], "slow");
    assert_eq!(doc["model"], "lugre");
    assert_eq!(doc["converged"], true);
    assert_eq!(doc["turning_points"], 8);
}

#[test]
fn slow_fit_table_and_fixed_parameters() {
    let dir = scratch("slow-table");
    let file = slow_file(
        &dir,
        &LuGre::paper().with_sigma0(6.0).unwrap(),
        &[0.0, 1.0, 0.5, 1.5],
    );
    let f = file.to_str().unwrap();
    let out = lugre(&["fit", "--input", f]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    for want in [
        "LuGre slow-loop fit",
        "95 % confidence interval",
        "sigma0",
        "fs = g(0)",
        "residual RMS",
        "converged",
    ] {
        assert!(text.contains(want), "{want} in\n{text}");
    }
    // Fs held at 2 (the truth): only sigma0 is fitted.
    let doc = json(&["fit", "--input", f, "--fix", "fs", "--fs", "2", "--json"]);
    assert_eq!(doc["parameters"].as_object().unwrap().len(), 1);
    recovered(&doc, "sigma0", 6.0, 0.02);
    assert_eq!(doc["fixed"]["fs"], 2.0);
    // The same with the value given with --fix.
    let same = json(&["fit", "--input", f, "--fix", "fs=2", "--json"]);
    assert_eq!(same["parameters"], doc["parameters"]);
    assert_eq!(same["fixed"]["fs"], 2.0);
    rejects(&["fit", "--input", f, "--fix", "fs=two"], "--fix");
    rejects(&["fit", "--input", f, "--fix", "fs=-1"], "fs");
    // A start value from the flags is only a start.
    let doc = json(&["fit", "--input", f, "--sigma0", "50", "--json"]);
    recovered(&doc, "sigma0", 6.0, 0.02);
}

#[test]
fn slow_fit_of_dahl() {
    let dir = scratch("dahl");
    let dahl = lugre::Dahl::new(2.0, 0.8).unwrap();
    let file = slow_file(&dir, &dahl.to_lugre(), &[-1.0, 1.0]);
    let doc = json(&[
        "fit",
        "--model",
        "dahl",
        "--input",
        file.to_str().unwrap(),
        "--json",
    ]);
    recovered(&doc, "rho", 2.0, 0.02);
    recovered(&doc, "fc", 0.8, 0.02);
    assert_eq!(doc["model"], "dahl");
}

#[test]
fn full_fit_recovers_canudas_de_wit_1995() {
    let dir = scratch("full");
    let p = LuGreParams::canudas_de_wit_1995();
    let speeds = [1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 1e-1];
    let file = rate_file(
        &dir,
        "full.csv",
        &LuGre::from_params(p).unwrap(),
        1e-3,
        &speeds,
    );
    let doc = json(&[
        "fit",
        "--fit",
        "full",
        "--beta",
        "2",
        "--input",
        file.to_str().unwrap(),
        "--json",
    ]);
    for (name, want) in [
        ("sigma0", p.sigma0),
        ("sigma1", p.sigma1),
        ("sigma2", p.sigma2),
        ("fc", p.fc),
        ("fs", p.fs),
        ("vs", p.vs),
    ] {
        recovered(&doc, name, want, 0.05);
    }
    assert_eq!(doc["fixed"]["beta"], 2.0);
    assert_eq!(doc["fit"], "full");
    assert_eq!(doc["starts"], 3);
}

#[test]
fn csv_and_plots_are_written() {
    let dir = scratch("outputs");
    let file = slow_file(
        &dir,
        &LuGre::paper().with_sigma0(6.0).unwrap(),
        &[0.0, 1.0, 0.5, 1.5],
    );
    let csv = dir.join("fit.csv");
    let svg = dir.join("fit.svg");
    let out = lugre(&[
        "fit",
        "--input",
        file.to_str().unwrap(),
        "--csv",
        csv.to_str().unwrap(),
        "--plot",
        svg.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("u,F,fit,residual"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert!(rows.len() > 500);
    for r in &rows {
        assert!(
            (r[1] - r[2] - r[3]).abs() <= 1e-12 * r[1].abs().max(1.0),
            "{r:?}"
        );
    }
    let s = std::fs::read_to_string(&svg).unwrap();
    assert!(s.starts_with("<svg") && s.contains("polyline"));
    assert!(s.contains("residual F - fit") && s.contains("friction force F"));
    let png = dir.join("fit.png");
    let out = lugre(&[
        "fit",
        "--input",
        file.to_str().unwrap(),
        "--plot",
        png.to_str().unwrap(),
    ]);
    assert!(out.status.success());
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    // A wrong extension is refused before any work.
    rejects(
        &[
            "fit",
            "--input",
            file.to_str().unwrap(),
            "--plot",
            "fit.pdf",
        ],
        "must end in .svg or .png",
    );
}

#[test]
fn sigma1_from_quasi_static_data_is_an_error() {
    let dir = scratch("unidentifiable");
    // The paper's model 1000 times slower than vs: sigma1 z' is far below the noise.
    let file = rate_file(&dir, "qs.csv", &LuGre::paper(), 6.0, &[1e-3]);
    let f = file.to_str().unwrap();
    rejects(
        &[
            "fit",
            "--fit",
            "full",
            "--input",
            f,
            "--fix",
            "sigma0=1,sigma2=0,fc=1,fs=2,vs=1,beta=1",
        ],
        "sigma1 cannot be identified from this data",
    );
    rejects(
        &[
            "fit", "--fit", "full", "--input", f, "--fix", "sigma2=0", "--beta", "1",
        ],
        "sigma1",
    );
    // No parameter silently takes the paper's dimensionless default.
    rejects(
        &["fit", "--fit", "full", "--input", f, "--fix", "sigma2=0"],
        "beta is held in the full fit but has no value: give it (e.g. 2, the usual Stribeck exponent) or fit it too (--beta V, --fix beta=V or --free beta)",
    );
    rejects(
        &[
            "fit", "--fit", "full", "--input", f, "--fix", "sigma2", "--beta", "1",
        ],
        "sigma2 is held in the full fit but has no value",
    );
    rejects(
        &["fit", "--input", f, "--free", "sigma1"],
        "sigma1 does not enter the slow loop",
    );
}

#[test]
fn bad_input_is_one_line_and_status_2() {
    let dir = scratch("errors");
    let file = slow_file(
        &dir,
        &LuGre::paper().with_sigma0(6.0).unwrap(),
        &[0.0, 1.0, 0.5, 1.5],
    );
    let f = file.to_str().unwrap();
    let write = |name: &str, text: &str| {
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        p.to_str().unwrap().to_string()
    };
    let ramp = write(
        "ramp.csv",
        &(0..20).map(|i| format!("{i},{i}\n")).collect::<String>(),
    );
    rejects(&["fit", "--input", &ramp], "has no reversal");
    let few = write("few.csv", "u,F\n0,0\n1,1\n0,0\n");
    rejects(&["fit", "--input", &few], "too few samples: 3");
    // NaN marks an input-only row (for the full fit); an infinite force is an error.
    let nan = write("nan.csv", "u,F\n0,0\n1,nan\n");
    rejects(&["fit", "--input", &nan], "row 2 has no force");
    let inf = write("inf.csv", "u,F\n0,0\n1,inf\n");
    rejects(
        &["fit", "--input", &inf],
        "line 3: F must be a finite number, got inf",
    );
    let header = write("header.csv", "a,b\n0,0\n");
    rejects(
        &["fit", "--input", &header],
        "line 1: no column u (u, x, position or displacement) in the header 'a,b'",
    );
    let times = write("times.csv", "t,u,F\n0,0,0\n1,1,1\n1,0,0\n");
    rejects(
        &["fit", "--fit", "full", "--input", &times],
        "line 4: times must be strictly increasing",
    );
    rejects(
        &["fit", "--fit", "full", "--input", f],
        "a full fit needs the samples' times",
    );
    rejects(
        &[
            "fit",
            "--input",
            f,
            "--sigma0",
            "0.5",
            "--bounds",
            "sigma0=1:10",
        ],
        "exclude its start value 0.5",
    );
    rejects(
        &["fit", "--input", f, "--bounds", "sigma0=5:1"],
        "must satisfy 0 <= lo < hi",
    );
    rejects(
        &["fit", "--input", f, "--fix", "rho"],
        "unknown parameter 'rho'",
    );
    rejects(
        &["fit", "--input", f, "--fix", "sigma0,fs"],
        "nothing to fit",
    );
    rejects(
        &["fit", "--input", f, "--x0", "1"],
        "--x0 applies to the full fit",
    );
    rejects(&["fit"], "no data");
    rejects(
        &["fit", "--input", f, "--model", "dahl", "--sigma0", "3"],
        "--sigma0 is a LuGre parameter",
    );
}

/// A lab's file as it comes: tab-separated, units in the header (mm, uN), an extra column and
/// the opposite sign convention. One command fits it: `--columns` names the columns, `--scale`
/// brings them to m and N with the sign flipped; the result is the fit of the SI file.
#[test]
fn a_lab_file_in_mm_and_micronewtons_with_the_opposite_sign() {
    let dir = scratch("lab");
    let model = LuGre::from_params(LuGreParams::canudas_de_wit_1995()).unwrap();
    let si = slow_file(&dir, &model, &[-2e-5, 2e-5]);
    let text = std::fs::read_to_string(&si).unwrap();
    let mut lab = String::from("Time [s]\tNormal [uN]\tPosition [mm]\tFriction [uN]\n");
    for (i, line) in text.lines().skip(1).enumerate() {
        let (u, f) = line.split_once(',').unwrap();
        let (u, f): (f64, f64) = (u.parse().unwrap(), f.parse().unwrap());
        lab.push_str(&format!(
            "{}\t5e6\t{:?}\t{:?}\n",
            i as f64 * 1e-3,
            u * 1e3,
            -f * 1e6
        ));
    }
    let path = dir.join("lab.tsv");
    std::fs::write(&path, lab).unwrap();
    let path = path.to_str().unwrap();
    let si = si.to_str().unwrap();
    let got = json(&[
        "fit",
        "--input",
        path,
        "--columns",
        "t=Time,u=Position,F=Friction",
        "--scale",
        "u=1e-3,F=-1e-6",
        "--json",
    ]);
    let want = json(&["fit", "--input", si, "--json"]);
    for p in ["sigma0", "fs"] {
        let (a, b) = (
            got["parameters"][p]["value"].as_f64().unwrap(),
            want["parameters"][p]["value"].as_f64().unwrap(),
        );
        assert!((a - b).abs() <= 1e-9 * b.abs(), "{p}: {a} vs {b}");
    }
    // Columns by number, and the mistakes a user makes, each one line.
    let by_number = json(&[
        "fit",
        "--input",
        path,
        "--columns",
        "t=1,u=3,F=4",
        "--scale",
        "u=1e-3,F=-1e-6",
        "--json",
    ]);
    assert_eq!(by_number["parameters"], got["parameters"]);
    rejects(
        &["fit", "--input", path, "--columns", "u=Positon,F=Friction"],
        "--columns u=Positon: no such column in the header",
    );
    let e = rejects(
        &["fit", "--input", path, "--columns", "u=Positon,F=Friction"],
        "did you mean 'Position [mm]'?",
    );
    assert!(e.contains("Time [s]"), "{e}");
    for (flag, value, message) in [
        (
            "--scale",
            "u=0",
            "--scale u=0: a factor must be a finite number other than 0",
        ),
        ("--scale", "w=2", "--scale: unknown column role 'w'"),
        (
            "--columns",
            "u=9,F=4",
            "--columns u=9: the file has 4 columns",
        ),
    ] {
        rejects(&["fit", "--input", path, flag, value], message);
    }
    // Without --columns and --scale the header's names are enough to read it, in the file's
    // own units and sign (mm, uN, friction opposed): fitted as it stands, refused here as the
    // values it holds cannot identify the model.
    rejects(
        &["fit", "--input", path],
        "cannot be identified from this data",
    );
}

/// A dense displacement with a sparse force: rows with an empty F (or NaN) drive the model but
/// carry no residual. Two of every three forces blanked, the full fit still finds the model;
/// its CSV has empty fields there, never NaN; the slow fit and an F-less file say why not.
#[test]
fn input_only_rows_in_a_full_fit() {
    let dir = scratch("sparse");
    let model = LuGre::paper();
    let dense = rate_file(&dir, "dense.csv", &model, 6.0, &[0.3, 1.0, 3.0]);
    let text = std::fs::read_to_string(&dense).unwrap();
    let mut sparse = String::from("t,u,F\n");
    for (i, line) in text.lines().skip(1).enumerate() {
        let (tu, f) = line.rsplit_once(',').unwrap();
        let f = match i % 3 {
            0 => f,
            1 => "",
            _ => "NaN",
        };
        sparse.push_str(&format!("{tu},{f}\n"));
    }
    let path = dir.join("sparse.csv");
    std::fs::write(&path, &sparse).unwrap();
    let (path, csv) = (path.to_str().unwrap(), dir.join("out.csv"));
    let j = json(&[
        "fit",
        "--input",
        path,
        "--fit",
        "full",
        "--fix",
        "sigma2=0",
        "--beta",
        "1",
        "--json",
        "--csv",
        csv.to_str().unwrap(),
    ]);
    let rows = text.lines().count() - 1;
    assert_eq!(j["samples"].as_u64().unwrap() as usize, rows.div_ceil(3));
    for (name, want) in [("sigma0", 1.0), ("fc", 1.0), ("fs", 2.0)] {
        let v = j["parameters"][name]["value"].as_f64().unwrap();
        assert!((v - want).abs() < 0.05 * want, "{name} = {v}");
    }
    let out = std::fs::read_to_string(&csv).unwrap();
    assert!(!out.to_ascii_lowercase().contains("nan"), "{out}");
    let second = out.lines().nth(2).unwrap();
    assert!(second.contains(",,") && second.ends_with(','), "{second}");
    rejects(
        &["fit", "--input", path],
        "row 2 has no force: the slow fit needs one at every row",
    );
    let empty = dir.join("empty.csv");
    std::fs::write(&empty, "t,u,F\n0,0,\n1,1,\n2,0,\n").unwrap();
    rejects(
        &["fit", "--input", empty.to_str().unwrap(), "--fit", "full"],
        "no row has a force",
    );
}

/// Sparse samples of a smooth motion (433 of a sine's 17 281) fitted with the cubic reading:
/// the residual RMS within 2 % of the fit on the dense input (the same forces, the dense
/// displacement driving the model through input-only rows), where the linear reading of the
/// sparse samples is several times worse; and the same samples as a velocity record.
#[test]
fn a_sparse_sine_record_fits_with_the_cubic_reading() {
    let dir = scratch("cubic");
    let model = LuGre::paper();
    let (n, every) = (17_281usize, 40usize); // 433 samples kept
    let t: Vec<f64> = (0..n).map(|i| 8.0 * i as f64 / (n - 1) as f64).collect();
    let u: Vec<f64> = t
        .iter()
        .map(|&t| 6.0 * (std::f64::consts::TAU * t / 4.0).sin())
        .collect();
    let mut out = Trajectory::default();
    Simulator::new(&model, Gamma::ONE, 0.0)
        .unwrap()
        .at_knots(
            &PiecewiseLinear::new(t.clone(), u.clone()).unwrap(),
            1,
            &mut out,
        )
        .unwrap();
    let f = noisy(&out.y, 21);
    let kept: Vec<usize> = (0..n).step_by(every).collect();
    assert_eq!(kept.len(), 433);
    let pick = |xs: &[f64]| -> Vec<f64> { kept.iter().map(|&i| xs[i]).collect() };
    let sparse = dir.join("sparse.csv");
    write_csv(&sparse, "t,u,F", &[&pick(&t), &pick(&u), &pick(&f)]);
    let dense_f: Vec<f64> = (0..n)
        .map(|i| if i % every == 0 { f[i] } else { f64::NAN })
        .collect();
    let dense = dir.join("dense.csv");
    write_csv(&dense, "t,u,F", &[&t, &u, &dense_f]);
    let rms = |path: &Path, extra: &[&str]| -> f64 {
        let mut args = vec![
            "fit",
            "--input",
            path.to_str().unwrap(),
            "--fit",
            "full",
            "--fix",
            "sigma2=0",
            "--beta",
            "1",
            "--json",
        ];
        args.extend(extra);
        json(&args)["rms"].as_f64().unwrap()
    };
    let (dense, cubic, linear) = (
        rms(&dense, &[]),
        rms(&sparse, &["--interpolate", "cubic"]),
        rms(&sparse, &[]),
    );
    // The same 433 samples as a velocity record (t, v, F: the tribometer's other usual
    // layout, here with the headers a lab writes), integrated from u = 0.
    let v: Vec<f64> = t
        .iter()
        .map(|&t| 6.0 * std::f64::consts::TAU / 4.0 * (std::f64::consts::TAU * t / 4.0).cos())
        .collect();
    let by_velocity = dir.join("velocity.csv");
    write_csv(
        &by_velocity,
        "Time [s],Velocity [m/s],Friction [N]",
        &[&pick(&t), &pick(&v), &pick(&f)],
    );
    let velocity = rms(&by_velocity, &[]);
    let no_times = dir.join("no-times.csv");
    write_csv(&no_times, "v,F", &[&pick(&v), &pick(&f)]);
    rejects(
        &["fit", "--input", no_times.to_str().unwrap()],
        "line 1: no column t (t or time) in the header 'v,F'",
    );
    eprintln!("rms: dense {dense:e}, cubic {cubic:e}, linear {linear:e}, velocity {velocity:e}");
    assert!(
        (cubic - dense).abs() <= 0.02 * dense,
        "cubic {cubic:e} vs dense {dense:e}"
    );
    assert!(
        (velocity - dense).abs() <= 0.02 * dense,
        "velocity record {velocity:e} vs dense {dense:e}"
    );
    // Read as given, the linear reading's O(h) error shows; with the noise handling (the
    // default) the samples are read as a smooth motion, each output with its own velocity.
    let as_given = rms(&sparse, &["--noise", "off"]);
    assert!(
        as_given > 1.5 * dense,
        "linear as given {as_given:e} vs dense {dense:e}"
    );
    assert!(
        (linear - dense).abs() <= 0.02 * dense,
        "linear {linear:e} vs dense {dense:e}"
    );
}

/// The lab file (examples/data: Time [s], Normal [uN], Position [mm], Friction [uN], the force
/// with the opposite sign) fitted to the friction coefficient with `--columns N=Normal`: its
/// normal force is a constant 5 N, so sigma0 per newton and mu_s are the force fit's sigma0 and
/// Fs divided by 5. A normal force <= 0 is refused, naming the row.
#[test]
fn a_normal_force_column_gives_friction_coefficients() {
    let lab = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/data/lab-slow-loop.tsv"
    );
    let args = |normal: bool| -> Vec<&str> {
        let columns = if normal {
            "u=3,F=4,N=Normal"
        } else {
            "u=3,F=4"
        };
        let scale = if normal {
            "u=1e-3,F=-1e-6,N=1e-6"
        } else {
            "u=1e-3,F=-1e-6"
        };
        vec![
            "fit",
            "--input",
            lab,
            "--columns",
            columns,
            "--scale",
            scale,
            "--json",
        ]
    };
    let force = json(&args(false));
    let coefficient = json(&args(true));
    assert_eq!(force["normal_force"], false);
    assert_eq!(coefficient["normal_force"], true);
    let value =
        |doc: &serde_json::Value, name: &str| doc["parameters"][name]["value"].as_f64().unwrap();
    for (per_newton, force_name) in [("sigma0", "sigma0"), ("mu_s", "fs")] {
        let (a, b) = (
            5.0 * value(&coefficient, per_newton),
            value(&force, force_name),
        );
        assert!(
            (a - b).abs() <= 1e-6 * b,
            "{per_newton}: 5 x {a} vs {force_name} {b}"
        );
    }
    let dir = scratch("normal");
    let bad = dir.join("bad-normal.csv");
    std::fs::write(&bad, "u,F,N\n0,0,1\n1,1,1\n0,0.5,0\n-1,-1,1\n0,0,1\n").unwrap();
    rejects(
        &["fit", "--input", bad.to_str().unwrap(), "--columns", "N=N"],
        "bad-normal.csv: line 4: N must be > 0, got 0",
    );
}

#[test]
fn noise_is_estimated_reported_and_gated() {
    let dir = scratch("noise");
    let servo = servo_file(&dir);
    let servo = servo.to_str().unwrap();
    let full = [
        "fit",
        "--fit",
        "full",
        "--input",
        servo,
        "--beta",
        "2",
        "--scale",
        "u=1e-3",
        "--fix",
        "sigma2=40",
    ];
    let doc = json(&[&full[..], &["--json"]].concat());
    let noise = &doc["noise"];
    // sqrt(0.5^2 + 0.1^2 / 12) um and 0.2 N, to the median's few per cent.
    let position = noise["position"].as_f64().unwrap();
    assert!((position / 0.5008e-6 - 1.0).abs() < 0.06, "{noise}");
    assert!(
        (noise["force"].as_f64().unwrap() / 0.2 - 1.0).abs() < 0.06,
        "{noise}"
    );
    assert_eq!(noise["handling"], "smoothed");
    assert!(noise["lambda"].as_f64().unwrap() > 1.0, "{noise}");
    for (name, want) in [("sigma0", 1e6), ("fc", 15.0), ("fs", 22.0), ("vs", 4e-3)] {
        let got = doc["parameters"][name]["value"].as_f64().unwrap();
        assert!((got / want - 1.0).abs() < 0.02, "{name}: {got} vs {want}");
    }
    assert!(doc["warnings"].is_array(), "{doc}");
    // The table says what was found and done.
    let out = lugre(&full);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("noise estimated in the record: position"),
        "{text}"
    );
    assert!(text.contains("smooth motion nearest the samples"), "{text}");
    // Off: the samples as given (the noise still reported), and the intervals said to be
    // untrustworthy.
    let doc = json(&[&full[..], &["--json", "--noise", "off"]].concat());
    assert_eq!(doc["noise"]["handling"], "as_given");
    let warnings = doc["warnings"].as_array().unwrap();
    assert!(
        warnings.iter().any(|w| w
            .as_str()
            .unwrap()
            .starts_with("the intervals cannot be trusted")),
        "{doc}"
    );
    rejects(
        &[&full[..], &["--noise", "some"]].concat(),
        "expected one of auto, off",
    );
    rejects(
        &[&full[..], &["--gate", "1e-6"]].concat(),
        "--gate applies to the slow fit",
    );
    // The slow fit's gate: given, reported, checked.
    let slow = slow_file(&dir, &LuGre::paper().with_sigma0(6.0).unwrap(), &[0.0, 1.0]);
    let slow = slow.to_str().unwrap();
    let doc = json(&["fit", "--input", slow, "--gate", "0.01", "--json"]);
    assert_eq!(doc["noise"]["handling"], "gate");
    assert_eq!(doc["noise"]["gate"], 0.01);
    assert_eq!(doc["turning_points"], 4);
    rejects(
        &["fit", "--input", slow, "--gate", "-1"],
        "--gate: the gate must be a finite number >= 0",
    );
}

/// A record of the zoo fit's reference (`crates/lugre/tests/reference/zoo_fit_reference.py`).
fn zoo_record(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../lugre/tests/reference/zoo_fit")
        .join(format!("{name}.csv"))
        .display()
        .to_string()
}

#[test]
fn a_model_of_the_zoo_is_fitted_and_echoed_by_name() {
    let input = zoo_record("bouc-wen-noisy");
    let doc = json(&["fit", "--model", "bouc-wen", "--input", &input, "--json"]);
    assert_eq!(doc["model"], "bouc-wen");
    assert_eq!(doc["fit"], "slow");
    assert_eq!(doc["values"]["kind"], "bouc-wen");
    // The generator's values (kx, kw, rho, sigma, n) = (0.1, 1.5, 2, 0.75, 2), force noise 0.01.
    for (name, want) in [
        ("kx", 0.1),
        ("kw", 1.5),
        ("rho", 2.0),
        ("sigma", 0.75),
        ("n", 2.0),
    ] {
        let e = &doc["parameters"][name];
        let (v, se) = (e["value"].as_f64().unwrap(), e["stderr"].as_f64().unwrap());
        assert!((v - want).abs() < 4.0 * se, "{name}: {v} -+ {se}");
        assert_eq!(doc["values"][name].as_f64().unwrap(), v, "{name}");
        assert_eq!(e["at_bound"], false);
    }
    assert_eq!(doc["turning_points"], 4);
    assert!(doc["noise"]["force"].as_f64().unwrap() > 0.009);

    let input = zoo_record("maxwell-slip");
    let doc = json(&[
        "fit",
        "--model",
        "maxwell-slip",
        "--input",
        &input,
        "--json",
        "--elements",
        "4",
    ]);
    let k: Vec<f64> = (0..4)
        .map(|i| {
            doc["parameters"][format!("stiffness[{i}]")]["value"]
                .as_f64()
                .unwrap()
        })
        .collect();
    for (k, want) in k.iter().zip([0.4, 0.3, 0.2, 0.1]) {
        assert!((k / want - 1.0).abs() < 1e-8, "{k} vs {want}");
    }
    assert_eq!(
        doc["fixed"]["slip_displacement"],
        serde_json::json!([0.25, 0.75, 1.25, 1.75])
    );
}

#[test]
fn a_model_of_the_zoo_refuses_what_it_cannot_fit() {
    let input = zoo_record("elastoplastic");
    rejects(
        &["fit", "--model", "elastoplastic", "--input", &input, "--free", "fc"],
        "fc does not enter the slow loop of the elastoplastic model (it depends on sigma0, fs, zba)",
    );
    // The core's message, before the record is read.
    rejects(
        &["fit", "--model", "bouc-wen", "--input", &input, "--fit", "full"],
        "--fit full: the bouc-wen model has no finite-rate form (the models of the zoo with one: maxwell-slip, elastoplastic); fit its slow loop (--fit slow)",
    );
    let timed = zoo_record("elastoplastic-full");
    for (file, extra, message) in [
        (
            &input,
            &["--fit", "stribeck"][..],
            "--fit stribeck: the Elasto-plastic model is fitted to its slow loop (--fit slow) or, with a finite-rate form, to a rate-dependent record (--fit full)",
        ),
        (
            &input,
            &["--fit", "full"][..],
            "a full fit needs the samples' times: columns t,u,F (this file has u,F)",
        ),
        (
            &timed,
            &["--fit", "full", "--x0", "0.1"][..],
            "--x0: x0 = 0.1: the full fit of the elastoplastic model runs from rest",
        ),
        (
            &timed,
            &["--fit", "full", "--gate", "0.1"][..],
            "--gate applies to the slow fit",
        ),
        (
            &timed,
            &["--starts", "2"][..],
            "--starts applies to the full fit (add --fit full)",
        ),
    ] {
        let mut a = vec!["fit", "--model", "elastoplastic", "--input", file];
        a.extend_from_slice(extra);
        rejects(&a, message);
    }
    rejects(
        &[
            "fit",
            "--model",
            "bouc-wen",
            "--input",
            &input,
            "--elements",
            "3",
        ],
        "the bouc-wen model has no elements",
    );
    rejects(
        &["fit", "--input", &input, "--elements", "3"],
        "--elements applies to an element model of the zoo",
    );
    rejects(
        &[
            "fit",
            "--model",
            "maxwell-slip",
            "--input",
            &input,
            "--elements",
            "65",
        ],
        "--elements: the number of elements must be from 1 to 64, got 65",
    );
    let small = zoo_record("bouc-wen-small");
    rejects(
        &["fit", "--model", "bouc-wen", "--input", &small],
        "kx, kw, rho cannot be identified from this data",
    );
}

/// `--fit full` on a record `t,u,F` of the generator (`zoo_full_fit_reference.py`: the
/// elasto-plastic model of Dupont et al. integrated by scipy's Radau at rtol 1e-12, force
/// noise 0.01): every 95 % interval holds the generator's value, and the document has the
/// slow zoo fit's keys (but
/// `turning_points`, as the LuGre full fit) with `"fit": "full"`.
#[test]
fn a_finite_rate_model_of_the_zoo_is_fitted_in_full() {
    let input = zoo_record("elastoplastic-full-noisy");
    let doc = json(&[
        "fit",
        "--model",
        "elastoplastic",
        "--fit",
        "full",
        "--input",
        &input,
        "--json",
    ]);
    assert_eq!(doc["model"], "elastoplastic");
    assert_eq!(doc["fit"], "full");
    assert_eq!(doc["starts"], 3);
    for (name, want) in [
        ("sigma0", 2.0),
        ("fc", 1.0),
        ("fs", 1.5),
        ("zba", 0.3),
        ("sigma1", 0.5),
        ("sigma2", 0.2),
        ("vs", 0.5),
        ("beta", 2.0),
    ] {
        let e = &doc["parameters"][name];
        let ci: Vec<f64> = (0..2).map(|k| e["ci95"][k].as_f64().unwrap()).collect();
        assert!(ci[0] <= want && want <= ci[1], "{name}: {ci:?}");
        assert_eq!(doc["values"][name], e["value"], "{name}");
        assert_eq!(e["at_bound"], false);
    }
    let slow = json(&[
        "fit",
        "--model",
        "elastoplastic",
        "--input",
        &zoo_record("elastoplastic"),
        "--json",
    ]);
    let keys = |d: &serde_json::Value| {
        let mut k: Vec<String> = d.as_object().unwrap().keys().cloned().collect();
        k.sort();
        k
    };
    // The LuGre full fit's keys: `turning_points` is the slow loop's alone.
    let mut slow_keys = keys(&slow);
    slow_keys.retain(|k| k != "turning_points");
    assert_eq!(keys(&doc), slow_keys);
}
