"""LuGre.simulate / Dahl.simulate (eq. 5) and lugre.cycles against independent values.

Finite-gamma references: eq. 5 solved by mpmath's Taylor-series ODE solver (mp.odefun, 30
digits), restarted at every kink, with |u'| = s u' and g's |v| = s v on each piece of constant
sign s (so the right-hand side is analytic where the Taylor method expands it):

    from mpmath import mp, mpf, exp, odefun, cos, pi, sign
    mp.dps = 30
    sigma0, sigma1, sigma2, fc, fs, vs, beta = map(mpf, (1, 1, 0, 1, 2, 1, 1))
    def solve(du, gamma, kinks, t_out, z0=mpf(0), constant_slope=False):
        out, z = {}, z0
        for a, b in zip(kinks[:-1], kinks[1:]):
            s = sign(du((a + b) / 2))
            def rhs(t, z, s=s):
                v = s if constant_slope else du(t)
                gv = fc + (fs - fc) * exp(-(s * v / gamma / vs) ** beta)
                return -sigma0 * s * v / gv * z + v
            f = odefun(rhs, a, z)
            for t in t_out:
                if a <= t < b:
                    v = s if constant_slope else du(t)
                    gv = fc + (fs - fc) * exp(-(s * v / gamma / vs) ** beta)
                    dz = -sigma0 * s * v / gv * f(t) + v
                    out[t] = sigma0 * f(t) + sigma1 / gamma * dz + sigma2 * v / gamma
            z = f(b)
        return [out[t] for t in t_out]
    # Example 3, gamma = 10 (turning points 0, 1, 0.2, 1.5 at unit speed: kinks 0, 1, 1.8, 3.1, 4.6)
    solve(lambda t: 1 if t < 1 or mpf("1.8") <= t < mpf("3.1") else -1, mpf(10),
          [mpf(0), mpf(1), mpf("1.8"), mpf("3.1"), mpf("4.6")],
          [mpf("0.5"), mpf("1.5"), mpf("2.5"), mpf(4)], constant_slope=True)
    # sine A = 1, T = 2, gamma = 10 (reversals at 0.5, 1.5)
    solve(lambda t: pi * cos(pi * t), mpf(10), [mpf(0), mpf("0.5"), mpf("1.5"), mpf("2.000001")],
          [mpf("0.25"), mpf(1), mpf("1.75"), mpf(2)])

Rate-independent limit (gamma = inf) from x0 = 0, by hand: y* obeys eq. 8's recursion from
y*(0) = 0, so y*(t) = y°(t) - y°(0) exp(-a rho_u(t)) (docs/mathematics.md#transient-and-convergence-to-the-loop; here rho_u(t) = t).
"""

import math

import numpy as np
import pytest

import lugre

EX3_TURNING_POINTS = [0, 1, 0.2, 1.5]
EX3_GAMMA10 = ([0.5, 1.5, 2.5, 4.0], [0.51667493092026719, 0.050295499430234758, 0.56182699322884962, -0.26543646689307049])
SINE_GAMMA10 = ([0.25, 1.0, 1.75, 2.0], [0.73283287460056647, -0.57871726296864538, -0.25435671547033098, 0.49262278721466295])
# y° of Example 3 at its turning points (mpmath, eqs. 13-16; see test_reference.py).
EX3_Y = [-0.70714090927459094, 0.35803603836262405, -0.41936117421106933, 0.73698271654353845]
EX3_RHO = [0.0, 1.0, 1.8, 3.1]


def test_returns_a_mapping_of_float64_arrays():
    r = lugre.LuGre().simulate(EX3_TURNING_POINTS, gamma=10, periods=3)
    assert set(r) == {"t", "u", "z", "dz", "y"}
    n = len(r["t"])
    # As `lugre simulate`: 200 evenly spaced times per period and every turning point; the
    # knots of 3 periods (13) include the grid's ends.
    assert n == 3 * 200 + 1 + 3 * 3
    for k, v in r.items():
        assert isinstance(v, np.ndarray) and v.dtype == np.float64 and v.shape == (n,), k
    for t, u in zip([0.0, 1.0, 1.8, 3.1, 4.6], [0.0, 1.0, 0.2, 1.5, 0.0]):
        (i,) = np.flatnonzero(np.isclose(r["t"], t, rtol=1e-15, atol=0))
        assert r["u"][i] == u


def test_knots_on_request():
    r = lugre.LuGre().simulate(EX3_TURNING_POINTS, gamma=10, periods=3, times="knots")
    assert len(r["t"]) == 4 * 3 + 1  # every knot of 3 periods
    np.testing.assert_allclose(r["t"][:5], [0.0, 1.0, 1.8, 3.1, 4.6], rtol=1e-15)
    np.testing.assert_array_equal(r["u"][:5], [0.0, 1.0, 0.2, 1.5, 0.0])
    with pytest.raises(ValueError, match="a sine has no knots"):
        lugre.LuGre().simulate(sine=(1, 2), times="knots")


def test_example_3_gamma_10_against_an_independent_ode_solver():
    t, want = EX3_GAMMA10
    r = lugre.LuGre().simulate(turning_points=EX3_TURNING_POINTS, gamma=10, times=t)
    np.testing.assert_array_equal(r["t"], t)
    np.testing.assert_allclose(r["y"], want, rtol=1e-13, atol=1e-15)
    # y = sigma0 z + (sigma1 / gamma) z' (sigma2 = 0)
    np.testing.assert_allclose(r["y"], r["z"] + r["dz"] / 10, rtol=1e-14)


def test_sine_gamma_10_against_an_independent_ode_solver():
    t, want = SINE_GAMMA10
    r = lugre.LuGre().simulate(sine=(1, 2), gamma=10, times=t, tol=1e-13)
    np.testing.assert_allclose(r["y"], want, rtol=1e-11, atol=1e-13)
    # The default tolerance 1e-10 is relative to the state's scale g(0)/sigma0.
    r = lugre.LuGre().simulate(sine=(1, 2), gamma=10, times=t)
    np.testing.assert_allclose(r["y"], want, rtol=0, atol=1e-8)
    np.testing.assert_allclose(r["u"], np.sin(np.pi * np.array(t)), atol=1e-15)


def test_rate_independent_limit_converges_to_the_loop():
    m = lugre.LuGre()
    periods = 4
    P = 4.6
    t = np.array([k * P + r for k in range(periods) for r in EX3_RHO])
    r = m.simulate(EX3_TURNING_POINTS, gamma=math.inf, periods=periods, times=t)
    a = m.a
    y_loop = np.tile(EX3_Y, periods)
    np.testing.assert_allclose(r["y"], y_loop - EX3_Y[0] * np.exp(-a * t), rtol=1e-13, atol=1e-15)
    # ... and y*_{u,k} - y° shrinks like exp(-a P k).
    gaps = np.abs(r["y"] - y_loop).reshape(periods, 4).max(axis=1)
    np.testing.assert_allclose(gaps[1:] / gaps[:-1], math.exp(-a * P), rtol=1e-9)


def test_sampled_input_equals_turning_points_at_unit_speed():
    m = lugre.LuGre(sigma0=6)
    a = m.simulate([0, 1, 0.5, 1.5], gamma=3, periods=2, samples_per_period=40)
    b = m.simulate(t=[0, 1, 1.5, 2.5, 4.0], u=[0, 1, 0.5, 1.5, 0], gamma=3, periods=2, samples_per_period=40)
    assert len(a["t"]) == 2 * 40 + 1
    for k in a:
        np.testing.assert_allclose(a[k], b[k], rtol=1e-14, atol=1e-15)


def test_inputs_accept_any_real_sequence():
    m = lugre.LuGre()
    want = m.simulate(t=[0.0, 1.0, 2.0], u=[0.0, 1.0, 0.0], gamma=2, times=[0.5, 1.5])["y"]
    for t, u, times in (
        ((0, 1, 2), (0, 1, 0), (0.5, 1.5)),
        (np.array([0, 1, 2], dtype=np.int32), np.array([0, 1, 0], dtype=np.float32), np.array([0.5, 9, 1.5])[::2]),
    ):
        np.testing.assert_array_equal(m.simulate(t=t, u=u, gamma=2, times=times)["y"], want)


def test_dahl_simulates_as_its_lugre_model():
    d = lugre.Dahl(rho=2, fc=0.5)
    a = d.simulate([-1, 1], gamma=5, periods=2)
    b = d.to_lugre().simulate([-1, 1], gamma=5, periods=2)
    for k in a:
        np.testing.assert_array_equal(a[k], b[k])


@pytest.mark.parametrize(
    "kwargs, message",
    [
        (dict(), "no input: give turning_points, t and u, or sine=(A, T[, phase[, offset]])"),
        (dict(turning_points=[0, 1], sine=(1, 2)), "give one input, not turning_points and sine"),
        (dict(t=[0, 1]), "a sampled input needs both t and u (arrays of equal length)"),
        (dict(turning_points=[0, 1], gamma=0), "gamma must be > 0 (a positive number or inf), got 0"),
        (dict(turning_points=[0, 1], gamma=math.nan), "gamma must be > 0 (a positive number or inf), got NaN"),
        (dict(turning_points=[0, 1], periods=0), "the number of periods must be at least 1, got 0"),
        (dict(turning_points=[0, 1], x0=math.inf), "x0 must be a finite number, got inf"),
        (dict(t=[0, 1, 1], u=[0, 1, 0]), "times must be strictly increasing: t[2] = 1 after t[1] = 1"),
        (dict(t=[0, 1, 2], u=[0, 1]), "t and u have different lengths (3 and 2)"),
        (dict(t=[0, 1], u=[0, 1], periods=2), "to repeat the input over 2 periods it must end where it starts, but u[0] = 0 and u[1] = 1"),
        (dict(turning_points=[0, 1], times=[5]), "output time t[0] = 5 is outside the run [0, 2]"),
        (dict(turning_points=[], gamma=2), "turning_points: the input is empty"),
        (dict(sine=(1,)), "sine takes 2 to 4 numbers (A, T[, phase[, offset]]), got 1"),
        (dict(sine=(0, 2)), "the sine's amplitude must be a finite number > 0, got 0"),
        (dict(sine=(1, 2), tol=0), "the tolerance must be a number in [1e-14, 1), got 0"),
        (dict(turning_points=[0, 1], times=[0.5], samples_per_period=4), "give times or samples_per_period, not both"),
        (dict(turning_points=[0, 1], samples_per_period=0), "samples_per_period must be at least 1, got 0"),
    ],
)
def test_simulate_value_errors(kwargs, message):
    with pytest.raises(ValueError) as e:
        lugre.LuGre().simulate(**kwargs)
    assert str(e.value) == message


@pytest.mark.parametrize(
    "kwargs",
    [dict(sine="ab"), dict(sine=3.0), dict(turning_points="01"), dict(turning_points=[0, 1], gamma="inf"),
     dict(turning_points=[0, 1], periods=1.5), dict(t=[0, 1], u=[0, None]), dict(turning_points=[0, 1], times=["a"])],
)
def test_simulate_type_errors(kwargs):
    with pytest.raises(TypeError):
        lugre.LuGre().simulate(**kwargs)


def test_simulate_huge_outputs_fail_cleanly():
    # The core's bound on the output rows (the CLI's too), before anything is allocated.
    with pytest.raises(ValueError, match=r"the run would produce 4000000000000000001 output rows \(more than 50000000\)"):
        lugre.LuGre().simulate([0, 1], periods=4_000_000_000, samples_per_period=10**9)
    with pytest.raises(ValueError, match="periods must be at most 1000000 for a sine"):
        lugre.LuGre().simulate(sine=(1, 1), periods=4_294_967_295, times=[0, 1])


# ---------------------------------------------------------------------------------------------
# lugre.cycles: the ASTM E1049-85 worked example (Fig. 6 history counted as a non-repeating
# history, §5.4.4, Table 4), and the energies of its full cycle (-1, 3) against y* by
# quadrature of eq. 6 (mpmath, 40 digits): LuGre sigma0 = 1, g(0) = 2, x0 = 0; arc from sample
# 4 (u = -1) through sample 5 (u = 3) back to u = -1, 4/7 of the way to sample 6:
# W = 3.3945078086780729, D = 3.8539249183485374, dV = -0.4594171096704645,
# gap = 0.27572801914598899, y* at the last sample -1.8044032850081933.

ASTM = [-2, 1, -3, 5, -1, 3, -4, 4, -2]


def test_cycles_astm_example():
    c = lugre.cycles(ASTM)
    cyc = c["cycles"]
    assert list(zip(cyc["range"], cyc["count"])) == [(3, 0.5), (4, 0.5), (4, 1), (8, 0.5), (9, 0.5), (8, 0.5), (6, 0.5)]
    for k in ("range", "mean", "count", "closure_position"):
        assert cyc[k].dtype == np.float64
    for k in ("start", "end", "closure"):
        assert cyc[k].dtype == np.int64
    full = int(np.flatnonzero(cyc["count"] == 1.0)[0])
    assert (cyc["start"][full], cyc["end"][full], cyc["closure"][full]) == (4, 5, 6)
    assert cyc["closure_position"][full] == 5 + 4 / 7
    assert (cyc["closure"] == -1).sum() == 6 and np.isnan(cyc["closure_position"]).sum() == 6
    np.testing.assert_array_equal(c["reversals"]["index"], np.arange(9))
    np.testing.assert_array_equal(c["reversals"]["u"], ASTM)
    assert c["summary"] == dict(samples=9, reversals=9, full_cycles=1, half_cycles=6, energy=None)
    assert "work" not in cyc


def test_cycles_energy_against_quadrature():
    c = lugre.cycles(np.array(ASTM, dtype=np.float32), model=lugre.LuGre())
    cyc = c["cycles"]
    full = int(np.flatnonzero(cyc["count"] == 1.0)[0])
    for k, want in (("work", 3.3945078086780729), ("dissipation", 3.8539249183485374),
                    ("stored_energy_change", -0.4594171096704645), ("closure_gap", 0.27572801914598899)):
        assert math.isclose(cyc[k][full], want, rel_tol=1e-13), k
        assert np.isnan(np.delete(cyc[k], full)).all()
    e = c["summary"]["energy"]
    assert e["y_start"] == 0.0
    assert math.isclose(e["y_end"], -1.8044032850081933, rel_tol=1e-13)


def test_cycles_errors():
    # (A one-sample history is no error: empty columns, as rainflow; test_cycles.py.)
    with pytest.raises(ValueError):
        lugre.cycles([0, math.nan, 1])
    with pytest.raises(ValueError):
        lugre.cycles([0, 1, 0], gate=-1)
    with pytest.raises(TypeError, match="model"):
        lugre.cycles([0, 1, 0], model="lugre")
    with pytest.raises(TypeError, match="series"):
        lugre.cycles("0,1,0")


def test_samples_of_a_smooth_motion_read_as_cubic():
    # A sine sampled 200 times a period, against the adaptive solution of the sine itself: the
    # cubic reading is far closer than the linear one on average (simulate::smooth's orders).
    m = lugre.LuGre(sigma0=1e5, sigma1=1e5 ** 0.5, sigma2=0.4, fc=1.0, fs=1.5, vs=1e-3, beta=2.0)
    a, period, n = 1e-5, 0.05, 200
    t = np.linspace(0.0, period, n + 1)
    u = a * np.sin(2 * np.pi * t / period + 0.3)
    ref = m.simulate(sine=(a, period, 0.3), times=t[:-1])["y"]
    lin = m.simulate(t=t, u=u)["y"][:-1]
    cub = m.simulate(t=t, u=u, interpolate="cubic")["y"][:-1]
    assert np.mean(np.abs(cub - ref)) < 0.1 * np.mean(np.abs(lin - ref))
    with pytest.raises(ValueError, match="interpolate must be 'linear' or 'cubic'"):
        m.simulate(t=t, u=u, interpolate="spline")
    with pytest.raises(ValueError, match="applies to sampled inputs"):
        m.simulate(turning_points=[0, 1], interpolate="cubic")
