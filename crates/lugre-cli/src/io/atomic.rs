//! Files are written to a temporary file in the same directory and renamed into place, so an
//! interrupted run never leaves a truncated output.

use anyhow::{Context, Result};
use std::io::{BufWriter, Write};
use std::path::Path;

/// `.NAME.tmp-PID` in the same directory as `path` (so the rename is atomic).
fn temporary_sibling(path: &Path) -> Result<std::path::PathBuf> {
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
    // The extension is kept last: encoders choose the format from it.
    Ok(dir.join(format!(
        ".{}.tmp-{}{ext}",
        name.to_string_lossy(),
        std::process::id()
    )))
}

/// Writes `path` atomically with `fill`.
pub(crate) fn write_atomic(
    path: &Path,
    fill: impl FnOnce(&mut dyn Write) -> Result<()>,
) -> Result<()> {
    let tmp = temporary_sibling(path)?;
    let result = (|| -> Result<()> {
        let file = std::fs::File::create(&tmp)
            .with_context(|| format!("cannot write '{}'", path.display()))?;
        let mut w = BufWriter::new(file);
        fill(&mut w)?;
        let file = w
            .into_inner()
            .map_err(|e| e.into_error())
            .with_context(|| format!("cannot write '{}'", path.display()))?;
        file.sync_all()
            .with_context(|| format!("cannot write '{}'", path.display()))?;
        std::fs::rename(&tmp, path).with_context(|| format!("cannot write '{}'", path.display()))
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}
