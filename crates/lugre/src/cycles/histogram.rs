//! Rainflow counts binned by range, and by range and mean (the matrix fatigue analyses take).

use super::Cycle;
use crate::error::HistoryError;

/// Counts of cycles (full = 1, half = 0.5) in `bins` equal bins of range over
/// `[0, max - min]` and of mean over `[min, max]`, where `min` and `max` bound the history
/// (every range and mean then falls in a bin). Bins are closed on the left, the last one on
/// both sides.
#[derive(Debug, Clone, PartialEq)]
pub struct Histogram {
    bins: usize,
    min: f64,
    max: f64,
    /// `range_counts[r]`.
    range_counts: Vec<f64>,
    /// `counts[r * bins + m]`.
    counts: Vec<f64>,
}

impl Histogram {
    /// `bins >= 1`; `min <= max`, both finite with `max - min` finite.
    pub fn new(bins: usize, min: f64, max: f64) -> Result<Self, HistoryError> {
        if bins == 0 {
            return Err(HistoryError::NoBins { bins });
        }
        if !(min.is_finite() && max.is_finite() && min <= max && (max - min).is_finite()) {
            return Err(HistoryError::BadBounds { min, max });
        }
        Ok(Self {
            bins,
            min,
            max,
            range_counts: vec![0.0; bins],
            counts: vec![0.0; bins * bins],
        })
    }

    pub fn bins(&self) -> usize {
        self.bins
    }

    /// The bin of `x` among `bins` equal bins over `[lo, lo + width]`.
    fn bin(&self, x: f64, lo: f64, width: f64) -> usize {
        if width <= 0.0 {
            return 0;
        }
        let k = ((x - lo) / width * self.bins as f64).floor();
        // Clamped: the top edge belongs to the last bin, and rounding may step just outside.
        if k >= 1.0 {
            (k as usize).min(self.bins - 1)
        } else {
            0
        }
    }

    pub fn add(&mut self, c: &Cycle) {
        let width = self.max - self.min;
        let r = self.bin(c.range, 0.0, width);
        let m = self.bin(c.mean, self.min, width);
        self.range_counts[r] += c.count;
        self.counts[r * self.bins + m] += c.count;
    }

    /// `bins + 1` edges of the range bins, `0` to `max - min`.
    pub fn range_edges(&self) -> Vec<f64> {
        edges(0.0, self.max - self.min, self.bins)
    }

    /// `bins + 1` edges of the mean bins, `min` to `max`.
    pub fn mean_edges(&self) -> Vec<f64> {
        edges(self.min, self.max, self.bins)
    }

    /// Counts per range bin.
    pub fn range_counts(&self) -> &[f64] {
        &self.range_counts
    }

    /// Counts per mean bin for range bin `r`.
    pub fn range_row(&self, r: usize) -> &[f64] {
        &self.counts[r * self.bins..(r + 1) * self.bins]
    }

    /// The total count (full cycles + half of the half cycles).
    pub fn total(&self) -> f64 {
        self.range_counts.iter().sum()
    }
}

fn edges(lo: f64, hi: f64, bins: usize) -> Vec<f64> {
    (0..=bins)
        .map(|k| {
            if k == bins {
                hi
            } else {
                lo + (hi - lo) * (k as f64 / bins as f64)
            }
        })
        .collect()
}
