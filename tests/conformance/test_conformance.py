"""The conformance table (cases.json, format in README.md) through Python (the package
`lugre`) and the FMUs (fmpy): every case that names `python` calls lugre with its `fields`,
every case that names `fmu` drives an FMU; an accepted case's numbers must be the CLI's
`--json` to the last bit (`same`) and pass its `checks`, a refused one must raise ValueError
(or TypeError, `"kind": "type"`) / return fmi3Error with the message of `error`, spelled as
Python spells it (keywords) and as the FMUs log it.

The CLI is $LUGRE_EXE, else target/release/lugre (under $CARGO_TARGET_DIR if set); the FMUs
are target/fmu/*.fmu (bash scripts/build-fmu.sh). Run by scripts/test.sh; the Rust runner
(crates/lugre-cli/tests/conformance.rs) covers the CLI and the C ABI, the Octave one
(conformance.m) the MEX functions.
"""

import json
import math
import os
import pathlib
import subprocess
import tempfile

import numpy as np
import pytest

import lugre

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parents[1]
TARGET = pathlib.Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
EXE = os.environ.get("LUGRE_EXE") or str(TARGET / "release" / "lugre")
TABLE = json.loads((HERE / "cases.json").read_text(encoding="utf-8"))
CASES = TABLE["cases"]
RAN = {"python": 0, "fmu": 0}


def cases_for(front_end):
    return [pytest.param(c, id=c["id"]) for c in CASES if front_end in c["front_ends"]]


# ---- the table's language: numbers, paths, checks, messages


def number(v):
    """A number of the table ("nan", "inf", "-inf" for those JSON cannot hold)."""
    return {"nan": math.nan, "inf": math.inf, "-inf": -math.inf}.get(v, v) if isinstance(v, str) else v


def numbers(v):
    return [number(x) for x in v] if isinstance(v, list) else number(v)


def select(v, path):
    """The values a path selects: `a.b` keys, `[]` every element, `[k]` one (negative from the
    end), `[k:]` from k on; a leading `#` counts them."""
    if path.startswith("#"):
        inner = select(v, path[1:])
        return [len(inner[0]) if len(inner) == 1 and isinstance(inner[0], list) else len(inner)]
    current = [v]
    for segment in path.split("."):
        key, _, rest = segment.partition("[")
        current = [x.get(key) if isinstance(x, dict) else None for x in current]
        rest = "[" + rest if rest else ""
        while rest:
            inside, rest = rest[1:].split("]", 1)
            out = []
            for x in current:
                if not isinstance(x, list):
                    out.append(None)
                elif inside == "":
                    out.extend(x)
                elif inside.endswith(":"):
                    out.extend(x[int(inside[:-1]):])
                else:
                    k = int(inside)
                    out.append(x[k] if -len(x) <= k < len(x) else None)
            current = out
    if len(current) == 1 and isinstance(current[0], list):
        return current[0]
    return current


def bits_equal(a, b):
    """Equal to the last bit (numbers; booleans and strings as they are)."""
    if isinstance(a, bool) or isinstance(b, bool) or not isinstance(a, (int, float)) or not isinstance(b, (int, float)):
        return a == b and type(a) is type(b)
    return np.float64(a).tobytes() == np.float64(b).tobytes()


def check(v, path, op, want):
    got = select(v, path)
    assert got, f"{path} selects nothing"
    ops = {"==": lambda g: g == want, "!=": lambda g: g != want, "<": lambda g: g < want,
           "<=": lambda g: g <= want, ">": lambda g: g > want, ">=": lambda g: g >= want}
    for g in got:
        assert ops[op](g), f"check {path} {op} {want} fails: {g}"


def same_paths(case):
    out = []
    for s in case["ok"].get("same", []):
        if isinstance(s, str) and s.startswith("@"):
            out.extend(TABLE["sets"][s[1:]])
        else:
            out.append(s)
    return out


def spelled(case, name, front_end):
    """`name` as `front_end` spells it: the case's own spelling, else the table's, else the name."""
    own = case.get("spell", {}).get(name, {})
    if front_end in own:
        return own[front_end]
    return TABLE["spelling"].get(front_end, {}).get(name, name)


def message(case, front_end):
    """The expected message: `{name}` spelled as `front_end` spells it, `{at:k}` and `{item:k}`
    (element k of an array, 0-based) as `[k]`."""
    out, rest = "", case["error"]["message"]
    while "{" in rest:
        head, rest = rest.split("{", 1)
        name, rest = rest.split("}", 1)
        kind, _, k = name.partition(":")
        if name == "@lugre_parameters":  # the core's table, so a parameter added needs no edit
            out += head + ", ".join(lugre.PARAMETERS["LuGre"])
            continue
        out += head + (f"[{k}]" if kind in ("at", "item") and k else spelled(case, name, front_end))
    return out + rest


class Refused(Exception):
    """A front end's refusal: its kind ("value", "type") and message."""

    def __init__(self, kind, message):
        super().__init__(message)
        self.kind, self.message = kind, message


def judge(case, front_end, run):
    """Runs the case through `run` (-> the answer in the CLI's JSON shape, or Refused) and
    checks it against the table and the CLI."""
    RAN[front_end] += 1
    try:
        got = run(case)
    except Refused as e:
        assert "error" in case, f"refused: {e.message}"
        assert e.kind == case["error"].get("kind", "value"), f"a {e.kind} error: {e.message}"
        assert e.message == message(case, front_end)
        return
    assert "ok" in case, f"accepted, wanted \"{case['error']['message']}\""
    for path, op, want in case["ok"].get("checks", []):
        check(got, path, op, want)
    if "cli" in case["front_ends"]:
        reference = cli(case)
        for s in same_paths(case):
            theirs, ours = (s, s) if isinstance(s, str) else s
            a, b = select(reference, theirs), select(got, ours)
            assert a and len(a) == len(b) and all(bits_equal(x, y) for x, y in zip(a, b)), (
                f"{ours} is not the CLI's {theirs}:\n  got {b}\n  CLI {a}")


def exe():
    """The CLI, the reference every number is compared with."""
    if not os.path.exists(EXE):
        pytest.fail(f"{EXE} is missing: cargo build --release -p lugre-cli (or set LUGRE_EXE)")
    return EXE


def cli(case):
    """The CLI's JSON for the case (its file written with every digit of the doubles)."""
    with tempfile.TemporaryDirectory() as d:
        args = []
        spec = case.get("file")
        path = os.path.join(d, spec["name"]) if spec else None
        if spec:
            cols = [numbers(case["fields"][c]) for c in spec["columns"]]
            rows = "".join(",".join(repr(float(c[i])) for c in cols) + "\n" for i in range(len(cols[0])))
            pathlib.Path(path).write_text(spec["header"] + "\n" + rows)
        for a in case["cli"]:
            a = a.replace("@dir/", d + "/")
            args.append(a.replace("@file", path) if path else a)
        r = subprocess.run([exe(), *args], capture_output=True, text=True)
        assert r.returncode == 0, f"the CLI refused {args}: {r.stderr}"
        return json.loads(r.stdout)


# ---- Python


def model_of(m):
    if m is None:
        return None
    m = dict(m)
    if "model" in m:  # a model of the zoo by name, its parameters by the table's names
        return lugre.ZooModel(m.pop("model"), **{k: numbers(v) for k, v in m.items()})
    if m.pop("family", None) == "dahl":
        return lugre.Dahl(**{k: number(v) for k, v in m.items()})
    values = {k: number(v) for k, v in m.items() if k != "preset"}
    if "preset" in m:
        return lugre.LuGre.preset(m["preset"], **values)
    return lugre.LuGre(**values)


def tolist(a):
    return [None if isinstance(x, float) and math.isnan(x) else x for x in np.asarray(a).tolist()]


def py_loop(f):
    model = model_of(f.get("model")) or lugre.LuGre()
    hl = model.loop(numbers(f["turning_points"]))
    out = {"period": hl.period, "work_per_period": hl.work_per_period,
           "turning_points": [{"rho": r, "u": u, "y": y} for r, u, y in zip(hl.rho.tolist(), hl.u.tolist(), hl.y.tolist())],
           "loops": [loop.to_dict() for loop in hl.loops]}
    if "samples" in f:
        c = hl.sample(f["samples"])
        out["points"] = [{"rho": r, "u": u, "y": y} for r, u, y in zip(c.rho.tolist(), c.u.tolist(), c.y.tolist())]
    return out


def py_cycles(f):
    model = model_of(f.get("model"))
    x0 = number(f["x0"]) if "x0" in f else None  # given only when the case gives it
    r = lugre.cycles(numbers(f["history"]), number(f.get("gate", 0.0)), model, x0)["cycles"]
    rows = []
    for k in range(len(r["range"])):
        full = r["count"][k] == 1.0
        row = {name: r[name][k].item() for name in ("range", "mean", "count", "start", "end")}
        row["closure"] = r["closure"][k].item() if full else None
        row["closure_position"] = r["closure_position"][k].item() if full else None
        for name in ("work", "stored_energy_change", "dissipation", "closure_gap"):
            row[name] = r[name][k].item() if full and model is not None else None
        rows.append(row)
    return {"cycles": rows}


def py_simulate(f):
    model = model_of(f.get("model")) or lugre.LuGre()
    zoo = isinstance(model, lugre.ZooModel)
    # LuGre's initial state defaults to 0; a model of the zoo gets it only when the case gives it.
    keywords = {"x0": number(f["x0"])} if "x0" in f else {} if zoo else {"x0": 0.0}
    if "t" in f:
        keywords.update(t=numbers(f["t"]), u=numbers(f["x"]))
        if not zoo:  # a model of the zoo answers at the knots anyway
            keywords["times"] = "knots"
    for name in ("turning_points", "sine", "speed", "periods", "samples_per_period", "times"):
        if name in f:
            keywords[name] = numbers(f[name])
    r = lugre.simulate(model, **keywords)
    return {k: v if k == "model" else tolist(v) for k, v in r.items()}


def py_sweep(f):
    model = model_of(f.get("model")) or lugre.LuGre()
    keywords = {name: numbers(f[name]) for name in ("offset", "tol") if name in f}
    r = lugre.sweep(model, amplitudes=numbers(f["amplitudes"]), frequencies=numbers(f["frequencies"]), **keywords)
    columns = [tolist(r[name]) for name in lugre.SWEEP_COLUMNS]
    return {"points": [dict(zip(lugre.SWEEP_COLUMNS, row)) for row in zip(*columns)]}


def py_fit(f):
    keywords = {"kind": f.get("kind", "slow"), "model": f.get("family", "lugre")}
    for name in ("t", "fix", "starts", "x0"):
        if name in f:
            keywords[name] = numbers(f[name]) if name != "fix" else f[name]
    r = lugre.fit(numbers(f["u"]), numbers(f["f"]), **keywords)
    out = {k: r[k] for k in ("rms", "samples", "dof", "t_quantile", "condition_number", "iterations",
                              "evaluations", "starts", "converged", "turning_points")}
    out["parameters"] = {name: dict(p, ci95=list(p["ci95"])) for name, p in r["parameters"].items()}
    return out


def py_dynamics(f):
    keywords = {}
    for name, value in f.items():
        if name == "model":
            keywords[name] = model_of(value)
        elif isinstance(value, list) and value and isinstance(value[0], list):
            keywords[name] = (np.array([number(p[0]) for p in value]), np.array([number(p[1]) for p in value]))
        else:
            keywords[name] = numbers(value)
    r = lugre.dynamics(**keywords)
    out = {k: tolist(r[k]) for k in ("t", "x", "v", "z", "friction", "drive")}
    out.update(events=list(r["events"]), stats=dict(r["stats"]), energy=dict(r["energy"]),
               breakaway=r.get("breakaway"))
    if r.get("loops") is not None:
        out["loops"] = [dict(loop, turning_points=tolist(loop["turning_points"])) for loop in r["loops"]]
    return out


PYTHON = {"loop": py_loop, "cycles": py_cycles, "simulate": py_simulate, "fit": py_fit, "dynamics": py_dynamics,
          "sweep": py_sweep}


def run_python(case):
    try:
        return PYTHON[case["command"]](case["fields"])
    except ValueError as e:
        raise Refused("value", str(e)) from e
    except TypeError as e:
        raise Refused("type", str(e)) from e


@pytest.mark.parametrize("case", cases_for("python"))
def test_python(case):
    judge(case, "python", run_python)


# ---- the FMUs


def fmu_path(name):
    path = TARGET / "fmu" / f"lugre-{name}.fmu"
    if not path.exists():
        pytest.fail(f"{path} is missing: run bash scripts/build-fmu.sh")
    return path


class Fmu:
    """An FMU instance in co-simulation whose fmi3Error is a Refused with the logged message."""

    def __init__(self, name, tmp):
        fmpy = pytest.importorskip("fmpy")
        from fmpy.fmi3 import FMU3Slave

        unzipped = fmpy.extract(str(fmu_path(name)), unzipdir=str(tmp))
        md = fmpy.read_model_description(unzipped)
        self.vr = {v.name: v.valueReference for v in md.modelVariables}
        self.logs = []
        self.fmu = FMU3Slave(guid=md.guid, unzipDirectory=unzipped,
                             modelIdentifier=md.coSimulation.modelIdentifier, instanceName=name)
        self.fmu.instantiate(logMessage=lambda env, status, category, message: self.logs.append(message.decode()))

    def call(self, method, *args, **kwargs):
        from fmpy.fmi1 import FMICallException

        try:
            return getattr(self.fmu, method)(*args, **kwargs)
        except FMICallException as e:
            raise Refused("value", self.logs[-1] if self.logs else str(e)) from e

    def set(self, values):
        """Scalars, and arrays (a list: the variable's values in order)."""
        flat = [number(x) for v in values.values() for x in (v if isinstance(v, list) else [v])]
        self.call("setFloat64", [self.vr[k] for k in values], flat)

    def get(self, names):
        return dict(zip(names, self.call("getFloat64", [self.vr[k] for k in names])))

    def close(self):
        self.fmu.freeInstance()


def fmu_parameters(m):
    """A model's parameters as the FMU's (its start values are Table I: a preset sets none)."""
    m = dict(m or {})
    m.pop("preset", None)
    return {k: number(v) for k, v in m.items()}


def fmu_element(case, tmp):
    f = case["fields"]
    fmu = Fmu("friction", tmp)
    try:
        x = numbers(f["x"])
        dt = numbers(f["dt"]) if "dt" in f else list(np.diff(numbers(f["t"])))
        fmu.set({**fmu_parameters(f.get("model")), "z0": number(f.get("z0", 0.0))})
        fmu.call("enterInitializationMode", startTime=0.0)
        fmu.call("exitInitializationMode")
        t, zs, fs = 0.0, [], []
        for k, h in enumerate(dt):
            # Dyadic knots: x + v h is x[k + 1] exactly.
            fmu.set({"x": x[k], "v": (x[k + 1] - x[k]) / h})
            fmu.call("doStep", currentCommunicationPoint=t, communicationStepSize=h)
            t += h
            got = fmu.get(["z", "F"])
            zs.append(got["z"])
            fs.append(got["F"])
        return {"z": zs, "F": fs}
    finally:
        fmu.close()


def fmu_calls(case, tmp):
    f = case["fields"]
    fmu = Fmu(f["fmu"], tmp)
    out = {}
    try:
        fmu.set(f.get("parameters", {}))
        for call in f["calls"]:
            if call[0] == "init":
                fmu.call("enterInitializationMode", startTime=number(call[1]))
                fmu.call("exitInitializationMode")
            elif call[0] == "step":
                fmu.call("doStep", currentCommunicationPoint=number(call[1]), communicationStepSize=number(call[2]))
            elif call[0] == "get":
                out.update(fmu.get(call[1]))
            else:
                raise AssertionError(f"unknown call {call[0]}")
        return out
    finally:
        fmu.close()


def fmu_zoo_loop(case, tmp):
    """A model of the zoo (lugre-NAME.fmu) from rest at the input's mid-range up to its global
    maximum, then one period of the turning points, one communication step each (u set, held):
    the forces there, in the CLI's `turning_points` shape. For a Masing model (whose minor loops
    close) this is the periodic regime, to the last bit for dyadic turning points."""
    f = case["fields"]
    m = dict(f["model"])
    name = m.pop("model")
    u = numbers(f["turning_points"])
    fmu = Fmu(name, tmp)
    try:
        arrays = [len(v) for k, v in m.items() if isinstance(v, list) and "elements" in fmu.vr]
        if arrays:
            fmu.call("enterConfigurationMode")
            fmu.call("setUInt64", [fmu.vr["elements"]], [arrays[0]])
            fmu.call("exitConfigurationMode")
        fmu.set({**m, "u": 0.5 * (max(u) + min(u))})
        fmu.call("enterInitializationMode", startTime=0.0)
        fmu.call("exitInitializationMode")
        r = u.index(max(u))
        period = u[r:] + u[:r]
        out, t = [], 0.0
        for x in [period[0]] + period[1:] + period[:1]:
            fmu.set({"u": x})
            fmu.call("doStep", currentCommunicationPoint=t, communicationStepSize=1.0)
            t += 1.0
            out.append({"u": x, "y": fmu.get(["F"])["F"]})
        # The first point is the maximum reached from rest; the period's points follow, the
        # maximum again last: the CLI lists the input's order from its first point.
        n = len(u)
        return {"turning_points": [out[(k - r) % n or n] for k in range(n)]}
    finally:
        fmu.close()


@pytest.mark.parametrize("case", cases_for("fmu"))
def test_fmu(case, tmp_path):
    run = {"element": fmu_element, "fmu": fmu_calls, "loop": fmu_zoo_loop}[case["command"]]
    judge(case, "fmu", lambda c: run(c, tmp_path))


def test_the_table():
    """The table's form: at least 60 cases, unique ids, one of ok/error, known front ends."""
    assert len(CASES) >= 60
    assert len({c["id"] for c in CASES}) == len(CASES)
    for c in CASES:
        assert ("ok" in c) != ("error" in c), c["id"]
        assert set(c["front_ends"]) <= {"cli", "python", "c", "mex", "fmu"}, c["id"]
        assert ("cli" in c["front_ends"]) == ("cli" in c), c["id"]
