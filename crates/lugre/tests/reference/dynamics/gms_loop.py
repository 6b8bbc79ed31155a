#!/usr/bin/env python3
"""Independent reference for a friction-displacement loop of GMS friction under a prescribed
velocity (crates/lugre/tests/dynamics_gms.rs, `gms_loop_work_matches_scipy`): the model and
its element equations are gms_dynamics.py's (Table I scale); the velocity is a triangle wave's,
+-1e-5 m/s with linear ramps of 0.1 s centred on the reversals at 2, 6 and 10 s (knots 0,
1.95, 2.05, 5.95, 6.05, 9.95, 10.05 s), so x goes 0 -> A (2 s) -> -A (6 s) -> A (10 s),
A = 1.975e-5 m. The loop is x from 2 s to 10 s; its work integral F dx = integral F v dt is a
state of the integration (exact to the tolerance), and also the trapezoid rule on the crate's
output grid (t_j = 10 j / 20000) from the dense output, to show the quadrature's error.

Made with (from the repository root):

    python3 -m venv /tmp/venv-gms && /tmp/venv-gms/bin/pip install numpy scipy
    /tmp/venv-gms/bin/python crates/lugre/tests/reference/dynamics/gms_loop.py
"""
import os
import sys

import numpy as np
from scipy.integrate import solve_ivp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gms_dynamics import K_EL, element_rates, friction, mode_events, switch_modes  # noqa: E402

KNOTS = np.array([0.0, 1.95, 2.05, 5.95, 6.05, 9.95, 10.05])
V0 = 1e-5
VEL = np.array([V0, V0, -V0, -V0, V0, V0, -V0])


def v_of(t):
    return float(np.interp(t, KNOTS, VEL))


def run(method, t0, t1, grid):
    """From rest at 0 to t1: the state (x, F_i, W) with W = integral_t0^t F v dt, and the
    friction on `grid` (times in [0, t1]) from the dense output."""
    y = np.zeros(2 + len(K_EL))  # x, F_i..., W
    mode = np.zeros(len(K_EL))
    stops = sorted(set([t for t in KNOTS if 0 < t < t1] + [t0, t1]))
    t = 0.0
    out = {}
    for stop in stops:
        while t < stop:
            def rhs(tt, yy):
                v = v_of(tt)
                F = yy[1:-1]
                dF = element_rates(v, F, mode)
                fr = friction(v, F, mode)
                return np.concatenate([[v], dF, [fr * v if tt >= t0 else 0.0]])

            events = mode_events(mode, lambda tt, yy: v_of(tt), lambda yy, i: yy[1 + i])
            sol = solve_ivp(rhs, (t, stop), y, method=method, rtol=1e-12,
                            atol=[1e-18] + [1e-14] * len(K_EL) + [1e-20],
                            events=[e[3] for e in events] or None, dense_output=True)
            for tg in grid:
                if sol.t[0] <= tg <= sol.t[-1] and tg not in out:
                    yy = sol.sol(tg)
                    out[tg] = (yy[0], friction(v_of(tg), yy[1:-1], mode))
            y = sol.y[:, -1].copy()
            t = sol.t[-1]
            if sol.status == 1:
                switch_modes(mode, events, sol, v_of(t))
    return y, out


if __name__ == "__main__":
    grid = [10.0 * j / 20000 for j in range(4000, 20001)]
    res = {}
    for method in ("Radau", "DOP853"):
        y, out = run(method, 2.0, 10.0, grid)
        xs = np.array([out[t][0] for t in grid])
        fs = np.array([out[t][1] for t in grid])
        trap = float(np.sum(0.5 * (fs[1:] + fs[:-1]) * np.diff(xs)))
        v_end = 0.5 * sum(F * F / k for F, k in zip(y[1:-1], K_EL))
        res[method] = (y[-1], trap, v_end)
        print(f"{method}: work exact {float(y[-1])!r}, trapezoid on the grid {trap!r}, x(10) {float(y[0])!r}, V(10) {float(v_end)!r}")
    print(f"Radau - DOP853: exact {abs(res['Radau'][0] - res['DOP853'][0]) / res['Radau'][0]:.1e}, "
          f"trapezoid {abs(res['Radau'][1] - res['DOP853'][1]) / res['Radau'][1]:.1e} relative")
