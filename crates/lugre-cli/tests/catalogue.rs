//! A catalogue of bad and extreme inputs across every command, run through the real binary with
//! `RUST_BACKTRACE=1`. The promise: whatever a user feeds `lugre`, it either answers exactly
//! (status 0, no NaN or infinity anywhere in the output) or says in one line on stderr what is
//! wrong (status 2, nothing on stdout) — never a panic, a backtrace or a half-written file.
//!
//! Each test is one theme; every case in it is listed with the problem it names. The other
//! test files check each command's normal behaviour and a few errors each; the cases here are
//! the ones they do not.

mod common;

use common::{accepts, accepts_json, f, lugre, rejects, TempDir};

/// A flag that takes a comma-separated list of numbers, in a valid context: the arguments
/// before it, and the list with a bad item at 1-based `position`.
struct ListFlag {
    head: Vec<&'static str>,
    flag: &'static str,
    list: fn(&str) -> String,
    position: usize,
}

fn list_flags() -> Vec<ListFlag> {
    let case = |head: &[&'static str], flag, list, position| ListFlag {
        head: head.to_vec(),
        flag,
        list,
        position,
    };
    vec![
        case(&["loop"], "--turning-points", |x| format!("0,{x},1"), 2),
        case(&["loop"], "--bimodal", |x| format!("0,0.2,1,{x}"), 4),
        case(
            &["loop", "--turning-points", "0,1"],
            "--at",
            |x| format!("0.5,{x}"),
            2,
        ),
        case(&["simulate"], "--turning-points", |x| format!("{x},1"), 1),
        case(&["simulate"], "--bimodal", |x| format!("0,{x},1,1.5"), 2),
        case(&["simulate"], "--sine", |x| format!("1,2,{x}"), 3),
        case(
            &["simulate", "--turning-points", "0,1"],
            "--times",
            |x| format!("0,{x}"),
            2,
        ),
        case(&["cycles"], "--values", |x| format!("1,2,-1,{x},2"), 4),
    ]
}

fn args_with<'a>(head: &'a [&'a str], flag: &'a str, list: &'a str) -> Vec<&'a str> {
    let mut v = head.to_vec();
    v.push(flag);
    v.push(list);
    v
}

/// NaN, infinities, empty items and garbage in every list flag: the flag and the item are
/// named.
#[test]
fn bad_numbers_in_every_list_flag() {
    let bad: [(&str, &str); 9] = [
        ("nan", "must be a finite number, got NaN"),
        ("NaN", "must be a finite number, got NaN"),
        ("inf", "must be a finite number, got inf"),
        ("-infinity", "must be a finite number, got -inf"),
        ("1e999", "must be a finite number, got inf"),
        ("", "is empty"),
        ("0x10", "is '0x10', which is not a number"),
        ("1 2", "is '1 2', which is not a number"),
        ("½", "is '½', which is not a number"),
    ];
    for ListFlag {
        head,
        flag,
        list,
        position,
    } in list_flags()
    {
        for (item, want) in bad {
            let text = list(item);
            rejects(
                &args_with(&head, flag, &text),
                &format!("{flag}: item {position} {want}"),
            );
        }
        // The whole list empty, or only spaces.
        for text in ["", "   "] {
            rejects(
                &args_with(&head, flag, text),
                &format!("{flag}: empty list"),
            );
        }
    }
}

/// One turning point, or values all equal: no loop (status 2) for periodic inputs; a history of
/// equal samples is valid (one half cycle of range 0).
#[test]
fn one_turning_point_and_all_equal_values() {
    let dir = TempDir::new("catalogue-equal");
    rejects(
        &["loop", "--turning-points", "5"],
        "--turning-points: a periodic input needs at least 2 distinct values, got 1",
    );
    rejects(
        &["simulate", "--turning-points", "2,2,2,2"],
        "needs at least 2 distinct values, got 1",
    );
    let one = dir.file("one.csv", "u\n0.25\n");
    rejects(
        &["loop", "--input", &one],
        "needs at least 2 distinct values, got 1",
    );
    let equal = dir.file("equal.csv", "t,u\n0,3\n1,3\n2,3\n");
    rejects(
        &["loop", "--input", &equal],
        "needs at least 2 distinct values, got 1",
    );
    // Simulating a constant input is fine: nothing moves, y stays sigma0 x0.
    let j = accepts_json(&["simulate", "--input", &equal, "--x0", "0.5", "--json"]);
    assert!(j["y"].as_array().unwrap().iter().all(|y| f(y) == 0.5));
    // A history that never moves: one half cycle of range 0, in every output.
    let j = accepts_json(&[
        "cycles",
        "--sigma0",
        "1",
        "--fs",
        "2",
        "--values",
        "4,4,4,4",
        "--energy",
        "--histogram",
        "--json",
    ]);
    assert_eq!(j["half_cycles"], 1);
    assert_eq!(j["full_cycles"], 0);
    assert_eq!(f(&j["cycles"][0]["range"]), 0.0);
    accepts(&[
        "cycles",
        "--sigma0",
        "1",
        "--fs",
        "2",
        "--values",
        "4,4",
        "--histogram",
        "--energy",
    ]);
}

/// Each inequality of Definition 1 (through `simulate`; `loop --bimodal` is checked in
/// loop_cli.rs), and the boundary cases it allows.
#[test]
fn every_definition_1_inequality() {
    for (b, want) in [
        (
            "0.3,0.2,1,1.5",
            "umin1 <= umin2 fails (umin1 = 0.3, umin2 = 0.2)",
        ),
        ("0,1,1,1.5", "umin2 < umax1 fails (umin2 = 1, umax1 = 1)"),
        ("0,1.2,1,1.5", "umin2 < umax1 fails"),
        (
            "0,0.2,1.6,1.5",
            "umax1 <= umax2 fails (umax1 = 1.6, umax2 = 1.5)",
        ),
        (
            "0,0,1,1",
            "umin1 != umin2 or umax1 != umax2 fails (umin1 = umin2 = 0 and umax1 = umax2 = 1)",
        ),
    ] {
        rejects(
            &["simulate", "--bimodal", b],
            &format!("--bimodal: bimodal input breaks Definition 1: {want}"),
        );
    }
    rejects(
        &["simulate", "--bimodal", "0,0.2,1,1.5,2"],
        "--bimodal takes 4 numbers UMIN1,UMIN2,UMAX1,UMAX2, got 5",
    );
    // Each equality alone is allowed, with exactly Theorem A's minor loop [rho_1, rho_5].
    for (b, rho5) in [("0,0,1,1.5", 3.0), ("0,0.2,1,1", 2.6)] {
        let j = accepts_json(&["loop", "--bimodal", b, "--json"]);
        assert_eq!(f(&j["theorem_a"]["minor_loop"][0]), 1.0);
        assert!((f(&j["theorem_a"]["minor_loop"][1]) - rho5).abs() < 1e-15);
    }
}

/// Every model parameter out of its domain, through every command that takes a model.
#[test]
fn every_invalid_model_parameter() {
    let dir = TempDir::new("catalogue-model");
    let data = slow_loop_data(&dir);
    let cases: [(&[&str], &str); 17] = [
        (&["--sigma0", "-1"], "sigma0 must be > 0, got -1"),
        (
            &["--sigma0", "inf"],
            "sigma0 must be a finite number, got inf",
        ),
        (&["--sigma1", "-1"], "sigma1 must be >= 0, got -1"),
        (
            &["--sigma1", "inf"],
            "sigma1 must be a finite number, got inf",
        ),
        (&["--sigma2", "-0.5"], "sigma2 must be >= 0, got -0.5"),
        (
            &["--sigma2", "nan"],
            "sigma2 must be a finite number, got NaN",
        ),
        (&["--fc", "0"], "fc must be > 0, got 0"),
        (&["--fc=-inf"], "fc must be a finite number, got -inf"),
        (&["--fs", "0"], "fs must be > 0, got 0"),
        (&["--fs", "nan"], "fs must be a finite number, got NaN"),
        (&["--vs", "0"], "vs must be > 0, got 0"),
        (&["--vs", "-1"], "vs must be > 0, got -1"),
        // A subnormal vs: 1 / vs overflows, so g(0) would be 0 * inf.
        (
            &["--vs", "4e-309"],
            "vs must be >= 5.56268464626801e-309 (1 / vs overflows below it), got 4e-309",
        ),
        (&["--beta", "0"], "beta must be > 0, got 0"),
        (
            &["--beta", "1e999"],
            "--beta expects a finite number, got '1e999'",
        ),
        (&["--model", "dahl", "--rho", "0"], "rho must be > 0, got 0"),
        (
            &["--model", "dahl", "--rho", "1e200", "--fc", "1e200"],
            "sigma0 = rho * fc must be a finite number, got inf",
        ),
    ];
    let commands: [&[&str]; 4] = [
        &["loop", "--turning-points", "0,1"],
        &["simulate", "--turning-points", "0,1"],
        &["cycles", "--values", "0,1,0", "--energy"],
        &["fit", "--input", &data],
    ];
    for (i, (model, want)) in cases.iter().enumerate() {
        // Every case through one command in turn, and the first ones through all of them.
        let which: Vec<&[&str]> = if i < 2 {
            commands.to_vec()
        } else {
            vec![commands[i % commands.len()]]
        };
        for cmd in which {
            let mut args = cmd.to_vec();
            args.extend_from_slice(model);
            rejects(&args, want);
        }
    }
    // sigma0 / g(0) underflows to 0: a is not a positive number.
    rejects(
        &[
            "loop",
            "--turning-points",
            "0,1",
            "--sigma0",
            "1e-300",
            "--fs",
            "1e300",
        ],
        "a = sigma0 / g(0) = 1e-300 / 1e300 is not a finite positive number",
    );
}

/// `gamma` 0, negative, NaN, empty, garbage, underflowing to 0 or so small that 1 / gamma
/// overflows; `inf` and huge values are the rate-independent limit.
#[test]
fn gamma_zero_negative_nan_and_extremes() {
    let b = ["simulate", "--bimodal", "0,0.2,1,1.5", "--gamma"];
    for (g, want) in [
        ("-0", "gamma must be > 0 (a positive number or inf), got -0"),
        (
            "1e-400",
            "gamma must be > 0 (a positive number or inf), got 0",
        ),
        ("-inf", "--gamma must be a number > 0 or 'inf', got '-inf'"),
        ("NaN", "--gamma must be a number > 0 or 'inf', got 'NaN'"),
        ("", "--gamma must be a number > 0 or 'inf', got ''"),
        ("ten", "--gamma must be a number > 0 or 'inf', got 'ten'"),
        ("4e-320", "overflows f64"),
    ] {
        let mut args = b.to_vec();
        args.push(g);
        rejects(&args, want);
    }
    // gamma = inf and gamma = 1e308 both give the rate-independent limit y*_u.
    let inf = accepts_json(&[
        "simulate",
        "--bimodal",
        "0,0.2,1,1.5",
        "--gamma",
        "Infinity",
        "--json",
    ]);
    let huge = accepts_json(&[
        "simulate",
        "--bimodal",
        "0,0.2,1,1.5",
        "--gamma",
        "1e308",
        "--json",
    ]);
    for (a, b) in inf["y"]
        .as_array()
        .unwrap()
        .iter()
        .zip(huge["y"].as_array().unwrap())
    {
        assert!((f(a) - f(b)).abs() <= 1e-15, "{a} {b}");
    }
}

/// The CSV reader's corner cases, for every command that reads one: a clean file and its
/// CRLF, BOM, commented and blank-padded versions give the same answers; every malformed file
/// is one line naming the line.
#[test]
fn csv_files_good_and_bad() {
    let dir = TempDir::new("catalogue-csv");
    let clean = "t,u\n0,0\n1,1\n1.8,0.2\n3.1,1.5\n4.6,0\n";
    let variants = [
        ("clean.csv", clean.to_string()),
        ("crlf.csv", clean.replace('\n', "\r\n")),
        ("cr-only.csv", clean.replace('\n', "\r")),
        ("bom.csv", format!("\u{feff}{clean}")),
        (
            "comments.csv",
            format!(
                "# a measured period\n{}",
                clean.replace("1,1\n", "1,1\n# the peak\n")
            ),
        ),
        (
            "blank-lines.csv",
            format!("\n{}\n\n\n", clean.replace("1,1\n", "1,1\n\n")),
        ),
        ("no-final-newline.csv", clean.trim_end().to_string()),
        ("spaces.csv", clean.replace(',', " , ")),
        ("tabs.csv", clean.replace(',', "\t")),
        // The usual names with units, and columns the commands do not read.
        (
            "units.csv",
            clean.replace("t,u\n", "Time [s],Displacement [um]\n"),
        ),
        (
            "extra-columns.csv",
            clean
                .lines()
                .map(|l| format!("{l},{}\n", if l == "t,u" { "F" } else { "7" }))
                .collect(),
        ),
    ];
    let runs: [&[&str]; 3] = [
        &["loop", "--json", "--input"],
        &["simulate", "--json", "--input"],
        &[
            "cycles", "--sigma0", "1", "--fs", "2", "--json", "--energy", "--input",
        ],
    ];
    for run in runs {
        let mut first: Option<serde_json::Value> = None;
        for (name, text) in &variants {
            let path = dir.file(name, text);
            let mut args = run.to_vec();
            args.push(&path);
            let j = accepts_json(&args);
            match &first {
                None => first = Some(j),
                Some(want) => assert_eq!(&j, want, "{name} differs from clean.csv"),
            }
        }
    }
    // No header: one column is u, two are t,u (simulate needs the times).
    let no_header = dir.file("no-header.csv", "0\n1\n0.2\n1.5\n");
    let a = accepts_json(&["loop", "--input", &no_header, "--json"]);
    let b = accepts_json(&["loop", "--turning-points", "0,1,0.2,1.5", "--json"]);
    assert_eq!(a, b);
    rejects(
        &["simulate", "--input", &no_header],
        "line 1: expected 2 columns (t,u), found 1",
    );

    let bad: [(&str, &[u8], &str); 13] = [
        (
            "wrong-header.csv",
            b"time,value\n0,1\n1,2\n",
            "line 1: no column u (u, x, position or displacement) in the header 'time,value'",
        ),
        (
            // After comments, CRLF: the header's own line.
            "wrong-header-crlf.csv",
            b"# rig 3\r\n# 2024-05-01\r\ntime,value\r\n0,1\r\n1,2\r\n",
            "line 3: no column u",
        ),
        (
            "two-u-columns.csv",
            b"t,u,x\n0,0,0\n1,1,1\n",
            "line 1: the header has two columns for u: 'u' (column 2) and 'x' (column 3)",
        ),
        (
            "missing-cell.csv",
            b"t,u\n0,0\n1,\n2,0\n",
            "line 3: empty value for u",
        ),
        (
            "missing-time.csv",
            b"t,u\n0,0\n,1\n",
            "line 3: empty value for t",
        ),
        (
            "short-row.csv",
            b"t,u\n0,0\n1\n",
            "line 3: expected 2 values (t,u), found 1",
        ),
        (
            "extra-cell.csv",
            b"t,u\n0,0\n1,1,2\n",
            "line 3: expected 2 values (t,u), found 3",
        ),
        (
            "non-utf8.csv",
            b"t,u\n0,0\n1,\xff\xfe\n",
            "line 3: not valid UTF-8 text",
        ),
        (
            "latin1-header.csv",
            b"t,\xb5\n0,0\n",
            "line 1: not valid UTF-8 text",
        ),
        (
            "decreasing.csv",
            b"t,u\n0,0\n2,1\n1,0\n",
            "line 4: times must be strictly increasing, t = 1 follows t = 2",
        ),
        (
            "repeated.csv",
            b"t,u\n0,0\n1,1\n1,0\n",
            "line 4: times must be strictly increasing, t = 1 follows t = 1",
        ),
        (
            "inline-comment.csv",
            b"t,u\n0,0\n1,1 # peak\n",
            "line 3: u = '1 # peak' is not a number",
        ),
        ("bom-only.csv", b"\xef\xbb\xbf", "no data rows"),
    ];
    for (name, text, want) in bad {
        let path = dir.file(name, text);
        for cmd in ["loop", "simulate"] {
            rejects(&[cmd, "--input", &path], want);
        }
    }
    // A file without line breaks is refused at its first megabyte, not read into memory.
    let long = dir.file("one-long-line.csv", vec![b'7'; 3 << 20]);
    for cmd in ["loop", "simulate", "cycles"] {
        rejects(
            &[cmd, "--input", &long],
            "line 1: a line is longer than 1048576 bytes (not a CSV file of numbers?)",
        );
    }
    #[cfg(unix)]
    rejects(&["cycles", "--input", "/dev/zero"], "a line is longer than");
    #[cfg(unix)]
    rejects(
        &["loop", "--input", dir.path().to_str().unwrap()],
        "Is a directory",
    );
    // cycles reads any header naming the column, and needs at least one sample.
    let path = dir.file("only-comments.csv", "# nothing\n\n# here\n");
    rejects(
        &["cycles", "--input", &path],
        "the history is empty (no samples)",
    );
    let path = dir.file("decreasing-t.csv", "t,u\n0,0\n2,1\n1,0\n");
    rejects(
        &["cycles", "--input", &path, "--json"],
        "line 4: times must be strictly increasing",
    );
    let path = dir.file("nul.csv", b"u\n0\n1\x00\n");
    rejects(&["cycles", "--input", &path], "line 3");
    // Times far apart are named in a few characters, not hundreds of digits.
    let path = dir.file("huge-times.csv", "t,u\n1e300,0\n1e299,1\n");
    for cmd in ["loop", "simulate", "cycles"] {
        rejects(
            &[cmd, "--input", &path],
            "line 3: times must be strictly increasing, t = 1e299 follows t = 1e300",
        );
    }
}

/// `lugre fit` reads its `u,F` or `t,u,F` file with the same reader as the other commands: the
/// same tolerance (BOM, CRLF, CR, comments, blank lines, spaces, columns in any order), the
/// same limits (a line of at most a megabyte) and messages of a few dozen characters whatever
/// the file holds.
#[test]
fn fit_csv_files_good_and_bad() {
    let dir = TempDir::new("catalogue-fit-csv");
    let clean = std::fs::read_to_string(slow_loop_data(&dir)).unwrap();
    let (header, rows) = clean.split_once('\n').unwrap();
    assert_eq!(header, "u,F");
    let swapped: String = rows
        .lines()
        .map(|l| {
            let (u, f) = l.split_once(',').unwrap();
            format!("{f},{u}\n")
        })
        .collect();
    let variants = [
        ("crlf.csv", clean.replace('\n', "\r\n")),
        ("cr-only.csv", clean.replace('\n', "\r")),
        ("bom.csv", format!("\u{feff}{clean}")),
        (
            "comments.csv",
            format!("# slow loop\n{header}\n# u,F\n{rows}"),
        ),
        ("blank-lines.csv", format!("\n{header}\n\n{rows}\n\n")),
        ("no-header.csv", rows.to_string()),
        ("spaces.csv", clean.replace(',', " , ")),
        ("swapped.csv", format!("f,U\n{swapped}")),
        // The usual names with units; a file as `lugre loop --csv` writes it (rho,u,y: rho is
        // not a time, y is the force).
        ("names.csv", format!("Position [m],Friction [N]\n{rows}")),
        (
            "loop-csv.csv",
            format!(
                "rho,u,y\n{}",
                rows.lines()
                    .enumerate()
                    .map(|(k, l)| format!("{k},{l}\n"))
                    .collect::<String>()
            ),
        ),
    ];
    let want = accepts_json(&["fit", "--json", "--input", &dir.file("clean.csv", &clean)]);
    for (name, text) in &variants {
        let mut j = accepts_json(&["fit", "--json", "--input", &dir.file(name, text)]);
        // The file's name is part of the report.
        j["input"] = want["input"].clone();
        assert_eq!(j, want, "{name} differs from clean.csv");
    }

    let huge_number = format!("1{}", "0".repeat(400));
    let garbage = "x".repeat(100_000);
    let bad: Vec<(&str, Vec<u8>, String)> = vec![
        (
            "wrong-header.csv",
            b"time,force\n0,1\n".to_vec(),
            "line 1: no column u (u, x, position or displacement) in the header 'time,force'"
                .into(),
        ),
        (
            "series-header.csv",
            b"t,u\n0,1\n".to_vec(),
            "line 1: no column F (F, force, friction or y) in the header 't,u'".into(),
        ),
        (
            "repeated-column.csv",
            b"u,F,F\n0,1,2\n".to_vec(),
            "line 1: the header has two columns for F: 'F' (column 2) and 'F' (column 3)".into(),
        ),
        (
            "four-columns.csv",
            b"0,1,2,3\n".to_vec(),
            "line 1: expected 2 columns (u,F) or 3 columns (t,u,F), found 4".into(),
        ),
        (
            // (An empty F is an input-only row of the full fit now: tests/fit.rs.)
            "missing-cell.csv",
            b"u,F\n0,0\n,1\n".to_vec(),
            "line 3: empty value for u".into(),
        ),
        (
            "short-row.csv",
            b"t,u,F\n0,0,0\n1,1\n".to_vec(),
            "line 3: expected 3 values (t,u,F), found 2".into(),
        ),
        (
            "non-utf8.csv",
            b"u,F\n0,0\n1,\xff\xfe\n".to_vec(),
            "line 3: not valid UTF-8 text".into(),
        ),
        (
            "inf.csv",
            b"u,F\n0,0\n1,-inf\n".to_vec(),
            "line 3: F must be a finite number, got -inf".into(),
        ),
        (
            "huge-number.csv",
            format!("u,F\n0,0\n1,{huge_number}\n").into_bytes(),
            "line 3: F must be a finite number, got inf".to_string(),
        ),
        (
            "huge-garbage.csv",
            format!("u,F\n{garbage},0\n").into_bytes(),
            "line 2: u = 'xxxxxxxx".into(),
        ),
        (
            "huge-header.csv",
            format!("u,{garbage}\n0,0\n").into_bytes(),
            "line 1: no column F (F, force, friction or y) in the header 'u,xxxxx".into(),
        ),
        (
            "huge-times.csv",
            b"t,u,F\n1e300,0,0\n1e299,1,1\n".to_vec(),
            "line 3: times must be strictly increasing, t = 1e299 follows t = 1e300".into(),
        ),
        (
            "one-long-line.csv",
            vec![b'7'; 3 << 20],
            "line 1: a line is longer than 1048576 bytes (not a CSV file of numbers?)".into(),
        ),
        (
            "bom-only.csv",
            b"\xef\xbb\xbf".to_vec(),
            "no data rows".into(),
        ),
        (
            "only-comments.csv",
            b"# nothing\n\n".to_vec(),
            "no data rows".into(),
        ),
    ];
    for (name, text, want) in bad {
        let path = dir.file(name, text);
        for fit in ["slow", "full"] {
            let err = rejects(&["fit", "--fit", fit, "--input", &path], &want);
            assert!(err.starts_with(&format!("lugre: error: {path}: ")), "{err}");
            assert!(
                err.len() < 200 + path.len(),
                "{name}: a short line, got {err}"
            );
        }
    }
    // /dev/zero (no line break, no end): refused at its first megabyte, not read forever.
    #[cfg(unix)]
    for fit in ["slow", "full"] {
        rejects(
            &["fit", "--fit", fit, "--input", "/dev/zero"],
            "/dev/zero: line 1: a line is longer than 1048576 bytes",
        );
    }
    #[cfg(unix)]
    rejects(
        &["fit", "--input", dir.path().to_str().unwrap()],
        "Is a directory",
    );
    rejects(&["fit", "--input", &dir.join("missing.csv")], "cannot read");
    // Numbers of the flags, named briefly too (the core's messages).
    let data = slow_loop_data(&dir);
    rejects(
        &["fit", "--input", &data, "--bounds", "sigma0=1e300:1"],
        "--bounds: the bounds of sigma0 must satisfy 0 <= lo < hi (hi may be inf), got [1e300, 1]",
    );
    rejects(
        &[
            "fit",
            "--input",
            &data,
            "--sigma0",
            "1e300",
            "--bounds",
            "sigma0=0:1",
        ],
        "the bounds [0, 1] of sigma0 exclude its start value 1e300 (it must lie strictly inside)",
    );
    rejects(
        &[
            "fit",
            "--input",
            &data,
            "--fs",
            "1e-300",
            "--bounds",
            "fs=1e-200:inf",
        ],
        "the bounds [1e-200, inf] of fs exclude its start value 1e-300",
    );
}

/// Every numeric flag takes a value starting with '-' after a space (`--fc -inf`, not only
/// `--fc=-inf`) and says what is wrong with it; an unknown flag is still named as one, and a
/// flag where a value belongs is not taken for a number.
#[test]
fn numeric_flags_take_values_starting_with_a_minus() {
    let dir = TempDir::new("catalogue-minus");
    let data = slow_loop_data(&dir);
    let timed = dir.file("timed.csv", "t,u,F\n0,0,0\n1,1,1\n2,0,0\n");
    let commands: [&[&str]; 4] = [
        &["loop", "--turning-points", "0,1"],
        &["simulate", "--turning-points", "0,1"],
        &["cycles", "--values", "0,1,0", "--energy"],
        &["fit", "--input", &data],
    ];
    let model: [(&[&str], &str, &str); 8] = [
        (&[], "--sigma0", "sigma0 must be > 0, got"),
        (&[], "--sigma1", "sigma1 must be >= 0, got"),
        (&[], "--sigma2", "sigma2 must be >= 0, got"),
        (&[], "--fc", "fc must be > 0, got"),
        (&[], "--fs", "fs must be > 0, got"),
        (&[], "--vs", "vs must be > 0, got"),
        (&[], "--beta", "beta must be > 0, got"),
        (&["--model", "dahl"], "--rho", "rho must be > 0, got"),
    ];
    for cmd in commands {
        for (head, flag, negative) in model {
            let name = &flag[2..];
            for (value, want) in [
                ("-1", format!("{negative} -1")),
                ("-0.5", format!("{negative} -0.5")),
                ("-.5", format!("{negative} -0.5")),
                ("-1e-3", format!("{negative} -0.001")),
                ("-inf", format!("{name} must be a finite number, got -inf")),
                (
                    "-Infinity",
                    format!("{name} must be a finite number, got -inf"),
                ),
                (
                    "-1e999",
                    format!("{flag} expects a finite number, got '-1e999'"),
                ),
            ] {
                let mut args = cmd.to_vec();
                args.extend_from_slice(head);
                args.extend_from_slice(&[flag, value]);
                rejects(&args, &want);
            }
        }
    }
    // Other numeric flags: a negative value is read and judged.
    for (args, want) in [
        (
            &["simulate", "--sine", "-1,2"][..],
            "--sine: the sine's amplitude must be a finite number > 0, got -1",
        ),
        (
            &["simulate", "--sine", "1,2", "--x0", "-inf"],
            "--x0 must be a finite number, got '-inf'",
        ),
        (
            &["simulate", "--sine", "1,2", "--gamma", "-1"],
            "--gamma: gamma must be > 0 (a positive number or inf), got -1",
        ),
        (
            &["simulate", "--sine", "1,2", "--periods", "-1"],
            "--periods must be at least 1, got -1",
        ),
        (
            &["simulate", "--sine", "1,2", "--tol", "-1e-3"],
            "--tol: the tolerance must be a number in [1e-14, 1), got -0.001",
        ),
        (
            &["simulate", "--sine", "1,1", "--times", "-1"],
            "--times: output time t[0] = -1 is outside the run [0, 1]",
        ),
        (
            &["simulate", "--sine", "1,1", "--samples-per-period", "-5"],
            "--samples-per-period must be a whole number >= 1, got -5",
        ),
        (
            &["loop", "--turning-points", "0,1", "--samples", "-1"],
            "--samples must be a whole number, got -1",
        ),
        (
            &["cycles", "--values", "0,2,1", "--gate", "-1"],
            "--gate: the gate must be a finite number >= 0, got -1",
        ),
        (
            &["cycles", "--values", "0,2,1", "--gate", "-inf"],
            "--gate: the gate must be a finite number >= 0, got -inf",
        ),
        (
            &[
                "cycles", "--sigma0", "1", "--fs", "2", "--values", "0,2,1", "--x0", "-1e300",
            ],
            "--x0: x0 must satisfy |sigma0 x0| <= g(0)",
        ),
        (
            &["cycles", "--values", "0,2,1", "--histogram", "--bins", "-1"],
            "--bins must be a whole number >= 1, got -1",
        ),
        (
            &["fit", "--input", &data, "--fit", "full", "--starts", "-1"],
            "--starts must be a whole number >= 1, got -1",
        ),
        (
            &["fit", "--input", &timed, "--fit", "full", "--x0", "-inf"],
            "--x0: item 1 must be a finite number, got -inf",
        ),
        (
            &["fit", "--input", &data, "--bounds", "-1"],
            "--bounds: '-1' is not NAME=LO:HI",
        ),
    ] {
        rejects(args, want);
    }
    // Valid negative values are accepted after a space.
    accepts(&["simulate", "--sine", "1,2,-1,-0.5", "--x0", "-0.5"]);
    accepts(&["simulate", "--turning-points", "-1,1", "--x0", "-0.5"]);
    let j = accepts_json(&[
        "cycles", "--sigma0", "1", "--fs", "2", "--values", "-2,1,-3", "--x0", "-0.5", "--json",
    ]);
    assert_eq!(j["half_cycles"], 2);
    accepts(&["loop", "--turning-points", "-1,1", "--at", "-0.5"]);
    // An unknown flag is still one, before or after a negative value.
    for args in [
        &["loop", "--turning-points", "0,1", "--bogus", "-1"][..],
        &["loop", "--turning-points", "0,1", "--fc", "-1", "--bogus"],
        &["loop", "--turning-points", "0,1", "--fcc", "-1"],
        &["cycles", "--values", "0,1", "--gate", "1", "--x1", "-1"],
    ] {
        let bogus = args.iter().rev().find(|a| a.starts_with("--")).unwrap();
        rejects(args, &format!("unexpected argument '{bogus}' found"));
    }
    // A flag where the value belongs is named, not read as a number; `--` is not a number
    // either; the value missing at the end is said so.
    for (args, want) in [
        (
            &["loop", "--turning-points", "0,1", "--fc", "--json"][..],
            "--fc expects a number, got the flag '--json' (the value is missing)",
        ),
        (
            &["loop", "--turning-points", "0,1", "--sigma0", "--bogus"],
            "--sigma0 expects a number, got the flag '--bogus' (the value is missing)",
        ),
        (
            &["loop", "--turning-points", "0,1", "--samples", "--json"],
            "--samples must be a whole number, got the flag '--json' (the value is missing)",
        ),
        (
            &["cycles", "--values", "0,1", "--gate", "--json"],
            "--gate expects a number, got the flag '--json' (the value is missing)",
        ),
        (
            &["loop", "--turning-points", "0,1", "--fc", "--"],
            "--fc expects a number, got '--'",
        ),
        (
            &["cycles", "--values", "0,1", "--histogram", "--bins", "--"],
            "--bins must be a whole number >= 1, got '--'",
        ),
    ] {
        rejects(args, want);
    }
    rejects(
        &["loop", "--turning-points", "0,1", "--fc"],
        "a value is required for '--fc <FC>' but none was supplied",
    );
}

/// A 100 kB argument in any flag, list item or position is echoed as a short excerpt (its
/// start, '...' and its length), as a bad CSV cell is: one short line, never the whole text.
#[test]
fn huge_arguments_are_quoted_short() {
    let dir = TempDir::new("catalogue-huge-args");
    let data = slow_loop_data(&dir);
    let timed = dir.file("timed.csv", "t,u,F\n0,0,0\n1,1,1\n2,0,0\n");
    let huge = "x".repeat(100_000);
    let digits = format!("-{}", "9".repeat(100_000));
    let list = format!("0,{huge},1");
    let pair = format!("sigma0={huge}");
    let empty_name = format!("{huge},,fs");
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec!["loop", "--turning-points", "0,1", "--fc", &huge],
            "--fc expects a number, got 'xxxx",
        ),
        (
            vec!["loop", "--turning-points", "0,1", "--fc", &digits],
            "--fc expects a finite number, got '-999",
        ),
        (
            vec!["loop", "--turning-points", "0,1", "--samples", &huge],
            "--samples must be a whole number, got 'xxxx",
        ),
        (
            vec!["loop", "--turning-points", "0,1", "--samples", &digits],
            "--samples must be a whole number, got '-999",
        ),
        (
            vec!["cycles", "--values", "0,2,1", "--gate", &huge],
            "--gate expects a number",
        ),
        (
            vec!["loop", "--turning-points", &list],
            "--turning-points: item 2 is 'xxxx",
        ),
        (
            vec!["cycles", "--values", &list],
            "--values: item 2 is 'xxxx",
        ),
        (
            vec!["simulate", "--sine", "1,2", "--x0", &huge],
            "--x0 must be a number, got 'xxxx",
        ),
        (
            vec!["simulate", "--sine", "1,2", "--x0", &digits],
            "--x0 must be a finite number, got '-999",
        ),
        (
            vec!["simulate", "--sine", "1,2", "--gamma", &huge],
            "--gamma must be a number > 0 or 'inf', got 'xxxx",
        ),
        (
            vec!["simulate", "--sine", "1,2", "--periods", &huge],
            "--periods must be a whole number from 1 to 4294967295, got 'xxxx",
        ),
        (
            vec!["simulate", "--sine", "1,2", "--tol", &huge],
            "--tol must be a number, got 'xxxx",
        ),
        (
            vec!["fit", "--input", &timed, "--fit", "full", "--x0", &huge],
            "--x0: item 1 is 'xxxx",
        ),
        (
            vec!["fit", "--input", &data, "--bounds", &huge],
            "--bounds: 'xxxx",
        ),
        (
            vec!["fit", "--input", &data, "--bounds", &pair],
            "--bounds: 'sigma0=xxxx",
        ),
        (
            vec!["fit", "--input", &data, "--fix", &huge],
            "--fix: unknown parameter 'xxxx",
        ),
        (
            vec!["fit", "--input", &data, "--free", &huge],
            "--free: unknown parameter 'xxxx",
        ),
        (
            vec!["fit", "--input", &data, "--fix", &empty_name],
            "--fix: empty name in 'xxxx",
        ),
        (
            vec!["loop", "--turning-points", "0,1", &huge],
            "unexpected argument 'xxxx",
        ),
        (
            vec!["loop", "--turning-points", "0,1", "--model", &huge],
            "invalid value 'xxxx",
        ),
    ];
    for (args, want) in cases {
        let line = rejects(&args, want);
        assert!(line.len() < 300, "{want}: {} bytes", line.len());
        assert!(line.contains(" characters)"), "{line}");
    }
}

/// Every output flag pointed at a path that cannot be written (under a regular file, or an
/// existing directory): one line naming the path, no output, no file, no temporary file.
#[test]
fn every_output_flag_unwritable() {
    let dir = TempDir::new("catalogue-unwritable");
    let data = slow_loop_data(&dir);
    let blocker = dir.file("a-file", "not a directory");
    std::fs::create_dir(dir.path().join("a-dir")).unwrap();
    let under_file = |name: &str| format!("{blocker}/{name}");
    let a_dir = dir.join("a-dir");
    let before = dir.entries();
    let runs: Vec<(Vec<&str>, &str)> = vec![
        (vec!["loop", "--turning-points", "0,1", "--csv"], "csv"),
        (vec!["loop", "--turning-points", "0,1", "--plot"], "svg"),
        (vec!["loop", "--turning-points", "0,1", "--plot"], "png"),
        (vec!["simulate", "--turning-points", "0,1", "--csv"], "csv"),
        (vec!["simulate", "--turning-points", "0,1", "--plot"], "svg"),
        (vec!["cycles", "--values", "0,2,1,3,0", "--csv"], "csv"),
        (
            vec!["cycles", "--values", "0,2,1,3,0", "--json", "--csv"],
            "csv",
        ),
        (vec!["fit", "--input", &data, "--csv"], "csv"),
        (vec!["fit", "--input", &data, "--plot"], "png"),
    ];
    for (head, ext) in &runs {
        let file = under_file(&format!("out.{ext}"));
        let mut args = head.clone();
        args.push(&file);
        rejects(&args, &format!("cannot write '{file}'"));
        // An existing directory cannot be replaced by a file.
        let target = if *ext == "csv" {
            a_dir.clone()
        } else {
            // The plot's format comes from the extension: a directory named like a figure.
            let d = dir.join(&format!("figure.{ext}"));
            let _ = std::fs::create_dir(&d);
            d
        };
        let mut args = head.clone();
        args.push(&target);
        rejects(&args, &format!("cannot write '{target}'"));
    }
    let mut after = dir.entries();
    after.retain(|e| !e.starts_with("figure."));
    assert_eq!(
        after, before,
        "no file and no temporary file is left behind"
    );
    assert!(std::fs::read_dir(dir.path().join("a-dir"))
        .unwrap()
        .next()
        .is_none());
    // paper --out: a path under a regular file.
    rejects(
        &["paper", "--out", &under_file("figures")],
        "cannot create the output directory",
    );
}

/// A failing run leaves no partial file and no temporary file: the error comes after the
/// output was being written (paper: its second file cannot be renamed into place; cycles: the
/// energies overflow after the CSV was filled).
#[test]
fn a_failing_run_leaves_no_partial_or_temporary_file() {
    let dir = TempDir::new("catalogue-atomic");
    // paper writes fig03.svg, then fig03.png: a directory in the PNG's place (in a folder
    // lugre did not create, hence --force; it marks the folder first).
    let out = dir.path().join("paper");
    std::fs::create_dir_all(out.join("fig03.png")).unwrap();
    let out_s = out.to_str().unwrap();
    rejects(&["paper", "--out", out_s, "--force"], "cannot write");
    let mut names: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(
        names,
        [".lugre-paper", "fig03.png", "fig03.svg"],
        "no temporary file"
    );
    // The file written before the error is complete.
    let svg = std::fs::read_to_string(out.join("fig03.svg")).unwrap();
    assert!(svg.trim_end().ends_with("</svg>"));
    // cycles: the CSV is filled while counting; the totals then overflow. Neither the CSV
    // nor its temporary file remains, and nothing reaches stdout.
    let csv = dir.join("cycles.csv");
    for extra in [&[][..], &["--json"][..], &["--histogram"][..]] {
        let mut args = vec![
            "cycles",
            "--values=0,8e307,-8e307,8e307,-8e307,0",
            "--sigma0",
            "1e10",
            "--fc",
            "1e10",
            "--fs",
            "1e10",
            "--energy",
            "--csv",
            &csv,
        ];
        args.extend_from_slice(extra);
        rejects(&args, "the energies along the history overflow f64");
    }
    // simulate: the plot's format is checked before the run, the CSV is never started.
    let csv = dir.join("simulate.csv");
    rejects(
        &[
            "simulate",
            "--turning-points",
            "0,1",
            "--csv",
            &csv,
            "--plot",
            &dir.join("y.pdf"),
        ],
        "must end in .svg or .png",
    );
    assert_eq!(dir.entries(), vec!["paper".to_string()]);
}

/// A file of 2 million samples (cycles, streamed), a period of a million samples (loop), and
/// a million-line history whose last line is bad: nothing is printed before it is found.
#[test]
fn huge_files() {
    let dir = TempDir::new("catalogue-huge");
    // A random walk of integers (xorshift), 1000 steps, repeated: many reversals and cycles.
    let mut block = String::new();
    let (mut u, mut state) = (0i64, 0x2545F4914F6CDD1Du64);
    for _ in 0..1000 {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        u += (state % 7) as i64 - 3;
        block.push_str(&u.to_string());
        block.push('\n');
    }
    let million = format!("u\n{}", block.repeat(1000));
    let path = dir.file("walk.csv", format!("{million}{}", block.repeat(1000)));
    let out = accepts(&["cycles", "--input", &path]);
    assert!(
        out.starts_with(&format!("History: 2000000 samples from {path} (column u)")),
        "{}",
        &out[..200]
    );
    let path = dir.file("period.csv", &million);
    let out = accepts(&["loop", "--input", &path]);
    assert!(out.contains("Work per period"));
    // A bad last line: status 2, and nothing was printed before it was found.
    let path = dir.file("bad-end.csv", format!("{million}oops\n"));
    rejects(
        &["cycles", "--input", &path],
        "line 1000002: u = 'oops' is not a number",
    );
}

/// Values near the ends of f64: answers where they exist (exact: a saturated triangle's
/// work is 4 g0 (A - tanh(a A) / a)), one clear line where a result overflows.
#[test]
fn values_near_1e308_and_1e_minus_308() {
    // A triangle between -1e307 and 1e307: W = 4 g0 A to rounding.
    let j = accepts_json(&["loop", "--turning-points=-1e307,1e307", "--json"]);
    assert!((f(&j["work_per_period"]) / 8e307 - 1.0).abs() < 1e-15);
    // 4e307: the period is finite, the work per period (3.2e308) is not.
    rejects(
        &["loop", "--turning-points=-4e307,4e307"],
        "the work per period overflows f64",
    );
    rejects(
        &["loop", "--turning-points=-1e308,1e308"],
        "the input's total variation over one period overflows f64",
    );
    rejects(
        &["simulate", "--turning-points", "0,1e308,-1e308"],
        "the input's total variation over one period overflows f64",
    );
    // A saturated loop at a stiffness where sigma0 u overflows: y° = +-g0, W = 4 g0 A.
    let j = accepts_json(&[
        "loop",
        "--turning-points",
        "0,1e300",
        "--sigma0",
        "1e300",
        "--json",
    ]);
    assert_eq!(f(&j["turning_points"][0]["y"]), -2.0);
    assert_eq!(f(&j["work_per_period"]), 4e300);
    let j = accepts_json(&[
        "loop",
        "--turning-points",
        "0,1",
        "--sigma0",
        "1e308",
        "--json",
    ]);
    assert_eq!(f(&j["work_per_period"]), 4.0);
    // Fs far below Fc: g(0) = Fs exactly, not Fc + (Fs - Fc) rounded to 0.
    let j = accepts_json(&[
        "loop",
        "--turning-points",
        "0,1",
        "--fs",
        "1e-300",
        "--json",
    ]);
    assert_eq!(f(&j["g0"]), 1e-300);
    assert_eq!(f(&j["work_per_period"]), 2e-300);
    accepts(&[
        "simulate",
        "--turning-points",
        "0,1",
        "--fs",
        "1e-300",
        "--json",
    ]);
    // Tiny inputs: elastic, y° = sigma0 (u - mean) to rounding, everything finite.
    let j = accepts_json(&["loop", "--turning-points=-1e-308,1e-308", "--json"]);
    assert!((f(&j["turning_points"][1]["y"]) - 1e-308).abs() <= 1e-323);
    accepts(&["loop", "--turning-points", "0,5e-324", "--samples", "5"]);
    accepts(&["simulate", "--turning-points", "0,1e-308", "--json"]);
    accepts(&["simulate", "--sine", "1e-308,1", "--json"]);
    accepts(&[
        "simulate",
        "--sine",
        "1,1e-300",
        "--samples-per-period",
        "3",
    ]);
    accepts(&[
        "simulate",
        "--turning-points",
        "0,1",
        "--sigma0",
        "1e-308",
        "--json",
    ]);
    accepts(&[
        "cycles",
        "--sigma0",
        "1",
        "--fs",
        "2",
        "--values",
        "1e-308,-1e-308,5e-324,-5e-324,1e-308",
        "--energy",
        "--histogram",
    ]);
    // Histories up to f64::MAX / 2: ranges and means stay finite.
    let j = accepts_json(&[
        "cycles",
        "--values=-8.9e307,8.9e307,-8.9e307,8.9e307",
        "--histogram",
        "--json",
    ]);
    assert_eq!(f(&j["cycles"][0]["range"]), 1.78e308);
    // u ~ 1e300 with sigma0 ~ 1e-300: every energy is ~ g0 u and fits (this was an overflow
    // error: l^2 overflowed inside the closed forms).
    let j = accepts_json(&[
        "cycles",
        "--fs",
        "2",
        "--values",
        "0,1e300,1,1e300,0",
        "--sigma0",
        "1e-300",
        "--energy",
        "--json",
    ]);
    let h = &j["history"];
    let (w, dv, d) = (
        f(&h["work"]),
        f(&h["stored_energy_change"]),
        f(&h["dissipation"]),
    );
    assert!(w > 1e299 && d > 0.0, "{h}");
    assert!((w - dv - d).abs() <= 1e-12 * w, "W = dV + D: {h}");
    // Where the energies really overflow (g0 = 1e10 over a variation of ~5e308):
    rejects(
        &[
            "cycles",
            "--values=0,8e307,-8e307,8e307,-8e307,0",
            "--sigma0",
            "1e10",
            "--fc",
            "1e10",
            "--fs",
            "1e10",
            "--energy",
        ],
        "the energies along the history overflow f64",
    );
    rejects(
        &[
            "simulate",
            "--turning-points",
            "0,1",
            "--x0",
            "1e305",
            "--sigma0",
            "1e10",
        ],
        "--x0: x0 = 1e305 cannot be represented",
    );
    // Requests for absurd amounts of output are refused, not attempted.
    rejects(
        &[
            "loop",
            "--turning-points",
            "0,1",
            "--samples",
            "18446744073709551615",
        ],
        "--samples must be at most 10000000 (memory for the points), got 18446744073709551615",
    );
    rejects(
        &[
            "simulate",
            "--sine",
            "1,1",
            "--samples-per-period",
            "18446744073709551615",
        ],
        "the run would produce 18446744073709551615 output rows",
    );
    // A phase so large it has lost its angle (this used to hang).
    rejects(
        &["simulate", "--sine", "1,1,1e17"],
        "the sine's phase must be at most 1e6 radians in magnitude",
    );
}

/// `a P = 1e12` and `a P = 1e-12`, LuGre and Dahl, against the closed form of the symmetric
/// triangle between -A and A: `y°(-A) = -g0 tanh(a A)`, `W = 4 g0 (A - tanh(a A) / a)`
/// (`= (4/3) g0 a^2 A^3 (1 - 2 (a A)^2 / 5)` for small `a A`, where it cancels).
#[test]
fn a_times_period_1e12_and_1e_minus_12_are_exact() {
    let tol = lugre_test_support::prec::LOOP;
    let rel = |a: f64, b: f64| ((a - b) / b).abs();
    // (model flags, g0, a, y°(-1), W) with A = 1, P = 4.
    let cases: [(&[&str], f64, f64, f64, f64); 4] = [
        (
            &["--sigma0", "5e11"],
            2.0,
            2.5e11,
            -2.0,
            8.0 * (1.0 - 1.0 / 2.5e11),
        ),
        (
            &["--model", "dahl", "--rho", "2.5e11"],
            1.0,
            2.5e11,
            -1.0,
            4.0 * (1.0 - 1.0 / 2.5e11),
        ),
        (
            &["--sigma0", "5e-13"],
            2.0,
            2.5e-13,
            -2.0 * 2.5e-13,
            4.0 / 3.0 * 2.0 * 2.5e-13 * 2.5e-13,
        ),
        (
            &["--model", "dahl", "--rho", "2.5e-13", "--fc", "3"],
            3.0,
            2.5e-13,
            -3.0 * 2.5e-13,
            4.0 / 3.0 * 3.0 * 2.5e-13 * 2.5e-13,
        ),
    ];
    for (model, g0, a, y0, w) in cases {
        let mut args = vec!["loop", "--turning-points=-1,1", "--json"];
        args.extend_from_slice(model);
        let j = accepts_json(&args);
        assert_eq!(f(&j["g0"]), g0);
        assert!(rel(f(&j["a"]) * 4.0, a * 4.0) < 1e-15, "a P");
        assert!(
            rel(f(&j["turning_points"][0]["y"]), y0) < tol,
            "{model:?} y°"
        );
        assert!(rel(f(&j["work_per_period"]), w) < tol, "{model:?} W");
        let major = &j["loops"][0];
        assert!(rel(f(&major["dissipation"]), w) < tol);
        assert_eq!(f(&major["stored_energy_change"]), 0.0);
        // The rate-independent simulation from x0 = 0 lands on the loop: exactly, at a P =
        // 1e12 (it saturates within the first segment); at 1e-12 it is still
        // sigma0 x0 = 0 + the elastic ramp, 1e-12 away from y° relative to g0.
        let mut args = vec![
            "simulate",
            "--turning-points=-1,1",
            "--gamma",
            "inf",
            "--periods",
            "3",
            "--times",
            "8,10",
            "--json",
        ];
        args.extend_from_slice(model);
        let s = accepts_json(&args);
        let y_end = f(&s["y"][0]);
        assert!(
            (y_end - y0).abs() <= 1e-11 * g0,
            "{model:?}: {y_end} vs {y0}"
        );
    }
    // A minor loop at a P = 1e12 (saturated: W = 2 g0 (1 - 2 / (a range)) to rounding) and
    // at 1e-12 (elastic: W > 0, tiny, and D >= 0).
    let j = accepts_json(&[
        "loop",
        "--sigma0",
        "1e12",
        "--bimodal",
        "0,0.5,1,1.5",
        "--json",
    ]);
    let minor = &j["loops"][1];
    assert!(rel(f(&minor["work"]), 2.0 * 2.0 * 0.5 - 2.0 * 2.0 * 2.0 / 5e11) < 1e-9);
    let j = accepts_json(&[
        "loop",
        "--sigma0",
        "1e-12",
        "--bimodal",
        "0,0.5,1,1.5",
        "--json",
    ]);
    let minor = &j["loops"][1];
    assert!(f(&minor["dissipation"]) > 0.0 && f(&minor["dissipation"]) < 1e-24);
}

/// The other scalar flags: whole numbers, tolerances, gates, initial states, names.
#[test]
fn other_flags_out_of_range() {
    let dir = TempDir::new("catalogue-flags");
    let data = slow_loop_data(&dir);
    let tp = ["simulate", "--turning-points", "0,1"];
    let with = |extra: &[&'static str]| -> Vec<&'static str> {
        let mut v = tp.to_vec();
        v.extend_from_slice(extra);
        v
    };
    for (args, want) in [
        (
            with(&["--periods", "-1"]),
            "--periods must be at least 1, got -1",
        ),
        (
            with(&["--periods", "99999999999"]),
            "--periods must be a whole number from 1 to 4294967295",
        ),
        (
            with(&["--periods", "nan"]),
            "--periods must be a whole number",
        ),
        (
            with(&["--x0", "nan"]),
            "--x0 must be a finite number, got 'nan'",
        ),
        (with(&["--x0", "zero"]), "--x0 must be a number, got 'zero'"),
        (
            vec!["simulate", "--sine", "1,1", "--tol", "1"],
            "--tol: the tolerance must be a number in [1e-14, 1), got 1",
        ),
        (
            vec!["simulate", "--sine", "1,1", "--tol", "1e-15"],
            "the tolerance must be a number in [1e-14, 1)",
        ),
        (
            vec!["simulate", "--sine", "1,1", "--tol", "nan"],
            "--tol must be a finite number",
        ),
        (
            vec!["simulate", "--sine", "1,-1"],
            "the sine's period must be a finite number > 0, got -1",
        ),
        (
            vec!["simulate", "--sine", "1e300,1e-300"],
            "largest speed A 2 pi / T must be a finite number",
        ),
        (
            vec!["simulate", "--sine", "1,1,0,1e308,5"],
            "--sine takes A,T[,PHASE[,OFFSET]] (2 to 4 numbers), got 5",
        ),
        (
            vec!["simulate", "--sine", "1,1", "--times", "0,2"],
            "--times: output time t[1] = 2 is outside the run [0, 1]",
        ),
        (
            vec!["cycles", "--values", "1,2,1", "--gate", "inf"],
            "--gate: the gate must be a finite number >= 0, got inf",
        ),
        (
            vec![
                "cycles", "--sigma0", "1", "--fs", "2", "--values", "1,2,1", "--x0", "nan",
            ],
            "--x0: x0 must satisfy |sigma0 x0| <= g(0)",
        ),
        (
            vec![
                "cycles",
                "--values",
                "1,2,1",
                "--histogram",
                "--bins",
                "1001",
            ],
            "--bins must be between 1 and 1000, got 1001",
        ),
        (
            vec!["cycles", "--values", "1,2,1", "--bins", "3"],
            "--histogram",
        ),
        (
            vec!["cycles", "--values", "1,2,1", "--histogram", "--bins", "-3"],
            "--bins must be a whole number >= 1, got -3",
        ),
        (
            vec!["cycles", "--values", "1,2,1", "--histogram", "--bins", "0"],
            "--bins must be a whole number >= 1, got 0",
        ),
        (
            vec![
                "cycles",
                "--values",
                "1,2,1",
                "--histogram",
                "--bins",
                "2.5",
            ],
            "--bins must be a whole number >= 1, got '2.5'",
        ),
        (
            vec!["loop", "--turning-points", "0,1", "--samples", "-2"],
            "--samples must be a whole number, got -2",
        ),
        (
            vec!["simulate", "--sine", "1,1", "--samples-per-period", "0"],
            "--samples-per-period must be a whole number >= 1, got 0",
        ),
        (
            vec!["fit", "--input", &data, "--fit", "full", "--starts", "0"],
            "--starts must be a whole number >= 1, got 0",
        ),
        (
            vec!["loop", "--turning-points", "0,1", "--plot", "x.pdf"],
            "must end in .svg or .png",
        ),
        (
            vec!["fit", "--input", &data, "--bounds", "sigma0=1:0"],
            "the bounds of sigma0 must satisfy 0 <= lo < hi",
        ),
        (
            vec!["fit", "--input", &data, "--bounds", "sigma0=a:b"],
            "--bounds",
        ),
        (
            vec!["fit", "--input", &data, "--bounds", "sigma0=nan:1"],
            "--bounds: item 1 must be a finite number, got NaN",
        ),
        (
            vec!["fit", "--input", &data, "--bounds", "sigma0=1:"],
            "--bounds",
        ),
        (
            vec!["fit", "--input", &data, "--free", "gamma"],
            "--free: unknown parameter 'gamma'",
        ),
        (
            vec!["fit", "--input", &data, "--fix", "sigma0,fs"],
            "nothing to fit",
        ),
        (
            vec!["fit", "--input", &data, "--x0", "1"],
            "--x0 applies to the full fit",
        ),
        (
            vec!["fit", "--input", &data, "--fit", "full"],
            "a full fit needs the samples' times",
        ),
        (
            vec!["loop", "--turning-points", "0,1", "--sigma0", "abc"],
            "--sigma0 expects a number, got 'abc'",
        ),
        (
            vec!["loop", "--turning-points", "0,1", "--fs", ""],
            "--fs expects a number, got ''",
        ),
        (
            vec!["loop", "--turning-points", "0,1", "--model", "coulomb"],
            "[possible values: lugre, dahl, maxwell-slip, prandtl-ishlinskii",
        ),
        (vec!["bogus"], "unrecognized subcommand 'bogus'"),
        (
            vec!["loop", "--turning-points"],
            "a value is required for '--turning-points",
        ),
    ] {
        rejects(&args, want);
    }
}

/// A reader that stops early (`| head`) is not an error: status 0, nothing on stderr.
#[test]
fn stdout_closed_early() {
    use std::process::{Command, Stdio};
    let mut child = Command::new(env!("CARGO_BIN_EXE_lugre"))
        .args([
            "simulate",
            "--turning-points",
            "0,1",
            "--periods",
            "100",
            "--samples-per-period",
            "10000",
            "--json",
        ])
        .env("RUST_BACKTRACE", "1")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{:?}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.stderr.is_empty());
}

/// Help, version and a bare command are not errors of the input, and print no NaN.
#[test]
fn no_arguments() {
    let out = lugre(&[]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        out.stdout.is_empty() || !common::has_nan_or_inf(&String::from_utf8_lossy(&out.stdout))
    );
    rejects(&["loop"], "no input");
    rejects(&["simulate"], "no input");
    rejects(&["cycles"], "no input");
    rejects(&["fit"], "no data");
}

/// One period of a slow loop (LuGre, sigma0 = 3, g(0) = 2) as `u,F` data for `lugre fit`:
/// three periods of a triangle between -1 and 1, 200 samples each, from the library itself.
fn slow_loop_data(dir: &TempDir) -> String {
    let model = lugre::RateIndependent::new(3.0, 2.0).unwrap();
    let tp = lugre::TurningPoints::new(&[-1.0, 1.0]).unwrap();
    let hl = lugre::HysteresisLoop::new(model, &tp).unwrap();
    let mut text = String::from("u,F\n");
    for k in 0..3 {
        for p in hl.sample(201).iter().skip(usize::from(k > 0)) {
            text.push_str(&format!("{},{}\n", p.u, p.y));
        }
    }
    dir.file("slow-loop.csv", text)
}
