//! The output policy, the same for every command, checked before anything is read or computed:
//!
//! * an output never replaces an input (the user's measurement is not overwritten by a result);
//! * two outputs never go to one file (one would silently replace the other);
//! * `lugre paper` writes into a folder only when lugre created it (it holds [`FOLDER_MARK`]),
//!   it is empty or new, or `--force` is given: a user's own `index.html` is not replaced.
//!
//! Two paths are the same file when they lead to the same file on disk, through symlinks or as
//! hard links (the same device and inode, on unix), or resolve to the same path (a file not yet
//! written: its folder resolved, then its name). Files are written atomically (`atomic`).

use anyhow::{bail, Context, Result};
use std::path::{Path, PathBuf};

/// A file named on the command line: the flag that named it and its path.
#[derive(Debug, Clone, Copy)]
struct Named<'a> {
    flag: &'static str,
    path: &'a Path,
}

/// The files a run reads and writes, by the flags that name them.
#[derive(Debug, Default)]
pub(crate) struct Files<'a> {
    inputs: Vec<Named<'a>>,
    outputs: Vec<Named<'a>>,
}

impl<'a> Files<'a> {
    pub(crate) fn new() -> Self {
        Self::default()
    }

    /// A file the run reads, when the flag is given.
    pub(crate) fn input(mut self, flag: &'static str, path: Option<&'a Path>) -> Self {
        if let Some(path) = path {
            self.inputs.push(Named { flag, path });
        }
        self
    }

    /// A file the run writes, when the flag is given.
    pub(crate) fn output(mut self, flag: &'static str, path: Option<&'a Path>) -> Self {
        if let Some(path) = path {
            self.outputs.push(Named { flag, path });
        }
        self
    }

    /// Refuses an output that is an input or another output, naming both flags and paths.
    pub(crate) fn check(&self) -> Result<()> {
        let inputs: Vec<Identity> = self.inputs.iter().map(|f| Identity::of(f.path)).collect();
        let outputs: Vec<Identity> = self.outputs.iter().map(|f| Identity::of(f.path)).collect();
        for (k, (out, id)) in self.outputs.iter().zip(&outputs).enumerate() {
            if let Some(input) = self.inputs.iter().zip(&inputs).find(|(_, i)| i.same(id)) {
                bail!(
                    "{} '{}' is the same file as {} '{}': lugre never writes over an input; give {} another file",
                    out.flag,
                    out.path.display(),
                    input.0.flag,
                    input.0.path.display(),
                    out.flag
                );
            }
            if let Some(earlier) = self.outputs[..k]
                .iter()
                .zip(&outputs)
                .find(|(_, e)| e.same(id))
            {
                bail!(
                    "{} '{}' and {} '{}' are the same file: give each output its own file",
                    earlier.0.flag,
                    earlier.0.path.display(),
                    out.flag,
                    out.path.display()
                );
            }
        }
        Ok(())
    }
}

/// What tells two paths to one file apart: the resolved path, and the file's device and inode
/// when it exists (unix).
#[derive(Debug)]
struct Identity {
    path: Option<PathBuf>,
    inode: Option<(u64, u64)>,
}

impl Identity {
    fn of(path: &Path) -> Self {
        Self {
            path: resolve(path),
            inode: std::fs::metadata(path).ok().and_then(|m| inode(&m)),
        }
    }

    fn same(&self, other: &Self) -> bool {
        fn equal<T: PartialEq>(a: &Option<T>, b: &Option<T>) -> bool {
            matches!((a, b), (Some(a), Some(b)) if a == b)
        }
        equal(&self.inode, &other.inode) || equal(&self.path, &other.path)
    }
}

#[cfg(unix)]
fn inode(m: &std::fs::Metadata) -> Option<(u64, u64)> {
    use std::os::unix::fs::MetadataExt;
    Some((m.dev(), m.ino()))
}

#[cfg(not(unix))]
fn inode(_: &std::fs::Metadata) -> Option<(u64, u64)> {
    None
}

/// `path` with every symlink resolved: the file's when it exists, else its folder's joined with
/// its name (a file about to be written). `None` when neither resolves.
fn resolve(path: &Path) -> Option<PathBuf> {
    if let Ok(p) = std::fs::canonicalize(path) {
        return Some(p);
    }
    let name = path.file_name()?;
    let folder = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    std::fs::canonicalize(folder).ok().map(|p| p.join(name))
}

/// The file `lugre paper` leaves in the folder it writes: lugre's files there may be replaced.
pub(crate) const FOLDER_MARK: &str = ".lugre-paper";

/// What [`FOLDER_MARK`] says to a person who finds it.
const FOLDER_MARK_TEXT: &str = "This folder was written by `lugre paper`; running it again \
replaces the files it wrote here.\n";

/// A folder a command writes many files into (`flag` names it), checked before anything is
/// computed and created (and marked) only when the files are ready.
#[derive(Debug)]
pub(crate) struct OutputFolder<'a> {
    flag: &'static str,
    dir: &'a Path,
}

impl<'a> OutputFolder<'a> {
    /// Refuses a folder that exists, holds files and was not written by lugre (it lacks
    /// [`FOLDER_MARK`]), unless `force`. A missing folder, or a path that is no folder, is
    /// left to [`OutputFolder::create`] to report.
    pub(crate) fn check(flag: &'static str, dir: &'a Path, force: bool) -> Result<Self> {
        if !force && dir.is_dir() && !dir.join(FOLDER_MARK).exists() {
            let entries = std::fs::read_dir(dir)
                .with_context(|| format!("cannot read the folder '{}' ({flag})", dir.display()))?;
            let mut names: Vec<String> = entries
                .filter_map(|e| e.ok())
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect();
            names.sort();
            if let Some(first) = names.first() {
                bail!(
                    "{flag} '{}' is a folder lugre did not create and it holds files (e.g. '{first}'): lugre paper does not write over them; give a new or empty folder, or --force to replace the files it writes there",
                    dir.display()
                );
            }
        }
        Ok(Self { flag, dir })
    }

    /// Creates the folder (and its parents) if missing, and marks it as lugre's.
    pub(crate) fn create(&self) -> Result<&'a Path> {
        std::fs::create_dir_all(self.dir).with_context(|| {
            format!(
                "cannot create the output directory '{}' ({})",
                self.dir.display(),
                self.flag
            )
        })?;
        super::atomic::write_atomic(&self.dir.join(FOLDER_MARK), |w| {
            Ok(w.write_all(FOLDER_MARK_TEXT.as_bytes())?)
        })?;
        Ok(self.dir)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::scratch_folder as scratch;

    #[test]
    fn a_path_through_its_folder_is_the_same_file() {
        let dir = scratch("outputs-paths");
        let a = dir.join("a.csv");
        std::fs::write(&a, "u\n1\n").unwrap();
        let roundabout = dir.join(".").join("a.csv");
        let err = Files::new()
            .input("--input", Some(&a))
            .output("--csv", Some(&roundabout))
            .check()
            .unwrap_err()
            .to_string();
        assert!(
            err.starts_with("--csv '") && err.contains("--input '"),
            "{err}"
        );
        // A file not yet written is compared by its resolved folder and name.
        let new = dir.join("new.svg");
        let err = Files::new()
            .output("--csv", Some(&new))
            .output(
                "--plot",
                Some(
                    &dir.join("..")
                        .join(dir.file_name().unwrap())
                        .join("new.svg"),
                ),
            )
            .check()
            .unwrap_err()
            .to_string();
        assert!(err.contains("are the same file"), "{err}");
        // Different files pass.
        Files::new()
            .input("--input", Some(&a))
            .output("--csv", Some(&new))
            .output("--plot", Some(&dir.join("b.svg")))
            .check()
            .unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_folder_is_checked_before_and_marked_after() {
        let dir = scratch("outputs-folder");
        let theirs = dir.join("theirs");
        std::fs::create_dir_all(&theirs).unwrap();
        std::fs::write(theirs.join("index.html"), "mine").unwrap();
        let err = OutputFolder::check("--out", &theirs, false)
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("'index.html'") && err.contains("--force"),
            "{err}"
        );
        OutputFolder::check("--out", &theirs, true).unwrap();

        let empty = dir.join("empty");
        std::fs::create_dir_all(&empty).unwrap();
        OutputFolder::check("--out", &empty, false).unwrap();

        let ours = dir.join("new").join("figures");
        OutputFolder::check("--out", &ours, false)
            .unwrap()
            .create()
            .unwrap();
        std::fs::write(ours.join("index.html"), "lugre's").unwrap();
        assert!(ours.join(FOLDER_MARK).exists());
        OutputFolder::check("--out", &ours, false).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
