"""The steady-state sweep section of bench/compare.py (`--only sweep`): lugre.sweep on the 50 x 50
grid of the issue (amplitudes 1e-7..1e-3 m over four decades, frequencies 0.1..100 Hz over
three, the Table I parameters of Canudas de Wit et al. 1995) against scipy reaching the same
accuracy by simulating each point to its steady state.

scipy's way is the reference script's (crates/lugre/tests/reference/sweep_reference.py, imported
here): solve_ivp Radau at rtol 1e-12 from z = 0, period after period with stops at the
reversals, until the state and the period's energy change by less than 1e-13, the energy per
cycle integrated as an extra state. Simulating all 2500 points that way takes hours, so scipy
runs a sample of points across the grid, and its grid time is the sample's mean time per point
times 2500 (said so in the row). The agreement is the largest relative difference between the
two energies per cycle over the sample.

Runs standalone too, in an environment with lugre, numpy and scipy:

    python3 bench/compare_sweep.py
"""

from __future__ import annotations

import importlib.util
import math
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
REFERENCE = os.path.join(ROOT, "crates", "lugre", "tests", "reference", "sweep_reference.py")

AMPLITUDES = "1e-7:1e-3:50"
FREQUENCIES = "0.1:100:50"
POINTS = 50 * 50
# The sample scipy runs: across the grid's amplitudes and frequencies (the smallest amplitudes
# take hundreds of periods to settle: the contraction per period is exp(-4 sigma0 A / g)).
SAMPLE = [(1e-6, 0.1), (1e-5, 1.0), (1e-4, 10.0), (1e-3, 100.0), (1e-3, 0.1)]


def _reference():
    spec = importlib.util.spec_from_file_location("sweep_reference", REFERENCE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def sweep_rows(rows: list, summary: list, log, fmt_time, fmt_ratio) -> None:
    """Appends (case, method, time, agreement, ratio) rows (strings) for the grid."""
    import lugre

    ref = _reference()
    model = lugre.LuGre(**ref.CANUDAS)
    case = "sweep: 50 x 50 grid, canudas1995"
    best = math.inf
    for _ in range(5):
        t0 = time.perf_counter()
        grid = lugre.sweep(model, amplitudes=AMPLITUDES, frequencies=FREQUENCIES)
        best = min(best, time.perf_counter() - t0)
    log(f"sweep: lugre {best:.3f} s for {POINTS} points")
    rows.append((case, "lugre.sweep (all cores, tol 1e-12)", fmt_time(best), "reference", fmt_ratio(1.0)))
    spent, worst = 0.0, 0.0
    for a, f in SAMPLE:
        t0 = time.perf_counter()
        d_scipy, _, periods = ref.steady(ref.CANUDAS, a, f, "Radau")
        dt = time.perf_counter() - t0
        spent += dt
        d_lugre = lugre.sweep(model, amplitudes=[a], frequencies=[f])["dissipation"][0]
        worst = max(worst, abs(d_scipy / d_lugre - 1.0))
        log(f"sweep: scipy A={a:g} f={f:g}: {dt:.1f} s, {periods} periods, rel {d_scipy / d_lugre - 1:.1e}")
    estimate = spent / len(SAMPLE) * POINTS
    rows.append((case, f"scipy Radau rtol 1e-12 to steady state (mean of {len(SAMPLE)} points x {POINTS})",
                 fmt_time(estimate), f"max rel. diff. {worst:.1e}", fmt_ratio(estimate / best)))
    summary.append(f"sweep: lugre.sweep runs the 50 x 50 grid in {fmt_time(best)}; scipy simulating to "
                   f"steady state would take about {fmt_time(estimate)} ({estimate / best:.0f}x), "
                   f"agreeing to {worst:.1e} on the {len(SAMPLE)} points it ran.")


def main() -> None:
    rows: list = []
    summary: list = []

    def fmt_time(s):
        return f"{s * 1e3:.1f} ms" if s < 1 else f"{s:.2f} s" if s < 100 else f"{s / 60:.0f} min"

    def fmt_ratio(r):
        return f"{r:.0f}x" if r >= 10 else f"{r:.2f}x"

    sweep_rows(rows, summary, lambda m: print(m, file=sys.stderr, flush=True), fmt_time, fmt_ratio)
    for r in rows:
        print(" | ".join(r))
    for s in summary:
        print("* " + s)


if __name__ == "__main__":
    main()
