//! The exact response of eq. 1 at a realistic stiffness (Canudas de Wit et al. 1995:
//! `sigma0 = 1e5 N/m`) to a displacement 0 -> 8 mm -> 4 mm -> 10 mm -> 0 at 10 mm/s, sampled 200
//! times per period and at every turning point (where the `sigma1` term jumps).
//!
//! ```sh
//! cargo run -p lugre --example simulate
//! ```

use lugre::simulate::{Drive, Request};
use lugre::{LuGre, LuGreParams, PiecewiseLinear, TurningPoints};

fn main() -> Result<(), lugre::Error> {
    let model = LuGre::from_params(LuGreParams::canudas_de_wit_1995())?;
    let tp = TurningPoints::new(&[0.0, 8e-3, 4e-3, 10e-3])?;
    // 10 mm/s: the input runs at that speed between turning points.
    let input = PiecewiseLinear::from_turning_points(&tp, 10e-3)?;
    let request = Request::new(Drive::TurningPoints(input)).with_periods(3)?;
    let y = request.run(&model, None)?;

    let (peak, at) =
        y.y.iter()
            .zip(&y.t)
            .fold((0.0f64, 0.0), |(m, at), (&f, &t)| {
                if f.abs() > m.abs() {
                    (f, t)
                } else {
                    (m, at)
                }
            });
    println!("{} samples over {} s", y.len(), y.t[y.len() - 1]);
    println!("largest |F| = {peak:.6} N at t = {at:.4} s (Fs = 1.5 N, plus the sigma1 jump)");
    for i in (0..y.len()).step_by(y.len() / 8) {
        println!(
            "  t = {:8.4} s  u = {:9.6} m  z = {:12.6e} m  F = {:9.6} N",
            y.t[i], y.u[i], y.z[i], y.y[i]
        );
    }
    Ok(())
}
