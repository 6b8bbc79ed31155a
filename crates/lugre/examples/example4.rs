//! The paper's Example 4: the hysteresis loop of the LuGre model with `sigma0 = 6` for the
//! bimodal input `umin1 = 0, umin2 = 0.5, umax1 = 1, umax2 = 1.5`, Theorem A's points and every
//! loop with its energies (the numbers of `lugre loop --sigma0 6 --bimodal 0,0.5,1,1.5`).
//!
//! ```sh
//! cargo run -p lugre --example example4
//! ```

use lugre::{Bimodal, HysteresisLoop, LuGre, TheoremA};

fn main() -> Result<(), lugre::Error> {
    // The paper's parameters (sigma1 = 1, Fc = 1, Fs = 2, vs = 1, beta = 1) with sigma0 = 6.
    let model = LuGre::paper().with_sigma0(6.0)?;
    let input = Bimodal::new(0.0, 0.5, 1.0, 1.5)?;
    let hl = HysteresisLoop::new(model.rate_independent(), &input.turning_points())?;

    println!("y° at the turning points (period P = {}):", hl.period());
    for ((rho, u), y) in hl
        .turning_rho()
        .iter()
        .zip(hl.turning_points())
        .zip(hl.turning_y())
    {
        println!("  rho = {rho:<4} u = {u:<4} y° = {y:.12}");
    }

    let a = TheoremA::new(&input, &hl);
    println!(
        "Theorem A: the minor loop is rho in [rho_1, rho_5] = [{}, {}]",
        a.rho[1], a.rho[5]
    );

    for l in hl.loops() {
        let e = l.energy;
        println!(
            "{:?} loop [{}, {}]: W = {:.8}, dV = {:.8}, D = {:.8}, gap = {:.8}",
            l.kind,
            l.start.rho,
            l.end.rho,
            e.work,
            e.stored_energy_change,
            e.dissipation,
            e.closure_gap
        );
    }
    println!(
        "work per period (dissipated per cycle): {:.11}",
        hl.work_per_period()
    );
    Ok(())
}
