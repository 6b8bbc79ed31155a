"""The Bouc-Wen section of bench/compare.py (`--only bouc-wen`): lugre's exact segment map
(lugre::zoo::BoucWen) against openseespy's BoucWen uniaxial material (backward Euler with Newton,
first order in the strain step) on the same periodic strain history with nested reversals.

Both are scored against the scipy reference (crates/lugre/tests/reference/bouc_wen_reference.py,
imported here: Radau and DOP853 at rtol 1e-12, agreeing): the periodic force at every turning
point, error = max |F - F_ref| / kw. openseespy starts from z = 0; it runs PERIODS periods at
10, 100 and 1000 strain steps per monotone segment and is scored on the last one. Its time per
turning point is the time of the last period's setStrain/getStress calls over its turning points.

lugre is timed through the example binary crates/lugre/examples/bouc_wen_loops.rs (the front
ends do not have the model yet): the loops and every minor loop, with energies, of the period
repeated 10^4 times, best of five, per turning point.

openseespy's classical parameters map onto the normalized ones (Ikhouane and Rodellar 2007):
zbar = (Ao / (beta + gamma))^(1/n), rho = Ao / zbar, sigma = beta / (beta + gamma),
kx = alpha ko, kw = (1 - alpha) ko zbar.

Runs standalone too, in an environment with numpy, scipy and openseespy:

    python3 bench/compare_bouc_wen.py
"""

from __future__ import annotations

import importlib.util
import json
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
REFERENCE = os.path.join(ROOT, "crates", "lugre", "tests", "reference", "bouc_wen_reference.py")
PERIOD = [1.0, -1.0, 0.4, -0.3, 0.8, -0.6, 0.1, -0.9]
PERIODS = 30
REPEAT = 10_000
# Classical parameters (openseespy's order): alpha, ko, n, gamma, beta, Ao.
CASES = [dict(alpha=0.1, ko=2.0, n=1.0, gamma=0.3, beta=0.6, Ao=1.0),
         dict(alpha=0.1, ko=2.0, n=2.0, gamma=0.3, beta=0.6, Ao=1.0)]


def normalized(c):
    zbar = (c["Ao"] / (c["beta"] + c["gamma"])) ** (1.0 / c["n"])
    return (c["alpha"] * c["ko"], (1.0 - c["alpha"]) * c["ko"] * zbar, c["Ao"] / zbar,
            c["beta"] / (c["beta"] + c["gamma"]), c["n"])


def reference_module():
    spec = importlib.util.spec_from_file_location("bouc_wen_reference", REFERENCE)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def lugre_run(p):
    exe = os.path.join(os.environ.get("CARGO_TARGET_DIR", os.path.join(ROOT, "target")),
                       "release", "examples", "bouc_wen_loops")
    if not os.access(exe, os.X_OK):
        subprocess.run(["cargo", "build", "--release", "-q", "-p", "lugre", "--example",
                        "bouc_wen_loops"], cwd=ROOT, check=True)
    out = subprocess.run([exe, *map(repr, p), str(REPEAT), *map(repr, PERIOD)], cwd=ROOT,
                         check=True, capture_output=True, text=True).stdout
    res = json.loads(out)
    return res["force"], res["seconds_per_turning_point"]


def opensees_run(c, steps):
    """The last period's force at the turning points and its time per turning point."""
    import openseespy.opensees as ops
    ops.wipe()
    ops.uniaxialMaterial("BoucWen", 1, c["alpha"], c["ko"], c["n"], c["gamma"], c["beta"],
                         c["Ao"], 0.0, 0.0, 0.0)
    ops.testUniaxialMaterial(1)
    m = len(PERIOD)
    start = PERIOD[-1]
    # From rest at 0 to the last point, then whole periods.
    path = [(0.0, start)] + [(PERIOD[(k - 1) % m], PERIOD[k % m]) for k in range(m * PERIODS)]
    force, elapsed = [0.0] * m, 0.0
    for i, (a, b) in enumerate(path):
        last = i > len(path) - 1 - m
        t = time.perf_counter()
        for j in range(1, steps + 1):
            ops.setStrain(a + (b - a) * j / steps)
            f = ops.getStress()
        if last:
            elapsed += time.perf_counter() - t
            force[(i - 1) % m] = f
    return force, elapsed / m


def bouc_wen_rows(rows, summary, log, fmt_time, fmt_ratio):
    ref = reference_module()
    for c in CASES:
        p = normalized(c)
        name = f"Bouc-Wen n={c['n']:g} ({len(PERIOD)}-point period, nested)"
        log(f"{name}: scipy reference")
        want, _ = ref.loops(p, PERIOD)
        kw = p[1]
        err = lambda got: max(abs(g - w) for g, w in zip(got, want)) / kw
        force, t_lugre = lugre_run(p)
        e_lugre = err(force)
        rows.append((name, "lugre (exact segment map, loops + energies)", fmt_time(t_lugre),
                     f"max|dF|/kw {e_lugre:.1e}", "1"))
        best = None
        for steps in (10, 100, 1000):
            log(f"{name}: openseespy, {steps} steps per segment")
            f, t = opensees_run(c, steps)
            e = err(f)
            rows.append((name, f"openseespy BoucWen, {steps} steps/segment", fmt_time(t),
                         f"max|dF|/kw {e:.1e}", fmt_ratio(t / t_lugre)))
            best = (steps, t, e)
        steps, t, e = best
        summary.append(f"{name}: lugre {t / t_lugre:.0f}x faster than openseespy at {steps} steps "
                       f"per segment, at {e / max(e_lugre, 1e-16):.0e}x smaller error "
                       f"({e_lugre:.1e} vs {e:.1e} of kw).")


if __name__ == "__main__":
    rows, summary = [], []

    def fmt(s):
        return f"{s:.3g} s"

    bouc_wen_rows(rows, summary, lambda m: print(m, file=sys.stderr), fmt,
                  lambda r: f"{r:.0f}x")
    for r in rows:
        print("  ".join(r))
    for s in summary:
        print("* " + s)
