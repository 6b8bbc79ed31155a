#!/usr/bin/env python3
"""Independent reference values for the elasto-plastic friction of Dupont, Hayward, Armstrong
and Altpeter (IEEE TAC 47(5), 2002) at finite rate, in two experiments of Canudas de Wit et al.
(1995) with their Table I parameters: the frictional lag (Fig. 3, a prescribed velocity) and
stick-slip (Fig. 6, a spring pulled at 0.1 m/s).  Nothing here uses the crate.

Made with (from the repository root):

    python3 -m venv /tmp/venv-ep && /tmp/venv-ep/bin/pip install numpy scipy
    /tmp/venv-ep/bin/python crates/lugre/tests/reference/dynamics/elastoplastic_dynamics.py

Model (SI units), w = sgn(v) z, z_ss(v) = g(v) / sigma0:
    g(v)  = Fc + (Fs - Fc) exp(-(v/vs)^2)
    alpha = 0 (w <= zba),  sin^2(pi/2 (w - zba)/(z_ss - zba)) (zba < w < z_ss),  1 (w >= z_ss)
    z'    = v (1 - alpha w / z_ss)
    F     = sigma0 z + sigma1 z' + sigma2 v
    sigma0 = 1e5, sigma1 = sqrt(1e5), sigma2 = 0.4, Fc = 1, Fs = 1.5, vs = 1e-3, zba = 0.5e-5.

Each integration is split where the right-hand side is not smooth: at v = 0 (the sign of v is
frozen in between, |v| -> s v), at w = zba and at w = z_ss (the blend is only C^1 there): all are
terminal events of solve_ivp, after which the integration restarts from the event's state (a
kink met again within 1e-9 s, the state running along it, is not split on the next piece).
Output times are integration ends (no interpolant).  Two methods (Radau and DOP853) at rtol
1e-12 and tiny atol; the printed values are Radau's, with the largest Radau-DOP853 difference.
"""
import math

import numpy as np
from scipy.integrate import solve_ivp

S0, S1, S2 = 1e5, math.sqrt(1e5), 0.4
FC, FS, VS = 1.0, 1.5, 1e-3
ZBA = 0.5e-5


def g(v):
    return FC + (FS - FC) * math.exp(-(v / VS) ** 2)


def alpha(w, zss):
    if w <= ZBA:
        return 0.0
    if w >= zss:
        return 1.0
    return math.sin(0.5 * math.pi * (w - ZBA) / (zss - ZBA)) ** 2


def zdot(v, z, s):
    sign = s if s != 0.0 else math.copysign(1.0, v) if v != 0.0 else 0.0
    zss = g(v) / S0
    w = sign * z
    return v * (1.0 - alpha(w, zss) * w / zss)


def friction(v, z, s):
    return S0 * z + S1 * zdot(v, z, s) + S2 * v


def events_for(zfun, vfun, s, muted):
    """Terminal events: v = 0 (with a frozen sign), w = zba, w = z_ss."""
    def ev_v(t, y):
        return vfun(t, y)

    def ev_zba(t, y):
        sign = s if s != 0.0 else 1.0
        return sign * zfun(y) - ZBA

    def ev_zss(t, y):
        sign = s if s != 0.0 else 1.0
        return sign * zfun(y) - g(vfun(t, y)) / S0

    def never(t, y):
        return 1.0

    evs = [ev_zba, ev_zss, ev_v if s != 0.0 else never]
    evs = [never if i in muted else e for i, e in enumerate(evs)]
    for e in evs:
        e.terminal = True
    return evs


def integrate(rhs, y0, bounds, zfun, vfun, sign_at, method, rtol, atol, vindex=1):
    """Integrates from bounds[0] through each later bound, splitting at the events."""
    t, y = bounds[0], np.array(y0, float)
    out, muted = [], set()
    for tb in bounds[1:]:
        while t < tb:
            s = sign_at(t, y)
            sol = solve_ivp(lambda tt, yy: rhs(tt, yy, s), (t, tb), y, method=method,
                            rtol=rtol, atol=atol, events=events_for(zfun, vfun, s, muted))
            muted = set()
            if sol.status == 1:
                hits = [(e[0], i) for i, e in enumerate(sol.t_events) if len(e)]
                te, i = min(hits)
                if i < 2 and te - t < 1e-9:
                    # The same kink again at once: the state runs along w = zba or w = z_ss
                    # (tangent to it); the next piece goes on without splitting there (the
                    # blend is C^1: the error control copes).
                    muted = {i}
                t, y = te, np.array(sol.y_events[i][0])
                if i == 2:
                    y[vindex] = 0.0  # v = 0 there; the sign goes on from the acceleration
                # Step just past the event's root so that its function leaves 0.
                s_next = sign_at(t, y)
                t_next = min(t + 1e-14 * max(1.0, abs(t)), tb)
                sol2 = solve_ivp(lambda tt, yy: rhs(tt, yy, s_next), (t, t_next), y,
                                 method="DOP853", rtol=rtol, atol=atol)
                t, y = t_next, sol2.y[:, -1]
            else:
                t, y = tb, sol.y[:, -1]
        out.append((t, y.copy()))
    return out


def lag(method, rtol):
    """Fig. 3: v = 1e-3 (cos 10 t + 1.5) > 0; state z; three periods."""
    w = 10.0

    def vel(t):
        return 1e-3 * (math.cos(w * t) + 1.5)

    rhs = lambda t, y, s: [zdot(vel(t), y[0], 1.0)]
    period = 2 * math.pi / w
    times = [0.0] + [k * period / 8 for k in range(1, 25)]
    res = integrate(rhs, [0.0], times, lambda y: y[0], lambda t, y: vel(t),
                    lambda t, y: 1.0, method, rtol, [1e-20])
    return [(t, y[0], friction(vel(t), y[0], 1.0)) for t, y in res]


def stick_slip(method, rtol):
    """Fig. 6: spring k = 2 N/m pulled at 0.1 m/s, M = 1 kg; state (x, v, z); 20 s."""
    k, pull = 2.0, 0.1

    def sign_at(t, y):
        if y[1] != 0.0:
            return math.copysign(1.0, y[1])
        a = k * (pull * t - y[0]) - friction(0.0, y[2], 0.0)
        # A mass ringing down (|v'| tiny at v = 0): the sign is no longer frozen.
        return 0.0 if abs(a) < 1e-8 else math.copysign(1.0, a)

    def rhs(t, y, s):
        x, v, z = y
        dz = zdot(v, z, s)
        f = S0 * z + S1 * dz + S2 * v
        return [v, k * (pull * t - x) - f, dz]

    times = [0.0] + [float(t) for t in range(1, 21)]
    res = integrate(rhs, [0.0, 0.0, 0.0], times, lambda y: y[2], lambda t, y: y[1],
                    sign_at, method, rtol, [1e-14, 1e-15, 1e-18])
    return [(t, y[0], y[1], y[2], friction(y[1], y[2], sign_at(t, y))) for t, y in res]


def main():
    for name, fn in [("lag", lag), ("stick-slip", stick_slip)]:
        ref = fn("Radau", 1e-12)
        other = fn("DOP853", 1e-12)
        diff = max(abs(a - b) for ra, rb in zip(ref, other) for a, b in zip(ra[1:], rb[1:]))
        print(f"# {name}: Radau rtol 1e-12 (DOP853 rtol 1e-12 differs by at most {diff:.2e})")
        for row in ref:
            print("(" + ", ".join(repr(float(v)) for v in row) + "),")


if __name__ == "__main__":
    main()
