//! Properties of the closed-loop solver over random systems: any stiffness (`sigma0` from 1e4 to
//! 3e8 N/m), any mass (a gram to a tonne), any damping ratio of the bristles from 0.05 to 2 (an
//! undamped `sigma1 = 0` rings for its whole run, every sign change an event: correct and
//! slow, kept out of the random cases), any Stribeck curve, driven by a force profile, a pulled
//! spring or a PID controller. Whatever the system, the run succeeds, every output is finite,
//! the bristles stay within their reach, the events are in order and of the kinds the drive can
//! produce, and the energy balance closes to the tolerance.

use lugre::dynamics::{EventKind, Pid, Profile, Steps, System, Tolerances};
use lugre::{LuGre, LuGreParams};
use proptest::prelude::*;

/// A random Table-I-like model: `(sigma0, mass, zeta, sigma2, Fc, Fs / Fc, vs)`.
fn model() -> impl Strategy<Value = (f64, f64, f64, f64, f64, f64, f64)> {
    (
        4.0..8.5f64,
        -3.0..3.0f64,
        0.05..2.0f64,
        0.0..2.0f64,
        0.1..2.0f64,
        1.0..2.0f64,
        -4.0..-1.0f64,
    )
        .prop_map(|(s0, m, zeta, s2, fc, ratio, vs)| {
            (
                10f64.powf(s0),
                10f64.powf(m),
                zeta,
                s2,
                fc,
                ratio,
                10f64.powf(vs),
            )
        })
}

/// How the mass is driven.
#[derive(Debug, Clone)]
enum Drive {
    /// A force profile through `(t, F / Fs)` knots, over `[0, t_end]`.
    Force(Vec<(f64, f64)>),
    /// A spring of stiffness `k` (N/m) pulled at `speed` (m/s).
    Spring { k: f64, speed: f64 },
    /// A PID controller towards `xd` (m), gains scaled by the mass.
    Pid { kp: f64, ki: f64, kv: f64, xd: f64 },
}

fn drive() -> impl Strategy<Value = Drive> {
    prop_oneof![
        prop::collection::vec((0.05..1.0f64, -2.5..2.5f64), 1..4).prop_map(|steps| {
            // Knot times as running sums of the gaps (strictly increasing), from 0.
            let mut t = 0.0;
            let mut knots = vec![(0.0, 0.0)];
            for (gap, f) in steps {
                t += gap;
                knots.push((t, f));
            }
            Drive::Force(knots)
        }),
        (-1.0..3.0f64, -3.0..0.0f64).prop_map(|(k, v)| Drive::Spring {
            k: 10f64.powf(k),
            speed: 10f64.powf(v),
        }),
        (0.1..10.0f64, 0.0..5.0f64, 0.1..10.0f64, -1.0..1.0f64)
            .prop_map(|(kp, ki, kv, xd)| { Drive::Pid { kp, ki, kv, xd } }),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn any_system_runs_finite_with_its_energy_balanced(
        (sigma0, mass, zeta, sigma2, fc, ratio, vs) in model(),
        drive in drive(),
        t_end in 0.2..3.0f64,
    ) {
        // Any parameter the table has besides these at its default.
        #[allow(clippy::needless_update)]
        let p = LuGreParams {
            sigma0,
            sigma1: 2.0 * zeta * (sigma0 * mass).sqrt(),
            sigma2,
            fc,
            fs: fc * ratio,
            vs,
            beta: 2.0,
            ..LuGreParams::default()
        };
        let model = LuGre::from_params(p).unwrap();
        let system = System::new(model, mass).unwrap();
        let system = match &drive {
            Drive::Force(knots) => {
                let (t, f): (Vec<f64>, Vec<f64>) =
                    knots.iter().map(|&(t, f)| (t, f * p.fs)).unzip();
                system.with_force(Profile::new("the force", t, f).unwrap())
            }
            Drive::Spring { k, speed } => {
                system.with_spring(*k, Profile::ramp(0.0, *speed).unwrap()).unwrap()
            }
            Drive::Pid { kp, ki, kv, xd } => system
                .with_pid(Pid {
                    kp: kp * p.fs,
                    ki: ki * p.fs,
                    kv: kv * p.fs,
                    setpoint: Steps::constant(xd * 1e-3).unwrap(),
                })
                .unwrap(),
        };
        // A hundred outputs (enough to see the largest speed), the last at t_end itself
        // (t_end * 100 / 100 can round past it).
        let times: Vec<f64> = (1..=100).map(|i| t_end * f64::from(i) / 100.0).collect();
        let times: Vec<f64> = times.iter().map(|&t| t.min(t_end)).collect();
        let m = system
            .solve(t_end, &times, Tolerances::default())
            .map_err(|e| TestCaseError::fail(format!("{e}")))?;
        for column in [&m.x, &m.v, &m.z, &m.friction, &m.drive] {
            prop_assert_eq!(column.len(), times.len());
            prop_assert!(column.iter().all(|v| v.is_finite()), "{:?}", column);
        }
        // The bristles never deflect past their reach g / sigma0 <= max(Fc, Fs) / sigma0 (eq. 5
        // keeps |z| below it from 0), up to the tolerance.
        let reach = p.fs.max(p.fc) / sigma0;
        prop_assert!(
            m.z.iter().all(|z| z.abs() <= reach * (1.0 + 1e-6)),
            "z {:?} past the reach {reach:e}", m.z
        );
        prop_assert!(m.events.windows(2).all(|w| w[0].t <= w[1].t));
        for e in &m.events {
            prop_assert!(e.t > 0.0 && e.t <= t_end && e.x.is_finite());
            prop_assert!(matches!(e.kind, EventKind::VelocityZero | EventKind::Kink));
        }
        // Relative to the energies involved, with a floor: the work of the largest friction
        // force over the velocity's absolute tolerance, atol w0 = rtol (g(0) / sigma0)
        // sqrt(sigma0 / M), for the run (a stuck mass's velocity is only that accurate); and
        // amplified by sigma1 |v| / min(Fc, Fs): sliding, z' = v (1 - sigma0 |z| / g) is a
        // cancellation, so the dissipation sigma1 z' v carries sigma1 v^2 times z's relative
        // error (docs/mathematics.md, "Energy balance").
        let e = m.energy;
        let scale = e.input.abs().max(e.dissipated).max(e.stored_end);
        let rtol = Tolerances::DEFAULT_RTOL;
        let atol_v = rtol * p.fs / sigma0 * (sigma0 / mass).sqrt();
        let floor = p.fs.max(p.fc) * atol_v * t_end;
        let v_max = m.v.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        let amplification = 1.0 + p.sigma1 * v_max / p.fc.min(p.fs);
        prop_assert!(
            e.residual().abs()
                <= 10.0 * rtol * amplification * scale + floor,
            "energy {e:?}: residual {:e} of {scale:e} (amplification {amplification:e})",
            e.residual()
        );
    }
}
