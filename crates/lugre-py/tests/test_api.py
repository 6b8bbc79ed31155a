"""The Pythonic surface: defaults, attributes, reprs, docstrings, pickling, and the issue's
"done when" command."""

import copy
import inspect
import pickle
import subprocess
import sys

import numpy as np

import lugre


def test_paper_defaults():
    m = lugre.LuGre()
    assert (m.sigma0, m.sigma1, m.sigma2, m.fc, m.fs, m.vs, m.beta) == (1.0, 1.0, 0.0, 1.0, 2.0, 1.0, 1.0)
    assert (m.g0, m.a) == (2.0, 0.5)
    d = lugre.Dahl()
    assert (d.rho, d.fc, d.sigma0, d.g0, d.a) == (1.0, 1.0, 1.0, 1.0, 1.0)
    # The paper's values, first among the table's parameters (test_tables checks all of them).
    paper = dict(sigma0=1.0, sigma1=1.0, sigma2=0.0, fc=1.0, fs=2.0, vs=1.0, beta=1.0)
    assert list(m.to_dict().items())[: len(paper)] == list(paper.items())


def test_signatures_show_the_defaults():
    assert str(inspect.signature(lugre.LuGre)).startswith("(*, sigma0=1.0, sigma1=1.0, sigma2=0.0, fc=1.0, fs=2.0, vs=1.0, beta=1.0")
    assert str(inspect.signature(lugre.Dahl)) == "(*, rho=1.0, fc=1.0)"
    assert "turning_points" in str(inspect.signature(lugre.LuGre.loop))
    assert "n=1001" in str(inspect.signature(lugre.HysteresisLoop.sample))


def test_reprs():
    m = lugre.LuGre(sigma0=6)
    assert repr(m).startswith("LuGre(sigma0=6.0, sigma1=1.0, sigma2=0.0, fc=1.0, fs=2.0, vs=1.0, beta=1.0")
    assert eval(repr(m), {"LuGre": lugre.LuGre}) == m
    assert repr(lugre.Dahl(rho=2.5)) == "Dahl(rho=2.5, fc=1.0)"
    hl = m.loop_bimodal(0, 0.5, 1, 1.5)
    r = repr(hl)
    assert r.startswith("HysteresisLoop(model=LuGre(sigma0=6.0")
    assert "turning_points=[0.0, 1.0, 0.5, 1.5]" in r and "period=4.0" in r and "loops=2" in r
    long = lugre.LuGre().loop(np.arange(100) % 2 * (np.arange(100) + 1.0))
    assert "..." in repr(long) and len(repr(long)) < 400
    minor = hl.loops[1]
    assert repr(minor).startswith("Loop(kind='minor', depth=1, parent=0, start=(rho=1.0, u=1.0, y=1.80297")
    assert repr(minor.start) == f"LoopPoint(rho=1.0, u=1.0, y={minor.start.y!r})"
    assert repr(hl.theorem_a).startswith("TheoremA(rho=[0.0, 1.0, 1.5, 2.5, 4.0, 2.0], y=[")
    assert repr(hl.theorem_a).endswith("minor_loop=(1.0, 2.0))")


def test_theorem_a_prints_a_table():
    ta = lugre.LuGre(sigma0=6).loop_bimodal(0, 0.5, 1, 1.5).theorem_a
    s = str(ta)
    lines = s.splitlines()
    assert lines[0] == "Theorem A (bimodal input)"
    for i in range(6):
        assert lines[2 + i].split()[0] == f"rho_{i}"
    assert lines[7].split() == ["rho_5", "2.0", "1.2968184494717006"]
    assert lines[-1] == "minor loop: rho in [rho_1, rho_5] = [1.0, 2.0]"
    assert ta.to_dict()["minor_loop"] == [1.0, 2.0]
    assert len(ta.to_dict()["y"]) == 6


def test_theorem_a_only_for_bimodal_inputs():
    assert lugre.LuGre().loop([0, 1, 0.2, 1.5]).theorem_a is None
    assert lugre.Dahl().loop_bimodal(0, 0.2, 1, 1.5).theorem_a is not None


def test_loop_objects():
    hl = lugre.LuGre(sigma0=6).loop_bimodal(0, 0.5, 1, 1.5)
    loops = hl.loops
    assert isinstance(loops, list) and all(isinstance(l, lugre.Loop) for l in loops)
    minor = loops[1]
    for name in ("kind", "start", "reversal", "end", "work", "stored_energy_change", "dissipation", "closure_gap", "parent", "depth"):
        assert hasattr(minor, name), name
    rho, u, y = minor.start
    assert (rho, u, y) == (minor.start.rho, minor.start.u, minor.start.y)
    assert minor.start[-1] == y and len(minor.start) == 3
    d = minor.to_dict()
    assert d["kind"] == "minor" and d["parent"] == 0 and d["depth"] == 1
    assert d["start"] == {"rho": 1.0, "u": 1.0, "y": minor.start.y}
    assert set(d) == {"kind", "start", "reversal", "end", "work", "stored_energy_change", "dissipation", "closure_gap", "parent", "depth"}
    assert hl.loops[1].start == minor.start  # LoopPoint compares by value
    assert hl.model == lugre.LuGre(sigma0=6)
    assert len(hl) == 4


def test_models_are_immutable_values():
    m = lugre.LuGre(sigma0=6)
    try:
        m.sigma0 = 7
    except AttributeError:
        pass
    else:
        raise AssertionError("sigma0 is read-only")
    assert m == lugre.LuGre(sigma0=6.0) and m != lugre.LuGre(sigma0=7)
    for obj in (m, lugre.Dahl(rho=3, fc=0.25)):
        assert pickle.loads(pickle.dumps(obj)) == obj
        assert copy.deepcopy(obj) == obj


def test_docstrings_are_visible_in_help():
    for obj, words in (
        (lugre, "hysteresis loops and minor loops"),
        (lugre.LuGre, "Stribeck"),
        (lugre.Dahl, "w' = rho"),
        (lugre.LuGre.loop, "turning points"),
        (lugre.LuGre.loop_bimodal, "Definition 1"),
        (lugre.HysteresisLoop, "normalized variable"),
        (lugre.HysteresisLoop.y_at, "elementwise"),
        (lugre.HysteresisLoop.sample, "both ends"),
        (lugre.HysteresisLoop.loops, "major loop"),
        (lugre.Loop, "closure_gap"),
        (lugre.TheoremA, "rho_5"),
        (lugre.LuGre.simulate, "eq. 5"),
        (lugre.Dahl.simulate, "eq. 5"),
        (lugre.cycles, "rainflow"),
        (lugre.fit, "standard errors"),
    ):
        assert obj.__doc__ and words in obj.__doc__, obj
    r = subprocess.run([sys.executable, "-c", "import lugre; help(lugre.LuGre)"], capture_output=True, text=True,
                       env={**_env(), "PAGER": "cat", "TERM": "dumb"})
    assert r.returncode == 0 and "sigma0=1.0" in r.stdout and "loop_bimodal" in r.stdout


def test_type_stubs_are_shipped():
    import importlib.resources as res
    files = res.files("lugre")
    assert files.joinpath("__init__.pyi").is_file()
    assert files.joinpath("py.typed").is_file()
    stub = files.joinpath("__init__.pyi").read_text()
    for name in lugre.__all__:
        if name[0].islower() and name != "__version__":  # functions
            assert f"def {name}(" in stub, name
        elif name.isupper():  # constants
            assert f"\n{name}: " in stub, name
        elif name != "__version__":
            assert f"class {name}" in stub, name
    assert stub.count("def simulate(") == 2


def test_version():
    assert isinstance(lugre.__version__, str) and lugre.__version__.count(".") == 2


def test_done_when_command():
    """The issue's check: prints rho_0..rho_5 with rho_5 = 2 and y° there."""
    code = "import lugre; print(lugre.LuGre(sigma0=6).loop_bimodal(0, 0.5, 1, 1.5).theorem_a)"
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=_env())
    assert r.returncode == 0, r.stderr
    out = r.stdout
    for i in range(6):
        assert f"rho_{i}" in out
    row5 = next(l for l in out.splitlines() if l.split()[:1] == ["rho_5"])
    assert row5.split()[1:] == ["2.0", "1.2968184494717006"]


def _env():
    import os

    return {k: v for k, v in os.environ.items()}


def _stub_functions():
    import ast
    import importlib.resources

    tree = ast.parse(importlib.resources.files("lugre").joinpath("__init__.pyi").read_text())
    return {node.name: node for node in tree.body if isinstance(node, ast.FunctionDef)}


def _stub_parameters(node):
    a = node.args
    return [p.arg for p in a.posonlyargs + a.args], [p.arg for p in a.kwonlyargs]


def test_the_stubs_match_the_signatures():
    """Every module-level function's stub has the compiled function's parameters, positional
    and keyword-only alike (a keyword added to one and not the other fails here)."""
    stubs = _stub_functions()
    checked = 0
    for name, node in stubs.items():
        func = getattr(lugre, name, None)
        if func is None or not callable(func):
            continue
        try:
            sig = inspect.signature(func)
        except (TypeError, ValueError):
            continue
        positional = [p.name for p in sig.parameters.values() if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
        keyword = [p.name for p in sig.parameters.values() if p.kind == p.KEYWORD_ONLY]
        assert _stub_parameters(node) == (positional, keyword), name
        checked += 1
    assert checked >= 3, checked


def test_dynamics_takes_the_core_request_fields():
    """The keywords of lugre.dynamics are the core request's fields (lugre::dynamics::Field):
    a field added to the core without a keyword fails here. `input` (a measured force file) is
    the command line's; Python takes the arrays as `force`."""
    sig = inspect.signature(lugre.dynamics)
    assert set(sig.parameters) == set(lugre.DYNAMICS_FIELDS) - {"input"}
