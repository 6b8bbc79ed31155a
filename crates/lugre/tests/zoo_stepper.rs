//! `ZooStepper` (a finite-rate model of the zoo stepped at the input's rate): its forces are
//! `ZooModel::simulate`'s bit for bit, its work and stored energy are an independent
//! integration's, and its dissipation is the work minus the change of the stored energy.

use lugre::zoo::ZooModel;

// Made by `python3 crates/lugre/tests/reference/zoo_stepper_energy.py` (scipy 1.17.1: each
// interval by solve_ivp with the work as a state, the mode changes as terminal events, Radau
// and DOP853 at rtol 1e-12), on the table's defaults with sigma2 = 0.2; pasted as printed.
const T: [f64; 31] = [
    0.0,
    1.7333010847678838,
    3.526108402106238,
    5.104383749909855,
    5.362341231499535,
    5.652700740690417,
    6.445647802725568,
    8.222454602148574,
    10.134037720731268,
    11.292738690352474,
    12.905973418622303,
    13.698778909740192,
    15.371328850164597,
    17.04146469970389,
    17.372362530059995,
    19.305002313727073,
    20.123676613698468,
    20.64316954460286,
    21.778722181445406,
    23.09855349969086,
    23.32877477174677,
    23.796386042743936,
    24.615699418402155,
    25.215006594438087,
    26.500565434271238,
    26.854616048092467,
    28.377299459310258,
    29.43863991797845,
    30.16748981253015,
    32.11311272455733,
    34.08641088489198,
];
const U: [f64; 31] = [
    0.0,
    1.601563866525499,
    3.444808064973993,
    1.787885597808497,
    1.1418606991805116,
    -0.2812969978480018,
    -0.38149427726303076,
    1.3543523249670826,
    1.4575674236272835,
    3.234467734919242,
    3.92121504228983,
    2.450798318253629,
    4.314603417241217,
    4.922484860486107,
    5.161256615097777,
    3.93188706958053,
    5.38709284281143,
    6.825691864854184,
    8.083699808249781,
    6.351589260101111,
    7.104992199420635,
    8.955147846385334,
    9.37967583819897,
    9.507393046780342,
    11.489569540513251,
    13.235438861223786,
    14.696702076508856,
    16.623752515633644,
    16.298726820004436,
    15.522652812397759,
    14.302316151210102,
];
// GMS: largest |Radau - DOP853| / max|W| = 9.9e-15
const GMS_WORK: [f64; 31] = [
    0.0,
    2.4066924828054854,
    5.427013239776873,
    6.2602738383394945,
    7.619588601920643,
    12.455824581916609,
    12.652197757754495,
    13.407333837713498,
    13.431262635512637,
    16.6976027534494,
    17.995421337029466,
    19.524802670909448,
    22.998501318199093,
    24.183922325952565,
    24.458689327439387,
    24.19592730576859,
    27.480366765898136,
    29.544721810524226,
    31.753113381569207,
    33.17544500555404,
    36.17053442663149,
    41.12983556623971,
    42.10077930483445,
    42.3734557664155,
    44.596866057661714,
    47.187497405134714,
    49.794596364089884,
    52.38158418000204,
    52.23041244598524,
    52.19446892541081,
    53.20388797408616,
];
const GMS_STORED: [f64; 31] = [
    0.0,
    0.7937057910943373,
    1.2096519204586302,
    0.13004826745612397,
    0.13838721930374653,
    0.5060693599651741,
    1.217500561201689,
    0.08392147494570669,
    0.10326772236282823,
    0.8862678636573986,
    1.7436585426500564,
    0.3009992557240016,
    1.1575762914003396,
    1.8851821661575108,
    1.4933761936051275,
    0.3220106269563827,
    0.8968942645100152,
    0.7422552984768154,
    1.1612247195705248,
    0.12498013829318706,
    0.2944894993194071,
    0.6815984357641296,
    1.6637147496626308,
    2.1267778610527817,
    0.9671680516448351,
    0.6739136174073127,
    1.2552307592719847,
    0.8872445541601366,
    0.5621411994753027,
    0.1528694974120337,
    0.2894370051871619,
];
// ELASTOPLASTIC: largest |Radau - DOP853| / max|W| = 5.8e-14
const ELASTOPLASTIC_WORK: [f64; 31] = [
    0.0,
    2.5500312789540063,
    5.436873636666428,
    6.693031532989629,
    8.767675896951559,
    12.13454785471104,
    12.250833213718774,
    13.92941997455102,
    14.00954067656616,
    17.079973549867674,
    18.148324188660133,
    20.410587347285993,
    23.599924184908932,
    24.53744992753148,
    24.921658606863495,
    24.84445052757458,
    28.031466760282633,
    30.34208876595608,
    32.352302951276286,
    34.38289670637579,
    37.27610708412187,
    43.03302734905289,
    43.67921540321138,
    43.8617986551421,
    46.85574514598202,
    49.61154983340075,
    51.94741448492196,
    54.805600484222445,
    54.64479501311935,
    54.64427459760063,
    56.11866807078841,
];
const ELASTOPLASTIC_STORED: [f64; 31] = [
    0.0,
    0.7157288474899629,
    0.8846247064161474,
    0.05339621656658645,
    0.3732880479395763,
    0.4896743856315035,
    0.5746361169044281,
    0.21895465010466617,
    0.29103350709508363,
    0.6906724153759377,
    1.0115121038698347,
    0.0011561398253920874,
    0.718489445570265,
    1.0244286056459926,
    1.0379790476354724,
    0.022355340839864474,
    0.5773023551628443,
    0.5679238451195019,
    0.8046464146949576,
    0.10743072063277415,
    0.04201272886424244,
    0.49125702559118745,
    0.7600096009675478,
    0.8496050217829813,
    0.7582676676742393,
    0.5479397516866702,
    0.8689927877781514,
    0.7108989883449731,
    0.3761618965738517,
    0.004167114737049747,
    0.5473002719035164,
];

/// The model of the reference: the table's defaults with `sigma2 = 0.2`.
fn model(name: &str) -> ZooModel {
    ZooModel::new(name, &[("sigma2", &[0.2])]).unwrap()
}

/// Each step's force, cumulative work, stored energy and dissipation along `T`, `U`.
fn run(name: &str) -> Vec<[f64; 4]> {
    let mut s = model(name).stepper(U[0]).unwrap();
    let mut out = vec![[s.force(), s.work(), s.stored_energy(), s.dissipation()]];
    for j in 1..T.len() {
        s.step(U[j], T[j] - T[j - 1]).unwrap();
        out.push([s.force(), s.work(), s.stored_energy(), s.dissipation()]);
    }
    out
}

#[test]
fn the_steppers_forces_are_simulates_bit_for_bit() {
    for name in ["maxwell-slip", "elastoplastic"] {
        let m = model(name);
        let got = run(name);
        // The force after a step is the one at the last sample of the input up to it (the
        // velocity before it); GMS reports that one at every sample.
        for j in 1..T.len() {
            let prefix = m.simulate(&T[..=j], &U[..=j]).unwrap();
            assert_eq!(got[j][0].to_bits(), prefix[j].to_bits(), "{name} {j}");
        }
        if name == "maxwell-slip" {
            let whole = m.simulate(&T, &U).unwrap();
            assert!(got
                .iter()
                .zip(&whole)
                .all(|(a, b)| a[0].to_bits() == b.to_bits()));
        }
    }
}

#[test]
fn the_energies_are_the_independent_integrations() {
    // Radau and DOP853 agree to 6e-14 of the largest work; allowed 1e-11 of it.
    for (name, work, stored) in [
        ("maxwell-slip", &GMS_WORK, &GMS_STORED),
        ("elastoplastic", &ELASTOPLASTIC_WORK, &ELASTOPLASTIC_STORED),
    ] {
        let got = run(name);
        let scale = work.iter().fold(0.0_f64, |m, w| m.max(w.abs()));
        for (j, g) in got.iter().enumerate() {
            assert!(
                (g[1] - work[j]).abs() <= 1e-11 * scale,
                "{name} W[{j}] {} {}",
                g[1],
                work[j]
            );
            assert!(
                (g[2] - stored[j]).abs() <= 1e-11 * scale,
                "{name} V[{j}] {} {}",
                g[2],
                stored[j]
            );
        }
    }
}

/// `D = W - ΔV` to rounding; the elasto-plastic model dissipates on every step of this input
/// and GMS over the run. A GMS step may return energy (here three of 30): the micro-damping
/// term `(sigma1 / K) v sum_i F_i'` is negative where a slipping element relaxes down to a
/// level that fell, and (G2) pulls a slipping element up to a level that rose faster than its
/// spring would (docs/mathematics.md, (G7)): the model is not passive step by step.
#[test]
fn the_dissipation_is_the_work_less_the_stored_energy() {
    for name in ["maxwell-slip", "elastoplastic"] {
        let got = run(name);
        let scale = got.iter().fold(0.0_f64, |m, g| m.max(g[1].abs()));
        for (j, g) in got.iter().enumerate() {
            assert!((g[3] - (g[1] - g[2])).abs() <= 1e-15 * scale, "{name} {j}");
            assert!(g[3] >= -1e-15 * scale, "{name} {j}");
            if j > 0 && name == "elastoplastic" {
                assert!(g[3] - got[j - 1][3] >= -1e-15 * scale, "{name} {j}");
            }
        }
    }
}

#[test]
fn a_rate_independent_model_and_bad_steps_are_refused() {
    let e = ZooModel::new("bouc-wen", &[])
        .unwrap()
        .stepper(0.0)
        .unwrap_err();
    assert_eq!(
        e.to_string(),
        "the Bouc-Wen model has no finite-rate form: it is rate-independent, stepped by its exact segment map"
    );
    let mut s = model("elastoplastic").stepper(0.0).unwrap();
    let e = s.step(1.0, 0.0).unwrap_err().to_string();
    assert_eq!(e, "dt must be >= 0, with a finite velocity (u_to - u) / dt for the move from u = 0 to 1, got 0");
    assert!(s
        .step(f64::NAN, 1.0)
        .unwrap_err()
        .to_string()
        .starts_with("u must be a finite number"));
    assert!(s.step(1.0, -1.0).is_err() && s.step(1.0, f64::INFINITY).is_err());
    s.step(0.0, 0.0).unwrap();
    assert_eq!((s.input(), s.force(), s.work()), (0.0, 0.0, 0.0));
}
