//! Files are written to a temporary file in the same directory and renamed into place, so an
//! interrupted run never leaves a truncated output: on an error (or a panic) the temporary file
//! is removed and the path keeps what it held before. Which paths may be written at all is the
//! output policy's to say (`outputs`).

use anyhow::{Context, Result};
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// Names tried for the temporary file before giving up (another one may be left by a run that
/// was killed with the same process id).
const ATTEMPTS: u32 = 16;

/// A new file `.NAME.tmp-PID[-K]EXT` in the same directory as `path` (so the rename is atomic),
/// never one that exists already.
fn create_temporary(path: &Path) -> Result<(File, PathBuf)> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let name = path
        .file_name()
        .with_context(|| format!("cannot write '{}': not a file name", path.display()))?;
    let ext = path
        .extension()
        .map(|e| format!(".{}", e.to_string_lossy()))
        .unwrap_or_default();
    let pid = std::process::id();
    let mut k = 0;
    loop {
        let suffix = if k == 0 {
            String::new()
        } else {
            format!("-{k}")
        };
        // The extension is kept last: encoders choose the format from it.
        let tmp = dir.join(format!(
            ".{}.tmp-{pid}{suffix}{ext}",
            name.to_string_lossy()
        ));
        match File::options().write(true).create_new(true).open(&tmp) {
            Ok(file) => return Ok((file, tmp)),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists && k + 1 < ATTEMPTS => k += 1,
            Err(e) => return Err(e).with_context(|| format!("cannot write '{}'", path.display())),
        }
    }
}

/// The temporary file, removed when dropped unless it was renamed into place.
struct Temporary {
    path: PathBuf,
    renamed: bool,
}

impl Drop for Temporary {
    fn drop(&mut self) {
        if !self.renamed {
            let _ = std::fs::remove_file(&self.path);
        }
    }
}

/// Writes `path` atomically with `fill`.
pub(crate) fn write_atomic(
    path: &Path,
    fill: impl FnOnce(&mut dyn Write) -> Result<()>,
) -> Result<()> {
    let cannot = || format!("cannot write '{}'", path.display());
    let (file, tmp) = create_temporary(path)?;
    let mut tmp = Temporary {
        path: tmp,
        renamed: false,
    };
    let mut w = BufWriter::new(file);
    fill(&mut w)?;
    let file = w
        .into_inner()
        .map_err(|e| e.into_error())
        .with_context(cannot)?;
    file.sync_all().with_context(cannot)?;
    std::fs::rename(&tmp.path, path).with_context(cannot)?;
    tmp.renamed = true;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::scratch_folder as scratch;

    fn entries(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }

    /// An error or a panic half-way leaves the old file as it was and no temporary file.
    #[test]
    fn a_failed_write_leaves_the_old_file_and_nothing_else() {
        let dir = scratch("atomic-fail");
        let path = dir.join("out.csv");
        std::fs::write(&path, "old\n").unwrap();
        let err = write_atomic(&path, |w| {
            w.write_all(b"half")?;
            anyhow::bail!("stopped")
        });
        assert!(err.is_err());
        let panicked = std::panic::catch_unwind(|| {
            let _ = write_atomic(&path, |w| {
                w.write_all(b"half").unwrap();
                panic!("stopped")
            });
        });
        assert!(panicked.is_err());
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "old\n");
        assert_eq!(entries(&dir), vec!["out.csv".to_string()]);
        write_atomic(&path, |w| Ok(w.write_all(b"new\n")?)).unwrap();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "new\n");
        assert_eq!(entries(&dir), vec!["out.csv".to_string()]);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    /// A file that happens to have the temporary file's name is not touched.
    #[test]
    fn a_file_with_the_temporary_name_is_left_alone() {
        let dir = scratch("atomic-taken");
        let path = dir.join("out.csv");
        let taken = dir.join(format!(".out.csv.tmp-{}.csv", std::process::id()));
        std::fs::write(&taken, "someone's\n").unwrap();
        write_atomic(&path, |w| Ok(w.write_all(b"new\n")?)).unwrap();
        assert_eq!(std::fs::read_to_string(&taken).unwrap(), "someone's\n");
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "new\n");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
