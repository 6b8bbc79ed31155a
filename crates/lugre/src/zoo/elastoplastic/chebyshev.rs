//! Piecewise Chebyshev series built once per model: an adaptive fit of an analytic integrand
//! and its exact integral, for the tables of the elasto-plastic blend
//! ([`super::ElastoPlastic`]).
//!
//! On a piece `[a, b]` with `x = m + h t`, `t in [-1, 1]`, a function is `sum_k c_k T_k(t)`
//! (`c_0` at full weight). The fit interpolates at the `N + 1` Chebyshev points of the first kind;
//! a piece is halved until its last two coefficients are below `TAIL` times the largest, which
//! for an analytic function bounds the error of the piece by about that much (the coefficients
//! of an analytic function fall geometrically). The integral from `x` to the right end of the
//! last piece is another series per piece (`C_1 = c_0 - c_2/2`, `C_k = (c_(k-1) - c_(k+1))/(2k)`),
//! exact for the fitted integrand.

/// Degree of the fitted integrands.
pub(crate) const DEGREE: usize = 16;
/// Coefficients kept per piece: the integral has degree `DEGREE + 1`.
const STRIDE: usize = DEGREE + 2;
/// A piece is accepted when its last two coefficients are below this times its largest: a few
/// times the rounding noise of the interpolation sums (about 17 eps).
const TAIL: f64 = 5e-15;
/// At most this many pieces per table (reached only for parameters at the edge of the domain).
const MAX_PIECES: usize = 4096;

/// A piecewise Chebyshev series on `[breaks[0], breaks[n]]`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Table {
    breaks: Vec<f64>,
    /// Per piece: midpoint and inverse half-width.
    map: Vec<(f64, f64)>,
    coef: Vec<f64>,
}

/// One fitted piece: its interval and coefficients.
struct Piece {
    a: f64,
    b: f64,
    c: [f64; DEGREE + 1],
}

impl Table {
    /// The value at `x` (clamped to the table's interval).
    #[inline]
    pub(crate) fn eval(&self, x: f64) -> f64 {
        let last = self.map.len() - 1;
        let i = self.breaks[1..=last].partition_point(|&b| b <= x);
        let (m, inv) = self.map[i];
        let t = ((x - m) * inv).clamp(-1.0, 1.0);
        clenshaw(&self.coef[i * STRIDE..(i + 1) * STRIDE], t)
    }

    /// The series of `f` on `[lo, hi]`, pieces refined from the initial `breaks`.
    pub(crate) fn fit(f: &dyn Fn(f64) -> f64, breaks: &[f64]) -> Self {
        Self::from_pieces(&adapt(f, breaks), |c, _| {
            let mut out = [0.0; STRIDE];
            out[..=DEGREE].copy_from_slice(c);
            out
        })
    }

    /// `x -> integral of f from x to the right end`, `f` fitted from the initial `breaks`.
    pub(crate) fn integral(f: &dyn Fn(f64) -> f64, breaks: &[f64]) -> Self {
        let pieces = adapt(f, breaks);
        let series: Vec<[f64; STRIDE]> = pieces.iter().map(|p| antiderivative(&p.c)).collect();
        // Accumulated from the right, so that each piece's constant carries only the errors of
        // the pieces to its right.
        let mut right = vec![0.0; pieces.len()];
        let mut acc = 0.0;
        for (k, (p, big)) in pieces.iter().zip(&series).enumerate().rev() {
            right[k] = acc;
            acc += 0.5 * (p.b - p.a) * (clenshaw(big, 1.0) - clenshaw(big, -1.0));
        }
        // On a piece of half-width h: right + h (B(1) - B(t)).
        let mut k = 0;
        Self::from_pieces(&pieces, |_, h| {
            let big = &series[k];
            let mut out = [0.0; STRIDE];
            out[0] = right[k] + h * clenshaw(big, 1.0);
            for j in 1..STRIDE {
                out[j] = -h * big[j];
            }
            k += 1;
            out
        })
    }

    fn from_pieces(
        pieces: &[Piece],
        mut series: impl FnMut(&[f64; DEGREE + 1], f64) -> [f64; STRIDE],
    ) -> Self {
        let mut breaks = Vec::with_capacity(pieces.len() + 1);
        let mut map = Vec::with_capacity(pieces.len());
        let mut coef = Vec::with_capacity(pieces.len() * STRIDE);
        for p in pieces {
            breaks.push(p.a);
            let h = 0.5 * (p.b - p.a);
            map.push((0.5 * (p.a + p.b), 1.0 / h));
            coef.extend_from_slice(&series(&p.c, h));
        }
        breaks.push(pieces.last().map_or(0.0, |p| p.b));
        Self { breaks, map, coef }
    }
}

/// `sum_k c_k T_k(t)`.
#[inline]
fn clenshaw(c: &[f64], t: f64) -> f64 {
    let (mut b1, mut b2) = (0.0, 0.0);
    let t2 = 2.0 * t;
    for &ck in c[1..].iter().rev() {
        (b1, b2) = (ck + t2 * b1 - b2, b1);
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

/// Interpolating coefficients of `f` on `[a, b]` at the Chebyshev points of the first kind.
fn interpolate(f: &dyn Fn(f64) -> f64, a: f64, b: f64) -> [f64; DEGREE + 1] {
    let n = DEGREE + 1;
    let theta = |j: usize| std::f64::consts::PI * (j as f64 + 0.5) / n as f64;
    let values: Vec<f64> = (0..n)
        .map(|j| f(0.5 * (a + b) + 0.5 * (b - a) * theta(j).cos()))
        .collect();
    let mut c = [0.0; DEGREE + 1];
    for (k, ck) in c.iter_mut().enumerate() {
        let sum: f64 = values
            .iter()
            .enumerate()
            .map(|(j, v)| v * (k as f64 * theta(j)).cos())
            .sum();
        *ck = sum * if k == 0 { 1.0 } else { 2.0 } / n as f64;
    }
    c
}

/// Fits `f` on each interval of `breaks`, halving a piece until its tail is small.
fn adapt(f: &dyn Fn(f64) -> f64, breaks: &[f64]) -> Vec<Piece> {
    let mut out = Vec::new();
    // Left to right: a stack of intervals, the leftmost on top.
    let mut todo: Vec<(f64, f64)> = breaks.windows(2).rev().map(|w| (w[0], w[1])).collect();
    while let Some((a, b)) = todo.pop() {
        let c = interpolate(f, a, b);
        let scale = c.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let tail = c[DEGREE].abs().max(c[DEGREE - 1].abs());
        // Rounding of the nodes themselves (relative to |x|, not to the width) bounds what
        // halving can reach: below it the tail is noise.
        let noise = 4.0 * f64::EPSILON * (scale + c[1].abs() * a.abs().max(b.abs()) / (b - a));
        let m = 0.5 * (a + b);
        let splittable = m > a && m < b && out.len() + todo.len() + 2 <= MAX_PIECES;
        if tail <= (TAIL * scale).max(noise) || !splittable {
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
    fn fits_and_integrates_an_analytic_function() {
        let f = |x: f64| 1.0 / (1.0 + 25.0 * x * x);
        let t = Table::fit(&f, &[-1.0, 0.0, 1.0]);
        let i = Table::integral(&f, &[-1.0, 0.0, 1.0]);
        for k in 0..=200 {
            let x = -1.0 + k as f64 / 100.0;
            assert!((t.eval(x) - f(x)).abs() <= 2e-15, "{x}");
            // The integral from x to 1 of 1/(1+25x^2) is (atan(5) - atan(5x))/5.
            let exact = (5.0f64.atan() - (5.0 * x).atan()) / 5.0;
            assert!(
                (i.eval(x) - exact).abs() <= 4e-16,
                "{x}: {} {exact}",
                i.eval(x)
            );
        }
    }
}
