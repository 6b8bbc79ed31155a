//! `lugre sweep` run as a user would: the real binary, its stdout, stderr, files and exit
//! status.

mod common;
use common::{accepts, accepts_json, f, rejects, TempDir};

use lugre::sweep::COLUMNS;

/// The keys the issue fixes (outside tools read them): kept exactly.
const FIXED: [&str; 5] = ["amplitude", "frequency", "dissipation", "gain", "phase"];

#[test]
fn the_documented_command_gives_every_point() {
    let doc = accepts_json(&[
        "sweep",
        "--preset",
        "canudas1995",
        "--amplitudes",
        "1e-6,1e-5",
        "--frequencies",
        "0.1,1",
        "--json",
    ]);
    assert_eq!(f(&doc["model"]["sigma0"]), 1e5);
    assert_eq!(doc["parameters"]["amplitudes"].as_array().unwrap().len(), 2);
    assert!(FIXED.iter().all(|k| COLUMNS.contains(k)));
    let points = doc["points"].as_array().unwrap();
    assert_eq!(points.len(), 4);
    let order = [(1e-6, 0.1), (1e-6, 1.0), (1e-5, 0.1), (1e-5, 1.0)];
    for (p, (a, fr)) in points.iter().zip(order) {
        for c in COLUMNS {
            assert!(p[c].is_number(), "{c} in {p}");
        }
        assert_eq!((f(&p["amplitude"]), f(&p["frequency"])), (a, fr));
        let (d, phase) = (f(&p["dissipation"]), f(&p["phase"]));
        assert!(d > 0.0 && phase > 0.0 && phase < std::f64::consts::PI);
        // The energy is the first harmonic's: D = pi A a1 (eq. P6).
        assert!((d - std::f64::consts::PI * a * f(&p["a1"])).abs() < 1e-12 * d);
        assert!(p.get("loop").is_none());
    }
}

/// At a quasi-static frequency the energy per cycle is the closed-form loop's (`lugre loop`,
/// eq. 10) to 1e-12: two independent computations (the loop's closed form; the integrated
/// orbit).
#[test]
fn quasi_static_energy_is_the_loops() {
    for a in ["1e-6", "1e-5", "1e-4", "1e-3"] {
        let sweep = accepts_json(&[
            "sweep",
            "--preset",
            "canudas1995",
            "--amplitudes",
            a,
            "--frequencies",
            "1e-13",
            "--json",
        ]);
        let tp = format!("--turning-points=-{a},{a}");
        let hl = accepts_json(&["loop", "--preset", "canudas1995", &tp, "--json"]);
        let want = f(&hl["loops"][0]["dissipation"]);
        let got = f(&sweep["points"][0]["dissipation"]);
        assert!(
            (got - want).abs() < 1e-12 * want,
            "A = {a}: {got} vs {want}"
        );
    }
}

#[test]
fn ranges_loops_offset_and_csv() {
    let dir = TempDir::new("sweep-csv");
    let csv = dir.path().join("points.csv");
    let csv_arg = csv.to_str().unwrap();
    let text = accepts(&[
        "sweep",
        "--preset",
        "canudas1995",
        "--amplitudes",
        "1e-7:1e-3:3",
        "--frequencies",
        "1",
        "--csv",
        csv_arg,
    ]);
    assert!(
        text.contains("3 points") && text.contains("Wrote 3 points to"),
        "{text}"
    );
    let written = std::fs::read_to_string(&csv).unwrap();
    let lines: Vec<&str> = written.lines().collect();
    assert_eq!(lines[0], COLUMNS.join(","));
    assert_eq!(lines.len(), 4);
    let amplitudes: Vec<f64> = lines[1..]
        .iter()
        .map(|l| l.split(',').next().unwrap().parse().unwrap())
        .collect();
    assert_eq!(amplitudes, [1e-7, 1e-5, 1e-3]);
    let doc = accepts_json(&[
        "sweep",
        "--amplitudes",
        "0.5",
        "--frequencies",
        "0.2",
        "--offset=-3",
        "--loops",
        "101",
        "--json",
    ]);
    let l = &doc["points"][0]["loop"];
    let u: Vec<f64> = l["u"].as_array().unwrap().iter().map(f).collect();
    let force: Vec<f64> = l["force"].as_array().unwrap().iter().map(f).collect();
    assert_eq!((u.len(), force.len()), (101, 101));
    assert!(u.iter().all(|x| (-3.5 - 1e-12..=-2.5 + 1e-12).contains(x)));
    assert!((force[0] - force[100]).abs() < 1e-9);
    let peak = f(&doc["points"][0]["peak_force"]);
    assert!(force.iter().all(|x| x.abs() <= peak * (1.0 + 1e-12)));
}

#[test]
fn bad_input_is_one_line_naming_the_value() {
    let base = ["sweep", "--preset", "canudas1995"];
    let cases: [(&[&str], &str); 10] = [
        (
            &["--amplitudes", "1e300", "--frequencies", "1"],
            "at amplitude 1e300, frequency 1: the force or the energy per cycle overflows f64 (values too large for this model)",
        ),
        (
            &["--amplitudes", "0", "--frequencies", "1"],
            "--amplitudes: amplitude must be a finite number > 0, got 0",
        ),
        (
            &["--amplitudes", "-1e-6", "--frequencies", "1"],
            "--amplitudes: amplitude must be a finite number > 0, got -1e-6",
        ),
        (
            &["--amplitudes", "1e-6", "--frequencies", "0"],
            "--frequencies: frequency must be a finite number > 0, got 0",
        ),
        (
            &["--amplitudes", "1e-6", "--frequencies", "inf"],
            "--frequencies: frequency must be a finite number > 0, got inf",
        ),
        (
            &["--amplitudes", "1e-6,abc", "--frequencies", "1"],
            "--amplitudes: item 2 is 'abc', which is not a number",
        ),
        (
            &["--amplitudes", "1e-6", "--frequencies", "1:10"],
            "--frequencies: a range is START:STOP:COUNT",
        ),
        (
            &[
                "--amplitudes",
                "1e-7:1e-3:2000",
                "--frequencies",
                "1:10:1000",
                "--loops",
                "1000",
            ],
            "the grid of 2000000 points (2000 amplitudes x 1000 frequencies) with 1000 loop samples each needs about 48",
        ),
        (
            &["--amplitudes", "1e-6", "--frequencies", "1", "--loops", "1"],
            "--loops must be a whole number >= 2, got 1",
        ),
        (
            &["--amplitudes", "1e-6", "--frequencies", "1", "--tol", "0"],
            "--tol: the tolerance must be a number in [1e-14, 1), got 0",
        ),
    ];
    for (args, want) in cases {
        let all: Vec<&str> = base.iter().chain(args).copied().collect();
        rejects(&all, want);
    }
}

/// `--plot` draws the five panels (SVG and PNG alike), with the units of `--units` or the
/// preset's SI in the labels.
#[test]
fn the_figure_has_its_panels_and_units() {
    let dir = TempDir::new("sweep-plot");
    let (svg, png) = (dir.join("sweep.svg"), dir.join("sweep.png"));
    let args = |path: &str, units: &[&'static str]| -> Vec<String> {
        let mut a: Vec<String> = [
            "sweep",
            "--preset",
            "canudas1995",
            "--amplitudes",
            "1e-6:1e-4:3",
            "--frequencies",
            "0.1,10",
            "--plot",
            path,
        ]
        .iter()
        .map(|s| s.to_string())
        .collect();
        a.extend(units.iter().map(|s| s.to_string()));
        a
    };
    let run = |a: Vec<String>| accepts(&a.iter().map(String::as_str).collect::<Vec<_>>());
    run(args(&svg, &[]));
    let text = std::fs::read_to_string(&svg).unwrap();
    for label in [
        "steady-state loops at f = 0.1 Hz",
        "friction against velocity",
        "energy dissipated per cycle",
        "describing function: gain",
        "input u [m]",
        "energy per cycle [J]",
        "A = 1e-5",
        "f = 10 Hz",
    ] {
        assert!(text.contains(label), "{label} not in the figure");
    }
    run(args(&png, &["--units", "u=mm,F=N"]));
    assert!(std::fs::read(&png).unwrap().starts_with(b"\x89PNG"));
    rejects(
        &args(&svg, &["--units", "w=s"])
            .iter()
            .map(String::as_str)
            .collect::<Vec<_>>(),
        "--units: unknown quantity 'w' (give t=UNIT, u=UNIT or F=UNIT)",
    );
}
