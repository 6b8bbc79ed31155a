"""Reference energies per cycle for `lugre::sweep`, computed independently of the crate.

The LuGre model under u = A sin(2 pi f t) is simulated from z(0) = 0 with scipy's solve_ivp
(Radau, rtol = 1e-12, and DOP853 at the same tolerance where the problem is not stiff), period
after period, until the state at the period's start and the period's energy change by less than
1e-13 (relative) or 1000 periods have run. The integration stops at every reversal (where |u'|
has a kink). Over the last period the energy is integrated as extra states:

    D' = sigma0 r z^2 + sigma1 z' u' + sigma2 u'^2     (dissipation rate, r = sigma0 |u'| / g)
    W' = F u',  F = sigma0 z + sigma1 z' + sigma2 u'    (work)

with g(v) = Fc + (Fs - Fc) exp(-|v / vs|^beta). On the periodic orbit W = D; the script prints
both and their relative difference, and the Rust table takes D.

Run once (scipy 1.17.1, numpy; a few minutes):

    python3 crates/lugre/tests/reference/sweep_reference.py

and paste the printed table into crates/lugre/tests/sweep_reference.rs.
"""

import math
import sys

import numpy as np
from scipy.integrate import solve_ivp

RTOL = 1e-12
CONVERGED = 1e-13
MAX_PERIODS = 1000

PAPER = dict(sigma0=1.0, sigma1=1.0, sigma2=0.0, fc=1.0, fs=2.0, vs=1.0, beta=1.0)
CANUDAS = dict(sigma0=1e5, sigma1=math.sqrt(1e5), sigma2=0.4, fc=1.0, fs=1.5, vs=1e-3, beta=2.0)

# (label, parameters, amplitude, frequency): rates from quasi-static to far above vs, sigma0
# from 1 to 1e8.
CASES = [
    ("paper", PAPER, 0.5, 1e-3),
    ("paper", PAPER, 0.5, 0.1),
    ("paper", PAPER, 2.0, 1.0),
    ("paper sigma0=1e4", dict(PAPER, sigma0=1e4), 1e-3, 0.1),
    ("paper sigma0=1e8", dict(PAPER, sigma0=1e8), 1e-6, 1.0),
    ("paper sigma0=1e8", dict(PAPER, sigma0=1e8), 1e-3, 0.01),
    ("canudas1995", CANUDAS, 1e-6, 0.1),
    ("canudas1995", CANUDAS, 1e-5, 1.0),
    ("canudas1995", CANUDAS, 1e-4, 0.1),
    ("canudas1995", CANUDAS, 1e-4, 10.0),
    ("canudas1995", CANUDAS, 1e-3, 1.0),
    ("canudas1995", CANUDAS, 1e-3, 100.0),
    ("canudas1995 sigma0=1e8", dict(CANUDAS, sigma0=1e8), 1e-4, 1.0),
]


def make_rhs(p, a, w):
    s0, s1, s2 = p["sigma0"], p["sigma1"], p["sigma2"]
    fc, fs, vs, beta = p["fc"], p["fs"], p["vs"], p["beta"]

    def g(v):
        return fc + (fs - fc) * math.exp(-abs(v / vs) ** beta)

    def rhs(t, y):
        z = y[0]
        v = a * w * math.cos(w * t)
        r = s0 * abs(v) / g(v)
        dz = v - r * z
        force = s0 * z + s1 * dz + s2 * v
        return [dz, s0 * r * z * z + s1 * dz * v + s2 * v * v, force * v]

    def jac(t, y):
        z = y[0]
        v = a * w * math.cos(w * t)
        r = s0 * abs(v) / g(v)
        return [
            [-r, 0.0, 0.0],
            [2 * s0 * r * z - s1 * r * v, 0.0, 0.0],
            [(s0 - s1 * r) * v, 0.0, 0.0],
        ]

    return rhs, jac


def one_period(rhs, jac, z0, t0, period, method):
    """z after one period from (t0, z0), and the period's D and W; stops at the reversals."""
    stops = [t0, t0 + period / 4, t0 + 3 * period / 4, t0 + period]
    y = [z0, 0.0, 0.0]
    for lo, hi in zip(stops, stops[1:]):
        kw = dict(jac=jac) if method == "Radau" else {}
        sol = solve_ivp(rhs, (lo, hi), y, method=method, rtol=RTOL,
                        atol=[1e-22, 1e-30, 1e-30], **kw)
        if not sol.success:
            raise RuntimeError(sol.message)
        y = sol.y[:, -1]
    return y[0], y[1], y[2]


def steady(p, a, f, method):
    rhs, jac = make_rhs(p, a, 2 * math.pi * f)
    period = 1.0 / f
    z, d_prev = 0.0, None
    for k in range(MAX_PERIODS):
        z_end, d, wk = one_period(rhs, jac, z, 0.0, period, method)
        done = abs(z_end - z) <= CONVERGED * max(abs(z_end), 1e-300)
        done = done and d_prev is not None and abs(d - d_prev) <= CONVERGED * abs(d)
        z, d_prev = z_end, d
        if done:
            return d, wk, k + 1
    return d_prev, wk, MAX_PERIODS


def main():
    print("// label, sigma0, amplitude, frequency, dissipation (Radau)", file=sys.stderr)
    for label, p, a, f in CASES:
        d, wk, periods = steady(p, a, f, "Radau")
        line = f'    ("{label}", {p["sigma0"]!r}, {a!r}, {f!r}, {float(d)!r}),'
        note = f"// W/D-1 = {wk / d - 1:.1e}, {periods} periods"
        if p["sigma0"] <= 1e4 and a * p["sigma0"] / p["fs"] < 1e3:
            d8, _, _ = steady(p, a, f, "DOP853")
            note += f", DOP853 rel {d8 / d - 1:.1e}"
        print(line, note, flush=True)


if __name__ == "__main__":
    main()
