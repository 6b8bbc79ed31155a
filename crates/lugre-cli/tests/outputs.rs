//! The output policy, run as a user would, for every command that writes: an output never
//! replaces an input (same path, a symlink or a hard link), two outputs never share a file,
//! `lugre paper` does not write into a folder of the user's without `--force`, and a failed
//! write leaves the old file and no temporary file.

mod common;
use common::{lugre, rejects, TempDir};

/// A slow loop `fit` reads (columns u,F): the rate-independent LuGre loop of sigma0 = 6,
/// g(0) = 1.5 on 0 -> 1 -> 0, each branch relaxing exponentially towards +-g(0).
fn slow_loop() -> String {
    let (sigma0, g) = (6.0f64, 1.5f64);
    let mut text = String::from("u,F\n");
    let mut y = -g * (1.0 - (-sigma0 / g).exp()) / (1.0 + (-sigma0 / g).exp());
    for (from, to) in [(0.0f64, 1.0f64), (1.0, 0.0)] {
        let dir = (to - from).signum();
        let y0 = y;
        for k in 0..=20 {
            let u = from + (to - from) * f64::from(k) / 20.0;
            y = dir * g - (dir * g - y0) * (-sigma0 * (u - from).abs() / g).exp();
            text += &format!("{u},{y}\n");
        }
    }
    text
}

/// `args` are refused with one line naming both flags and both paths, and `input` is unchanged.
#[track_caller]
fn refused_and_unchanged(args: &[&str], flags: [&str; 2], paths: [&str; 2], input: &str) {
    let before = std::fs::read(input).unwrap();
    let err = rejects(args, "the same file");
    for (flag, path) in flags.iter().zip(paths) {
        assert!(
            err.contains(&format!("{flag} '{path}'")),
            "{flag} {path}: {err}"
        );
    }
    assert_eq!(std::fs::read(input).unwrap(), before, "{input} was changed");
}

#[test]
fn fit_does_not_write_over_its_input_by_any_name() {
    let dir = TempDir::new("outputs-fit");
    let d = dir.file("d.csv", slow_loop());
    refused_and_unchanged(
        &["fit", "--input", &d, "--csv", &d],
        ["--csv", "--input"],
        [&d, &d],
        &d,
    );
    let link = dir.join("link.csv");
    std::os::unix::fs::symlink(&d, &link).unwrap();
    refused_and_unchanged(
        &["fit", "--input", &d, "--csv", &link],
        ["--csv", "--input"],
        [&link, &d],
        &d,
    );
    let hard = dir.join("hard.csv");
    std::fs::hard_link(&d, &hard).unwrap();
    refused_and_unchanged(
        &[
            "fit",
            "--input",
            &hard,
            "--plot",
            &dir.join("fig.svg"),
            "--csv",
            &d,
        ],
        ["--csv", "--input"],
        [&d, &hard],
        &d,
    );
    // Nothing else was written, and a different file is fine.
    assert_eq!(dir.entries(), ["d.csv", "hard.csv", "link.csv"]);
    let out = lugre(&["fit", "--input", &d, "--csv", &dir.join("fitted.csv")]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(std::fs::read_to_string(&d).unwrap(), slow_loop());
}

#[test]
fn simulate_loop_cycles_and_dynamics_do_not_write_over_their_input() {
    let dir = TempDir::new("outputs-commands");
    let path = dir.file("path.csv", "t,u\n0,0\n1,1\n2,0.5\n3,0\n");
    let link = dir.join("link.csv");
    std::os::unix::fs::symlink(&path, &link).unwrap();
    refused_and_unchanged(
        &["simulate", "--input", &path, "--csv", &link],
        ["--csv", "--input"],
        [&link, &path],
        &path,
    );
    refused_and_unchanged(
        &["loop", "--input", &link, "--csv", &path],
        ["--csv", "--input"],
        [&path, &link],
        &path,
    );
    // A plot over an input, whatever the input's name.
    let svg = dir.file("path.svg", "t,u\n0,0\n1,1\n2,0.5\n3,0\n");
    refused_and_unchanged(
        &["simulate", "--input", &svg, "--plot", &svg],
        ["--plot", "--input"],
        [&svg, &svg],
        &svg,
    );

    let history = dir.file("history.csv", "u\n-2\n1\n-3\n5\n-1\n3\n-4\n4\n-2\n");
    let hard = dir.join("hard.csv");
    std::fs::hard_link(&history, &hard).unwrap();
    refused_and_unchanged(
        &["cycles", "--input", &history, "--csv", &hard],
        ["--csv", "--input"],
        [&hard, &history],
        &history,
    );

    let force = dir.file("force.csv", "t,F\n0,0\n1,0.5\n2,1\n");
    refused_and_unchanged(
        &["dynamics", "--input", &force, "--csv", &force],
        ["--csv", "--input"],
        [&force, &force],
        &force,
    );
    refused_and_unchanged(
        &["dynamics", "--input", &force, "--plot", &force],
        ["--plot", "--input"],
        [&force, &force],
        &force,
    );
}

#[test]
fn two_outputs_never_share_a_file() {
    let dir = TempDir::new("outputs-two");
    let out = dir.join("out.svg");
    let err = rejects(
        &[
            "loop",
            "--bimodal",
            "0,0.2,1,1.5",
            "--csv",
            &out,
            "--plot",
            &out,
        ],
        "are the same file",
    );
    assert!(
        err.contains(&format!("--csv '{out}' and --plot '{out}'")),
        "{err}"
    );
    // Through a link to a file that exists.
    let real = dir.file("real.svg", "<svg/>");
    let link = dir.join("link.svg");
    std::os::unix::fs::symlink(&real, &link).unwrap();
    let err = rejects(
        &["simulate", "--sine", "1,2", "--csv", &real, "--plot", &link],
        "are the same file",
    );
    assert!(err.contains("--csv") && err.contains("--plot"), "{err}");
    assert_eq!(std::fs::read_to_string(&real).unwrap(), "<svg/>");
    assert_eq!(dir.entries(), ["link.svg", "real.svg"]);
}

/// The files are checked before anything else: a request that is wrong in other ways too gets
/// the output policy's message, and nothing is read or computed.
#[test]
fn the_files_are_checked_first() {
    let dir = TempDir::new("outputs-first");
    let out = dir.join("out.svg");
    rejects(
        &[
            "loop",
            "--bimodal",
            "0,0.2,1",
            "--csv",
            &out,
            "--plot",
            &out,
        ],
        "are the same file",
    );
    rejects(
        &["fit", "--input", &out, "--csv", &out, "--fit", "full"],
        "lugre never writes over an input",
    );
}

/// A folder of the user's is not written into without `--force`; one lugre wrote is.
#[test]
fn paper_does_not_write_into_a_folder_of_the_users() {
    let dir = TempDir::new("outputs-paper");
    let theirs = dir.path().join("site");
    std::fs::create_dir_all(&theirs).unwrap();
    std::fs::write(theirs.join("index.html"), "my page").unwrap();
    let site = theirs.to_str().unwrap();
    let err = rejects(&["paper", "--out", site], "lugre did not create");
    assert!(
        err.contains(&format!("--out '{site}'")) && err.contains("--force"),
        "{err}"
    );
    assert_eq!(
        std::fs::read_to_string(theirs.join("index.html")).unwrap(),
        "my page"
    );
    assert_eq!(std::fs::read_dir(&theirs).unwrap().count(), 1);

    // One run (the whole paper takes a while in a debug build): with --force it writes, and
    // marks the folder as lugre's, so that the next run needs no --force (`io::outputs`' tests).
    let out = lugre(&["paper", "--out", site, "--force"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(theirs.join("fig03.svg").exists());
    assert!(theirs.join(".lugre-paper").exists());
}

/// A run that fails half-way through writing leaves the old output as it was and no temporary
/// file (`cycles --csv` writes the cycles as it reads the history).
#[test]
fn a_failed_run_leaves_the_old_output_and_no_temporary_file() {
    let dir = TempDir::new("outputs-atomic");
    let history = dir.file("history.csv", "u\n1\n3\n2\n5\n0\n4\nabc\n2\n");
    let out = dir.file("cycles.csv", "old\n");
    rejects(
        &["cycles", "--input", &history, "--csv", &out],
        "line 8: u = 'abc' is not a number",
    );
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "old\n");
    assert_eq!(dir.entries(), ["cycles.csv", "history.csv"]);
}
