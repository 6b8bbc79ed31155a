//! Piecewise Chebyshev series built once per model: an adaptive fit of `K` analytic functions
//! on shared pieces, or of their integrands and the exact integrals, for the tables of the
//! elasto-plastic blend ([`super::ElastoPlastic`]).
//!
//! On a piece `[a, b]` with `x = m + h t`, `t in [-1, 1]`, a function is `sum_k c_k T_k(t)`
//! (`c_0` at full weight). The fit interpolates at the `N + 1` Chebyshev points of the first kind;
//! a piece is halved until, for every function, its last two coefficients are below `TAIL`
//! times the largest (or below the rounding of the nodes themselves), which for an analytic
//! function bounds the error of the piece by about that much (the coefficients of an analytic
//! function fall geometrically). The integral from `x` to the right end of the last piece is
//! another series per piece (`C_1 = c_0 - c_2/2`, `C_k = (c_(k-1) - c_(k+1))/(2k)`), exact for
//! the fitted integrand.
//!
//! Evaluation splits a series into its even and odd parts, `T_2k(t) = T_k(s)` and
//! `T_(2k+1)(t) = t V_k(s)` with `s = 2t^2 - 1` and `V` the Chebyshev polynomials of the third
//! kind (`V_0 = 1`, `V_1 = 2s - 1`, the same recurrence): two Clenshaw chains of half the length
//! per function, all `2K` independent, so the latency is that of one short chain; each step a
//! fused multiply-add (`mul_add`, one rounding on every CPU: the values do not depend on which
//! CPU ran them).

/// Degree of the fitted functions and integrands.
const DEGREE: usize = 16;
/// Coefficients kept per piece: the integral has degree `DEGREE + 1`.
const STRIDE: usize = DEGREE + 2;
/// A piece is accepted when its last two coefficients are below this times its largest: a few
/// times the rounding noise of the interpolation sums (about 17 eps).
const TAIL: f64 = 5e-15;
/// At most this many pieces per table (reached only for parameters at the edge of the domain).
const MAX_PIECES: usize = 4096;

/// `K` piecewise Chebyshev series on shared pieces of `[breaks[0], breaks[n]]`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Table<const K: usize> {
    breaks: Vec<f64>,
    /// Per piece: midpoint and inverse half-width.
    map: Vec<(f64, f64)>,
    /// Per piece, coefficient `k` of each function.
    coef: Vec<[[f64; K]; STRIDE]>,
}

/// One fitted piece: its interval and each function's coefficients.
struct Piece<const K: usize> {
    a: f64,
    b: f64,
    c: [[f64; DEGREE + 1]; K],
}

impl<const K: usize> Table<K> {
    /// The values at `x` (the end pieces extend past the table's interval).
    #[inline(always)]
    pub(crate) fn eval(&self, x: f64) -> [f64; K] {
        let i = self.piece(x);
        let (m, inv) = self.map[i];
        series(&self.coef[i], (x - m) * inv)
    }

    /// The piece holding `x` (the first or last beyond the ends): a binary search whose steps
    /// depend on the number of pieces only (conditional moves, no mispredicted branches).
    #[inline(always)]
    fn piece(&self, x: f64) -> usize {
        let (mut lo, mut len) = (0, self.map.len());
        while len > 1 {
            let half = len / 2;
            lo = if self.breaks[lo + half] <= x {
                lo + half
            } else {
                lo
            };
            len -= half;
        }
        lo
    }

    /// The series of `f` from the initial `breaks`.
    pub(crate) fn fit(f: &dyn Fn(f64) -> [f64; K], breaks: &[f64]) -> Self {
        let pieces = adapt(f, breaks);
        Self::from_pieces(&pieces, |p, _| {
            let mut out = [[0.0; K]; STRIDE];
            for (j, c) in p.c.iter().enumerate() {
                for (k, ck) in c.iter().enumerate() {
                    out[k][j] = *ck;
                }
            }
            out
        })
    }

    /// `x -> offset + integral of f from x to the right end`, `f` fitted from `breaks`.
    pub(crate) fn integral(f: &dyn Fn(f64) -> [f64; K], breaks: &[f64], offset: [f64; K]) -> Self {
        let pieces = adapt(f, breaks);
        let series: Vec<[[f64; STRIDE]; K]> = pieces
            .iter()
            .map(|p| p.c.map(|c| antiderivative(&c)))
            .collect();
        // Accumulated from the right, so that each piece's constant carries only the errors of
        // the pieces to its right.
        let mut right = vec![offset; pieces.len()];
        let mut acc = offset;
        for (k, (p, big)) in pieces.iter().zip(&series).enumerate().rev() {
            right[k] = acc;
            for (a, b) in acc.iter_mut().zip(big) {
                *a += 0.5 * (p.b - p.a) * (sum(b, 1.0) - sum(b, -1.0));
            }
        }
        // On a piece of half-width h: right + h (B(1) - B(t)).
        let mut k = 0;
        Self::from_pieces(&pieces, |_, h| {
            let mut out = [[0.0; K]; STRIDE];
            for (j, big) in series[k].iter().enumerate() {
                out[0][j] = right[k][j] + h * sum(big, 1.0);
                for (o, b) in out.iter_mut().zip(big).skip(1) {
                    o[j] = -h * b;
                }
            }
            k += 1;
            out
        })
    }

    fn from_pieces(
        pieces: &[Piece<K>],
        mut series: impl FnMut(&Piece<K>, f64) -> [[f64; K]; STRIDE],
    ) -> Self {
        let mut breaks = Vec::with_capacity(pieces.len() + 1);
        let mut map = Vec::with_capacity(pieces.len());
        let mut coef = Vec::with_capacity(pieces.len());
        for p in pieces {
            breaks.push(p.a);
            let h = 0.5 * (p.b - p.a);
            map.push((0.5 * (p.a + p.b), 1.0 / h));
            coef.push(series(p, h));
        }
        breaks.push(pieces.last().map_or(0.0, |p| p.b));
        Self { breaks, map, coef }
    }
}

/// [`clenshaw`] with fused multiply-adds in hardware where the CPU has them. `mul_add` rounds
/// once on every CPU (in software where there is no instruction), so the values are the same
/// bit for bit whichever way runs; the dispatch is this one place.
#[inline(always)]
fn series<const K: usize>(c: &[[f64; K]; STRIDE], t: f64) -> [f64; K] {
    #[cfg(target_arch = "x86_64")]
    {
        if std::arch::is_x86_feature_detected!("fma") {
            // SAFETY: the CPU has the feature the function is compiled for.
            return unsafe { clenshaw_fma(c, t) };
        }
    }
    clenshaw(c, t)
}

/// [`clenshaw`] compiled with the FMA instructions.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
fn clenshaw_fma<const K: usize>(c: &[[f64; K]; STRIDE], t: f64) -> [f64; K] {
    clenshaw(c, t)
}

/// `sum_k c_k T_k(t)` for each of the `K` series, by the even/odd split. Each step is
/// `b_j = 2 s b_(j+1) + (c_j - b_(j+2))`: the bracket does not wait for `b_(j+1)`, so the chain
/// that does is one fused multiply-add per coefficient.
#[inline(always)]
fn clenshaw<const K: usize>(c: &[[f64; K]; STRIDE], t: f64) -> [f64; K] {
    let s = 2.0 * t * t - 1.0;
    let s2 = 2.0 * s;
    let (mut e1, mut e2) = ([0.0f64; K], [0.0; K]);
    let (mut o1, mut o2) = ([0.0f64; K], [0.0; K]);
    // Even coefficients c_0, c_2, ... (T_k(s)); odd c_1, c_3, ... (V_k(s)).
    for j in (1..STRIDE / 2).rev() {
        for k in 0..K {
            (e1[k], e2[k]) = (e1[k].mul_add(s2, c[2 * j][k] - e2[k]), e1[k]);
            (o1[k], o2[k]) = (o1[k].mul_add(s2, c[2 * j + 1][k] - o2[k]), o1[k]);
        }
    }
    let mut out = [0.0; K];
    for k in 0..K {
        let even = e1[k].mul_add(s, c[0][k] - e2[k]);
        let b0 = o1[k].mul_add(s2, c[1][k] - o2[k]);
        out[k] = (b0 - o1[k]).mul_add(t, even);
    }
    out
}

/// `sum_k c_k T_k(t)` by the plain recurrence (for building).
fn sum(c: &[f64], t: f64) -> f64 {
    let (mut b1, mut b2) = (0.0, 0.0);
    for &ck in c[1..].iter().rev() {
        (b1, b2) = (ck + 2.0 * t * b1 - b2, b1);
    }
    c[0] + t * b1 - b2
}

/// Coefficients `C_0 = 0, C_1, ..., C_(N+1)` of an antiderivative in `t`.
fn antiderivative(c: &[f64; DEGREE + 1]) -> [f64; STRIDE] {
    let at = |k: usize| if k <= DEGREE { c[k] } else { 0.0 };
    let mut out = [0.0; STRIDE];
    out[1] = at(0) - 0.5 * at(2);
    for (k, o) in out.iter_mut().enumerate().skip(2) {
        *o = (at(k - 1) - at(k + 1)) / (2.0 * k as f64);
    }
    out
}

/// Interpolating coefficients of each of `f`'s values on `[a, b]` at the Chebyshev points of
/// the first kind.
fn interpolate<const K: usize>(
    f: &dyn Fn(f64) -> [f64; K],
    a: f64,
    b: f64,
) -> [[f64; DEGREE + 1]; K] {
    let n = DEGREE + 1;
    let theta = |j: usize| std::f64::consts::PI * (j as f64 + 0.5) / n as f64;
    let values: Vec<[f64; K]> = (0..n)
        .map(|j| f(0.5 * (a + b) + 0.5 * (b - a) * theta(j).cos()))
        .collect();
    let mut c = [[0.0; DEGREE + 1]; K];
    for (i, ci) in c.iter_mut().enumerate() {
        for (k, ck) in ci.iter_mut().enumerate() {
            let sum: f64 = values
                .iter()
                .enumerate()
                .map(|(j, v)| v[i] * (k as f64 * theta(j)).cos())
                .sum();
            *ck = sum * if k == 0 { 1.0 } else { 2.0 } / n as f64;
        }
    }
    c
}

/// Whether the series `c` on `[a, b]` has converged: its tail below `TAIL` of its scale, or
/// below the rounding of the nodes (relative to `|x|`, not to the width), which halving cannot
/// reduce.
fn converged(c: &[f64; DEGREE + 1], a: f64, b: f64) -> bool {
    let scale = c.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let tail = c[DEGREE].abs().max(c[DEGREE - 1].abs());
    let noise = 4.0 * f64::EPSILON * (scale + c[1].abs() * a.abs().max(b.abs()) / (b - a));
    tail <= (TAIL * scale).max(noise)
}

/// Fits `f` on each interval of `breaks`, halving a piece until every function has converged.
fn adapt<const K: usize>(f: &dyn Fn(f64) -> [f64; K], breaks: &[f64]) -> Vec<Piece<K>> {
    let mut out = Vec::new();
    // Left to right: a stack of intervals, the leftmost on top.
    let mut todo: Vec<(f64, f64)> = breaks.windows(2).rev().map(|w| (w[0], w[1])).collect();
    while let Some((a, b)) = todo.pop() {
        let c = interpolate(f, a, b);
        let m = 0.5 * (a + b);
        let splittable = m > a && m < b && out.len() + todo.len() + 2 <= MAX_PIECES;
        if c.iter().all(|c| converged(c, a, b)) || !splittable {
            out.push(Piece { a, b, c });
        } else {
            todo.push((m, b));
            todo.push((a, m));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fits_and_integrates_analytic_functions() {
        let f = |x: f64| [1.0 / (1.0 + 25.0 * x * x), (3.0 * x).sin()];
        let t = Table::fit(&f, &[-1.0, 0.0, 1.0]);
        let i = Table::integral(&f, &[-1.0, 0.0, 1.0], [0.5, 0.0]);
        for k in 0..=200 {
            let x = -1.0 + k as f64 / 100.0;
            let [a, b] = t.eval(x);
            assert!(
                (a - f(x)[0]).abs() <= 2e-15 && (b - f(x)[1]).abs() <= 2e-15,
                "{x}"
            );
            // The integrals from x to 1: (atan(5) - atan(5x))/5 and (cos(3x) - cos(3))/3.
            let exact = [
                0.5 + (5.0f64.atan() - (5.0 * x).atan()) / 5.0,
                ((3.0 * x).cos() - 3.0f64.cos()) / 3.0,
            ];
            let got = i.eval(x);
            for (g, e) in got.iter().zip(exact) {
                assert!((g - e).abs() <= 1e-15, "{x}: {g} {e}");
            }
        }
    }

    /// The dispatched evaluation and the portable one agree bit for bit (the one rounding of
    /// `mul_add`), on every piece and across it.
    #[test]
    fn the_dispatch_changes_no_bit() {
        let f = |x: f64| [(-x).exp() / (1.0 + x * x), (2.0 * x).cos()];
        let t = Table::integral(&f, &[0.0, 0.5, 3.0], [0.25, -1.0]);
        for k in 0..=3000 {
            let x = 3.0 * f64::from(k) / 3000.0;
            let i = t.piece(x);
            let (m, inv) = t.map[i];
            let u = (x - m) * inv;
            let (fast, portable) = (series(&t.coef[i], u), clenshaw(&t.coef[i], u));
            assert_eq!(fast.map(f64::to_bits), portable.map(f64::to_bits), "{x}");
        }
    }
}
