"""Results against independent values: the paper's Examples 3 and 4 and two hand-checkable
inputs, computed at 50 digits with mpmath, not with the library.

The reference values were printed by this script (mpmath 1.3, `python3 ref.py`) and pasted
with every digit it printed:

    from mpmath import mp, mpf, exp, quad
    mp.dps = 50

    def general(sigma0, g0, tp, arcs, points):
        # y° from eq. 8, y°(rho) = sigma0 e^{-a rho} (y°(0)/sigma0 + int_0^rho e^{a tau} psi'(tau) dtau),
        # y°(0) from y°(P) = y°(0) (eq. 10); every integral by mpmath quadrature.
        sigma0 = mpf(sigma0); g0 = mpf(g0); a = sigma0 / g0
        tp = [mpf(v) for v in tp]; n = len(tp)
        rk = [mpf(0)]
        for k in range(n):
            rk.append(rk[-1] + abs(tp[(k + 1) % n] - tp[k]))
        P = rk[-1]
        def slope(r):
            r = r % P
            for k in range(n):
                if rk[k] <= r < rk[k + 1]:
                    return 1 if tp[(k + 1) % n] > tp[k] else -1
        def I(r):
            pts = [x for x in rk if x < r] + [r]
            return sum(quad(lambda t: exp(a * t) * slope(t), [pts[i], pts[i + 1]])
                       for i in range(len(pts) - 1))
        y0 = sigma0 * exp(-a * P) * I(P) / (1 - exp(-a * P))
        def y(r):
            r = r % P
            return sigma0 * exp(-a * r) * (y0 / sigma0 + I(r))
        def integrate(f, lo, hi):
            pts = sorted(set([lo, hi] + [x + p * P for p in range(3) for x in rk if lo < x + p * P < hi]))
            return sum(quad(f, [pts[i], pts[i + 1]]) for i in range(len(pts) - 1))
        print("y at turning points", [mp.nstr(y(r), 17) for r in rk[:-1]])
        print("work per period", mp.nstr(integrate(lambda r: y(r) * slope(r), 0, P), 17))
        for lo, hi in arcs:
            lo = mpf(lo); hi = mpf(hi)
            W = integrate(lambda r: y(r) * slope(r), lo, hi)          # work  int y° dpsi
            D = integrate(lambda r: y(r) ** 2, lo, hi) / g0           # dissipation
            print("arc", lo, hi, "W", mp.nstr(W, 17), "D", mp.nstr(D, 17),
                  "dV", mp.nstr((y(hi) ** 2 - y(lo) ** 2) / (2 * sigma0), 17),
                  "gap", mp.nstr(y(hi) - y(lo), 17))
        print("points", [mp.nstr(y(mpf(x)), 17) for x in points])

and, for the bimodal inputs, Theorem A's own formulas: y°(0) by eq. 13,

    y0 = g0 e^{-a r4} / (1 - e^{-a r4}) (2 e^{a r1} - 2 e^{a r2} + 2 e^{a r3} - e^{a r4} - 1)

and y° on [rho_i, rho_i+1] by eqs. 13-16 (sign + on the increasing segments i = 0, 2, - on the
decreasing ones, as in the proof; the statement's printed signs are an erratum), rho_5 =
rho_2 + umax1 - umin2. Both routes agree to all 17 digits on Example 4.
"""

import math

import numpy as np
import pytest

import lugre

REL = 1e-13  # the library's results are good to a few ulps; the references to 17 digits


def close(got, want, rel=REL, abs_=1e-15):
    return math.isclose(got, want, rel_tol=rel, abs_tol=abs_)


def assert_all_close(got, want, rel=REL, abs_=1e-15):
    got = np.asarray(got, dtype=np.float64)
    want = np.asarray(want, dtype=np.float64)
    assert got.shape == want.shape
    np.testing.assert_allclose(got, want, rtol=rel, atol=abs_)


# ---------------------------------------------------------------------------------------------
# Example 4 (paper §4.4): sigma0 = 6, Fs = 2 (g(0) = 2), bimodal 0, 0.5, 1, 1.5.

EX4_RHO = [0.0, 1.0, 1.5, 2.5, 4.0, 2.0]
EX4_Y = [
    -1.9573070266459944,
    1.8029772845117475,
    -1.151441069466053,
    1.8430989880171994,
    -1.9573070266459944,
    1.2968184494717006,
]
EX4_MINOR_W = 0.1991073756948153
EX4_MINOR_D = 0.32985645882607939
EX4_MINOR_DV = -0.1307490831312641
EX4_MINOR_GAP = -0.50615883504004687
EX4_WORK_PER_PERIOD = 3.4967837542393372
# y° at rho = 0.5, 2.2, 4.0, -0.3 (eqs. 13-16).
EX4_AT = ([0.5, 2.2, 4.0, -0.3], [1.1170054493879726, 1.6140857827834297, -1.9573070266459944, -1.8949922299139471])


@pytest.fixture(scope="module")
def ex4():
    return lugre.LuGre(sigma0=6).loop_bimodal(0, 0.5, 1, 1.5)


def test_example_4_theorem_a(ex4):
    ta = ex4.theorem_a
    assert ta is not None
    assert_all_close(ta.rho, EX4_RHO, abs_=0)
    assert_all_close(ta.y, EX4_Y)
    assert ta.minor_loop == (1.0, 2.0)
    assert close(ta.y[0], -1.9573070266459944)
    assert close(ta.y[5], 1.2968184494717006)


def test_example_4_turning_points(ex4):
    assert_all_close(ex4.rho, [0.0, 1.0, 1.5, 2.5], abs_=0)
    assert_all_close(ex4.u, [0.0, 1.0, 0.5, 1.5], abs_=0)
    assert_all_close(ex4.y, EX4_Y[:4])
    assert ex4.period == 4.0
    assert close(ex4.work_per_period, EX4_WORK_PER_PERIOD)


def test_example_4_loops(ex4):
    loops = ex4.loops
    assert [l.kind for l in loops] == ["major", "minor"]
    major, minor = loops
    assert (major.parent, major.depth) == (None, 0)
    assert (minor.parent, minor.depth) == (0, 1)
    # The minor loop is Theorem A's arc [rho_1, rho_5] = [1, 2], turning at umin2.
    assert (minor.start.rho, minor.reversal.rho, minor.end.rho) == (1.0, 1.5, 2.0)
    assert (minor.start.u, minor.reversal.u, minor.end.u) == (1.0, 0.5, 1.0)
    assert close(minor.start.y, EX4_Y[1])
    assert close(minor.end.y, EX4_Y[5])
    assert close(minor.work, EX4_MINOR_W)
    assert close(minor.dissipation, EX4_MINOR_D)
    assert close(minor.stored_energy_change, EX4_MINOR_DV)
    assert close(minor.closure_gap, EX4_MINOR_GAP)
    # The major loop is the whole period from the global maximum; it closes.
    assert (major.start.u, major.reversal.u) == (1.5, 0.0)
    assert close(major.end.rho - major.start.rho, 4.0)
    assert close(major.work, EX4_WORK_PER_PERIOD)
    assert close(major.dissipation, EX4_WORK_PER_PERIOD)
    assert major.closure_gap == 0.0


def test_example_4_y_at(ex4):
    rho, want = EX4_AT
    assert_all_close(ex4.y_at(rho), want)
    # Theorem A's rho_5 and periodicity.
    assert close(ex4.y_at(2.0), EX4_Y[5])
    assert close(ex4.y_at(2.0 + 3 * 4.0), EX4_Y[5], rel=1e-12)


def test_example_4_from_turning_points_is_the_same_loop(ex4):
    hl = lugre.LuGre(sigma0=6).loop([0, 1, 0.5, 1.5])
    assert hl.theorem_a is None
    assert_all_close(hl.y, ex4.y, rel=0, abs_=0)
    assert hl.work_per_period == ex4.work_per_period


# ---------------------------------------------------------------------------------------------
# Example 3 (paper §4.3): sigma0 = 1, g(0) = 2, bimodal 0, 0.2, 1, 1.5.

EX3_RHO = [0.0, 1.0, 1.8, 3.1, 4.6, 2.6]
EX3_Y = [
    -0.70714090927459094,
    0.35803603836262405,
    -0.41936117421106933,
    0.73698271654353845,
    -0.70714090927459094,
    0.37825370632599766,
]
EX3_MINOR = dict(W=0.049975813778479284, D=0.042532782987003445, dV=0.0074430307914758387, gap=0.020217667963373604)
EX3_WORK_PER_PERIOD = 0.31391664643270895
EX3_AT = ([0.5, 2.2, 4.0, -0.3], [-0.10832346002768643, 0.019194603870540749, -0.25482276942960371, -0.49791203737266768])


def test_example_3():
    hl = lugre.LuGre().loop_bimodal(0, 0.2, 1, 1.5)  # the paper's defaults: sigma0 = 1, Fs = 2
    ta = hl.theorem_a
    assert_all_close(ta.rho, EX3_RHO, rel=1e-15)
    assert_all_close(ta.y, EX3_Y)
    assert_all_close(ta.minor_loop, [1.0, 2.6], rel=1e-15)
    assert close(hl.work_per_period, EX3_WORK_PER_PERIOD)
    assert_all_close(hl.y_at(EX3_AT[0]), EX3_AT[1])
    major, minor = hl.loops
    assert major.kind == "major" and minor.kind == "minor"
    assert close(minor.start.rho, 1.0) and close(minor.end.rho, 2.6)
    assert close(minor.work, EX3_MINOR["W"])
    assert close(minor.dissipation, EX3_MINOR["D"])
    assert close(minor.stored_energy_change, EX3_MINOR["dV"])
    assert close(minor.closure_gap, EX3_MINOR["gap"])


def test_example_3_only_sigma0_and_fs_matter():
    # The loop depends on sigma0 and g(0) = Fs only (not sigma1, sigma2, Fc, vs, beta).
    a = lugre.LuGre().loop_bimodal(0, 0.2, 1, 1.5)
    b = lugre.LuGre(sigma1=7, sigma2=0.3, fc=0.5, vs=0.01, beta=2).loop_bimodal(0, 0.2, 1, 1.5)
    assert_all_close(a.y, b.y, rel=0, abs_=0)


# ---------------------------------------------------------------------------------------------
# Nested minor loops: LuGre sigma0 = 1, g(0) = 2, turning points 0, 10, 2, 8, 4, 6.
# Rainflow by hand (started at the maximum 10): (4, 6) closes inside (2, 8), which closes
# inside the major loop (10, 0). Arcs: major [10, 46], (2, 8) [18, 34], (4, 6) [28, 32].

NESTED_Y = [
    -1.8646839301345923,
    1.9739599645105358,
    -1.9272143843317381,
    1.8044755089520171,
    -1.4851202294292225,
    0.71789591758228876,
]
NESTED_WORK_PER_PERIOD = 32.906600260238422
NESTED_ARCS = [
    # (start, reversal, end, W, D, dV, gap)
    (10.0, 36.0, 46.0, 32.906600260238422, 32.906600260238422, 0.0, 0.0),
    (18.0, 24.0, 34.0, 8.8512590351096751, 9.3763426747135703, -0.52508363960389519, 0.29504159814537052),
    (28.0, 30.0, 32.0, 0.15789193345703357, 0.760541002631751, -0.60264906917471743, 0.48497826075153939),
]
NESTED_AT = ([5.0, 29.0], [1.6827674249130982, -0.11383227193355071])


def test_nested_minor_loops():
    hl = lugre.LuGre().loop([0, 10, 2, 8, 4, 6])
    assert_all_close(hl.y, NESTED_Y)
    assert hl.period == 36.0
    assert close(hl.work_per_period, NESTED_WORK_PER_PERIOD)
    assert_all_close(hl.y_at(NESTED_AT[0]), NESTED_AT[1])
    loops = hl.loops
    assert [(l.kind, l.parent, l.depth) for l in loops] == [("major", None, 0), ("minor", 0, 1), ("minor", 1, 2)]
    for l, (a, b, c, w, d, dv, gap) in zip(loops, NESTED_ARCS):
        assert (l.start.rho, l.reversal.rho, l.end.rho) == (a, b, c)
        assert l.start.u == l.end.u  # the arc ends where the input returns to u_A
        assert close(l.work, w), (l, w)
        assert close(l.dissipation, d), (l, d)
        assert close(l.stored_energy_change, dv), (l, dv)
        assert close(l.closure_gap, gap), (l, gap)
        assert close(l.work, l.stored_energy_change + l.dissipation)


# ---------------------------------------------------------------------------------------------
# Dahl, by hand: rho = 2, fc = 0.5 is LuGre with sigma0 = 1, g = 0.5, a = 2. For the symmetric
# triangle -1 <-> 1 the loop's extremes solve Y = g0 + (-Y - g0) e^{-2a}, Y = fc tanh(rho) =
# 0.48201379003790844; the work per period (quadrature) 1.0359724199241831; y°(0.5) =
# 0.13873731569820415.


def test_dahl_symmetric_triangle():
    m = lugre.Dahl(rho=2, fc=0.5)
    assert (m.sigma0, m.g0, m.a) == (1.0, 0.5, 2.0)
    hl = m.loop([-1, 1])
    y_max = 0.5 * math.tanh(2.0)
    assert close(y_max, 0.48201379003790844, rel=1e-15)
    assert_all_close(hl.y, [-y_max, y_max])
    assert close(hl.work_per_period, 1.0359724199241831)
    assert close(hl.y_at(0.5), 0.13873731569820415)
    assert len(hl.loops) == 1 and hl.loops[0].kind == "major"


def test_dahl_is_lugre_with_g_constant():
    d = lugre.Dahl(rho=3, fc=0.7)
    l = d.to_lugre()
    assert (l.sigma0, l.sigma1, l.sigma2, l.fc, l.fs) == (3 * 0.7, 0.0, 0.0, 0.7, 0.7)
    a = d.loop([0, 1, 0.2, 1.5])
    b = l.loop([0, 1, 0.2, 1.5])
    assert_all_close(a.y, b.y, rel=0, abs_=0)


# ---------------------------------------------------------------------------------------------
# Stiffness: the paper's eq. 13 overflows once a rho_4 > ~709; the library does not. The
# realistic sigma0 = 1e5, Fs = 1.5 on a bimodal input of millimetres has a = 1e5 / 1.5 and
# a L >= 266 on every segment, so the loop saturates: y° = -s g0 at the start of each segment
# to within e^-266, and each segment's work g0 l + s (y_k - s g0)(1 - e^{-a l}) / a is
# g0 l - 2 g0 / a: over the 4 segments W = g0 (P - 8 / a) (by hand).


def test_realistic_stiffness_does_not_overflow():
    hl = lugre.LuGre(sigma0=1e5, fs=1.5).loop_bimodal(0, 0.004, 0.008, 0.010)
    assert hl.a * hl.period > 709  # where eq. 13 overflows
    assert np.all(np.isfinite(hl.y))
    assert_all_close(np.abs(hl.y), [1.5] * 4, rel=1e-15)
    assert close(hl.period, 0.028, rel=1e-15)
    assert close(hl.work_per_period, 1.5 * (hl.period - 8 / (1e5 / 1.5)), rel=1e-12)
    assert all(l.dissipation >= 0 for l in hl.loops)
