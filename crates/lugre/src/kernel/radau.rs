//! The Butcher tableau of the three-stage Radau IIA method (order 5, L-stable, stiffly
//! accurate), shared by the two integrators built on it: the scalar one of
//! [`crate::simulate`] (a linear ODE per step) and the small stiff system of
//! [`crate::dynamics`].

/// Nodes `c = ((4 - sqrt 6) / 10, (4 + sqrt 6) / 10, 1)` (mpmath, 40 digits, rounded).
pub(crate) const C: [f64; 3] = [0.1550510257216822, 0.6449489742783178, 1.0];

/// Coefficients (Hairer & Wanner, Solving ODEs II, Table IV.5.6), e.g.
/// `a11 = (88 - 7 sqrt 6) / 360` (mpmath, 40 digits, rounded). The last row is the weights.
pub(crate) const A: [[f64; 3]; 3] = [
    [
        0.1968154772236604,
        -0.06553542585019839,
        0.02377097434822015,
    ],
    [0.3944243147390873, 0.2920734116652285, -0.04154875212599793],
    [0.37640306270046725, 0.5124858261884216, 0.1111111111111111],
];

/// The eigen-decomposition `A^-1 = T diag(U1, ALPH +- i BETA) T^-1` (in the real block form
/// `[[ALPH, -BETA], [BETA, ALPH]]` for the complex pair) that reduces Newton's `3n x 3n` stage
/// system to one real and one complex `n x n` system (Hairer & Wanner, Solving ODEs II, IV.8,
/// eq. (8.16)-(8.17)). `U1 = 1 / ((6 + 81^(1/3) - 9^(1/3)) / 30)` and `ALPH +- i BETA` the inverse
/// of `(12 - 81^(1/3) + 9^(1/3)) / 60 +- i (81^(1/3) + 9^(1/3)) sqrt 3 / 60` (mpmath, 40 digits,
/// rounded); `T` as published with radau5 (its inverse checked by mpmath and in the tests).
pub(crate) const U1: f64 = 3.637834252744495732;
pub(crate) const ALPH: f64 = 2.681082873627752134;
pub(crate) const BETA: f64 = 3.050430199247410569;
pub(crate) const T: [[f64; 3]; 3] = [
    [
        9.1232394870892942792e-02,
        -0.14125529502095420843,
        -3.0029194105147424492e-02,
    ],
    [
        0.24171793270710701896,
        0.20412935229379993199,
        0.38294211275726193779,
    ],
    [0.96604818261509293619, 1.0, 0.0],
];
pub(crate) const TI: [[f64; 3]; 3] = [
    [
        4.3255798900631553510,
        0.33919925181580986954,
        0.54177053993587487119,
    ],
    [
        -4.1787185915519047273,
        -0.32768282076106238708,
        0.47662355450055045196,
    ],
    [
        -0.50287263494578687595,
        2.5719269498556054292,
        -0.59603920482822492497,
    ],
];

/// The embedded error estimate's weights (Hairer & Wanner IV.8, eq. (8.20), scaled by
/// `1 / gamma0 = U1`): `-(13 + 7 sqrt 6) / 3`, `(-13 + 7 sqrt 6) / 3`, `-1 / 3`.
pub(crate) const DD: [f64; 3] = [-10.04880939982741556, 1.382142733160748896, -1.0 / 3.0];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tableau_is_the_collocation_one() {
        // Row sums are the nodes; the last row is the weights, which integrate 1, t, .., t^4.
        for i in 0..3 {
            let s: f64 = A[i].iter().sum();
            assert!((s - C[i]).abs() < 1e-15, "row {i}: {s}");
        }
        for p in 0..5 {
            let quad: f64 = (0..3).map(|j| A[2][j] * C[j].powi(p)).sum();
            assert!(
                (quad - 1.0 / f64::from(p + 1)).abs() < 1e-15,
                "t^{p}: {quad}"
            );
        }
    }

    #[test]
    fn the_transformation_diagonalises_the_inverse_tableau() {
        // TI A T = diag(1 / U1, [[ALPH, -BETA], [BETA, ALPH]]^-1), i.e. TI A^-1 T is the block
        // form: checked as TI A T times the block form = I.
        let product = |a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]| -> [[f64; 3]; 3] {
            std::array::from_fn(|i| {
                std::array::from_fn(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum())
            })
        };
        let block = [[U1, 0.0, 0.0], [0.0, ALPH, -BETA], [0.0, BETA, ALPH]];
        let identity = product(&product(&product(&TI, &A), &T), &block);
        let t_ti = product(&T, &TI);
        for (i, (row, t_row)) in identity.iter().zip(&t_ti).enumerate() {
            for (j, (&p, &q)) in row.iter().zip(t_row).enumerate() {
                let want = if i == j { 1.0 } else { 0.0 };
                assert!((p - want).abs() < 1e-14, "TI A T block ({i}, {j}): {p}");
                assert!((q - want).abs() < 1e-14, "T TI ({i}, {j}): {q}");
            }
        }
    }
}
