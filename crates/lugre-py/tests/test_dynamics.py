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


TABLE1 = dict(sigma0=1e5, sigma1=math.sqrt(1e5), sigma2=0.4, fc=1, fs=1.5, vs=1e-3, beta=2)


@pytest.mark.parametrize(
    "kwargs, message",
    [
        (dict(scenario="nope"), "unknown scenario"),
        (dict(scenario="pid", mass=0), "mass must be a finite number > 0, got 0"),
        (dict(scenario="pid", rtol=2), "rtol must be a number in \\(0, 1\\), got 2"),
        (dict(force_rate=1.0), "name the friction model"),
        (dict(force_rate=1.0, model=lugre.LuGre(**TABLE1)), "give t_end"),
        (dict(spring=2.0, t_end=1.0, model=lugre.LuGre(**TABLE1)), "spring needs pull or end"),
        (dict(scenario="pid", damping=-1), "damping must be a finite number >= 0, got -1"),
        (dict(force=([0, 1, 1], [0, 1, 2]), t_end=2.0, scenario="pid"), "force: times must be strictly increasing"),
        (dict(scenario="pid", times=[1.0, 200.0], t_end=100.0), "outside the run"),
        (dict(scenario="pid", samples=1), "samples must be a whole number from 2 to 10000000, got 1"),
        (dict(scenario="pid", samples=10**12), "samples must be a whole number from 2 to 10000000"),
        (dict(scenario="pid", samples=2**64 - 1), "samples must be a whole number from 2 to 10000000"),
        (dict(scenario="pid", samples=-1), "samples must be a whole number from 2 to 10000000, got -1"),
        (dict(scenario="presliding", setpoint=2.0), "setpoint needs pid"),
        (dict(scenario="pid", force_rate=1.0, force=([0], [1])), "give force_rate or force, not both"),
        (dict(scenario="lag", velocity=([0], [1e-3]), spring=1.0, pull=1.0), "give spring or velocity, not both"),
    ],
)
def test_bad_input_raises_value_error(kwargs, message):
    with pytest.raises(ValueError, match=message):
        lugre.dynamics(**kwargs)


def test_wrong_types_raise_type_error():
    with pytest.raises(TypeError):
        lugre.dynamics("lugre", scenario="pid")
    with pytest.raises(TypeError, match="t_end must be a real number, got str"):
        lugre.dynamics(scenario="pid", t_end="1")
    with pytest.raises(TypeError, match="samples must be an integer, got float"):
        lugre.dynamics(scenario="pid", samples=10.0)
    with pytest.raises(TypeError, match="loops must be True or False"):
        lugre.dynamics(scenario="pid", loops="yes")


def test_keywords_on_a_scenario_replace_its_fields():
    # New gains on the PID experiment keep its set point, 1 m (it was dropped to 0).
    r = lugre.dynamics(scenario="pid", pid=(3, 8, 6), t_end=40.0, samples=3)
    assert abs(r["x"][-1] - 1.0) < 0.15
    # A set point on top replaces the scenario's (it was ignored).
    r = lugre.dynamics(scenario="pid", setpoint=2.0, t_end=60.0, samples=3)
    assert abs(r["x"][-1] - 2.0) < 0.15
    assert "replaced" in r["description"]


def test_the_same_answer_as_the_command_line(lugre_cli):
    r = lugre.dynamics(scenario="pid", pid=(3, 8, 6), t_end=20.0, samples=11)
    j = lugre_cli(["dynamics", "--scenario", "pid", "--pid", "3,8,6", "--t-end", "20", "--samples", "11", "--json"])
    for key in lugre.DYNAMICS_COLUMNS:
        assert list(r[key]) == j[key], key
    assert r["energy"] == j["energy"]


def test_loops_a_frame_and_pickling():
    import pickle

    r = lugre.dynamics(scenario="presliding", samples=101)
    assert len(r["loops"]) == 1 and r["loops"][0]["dissipation"] > 0
    assert "loops" not in lugre.dynamics(scenario="presliding", samples=11, loops=False)
    assert lugre.dynamics(scenario="stick-slip", samples=11, loops=True)["loops"] == []
    back = pickle.loads(pickle.dumps(r))
    assert isinstance(back, lugre.DynamicsResult)
    np.testing.assert_array_equal(back["x"], r["x"])
    cols = r.columns()
    assert list(cols) == list(lugre.DYNAMICS_COLUMNS) == ["t", "x", "v", "z", "friction", "drive"]
    pd = pytest.importorskip("pandas")
    frame = r.to_frame()
    assert isinstance(frame, pd.DataFrame) and frame.shape == (101, 6)
    np.testing.assert_array_equal(frame["friction"].to_numpy(), r["friction"])


def test_a_prescribed_velocity_reports_its_drive():
    # The drive is the force M v' + F that makes the mass follow the velocity (it was 0).
    r = lugre.dynamics(scenario="lag", samples=51, mass=2.0)
    w, t = 10.0, r["t"]
    dv = -1e-3 * w * np.sin(w * t)
    np.testing.assert_allclose(r["drive"], 2.0 * dv + r["friction"], rtol=1e-12, atol=1e-15)
    e = r["energy"]
    assert abs(e["input"] - (e["stored_end"] - e["stored_start"]) - e["dissipated"]) < 1e-9 * e["input"]


def test_gms_friction_from_a_zoo_model():
    # The Maxwell-slip model runs as GMS through the core's Request::with_zoo (no code here):
    # stick-slip on Table I's scale, the positions of the core's scipy reference
    # (crates/lugre/tests/reference/dynamics/gms_dynamics.py, Radau at rtol 1e-12).
    m = lugre.ZooModel("maxwell-slip", stiffness=[2.5e4] * 4,
                       slip_force=[1.5 / 16, 4.5 / 16, 7.5 / 16, 10.5 / 16],
                       fc=1, vs=1e-3, beta=2, sigma1=1e5 ** 0.5, sigma2=0.4)
    r = lugre.dynamics(m, scenario="stick-slip", times=[0, 5, 8, 10], rtol=1e-10)
    want = [0.0, 1.2486857109672413e-05, 0.03147184263623526, 0.640066030131164]
    assert max(abs(a - b) for a, b in zip(r["x"], want)) <= 1e-9


def test_a_model_of_the_zoo_as_the_friction():
    # The elasto-plastic law runs; the other models of the zoo are refused by the core.
    ep = lugre.ZooModel("elastoplastic", sigma0=1e5, sigma1=300, sigma2=0.4, fc=1, fs=1.5,
                        vs=1e-3, beta=2, zba=5e-6)
    r = lugre.dynamics(ep, scenario="stick-slip", t_end=30, samples=11)
    assert r["x"][-1] > 1 and len(r["events"]) > 4
    with pytest.raises(ValueError, match="model bouc-wen: the dynamics take lugre, dahl, maxwell-slip or elastoplastic"):
        lugre.dynamics(lugre.ZooModel("bouc-wen"), scenario="stick-slip")
    with pytest.raises(TypeError, match="model must be a lugre.LuGre, lugre.Dahl or lugre.ZooModel, got int"):
        lugre.dynamics(3, scenario="lag")


def test_gms_loops_of_the_presliding_experiment(lugre_cli):
    # The loops of GMS friction reach Python as the command line gives them, to the last bit,
    # each with the core's fields; the work splits exactly into the springs' stored energy and
    # the dissipation, and at the experiment's slow drive it is the Maxwell-slip loop's work per
    # period to O(rate) (0.15 % here; crates/lugre/tests/dynamics_gms.rs bounds it).
    r = lugre.dynamics(model=lugre.ZooModel("maxwell-slip"), scenario="presliding", loops=True)
    j = lugre_cli(["dynamics", "--scenario", "presliding", "--model", "maxwell-slip", "--loops", "--json"])
    assert len(r["loops"]) == len(j["loops"]) >= 1
    for got, want in zip(r["loops"], j["loops"]):
        assert list(got) == list(want)
        assert {k: np.asarray(v).tolist() for k, v in got.items()} == want
        assert got["dissipation"] == got["work"] - got["bristle_energy_change"] > 0
        assert len(got["turning_points"]) >= 2 and got["t_start"] < got["t_turn"] < got["t_close"]
        assert abs(got["work"] / got["rate_independent_work"] - 1) < 1e-2
