#!/usr/bin/env python3
"""The servo-axis record, generated independently of the crate.

LuGre (Canudas de Wit et al. 1995, the paper's eq. 1 with the Stribeck curve and viscous term)

    dz/dt = v - sigma0 |v| z / g(v),    g(v) = Fc + (Fs - Fc) exp(-(|v| / vs)^beta)
    F     = sigma0 z + sigma1 dz/dt + sigma2 v

driven by u(t) = A sin(2 pi f t), A = 5 mm, f = 0.5 Hz, from z(0) = 0, with the true
sigma0 = 1e6 N/m, sigma1 = 1500 N s/m, sigma2 = 40 N s/m, Fc = 15 N, Fs = 22 N, vs = 4 mm/s,
beta = 2. Solved with scipy's Radau (rtol 1e-10, atol 1e-16 m on z) piece by piece between the
reversals (where |v| has its kink), dense output at the samples t_i = i / 1 kHz, i = 0..4000
(two periods). Nothing here uses the crate.

The record as a lab would have it: u in mm, plus Gaussian position noise (0.5 um), then rounded
to 0.1 um (the encoder's resolution); F plus Gaussian force noise (0.2 N). Columns t [s], u [mm],
F [N].

    python3 servo_axis.py clean > servo_axis_clean.csv       # noise-free samples (the tests')
    python3 servo_axis.py record SEED > record.csv            # one noisy record
    python3 servo_axis.py records DIR N [FIRST_SEED]          # N records DIR/servo_SEED.csv

Options (before the command): --position-noise UM, --force-noise N, --resolution UM (0: none).

The crate's test `servo_axis_monte_carlo` (crates/lugre/tests/fit_noise.rs) reads the clean
samples written by `clean` (crates/lugre/tests/reference/servo_axis_clean.csv) and adds its own
noise of the same levels; the full Monte Carlo (scripts/servo_axis_monte_carlo.py) fits records
written by `records`.
"""

import argparse
import os
import sys

import numpy as np
from scipy.integrate import solve_ivp

SIGMA0, SIGMA1, SIGMA2 = 1e6, 1500.0, 40.0
FC, FS, VS, BETA = 15.0, 22.0, 4e-3, 2.0
AMPLITUDE, FREQUENCY = 5e-3, 0.5  # m, Hz
RATE, SAMPLES = 1000.0, 4001  # Hz, two periods


def g(v):
    return FC + (FS - FC) * np.exp(-((np.abs(v) / VS) ** BETA))


def motion(t):
    w = 2.0 * np.pi * FREQUENCY
    return AMPLITUDE * np.sin(w * t), AMPLITUDE * w * np.cos(w * t)


def rhs(t, z):
    _, v = motion(t)
    return [v - SIGMA0 * abs(v) * z[0] / g(v)]


def jac(t, z):
    _, v = motion(t)
    return [[-SIGMA0 * abs(v) / g(v)]]


def clean():
    """(t, u [m], F [N]) noise-free at the samples."""
    t = np.arange(SAMPLES) / RATE
    # Reversals of the sine: t = (k + 1/2) / (2 f).
    half = 1.0 / (2.0 * FREQUENCY)
    cuts = [0.0] + [half * (k + 0.5) for k in range(8) if half * (k + 0.5) < t[-1]] + [t[-1]]
    z = np.empty(SAMPLES)
    z0 = 0.0
    for a, b in zip(cuts[:-1], cuts[1:]):
        sel = (t >= a) & (t <= b)
        sol = solve_ivp(rhs, (a, b), [z0], method="Radau", jac=jac, rtol=1e-10,
                        atol=1e-16, dense_output=True)
        assert sol.success, sol.message
        z[sel] = sol.sol(t[sel])[0]
        z0 = sol.y[0, -1]
    u, v = motion(t)
    zdot = v - SIGMA0 * np.abs(v) * z / g(v)
    f = SIGMA0 * z + SIGMA1 * zdot + SIGMA2 * v
    return t, u, f


def noisy(t, u, f, seed, position_noise, force_noise, resolution):
    rng = np.random.default_rng(seed)
    um = u * 1e6 + position_noise * rng.standard_normal(u.size)
    if resolution > 0:
        um = np.round(um / resolution) * resolution
    fn = f + force_noise * rng.standard_normal(f.size)
    return t, um * 1e-3, fn


def write(out, t, u_mm, f, digits):
    out.write("t,u,F\n")
    for a, b, c in zip(t, u_mm, f):
        out.write(f"{a:.3f},{b:.{digits}g},{c:.{digits}g}\n")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--position-noise", type=float, default=0.5, help="um (default 0.5)")
    p.add_argument("--force-noise", type=float, default=0.2, help="N (default 0.2)")
    p.add_argument("--resolution", type=float, default=0.1, help="um (default 0.1; 0: none)")
    p.add_argument("command", choices=["clean", "record", "records"])
    p.add_argument("args", nargs="*")
    a = p.parse_args()
    t, u, f = clean()
    if a.command == "clean":
        write(sys.stdout, t, u * 1e3, f, 15)
    elif a.command == "record":
        seed = int(a.args[0]) if a.args else 1
        write(sys.stdout, *noisy(t, u, f, seed, a.position_noise, a.force_noise, a.resolution), 10)
    else:
        out, n = a.args[0], int(a.args[1])
        first = int(a.args[2]) if len(a.args) > 2 else 1
        os.makedirs(out, exist_ok=True)
        for seed in range(first, first + n):
            with open(os.path.join(out, f"servo_{seed}.csv"), "w") as fh:
                write(fh, *noisy(t, u, f, seed, a.position_noise, a.force_noise, a.resolution), 10)


if __name__ == "__main__":
    main()
