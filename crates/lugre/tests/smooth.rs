//! The cubic reading of samples of a smooth motion (`lugre::simulate::smooth`) against the
//! independent adaptive solution of the same sine (`Simulator::sine`, L-stable, rtol 1e-12): the
//! output at the samples converges with the sample spacing at the orders the module docs state
//! (linear reading: first order; cubic: second away from reversals).

use lugre::simulate::{SmoothSamples, Tolerance};
use lugre::{Gamma, LuGre, LuGreParams, PiecewiseLinear, Simulator, Sine, Trajectory};

/// A phase that puts no reversal on a sample (at N = 100..800 samples a period).
const PHASE: f64 = 0.3;

/// Worst |y - y_ref| at the samples of one period, relative to max |y_ref|, for N samples:
/// (linear reading, cubic reading away from the samples where the data reverse, cubic reading
/// at those samples and their neighbours).
fn errors(n: usize) -> (f64, f64, f64) {
    // Table I; a 10 um, 20 Hz sine (peak speed 1.26 mm/s: the Stribeck range).
    let model = LuGre::from_params(LuGreParams::canudas_de_wit_1995()).unwrap();
    let (a, period) = (1e-5, 0.05);
    let t: Vec<f64> = (0..=n).map(|k| period * k as f64 / n as f64).collect();
    let x: Vec<f64> = t
        .iter()
        .map(|&t| a * (std::f64::consts::TAU * t / period + PHASE).sin())
        .collect();
    let sim = Simulator::new(&model, Gamma::ONE, 0.0).unwrap();
    let mut reference = Trajectory::default();
    let sine = Sine::new(a, period, PHASE, 0.0).unwrap();
    sim.sine(&sine, 1, &t, Tolerance::new(1e-12).unwrap(), &mut reference)
        .unwrap();
    let scale = reference.y.iter().fold(0.0f64, |m, y| m.max(y.abs()));
    let reversal = |i: usize| i > 0 && i < n && (x[i] - x[i - 1]) * (x[i + 1] - x[i]) <= 0.0;
    // A reversal and its two neighbours (the shape rule limits their slopes too).
    let near = |i: usize| (i.saturating_sub(1)..=i + 1).any(reversal);
    // The last sample closes the period: its value is the next period's first.
    let worst = |y: &[f64], keep: &dyn Fn(usize) -> bool| {
        (0..n)
            .filter(|&i| keep(i))
            .map(|i| (y[i] - reference.y[i]).abs())
            .fold(0.0f64, f64::max)
            / scale
    };
    let mut linear = Trajectory::default();
    let input = PiecewiseLinear::new(t.clone(), x.clone()).unwrap();
    sim.at_knots(&input, 1, &mut linear).unwrap();
    let mut cubic = Trajectory::default();
    let motion = SmoothSamples::pchip(t, x.clone(), 1e-10).unwrap();
    sim.at_samples(&motion, &mut cubic).unwrap();
    (
        worst(&linear.y, &|_| true),
        worst(&cubic.y, &|i| !near(i)),
        worst(&cubic.y, &near),
    )
}

/// Measured (N = 100, 200, 400, 800): linear 2.2e-2, 1.1e-2, 5.5e-3, 2.7e-3 (first order);
/// cubic away from reversals second order (5.4e-4, 1.5e-4, 3.4e-5, 8.6e-6); at a reversal sample,
/// where the shape rule puts the slope 0, and at its neighbours, whose slopes it limits, the
/// velocity is off by up to the distance to the true reversal times the acceleration: first
/// order at most, and below the linear reading's error.
#[test]
fn the_cubic_reading_converges_at_second_order_away_from_reversals() {
    let e: Vec<(f64, f64, f64)> = [100, 200, 400, 800].into_iter().map(errors).collect();
    for w in e.windows(2) {
        let (linear, cubic) = (w[0].0 / w[1].0, w[0].1 / w[1].1);
        assert!((1.6..2.6).contains(&linear), "linear ratio {linear}: {e:?}");
        assert!(cubic > 3.0, "cubic ratio {cubic}: {e:?}");
    }
    for (linear, cubic, at_reversals) in &e {
        assert!(cubic * 20.0 < *linear, "{e:?}");
        assert!(at_reversals < linear, "{e:?}");
    }
}
