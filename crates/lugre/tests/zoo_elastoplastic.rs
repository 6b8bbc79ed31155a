//! The elasto-plastic model's rate-independent part (`lugre::zoo::ElastoPlastic`) against an
//! independent integration (`tests/reference/elastoplastic_reference.py`: scipy's Radau and
//! DOP853 at rtol 1e-12 agreeing to 1e-11, piecewise at `w = z_ba`), its stiction (minor loops
//! inside the break-away band close with no dissipation), its large-amplitude limit (LuGre's
//! rate-independent loop) and its parameter domains.
//!
//! Tolerances: 1e-10 relative — the state to `z_max`, the dissipation to itself (exactly 0 where
//! the reference's is), the work to the segment's work scale `fs (z_max + |du|)`, forces to
//! `fs`, loop energies to `fs` times the input's range.

use lugre::zoo::{ElastoPlastic, SingleState};
use lugre::TurningPoints;

const TOL: f64 = 1e-10;

/// A periodic input of the reference: turning points, the periodic force at each, and per loop
/// (starting at turning point `i`) its work, stored-energy change, dissipation, closure gap.
struct Periodic {
    name: &'static str,
    u: &'static [f64],
    force: &'static [f64],
    arcs: &'static [(usize, f64, f64, f64, f64)],
}

fn set_a() -> ElastoPlastic {
    ElastoPlastic::new(2.0e4, 1.0, 1.5, 3.0e-5).unwrap()
}

fn set_b() -> ElastoPlastic {
    ElastoPlastic::new(2.0e4, 1.0, 1.5, 0.0).unwrap()
}

#[test]
fn random_segments_match_the_integration() {
    for (model, rows) in [(set_a(), &SEGMENTS_A[..]), (set_b(), &SEGMENTS_B[..])] {
        let z_max = model.z_max();
        for &(z_a, du, z_b, work, dissipation) in rows {
            let (z, d) = model.segment(0.0, z_a, du);
            let stored = model.stored_energy(du, z) - model.stored_energy(0.0, z_a);
            assert!(
                (z - z_b).abs() <= TOL * z_max,
                "z {z} vs {z_b} ({z_a}, {du})"
            );
            if dissipation == 0.0 {
                assert_eq!(d, 0.0, "({z_a}, {du})");
            } else {
                assert!(
                    (d - dissipation).abs() <= TOL * dissipation,
                    "D {d} vs {dissipation} ({z_a}, {du})"
                );
            }
            let scale = model.fs() * (z_max + du.abs());
            assert!(
                (stored + d - work).abs() <= TOL * scale,
                "W {} vs {work} ({z_a}, {du})",
                stored + d
            );
        }
    }
}

#[test]
fn periodic_inputs_match_the_integration() {
    let model = set_a();
    for case in PERIODIC {
        let hl = model.loops(&TurningPoints::new(case.u).unwrap()).unwrap();
        let fs = model.fs();
        for (f, r) in hl.turning_force().iter().zip(case.force) {
            assert!((f - r).abs() <= TOL * fs, "{}: force {f} vs {r}", case.name);
        }
        let range = case.u.iter().fold(0.0f64, |m, x| m.max(x.abs())) * 2.0;
        for &(start, work, stored, dissipation, gap) in case.arcs {
            let l = hl
                .loops()
                .iter()
                .find(|l| l.start.u == case.u[start])
                .unwrap_or_else(|| panic!("{}: no loop starts at {}", case.name, start));
            let e = &l.energy;
            for (what, a, b) in [
                ("work", e.work, work),
                ("stored energy", e.stored_energy_change, stored),
                ("dissipation", e.dissipation, dissipation),
            ] {
                assert!(
                    (a - b).abs() <= TOL * fs * range,
                    "{} loop at {start}: {what} {a} vs {b}",
                    case.name
                );
            }
            assert!((e.closure_gap - gap).abs() <= TOL * fs, "{}", case.name);
        }
    }
}

#[test]
fn minor_loops_inside_the_break_away_band_close_without_dissipation() {
    let model = set_a();
    // Nested reversals, every deflection within |z| <= zba = 3e-5 (range 5.6e-5 < 2 zba).
    let u = [
        2.8e-5, -2.8e-5, 1.9e-5, -7e-6, 1.3e-5, -1e-6, 2.2e-5, -1.7e-5, 4e-6, -9e-6,
    ];
    let hl = model.loops(&TurningPoints::new(&u).unwrap()).unwrap();
    assert!(hl.loops().len() >= 4);
    for l in hl.loops() {
        assert_eq!(l.energy.dissipation, 0.0);
        assert!(l.energy.closure_gap.abs() <= 1e-14 * model.fs(), "{l:?}");
        assert!(l.energy.work.abs() <= 1e-14 * model.fs() * 5.6e-5, "{l:?}");
    }
    // The periodic state is the one reached from rest at the mid-range: F = sigma0 (u - 0).
    for (f, x) in hl.turning_force().iter().zip(u) {
        assert!((f - 2.0e4 * x).abs() <= 1e-14 * model.fs(), "{f} {x}");
    }
}

#[test]
fn the_large_amplitude_loop_tends_to_lugres_rate_independent_loop() {
    let model = set_a();
    let lugre = lugre::model::RateIndependent::new(model.sigma0(), model.fs()).unwrap();
    let mut previous = f64::INFINITY;
    for amplitude in [10.0, 100.0, 1000.0] {
        let a = amplitude * model.z_max();
        let input = TurningPoints::new(&[a, -a]).unwrap();
        let mine = model.loops(&input).unwrap().work_per_period();
        let theirs = lugre::HysteresisLoop::new(lugre, &input)
            .unwrap()
            .work_per_period();
        // Both tend to Coulomb's 2 fs (2a) per period; their difference is O(z_max / a).
        let coulomb = 4.0 * model.fs() * a;
        let gap = (mine - theirs).abs() / coulomb;
        assert!(gap < previous, "{amplitude}: {gap}");
        assert!(
            (mine / coulomb - 1.0).abs() < 2.0 / amplitude,
            "{amplitude}"
        );
        previous = gap;
    }
    assert!(previous < 1e-3);
}

#[test]
fn parameters_outside_their_domains_are_refused_by_name() {
    let cases = [
        ((0.0, 1.0, 1.5, 0.0), "sigma0 must be > 0, got 0"),
        (
            (f64::NAN, 1.0, 1.5, 0.0),
            "sigma0 must be a finite number, got a value that is not a finite number",
        ),
        ((1.0, -1.0, 1.5, 0.0), "fc must be > 0, got -1"),
        ((1.0, 1.0, 0.5, 0.0), "fs must be >= fc = 1, got 0.5"),
        ((2.0, 1.0, 1.5, -0.1), "zba must be >= 0 and < fc / sigma0 = 0.5 (the break-away displacement below every steady-state deflection), got -0.1"),
        ((2.0, 1.0, 1.5, 0.5), "zba must be >= 0 and < fc / sigma0 = 0.5 (the break-away displacement below every steady-state deflection), got 0.5"),
    ];
    for ((sigma0, fc, fs, zba), message) in cases {
        let e = ElastoPlastic::new(sigma0, fc, fs, zba).unwrap_err();
        assert_eq!(e.to_string(), message);
    }
    assert!(ElastoPlastic::new(1e-300, 1.0, 1e300, 0.0).is_err());
}

#[test]
fn the_state_stays_in_its_bounds_and_saturates() {
    let model = set_a();
    let (lo, hi) = model.bounds();
    let (z, d) = model.segment(0.0, lo, 1.0);
    assert_eq!(z, hi);
    // From -z_max to +z_max and then 1 m of sliding at fs (the work of the stroke).
    assert!((d - model.fs() * 1.0).abs() <= 1e-3 * model.fs());
    // From above the bounds (alpha = 1): the exponential approach, in closed form.
    let (z, d) = model.segment(0.0, 2.0 * hi, 1e-6);
    let expected = hi + hi * (-1e-6 / hi).exp();
    assert!((z - expected).abs() <= 1e-15 * hi);
    assert!(d > 0.0);
}

// Command: python3 crates/lugre/tests/reference/elastoplastic_reference.py (scipy 1.17.1, numpy
// 2.4.6; about 6 minutes)
// Generated by crates/lugre/tests/reference/elastoplastic_reference.py (scipy solve_ivp,
// Radau and DOP853 at rtol 1e-12, their mean). Rows: (z_a, du, z_b, work, dissipation).
// Set A: {'sigma0': 20000.0, 'fc': 1.0, 'fs': 1.5, 'zba': 3e-05}
const SEGMENTS_A: [(f64, f64, f64, f64, f64); 32] = [
    (
        -4.300318312457346e-05,
        2.577002443472698e-06,
        -4.0426180681100766e-05,
        -2.1499767438459515e-06,
        0.0,
    ),
    (
        3.912782211720513e-05,
        -2.0601721197533457e-05,
        1.852610091967166e-05,
        -1.1877700483497872e-05,
        0.0,
    ),
    (
        -5.2213858718490226e-05,
        -9.190399497660025e-05,
        -7.195011006902124e-05,
        0.00012144245691760531,
        9.693714395090728e-05,
    ),
    (
        6.372469111969063e-05,
        -0.000142086899271083,
        -6.282918912061381e-05,
        1.641335589561996e-05,
        1.7546648423081367e-05,
    ),
    (
        2.4383906603827195e-05,
        -2.768792266618835e-06,
        2.1615114337208364e-05,
        -1.2736173345357707e-06,
        0.0,
    ),
    (
        -6.398645651551274e-05,
        -4.0806763508720835e-05,
        -7.03373856764907e-05,
        5.52929977986643e-05,
        4.676218573474639e-05,
    ),
    (
        -3.9406490266048484e-05,
        -0.000278714430155315,
        -7.474958601290957e-05,
        0.0003889075961645077,
        0.00034856130482437597,
    ),
    (
        7.301401626761925e-05,
        -3.0651791860781168e-06,
        6.994883708154112e-05,
        -4.382067624681846e-06,
        0.0,
    ),
    (
        -2.8509225068769138e-05,
        -1.0806018244898134e-05,
        -3.9160178046589283e-05,
        7.3220735310970255e-06,
        1.146372249085885e-07,
    ),
    (
        6.774074022330028e-05,
        8.883936301397853e-07,
        6.787549001235105e-05,
        1.204810860336825e-06,
        1.0220682761756912e-06,
    ),
    (
        -7.305758717068549e-05,
        -0.0002930299281549856,
        -7.496667928613544e-05,
        0.00043690909591483464,
        0.0004340831763149551,
    ),
    (
        -4.643202956497721e-06,
        1.3479357881504135e-05,
        8.836154925006415e-06,
        5.651830016348592e-07,
        0.0,
    ),
    (
        1.1136188464130013e-05,
        -3.833235215539744e-05,
        -2.7196163691267438e-05,
        6.156166260135896e-06,
        0.0,
    ),
    (
        -7.438161565401891e-05,
        -2.2556722484810673e-06,
        -7.440093179061964e-05,
        3.3560490572247417e-06,
        3.3273100171222642e-06,
    ),
    (
        -5.770208178065539e-05,
        0.0002983889494340282,
        7.426494975482626e-05,
        0.00025555804993181435,
        0.00023370052472915972,
    ),
    (
        -1.951212296262098e-05,
        1.7499159640751937e-06,
        -1.7762206998545783e-05,
        -6.522694504925201e-07,
        0.0,
    ),
    (
        4.8898961105498686e-05,
        -4.900206143910482e-05,
        -1.0310033360614626e-07,
        -2.3910977675182836e-05,
        0.0,
    ),
    (
        6.126202000004327e-05,
        -8.094994173211326e-06,
        5.316702582683194e-05,
        -9.263024592146867e-06,
        0.0,
    ),
    (
        -6.62903483572368e-05,
        -3.7977774995398045e-06,
        -6.699220566892122e-05,
        5.062269268255683e-06,
        4.1268159176233265e-06,
    ),
    (
        -9.994608154918582e-06,
        -0.0003289526660931091,
        -7.481091355687573e-05,
        0.00043445890533436984,
        0.00037949109938392945,
    ),
    (
        -3.6615359593301846e-06,
        1.9168371409174037e-06,
        -1.7446988184127805e-06,
        -1.0362871614497063e-07,
        0.0,
    ),
    (
        6.797591827285638e-05,
        3.2601095995074366e-05,
        7.12347444531919e-05,
        4.5523804335658344e-05,
        4.098717081292344e-05,
    ),
    (
        -7.31350478744498e-05,
        1.694738006959766e-06,
        -7.144030986749003e-05,
        -2.4501735363507025e-06,
        0.0,
    ),
    (
        -1.2709368862243772e-05,
        6.677739178612248e-05,
        5.1369163127573836e-05,
        2.7287893655842975e-05,
        2.515265020335804e-06,
    ),
    (
        4.527817509894452e-05,
        5.118442253901e-06,
        4.9343857408660637e-05,
        4.8475961002783e-06,
        1.0005648635227798e-06,
    ),
    (
        -1.122039400973027e-05,
        1.2081207502321093e-05,
        8.608134925908259e-07,
        -1.2515624186456452e-06,
        0.0,
    ),
    (
        1.3836163006614331e-05,
        8.030848214021049e-06,
        2.1867011220635382e-05,
        2.8672677297779072e-06,
        0.0,
    ),
    (
        7.202953493996178e-06,
        -4.841925428478896e-06,
        2.3610280655172788e-06,
        -4.630808551051147e-07,
        0.0,
    ),
    (
        4.64101521227367e-05,
        -0.00012295526444976398,
        -6.225869705815104e-05,
        3.320962527825929e-05,
        1.5987193885015503e-05,
    ),
    (
        -4.797169751220628e-05,
        1.361253073028899e-06,
        -4.6610444439177385e-05,
        -1.2875023138497652e-06,
        0.0,
    ),
    (
        6.223144282585931e-06,
        0.00013475295757015652,
        7.160652753859158e-05,
        0.00014228329214036853,
        9.139561952663662e-05,
    ),
    (
        4.269664513998809e-05,
        -3.0665623057031817e-06,
        3.9630082834284894e-05,
        -2.5246004075778516e-06,
        0.0,
    ),
];
// Set B: {'sigma0': 20000.0, 'fc': 1.0, 'fs': 1.5, 'zba': 0.0}
const SEGMENTS_B: [(f64, f64, f64, f64, f64); 32] = [
    (
        1.8106569120544412e-06,
        9.10847041587903e-07,
        2.7214395143520645e-06,
        4.128058045709512e-08,
        3.0346860323620153e-12,
    ),
    (
        -6.796933842461112e-05,
        0.0003259639096973215,
        7.389925580044402e-05,
        0.00025607069784537654,
        0.00024765800742557485,
    ),
    (
        -2.9089284963544344e-05,
        -3.6118507191966113e-06,
        -3.2171428217887786e-05,
        2.213515422037766e-06,
        3.253724831535705e-07,
    ),
    (
        -3.9994000418161406e-05,
        2.281721849116835e-06,
        -3.7712278569044575e-05,
        -1.7730411457867626e-06,
        0.0,
    ),
    (
        -6.819265989831129e-05,
        3.245740521800256e-05,
        -3.57352546803087e-05,
        -3.373230436940225e-05,
        0.0,
    ),
    (
        9.750983636697152e-06,
        1.2461685466679428e-05,
        2.1894191961909822e-05,
        3.956832342598286e-06,
        1.1409274478007212e-07,
    ),
    (
        2.1764373153033555e-06,
        -3.096005370370025e-06,
        -9.19567009636922e-07,
        -3.891274364092722e-08,
        1.5381395712265378e-14,
    ),
    (
        -6.204455113671381e-05,
        1.462020910893798e-06,
        -6.0582530225819994e-05,
        -1.792833571938996e-06,
        0.0,
    ),
    (
        5.059200907975361e-05,
        1.0080817020970308e-06,
        5.107737563999554e-05,
        1.0249287449994068e-06,
        5.314595495660264e-07,
    ),
    (
        7.478551795038313e-05,
        1.0999112159400094e-06,
        7.478866212889603e-05,
        1.6451832685508982e-06,
        1.6404803893200022e-06,
    ),
    (
        -5.2577194616164935e-05,
        -5.79659341306224e-05,
        -6.709457508385932e-05,
        7.106623727923736e-05,
        5.369303115946175e-05,
    ),
    (
        6.550660722028997e-05,
        6.241319856743265e-05,
        7.144033795305193e-05,
        8.615002762418772e-05,
        7.80239646508586e-05,
    ),
    (
        1.4174069072249673e-05,
        -7.953193542049655e-05,
        -5.2268579810568517e-05,
        3.649995212129945e-05,
        1.1188950107811855e-05,
    ),
    (
        -1.8231483139121506e-05,
        2.94668624784354e-06,
        -1.5284796891277963e-05,
        -9.876196144445117e-07,
        0.0,
    ),
    (
        -5.826014662215162e-07,
        -6.061098297763772e-05,
        -5.030701891050049e-05,
        3.423279901477521e-05,
        8.928231742845305e-06,
    ),
    (
        -3.859277093583729e-05,
        8.9609865764993e-06,
        -2.9631784359337986e-05,
        -6.113593241876998e-06,
        0.0,
    ),
    (
        -3.0804662418440364e-05,
        5.728244960253179e-06,
        -2.507641745818718e-05,
        -3.201005141767971e-06,
        0.0,
    ),
    (
        4.947675145781047e-05,
        -1.6122397894414221e-06,
        4.786451166836905e-05,
        -1.5693745756651372e-06,
        0.0,
    ),
    (
        -5.2585178070931466e-05,
        2.926258459082284e-06,
        -4.9658919611849186e-05,
        -2.9919265573547228e-06,
        0.0,
    ),
    (
        -9.363120509081756e-06,
        -5.341348783400035e-06,
        -1.4649021383416784e-05,
        1.283191228158713e-06,
        1.3933209916567713e-08,
    ),
    (
        7.081159426522759e-05,
        -4.934201303945474e-06,
        6.587739296128208e-05,
        -6.7445097900802976e-06,
        0.0,
    ),
    (
        -2.8046048981620404e-05,
        1.8184280787403661e-06,
        -2.6227620902880033e-05,
        -9.869276525426101e-07,
        0.0,
    ),
    (
        -1.5489426555141896e-05,
        -9.326510869902817e-05,
        -6.480443335365123e-05,
        8.784400432095974e-05,
        4.824708184815287e-05,
    ),
    (
        -1.8516313060228725e-07,
        -1.4065484572440974e-05,
        -1.419193973451324e-05,
        2.0270924659306047e-06,
        1.3323785499390682e-08,
    ),
    (
        6.610194378568748e-06,
        -0.00012694020131475043,
        -6.659922920937504e-05,
        0.00010493593994685009,
        6.101831333124581e-05,
    ),
    (
        -4.073868848173625e-05,
        -7.847909650754077e-05,
        -6.70196037206932e-05,
        9.015941712824804e-05,
        6.183955169157998e-05,
    ),
    (
        1.3824880020188321e-05,
        -0.0002859900203359583,
        -7.409433509625111e-05,
        0.00032133019443591,
        0.0002683417625780805,
    ),
    (
        -5.512253052229411e-05,
        7.241920851620609e-06,
        -4.7880609670673506e-05,
        -7.45940588745853e-06,
        0.0,
    ),
    (
        5.3207620483739374e-05,
        -1.1541642658489301e-05,
        4.1665977825250066e-05,
        -1.0949971694074107e-05,
        0.0,
    ),
    (
        -2.76013220259098e-05,
        -4.432099442629681e-06,
        -3.1444490387883125e-05,
        2.6185137351926474e-06,
        3.4928375343564103e-07,
    ),
    (
        -2.7539248470156053e-05,
        2.5454174945805906e-05,
        -2.0850735243501463e-06,
        -7.540626746990471e-06,
        0.0,
    ),
    (
        -1.3035710566584386e-05,
        -0.00011914926806341694,
        -6.808119337214179e-05,
        0.00011969413728628336,
        7.504294587629122e-05,
    ),
];
// Set A, periodic inputs: the force at each turning point (periodic state), and per loop
// (the arc from turning point i until the input is back at u_i): (i, work, stored-energy
// change, dissipation, closure gap).
const PERIODIC: [Periodic; 3] = [
    Periodic {
        name: "inside",
        u: &[
            2.5e-05, -2.5e-05, 1.5e-05, -5e-06, 1e-05, 0.0, 2e-05, -1.5e-05,
        ],
        force: &[
            0.5000000000000001,
            -0.5000000000000002,
            0.3000000000000001,
            -0.1,
            0.20000000000000012,
            1.122318655111948e-16,
            0.40000000000000024,
            -0.29999999999999993,
        ],
        arcs: &[
            (
                0,
                -2.541098841762901e-20,
                3.1019272970738538e-21,
                0.0,
                1.3552527156068805e-16,
            ),
            (
                2,
                -3.8116482626443515e-21,
                1.5509636485369269e-21,
                0.0,
                1.0164395367051604e-16,
            ),
            (
                4,
                -8.470329472543003e-22,
                6.462348535570529e-22,
                0.0,
                6.776263578034403e-17,
            ),
            (
                6,
                -1.164670302474663e-20,
                1.0339757656912846e-21,
                0.0,
                6.776263578034403e-17,
            ),
        ],
    },
    Periodic {
        name: "beyond",
        u: &[
            0.000375, -0.000375, 0.000225, -7.5e-05, 0.00015, 0.0, 0.0003, -0.000225,
        ],
        force: &[
            1.4996886292792695,
            -1.4999578974806098,
            1.499688463324291,
            -1.4815987213257324,
            1.4426654270061647,
            -1.2535404851549927,
            1.4845775818834777,
            -1.4991597730881447,
        ],
        arcs: &[
            (0, 0.0033075292546332676, 0.0, 0.003307529254633252, 0.0),
            (
                2,
                0.00045002322631850357,
                -3.4868471366368363e-06,
                0.0004535100734551404,
                -0.04724514203340502,
            ),
            (
                4,
                3.3587772927570216e-05,
                -9.524251308848642e-06,
                4.3112024236418824e-05,
                -0.13870473667653144,
            ),
            (
                6,
                0.0010935712509307614,
                1.0871180730446998e-06,
                0.0010924841328577126,
                0.014573951335490186,
            ),
        ],
    },
    Periodic {
        name: "mixed",
        u: &[
            6e-05, -6e-05, 3.6e-05, -1.2e-05, 2.4e-05, 0.0, 4.8e-05, -3.6e-05,
        ],
        force: &[
            1.1102291686869863,
            -1.148798510927398,
            0.7688152364317846,
            -0.19118476356821576,
            0.5288152364317844,
            0.04881523643178448,
            0.97501584697724,
            -0.7044594429100642,
        ],
        arcs: &[
            (
                0,
                1.416067736176935e-05,
                1.0339757656912846e-19,
                1.4160677361769292e-05,
                1.8973538018496328e-15,
            ),
            (
                2,
                -4.7082159289613395e-09,
                -8.769181762042387e-08,
                8.298360169152318e-08,
                -0.002284614039669121,
            ),
            (
                4,
                -8.470329472543003e-22,
                4.135903062765138e-21,
                0.0,
                1.3552527156068805e-16,
            ),
            (
                6,
                -7.950235980251165e-08,
                -1.242038210520783e-06,
                1.162535850718224e-06,
                -0.025819147954369737,
            ),
        ],
    },
];

/// `zba` not given is `fc / (2 sigma0)` at any scale (the table's default `0.5` m is its value
/// at the defaults `fc = 1` N, `sigma0 = 1` N/m), so naming Table I's stiffness alone builds
/// a model; a `zba` given is kept.
#[test]
fn an_unnamed_break_away_displacement_follows_the_scale() {
    use lugre::zoo::{ZooKind, ZooModel, MODELS};
    let zba = |m: &ZooModel| match m.kind() {
        ZooKind::ElastoPlastic(ep) => ep.zba(),
        _ => unreachable!(),
    };
    let spec = MODELS.iter().find(|m| m.name == "elastoplastic").unwrap();
    let default = |n: &str| spec.parameter(n).unwrap().default[0];
    assert_eq!(
        default("zba"),
        ElastoPlastic::DEFAULT_ZBA_FRACTION * default("fc") / default("sigma0")
    );
    let table_i = ZooModel::new("elastoplastic", &[("sigma0", &[1e5])]).unwrap();
    assert_eq!(zba(&table_i), 5e-6);
    assert!(!table_i.is_named("zba") && table_i.is_named("sigma0"));
    let given = ZooModel::new("elastoplastic", &[("zba", &[0.25])]).unwrap();
    assert_eq!(zba(&given), 0.25);
    // Over a base: unnamed values replaced, named kept, zba following the new scale.
    let over = given
        .over(&[("sigma0", vec![2.0]), ("zba", vec![0.1])])
        .unwrap();
    assert_eq!((zba(&over), over.named()[0].1[0]), (0.25, 2.0));
    let over = table_i
        .over(&[("sigma0", vec![7.0]), ("fc", vec![2.0])])
        .unwrap();
    assert_eq!((zba(&over), over.named()[0].1[0]), (0.5 * 2.0 / 1e5, 1e5));
}
