"""Every ```python block of the README runs as pasted (in order, in one namespace, from the
repository root). matplotlib, which the plotting lines use, is stubbed when it is not installed:
the lugre calls are what is checked."""

import os
import pathlib
import re
import sys
import types

ROOT = pathlib.Path(__file__).resolve().parents[3]


def blocks():
    text = (ROOT / "README.md").read_text()
    return re.findall(r"^```python\n(.*?)^```", text, flags=re.S | re.M)


def test_every_python_block_of_the_readme_runs(monkeypatch):
    found = blocks()
    assert len(found) >= 2
    try:
        import matplotlib

        matplotlib.use("Agg")
    except ImportError:
        plt = types.ModuleType("matplotlib.pyplot")
        for name in ("plot", "xlabel", "ylabel", "legend", "show", "figure", "title"):
            setattr(plt, name, lambda *a, **k: None)
        mpl = types.ModuleType("matplotlib")
        mpl.pyplot = plt
        monkeypatch.setitem(sys.modules, "matplotlib", mpl)
        monkeypatch.setitem(sys.modules, "matplotlib.pyplot", plt)
    monkeypatch.chdir(ROOT)
    namespace = {}
    for k, code in enumerate(found):
        exec(compile(code, f"README.md python block {k + 1}", "exec"), namespace)
    # The lab file's fit recovers the generating model (Table I: sigma0 = 1e5, Fs = 1.5).
    p = namespace["r"]["parameters"]
    assert abs(p["sigma0"]["value"] - 1e5) < 1e3 and abs(p["fs"]["value"] - 1.5) < 0.01
