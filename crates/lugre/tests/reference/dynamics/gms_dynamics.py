#!/usr/bin/env python3
"""Independent reference values for GMS friction (Al-Bender, Lampaert and Swevers, IEEE TAC
50(11), 2005) on a mass, in two experiments of Canudas de Wit et al. (1995) on the Table I scale:
stick-slip (Fig. 6, a spring of 2 N/m pulled at 0.1 m/s) and break-away (Fig. 4, F = r t).
Nothing here uses the crate; each element is a state of its own (the crate aggregates them).

Made with (from the repository root):

    python3 -m venv /tmp/venv-gms && /tmp/venv-gms/bin/pip install numpy scipy
    /tmp/venv-gms/bin/python crates/lugre/tests/reference/dynamics/gms_dynamics.py

Model (SI units): elements k_i = 1e5 [1,1,1,1]/4 N/m, f_i = 1.5 [1,3,5,7]/16 N (F_s = 1.5 N),
alpha_i = f_i / F_s, g(v) = Fc + (F_s - Fc) exp(-(v/vs)^2), Fc = 1, vs = 1e-3, C = 10 N/s,
sigma1 = sqrt(1e5), sigma2 = 0.4, M = 1 kg:
    sticking:  F_i' = k_i v                       until sgn(v) F_i = alpha_i g(v)
    slipping:  F_i' = s C (alpha_i - F_i / (s g(v)))   (s its direction) until v reverses
    F = sum F_i + (sigma1 / K) sum F_i' + sigma2 v,   M x'' = drive - F

Each piece between mode changes is one solve_ivp call; the mode changes are terminal events
(a sticking element at its level in the direction of v; v through 0 against the slipping
elements), the integration restarting from the event's state. Output times are integration
ends. Radau and DOP853 at rtol 1e-12, tiny atol; the printed values are Radau's, with the
largest Radau-DOP853 difference.
"""
import math

import numpy as np
from scipy.integrate import solve_ivp

K_EL = np.array([1e5 / 4] * 4)
F_EL = 1.5 * np.array([1.0, 3.0, 5.0, 7.0]) / 16
FS = F_EL.sum()
ALPHA = F_EL / FS
K = K_EL.sum()
FC, VS, C = 1.0, 1e-3, 10.0
S1, S2 = math.sqrt(1e5), 0.4
M = 1.0


def g(v):
    return FC + (FS - FC) * math.exp(-((v / VS) ** 2))


def element_rates(v, F, mode):
    out = np.empty(len(F))
    for i in range(len(F)):
        if mode[i] == 0:
            out[i] = K_EL[i] * v
        else:
            s = mode[i]
            out[i] = s * C * (ALPHA[i] - F[i] / (s * g(v)))
    return out


def friction(v, F, mode):
    return F.sum() + S1 / K * element_rates(v, F, mode).sum() + S2 * v


def mode_events(mode, velocity, force):
    """The terminal events of a piece in `mode` (0 sticking, else the direction of slipping):
    a sticking element at its level in the direction of v, v through 0 against the slipping
    elements; `velocity(t, y)` and `force(y, i)` read the state."""
    events = []
    for i in range(len(K_EL)):
        if mode[i] == 0:
            for s in (1.0, -1.0):
                ev = lambda tt, yy, i=i, s=s: ALPHA[i] * g(velocity(tt, yy)) - s * force(yy, i)
                ev.terminal, ev.direction = True, -1
                events.append(("onset", i, s, ev))
    slipping = [m for m in mode if m != 0]
    if slipping:
        d = slipping[0]
        ev = lambda tt, yy, d=d: d * velocity(tt, yy)
        ev.terminal, ev.direction = True, -1
        events.append(("reversal", None, d, ev))
    return events


def switch_modes(mode, events, sol, v):
    """The modes after the events `sol` stopped at, the velocity there `v`."""
    for (kind, i, s, _), te in zip(events, sol.t_events):
        if not len(te):
            continue
        if kind == "reversal":
            mode[:] = 0.0
        elif np.sign(v) == s:
            mode[i] = s


def run(drive, t_end, times, method):
    y = np.zeros(2 + len(K_EL))  # x, v, F_i
    mode = np.zeros(len(K_EL))
    t = 0.0
    out = []
    for stop in times:
        while t < stop:
            def rhs(tt, yy):
                x, v, F = yy[0], yy[1], yy[2:]
                dF = element_rates(v, F, mode)
                fr = F.sum() + S1 / K * dF.sum() + S2 * v
                return np.concatenate([[v, (drive(tt, x) - fr) / M], dF])

            events = mode_events(mode, lambda tt, yy: yy[1], lambda yy, i: yy[2 + i])
            sol = solve_ivp(rhs, (t, stop), y, method=method, rtol=1e-12,
                            atol=[1e-16, 1e-14] + [1e-12] * len(K_EL),
                            events=[e[3] for e in events] or None)
            y = sol.y[:, -1].copy()
            t = sol.t[-1]
            if sol.status == 1:
                switch_modes(mode, events, sol, y[1])
                if t >= stop:
                    break
        out.append((t, y[0], y[1], friction(y[1], y[2:], mode)))
    return np.array(out)


def report(name, drive, t_end, times):
    radau = run(drive, t_end, times, "Radau")
    dop = run(drive, t_end, times, "DOP853")
    for col, what in ((1, "x"), (2, "v"), (3, "friction")):
        scale = np.abs(radau[:, col]).max()
        print(f"// {name}: {what} Radau - DOP853 = {np.abs(radau[:, col] - dop[:, col]).max() / scale:.1e} of its largest")
    print(f"{name}_T = {[float(x) for x in radau[:, 0]]!r}")
    print(f"{name}_X = {[float(x) for x in radau[:, 1]]!r}")
    print(f"{name}_V = {[float(x) for x in radau[:, 2]]!r}")
    print(f"{name}_F = {[float(x) for x in radau[:, 3]]!r}")


if __name__ == "__main__":
    report("stick_slip", lambda t, x: 2.0 * (0.1 * t - x), 10.0,
           [0.5 * k for k in range(1, 21)])
    report("breakaway", lambda t, x: 10.0 * t, 0.2,
           [0.01 * k for k in range(1, 21)])
