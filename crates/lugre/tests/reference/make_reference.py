#!/usr/bin/env python3
"""Independent reference values for the `lugre` integration tests.

Nothing here uses the crate: every number is computed with mpmath (mp.dps = 50, raised where
stated) from the paper's own formulas, from quadrature of the paper's definitions, or from closed
forms worked out by hand.

    cd crates/lugre/tests && python3 reference/make_reference.py > common/reference_values.rs

Sources of the numbers (symbols as in the paper and docs/mathematics.md, a = sigma0 / g0):

* EQ13  -- the paper's eqs. 13-16 (proof of Theorem A) evaluated literally:
      y°(0) = g0 e^{-a r4} / (1 - e^{-a r4}) (2 e^{a r1} - 2 e^{a r2} + 2 e^{a r3} - e^{a r4} - 1)
      y°(r) = e^{-a (r - ri)} (y°(ri) +- g0 [e^{a (r - ri)} - 1])   (+ on i = 0, 2; - on i = 1, 3)
  mpmath's exponent range is unbounded, so e^{a r4} never overflows.
* QUAD  -- eq. 10 and eq. 8 integrated by mp.quad (tanh-sinh, breakpoints at the turning points):
      y°(0)   = sigma0 e^{-a P} int_0^P e^{a t} psi'(t) dt / (1 - e^{-a P})
      y°(rho) = sigma0 e^{-a rho} (y°(0) / sigma0 + int_0^rho e^{a t} psi'(t) dt)
  For inputs with more than four turning points this is the only source of y° at the turning
  points; between them y° is continued with the eq. 13-16 form on each segment.
* Energies -- mp.quad over the arc, with y° from the above:
      W = int y° dpsi,  D = (1/g0) int y°^2 drho,  dV = (y°(C)^2 - y°(A)^2) / (2 sigma0)
* Dahl, symmetric triangle -A -> A -> -A (worked by hand, see the Dahl section below).

Inputs are the exact binary values of the f64 literals the tests pass (mpf(float)), so the
reference is the exact answer for the f64 problem. Self-checks (asserts) at the end of each
section: EQ13 == QUAD to 1e-40, results unchanged when mp.dps is doubled, W = dV + D on the
reference values, y°(P) == y°(0).
"""

from mpmath import mp, mpf, exp, quad, tanh, nstr, fabs

mp.dps = 50

OUT = []


def emit(line=""):
    OUT.append(line)


def lit(x):
    """An f64 literal for an mpf (22 significant digits; Rust rounds it correctly)."""
    s = nstr(mpf(x), 22)
    if "." not in s and "e" not in s and "inf" not in s:
        s += ".0"
    return s


def flit(x):
    """The shortest literal of a Python float (round-trips to the same f64 in Rust)."""
    r = repr(float(x))
    if "." not in r and "e" not in r:
        r += ".0"
    return r


def B(x):
    """The exact value of the f64 nearest to x (an mpf is taken as it is)."""
    if isinstance(x, type(mpf(0))):
        return x
    return mpf(float(x))


# --------------------------------------------------------------------------------------------
# Theorem A, literally (eqs. 13-16)


class TheoremA:
    def __init__(self, sigma0, g0, umin1, umin2, umax1, umax2):
        self.sigma0, self.g0 = B(sigma0), B(g0)
        self.a = self.sigma0 / self.g0
        umin1, umin2, umax1, umax2 = map(B, (umin1, umin2, umax1, umax2))
        r1 = umax1 - umin1
        r2 = r1 + umax1 - umin2
        r3 = r2 + umax2 - umin2
        r4 = r3 + umax2 - umin1
        r5 = umax1 - umin2 + r2
        self.r = [mpf(0), r1, r2, r3, r4, r5]
        self.u = [umin1, umax1, umin2, umax2]
        a, g0 = self.a, self.g0
        y0 = (
            g0
            * exp(-a * r4)
            / (1 - exp(-a * r4))
            * (2 * exp(a * r1) - 2 * exp(a * r2) + 2 * exp(a * r3) - exp(a * r4) - 1)
        )
        y1 = exp(-a * r1) * (y0 + g0 * (exp(a * r1) - 1))
        y2 = exp(-a * (r2 - r1)) * (y1 - g0 * (exp(a * (r2 - r1)) - 1))
        y3 = exp(-a * (r3 - r2)) * (y2 + g0 * (exp(a * (r3 - r2)) - 1))
        self.yk = [y0, y1, y2, y3]
        # eq. 16 at r4 closes the period: the reference's own periodicity check.
        y4 = exp(-a * (r4 - r3)) * (y3 - g0 * (exp(a * (r4 - r3)) - 1))
        scale = max(fabs(v) for v in self.yk)
        assert fabs(y4 - y0) <= scale * mpf(10) ** (-(mp.dps - 30)), (y4, y0)

    def period(self):
        return self.r[4]

    def y(self, rho):
        """y°(rho) by eqs. 13-16, rho reduced to [0, r4)."""
        rho = mpf(rho) % self.r[4]
        a, g0, r = self.a, self.g0, self.r
        sign = [1, -1, 1, -1]
        for i in range(3, -1, -1):
            if rho >= r[i]:
                d = rho - r[i]
                return exp(-a * d) * (self.yk[i] + sign[i] * g0 * (exp(a * d) - 1))
        raise AssertionError


# --------------------------------------------------------------------------------------------
# Any periodic input: eq. 10 and eq. 8 by quadrature


class Quad:
    def __init__(self, sigma0, g0, u):
        self.sigma0, self.g0 = B(sigma0), B(g0)
        self.a = self.sigma0 / self.g0
        self.u = [B(x) for x in u]
        n = len(u)
        self.n = n
        self.r = [mpf(0)]
        self.s = []
        for k in range(n):
            d = self.u[(k + 1) % n] - self.u[k]
            self.s.append(1 if d > 0 else -1)
            self.r.append(self.r[k] + fabs(d))
        a, P = self.a, self.r[n]
        integral = self.int_to(P)
        self.y0 = self.sigma0 * exp(-a * P) * integral / (1 - exp(-a * P))  # eq. 10
        # eq. 8 at every turning point
        self.yk = [self.eq8(self.r[k]) for k in range(n)]
        yP = self.eq8(P)
        scale = max(fabs(v) for v in self.yk)
        assert fabs(yP - self.y0) <= scale * mpf(10) ** -40

    def psi_dot(self, t):
        t = mpf(t) % self.r[self.n]
        for k in range(self.n - 1, -1, -1):
            if t >= self.r[k]:
                return self.s[k]
        raise AssertionError

    def int_to(self, rho):
        """int_0^rho e^{a t} psi'(t) dt, piece by piece (psi' is +-1 between turning points)."""
        a = self.a
        total = mpf(0)
        for k in range(self.n):
            lo, hi = self.r[k], min(self.r[k + 1], rho)
            if hi <= lo:
                break
            s = self.s[k]
            total += quad(lambda t: s * exp(a * t), [lo, hi])
        return total

    def eq8(self, rho):
        """eq. 8 for rho in [0, P]."""
        a = self.a
        return self.sigma0 * exp(-a * rho) * (self.y0 / self.sigma0 + self.int_to(rho))

    def period(self):
        return self.r[self.n]

    def seg(self, rho):
        P = self.r[self.n]
        rho = mpf(rho) % P
        for k in range(self.n - 1, -1, -1):
            if rho >= self.r[k]:
                return k, rho - self.r[k]
        raise AssertionError

    def y(self, rho):
        """y° by the eq. 13-16 form on the segment, from eq. 8's value at its start."""
        k, d = self.seg(rho)
        a, g0 = self.a, self.g0
        return exp(-a * d) * (self.yk[k] + self.s[k] * g0 * (exp(a * d) - 1))

    def psi(self, rho):
        k, d = self.seg(rho)
        return self.u[k] + self.s[k] * d


def energies(model, rho_a, rho_c, extra_breaks=()):
    """W = int y° dpsi and D = (1/g0) int y°^2 drho over [rho_a, rho_c], by mp.quad split at
    every turning point (psi' jumps there) and at `extra_breaks` (offsets after each turning
    point, for boundary layers)."""
    rho_a, rho_c = mpf(rho_a), mpf(rho_c)
    P = model.period()
    turning = model.r[: len(model.r) - 1] if isinstance(model, Quad) else model.r[:4]
    breaks = {rho_a, rho_c}
    k = 0
    while True:
        base = k * P
        if base > rho_c:
            break
        for r in turning:
            for off in (mpf(0),) + tuple(extra_breaks):
                x = base + r + off
                if rho_a < x < rho_c:
                    breaks.add(x)
        k += 1
    pts = sorted(breaks)
    W = mpf(0)
    D = mpf(0)
    for lo, hi in zip(pts, pts[1:]):
        mid = (lo + hi) / 2
        s = psi_dot(model, mid)
        W += quad(lambda r: s * model.y(r), [lo, hi])
        D += quad(lambda r: model.y(r) ** 2, [lo, hi]) / model.g0
    return W, D


def psi_dot(model, rho):
    P = model.period()
    rho = mpf(rho) % P
    if isinstance(model, Quad):
        return model.psi_dot(rho)
    sign = [1, -1, 1, -1]
    for i in range(3, -1, -1):
        if rho >= model.r[i]:
            return sign[i]
    raise AssertionError


# --------------------------------------------------------------------------------------------
# 1. The paper's Examples 3 and 4 (and Fig. 16's variant)

EXAMPLES = [
    # name, sigma0, g0 (= Fs of the paper's Stribeck curve), (umin1, umin2, umax1, umax2), probes
    ("example3", 1.0, 2.0, (0.0, 0.2, 1.0, 1.5),
     [0.3, 0.77, 1.25, 1.6, 2.0, 2.6, 2.9, 3.5, 4.1, 4.5]),
    ("example4", 6.0, 2.0, (0.0, 0.5, 1.0, 1.5),
     [0.3, 0.77, 1.2, 1.45, 1.7, 2.0, 2.3, 3.0, 3.6, 3.95]),
    ("fig16", 1.0, 2.0, (0.0, 0.5, 1.0, 1.5),
     [0.3, 1.2, 1.7, 3.0, 3.95]),
]

emit("// @generated by tests/reference/make_reference.py (mpmath, mp.dps = 50); do not edit.")
emit("// Regenerate: cd crates/lugre/tests && python3 reference/make_reference.py \\")
emit("//     > common/reference_values.rs")
emit("#![allow(dead_code)]")
emit()

for name, sigma0, g0, bimodal, probes in EXAMPLES:
    ta = TheoremA(sigma0, g0, *bimodal)
    umin1, umin2, umax1, umax2 = bimodal
    qd = Quad(sigma0, g0, [umin1, umax1, umin2, umax2])
    scale = max(fabs(v) for v in ta.yk)
    y13 = [ta.y(r) for r in ta.r]
    yq = [qd.eq8(r) for r in ta.r[:5]] + [qd.eq8(ta.r[5])]
    for p, q in zip(y13, yq):
        assert fabs(p - q) <= scale * mpf(10) ** -40, (p, q)
    interior = []
    for x in probes:
        p13, pq = ta.y(B(x)), qd.eq8(B(x))
        assert fabs(p13 - pq) <= scale * mpf(10) ** -40
        interior.append((x, p13, pq))
    # Energies: the major loop over one whole period (any start: the integrand is periodic; we
    # take the canonical start at the global maximum, rho_3), and the minor loop [rho_1, rho_5].
    r = ta.r
    Wmaj, Dmaj = energies(ta, r[3], r[3] + r[4])
    Wmin, Dmin = energies(ta, r[1], r[5])
    dVmin = (ta.y(r[5]) ** 2 - ta.y(r[1]) ** 2) / (2 * ta.sigma0)
    gap = ta.y(r[5]) - ta.y(r[1])
    assert fabs(Wmaj - Dmaj) < mpf(10) ** -40
    assert fabs(Wmin - dVmin - Dmin) < mpf(10) ** -40
    # quadrature of the minor-loop work with y° from eq. 8 at every node (slow, a check only)
    if name == "example3":
        Wq = quad(lambda x: -qd.eq8(x), [r[1], r[2]]) + quad(lambda x: qd.eq8(x), [r[2], r[5]])
        assert fabs(Wq - Wmin) < mpf(10) ** -40

    emit(f"/// {name}: sigma0 = {sigma0}, g0 = {g0}, (umin1, umin2, umax1, umax2) = {bimodal}.")
    emit(f"pub mod {name} {{")
    emit(f"    pub const SIGMA0: f64 = {flit(sigma0)};")
    emit(f"    pub const G0: f64 = {flit(g0)};")
    emit(f"    pub const BIMODAL: [f64; 4] = [{', '.join(flit(v) for v in bimodal)}];")
    emit("    /// rho_0..rho_5 (exact sums of the inputs' binary values).")
    emit(f"    pub const RHO: [f64; 6] = [{', '.join(lit(v) for v in r)}];")
    emit("    /// y° at rho_0..rho_5 by the paper's eqs. 13-16, literally.")
    emit(f"    pub const Y_EQ13: [f64; 6] = [{', '.join(lit(v) for v in y13)}];")
    emit("    /// y° at rho_0..rho_5 by mp.quad of eq. 10 (y°(0)) and eq. 8.")
    emit(f"    pub const Y_QUAD: [f64; 6] = [{', '.join(lit(v) for v in yq)}];")
    emit("    /// (rho, y° by eqs. 13-16, y° by quadrature of eq. 8) at interior points.")
    emit(f"    pub const INTERIOR: [(f64, f64, f64); {len(interior)}] = [")
    for x, p13, pq in interior:
        emit(f"        ({flit(x)}, {lit(p13)}, {lit(pq)}),")
    emit("    ];")
    emit("    /// Major loop: W and D (mp.quad over one period).")
    emit(f"    pub const MAJOR_W: f64 = {lit(Wmaj)};")
    emit(f"    pub const MAJOR_D: f64 = {lit(Dmaj)};")
    emit("    /// Minor loop [rho_1, rho_5]: W, D (mp.quad), dV and closure gap y°(rho_5) - y°(rho_1).")
    emit(f"    pub const MINOR_W: f64 = {lit(Wmin)};")
    emit(f"    pub const MINOR_D: f64 = {lit(Dmin)};")
    emit(f"    pub const MINOR_DV: f64 = {lit(dVmin)};")
    emit(f"    pub const MINOR_GAP: f64 = {lit(gap)};")
    emit("}")
    emit()

# --------------------------------------------------------------------------------------------
# 2. Stability: a P from ~1e-12 to ~1e12 (eqs. 13-16 at 60 and 120 digits)

# 1/2.3 and 1/2.25: a P = 1 (the crate switches formulas there) for P = 4.6 and P = 4.5
SWEEP_SIGMA0 = [4e-13, 1e-12, 1e-9, 1e-6, 1e-3, 0.1, 0.43, 1 / 2.3, 0.44, 1 / 2.25, 0.45, 1.0,
                10.0, 300.0, 320.0, 1e3, 1e5, 1e6, 1e9, 1e12]
LAYER = [0.1, 1.0, 5.0]  # probes at rho_k + c / a: inside the boundary layer after a reversal
LAYER_BREAKS = (0.25, 1, 4, 16, 64)  # extra quadrature breakpoints at rho_k + c / a


def sweep_case(sigma0, g0, bimodal, exact_rho, minor_energies):
    """y° at the exact rho_0..rho_3 and rho_5; probes (rho an f64, y° at exactly that rho):
    mid-segment points, rho_5 as an f64, and boundary-layer points after every turning point
    whose rho_k is exact in f64 (`exact_rho`: indices k); energies W, D of the major loop (one
    period) and, if `minor_energies`, W, D, dV of the minor loop [rho_1, rho_5] (only for inputs
    whose rho_k are exact in f64: at small a P the minor loop's W is far smaller than
    y°(rho_5) ulp(rho_5), so the arc's end must be exactly the reference's)."""
    vals = {}
    for dps in (60, 120):
        with mp.workdps(dps):
            ta = TheoremA(sigma0, g0, *bimodal)
            rk = [float(v) for v in ta.r]
            a = sigma0 / g0
            probes = []
            for k in range(4):
                length = rk[k + 1] - rk[k]
                probes.append(("mid", k, rk[k] + 0.5 * length))
                if k in exact_rho:
                    assert mpf(rk[k]) == ta.r[k]
                    for c in LAYER:
                        off = c / a
                        if off < 0.5 * length:
                            probes.append(("layer", k, rk[k] + off))
            probes.append(("rho5", 5, rk[5]))
            turning = [ta.y(ta.r[k]) for k in (0, 1, 2, 3, 5)]
            pts = [(kind, k, x, ta.y(B(x))) for kind, k, x in probes]
            vals[dps] = (turning, pts)
            scale = max(fabs(v) for v in ta.yk)
    (t60, p60), (t120, p120) = vals[60], vals[120]
    for y1, y2 in zip(t60, t120):
        assert fabs(y1 - y2) <= scale * mpf(10) ** -25, (sigma0, y1, y2)
    for (_, _, x1, y1), (_, _, x2, y2) in zip(p60, p120):
        assert x1 == x2
        assert fabs(y1 - y2) <= scale * mpf(10) ** -25, (sigma0, x1, y1, y2)
    # energies, at 60 digits (quadrature), checked against W = dV + D
    with mp.workdps(60):
        ta = TheoremA(sigma0, g0, *bimodal)
        a = ta.a
        brk = tuple(mpf(c) / a for c in LAYER_BREAKS)
        r = ta.r
        Wmaj, Dmaj = energies(ta, r[3], r[3] + r[4], brk)
        assert fabs(Wmaj - Dmaj) <= fabs(Wmaj) * mpf(10) ** -30, (sigma0, Wmaj, Dmaj)
        en = [Wmaj, Dmaj]
        if minor_energies:
            Wmin, Dmin = energies(ta, r[1], r[5], brk)
            dV = (ta.y(r[5]) ** 2 - ta.y(r[1]) ** 2) / (2 * ta.sigma0)
            assert fabs(Wmin - dV - Dmin) <= (fabs(Wmin) + fabs(dV) + Dmin) * mpf(10) ** -30
            en += [Wmin, Dmin, dV]
    return scale, t120, p120, en


emit("/// Stability sweep: (sigma0, loop scale max|y°| at the turning points, y° at the exact")
emit("/// rho_0, rho_1, rho_2, rho_3, rho_5, [(rho, y° at that f64 rho)], energies [W, D] of the")
emit("/// major loop and, for the dyadic input, [W, D, dV] of the minor loop). y° by eqs. 13-16 at")
emit("/// mp.dps = 120 (agreeing with mp.dps = 60 to 1e-25 of the scale); energies by mp.quad at")
emit("/// mp.dps = 60 with breakpoints in the boundary layers, W = dV + D to 1e-30.")
emit("pub type SweepCase = (f64, f64, [f64; 5], &'static [(f64, f64)], &'static [f64]);")
emit()
for cname, g0, bimodal, exact, minor_en in [
    ("SWEEP_EXAMPLE3", 2.0, (0.0, 0.2, 1.0, 1.5), {0, 1}, False),
    ("SWEEP_DYADIC", 2.0, (0.0, 0.25, 1.0, 1.5), {0, 1, 2, 3}, True),
]:
    emit(f"/// g0 = {g0}, bimodal {bimodal}; layer probes after rho_k for k in {sorted(exact)}.")
    emit(f"pub const {cname}_BIMODAL: [f64; 4] = [{', '.join(flit(v) for v in bimodal)}];")
    emit(f"pub const {cname}_G0: f64 = {flit(g0)};")
    emit(f"pub const {cname}: &[SweepCase] = &[")
    for sigma0 in SWEEP_SIGMA0:
        scale, turning, pts, en = sweep_case(sigma0, g0, bimodal, exact, minor_en)
        emit(f"    ({flit(sigma0)}, {lit(scale)}, [{', '.join(lit(v) for v in turning)}], &[")
        for kind, k, x, y in pts:
            emit(f"        ({flit(x)}, {lit(y)}), // {kind} {k}")
        emit(f"    ], &[{', '.join(lit(v) for v in en)}]),")
    emit("];")
    emit()

# --------------------------------------------------------------------------------------------
# 2b. The realistic case: sigma0 = 1e5 N/m, Fs = 1.5 N, 1 cm of travel (a rho_4 ~ 1867 > 709)

R_SIGMA0, R_G0, R_BIMODAL = 1e5, 1.5, (0.0, 0.004, 0.008, 0.010)
scale, turning, pts, _ = sweep_case(R_SIGMA0, R_G0, R_BIMODAL, {0, 1}, False)
ta = TheoremA(R_SIGMA0, R_G0, *R_BIMODAL)
a = ta.a
layer_breaks = tuple(mpf(c) / a for c in LAYER_BREAKS)
Wmaj, Dmaj = energies(ta, ta.r[3], ta.r[3] + ta.r[4], layer_breaks)
Wmin, Dmin = energies(ta, ta.r[1], ta.r[5], layer_breaks)
dVmin = (ta.y(ta.r[5]) ** 2 - ta.y(ta.r[1]) ** 2) / (2 * ta.sigma0)
assert fabs(Wmaj - Dmaj) < mpf(10) ** -35
assert fabs(Wmin - dVmin - Dmin) < mpf(10) ** -35
# self-check of the quadrature: other breakpoints, same result
Wmaj2, _ = energies(ta, ta.r[3], ta.r[3] + ta.r[4], tuple(mpf(c) / a for c in (0.5, 2, 8, 32)))
assert fabs(Wmaj2 - Wmaj) < mpf(10) ** -35
emit("/// Realistic stiffness: sigma0 = 1e5 N/m, g0 = Fs = 1.5 N, bimodal in metres")
emit(f"/// {R_BIMODAL} (a rho_4 = {nstr(a * ta.r[4], 8)}: e^(a rho_4) overflows f64).")
emit("pub mod realistic {")
emit(f"    pub const SIGMA0: f64 = {flit(R_SIGMA0)};")
emit(f"    pub const G0: f64 = {flit(R_G0)};")
emit(f"    pub const BIMODAL: [f64; 4] = [{', '.join(flit(v) for v in R_BIMODAL)}];")
emit(f"    pub const SCALE: f64 = {lit(scale)};")
emit("    /// y° at the exact rho_0, rho_1, rho_2, rho_3, rho_5 (eqs. 13-16 at mp.dps = 120).")
emit(f"    pub const TURNING: [f64; 5] = [{', '.join(lit(v) for v in turning)}];")
emit("    /// (rho, y° at that f64 rho by eqs. 13-16 at mp.dps = 120).")
emit("    pub const POINTS: &[(f64, f64)] = &[")
for kind, k, x, y in pts:
    emit(f"        ({flit(x)}, {lit(y)}), // {kind} {k}")
emit("    ];")
emit("    /// W, D of the major loop; W, D, dV of the minor loop [rho_1, rho_5] (mp.quad with")
emit("    /// extra breakpoints in the boundary layers rho_k + c / a, c = 1/4 .. 64).")
emit(f"    pub const MAJOR_W: f64 = {lit(Wmaj)};")
emit(f"    pub const MAJOR_D: f64 = {lit(Dmaj)};")
emit(f"    pub const MINOR_W: f64 = {lit(Wmin)};")
emit(f"    pub const MINOR_D: f64 = {lit(Dmin)};")
emit(f"    pub const MINOR_DV: f64 = {lit(dVmin)};")
emit("}")
emit()

# --------------------------------------------------------------------------------------------
# 5. A 7-modal input with nesting, designed by hand (see tests/minor_loops.rs for the pairing)

SEVEN_U = [10.0, 0.0, 8.0, 1.0, 5.0, 3.0, 9.0, 2.0, 7.0, 4.0, 6.0, 4.5, 8.5, 3.5]
# Loops by hand, in the order the crate reports them (major first, then by start):
# (rho_A, rho_B, rho_C). rho_k of the turning points: 0 10 18 25 29 31 37 44 49 52 54 55.5
# 59.5 64.5, period 71.
SEVEN_ARCS = [
    (0, 10, 71),        # major: 10 -> 0 -> 10
    (18, 25, 36),       # 8 -> 1 -> back to 8 at 31 + 5 (the nested 5-3 adds 4 of travel)
    (29, 31, 33),       # 5 -> 3 -> 5
    (37, 44, 70),       # 9 -> 2 -> back to 9 at 64.5 + 5.5
    (49, 52, 58),       # 7 -> 4 -> back to 7 at 55.5 + 2.5 (the nested 6-4.5 adds 3)
    (54, 55.5, 57),     # 6 -> 4.5 -> 6
    (59.5, 64.5, 69.5), # 8.5 -> 3.5 -> 8.5
]
SEVEN_SIGMA0, SEVEN_G0 = 1.0, 2.0
qd = Quad(SEVEN_SIGMA0, SEVEN_G0, SEVEN_U)
assert [float(v) for v in qd.r[:14]] == [0, 10, 18, 25, 29, 31, 37, 44, 49, 52, 54, 55.5, 59.5,
                                          64.5]
emit(f"/// The 7-modal input, sigma0 = {SEVEN_SIGMA0}, g0 = {SEVEN_G0}: y° at the turning points")
emit("/// (mp.quad of eqs. 10 and 8) and, per loop (rho_A, rho_B, rho_C, u_A, u_B, u_C, y_A, y_B,")
emit("/// y_C, W, D, dV) over the arcs worked out by hand (mp.quad for W and D).")
emit("pub mod seven {")
emit(f"    pub const SIGMA0: f64 = {flit(SEVEN_SIGMA0)};")
emit(f"    pub const G0: f64 = {flit(SEVEN_G0)};")
emit(f"    pub const U: [f64; 14] = [{', '.join(flit(v) for v in SEVEN_U)}];")
emit(f"    pub const Y: [f64; 14] = [{', '.join(lit(v) for v in qd.yk)}];")
emit("    pub const LOOPS: [[f64; 12]; 7] = [")
for ra, rb, rc in SEVEN_ARCS:
    ra, rb, rc = mpf(ra), mpf(rb), mpf(rc)
    W, D = energies(qd, ra, rc)
    ya, yb, yc = qd.y(ra), qd.y(rb), qd.y(rc)
    dV = (yc**2 - ya**2) / (2 * qd.sigma0)
    assert fabs(W - dV - D) < mpf(10) ** -35
    assert qd.psi(rc) == qd.psi(ra)
    row = [ra, rb, rc, qd.psi(ra), qd.psi(rb), qd.psi(rc), ya, yb, yc, W, D, dV]
    emit("        [" + ", ".join(lit(v) for v in row) + "],")
emit("    ];")
emit("}")
emit()

# --------------------------------------------------------------------------------------------
# 6. Repeated global maximum and repeated minima

REP_U = [10.0, 0.0, 6.0, 3.0, 10.0, 0.0, 10.0, 3.0, 7.0, 0.0]
qd = Quad(1.0, 2.0, REP_U)
Wp, Dp = energies(qd, 0, qd.period())
assert fabs(Wp - Dp) < mpf(10) ** -35
emit("/// Repeated maxima and minima, sigma0 = 1, g0 = 2: y° at the turning points (mp.quad of")
emit("/// eqs. 10 and 8) and the work per period (mp.quad).")
emit("pub mod repeated {")
emit(f"    pub const U: [f64; 10] = [{', '.join(flit(v) for v in REP_U)}];")
emit(f"    pub const Y: [f64; 10] = [{', '.join(lit(v) for v in qd.yk)}];")
emit(f"    pub const WORK_PER_PERIOD: f64 = {lit(Wp)};")
emit("}")
emit()

# --------------------------------------------------------------------------------------------
# 7. Dahl, symmetric triangle -A -> A -> -A, worked by hand.
#
# Rate-independent Dahl: dy/drho = rho_d (s Fc - y) (LuGre with sigma0 = rho_d Fc, g0 = Fc,
# a = rho_d). With E = exp(-2 rho_d A), going up from y_b at -A: y_t = Fc + (y_b - Fc) E; by
# symmetry y_b = -y_t, so y_t (1 + E) = Fc (1 - E): y_t = Fc tanh(rho_d A), y_b = -y_t.
# On the rising branch, l after -A: y = Fc (1 - (1 + tanh(rho_d A)) exp(-rho_d l)).
# Work per period: twice the rising branch,
#   W = 2 Fc (2A - (1 + t)(1 - E) / rho_d) with (1 + t)(1 - E) = 2t:  W = 4 Fc (A - t / rho_d).
# These closed forms are checked here against eq. 8/10 quadrature.

DAHL = [(1.0, 1.0, 1.0), (2.5, 0.8, 0.3), (1e4, 1.2, 0.01), (1e-6, 3.0, 2.0), (50.0, 1.0, 20.0)]
emit("/// Dahl (rho, Fc, A): (y° at -A = -Fc tanh(rho A), W per period = 4 Fc (A - tanh(rho A)/rho),")
emit("/// [(l, y° at l after -A on the rising branch = Fc (1 - (1 + tanh(rho A)) e^(-rho l)))]).")
emit("pub type DahlCase = (f64, f64, f64, f64, f64, &'static [(f64, f64)]);")
emit("pub const DAHL: &[DahlCase] = &[")
for rho_d, fc, A in DAHL:
    rd, F, Am = B(rho_d), B(fc), B(A)
    t = tanh(rd * Am)
    yb = -F * t
    W = 4 * F * (Am - t / rd)
    ls = [0.25 * A, 0.5 * A, 1.0 * A, 1.9 * A]
    pts = [(l, F * (1 - (1 + t) * exp(-rd * B(l)))) for l in ls]
    if rho_d * A <= 50:
        q = Quad(rd * F, F, [-A, A])  # a = rho_d exactly
        sc = F
        assert fabs(q.yk[0] - yb) < sc * mpf(10) ** -40, (rho_d, q.yk[0] - yb, yb)
        for l, y in pts:
            assert fabs(q.eq8(B(l)) - y) < sc * mpf(10) ** -40
        Wq, _ = energies(q, 0, q.period())
        assert fabs(Wq - W) < mpf(10) ** -40 * (1 + W)
    emit(f"    ({flit(rho_d)}, {flit(fc)}, {flit(A)}, {lit(yb)}, {lit(W)}, &[")
    for l, y in pts:
        emit(f"        ({flit(l)}, {lit(y)}),")
    emit("    ]),")
emit("];")

print("\n".join(OUT))
