//! A spool: bytes kept in memory up to a limit, then in a temporary file, replayed in order
//! (`lugre cycles` holds the reversals' JSON while it counts).

use anyhow::{Context, Result};
use std::fs::File;
use std::io::{self, BufWriter, Read, Write};
use std::path::PathBuf;

/// Bytes kept in memory up to a limit, then in a temporary file removed on drop.
pub(crate) struct Spool {
    limit: usize,
    memory: Vec<u8>,
    file: Option<(PathBuf, BufWriter<File>)>,
}

impl Spool {
    pub(crate) fn new(limit: usize) -> Self {
        Self {
            limit,
            memory: Vec::new(),
            file: None,
        }
    }

    /// Hands the bytes to `f`, in order, in chunks.
    pub(crate) fn replay(&self, mut f: impl FnMut(&[u8]) -> Result<()>) -> Result<()> {
        f(&self.memory)?;
        if let Some((path, w)) = &self.file {
            // The writer was flushed by `JsonOut::finish`.
            debug_assert!(w.buffer().is_empty());
            let mut file =
                File::open(path).with_context(|| format!("cannot read '{}'", path.display()))?;
            let mut buf = vec![0u8; 1 << 20];
            loop {
                let n = file.read(&mut buf)?;
                if n == 0 {
                    break;
                }
                f(&buf[..n])?;
            }
        }
        Ok(())
    }
}

impl Write for Spool {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        if self.file.is_none() && self.memory.len() + buf.len() <= self.limit {
            self.memory.extend_from_slice(buf);
            return Ok(buf.len());
        }
        if self.file.is_none() {
            let path = std::env::temp_dir().join(format!(
                "lugre-cycles-{}-{}.json",
                std::process::id(),
                std::time::SystemTime::now()
                    .duration_since(std::time::UNIX_EPOCH)
                    .map_or(0, |d| d.as_nanos())
            ));
            let file = File::options().write(true).create_new(true).open(&path)?;
            self.file = Some((path, BufWriter::with_capacity(1 << 20, file)));
        }
        match self.file.as_mut() {
            Some((_, w)) => w.write(buf),
            None => Err(io::Error::other("spool file missing")),
        }
    }

    fn flush(&mut self) -> io::Result<()> {
        match self.file.as_mut() {
            Some((_, w)) => w.flush(),
            None => Ok(()),
        }
    }
}

impl Drop for Spool {
    fn drop(&mut self) {
        if let Some((path, _)) = self.file.take() {
            let _ = std::fs::remove_file(path);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spool_spills_to_a_file_and_replays_in_order() {
        let mut spool = Spool::new(10);
        let mut want = Vec::new();
        for k in 0..1000 {
            let chunk = format!("{k},");
            spool.write_all(chunk.as_bytes()).unwrap();
            want.extend_from_slice(chunk.as_bytes());
        }
        spool.flush().unwrap();
        let path = spool
            .file
            .as_ref()
            .map(|(p, _)| p.clone())
            .expect("spilled");
        assert!(path.exists());
        let mut got = Vec::new();
        spool
            .replay(|c| {
                got.extend_from_slice(c);
                Ok(())
            })
            .unwrap();
        assert_eq!(got, want);
        drop(spool);
        assert!(!path.exists(), "removed on drop");
    }
}
