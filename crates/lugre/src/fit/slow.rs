//! The slow-loop fit: `sigma0` and `g(0)` from the hysteresis loop `y°` (paper eqs. 8-10).
//!
//! The samples' turning points are found once (cyclically: the record is one or more periods
//! of a periodic input, closed from its last sample back to its first, as `lugre loop --input`
//! reads it). Sample `i` lies on segment `k` at the offset `l_i = |u_i - u_k|` from the turning
//! point `u_k`, at `rho_i = rho_k + l_i`, where (`docs/mathematics.md#slow-loop-fit`, with `a = sigma0 / g0`,
//! `s_k = +-1` the segment's direction and `y_k = y°(rho_k)` from [`HysteresisLoop`])
//!
//! ```text
//! y°(rho_i) = y_k e_i + s_k g0 (1 - e_i)          e_i = exp(-a l_i)                  (F1)
//! ```
//!
//! At fixed `a` the loop is proportional to `g0` (every term of the recursion is), so with
//! `D = dy°/da` at fixed `g0`:
//!
//! ```text
//! dy°/dsigma0 = D / g0          dy°/dg0 = y° / g0 - (a / g0) D                           (F2)
//! D(rho_i)    = D_k e_i - l_i e_i (y_k - s_k g0)                                          (F3)
//! D_{k+1}     = D_k E_k - L_k E_k (y_k - s_k g0)        E_k = exp(-a L_k)
//! D_0         = B / (1 - exp(-a P))                                                       (F4)
//! ```
//!
//! where `B` is `D_N` of (F3) run over one period from `D_0 = 0`: the loop is periodic, so its
//! derivative is too (`D_N = exp(-a P) D_0 + B = D_0`). Per evaluation: one [`HysteresisLoop`]
//! for the `y_k` (a few operations per turning point), then one exponential per sample for the
//! output and both derivatives, written into buffers allocated once.
//!
//! The turning points are the reversals of the motion, estimated between the samples: the
//! extreme sample falls short of the true reversal, and the force right after a reversal is
//! steep (slope `sigma0`), so taking the sample for the reversal biases both estimates (by about
//! 0.1 % with 1000 samples a period; the 95 % intervals then miss the truth). A parabola (smooth
//! motion) or two lines (constant-speed reversal) through the five samples around the extreme
//! give it ([`refined_reversal`]); a reversal sampled where it happens is kept.
//!
//! Start values (no guess needed): `g0` is the median of `s_k F` over the last 10 % of the
//! longer segments (the force plateaus); `a` is `ln 2 / l_half`, with `l_half` the travel after
//! a reversal at which the force has covered half its way from the reversal value to the
//! plateau (the initial slope `a (g0 - s_k y_k)` of (F1), measured by the secant to the half
//! point, which noise hardly moves); `sigma0 = a g0`. Dahl: `rho = a`, `Fc = g0`.

use super::lm::Evaluator;
use super::spec::Family;
use crate::error::FitError;
use crate::input::TurningPoints;
use crate::kernel::numerics::one_minus_exp;
use crate::kernel::relax::decay;
use crate::loops::HysteresisLoop;
use crate::model::RateIndependent;
use nalgebra::DMatrix;

/// Samples `start..end`, all on segment `k`, in the order of increasing offset.
#[derive(Debug, Clone, Copy)]
struct Run {
    k: usize,
    start: usize,
    end: usize,
}

/// The samples placed on the normalized input, and the buffers of one evaluation.
#[derive(Debug, Clone)]
pub(crate) struct SlowLoop {
    family: Family,
    /// Family indices of the free parameters.
    free: Vec<usize>,
    tp: TurningPoints,
    /// The samples at the turning points.
    reversals: Vec<usize>,
    /// `s_k`.
    direction: Vec<f64>,
    /// `L_k`.
    length: Vec<f64>,
    /// `rho_k`.
    rho: Vec<f64>,
    runs: Vec<Run>,
    /// `l_i`.
    offset: Vec<f64>,
    /// `D_k` (scratch).
    d: Vec<f64>,
}

/// One of the longer segments, for the start values.
struct LongSegment {
    /// Its samples `(l, F)` in order of travel.
    points: Vec<(f64, f64)>,
    /// Its direction.
    s: f64,
    /// The plateau over its last 10 %: mean travel and median `s F` there.
    l_end: f64,
    plateau: f64,
}

/// The sample indices at which the cyclic sequence `u` reverses, ascending. In a run of equal
/// values the first sample stands for the run (the run at the end of the record continues the
/// one at its start, cyclically). With a gate `gate > 0`, a turn is a reversal only once the
/// sequence has come back from its extreme by at least `gate` (the rule of the rainflow
/// counter's gate, [`crate::cycles`]): noise smaller than the gate makes no reversal.
fn cyclic_reversals(u: &[f64], gate: f64) -> Vec<usize> {
    let n = u.len();
    let mut reps: Vec<usize> = (0..n).filter(|&i| i == 0 || u[i] != u[i - 1]).collect();
    if reps.len() > 1 && u[n - 1] == u[0] {
        // The first run is the end of the last one.
        reps.remove(0);
    }
    let m = reps.len();
    if m < 2 {
        return Vec::new();
    }
    if gate > 0.0 {
        return gated_reversals(u, &reps, gate);
    }
    let mut out: Vec<usize> = (0..m)
        .filter(|&j| {
            let prev = u[reps[(j + m - 1) % m]];
            let next = u[reps[(j + 1) % m]];
            let v = u[reps[j]];
            (v > prev) != (next > v)
        })
        .map(|j| reps[j])
        .collect();
    out.sort_unstable();
    out
}

/// [`cyclic_reversals`] with a gate: one walk round the cycle of run representatives `reps`
/// from the highest (a reversal whatever the gate), each extreme confirmed once the sequence
/// has come back from it by `gate`.
fn gated_reversals(u: &[f64], reps: &[usize], gate: f64) -> Vec<usize> {
    let m = reps.len();
    let top = (0..m).fold(0, |b, j| if u[reps[j]] > u[reps[b]] { j } else { b });
    let mut out = vec![reps[top]];
    // Heading down from the top: the candidate is the lowest value since the last reversal.
    let mut down = true;
    let mut cand = reps[top];
    for step in 1..m {
        let i = reps[(top + step) % m];
        let (v, c) = (u[i], u[cand]);
        let (further, back) = if down { (v < c, v - c) } else { (v > c, c - v) };
        if further {
            cand = i;
        } else if back >= gate {
            out.push(cand);
            down = !down;
            cand = i;
        }
    }
    // The walk ends below the top: a last minimum is confirmed by the climb back to it.
    if down && u[reps[top]] - u[cand] >= gate {
        out.push(cand);
    }
    out.sort_unstable();
    out
}

/// How well a local shape must predict the two samples it was not built from, relative to the
/// largest step next to the reversal, for [`refined_reversal`] to use it.
const CLEAN_SHAPE: f64 = 1e-3;

/// The reversal near sample `r` (an extreme sample, `2 <= r < n - 2`), estimated between the
/// samples: the input turned somewhere between `r - 1` and `r + 1`, generally not at a sample,
/// and the sampled extreme falls short of the true one. Two local shapes through the five
/// samples `r - 2 ..= r + 2` (equally spaced in time): a parabola through the middle three
/// (a smooth motion, e.g. a sine) and two straight lines through the outer pairs (a
/// constant-speed reversal, e.g. a triangle wave); the one that predicts the samples it was not
/// built from better gives the reversal. The sample itself where the turn is a plateau, the
/// shapes do not turn or do not fit the samples cleanly (`CLEAN_SHAPE`), or the estimate lies
/// further out than one step.
fn refined_reversal(u: &[f64], r: usize) -> f64 {
    let (m2, m1, u0, p1, p2) = (u[r - 2], u[r - 1], u[r], u[r + 1], u[r + 2]);
    // s = +1 at a maximum, -1 at a minimum.
    let s = if u0 > m1 { 1.0 } else { -1.0 };
    let turns = s * (u0 - m1) > 0.0 && s * (u0 - p1) > 0.0;
    if !turns {
        return u0;
    }
    // Parabola u(x) = u0 + b x + c x^2 through x = -1, 0, 1; vertex u0 - b^2 / (4 c).
    let (b, c) = ((p1 - m1) / 2.0, (p1 + m1 - 2.0 * u0) / 2.0);
    let parabola = u0 - b * b / (4.0 * c);
    let parabola_miss = (u0 - 2.0 * b + 4.0 * c - m2).abs() + (u0 + 2.0 * b + 4.0 * c - p2).abs();
    // Lines through (-2, m2), (-1, m1) and (1, p1), (2, p2); they meet at x where
    // m1 + sl (x + 1) = p1 + sr (x - 1).
    let (sl, sr) = (m1 - m2, p2 - p1);
    let lines = if sl != sr {
        let x = (p1 - m1 - sr - sl) / (sl - sr);
        let on_left = m1 + sl;
        let on_right = p1 - sr;
        // u0 lies on the line of its side of the turn.
        let miss = if x >= 0.0 {
            on_left - u0
        } else {
            on_right - u0
        };
        Some((m1 + sl * (x + 1.0), miss.abs()))
    } else {
        None
    };
    let (estimate, miss) = match lines {
        Some((v, miss)) if miss < parabola_miss => (v, miss),
        _ => (parabola, parabola_miss),
    };
    let step = (u0 - m1).abs().max((u0 - p1).abs());
    let beyond = s * (estimate - u0);
    // Only a shape that fits the five samples cleanly: not a kink between unevenly spaced
    // samples (a reversal sampled where it is, between samples at other times).
    if miss <= CLEAN_SHAPE * step && beyond.is_finite() && (0.0..=step).contains(&beyond) {
        estimate
    } else {
        u0
    }
}

impl SlowLoop {
    /// Places the samples `u` (finite, checked by the caller) on their loop, each reversal
    /// (turns by at least `gate`, [`cyclic_reversals`]) estimated between the samples
    /// ([`refined_reversal`]), or at `turning` (the values estimated on the full record, for a
    /// thinned one with the same reversals).
    pub fn new(
        family: Family,
        free: Vec<usize>,
        u: &[f64],
        turning: Option<&[f64]>,
        gate: f64,
    ) -> Result<Self, FitError> {
        let n = u.len();
        let rev = cyclic_reversals(u, gate);
        if !rev.iter().any(|&r| r > 0 && r < n - 1) {
            return Err(FitError::NoReversal { fit: "slow" });
        }
        let values: Vec<f64> = match turning {
            Some(t) if t.len() == rev.len() => t.to_vec(),
            _ => rev
                .iter()
                .map(|&r| {
                    if r >= 2 && r + 2 < n {
                        refined_reversal(u, r)
                    } else {
                        u[r]
                    }
                })
                .collect(),
        };
        let tp = TurningPoints::new(&values).map_err(|_| FitError::NoReversal { fit: "slow" })?;
        let m = values.len();
        let direction: Vec<f64> = (0..m)
            .map(|k| {
                if values[(k + 1) % m] > values[k] {
                    1.0
                } else {
                    -1.0
                }
            })
            .collect();
        let length: Vec<f64> = (0..m)
            .map(|k| (values[(k + 1) % m] - values[k]).abs())
            .collect();
        let mut rho = Vec::with_capacity(m + 1);
        rho.push(0.0);
        for k in 0..m {
            rho.push(rho[k] + length[k]);
        }
        let mut runs = Vec::with_capacity(m + 1);
        for k in 0..m - 1 {
            runs.push(Run {
                k,
                start: rev[k],
                end: rev[k + 1],
            });
        }
        runs.push(Run {
            k: m - 1,
            start: rev[m - 1],
            end: n,
        });
        if rev[0] > 0 {
            runs.push(Run {
                k: m - 1,
                start: 0,
                end: rev[0],
            });
        }
        let mut offset = vec![0.0; n];
        for r in &runs {
            for i in r.start..r.end {
                offset[i] = (u[i] - values[r.k]).abs();
            }
        }
        Ok(Self {
            family,
            free,
            tp,
            reversals: rev,
            direction,
            length,
            rho,
            runs,
            offset,
            d: vec![0.0; m + 1],
        })
    }

    /// The samples placed on their loop for a model evaluated elsewhere (a model of the zoo,
    /// [`super::zoo`]): the placement and the data starts do not depend on the family, which
    /// only [`Evaluator::evaluate`] reads.
    pub fn placement(u: &[f64], gate: f64) -> Result<Self, FitError> {
        Self::new(Family::LuGre, Vec::new(), u, None, gate)
    }

    /// The samples at the turning points, ascending.
    pub fn reversal_samples(&self) -> &[usize] {
        &self.reversals
    }

    pub fn turning_points(&self) -> &TurningPoints {
        &self.tp
    }

    /// About `target` sample indices, ascending: every `k`-th sample and every turning point
    /// (so that a loop placed on them has the same turning points).
    pub fn thinned(&self, target: usize) -> Vec<usize> {
        let n = self.offset.len();
        let k = n.div_ceil(target.max(1));
        let mut idx: Vec<usize> = (0..n)
            .step_by(k)
            .chain(self.reversals.iter().copied())
            .collect();
        idx.sort_unstable();
        idx.dedup();
        idx
    }

    /// `rho` of every sample (`rho_k + l_i`).
    pub fn sample_rho(&self) -> Vec<f64> {
        let mut out = vec![0.0; self.offset.len()];
        for r in &self.runs {
            let rho_k = self.rho[r.k];
            for (o, l) in out[r.start..r.end]
                .iter_mut()
                .zip(&self.offset[r.start..r.end])
            {
                *o = rho_k + l;
            }
        }
        out
    }

    /// `(sigma0, g0)` of a family parameter vector.
    pub fn rate_independent(family: Family, values: &[f64]) -> (f64, f64) {
        match family {
            Family::LuGre => (values[0], values[4]),
            Family::Dahl => (values[0] * values[1], values[1]),
        }
    }

    /// Start values from the data (module docs): `(sigma0, g0)`.
    pub fn data_start(&self, f: &[f64]) -> Result<(f64, f64), FitError> {
        let f_max = f.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        if f_max == 0.0 {
            return Err(FitError::ZeroForce);
        }
        let l_max = self.length.iter().fold(0.0f64, |m, &l| m.max(l));
        let mut segments: Vec<LongSegment> = Vec::new();
        for k in (0..self.length.len()).filter(|&k| self.length[k] >= 0.5 * l_max) {
            let points: Vec<(f64, f64)> = self
                .runs
                .iter()
                .filter(|r| r.k == k)
                .flat_map(|r| r.start..r.end)
                .map(|i| (self.offset[i], f[i]))
                .collect();
            let s = self.direction[k];
            let near_end = 0.9 * self.length[k];
            let mut ends: Vec<f64> = points
                .iter()
                .filter(|p| p.0 >= near_end)
                .map(|p| s * p.1)
                .collect();
            let count = ends.len() as f64;
            let l_end = points
                .iter()
                .filter(|p| p.0 >= near_end)
                .map(|p| p.0)
                .sum::<f64>()
                / count;
            if let Some(plateau) = median(&mut ends) {
                segments.push(LongSegment {
                    points,
                    s,
                    l_end,
                    plateau,
                });
            }
        }
        let mut plateaus: Vec<f64> = segments.iter().map(|g| g.plateau).collect();
        let mut g0 = match median(&mut plateaus) {
            Some(g) if g > 0.0 => g,
            _ => f_max,
        };
        let mut a = 2.0 / l_max;
        // The plateau is short of g0 where the loop has not saturated: refine the pair a few
        // times, a from the half-rise towards g0, then g0 from the exponential (F1) through
        // the reversal value and the plateau at that a.
        for _ in 0..4 {
            let mut rates: Vec<f64> = segments
                .iter()
                .filter_map(|g| half_rise_rate(&g.points, g.s, g0))
                .collect();
            let Some(rate) = median(&mut rates) else {
                break;
            };
            a = rate;
            let mut corrected: Vec<f64> = segments
                .iter()
                .filter_map(|g| {
                    let e = (-a * g.l_end).exp();
                    // Only where the segment relaxes well past half-way: else the division
                    // amplifies the noise.
                    (e < 0.5).then(|| (g.plateau - g.s * g.points[0].1 * e) / (1.0 - e))
                })
                .collect();
            match median(&mut corrected) {
                Some(g) if g > 0.0 && g.is_finite() => g0 = g,
                _ => break,
            }
        }
        Ok((a * g0, g0))
    }

    /// The loop for a family parameter vector, if it is a valid model.
    pub fn hysteresis_loop(&self, values: &[f64]) -> Option<HysteresisLoop> {
        let (sigma0, g0) = Self::rate_independent(self.family, values);
        let model = RateIndependent::new(sigma0, g0).ok()?;
        HysteresisLoop::new(model, &self.tp).ok()
    }
}

/// `ln 2 / l_half` from the samples `(l, F)` of one segment in order of travel `l` after its
/// reversal (the first at `l = 0`), direction `s`, towards the plateau `s plateau`: `l_half` is
/// where the force first covers half the way from its value at the reversal to the plateau
/// (linear between samples). `None` if the force does not rise towards the plateau.
pub(crate) fn half_rise_rate(points: &[(f64, f64)], s: f64, plateau: f64) -> Option<f64> {
    let (&(l0, f0), rest) = points.split_first()?;
    if l0 != 0.0 || s * f0 >= plateau {
        return None;
    }
    let half = 0.5 * (f0 + s * plateau);
    let (mut l_prev, mut f_prev) = (0.0, f0);
    for &(l, fi) in rest {
        if s * (fi - half) >= 0.0 {
            let l_half = if fi != f_prev {
                l_prev + (half - f_prev) / (fi - f_prev) * (l - l_prev)
            } else {
                l
            };
            return (l_half > 0.0).then(|| std::f64::consts::LN_2 / l_half);
        }
        (l_prev, f_prev) = (l, fi);
    }
    None
}

/// The median (sorts `v`); `None` for an empty slice.
pub(crate) fn median(v: &mut [f64]) -> Option<f64> {
    if v.is_empty() {
        return None;
    }
    v.sort_unstable_by(f64::total_cmp);
    let n = v.len();
    Some(if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    })
}

impl Evaluator for SlowLoop {
    fn evaluate(&mut self, values: &[f64], y: &mut [f64], jac: &mut DMatrix<f64>) -> bool {
        let Some(hl) = self.hysteresis_loop(values) else {
            return false;
        };
        let model = hl.model();
        let (a, g0) = (model.a(), model.g0());
        let yk = hl.turning_y();
        let m = yk.len();
        // (F3) over one period from D_0 = 0, then (F4) and the periodic D_k.
        self.d[0] = 0.0;
        for (k, (&l, (&y, &s))) in self
            .length
            .iter()
            .zip(yk.iter().zip(&self.direction))
            .enumerate()
        {
            let e = (-a * l).exp();
            self.d[k + 1] = self.d[k] * e - l * e * (y - s * g0);
        }
        let d0 = self.d[m] / one_minus_exp(a * self.rho[m]);
        for k in 0..m {
            self.d[k] += d0 * (-a * self.rho[k]).exp();
        }
        // With finite D_k (and |y_k| <= g0, 0 <= l_i <= L_k) every derivative below is finite.
        if !self.d[..m].iter().all(|d| d.is_finite()) {
            return false;
        }
        // (d sigma0 / d p, d g0 / d p) for the loop's two parameters, in the family's order.
        let chain = match self.family {
            // (sigma0, g0) = (sigma0, fs).
            Family::LuGre => [(1.0, 0.0), (0.0, 1.0)],
            // sigma0 = rho fc, g0 = fc.
            Family::Dahl => [(values[1], 0.0), (values[0], 1.0)],
        };
        let slow = self.family.slow_parameters();
        // Column c = ws[c] dy/dsigma0 + wg[c] dy/dg0.
        let mut ws = [0.0; 2];
        let mut wg = [0.0; 2];
        for (c, i) in self.free.iter().enumerate() {
            let which = if *i == slow[0] { 0 } else { 1 };
            (ws[c], wg[c]) = chain[which];
        }
        let p = self.free.len();
        let (inv_g0, a_over_g0) = (1.0 / g0, a / g0);
        let cols = jac.as_mut_slice();
        let n = y.len();
        for r in &self.runs {
            let (yk, dk, s) = (yk[r.k], self.d[r.k], self.direction[r.k]);
            let sg0 = s * g0;
            let gap = yk - sg0;
            for i in r.start..r.end {
                let l = self.offset[i];
                let (e, one_minus_e) = decay(a * l);
                let yi = yk * e + sg0 * one_minus_e;
                let da = (dk - l * gap) * e;
                let d_sigma0 = da * inv_g0;
                let d_g0 = yi * inv_g0 - a_over_g0 * da;
                y[i] = yi;
                for c in 0..p {
                    cols[c * n + i] = ws[c] * d_sigma0 + wg[c] * d_g0;
                }
            }
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reversals_of_sampled_periods() {
        // Two periods of 0 -> 1 -> -1 -> 0 with a plateau at the top.
        let u = [
            0.0, 0.5, 1.0, 1.0, 0.0, -1.0, 0.0, 0.5, 1.0, 0.0, -1.0, -0.5, 0.0,
        ];
        assert_eq!(cyclic_reversals(&u, 0.0), vec![2, 5, 8, 10]);
        // Any gate up to the smallest excursion finds the same (the top's run at its first
        // sample, as without a gate).
        assert_eq!(cyclic_reversals(&u, 0.5), vec![2, 5, 8, 10]);
        // A ramp reverses only where the record closes.
        assert_eq!(cyclic_reversals(&[0.0, 1.0, 2.0], 0.0), vec![0, 2]);
        assert_eq!(cyclic_reversals(&[0.0, 1.0, 2.0], 1.0), vec![0, 2]);
        assert!(cyclic_reversals(&[3.0, 3.0], 0.0).is_empty());
        // A wiggle of 0.1 on the way down is two reversals without a gate, none with 0.2.
        let w = [0.0, 1.0, 0.5, 0.6, 0.2, -1.0, -0.5];
        assert_eq!(cyclic_reversals(&w, 0.0), vec![1, 2, 3, 5]);
        assert_eq!(cyclic_reversals(&w, 0.2), vec![1, 5]);
        let e = SlowLoop::new(Family::LuGre, vec![0, 4], &[0.0, 1.0, 2.0], None, 0.0).unwrap_err();
        assert_eq!(e, FitError::NoReversal { fit: "slow" });
    }

    #[test]
    fn samples_lie_on_the_core_loop_and_derivatives_match_differences() {
        // Example 4's bimodal input, sampled unevenly, starting mid-segment, two periods.
        let mut u = Vec::new();
        for _ in 0..2 {
            for (a, b) in [(0.3, 1.0), (1.0, 0.5), (0.5, 1.5), (1.5, 0.0), (0.0, 0.3)] {
                let steps = 37;
                for j in 0..steps {
                    let x: f64 = j as f64 / steps as f64;
                    u.push(a + (b - a) * x * x.sqrt());
                }
            }
        }
        for family in [Family::LuGre, Family::Dahl] {
            let (values, free) = match family {
                Family::LuGre => (vec![6.0, 1.0, 0.0, 1.0, 2.0, 1.0, 1.0], vec![0, 4]),
                Family::Dahl => (vec![3.0, 2.0], vec![0, 1]),
            };
            let mut sl = SlowLoop::new(family, free.clone(), &u, None, 0.0).unwrap();
            // Both periods' turning points: the same periodic loop.
            assert_eq!(
                sl.turning_points().values(),
                &[1.0, 0.5, 1.5, 0.0, 1.0, 0.5, 1.5, 0.0]
            );
            let n = u.len();
            let mut y = vec![0.0; n];
            let mut jac = DMatrix::zeros(n, 2);
            assert!(sl.evaluate(&values, &mut y, &mut jac));
            let hl = sl.hysteresis_loop(&values).unwrap();
            for (i, rho) in sl.sample_rho().iter().enumerate() {
                let want = hl.y_at(*rho);
                assert!(
                    (y[i] - want).abs() <= lugre_test_support::prec::LOOP * 2.0,
                    "{i}: {} vs {want}",
                    y[i]
                );
                assert!((hl.psi_at(*rho) - u[i]).abs() <= lugre_test_support::prec::FEW_ULPS * 4.0);
            }
            for (c, &i) in free.iter().enumerate() {
                let h = 1e-6 * values[i];
                let (mut up, mut down) = (values.clone(), values.clone());
                up[i] += h;
                down[i] -= h;
                let (mut y_up, mut y_down) = (vec![0.0; n], vec![0.0; n]);
                let mut scratch = DMatrix::zeros(n, 2);
                assert!(sl.evaluate(&up, &mut y_up, &mut scratch));
                assert!(sl.evaluate(&down, &mut y_down, &mut scratch));
                for s in 0..n {
                    let fd = (y_up[s] - y_down[s]) / (2.0 * h);
                    assert!(
                        (jac[(s, c)] - fd).abs() <= 1e-7 * (1.0 + fd.abs()),
                        "{family:?} column {c} sample {s}: {} vs {fd}",
                        jac[(s, c)]
                    );
                }
            }
        }
    }
}
