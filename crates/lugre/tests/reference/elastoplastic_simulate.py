#!/usr/bin/env python3
"""Independent reference values for `ZooModel::simulate` of the elasto-plastic model of Dupont,
Hayward, Armstrong and Altpeter (IEEE TAC 47(5), 2002) at finite rate: the force at each sample of
an input linear in time between samples, from rest.  Nothing here uses the crate.

Made with (from the repository root; scipy 1.17.1):

    python3 crates/lugre/tests/reference/elastoplastic_simulate.py

Model (SI units), on each interval v = du/dt constant, w = sgn(v) z, z_ss = g(v) / sigma0:
    g(v)  = Fc + (Fs - Fc) exp(-|v/vs|^beta)
    alpha = 0 (w <= zba),  sin^2(pi/2 (w - zba)/(z_ss - zba)) (zba < w < z_ss),  1 (w >= z_ss)
    z'    = v (1 - alpha w / z_ss)
    F     = sigma0 z + sigma1 z' + sigma2 v     (v of the interval after the sample; the last
                                                 sample: the interval before)

Each interval is integrated in time by solve_ivp, split at the blend's kinks (w = zba, w = z_ss:
terminal events, restarted from the event's state).  Radau and DOP853 at rtol 1e-12 (atol 1e-14
of z_ss); the printed values are Radau's, with the largest relative Radau-DOP853 difference.
"""
import math

import numpy as np
from scipy.integrate import solve_ivp

CASES = {
    # sigma0 = 1: the zoo's defaults (fc = 1, fs = 2, zba = 0.5) with rates on their scale.
    "UNIT": dict(s0=1.0, s1=1.0, s2=0.4, fc=1.0, fs=2.0, vs=0.5, beta=2.0, zba=0.5, amp=3.0, speed=0.4),
    # sigma0 = 1e5: Table I of Canudas de Wit et al. (1995), zba = Fc / sigma0 / 2.
    "TABLE1": dict(s0=1e5, s1=math.sqrt(1e5), s2=0.4, fc=1.0, fs=1.5, vs=1e-3, beta=2.0, zba=0.5e-5,
                   amp=2e-4, speed=1e-3),
}


def samples(c):
    """An irregularly sampled, decaying two-tone input with reversals of every size."""
    n = 48
    k = np.arange(n)
    t = (k + 0.35 * np.sin(1.7 * k)) * 1.0
    t[0] = 0.0
    t = t * c["amp"] / c["speed"] / 6.0
    phase = 2 * math.pi * k / 16
    u = c["amp"] * (np.sin(phase) * (1 - k / (1.5 * n)) + 0.3 * np.sin(3.1 * phase + 0.4))
    u[0] = 0.0
    return t, u


def solve(c, t, u, method):
    s0, zba = c["s0"], c["zba"]

    def g(v):
        return c["fc"] + (c["fs"] - c["fc"]) * math.exp(-abs(v / c["vs"]) ** c["beta"])

    def alpha(w, zss):
        if w <= zba:
            return 0.0
        if w >= zss:
            return 1.0
        return math.sin(0.5 * math.pi * (w - zba) / (zss - zba)) ** 2

    def zdot(v, z):
        if v == 0.0:
            return 0.0
        zss = g(v) / s0
        w = math.copysign(1.0, v) * z
        return v * (1.0 - alpha(w, zss) * w / zss)

    def force(v, z):
        return s0 * z + c["s1"] * zdot(v, z) + c["s2"] * v

    n = len(t)
    vel = [(u[i + 1] - u[i]) / (t[i + 1] - t[i]) for i in range(n - 1)]
    z = 0.0
    out = [force(vel[0], z)]
    for i in range(n - 1):
        v = vel[i]
        zss = g(v) / s0
        s = math.copysign(1.0, v)
        ta, tb = t[i], t[i + 1]
        while ta < tb:
            def e1(_, y):
                return s * y[0] - zba
            def e2(_, y):
                return s * y[0] - zss
            e1.terminal = e2.terminal = True
            # A kink the state sits on is not an event of this piece.
            evs = [e for e in (e1, e2) if abs(e(0, [z])) > 1e-13 * zss]
            sol = solve_ivp(lambda _, y: [zdot(v, y[0])], (ta, tb), [z], method=method,
                            rtol=1e-12, atol=1e-14 * zss, events=evs or None)
            z = sol.y[0, -1]
            ta = sol.t[-1]
            if sol.status != 1:
                break
        out.append(force(vel[min(i + 1, n - 2)], z))
    return np.array(out)


def main():
    for name, c in CASES.items():
        t, u = samples(c)
        radau = solve(c, t, u, "Radau")
        dop = solve(c, t, u, "DOP853")
        scale = np.max(np.abs(radau))
        print(f"// {name}: largest |Radau - DOP853| / max|F| = {np.max(np.abs(radau - dop)) / scale:.1e}")
        print(f"const {name}: &[(f64, f64, f64)] = &[")
        for a, b, f in zip(t, u, radau):
            print(f"    ({float(a)!r}, {float(b)!r}, {float(f)!r}),")
        print("];")


if __name__ == "__main__":
    main()
