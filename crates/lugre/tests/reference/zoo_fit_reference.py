"""Records for the slow-loop fit of the zoo's models (crates/lugre/tests/zoo_fit.rs).

Independent of lugre: each model written from its definition,

* Maxwell-slip: element i a spring k_i in series with a slip at |k_i z_i| = f_i: z_i += du, then
  clamped to [-f_i/k_i, f_i/k_i] (exact for a monotone step), F = sum k_i z_i;
* Prandtl-Ishlinskii: play operators p_i = max(u - r_i, min(u + r_i, p_i)), F = w0 u + sum w_i p_i;
* Bouc-Wen (normalized): dw/du = rho (1 - sigma sgn(du) |w|^(n-1) w + (sigma - 1) |w|^n),
  F = kx u + kw w, by scipy's solve_ivp Radau (rtol 1e-12, atol 1e-15) on each segment;
* elasto-plastic (Dupont et al. 2002, slow limit): with s = sgn(du), w = s z,
  dw/d|u| = 1 - alpha(w) w / z_max, alpha = 0 (w <= zba), sin^2(pi/2 (w - zba)/(z_max - zba))
  (zba < w < z_max), 1 (w >= z_max), z_max = fs / sigma0, F = sigma0 z; Radau as above.

The input: the turning points 2, -2, 1, -0.5 repeated (a major loop with a minor loop inside),
joined by straight lines, 100 samples per unit of travel (the small loop 0.05, -0.05 of
bouc-wen-small: 5000), every turning point a sample. Each
model runs from rest at u = 0 up to 2, then 3 periods (Maxwell-slip, Prandtl-Ishlinskii:
periodic after one) or 12 (Bouc-Wen, elasto-plastic; 40 for the small loop), and the
last period is written: one period from the global maximum, closing back to it. The
small Bouc-Wen loop carries force noise 1e-3.

Writes crates/lugre/tests/reference/zoo_fit/<case>.csv (u, F); the noisy cases add Gaussian
force noise of standard deviation 0.01 (numpy seed 28).

Run: python3 crates/lugre/tests/reference/zoo_fit_reference.py   (numpy, scipy)
"""
import os

import numpy as np
from scipy.integrate import solve_ivp

RTOL, ATOL = 1e-12, 1e-15
HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "zoo_fit")


def grid(amplitude, n):
    return [amplitude * (2 * i + 1) / (2 * n) for i in range(n)]


def path(turning, per_unit=100):
    """One period of samples from turning[0], the turning points among them."""
    u = []
    m = len(turning)
    for k in range(m):
        a, b = turning[k], turning[(k + 1) % m]
        steps = int(round(abs(b - a) * per_unit))
        u.extend(a + (b - a) * j / steps for j in range(steps))
    return np.array(u)


class Maxwell:
    def __init__(self, k, delta):
        self.k, self.d = np.array(k), np.array(delta)
        self.z = np.zeros(len(k))
        self.u = 0.0

    def step(self, u):
        self.z = np.clip(self.z + (u - self.u), -self.d, self.d)
        self.u = u
        return float(np.dot(self.k, self.z))


class Prandtl:
    def __init__(self, w0, r, w):
        self.w0, self.r, self.w = w0, np.array(r), np.array(w)
        self.p = np.zeros(len(r))

    def step(self, u):
        self.p = np.maximum(u - self.r, np.minimum(u + self.r, self.p))
        return self.w0 * u + float(np.dot(self.w, self.p))


class Ode:
    """A single-state model dz/du = h(z, s) integrated along each step."""

    def __init__(self, h, force):
        self.h, self.force = h, force
        self.u, self.z = 0.0, 0.0

    def step(self, u):
        if u != self.u:
            s = 1.0 if u > self.u else -1.0
            sol = solve_ivp(lambda x, y: [self.h(y[0], s)], (self.u, u), [self.z],
                            method="Radau", rtol=RTOL, atol=ATOL)
            self.z = float(sol.y[0, -1])
            self.u = u
        return self.force(u, self.z)


def bouc_wen(kx, kw, rho, sigma, n):
    def h(w, s):
        a = abs(w)
        return rho * (1.0 - sigma * s * a ** (n - 1.0) * w + (sigma - 1.0) * a**n)

    return Ode(h, lambda u, w: kx * u + kw * w)


def elastoplastic(sigma0, fs, zba):
    zmax = fs / sigma0

    def h(z, s):
        w = s * z
        if w <= zba:
            alpha = 0.0
        elif w < zmax:
            alpha = np.sin(0.5 * np.pi * (w - zba) / (zmax - zba)) ** 2
        else:
            alpha = 1.0
        return 1.0 - alpha * w / zmax  # dz/du = dw/d|u|

    return Ode(h, lambda u, z: sigma0 * z)


def record(model, turning, periods, per_unit=100):
    for u in np.linspace(0.0, turning[0], 201)[1:]:
        model.step(u)
    one = path(turning, per_unit)
    for _ in range(periods - 1):
        for u in one[1:]:
            model.step(u)
        model.step(one[0])
    f = []
    for u in one:
        f.append(model.step(u))
    return one, np.array(f)


def write(name, u, f):
    os.makedirs(HERE, exist_ok=True)
    with open(os.path.join(HERE, name + ".csv"), "w") as out:
        out.write("u,F\n")
        for a, b in zip(u, f):
            out.write(f"{float(a)!r},{float(b)!r}\n")


def main():
    major = [2.0, -2.0, 1.0, -0.5]
    g = grid(2.0, 4)
    cases = {
        "maxwell-slip": (lambda: Maxwell([0.4, 0.3, 0.2, 0.1], g), major, 3),
        "prandtl-ishlinskii": (lambda: Prandtl(0.3, g, [0.5, 0.25, 0.2, 0.1]), major, 3),
        "bouc-wen": (lambda: bouc_wen(0.1, 1.5, 2.0, 0.75, 2.0), major, 12),
        "elastoplastic": (lambda: elastoplastic(2.0, 1.5, 0.3), major, 12),
        # Never near saturation: rho |du| <= 0.2.
        "bouc-wen-small": (lambda: bouc_wen(0.1, 1.5, 2.0, 0.75, 2.0), [0.05, -0.05], 40, 5000),
    }
    rng = np.random.default_rng(28)
    for name, (make, turning, periods, *per_unit) in cases.items():
        u, f = record(make(), turning, periods, *per_unit)
        if name.endswith("small"):
            # A small loop measured as a laboratory would: force noise 1e-3.
            write(name, u, f + 1e-3 * rng.standard_normal(len(f)))
            continue
        write(name, u, f)
        write(name + "-noisy", u, f + 0.01 * rng.standard_normal(len(f)))
        print(name, len(u), "samples")


if __name__ == "__main__":
    main()
