//! Piecewise Chebyshev antiderivatives (the general-`n` representation of
//! [`super::BoucWen`], its equations B9-B11).
//!
//! Two integrands `f = (f_1, f_2)`, smooth on `[a, b]`, are interpolated on panels at the
//! `NODES` Chebyshev points of the first kind (never an end point, where the integrands are
//! 0/0 limits); a panel is halved until the last two coefficients of both are below
//! `tolerance x max(1, max |c_k|)` (the caller's, above the rounding plateau of its
//! integrands). Their antiderivatives `F_i(x) = int_a^x f_i`, one degree higher, follow from
//! the coefficients exactly (`C_k = (c_(k-1) - c_(k+1)) / 2k`); the interpolation error of
//! `f` (about the dropped coefficients) integrates to about `tolerance x (b - a)` in `F`.

/// Chebyshev points per panel.
const NODES: usize = 32;
/// Coefficients of an antiderivative on a panel (one degree more than the integrand).
const TERMS: usize = NODES + 1;
/// Most panels of one table: halving reaches a singularity at distance `d` from the range in
/// about `log2(1 / d)` panels, and `d >= 2^-1030` for the parameters `new` accepts.
pub(super) const MAX_PANELS: usize = 2048;

/// `F_1, F_2` on `[a, b]`, piecewise Chebyshev.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Antiderivatives {
    /// Panel edges, increasing: panel `i` is `[edges[i], edges[i+1]]`.
    edges: Vec<f64>,
    /// Per panel, the coefficients of `F_1` then `F_2` in the panel's variable `s` in [-1, 1],
    /// each including its value at the panel's left edge.
    coef: Vec<[[f64; TERMS]; 2]>,
}

impl Antiderivatives {
    /// `F_i(x) = int_a^x f_i`; `None` when more than [`MAX_PANELS`] panels would be needed.
    pub(super) fn new(f: &dyn Fn(f64) -> [f64; 2], a: f64, b: f64, tolerance: f64) -> Option<Self> {
        let cos = cosines();
        let mut out = Self {
            edges: vec![a],
            coef: Vec::new(),
        };
        // Left-most interval on top, so that panels are accepted from left to right.
        let mut pending = vec![(a, b)];
        let mut start = [0.0, 0.0];
        while let Some((lo, hi)) = pending.pop() {
            let c = [0, 1].map(|i| interpolate(&|x| f(x)[i], lo, hi, &cos));
            if !(converged(&c[0], tolerance) && converged(&c[1], tolerance)) {
                let mid = 0.5 * (lo + hi);
                if out.coef.len() + pending.len() + 2 > MAX_PANELS || mid <= lo || mid >= hi {
                    return None;
                }
                pending.push((mid, hi));
                pending.push((lo, mid));
                continue;
            }
            let panel = [0, 1].map(|i| integrate(&c[i], 0.5 * (hi - lo), start[i]));
            start = [0, 1].map(|i| clenshaw(&panel[i], 1.0));
            out.coef.push(panel);
            out.edges.push(hi);
        }
        Some(out)
    }

    /// `(F_1(x), F_2(x))` for `x` in `[a, b]` (clamped to it): four independent recurrences of half the length.
    #[inline]
    pub(super) fn eval_both(&self, x: f64) -> (f64, f64) {
        let (i, s) = self.locate(x);
        (split(&self.coef[i][0], s), split(&self.coef[i][1], s))
    }

    /// The panel holding `x` and its variable `s` in [-1, 1].
    #[inline]
    fn locate(&self, x: f64) -> (usize, f64) {
        let last = self.coef.len() - 1;
        let i = self.edges[1..=last].partition_point(|&e| e <= x).min(last);
        let (lo, hi) = (self.edges[i], self.edges[i + 1]);
        let s = ((2.0 * x - lo - hi) / (hi - lo)).clamp(-1.0, 1.0);
        (i, s)
    }

    /// Number of panels.
    #[cfg(test)]
    pub(super) fn panels(&self) -> usize {
        self.coef.len()
    }
}

/// `cos(pi k (j + 1/2) / NODES)` for `k, j < NODES`.
fn cosines() -> Vec<[f64; NODES]> {
    (0..NODES)
        .map(|k| {
            std::array::from_fn(|j| {
                (std::f64::consts::PI * k as f64 * (j as f64 + 0.5) / NODES as f64).cos()
            })
        })
        .collect()
}

/// Chebyshev coefficients `c_k` of `f` on `[lo, hi]`: `f = c_0/2 + sum c_k T_k(s)`.
fn interpolate(f: &dyn Fn(f64) -> f64, lo: f64, hi: f64, cos: &[[f64; NODES]]) -> [f64; NODES] {
    let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
    let values: [f64; NODES] = std::array::from_fn(|j| f(mid + half * cos[1][j]));
    std::array::from_fn(|k| {
        let sum: f64 = values.iter().zip(&cos[k]).map(|(v, c)| v * c).sum();
        2.0 * sum / NODES as f64
    })
}

/// The dropped coefficients are negligible: the last two below the tolerance.
fn converged(c: &[f64; NODES], tolerance: f64) -> bool {
    let scale = c.iter().fold(1.0f64, |m, x| m.max(x.abs()));
    c[NODES - 1].abs() + c[NODES - 2].abs() <= tolerance * scale && c.iter().all(|x| x.is_finite())
}

/// Coefficients of `F(s) = start + half int_-1^s f`, `F = sum C_k T_k(s)`.
fn integrate(c: &[f64; NODES], half: f64, start: f64) -> [f64; TERMS] {
    let at = |k: usize| if k < NODES { c[k] } else { 0.0 };
    let mut out = [0.0; TERMS];
    for (k, o) in out.iter_mut().enumerate().skip(1) {
        *o = half * (at(k - 1) - at(k + 1)) / (2 * k) as f64;
    }
    // F(-1) = start: T_k(-1) = (-1)^k.
    let at_left: f64 = out
        .iter()
        .enumerate()
        .skip(1)
        .map(|(k, x)| if k % 2 == 0 { *x } else { -x })
        .sum();
    out[0] = start - at_left;
    out
}

/// `sum C_k T_k(t)` split into its even and odd parts (as the elasto-plastic model's tables,
/// `zoo/elastoplastic/chebyshev.rs`): `T_2k(t) = T_k(s)`, `T_(2k+1)(t) = t V_k(s)`,
/// `s = 2t² - 1`, `V` the Chebyshev polynomials of the third kind (`V_0 = 1`, `V_1 = 2s - 1`,
/// the same recurrence). Two independent recurrences of half the length: half the latency of
/// [`clenshaw`], the same rounding class.
#[inline(always)]
fn split(c: &[f64; TERMS], t: f64) -> f64 {
    let s = 2.0 * t * t - 1.0;
    let s2 = 2.0 * s;
    let (mut e1, mut e2, mut o1, mut o2) = (0.0, 0.0, 0.0, 0.0);
    // TERMS = 33: even c_0..c_32 (T_0..T_16 of s), odd c_1..c_31 (V_0..V_15 of s).
    for j in (1..=(TERMS - 1) / 2).rev() {
        (e1, e2) = (c[2 * j] + s2 * e1 - e2, e1);
        if 2 * j + 1 < TERMS {
            (o1, o2) = (c[2 * j + 1] + s2 * o1 - o2, o1);
        }
    }
    let even = c[0] + s * e1 - e2;
    let odd = c[1] + s2 * o1 - o2 - o1;
    even + t * odd
}

/// `sum C_k T_k(s)` by Clenshaw's recurrence.
#[inline]
fn clenshaw(c: &[f64; TERMS], s: f64) -> f64 {
    let (mut b1, mut b2) = (0.0, 0.0);
    for &ck in c[1..].iter().rev() {
        (b1, b2) = (ck + 2.0 * s * b1 - b2, b1);
    }
    c[0] + s * b1 - b2
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integrates_smooth_functions_to_rounding() {
        let t = Antiderivatives::new(&|x| [x.cos(), 1.0 / (1.0 + x * x)], 0.0, 3.0, 1e-15).unwrap();
        for x in [0.0, 0.3, 1.7, 2.999, 3.0] {
            let (a, b) = t.eval_both(x);
            assert!((a - x.sin()).abs() < 1e-15, "{a} vs {}", x.sin());
            assert!((b - x.atan()).abs() < 1e-15, "{b} vs {}", x.atan());
        }
    }

    #[test]
    fn grades_toward_a_nearby_singularity() {
        // 1 / (x + 1e-6) on [0, 1]: log(1 + 1e6 x) needs panels down to ~1e-6.
        let t = Antiderivatives::new(&|x| [1.0 / (x + 1e-6), 0.0], 0.0, 1.0, 1e-15).unwrap();
        assert!(t.panels() > 10 && t.panels() < 200, "{}", t.panels());
        for x in [1e-7, 1e-3, 0.5, 1.0] {
            let want = (x * 1e6f64).ln_1p();
            assert!((t.eval_both(x).0 - want).abs() < 1e-13 * want.max(1.0));
        }
    }
}
