//! The slow-loop fit of the zoo's models against records from an independent generator
//! (`tests/reference/zoo_fit_reference.py`: each model written from its definition, the ODE
//! models by scipy's Radau at rtol 1e-12): noise-free records give back the parameters, noisy
//! ones within their 95 % intervals, and the unidentifiable cases are named.

mod common;

use lugre::fit::{fit_zoo, FitError, SlowOptions, Why, ZooFitSpec};

fn record(name: &str) -> (Vec<f64>, Vec<f64>) {
    let text = match name {
        "maxwell-slip" => include_str!("reference/zoo_fit/maxwell-slip.csv"),
        "maxwell-slip-noisy" => include_str!("reference/zoo_fit/maxwell-slip-noisy.csv"),
        "prandtl-ishlinskii" => include_str!("reference/zoo_fit/prandtl-ishlinskii.csv"),
        "prandtl-ishlinskii-noisy" => {
            include_str!("reference/zoo_fit/prandtl-ishlinskii-noisy.csv")
        }
        "bouc-wen" => include_str!("reference/zoo_fit/bouc-wen.csv"),
        "bouc-wen-noisy" => include_str!("reference/zoo_fit/bouc-wen-noisy.csv"),
        "bouc-wen-small" => include_str!("reference/zoo_fit/bouc-wen-small.csv"),
        "elastoplastic" => include_str!("reference/zoo_fit/elastoplastic.csv"),
        "elastoplastic-noisy" => include_str!("reference/zoo_fit/elastoplastic-noisy.csv"),
        _ => panic!("no record {name}"),
    };
    text.lines()
        .skip(1)
        .map(|l| {
            let (u, f) = l.split_once(',').unwrap();
            (u.parse::<f64>().unwrap(), f.parse::<f64>().unwrap())
        })
        .unzip()
}

/// The generator's parameters of each case, by the names the fit reports.
fn truth(model: &str) -> Vec<(&'static str, f64)> {
    match model {
        "maxwell-slip" => vec![
            ("stiffness[0]", 0.4),
            ("stiffness[1]", 0.3),
            ("stiffness[2]", 0.2),
            ("stiffness[3]", 0.1),
        ],
        "prandtl-ishlinskii" => vec![
            ("linear_weight", 0.3),
            ("weights[0]", 0.5),
            ("weights[1]", 0.25),
            ("weights[2]", 0.2),
            ("weights[3]", 0.1),
        ],
        "bouc-wen" => vec![
            ("kx", 0.1),
            ("kw", 1.5),
            ("rho", 2.0),
            ("sigma", 0.75),
            ("n", 2.0),
        ],
        _ => vec![("sigma0", 2.0), ("fs", 1.5), ("zba", 0.3)],
    }
}

const MODELS: [&str; 4] = [
    "maxwell-slip",
    "prandtl-ishlinskii",
    "bouc-wen",
    "elastoplastic",
];

#[test]
fn noise_free_records_give_back_the_parameters() {
    for model in MODELS {
        let (u, f) = record(model);
        let spec = ZooFitSpec::new(model).unwrap();
        let r = fit_zoo(&spec, &u, &f, SlowOptions::default()).unwrap();
        assert_eq!(r.model.spec().name, model);
        // The generator's Radau at rtol 1e-12 and the exact segment maps.
        common::assert_gives_back(model, &r, &truth(model));
    }
}

/// One noisy record per model (the generator's, force noise 0.01): each estimate within 4
/// standard errors of the truth (a miss has probability 6e-5 for each; how often the 95 %
/// intervals hold it is the coverage tests' question), the noise found.
#[test]
fn noisy_records_hold_the_truth() {
    for model in MODELS {
        let (u, f) = record(&format!("{model}-noisy"));
        let spec = ZooFitSpec::new(model).unwrap();
        let r = fit_zoo(&spec, &u, &f, SlowOptions::default()).unwrap();
        assert!(r.converged, "{model}: {}", r.termination);
        assert!((r.rms / 0.01 - 1.0).abs() < 0.1, "{model}: rms {}", r.rms);
        assert!(
            (r.noise.force / 0.01 - 1.0).abs() < 0.2,
            "{model}: {:?}",
            r.noise
        );
        let truth = truth(model);
        common::assert_within_four_errors(model, &r, &truth);
        for (name, value) in truth {
            let e = r.estimate(name).unwrap();
            assert!(e.stderr < 0.05 * value, "{model} {name}: {e:?}");
        }
    }
}

/// A loop that never nears saturation (rho |du| <= 0.2, force noise 1e-3) shows the initial
/// stiffness `kx + kw rho` and the curvature, not the plateau `kw`: the three are named as
/// collinear. (Held at known `kx` and `kw`, the same record does give `rho`, and `n` within
/// about 3 %: `n` alone is not what the small loop hides.)
#[test]
fn bouc_wen_plateau_from_a_loop_that_never_nears_saturation_is_named() {
    let (u, f) = record("bouc-wen-small");
    let spec = ZooFitSpec::new("bouc-wen").unwrap();
    let e = fit_zoo(&spec, &u, &f, SlowOptions::default()).unwrap_err();
    let FitError::Unidentifiable { parameters } = &e else {
        panic!("{e}");
    };
    let named: Vec<&str> = parameters.iter().map(|p| p.name).collect();
    assert_eq!(named, ["kx", "kw", "rho"], "{e}");
    assert!(parameters
        .iter()
        .all(|p| matches!(p.why, Why::Collinear { .. })));
}

#[test]
fn an_element_beyond_the_amplitude_is_named() {
    let (u, f) = record("prandtl-ishlinskii");
    // The record's amplitude is 2: the last play never slips (the others are the record's).
    let spec = ZooFitSpec::new("prandtl-ishlinskii")
        .unwrap()
        .with_thresholds(&[0.25, 0.75, 1.25, 1.75, 2.5]);
    let e = fit_zoo(&spec, &u, &f, SlowOptions::default()).unwrap_err();
    let FitError::Unidentifiable { parameters } = &e else {
        panic!("{e}");
    };
    assert!(
        parameters
            .iter()
            .any(|p| p.name == "weights[4]" && matches!(p.why, Why::NoEffect { .. })),
        "{e}"
    );
}

#[test]
fn parameters_outside_the_slow_loop_are_refused() {
    let (u, f) = record("elastoplastic");
    for name in ["fc", "sigma1", "vs"] {
        let spec = ZooFitSpec::new("elastoplastic")
            .unwrap()
            .free(name)
            .unwrap();
        let e = fit_zoo(&spec, &u, &f, SlowOptions::default()).unwrap_err();
        assert!(
            matches!(e, FitError::NotInZooSlowLoop { name: n, .. } if n == name),
            "{e}"
        );
        assert!(e.to_string().contains("sigma0, fs, zba"), "{e}");
    }
    let spec = ZooFitSpec::new("bouc-wen").unwrap().with_elements(3);
    let e = fit_zoo(&spec, &u, &f, SlowOptions::default()).unwrap_err();
    assert!(matches!(e, FitError::NoElements { .. }), "{e}");
    let spec = ZooFitSpec::new("maxwell-slip").unwrap().with_elements(0);
    let e = fit_zoo(&spec, &u, &f, SlowOptions::default()).unwrap_err();
    assert!(e.to_string().contains("got 0"), "{e}");
    let e = ZooFitSpec::new("bouc-wen")
        .unwrap()
        .set("nn", &[1.0])
        .unwrap_err();
    assert!(e.to_string().contains("kx, kw, rho, sigma, n"), "{e}");
}

#[test]
fn a_held_parameter_keeps_its_value() {
    let (u, f) = record("bouc-wen");
    let spec = ZooFitSpec::new("bouc-wen")
        .unwrap()
        .set("n", &[2.0])
        .unwrap()
        .fix("n")
        .unwrap();
    let r = fit_zoo(&spec, &u, &f, SlowOptions::default()).unwrap();
    assert!(r.estimate("n").is_none());
    assert_eq!(r.fixed, vec![("n", vec![2.0])]);
    assert!((r.estimate("rho").unwrap().value / 2.0 - 1.0).abs() < 1e-8);
}

/// Gaussian draws (xorshift64* and Box-Muller): deterministic noise for the coverage check.
struct Gauss(u64);

impl Gauss {
    fn uniform(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        ((self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }

    fn next(&mut self) -> f64 {
        let (a, b) = (self.uniform(), self.uniform());
        (-2.0 * a.ln()).sqrt() * (std::f64::consts::TAU * b).cos()
    }
}

/// How often each 95 % interval holds the truth over `records` noisy copies (force noise
/// 0.01) of each noise-free record: `(model, parameter, covered, fitted)`.
fn coverage(records: usize) -> Vec<(&'static str, &'static str, usize, usize)> {
    let mut out = Vec::new();
    let mut gauss = Gauss(0x2028_0028);
    for model in MODELS {
        let (u, f) = record(model);
        let mut hits = vec![0; truth(model).len()];
        let mut fitted = 0;
        for _ in 0..records {
            let noisy: Vec<f64> = f.iter().map(|f| f + 0.01 * gauss.next()).collect();
            let spec = ZooFitSpec::new(model).unwrap();
            let Ok(r) = fit_zoo(&spec, &u, &noisy, SlowOptions::default()) else {
                continue;
            };
            fitted += 1;
            for (k, (name, value)) in truth(model).into_iter().enumerate() {
                let e = r.estimate(name).unwrap();
                hits[k] += usize::from(e.ci95[0] <= value && value <= e.ci95[1]);
            }
        }
        for (k, (name, _)) in truth(model).into_iter().enumerate() {
            out.push((model, name, hits[k], fitted));
        }
    }
    out
}

/// The 95 % intervals cover the truth at about their nominal rate: 10 records per model here
/// (each interval at least 7 of 10: a binomial(10, 0.95) falls below 7 with probability 1e-3);
/// the ignored test runs 100. Its result (2026-11-27), intervals holding the truth of 100:
/// maxwell-slip stiffness[0..4] 97, 96, 92, 89; prandtl-ishlinskii linear_weight 96,
/// weights[0..4] 96, 97, 96, 94; bouc-wen kx 98, kw 98, rho 92, sigma 95, n 98;
/// elastoplastic sigma0 91, fs 95, zba 96.
#[test]
fn intervals_cover_the_truth() {
    for (model, name, covered, fitted) in coverage(10) {
        assert_eq!(fitted, 10, "{model}: a noisy record did not fit");
        assert!(covered >= 7, "{model} {name}: {covered} of {fitted}");
    }
}

#[test]
#[ignore = "100 noisy records per model: minutes; run with --ignored --nocapture"]
fn intervals_cover_the_truth_at_their_nominal_rate() {
    for (model, name, covered, fitted) in coverage(100) {
        println!("{model:<20} {name:<14} {covered:>3} of {fitted}");
        // binomial(100, 0.95) falls below 88 with probability 1e-3.
        assert!(covered >= 88, "{model} {name}: {covered} of {fitted}");
    }
}

/// A model's values as the starts (a front end's model object): its defaults on the edge of
/// their domains (Bouc-Wen's kx = 0, n = 1) are moved inside, and the fit gives the same
/// parameters.
#[test]
fn a_model_on_the_edge_of_its_domain_starts_the_fit() {
    let (u, f) = record("bouc-wen");
    let model = lugre::zoo::ZooModel::new("bouc-wen", &[]).unwrap();
    let mut spec = ZooFitSpec::new("bouc-wen").unwrap();
    for (name, values) in model.named() {
        spec = spec.set(name, &values).unwrap();
    }
    let r = fit_zoo(&spec, &u, &f, SlowOptions::default()).unwrap();
    for (name, value) in truth("bouc-wen") {
        let e = r.estimate(name).unwrap();
        assert!((e.value / value - 1.0).abs() < 1e-8, "{name}: {}", e.value);
    }
}
