"""lugre-mass.fmu (a mass with LuGre friction, drive force in) in a real FMI host (fmpy):
validated; in a co-simulation loop that closes a spring around it the stick-slip period of
`lugre dynamics --scenario stick-slip` comes back to 1e-4; model exchange with CVode follows
lugre.dynamics; the run starts from the parameters x0, v0, z0.

Run by scripts/test.sh after `bash scripts/build-fmu.sh` (needs fmpy).
"""

import os
import pathlib

import numpy as np
import pytest

fmpy = pytest.importorskip("fmpy")
from fmpy import read_model_description, extract  # noqa: E402
from fmpy.fmi3 import FMU3Slave  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
FMU = pathlib.Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target")) / "fmu" / "lugre-mass.fmu"
# The value references by name, as the model description gives them (the parameters' follow
# the core's table).
VR = {v.name: v.valueReference for v in read_model_description(str(FMU)).modelVariables} if FMU.exists() else {}

# The stick-slip period of the independent reference (scipy Radau at rtol 1e-12,
# crates/lugre/tests/reference/dynamics/reference.json), s.
PERIOD = 6.362719821065907


def slave(tmp_path):
    """A co-simulation instance of the mass FMU, instantiated."""
    unzipped = extract(str(FMU), unzipdir=str(tmp_path))
    md = read_model_description(unzipped)
    fmu = FMU3Slave(guid=md.guid, unzipDirectory=unzipped,
                    modelIdentifier=md.coSimulation.modelIdentifier, instanceName="mass")
    fmu.instantiate()
    return fmu


def test_the_fmu_validates():
    from fmpy.validation import validate_fmu
    assert validate_fmu(str(FMU)) == []


def test_stick_slip_in_a_host_loop(tmp_path):
    # The host closes the loop: a spring k = 2 N/m whose free end moves at 0.1 m/s, its force
    # (and its rate over the step) set at each 1 ms communication point.
    fmu = slave(tmp_path)
    fmu.enterInitializationMode(startTime=0.0)
    fmu.exitInitializationMode()
    k, pull, h, n = 2.0, 0.1, 1e-3, 30000
    x = v = 0.0
    vs = np.empty(n + 1)
    vs[0] = 0.0
    for i in range(n):
        t = i * h
        fmu.setFloat64([VR["force"], VR["dforce"]], [k * (pull * t - x), k * (pull - v)])
        fmu.doStep(currentCommunicationPoint=t, communicationStepSize=h)
        x, v = fmu.getFloat64([VR["x"], VR["v"]])
        vs[i + 1] = v
    fmu.terminate()
    fmu.freeInstance()
    # Slip onsets: v rising through the pull speed, located linearly between the samples.
    i = np.nonzero((vs[:-1] < pull) & (vs[1:] >= pull))[0]
    onsets = (i + (pull - vs[i]) / (vs[i + 1] - vs[i])) * h
    assert len(onsets) == 4, onsets
    periods = np.diff(onsets)
    assert np.all(np.abs(periods - PERIOD) / PERIOD < 1e-4), periods


def test_model_exchange_with_cvode_is_lugre_dynamics():
    # A 1.4 N force applied at once (not ramped): the bristles overshoot past Fs = 1.5 N and
    # the mass breaks away. CVode (rtol 1e-8, the v = 0 crossings as state events) against
    # lugre.dynamics with located sign changes.
    import lugre
    res = fmpy.simulate_fmu(str(FMU), fmi_type="ModelExchange", solver="CVode", relative_tolerance=1e-8,
                            stop_time=0.5, output_interval=1e-3, start_values={"force": 1.4},
                            output=["x", "v", "friction"])
    table1 = lugre.LuGre(sigma0=1e5, sigma1=1e5 ** 0.5, sigma2=0.4, fc=1.0, fs=1.5, vs=1e-3, beta=2.0)
    times, index = np.unique(res["time"], return_index=True)
    ref = lugre.dynamics(table1, mass=1.0, force=([0.0], [1.4]), t_end=0.5, times=times, rtol=1e-10)
    assert ref["x"][-1] > 0.04  # it slid
    err = np.max(np.abs(res["x"][index] - ref["x"])) / np.max(np.abs(ref["x"]))
    assert err < 1e-5, err


def sliding(t, x0=1.0, v0=0.2):
    """A mass sliding at v0 > 0.09 m/s with no drive and z0 = Fc / sigma0: g(v) = Fc exactly
    (exp(-(v/vs)^2) underflows), so z stays at its steady value, F = Fc + sigma2 v and
    v' = -(a + b v) with a = Fc / m = 1, b = sigma2 / m = 0.4: in closed form."""
    a, b = 1.0, 0.4
    decay = np.exp(-b * t)
    return x0 + (v0 + a / b) * (1 - decay) / b - a / b * t, (v0 + a / b) * decay - a / b


def test_initial_position_velocity_and_deflection(tmp_path):
    # Co-simulation and model exchange from x0 = 1 m, v0 = 0.2 m/s, z0 = 1e-5 m, against the
    # closed form.
    fmu = slave(tmp_path)
    fmu.setFloat64([VR["x0"], VR["v0"], VR["z0"]], [1.0, 0.2, 1e-5])
    fmu.enterInitializationMode(startTime=0.0)
    fmu.exitInitializationMode()
    assert fmu.getFloat64([VR["x"], VR["v"], VR["z"], VR["friction"]]) == [1.0, 0.2, 1e-5, 1.0 + 0.4 * 0.2]
    for i in range(100):
        fmu.doStep(currentCommunicationPoint=i * 1e-3, communicationStepSize=1e-3)
    x, v = fmu.getFloat64([VR["x"], VR["v"]])
    fmu.freeInstance()
    want_x, want_v = sliding(0.1)
    assert 0.09 < v < 0.2 and abs(x - want_x) < 1e-9 and abs(v - want_v) < 1e-8, (x - want_x, v - want_v)

    res = fmpy.simulate_fmu(str(FMU), fmi_type="ModelExchange", solver="CVode", relative_tolerance=1e-10,
                            stop_time=0.1, output_interval=1e-2,
                            start_values={"x0": 1.0, "v0": 0.2, "z0": 1e-5}, output=["x", "v"])
    want_x, want_v = sliding(res["time"])
    assert np.max(np.abs(res["x"] - want_x)) < 1e-8 and np.max(np.abs(res["v"] - want_v)) < 1e-8
