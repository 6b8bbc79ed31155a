"""lugre-mass-NAME.fmu for every finite-rate model of the core's zoo table (the descriptions in
crates/lugre-fmu/fmu/mass/, written from the table) in a real FMI host (fmpy): validated;
driven in co-simulation by a force that ramps up, holds and ramps down through zero (the
force and its rate set at each communication point), the position, velocity and friction are
`lugre dynamics --model NAME --force-profile ...`'s to the solver's tolerance, at 1 ms steps
and at random step sizes alike; bad parameters are fmi3Error with the parameter and its value
logged. No test names a model: a finite-rate model added to the table is tested here once its
FMU is built.

The CLI is $LUGRE_EXE, else target/release/lugre (under $CARGO_TARGET_DIR if set). Run by
scripts/test.sh after `bash scripts/build-fmu.sh` (needs fmpy).
"""

import json
import os
import subprocess

import numpy as np
import pytest

fmpy = pytest.importorskip("fmpy")
from fmpy.fmi1 import FMICallException  # noqa: E402
import cosim  # noqa: E402

EXE = os.environ.get("LUGRE_EXE") or str(cosim.TARGET / "release" / "lugre")
MODELS = sorted(p.stem for p in (cosim.ROOT / "crates" / "lugre-fmu" / "fmu" / "mass").glob("*.xml"))
# The force (t [s], P [N]): up to 3 N, held, down to -3 N, held to T_END: every default
# model breaks away, slides, reverses and slides back.
FORCE = [(0.0, 0.0), (2.0, 3.0), (4.0, 3.0), (6.0, -3.0)]
T_END = 9.0
TIMES = [0.5 * k for k in range(1, 19)]
RNG = np.random.default_rng(7)


def test_every_finite_rate_model_has_its_fmu():
    assert len(MODELS) >= 2, MODELS


def fmu_path(name):
    return cosim.fmu_path(f"lugre-mass-{name}.fmu")


@pytest.fixture(scope="module")
def unzipped(tmp_path_factory):
    return cosim.unzip_all(tmp_path_factory, {name: f"lugre-mass-{name}.fmu" for name in MODELS})


class Host(cosim.Host):
    """A mass FMU driven by a force from the time 0."""

    def __init__(self, directory):
        super().__init__(directory, "mass")

    def get(self, *names):
        return self.fmu.getFloat64([self.vr[n] for n in names])

    def start(self):
        self.fmu.enterInitializationMode(startTime=0.0)
        self.fmu.exitInitializationMode()


def force_at(t):
    """The force and its slope at t (the slope of the piece starting at t)."""
    for (t0, f0), (t1, f1) in zip(FORCE[:-1], FORCE[1:]):
        if t < t1:
            slope = (f1 - f0) / (t1 - t0)
            return f0 + slope * (t - t0), slope
    return FORCE[-1][1], 0.0


def communication_points(kind):
    """The points from 0 to T_END: every 1 ms, or random sizes between the force's kinks and
    the output times (each a point, so that the force is linear over every step)."""
    if kind == "1ms":
        return np.linspace(0.0, T_END, 9001)
    fixed = sorted({0.0, T_END, *TIMES, *(t for t, _ in FORCE)})
    points = [0.0]
    for a, b in zip(fixed[:-1], fixed[1:]):
        cuts = np.sort(RNG.uniform(a, b, RNG.integers(0, 40)))
        points.extend([*cuts, b])
    return np.array(points)


def drive(host, points):
    """Steps the FMU through `points`; (x, v, friction) at TIMES."""
    host.start()
    out = []
    for t0, t1 in zip(points[:-1], points[1:]):
        force, rate = force_at(t0)
        host.set("force", force)
        host.set("dforce", rate)
        host.fmu.doStep(currentCommunicationPoint=float(t0), communicationStepSize=float(t1 - t0))
        if np.min(np.abs(np.array(TIMES) - t1)) < 1e-9:
            out.append(host.get("x", "v", "friction"))
    host.fmu.terminate()
    host.fmu.freeInstance()
    return np.array(out)


def cli_dynamics(name):
    profile = ",".join(f"{t:g}:{f:g}" for t, f in FORCE)
    times = ",".join(f"{t:g}" for t in TIMES)
    done = subprocess.run([EXE, "dynamics", "--model", name, "--force-profile", profile, "--t-end", f"{T_END:g}",
                           "--times", times, "--json"], capture_output=True, text=True, check=True)
    d = json.loads(done.stdout)
    return np.array([d["x"], d["v"], d["friction"]]).T


@pytest.mark.parametrize("name", MODELS)
def test_the_fmu_validates(name):
    from fmpy.validation import validate_fmu
    assert validate_fmu(str(fmu_path(name))) == []


@pytest.mark.parametrize("name", MODELS)
@pytest.mark.parametrize("steps", ["1ms", "random"])
def test_co_simulation_is_lugre_dynamics_whatever_the_steps(unzipped, name, steps):
    got = drive(Host(unzipped[name]), communication_points(steps))
    want = cli_dynamics(name)
    scale = np.max(np.abs(want), axis=0)
    assert scale[0] > 0.1 and scale[1] > 0.1, f"{name}: the mass slides ({scale})"
    # Both solve to rtol 1e-8 (the FMU's default tolerance and the CLI's); restarting at each of
    # up to 9000 communication points keeps the difference within 1e-7 of each column's scale.
    err = np.max(np.abs(got - want) / scale, axis=0)
    assert np.all(err < 1e-7), (name, steps, err)


@pytest.mark.parametrize("name", MODELS)
def test_bad_parameters_are_errors_naming_them(unzipped, name):
    host = Host(unzipped[name])
    first = min((v for v in host.md.modelVariables if v.causality == "parameter"), key=lambda v: v.valueReference)
    n = len(str(first.start).split())
    host.set(first.name, [-2.5] * n)
    host.fmu.enterInitializationMode(startTime=0.0)
    with pytest.raises(FMICallException):
        host.fmu.exitInitializationMode()
    assert first.name in host.logs[-1] and "-2.5" in host.logs[-1], host.logs
    host.fmu.freeInstance()

    host = Host(unzipped[name])
    host.set("m", -3.0)
    host.fmu.enterInitializationMode(startTime=0.0)
    with pytest.raises(FMICallException):
        host.fmu.exitInitializationMode()
    assert host.logs[-1] == "the mass must be a finite number > 0, got -3", host.logs
    host.fmu.freeInstance()
