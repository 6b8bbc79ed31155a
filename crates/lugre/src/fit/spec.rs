//! What to fit: the model family, which parameters are free, their start values and bounds, and
//! the map from bounded parameters to the unconstrained variables the optimizer moves.

use super::full;
use crate::error::FitError;
use crate::model::{Dahl, LuGreParams, Parameter};

/// The LuGre parameters' names, in the order of [`LuGreParams`] ([`Parameter::LUGRE`]).
pub(crate) const LUGRE_PARAMETERS: [&str; Parameter::LUGRE.len()] = names(Parameter::LUGRE);

/// The Dahl parameters' names ([`Parameter::DAHL`]).
pub(crate) const DAHL_PARAMETERS: [&str; Parameter::DAHL.len()] = names(Parameter::DAHL);

const fn names<const N: usize>(ps: [Parameter; N]) -> [&'static str; N] {
    let mut out = [""; N];
    let mut i = 0;
    while i < N {
        out[i] = ps[i].name();
        i += 1;
    }
    out
}

/// The model whose parameters are identified.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Family {
    /// LuGre with the Stribeck `g` and viscous `f`: `sigma0, sigma1, sigma2, fc, fs, vs, beta`.
    LuGre,
    /// Dahl: `rho, fc` (LuGre with `g = Fc`, `sigma0 = rho Fc`, `sigma1 = 0`, `f = 0`).
    Dahl,
}

impl Family {
    /// Both families, in the order `--model` lists them.
    pub const ALL: [Family; 2] = [Family::LuGre, Family::Dahl];

    /// The name of `--model`, Python's `model=` and the C ABI's model name.
    pub const fn name(self) -> &'static str {
        crate::model::FAMILY_NAMES[self as usize]
    }

    /// The parameter names, in a fixed order.
    pub fn parameters(self) -> &'static [&'static str] {
        match self {
            Family::LuGre => &LUGRE_PARAMETERS,
            Family::Dahl => &DAHL_PARAMETERS,
        }
    }

    pub fn label(self) -> &'static str {
        match self {
            Family::LuGre => "LuGre",
            Family::Dahl => "Dahl",
        }
    }

    /// The parameters, in the order of [`Self::parameters`].
    fn table(self) -> &'static [Parameter] {
        match self {
            Family::LuGre => &Parameter::LUGRE,
            Family::Dahl => &Parameter::DAHL,
        }
    }

    /// The index of `name` (case-insensitive).
    pub fn index(self, name: &str) -> Result<usize, FitError> {
        let lower = name.trim().to_ascii_lowercase();
        self.parameters()
            .iter()
            .position(|p| *p == lower)
            .ok_or_else(|| FitError::UnknownParameter {
                name: name.to_string(),
                model: self.label(),
                known: self.parameters(),
            })
    }

    /// The two parameters the slow loop depends on: `sigma0` and `g(0) = Fs` (Dahl: `rho`, `Fc`),
    /// by their index in [`Self::parameters`] (the table's
    /// [`Parameter::LUGRE_RATE_INDEPENDENT`]).
    pub(crate) fn slow_parameters(self) -> [usize; 2] {
        match self {
            Family::LuGre => LUGRE_SLOW,
            Family::Dahl => DAHL_SLOW,
        }
    }

    /// Whether a full fit frees parameter `i` unless told otherwise: the table says so
    /// ([`Parameter::fit_frees_by_default`]: all but `beta`) and the fit has its derivative.
    fn full_default(self, i: usize) -> bool {
        let p = self.table()[i];
        p.fit_frees_by_default() && full::differentiates(p)
    }

    /// Whether a full fit can fit parameter `i` (it has its derivative).
    fn in_full_fit(self, i: usize) -> bool {
        full::differentiates(self.table()[i])
    }
}

/// The index of `p` in `list` (at compile time: a parameter missing is a build error).
pub(crate) const fn index_of(list: &[Parameter], p: Parameter) -> usize {
    let mut i = 0;
    while i < list.len() {
        if list[i] as u8 == p as u8 {
            return i;
        }
        i += 1;
    }
    panic!("a parameter is not in the family's list")
}

const LUGRE_SLOW: [usize; 2] = [
    index_of(&Parameter::LUGRE, Parameter::LUGRE_RATE_INDEPENDENT[0]),
    index_of(&Parameter::LUGRE, Parameter::LUGRE_RATE_INDEPENDENT[1]),
];
const DAHL_SLOW: [usize; 2] = [
    index_of(&Parameter::DAHL, Parameter::Rho),
    index_of(&Parameter::DAHL, Parameter::Fc),
];

/// Which fit: the slow loop (rate-independent limit), the exact simulation, or one of the
/// lab's experiments (the steady-state Stribeck curve, the presliding test, the three in
/// turn).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FitKind {
    Slow,
    Full,
    /// `Fc, Fs, vs, sigma2` (and `beta` if freed) from constant-velocity runs
    /// ([`super::fit_stribeck`]).
    Stribeck,
    /// `sigma0, sigma1` from a presliding test.
    Presliding,
    /// The Stribeck and presliding fits in turn, then optionally a full fit.
    Staged,
}

impl FitKind {
    pub fn label(self) -> &'static str {
        match self {
            FitKind::Slow => "slow",
            FitKind::Full => "full",
            FitKind::Stribeck => "stribeck",
            FitKind::Presliding => "presliding",
            FitKind::Staged => "staged",
        }
    }

    /// Whether the fit's model uses parameter `i` of `family` (the steady-state curve (T1) has
    /// no `sigma0`, `sigma1`; the slow loop only its two).
    pub(crate) fn uses(self, family: Family, i: usize) -> bool {
        match self {
            FitKind::Slow => family.slow_parameters().contains(&i),
            FitKind::Stribeck => !LUGRE_DYNAMIC.contains(&i),
            FitKind::Full | FitKind::Presliding | FitKind::Staged => true,
        }
    }

    /// Whether the fit frees parameter `i` of `family` unless told otherwise.
    fn frees(self, family: Family, i: usize) -> bool {
        match self {
            FitKind::Slow => self.uses(family, i),
            FitKind::Stribeck => self.uses(family, i) && family.full_default(i),
            FitKind::Presliding => LUGRE_DYNAMIC.contains(&i),
            FitKind::Full | FitKind::Staged => family.full_default(i),
        }
    }
}

/// The parameters of the bristles' dynamics, `sigma0` and `sigma1`: absent from the
/// steady-state curve, and what a presliding test determines.
const LUGRE_DYNAMIC: [usize; 2] = [
    index_of(&Parameter::LUGRE, Parameter::Sigma0),
    index_of(&Parameter::LUGRE, Parameter::Sigma1),
];

/// Bounds `0 <= lo < hi <= inf` on a parameter. Every parameter of the models is positive, so
/// the default is `(0, inf)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounds {
    pub lo: f64,
    pub hi: f64,
}

impl Bounds {
    pub(crate) const POSITIVE: Bounds = Bounds {
        lo: 0.0,
        hi: f64::INFINITY,
    };

    fn check(self, name: &'static str) -> Result<Self, FitError> {
        let ok = self.lo >= 0.0 && self.lo.is_finite() && self.hi > self.lo && !self.hi.is_nan();
        if ok {
            Ok(self)
        } else {
            Err(FitError::BadBounds {
                name,
                lo: self.lo,
                hi: self.hi,
            })
        }
    }

    /// Strictly inside.
    pub(crate) fn contains(self, p: f64) -> bool {
        p > self.lo && p < self.hi
    }

    /// A start from the data moved strictly inside (a start the user gave is never moved: it
    /// is an error instead).
    pub(crate) fn pull_inside(self, p: f64) -> f64 {
        if self.contains(p) {
            return p;
        }
        if self.hi.is_finite() {
            // 5 % in from the violated bound: inside, and not where the logistic map is flat.
            let span = self.hi - self.lo;
            if p <= self.lo {
                self.lo + 0.05 * span
            } else {
                self.hi - 0.05 * span
            }
        } else if self.lo > 0.0 {
            2.0 * self.lo
        } else {
            // Only a start of 0 or below with bounds (0, inf): data starts are positive, but
            // keep the map defined.
            f64::MIN_POSITIVE.max(p.abs())
        }
    }

    /// Whether the estimate `p` is at a bound: [`Self::at_bound`], or, for the bound 0, below `1e-6` of the fit's start `start`: the
    /// log-map's variable has run 14 units towards minus infinity, which only a push against
    /// the bound does (`sigma2 = 0` in data without viscous friction).
    pub(crate) fn reached(self, p: f64, start: f64) -> bool {
        self.at_bound(p) || (self.lo == 0.0 && p <= AT_ZERO_OF_START * start)
    }

    /// Cuts `x` to the bounds (an interval of an estimate at its bound ends there).
    pub(crate) fn clamp(self, x: f64) -> f64 {
        x.max(self.lo).min(self.hi)
    }

    /// Where `p` sits relative to the bounds: within `1e-6` of the span (relative) of one of
    /// them, the optimizer's variable has run off to infinity and the estimate is the bound.
    fn at_bound(self, p: f64) -> bool {
        let near = |b: f64| (p - b).abs() <= 1e-6 * b.abs().max(p.abs());
        (self.lo > 0.0 && near(self.lo)) || (self.hi.is_finite() && near(self.hi))
    }
}

/// A fitted value this far below its start, with the bound 0, is at the bound.
const AT_ZERO_OF_START: f64 = 1e-6;

/// The map between a bounded parameter `p` and the unconstrained variable `theta` the
/// Levenberg-Marquardt iteration moves: `p = lo + exp(theta + shift)` for `hi = inf` (the
/// log-parametrisation for positive parameters), `p = lo + (hi - lo) / (1 + exp(-theta -
/// shift))` otherwise. The optimizer then needs no constraint handling, and a parameter that
/// the data push to a bound goes there asymptotically. The shift puts the start at
/// `theta = 1`: MINPACK's step test is relative to `|theta|`, which must not be near 0.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Transform {
    bounds: Bounds,
    shift: f64,
}

impl Transform {
    /// The map with `theta(start) = 1`.
    pub fn new(bounds: Bounds, start: f64) -> Self {
        let unshifted = Self { bounds, shift: 0.0 };
        Self {
            bounds,
            shift: unshifted.to_theta(start) - 1.0,
        }
    }

    pub fn to_theta(self, p: f64) -> f64 {
        let Bounds { lo, hi } = self.bounds;
        let raw = if hi.is_infinite() {
            (p - lo).ln()
        } else {
            ((p - lo) / (hi - p)).ln()
        };
        raw - self.shift
    }

    pub fn to_p(self, theta: f64) -> f64 {
        let Bounds { lo, hi } = self.bounds;
        let raw = theta + self.shift;
        if hi.is_infinite() {
            lo + raw.exp()
        } else {
            lo + (hi - lo) / (1.0 + (-raw).exp())
        }
    }

    /// `dp / dtheta` at `p`.
    pub fn slope(self, p: f64) -> f64 {
        let Bounds { lo, hi } = self.bounds;
        if hi.is_infinite() {
            p - lo
        } else {
            (p - lo) * (hi - p) / (hi - lo)
        }
    }
}

/// The request: the model, the value of every parameter (fixed ones keep it), which parameters
/// are free, start values and bounds.
///
/// A free parameter starts from the value given with [`FitSpec::set`], else from the data (see
/// the module docs): no guess is needed. The parameters a fit frees by default are `sigma0`
/// and `fs = g(0)` (slow fit; Dahl: `rho`, `fc`) and `sigma0, sigma1, sigma2, fc, fs, vs`
/// (full fit; `beta` stays fixed unless freed; Dahl: `rho`, `fc`).
#[derive(Debug, Clone, PartialEq)]
pub struct FitSpec {
    family: Family,
    values: Vec<f64>,
    start_given: Vec<bool>,
    /// The value was given (a model's values, `set`), not a family default: a parameter the
    /// fit holds must have one.
    value_given: Vec<bool>,
    fixed: Vec<bool>,
    freed: Vec<bool>,
    bounds: Vec<Bounds>,
}

/// A spec resolved for one kind of fit.
#[derive(Debug, Clone)]
pub(crate) struct Resolved {
    pub family: Family,
    /// Every parameter of the family (free ones: their start, once chosen).
    pub values: Vec<f64>,
    /// Indices of the free parameters, in the family's order.
    pub free: Vec<usize>,
    /// Whether the user gave each free parameter's start.
    pub given: Vec<bool>,
    pub bounds: Vec<Bounds>,
}

impl Resolved {
    pub fn names(&self) -> Vec<&'static str> {
        self.free
            .iter()
            .map(|&i| self.family.parameters()[i])
            .collect()
    }

    /// The space the optimizer moves in ([`super::lm::minimize`]).
    pub fn space(&self) -> super::lm::Space<'_> {
        super::lm::Space {
            values: &self.values,
            free: &self.free,
            bounds: &self.bounds,
        }
    }

    /// Data starts for the free parameters without a given one, pulled inside their bounds.
    pub fn fill_starts(&mut self, data_start: &[f64]) {
        for (j, &i) in self.free.iter().enumerate() {
            if !self.given[j] {
                self.values[i] = self.bounds[j].pull_inside(data_start[i]);
            }
        }
    }

    pub fn free_values(&self) -> Vec<f64> {
        self.free_values_of(&self.values)
    }

    /// The free entries of a family parameter vector.
    pub fn free_values_of(&self, values: &[f64]) -> Vec<f64> {
        self.free.iter().map(|&i| values[i]).collect()
    }

    /// The LuGre parameters these values stand for (Dahl: `sigma0 = rho Fc`, `g = Fc`).
    pub fn lugre(&self, values: &[f64]) -> LuGreParams {
        lugre_params(self.family, values)
    }
}

/// The LuGre parameters of a family's parameter vector.
pub(crate) fn lugre_params(family: Family, v: &[f64]) -> LuGreParams {
    match family {
        Family::LuGre => {
            let mut p = LuGreParams::default();
            for (q, &x) in Parameter::LUGRE.iter().zip(v) {
                p.set(*q, x);
            }
            p
        }
        Family::Dahl => Dahl::lugre_params(v[0], v[1]),
    }
}

impl FitSpec {
    /// The LuGre model with these values (for the fixed parameters; free ones start from the
    /// data).
    pub fn lugre(p: LuGreParams) -> Self {
        let values = p.named().map(|(_, v)| v).to_vec();
        Self::with_values(Family::LuGre, values, true)
    }

    /// The Dahl model with these values (for the fixed parameter; free ones start from the data).
    pub fn dahl(rho: f64, fc: f64) -> Self {
        Self::with_values(Family::Dahl, vec![rho, fc], true)
    }

    /// The family with its defaults: the paper's LuGre parameters ([`LuGreParams::default`]),
    /// Dahl `rho = 1`, `Fc = 1`. They are the paper's dimensionless values, not a
    /// measurement's: a parameter the fit holds must then be given ([`set`](Self::set)).
    pub fn new(family: Family) -> Self {
        let defaults = match family {
            Family::LuGre => Parameter::LUGRE.map(Parameter::default_value).to_vec(),
            Family::Dahl => Parameter::DAHL.map(Parameter::default_value).to_vec(),
        };
        Self::with_values(family, defaults, false)
    }

    fn with_values(family: Family, values: Vec<f64>, given: bool) -> Self {
        let n = values.len();
        Self {
            family,
            values,
            start_given: vec![false; n],
            value_given: vec![given; n],
            fixed: vec![false; n],
            freed: vec![false; n],
            bounds: vec![Bounds::POSITIVE; n],
        }
    }

    pub fn family(&self) -> Family {
        self.family
    }

    /// The value of parameter `name`: kept if it is fixed, the start if it is free.
    pub fn set(mut self, name: &str, value: f64) -> Result<Self, FitError> {
        let i = self.family.index(name)?;
        // The parameter's domain (sigma0 > 0, sigma2 >= 0, ...): a value held at, or started
        // from, a value no model has is refused here, not found unevaluable in the fit.
        if let Some(p) = Parameter::from_name(self.family.parameters()[i]) {
            p.check(value)?;
        }
        self.values[i] = value;
        self.start_given[i] = true;
        self.value_given[i] = true;
        Ok(self)
    }

    /// Keeps `name` at its value.
    pub fn fix(mut self, name: &str) -> Result<Self, FitError> {
        let i = self.family.index(name)?;
        self.fixed[i] = true;
        Ok(self)
    }

    /// Fits `name` too (e.g. `beta` in a full fit).
    pub fn free(mut self, name: &str) -> Result<Self, FitError> {
        let i = self.family.index(name)?;
        self.freed[i] = true;
        Ok(self)
    }

    /// Bounds `0 <= lo < hi <= inf` on `name`.
    pub fn bounds(mut self, name: &str, lo: f64, hi: f64) -> Result<Self, FitError> {
        let i = self.family.index(name)?;
        self.bounds[i] = Bounds { lo, hi }.check(self.family.parameters()[i])?;
        Ok(self)
    }

    /// The value of `name` (its start, if it is free and was given).
    pub fn value(&self, name: &str) -> Result<f64, FitError> {
        Ok(self.values[self.family.index(name)?])
    }

    /// This spec with every parameter but those of `free` held (at its value), and the
    /// starts `(index, value)` given to those the user gave none.
    pub(crate) fn holding_all_but(&self, free: &[usize], starts: &[(usize, f64)]) -> FitSpec {
        let mut out = self.clone();
        for i in 0..out.values.len() {
            if free.contains(&i) {
                out.fixed[i] = false;
                out.freed[i] = true;
            } else {
                out.fixed[i] = true;
                out.freed[i] = false;
                // Held at its value (a default here is one the fit never uses: checked by
                // the caller's resolve).
                out.value_given[i] = true;
            }
        }
        for &(i, v) in starts {
            if free.contains(&i) && !self.start_given[i] && v.is_finite() && v > 0.0 {
                out.values[i] = v;
                out.start_given[i] = true;
            }
        }
        out
    }

    /// The free parameters of a fit of this kind, checked.
    pub(crate) fn resolve(&self, kind: FitKind) -> Result<Resolved, FitError> {
        let names = self.family.parameters();
        if self.family == Family::Dahl
            && matches!(
                kind,
                FitKind::Stribeck | FitKind::Presliding | FitKind::Staged
            )
        {
            return Err(FitError::NotForFamily {
                fit: kind.label(),
                family: self.family.label(),
            });
        }
        let mut free = Vec::new();
        for (i, &name) in names.iter().enumerate() {
            if self.fixed[i] && self.freed[i] {
                return Err(FitError::FixedAndFree { name });
            }
            if self.freed[i] && !kind.uses(self.family, i) {
                return Err(match kind {
                    FitKind::Stribeck => FitError::NotInSteadyState { name },
                    _ => FitError::NotInSlowLoop { name },
                });
            }
            let full = matches!(kind, FitKind::Full | FitKind::Staged);
            if self.freed[i] && full && !self.family.in_full_fit(i) {
                return Err(FitError::NotInFullFit { name });
            }
            if (kind.frees(self.family, i) || self.freed[i]) && !self.fixed[i] {
                free.push(i);
            }
        }
        if free.is_empty() {
            return Err(FitError::NothingToFit { fit: kind.label() });
        }
        // A parameter the model of this fit uses, held, must have a value from the user: the
        // family's defaults are the paper's dimensionless values.
        for (i, &name) in names.iter().enumerate() {
            // A parameter the fit cannot fit, left alone, keeps a default that means "absent"
            // (Parameter::default_is_absence): the model without it.
            let absent = matches!(kind, FitKind::Full | FitKind::Staged)
                && !self.fixed[i]
                && !self.family.in_full_fit(i)
                && self.family.table()[i].default_is_absence();
            if kind.uses(self.family, i) && !free.contains(&i) && !self.value_given[i] && !absent {
                return Err(FitError::NotGiven {
                    name,
                    fit: kind.label(),
                    example: example_value(name),
                });
            }
        }
        let mut given = Vec::with_capacity(free.len());
        let mut bounds = Vec::with_capacity(free.len());
        for &i in &free {
            let b = self.bounds[i].check(names[i])?;
            let v = self.values[i];
            if self.start_given[i] {
                if !(v.is_finite() && v > 0.0) {
                    return Err(FitError::BadStart {
                        name: names[i],
                        value: v,
                    });
                }
                if !b.contains(v) {
                    return Err(FitError::StartOutsideBounds {
                        name: names[i],
                        start: v,
                        lo: b.lo,
                        hi: b.hi,
                    });
                }
            }
            given.push(self.start_given[i]);
            bounds.push(b);
        }
        Ok(Resolved {
            family: self.family,
            values: self.values.clone(),
            free,
            given,
            bounds,
        })
    }
}

/// A value to suggest for a held parameter nobody gave (the message's example).
fn example_value(name: &str) -> &'static str {
    match name {
        "beta" => "2, the usual Stribeck exponent",
        "sigma2" => "0 for no viscous friction",
        _ => "a value from your setup",
    }
}

#[cfg(test)]
mod tests {

    #[test]
    fn the_families_are_the_tables() {
        for f in [Family::LuGre, Family::Dahl] {
            let names: Vec<&str> = f.table().iter().map(|p| p.name()).collect();
            assert_eq!(names, f.parameters());
            let e = f.index("mu").unwrap_err().to_string();
            assert!(
                e.ends_with(&format!("(its parameters: {})", names.join(", "))),
                "{e}"
            );
        }
        let slow = Family::LuGre.slow_parameters().map(|i| Parameter::LUGRE[i]);
        assert_eq!(slow, Parameter::LUGRE_RATE_INDEPENDENT);
        // A full fit holds beta (and any parameter it has no derivative for), frees the rest.
        for (i, p) in Parameter::LUGRE.into_iter().enumerate() {
            let want = p != Parameter::Beta && full::differentiates(p);
            assert_eq!(Family::LuGre.full_default(i), want, "{p}");
        }
        assert_eq!(Family::Dahl.slow_parameters(), [0, 1]);
    }

    use super::*;

    #[test]
    fn transforms_round_trip_and_stay_inside() {
        for b in [
            Bounds::POSITIVE,
            Bounds {
                lo: 2.0,
                hi: f64::INFINITY,
            },
            Bounds { lo: 0.5, hi: 3.0 },
        ] {
            let t = Transform::new(b, 2.5);
            assert!((t.to_theta(2.5) - 1.0).abs() < 1e-15);
            for p in [0.6, 1.0, 2.5, 2.9] {
                if !b.contains(p) {
                    continue;
                }
                let theta = t.to_theta(p);
                assert!((t.to_p(theta) - p).abs() <= 1e-15 * p.max(1.0) * 4.0);
                let h = 1e-6;
                let fd = (t.to_p(theta + h) - t.to_p(theta - h)) / (2.0 * h);
                assert!((fd - t.slope(p)).abs() < 1e-8 * t.slope(p).max(1.0));
            }
            for theta in [-1e3, -30.0, 0.0, 30.0] {
                let p = t.to_p(theta);
                assert!(p >= b.lo && p <= b.hi, "{p} outside {b:?}");
            }
        }
    }

    #[test]
    fn free_sets_by_kind() {
        // The family's defaults are no values for held parameters: beta is held in a full fit.
        assert_eq!(
            FitSpec::new(Family::LuGre)
                .resolve(FitKind::Full)
                .unwrap_err(),
            FitError::NotGiven {
                name: "beta",
                fit: "full",
                example: "2, the usual Stribeck exponent"
            }
        );
        // The free parameters by name, whatever their places in the table.
        let free = |s: &FitSpec, kind| -> Vec<&str> {
            let names = s.family().parameters();
            s.resolve(kind)
                .unwrap()
                .free
                .iter()
                .map(|&i| names[i])
                .collect()
        };
        let s = FitSpec::lugre(LuGreParams::default());
        assert_eq!(free(&s, FitKind::Slow), ["sigma0", "fs"]);
        assert_eq!(
            free(&s, FitKind::Full),
            ["sigma0", "sigma1", "sigma2", "fc", "fs", "vs"]
        );
        let s = s.fix("sigma2").unwrap().free("beta").unwrap();
        assert_eq!(
            free(&s, FitKind::Full),
            ["sigma0", "sigma1", "fc", "fs", "vs", "beta"]
        );
        assert_eq!(
            s.resolve(FitKind::Slow).unwrap_err(),
            FitError::NotInSlowLoop { name: "beta" }
        );
        let s = FitSpec::new(Family::Dahl)
            .fix("rho")
            .unwrap()
            .fix("FC")
            .unwrap();
        assert_eq!(
            s.resolve(FitKind::Slow).unwrap_err(),
            FitError::NothingToFit { fit: "slow" }
        );
        assert!(matches!(
            FitSpec::new(Family::Dahl).fix("sigma0"),
            Err(FitError::UnknownParameter { .. })
        ));
        let both = FitSpec::new(Family::Dahl)
            .fix("rho")
            .unwrap()
            .free("rho")
            .unwrap();
        assert_eq!(
            both.resolve(FitKind::Full).unwrap_err(),
            FitError::FixedAndFree { name: "rho" }
        );
    }

    #[test]
    fn starts_and_bounds_are_checked() {
        let s = FitSpec::new(Family::LuGre).set("sigma0", 5.0).unwrap();
        let s2 = s.clone().bounds("sigma0", 10.0, 100.0).unwrap();
        assert_eq!(
            s2.resolve(FitKind::Slow).unwrap_err(),
            FitError::StartOutsideBounds {
                name: "sigma0",
                start: 5.0,
                lo: 10.0,
                hi: 100.0
            }
        );
        assert!(matches!(
            s.clone().bounds("sigma0", 3.0, 1.0),
            Err(FitError::BadBounds { .. })
        ));
        assert!(matches!(
            s.bounds("sigma0", -1.0, 1.0),
            Err(FitError::BadBounds { .. })
        ));
        let b = Bounds { lo: 1.0, hi: 2.0 };
        assert_eq!(b.pull_inside(5.0), 1.95);
        assert_eq!(b.pull_inside(0.1), 1.05);
    }
}
