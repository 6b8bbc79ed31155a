//! `ZooModel::simulate`: the elasto-plastic model at finite rate against an independent scipy
//! solve, its slow limit, and the rate-independent models' exact path.

use lugre::zoo::ZooModel;
use lugre::TurningPoints;

// Made by `python3 crates/lugre/tests/reference/elastoplastic_simulate.py` (scipy 1.17.1;
// Radau at rtol 1e-12 split at the blend's kinks, DOP853 agreeing as printed): `(t, u, F)`.
const UNIT: &[(f64, f64, f64)] = &[
    (0.0, 0.0, 1.6887344046569692),
    (1.683853354572955, 2.0311293516174285, 1.4409009713426202),
    (2.3882007678632613, 2.334253489369157, 0.5716853358123563),
    (3.344956076481617, 1.9453193323535662, 0.8429637188248065),
    (5.216174591123141, 2.069410854105394, 1.4477183550121533),
    (6.599338111772776, 2.7611848178522918, 1.3186112266060543),
    (7.193804824177826, 2.8344673582763935, -0.25377559841943387),
    (8.479565013396297, 1.4704487241304713, -1.6533746854641114),
    (10.375883293999717, -0.5894841168182443, -1.4910534857378601),
    (11.423574000744642, -1.8466194535141587, -0.9417649960983343),
    (12.07938859730269, -1.8201217499685183, -0.6940421206542025),
    (13.684812926206286, -1.5015698584109645, -0.9849673342795435),
    (15.437409393812416, -1.9205087857004115, -1.4288512929670927),
    (16.202471489501963, -2.716684216754196, -0.8299556920615212),
    (17.074838179987058, -2.5967093086966475, 0.25790336169171857),
    (18.907088029884697, -1.078005249531611, 2.2721405062737157),
    (20.384681964472193, 0.7707889130271832, 1.5407912838311886),
    (20.993783663761246, 1.5796813439110404, 0.6723001066075125),
    (22.181342164073673, 1.3066332031304215, 0.5993224852147943),
    (24.08833095168522, 1.1406938358019738, 1.3936072606117293),
    (25.23147367517751, 1.8283313549037719, 1.5114838553429553),
    (25.852020831072824, 2.6285768935880647, 0.6815078319593117),
    (27.371081174343633, 2.2720405608865883, -0.586271431306623),
    (29.181200130720896, 0.6690059468007257, -2.2228458778097253),
    (30.017803300090563, -0.8766435200268793, -1.4596970034799606),
    (30.814212154885173, -1.2439582112858134, -0.8260055599768942),
    (32.59449442895734, -0.8209795060227263, -0.7768885915064329),
    (34.16143767128931, -0.8678710687608535, -2.1004303762602823),
    (34.79948261365985, -1.7692725417432196, -1.472652516615042),
    (35.8902334511916, -2.475342151795415, -0.658845197415462),
    (37.79322526443148, -1.8691697745003153, 1.3043359067573324),
    (39.034205626987706, -0.2709999437974445, 2.140201250448958),
    (39.63353807499817, 0.8966861513517853, 0.9421929884394866),
    (41.06022757582314, 0.8598264014230639, 0.5851532673883022),
    (42.91536418905042, 0.38762764678489203, 0.9149773029706718),
    (43.83273764640352, 0.6796620953637756, 2.1836624427745606),
    (44.56331523052944, 1.7164844452012846, 1.333627859479367),
    (46.279791210174466, 2.241834420322329, 0.5746633034375356),
    (47.9290079026518, 1.404460569593414, -2.6248184259969114),
    (
        48.609658177293625,
        -0.08953973239077478,
        -1.5302930841250042,
    ),
    (49.607156639698424, -0.8289548946025975, -0.7572663179307202),
    (
        51.491573230897195,
        -0.45240083871846437,
        -0.21456949739919887,
    ),
    (52.830592598760994, -0.025924945257330245, -1.50589826262129),
    (53.423236696692385, -0.564344866026072, -1.6630227846375836),
    (54.753610706377, -1.6425053428272263, -1.2038287183722503),
    (56.64025511118098, -1.9207658076396186, 0.19019640196006682),
    (57.645824848730264, -0.9003297414798567, 2.4604634235769294),
    (58.32216743103828, 0.3898075197883868, 2.1383112933195383),
];
const TABLE1: &[(f64, f64, f64)] = &[
    (0.0, 0.0, 0.9548217891826984),
    (
        0.04490275612194547,
        0.00013540862344116192,
        1.0862093516963178,
    ),
    (
        0.06368535380968697,
        0.00015561689929127716,
        0.8200631845696303,
    ),
    (
        0.08919882870617646,
        0.00012968795549023776,
        -0.9940562536329058,
    ),
    (
        0.13909798909661708,
        0.00013796072360702625,
        0.17662163099568076,
    ),
    (
        0.17598234964727402,
        0.00018407898785681944,
        1.1466589705130317,
    ),
    (
        0.19183479531140868,
        0.00018896449055175958,
        0.420747094383193,
    ),
    (
        0.2261217336905679,
        9.802991494203142e-05,
        -1.0014079068554458,
    ),
    (
        0.2766902211733258,
        -3.9298941121216286e-05,
        -1.001274640398079,
    ),
    (
        0.3046286400198572,
        -0.0001231079635676106,
        -0.9680790687126056,
    ),
    (
        0.3221170292614052,
        -0.00012134144999790122,
        -0.6663455118043295,
    ),
    (
        0.36492834469883445,
        -0.00010010465722739763,
        0.9095742995879784,
    ),
    (
        0.4116642505016645,
        -0.0001280339190466941,
        -1.0354939448220146,
    ),
    (
        0.43206590638671916,
        -0.00018111228111694638,
        -0.8926584161109673,
    ),
    (
        0.45532901813298826,
        -0.00017311395391310982,
        0.4544225092990145,
    ),
    (
        0.5041890141302586,
        -7.186701663544074e-05,
        1.0013530377095206,
    ),
    (
        0.5435915190525918,
        5.138592753514555e-05,
        1.0013351750541906,
    ),
    (
        0.5598342310336332,
        0.00010531208959406937,
        0.818007489472684,
    ),
    (
        0.5915024577086313,
        8.710888020869477e-05,
        -0.8637202688245419,
    ),
    (
        0.6423554920449391,
        7.604625572013159e-05,
        -0.8311757305243328,
    ),
    (0.6728392980047336, 0.0001218887569935848, 1.000472923531131),
    (
        0.6893872221619421,
        0.00017523845957253764,
        0.8144330596692618,
    ),
    (
        0.729895497982497,
        0.00015146937072577256,
        -1.0376938517920768,
    ),
    (
        0.7781653368192241,
        4.460039645338171e-05,
        -1.0001343888911813,
    ),
    (
        0.8004747546690818,
        -5.844290133512529e-05,
        -1.0766188674094421,
    ),
    (
        0.8217123241302714,
        -8.293054741905424e-05,
        -0.9356297125887726,
    ),
    (
        0.8691865181055292,
        -5.4731967068181755e-05,
        1.1687351840237974,
    ),
    (
        0.9109716712343817,
        -5.785807125072357e-05,
        -0.23848113156886783,
    ),
    (
        0.9279862030309295,
        -0.00011795150278288132,
        -1.024032681397516,
    ),
    (
        0.9570728920317758,
        -0.0001650228101196943,
        -0.7839949534351678,
    ),
    (
        1.0078193403848394,
        -0.00012461131830002103,
        0.9970750464247837,
    ),
    (
        1.0409121500530059,
        -1.8066662919829636e-05,
        1.0019368244566864,
    ),
    (1.056894348666618, 5.977907675678569e-05, 0.979549132438581),
    (
        1.0949394020219503,
        5.7321760094870924e-05,
        0.5527855573545322,
    ),
    (
        1.1444097117080114,
        2.5841843118992803e-05,
        -1.010562118433419,
    ),
    (
        1.1688730039040938,
        4.5310806357585045e-05,
        1.5840893481875273,
    ),
    (
        1.1883550728141186,
        0.00011443229634675232,
        1.1066751808515005,
    ),
    (
        1.2341277656046525,
        0.00014945562802148857,
        0.8683743539203794,
    ),
    (
        1.278106877404048,
        9.363070463956094e-05,
        -0.9320719177628652,
    ),
    (
        1.2962575513944967,
        -5.969315492718319e-06,
        -1.0114297933317393,
    ),
    (
        1.3228575103919582,
        -5.526365964017317e-05,
        -0.8578395131723583,
    ),
    (
        1.3731086194905922,
        -3.0160055914564295e-05,
        1.1946029218569667,
    ),
    (
        1.4088158026336266,
        -1.7283296838220165e-06,
        0.5387909697119215,
    ),
    (
        1.4246196452451307,
        -3.7622991068404806e-05,
        -1.0036143247883849,
    ),
    (
        1.460096285503387,
        -0.00010950035618848175,
        -1.0785809254723788,
    ),
    (
        1.5104068029648259,
        -0.00012805105384264124,
        -0.5750972472905921,
    ),
    (
        1.5372219959661406,
        -6.002198276532378e-05,
        1.001892919028261,
    ),
    (
        1.5552577981610207,
        2.5987167985892453e-05,
        1.0019075177631447,
    ),
];
// // UNIT: largest |Radau - DOP853| / max|F| = 6.8e-13

/// Relative to the largest force: the references' own agreement is 7e-13.
const TOL: f64 = 5e-12;

fn check(model: &ZooModel, reference: &[(f64, f64, f64)]) {
    let t: Vec<f64> = reference.iter().map(|r| r.0).collect();
    let u: Vec<f64> = reference.iter().map(|r| r.1).collect();
    let force = model.simulate(&t, &u).unwrap();
    let scale = reference.iter().map(|r| r.2.abs()).fold(0.0, f64::max);
    for (i, (f, r)) in force.iter().zip(reference).enumerate() {
        assert!(
            (f - r.2).abs() <= TOL * scale,
            "sample {i}: {f} against {}",
            r.2
        );
    }
}

#[test]
fn elastoplastic_at_unit_stiffness_matches_scipy() {
    let model = ZooModel::new(
        "elastoplastic",
        &[
            ("sigma0", &[1.0]),
            ("sigma1", &[1.0]),
            ("sigma2", &[0.4]),
            ("fc", &[1.0]),
            ("fs", &[2.0]),
            ("vs", &[0.5]),
            ("beta", &[2.0]),
            ("zba", &[0.5]),
        ],
    )
    .unwrap();
    check(&model, UNIT);
}

#[test]
fn elastoplastic_with_table_i_matches_scipy() {
    let model = ZooModel::new(
        "elastoplastic",
        &[
            ("sigma0", &[1e5]),
            ("sigma1", &[1e5f64.sqrt()]),
            ("sigma2", &[0.4]),
            ("fc", &[1.0]),
            ("fs", &[1.5]),
            ("vs", &[1e-3]),
            ("beta", &[2.0]),
            ("zba", &[0.5e-5]),
        ],
    )
    .unwrap();
    check(&model, TABLE1);
}

/// Turning points 0 -> a -> b -> ... reached at unequal speeds: `(t, u)`.
fn zigzag(turning: &[f64], per_segment: usize) -> (Vec<f64>, Vec<f64>) {
    let (mut t, mut u) = (vec![0.0], vec![0.0]);
    let mut from = 0.0;
    for (k, &to) in turning.iter().enumerate() {
        let duration = 0.3 + k as f64;
        let t0 = *t.last().unwrap();
        for j in 1..=per_segment {
            let f = j as f64 / per_segment as f64;
            t.push(t0 + duration * f);
            u.push(from + (to - from) * f);
        }
        from = to;
    }
    (t, u)
}

#[test]
fn without_rate_terms_the_finite_rate_is_the_slow_path() {
    // sigma1 = sigma2 = 0 and fc = fs (g constant): z_ss = z_max at every speed.
    for sigma0 in [1.0, 1e8] {
        let fs = 2.0;
        let zba = 0.4 * fs / sigma0;
        let model = ZooModel::new(
            "elastoplastic",
            &[
                ("sigma0", &[sigma0]),
                ("fc", &[fs]),
                ("fs", &[fs]),
                ("zba", &[zba]),
                ("sigma1", &[0.0]),
                ("sigma2", &[0.0]),
            ],
        )
        .unwrap();
        let scale = fs / sigma0;
        let turning: Vec<f64> = [3.0, -2.0, 1.0, 0.5, 4.0, -5e3]
            .iter()
            .map(|x| x * scale)
            .collect();
        let (t, u) = zigzag(&turning, 7);
        let rate = model.simulate(&t, &u).unwrap();
        let slow = model.exact_path(&u).unwrap();
        for (i, (a, b)) in rate.iter().zip(&slow).enumerate() {
            assert!((a - b).abs() <= 1e-13 * fs, "{sigma0} sample {i}: {a} {b}");
        }
    }
}

#[test]
fn a_huge_stretch_at_high_stiffness_reaches_steady_sliding() {
    // sigma0 = 1e8: one interval spanning 1e6 steady deflections ends at F = g(v) + sigma2 v.
    let model = ZooModel::new(
        "elastoplastic",
        &[("sigma0", &[1e8]), ("zba", &[1e-9]), ("sigma1", &[1e4])],
    )
    .unwrap();
    let force = model.simulate(&[0.0, 1.0], &[0.0, 0.02]).unwrap();
    let lugre::zoo::ZooKind::ElastoPlastic(ep) = model.kind() else {
        unreachable!()
    };
    let p = ep.lugre_params();
    let g = p.fc + (p.fs - p.fc) * (-(0.02 / p.vs).powf(p.beta)).exp();
    assert!(
        (force[1] - (g + p.sigma2 * 0.02)).abs() <= 1e-12 * g,
        "{force:?}"
    );
    // At the start, at rest: only the rate terms, sigma1 v + sigma2 v.
    assert!((force[0] - (1e4 + p.sigma2) * 0.02).abs() <= 1e-12 * 200.0);
}

#[test]
fn rate_independent_models_follow_their_exact_path_whatever_the_times() {
    let rate_independent = lugre::zoo::MODELS.iter().filter(|m| !m.finite_rate);
    for name in rate_independent.map(|m| m.name) {
        let model = ZooModel::new(name, &[]).unwrap();
        let (t, u) = zigzag(&[3.0, -2.0, 1.0, 0.5, 4.0], 5);
        let fast: Vec<f64> = t.iter().map(|t| t * 1e-3).collect();
        let a = model.simulate(&t, &u).unwrap();
        assert_eq!(a, model.simulate(&fast, &u).unwrap(), "{name}");
        assert_eq!(a, model.exact_path(&u).unwrap(), "{name}");
        // The path through the turning points alone: the same force there.
        let ends = model.exact_path(&[0.0, 3.0, -2.0, 1.0, 0.5, 4.0]).unwrap();
        for (k, f) in ends.iter().enumerate() {
            assert!((a[5 * k] - f).abs() <= 1e-13 * 4.0, "{name} {k}");
        }
    }
}

#[test]
fn bad_samples_are_named() {
    let model = ZooModel::new("bouc-wen", &[]).unwrap();
    let message = |t: &[f64], u: &[f64]| model.simulate(t, u).unwrap_err().to_string();
    let m = message(&[0.0, 1.0], &[0.0]);
    assert!(
        m.contains("t and u") && m.contains("2") && m.contains("1"),
        "{m}"
    );
    let m = message(&[0.0, 1.0, 1.0], &[0.0, 1.0, 2.0]);
    assert!(m.contains('t') && m.contains("increasing"), "{m}");
    let m = message(&[0.0, 1.0], &[0.0, f64::NAN]);
    assert!(m.contains('u') && m.contains("NaN"), "{m}");
    assert!(!message(&[], &[]).is_empty());
}

/// The table's `finite_rate` is what `simulate` does: a model without it gives one answer at
/// any time scale, one with it answers to the rate (a thousand times faster, another force).
#[test]
fn the_rate_matters_exactly_for_the_models_with_a_finite_rate_form() {
    use lugre::zoo::MODELS;
    let u = [0.0, 0.3, 1.5, -2.0, 0.7, 2.5];
    let t: Vec<f64> = (0..u.len()).map(|i| i as f64).collect();
    let fast: Vec<f64> = t.iter().map(|t| t * 1e-3).collect();
    for spec in MODELS {
        let model = ZooModel::new(spec.name, &[]).unwrap();
        let slow = model.simulate(&t, &u).unwrap();
        let quick = model.simulate(&fast, &u).unwrap();
        assert_eq!(slow != quick, spec.finite_rate, "{}", spec.name);
    }
}

/// Turning points are simulated at LuGre's default output density (`Drive::zoo_samples`): the
/// same piecewise-linear motion seen more often, so every model's force at the turning points
/// is the one of the turning points alone (each interval map composes with itself); a count
/// beyond the limit is refused before allocating.
#[test]
fn turning_points_are_sampled_densely_and_the_motion_is_the_same() {
    use lugre::simulate::{Drive, PiecewiseLinear, Request};
    use lugre::zoo::MODELS;
    let tp = TurningPoints::new(&[3.0, -1.0, 2.0, -3.0]).unwrap();
    let pl = PiecewiseLinear::from_turning_points(&tp, 0.5).unwrap();
    let drive = Drive::TurningPoints(pl.clone());
    let (t, u) = drive.zoo_samples(None).unwrap().unwrap();
    assert_eq!(t.len(), Request::DEFAULT_SAMPLES_PER_PERIOD + 1 + 3);
    for spec in MODELS {
        let model = ZooModel::new(spec.name, &[]).unwrap();
        let dense = model.simulate(&t, &u).unwrap();
        let knots = model.simulate(pl.times(), pl.values()).unwrap();
        for (tk, fk) in pl.times().iter().zip(&knots) {
            let i = t.iter().position(|x| x == tk).unwrap();
            assert!(
                (dense[i] - fk).abs() <= 1e-12 * 4.0,
                "{} at t = {tk}",
                spec.name
            );
        }
    }
    let record = Drive::Samples(pl);
    assert_eq!(record.zoo_samples(None).unwrap().unwrap().0.len(), 5);
    assert!(record.zoo_samples(Some(usize::MAX)).is_err());
}
