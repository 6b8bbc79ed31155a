"""The Pythonic surface: defaults, attributes, reprs, docstrings, pickling, and the issue's
"done when" command."""

import copy
import inspect
import pathlib
import pickle
import subprocess
import sys

import numpy as np
import pytest

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
    assert files.joinpath("chunk.pyi").is_file()
    stub = files.joinpath("__init__.pyi").read_text()
    for name in lugre.__all__:
        if inspect.ismodule(getattr(lugre, name)):
            assert f"from . import {name} as {name}" in stub, name
        elif name[0].islower() and name != "__version__":  # functions
            assert f"def {name}(" in stub, name
        elif name.isupper():  # constants
            assert f"\n{name}: " in stub, name
        elif name != "__version__":
            assert f"class {name}" in stub, name
    # LuGre.simulate, Dahl.simulate, ZooModel.simulate and the two overloads of lugre.simulate.
    assert stub.count("def simulate(") == 5


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


def _stub_tree(module):
    import ast
    import importlib.resources

    name = "__init__.pyi" if module is lugre else module.__name__.rsplit(".", 1)[1] + ".pyi"
    # The source tree's stub where there is one (the installed one is its copy at the build).
    source = pathlib.Path(__file__).resolve().parents[1] / "python" / "lugre" / name
    stub = source if source.exists() else importlib.resources.files("lugre").joinpath(name)
    return ast.parse(stub.read_text())


def _stub_parameters(node, drop_self=False):
    a = node.args
    positional = [p.arg for p in a.posonlyargs + a.args]
    if drop_self and positional[:1] in (["self"], ["cls"]):
        positional = positional[1:]
    return positional, [p.arg for p in a.kwonlyargs]


def _runtime_parameters(func):
    """(positional, keyword-only) parameter names of a compiled callable, without self."""
    sig = inspect.signature(func)
    params = [p for p in sig.parameters.values() if p.name not in ("self", "$self", "cls")]
    positional = [p.name for p in params if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
    keyword = [p.name for p in params if p.kind == p.KEYWORD_ONLY]
    return positional, keyword


def _decorators(node):
    import ast

    return {d.id for d in node.decorator_list if isinstance(d, ast.Name)}


def _stubbed_modules():
    return [lugre, lugre.chunk]


def test_the_stubs_match_the_signatures():
    """Every function's stub (of the package and of lugre.chunk) and every method's stub (of
    each class stubbed) has the compiled callable's parameters, positional and keyword-only
    alike: a keyword added to one and not the other fails here. Every public method a class
    has at run time is stubbed, and every name a module exports has a stub."""
    import ast

    checked = 0
    for module in _stubbed_modules():
        tree = _stub_tree(module)
        stubbed = {node.name for node in tree.body if isinstance(node, (ast.FunctionDef, ast.ClassDef))}
        stubbed |= {a.asname or a.name for node in tree.body if isinstance(node, ast.ImportFrom)
                    for a in node.names}
        stubbed |= {t.id for node in tree.body if isinstance(node, ast.AnnAssign)
                    for t in [node.target] if isinstance(t, ast.Name)}
        for name in module.__all__:
            assert name in stubbed or name == "__version__", f"{module.__name__}.{name} has no stub"
        for node in tree.body:
            obj = getattr(module, getattr(node, "name", ""), None)
            if isinstance(node, ast.FunctionDef) and callable(obj):
                assert _stub_parameters(node) == _runtime_parameters(obj), f"{module.__name__}.{node.name}"
                checked += 1
            elif isinstance(node, ast.ClassDef) and isinstance(obj, type):
                checked += _check_class(node, obj)
    assert checked >= 50, checked  # the functions and methods stubbed (51 today)


def _check_class(node, cls):
    """The methods stubbed in `node` against the class `cls`; returns how many were checked."""
    import ast

    methods = [m for m in node.body if isinstance(m, ast.FunctionDef)]
    names = {m.name for m in methods}
    public = {n for n, v in vars(cls).items() if not n.startswith("_") and callable(v)}
    public |= {n for n, v in vars(cls).items() if not n.startswith("_") and isinstance(v, (property, type(lugre.LuGre.g0)))}
    missing = public - names
    assert not missing, f"{cls.__name__}: not in the stub: {sorted(missing)}"
    checked = 0
    for m in methods:
        if "property" in _decorators(m) or (m.name.startswith("__") and m.name != "__init__"):
            continue
        target = cls if m.name == "__init__" else getattr(cls, m.name, None)
        assert target is not None, f"{cls.__name__}.{m.name} is stubbed but does not exist"
        if m.name == "__init__" and cls.__init__ is object.__init__ and cls.__new__ is object.__new__:
            continue
        try:
            runtime = _runtime_parameters(target)
        except (TypeError, ValueError):
            continue  # a dict subclass' inherited slots, say
        assert _stub_parameters(m, drop_self=True) == runtime, f"{cls.__name__}.{m.name}"
        checked += 1
    return checked


def test_dynamics_takes_the_core_request_fields():
    """The keywords of lugre.dynamics are the core request's fields (lugre::dynamics::Field):
    a field added to the core without a keyword fails here. `input` (a measured force file) is
    the command line's; Python takes the arrays as `force`."""
    sig = inspect.signature(lugre.dynamics)
    assert set(sig.parameters) == set(lugre.DYNAMICS_FIELDS) - {"input"}


def test_the_fit_result_stub_has_every_key():
    """The keys of lugre.fit's result are FitResult's in the stub (a key added to one and not
    the other fails here): the required ones for a slow fit, all of them (the NotRequired ones
    too) for a Stribeck fit."""
    import ast
    import importlib.resources

    tree = ast.parse(importlib.resources.files("lugre").joinpath("__init__.pyi").read_text())
    cls = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "FitResult")
    keys = [n for n in cls.body if isinstance(n, ast.AnnAssign)]
    stub = {n.target.id for n in keys}
    optional = {n.target.id for n in keys if isinstance(n.annotation, ast.Subscript)
                and getattr(n.annotation.value, "id", None) == "NotRequired"}
    rho, u, y = lugre.LuGre(sigma0=6).loop([0, 1, 0.5, 1.5]).sample(401)
    r = lugre.fit(u, y + 1e-3 * np.sin(np.arange(len(u))))
    assert set(r) == stub - optional
    v = np.array([-1e-2, -3e-3, -1e-3, -3e-4, 3e-4, 1e-3, 3e-3, 1e-2])
    f = np.sign(v) * (1 + 0.5 * np.exp(-(v / 1e-3) ** 2)) + 0.4 * v
    assert set(lugre.fit(None, f, v=v, kind="stribeck", fix={"beta": 2})) == stub


def test_presets_are_the_cores():
    m = lugre.LuGre.preset("canudas1995")
    # Table I of Canudas de Wit et al. (1995), as the CLI's --preset canudas1995.
    assert (m.sigma0, m.sigma1, m.sigma2, m.fc, m.fs, m.vs, m.beta) == (
        1e5, 1e5 ** 0.5, 0.4, 1.0, 1.5, 1e-3, 2.0)
    o = lugre.LuGre.preset("canudas1995", fs=2)
    assert o.fs == 2.0 and o.sigma0 == 1e5
    with pytest.raises(ValueError) as e:
        lugre.LuGre.preset("canudas1996")
    assert str(e.value) == "unknown preset 'canudas1996' (presets: canudas1995)"
    with pytest.raises(TypeError, match="unexpected keyword argument 'rho'"):
        lugre.LuGre.preset("canudas1995", rho=1)
    with pytest.raises(ValueError, match="fs"):
        lugre.LuGre.preset("canudas1995", fs=-1)
