//! [`Request`]: the grid of amplitudes and frequencies, with the one set of defaults and
//! checks that the command line (`lugre sweep`) and the Python package (`lugre.sweep`) share,
//! and its run in parallel over the points.

use super::harmonics::Point;
use super::SweepError;
use crate::model::{LuGre, VelocityFn};
use crate::simulate::Tolerance;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

/// A sweep: every amplitude with every frequency (amplitude-major: the frequencies of the
/// first amplitude come first), the offset of the input, the loop samples per point and the
/// integrator's tolerance, each with its default.
#[derive(Debug, Clone, PartialEq)]
pub struct Request {
    amplitudes: Vec<f64>,
    frequencies: Vec<f64>,
    offset: f64,
    loop_samples: usize,
    tol: Tolerance,
}

/// The points of a sweep, in the request's order.
#[derive(Debug, Clone, PartialEq)]
pub struct Sweep {
    pub points: Vec<Point>,
}

/// Parses a list of values as the command line and the Python package take it: numbers
/// separated by commas (`1e-6,1e-5`) or `START:STOP:COUNT`, `COUNT` values from `START` to
/// `STOP` spaced evenly on a log scale (both ends included, exactly). `what` names the list in
/// messages (`"amplitudes"`). The values themselves are checked by [`Request::new`].
///
/// ```
/// use lugre::sweep::parse_values;
/// assert_eq!(parse_values("amplitudes", "1e-6, 1e-5").unwrap(), [1e-6, 1e-5]);
/// let f = parse_values("frequencies", "0.1:100:4").unwrap();
/// assert_eq!(f.len(), 4);
/// assert_eq!((f[0], f[3]), (0.1, 100.0));
/// assert!((f[1] - 1.0).abs() < 1e-15);
/// ```
pub fn parse_values(what: &'static str, text: &str) -> Result<Vec<f64>, SweepError> {
    let text = text.trim();
    if text.is_empty() {
        return Err(SweepError::EmptyList { what });
    }
    if text.contains(':') {
        return parse_range(what, text);
    }
    text.split(',')
        .enumerate()
        .map(|(i, item)| {
            item.trim()
                .parse::<f64>()
                .map_err(|_| SweepError::NotANumber {
                    what,
                    position: i + 1,
                    item: shorten(item.trim()),
                })
        })
        .collect()
}

/// `START:STOP:COUNT`, log spacing.
fn parse_range(what: &'static str, text: &str) -> Result<Vec<f64>, SweepError> {
    let bad = || SweepError::BadRange {
        what,
        text: shorten(text),
        most: Request::MAX_POINTS,
    };
    let parts: Vec<&str> = text.split(':').map(str::trim).collect();
    let [start, stop, count] = parts[..] else {
        return Err(bad());
    };
    let number = |s: &str| s.parse::<f64>().ok().filter(|v| v.is_finite() && *v > 0.0);
    let (Some(start), Some(stop)) = (number(start), number(stop)) else {
        return Err(bad());
    };
    let count = match count.parse::<usize>() {
        Ok(n) if (1..=Request::MAX_POINTS).contains(&n) => n,
        _ => return Err(bad()),
    };
    if count == 1 {
        return Ok(vec![start]);
    }
    // As numpy's logspace: 10 to evenly spaced exponents, so that decades land on powers of
    // ten exactly (1e-7:1e-3:5 gives 1e-5, not 1.0000000000000004e-5).
    let (lo, hi) = (start.log10(), stop.log10());
    Ok((0..count)
        .map(|i| match i {
            0 => start,
            i if i == count - 1 => stop,
            i => 10f64.powf(lo + (hi - lo) * (i as f64 / (count - 1) as f64)),
        })
        .collect())
}

/// At most 40 characters of a user's text, for a message.
fn shorten(text: &str) -> String {
    match text.char_indices().nth(40) {
        Some((i, _)) => format!("{}...", &text[..i]),
        None => text.to_string(),
    }
}

impl Request {
    /// The integrator's relative tolerance by default: `1e-12` (energies to about `1e-11`).
    pub const DEFAULT_TOLERANCE: f64 = 1e-12;
    /// The most points a sweep may have.
    pub const MAX_POINTS: usize = 10_000_000;
    /// The most memory the points and their loops may take (bytes): 2 GB.
    pub const MAX_BYTES: u64 = 2_000_000_000;

    /// The grid, every value finite and `> 0`; offset 0, no loops, tolerance
    /// [`Self::DEFAULT_TOLERANCE`].
    pub fn new(amplitudes: Vec<f64>, frequencies: Vec<f64>) -> Result<Self, SweepError> {
        for (what, values) in [("amplitude", &amplitudes), ("frequency", &frequencies)] {
            if values.is_empty() {
                return Err(SweepError::EmptyList {
                    what: if what == "amplitude" {
                        "amplitudes"
                    } else {
                        "frequencies"
                    },
                });
            }
            if let Some(&value) = values.iter().find(|v| !(v.is_finite() && **v > 0.0)) {
                return Err(SweepError::NotPositive { what, value });
            }
        }
        let r = Self {
            amplitudes,
            frequencies,
            offset: 0.0,
            loop_samples: 0,
            tol: Tolerance::new(Self::DEFAULT_TOLERANCE).expect("in range"),
        };
        r.check_size()?;
        Ok(r)
    }

    /// The input's mean value (it shifts the loop along `u` only: the model sees `u'`).
    pub fn with_offset(mut self, offset: f64) -> Result<Self, SweepError> {
        if !offset.is_finite() {
            return Err(SweepError::BadOffset { value: offset });
        }
        self.offset = offset;
        Ok(self)
    }

    /// The loop of each point at `n` evenly spaced times over a period (both ends), `n = 0`
    /// for none; checked against [`Self::MAX_BYTES`] before anything is allocated.
    pub fn with_loop_samples(mut self, n: usize) -> Result<Self, SweepError> {
        if n == 1 {
            return Err(SweepError::BadLoopSamples { value: n });
        }
        self.loop_samples = n;
        self.check_size()?;
        Ok(self)
    }

    pub fn with_tolerance(mut self, tol: Tolerance) -> Self {
        self.tol = tol;
        self
    }

    pub fn amplitudes(&self) -> &[f64] {
        &self.amplitudes
    }
    pub fn frequencies(&self) -> &[f64] {
        &self.frequencies
    }
    pub fn offset(&self) -> f64 {
        self.offset
    }
    pub fn loop_samples(&self) -> usize {
        self.loop_samples
    }
    pub fn tolerance(&self) -> Tolerance {
        self.tol
    }

    /// The number of points (amplitudes times frequencies).
    pub fn points(&self) -> usize {
        self.amplitudes.len().saturating_mul(self.frequencies.len())
    }

    /// The memory the result takes, in bytes (points and loops), saturating.
    pub fn bytes(&self) -> u64 {
        let per_point = std::mem::size_of::<Point>() as u64 + 3 * 8 * self.loop_samples as u64;
        (self.points() as u64).saturating_mul(per_point)
    }

    /// At most [`Self::MAX_POINTS`] points and [`Self::MAX_BYTES`] of results.
    pub fn check_size(&self) -> Result<(), SweepError> {
        let bytes = self.bytes();
        if self.points() > Self::MAX_POINTS || bytes > Self::MAX_BYTES {
            return Err(SweepError::TooLarge {
                amplitudes: self.amplitudes.len(),
                frequencies: self.frequencies.len(),
                points: self.amplitudes.len() as u64 * self.frequencies.len() as u64,
                samples: self.loop_samples,
                bytes,
                limit: Self::MAX_BYTES,
            });
        }
        Ok(())
    }

    /// The amplitude and frequency of point `i`.
    pub fn point(&self, i: usize) -> (f64, f64) {
        let n = self.frequencies.len();
        (self.amplitudes[i / n], self.frequencies[i % n])
    }

    /// Computes every point on all cores, reporting `(done, total)` to `progress` after each
    /// point if given (from the worker threads). The first failing point in the grid's order
    /// is the error.
    pub fn run<G: VelocityFn + Sync, F: VelocityFn + Sync>(
        &self,
        model: &LuGre<G, F>,
        progress: Option<&(dyn Fn(usize, usize) + Sync)>,
    ) -> Result<Sweep, SweepError> {
        self.check_size()?;
        let total = self.points();
        let threads = std::thread::available_parallelism()
            .map_or(1, |n| n.get())
            .min(total);
        let next = AtomicUsize::new(0);
        let done = AtomicUsize::new(0);
        // The lowest index that failed: points after it are skipped, points before it are
        // all computed, so the error reported does not depend on the threads' timing.
        let first_error = AtomicUsize::new(usize::MAX);
        let results: Mutex<Vec<(usize, Result<Point, SweepError>)>> =
            Mutex::new(Vec::with_capacity(total));
        let work = || {
            let mut mine = Vec::new();
            loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                if i >= total || i > first_error.load(Ordering::Relaxed) {
                    break;
                }
                let result = self.compute(model, i);
                if result.is_err() {
                    first_error.fetch_min(i, Ordering::Relaxed);
                }
                mine.push((i, result));
                let d = done.fetch_add(1, Ordering::Relaxed) + 1;
                if let Some(report) = progress {
                    report(d, total);
                }
            }
            results
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .extend(mine);
        };
        std::thread::scope(|s| {
            for _ in 1..threads {
                s.spawn(work);
            }
            work();
        });
        let mut results = results.into_inner().unwrap_or_else(|e| e.into_inner());
        results.sort_unstable_by_key(|(i, _)| *i);
        let points = results
            .into_iter()
            .map(|(_, r)| r)
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Sweep { points })
    }

    /// Point `i` (its failure names its amplitude and frequency).
    fn compute<G: VelocityFn, F: VelocityFn>(
        &self,
        model: &LuGre<G, F>,
        i: usize,
    ) -> Result<Point, SweepError> {
        let (amplitude, frequency) = self.point(i);
        Point::compute(
            model,
            amplitude,
            frequency,
            self.offset,
            self.tol,
            self.loop_samples,
        )
    }
}
