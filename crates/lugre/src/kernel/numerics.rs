//! Stable elementary functions of the closed forms, and double-double accumulation.
//!
//! Every exponential in this crate has a non-positive argument. On a segment of length `l` the
//! loop relaxes like `exp(-z)` with `z = a l >= 0`; the closed forms need
//!
//! * `phi(z) = (1 - exp(-z)) / z`            (`-expm1(-z) / z`),
//! * `h(z)   = (1 - phi(z)) / z`,
//! * `q(z)   = 1 - 2 phi(z) + phi(2z) = integral_0^1 (1 - exp(-z t))^2 dt`,
//!
//! each accurate to a few ulps for every `z` in `[0, inf]`. Where the direct formula cancels
//! (small `z`) a Taylor series is used instead. [`PhiFamily`] gives all of them (and
//! `phi(2z)`, `phi(z) - phi(2z)`) at one `z` from a single exponential.

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

/// Below this `z` the closed forms cancel and their Taylor series are used instead (at 0.5 the
/// direct forms lose at most 5 bits; the series need at most 20 terms).
const SERIES_BELOW: f64 = 0.5;

/// Taylor coefficients of `h(z) = sum_n (-1)^n z^n / (n+2)!`, `n = 0..15` (the last term is
/// below 1e-17 of the sum at `z = 0.5`).
const H_SERIES: [f64; 15] = [
    0.5,
    -0.16666666666666666,
    0.041666666666666664,
    -0.008333333333333333,
    0.001388888888888889,
    -0.0001984126984126984,
    2.48015873015873e-05,
    -2.7557319223985893e-06,
    2.755731922398589e-07,
    -2.505210838544172e-08,
    2.08767569878681e-09,
    -1.6059043836821613e-10,
    1.1470745597729725e-11,
    -7.647163731819816e-13,
    4.779477332387385e-14,
];

/// Taylor coefficients of `q(z)/z = sum_m (-1)^(m+1) (2^(m+1) - 2) z^m / (m+2)!`, `m = 1..20`.
const Q_SERIES: [f64; 19] = [
    0.3333333333333333,
    -0.25,
    0.11666666666666667,
    -0.041666666666666664,
    0.012301587301587301,
    -0.003125,
    0.0006999559082892416,
    -0.00014054232804232804,
    2.5603254769921436e-05,
    -4.2713844797178134e-06,
    6.574572546794769e-07,
    -9.394540644540644e-08,
    1.2527583625467223e-08,
    -1.5660435427300506e-09,
    1.8424603970627936e-10,
    -2.0472094573725967e-11,
    2.1549737648205952e-12,
    -2.1549819854558418e-13,
    2.052367710260443e-14,
];

/// `sum_i c[i] z^i` by Estrin's scheme: pairs `c[2i] + c[2i+1] z`, then pairs of those with
/// `z^2`, `z^4`, ...: the same few roundings as Horner's rule on these alternating series with
/// fast-falling terms, but a dependency chain of `log2(N)` steps instead of `N` (the series
/// are on the critical path of every piece of the loop).
#[inline(always)]
fn polynomial<const N: usize>(c: &[f64; N], z: f64) -> f64 {
    let mut terms = *c;
    let (mut len, mut x) = (N, z);
    while len > 1 {
        let half = len.div_ceil(2);
        for i in 0..half {
            let odd = if 2 * i + 1 < len {
                terms[2 * i + 1]
            } else {
                0.0
            };
            terms[i] = terms[2 * i] + odd * x;
        }
        len = half;
        x *= x;
    }
    terms[0]
}

/// `h(z) = (1 - phi(z)) / z = (z - 1 + exp(-z)) / z^2` for `z >= 0` (1/2 at 0, `~1/z` at
/// infinity).
#[inline]
pub fn h(z: f64) -> f64 {
    if z < SERIES_BELOW {
        polynomial(&H_SERIES, z)
    } else {
        (1.0 - phi(z)) / z
    }
}

/// The whole family at one `z >= 0` from at most one exponential, for the per-piece closed
/// forms that need several members at the same `z` (the loop's energies, [`crate::loops`]).
///
/// Below `z = 1/2` `h` and `q/z` come from their series and the rest from the identities
/// `phi = 1 - z h` and `exp(-z) = 1 - z phi` (no exponential at all); above, from `exp(-z)`.
/// Everywhere `phi(2z) = phi (1 + exp(-z)) / 2` and `phi(z) - phi(2z) = (1 - exp(-z)) phi / 2`,
/// which are exact identities without cancellation. `z = inf` gives `exp(-z) = phi = h = 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PhiFamily {
    /// `exp(-z)`
    pub e: f64,
    /// `1 - exp(-z)`, without cancellation.
    pub one_minus_e: f64,
    pub phi: f64,
    pub h: f64,
    /// `phi(2z)`
    pub phi2: f64,
    /// `phi(z) - phi(2z)`
    pub phi_minus_phi2: f64,
    /// `q(z) / z`
    pub q_over_z: f64,
}

impl PhiFamily {
    #[inline(always)]
    pub fn new(z: f64) -> Self {
        if z < SERIES_BELOW {
            Self::series(z)
        } else {
            Self::exponential(z)
        }
    }

    /// For `z < SERIES_BELOW`: no exponential, no division, no branch (so a loop of them
    /// vectorizes, see [`PhiBlock`]).
    #[inline(always)]
    fn series(z: f64) -> Self {
        let h = polynomial(&H_SERIES, z);
        let phi = 1.0 - z * h;
        let one_minus_e = z * phi;
        Self::with(
            1.0 - one_minus_e,
            one_minus_e,
            phi,
            h,
            z * polynomial(&Q_SERIES, z),
        )
    }

    #[inline(always)]
    fn exponential(z: f64) -> Self {
        let e = (-z).exp();
        let one_minus_e = 1.0 - e;
        let inv_z = 1.0 / z;
        let phi = one_minus_e * inv_z;
        let h = (1.0 - phi) * inv_z;
        let q_over_z = (1.0 - 2.0 * phi + 0.5 * phi * (1.0 + e)) * inv_z;
        Self::with(e, one_minus_e, phi, h, q_over_z)
    }

    #[inline(always)]
    fn with(e: f64, one_minus_e: f64, phi: f64, h: f64, q_over_z: f64) -> Self {
        Self {
            e,
            one_minus_e,
            phi,
            h,
            phi2: 0.5 * phi * (1.0 + e),
            phi_minus_phi2: 0.5 * one_minus_e * phi,
            q_over_z,
        }
    }
}

/// Lanes per [`PhiBlock`].
pub const BLOCK: usize = 64;

/// [`PhiFamily`] at up to [`BLOCK`] arguments, as columns: where every argument is below the
/// series threshold (short pieces, the common case away from saturation) the block is one
/// branch-free loop the compiler vectorizes; otherwise each lane is [`PhiFamily::new`]. The
/// values are the same either way.
#[derive(Debug, Clone)]
pub struct PhiBlock {
    e: [f64; BLOCK],
    one_minus_e: [f64; BLOCK],
    phi: [f64; BLOCK],
    h: [f64; BLOCK],
    phi2: [f64; BLOCK],
    phi_minus_phi2: [f64; BLOCK],
    q_over_z: [f64; BLOCK],
}

impl Default for PhiBlock {
    fn default() -> Self {
        Self {
            e: [0.0; BLOCK],
            one_minus_e: [0.0; BLOCK],
            phi: [0.0; BLOCK],
            h: [0.0; BLOCK],
            phi2: [0.0; BLOCK],
            phi_minus_phi2: [0.0; BLOCK],
            q_over_z: [0.0; BLOCK],
        }
    }
}

impl PhiBlock {
    /// The family at each `z[i]` into lane `i` (lanes past `z`'s end are left as they were).
    #[inline(always)]
    pub fn fill(&mut self, z: &[f64; BLOCK]) {
        if z.iter().all(|&z| z < SERIES_BELOW) {
            for (i, &z) in z.iter().enumerate() {
                self.set(i, PhiFamily::series(z));
            }
        } else {
            for (i, &z) in z.iter().enumerate() {
                self.set(i, PhiFamily::new(z));
            }
        }
    }

    #[inline(always)]
    fn set(&mut self, i: usize, f: PhiFamily) {
        self.e[i] = f.e;
        self.one_minus_e[i] = f.one_minus_e;
        self.phi[i] = f.phi;
        self.h[i] = f.h;
        self.phi2[i] = f.phi2;
        self.phi_minus_phi2[i] = f.phi_minus_phi2;
        self.q_over_z[i] = f.q_over_z;
    }

    #[inline(always)]
    pub fn get(&self, i: usize) -> PhiFamily {
        PhiFamily {
            e: self.e[i],
            one_minus_e: self.one_minus_e[i],
            phi: self.phi[i],
            h: self.h[i],
            phi2: self.phi2[i],
            phi_minus_phi2: self.phi_minus_phi2[i],
            q_over_z: self.q_over_z[i],
        }
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
    #[cfg(test)]
    pub fn from_f64(x: f64) -> Self {
        Self { hi: x, lo: 0.0 }
    }

    /// Knuth's two-sum: `a + b = s + e` exactly.
    #[inline(always)]
    pub(crate) fn two_sum(a: f64, b: f64) -> (f64, f64) {
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

    /// `a * b` exactly (Dekker's two-product with Veltkamp splitting, so no FMA instruction is
    /// needed), for `|a|, |b|` below about `1e300` and a product that neither over- nor
    /// underflows; beyond, `a * b` rounded (never NaN from the splitting).
    #[inline]
    pub fn product(a: f64, b: f64) -> Self {
        const SPLIT: f64 = 134_217_729.0; // 2^27 + 1
        let split = |x: f64| {
            let t = SPLIT * x;
            let hi = t - (t - x);
            (hi, x - hi)
        };
        let p = a * b;
        let (ah, al) = split(a);
        let (bh, bl) = split(b);
        let e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
        // Past about 1e300 the splitting overflows (e is NaN): the rounded product alone then.
        Self {
            hi: p,
            lo: if e.is_finite() { e } else { 0.0 },
        }
    }
}

impl std::ops::Add for DoubleDouble {
    type Output = Self;
    #[inline(always)]
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
    const PHI: [(f64, f64); 9] = [
        (1e-12, 0.9999999999995),
        (1e-3, 0.99950016662500833194),
        (0.2, 0.90634623461009070665),
        (0.3, 0.86393926439427377978),
        (0.49, 0.79055837921547741023),
        (0.51, 0.78334200232889030824),
        (0.7, 0.71916385172655783614),
        (1.0, 0.6321205588285576784),
        (30.0, 0.033333333333330214126),
    ];
    const OMP: [(f64, f64); 9] = [
        (1e-12, 4.9999999999983333333e-13),
        (1e-3, 0.00049983337499166805536),
        (0.2, 0.09365376538990929335),
        (0.3, 0.13606073560572622022),
        (0.49, 0.20944162078452258977),
        (0.51, 0.21665799767110969176),
        (0.7, 0.28083614827344216386),
        (1.0, 0.3678794411714423216),
        (30.0, 0.96666666666666978587),
    ];
    const Q: [(f64, f64); 9] = [
        (1e-12, 3.3333333333308333333e-25),
        (1e-3, 3.330834499583456318e-7),
        (0.2, 0.011507415690720334838),
        (0.3, 0.024102077721408386065),
        (0.49, 0.056320895802310956367),
        (0.51, 0.060183701054887718544),
        (0.7, 0.099817322302879701342),
        (1.0, 0.16809124072457829724),
        (30.0, 0.95000000000000623842),
    ];
    // phi(z) - phi(2z), same tool.
    const PMP: [(f64, f64); 9] = [
        (1e-12, 4.999999999995e-13),
        (1e-3, 0.00049950029154170970973),
        (0.2, 0.082146349699188958511),
        (0.3, 0.11195865788431783416),
        (0.49, 0.15312072498221163341),
        (0.51, 0.15647429661622197322),
        (0.7, 0.18101882597056246252),
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
            assert!(rel(z * h(z), want) < 4e-15, "z h({z}) = {}", z * h(z));
        }
    }

    /// The one-exponential family against the same mpmath values (and `exp(-z)` against
    /// `1 - z phi`'s reference: `1 - exp(-z) = z phi`).
    #[test]
    fn phi_family_from_one_exponential_matches_mpmath() {
        for (((z, p), (_, omp)), ((_, q), (_, pmp))) in PHI.iter().zip(&OMP).zip(Q.iter().zip(&PMP))
        {
            let f = PhiFamily::new(*z);
            assert!(rel(f.phi, *p) < 4e-15, "phi({z}) = {}", f.phi);
            assert!(rel(f.h * z, *omp) < 4e-15, "z h({z}) = {}", f.h * z);
            assert!(rel(f.one_minus_e, z * p) < 4e-15, "1 - exp(-{z})");
            assert!(
                rel(f.q_over_z * z, *q) < 1e-14,
                "q({z}) = {}",
                f.q_over_z * z
            );
            assert!(rel(f.phi_minus_phi2, *pmp) < 4e-15, "phi - phi2 at {z}");
            assert!(rel(f.phi2, p - pmp) < 4e-15, "phi(2 {z})");
        }
        let inf = PhiFamily::new(f64::INFINITY);
        assert_eq!((inf.e, inf.phi, inf.h, inf.q_over_z), (0.0, 0.0, 0.0, 0.0));
        assert_eq!(
            (inf.one_minus_e, inf.phi2, inf.phi_minus_phi2),
            (1.0, 0.0, 0.0)
        );
        let zero = PhiFamily::new(0.0);
        assert_eq!(
            (zero.e, zero.phi, zero.h, zero.q_over_z),
            (1.0, 1.0, 0.5, 0.0)
        );
    }

    #[test]
    fn limits_are_finite() {
        assert_eq!(phi(0.0), 1.0);
        assert_eq!(phi(f64::INFINITY), 0.0);
        assert_eq!(h(0.0), 0.5);
        assert_eq!(h(f64::INFINITY), 0.0);
    }

    #[test]
    fn product_is_exact() {
        // (1 + 2^-30)^2 = 1 + 2^-29 + 2^-60: the last term is below f64's precision.
        let x = 1.0 + 2f64.powi(-30);
        let p = DoubleDouble::product(x, x);
        assert_eq!(p.hi, 1.0 + 2f64.powi(-29));
        assert_eq!(p.lo, 2f64.powi(-60));
        let p = DoubleDouble::product(0.1, 3.0);
        assert_eq!(p.hi, 0.1 * 3.0);
        assert_eq!(p.lo, 0.1f64.mul_add(3.0, -(0.1 * 3.0)));
    }

    #[test]
    fn double_double_keeps_small_terms() {
        let s = DoubleDouble::from_f64(1e17).add_f64(1.0).add_f64(-1e17);
        assert_eq!(s.to_f64(), 1.0);
    }
}
