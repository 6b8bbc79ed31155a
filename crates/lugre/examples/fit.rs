//! Identification from a slow loop: a synthetic "measurement" from a known model plus small
//! deterministic noise, fitted for `sigma0` and `g(0) = Fs` with standard errors and 95 %
//! intervals.
//!
//! ```sh
//! cargo run -p lugre --example fit
//! ```

use lugre::fit::{fit_slow, Family, FitSpec};
use lugre::{HysteresisLoop, LuGre, TurningPoints};

fn main() -> Result<(), lugre::Error> {
    // The truth: sigma0 = 6, Fs = 2 (the paper's Example 4), two periods of 0 -> 1 -> 0.5 -> 1.5.
    let model = LuGre::paper().with_sigma0(6.0)?.rate_independent();
    let hl = HysteresisLoop::new(model, &TurningPoints::new(&[0.0, 1.0, 0.5, 1.5])?)?;
    let n = 4000;
    let (mut u, mut f) = (Vec::with_capacity(n), Vec::with_capacity(n));
    for i in 0..n {
        let rho = 2.0 * hl.period() * i as f64 / n as f64;
        let p = hl.point_at(rho);
        // Noise of 0.02 N from a fixed sequence (reproducible).
        let noise = 0.02 * ((i as f64 * 12.9898).sin() * 43758.5453).fract();
        u.push(p.u);
        f.push(p.y + noise);
    }

    let report = fit_slow(&FitSpec::new(Family::LuGre), &u, &f)?;
    println!(
        "slow-loop fit of {} samples: residual RMS {:.4}",
        u.len(),
        report.rms
    );
    for name in ["sigma0", "fs"] {
        let e = report.estimate(name).expect("a fitted parameter");
        println!(
            "  {name:6} = {:.5} ± {:.5}   95 % interval [{:.5}, {:.5}]",
            e.value, e.stderr, e.ci95[0], e.ci95[1]
        );
    }
    Ok(())
}
