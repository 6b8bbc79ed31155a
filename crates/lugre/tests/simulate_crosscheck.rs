//! `lugre::simulate`: the exact solution of eq. 5 for piecewise-linear inputs, the adaptive
//! integrator for sines, the rate-independent limit and its convergence, Dahl, and the paper's
//! Example 1, each against an independent reference: mpmath (50 digits, script below), the
//! closed forms written out here, or the stiff solver of the `differential-equations` crate
//! (Radau5 with Newton iterations and its own error control), restarted at every kink.

use differential_equations::prelude::{ImplicitRungeKutta, IVP};
use lugre::simulate::{merge_times, uniform_times};
use lugre::{
    paper_example_1, Bimodal, Dahl, Gamma, HysteresisLoop, LuGre, LuGreParams, PiecewiseLinear,
    SimulateError, Simulator, Sine, Tolerance, Trajectory, TurningPoints,
};
use lugre_test_support::prec::{ADAPTIVE, EXACT_SIMULATION, STIFF_SOLVER};

/// `|got - want| <= tol * max(|want|, scale)`.
#[track_caller]
fn assert_close(what: &str, got: f64, want: f64, scale: f64, tol: f64) {
    let err = (got - want).abs() / want.abs().max(scale);
    assert!(
        err <= tol,
        "{what}: got {got:e}, want {want:e}: relative error {err:.2e} > {tol:e} (scale {scale:e})"
    );
}

fn paper_model() -> LuGre {
    LuGre::paper()
}

fn canudas() -> LuGre {
    LuGre::from_params(LuGreParams::canudas_de_wit_1995()).expect("valid")
}

/// The periodic input through `tp` at `speed`.
fn periodic(tp: &[f64], speed: f64) -> PiecewiseLinear {
    PiecewiseLinear::from_turning_points(&TurningPoints::new(tp).expect("valid"), speed)
        .expect("valid")
}

fn at_knots(model: &LuGre, gamma: Gamma, x0: f64, input: &PiecewiseLinear, k: u32) -> Trajectory {
    let mut out = Trajectory::default();
    Simulator::new(model, gamma, x0)
        .expect("valid")
        .at_knots(input, k, &mut out)
        .expect("finite");
    out
}

fn at_times(
    model: &LuGre,
    gamma: Gamma,
    x0: f64,
    input: &PiecewiseLinear,
    k: u32,
    times: &[f64],
) -> Trajectory {
    let mut out = Trajectory::default();
    Simulator::new(model, gamma, x0)
        .expect("valid")
        .at_times(input, k, times, &mut out)
        .expect("finite");
    out
}

// ---------------------------------------------------------------------------------------------
// The exact solution against mpmath.

const T: [f64; 8] = [0.0, 0.3, 0.7, 1.0, 1.6, 2.5, 2.6, 3.4];
const U: [f64; 8] = [0.0, 0.25, 0.25, -0.4, 0.9, 0.95, 0.1, -0.15];

// mpmath, mp.dps = 50: the direct form z_inf + (z_k - z_inf) exp(-k tau) (not the code's), from
// the exact decimal values of the f64 knots:
//   from mpmath import mp, mpf, exp, sqrt, nstr
//   mp.dps = 50
//   T = [0.0, 0.3, 0.7, 1.0, 1.6, 2.5, 2.6, 3.4]
//   U = [0.0, 0.25, 0.25, -0.4, 0.9, 0.95, 0.1, -0.15]
//   def g(v, fc, fs, vs, beta): return fc + (fs - fc) * exp(-abs(v / vs) ** beta)
//   def run(sigma0, sigma1, sigma2, fc, fs, vs, beta, gamma, x0, T, U):
//       t = [mpf(x) for x in T]; u = [mpf(x) for x in U]
//       z = mpf(x0); rows = []
//       n = len(t)
//       for i in range(n):
//           j = i if i < n - 1 else n - 2          # outgoing slope; the last knot: incoming (open input)
//           v = (u[j + 1] - u[j]) / (t[j + 1] - t[j])
//           w = v / gamma
//           gg = g(w, fc, fs, vs, beta)
//           k = sigma0 * abs(v) / gg
//           dz = v - k * z
//           y = sigma0 * z + sigma1 / gamma * dz + sigma2 * w
//           rows.append((z, y))
//           if i < n - 1:
//               zinf = v / k if k != 0 else 0
//               z = zinf + (z - zinf) * exp(-k * (t[i + 1] - t[i])) if k != 0 else z + v * (t[i+1]-t[i])
//       return rows
//   for s0 in ['1e-3', '1', '1e3', '1e6', '1e9']:
//       sigma0 = mpf(float(s0))
//       for scale in sorted({1.0, min(1.0, 4.0 / float(s0))}, reverse=True):
//           Us = [u * scale for u in U]   # double products, as in the Rust test
//           for gamma in [1, 10]:
//               rows = run(sigma0, 1, mpf(0.3), 1, 2, 1, 1, mpf(gamma), mpf(0.7) / sigma0, T, Us)
//               print(f"    ({s0}, {scale!r}, {gamma}.0, &[" + ", ".join(f"({nstr(z, 17, strip_zeros=False)}, {nstr(y, 17, strip_zeros=False)})" for z, y in rows) + "]),")
//   # Between knots: sigma0 = 1e6, U scaled by 4e-6, gamma = 1, at times 0.15, 0.5, 1.0 (a knot:
//   # value just after it), 2.55, 3.4 (the end of an open input: slope just before it).
//   def at(sigma0, scale, gamma, times):
//       t = [mpf(x) for x in T]; u = [mpf(x * scale) for x in U]
//       z = mpf(0.7) / sigma0; res = []; n = len(t)
//       zs = []
//       for i in range(n - 1):
//           zs.append(z)
//           v = (u[i + 1] - u[i]) / (t[i + 1] - t[i]); gg = g(v / gamma, 1, 2, 1, 1)
//           k = sigma0 * abs(v) / gg
//           if k != 0:
//               zinf = v / k
//               z = zinf + (z - zinf) * exp(-k * (t[i + 1] - t[i]))
//       zs.append(z)
//       for tau in times:
//           tau = mpf(tau)
//           i = max(j for j in range(n - 1) if t[j] <= tau)
//           if tau == t[-1]: i = n - 2
//           v = (u[i + 1] - u[i]) / (t[i + 1] - t[i]); gg = g(v / gamma, 1, 2, 1, 1)
//           k = sigma0 * abs(v) / gg
//           zt = v / k + (zs[i] - v / k) * exp(-k * (tau - t[i])) if k != 0 else zs[i]
//           ut = u[i] + v * (tau - t[i])
//           dz = v - k * zt
//           res.append((ut, zt, sigma0 * zt + dz / gamma + mpf(0.3) * v / gamma))
//       return res
//   print("at_times:")
//   for ut, zt, y in at(mpf(1e6), 4e-6, mpf(1), [0.15, 0.5, 1.0, 2.55, 3.4]):
//       print(f"({nstr(ut, 17)}, {nstr(zt, 17)}, {nstr(y, 17)}),")
/// `(sigma0, scale of u, gamma, [(z, y) at each knot])`; sigma1 = 1, sigma2 = 0.3, Fc = 1,
/// Fs = 2, vs = 1, beta = 1, x0 = 0.7 / sigma0. `y` at a knot is the value just after it.
#[allow(clippy::type_complexity)]
const KNOTS: [(f64, f64, f64, &[(f64, f64)]); 16] = [
    (
        1e-3,
        1.0,
        1.0,
        &[
            (699.99999999999994, 1.3767154176868457),
            (700.12800347173101, 0.70012800347173103),
            (700.12800347173101, -3.4775650600497934),
            (699.07000409019369, 2.1567669907866117),
            (699.55433976739276, 0.75180485620228364),
            (699.58636482075228, -16.295688060864911),
            (698.14245100362059, 0.16590056672422874),
            (697.79168281768156, 0.16561310072630047),
        ],
    ),
    (
        1e-3,
        1.0,
        10.0,
        &[
            (699.99999999999994, 0.77795209168658995),
            (700.15884593354239, 0.70015884593354240),
            (700.15884593354239, 0.33445649118361879),
            (699.25690126120602, 0.89699613462364623),
            (700.05304995672495, 0.70532527874350092),
            (700.08549960905686, -0.82180286364723515),
            (698.81898837559205, 0.64710434546056964),
            (698.48029273193504, 0.64677102461898228),
        ],
    ),
    (
        1.0,
        1.0,
        1.0,
        &[
            (0.69999999999999996, 1.3767154176868457),
            (0.81748106008933469, 0.81748106008933469),
            (0.81748106008933469, -3.5883425838634155),
            (-0.036258542980764047, 2.8508935690096285),
            (0.75608812776069065, 0.80672465066189700),
            (0.78627156715110201, -16.945677188418140),
            (-0.23650532076491848, -0.60007384370756726),
            (-0.43750181472333822, -0.76479704276611655),
        ],
    ),
    (
        1.0,
        1.0,
        10.0,
        &[
            (0.69999999999999996, 0.77795209168658995),
            (0.84894892996530825, 0.84894892996530825),
            (0.84894892996530825, 0.46538823183488568),
            (0.046405466988501102, 0.32250237563260936),
            (0.94922390198917120, 0.95380206691064744),
            (0.97510166048638859, -0.71055389583589875),
            (-0.10291537257517413, -0.14190719609984951),
            (-0.32542693687796927, -0.36088769751851076),
        ],
    ),
    (
        1e3,
        1.0,
        1.0,
        &[
            (0.00069999999999999996, 1.3767154176868457),
            (0.0014345982085070782, 1.4345982085070782),
            (0.0014345982085070782, -4.1708813909044786),
            (-0.0011145588439926877, 3.8687744893406450),
            (0.0011145588439926877, 1.1549613203431431),
            (0.0019459594689009988, -25.641331201196965),
            (-0.0010002034683690106, -1.2259494473609240),
            (-0.0017316156289466417, -1.8253656289466418),
        ],
    ),
    (
        1e3,
        1.0,
        10.0,
        &[
            (0.00069999999999999996, 0.77795209168658995),
            (0.0019200444146293232, 1.9200444146293232),
            (0.0019200444146293232, 1.4079268231890735),
            (-0.0018051983240180706, -1.3068649906847373),
            (0.0018051983240180706, 1.8073921774877655),
            (0.0019944598480024446, -0.29820523301757790),
            (-0.0014274149319487270, -1.4453881120208252),
            (-0.0019692332344763441, -1.9786082344763441),
        ],
    ),
    (
        1e3,
        0.004,
        1.0,
        &[
            (0.00069999999999999996, 0.70316472222402259),
            (0.0012108558806879277, 1.2108558806879277),
            (0.0012108558806879277, 1.1943194348312817),
            (-0.0011235646131240303, -1.1074080685525924),
            (0.0017626053645707744, 1.7626983866585955),
            (0.0017851776905906391, 1.7101138031922150),
            (-0.0013007109667895592, -1.3015225143451604),
            (-0.0015755005183100913, -1.5761402150563377),
        ],
    ),
    (
        1e3,
        0.004,
        10.0,
        &[
            (0.00069999999999999996, 0.70031664722222236),
            (0.0012114446956890203, 1.2114446956890203),
            (0.0012114446956890203, 1.2097928421718431),
            (-0.0011246417887351584, -1.1230275661106505),
            (0.0017673809802456012, 1.7673902313498477),
            (0.0017895157259256814, 1.7820483774961419),
            (-0.0013069397711335222, -1.3070205822925929),
            (-0.0015796016753181788, -1.5796654440431524),
        ],
    ),
    (
        1e6,
        1.0,
        1.0,
        &[
            (6.9999999999999996e-7, 1.3767154176868457),
            (1.4345982085070782e-6, 1.4345982085070782),
            (1.4345982085070782e-6, -4.1708813909044786),
            (-1.1145588439926877e-6, 3.8687744893406450),
            (1.1145588439926877e-6, 1.1549613203431431),
            (1.9459594689067655e-6, -25.641331201240205),
            (-1.0002034683690106e-6, -1.2259494473609240),
            (-1.7316156289466417e-6, -1.8253656289466418),
        ],
    ),
    (
        1e6,
        1.0,
        10.0,
        &[
            (6.9999999999999996e-7, 0.77795209168658995),
            (1.9200444146293232e-6, 1.9200444146293232),
            (1.9200444146293232e-6, 1.4079268231890735),
            (-1.8051983240180706e-6, -1.3068649906847373),
            (1.8051983240180706e-6, 1.8073921774877655),
            (1.9944598480048968e-6, -0.29820523301658598),
            (-1.4274149319487270e-6, -1.4453881120208252),
            (-1.9692332344763441e-6, -1.9786082344763441),
        ],
    ),
    (
        1e6,
        4e-06,
        1.0,
        &[
            (6.9999999999999996e-7, 0.70000316666472218),
            (1.2115094878842176e-6, 1.2115094878842176),
            (1.2115094878842176e-6, 1.2114929713203540),
            (-1.1247601867067109e-6, -1.1247440460581147),
            (1.7679074717702840e-6, 1.7679075642249875),
            (1.7899939771973454e-6, 1.7899193467824248),
            (-1.3076227648278106e-6, -1.3076235725630718),
            (-1.5800516181781340e-6, -1.5800522556452555),
        ],
    ),
    (
        1e6,
        4e-06,
        10.0,
        &[
            (6.9999999999999996e-7, 0.70000031666664718),
            (1.2115100769246202e-6, 1.2115100769246202),
            (1.2115100769246202e-6, 1.2115084252700260),
            (-1.1247612629675665e-6, -1.1247596489041413),
            (1.7679122591226654e-6, 1.7679122683680845),
            (1.7899983259053649e-6, 1.7899908629030377),
            (-1.3076289717436860e-6, -1.3076290525168702),
            (-1.5800557074053745e-6, -1.5800557711518866),
        ],
    ),
    (
        1e9,
        1.0,
        1.0,
        &[
            (6.9999999999999996e-10, 1.3767154176868457),
            (1.4345982085070782e-9, 1.4345982085070782),
            (1.4345982085070782e-9, -4.1708813909044786),
            (-1.1145588439926877e-9, 3.8687744893406450),
            (1.1145588439926877e-9, 1.1549613203431431),
            (1.9459594689067655e-9, -25.641331201240205),
            (-1.0002034683690106e-9, -1.2259494473609240),
            (-1.7316156289466417e-9, -1.8253656289466418),
        ],
    ),
    (
        1e9,
        1.0,
        10.0,
        &[
            (6.9999999999999996e-10, 0.77795209168658995),
            (1.9200444146293232e-9, 1.9200444146293232),
            (1.9200444146293232e-9, 1.4079268231890735),
            (-1.8051983240180706e-9, -1.3068649906847373),
            (1.8051983240180706e-9, 1.8073921774877655),
            (1.9944598480048968e-9, -0.29820523301658598),
            (-1.4274149319487270e-9, -1.4453881120208252),
            (-1.9692332344763441e-9, -1.9786082344763441),
        ],
    ),
    (
        1e9,
        4e-09,
        1.0,
        &[
            (6.9999999999999996e-10, 0.70000000316666662),
            (1.2115101417190870e-9, 1.2115101417190870),
            (1.2115101417190870e-9, 1.2115101252025430),
            (-1.1247613813561679e-9, -1.1247613652155352),
            (1.7679127857325997e-9, 1.7679127858250538),
            (1.7899988042643130e-9, 1.7899987296343329),
            (-1.3076296545020874e-9, -1.3076296553098189),
            (-1.5800561572190829e-9, -1.5800561578565478),
        ],
    ),
    (
        1e9,
        4e-09,
        10.0,
        &[
            (6.9999999999999996e-10, 0.70000000031666662),
            (1.2115101423081276e-9, 1.2115101423081276),
            (1.2115101423081276e-9, 1.2115101406564732),
            (-1.1247613824324278e-9, -1.1247613808183645),
            (1.7679127905199638e-9, 1.7679127905292092),
            (1.7899988086130317e-9, 1.7899988011500337),
            (-1.3076296607089798e-9, -1.3076296607897530),
            (-1.5800561613082973e-9, -1.5800561613720438),
        ],
    ),
];

/// The same script's `at_times`: `(u, z, y)` at t = 0.15, 0.5, 1.0, 2.55, 3.4 for sigma0 = 1e6,
/// u scaled by 4e-6, gamma = 1.
const BETWEEN: [(f64, f64, f64); 5] = [
    (
        4.9999999999999998e-7,
        9.8755866652693403e-7,
        0.98756135392641326,
    ),
    (
        9.9999999999999995e-7,
        1.2115094878842176e-6,
        1.2115094878842176,
    ),
    (
        -1.5999999999999999e-6,
        -1.1247601867067109e-6,
        -1.1247440460581147,
    ),
    (
        2.1000000000000073e-6,
        -3.8010392176489613e-7,
        -0.3801416598883761,
    ),
    (
        -5.9999999999999997e-7,
        -1.580051618178134e-6,
        -1.5800522556452555,
    ),
];

fn knots_model(sigma0: f64) -> LuGre {
    LuGre::from_params(LuGreParams {
        sigma0,
        sigma1: 1.0,
        sigma2: 0.3,
        ..LuGreParams::default()
    })
    .expect("valid")
}

fn knots_input(scale: f64) -> PiecewiseLinear {
    PiecewiseLinear::new(T.to_vec(), U.iter().map(|u| u * scale).collect()).expect("valid")
}

#[test]
fn exact_solution_matches_mpmath_for_sigma0_over_g_from_1e_minus_3_to_1e9() {
    for (sigma0, scale, gamma, want) in KNOTS {
        let model = knots_model(sigma0);
        let input = knots_input(scale);
        let out = at_knots(&model, Gamma::new(gamma).unwrap(), 0.7 / sigma0, &input, 1);
        assert_eq!(out.len(), want.len());
        assert_eq!(out.t, T.to_vec(), "the knots' own times come back exactly");
        for (i, &(z, y)) in want.iter().enumerate() {
            let what = format!("sigma0 = {sigma0:e}, scale {scale:e}, gamma = {gamma}, knot {i}");
            // Scales: the state's, g(0) / sigma0 = 2 / sigma0, and the force's, g(0) = 2.
            assert_close(
                &format!("z, {what}"),
                out.z[i],
                z,
                2.0 / sigma0,
                EXACT_SIMULATION,
            );
            assert_close(&format!("y, {what}"), out.y[i], y, 2.0, EXACT_SIMULATION);
        }
    }
}

#[test]
fn exact_solution_between_knots_matches_mpmath() {
    let model = knots_model(1e6);
    let input = knots_input(4e-6);
    let times = [0.15, 0.5, 1.0, 2.55, 3.4];
    let out = at_times(&model, Gamma::ONE, 0.7 / 1e6, &input, 1, &times);
    for (i, &(u, z, y)) in BETWEEN.iter().enumerate() {
        let what = format!("t = {}", times[i]);
        assert_close(&format!("u, {what}"), out.u[i], u, 1e-6, EXACT_SIMULATION);
        assert_close(&format!("z, {what}"), out.z[i], z, 2e-6, EXACT_SIMULATION);
        assert_close(&format!("y, {what}"), out.y[i], y, 2.0, EXACT_SIMULATION);
    }
}

#[test]
fn outputs_at_the_knots_agree_between_both_paths_over_several_periods() {
    // A closed input repeated: at_times on the knot times must give at_knots' rows, and the end
    // of a period is a kink like the others (the next period's slope).
    let input = periodic(&[0.0, 1.0, 0.2, 1.5], 1.0);
    for gamma in [Gamma::ONE, Gamma::new(10.0).unwrap(), Gamma::INFINITE] {
        let a = at_knots(&paper_model(), gamma, 0.3, &input, 3);
        let b = at_times(&paper_model(), gamma, 0.3, &input, 3, &input.knot_times(3));
        assert_eq!(a.t, b.t);
        for i in 0..a.len() {
            assert_close("z", b.z[i], a.z[i], 1.0, 4.0 * f64::EPSILON);
            assert_close("y", b.y[i], a.y[i], 1.0, 4.0 * f64::EPSILON);
        }
        // One period alone ends with the same values as the first period of three.
        let one = at_knots(&paper_model(), gamma, 0.3, &input, 1);
        assert_eq!(one.y[4], a.y[4]);
        assert_eq!(one.dz[4], a.dz[4]);
    }
}

// ---------------------------------------------------------------------------------------------
// The exact solution against an independent stiff solver.

/// Radau5 (the `differential-equations` crate) for `z' = f(t, z)` from `(t0, z0)` to `t1`, with
/// tight tolerances; `atol` is the state's absolute scale.
fn radau5(f: &dyn Fn(f64, f64) -> f64, t0: f64, z0: f64, t1: f64, atol: f64) -> f64 {
    if t1 <= t0 {
        return z0;
    }
    let sol = IVP::ode_from_fn(|t: f64, z: &f64, dz: &mut f64| *dz = f(t, *z), t0, t1, z0)
        .method(ImplicitRungeKutta::radau5().rtol(1e-12).atol(atol))
        .solve()
        .expect("Radau5 solves");
    let (t, z) = sol.last().expect("a last point");
    assert!((t - t1).abs() <= 1e-12 * t1.abs().max(1.0));
    *z
}

/// Eq. 5 by Radau5 on a piecewise-linear input: restarted at every knot (kink) and at every
/// output time. Returns `y` at `times` (the value just after a knot, with the next slope).
fn reference_piecewise(
    model: &LuGre,
    gamma: f64,
    x0: f64,
    input: &PiecewiseLinear,
    periods: u32,
    times: &[f64],
) -> Vec<f64> {
    let (kt, ku) = (input.times(), input.values());
    let n = kt.len();
    let period = input.period();
    let (sigma0, sigma1) = (model.sigma0(), model.sigma1());
    let atol = 1e-12 * model.g0() / sigma0;
    let mut ys = Vec::new();
    let (mut t, mut z) = (kt[0], x0);
    let mut j = 0;
    for p in 0..periods {
        for i in 0..n - 1 {
            let b = kt[i + 1] + f64::from(p) * period;
            let last = p == periods - 1 && i == n - 2;
            let v = (ku[i + 1] - ku[i]) / (kt[i + 1] - kt[i]);
            let g = model.g(v / gamma);
            let k = sigma0 * v.abs() / g;
            let f = move |_t: f64, z: f64| -k * z + v;
            while j < times.len() && (times[j] < b || (last && times[j] <= b + 1e-12)) {
                z = radau5(&f, t, z, times[j], atol);
                t = times[j];
                let (v_out, k_out) = if last && times[j] >= b {
                    // The end of a closed input: the next period's first slope.
                    let v0 = (ku[1] - ku[0]) / (kt[1] - kt[0]);
                    (v0, sigma0 * v0.abs() / model.g(v0 / gamma))
                } else {
                    (v, k)
                };
                let dz = v_out - k_out * z;
                ys.push(sigma0 * z + sigma1 / gamma * dz + model.f(v_out / gamma));
                j += 1;
            }
            z = radau5(&f, t, z, b, atol);
            t = b;
        }
    }
    assert_eq!(ys.len(), times.len());
    ys
}

#[test]
fn exact_solution_matches_radau5_on_paper_examples_2_and_3() {
    let examples: [(&str, &[f64], u32); 2] = [
        ("Example 2", &[0.0, 1.0], 4),
        ("Example 3", &[0.0, 1.0, 0.2, 1.5], 3),
    ];
    for (name, tp, periods) in examples {
        let input = periodic(tp, 1.0);
        let times = merge_times(
            &uniform_times(0.0, input.period(), periods, 40),
            &input.knot_times(periods),
        );
        for gamma in [1.0, 10.0, 100.0] {
            let want = reference_piecewise(&paper_model(), gamma, 0.0, &input, periods, &times);
            let got = at_times(
                &paper_model(),
                Gamma::new(gamma).unwrap(),
                0.0,
                &input,
                periods,
                &times,
            );
            for (i, &w) in want.iter().enumerate() {
                let what = format!("{name}, gamma = {gamma}, t = {}", times[i]);
                assert_close(&what, got.y[i], w, 2.0, STIFF_SOLVER);
            }
        }
    }
}

#[test]
fn exact_solution_matches_radau5_on_canudas_de_wit_parameters() {
    // sigma0 = 1e5 N/m: a bimodal displacement 0 -> 8 mm -> 4 mm -> 10 mm -> 0 at 10 mm/s over
    // 10 periods (k dt up to ~1e3 per segment: stiff), and the same shape at micrometres and
    // 0.1 mm/s, in pre-sliding.
    let model = canudas();
    let cases: [(f64, f64, u32); 2] = [(1e-3, 1e-2, 10), (1e-6, 1e-4, 3)];
    for (scale, speed, periods) in cases {
        let b = Bimodal::new(0.0, 4.0 * scale, 8.0 * scale, 10.0 * scale).unwrap();
        let input = PiecewiseLinear::from_turning_points(&b.turning_points(), speed).unwrap();
        let times = merge_times(
            &uniform_times(0.0, input.period(), periods, 25),
            &input.knot_times(periods),
        );
        let want = reference_piecewise(&model, 1.0, 0.0, &input, periods, &times);
        let got = at_times(&model, Gamma::ONE, 0.0, &input, periods, &times);
        for (i, &w) in want.iter().enumerate() {
            let what = format!("{scale} m, t = {} s", times[i]);
            assert_close(&what, got.y[i], w, 1.5, STIFF_SOLVER);
        }
        // Pre-sliding stays below the breakaway force; gross sliding reaches Fc.
        let peak = got.y.iter().fold(0.0f64, |m, y| m.max(y.abs()));
        if scale < 1e-5 {
            assert!(peak < 1.0, "pre-sliding peak {peak}");
        } else {
            assert!(peak > 1.0, "sliding peak {peak}");
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The rate-independent limit.

#[test]
fn y_gamma_converges_to_y_star_like_c_over_gamma() {
    // Example 3 from x0 = 0 over 3 periods. sup |y_gamma - y*| is O(1/gamma) (the sigma1 z' /
    // gamma term, g(v / gamma) - g(0), the lag of z): gamma * sup must settle to a constant.
    let input = periodic(&[0.0, 1.0, 0.2, 1.5], 1.0);
    let times = merge_times(
        &uniform_times(0.0, input.period(), 3, 400),
        &input.knot_times(3),
    );
    let star = at_times(&paper_model(), Gamma::INFINITE, 0.0, &input, 3, &times);
    let scaled: Vec<f64> = [1e2, 1e3, 1e4, 1e5]
        .iter()
        .map(|&gamma| {
            let y = at_times(
                &paper_model(),
                Gamma::new(gamma).unwrap(),
                0.0,
                &input,
                3,
                &times,
            );
            let sup =
                y.y.iter()
                    .zip(&star.y)
                    .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
            gamma * sup
        })
        .collect();
    for w in scaled.windows(2) {
        assert!((w[1] / w[0] - 1.0).abs() < 0.02, "gamma * sup: {scaled:?}");
    }
}

#[test]
fn y_star_periods_converge_to_the_loop_like_exp_minus_a_p_k() {
    // y*_{u,k} - y° = (sigma0 x0 - y°(0)) exp(-a rho_u(t)) at every turning point, so that
    // sup_t |y*_{u,k} - y°| = |y°(0) - sigma0 x0| exp(-a P k) (at the period's start).
    let cases: [(LuGre, &[f64], &[f64]); 3] = [
        (paper_model(), &[0.0, 1.0], &[0.0, 0.5, -3.0]),
        (paper_model(), &[0.0, 1.0, 0.2, 1.5], &[0.0, 1.9, -0.4]),
        (canudas(), &[0.0, 8e-6, 4e-6, 10e-6], &[0.0, 1e-5, -2e-5]),
    ];
    for (model, tp, x0s) in cases {
        let turning = TurningPoints::new(tp).unwrap();
        let hl = HysteresisLoop::new(model.rate_independent(), &turning).unwrap();
        let input = PiecewiseLinear::from_turning_points(&turning, 1.0).unwrap();
        let (a, p, n) = (hl.model().a(), hl.period(), hl.len());
        for &x0 in x0s {
            let star = at_knots(&model, Gamma::INFINITE, x0, &input, 4);
            let gap0 = model.sigma0() * x0 - hl.turning_y()[0];
            for k in 0..4u32 {
                let mut sup: f64 = 0.0;
                for j in 0..n {
                    let got = star.y[k as usize * n + j] - hl.turning_y()[j];
                    let rho = hl.turning_rho()[j] + f64::from(k) * p;
                    let want = gap0 * (-a * rho).exp();
                    let what = format!("{tp:?}, x0 = {x0}, k = {k}, turning point {j}");
                    assert_close(&what, got, want, model.g0(), EXACT_SIMULATION);
                    sup = sup.max(got.abs());
                }
                assert_close(
                    &format!("{tp:?}, x0 = {x0}, sup at k = {k}"),
                    sup,
                    hl.transient_amplitude(x0, k),
                    model.g0(),
                    EXACT_SIMULATION,
                );
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Dahl.

/// The Dahl model in closed form: on a monotone piece from `w_k`, `w = s + (w_k - s)
/// exp(-rho |u - u_k|)`, `s` the direction; `y = Fc w`.
fn dahl_closed_form(rho: f64, fc: f64, w0: f64, u: &[f64], at: &[(usize, f64)]) -> Vec<f64> {
    // `at`: (segment, u there) in order.
    let mut w = w0;
    let mut seg = 0;
    let mut out = Vec::new();
    for &(i, ut) in at {
        while seg < i {
            let s = (u[seg + 1] - u[seg]).signum();
            w = s + (w - s) * (-rho * (u[seg + 1] - u[seg]).abs()).exp();
            seg += 1;
        }
        let s = (u[seg + 1] - u[seg]).signum();
        out.push(fc * (s + (w - s) * (-rho * (ut - u[seg]).abs()).exp()));
    }
    out
}

#[test]
fn dahl_reduces_to_its_closed_form_at_any_gamma() {
    let (rho, fc, w0) = (2.5, 0.8, -0.3);
    let model = Dahl::new(rho, fc).unwrap().to_lugre();
    let input = PiecewiseLinear::new(T.to_vec(), U.to_vec()).unwrap();
    let times = [0.0, 0.1, 0.3, 0.45, 0.99, 1.0, 1.3, 2.0, 2.55, 3.0];
    let at: Vec<(usize, f64)> = times
        .iter()
        .map(|&t| {
            let i = T.partition_point(|&k| k <= t) - 1;
            (i, U[i] + (U[i + 1] - U[i]) * (t - T[i]) / (T[i + 1] - T[i]))
        })
        .collect();
    let want = dahl_closed_form(rho, fc, w0, &U, &at);
    for gamma in [Gamma::ONE, Gamma::new(7.0).unwrap(), Gamma::INFINITE] {
        let got = at_times(&model, gamma, w0 / rho, &input, 1, &times);
        for (i, &w) in want.iter().enumerate() {
            let what = format!("gamma = {}, t = {}", gamma.value(), times[i]);
            assert_close(&what, got.y[i], w, fc, EXACT_SIMULATION);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Smooth inputs: the adaptive integrator.

fn sine_run(
    model: &LuGre,
    gamma: Gamma,
    x0: f64,
    sine: &Sine,
    periods: u32,
    times: &[f64],
    tol: f64,
) -> Trajectory {
    let mut out = Trajectory::default();
    Simulator::new(model, gamma, x0)
        .unwrap()
        .sine(sine, periods, times, Tolerance::new(tol).unwrap(), &mut out)
        .expect("finite");
    out
}

#[test]
fn adaptive_integrator_is_exact_to_tolerance_at_any_stiffness() {
    // The Dahl model is rate independent at any gamma, so on a sine its exact state is the
    // closed form in u between reversals. sigma0 / g from 1e-3 to 1e9, gamma = 3 (the adaptive
    // path), amplitude 1, period 2, phase 0.3.
    let sine = Sine::new(1.0, 2.0, 0.3, 0.5).unwrap();
    let times = uniform_times(0.0, 2.0, 2, 100);
    for rho in [1e-3, 1.0, 1e3, 1e6, 1e9] {
        let model = Dahl::new(rho, 1.0).unwrap().to_lugre();
        let w0 = 0.2;
        let got = sine_run(
            &model,
            Gamma::new(3.0).unwrap(),
            w0 / rho,
            &sine,
            2,
            &times,
            1e-10,
        );
        // Reversals of sin(pi t + 0.3) + 0.5: t = (pi/2 - 0.3 + m pi) / pi.
        let mut w = w0;
        let mut u_k = sine.u(0.0);
        let mut m = 0.0;
        for (i, &t) in times.iter().enumerate() {
            loop {
                let t_rev = (std::f64::consts::FRAC_PI_2 - 0.3 + m * std::f64::consts::PI)
                    / std::f64::consts::PI;
                if t_rev > t {
                    break;
                }
                let u_rev = if (m as i64) % 2 == 0 { 1.5 } else { -0.5 };
                let s = (u_rev - u_k).signum();
                w = s + (w - s) * (-rho * (u_rev - u_k).abs()).exp();
                u_k = u_rev;
                m += 1.0;
            }
            let u = sine.u(t);
            let s = if (m as i64) % 2 == 0 { 1.0 } else { -1.0 };
            let want = s + (w - s) * (-rho * (u - u_k).abs()).exp();
            assert_close(
                &format!("rho = {rho:e}, t = {t}"),
                got.y[i],
                want,
                1.0,
                ADAPTIVE,
            );
        }
    }
}

/// Eq. 5 on a sine by Radau5, restarted at every reversal and output time.
fn reference_sine(model: &LuGre, gamma: f64, x0: f64, sine: &Sine, times: &[f64]) -> Vec<f64> {
    let (sigma0, sigma1) = (model.sigma0(), model.sigma1());
    let atol = 1e-12 * model.g0() / sigma0;
    let f = |t: f64, z: f64| {
        let v = sine.du(t);
        -sigma0 * v.abs() / model.g(v / gamma) * z + v
    };
    let stops = merge_times(&sine.reversals(0.0, times[times.len() - 1]), times);
    let (mut t, mut z) = (0.0, x0);
    let mut ys = Vec::new();
    for &stop in &stops {
        z = radau5(&f, t, z, stop, atol);
        t = stop;
        if times.contains(&stop) {
            let v = sine.du(t);
            let dz = f(t, z);
            ys.push(sigma0 * z + sigma1 / gamma * dz + model.f(v / gamma));
        }
    }
    ys
}

#[test]
fn adaptive_integrator_matches_radau5_on_sines() {
    let cases: [(&str, LuGre, Sine, f64); 4] = [
        (
            "paper, gamma 1",
            paper_model(),
            Sine::new(1.0, 4.0, 0.0, 0.5).unwrap(),
            1.0,
        ),
        (
            "paper, gamma 10",
            paper_model(),
            Sine::new(1.0, 4.0, 0.0, 0.5).unwrap(),
            10.0,
        ),
        // 1 mm at 1 Hz: u' up to 6 mm/s = 6 vs, stiff (k ~ 400 /s) and Stribeck near reversals.
        (
            "Canudas, 1 mm",
            canudas(),
            Sine::new(1e-3, 1.0, 0.2, 0.0).unwrap(),
            1.0,
        ),
        (
            "Canudas, 3 um",
            canudas(),
            Sine::new(3e-6, 1.0, 0.0, 0.0).unwrap(),
            1.0,
        ),
    ];
    for (name, model, sine, gamma) in cases {
        let times = uniform_times(0.0, sine.period(), 2, 50);
        let want = reference_sine(&model, gamma, 0.0, &sine, &times);
        let got = sine_run(
            &model,
            Gamma::new(gamma).unwrap(),
            0.0,
            &sine,
            2,
            &times,
            1e-10,
        );
        for (i, &w) in want.iter().enumerate() {
            let what = format!("{name}, t = {}", times[i]);
            assert_close(&what, got.y[i], w, model.g0(), ADAPTIVE);
        }
    }
}

#[test]
fn sine_in_the_rate_independent_limit_tends_to_the_loop() {
    // gamma = inf on a sine is eq. 6 in closed form; after a few periods y* at the extremes is
    // the loop y° of the turning points (A + offset, -A + offset) up to exp(-a P k).
    let model = paper_model();
    let sine = Sine::new(0.7, 3.0, 0.0, 0.1).unwrap();
    let quarter = 0.75;
    let times = [quarter + 3.0 * 5.0, 3.0 * 3.0 * 2.0 - quarter + 3.0];
    let got = sine_run(&model, Gamma::INFINITE, 0.0, &sine, 7, &times, 1e-10);
    let hl = HysteresisLoop::new(
        model.rate_independent(),
        &TurningPoints::new(&[0.8, -0.6]).unwrap(),
    )
    .unwrap();
    // exp(-a P k) = exp(-0.5 * 2.8 * 5) ~ 1e-3: compare to that.
    assert_close("max", got.y[0], hl.turning_y()[0], 2.0, 2e-3);
    assert_close("min", got.y[1], hl.turning_y()[1], 2.0, 2e-3);
}

// ---------------------------------------------------------------------------------------------
// The paper's Example 1.

#[test]
fn example_1_steady_state_is_what_the_response_from_rest_tends_to() {
    // From rest, x's transient is (0 - x°(0)) exp(-rho_u(t)) exactly (x relaxes in the
    // variation of u: 4 per period), and y's decays like exp(-t) and exp(-rho_u(t)): after 8
    // periods of gamma = 20 both are below 1e-13 and the response is the steady state, which was
    // computed from the period map instead.
    let gamma = 20.0;
    let ex = paper_example_1(gamma, 8, 200, Tolerance::new(1e-11).unwrap()).unwrap();
    let n = ex.t.len();
    for i in n - 201..n {
        assert_close("x", ex.x[i], ex.x_steady[i], 1.0, 1e-12);
        assert_close("y", ex.y[i], ex.y_steady[i], 1.0, 1e-9);
    }
    let variation = |t: f64| {
        let (k, s) = ((t / gamma).floor(), (t / gamma).fract());
        let u = (std::f64::consts::TAU * s).sin();
        4.0 * k
            + if s <= 0.25 {
                u
            } else if s <= 0.75 {
                2.0 - u
            } else {
                4.0 + u
            }
    };
    let x_transient = ex.x_transient();
    for (i, &t) in ex.t.iter().enumerate() {
        let want = -ex.x_steady[0] * (-variation(t)).exp();
        assert_close(
            &format!("x transient at t = {t}"),
            x_transient[i],
            want,
            1.0,
            EXACT_SIMULATION,
        );
    }
    // ... while in the first period y's transient is there.
    let transient = ex.y_transient();
    assert!(transient[20].abs() > 1e-3, "{}", transient[20]);
}

// mpmath, mp.dps = 30 (the closed form of x written out again, and y by quadrature):
//   # Paper Example 1 (eq. 18), gamma = 20, from rest: x in closed form between reversals of
//   # u = sin(2 pi t / gamma), y(t) = integral_0^t exp(-(t - s)) x(s) ds by mpmath.quad split at
//   # the reversals (t = 5, 15, 25, 35).
//   from mpmath import mp, mpf, sin, exp, pi, quad, nstr
//   mp.dps = 30
//   gamma = mpf(20); w = 2 * pi / gamma
//   revs = [gamma / 4 + m * gamma / 2 for m in range(4)]
//   def stretch(s):
//       # (start time, u there, x there, direction) of the stretch holding s
//       t0, u0, x0, d = mpf(0), mpf(0), mpf(0), 1
//       for r in revs:
//           if s <= r: break
//           ur = mpf(d)                       # the extreme: +1 at a maximum, -1 at a minimum
//           x0 = d + (x0 - d) * exp(-abs(ur - u0)); t0, u0, d = r, ur, -d
//       return t0, u0, x0, d
//   def x(s):
//       t0, u0, x0, d = stretch(s)
//       return d + (x0 - d) * exp(-abs(sin(w * s) - u0))
//   def y(t):
//       pts = [mpf(0)] + [r for r in revs if r < t] + [t]
//       return sum(quad(lambda s: exp(-(t - s)) * x(s), [a, b]) for a, b in zip(pts, pts[1:]))
//   for t in [2.5, 5, 10, 17.5, 20, 30, 40]:
//       print(f"({t!r}, {nstr(x(mpf(t)), 17)}, {nstr(y(mpf(t)), 17)}),")
/// `(t, x, y)` from that script.
const EXAMPLE_1: [(f64, f64, f64); 7] = [
    (2.5, 0.50693130860476021, 0.35584361713130722),
    (5.0, 0.63212055882855768, 0.59209584241763953),
    (10.0, -0.39957640089372805, -0.17395926297017427),
    (17.5, -0.32740203529014751, -0.54098391257484091),
    (20.0, 0.34549961550410906, 0.099440602117325045),
    (30.0, -0.35281811257133867, -0.10952792048957467),
    (40.0, 0.35182766169787883, 0.10816275029549936),
];

#[test]
fn example_1_matches_mpmath() {
    // gamma = 20, 8 samples per period: t = 2.5 j exactly.
    let ex = paper_example_1(20.0, 2, 8, Tolerance::new(1e-11).unwrap()).unwrap();
    for (t, x, y) in EXAMPLE_1 {
        let j = (t / 2.5) as usize;
        assert_eq!(ex.t[j], t);
        assert_close(&format!("x at t = {t}"), ex.x[j], x, 1.0, EXACT_SIMULATION);
        assert_close(&format!("y at t = {t}"), ex.y[j], y, 1.0, ADAPTIVE);
    }
}

#[test]
fn example_1_loops_approach_the_dahl_loop_as_gamma_grows() {
    // As gamma -> inf the lag vanishes: the steady y tends to x (the Dahl loop) like 1/gamma.
    let sup = |gamma: f64| {
        let ex = paper_example_1(gamma, 1, 400, Tolerance::new(1e-10).unwrap()).unwrap();
        ex.y_steady
            .iter()
            .zip(&ex.x_steady)
            .fold(0.0f64, |m, (y, x)| m.max((y - x).abs()))
    };
    let s: Vec<f64> = [20.0, 200.0, 2000.0].iter().map(|&g| sup(g)).collect();
    assert!(s[0] > 5.0 * s[1] && s[1] > 5.0 * s[2], "{s:?}");
}

// ---------------------------------------------------------------------------------------------
// Errors: typed, carrying the offending value.

#[test]
fn invalid_requests_are_typed_errors() {
    let model = paper_model();
    assert_eq!(Gamma::new(0.0), Err(SimulateError::BadGamma { value: 0.0 }));
    assert_eq!(
        Gamma::new(-1.0),
        Err(SimulateError::BadGamma { value: -1.0 })
    );
    assert!(matches!(
        Gamma::new(f64::NAN),
        Err(SimulateError::BadGamma { .. })
    ));
    assert!(Gamma::new(f64::INFINITY).is_ok());
    assert!(matches!(
        Simulator::new(&model, Gamma::ONE, f64::NAN),
        Err(SimulateError::BadX0 { .. })
    ));
    let stiff = canudas();
    assert_eq!(
        Simulator::new(&stiff, Gamma::ONE, 1e305).unwrap_err(),
        SimulateError::X0Overflow {
            x0: 1e305,
            sigma0: 1e5
        }
    );
    assert!(matches!(
        PiecewiseLinear::new(vec![], vec![]),
        Err(SimulateError::Input(lugre::InputError::Empty))
    ));
    assert_eq!(
        PiecewiseLinear::new(vec![1.0], vec![0.0]),
        Err(SimulateError::TooFewSamples { count: 1 })
    );
    assert!(matches!(
        PiecewiseLinear::new(vec![0.0, 1.0, 1.0], vec![0.0, 1.0, 0.0]),
        Err(SimulateError::Input(lugre::InputError::Data(
            lugre::DataError::TimesNotIncreasing { index: 2, .. }
        )))
    ));
    let open = PiecewiseLinear::new(vec![0.0, 1.0], vec![0.0, 1.0]).unwrap();
    let sim = Simulator::new(&model, Gamma::ONE, 0.0).unwrap();
    let mut out = Trajectory::default();
    assert_eq!(
        sim.at_knots(&open, 0, &mut out),
        Err(SimulateError::BadPeriods { value: 0 })
    );
    assert!(matches!(
        sim.at_knots(&open, 2, &mut out),
        Err(SimulateError::NotClosed { periods: 2, .. })
    ));
    for (times, want) in [
        (vec![0.5, 0.5], "strictly increasing"),
        (vec![0.5, f64::NAN], "t[1] must be a finite number, got NaN"),
        (vec![0.5, 1.5], "outside the run [0, 1]"),
        (vec![-0.1], "outside"),
    ] {
        let e = sim.at_times(&open, 1, &times, &mut out).unwrap_err();
        assert!(e.to_string().contains(want), "{e}");
    }
    assert!(out.is_empty(), "nothing half-written");
    assert!(matches!(
        Sine::new(0.0, 1.0, 0.0, 0.0),
        Err(SimulateError::BadSine {
            name: "amplitude",
            ..
        })
    ));
    assert!(matches!(
        Sine::new(1.0, -1.0, 0.0, 0.0),
        Err(SimulateError::BadSine { name: "period", .. })
    ));
    assert!(matches!(
        Sine::new(1.0, 1.0, f64::INFINITY, 0.0),
        Err(SimulateError::BadSine { name: "phase", .. })
    ));
    assert!(
        Tolerance::new(0.0).is_err()
            && Tolerance::new(1.0).is_err()
            && Tolerance::new(1e-8).is_ok()
    );
}
