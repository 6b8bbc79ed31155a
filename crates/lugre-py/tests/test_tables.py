"""The core's tables against the Python surface: every model's keywords (names, order,
defaults), getters, repr, dict, docstring and type stub are the parameters of ``lugre.PARAMETERS``
(the core's ``lugre::model::Parameter``); the cycle and loop columns are ``lugre.CYCLE_COLUMNS``
and ``lugre.LOOP_COLUMNS``, and the command line's JSON names the same parameters. A parameter
added to the core's table and not to one of these fails here, naming it."""

import ast
import importlib.resources
import inspect
import os
import pathlib

import numpy as np
import pytest

import lugre

MODELS = {"LuGre": lugre.LuGre, "Dahl": lugre.Dahl}
STUB = pathlib.Path(__file__).resolve().parents[1] / "python" / "lugre" / "__init__.pyi"
BEGIN = "    # The keywords and properties of the core's table (lugre.PARAMETERS), written from it:"
END = "    # end of the table's parameters"


def _stub_class(name):
    # The source tree's stub where there is one (the installed one is its copy at the build).
    stub = STUB if STUB.exists() else importlib.resources.files("lugre").joinpath("__init__.pyi")
    tree = ast.parse(stub.read_text())
    for node in tree.body:
        if isinstance(node, ast.ClassDef) and node.name == name:
            return node
    raise AssertionError(f"no class {name} in the stub")


@pytest.mark.parametrize("model", MODELS)
def test_the_keywords_are_the_tables(model):
    table = lugre.PARAMETERS[model]
    params = list(inspect.signature(MODELS[model]).parameters.values())
    assert [p.name for p in params] == list(table), model
    for p in params:
        assert p.kind == p.KEYWORD_ONLY, p
        assert p.default == table[p.name]["default"], p
    # Each keyword's default is the value a bare constructor takes.
    assert MODELS[model]().to_dict() == {name: row["default"] for name, row in table.items()}


def _stub_block(table):
    """The stub's lines of a model's parameters, written from its table."""
    lines = ["    def __init__(", "        self,", "        *,"]
    lines += [f"        {name}: _Real = {row['default']!r}," for name, row in table.items()]
    lines.append("    ) -> None: ...")
    for name in table:
        lines += ["    @property", f"    def {name}(self) -> float: ..."]
    return lines


def _with_the_table(text):
    """The stub with each model's parameter lines (between the markers, in the order of the
    classes) written from lugre.PARAMETERS."""
    lines = text.split("\n")
    out, model = [], None
    i = 0
    while i < len(lines):
        line = lines[i]
        if line.startswith("class "):
            model = line[len("class "):].split(":")[0].split("(")[0]
        out.append(line)
        if line.startswith(BEGIN):
            out.append(lines[i + 1])  # the marker's second line
            out += _stub_block(lugre.PARAMETERS[model])
            i = next(k for k in range(i, len(lines)) if lines[k] == END)
            continue
        i += 1
    return "\n".join(out)


def test_the_stubs_parameters_are_written_from_the_table():
    """The source stub's parameter lines are lugre.PARAMETERS' (LUGRE_BLESS=1 rewrites them; the
    installed stub is the source's at the last build)."""
    if not STUB.exists():
        pytest.skip(f"no source tree at {STUB}")
    text = STUB.read_text()
    want = _with_the_table(text)
    if os.environ.get("LUGRE_BLESS") and want != text:
        STUB.write_text(want)
        text = want
    assert text == want, f"{STUB} is not lugre.PARAMETERS: run LUGRE_BLESS=1 pytest {__file__}"
    assert text.count(BEGIN) == len(MODELS), "a model without its marked parameter lines"


@pytest.mark.parametrize("model", MODELS)
def test_the_stub_is_the_tables(model):
    table = lugre.PARAMETERS[model]
    cls = _stub_class(model)
    init = next(n for n in cls.body if isinstance(n, ast.FunctionDef) and n.name == "__init__")
    names = [a.arg for a in init.args.kwonlyargs]
    defaults = [ast.literal_eval(d) for d in init.args.kw_defaults]
    assert names == list(table), model
    assert defaults == [row["default"] for row in table.values()], model
    properties = {
        n.name
        for n in cls.body
        if isinstance(n, ast.FunctionDef) and any(getattr(d, "id", None) == "property" for d in n.decorator_list)
    }
    for name in table:
        assert name in properties, f"stub {model}.{name}: no property"


@pytest.mark.parametrize("model", MODELS)
def test_getters_repr_and_dict_follow_the_table(model):
    table = lugre.PARAMETERS[model]
    # A value off the default for each parameter, in its domain.
    values = {name: row["default"] + 0.25 for name, row in table.items()}
    m = MODELS[model](**values)
    for name, v in values.items():
        assert getattr(m, name) == v, name
    assert list(m.to_dict().items()) == list(values.items())
    assert repr(m) == f"{model}(" + ", ".join(f"{k}={v!r}" for k, v in values.items()) + ")"


@pytest.mark.parametrize("model", MODELS)
def test_the_docstring_lists_every_keyword_from_the_table(model):
    doc = MODELS[model].__doc__
    table = lugre.PARAMETERS[model]
    lines = [line.strip() for line in doc.splitlines()]
    for name, row in table.items():
        line = next((l for l in lines if l.split(" ", 1)[0] == name and "=" in l), None)
        assert line is not None, f"{model}.__doc__: no line for {name}"
        default = row["default"]
        assert f"= {default:g} " in line, line
        for word in (row["description"], row["domain"]):
            assert word in line, (word, line)
        if row["unit"] != "1":
            assert f"[{row['unit']}]" in line, line


def test_the_table_holds_what_the_core_checks():
    """The domains are the ones the constructors enforce: the message names the parameter and
    its condition."""
    for model, table in lugre.PARAMETERS.items():
        for name, row in table.items():
            bad = -1.0 if row["domain"] == ">= 0" else 0.0
            with pytest.raises(ValueError, match=f"^{name} must be {row['domain']}, got"):
                MODELS[model](**{name: bad})


def test_the_columns_are_the_cores():
    x = [-2.0, 1.0, -3.0, 5.0, -1.0, 3.0, -4.0, 4.0, -2.0]
    with_model = lugre.cycles(x, model=lugre.LuGre(sigma0=6))["cycles"]
    assert list(with_model) == list(lugre.CYCLE_COLUMNS)
    without = lugre.cycles(x)["cycles"]
    assert list(without) == list(lugre.CYCLE_COLUMNS)[: len(without)]
    curve = lugre.LuGre().loop([0, 1]).sample(5)
    rho, u, y = curve
    for name, column in zip(lugre.LOOP_COLUMNS, (rho, u, y)):
        np.testing.assert_array_equal(getattr(curve, name), column)


def test_the_command_line_names_the_same_parameters(lugre_cli):
    """`lugre loop --json`'s model is the same table: the same names, the same defaults."""
    for model, table in lugre.PARAMETERS.items():
        j = lugre_cli(["loop", "--model", model.lower(), "--turning-points", "0,1", "--json"])
        got = {k: v for k, v in j["model"].items() if k != "kind"}
        assert got == {name: row["default"] for name, row in table.items()}, model


@pytest.mark.parametrize("model", MODELS)
def test_a_keyword_not_in_the_table_is_a_type_error_naming_the_table(model):
    names = ", ".join(lugre.PARAMETERS[model])
    with pytest.raises(TypeError, match=rf"^{model}\(\) got an unexpected keyword argument 'mu' \(its parameters: {names}\)$"):
        MODELS[model](mu=1.0)
    with pytest.raises(TypeError, match="positional"):
        MODELS[model](1.0)
    with pytest.raises(AttributeError, match=f"'{model}' object has no attribute 'mu'"):
        MODELS[model]().mu
