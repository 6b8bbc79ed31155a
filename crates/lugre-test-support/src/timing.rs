//! What the speed examples share: the best of several timed runs, and a reproducible random
//! walk (xorshift64, no dependency) to time them on.

use std::time::Instant;

/// The shortest of `runs` timed calls of `f`, in seconds.
pub fn best_of(runs: usize, mut f: impl FnMut()) -> f64 {
    (0..runs)
        .map(|_| {
            let t = Instant::now();
            f();
            t.elapsed().as_secs_f64()
        })
        .fold(f64::INFINITY, f64::min)
}

/// `n` samples of a random walk from 0 with steps uniform in `[-step/2, step/2)`.
pub fn random_walk(n: usize, step: f64) -> Vec<f64> {
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    let mut x = 0.0;
    (0..n)
        .map(|_| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            x += ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * step;
            x
        })
        .collect()
}
