//! Helpers shared by the CLI's integration tests: run the real binary as a user would (with
//! `RUST_BACKTRACE=1`, as on the machines it runs on) and check what a user sees.
#![allow(dead_code)] // each test file uses a different subset

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Runs `lugre` with `args`.
pub fn lugre(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_lugre"))
        .args(args)
        .env("RUST_BACKTRACE", "1")
        .output()
        .expect("the binary runs")
}

/// Bad input: exit status 2, one line on stderr containing `want` (no panic message, no
/// backtrace), nothing on stdout. Returns the line.
#[track_caller]
pub fn rejects(args: &[&str], want: &str) -> String {
    let out = lugre(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert_eq!(err.lines().count(), 1, "{args:?}: one line, got {err}");
    assert!(err.contains(want), "{args:?}: wanted '{want}' in {err}");
    assert!(
        !err.contains("panicked") && !err.contains("backtrace"),
        "{err}"
    );
    assert!(out.stdout.is_empty(), "{args:?}");
    err.into_owned()
}

/// Valid input, however extreme: exit status 0, nothing on stderr, no NaN or infinity on
/// stdout. Returns stdout.
pub fn accepts(args: &[&str]) -> String {
    let out = lugre(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{args:?}: {err}");
    assert!(err.is_empty(), "{args:?}: nothing on stderr, got {err}");
    let text = String::from_utf8(out.stdout).expect("stdout is UTF-8");
    assert!(!has_nan_or_inf(&text), "{args:?}: NaN or inf in\n{text}");
    text
}

/// [`accepts`], parsed as JSON.
pub fn accepts_json(args: &[&str]) -> serde_json::Value {
    serde_json::from_str(&accepts(args)).expect("valid JSON")
}

/// Whether `text` has a word `NaN`, `inf` or `infinity` (any case; not inside words such as
/// "Rainflow").
pub fn has_nan_or_inf(text: &str) -> bool {
    text.split(|c: char| !c.is_ascii_alphanumeric())
        .any(|w| ["nan", "inf", "infinity"].contains(&w.to_ascii_lowercase().as_str()))
}

/// A number in a JSON document.
pub fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().expect("a number")
}

/// A fresh directory under the system's temporary directory, removed on drop.
pub struct TempDir(PathBuf);

impl TempDir {
    pub fn new(name: &str) -> Self {
        let dir = std::env::temp_dir().join(format!("lugre-test-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("create a temporary directory");
        Self(dir)
    }

    pub fn path(&self) -> &Path {
        &self.0
    }

    /// Writes `contents` to `name` in the directory; returns its path as a string.
    pub fn file(&self, name: &str, contents: impl AsRef<[u8]>) -> String {
        let p = self.0.join(name);
        std::fs::write(&p, contents).expect("write a test file");
        p.to_str().expect("UTF-8 path").to_string()
    }

    /// The path of `name` in the directory, as a string (nothing is created).
    pub fn join(&self, name: &str) -> String {
        self.0.join(name).to_str().expect("UTF-8 path").to_string()
    }

    /// The names of the entries in the directory, sorted.
    pub fn entries(&self) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(&self.0)
            .expect("read the directory")
            .map(|e| {
                e.expect("an entry")
                    .file_name()
                    .to_string_lossy()
                    .into_owned()
            })
            .collect();
        v.sort();
        v
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}
