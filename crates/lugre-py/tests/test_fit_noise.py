"""lugre.fit on records as labs make them: the noise found, how it was used, the gate.

The servo-axis samples are those of the independent generator (scipy Radau,
crates/lugre/tests/reference/servo_axis.py, committed noise-free as servo_axis_clean.csv); the
noise is added here: 0.5 um on the position, rounded to 0.1 um, and 0.2 N on the force.
"""

import os

import numpy as np
import pytest

import lugre

CLEAN = os.path.join(
    os.path.dirname(__file__), "..", "..", "lugre", "tests", "reference", "servo_axis_clean.csv"
)


@pytest.fixture(scope="module")
def servo():
    t, u_mm, f = np.loadtxt(CLEAN, delimiter=",", skiprows=1).T
    rng = np.random.default_rng(7)
    u = np.round((u_mm * 1e-3 + 0.5e-6 * rng.standard_normal(t.size)) / 1e-7) * 1e-7
    return t, u, f + 0.2 * rng.standard_normal(t.size)


def test_the_noise_is_found_used_and_reported(servo):
    t, u, f = servo
    r = lugre.fit(u, f, t=t, kind="full", model=lugre.LuGre(beta=2), fix={"sigma2": 40})
    n = r["noise"]
    assert abs(n["position"] / 0.5008e-6 - 1) < 0.06
    assert abs(n["force"] / 0.2 - 1) < 0.06
    assert n["handling"] == "smoothed" and n["lambda"] > 1
    assert "smooth motion" in n["description"]
    truth = {"sigma0": 1e6, "fc": 15.0, "fs": 22.0, "vs": 4e-3}
    for name, want in truth.items():
        assert abs(r["parameters"][name]["value"] / want - 1) < 0.02, name
    assert r["covariance"]["method"] in ("classical", "newey-west")
    assert isinstance(r["warnings"], list)
    off = lugre.fit(u, f, t=t, kind="full", model=lugre.LuGre(beta=2), fix={"sigma2": 40}, noise="OFF")
    assert off["noise"]["handling"] == "as_given"
    assert any(w.startswith("the intervals cannot be trusted") for w in off["warnings"])


def test_gate_and_noise_arguments(servo):
    t, u, f = servo
    r = lugre.fit(u, f, gate=1e-5)
    assert r["noise"]["handling"] == "gate" and r["noise"]["gate"] == 1e-5
    # The slow model on rate-dependent data: told in words, with the full fit named.
    assert any("kind='full'" in w for w in r["warnings"])
    with pytest.raises(ValueError, match="gate: the gate must be a finite number >= 0"):
        lugre.fit(u, f, gate=-1)
    with pytest.raises(ValueError, match="gate applies to the slow fit"):
        lugre.fit(u, f, t=t, kind="full", gate=1e-6)
    with pytest.raises(ValueError, match="noise must be one of 'auto', 'off'"):
        lugre.fit(u, f, noise="some")
    with pytest.raises(TypeError, match="noise must be one of"):
        lugre.fit(u, f, noise=1)
