"""Reference forces of the GMS model along piecewise-linear motions, for
`crates/lugre/tests/zoo_gms.rs` (the exact `MaxwellSlip::simulate`).

An independent integration of the published equations (Al-Bender, Lampaert and Swevers,
IEEE TAC 50(11), 2005), each interval of constant velocity solved by scipy's solve_ivp with
the stick-to-slip transitions located as terminal events, by Radau and by DOP853 at
rtol 1e-12; the two must agree. Run once:

    python crates/lugre/tests/reference/gms_reference.py

and paste the printed arrays into the test.
"""
import numpy as np
from scipy.integrate import solve_ivp


def stribeck(v, fc, fs, vs, beta):
    return fc + (fs - fc) * np.exp(-abs(v / vs) ** beta)


def interval(F, mode, k, alpha, v, h, g, C, method):
    """Moves the element forces F over h seconds at velocity v; mode 0 sticks, +-1 slips."""
    s = np.sign(v)
    t0 = 0.0
    while t0 < h:
        def rhs(_t, y):
            # sticking: dF/dt = k v; slipping: dF/dt = sgn(v) C (alpha - F / s(v))
            return np.where(mode == 0, k * v, s * C * (alpha - y / (s * g)))

        sticking = [i for i in range(len(k)) if mode[i] == 0]
        events = []
        for i in sticking:
            ev = lambda _t, y, i=i: alpha[i] * g - s * y[i]
            ev.terminal, ev.direction = True, -1
            events.append(ev)
        atol = 1e-15 * max(1.0, g)
        sol = solve_ivp(rhs, (t0, h), F, method=method, rtol=1e-12, atol=atol,
                        events=events or None)
        F = sol.y[:, -1].copy()
        if sol.status != 1:
            return F, rhs(h, F)
        for i, te in zip(sticking, sol.t_events):
            if len(te):
                mode[i] = s
        t0 = sol.t[-1]
    return F, rhs(h, F)


def simulate(k, f, rate, t, u, method):
    fc, vs, beta, C, sigma1, sigma2 = rate
    k, f = np.asarray(k, float), np.asarray(f, float)
    fs, K = f.sum(), k.sum()
    alpha = f / fs
    F = np.zeros(len(k))
    mode = np.zeros(len(k))
    out = [0.0]
    for j in range(1, len(t)):
        h = t[j] - t[j - 1]
        v = (u[j] - u[j - 1]) / h
        if v == 0.0:
            mode[:] = 0.0
            out.append(F.sum())
            continue
        s, g = np.sign(v), stribeck(v, fc, fs, vs, beta)
        mode[mode == -s] = 0.0  # a reversal ends slipping
        mode[(mode == 0) & (s * F >= alpha * g)] = s  # beyond its level: slips at once
        F, dF = interval(F, mode, k, alpha, v, h, g, C, method)
        out.append(F.sum() + sigma1 / K * dF.sum() + sigma2 * v)
    return np.array(out)


DEFAULT_K = [0.25, 0.25, 0.25, 0.25]
DEFAULT_F = [0.125, 0.375, 0.625, 0.875]
CASES = {
    "defaults": (DEFAULT_K, DEFAULT_F, (1.0, 1.0, 1.0, 10.0, 1.0, 0.0),
                 [0, 1, 2.5, 3, 4, 4.5, 6, 7, 8],
                 [0, 1.2, 3.0, 3.0, 1.0, 1.5, -2.0, -1.0, -1.3]),
    "table1": ([4e4, 3e4, 2e4, 1e4], [0.15, 0.3, 0.45, 0.6],
               (1.0, 1e-3, 2.0, 50.0, 316.2, 0.4),
               [0, 1e-3, 3e-3, 4e-3, 6e-3, 0.01, 0.012, 0.02],
               [0, 2e-6, 1e-5, 1.2e-5, 5e-6, -1e-5, -1e-5, -8e-6]),
}


def random_case(seed, n):
    rng = np.random.default_rng(seed)
    t = np.concatenate([[0.0], np.cumsum(rng.uniform(0.2, 2.0, n))])
    u = np.concatenate([[0.0], np.cumsum(rng.uniform(-2.0, 2.0, n))])
    return DEFAULT_K, DEFAULT_F, (0.6, 1.0, 2.0, 3.0, 0.5, 0.2), list(t), list(u)


CASES["random"] = random_case(28, 30)

if __name__ == "__main__":
    for name, (k, f, rate, t, u) in CASES.items():
        radau = simulate(k, f, rate, t, u, "Radau")
        dop = simulate(k, f, rate, t, u, "DOP853")
        scale = np.abs(radau).max()
        print(f"// {name}: Radau - DOP853 = {np.abs(radau - dop).max() / scale:.1e} of max |F|")
        print(f"t = {[float(x) for x in t]!r}")
        print(f"u = {[float(x) for x in u]!r}")
        print(f"force = {[float(x) for x in radau]!r}")
