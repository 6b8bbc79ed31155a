//! The zoo's model table: every model by name with its parameters (names, units, shapes,
//! domains, defaults and their source), built from named values ([`ZooModel::new`]), so
//! that a front end translates a request to names and arrays and has each model of the table
//! without code of its own.
//!
//! A parameter is a scalar or one value per element ([`Shape`]); the element arrays of a
//! model have one length, its number of elements. A parameter not given takes its default.
//!
//! The defaults put every model on the scale of the paper's Example 2 (initial stiffness
//! `sigma0 = 1` N/m, saturation force `g(0) = Fs = 2` N), so that their loops compare with
//! LuGre's default loop on one figure; the literature has no canonical element
//! distributions for these models.

use super::gms::GmsRate;
use super::{
    BoucWen, ElastoPlastic, MaxwellSlip, PrandtlIshlinskii, Segmental, ZooElement, ZooLoop,
};
use crate::cycles::{Cycle, CycleSink, CycleSummary, HistoryEnergy};
use crate::error::{HistoryError, SamplesError, ZooError};
use crate::input::TurningPoints;
use crate::loops::LoopPoint;
use crate::model::Parameter;

/// Whether a parameter is one number or one number per element.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// One number.
    Scalar,
    /// One number per element (all of a model's element arrays equally long).
    Elements,
}

/// A parameter of a model of the zoo.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZooParameter {
    /// The name everywhere: the command line's flag, the Python keyword, the C name, JSON.
    pub name: &'static str,
    /// The unit with displacements in metres and forces in newtons.
    pub unit: &'static str,
    /// What it is, in a few words.
    pub description: &'static str,
    /// The values it may take (each checked by the model's `new`; a test checks they agree).
    pub domain: Domain,
    pub shape: Shape,
    /// The default: one value for a scalar, the default elements for an array.
    pub default: &'static [f64],
    /// The slow (rate-independent) loop depends on it; `false`: only the finite-rate form
    /// ([`ZooModelSpec::finite_rate`]) uses it, and a slow-loop fit refuses to free it.
    pub slow_loop: bool,
}

/// The values a parameter of the zoo may take (each value of an element array alike).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Domain {
    /// Finite and `> 0`.
    Positive,
    /// Finite and `>= 0`.
    NonNegative,
    /// Finite.
    Finite,
    /// Finite and in `[lo, hi]`.
    Closed(f64, f64),
}

impl Domain {
    /// The condition as help texts write it: `> 0`, `>= 0`, `finite`, `in [1, 100]`.
    pub fn text(&self) -> String {
        match self {
            Domain::Positive => "> 0".into(),
            Domain::NonNegative => ">= 0".into(),
            Domain::Finite => "finite".into(),
            Domain::Closed(lo, hi) if hi.is_infinite() => format!(">= {lo}"),
            Domain::Closed(lo, hi) => format!("in [{lo}, {hi}]"),
        }
    }

    /// A value outside the domain (for the test that each model's `new` refuses it).
    pub fn outside(&self) -> f64 {
        match self {
            Domain::Positive => 0.0,
            Domain::NonNegative => -1.0,
            Domain::Finite => f64::NAN,
            Domain::Closed(lo, _) => lo - 0.5 * lo.abs().max(1.0),
        }
    }
}

/// What a model of the zoo is and what lugre does with it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZooModelSpec {
    /// The name of `--model`, Python's `model=`, the C ABI's and MEX's model name.
    pub name: &'static str,
    /// The name in reports and figures.
    pub label: &'static str,
    /// The model's equations in one line.
    pub equations: &'static str,
    /// The publication that defines it.
    pub reference: &'static str,
    pub parameters: &'static [ZooParameter],
    /// Every minor loop closes (Masing behaviour).
    pub closes_minor_loops: bool,
    /// The model has a finite-rate form: it is a friction of `lugre dynamics`
    /// ([`crate::dynamics::Request::with_zoo`]) and [`ZooModel::simulate`] runs it at the
    /// input's rate (a test checks both agree with this).
    pub finite_rate: bool,
}

const MAXWELL_SLIP: ZooModelSpec = ZooModelSpec {
    name: "maxwell-slip",
    label: "Maxwell-slip",
    equations: "F = sum_i k_i z_i, element i sticks (dz_i = du) until |k_i z_i| = f_i, then slips; at finite rate GMS: slip level f_i g(v) / sum f_j, a slipping element relaxes to it at the rate C / g(v)",
    reference: "Al-Bender, Lampaert and Swevers, IEEE Trans. Automatic Control 50(11), 2005",
    parameters: &[
        ZooParameter {
            name: "stiffness",
            unit: "N/m",
            description: "element stiffnesses k_i",
            domain: Domain::Positive,
            shape: Shape::Elements,
            default: &[0.25, 0.25, 0.25, 0.25],
            slow_loop: true,
        },
        ZooParameter {
            name: "slip_force",
            unit: "N",
            description: "element slip forces f_i",
            domain: Domain::Positive,
            shape: Shape::Elements,
            default: &[0.125, 0.375, 0.625, 0.875],
            slow_loop: true,
        },
        // GMS at finite rate (`lugre dynamics`, `MaxwellSlip::simulate`): the slip levels
        // follow the Stribeck curve from sum f_i down to fc; the slow loop ignores them.
        rate_parameter(Parameter::Fc, &[Parameter::Fc.default_value()]),
        rate_parameter(Parameter::Vs, &[Parameter::Vs.default_value()]),
        rate_parameter(Parameter::Beta, &[Parameter::Beta.default_value()]),
        ZooParameter {
            name: "attraction",
            unit: "N/s",
            description: "GMS attraction C: a slipping element's force approaches its slip level at the rate C / g(v)",
            domain: Domain::Positive,
            shape: Shape::Scalar,
            default: &[super::gms::DEFAULT_ATTRACTION],
            slow_loop: false,
        },
        rate_parameter(Parameter::Sigma1, &[Parameter::Sigma1.default_value()]),
        rate_parameter(Parameter::Sigma2, &[Parameter::Sigma2.default_value()]),
    ],
    closes_minor_loops: true,
    finite_rate: true,
};

const PRANDTL_ISHLINSKII: ZooModelSpec = ZooModelSpec {
    name: "prandtl-ishlinskii",
    label: "Prandtl-Ishlinskii",
    equations: "F = w0 u + sum_i w_i p_i, p_i the play operator of threshold r_i",
    reference: "Brokate and Sprekels, Hysteresis and Phase Transitions, Springer 1996, ch. 2",
    parameters: &[
        ZooParameter {
            name: "linear_weight",
            unit: "N/m",
            description: "weight w0 of the input itself",
            domain: Domain::Positive,
            shape: Shape::Scalar,
            default: &[0.25],
            slow_loop: true,
        },
        ZooParameter {
            name: "thresholds",
            unit: "m",
            description: "play-operator thresholds r_i",
            domain: Domain::NonNegative,
            shape: Shape::Elements,
            default: &[0.5, 1.5, 2.5, 3.5],
            slow_loop: true,
        },
        ZooParameter {
            name: "weights",
            unit: "N/m",
            description: "play-operator weights w_i (the loading slope w0 + sum of w_i with r_i <= r stays > 0)",
            domain: Domain::Finite,
            shape: Shape::Elements,
            default: &[0.25, 0.25, 0.125, 0.125],
            slow_loop: true,
        },
    ],
    closes_minor_loops: true,
    finite_rate: false,
};

const BOUC_WEN: ZooModelSpec = ZooModelSpec {
    name: "bouc-wen",
    label: "Bouc-Wen",
    equations: "F = kx u + kw w, w' = rho (u' - sigma |u'| |w|^(n-1) w + (sigma - 1) u' |w|^n)",
    reference: "Ikhouane and Rodellar, Systems with Hysteresis, Wiley 2007 (the normalized form)",
    parameters: &[
        ZooParameter {
            name: "kx",
            unit: "N/m",
            description: "stiffness of the elastic part",
            domain: Domain::NonNegative,
            shape: Shape::Scalar,
            default: &[0.0],
            slow_loop: true,
        },
        ZooParameter {
            name: "kw",
            unit: "N",
            description: "force of the hysteretic part (|w| <= 1)",
            domain: Domain::Positive,
            shape: Shape::Scalar,
            default: &[2.0],
            slow_loop: true,
        },
        ZooParameter {
            name: "rho",
            unit: "1/m",
            description: "inverse length of the hysteretic part (initial stiffness kx + kw rho)",
            domain: Domain::Positive,
            shape: Shape::Scalar,
            default: &[0.5],
            slow_loop: true,
        },
        ZooParameter {
            name: "sigma",
            unit: "1",
            description: "shape: 1/2 linear unloading, 1 the Dahl model (n = 1); beta / (beta + gamma) of the classical form",
            domain: Domain::Closed(0.5, f64::INFINITY),
            shape: Shape::Scalar,
            default: &[2.0 / 3.0],
            slow_loop: true,
        },
        ZooParameter {
            name: "n",
            unit: "1",
            description: "sharpness of the transition to the plateau",
            domain: Domain::Closed(1.0, super::bouc_wen::MAX_EXPONENT),
            shape: Shape::Scalar,
            default: &[1.0],
            slow_loop: true,
        },
    ],
    closes_minor_loops: false,
    finite_rate: false,
};

const ELASTOPLASTIC: ZooModelSpec = ZooModelSpec {
    name: "elastoplastic",
    label: "Elasto-plastic",
    equations: "F = sigma0 z, dz/du = 1 - alpha(z) z / z_max moving as z does (alpha = 0 for |z| <= zba: stiction), z_max = Fs / sigma0",
    reference: "Dupont, Hayward, Armstrong and Altpeter, IEEE Trans. Automatic Control 47(5), 2002",
    parameters: &[
        ZooParameter {
            name: "sigma0",
            unit: "N/m",
            description: "bristle stiffness",
            domain: Domain::Positive,
            shape: Shape::Scalar,
            default: &[1.0],
            slow_loop: true,
        },
        ZooParameter {
            name: "fc",
            unit: "N",
            description: "Coulomb force (zba < fc / sigma0)",
            domain: Domain::Positive,
            shape: Shape::Scalar,
            default: &[1.0],
            // The slow loop's z_max is fs / sigma0: fc only bounds zba.
            slow_loop: false,
        },
        ZooParameter {
            name: "fs",
            unit: "N",
            description: "stiction force, the slow loop's plateau (fs >= fc)",
            domain: Domain::Positive,
            shape: Shape::Scalar,
            default: &[2.0],
            slow_loop: true,
        },
        ZooParameter {
            name: "zba",
            unit: "m",
            description: "break-away displacement: purely elastic for |z| <= zba (zba < fc / sigma0; not given: fc / (2 sigma0))",
            domain: Domain::NonNegative,
            shape: Shape::Scalar,
            default: &[0.5],
            slow_loop: true,
        },
        // The finite rate's (`lugre dynamics`), with LuGre's names, units and defaults; the
        // slow loop ignores them.
        rate_parameter(Parameter::Sigma1, &[Parameter::Sigma1.default_value()]),
        rate_parameter(Parameter::Sigma2, &[Parameter::Sigma2.default_value()]),
        rate_parameter(Parameter::Vs, &[Parameter::Vs.default_value()]),
        rate_parameter(Parameter::Beta, &[Parameter::Beta.default_value()]),
    ],
    closes_minor_loops: false,
    finite_rate: true,
};

/// The zoo's entry of LuGre's parameter `p` (name, unit, description, domain from the model
/// table of [`Parameter`]) with its `default`.
const fn lugre_parameter(p: Parameter, default: &'static [f64]) -> ZooParameter {
    ZooParameter {
        name: p.name(),
        unit: p.unit(),
        description: p.description(),
        domain: match p.domain() {
            crate::model::Domain::Positive => Domain::Positive,
            crate::model::Domain::NonNegative => Domain::NonNegative,
        },
        shape: Shape::Scalar,
        default,
        slow_loop: true,
    }
}

/// [`lugre_parameter`], used only at finite rate.
const fn rate_parameter(p: Parameter, default: &'static [f64]) -> ZooParameter {
    ZooParameter {
        slow_loop: false,
        ..lugre_parameter(p, default)
    }
}

/// Every model of the zoo, in the order `--help` lists them.
pub const MODELS: [ZooModelSpec; 4] = [MAXWELL_SLIP, PRANDTL_ISHLINSKII, BOUC_WEN, ELASTOPLASTIC];

impl ZooModelSpec {
    /// The model called `name` (case-insensitive, blanks around ignored).
    pub fn find(name: &str) -> Option<&'static ZooModelSpec> {
        let name = name.trim();
        MODELS.iter().find(|m| m.name.eq_ignore_ascii_case(name))
    }

    /// The parameter called `name` of this model.
    pub fn parameter(&self, name: &str) -> Option<&'static ZooParameter> {
        self.parameters
            .iter()
            .find(|p| p.name.eq_ignore_ascii_case(name.trim()))
    }

    /// The parameters' names, comma-separated (for messages and help).
    pub fn parameter_names(&self) -> String {
        let names: Vec<&str> = self.parameters.iter().map(|p| p.name).collect();
        names.join(", ")
    }
}

/// A model of the zoo, built from the table ([`ZooModel::new`]): its kind and values, and
/// which parameters were named (the others took the table's default, and take a base's value
/// where one applies: [`ZooModel::over`]). Two models are equal when their kinds and values
/// are, however they were named.
#[derive(Debug, Clone)]
pub struct ZooModel {
    kind: ZooKind,
    /// Bit `i` set: the table's parameter `i` was given to [`ZooModel::new`] (a model has
    /// fewer than 64 parameters: checked at compile time below).
    given: u64,
}

impl PartialEq for ZooModel {
    fn eq(&self, other: &Self) -> bool {
        self.kind == other.kind
    }
}

impl From<ZooKind> for ZooModel {
    /// The model of a concrete kind, every parameter named.
    fn from(kind: ZooKind) -> Self {
        Self {
            kind,
            given: u64::MAX,
        }
    }
}

// Each model's parameters fit the bits of `ZooModel::given`.
const _: () = {
    let mut i = 0;
    while i < MODELS.len() {
        assert!(MODELS[i].parameters.len() < 64);
        i += 1;
    }
};

/// The concrete model of a [`ZooModel`].
#[derive(Debug, Clone, PartialEq)]
pub enum ZooKind {
    MaxwellSlip(MaxwellSlip),
    PrandtlIshlinskii(PrandtlIshlinskii),
    BoucWen(BoucWen),
    ElastoPlastic(ElastoPlastic),
}

/// Runs `$body` with `$m` bound to the concrete model (one dispatch for every method).
macro_rules! each {
    ($self:expr, $m:ident => $body:expr) => {
        match $self.kind() {
            ZooKind::MaxwellSlip(x) => {
                let $m = x.bank();
                $body
            }
            ZooKind::PrandtlIshlinskii(x) => {
                let $m = x.bank();
                $body
            }
            ZooKind::BoucWen(x) => {
                let $m = x;
                $body
            }
            ZooKind::ElastoPlastic(x) => {
                let $m = x;
                $body
            }
        }
    };
}
pub(crate) use each;

impl ZooModel {
    /// The model `name` of [`MODELS`] with the values `given` by parameter name (any
    /// parameter not given takes its default).
    ///
    /// # Errors
    /// [`ZooError::UnknownModel`], [`ZooError::UnknownParameter`] (naming the model's
    /// parameters), [`ZooError::NotScalar`] for several values of a scalar, and the model's
    /// own checks (domains, lengths) naming the parameter and the value.
    pub fn new(name: &str, given: &[(&str, &[f64])]) -> Result<Self, ZooError> {
        let spec = ZooModelSpec::find(name).ok_or_else(|| ZooError::UnknownModel {
            name: name.trim().to_string(),
            known: model_names(),
        })?;
        let values = Resolved {
            values: resolve(spec, given)?,
            spec,
            given,
        };
        let kind = match spec.name {
            "maxwell-slip" => values.maxwell_slip()?,
            "prandtl-ishlinskii" => ZooKind::PrandtlIshlinskii(PrandtlIshlinskii::new(
                values.scalar("linear_weight"),
                values.value("thresholds"),
                values.value("weights"),
            )?),
            "elastoplastic" => values.elastoplastic()?,
            _ => ZooKind::BoucWen(BoucWen::new(
                values.scalar("kx"),
                values.scalar("kw"),
                values.scalar("rho"),
                values.scalar("sigma"),
                values.scalar("n"),
            )?),
        };
        Ok(Self {
            kind,
            given: values.given_bits(),
        })
    }

    /// This model with `base`'s values for each parameter of the same name that was not
    /// named (a scenario's Table I under the elasto-plastic model), the named ones kept, the
    /// others at their defaults (a default that follows other values, as elasto-plastic's
    /// `zba`, follows the new ones). The result remembers the same names as named.
    ///
    /// # Errors
    /// The model's own checks of the values together (e.g. `zba < fc / sigma0`).
    pub fn over(&self, base: &[(&str, Vec<f64>)]) -> Result<Self, ZooError> {
        let named = self.named();
        let given: Vec<(&str, Vec<f64>)> = named
            .into_iter()
            .filter_map(|(name, values)| {
                if self.is_named(name) {
                    return Some((name, values));
                }
                let b = base.iter().find(|(b, _)| b.eq_ignore_ascii_case(name));
                b.map(|(_, v)| (name, v.clone()))
            })
            .collect();
        let refs: Vec<(&str, &[f64])> = given.iter().map(|(n, v)| (*n, v.as_slice())).collect();
        let kind = Self::new(self.spec().name, &refs)?.kind;
        Ok(Self {
            kind,
            given: self.given,
        })
    }

    /// Whether the parameter `name` was given to [`ZooModel::new`] (not the table's default).
    pub fn is_named(&self, name: &str) -> bool {
        let i = self
            .spec()
            .parameters
            .iter()
            .position(|p| p.name.eq_ignore_ascii_case(name));
        i.is_some_and(|i| self.given >> i & 1 == 1)
    }

    /// The concrete model.
    pub fn kind(&self) -> &ZooKind {
        &self.kind
    }

    /// The model's entry in the table.
    pub fn spec(&self) -> &'static ZooModelSpec {
        match &self.kind {
            ZooKind::MaxwellSlip(_) => &MODELS[0],
            ZooKind::PrandtlIshlinskii(_) => &MODELS[1],
            ZooKind::BoucWen(_) => &MODELS[2],
            ZooKind::ElastoPlastic(_) => &MODELS[3],
        }
    }

    /// Each parameter by name with its values, in the table's order (what reports echo).
    pub fn named(&self) -> Vec<(&'static str, Vec<f64>)> {
        let values: Vec<Vec<f64>> = match &self.kind {
            ZooKind::MaxwellSlip(m) => [m.stiffness().to_vec(), m.slip_force().to_vec()]
                .into_iter()
                .chain(m.rate().values().iter().map(|&x| vec![x]))
                .collect(),
            ZooKind::PrandtlIshlinskii(m) => vec![
                vec![m.linear_weight()],
                m.thresholds().to_vec(),
                m.weights().to_vec(),
            ],
            ZooKind::BoucWen(m) => [m.kx(), m.kw(), m.rho(), m.sigma(), m.n()]
                .iter()
                .map(|&x| vec![x])
                .collect(),
            ZooKind::ElastoPlastic(m) => [m.sigma0(), m.fc(), m.fs(), m.zba()]
                .iter()
                .chain(m.rate().iter())
                .map(|&x| vec![x])
                .collect(),
        };
        self.spec()
            .parameters
            .iter()
            .map(|p| p.name)
            .zip(values)
            .collect()
    }

    /// The loop and every minor loop for the periodic input `input`, with their energies.
    ///
    /// # Errors
    /// See [`ZooLoop::new`].
    pub fn loops(&self, input: &TurningPoints) -> Result<ZooLoop, ZooError> {
        each!(self, m => ZooLoop::new(m, input))
    }

    /// The energies of each full cycle of `cycles` (counted on the history `u`, e.g. by
    /// [`crate::cycles::count_cycles`]) along this model's path from rest at `u[0]`, filled
    /// into the cycles, and the totals over the history (`docs/mathematics.md`, (H1)).
    pub fn cycle_energies(&self, u: &[f64], cycles: &mut [Cycle]) -> HistoryEnergy {
        let u0 = u.first().copied().unwrap_or(0.0);
        each!(self, m => super::history::cycle_energies(m, m.rest(u0), u, cycles))
    }

    /// Reversals and rainflow cycles of the history `u` with the noise gate `gate` (as
    /// [`crate::CycleCounter`] counts them), each full cycle with its energies along this
    /// model's path from rest at `u[0]`, passed to `sink`; returns the summary with the totals
    /// along the history. The history is held whole: at most
    /// [`super::MAX_HISTORY_SAMPLES`] samples.
    ///
    /// # Errors
    /// The counter's ([`HistoryError`]: a sample not finite, fewer than 2 samples, a bad gate),
    /// [`HistoryError::HeldTooLong`], and [`HistoryError::EnergyOverflow`] or
    /// [`HistoryError::TotalsOverflow`] where the energies overflow f64.
    pub fn count_cycles(
        &self,
        u: &[f64],
        gate: f64,
        sink: &mut impl CycleSink,
    ) -> Result<CycleSummary, HistoryError> {
        super::history::count(self, u, gate, sink)
    }

    /// The periodic response of `hl` (computed by [`Self::loops`] of this model) at `rhos`.
    pub fn points(&self, hl: &ZooLoop, rhos: &[f64]) -> Vec<LoopPoint> {
        each!(self, m => hl.points(m, rhos))
    }

    /// This model as a hysteresis element at rest at input `u`, to be driven one monotone
    /// segment at a time ([`ZooElement`]).
    ///
    /// # Errors
    /// [`ZooError::Domain`] for a non-finite `u`.
    pub fn element(&self, u: f64) -> Result<ZooElement, ZooError> {
        each!(self, m => ZooElement::at_rest(self, m, u))
    }

    /// The force at each sample of the input `u` at the times `t` (linear in `t` between
    /// samples) from rest at `u[0]`: the exact path of a rate-independent model (each interval
    /// one monotone segment, its exact segment map; `t` only checked), the finite-rate response
    /// of a model with rate dependence (elasto-plastic: (E1) with the interval's velocity,
    /// `docs/mathematics.md#elasto-plastic-at-finite-rate`; at a sample the value just after
    /// it, as LuGre's [`crate::Simulator`] reports).
    ///
    /// # Errors
    /// [`ZooError::LengthMismatch`] for `t` and `u` of different lengths, [`ZooError::Input`]
    /// for none, a value not finite or `t` not strictly increasing (naming the column, the
    /// index and the value), [`ZooError::Overflow`] where the force overflows.
    ///
    /// ```
    /// use lugre::zoo::ZooModel;
    /// let model = ZooModel::new("elastoplastic", &[("sigma1", &[0.0]), ("sigma2", &[0.0])])?;
    /// let force = model.simulate(&[0.0, 1.0, 2.0], &[0.0, 0.25, 0.5])?;
    /// // Inside the break-away band (zba = 0.5 m): purely elastic, F = sigma0 u.
    /// assert_eq!(force, vec![0.0, 0.25, 0.5]);
    /// # Ok::<(), lugre::Error>(())
    /// ```
    pub fn simulate(&self, t: &[f64], u: &[f64]) -> Result<Vec<f64>, ZooError> {
        check_samples(t, u)?;
        // The Generalized Maxwell-slip model is Maxwell-slip at finite rate.
        match self.spec().finite_rate {
            true => self.simulate_rate(t, u),
            false => self.exact_path(u),
        }
    }

    /// The refusal of `option` (as the front end spells it: `--x0`, `x0`), an option of
    /// LuGre's and Dahl's simulation that [`Self::simulate`] does not take.
    pub fn simulate_option(&self, option: &str) -> ZooError {
        ZooError::SimulateOption {
            option: option.to_string(),
            model: self.spec().label,
        }
    }

    /// The force at each sample of `u` along the model's rate-independent path from rest at
    /// `u[0]` (each step one monotone segment, the exact segment map): the slow limit of
    /// [`Self::simulate`] for every model.
    ///
    /// # Errors
    /// [`ZooError::Input`] for no sample or one not finite, [`ZooError::Overflow`].
    pub fn exact_path(&self, u: &[f64]) -> Result<Vec<f64>, ZooError> {
        crate::input::check_all_finite("u", u)?;
        let mut element = self.element(u[0])?;
        let mut out = Vec::with_capacity(u.len());
        out.push(element.force());
        for &x in &u[1..] {
            element.advance(x)?;
            out.push(element.force());
        }
        Ok(out)
    }

    /// `n` points of the loop `hl` evenly spaced over one period.
    ///
    /// # Errors
    /// See [`ZooLoop::try_sample`].
    pub fn sample(&self, hl: &ZooLoop, n: usize) -> Result<Vec<LoopPoint>, SamplesError> {
        each!(self, m => hl.try_sample(m, n))
    }
}

/// The name of every model lugre has, comma-separated: LuGre and Dahl, then the zoo's.
pub fn model_names() -> String {
    let classic = crate::model::FAMILY_NAMES;
    let names: Vec<&str> = classic
        .into_iter()
        .chain(MODELS.iter().map(|m| m.name))
        .collect();
    names.join(", ")
}

/// The models `lugre dynamics` takes, as its messages list them: `lugre, dahl or
/// elastoplastic` (LuGre and Dahl, then each model of the zoo with a finite-rate form).
pub fn dynamics_model_names() -> String {
    let classic = crate::model::FAMILY_NAMES;
    let names: Vec<&str> = classic
        .into_iter()
        .chain(MODELS.iter().filter(|m| m.finite_rate).map(|m| m.name))
        .collect();
    match names.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} or {last}", rest.join(", ")),
        _ => names.join(", "),
    }
}

/// A model's values by parameter ([`resolve`]), and the names given (any case, any spaces
/// around), for [`ZooModel::new`].
struct Resolved<'a> {
    spec: &'static ZooModelSpec,
    values: Vec<Vec<f64>>,
    given: &'a [(&'a str, &'a [f64])],
}

impl Resolved<'_> {
    fn value(&self, name: &str) -> &[f64] {
        let i = self.spec.parameters.iter().position(|p| p.name == name);
        i.map_or(&[], |i| &self.values[i])
    }

    /// A scalar parameter's value ([`resolve`] has checked it holds one).
    fn scalar(&self, name: &str) -> f64 {
        self.value(name)[0]
    }

    fn is_given(&self, name: &str) -> bool {
        self.given
            .iter()
            .any(|(n, _)| n.trim().eq_ignore_ascii_case(name))
    }

    /// The bit `i` set for each parameter `i` of the table given ([`ZooModel::is_named`]).
    fn given_bits(&self) -> u64 {
        let parameters = self.spec.parameters.iter().enumerate();
        parameters
            .filter(|(_, p)| self.is_given(p.name))
            .fold(0u64, |bits, (i, _)| bits | 1 << i)
    }

    /// Maxwell-slip, with its finite rate (GMS).
    fn maxwell_slip(&self) -> Result<ZooKind, ZooError> {
        let bank = MaxwellSlip::new(self.value("stiffness"), self.value("slip_force"))?;
        Ok(ZooKind::MaxwellSlip(bank.with_rate(GmsRate {
            fc: self.scalar("fc"),
            vs: self.scalar("vs"),
            beta: self.scalar("beta"),
            attraction: self.scalar("attraction"),
            sigma1: self.scalar("sigma1"),
            sigma2: self.scalar("sigma2"),
        })?))
    }

    /// The elasto-plastic model, `zba` scaled with `fc / sigma0` unless given
    /// ([`scaled_zba`]), with its finite rate.
    fn elastoplastic(&self) -> Result<ZooKind, ZooError> {
        let (sigma0, fc) = (self.scalar("sigma0"), self.scalar("fc"));
        let zba = scaled_zba(self.is_given("zba"), self.scalar("zba"), fc, sigma0);
        let model = ElastoPlastic::new(sigma0, fc, self.scalar("fs"), zba)?;
        Ok(ZooKind::ElastoPlastic(model.with_rate(
            self.scalar("sigma1"),
            self.scalar("sigma2"),
            self.scalar("vs"),
            self.scalar("beta"),
        )?))
    }
}

/// Elasto-plastic's `zba`: the one given, else `fc / (2 sigma0)` (the table's default where
/// that is not a finite number, so that `new` names the parameter at fault).
fn scaled_zba(given: bool, zba: f64, fc: f64, sigma0: f64) -> f64 {
    let scaled = ElastoPlastic::DEFAULT_ZBA_FRACTION * fc / sigma0;
    if given || !scaled.is_finite() {
        zba
    } else {
        scaled
    }
}

/// `t` and `u` of one length, at least one sample, finite, `t` strictly increasing.
fn check_samples(t: &[f64], u: &[f64]) -> Result<(), ZooError> {
    if t.len() != u.len() {
        return Err(ZooError::LengthMismatch {
            first: "t",
            n_first: t.len(),
            second: "u",
            n_second: u.len(),
        });
    }
    crate::input::check_times(t)?;
    crate::input::check_all_finite("u", u)?;
    Ok(())
}

/// Each parameter's values: the given ones, else the default.
fn resolve(spec: &ZooModelSpec, given: &[(&str, &[f64])]) -> Result<Vec<Vec<f64>>, ZooError> {
    for (name, values) in given {
        let p = spec
            .parameter(name)
            .ok_or_else(|| ZooError::UnknownParameter {
                model: spec.name,
                name: name.trim().to_string(),
                known: spec.parameter_names(),
            })?;
        if p.shape == Shape::Scalar && values.len() != 1 {
            return Err(ZooError::NotScalar {
                name: p.name,
                count: values.len(),
            });
        }
    }
    Ok(spec
        .parameters
        .iter()
        .map(|p| {
            given
                .iter()
                .rev()
                .find(|(n, _)| n.trim().eq_ignore_ascii_case(p.name))
                .map_or_else(|| p.default.to_vec(), |(_, v)| v.to_vec())
        })
        .collect())
}
