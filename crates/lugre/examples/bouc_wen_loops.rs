//! The periodic Bouc-Wen response of `lugre::zoo::BoucWen` and its loop time, for
//! `bench/compare_bouc_wen.py` (until the front ends have the model):
//!
//! ```text
//! cargo run --release -p lugre --example bouc_wen_loops -- KX KW RHO SIGMA N REPEAT U1 U2 ...
//! ```
//!
//! prints `{"force": [...], "seconds_per_turning_point": t}`: the periodic force at each turning
//! point of the period `U1 U2 ...`, and the best of five timings of the loops of that period
//! repeated `REPEAT` times, per turning point.

use lugre::zoo::BoucWen;
use lugre::TurningPoints;
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .map(|a| a.parse::<f64>())
        .collect::<Result<_, _>>()?;
    if args.len() < 8 {
        return Err("usage: KX KW RHO SIGMA N REPEAT U1 U2 ...".into());
    }
    let model = BoucWen::new(args[0], args[1], args[2], args[3], args[4])?;
    let period = &args[6..];
    let force = model
        .loops(&TurningPoints::new(period)?)?
        .turning_force()
        .to_vec();
    let repeat = args[5] as usize;
    let long: Vec<f64> = period
        .iter()
        .cycle()
        .take(period.len() * repeat.max(1))
        .copied()
        .collect();
    let input = TurningPoints::new(&long)?;
    let mut best = f64::INFINITY;
    for _ in 0..5 {
        let t = Instant::now();
        let hl = model.loops(&input)?;
        std::hint::black_box(hl.loops().len());
        best = best.min(t.elapsed().as_secs_f64());
    }
    let list: Vec<String> = force.iter().map(|f| format!("{f:e}")).collect();
    println!(
        "{{\"force\": [{}], \"seconds_per_turning_point\": {:e}}}",
        list.join(", "),
        best / long.len() as f64
    );
    Ok(())
}
