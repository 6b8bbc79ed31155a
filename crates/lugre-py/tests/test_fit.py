"""lugre.fit: parameter identification (the engine of `lugre fit`) on synthetic data made with
the package itself (the hysteresis loop's y_at, simulate) plus fixed-seed Gaussian noise from
numpy. The true values must come back within 2 % (slow fit) or 5 % (full fit) and lie inside
the reported 95 % intervals; requests the data cannot answer raise ValueError naming the
parameters; arguments of the wrong type raise TypeError."""

import doctest
import inspect
import math
import subprocess
import sys
import warnings

import numpy as np
import pytest

import lugre

SLOW_RECOVERY = 0.02
FULL_RECOVERY = 0.05

# Canudas de Wit et al. (1995): N/m, N s/m, N s/m, N, N, m/s.
CANUDAS = dict(sigma0=1e5, sigma1=math.sqrt(1e5), sigma2=0.4, fc=1.0, fs=1.5, vs=1e-3, beta=2.0)


def noisy(y, sd, seed):
    """y plus Gaussian noise of standard deviation sd (numpy's PCG64, fixed seed)."""
    return y + sd * np.random.default_rng(seed).standard_normal(len(y))


def loop_record(hl, periods=2, per_period=1000):
    """(rho, u, y°) at per_period evenly spaced rho per period and at every turning point (a test
    samples its reversals), over whole periods of the loop hl."""
    one = np.union1d(np.linspace(0.0, hl.period, per_period, endpoint=False), hl.rho)
    one = one[one < hl.period]
    rho = np.concatenate([one + k * hl.period for k in range(periods)])
    return rho, hl.u_at(rho), hl.y_at(rho)


def triangle_record(amp, speeds, per_sweep):
    """Times and positions of triangles between -amp and amp at each speed in turn (one sweep
    up, one down), per_sweep samples a sweep, from u = -amp at t = 0."""
    t, u = [0.0], [-amp]
    for v in speeds:
        for target in (amp, -amp):
            x = np.arange(1, per_sweep + 1) / per_sweep
            t.extend(t[-1] + abs(target - u[-1]) / v * x)
            u.extend(u[-1] + (target - u[-1]) * x)
    return np.array(t), np.array(u)


def check_recovery(r, truth, tol):
    """Every fitted parameter within tol (relative) of the truth, the truth inside its 95 %
    interval."""
    assert set(r["parameters"]) == set(truth)
    for name, want in truth.items():
        e = r["parameters"][name]
        assert abs(e["value"] - want) <= tol * want, (name, e, want)
        lo, hi = e["ci95"]
        assert lo <= want <= hi, (name, e, want)
        assert 0 < e["stderr"] < e["value"], (name, e)
        assert math.isclose(hi - e["value"], r["t_quantile"] * e["stderr"], rel_tol=1e-9)
        assert e["at_bound"] is False
    assert r["converged"] is True, r["termination"]


@pytest.fixture(scope="module")
def example4():
    """The paper's Example 4 loop (sigma0 = 6, g(0) = fs = 2, bimodal 0 -> 1 -> 0.5 -> 1.5),
    two periods sampled, 1 % noise (of the force's RMS)."""
    hl = lugre.LuGre(sigma0=6).loop_bimodal(0, 0.5, 1, 1.5)
    rho, u, y = loop_record(hl)
    sd = 0.01 * np.sqrt(np.mean(y**2))
    return u, y, noisy(y, sd, 1), sd, rho


def test_slow_fit_recovers_the_papers_example_4(example4):
    u, y, f, sd, rho = example4
    r = lugre.fit(u, f)
    check_recovery(r, dict(sigma0=6.0, fs=2.0), SLOW_RECOVERY)
    assert (r["model"], r["kind"], r["starts"]) == ("lugre", "slow", 1)
    assert list(r["parameters"]) == ["sigma0", "fs"]
    assert r["fixed"] == {}
    assert r["turning_points"] == 8  # 4 per period, 2 periods
    assert r["samples"] == len(u) and r["dof"] == len(u) - 2
    assert r["iterations"] >= 1 and r["evaluations"] >= r["iterations"]
    # The noise comes back as the residual RMS, and the fitted curve is the loop's.
    assert abs(r["rms"] - sd) < 0.1 * sd
    assert r["fitted"].dtype == np.float64 and r["fitted"].shape == u.shape
    np.testing.assert_array_equal(r["residuals"], f - r["fitted"])
    assert math.isclose(r["rms"], np.sqrt(np.mean(r["residuals"] ** 2)), rel_tol=1e-12)
    assert np.max(np.abs(r["fitted"] - y)) < 0.1 * sd
    # The two estimates are nearly uncorrelated here.
    c = r["correlation"]
    assert c.dtype == np.float64 and c.shape == (2, 2)
    np.testing.assert_allclose(np.diag(c), 1.0, rtol=1e-12)
    assert c[0, 1] == c[1, 0] and abs(c[0, 1]) < 0.5
    assert 1.0 <= r["condition_number"] < 1e10
    assert 1.96 < r["t_quantile"] < 1.962
    # Every parameter of the fitted model, the others at the paper's values.
    v = r["values"]
    defaults = {name: row["default"] for name, row in lugre.PARAMETERS["LuGre"].items()}
    assert v == {**defaults, "sigma0": r["parameters"]["sigma0"]["value"], "fs": r["parameters"]["fs"]["value"]}
    hl = lugre.LuGre(**v).loop_bimodal(0, 0.5, 1, 1.5)
    np.testing.assert_allclose(r["fitted"], hl.y_at(rho), rtol=0, atol=1e-12)


def test_slow_intervals_cover_the_truth_at_their_nominal_rate(example4):
    """The tests here use fixed seeds, for which the truth lies inside every interval; the rate
    at which a 95 % interval holds it, over 200 noise draws, must be 95 % within the binomial
    spread (190 expected, standard deviation 3.1)."""
    u, y, _, sd, _ = example4
    inside = {"sigma0": 0, "fs": 0}
    for seed in range(1000, 1200):
        r = lugre.fit(u, noisy(y, sd, seed))
        for name, want in (("sigma0", 6.0), ("fs", 2.0)):
            lo, hi = r["parameters"][name]["ci95"]
            inside[name] += lo <= want <= hi
    assert all(180 <= n <= 199 for n in inside.values()), inside


def test_noise_free_loop_is_recovered_to_rounding(example4):
    u, y, _, _, _ = example4
    r = lugre.fit(u, y)
    assert abs(r["parameters"]["sigma0"]["value"] - 6.0) < 1e-9
    assert abs(r["parameters"]["fs"]["value"] - 2.0) < 1e-9
    assert r["rms"] < 1e-12


def test_slow_fit_with_one_parameter_fixed(example4):
    u, _, f, _, _ = example4
    r = lugre.fit(u, f, fix={"fs": 2.0})  # the truth
    check_recovery(r, dict(sigma0=6.0), SLOW_RECOVERY)
    assert r["fixed"] == {"fs": 2.0}
    assert r["correlation"].shape == (1, 1)
    # A model object gives the values of the fixed parameters.
    r = lugre.fit(u, f, model=lugre.LuGre(fs=2, fc=0.5), fix=["FS"])
    assert r["fixed"] == {"fs": 2.0} and r["values"]["fc"] == 0.5
    # A fixed value away from the truth biases the other estimate and the residual.
    r_off = lugre.fit(u, f, fix={"fs": 2.2})
    assert r_off["fixed"] == {"fs": 2.2} and r_off["rms"] > 2 * r["rms"]


def test_an_estimate_held_by_its_bound_is_flagged(example4):
    u, _, f, _, _ = example4
    r = lugre.fit(u, f, bounds={"sigma0": (1, 3)})  # the truth, 6, is outside
    e = r["parameters"]["sigma0"]
    assert e["value"] <= 3.0 and math.isclose(e["value"], 3.0, rel_tol=1e-6) and e["at_bound"] is True
    assert r["parameters"]["fs"]["at_bound"] is False
    r = lugre.fit(u, f, bounds={"SIGMA0": (6.5, math.inf)})
    assert math.isclose(r["parameters"]["sigma0"]["value"], 6.5, rel_tol=1e-6)
    assert r["parameters"]["sigma0"]["at_bound"] is True


def test_slow_fit_recovers_dahl_from_a_simulated_sine():
    """A Dahl model under a slow sine (gamma = inf, the rate-independent limit y*), from x0 = 0:
    the first two periods (the transient, decayed like exp(-rho rho_u) to ~4e-11) are dropped."""
    dahl = lugre.Dahl(rho=3.0, fc=0.8)
    s = dahl.simulate(sine=(1.0, 2.0), gamma=math.inf, periods=4, samples_per_period=400)
    keep = s["t"] >= 4.0 - 1e-12
    u, y = s["u"][keep][:-1], s["y"][keep][:-1]  # whole periods: the last sample closes to the first
    assert len(u) == 800
    f = noisy(y, 0.01 * np.sqrt(np.mean(y**2)), 5)
    r = lugre.fit(u, f, model="Dahl", t=s["t"][keep][:-1])
    check_recovery(r, dict(rho=3.0, fc=0.8), SLOW_RECOVERY)
    assert r["model"] == "dahl" and r["values"] == {k: e["value"] for k, e in r["parameters"].items()}
    assert r["turning_points"] == 4


@pytest.fixture(scope="module")
def canudas():
    """A small Canudas de Wit record: triangles of +-1 mm at 0.1 mm/s .. 1 m/s (1001 samples),
    the exact simulation from x0 = 0, noise of 1 % of fs."""
    model = lugre.LuGre(**CANUDAS)
    t, u = triangle_record(1e-3, [1e-4, 1e-3, 1e-2, 1e-1, 1.0], 100)
    y = model.simulate(t=t, u=u)["y"]
    return t, u, y, noisy(y, 0.01 * CANUDAS["fs"], 6)


def test_full_fit_recovers_canudas_de_wit(canudas):
    t, u, y, f = canudas
    assert len(t) == 1001
    # beta is not fitted: its value (2) comes from the model; every other parameter starts
    # from the data (the paper's defaults are five decades off).
    r = lugre.fit(u, f, t=t, kind="full", model=lugre.LuGre(beta=2))
    truth = {k: v for k, v in CANUDAS.items() if k != "beta"}
    check_recovery(r, truth, FULL_RECOVERY)
    assert (r["kind"], r["starts"], r["turning_points"]) == ("full", 3, None)
    assert r["fixed"] == {"beta": 2.0}
    assert r["correlation"].shape == (6, 6)
    np.testing.assert_allclose(r["correlation"], r["correlation"].T, atol=1e-15)
    assert abs(r["rms"] - 0.015) < 0.15 * 0.015
    # "values" is the fitted model, and "fitted" its exact simulation.
    again = lugre.LuGre(**r["values"]).simulate(t=t, u=u)["y"]
    np.testing.assert_allclose(r["fitted"], again, rtol=0, atol=1e-9)
    # The same request with beta's value as a start of a parameter that is not fitted, as
    # `lugre fit --fit full --beta 2` gives it.
    r2 = lugre.fit(u, f, t=t, kind="full", start={"beta": 2})
    assert r2["parameters"] == r["parameters"]


def test_full_fit_options(canudas):
    t, u, _, f = canudas
    r = lugre.fit(u, f, t=t, kind="FULL", model=lugre.LuGre(beta=2), starts=1, x0=0.0)
    assert r["starts"] == 1
    check_recovery(r, {k: v for k, v in CANUDAS.items() if k != "beta"}, FULL_RECOVERY)
    # Start values and bounds: the fit ends at the same optimum.
    r2 = lugre.fit(
        u, f, t=t, kind="full", model=lugre.LuGre(beta=2), starts=1,
        start={"sigma0": 2e5, "vs": 2e-3}, bounds={"sigma0": (1e4, 1e6), "vs": (None, 0.1)},
    )
    for name, e in r["parameters"].items():
        assert math.isclose(e["value"], r2["parameters"][name]["value"], rel_tol=1e-5), name


def test_full_fit_recovers_the_papers_model_with_sigma2_fixed_at_0():
    """sigma0 = sigma1 = 1, fc = 1, fs = 2, vs = 1: sigma2 = 0 must be fixed (fitted
    parameters are positive), beta = 1 is not fitted."""
    t, u = triangle_record(6.0, [0.1, 0.3, 1.0, 3.0, 10.0], 100)
    y = lugre.LuGre().simulate(t=t, u=u)["y"]
    f = noisy(y, 0.01 * np.sqrt(np.mean(y**2)), 8)
    r = lugre.fit(u, f, t=t, kind="full", fix={"sigma2": 0, "beta": 1})
    check_recovery(r, dict(sigma0=1.0, sigma1=1.0, fc=1.0, fs=2.0, vs=1.0), FULL_RECOVERY)
    assert r["fixed"] == {"sigma2": 0.0, "beta": 1.0}
    # A held parameter needs a value: the family's defaults are the paper's, not the data's.
    with pytest.raises(ValueError) as e:
        lugre.fit(u, f, t=t, kind="full", fix={"sigma2": 0})
    assert str(e.value) == (
        "beta is held in the full fit but has no value: give it (e.g. 2, the usual Stribeck "
        "exponent) or fit it too (fix={'beta': value}, a model object that has it, or free=['beta'])"
    )
    # Without fixing it, sigma2 goes to its bound 0: reported there, with the others.
    r = lugre.fit(u, f, t=t, kind="full", fix={"beta": 1})
    assert r["parameters"]["sigma2"]["at_bound"]
    assert r["parameters"]["sigma2"]["ci95"][0] == 0.0
    assert any(w.startswith("sigma2 is at its bound 0") for w in r["warnings"])
    check_recovery(
        {**r, "parameters": {k: v for k, v in r["parameters"].items() if k != "sigma2"}},
        dict(sigma0=1.0, sigma1=1.0, fc=1.0, fs=2.0, vs=1.0),
        FULL_RECOVERY,
    )


def test_full_fit_recovers_dahl():
    dahl = lugre.Dahl(rho=2.0, fc=0.8)
    t, u = triangle_record(1.5, [0.5, 2.0], 200)
    y = dahl.simulate(t=t, u=u)["y"]
    f = noisy(y, 0.01 * np.sqrt(np.mean(y**2)), 8)
    r = lugre.fit(u, f, t=t, kind="full", model="dahl")
    check_recovery(r, dict(rho=2.0, fc=0.8), FULL_RECOVERY)


@pytest.fixture(scope="module")
def quasi_static():
    """The paper's model driven 1000 times slower than vs: the damping term sigma1 z' (~1e-4)
    is far below the noise (1 %, ~0.02)."""
    t, u = triangle_record(6.0, [1e-3], 500)
    y = lugre.LuGre().simulate(t=t, u=u)["y"]
    return t, u, noisy(y, 0.01 * np.sqrt(np.mean(y**2)), 9)


def test_sigma1_from_quasi_static_data_is_unidentifiable(quasi_static):
    t, u, f = quasi_static
    with pytest.raises(ValueError) as e:
        lugre.fit(u, f, t=t, kind="full", model=lugre.LuGre(), fix=["sigma0", "sigma2", "fc", "fs", "vs"])
    message = str(e.value)
    assert message.startswith("sigma1 cannot be identified from this data: sigma1 = "), message
    assert "its 95 % interval reaches 0" in message
    assert message.endswith("; fix it at values you know (fix={'sigma1': value}) or fit data that excite it")
    assert e.value.parameters == ("sigma1",)
    # All at once: sigma1 is among those named.
    with pytest.raises(ValueError) as e:
        lugre.fit(u, f, t=t, kind="full", fix={"sigma2": 0, "beta": 1})
    assert "sigma1" in e.value.parameters
    assert str(e.value).split(" cannot be identified")[0] == ", ".join(e.value.parameters)
    # A slow fit refuses it outright: the loop does not depend on it.
    with pytest.raises(ValueError) as e:
        lugre.fit(u, f, free="sigma1")
    assert str(e.value).startswith("sigma1 does not enter the slow loop")


# The LuGre parameters as the messages list them (the core's table).
_LUGRE = ", ".join(lugre.PARAMETERS["LuGre"])

# (keyword arguments on the Example 4 record, the message)
REQUEST_ERRORS = [
    (
        dict(fix=["sigma9"]),
        f"fix: unknown parameter 'sigma9' for the LuGre model (its parameters: {_LUGRE})",
    ),
    (dict(model="dahl", free=["sigma0"]), "free: unknown parameter 'sigma0' for the Dahl model (its parameters: rho, fc)"),
    (dict(start={"x": 1}), f"start: unknown parameter 'x' for the LuGre model (its parameters: {_LUGRE})"),
    (dict(fix="fs", free="fs"), "fs is both fixed and freed"),
    (dict(fix=["sigma0", "fs"]), "nothing to fit: every parameter of the slow fit is fixed"),
    (dict(free="beta"), "beta does not enter the slow loop: the rate-independent limit depends only on sigma0 and g(0) = Fs (Dahl: rho and Fc), so beta cannot be identified from quasi-static data (use a full fit of rate-dependent data)"),
    (dict(bounds={"sigma0": (3, 1)}), "bounds: the bounds of sigma0 must satisfy 0 <= lo < hi (hi may be inf), got [3, 1]"),
    (dict(bounds={"sigma0": (-1, None)}), "bounds: the bounds of sigma0 must satisfy 0 <= lo < hi (hi may be inf), got [-1, inf]"),
    (dict(bounds={"sigma0": (1, 2, 3)}), "bounds['sigma0'] must be a pair (lo, hi), got 3 values"),
    (
        dict(start={"sigma0": 5}, bounds={"sigma0": (10, 100)}),
        "the bounds [10, 100] of sigma0 exclude its start value 5 (it must lie strictly inside): change start['sigma0'] or bounds['sigma0']",
    ),
    (dict(start={"sigma0": -1}), "sigma0 must be > 0, got -1"),
    (dict(start={"fs": math.nan}), "fs must be a finite number, got NaN"),
    (dict(start={"sigma0": 2}, fix={"sigma0": 3}), "sigma0 is given both in start and in fix (a fixed parameter keeps the value in fix)"),
    (dict(x0=0.1), "x0 applies to the full fit (add kind='full')"),
    (dict(starts=2), "starts applies to the full fit (add kind='full')"),
    (dict(kind="medium"), "kind must be 'slow', 'full', 'stribeck', 'presliding' or 'staged', got 'medium'"),
    (dict(model="coulomb"), "model must be 'lugre', 'dahl', a lugre.LuGre or a lugre.Dahl, got 'coulomb'"),
]


@pytest.mark.parametrize("kwargs, message", REQUEST_ERRORS)
def test_bad_requests(example4, kwargs, message):
    u, _, f, _, _ = example4
    with pytest.raises(ValueError) as e:
        lugre.fit(u, f, **kwargs)
    assert str(e.value) == message


def test_bad_data():
    u = np.array([0.0, 1.0, 0.5, 1.5] * 5)
    f = np.sin(np.arange(20.0))
    cases = [
        ((u, f[:-1]), {}, "the data columns have different lengths: F has 19 values, u has 20"),
        ((u, np.where(np.arange(20) == 3, math.nan, f)), {}, "F[3] must be a finite number, got NaN"),
        ((np.where(np.arange(20) == 2, math.inf, u), f), {}, "u[2] must be a finite number, got inf"),
        ((np.arange(20.0), f), {}, "the input u has no reversal (it only rises or only falls, or is constant): the slow fit needs at least one turning point inside the data"),
        ((u, np.zeros(20)), {}, "the force F is 0 at every sample: there is nothing to fit"),
        ((u[:8], f[:8]), {}, "too few samples: 8 for 2 free parameter(s); the fit needs at least 10"),
        ((u, f), dict(kind="full"), "a full fit needs the samples' times: give t (strictly increasing, one per sample)"),
        ((u, f), dict(t=np.arange(19.0)), "the data columns have different lengths: t has 19 values, u has 20"),
        ((u, f), dict(t=np.r_[0.0, 2.0, 1.0, np.arange(3.0, 20.0)]), "times must be strictly increasing: t[2] = 1 after t[1] = 2"),
        ((u, f), dict(t=np.r_[np.arange(19.0), math.nan]), "t[19] must be a finite number, got NaN"),
        ((u, f), dict(t=np.arange(20.0), kind="full", starts=0), "the number of starts must be from 1 to 64, got 0"),
        ((u, f), dict(t=np.arange(20.0), kind="full", x0=math.inf), "x0 must be a finite number, got inf"),
        (
            (u, f),
            dict(t=np.arange(20.0), kind="full", start={"sigma1": 0}, fix={"beta": 1}),
            "start['sigma1']: the start value of sigma1 must be a finite number > 0, got 0 (to hold it at that value, give fix={'sigma1': 0.0})",
        ),
    ]
    for args, kwargs, message in cases:
        with pytest.raises(ValueError) as e:
            lugre.fit(*args, **kwargs)
        assert str(e.value) == message, (kwargs, message)


@pytest.mark.parametrize(
    "kwargs, word",
    [
        (dict(u="0,1,0"), "u"),
        (dict(u=None), "u"),
        (dict(f=[1.0, "x"] * 10), "f"),
        (dict(f=5.0), "f"),
        (dict(t="0123"), "t"),
        (dict(model=3), "model"),
        (dict(model=lugre.LuGre), "model"),
        (dict(kind=1), "kind"),
        (dict(fix=[1]), "fix"),
        (dict(fix=5), "fix"),
        (dict(free=[None]), "free"),
        (dict(start=[("sigma0", 6)]), "start"),
        (dict(start={"sigma0": "6"}), "start"),
        (dict(start={"sigma0": True}), "start"),
        (dict(start={1: 6}), "start"),
        (dict(fix={"fs": "2"}), "fix"),
        (dict(bounds={"sigma0": 5}), "bounds"),
        (dict(bounds={"sigma0": "ab"}), "bounds"),
        (dict(bounds={"sigma0": ("a", 10)}), "bounds"),
        (dict(bounds=[("sigma0", (1, 10))]), "bounds"),
        (dict(x0="0", kind="full"), "x0"),
        (dict(starts=1.5, kind="full"), "starts"),
    ],
)
def test_argument_types(example4, kwargs, word):
    u, _, f, _, _ = example4
    args = dict(u=u, f=f, t=np.arange(len(u), dtype=float))
    args.update(kwargs)
    with pytest.raises(TypeError, match=word):
        lugre.fit(**args)


def test_keyword_only_options(example4):
    u, _, f, _, _ = example4
    # fit(t, u, f) in the order of a t,u,F file is refused, not misread.
    with pytest.raises(TypeError):
        lugre.fit(np.arange(len(u), dtype=float), u, f)
    with pytest.raises(TypeError):
        lugre.fit(u)


def test_any_real_arrays_in(example4):
    u, _, f, _, _ = example4
    r = lugre.fit(u, f)
    # Lists, float32 and integer-free views, non-contiguous arrays: the same numbers.
    wide = np.zeros((len(u), 3))
    wide[:, 0], wide[:, 2] = u, f
    r_view = lugre.fit(wide[:, 0], wide[:, 2])
    r_list = lugre.fit(list(u), tuple(f))
    for other in (r_view, r_list):
        assert other["parameters"] == r["parameters"]
        np.testing.assert_array_equal(other["fitted"], r["fitted"])
    r32 = lugre.fit(u.astype(np.float32), f.astype(np.float32))
    assert abs(r32["parameters"]["sigma0"]["value"] - 6.0) < 0.02 * 6.0
    with pytest.raises(ValueError, match="one-dimensional"):
        lugre.fit(np.column_stack([u, u]), f)


def test_gil_is_released_during_a_fit(assert_gil_released):
    """Another Python thread runs while a full fit computes."""
    t, u = triangle_record(1e-3, [1e-4, 1e-3, 1e-2, 1e-1, 1.0], 10_000)
    y = lugre.LuGre(**CANUDAS).simulate(t=t, u=u)["y"]
    f = noisy(y, 0.015, 10)
    assert_gil_released(lambda: lugre.fit(u, f, t=t, kind="full", model=lugre.LuGre(beta=2)))


def test_no_warning_when_converged(example4):
    u, _, f, _, _ = example4
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert lugre.fit(u, f)["converged"] is True


def test_signature_docstring_and_example():
    assert str(inspect.signature(lugre.fit)) == (
        "(u, f, *, t=None, model='lugre', kind='slow', fix=(), free=(), start=None, bounds=None, x0=None, starts=None, interpolate='linear', normal=None, v=None, noise='auto', gate=None, stribeck=None, presliding=None, elements=None)"
    )
    doc = lugre.fit.__doc__
    for words in ("lugre fit", "kind=\"slow\"", "ci95", "correlation", "ValueError", "TypeError"):
        assert words in doc, words
    assert "fit" in lugre.__all__
    finder = doctest.DocTestFinder()
    runner = doctest.DocTestRunner()
    for test in finder.find(lugre.fit, "lugre.fit", globs={}):
        runner.run(test)
    assert runner.summarize(verbose=False) == (0, 5)


def test_bad_calls_never_crash_the_interpreter():
    code = r"""
import math, numpy as np, lugre
u = [0.0, 1.0, 0.5, 1.5] * 5
f = list(np.sin(np.arange(20.0)))
bad = [None, "x", [], [math.nan], [1e308, -1e308], np.zeros((2, 2)), object(), 1e400, 10**400, {"sigma0": None}]
for arg in bad:
    for call in (lambda a: lugre.fit(a, f), lambda a: lugre.fit(u, a), lambda a: lugre.fit(u, f, t=a, kind="full"),
                 lambda a: lugre.fit(u, f, fix=a), lambda a: lugre.fit(u, f, start=a), lambda a: lugre.fit(u, f, bounds=a),
                 lambda a: lugre.fit(u, f, model=a), lambda a: lugre.fit(u, f, t=list(range(20)), kind="full", x0=a),
                 lambda a: lugre.fit(u, f, t=list(range(20)), kind="full", starts=a)):
        try:
            call(arg)
        except (TypeError, ValueError, MemoryError):
            pass
print("alive")
"""
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "alive"


def test_full_fit_on_the_cubic_reading_of_sparse_samples():
    """433 samples of a sine (every 40th of 17 281): read as the C1 cubic through them
    (interpolate="cubic") the fit's residual is the noise's level, where the straight-line
    reading between samples as given (noise="off") is more than 1.5 times worse (as `lugre fit --interpolate cubic`)."""
    n, every = 17_281, 40
    t = np.linspace(0.0, 8.0, n)
    u = 6.0 * np.sin(2 * np.pi * t / 4.0)
    y = lugre.LuGre().simulate(t=t, u=u)["y"]
    sd = 0.01 * np.sqrt(np.mean(y**2))
    f = y + sd * np.random.default_rng(21).standard_normal(n)
    ts, us, fs = t[::every], u[::every], f[::every]
    held = {"sigma2": 0, "beta": 1}
    cubic = lugre.fit(us, fs, t=ts, kind="full", fix=held, interpolate="cubic")
    linear = lugre.fit(us, fs, t=ts, kind="full", fix=held, noise="off")
    assert abs(cubic["rms"] / sd - 1) < 0.1, (cubic["rms"], sd)
    assert linear["rms"] > 1.5 * cubic["rms"], (linear["rms"], cubic["rms"])
    # With the noise handling (the default) the samples are read as a smooth motion, each
    # output with its own velocity: as good as the cubic reading.
    smooth = lugre.fit(us, fs, t=ts, kind="full", fix=held)
    assert abs(smooth["rms"] / cubic["rms"] - 1) < 0.02, (smooth["rms"], cubic["rms"])
    assert cubic["fitted"].shape == fs.shape
    # The same samples as a velocity record (u=None, v with t): integrated from u = 0, read
    # as the C1 cubic, within 2 % of the displacement record's residual.
    vs = 6.0 * np.pi / 2.0 * np.cos(2 * np.pi * ts / 4.0)
    by_velocity = lugre.fit(None, fs, t=ts, v=vs, kind="full", fix=held)
    assert abs(by_velocity["rms"] / cubic["rms"] - 1) < 0.02, (by_velocity["rms"], cubic["rms"])
    assert np.max(np.abs(by_velocity["u"] - us)) < 1e-3 * 6.0
    with pytest.raises(ValueError, match="not both"):
        lugre.fit(us, fs, t=ts, v=vs)
    with pytest.raises(ValueError, match="needs the samples' times"):
        lugre.fit(None, fs, v=vs)
    with pytest.raises(ValueError, match="interpolate='cubic' applies to the full fit"):
        lugre.fit(us, fs, interpolate="cubic")
    with pytest.raises(ValueError, match="interpolate must be 'linear' or 'cubic'"):
        lugre.fit(us, fs, t=ts, kind="full", fix=held, interpolate="spline")


def test_a_normal_force_gives_friction_coefficients(example4):
    """normal=N: the fit of f / N (as `lugre fit --columns N=NAME`): with a constant N = 5,
    sigma0 and mu_s are the force fit's sigma0 and fs over 5."""
    u, _, f, _, _ = example4
    force = lugre.fit(u, f)
    coefficient = lugre.fit(u, 5 * f, normal=np.full(len(f), 25.0))
    assert coefficient["normal_force"] and not force["normal_force"]
    p, q = coefficient["parameters"], force["parameters"]
    assert set(p) == {"sigma0", "mu_s"}
    for a, b in ((p["sigma0"]["value"] * 5, q["sigma0"]["value"]), (p["mu_s"]["value"] * 5, q["fs"]["value"])):
        assert abs(a - b) <= 1e-6 * b, (a, b)
    with pytest.raises(ValueError, match=r"normal\[2\]: the normal force N must be > 0, got 0$"):
        lugre.fit(u, f, normal=np.where(np.arange(len(f)) == 2, 0.0, 1.0))
    with pytest.raises(ValueError, match="one normal force per sample"):
        lugre.fit(u, f, normal=np.ones(3))
