#!/usr/bin/env python3
"""Reference energies for `lugre::cycles` (paste the output into ../tests.rs).

    /tmp/rfvenv/bin/pip install rainflow==3.2.0 mpmath
    /tmp/rfvenv/bin/python make_energy_reference.py

Independent of the crate: cycles from the `rainflow` package; the closure by scanning the
samples for the first return to the start value (linear between samples); y* from eq. 6 solved
exactly on each straight piece at mp.dps = 50,
    y(rho) = s g0 + (y_k - s g0) exp(-a (rho - rho_k)),
and the energies over each full cycle's arc by mp.quad on every piece:
    W = integral y du,   D = (1/g0) integral y^2 drho,   dV = (y_C^2 - y_A^2) / (2 sigma0).
Self-check: W - dV - D == 0 to 1e-40 for every cycle. Inputs are the exact binary values of
the f64 literals the test passes.
"""

import rainflow
from mpmath import mp, mpf, exp, quad, nstr, fabs

mp.dps = 50

CASES = {
    # name: (sigma0, g0, x0, history)
    "PAPER": (6.0, 2.0, 0.05,
              [0.0, 1.0, 0.2, 0.8, 0.5, 1.5, -0.3, 0.6, 0.1, 1.2, -1.0, 0.4, 0.25, 0.7]),
    # Canudas de Wit 1995 stiffness (sigma0 = 1e5 N/m, g0 = Fs = 1.5 N), micrometre motions.
    "STIFF": (1e5, 1.5, 0.0,
              [0.0, 2e-5, 5e-6, 1.5e-5, 1e-5, 3e-5, -1e-5, 1.2e-5, 2e-6, 2.5e-5, -4e-5, 1e-6]),
    # Loops 1e-5 wide near y* = 0.56 g0: W is 1e-6 of dV and D, which cancel.
    "TINY": (1.0, 1.5, 0.0, [0.0, 0.7, 0.69999, 0.70001, 0.69998, 0.700005, 0.69, 0.9]),
}


def lit(x):
    s = nstr(mpf(x), 20)
    if "." not in s and "e" not in s:
        s += ".0"
    return s


def run(name, sigma0, g0, x0, h):
    sigma0, g0 = mpf(sigma0), mpf(g0)
    a = sigma0 / g0
    u = [mpf(v) for v in h]

    def piece(yk, s, l):
        return s * g0 + (yk - s * g0) * exp(-a * l)

    y = [sigma0 * mpf(x0)]
    for k in range(1, len(u)):
        d = u[k] - u[k - 1]
        s = 1 if d >= 0 else -1
        y.append(piece(y[-1], s, fabs(d)))

    def integrals(k0, u_from, k1, u_to):
        """W and D from u_from on step (k0 - 1 -> k0) ... to u_to on step (k1 - 1 -> k1).
        Steps are walked from sample k0 - 1 with its y."""
        W = mpf(0)
        D = mpf(0)
        for k in range(k0, k1 + 1):
            d = u[k] - u[k - 1]
            s = 1 if d >= 0 else -1
            lo = fabs(u_from - u[k - 1]) if k == k0 else mpf(0)
            hi = fabs(u_to - u[k - 1]) if k == k1 else fabs(d)
            if hi <= lo:
                continue
            f = lambda l: piece(y[k - 1], s, l)
            W += s * quad(f, [lo, hi])
            D += quad(lambda l: f(l) ** 2, [lo, hi]) / g0
        return W, D

    rows = []
    for rng, mean, count, i0, i1 in rainflow.extract_cycles(h):
        if count != 1.0:
            continue
        uA, uB = u[i0], u[i1]
        up = uA < uB
        c = next(k for k in range(i1 + 1, len(u)) if (u[k] <= uA if up else u[k] >= uA))
        frac = (uA - u[c - 1]) / (u[c] - u[c - 1])
        dC = u[c] - u[c - 1]
        sC = 1 if dC >= 0 else -1
        yC = piece(y[c - 1], sC, fabs(uA - u[c - 1]))
        # The arc from A (sample i0) to C: steps i0+1 .. c, the last one up to u_A.
        W, D = integrals(i0 + 1, u[i0], c, uA)
        dV = (yC ** 2 - y[i0] ** 2) / (2 * sigma0)
        assert fabs(W - dV - D) < mpf(10) ** -40 * (1 + fabs(W)), (W, dV, D)
        rows.append((i0, i1, c, c - 1 + frac, W, dV, D, yC - y[i0], y[i0], yC))

    print("#[rustfmt::skip]")
    print(f"const {name}: [Row; {len(rows)}] = [")
    for r in rows:
        print("    (" + ", ".join(str(v) if isinstance(v, int) else lit(v) for v in r) + "),")
    print("];")
    print("#[rustfmt::skip]")
    print(f"const {name}_Y: [f64; {len(y)}] = [" + ", ".join(lit(v) for v in y) + "];")


for name, (s0, g0, x0, h) in CASES.items():
    run(name, s0, g0, x0, h)
