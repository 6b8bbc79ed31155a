"""Every loop's work against the area the `hysteresis` package (PyPI, 2.0.5) measures on the
sampled loop: for each model of lugre.ZOO_MODELS on its defaults and for LuGre on the paper's
defaults, one periodic input with nested reversals (a major loop, two minor loops, each with a
minor loop inside), each loop's arc sampled with ZooLoop.y_at / u_at (HysteresisLoop's for
LuGre) over [start.rho, end.rho], the turning points inside included. The package's net area
(`SimpleCurve.setArea`, `getNetArea`: the trapezoid sum of y dx along the points, signed as
lugre's work, the integral of F du) must equal the loop's `work` within the sampling error:

* piecewise-linear loops (the Masing models, `closes_minor_loops`): the defaults' element
  thresholds are multiples of 1/2 and the turning points integers, so every vertex of the exact
  path lies at a multiple of 1/2 in rho, on the grid (checked: the sampled force is linear
  between them); the trapezoids are then exact, and the area agrees to rounding, 1e-12 of the
  loop's scale (the sampling error reported is |A_h - A_{2h}|, both grids on the vertices);
* smooth loops (Bouc-Wen, LuGre): the trapezoid error is c h^2 + O(h^4), estimated from the
  areas A_h and A_{h/2} as (A_h - A_{h/2}) / 3; the area at h/2 must lie within 1/2 of
  |A_h - A_{h/2}| of the work (the estimate with a margin of 1.5), and the extrapolated area
  (4 A_{h/2} - A_h) / 3 within 1% of it (the leading error term removed, what is left is the
  O(h^4) rest).

`python crates/lugre-py/tests/test_zoo_areas.py` prints the comparison as BENCHMARKS.md
records it.
"""

import sys
from importlib.metadata import version

import hysteresis
import numpy as np
import pytest

import lugre

# One period of turning points (integers): the major loop 4 -> -4 -> 4, minor loops 0 -> 3 -> 0
# and 0 -> -2 -> 0, with 1 -> 2 -> 1 and -1 -> -3 -> -1 inside them.
INPUT = [4, 0, 3, 1, 2, -4, 0, -2, -1, -3]
# Grid steps in rho: piecewise-linear loops (a divisor of 1/2), smooth loops (h and h/2).
STEP_MASING = 1 / 64
STEP_SMOOTH = 1 / 1024


def models():
    out = [(name, lugre.ZooModel(name)) for name in lugre.ZOO_MODELS]
    return out + [("lugre", lugre.LuGre())]


def net_area(u, y):
    """The hysteresis package's area of the curve (u, y)."""
    curve = hysteresis.SimpleCurve(np.column_stack([u, y]))
    curve.setArea()
    return float(curve.getNetArea())


def arc_grid(hl, loop, step):
    """rho over the loop's arc: every multiple of `step` from its start (an integer here), and
    the turning points inside (each period's copy)."""
    a, b = loop.start.rho, loop.end.rho
    n = int(round((b - a) / step))
    grid = a + step * np.arange(n + 1)
    grid[-1] = b
    turning = np.concatenate([hl.rho + k * hl.period for k in range(-1, 3)])
    return np.union1d(grid, turning[(turning > a) & (turning < b)])


def area_at(hl, loop, step):
    rho = arc_grid(hl, loop, step)
    return net_area(hl.u_at(rho), hl.y_at(rho)), rho


def piecewise_linear(name):
    return name in lugre.ZOO_MODELS and lugre.ZOO_MODELS[name]["closes_minor_loops"]


def compare(name, model):
    """Per loop: (kind, depth, work, area, difference, sampling-error estimate)."""
    hl = model.loop(INPUT)
    scale = max(abs(hl.y).max() * hl.period, 1.0)
    rows = []
    for loop in hl.loops:
        if piecewise_linear(name):
            area, rho = area_at(hl, loop, STEP_MASING)
            # Vertices only at multiples of 1/2: the force is linear between them.
            y = hl.y_at(rho)
            for k0, k1 in pieces(rho):
                seg_r, seg_y = rho[k0:k1 + 1], y[k0:k1 + 1]
                fit = np.polyval(np.polyfit(seg_r - seg_r[0], seg_y, 1), seg_r - seg_r[0])
                assert np.abs(fit - seg_y).max() <= 1e-12 * scale, (name, seg_r[0])
            # Both grids hold every vertex: they differ by rounding only.
            estimate = abs(area_at(hl, loop, 2 * STEP_MASING)[0] - area)
        else:
            coarse, _ = area_at(hl, loop, 2 * STEP_SMOOTH)
            area, _ = area_at(hl, loop, STEP_SMOOTH)
            estimate = abs(coarse - area) / 3
            extrapolated = (4 * area - coarse) / 3
            assert abs(extrapolated - loop.work) <= 0.03 * estimate + 1e-13 * scale, (
                name, loop.kind, loop.work, extrapolated, estimate)
        rows.append((loop.kind, loop.depth, loop.work, area, loop.work - area, estimate))
    return rows, scale


def pieces(rho):
    """Index ranges of `rho` between consecutive multiples of 1/2."""
    marks = np.flatnonzero(np.isclose(rho * 2, np.round(rho * 2), rtol=0, atol=1e-12))
    return list(zip(marks[:-1], marks[1:]))


@pytest.mark.parametrize("name,model", models(), ids=[n for n, _ in models()])
def test_every_loops_work_is_the_area_the_hysteresis_package_measures(name, model):
    assert version("hysteresis") == "2.0.5"
    rows, scale = compare(name, model)
    assert len(rows) == 5 and [r[1] for r in rows] == [0, 1, 2, 1, 2]
    for kind, depth, work, area, diff, estimate in rows:
        if piecewise_linear(name):
            # Exact trapezoids on the vertices: rounding only.
            assert abs(diff) <= 1e-12 * scale and estimate <= 1e-12 * scale, (name, kind, work, area)
        else:
            # Within the sampling error (the estimate (A_h - A_h/2) / 3, margin 1.5).
            assert abs(diff) <= 1.5 * estimate, (name, kind, work, area, estimate)
            assert estimate <= 1e-4 * scale, "the sampling is dense"


def main():
    print("| model | loop (depth) | work | hysteresis area | work - area | sampling error |")
    print("|---|---|---|---|---|---|")
    for name, model in models():
        rows, _ = compare(name, model)
        for kind, depth, work, area, diff, estimate in rows:
            print(f"| {name} | {kind} ({depth}) | {work:.15g} | {area:.15g} | {diff:.2e} | {estimate:.1e} |")


if __name__ == "__main__":
    sys.exit(main())
