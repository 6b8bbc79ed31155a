//! A streaming JSON emitter for large reports: numbers go straight from `zmij` (shortest
//! round-trip representation, as serde_json prints them) into a buffer flushed in large
//! chunks, cheaper than serde_json's generic path on large reports (BENCHMARKS.md).

use lugre::LoopPoint;
use std::io::{self, Write};

const FLUSH_AT: usize = 1 << 20;

pub(crate) struct JsonOut<W: Write> {
    out: W,
    buf: Vec<u8>,
    fmt: zmij::Buffer,
}

impl<W: Write> JsonOut<W> {
    pub(crate) fn new(out: W) -> Self {
        Self {
            out,
            buf: Vec::with_capacity(FLUSH_AT + 4096),
            fmt: zmij::Buffer::new(),
        }
    }

    /// Raw JSON text (punctuation, keys, or an already-serialized value).
    #[inline]
    pub(crate) fn raw(&mut self, s: &str) -> io::Result<()> {
        self.buf.extend_from_slice(s.as_bytes());
        self.maybe_flush()
    }

    /// A finite number (callers check finiteness first: JSON has no NaN/inf).
    #[inline]
    pub(crate) fn num(&mut self, x: f64) -> io::Result<()> {
        debug_assert!(x.is_finite());
        let s = self.fmt.format_finite(x);
        self.buf.extend_from_slice(s.as_bytes());
        Ok(())
    }

    #[inline]
    pub(crate) fn int(&mut self, x: usize) -> io::Result<()> {
        write!(self.buf, "{x}")
    }

    /// `prefix` (punctuation and key, e.g. `,"work":`) then a number: one copy each.
    #[inline]
    pub(crate) fn field(&mut self, prefix: &str, x: f64) -> io::Result<()> {
        self.buf.extend_from_slice(prefix.as_bytes());
        self.num(x)
    }

    /// The key `name` of an object's member: `{"name":` for the first (`first`), else
    /// `,"name":` (`name` needs no escaping: the core's column names).
    #[inline]
    pub(crate) fn key(&mut self, first: bool, name: &str) {
        self.buf
            .extend_from_slice(if first { b"{\"" } else { b",\"" });
        self.buf.extend_from_slice(name.as_bytes());
        self.buf.extend_from_slice(b"\":");
    }

    /// `{"rho":..,"u":..,"y":..}` ([`LoopPoint::COLUMNS`]).
    #[inline]
    pub(crate) fn point(&mut self, p: &LoopPoint) -> io::Result<()> {
        for (k, (name, x)) in LoopPoint::COLUMNS.iter().zip(p.values()).enumerate() {
            self.key(k == 0, name);
            self.num(x)?;
        }
        self.buf.push(b'}');
        self.maybe_flush()
    }

    /// `[x0,x1,...]`.
    pub(crate) fn array(&mut self, xs: &[f64]) -> io::Result<()> {
        self.buf.push(b'[');
        for (i, &x) in xs.iter().enumerate() {
            if i > 0 {
                self.buf.push(b',');
            }
            self.num(x)?;
        }
        self.buf.push(b']');
        self.maybe_flush()
    }

    /// `[{point},...]`.
    pub(crate) fn points(&mut self, ps: &[LoopPoint]) -> io::Result<()> {
        self.buf.push(b'[');
        for (i, p) in ps.iter().enumerate() {
            if i > 0 {
                self.buf.push(b',');
            }
            self.point(p)?;
        }
        self.buf.push(b']');
        Ok(())
    }

    #[inline]
    fn maybe_flush(&mut self) -> io::Result<()> {
        if self.buf.len() >= FLUSH_AT {
            self.out.write_all(&self.buf)?;
            self.buf.clear();
        }
        Ok(())
    }

    pub(crate) fn finish(mut self) -> io::Result<()> {
        self.out.write_all(&self.buf)?;
        self.buf.clear();
        self.out.flush()
    }
}
