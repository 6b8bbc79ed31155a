#!/usr/bin/env python3
"""Writes the example data of the README's "Identifying LuGre as a lab does": the three
experiments of a friction lab, generated independently of lugre (numpy, scipy's Radau at
rtol 1e-10):

* lab-stribeck.csv (t,u,F): constant-velocity runs, 24 speeds log-spaced from 1e-4 to 1 m/s
  (four decades), each run at +v then -v (so the slide stays short), 1 s each (the slowest
  longer: at least 20 relaxation lengths Fs / sigma0 of sliding) with 0.05 s ramps between,
  sampled at 100 Hz; the position rounded to 1 nm, the force with Gaussian noise
  of 0.01 N (1 % of Fc);
* lab-stribeck-table.csv (v,F): the same runs as a table, each row the commanded velocity and
  the mean force over the second half of its run (the part a lab would call steady);
* lab-presliding.csv (t,u,F): a presliding test, a 20 Hz sine whose amplitude grows from 0.5
  to 3 um over 1 s (far below break-away: the force stays under 0.35 N, Fs = 1.5 N), sampled at
  2 kHz, the position rounded to 1 nm, force noise 0.003 N (1 % of the force amplitude);
* lab-sine.csv (t,u,F): a rate-dependent record for the final full fit of a staged
  identification, a 1 mm sine at 0.6 Hz (peak speed 3.8 vs), two periods at 600 Hz, the
  position rounded to 1 nm, force noise 0.01 N.

The model is LuGre with the parameters of Canudas de Wit et al. (1995) (the core's preset
`canudas1995`): sigma0 = 1e5 N/m, sigma1 = sqrt(1e5) N s/m, sigma2 = 0.4 N s/m, Fc = 1 N,
Fs = 1.5 N, vs = 1e-3 m/s, beta = 2, from z = 0:

    dz/dt = v - sigma0 |v| z / g(v),  g(v) = Fc + (Fs - Fc) exp(-(v / vs)^2)
    F = sigma0 z + sigma1 dz/dt + sigma2 v

integrated piece by piece (each ramp and plateau, each sine record whole) with Radau at
rtol 1e-10, atol 1e-16 (z is of order 1e-5 m).

    python3 examples/data/make_lab_experiments.py        # from the repository root
"""

import os

import numpy as np
from scipy.integrate import solve_ivp

HERE = os.path.dirname(os.path.abspath(__file__))
SIGMA0, SIGMA1, SIGMA2 = 1e5, np.sqrt(1e5), 0.4
FC, FS, VS = 1.0, 1.5, 1e-3
RTOL, ATOL = 1e-10, 1e-16


def g(v):
    return FC + (FS - FC) * np.exp(-(v / VS) ** 2)


def zdot(v, z):
    return v - SIGMA0 * np.abs(v) * z / g(v)


def friction(v, z):
    return SIGMA0 * z + SIGMA1 * zdot(v, z) + SIGMA2 * v


def integrate(velocity, t0, t1, z0, t_eval):
    """z on [t0, t1] at t_eval and at t1, for the velocity function `velocity(t)`."""
    sol = solve_ivp(lambda t, z: zdot(velocity(t), z), (t0, t1), [z0], method="Radau",
                    rtol=RTOL, atol=ATOL, t_eval=np.clip(np.append(t_eval, t1), t0, t1))
    assert sol.success, sol.message
    return sol.y[0, :-1], sol.y[0, -1]


def stribeck_record(rng):
    dt, run, ramp = 0.01, 1.0, 0.05
    speeds = np.logspace(-4, 0, 24)
    targets = [s * v for v in speeds for s in (1.0, -1.0)]
    # Pieces: (t0, t1, v0, v1): a ramp from the previous velocity, then the plateau.
    pieces, t, v_prev = [], 0.0, 0.0
    for v in targets:
        # Slow runs last long enough to slide 20 relaxation lengths g / sigma0 (a lab runs
        # them for a distance, not a time).
        length = max(run, round(20 * FS / SIGMA0 / abs(v), 2))
        pieces.append((t, t + ramp, v_prev, v))
        pieces.append((t + ramp, t + ramp + length, v, v))
        t += ramp + length
        v_prev = v
    n = int(round(t / dt))
    times = np.arange(n + 1) * dt
    u_all, f_all, steady = np.zeros(n + 1), np.zeros(n + 1), []
    z, u = 0.0, 0.0
    for (t0, t1, v0, v1) in pieces:
        vel = (lambda a, b, c, d: (lambda s: c + (d - c) * (s - a) / (b - a)))(t0, t1, v0, v1)
        inside = (times >= t0 - 1e-12) & (times < t1 - 1e-12)
        te = times[inside]
        zs, z_end = integrate(vel, t0, t1, z, te)
        vs_ = np.array([vel(s) for s in te])
        u_all[inside] = u + v0 * (te - t0) + 0.5 * (v1 - v0) / (t1 - t0) * (te - t0) ** 2
        f_all[inside] = friction(vs_, zs)
        u += 0.5 * (v0 + v1) * (t1 - t0)
        z = z_end
        if v0 == v1:
            steady.append((v0, np.flatnonzero(inside)))
    # The last sample, at the end of the last plateau.
    u_all[n], f_all[n] = u, friction(targets[-1], z)
    f_noisy = f_all + rng.normal(0.0, 0.01, n + 1)
    u_rounded = np.round(u_all * 1e9) / 1e9
    with open(os.path.join(HERE, "lab-stribeck.csv"), "w") as out:
        out.write("t,u,F\n")
        for i in range(n + 1):
            out.write(f"{times[i]:.2f},{u_rounded[i]:.9f},{f_noisy[i]:.5f}\n")
    with open(os.path.join(HERE, "lab-stribeck-table.csv"), "w") as out:
        out.write("v,F\n")
        for v, idx in steady:
            half = idx[len(idx) // 2:]
            out.write(f"{v:.6g},{f_noisy[half].mean():.6f}\n")


def sine_record(name, amplitude, freq, duration, rate, noise, rng):
    """A sine u = A(t) sin(2 pi f t), A(t) = amplitude(t)."""
    times = np.arange(int(round(duration * rate)) + 1) / rate

    def u_of(t):
        return amplitude(t) * np.sin(2 * np.pi * freq * t)

    def v_of(t, h=1e-7):
        # Exact derivative of the product (amplitude linear in t).
        da = (amplitude(t + h) - amplitude(t - h)) / (2 * h)
        return da * np.sin(2 * np.pi * freq * t) + amplitude(t) * 2 * np.pi * freq * np.cos(
            2 * np.pi * freq * t)

    sol = solve_ivp(lambda t, z: zdot(v_of(t), z), (0.0, times[-1]), [0.0], method="Radau",
                    rtol=RTOL, atol=ATOL, t_eval=times, max_step=1.0 / (20 * freq))
    assert sol.success, sol.message
    z = sol.y[0]
    f = friction(v_of(times), z) + rng.normal(0.0, noise, len(times))
    u = np.round(u_of(times) * 1e9) / 1e9
    with open(os.path.join(HERE, name), "w") as out:
        out.write("t,u,F\n")
        for i in range(len(times)):
            out.write(f"{times[i]:.6g},{u[i]:.9f},{f[i]:.6f}\n")


def main():
    rng = np.random.default_rng(2026)
    stribeck_record(rng)
    sine_record("lab-presliding.csv", lambda t: 0.5e-6 + 2.5e-6 * t, 20.0, 1.0, 2000.0,
                0.003, rng)
    sine_record("lab-sine.csv", lambda t: 1e-3 + 0.0 * t, 0.6, 2.0 / 0.6, 600.0, 0.01, rng)
    print("wrote examples/data/lab-stribeck.csv, lab-stribeck-table.csv, lab-presliding.csv, "
          "lab-sine.csv")


if __name__ == "__main__":
    main()
