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
}
