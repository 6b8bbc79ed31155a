"""The hunting limit cycle of the PID experiment of Canudas de Wit, Olsson, Åström and Lischinsky
(IEEE TAC 40(3), 1995, Fig. 8) predicted by harmonic balance, and compared with the simulation.

    python examples/hunting.py

The loop: a 1 kg mass with the Table I LuGre friction F, under u = Kp (xd - x) + Ki q - Kv v,
q' = xd - x (Kp = 3 N/m, Ki = 4 N/(m s), Kv = 6 N s/m, xd = 1 m). With e = x - xd,

    m e'' + Kv e' + Kp e + Ki integral(e) = -F.

1. The friction's own describing function (``lugre.sweep``: N(A, w) = k_eq + i w c_eq for
   e = A sin(w t)) closed with the linear rest, N = m w^2 - Kp + i (Ki / w - Kv w), has no
   solution: it needs k_eq <= m Ki / Kv - Kp = -2.33 N/m below sqrt(Ki / Kv) or c_eq < 0 above,
   and the friction's k_eq is never that negative while c_eq = E / (pi w A^2) > 0. A sinusoidal
   displacement never sticks, and the hunting is made of sticks. Nor has the block "mass +
   friction" under a sine force with the whole PID as the linear part: its gain jumps over the
   one needed as the force passes the break-away (nothing stops the slip).
2. The block "mass + friction + the PD part" driven by the integral force w(t) = W sin(w t)
   (``lugre.dynamics`` with a force profile and gains (Kp, 0, Kv), run to its periodic steady
   state) has a describing function N_e(W, w) = e_1 / W that sticks and slips. The integrator
   closes it: W_1 = -Ki e_1 / (i w), so harmonic balance is N_e(W, w) = -i w / Ki:

       arg N_e(W, w) = -pi / 2,        |N_e(W, w)| = w / Ki,

   two real equations for (W, w), solved here by Newton's method.
   The integral force is the one nearly sinusoidal signal of the loop (a triangle: it ramps
   while the mass sticks), so this split is where the describing function's filtering
   assumption holds.

numpy only: the root-finders are written out.
"""

import math

import numpy as np

import lugre

# Table I of the paper and the experiment's loop (SI units).
MODEL = lugre.LuGre(sigma0=1e5, sigma1=1e5**0.5, sigma2=0.4, fc=1.0, fs=1.5, vs=1e-3, beta=2.0)
MASS, KP, KI, KV, XD = 1.0, 3.0, 4.0, 6.0, 1.0

# The block's periodic steady state: periods run (the first one kicked to 2 W so that the
# mass slips from the start: below the break-away a mass started at rest would only stick),
# force points per period (a piecewise-linear sine: force error <= (pi/512)^2/2 = 1.9e-5
# of W), output samples per period for the Fourier coefficient.
PERIODS, FORCE_POINTS, SAMPLES = 6, 512, 2048


def first_harmonic(t, y, w):
    """Complex amplitude Y of y ~ Im(Y exp(i w t)) over whole periods sampled uniformly
    (endpoint excluded): the rectangle rule, exact for trigonometric polynomials of degree
    below half the samples."""
    return 1j * 2.0 / len(y) * np.sum(y * np.exp(-1j * w * t))


def one_period(t, y):
    """The last whole period of a uniformly sampled run whose last SAMPLES + 1 points span it."""
    return t[-SAMPLES - 1 : -1], y[-SAMPLES - 1 : -1]


def simulated(t_end=300.0, settle=100.0):
    """The experiment as ``lugre dynamics --scenario pid`` runs it: the hunting's peak
    amplitude of e = x - xd, its first-harmonic amplitude, and its period (the mean spacing of
    the upward zero crossings of e after ``settle`` s); and over its last period the
    integral force w = Ki integral(xd - x) = drive + Kv v + Kp e (its peak and first
    harmonic W_1) with e_1 / W_1, which the integrator makes exactly -i w / Ki."""
    run = lugre.dynamics(scenario="pid", t_end=t_end, samples=int(t_end * 100) + 1)
    t, e = run["t"], run["x"] - XD
    late = t >= settle
    t, e = t[late], e[late]
    up = np.nonzero((e[:-1] < 0.0) & (e[1:] >= 0.0))[0]
    # The crossing times by linear interpolation between samples.
    crossings = t[up] - e[up] * (t[up + 1] - t[up]) / (e[up + 1] - e[up])
    period = float(np.mean(np.diff(crossings)))
    w = 2.0 * math.pi / period
    dense = lugre.dynamics(
        scenario="pid", times=np.linspace(crossings[-2], crossings[-1], SAMPLES + 1)
    )
    t1, e1 = one_period(dense["t"], dense["x"] - XD)
    _, force = one_period(dense["t"], dense["drive"] + KV * dense["v"] + KP * (dense["x"] - XD))
    e1, w1 = first_harmonic(t1, e1, w), first_harmonic(t1, force, w)
    return {
        "integral_peak": float(np.max(np.abs(force))),
        "integral_first_harmonic": float(abs(w1)),
        "ratio": e1 / w1,
        "amplitude": float((e.max() - e.min()) / 2.0),
        "first_harmonic": float(abs(e1)),
        "period": period,
    }


def plain_balance(amplitude, period):
    """The friction's describing function for a displacement sine against what the linear rest
    of the loop needs, at the simulated hunting, and the sign argument over a grid."""
    w = 2.0 * math.pi / period
    need = complex(MASS * w**2 - KP, KI / w - KV * w)
    point = lugre.sweep(MODEL, amplitudes=[amplitude], frequencies=[1.0 / period])
    have = complex(point["stiffness"][0], w * point["damping"][0])
    # Below sqrt(Ki / Kv) the balance needs k_eq = m w^2 - Kp <= m Ki / Kv - Kp; above it,
    # c_eq < 0. The grid: amplitudes over five decades, frequencies over four.
    grid = lugre.sweep(MODEL, amplitudes="1e-4:10:21", frequencies="1e-3:10:25")
    slow = np.asarray(grid["frequency"]) * 2.0 * math.pi < math.sqrt(KI / KV)
    return {
        "need": need,
        "have": have,
        "k_eq_min": float(np.min(np.asarray(grid["stiffness"])[slow])),
        "k_eq_needed_max": MASS * KI / KV - KP,
        "c_eq_min": float(np.min(grid["damping"])),
    }


def block(W, w):
    """The steady state of mass + friction + PD under the force W sin(w t):
    (N_e = e_1 / W, e over one period), or (None, e) when the mass only sticks."""
    T = 2.0 * math.pi / w
    tf = np.linspace(0.0, PERIODS * T, PERIODS * FORCE_POINTS + 1)
    force = np.where(tf < T, 2.0 * W, W) * np.sin(w * tf)
    times = np.linspace((PERIODS - 1) * T, PERIODS * T, SAMPLES + 1)
    run = lugre.dynamics(
        MODEL, mass=MASS, force=(tf, force), pid=(KP, 0.0, KV), setpoint=0.0, times=times
    )
    t, e = one_period(run["t"], run["x"])
    # Slipping both ways moves e across 0; a stuck mass stays on one side.
    if e.min() >= 0.0 or e.max() <= 0.0:
        return None, e
    return first_harmonic(t, e, w) / W, e


def open_loop_gap(w, tol=1e-7):
    """The whole PID as the linear part instead: the block mass + friction alone under the force
    U sin(w t) (from rest, no kick) with 1 + C(i w) N_x(U, w) = 0, C = Kp + Ki / (i w) + i Kv w,
    needs |N_x| = |x_1| / U = |1 / C(i w)|. Bisection in U on "|N_x| above that" closes in on
    where it is crossed: a jump (the gains at both ends of a bracket of width tol Fs)."""
    T = 2.0 * math.pi / w
    tf = np.linspace(0.0, PERIODS * T, PERIODS * FORCE_POINTS + 1)
    times = np.linspace((PERIODS - 1) * T, PERIODS * T, SAMPLES + 1)
    need = 1.0 / abs(complex(KP, KV * w - KI / w))

    def gain(U):
        run = lugre.dynamics(MODEL, mass=MASS, force=(tf, U * np.sin(w * tf)), times=times)
        t, x = one_period(run["t"], run["x"])
        return abs(first_harmonic(t, x, w)) / U

    lo, hi = 0.5 * MODEL.fs, MODEL.fs
    g_lo, g_hi = gain(lo), gain(hi)
    if not g_lo < need < g_hi:
        raise ValueError(f"|N_x| does not cross {need} between U = {lo} and {hi}")
    while hi - lo > tol * MODEL.fs:
        mid = 0.5 * (lo + hi)
        g = gain(mid)
        if g < need:
            lo, g_lo = mid, g
        else:
            hi, g_hi = mid, g
    return {"need": need, "U": hi, "below": g_lo, "above": g_hi}


def balance(W, w):
    """The two real equations of the harmonic balance N_e(W, w) = -i w / Ki, as
    (arg N_e + pi/2, Ki |N_e| / w - 1); None where the mass only sticks."""
    n, _ = block(W, w)
    if n is None:
        return None
    return np.array([np.angle(n) + math.pi / 2, KI * abs(n) / w - 1.0])


def predict(tol=1e-10, max_iter=50):
    """The (W, w) of the harmonic balance by Newton's method (the Jacobian by forward
    differences of 1e-5 relative), halving a step that ends where the mass only sticks or that
    does not lower the residual. The start: W = Fs (the integral force alone breaks the mass
    away) and w = sqrt(Ki / Kv) / 2 (the balance needs w below sqrt(Ki / Kv): above it the
    PD block's gain is below w / Ki)."""
    x = np.array([MODEL.fs, 0.5 * math.sqrt(KI / KV)])
    fx = balance(*x)
    for _ in range(max_iter):
        jac = np.empty((2, 2))
        for k in range(2):
            dx = np.zeros(2)
            dx[k] = 1e-5 * x[k]
            jac[:, k] = (balance(*(x + dx)) - fx) / dx[k]
        step = -np.linalg.solve(jac, fx)
        lam = 1.0
        while True:
            trial = balance(*(x + lam * step))
            if trial is not None and np.linalg.norm(trial) < np.linalg.norm(fx):
                break
            lam /= 2.0
            if lam < 1e-6:
                raise ValueError(f"the harmonic balance stalls at W = {x[0]}, w = {x[1]}")
        x, fx = x + lam * step, trial
        if np.all(np.abs(lam * step) <= tol * np.abs(x)):
            break
    else:
        raise ValueError(f"no harmonic balance after {max_iter} Newton steps")
    W, w = x
    n, e = block(W, w)
    return {
        "W": W,
        "w": w,
        "N": n,
        "period": 2.0 * math.pi / w,
        "first_harmonic": abs(n) * W,
        "amplitude": float((e.max() - e.min()) / 2.0),
    }


def main():
    sim = simulated()
    plain = plain_balance(sim["amplitude"], sim["period"])
    gap = open_loop_gap(2.0 * math.pi / sim["period"])
    p = predict()
    need, have, ratio = plain["need"], plain["have"], sim["ratio"]
    rel = {k: p[k] / sim[k] - 1.0 for k in ("amplitude", "first_harmonic", "period")}

    def deg(z):
        return math.degrees(math.atan2(z.imag, z.real))

    print("Hunting of the 1995 PID experiment (Fig. 8; Table I friction, Kp = 3, Ki = 4, Kv = 6)")
    print(
        f"simulated (lugre dynamics --scenario pid, 100..300 s): amplitude {sim['amplitude']:.5f} m "
        f"(first harmonic {sim['first_harmonic']:.5f} m), period {sim['period']:.4f} s\n"
        "1. the friction's describing function (lugre.sweep) with the linear rest: no solution.\n"
        f"   At the simulated hunting the loop needs N = {need.real:.4f} {need.imag:+.4f}i N/m "
        f"({deg(need):.1f} deg); the friction gives {have.real:.4f} {have.imag:+.4f}i N/m "
        f"({deg(have):.1f} deg).\n"
        f"   Below sqrt(Ki/Kv) it needs k_eq <= {plain['k_eq_needed_max']:.4f} N/m: the sweep's "
        f"least k_eq there is {plain['k_eq_min']:.3g} N/m; above, c_eq < 0: its least c_eq is "
        f"{plain['c_eq_min']:.3g} N s/m.\n"
        "   The whole PID as the linear part, mass + friction under U sin(w t) as the block: no "
        f"solution either.\n   It needs |N_x| = {gap['need']:.4f} m/N; |N_x| jumps from "
        f"{gap['below']:.3g} to {gap['above']:.3g} m/N at U = {gap['U']:.6f} N (stuck below; "
        "above, a slip that nothing stops).\n"
        "2. mass + friction + PD under the integral force W sin(w t), closed by Ki / s:\n"
        f"   balance at W = {p['W']:.5f} N, w = {p['w']:.5f} rad/s "
        f"(N_e = {abs(p['N']):.5f} m/N at {deg(p['N']):.3f} deg)\n"
        f"   predicted amplitude {p['amplitude']:.5f} m (first harmonic "
        f"{p['first_harmonic']:.5f} m), period {p['period']:.4f} s\n"
        f"   against the simulation: amplitude {rel['amplitude']:+.2%}, first harmonic "
        f"{rel['first_harmonic']:+.2%}, period {rel['period']:+.2%}\n"
        f"   why not closer: in the simulated cycle e_1 / W_1 = {abs(ratio):.6f} m/N at "
        f"{deg(ratio):.3f} deg (the balance holds), but the integral force is no sine: it peaks "
        f"at {sim['integral_peak']:.4f} N with W_1 = {sim['integral_first_harmonic']:.4f} N "
        f"(peak / W_1 = {sim['integral_peak'] / sim['integral_first_harmonic']:.3f}; a sine: 1)."
    )
    plain.update(open_loop=gap)
    return sim, plain, p


if __name__ == "__main__":
    main()
