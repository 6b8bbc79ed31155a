//! Stable elementary functions of the closed forms, and double-double accumulation.
//!
//! Every exponential in this crate has a non-positive argument. On a segment of length `l` the
//! loop relaxes like `exp(-z)` with `z = a l >= 0`; the closed forms need
//!
//! * `phi(z)          = (1 - exp(-z)) / z`            (`-expm1(-z) / z`),
//! * `one_minus_phi(z) = 1 - phi(z) = (z - 1 + exp(-z)) / z`,
//! * `h(z)            = (1 - phi(z)) / z`,
//! * `q(z)            = 1 - 2 phi(z) + phi(2z) = integral_0^1 (1 - exp(-z t))^2 dt`,
//!
//! each accurate to a few ulps for every `z` in `[0, inf]`. Where the direct formula cancels
//! (small `z`) a Taylor series is used instead.

/// `(1 - exp(-z)) / z` for `z >= 0`, with `phi(0) = 1` and `phi(inf) = 0`.
#[inline]
pub fn phi(z: f64) -> f64 {
    if z == 0.0 {
        1.0
    } else {
        -(-z).exp_m1() / z
    }
}

/// `1 - exp(-z)` for `z >= 0`, without cancellation.
#[inline]
pub fn one_minus_exp(z: f64) -> f64 {
    -(-z).exp_m1()
}

/// `h(z) = (1 - phi(z)) / z = (z - 1 + exp(-z)) / z^2` for `z >= 0` (1/2 at 0, `~1/z` at
/// infinity).
#[inline]
pub fn h(z: f64) -> f64 {
    if z < 1.0 {
        // sum_{n>=0} (-z)^n / (n+2)!  ; 20 terms reach 1/22! < 1e-21.
        let mut term = 0.5;
        let mut sum = 0.5;
        for n in 1..20 {
            term *= -z / (n as f64 + 2.0);
            sum += term;
        }
        sum
    } else {
        (1.0 - phi(z)) / z
    }
}

/// `1 - phi(z) = (z - 1 + exp(-z)) / z` for `z >= 0` (tends to `z/2` at 0 and 1 at infinity).
#[inline]
pub fn one_minus_phi(z: f64) -> f64 {
    if z < 1.0 {
        z * h(z)
    } else {
        1.0 - phi(z)
    }
}

/// `phi(z) - phi(2z)` for `z >= 0` (tends to `z/2` at 0).
#[inline]
pub fn phi_minus_phi2(z: f64) -> f64 {
    if z < 1.0 {
        z * (2.0 * h(2.0 * z) - h(z))
    } else {
        phi(z) - phi(2.0 * z)
    }
}

/// `q(z) / z` where `q(z) = 1 - 2 phi(z) + phi(2z) = integral_0^1 (1 - exp(-z t))^2 dt`, for
/// `z > 0` (tends to `z/3` at 0 and `1/z` at infinity).
#[inline]
pub fn q_over_z(z: f64) -> f64 {
    if z < 1.0 {
        // sum_{n>=2} (-1)^n z^(n-1) (2^n - 2) / (n+1)!  ; 26 terms reach 2^27/28! < 1e-20.
        let mut zn_fact = z / 6.0; // z^(2-1) / 3!
        let mut pow2 = 4.0;
        let mut sum = zn_fact * (pow2 - 2.0);
        for n in 3..28 {
            zn_fact *= -z / (n as f64 + 1.0);
            pow2 *= 2.0;
            sum += zn_fact * (pow2 - 2.0);
        }
        sum
    } else {
        (1.0 - 2.0 * phi(z) + phi(2.0 * z)) / z
    }
}

/// An unevaluated sum `hi + lo` with `|lo| <= ulp(hi)/2`: about 32 significant digits, used for
/// running sums of work along many segments so that differences of prefix sums stay exact.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct DoubleDouble {
    pub hi: f64,
    pub lo: f64,
}

impl DoubleDouble {
    pub const ZERO: Self = Self { hi: 0.0, lo: 0.0 };

    #[inline]
    pub fn from_f64(x: f64) -> Self {
        Self { hi: x, lo: 0.0 }
    }

    /// Knuth's two-sum: `a + b = s + e` exactly.
    #[inline]
    fn two_sum(a: f64, b: f64) -> (f64, f64) {
        let s = a + b;
        let bb = s - a;
        let e = (a - (s - bb)) + (b - bb);
        (s, e)
    }

    #[inline]
    pub fn add_f64(self, x: f64) -> Self {
        let (s, e) = Self::two_sum(self.hi, x);
        let e = e + self.lo;
        let (hi, lo) = Self::two_sum(s, e);
        Self { hi, lo }
    }

    #[inline]
    pub fn to_f64(self) -> f64 {
        self.hi + self.lo
    }
}

impl std::ops::Add for DoubleDouble {
    type Output = Self;
    #[inline]
    fn add(self, other: Self) -> Self {
        let (s, e) = Self::two_sum(self.hi, other.hi);
        let e = e + self.lo + other.lo;
        let (hi, lo) = Self::two_sum(s, e);
        Self { hi, lo }
    }
}

impl std::ops::Neg for DoubleDouble {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}

impl std::ops::Sub for DoubleDouble {
    type Output = Self;
    #[inline]
    fn sub(self, other: Self) -> Self {
        self + (-other)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    // Reference values: mpmath with mp.dps = 50, e.g.
    //   phi = lambda z: -mp.expm1(-z)/z ; omp = lambda z: 1 - phi(z)
    //   q = lambda z: 1 - 2*phi(z) + phi(2*z)
    // printed with mp.nstr(x, 20).
    const PHI: [(f64, f64); 5] = [
        (1e-12, 0.9999999999995),
        (1e-3, 0.99950016662500833194),
        (0.5, 0.78693868057473315279),
        (1.0, 0.6321205588285576784),
        (30.0, 0.033333333333330214126),
    ];
    const OMP: [(f64, f64); 5] = [
        (1e-12, 4.9999999999983333333e-13),
        (1e-3, 0.00049983337499166805536),
        (0.5, 0.21306131942526684721),
        (1.0, 0.3678794411714423216),
        (30.0, 0.96666666666666978587),
    ];
    const Q: [(f64, f64); 5] = [
        (1e-12, 3.3333333333308333333e-25),
        (1e-3, 3.330834499583456318e-7),
        (0.5, 0.05824319767909137282),
        (1.0, 0.16809124072457829724),
        (30.0, 0.95000000000000623842),
    ];

    // phi(z) - phi(2z), same tool.
    const PMP: [(f64, f64); 5] = [
        (1e-12, 4.999999999995e-13),
        (1e-3, 0.00049950029154170970973),
        (0.5, 0.15481812174617547439),
        (1.0, 0.19978820044686402435),
        (30.0, 0.016666666666663547459),
    ];

    fn rel(a: f64, b: f64) -> f64 {
        ((a - b) / b).abs()
    }

    #[test]
    fn phi_family_matches_mpmath() {
        for (z, want) in PHI {
            assert!(rel(phi(z), want) < 4e-15, "phi({z}) = {}", phi(z));
        }
        for (z, want) in OMP {
            assert!(
                rel(one_minus_phi(z), want) < 4e-15,
                "1-phi({z}) = {}",
                one_minus_phi(z)
            );
        }
        for (z, want) in Q {
            let got = q_over_z(z) * z;
            assert!(rel(got, want) < 1e-14, "q({z}) = {got}");
        }
        for (z, want) in PMP {
            let got = phi_minus_phi2(z);
            assert!(rel(got, want) < 1e-14, "phi({z}) - phi(2z) = {got}");
        }
    }

    #[test]
    fn limits_are_finite() {
        assert_eq!(phi(0.0), 1.0);
        assert_eq!(phi(f64::INFINITY), 0.0);
        assert_eq!(one_minus_phi(f64::INFINITY), 1.0);
        assert_eq!(q_over_z(f64::INFINITY), 0.0);
        assert_eq!(h(0.0), 0.5);
        assert_eq!(one_minus_phi(0.0), 0.0);
    }

    #[test]
    fn double_double_keeps_small_terms() {
        let s = DoubleDouble::from_f64(1e17).add_f64(1.0).add_f64(-1e17);
        assert_eq!(s.to_f64(), 1.0);
    }
}
