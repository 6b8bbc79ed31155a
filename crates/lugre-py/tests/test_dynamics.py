"""lugre.dynamics: the 1995 experiments against the independent reference
(crates/lugre/tests/reference/dynamics/reference.json: scipy Radau, LSODA and DOP853 agreeing to
~1e-10), the result's shape, and bad input."""

import json
import math
import pathlib

import numpy as np
import pytest

import lugre

REFERENCE = json.loads(
    (pathlib.Path(__file__).parents[2] / "lugre" / "tests" / "reference" / "dynamics" / "reference.json").read_text()
)


def test_stick_slip_onsets_and_positions():
    want = REFERENCE["stickslip"]["values"]
    r = lugre.dynamics(scenario="stick-slip", times=[10.0, 20.0, 30.0])
    for got, s in zip(r["x"], want["samples"]):
        assert abs(got - s["x"]) < 1e-6, (got, s)
    onsets = [s["t"] for s in want["slip_onsets"]]
    np.testing.assert_allclose(r["slip_onsets"], onsets, rtol=0, atol=6.4e-6)
    assert abs(r["period"] - want["periods"][0]) < 6.4e-6


def test_breakaway_and_a_result_of_arrays():
    case = next(c for c in REFERENCE["breakaway"]["values"]["rates"] if c["rate"] == 10.0)
    r = lugre.dynamics(scenario="breakaway", force_rate=10.0, samples=101)
    b = r["breakaway"]
    assert abs(b["t"] - case["t"]) / case["t"] < 1e-6
    assert abs(b["force"] - case["F"]) < 1.5e-6
    for key in ("t", "x", "v", "z", "friction", "drive"):
        assert isinstance(r[key], np.ndarray) and r[key].dtype == np.float64 and r[key].shape == (101,), key
    assert set(r["stats"]) == {"steps", "rejected", "rhs_evaluations", "jacobians", "restarts"}


def test_pid_and_a_system_from_keywords():
    want = REFERENCE["pid"]["values"]["samples"]
    times = [s["t"] for s in want]
    model = lugre.LuGre(sigma0=1e5, sigma1=math.sqrt(1e5), sigma2=0.4, fc=1, fs=1.5, vs=1e-3, beta=2)
    r = lugre.dynamics(model, pid=(3, 4, 6), setpoint=1.0, t_end=100.0, times=times)
    np.testing.assert_allclose(r["x"], [s["x"] for s in want], rtol=0, atol=1e-6)
    assert all(e["kind"] in ("velocity_zero", "velocity_up", "kink") for e in r["events"])


def test_frictional_lag_from_a_velocity_profile():
    # v = 1.5e-3 m/s held: z settles to g(v) / sigma0, F to g(v) + sigma2 v.
    r = lugre.dynamics(velocity=([0, 1], [1.5e-3, 1.5e-3]), model=lugre.LuGre(sigma0=1e5, sigma1=316, sigma2=0.4, fc=1, fs=1.5, vs=1e-3, beta=2), t_end=1.0, samples=3)
    g = 1 + 0.5 * math.exp(-(1.5 ** 2))
    assert abs(r["friction"][-1] - (g + 0.4 * 1.5e-3)) < 1e-9


@pytest.mark.parametrize(
    "kwargs, message",
    [
        (dict(scenario="nope"), "unknown scenario"),
        (dict(scenario="pid", mass=0), "the mass must be a finite number > 0"),
        (dict(scenario="pid", rtol=2), "rtol"),
        (dict(force_rate=1.0), "t_end"),
        (dict(spring=2.0, t_end=1.0), "pull"),
        (dict(scenario="pid", damping=-1), "the damping"),
        (dict(force=([0, 1, 1], [0, 1, 2]), t_end=2.0), "strictly increasing"),
        (dict(scenario="pid", times=[1.0, 200.0]), "outside the run"),
        (dict(scenario="pid", samples=1), "samples"),
    ],
)
def test_bad_input_raises_value_error(kwargs, message):
    with pytest.raises(ValueError, match=message):
        lugre.dynamics(**kwargs)


def test_wrong_types_raise_type_error():
    with pytest.raises(TypeError):
        lugre.dynamics("lugre", scenario="pid")
