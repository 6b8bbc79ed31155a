//! `examples/c/friction.c` built against the static library and run: what it prints is the core's
//! own results to the last bit (parsed back from `%.17g`).

mod common;

fn numbers_after(line: &str, key: &str) -> f64 {
    let rest = &line[line.find(key).expect(key) + key.len()..];
    rest.split_whitespace().next().unwrap().parse().unwrap()
}

#[test]
fn the_c_example_prints_the_cores_results() {
    let out = common::compile_and_run(&common::root().join("examples/c/friction.c"), &[]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();

    // y° at the turning points, as the core computes it.
    let model = lugre::LuGre::from_params(lugre::LuGreParams {
        sigma0: 6.0,
        ..Default::default()
    })
    .unwrap();
    let tp = lugre::TurningPoints::new(&[0.0, 1.0, 0.5, 1.5]).unwrap();
    let hl = lugre::HysteresisLoop::new(model.rate_independent(), &tp).unwrap();
    let ys: Vec<f64> = text
        .lines()
        .filter(|l| l.starts_with("turning point"))
        .map(|l| numbers_after(l, "y = "))
        .collect();
    assert_eq!(ys, hl.turning_y(), "{text}");
    let work = text
        .lines()
        .find(|l| l.starts_with("work per period"))
        .unwrap();
    assert_eq!(numbers_after(work, "period "), hl.work_per_period());

    // The element steps are the exact simulation at the knots.
    let table1 = lugre::LuGre::from_params(lugre::LuGreParams::canudas_de_wit_1995()).unwrap();
    let input = lugre::PiecewiseLinear::new(
        vec![0.0, 5e-3, 1e-2, 1.5e-2, 2e-2],
        vec![0.0, 5e-6, 1e-5, 1e-5, 0.0],
    )
    .unwrap();
    let mut sim = lugre::Trajectory::default();
    lugre::Simulator::new(&table1, lugre::Gamma::ONE, 0.0)
        .unwrap()
        .at_knots(&input, 1, &mut sim)
        .unwrap();
    let zs: Vec<f64> = text
        .lines()
        .filter(|l| l.starts_with("step "))
        .map(|l| numbers_after(l, "z = "))
        .collect();
    assert_eq!(zs, sim.z[1..], "{text}");
    assert!(
        text.contains("sigma0 = -1: status 1, message: sigma0 must be > 0, got -1"),
        "{text}"
    );
}
