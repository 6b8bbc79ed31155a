"""lugre.read: a data file's columns by role, with units, from the reader the lugre command
uses (the Rust crate lugre-io): the same names, delimiters, comments, options and messages."""

import pickle
import re

import numpy as np
import pandas as pd
import pytest

import lugre


def write(tmp_path, name, text):
    p = tmp_path / name
    p.write_bytes(text.encode() if isinstance(text, str) else text)
    return p


def test_usual_names_units_and_other_columns(tmp_path):
    p = write(tmp_path, "lab.tsv",
              "# rig 3\r\nTime [s]\tNormal [uN]\tPosition [mm]\tFriction (uN)\tNote\r\n"
              "0\t5\t1.5\t-2\ta\r\n0.5\t5\t2.5\t-3\tb\r\n")
    d = lugre.read(p)
    assert isinstance(d, lugre.Columns) and isinstance(d, dict)
    assert list(d) == ["t", "u", "F", "N"]
    assert d["t"].dtype == np.float64 and d["u"].tolist() == [1.5, 2.5]
    assert d.units == {"t": "s", "u": "mm", "F": "uN", "N": "uN"}
    assert d.names["F"] == "Friction (uN)"
    assert d.path == str(p)
    # Straight into pandas; picklable.
    assert list(pd.DataFrame(d).columns) == ["t", "u", "F", "N"]
    e = pickle.loads(pickle.dumps(d))
    assert e.units == d.units and e["u"].tolist() == d["u"].tolist()
    # Only the roles asked for; a role by any of its names.
    d = lugre.read(p, roles=["position"])
    assert list(d) == ["t", "u"]
    assert "t [s], u [mm]" in repr(d)


def test_the_issue_files(tmp_path):
    # `lugre cycles --input` said "no column 'u'" on this header.
    d = lugre.read(write(tmp_path, "a.csv", "Time [s],Displacement [um]\n0,1\n1,2\n"))
    assert d["u"].tolist() == [1.0, 2.0] and d.units["u"] == "um"
    # `lugre dynamics --input` said "no column 'F'".
    d = lugre.read(write(tmp_path, "b.tsv", "time [s]\tforce [N]\n0\t0\n10\t1.425\n"))
    assert d["F"].tolist() == [0.0, 1.425]
    # A file `lugre loop --csv` writes: rho is not a time, y is the force.
    d = lugre.read(write(tmp_path, "c.csv", "rho,u,y\n0,0,-1\n1,1,1\n"))
    assert list(d) == ["u", "F"]


def test_options_as_dicts_or_the_commands_text(tmp_path):
    p = write(tmp_path, "lab.csv", "a;b;c\n0;1;2\n1;3;4\n")
    d = lugre.read(p, columns={"t": 1, "u": "B", "F": 3}, scale={"u": 1e-3, "F": -2})
    assert d["u"].tolist() == [1e-3, 3e-3] and d["F"].tolist() == [-4.0, -8.0]
    same = lugre.read(p, columns="t=1,u=B,F=3", scale="u=1e-3,F=-2")
    assert same.keys() == d.keys() and all((same[k] == d[k]).all() for k in d)
    d = lugre.read(write(tmp_path, "sp.txt", "0 1\n1 2\n"), delimiter="space")
    assert d["t"].tolist() == [0.0, 1.0]
    # No header: u, t,u or t,u,F by the number of columns.
    assert list(lugre.read(write(tmp_path, "n1.csv", "1\n2\n"))) == ["u"]
    assert list(lugre.read(write(tmp_path, "n3.csv", "0,1,2\n1,2,3\n"))) == ["t", "u", "F"]


@pytest.mark.parametrize("text, kwargs, message", [
    ("u,u,F\n0,1,2\n", {},
     "line 1: the header has two columns for u: 'u' (column 1) and 'u' (column 2)"),
    ("t,u,F\n0,1,2\n", {"columns": {"u": 2, "F": 2}},
     "line 1: column 2 ('u') would be read as both u and F"),
    ("t,u,F\n0,1,2\n", {"columns": "u=1,u=2"}, "columns: u is given twice (u=1 and u=2)"),
    ("t,u,F\n0,1,2\n", {"columns": {"u": 1, "x": 2}}, "columns: u is given twice (u=1 and u=2)"),
    ("t,u,F\n0,1,2\n", {"scale": "u=2,u=3"}, "scale: u is given twice (u=2 and u=3)"),
    ("t,u,F\n0,1,2\n", {"scale": {"u": 0}}, "scale u=0: a factor must be a finite number other than 0"),
    ("t,u,F\n0,1,2\n", {"columns": {"u": 9}}, "line 1: columns u=9: the file has 3 columns"),
    ("t,u\n0,1\n", {"roles": ["F"]}, "line 1: no column F (F, force, friction or y) in the header 't,u'"),
    ("# a\n# b\ntime,value\n0,1\n", {"roles": ["u"]}, "line 3: no column u"),
    ("t,u\r\n0,1\r\n1,abc\r\n", {}, "line 3: u = 'abc' is not a number"),
    ("t,u\r\n0,1\r\n0,2\r\n", {}, "line 3: times must be strictly increasing, t = 0 follows t = 0"),
    ("t,u\n0,inf\n", {}, "line 2: u must be a finite number, got inf"),
    ("t,u\n", {}, "no data rows"),
    ("a,b\n0,1\n", {}, "line 1: no column u"),
])
def test_errors_name_the_file_the_line_and_the_column(tmp_path, text, kwargs, message):
    p = write(tmp_path, "bad.csv", text)
    with pytest.raises(ValueError) as e:
        lugre.read(p, **kwargs)
    got = str(e.value)
    assert message in got, got
    if "line" in message or "no data" in message:
        assert got.startswith(f"{p}: "), got


@pytest.mark.parametrize("kwargs, message", [
    ({"columns": 3}, "columns must be a dict"),
    ({"columns": {"u": 1.5}}, "columns: a column must be a header name (str) or a 1-based number (int), got float"),
    ({"columns": {1: 1}}, "columns: a role must be a str"),
    ({"scale": {"u": "x"}}, "must be a real number, got str"),
    ({"delimiter": 1}, "delimiter must be a str, got int"),
    ({"roles": "u"}, "roles must be a sequence of str"),
])
def test_wrong_types(tmp_path, kwargs, message):
    p = write(tmp_path, "ok.csv", "u\n1\n")
    with pytest.raises(TypeError, match=re.escape(message)):
        lugre.read(p, **kwargs)
    with pytest.raises(TypeError, match="path must be a str or an os.PathLike, got int"):
        lugre.read(3)


def test_bad_values_of_keywords(tmp_path):
    p = write(tmp_path, "ok.csv", "u\n1\n")
    for kwargs, message in [
        ({"delimiter": "pipe"}, "delimiter must be 'comma', 'semicolon', 'tab' or 'space', got 'pipe'"),
        ({"columns": {"u": 0}}, "columns u=0: columns are numbered from 1"),
        ({"columns": {"u": -1}}, "columns: a column number must be >= 1, got -1"),
        ({"roles": []}, "roles: name at least one column"),
        ({"roles": ["u", "x"]}, "roles: u is given twice"),
        ({"roles": ["t"]}, "roles: t is read whenever the file has it"),
    ]:
        with pytest.raises(ValueError, match=re.escape(message)):
            lugre.read(p, **kwargs)
    with pytest.raises(ValueError, match="cannot read the file"):
        lugre.read(p.parent / "missing.csv")
