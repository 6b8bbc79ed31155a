//! Solver statistics of the five 1995 experiments at the default tolerance (one output time at
//! the end), and their time: `cargo run --release -p lugre --example dynamics_stats`.
use lugre::dynamics::{Scenario, Tolerances};
use lugre::{LuGre, LuGreParams};
use std::time::Instant;

fn main() {
    let rtol: f64 = std::env::args()
        .nth(1)
        .map_or(1e-8, |s| s.parse().expect("rtol"));
    let tol = Tolerances::new(rtol, None).expect("valid");
    let mut total = 0.0;
    for (name, sc) in [
        ("presliding", Scenario::Presliding),
        ("stick-slip", Scenario::StickSlip),
        ("pid", Scenario::Pid),
        ("lag", Scenario::Lag { w: 10.0 }),
        ("breakaway 10", Scenario::Breakaway { rate: 10.0 }),
    ] {
        let model = LuGre::from_params(LuGreParams::canudas_de_wit_1995()).expect("valid");
        let setup = sc.setup(model, 1.0).expect("valid");
        let t = setup.t_end;
        let mut best = f64::INFINITY;
        let mut m = None;
        for _ in 0..20 {
            let start = Instant::now();
            m = Some(setup.system.solve(t, &[t], tol).expect("solves"));
            best = best.min(start.elapsed().as_secs_f64());
        }
        let m = m.expect("ran");
        total += best;
        println!(
            "{name:14} {:8.3} ms  x(end) = {:.12e}  {:?}",
            best * 1e3,
            m.x[0],
            m.stats
        );
    }
    println!("total {:.3} ms", total * 1e3);
}
