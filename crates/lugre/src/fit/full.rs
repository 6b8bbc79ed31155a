//! The full fit: every LuGre parameter from rate-dependent `(t, u, F)` data, on the exact
//! simulation of eq. 1 for the input linear between samples ([`crate::simulate::exact`]).
//!
//! Sample `i` is output just after its knot, on the segment to the next sample (the last one on
//! the segment the simulator uses at the end), with slope `v = du / dt` there:
//!
//! ```text
//! g = Fc + (Fs - Fc) E        E = exp(-r^beta),  r = |v| / vs
//! k = sigma0 |v| / g          c = sigma0 |du| / g           z_inf = sign(du) g / sigma0
//! y_i = sigma0 z_i + sigma1 (v - k z_i) + sigma2 v                                      (X1)
//! z_{i+1} = z_i e + z_inf (1 - e)                 e = exp(-c)                             (X2)
//! ```
//!
//! The derivatives are exact (forward sensitivities of the recursion, the same cost per
//! parameter as a few multiplications): for a parameter `p` let `q_p = [p = sigma0] / sigma0 -
//! (dg/dp) / g`, so that `dk/dp = k q_p`, `dc/dp = c q_p`, `dz_inf/dp = -z_inf q_p`; with
//! `Z = dz/dp`,
//!
//! ```text
//! Z_{i+1} = Z_i e + q_p [(z_inf - z_i) e c - z_inf (1 - e)]                              (X3)
//! dy_i/dp = [p = sigma0] z_i + [p = sigma1] (v - k z_i) + [p = sigma2] v
//!           + (sigma0 - sigma1 k) Z_i - sigma1 k q_p z_i                                  (X4)
//! dg/dFc = 1 - E   dg/dFs = E   dg/dvs = (Fs - Fc) E beta r^beta / vs   dg/dbeta = -(Fs - Fc) E r^beta ln r
//! ```
//!
//! A record read as the samples of a smooth motion (a smoothed record, [`super::noise`]) is
//! output at each inner sample with its own velocity, the central difference, rather than the
//! next segment's: the segment's slope is the velocity half a step later, an `O(h)` error of
//! the output (`sigma1 h a / 2`, 0.04 N on the servo axis at 1 kHz, which biases
//! `sigma0` and `Fs` by 0.1 %), the central one an `O(h^2)` error; `z` keeps the recursion (X2),
//! whose error on a smooth motion is `O(h^2)` already. With `v_i = (u_{i+1} - u_{i-1}) /
//! (t_{i+1} - t_{i-1})` and `g_i, k_i, q_p` formed from it,
//!
//! ```text
//! y_i = sigma0 z_i + sigma1 (v_i - k_i z_i) + sigma2 v_i                                (X5)
//! ```
//!
//! and (X4) with `v_i, k_i` and the output's `q_p`.
//!
//! `z` depends neither on `sigma1` nor on `sigma2` (`Z = 0` for them), and the initial state
//! `x0` is given, not fitted. The Dahl model maps to LuGre with `sigma0 = rho Fc`, `g = Fc`:
//! `dy/drho = Fc dy/dsigma0`, `dy/dFc = rho dy/dsigma0 + dy/dFc + dy/dFs` (LuGre's).
//!
//! Start values from the data. The record is cut at its reversals into segments; on each, the
//! force plateau (median of `s F` over the last 10 % of the travel) and the half-rise rate `a`
//! (as in the slow fit) give `sigma0 = median(a * plateau)`. The samples in the second half of
//! each segment are taken as steady sliding, `s F = g(v) + sigma2 |v|`: a straight line through
//! the faster half of them gives `Fc`, the slowest tenth `Fs`, and `vs` is the speed at which
//! `(s F - sigma2 |v| - Fc) / (Fs - Fc)` falls below `1/e` (medians of 16 speed classes). Then
//! `sigma1` and `sigma2`, on which the output depends linearly (X1), come from linear least
//! squares given the others. Further starts multiply the start `sigma0` and `vs` by 4 or 1/4
//! (re-solving `sigma1`, `sigma2`); the best end point wins.

use super::lm::Evaluator;
use super::slow::{half_rise_rate, median};
use super::spec::{index_of, lugre_params, Family, Resolved};
use crate::kernel::relax::decay;
use crate::model::{LuGre, Parameter};
use nalgebra::DMatrix;

/// The data as the simulator sees it, and which derivatives to form.
#[derive(Debug, Clone)]
pub(crate) struct Exact {
    family: Family,
    free: Vec<usize>,
    /// `u_{i+1} - u_i` and `v_i = du_i / dt_i` of segment `i`.
    du: Vec<f64>,
    v: Vec<f64>,
    /// The segment whose slope the last sample is output with.
    end_segment: usize,
    x0: f64,
    /// The velocity each sample is output with (X5), if not its segment's.
    v_out: Option<Vec<f64>>,
}

impl Exact {
    /// `t` strictly increasing, all finite, at least 2 samples (checked by the caller).
    pub fn new(family: Family, free: Vec<usize>, t: &[f64], u: &[f64], x0: f64) -> Self {
        let n = u.len();
        let du: Vec<f64> = (0..n - 1).map(|i| u[i + 1] - u[i]).collect();
        let v: Vec<f64> = (0..n - 1).map(|i| du[i] / (t[i + 1] - t[i])).collect();
        // As `Simulator::at_knots`: a record that ends where it starts is periodic, and its end
        // is the next period's first kink.
        let end_segment = if u[0] == u[n - 1] { 0 } else { n - 2 };
        Self {
            family,
            free,
            du,
            v,
            end_segment,
            x0,
            v_out: None,
        }
    }

    /// Outputs every inner sample with the central velocity `(u_{i+1} - u_{i-1}) / (t_{i+1} -
    /// t_{i-1})` (X5): for samples of a smooth motion (a smoothed record).
    pub fn with_central_output(mut self, t: &[f64], u: &[f64]) -> Self {
        let n = u.len();
        let v = (0..n)
            .map(|i| {
                if i == 0 || i + 1 == n {
                    self.v[self.segment_of(i)]
                } else {
                    (u[i + 1] - u[i - 1]) / (t[i + 1] - t[i - 1])
                }
            })
            .collect();
        self.v_out = Some(v);
        self
    }

    /// The same data with another set of free parameters.
    pub fn with_free(&self, free: Vec<usize>) -> Self {
        Self {
            free,
            ..self.clone()
        }
    }

    /// `|v|` of the segment sample `i` is output on.
    pub fn speed(&self, i: usize) -> f64 {
        self.v[self.segment_of(i)].abs()
    }

    fn segment_of(&self, i: usize) -> usize {
        if i < self.v.len() {
            i
        } else {
            self.end_segment
        }
    }

    /// For each output column: the LuGre parameters it sums, with weights.
    fn columns(&self, values: &[f64]) -> Vec<Vec<(usize, f64)>> {
        self.free
            .iter()
            .map(|&i| match (self.family, i) {
                (Family::LuGre, i) => vec![(i, 1.0)],
                // sigma0 = rho Fc, Fs = Fc (Dahl::lugre_params).
                (Family::Dahl, RHO) => vec![(SIGMA0, values[DAHL_FC])],
                (Family::Dahl, _) => vec![(SIGMA0, values[RHO]), (FC, 1.0), (FS, 1.0)],
            })
            .collect()
    }
}

/// An evaluator whose outputs are those of `inner` at the measured `rows` only (the rows where
/// a force was measured; the others still drive the simulation).
pub(crate) struct Rows<E> {
    pub(crate) inner: E,
    rows: Vec<usize>,
    y: Vec<f64>,
    jac: DMatrix<f64>,
    /// All rows measured: `inner` is used as it is.
    all: bool,
}

impl<E> Rows<E> {
    pub(crate) fn new(inner: E, rows: Vec<usize>, n: usize) -> Self {
        let all = rows.len() == n;
        Self {
            inner,
            rows,
            y: vec![0.0; n],
            jac: DMatrix::zeros(0, 0),
            all,
        }
    }
}

impl Rows<Exact> {
    /// The same rows with another set of free parameters.
    pub(crate) fn with_free(&self, free: Vec<usize>) -> Self {
        Self::new(self.inner.with_free(free), self.rows.clone(), self.y.len())
    }
}

impl<E: Evaluator> Evaluator for Rows<E> {
    fn evaluate(&mut self, values: &[f64], y: &mut [f64], jac: &mut DMatrix<f64>) -> bool {
        if self.all {
            return self.inner.evaluate(values, y, jac);
        }
        if self.jac.shape() != (self.y.len(), jac.ncols()) {
            self.jac = DMatrix::zeros(self.y.len(), jac.ncols());
        }
        if !self.inner.evaluate(values, &mut self.y, &mut self.jac) {
            return false;
        }
        for (k, &i) in self.rows.iter().enumerate() {
            y[k] = self.y[i];
            for c in 0..jac.ncols() {
                jac[(k, c)] = self.jac[(i, c)];
            }
        }
        true
    }
}

/// The parameters [`Exact::evaluate`] has derivatives for (the Dahl model's through its LuGre
/// form, [`Exact::columns`]). Any other parameter of the table is held by a full fit at its
/// value: a parameter added to the table is fitted once its derivative is written here.
const DIFFERENTIATED: [Parameter; 8] = [
    Parameter::Sigma0,
    Parameter::Sigma1,
    Parameter::Sigma2,
    Parameter::Fc,
    Parameter::Fs,
    Parameter::Vs,
    Parameter::Beta,
    Parameter::Rho,
];

/// Whether a full fit can fit `p` ([`DIFFERENTIATED`]).
pub(crate) fn differentiates(p: Parameter) -> bool {
    DIFFERENTIATED.contains(&p)
}

/// The LuGre parameters' places in a LuGre parameter vector, from the table.
const SIGMA0: usize = index_of(&Parameter::LUGRE, Parameter::Sigma0);
const FC: usize = index_of(&Parameter::LUGRE, Parameter::Fc);
const FS: usize = index_of(&Parameter::LUGRE, Parameter::Fs);
/// The Dahl parameters' places in a Dahl parameter vector.
const RHO: usize = index_of(&Parameter::DAHL, Parameter::Rho);
const DAHL_FC: usize = index_of(&Parameter::DAHL, Parameter::Fc);

/// The number of LuGre parameters: the length of the derivatives' arrays.
const N: usize = Parameter::LUGRE.len();

impl Evaluator for Exact {
    fn evaluate(&mut self, values: &[f64], y: &mut [f64], jac: &mut DMatrix<f64>) -> bool {
        let p = lugre_params(self.family, values);
        if LuGre::from_params(p).is_err() || !(p.sigma0 * self.x0).is_finite() {
            return false;
        }
        let columns = self.columns(values);
        let mut needed = [false; N];
        for &(j, _) in columns.iter().flatten() {
            needed[j] = true;
        }
        let needed: Vec<usize> = (0..N).filter(|&j| needed[j]).collect();
        let n = y.len();
        let cols = jac.as_mut_slice();
        let (sigma0, sigma1, sigma2) = (p.sigma0, p.sigma1, p.sigma2);
        let (fc, fs, vs, beta) = (p.fc, p.fs, p.vs, p.beta);
        let drop = fs - fc;
        let mut z = self.x0;
        let mut zs = [0.0f64; N];
        let mut q = [0.0f64; N];
        let mut dy = [0.0f64; N];
        // NaN once a derivative is not finite (`x * 0`): no branch in the loop.
        let mut bad = 0.0;
        let curve = |v: f64, q: &mut [f64; N]| -> f64 {
            // The simulator's operations (`Stribeck::eval`, `Simulator::segment`); the
            // reported fitted curve is the simulator's own, equal to a few roundings.
            let r = (v / vs).abs();
            let rb = if beta == 1.0 {
                r
            } else if beta == 2.0 {
                r * r
            } else {
                r.powf(beta)
            };
            let big_e = (-rb).exp();
            let g = fc + drop * big_e;
            let inv_g = 1.0 / g;
            for &j in &needed {
                q[j] = match Parameter::LUGRE[j] {
                    Parameter::Sigma0 => 1.0 / sigma0,
                    Parameter::Fc => -(1.0 - big_e) * inv_g,
                    Parameter::Fs => -big_e * inv_g,
                    Parameter::Vs => -drop * big_e * beta * rb / vs * inv_g,
                    // r^beta ln r -> 0 as r -> 0.
                    Parameter::Beta if r > 0.0 => drop * big_e * rb * r.ln() * inv_g,
                    _ => 0.0,
                };
            }
            g
        };
        let mut q_out = [0.0f64; N];
        for i in 0..n {
            let seg = self.segment_of(i);
            let (v, du) = (self.v[seg], self.du[seg]);
            let g = curve(v, &mut q);
            let sigma0_over_g = sigma0 / g;
            let c = sigma0_over_g * du.abs();
            let z_inf = (g / sigma0).copysign(du);
            // (X1) at the segment's velocity, or (X5) at the sample's own.
            let (v_o, k_o, q_o) = match &self.v_out {
                Some(vo) => {
                    let g_o = curve(vo[i], &mut q_out);
                    (vo[i], sigma0 / g_o * vo[i].abs(), &q_out)
                }
                None => (v, sigma0_over_g * v.abs(), &q),
            };
            let dz = v_o - k_o * z;
            y[i] = sigma0 * z + sigma1 * dz + sigma2 * v_o;
            let damp = sigma0 - sigma1 * k_o;
            let s1kz = sigma1 * k_o * z;
            for &j in &needed {
                dy[j] = match Parameter::LUGRE[j] {
                    Parameter::Sigma1 => dz,
                    Parameter::Sigma2 => v_o,
                    p => {
                        damp * zs[j] - s1kz * q_o[j] + if p == Parameter::Sigma0 { z } else { 0.0 }
                    }
                };
            }
            for (c_idx, col) in columns.iter().enumerate() {
                let d: f64 = col.iter().map(|&(j, w)| w * dy[j]).sum();
                bad += d * 0.0;
                cols[c_idx * n + i] = d;
            }
            if i + 1 < n {
                let (e, one_minus_e) = decay(c);
                let w = (z_inf - z) * e * c - z_inf * one_minus_e;
                for &j in &needed {
                    zs[j] = zs[j] * e + q[j] * w;
                }
                z = z * e + z_inf * one_minus_e;
            }
        }
        bad == 0.0
    }
}

/// The record cut at its reversals: `(start, end)` sample indices of each monotone segment
/// (consecutive segments share their reversal sample).
pub(crate) fn segments(u: &[f64]) -> Vec<(usize, usize)> {
    let n = u.len();
    let mut bounds = vec![0];
    let mut run_start = 0;
    let mut last_dir = 0.0;
    for i in 0..n - 1 {
        let d = u[i + 1] - u[i];
        if d == 0.0 {
            continue;
        }
        let dir = d.signum();
        if last_dir != 0.0 && dir != last_dir {
            bounds.push(run_start);
        }
        last_dir = dir;
        run_start = i + 1;
    }
    bounds.push(n - 1);
    bounds.windows(2).map(|w| (w[0], w[1])).collect()
}

/// Whether the record reverses at a sample strictly inside it.
pub(crate) fn has_reversal(u: &[f64]) -> bool {
    segments(u).len() > 1
}

/// Start values of every LuGre (or Dahl) parameter from the data (module docs), before the
/// linear solve for `sigma1`, `sigma2`. `current` supplies `beta` (and anything not estimated),
/// one value per LuGre parameter.
pub(crate) fn data_start(
    family: Family,
    ex: &Exact,
    u: &[f64],
    f: &[f64],
    current: &[f64],
) -> Vec<f64> {
    let f_rms = (f.iter().map(|v| v * v).sum::<f64>() / f.len() as f64).sqrt();
    let f_scale = if f_rms > 0.0 { f_rms } else { 1.0 };
    let segs = segments(u);
    let mut plateaus = Vec::new();
    let mut stiffness = Vec::new();
    let mut steady: Vec<(f64, f64)> = Vec::new();
    let mut l_max = 0.0f64;
    for &(a, b) in &segs {
        let s = (u[b] - u[a]).signum();
        let len = (u[b] - u[a]).abs();
        if len == 0.0 {
            continue;
        }
        l_max = l_max.max(len);
        let mut ends: Vec<f64> = (a..=b)
            .filter(|&i| (u[i] - u[a]).abs() >= 0.9 * len)
            .map(|i| s * f[i])
            .collect();
        let Some(plateau) = median(&mut ends).filter(|p| *p > 0.0) else {
            continue;
        };
        plateaus.push(plateau);
        let points: Vec<(f64, f64)> = (a..=b).map(|i| ((u[i] - u[a]).abs(), f[i])).collect();
        if let Some(rate) = half_rise_rate(&points, s, plateau) {
            stiffness.push(rate * plateau);
        }
        for i in a..b {
            if (u[i] - u[a]).abs() >= 0.5 * len {
                steady.push((ex.speed(i), s * f[i]));
            }
        }
    }
    let plateau = median(&mut plateaus).unwrap_or(f_scale);
    let sigma0 = median(&mut stiffness).unwrap_or(2.0 * plateau / l_max.max(f64::MIN_POSITIVE));
    if family == Family::Dahl {
        return vec![sigma0 / plateau, plateau];
    }
    steady.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
    let m = steady.len();
    // Fc and sigma2: a line through the faster half.
    let fast = &steady[m / 2..];
    let (mut fc, mut sigma2) = (plateau, 0.0);
    if fast.len() >= 2 {
        let nf = fast.len() as f64;
        let mv = fast.iter().map(|p| p.0).sum::<f64>() / nf;
        let mf = fast.iter().map(|p| p.1).sum::<f64>() / nf;
        let sxx: f64 = fast.iter().map(|p| (p.0 - mv).powi(2)).sum();
        let sxy: f64 = fast.iter().map(|p| (p.0 - mv) * (p.1 - mf)).sum();
        if sxx > 0.0 && sxy > 0.0 {
            sigma2 = sxy / sxx;
            fc = mf - sigma2 * mv;
        } else {
            fc = mf;
        }
        if !positive(fc) {
            fc = mf.max(plateau * 0.5);
            sigma2 = 0.0;
        }
    }
    let v_max = steady.last().map_or(1.0, |p| p.0).max(f64::MIN_POSITIVE);
    if !positive(sigma2) {
        // An effect of 1 % of the force at the highest speed.
        sigma2 = 0.01 * f_scale / v_max;
    }
    let mut slow_end: Vec<f64> = steady[..(m / 10).max(1).min(m)]
        .iter()
        .map(|p| p.1 - sigma2 * p.0)
        .collect();
    let mut fs = median(&mut slow_end).unwrap_or(plateau);
    if !positive(fs) {
        fs = plateau;
    }
    if (fs - fc).abs() < 1e-3 * fc {
        // No visible Stribeck effect: a start with one, so that vs has something to act on.
        fs = 1.1 * fc;
    }
    let v_min = steady.first().map_or(1.0, |p| p.0).max(f64::MIN_POSITIVE);
    let mut vs = (v_min * v_max).sqrt();
    const CLASSES: usize = 16;
    if m >= CLASSES {
        let mut prev: Option<(f64, f64)> = None;
        for c in 0..CLASSES {
            let part = &steady[c * m / CLASSES..(c + 1) * m / CLASSES];
            let mut sp: Vec<f64> = part.iter().map(|p| p.0).collect();
            let mut h: Vec<f64> = part
                .iter()
                .map(|p| (p.1 - sigma2 * p.0 - fc) / (fs - fc))
                .collect();
            let (Some(speed), Some(h)) = (median(&mut sp), median(&mut h)) else {
                continue;
            };
            if h < (-1.0f64).exp() {
                vs = match prev {
                    Some((s0, h0)) if h0 > h && s0 > 0.0 && speed > 0.0 => {
                        let x = (h0 - (-1.0f64).exp()) / (h0 - h);
                        (s0.ln() + x * (speed.ln() - s0.ln())).exp()
                    }
                    _ => speed.max(f64::MIN_POSITIVE),
                };
                break;
            }
            prev = Some((speed, h));
        }
    }
    let dz_scale = v_max;
    // The estimated parameters; the others (`beta`) keep their current values.
    let mut start = current.to_vec();
    for (p, v) in [
        (Parameter::Sigma0, sigma0),
        (Parameter::Sigma1, 0.01 * f_scale / dz_scale),
        (Parameter::Sigma2, sigma2),
        (Parameter::Fc, fc),
        (Parameter::Fs, fs),
        (Parameter::Vs, vs),
    ] {
        if let Some(i) = Parameter::LUGRE.iter().position(|&q| q == p) {
            start[i] = v;
        }
    }
    start
}

/// `x > 0` (false for NaN).
fn positive(x: f64) -> bool {
    x > 0.0
}

/// `sigma1` and `sigma2` (where free and without a given start) by linear least squares given
/// the other values, on which they enter (X1) linearly; a value that comes out `<= 0` is set
/// to an effect of 1 % of the force.
pub(crate) fn solve_linear(ex: &Rows<Exact>, resolved: &Resolved, values: &mut [f64], f: &[f64]) {
    let solve: Vec<usize> = [1usize, 2]
        .into_iter()
        .filter(|i| {
            resolved
                .free
                .iter()
                .position(|j| j == i)
                .is_some_and(|c| !resolved.given[c])
        })
        .collect();
    if resolved.family != Family::LuGre || solve.is_empty() {
        return;
    }
    let n = f.len();
    let mut probe = ex.with_free(solve.clone());
    let mut at = values.to_vec();
    for &i in &solve {
        at[i] = 0.0;
    }
    let mut y = vec![0.0; n];
    let mut jac = DMatrix::zeros(n, solve.len());
    if !probe.evaluate(&at, &mut y, &mut jac) {
        return;
    }
    let r: Vec<f64> = f.iter().zip(&y).map(|(f, y)| f - y).collect();
    let k = solve.len();
    let mut a = [[0.0; 2]; 2];
    let mut b = [0.0; 2];
    for c in 0..k {
        let cc = jac.column(c);
        b[c] = cc.iter().zip(&r).map(|(x, r)| x * r).sum();
        for (d, entry) in a[c].iter_mut().enumerate().take(k) {
            *entry = cc
                .iter()
                .zip(jac.column(d).iter())
                .map(|(x, y)| x * y)
                .sum();
        }
    }
    let x = if k == 1 {
        [b[0] / a[0][0], 0.0]
    } else {
        let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
        [
            (b[0] * a[1][1] - b[1] * a[0][1]) / det,
            (a[0][0] * b[1] - a[1][0] * b[0]) / det,
        ]
    };
    let f_rms = (f.iter().map(|v| v * v).sum::<f64>() / n as f64).sqrt();
    for (c, &i) in solve.iter().enumerate() {
        let col_rms = (a[c][c] / n as f64).sqrt();
        let fallback = if col_rms > 0.0 {
            0.01 * f_rms / col_rms
        } else {
            1.0
        };
        let v = if x[c].is_finite() && x[c] > 0.0 {
            x[c]
        } else {
            fallback
        };
        let slot = resolved.free.iter().position(|&j| j == i).unwrap_or(0);
        values[i] = resolved.bounds[slot].pull_inside(v);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Gamma, PiecewiseLinear, Simulator, Trajectory};

    fn record() -> (Vec<f64>, Vec<f64>) {
        // Uneven times, three speeds, a reversal mid-way, not closed.
        let mut t = vec![0.0];
        let mut u = vec![0.0];
        for (steps, du, dt) in [(40, 0.05, 0.1), (30, -0.08, 0.02), (50, 0.06, 0.3)] {
            for _ in 0..steps {
                let last = t.len() - 1;
                t.push(t[last] + dt * (1.0 + 0.3 * ((t.len() as f64) * 0.7).sin()));
                u.push(u[last] + du);
            }
        }
        (t, u)
    }

    #[test]
    fn output_is_the_simulators_and_derivatives_match_differences() {
        let (t, u) = record();
        let n = u.len();
        // The values by name (any other parameter of the table at its default).
        let lugre = |beta: f64| -> Vec<f64> {
            Parameter::LUGRE
                .map(|p| match p {
                    Parameter::Sigma0 => 3.0,
                    Parameter::Sigma1 => 0.7,
                    Parameter::Sigma2 => 0.2,
                    Parameter::Fc => 1.0,
                    Parameter::Fs => 1.8,
                    Parameter::Vs => 0.4,
                    Parameter::Beta => beta,
                    p => p.default_value(),
                })
                .to_vec()
        };
        let dahl = Parameter::DAHL
            .map(|p| if p == Parameter::Rho { 2.0 } else { 0.9 })
            .to_vec();
        for (family, values, table) in [
            (Family::LuGre, lugre(1.0), &Parameter::LUGRE[..]),
            (Family::LuGre, lugre(2.0), &Parameter::LUGRE[..]),
            (Family::LuGre, lugre(1.3), &Parameter::LUGRE[..]),
            (Family::Dahl, dahl, &Parameter::DAHL[..]),
        ] {
            // Every parameter the fit has a derivative for.
            let free: Vec<usize> = (0..values.len())
                .filter(|&i| differentiates(table[i]))
                .collect();
            let mut ex = Exact::new(family, free.clone(), &t, &u, 0.1);
            let mut y = vec![0.0; n];
            let mut jac = DMatrix::zeros(n, free.len());
            assert!(ex.evaluate(&values, &mut y, &mut jac));
            let model = LuGre::from_params(lugre_params(family, &values)).unwrap();
            let input = PiecewiseLinear::new(t.clone(), u.clone()).unwrap();
            let mut out = Trajectory::default();
            Simulator::new(&model, Gamma::ONE, 0.1)
                .unwrap()
                .at_knots(&input, 1, &mut out)
                .unwrap();
            let g0 = model.g0();
            for (a, b) in y.iter().zip(&out.y) {
                assert!(
                    (a - b).abs() <= lugre_test_support::prec::EXACT_SIMULATION * g0,
                    "{family:?} {values:?}: {a} vs {b}"
                );
            }
            check_derivatives(&mut ex, &values, &jac);
            // (X5): the output at each sample's central velocity.
            let mut central = ex.clone().with_central_output(&t, &u);
            assert!(central.evaluate(&values, &mut y, &mut jac));
            check_derivatives(&mut central, &values, &jac);
        }
    }

    /// The columns of `jac` against central differences of the output.
    fn check_derivatives(ex: &mut Exact, values: &[f64], jac: &DMatrix<f64>) {
        let (n, p) = jac.shape();
        for (c, &i) in ex.free.clone().iter().enumerate() {
            let h = 1e-6 * values[i];
            let (mut up, mut down) = (values.to_vec(), values.to_vec());
            up[i] += h;
            down[i] -= h;
            let (mut y_up, mut y_down) = (vec![0.0; n], vec![0.0; n]);
            let mut scratch = DMatrix::zeros(n, p);
            assert!(ex.evaluate(&up, &mut y_up, &mut scratch));
            assert!(ex.evaluate(&down, &mut y_down, &mut scratch));
            for s in 0..n {
                let fd = (y_up[s] - y_down[s]) / (2.0 * h);
                assert!(
                    (jac[(s, c)] - fd).abs() <= 1e-6 * (1.0 + fd.abs()),
                    "{:?} parameter {i} sample {s}: {} vs {fd}",
                    ex.family,
                    jac[(s, c)]
                );
            }
        }
    }

    #[test]
    fn reversals_of_a_record() {
        assert_eq!(
            segments(&[0.0, 1.0, 1.0, 0.5, 0.7, 0.7]),
            vec![(0, 1), (1, 3), (3, 5)]
        );
        assert!(!has_reversal(&[0.0, 1.0, 1.0, 2.0]));
        assert!(has_reversal(&[0.0, 1.0, 0.5]));
    }
}
