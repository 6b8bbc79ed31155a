"""lugre-NAME.fmu for every model of the core's zoo table (lugre.ZOO_MODELS) in a real FMI host
(fmpy): validated; driven in co-simulation on the model's defaults from rest, its forces at the
turning points of the periodic regime are the core's loop (lugre.ZooModel(NAME).loop) to 1e-12
and its work over a period the loop's, at any communication step size; element arrays resized
through the structural parameter `elements`; bad parameters, non-finite inputs and wrong sizes
are fmi3Error with the message logged. No test names a model: a model added to the table is
tested here once its FMU is built.

Run by scripts/test.sh after `bash scripts/build-fmu.sh` (needs fmpy and the lugre package).
"""

import math

import numpy as np
import pytest

fmpy = pytest.importorskip("fmpy")
import lugre  # noqa: E402
from fmpy import read_model_description  # noqa: E402
from fmpy.fmi1 import FMICallException  # noqa: E402
import cosim  # noqa: E402

MODELS = sorted(lugre.ZOO_MODELS)
# A periodic input with nested reversals (m), started at rest at its mid-range: for the Masing
# models the state at the global maximum is then the periodic one (docs/mathematics.md, Z5).
TURNING = [3.0, 1.0, 2.0, -3.0, 0.5, -1.0]
MID = 0.5 * (max(TURNING) + min(TURNING))


def fmu_path(name):
    return cosim.fmu_path(f"lugre-{name}.fmu")


@pytest.fixture(scope="module")
def unzipped(tmp_path_factory):
    return cosim.unzip_all(tmp_path_factory, {name: f"lugre-{name}.fmu" for name in MODELS})


class Host(cosim.Host):
    """A zoo model's FMU driven along an input `u` from the time 0."""

    def __init__(self, directory):
        super().__init__(directory, "zoo")
        self.t = 0.0

    def get(self, name, n=1):
        return self.fmu.getFloat64([self.vr[name]], nValues=n)

    def start(self, u0):
        self.set("u", u0)
        self.fmu.enterInitializationMode(startTime=0.0)
        self.fmu.exitInitializationMode()

    def move(self, to, steps):
        """From the input now to `to` in `steps` communication steps of random sizes, setting u
        and der(u) at each point (the input linear between points)."""
        u = self.get("u")[0]
        cuts = np.sort(RNG.uniform(0.0, 1.0, steps - 1))
        fractions = np.concatenate([[0.0], cuts, [1.0]])
        for a, b in zip(fractions[:-1], fractions[1:]):
            h = float(b - a) + 1e-3
            ua, ub = u + (to - u) * a, u + (to - u) * b
            self.set("u", ua)
            self.set("der(u)", (ub - ua) / h)
            self.fmu.doStep(currentCommunicationPoint=self.t, communicationStepSize=h)
            self.t += h
        self.set("u", to)
        self.set("der(u)", 0.0)


RNG = np.random.default_rng(28)


@pytest.mark.parametrize("name", MODELS)
def test_the_fmu_validates_and_describes_the_tables_model(name):
    from fmpy.validation import validate_fmu
    path = fmu_path(name)
    assert validate_fmu(str(path)) == []
    md = read_model_description(str(path))
    assert md.coSimulation is not None and md.modelExchange is None
    variables = {v.name: v for v in md.modelVariables}
    for pname, p in lugre.ZOO_MODELS[name]["parameters"].items():
        v = variables[pname]
        assert (v.causality, v.variability, v.unit.replace(".", " ")) == ("parameter", "fixed", p["unit"])
        default = np.atleast_1d(p["default"])
        if p["shape"] == "elements":
            assert [d.variable.name for d in v.dimensions] == ["elements"]
            assert int(variables["elements"].start) == len(default)
        else:
            assert v.dimensions == []
        assert [float(x) for x in str(v.start).split()] == list(default)


# The models stepped by their exact segment map; those with a finite-rate form are stepped at
# the input's rate (test_finite_rate_models_are_simulate_step_by_step).
SLOW = [m for m in MODELS if not lugre.ZOO_MODELS[m]["finite_rate"]]
RATE = [m for m in MODELS if lugre.ZOO_MODELS[m]["finite_rate"]]


@pytest.mark.parametrize("name", SLOW)
def test_co_simulation_on_the_defaults_is_the_cores_loop(name, unzipped):
    """From rest at the mid-range up to the global maximum, then periods of TURNING, each
    segment in 1 to 5 steps: the forces at the turning points of the last period are the loop's
    to 1e-12 of the force scale, and its work over that period the loop's work per period."""
    want = lugre.ZooModel(name).loop(TURNING)
    scale = max(abs(y) for y in want.y)
    host = Host(unzipped[name])
    host.start(MID)
    host.move(TURNING[0], 3)
    periods = 0
    while True:
        periods += 1
        w0 = host.get("work")[0]
        forces = []
        for u in TURNING[1:] + TURNING[:1]:
            host.move(u, int(RNG.integers(1, 6)))
            forces.append(host.get("F")[0])
        forces = forces[-1:] + forces[:-1]
        err = max(abs(a - b) for a, b in zip(forces, want.y)) / scale
        # Masing models are periodic at once; a single-state model contracts to its cycle.
        if err <= 1e-12 or periods == 200:
            break
    work = host.get("work")[0] - w0
    d = host.get("dissipation")[0]
    host.close()
    assert err <= 1e-12, (name, periods, err)
    assert abs(work - want.work_per_period) <= 1e-12 * max(abs(want.work_per_period), scale), (work, want.work_per_period)
    assert math.isfinite(d)
    if lugre.ZOO_MODELS[name]["closes_minor_loops"]:
        assert periods == 1


@pytest.mark.parametrize("name", RATE)
def test_finite_rate_models_are_simulate_step_by_step(name, unzipped):
    """A sampled input (irregular times, reversals of every size) given as u and der(u) at each
    communication point: after each step the force is the core's finite-rate simulation
    (lugre.ZooModel(NAME).simulate) at the last sample of the input up to that point, to 1e-12
    of the largest force; the work grows by integral F du and the dissipation stays >= 0 over
    the run."""
    rng = np.random.default_rng(28)
    n = 40
    t = np.concatenate([[0.0], np.cumsum(rng.uniform(0.05, 1.5, n))])
    u = np.concatenate([[0.0], np.cumsum(rng.uniform(-2.0, 2.0, n))])
    model = lugre.ZooModel(name)
    host = Host(unzipped[name])
    host.start(u[0])
    forces, works = [host.get("F")[0]], [host.get("work")[0]]
    for j in range(1, n + 1):
        h = float(t[j] - t[j - 1])
        host.set("u", u[j - 1])
        host.set("der(u)", (u[j] - u[j - 1]) / h)
        host.fmu.doStep(currentCommunicationPoint=float(t[j - 1]), communicationStepSize=h)
        forces.append(host.get("F")[0])
        works.append(host.get("work")[0])
    d = host.get("dissipation")[0]
    host.close()
    want = [0.0] + [float(model.simulate(t=t[: j + 1], u=u[: j + 1])["y"][-1]) for j in range(1, n + 1)]
    scale = max(abs(x) for x in want)
    err = max(abs(a - b) for a, b in zip(forces, want)) / scale
    assert err <= 1e-12, (name, err)
    assert forces[1:] != want[:-1]  # the rate matters: not the slow path shifted
    assert math.isfinite(works[-1]) and d >= -1e-12 * abs(works[-1])


def test_a_finite_rate_model_depends_on_the_rate(unzipped):
    """The same displacement in a long and a short step: different forces (the slow map would
    give one)."""
    forces = []
    for h in (100.0, 0.01):
        host = Host(unzipped[RATE[0]])
        host.start(0.0)
        host.set("u", 0.0)
        host.set("der(u)", 3.0 / h)
        host.fmu.doStep(currentCommunicationPoint=0.0, communicationStepSize=h)
        forces.append(host.get("F")[0])
        host.close()
    assert abs(forces[0] - forces[1]) > 1e-3 * abs(forces[0]), forces


@pytest.mark.parametrize("name", MODELS)
def test_bad_parameters_are_the_cores_message(name, unzipped):
    """Every parameter with a sign domain set outside it: fmi3Error at the end of initialization
    with the core's message (Python's ValueError, the same core) logged."""
    for pname, p in lugre.ZOO_MODELS[name]["parameters"].items():
        if p["domain"] not in ("> 0", ">= 0"):
            continue
        bad = np.array(p["default"], dtype=float)
        bad.flat[0] = -1.0
        with pytest.raises(ValueError) as python:
            lugre.ZooModel(name, **{pname: bad.tolist() if bad.ndim else float(bad)})
        host = Host(unzipped[name])
        host.set(pname, bad)
        host.fmu.enterInitializationMode(startTime=0.0)
        with pytest.raises(FMICallException):
            host.fmu.exitInitializationMode()
        assert host.logs[-1] == str(python.value), (pname, host.logs)
        host.fmu.freeInstance()


def an_element_model():
    return next(m for m in SLOW if any(p["shape"] == "elements" for p in lugre.ZOO_MODELS[m]["parameters"].values()))


def test_non_finite_inputs_and_wrong_sizes_are_refused(unzipped):
    name = an_element_model()
    params = lugre.ZOO_MODELS[name]["parameters"]
    array = next(p for p, v in params.items() if v["shape"] == "elements")
    n = len(params[array]["default"])
    host = Host(unzipped[name])
    with pytest.raises(FMICallException):
        host.set(array, [1.0] * (n - 1))
    assert host.logs[-1] == f"1 value references for {n - 1} values: their variables hold {n}"
    with pytest.raises(FMICallException):
        host.set(array, [1.0] * (n - 1) + [math.inf])
    assert host.logs[-1] == f"the value of {array} must be a finite number, got inf"
    host.start(0.0)
    for bad in (math.nan, math.inf):
        with pytest.raises(FMICallException):
            host.set("u", bad)
    assert host.logs[-1] == "the value of u must be a finite number, got inf"
    with pytest.raises(FMICallException):
        host.set(array, params[array]["default"])
    assert host.logs[-1] == f"{array} is a fixed parameter: set it before the end of initialization"
    with pytest.raises(FMICallException):
        host.set("F", 1.0)
    assert host.logs[-1] == "F cannot be set (it is computed by the FMU)"
    host.set("der(u)", 1e308)
    with pytest.raises(FMICallException):
        host.fmu.doStep(currentCommunicationPoint=0.0, communicationStepSize=1e10)
    assert host.logs[-1].startswith("the displacement u + der(u) (t - t_u) at the step's end is not finite")
    host.close()


def test_elements_is_a_structural_parameter(unzipped):
    """Two elements instead of the default count, set in configuration mode: the loop is the
    core's for those arrays; an array left at the old count is named; `elements` out of
    configuration mode or out of range is refused."""
    name = an_element_model()
    params = lugre.ZOO_MODELS[name]["parameters"]
    arrays = {p: v["default"][:2] for p, v in params.items() if v["shape"] == "elements"}
    host = Host(unzipped[name])
    elements = host.vr["elements"]
    assert host.fmu.getUInt64([elements]) == [len(params[next(iter(arrays))]["default"])]
    with pytest.raises(FMICallException):
        host.fmu.setUInt64([elements], [2])
    assert host.logs[-1].startswith("fmi3SetUInt64 is not allowed in the instantiated state")
    host.fmu.enterConfigurationMode()
    with pytest.raises(FMICallException):
        host.fmu.setUInt64([elements], [0])
    assert host.logs[-1] == "elements must be in [1, 134217728], got 0"
    host.fmu.setUInt64([elements], [2])
    host.fmu.exitConfigurationMode()
    assert host.fmu.getUInt64([elements]) == [2]
    first, *rest = arrays
    host.set(first, arrays[first])
    if rest:
        host.fmu.enterInitializationMode(startTime=0.0)
        with pytest.raises(FMICallException):
            host.fmu.exitInitializationMode()
        assert host.logs[-1] == f"{rest[0]} has no values for elements = 2: set its 2 values before the end of initialization"
        host.fmu.reset()
        host.fmu.enterConfigurationMode()
        host.fmu.setUInt64([elements], [2])
        host.fmu.exitConfigurationMode()
        for p, v in arrays.items():
            host.set(p, v)
    host.start(MID)
    assert list(host.get(first, 2)) == arrays[first]
    host.move(TURNING[0], 2)
    forces = []
    for u in TURNING[1:] + TURNING[:1]:
        host.move(u, 2)
        forces.append(host.get("F")[0])
    host.close()
    want = lugre.ZooModel(name, **arrays).loop(TURNING)
    np.testing.assert_allclose(forces[-1:] + forces[:-1], want.y, rtol=0, atol=1e-12 * max(abs(want.y)))


def test_a_headless_run_with_array_start_values(unzipped):
    """fmpy's simulate_fmu with the arrays as start values and u as an input signal (held over
    each step: the force at t_k+1 is the force at u(t_k))."""
    name = an_element_model()
    params = lugre.ZOO_MODELS[name]["parameters"]
    start = {p: [2.0 * x for x in v["default"]] for p, v in params.items() if v["shape"] == "elements"}
    signal = np.array([(0.0, MID), (1.0, TURNING[0]), (2.0, TURNING[3]), (3.0, TURNING[0])],
                      dtype=[("time", float), ("u", float)])
    r = fmpy.simulate_fmu(str(fmu_path(name)), fmi_type="CoSimulation", stop_time=4.0, output_interval=1.0,
                          start_values=start, input=signal, output=["u", "F", "work"])
    want = lugre.ZooModel(name, **start).loop([TURNING[0], TURNING[3]])
    assert abs(r["F"][2] - want.y[0]) <= 1e-12 * max(abs(want.y))
    assert abs(r["F"][3] - want.y[1]) <= 1e-12 * max(abs(want.y))
    assert abs(r["F"][4] - want.y[0]) <= 1e-12 * max(abs(want.y))
    assert abs(r["work"][4] - r["work"][2] - want.work_per_period) <= 1e-12 * max(abs(want.work_per_period), 1.0)
