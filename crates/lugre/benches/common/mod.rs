//! Inputs shared by the loop benches.

use lugre::TurningPoints;

/// Alternating random steps in [0.01, 1) times `scale`: every point is a reversal. A fixed LCG
/// keeps runs comparable.
pub fn random_turning_points(n: usize, scale: f64) -> TurningPoints {
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut u = 0.0;
    let values: Vec<f64> = (0..n)
        .map(|i| {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            let r = (state >> 11) as f64 / (1u64 << 53) as f64;
            let step = scale * (0.01 + 0.99 * r);
            u += if i % 2 == 0 { step } else { -step };
            u
        })
        .collect();
    TurningPoints::new(&values).expect("valid input")
}
