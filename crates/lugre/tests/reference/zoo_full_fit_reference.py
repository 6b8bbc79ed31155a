"""Records for the full fit of the zoo's finite-rate models (crates/lugre/tests/zoo_full_fit.rs).

Independent of lugre: the force of each model along an input linear in time between samples,
from rest at u = 0, by the integrations of the published equations already used for the
simulation's references (each interval of constant velocity by scipy's solve_ivp, its
switching points located as terminal events, Radau and DOP853 at rtol 1e-12; the printed
difference must be small):

* GMS (Al-Bender, Lampaert and Swevers 2005): gms_reference.simulate, the force at each sample
  the end of the interval before it;
* elasto-plastic at finite rate (Dupont et al. 2002 with LuGre's damping and Stribeck curve):
  the model of elastoplastic_simulate.py, the force at each sample with the velocity of the
  interval after it (the last sample: before). On an interval w = sgn(v) z rises while
  w < z_ss and falls towards z_ss above it, reaching it only asymptotically: the one kink
  crossed is w = zba, upwards, below which the motion is elastic (z linear in t, its time to
  the kink in closed form); from the kink on solve_ivp integrates.

The input: the turning points 0, 2, -2, 1, -0.5, 2.5, -1.5, 1.5, each segment at its own speed
(0.05 to 3 m/s, across the Stribeck velocity 0.5), its second half at another (the speed
three segments on), a sample every 0.05 m of travel. The case maxwell-slip-constant keeps one
speed per segment: a GMS element that starts to slip at constant speed stays on its level,
so the attraction (which acts only where the level moves while slipping) has no effect.
GMS's element thresholds are the fit's grid (ZF3) on the record's range: Delta_i = A (2 i + 1) /
(2 N), A = (2.5 - (-2)) / 2, N = 4, slip forces f_i = k_i Delta_i.

Writes crates/lugre/tests/reference/zoo_fit/<case>-full.csv (t, u, F); the noisy cases add
Gaussian force noise of standard deviation 0.01 (numpy seed 2028).

Run: python3 crates/lugre/tests/reference/zoo_full_fit_reference.py   (numpy, scipy)
"""
import os
import sys

import numpy as np
from scipy.integrate import solve_ivp

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import gms_reference  # noqa: E402

TURNING = [0.0, 2.0, -2.0, 1.0, -0.5, 2.5, -1.5, 1.5]
SPEEDS = [0.05, 1.0, 0.2, 3.0, 0.5, 0.1, 2.0]
STEP = 0.05

# The model's parameters, elastoplastic_simulate.py's names.
ELASTOPLASTIC = dict(s0=2.0, fc=1.0, fs=1.5, zba=0.3, s1=0.5, s2=0.2, vs=0.5, beta=2.0)
GMS_K = [0.4, 0.3, 0.2, 0.1]
GMS_RATE = (0.55, 0.5, 2.0, 3.0, 0.5, 0.2)  # fc, vs, beta, attraction, sigma1, sigma2


def elastoplastic(c, t, u, method):
    """The force at each sample (module docs)."""
    s0, zba = c["s0"], c["zba"]

    def g(v):
        return c["fc"] + (c["fs"] - c["fc"]) * np.exp(-abs(v / c["vs"]) ** c["beta"])

    def zdot(v, z):
        zss = g(v) / s0
        w = np.sign(v) * z
        if w <= zba:
            alpha = 0.0
        elif w >= zss:
            alpha = 1.0
        else:
            alpha = np.sin(0.5 * np.pi * (w - zba) / (zss - zba)) ** 2
        return v * (1.0 - alpha * w / zss)

    def force(v, z):
        return s0 * z + c["s1"] * zdot(v, z) + c["s2"] * v

    n = len(t)
    vel = [(u[i + 1] - u[i]) / (t[i + 1] - t[i]) for i in range(n - 1)]
    z = 0.0
    out = [force(vel[0], z)]
    for i in range(n - 1):
        v, s = vel[i], np.sign(vel[i])
        zss = g(v) / s0
        ta, tb = t[i], t[i + 1]
        if s * z < zba:
            # Elastic (alpha = 0): z moves with u until w reaches zba.
            to_kink = (zba - s * z) / abs(v)
            if to_kink >= tb - ta:
                z, ta = z + v * (tb - ta), tb
            else:
                z, ta = s * zba, ta + to_kink
        if ta < tb:
            sol = solve_ivp(lambda _, y: [zdot(v, y[0])], (ta, tb), [z], method=method,
                            rtol=1e-12, atol=1e-14 * zss)
            z = sol.y[0, -1]
        out.append(force(vel[min(i + 1, n - 2)], z))
    return np.array(out)


def record(change=True):
    """The input; `change`: each segment's second half at another speed (SPEEDS 3 on)."""
    t, u = [0.0], [TURNING[0]]
    for k, (a, b) in enumerate(zip(TURNING, TURNING[1:])):
        steps = int(round(abs(b - a) / STEP))
        for j in range(1, steps + 1):
            v = SPEEDS[(k + 3) % len(SPEEDS)] if change and 2 * j > steps else SPEEDS[k]
            u.append(a + (b - a) * j / steps)
            t.append(t[-1] + abs(b - a) / steps / v)
    return np.array(t), np.array(u)


def gms_slip_forces(u):
    amplitude = 0.5 * (u.max() - u.min())
    n = len(GMS_K)
    return [k * amplitude * (2 * i + 1) / (2 * n) for i, k in enumerate(GMS_K)]


def write(name, t, u, f):
    with open(os.path.join(HERE, "zoo_fit", name + ".csv"), "w") as out:
        out.write("t,u,F\n")
        for a, b, c in zip(t, u, f):
            out.write(f"{float(a)!r},{float(b)!r},{float(c)!r}\n")


def main():
    t, u = record()
    rng = np.random.default_rng(2028)
    slip = gms_slip_forces(u)
    cases = {
        "elastoplastic-full": lambda m: elastoplastic(ELASTOPLASTIC, t, u, m),
        "maxwell-slip-full": lambda m: gms_reference.simulate(GMS_K, slip, GMS_RATE, t, u, m),
    }
    for name, run in cases.items():
        radau, dop = np.asarray(run("Radau")), np.asarray(run("DOP853"))
        scale = np.max(np.abs(radau))
        edge = np.abs(radau - dop) > 1e-9 * scale
        # A GMS element that reaches its level at a sample: the force there is the left limit,
        # with the sticking rate k v in (G3); Radau's event, located at the interval's end
        # within rounding, switched it to slipping first. DOP853's event falls inside.
        print(f"{name}: samples on a switching instant {list(np.flatnonzero(edge))}")
        radau[edge] = dop[edge]
        diff = np.max(np.abs(radau - dop)) / scale
        print(f"{name}: {len(t)} samples, |Radau - DOP853| / max|F| = {diff:.1e} elsewhere")
        write(name, t, u, radau)
        write(name + "-noisy", t, u, radau + 0.01 * rng.standard_normal(len(t)))
    t, u = record(change=False)
    f = gms_reference.simulate(GMS_K, slip, GMS_RATE, t, u, "Radau")
    write("maxwell-slip-constant", t, u, f)
    print("GMS slip forces", slip)


if __name__ == "__main__":
    main()
