//! Periodic inputs, reduced to what the rate-independent limit sees: the cyclic sequence of
//! turning points (paper §3.2.2: the normalized input `psi_u = u o rho_u^-1` is piecewise linear
//! with slopes +-1 between consecutive extrema).
//!
//! Conventions:
//! * a period is given once; a trailing value equal to the first one (the period closing on
//!   itself) is the same point and is dropped;
//! * repeated consecutive values are collapsed, and points that are not reversals (the input
//!   keeps its direction through them) are dropped, cyclically;
//! * rho is measured from the first listed point that is a turning point.
//!
//! The checks every series of numbers goes through (finite, strictly increasing times, output
//! times inside a run) live here, with their errors in [`DataError`]: the library, the
//! command line, the Python package and the C ABI word them alike.

use crate::error::{num, DataError, InputError};

/// One period of a periodic input as its cyclic sequence of turning points (alternating local
/// maxima and minima, at least two, all finite).
#[derive(Debug, Clone, PartialEq)]
pub struct TurningPoints {
    u: Vec<f64>,
}

impl TurningPoints {
    /// The turning points of the cyclic sequence `values` (see the module conventions).
    pub fn new(values: &[f64]) -> Result<Self, InputError> {
        check_all_finite("u", values)?;
        Ok(Self {
            u: reversals(values)?,
        })
    }

    /// The turning points of one period of samples `(t, u)`, linear between samples. Only the
    /// turning points matter in the rate-independent limit; `t` is validated (finite, strictly
    /// increasing) but otherwise unused.
    pub fn from_samples(t: &[f64], u: &[f64]) -> Result<Self, InputError> {
        if t.len() != u.len() {
            return Err(InputError::LengthMismatch {
                t: t.len(),
                u: u.len(),
            });
        }
        check_times(t)?;
        Self::new(u)
    }

    /// The turning points, in order, first at rho = 0.
    pub fn values(&self) -> &[f64] {
        &self.u
    }

    pub fn len(&self) -> usize {
        self.u.len()
    }

    pub fn is_empty(&self) -> bool {
        self.u.is_empty()
    }
}

/// Checks that every value is finite, naming the first one that is not.
pub fn check_finite(what: &'static str, values: &[f64]) -> Result<(), DataError> {
    match values.iter().position(|v| !v.is_finite()) {
        Some(index) => Err(DataError::NotFinite {
            what,
            index: index as u64,
            value: values[index],
        }),
        None => Ok(()),
    }
}

/// Checks that (finite) times are strictly increasing, naming the first that is not.
pub fn check_increasing(t: &[f64]) -> Result<(), DataError> {
    increasing("times", t)
}

/// Checks that `t` (the `what`) is strictly increasing.
fn increasing(what: &'static str, t: &[f64]) -> Result<(), DataError> {
    match (1..t.len()).find(|&i| t[i] <= t[i - 1]) {
        Some(index) => Err(DataError::TimesNotIncreasing {
            what,
            index: index as u64,
            prev: t[index - 1],
            value: t[index],
        }),
        None => Ok(()),
    }
}

/// How far (in units of the run's largest time) an output time may lie outside the run
/// `[start, end]` and still be reported, at the end it is beyond (see [`check_output_times`]).
const OUTPUT_TIME_SLACK: f64 = 8.0 * f64::EPSILON;

/// Checks output times for a run over `[start, end]`: finite, strictly increasing, and inside
/// the run up to 8 units in the last place of its largest time `max(|start|, |end|, end - start)`.
///
/// One rule for every run (simulate, dynamics): an end is often computed (`periods x period`,
/// `3 x 4.6 = 13.799999999999999`) and output times are often computed too (`numpy.arange`,
/// `k dt`), so a time meant as the end can differ from it by a few units in the last place
/// on either side. Such a time belongs to the run and is reported at the end's state; a time
/// further out is refused. (8 ulps covers a sum or product of a few rounded terms; a time
/// off by more is not the end.)
pub fn check_output_times(times: &[f64], start: f64, end: f64) -> Result<(), DataError> {
    check_finite("t", times)?;
    increasing("output times", times)?;
    let slack = OUTPUT_TIME_SLACK * start.abs().max(end.abs()).max(end - start);
    match times
        .iter()
        .position(|&t| t < start - slack || t > end + slack)
    {
        Some(index) => Err(DataError::TimeOutOfRange {
            index: index as u64,
            value: times[index],
            start,
            end,
        }),
        None => Ok(()),
    }
}

/// Checks that there are values and every one is finite.
pub fn check_all_finite(what: &'static str, values: &[f64]) -> Result<(), InputError> {
    if values.is_empty() {
        return Err(InputError::Empty);
    }
    Ok(check_finite(what, values)?)
}

/// Checks that times are finite and strictly increasing.
pub fn check_times(t: &[f64]) -> Result<(), InputError> {
    check_all_finite("t", t)?;
    Ok(check_increasing(t)?)
}

/// The reversals of a cyclic sequence of finite values.
fn reversals(values: &[f64]) -> Result<Vec<f64>, InputError> {
    let mut distinct: Vec<f64> = Vec::with_capacity(values.len());
    for &v in values {
        if distinct.last() != Some(&v) {
            distinct.push(v);
        }
    }
    while distinct.len() > 1 && distinct.last() == distinct.first() {
        distinct.pop();
    }
    if distinct.len() < 2 {
        return Err(InputError::TooFewDistinct {
            distinct: distinct.len(),
        });
    }
    let n = distinct.len();
    let is_reversal = |i: usize| {
        let prev = distinct[(i + n - 1) % n];
        let next = distinct[(i + 1) % n];
        let v = distinct[i];
        (v > prev) != (next > v)
    };
    let turning: Vec<f64> = (0..n)
        .filter(|&i| is_reversal(i))
        .map(|i| distinct[i])
        .collect();
    Ok(turning)
}

/// The paper's bimodal input (Definition 1): turning points visited in the order
/// `umin1, umax1, umin2, umax2`, with `umin1 <= umin2 < umax1 <= umax2` and not both
/// `umin1 == umin2` and `umax1 == umax2`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bimodal {
    pub umin1: f64,
    pub umin2: f64,
    pub umax1: f64,
    pub umax2: f64,
}

impl Bimodal {
    /// Validated against Definition 1; the error names the inequality that fails.
    pub fn new(umin1: f64, umin2: f64, umax1: f64, umax2: f64) -> Result<Self, InputError> {
        check_all_finite("bimodal", &[umin1, umin2, umax1, umax2])?;
        let fail = |inequality: &'static str, detail: String| {
            Err(InputError::Definition1 { inequality, detail })
        };
        if umin1 > umin2 {
            return fail(
                "umin1 <= umin2",
                format!("umin1 = {}, umin2 = {}", num(umin1), num(umin2)),
            );
        }
        if umin2 >= umax1 {
            return fail(
                "umin2 < umax1",
                format!("umin2 = {}, umax1 = {}", num(umin2), num(umax1)),
            );
        }
        if umax1 > umax2 {
            return fail(
                "umax1 <= umax2",
                format!("umax1 = {}, umax2 = {}", num(umax1), num(umax2)),
            );
        }
        if umin1 == umin2 && umax1 == umax2 {
            return fail(
                "umin1 != umin2 or umax1 != umax2",
                format!(
                    "umin1 = umin2 = {} and umax1 = umax2 = {}",
                    num(umin1),
                    num(umax1)
                ),
            );
        }
        let b = Self {
            umin1,
            umin2,
            umax1,
            umax2,
        };
        if !b.rho()[4].is_finite() {
            return Err(InputError::VariationOverflow);
        }
        Ok(b)
    }

    /// The cyclic sequence `umin1, umax1, umin2, umax2` (every one a reversal under
    /// Definition 1, so rho = 0 is at `umin1`).
    pub fn turning_points(&self) -> TurningPoints {
        TurningPoints {
            u: vec![self.umin1, self.umax1, self.umin2, self.umax2],
        }
    }

    /// Theorem A's `rho_0 .. rho_5`: the turning points at `rho_0..rho_3`, the period
    /// `rho_4`, and `rho_5 = rho_2 + umax1 - umin2`, where the input first returns to `umax1`.
    pub fn rho(&self) -> [f64; 6] {
        let r1 = self.umax1 - self.umin1;
        let r2 = r1 + (self.umax1 - self.umin2);
        let r3 = r2 + (self.umax2 - self.umin2);
        let r4 = r3 + (self.umax2 - self.umin1);
        let r5 = r2 + (self.umax1 - self.umin2);
        [0.0, r1, r2, r3, r4, r5]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn drops_repeats_non_reversals_and_the_closing_point() {
        let tp = TurningPoints::new(&[0.0, 0.0, 0.5, 1.0, 1.0, 0.2, 1.5, 0.0]).unwrap();
        assert_eq!(tp.values(), &[0.0, 1.0, 0.2, 1.5]);
        // The first point is not a reversal: rho starts at the next one.
        let tp = TurningPoints::new(&[0.5, 1.0, -1.0, 0.0]).unwrap();
        assert_eq!(tp.values(), &[1.0, -1.0]);
    }

    #[test]
    fn rejects_degenerate_inputs() {
        assert_eq!(TurningPoints::new(&[]), Err(InputError::Empty));
        assert_eq!(
            TurningPoints::new(&[3.0, 3.0, 3.0]),
            Err(InputError::TooFewDistinct { distinct: 1 })
        );
        assert!(matches!(
            TurningPoints::new(&[0.0, f64::NAN]),
            Err(InputError::Data(DataError::NotFinite { index: 1, .. }))
        ));
        assert!(matches!(
            TurningPoints::from_samples(&[0.0, 1.0, 1.0], &[0.0, 1.0, 0.0]),
            Err(InputError::Data(DataError::TimesNotIncreasing {
                index: 2,
                ..
            }))
        ));
    }

    #[test]
    fn output_times_within_rounding_of_the_run_belong_to_it() {
        // 3 x 4.6 is computed as 13.799999999999999: 13.8 written by the user is its end.
        let end = 3.0 * 4.6;
        assert!(13.8 > end);
        assert_eq!(check_output_times(&[0.0, 13.8], 0.0, end), Ok(()));
        // numpy.arange(0, 1.0001, 0.1)[-1] is 1.0000000000000002.
        assert_eq!(check_output_times(&[1.0 + f64::EPSILON], 0.0, 1.0), Ok(()));
        assert_eq!(check_output_times(&[-f64::EPSILON], 0.0, 1.0), Ok(()));
        let beyond = 1.0 + 16.0 * f64::EPSILON;
        assert_eq!(
            check_output_times(&[0.5, beyond], 0.0, 1.0),
            Err(DataError::TimeOutOfRange {
                index: 1,
                value: beyond,
                start: 0.0,
                end: 1.0
            })
        );
        let e = check_output_times(&[0.5, 0.5], 0.0, 1.0).unwrap_err();
        assert_eq!(
            e.to_string(),
            "output times must be strictly increasing: t[1] = 0.5 after t[0] = 0.5"
        );
        let e = check_output_times(&[0.5, f64::NAN], 0.0, 1.0).unwrap_err();
        assert_eq!(e.to_string(), "t[1] must be a finite number, got NaN");
    }

    #[test]
    fn samples_of_a_sine_give_its_extrema() {
        let n = 1000;
        let t: Vec<f64> = (0..=n).map(|i| i as f64 / n as f64).collect();
        let u: Vec<f64> = t
            .iter()
            .map(|t| (2.0 * std::f64::consts::PI * t).sin())
            .collect();
        let tp = TurningPoints::from_samples(&t, &u).unwrap();
        assert_eq!(tp.len(), 2);
        assert_eq!(tp.values()[0], u[250]);
        assert_eq!(tp.values()[1], u[750]);
    }

    #[test]
    fn definition_1_names_the_failing_inequality() {
        let e = Bimodal::new(0.3, 0.2, 1.0, 1.5).unwrap_err();
        assert!(e.to_string().contains("umin1 <= umin2"), "{e}");
        let e = Bimodal::new(0.0, 1.0, 1.0, 1.5).unwrap_err();
        assert!(e.to_string().contains("umin2 < umax1"), "{e}");
        let e = Bimodal::new(0.0, 0.2, 1.6, 1.5).unwrap_err();
        assert!(e.to_string().contains("umax1 <= umax2"), "{e}");
        let e = Bimodal::new(0.0, 0.0, 1.0, 1.0).unwrap_err();
        assert!(e.to_string().contains("umin1 != umin2"), "{e}");
        assert!(Bimodal::new(0.0, 0.0, 1.0, 1.5).is_ok());
        assert!(Bimodal::new(0.0, 0.2, 1.0, 1.0).is_ok());
    }

    #[test]
    fn theorem_a_rhos_of_example_3() {
        // Paper §4.3: rho_1 = 1, rho_2 = 1.8, rho_3 = 3.1, rho_4 = 4.6.
        let r = Bimodal::new(0.0, 0.2, 1.0, 1.5).unwrap().rho();
        let want = [0.0, 1.0, 1.8, 3.1, 4.6, 2.6];
        for (a, b) in r.iter().zip(want) {
            assert!((a - b).abs() < 1e-15, "{r:?}");
        }
    }
}
