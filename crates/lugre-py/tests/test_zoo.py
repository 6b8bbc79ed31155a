"""The zoo's models from Python (lugre.ZooModel, lugre.ZooLoop, lugre.ZOO_MODELS), every model of
the core's table in turn, none named here: the table as the command line lists it, loops on the
defaults and on given arrays equal to `lugre loop --model NAME --json` to the last bit, the
surface of HysteresisLoop, pickling, and bad input refused as the command line refuses it."""

import math
import pickle
import subprocess

import numpy as np
import pytest

import lugre

MODELS = list(lugre.ZOO_MODELS)
# One period with a nested reversal and an inner one: a major loop and two minor loops.
INPUT = [3.0, 1.0, 2.0, -3.0, 0.5, -1.0]


def flag(name):
    return "--" + name.replace("_", "-")


def cli_args(name, given, samples=None):
    """`lugre loop --model NAME` with each given parameter as its flag, and the input."""
    args = ["loop", "--model", name]
    for p, v in given.items():
        values = np.atleast_1d(np.asarray(v, dtype=float))
        args.append(f"{flag(p)}={','.join(repr(float(x)) for x in values)}")
    args += [f"--turning-points={','.join(repr(x) for x in INPUT)}", "--json"]
    if samples is not None:
        args += ["--samples", str(samples)]
    return args


def as_json(hl, samples=None):
    """The loop in the shape of the command line's JSON."""
    out = {
        "model": {"kind": hl.model.name, **{k: v.tolist() if isinstance(v, np.ndarray) else v
                                            for k, v in hl.model.parameters.items()}},
        "period": hl.period,
        "turning_points": [{"rho": r, "u": u, "y": y}
                           for r, u, y in zip(hl.rho.tolist(), hl.u.tolist(), hl.y.tolist())],
        "loops": [loop.to_dict() for loop in hl.loops],
        "work_per_period": hl.work_per_period,
    }
    if samples is not None:
        rho, u, y = hl.sample(samples)
        out["points"] = [{"rho": a, "u": b, "y": c} for a, b, c in zip(rho.tolist(), u.tolist(), y.tolist())]
    return out


def same_bits(a, b, where=""):
    """Equal JSON values, floats compared by their bits (== would equate 0.0 and -0.0)."""
    if isinstance(a, dict):
        assert isinstance(b, dict) and sorted(a) == sorted(b), (where, sorted(a), sorted(b))
        for k in a:
            same_bits(a[k], b[k], f"{where}.{k}")
    elif isinstance(a, list):
        assert isinstance(b, list) and len(a) == len(b), (where, a, b)
        for i, (x, y) in enumerate(zip(a, b)):
            same_bits(x, y, f"{where}[{i}]")
    elif isinstance(a, float) or isinstance(b, float):
        assert float(a).hex() == float(b).hex(), (where, a, b)
    else:
        assert a == b, (where, a, b)


def scaled(name):
    """Every parameter given: element arrays twice as long as the defaults (each default element
    twice: a valid model whatever the model's own constraints are), alternately as lists and
    numpy arrays; scalars at their defaults."""
    out = {}
    for i, (p, row) in enumerate(lugre.ZOO_MODELS[name]["parameters"].items()):
        d = row["default"]
        if row["shape"] == "scalar":
            out[p] = d
        else:
            values = list(d) + list(d)
            out[p] = np.array(values) if i % 2 else values
    return out


def test_the_help_lists_the_table(lugre_exe):
    """Every model and parameter of ZOO_MODELS is in `lugre loop --help`, with its flag."""
    assert len(MODELS) >= 2
    text = subprocess.run([lugre_exe, "loop", "--help"], capture_output=True, text=True, check=True).stdout
    for name, m in lugre.ZOO_MODELS.items():
        assert name in text
        assert set(m) == {"label", "equations", "reference", "closes_minor_loops", "finite_rate", "parameters"}
        for p, row in m["parameters"].items():
            assert flag(p) in text, p
            assert row["shape"] in ("scalar", "elements")
            assert isinstance(row["slow_loop"], bool)
            assert isinstance(row["default"], float if row["shape"] == "scalar" else list)


@pytest.mark.parametrize("name", MODELS)
def test_defaults_are_the_command_lines_to_the_last_bit(name, lugre_cli):
    m = lugre.ZooModel(name)
    assert m.name == name and m.label == lugre.ZOO_MODELS[name]["label"]
    for p, row in lugre.ZOO_MODELS[name]["parameters"].items():
        assert np.asarray(m.parameters[p]).tolist() == row["default"]
    same_bits(as_json(m.loop(INPUT), samples=7), lugre_cli(cli_args(name, {}, samples=7)))


@pytest.mark.parametrize("name", MODELS)
def test_given_arrays_are_the_command_lines_to_the_last_bit(name, lugre_cli):
    given = scaled(name)
    m = lugre.ZooModel(name, **given)
    for p, v in given.items():
        assert np.array_equal(m.parameters[p], v)
    hl = m.loop(np.array(INPUT))
    assert len(hl.loops) == 3 and [l.kind for l in hl.loops] == ["major", "minor", "minor"]
    same_bits(as_json(hl, samples=11), lugre_cli(cli_args(name, given, samples=11)))
    # A name is found in any case, and a number is one element.
    upper = lugre.ZooModel(name.upper(), **given)
    assert upper == m


@pytest.mark.parametrize("name", MODELS)
def test_the_loop_has_the_surface_of_hysteresis_loop(name):
    hl = lugre.ZooModel(name).loop(INPUT)
    assert len(hl) == len(INPUT) and hl.u.tolist() == INPUT
    # At the turning points, y_at and u_at are the loop's own numbers (walked again from the
    # periodic state: equal up to rounding, 1e-13 relative to the largest force).
    scale = np.abs(hl.y).max()
    np.testing.assert_allclose(hl.y_at(hl.rho), hl.y, rtol=0, atol=1e-13 * scale)
    np.testing.assert_allclose(hl.u_at(hl.rho), hl.u, rtol=0, atol=1e-13 * np.abs(hl.u).max())
    assert isinstance(hl.y_at(1.0), float) and math.isnan(hl.y_at(math.inf))
    assert hl.y_at(np.zeros((2, 3))).shape == (2, 3)
    # Periodic in rho (exact: the walk starts over each period).
    r = np.linspace(0.1, hl.period - 0.1, 9)
    np.testing.assert_allclose(hl.y_at(r + hl.period), hl.y_at(r), rtol=0, atol=1e-12)
    rho, u, y = hl.sample(5)
    assert rho[0] == 0 and rho[-1] == hl.period and u[0] == max(INPUT)
    # The table is the records.
    t = hl.loop_table
    assert t["kind"].tolist() == [0 if l.kind == "major" else 1 for l in hl.loops]
    assert t["work"].tolist() == [l.work for l in hl.loops]
    assert t["parent"].tolist() == [-1 if l.parent is None else l.parent for l in hl.loops]
    assert hl.work_per_period == hl.loops[0].work
    # Energies: work = stored energy change + dissipation on every loop.
    for l in hl.loops:
        assert abs(l.work - l.stored_energy_change - l.dissipation) <= 1e-12 * max(1.0, abs(l.work))
    assert "ZooLoop(model=ZooModel(" in repr(hl)


@pytest.mark.parametrize("name", MODELS)
def test_models_and_loops_pickle(name):
    m = lugre.ZooModel(name, **scaled(name))
    assert pickle.loads(pickle.dumps(m)) == m
    hl = m.loop(INPUT)
    back = pickle.loads(pickle.dumps(hl))
    assert back.model == m
    same_bits(as_json(back, samples=5), as_json(hl, samples=5))


def first_bounded(name):
    """The first parameter whose domain excludes -1 (written '> 0' or '>= 0' in the table)."""
    for p, row in lugre.ZOO_MODELS[name]["parameters"].items():
        if row["domain"].startswith(">"):
            return p, row
    pytest.skip(f"{name} has no parameter bounded below")


@pytest.mark.parametrize("name", MODELS)
def test_a_value_outside_its_domain_is_the_command_lines_refusal(name, lugre_cli_error):
    p, row = first_bounded(name)
    value = -1.0 if row["shape"] == "scalar" else [-1.0] + list(row["default"][1:])
    with pytest.raises(ValueError) as e:
        lugre.ZooModel(name, **{p: value})
    assert str(e.value) == lugre_cli_error(cli_args(name, {p: value})), str(e.value)
    assert p in str(e.value)


@pytest.mark.parametrize("name", MODELS)
def test_arrays_of_different_lengths_are_the_command_lines_refusal(name, lugre_cli_error):
    rows = lugre.ZOO_MODELS[name]["parameters"]
    elements = [p for p, row in rows.items() if row["shape"] == "elements"]
    if len(elements) < 2:
        pytest.skip(f"{name} has one element array")
    given = {elements[0]: list(rows[elements[0]]["default"]) * 2}
    with pytest.raises(ValueError) as e:
        lugre.ZooModel(name, **given)
    assert str(e.value) == lugre_cli_error(cli_args(name, given))


@pytest.mark.parametrize("name", MODELS)
def test_wrong_names_and_types_are_type_errors_naming_the_argument(name):
    params = lugre.ZOO_MODELS[name]["parameters"]
    # A name the model does not have is a value here (the model is chosen by name): the core's
    # message, as C and MATLAB give it.
    with pytest.raises(ValueError, match=f"^the {name} model has no parameter 'no_such_parameter' "
                                         r"\(its parameters: " + ", ".join(params) + r"\)$"):
        lugre.ZooModel(name, no_such_parameter=1.0)
    for p, row in params.items():
        with pytest.raises(TypeError, match=f"^{p} must be a real number"):
            lugre.ZooModel(name, **{p: "1"})
        with pytest.raises(TypeError, match=f"^{p} must be a real number"):
            lugre.ZooModel(name, **{p: None})
        if row["shape"] == "scalar":
            with pytest.raises(ValueError, match=f"^{p} takes one value, got 2$"):
                lugre.ZooModel(name, **{p: [1.0, 2.0]})
            assert lugre.ZooModel(name, **{p: [row["default"]]}) == lugre.ZooModel(name)
        else:
            with pytest.raises(ValueError, match=f"^{p} must be one-dimensional"):
                lugre.ZooModel(name, **{p: np.ones((2, 2))})
            with pytest.raises(ValueError, match=rf"^{p}\[0\] must be .*, got NaN$"):
                lugre.ZooModel(name, **{p: [math.nan] * len(row["default"])})
    with pytest.raises(ValueError, match=r"^turning_points: "):
        lugre.ZooModel(name).loop([1.0, math.nan])
    with pytest.raises(ValueError, match="^n must be"):
        lugre.ZooModel(name).loop(INPUT).sample(1)


def test_names_that_are_not_the_zoos():
    with pytest.raises(TypeError, match="^name must be a string, got int"):
        lugre.ZooModel(3)
    with pytest.raises(ValueError, match=r"^unknown model 'no-such-model' \(the models: .*"
                                         + ", ".join(MODELS)):
        lugre.ZooModel("no-such-model")
    for name, cls in (("lugre", "LuGre"), ("dahl", "Dahl")):
        with pytest.raises(ValueError, match=f"use lugre.{cls}"):
            lugre.ZooModel(name)


def test_the_docstring_example_runs():
    import doctest

    runner = doctest.DocTestRunner()
    for test in doctest.DocTestFinder().find(lugre.ZooModel, "lugre.ZooModel", globs={"lugre": lugre}):
        runner.run(test)
    failed, attempted = runner.summarize(verbose=False)
    assert (failed, attempted) == (0, 2)


@pytest.mark.parametrize("name", MODELS)
def test_bad_values_raise_and_never_crash(name):
    """Anything at all for each parameter and for the input: a result or a ValueError/TypeError."""
    bad = [None, "x", [], [math.nan], [math.inf, 1.0], [1e308, -1e308], np.zeros((2, 2)), object(), 1e400,
           10**400, [True, False], np.array([1, 2], dtype=np.int8), np.arange(3.0)[::-1], {"a": 1}]
    for p in lugre.ZOO_MODELS[name]["parameters"]:
        for value in bad:
            try:
                lugre.ZooModel(name, **{p: value}).loop(INPUT).sample(3)
            except (ValueError, TypeError) as e:
                assert p in str(e), str(e)  # the message names the argument
    for value in bad:
        try:
            lugre.ZooModel(name).loop(value)
        except (ValueError, TypeError):
            pass


# ---- cycles of a measured history along a model's path (lugre.cycles with a ZooModel)

HISTORY = [0.0, 4.0, 1.0, 3.0, -4.0, -1.0, -3.0, 4.0, 0.0, 2.0, 1.5, 2.5, -0.5]
ENERGY = ("work", "stored_energy_change", "dissipation", "closure_gap")


@pytest.mark.parametrize("name", MODELS)
@pytest.mark.parametrize("gate", [0.0, 1.25])
def test_cycles_are_the_command_lines_to_the_last_bit(name, gate, lugre_cli):
    """lugre.cycles(u, gate, ZooModel(name)) gives `lugre cycles --model NAME --json`'s
    cycles, energies and totals, bit for bit."""
    given = scaled(name)
    r = lugre.cycles(np.array(HISTORY), gate, lugre.ZooModel(name, **given))
    args = ["cycles", "--model", name, f"--values={','.join(repr(x) for x in HISTORY)}",
            f"--gate={gate!r}", "--json"]
    for p, v in given.items():
        args.append(f"{flag(p)}={','.join(repr(float(x)) for x in np.atleast_1d(v))}")
    doc = lugre_cli(args)
    assert doc["model"]["kind"] == name
    rows = doc["cycles"]
    c = r["cycles"]
    assert len(c["range"]) == len(rows) and any(row["count"] == 1.0 for row in rows)
    for k, row in enumerate(rows):
        full = row["count"] == 1.0
        for col in ("range", "mean", "count", "start", "end"):
            same_bits(c[col][k].item(), row[col], f"{name} {col}[{k}]")
        for col in ("closure", "closure_position", *ENERGY):
            if full:
                same_bits(c[col][k].item(), row[col], f"{name} {col}[{k}]")
            else:
                assert row[col] is None
                assert c[col][k] == -1 if col == "closure" else math.isnan(c[col][k])
    same_bits(r["summary"]["energy"], doc["history"])
    assert r["reversals"]["u"].tolist() == [x["u"] for x in doc["reversals"]]


@pytest.mark.parametrize("name", MODELS)
def test_cycles_refuse_what_the_command_line_refuses(name, lugre_cli_error):
    m = lugre.ZooModel(name)
    label = lugre.ZOO_MODELS[name]["label"]
    message = f"x0 is the initial bristle state of LuGre and Dahl; the {label} model starts from rest"
    for x0 in (0.0, 1.0):
        with pytest.raises(ValueError) as e:
            lugre.cycles(HISTORY, model=m, x0=x0)
        assert str(e.value) == message
    assert lugre_cli_error(["cycles", "--model", name, "--x0", "1", "--values", "0,1,0"]) == f"--x0: {message}"
    with pytest.raises(ValueError, match=r"^u\[1\] must be a finite number, got NaN$"):
        lugre.cycles([0.0, math.nan, 1.0], model=m)
    with pytest.raises(ValueError, match=r"^a history needs at least 2 samples, got 1$"):
        lugre.cycles([0.0], model=m)


def test_cycles_name_the_models_they_take():
    with pytest.raises(TypeError) as e:
        lugre.cycles(HISTORY, model="maxwell-slip")
    assert str(e.value) == "model must be a lugre.LuGre, lugre.Dahl or lugre.ZooModel, got str"


def test_dask_takes_a_model_of_the_zoo_in_chunks_and_per_file(tmp_path):
    """lugre.dask.count/cycles follow a model of the zoo in chunks (equal to lugre.cycles, bit
    for bit; tests/test_dask_zoo.py checks it at length), with x0 refused as by lugre.cycles;
    cycles_many counts each file whole, as lugre.cycles."""
    ld = pytest.importorskip("lugre.dask")
    da = pytest.importorskip("dask.array")
    m = lugre.ZooModel(MODELS[0])
    x = da.from_array(np.array(HISTORY), chunks=5)
    got = ld.cycles(x, model=m).compute()
    want = lugre.cycles(np.array(HISTORY), model=m, reversals=False)["cycles"]
    np.testing.assert_array_equal(got["work"].to_numpy(), want["work"])
    with pytest.raises(ValueError, match="x0"):
        ld.cycles(x, model=m, x0=1.0)
    path = tmp_path / "h.npy"
    np.save(path, np.array(HISTORY))
    df = ld.cycles_many([str(path)], model=m)
    want = lugre.cycles(np.array(HISTORY), model=m, reversals=False)["cycles"]
    np.testing.assert_array_equal(df["work"].to_numpy(), want["work"])
