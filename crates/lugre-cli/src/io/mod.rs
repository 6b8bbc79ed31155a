//! Files and streams: CSV out (data files are read by `lugre-io`), the JSON writer, atomic
//! files, the output policy, the spool, and progress on stderr.

pub(crate) mod atomic;
pub(crate) mod csv;
pub(crate) mod json;
pub(crate) mod outputs;
pub(crate) mod progress;
pub(crate) mod spool;

/// A fresh, empty folder under the system's temporary folder for a unit test's files.
#[cfg(test)]
pub(crate) fn scratch_folder(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("lugre-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}
