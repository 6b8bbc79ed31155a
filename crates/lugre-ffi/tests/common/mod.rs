//! What the tests that build C programs share: the repository's root, the static library, a
//! C compiler run against the header.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Builds the staticlib (cargo test builds only the rlib) and returns its path.
pub fn static_library() -> PathBuf {
    let status = Command::new(env!("CARGO"))
        .args(["build", "--quiet", "-p", "lugre-ffi"])
        .current_dir(root())
        .status()
        .expect("cargo runs");
    assert!(status.success(), "cargo build -p lugre-ffi failed");
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| root().join("target"));
    target.join("debug/liblugre_c.a")
}

/// Compiles `source` (warnings are errors) with `defines` against the header and the static
/// library, runs it and returns what it did.
pub fn compile_and_run(source: &Path, defines: &[String]) -> Output {
    let lib = static_library();
    let stem = source.file_stem().unwrap().to_string_lossy().into_owned();
    let exe = std::env::temp_dir().join(format!("lugre-{stem}-{}", std::process::id()));
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".into());
    let status = Command::new(cc)
        .arg(source)
        .args(defines)
        .arg(format!(
            "-I{}",
            root().join("crates/lugre-ffi/include").display()
        ))
        .arg(&lib)
        .args(["-lm", "-lpthread", "-ldl", "-Wall", "-Werror", "-o"])
        .arg(&exe)
        .status()
        .expect("a C compiler (cc)");
    assert!(status.success(), "{} does not compile", source.display());
    let out = Command::new(&exe).output().expect("the program runs");
    let _ = std::fs::remove_file(&exe);
    out
}
