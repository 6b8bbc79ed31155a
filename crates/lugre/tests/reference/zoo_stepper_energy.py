#!/usr/bin/env python3
"""Independent reference energies for `ZooStepper` (crates/lugre/src/zoo/stepper.rs): the work
W = integral F du = integral F v dt of the input from rest and the stored energy V at each sample
of an input linear in time between samples, for GMS (the maxwell-slip entry at finite rate) and
the elasto-plastic model at finite rate.  Nothing here uses the crate: each interval of constant
velocity is integrated in time by scipy's solve_ivp with the work as one more state, W' = F v,
the mode changes (GMS: stick to slip; elasto-plastic: the blend's kinks w = zba, w = z_ss) as
terminal events.  Radau and DOP853 at rtol 1e-12; the printed values are Radau's, with the
largest Radau - DOP853 difference relative to the largest |W|.

Made with (from the repository root; scipy 1.17.1):

    python3 crates/lugre/tests/reference/zoo_stepper_energy.py

GMS (Al-Bender, Lampaert and Swevers 2005), K = sum k_i, Fs = sum f_i, alpha_i = f_i / Fs,
g(v) = fc + (Fs - fc) exp(-|v/vs|^beta), s = sgn v:
    sticking  F_i' = k_i v   until s F_i = alpha_i g(v);  slipping  F_i' = (C/g)(s alpha_i g - F_i)
    F = sum F_i + (sigma1/K) sum F_i' + sigma2 v,   V = sum F_i^2 / (2 k_i)
Elasto-plastic (Dupont et al. 2002), w = s z, z_ss = g(v)/sigma0, g with fc, fs:
    z' = v (1 - alpha(w) w / z_ss),   F = sigma0 z + sigma1 z' + sigma2 v,   V = sigma0 z^2 / 2
"""
import math

import numpy as np
from scipy.integrate import solve_ivp

RTOL = 1e-12


def samples(seed, n):
    """n intervals of random lengths and random moves (reversals of every size)."""
    rng = np.random.default_rng(seed)
    t = np.concatenate([[0.0], np.cumsum(rng.uniform(0.2, 2.0, n))])
    u = np.concatenate([[0.0], np.cumsum(rng.uniform(-2.0, 2.0, n))])
    return t, u


def gms(k, f, fc, vs, beta, C, s1, s2, t, u, method):
    k, f = np.asarray(k, float), np.asarray(f, float)
    K, fs = k.sum(), f.sum()
    a = f / fs
    F, mode, W = np.zeros(len(k)), np.zeros(len(k)), 0.0
    work, stored = [0.0], [0.0]
    for j in range(1, len(t)):
        h, v = t[j] - t[j - 1], (u[j] - u[j - 1]) / (t[j] - t[j - 1])
        if v == 0.0:
            mode[:] = 0.0
        else:
            s = math.copysign(1.0, v)
            g = fc + (fs - fc) * math.exp(-abs(v / vs) ** beta)
            mode[mode == -s] = 0.0
            mode[(mode == 0) & (s * F >= a * g)] = s
            t0 = 0.0
            while t0 < h:
                def dF(y):
                    return np.where(mode == 0, k * v, C / g * (s * a * g - y))

                def rhs(_t, y):
                    d = dF(y[:-1])
                    return np.append(d, (y[:-1].sum() + s1 / K * d.sum() + s2 * v) * v)

                sticking = [i for i in range(len(k)) if mode[i] == 0]
                events = []
                for i in sticking:
                    ev = lambda _t, y, i=i: a[i] * g - s * y[i]
                    ev.terminal, ev.direction = True, -1
                    events.append(ev)
                sol = solve_ivp(rhs, (t0, h), np.append(F, W), method=method, rtol=RTOL,
                                atol=1e-15, events=events or None)
                F, W = sol.y[:-1, -1].copy(), sol.y[-1, -1]
                if sol.status != 1:
                    break
                for i, te in zip(sticking, sol.t_events):
                    if len(te):
                        mode[i] = s
                t0 = sol.t[-1]
        work.append(W)
        stored.append(float(np.sum(F * F / (2 * k))))
    return np.array(work), np.array(stored)


def elastoplastic(s0, fc, fs, zba, s1, s2, vs, beta, t, u, method):
    z, W = 0.0, 0.0
    work, stored = [0.0], [0.0]
    for j in range(1, len(t)):
        h, v = t[j] - t[j - 1], (u[j] - u[j - 1]) / (t[j] - t[j - 1])
        s = math.copysign(1.0, v)
        zss = (fc + (fs - fc) * math.exp(-abs(v / vs) ** beta)) / s0

        def alpha(w):
            if w <= zba:
                return 0.0
            if w >= zss:
                return 1.0
            return math.sin(0.5 * math.pi * (w - zba) / (zss - zba)) ** 2

        def rhs(_t, y):
            w = s * y[0]
            dz = v * (1.0 - alpha(w) * w / zss)
            return [dz, (s0 * y[0] + s1 * dz + s2 * v) * v]

        def e1(_t, y):
            return s * y[0] - zba

        def e2(_t, y):
            return s * y[0] - zss

        e1.terminal = e2.terminal = True
        t0 = 0.0
        while t0 < h:
            evs = [e for e in (e1, e2) if abs(e(0, [z])) > 1e-13 * zss]
            sol = solve_ivp(rhs, (t0, h), [z, W], method=method, rtol=RTOL, atol=1e-15,
                            events=evs or None)
            z, W = sol.y[0, -1], sol.y[1, -1]
            t0 = sol.t[-1]
            if sol.status != 1:
                break
        work.append(W)
        stored.append(0.5 * s0 * z * z)
    return np.array(work), np.array(stored)


# The zoo table's defaults with sigma2 = 0.2 (every term of the work exercised).
CASES = {
    "GMS": lambda t, u, m: gms([0.25] * 4, [0.125, 0.375, 0.625, 0.875], 1.0, 1.0, 1.0, 10.0,
                               1.0, 0.2, t, u, m),
    "ELASTOPLASTIC": lambda t, u, m: elastoplastic(1.0, 1.0, 2.0, 0.5, 1.0, 0.2, 1.0, 1.0, t, u, m),
}


def main():
    t, u = samples(28, 30)
    print(f"const T: [f64; {len(t)}] = {[float(x) for x in t]!r};")
    print(f"const U: [f64; {len(u)}] = {[float(x) for x in u]!r};")
    for name, run in CASES.items():
        (w, v), (w2, v2) = run(t, u, "Radau"), run(t, u, "DOP853")
        scale = np.abs(w).max()
        print(f"// {name}: largest |Radau - DOP853| / max|W| = {max(np.abs(w - w2).max(), np.abs(v - v2).max()) / scale:.1e}")
        print(f"const {name}_WORK: [f64; {len(w)}] = {[float(x) for x in w]!r};")
        print(f"const {name}_STORED: [f64; {len(v)}] = {[float(x) for x in v]!r};")


if __name__ == "__main__":
    main()
