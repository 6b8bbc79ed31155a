"""lugre-friction.fmu in a real FMI host (fmpy): validated, and simulated headless in
co-simulation (exact for a piecewise-linear displacement with communication points at its
kinks: lugre's exact simulation to 1e-12) and in model exchange with CVode (to the solver's
tolerance); bad parameters and inputs, and calls out of FMI's order, are fmi3Error with the
message logged.

Run by scripts/test.sh after `bash scripts/build-fmu.sh` (needs fmpy and the lugre package).
"""

import os
import pathlib

import numpy as np
import pytest

fmpy = pytest.importorskip("fmpy")
import lugre  # noqa: E402
from fmpy import read_model_description, extract  # noqa: E402
from fmpy.fmi1 import FMICallException  # noqa: E402
from fmpy.fmi3 import FMU3Slave  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
FMU = pathlib.Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target")) / "fmu" / "lugre-friction.fmu"
# The value references by name, as the model description gives them (the parameters' follow
# the core's table).
VR = {v.name: v.valueReference for v in read_model_description(str(FMU)).modelVariables} if FMU.exists() else {}

# A piecewise-linear displacement (m) on the Table I scale, with a hold and a reversal.
T = np.array([0.0, 5e-3, 1e-2, 1.5e-2, 2e-2, 3e-2])
X = np.array([0.0, 5e-6, 1e-5, 1e-5, -2e-6, 4e-6])


def table1():
    return lugre.LuGre(sigma0=1e5, sigma1=1e5 ** 0.5, sigma2=0.4, fc=1.0, fs=1.5, vs=1e-3, beta=2.0)


@pytest.fixture(scope="module")
def unzipped(tmp_path_factory):
    if not FMU.exists():
        pytest.fail(f"{FMU} is missing: run bash scripts/build-fmu.sh")
    return extract(str(FMU), unzipdir=str(tmp_path_factory.mktemp("fmu")))


def slave(unzipped, logs=None):
    md = read_model_description(unzipped)
    fmu = FMU3Slave(guid=md.guid, unzipDirectory=unzipped,
                    modelIdentifier=md.coSimulation.modelIdentifier, instanceName="friction")

    def logger(env, status, category, message):
        if logs is not None:
            logs.append(message.decode())

    fmu.instantiate(logMessage=logger)
    return fmu


def test_the_fmu_validates():
    from fmpy.validation import validate_fmu
    assert validate_fmu(str(FMU)) == []


def test_co_simulation_is_the_exact_simulation_at_the_kinks(unzipped):
    fmu = slave(unzipped)
    fmu.enterInitializationMode(startTime=0.0)
    fmu.exitInitializationMode()
    zs, fs = [], []
    for k in range(len(T) - 1):
        h = T[k + 1] - T[k]
        fmu.setFloat64([VR["x"], VR["v"]], [X[k], (X[k + 1] - X[k]) / h])
        fmu.doStep(currentCommunicationPoint=T[k], communicationStepSize=h)
        z, f = fmu.getFloat64([VR["z"], VR["F"]])
        zs.append(z)
        fs.append(f)
    fmu.terminate()
    fmu.freeInstance()
    want = table1().simulate(t=T, u=X, times="knots")
    # z at every knot after the first; F with the step's velocity: the value just before the
    # kink, which the exact simulation gives at the last (open) knot.
    np.testing.assert_allclose(zs, want["z"][1:], rtol=1e-12, atol=1e-12 * 1e-5)
    assert abs(fs[-1] - want["y"][-1]) <= 1e-12 * 1.5


def test_model_exchange_with_cvode_to_its_tolerance():
    # The same piecewise-linear displacement, given to fmpy as x and its slope v with repeated
    # times at the kinks (fmpy stops CVode there: input events), integrated by CVode. (A smooth
    # input sampled for fmpy is held between its samples inside CVode's steps: that error is the
    # host's, not the FMU's.)
    slopes = np.diff(X) / np.diff(T)
    rows = [row for k in range(len(T) - 1) for row in ((T[k], X[k], slopes[k]), (T[k + 1], X[k + 1], slopes[k]))]
    signals = np.array(rows, dtype=[("time", np.float64), ("x", np.float64), ("v", np.float64)])
    errors = []
    for rtol in (1e-6, 1e-9):
        res = fmpy.simulate_fmu(str(FMU), fmi_type="ModelExchange", solver="CVode", relative_tolerance=rtol,
                                start_time=0.0, stop_time=T[-1], output_interval=1e-4, input=signals,
                                output=["F", "z"])
        times, index = np.unique(res["time"][1:-1], return_index=True)  # events repeat a time
        ref = table1().simulate(t=T, u=X, times=times)
        errors.append(np.max(np.abs(res["z"][1:-1][index] - ref["z"])) / np.max(np.abs(ref["z"])))
    # Measured: 2.8e-8 at rtol 1e-9 (CVode's default atol); looser at 1e-6.
    assert errors[1] < 1e-6 and errors[0] > errors[1], errors


def test_bad_parameters_and_inputs_are_errors_with_the_message(unzipped):
    logs = []
    fmu = slave(unzipped, logs)
    fmu.setFloat64([VR["sigma0"]], [-1.0])
    fmu.enterInitializationMode(startTime=0.0)
    with pytest.raises(FMICallException):
        fmu.exitInitializationMode()
    assert any("sigma0 must be > 0, got -1" in m for m in logs), logs
    fmu.freeInstance()

    logs.clear()
    fmu = slave(unzipped, logs)
    fmu.enterInitializationMode(startTime=0.0)
    fmu.exitInitializationMode()
    with pytest.raises(FMICallException):
        fmu.setFloat64([VR["x"]], [float("nan")])
    assert any("x must be a finite number" in m for m in logs), logs
    for h, shown in ((-1.0, "-1"), (float("nan"), "NaN"), (float("inf"), "inf")):
        logs.clear()
        with pytest.raises(FMICallException):
            fmu.doStep(currentCommunicationPoint=0.0, communicationStepSize=h)
        assert logs == [f"fmi3DoStep: the communication step size must be a finite number >= 0, got {shown}"], logs
    (f,) = fmu.getFloat64([VR["F"]])
    assert np.isfinite(f)
    fmu.freeInstance()


def test_z0_is_the_initial_deflection(unzipped):
    # z0 (named as in the mass FMU; x is the displacement input): at rest F = sigma0 z0.
    fmu = slave(unzipped)
    fmu.setFloat64([VR["z0"]], [1e-6])
    fmu.enterInitializationMode(startTime=0.0)
    fmu.exitInitializationMode()
    z, f = fmu.getFloat64([VR["z"], VR["F"]])
    assert (z, f) == (1e-6, 1e5 * 1e-6)
    fmu.freeInstance()


def test_calls_out_of_order_are_errors(unzipped):
    logs = []
    fmu = slave(unzipped, logs)
    with pytest.raises(FMICallException):
        fmu.doStep(currentCommunicationPoint=0.0, communicationStepSize=1e-3)
    assert "fmi3DoStep is not allowed in the instantiated state" in logs[-1], logs
    fmu.enterInitializationMode(startTime=0.0)
    fmu.exitInitializationMode()
    fmu.setFloat64([VR["x"], VR["v"]], [0.0, 1e-3])
    fmu.doStep(currentCommunicationPoint=0.0, communicationStepSize=1e-3)
    (t,) = fmu.getFloat64([0])
    # Initialization again after a step would rewind time: refused, time unchanged.
    with pytest.raises(FMICallException):
        fmu.enterInitializationMode(startTime=0.0)
    assert logs[-1] == ("fmi3EnterInitializationMode is not allowed in step mode: only in the instantiated "
                        "state (after instantiation or fmi3Reset) (fmi3Reset starts the instance again)"), logs
    assert fmu.getFloat64([0]) == [t] and t == 1e-3
    fmu.terminate()
    with pytest.raises(FMICallException):
        fmu.doStep(currentCommunicationPoint=t, communicationStepSize=1e-3)
    assert "fmi3DoStep is not allowed in the terminated state" in logs[-1], logs
    # fmi3Reset starts again, from the start values.
    fmu.reset()
    fmu.enterInitializationMode(startTime=0.0)
    fmu.exitInitializationMode()
    assert fmu.getFloat64([0, VR["x"]]) == [0.0, 0.0]
    fmu.freeInstance()
