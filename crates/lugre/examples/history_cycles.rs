//! Minor loops in a measured history: the rainflow cycles of ASTM E1049's worked example, where
//! each loop closes, and, with a model, the energy over each full cycle's loop.
//!
//! ```sh
//! cargo run -p lugre --example history_cycles
//! ```

use lugre::{count_cycles, count_cycles_with_energy, LuGre};

fn main() -> Result<(), lugre::Error> {
    // ASTM E1049-85's example history (a measured record would be read from a file).
    let u = [-2.0, 1.0, -3.0, 5.0, -1.0, 3.0, -4.0, 4.0, -2.0];
    let history = count_cycles(&u, 0.0)?;
    println!(
        "{} samples, {} reversals: {} full and {} half cycles",
        history.summary.samples,
        history.summary.reversals,
        history.summary.full_cycles,
        history.summary.half_cycles
    );
    for c in &history.cycles {
        let closes = c
            .closure
            .map_or("-".to_string(), |k| format!("{:.8}", k.position));
        println!(
            "  count {:3}  range {:3}  mean {:5}  samples {}..{}  closes at {closes}",
            c.count, c.range, c.mean, c.start, c.end
        );
    }

    // The same history as displacements (in units of 1/a) under the paper's model, from x0 = 0:
    // the energy of each full cycle's loop along the rate-independent response y*.
    let model = LuGre::paper().rate_independent();
    let with_energy = count_cycles_with_energy(&u, 0.0, model, 0.0)?;
    for c in with_energy.cycles.iter().filter(|c| c.count == 1.0) {
        let e = c.energy.expect("full cycles carry energies").arc;
        println!(
            "  full cycle {}..{}: W = {:.6}, dV = {:.6}, D = {:.6}",
            c.start, c.end, e.work, e.stored_energy_change, e.dissipation
        );
    }
    Ok(())
}
