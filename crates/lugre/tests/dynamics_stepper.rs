//! `MassStepper` (the mass with a finite-rate friction of the zoo, stepped under a force
//! linear over each step) against the run of `lugre dynamics --model NAME` on the same force
//! (`Request::with_zoo`, one solve over the whole time): the same motion to the solver's
//! tolerance, whatever the steps. (The run itself is checked against scipy in
//! `dynamics_gms.rs` and `dynamics_elastoplastic.rs`.)

use lugre::dynamics::{MassStepper, Request, State, Tolerances};
use lugre::zoo::{ZooModel, MODELS};

/// The force: up to 3 N at 1.5 N/s, held, down to -3 N over 2 s, held (every default model
/// breaks away, slides, reverses and sticks).
const FORCE: [(f64, f64); 4] = [(0.0, 0.0), (2.0, 3.0), (4.0, 3.0), (6.0, -3.0)];
const T_END: f64 = 9.0;

fn force_at(t: f64) -> (f64, f64) {
    for w in FORCE.windows(2) {
        let ((t0, f0), (t1, f1)) = (w[0], w[1]);
        if t < t1 {
            let slope = (f1 - f0) / (t1 - t0);
            return (f0 + slope * (t - t0), slope);
        }
    }
    (FORCE[FORCE.len() - 1].1, 0.0)
}

/// The stepper over `[0, T_END]` in `n` equal steps: `(x, v, friction)` after each.
fn stepped(model: &ZooModel, n: usize) -> Vec<[f64; 3]> {
    let tol = Tolerances::default();
    let mut s = MassStepper::of_zoo(model, 1.0, State::default(), tol).unwrap();
    let h = T_END / n as f64;
    (0..n)
        .map(|k| {
            // The force's kinks fall on steps' ends for these n.
            let (f, df) = force_at(k as f64 * h);
            s.step(f, df, h).unwrap();
            [s.x(), s.v(), s.friction()]
        })
        .collect()
}

#[test]
fn stepping_reproduces_the_dynamics_run_whatever_the_steps() {
    for spec in MODELS.iter().filter(|m| m.finite_rate) {
        let model = ZooModel::new(spec.name, &[]).unwrap();
        let times: Vec<f64> = (1..=36).map(|k| k as f64 * 0.25).collect();
        let (t, f): (Vec<f64>, Vec<f64>) = FORCE.iter().copied().unzip();
        let run = Request::new()
            .with_zoo(&model)
            .unwrap()
            .with_force(t, f)
            .unwrap()
            .with_t_end(T_END)
            .unwrap()
            .with_times(times)
            .unwrap()
            .build()
            .unwrap()
            .motion()
            .unwrap();
        let scale = run.x.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
        let vscale = run.v.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        assert!(
            scale > 0.1 && vscale > 0.1,
            "{}: the mass slides",
            spec.name
        );
        for n in [36, 360, 3600] {
            let out = stepped(&model, n);
            let every = n / 36;
            for (i, row) in out.iter().skip(every - 1).step_by(every).enumerate() {
                let dx = (row[0] - run.x[i]).abs() / scale;
                let dv = (row[1] - run.v[i]).abs() / vscale;
                let df = (row[2] - run.friction[i]).abs() / 3.0;
                // Both runs hold the local error to rtol 1e-8; the global errors stay within
                // 1e-7 of the scales here (BENCHMARKS.md: within 3x rtol per unit time).
                assert!(
                    dx < 1e-7 && dv < 1e-7 && df < 1e-7,
                    "{} n = {n}, t = {}: dx {dx:e} dv {dv:e} dF {df:e}",
                    spec.name,
                    run.t[i]
                );
            }
        }
    }
}

#[test]
fn a_model_without_a_finite_rate_form_is_refused_by_name() {
    let model = ZooModel::new("bouc-wen", &[]).unwrap();
    let err = MassStepper::of_zoo(&model, 1.0, State::default(), Tolerances::default())
        .unwrap_err()
        .to_string();
    assert!(err.contains("bouc-wen"), "{err}");
}

#[test]
fn a_bad_mass_and_a_bad_step_are_refused_by_name() {
    let model = ZooModel::new("elastoplastic", &[]).unwrap();
    let tol = Tolerances::default();
    let err = MassStepper::of_zoo(&model, -1.0, State::default(), tol).unwrap_err();
    assert!(err.to_string().contains("mass") && err.to_string().contains("-1"));
    let mut s = MassStepper::of_zoo(&model, 1.0, State::default(), tol).unwrap();
    let err = s.step(1.0, 0.0, 0.0).unwrap_err().to_string();
    assert!(err.contains("step size"), "{err}");
}
