#!/usr/bin/env python3
"""Independent reference values for closed-loop LuGre dynamics (Canudas de Wit, Olsson, Astrom,
Lischinsky, IEEE TAC 40(3), 1995, Table I parameters and the experiments of Figs. 2, 3, 4, 6, 8).

Nothing here uses the crate.  Every number comes from scipy's integrators (and, for the smooth
frictional-lag problem, mpmath's Taylor-series ODE solver) applied to the model as written below.

Made with (from the repository root; ~3.5 minutes on 2 shared cores, of which ~1 minute is the
peer timings and 15 s the mpmath check):

    python3 -m venv /tmp/venv-ref && /tmp/venv-ref/bin/pip install numpy scipy mpmath
    /tmp/venv-ref/bin/python crates/lugre/tests/reference/dynamics/make_dynamics_reference.py \\
        > crates/lugre/tests/reference/dynamics/summary.txt

with Python 3.11.7, numpy 2.4.6, scipy 1.17.1, mpmath 1.4.1.  It writes reference.json beside
itself (floats written by repr, so every digit round-trips) and prints a human summary.
`--no-peers` skips the scipy peer timings, `--no-mpmath` the mpmath check of experiment 4.

Model (SI units).  State (x, v, z) plus, for PID, the integral state I:
    g(v) = Fc + (Fs - Fc) exp(-(v/vs)^2)
    z'   = v - sigma0 |v| z / g(v)
    F    = sigma0 z + sigma1 z' + sigma2 v           (friction force on the mass)
    M v' = F_drive - F,  x' = v,  I' = x - xd
    sigma0 = 1e5, sigma1 = sqrt(1e5), sigma2 = 0.4, Fc = 1, Fs = 1.5, vs = 1e-3, M = 1; all at rest.

How the reference is made.
  * The solvers (scipy.integrate.Radau / LSODA / DOP853, analytic Jacobian for the implicit ones)
    are stepped by a small driver of our own instead of solve_ivp, so that
      - every integration stops exactly at the kinks of a piecewise-linear drive and at every
        reported sample time (reported states are step end values, not interpolants);
      - events (v = 0, x = xd, v = 0.1, dF/dt = 0, ...) are located by Brent's method on the
        step's dense output to 4 ulp in t, using the sign of the event function at the step's own
        end values (LSODA's interpolant does not pass exactly through them, which makes
        solve_ivp's own event code fail with "f(a) and f(b) must have different signs");
      - "v-split" mode: |v| makes the right-hand side only Lipschitz at v = 0, so each crossing of
        v = 0 ends the integration and it restarts with the sign of v frozen (|v| -> s v, a smooth
        extension), i.e. every piece is integrated with a smooth right-hand side.  Where the mass
        rings down to rest at v = 0 (pre-sliding holds) the crossings never end; once a crossing
        happens with |v'| < 1e-8 m/s^2 splitting is dropped until the next breakpoint (the ringing
        amplitude is then < 1e-10 m/s and its kinks are below the error tolerance).
  * The reference value is Radau, rtol 1e-12, v-split, atol (x, v, z[, I]) = (1e-16, 1e-15,
    1e-18) for pre-sliding and break-away, (1e-14, 1e-15, 1e-18[, 1e-14]) for stick-slip and PID
    (atol scales with rtol in the other runs).  The brief's atol (x 1e-14, v 1e-13, z 1e-16) is too
    loose for the pre-sliding experiment (x ~ 4.5e-5): LSODA then differs from Radau by 2e-8
    relative in x (2e-7 in the PID control force at t = 80); with the tighter atol all methods
    converge.  atol_v cannot go much below 1e-15: v' is a difference of O(1) forces, v carries a
    round-off floor, and Radau stalls in the pre-sliding holds with atol_v = 1e-17.
  * Estimated error of each quantity ("abs_err" in reference.json, beside every value) = the
    largest difference between the reference and the runs  Radau 1e-11 v-split, Radau 1e-12 no
    split, LSODA 1e-12 and 1e-13 v-split, LSODA 1e-13 no split, DOP853 1e-12 v-split.  This is
    conservative: it is dominated by LSODA at 1e-12 (Radau and DOP853 agree ~10x to 100x better).
    Experiment 4 uses Radau 1e-12 as reference and LSODA 1e-13, DOP853 1e-13 and, for w = 10 and
    25, mpmath.odefun at 25 digits (agrees with Radau to 2e-14 relative) for the estimate.
    Worst relative estimate per experiment (relative to max(|value|, natural scale), see summary.txt):
      - pre-sliding:   x ~2e-14 m (4e-10 relative), v ~1e-14 m/s, z ~3e-18 m, F ~3e-13 N
      - break-away:    t, F, x, v, z within 2e-10 relative (most 1e-11)
      - stick-slip:    onsets/periods ~6e-10 s (3e-11 relative), peak spring force 1e-11 relative,
                       samples ~1e-10 relative
      - frictional lag: z within 3e-17 m (2e-12 relative), F within 3e-12 N
      - PID:           event times ~3e-9 s at t ~ 90 s (4e-11 relative, phase drift), samples
                       within 5e-9 relative (u at t = 80 s, during a slip); limit-cycle period
                       24.43678645599 +- 1.2e-10 s, parking positions +- 5e-13 m
    Quantities that are ~0 by nature (v while stuck, ~1e-6 m/s; v at rest in the pre-sliding
    holds, ~1e-21 m/s) are accurate in absolute terms only (their abs_err is what counts).

Peer timings (scipy as the solver the Rust one is compared with): for each experiment, Radau,
BDF and LSODA at rtol 1e-3 ... 1e-10 (atol = the reference atol * rtol / 1e-12), run the plain way
(no v-split, samples from the dense output, restarts only at the drive's kinks, same event
location), error = max over every reported quantity of |q - ref| / max(|ref|, natural scale);
the loosest rtol of each method meeting 1e-6 is timed (best of 3) and the fastest reported, plus
the same integration as a bare solve_ivp call without events or dense output.

Definitions chosen (also in reference.json "definitions"):
  * pre-sliding (exp. 1): x_max / x_min are the sup / inf of x over [0, 65].  They are not local
    extremes: in each hold the mass rings down to rest at v = 0 (x oscillating with an upward /
    downward drift), so they equal x(15) = x(65) and x(40) up to the ~1e-21 m/s ringing left.
    The first four local extremes of x (v = 0) after t = 10, 35 and 60 are reported separately.
  * break-away (exp. 2): the first local maximum of the friction force F(t): the first root of
    dF/dt (analytic, from the state) crossing from + to -, located on the dense output; F and x
    evaluated there.  Cross-checked by a bounded scalar minimiser of -F on the dense output and by
    re-integrating to exactly t_break.
  * stick-slip slip onset (exp. 3): local maximum of the spring force k (0.1 t - x), i.e. v
    crossing 0.1 m/s upward (the spring force rises while v < 0.1); also reported: v crossing
    vs = 1e-3 m/s upward.  Stick onset: first v = 0 after a slip.  Period: difference of successive
    slip onsets.
  * PID (exp. 5): period = difference of successive upward crossings of x = xd (also given for
    downward crossings and for stops on the same side).  A "stop" is the first v = 0 after a
    crossing of xd: the local extreme of x that ends the slip; its x is the parking position (the
    mass then creeps back by ~9e-5 m while stuck, as the bristles reverse; x where |v| next
    exceeds vs is reported too).  Limit-cycle values come from a run to
    200 s (converged to < 1e-10 by then); the values in [0, 100] are reported as they are.
"""

import json
import math
import os
import sys
import time

import mpmath
import numpy as np
import scipy
from scipy.integrate import BDF, DOP853, LSODA, Radau
from scipy.optimize import brentq, minimize_scalar

HERE = os.path.dirname(os.path.abspath(__file__))

S0 = 1e5
S1 = math.sqrt(1e5)
S2 = 0.4
FC = 1.0
FS = 1.5
VS = 1e-3
M = 1.0


def gfun(v):
    e = math.exp(-(v / VS) ** 2)
    return FC + (FS - FC) * e, (FS - FC) * e * (-2.0 * v / VS ** 2)


class Model:
    """drive(t, y) -> (F_drive, dF_drive/dy).  n = 4 adds the integral state I' = x - xd.
    sgn: None -> |v| as it is; +1/-1 -> |v| replaced by sgn * v (smooth extension)."""

    def __init__(self, drive, n=3, xd=None):
        self.drive = drive
        self.n = n
        self.xd = xd
        self.sgn = None

    def parts(self, t, y):
        v, z = y[1], y[2]
        s = self.sgn
        if s is None:
            av = abs(v)
            sv = 1.0 if v > 0 else (-1.0 if v < 0 else 0.0)
        else:
            av = s * v
            sv = s
        g, gp = gfun(v)
        a = av / g                      # |v| / g
        ap = sv / g - av * gp / g ** 2  # d(|v| / g)/dv
        zd = v - S0 * a * z
        F = S0 * z + S1 * zd + S2 * v
        Fd, dFd = self.drive(t, y)
        vd = (Fd - F) / M
        return a, ap, zd, F, Fd, dFd, vd

    def rhs(self, t, y):
        a, ap, zd, F, Fd, dFd, vd = self.parts(t, y)
        out = [y[1], vd, zd]
        if self.n == 4:
            out.append(y[0] - self.xd)
        return out

    def jac(self, t, y):
        a, ap, zd, F, Fd, dFd, vd = self.parts(t, y)
        J = np.zeros((self.n, self.n))
        dzd_dv = 1.0 - S0 * ap * y[2]
        dzd_dz = -S0 * a
        J[0, 1] = 1.0
        J[1, :] = np.asarray(dFd, float) / M
        J[1, 1] -= (S1 * dzd_dv + S2) / M
        J[1, 2] -= (S0 + S1 * dzd_dz) / M
        J[2, 1] = dzd_dv
        J[2, 2] = dzd_dz
        if self.n == 4:
            J[3, 0] = 1.0
        return J

    def F(self, t, y):
        return self.parts(t, y)[3]

    def Fd(self, t, y):
        return self.parts(t, y)[4]

    def dFdt(self, t, y):
        a, ap, zd, F, Fd, dFd, vd = self.parts(t, y)
        zdd = vd - S0 * (ap * vd * y[2] + a * zd)
        return S0 * zd + S1 * zdd + S2 * vd


METHODS = dict(Radau=Radau, LSODA=LSODA, BDF=BDF, DOP853=DOP853)
EPS = np.finfo(float).eps


def pick_sign(model, t, y, delta=1e-6):
    """The side of v = 0 the motion is on, or about to move to, at (t, y)."""
    v = y[1]
    if abs(v) > 1e-12:
        return 1 if v > 0 else -1
    s = model.sgn
    model.sgn = None
    acc = model.rhs(t + delta, y)[1]
    model.sgn = s
    return 1 if acc >= 0 else -1


def _root(f, dense, ta, ga, tb, gb):
    """Root of f(t, dense(t)) in [ta, tb]; the end values are the step's own (ga, gb)."""
    def h(s):
        if s == ta:
            return ga
        if s == tb:
            return gb
        return f(s, dense(s))
    return brentq(h, ta, tb, xtol=4 * EPS, rtol=4 * EPS)


def integrate(model, y0, t0, breakpoints, method, rtol, atol, vsplit, events=(),
              min_split_acc=1e-8, stop=None):
    """Integrate from t0 to max(breakpoints), stopping exactly at every breakpoint.
    events: (name, f(t, y), direction) located on the dense output; 'v0' (v = 0) is always there.
    vsplit: restart at every v = 0 with the sign of v frozen per piece (see module docstring).
    stop: (name, count) ends the run at the count-th event `name`."""
    Cls = METHODS[method]
    t = float(t0)
    y = np.array(y0, float)
    pieces = []
    rec = {name: [] for name, _, _ in events}
    rec['v0'] = []
    at = {}
    nsteps = nsplit = 0
    done = False
    allev = list(events) + [('v0', lambda tt, yy: yy[1], 0)]
    for b in sorted(breakpoints):
        split = vsplit
        model.sgn = pick_sign(model, t, y) if split else None
        while t < b and not done:
            kw = dict(rtol=rtol, atol=atol)
            if method != 'DOP853':
                kw['jac'] = model.jac
            solver = Cls(model.rhs, t, y, b, **kw)
            tp0 = t
            gs = [f(t, y) for _, f, _ in allev]
            cut = None
            while solver.status == 'running':
                t_old = solver.t
                msg = solver.step()
                if solver.status == 'failed':
                    raise RuntimeError('%s at t=%r: %s' % (method, t_old, msg))
                nsteps += 1
                tn, yn = solver.t, solver.y
                dn = solver.dense_output()
                hits = []
                for k, (name, f, d) in enumerate(allev):
                    go, gn = gs[k], f(tn, yn)
                    gs[k] = gn
                    if name == 'v0' and split:
                        d = -model.sgn
                    first = t_old == tp0
                    up = (go < 0 < gn) or (go == 0 < gn and not first)
                    down = (go > 0 > gn) or (go == 0 > gn and not first)
                    if (up and d >= 0) or (down and d <= 0):
                        hits.append((_root(f, dn, t_old, go, tn, gn), k))
                hits.sort()
                for te, k in hits:
                    name = allev[k][0]
                    ye = dn(te)
                    rec[name].append((te, ye.copy(), model.sgn))
                    if name == 'v0' and split:
                        cut = (te, ye)
                        break
                    if stop is not None and name == stop[0] and len(rec[name]) >= stop[1]:
                        cut = (te, ye)
                        done = True
                        break
                if cut is not None:
                    break
                pieces.append((t_old, tn, dn, model.sgn))
            if cut is None:
                t = solver.t
                y = solver.y.copy()
                continue
            te, ye = cut
            pieces.append((t_old, te, dn, model.sgn))
            t = te
            y = ye.copy()
            if done:
                break
            nsplit += 1
            acc = model.rhs(te, ye)[1]
            y[1] = 0.0
            if abs(acc) < min_split_acc:
                split = False
                model.sgn = None
            else:
                model.sgn = -model.sgn
        at[b] = (y.copy(), model.sgn)
        if done:
            break
    return dict(pieces=pieces, events=rec, at=at, nsteps=nsteps, nsplit=nsplit, t_end=t, y_end=y)


def dense(res, t):
    """(state, sign mode) at t from the run's dense output."""
    P = res['pieces']
    if '_starts' not in res:
        res['_starts'] = np.array([p[0] for p in P])
    i = int(np.searchsorted(res['_starts'], t, side='right')) - 1
    i = max(0, min(i, len(P) - 1))
    a, b, s, sg = P[i]
    if not (a - 1e-12 <= t <= b + 1e-12):
        raise ValueError(t)
    return s(t), sg


def state_at(res, model, b):
    y, sg = res['at'][b]
    model.sgn = sg
    return y


# --------------------------------------------------------------------------------------------
# The experiments.  Each run(cfg) returns a flat dict name -> float; names use '.' for nesting and
# integers for list positions (unflattened into reference.json).  FLOORS gives, per experiment, a
# function name -> scale used for relative errors (max(|ref|, floor)).
# --------------------------------------------------------------------------------------------

def atol_for(atol12, rtol):
    """atol proportional to rtol; atol12 is the vector used at rtol = 1e-12.  Not tighter: v' is a
    difference of O(1) forces, so v carries a round-off floor of ~1e-16 * h and Radau stalls when
    atol_v comes near it (seen with atol_v = 1e-17 in the pre-sliding holds)."""
    return [rtol / 1e-12 * s for s in atol12]


# 1. pre-sliding (Fig. 2) ---------------------------------------------------------------------
E1_KT = [0.0, 10.0, 15.0, 35.0, 40.0, 60.0, 65.0]
E1_KF = [0.0, 1.425, 1.425, -1.425, -1.425, 1.425, 1.425]
E1_TIMES = [5.0, 10.0, 15.0, 25.0, 35.0, 40.0, 50.0, 60.0, 65.0]
E1_ATOL12 = [1e-16, 1e-15, 1e-18]


def e1_drive(t, y):
    return float(np.interp(t, E1_KT, E1_KF)), [0.0, 0.0, 0.0]


def run_presliding(method, rtol, vsplit, atol=None, peer=False):
    m = Model(e1_drive)
    atol = atol if atol is not None else atol_for(E1_ATOL12, rtol)
    bps = E1_KT[1:] if peer else sorted(set(E1_KT[1:] + E1_TIMES))
    r = integrate(m, [0, 0, 0], 0.0, bps, method, rtol, atol, vsplit)
    q = {}
    for i, t in enumerate(E1_TIMES):
        if peer:
            y, m.sgn = dense(r, t)
        else:
            y = state_at(r, m, t)
        q['samples.%d.t' % i] = t
        q['samples.%d.x' % i] = y[0]
        q['samples.%d.v' % i] = y[1]
        q['samples.%d.z' % i] = y[2]
        q['samples.%d.F' % i] = m.F(t, y)
    # local extremes of x (v = 0) after the two kinks where the force starts being held
    ext = r['events']['v0']
    for name, t0 in (('after_10', 10.0), ('after_35', 35.0), ('after_60', 60.0)):
        sel = [(te, ye) for te, ye, _ in ext if t0 < te < t0 + 5][:4]
        for j, (te, ye) in enumerate(sel):
            q['x_extremes_%s.%d.t' % (name, j)] = te
            q['x_extremes_%s.%d.x' % (name, j)] = ye[0]
    allx = [ye[0] for _, ye, _ in ext] + [q['samples.%d.x' % i] for i in range(len(E1_TIMES))]
    q['x_max'] = max(allx)
    q['x_min'] = min(allx)
    return q, r


def floors_presliding(name):
    if name.endswith('.t'):
        return 1.0
    if name.endswith('.F'):
        return FS
    if name.endswith('.v'):
        return 3e-5
    return 4.5e-5


# 2. break-away vs force rate (Fig. 4) --------------------------------------------------------
E2_RATES = [1.0, 2.0, 5.0, 10.0, 20.0, 50.0]
E2_ATOL12 = [1e-16, 1e-15, 1e-18]


def run_breakaway(method, rtol, vsplit, atol=None, peer=False, checks=False):
    q = {}
    runs = []
    for i, rate in enumerate(E2_RATES):
        m = Model(lambda t, y, rate=rate: (rate * t, [0.0, 0.0, 0.0]))
        at = atol if atol is not None else atol_for(E2_ATOL12, rtol)
        r = integrate(m, [0, 0, 0], 0.0, [3.0 / rate], method, rtol, at, vsplit,
                      events=[('dF', m.dFdt, -1)], stop=('dF', 1))
        te, ye, sg = r['events']['dF'][0]
        m.sgn = sg
        q['rates.%d.rate' % i] = rate
        q['rates.%d.t' % i] = te
        q['rates.%d.F' % i] = m.F(te, ye)
        q['rates.%d.x' % i] = ye[0]
        q['rates.%d.v' % i] = ye[1]
        q['rates.%d.z' % i] = ye[2]
        if checks:
            # (a) bounded scalar minimiser of -F on the dense output around the root
            def negF(t):
                y, m.sgn = dense(r, t)
                return -m.F(t, y)
            w = 1e-3 * te
            mres = minimize_scalar(negF, bounds=(te - w, min(te + w, r['t_end'])), method='bounded',
                                   options=dict(xatol=1e-14))
            q['check.%d.t_minimiser' % i] = mres.x
            q['check.%d.F_minimiser' % i] = -mres.fun
            # (b) re-integrate to exactly t_break, F from the step end value
            r2 = integrate(m, [0, 0, 0], 0.0, [te], method, rtol, at, vsplit)
            y2 = state_at(r2, m, te)
            q['check.%d.F_reintegrated' % i] = m.F(te, y2)
            q['check.%d.x_reintegrated' % i] = y2[0]
            # (c) no other local maximum of F before it (scan of the dense output)
            ts = np.linspace(0, te, 4001)[1:-1]
            Fs_ = []
            for t in ts:
                y, m.sgn = dense(r, t)
                Fs_.append(m.F(t, y))
            q['check.%d.F_monotone_before' % i] = float(np.all(np.diff(Fs_) > 0))
        runs.append(r)
    return q, runs


def floors_breakaway(name):
    if name.endswith('.x'):
        return 5e-5
    if name.endswith('.v'):
        return 5e-3
    if name.endswith('.z'):
        return 1.5e-5
    return 0.0  # t and F: relative to themselves


# 3. stick-slip (Fig. 6) ----------------------------------------------------------------------
E3_K = 2.0
E3_VD = 0.1
E3_TIMES = [10.0, 20.0, 30.0]
E3_ATOL12 = [1e-14, 1e-15, 1e-18]


def e3_drive(t, y):
    return E3_K * (E3_VD * t - y[0]), [-E3_K, 0.0, 0.0]


def run_stickslip(method, rtol, vsplit, atol=None, peer=False):
    m = Model(e3_drive)
    atol = atol if atol is not None else atol_for(E3_ATOL12, rtol)
    evs = [('onset', lambda t, y: y[1] - E3_VD, 1),
           ('onset_vs', lambda t, y: y[1] - VS, 1)]
    bps = [30.0] if peer else E3_TIMES
    r = integrate(m, [0, 0, 0], 0.0, bps, method, rtol, atol, vsplit, events=evs)
    q = {}
    for i, t in enumerate(E3_TIMES):
        if peer:
            y, m.sgn = dense(r, t)
        else:
            y = state_at(r, m, t)
        q['samples.%d.t' % i] = t
        q['samples.%d.x' % i] = y[0]
        q['samples.%d.v' % i] = y[1]
        q['samples.%d.z' % i] = y[2]
        q['samples.%d.F' % i] = m.F(t, y)
        q['samples.%d.spring' % i] = E3_K * (E3_VD * t - y[0])
    on = r['events']['onset']
    for j, (te, ye, sg) in enumerate(on):
        q['slip_onsets.%d.t' % j] = te
        q['slip_onsets.%d.spring_force' % j] = E3_K * (E3_VD * te - ye[0])
        q['slip_onsets.%d.x' % j] = ye[0]
        if j:
            q['periods.%d' % (j - 1)] = te - on[j - 1][0]
    for j, (te, ye, sg) in enumerate(r['events']['onset_vs']):
        q['slip_onsets_vs.%d.t' % j] = te
    # stick onsets: first v = 0 after each slip (after each onset)
    v0 = [te for te, _, _ in r['events']['v0']]
    for j, (te, ye, sg) in enumerate(on):
        later = [s for s in v0 if s > te]
        if later:
            s = later[0]
            q['stick_onsets.%d.t' % j] = s
    q['peak_spring_force'] = max(q['slip_onsets.%d.spring_force' % j] for j in range(len(on)))
    q['check.n_v0_crossings'] = float(len(v0))
    return q, r


def floors_stickslip(name):
    if name.endswith('.z'):
        return 1.5e-5
    if name.endswith('.v'):
        return 0.2
    if name.endswith('.x'):
        return 2.5
    if 'spring' in name or name.endswith('.F'):
        return FS
    return 0.0


# 4. frictional lag (Fig. 3) ------------------------------------------------------------------
E4_W = [1.0, 10.0, 25.0]


def e4_times(w):
    T = 2 * math.pi / w
    return [k * 3 * T / 12 for k in range(1, 13)]


def e4_v(w, t):
    return 1e-3 * (math.cos(w * t) + 1.5)


def run_lag(method, rtol, vsplit=None, atol=1e-20, peer=False):
    q = {}
    for i, w in enumerate(E4_W):
        def rhs(t, z, w=w):
            v = e4_v(w, t)
            g, _ = gfun(v)
            return [v - S0 * abs(v) * z[0] / g]

        def jac(t, z, w=w):
            v = e4_v(w, t)
            g, _ = gfun(v)
            return [[-S0 * abs(v) / g]]
        kw = dict(rtol=rtol, atol=atol)
        if method != 'DOP853':
            kw['jac'] = jac
        ts = e4_times(w)
        q['w.%d.w' % i] = w
        if peer:
            from scipy.integrate import solve_ivp
            s = solve_ivp(rhs, (0.0, ts[-1]), [0.0], method=method, t_eval=ts, **kw)
            zs = list(s.y[0])
        else:
            zs = []
            t, z = 0.0, np.array([0.0])
            for tk in ts:
                s = METHODS[method](rhs, t, z, tk, **kw)
                while s.status == 'running':
                    s.step()
                if s.status == 'failed':
                    raise RuntimeError('lag %s failed' % method)
                t, z = tk, s.y.copy()
                zs.append(z[0])
        for j, (t, z) in enumerate(zip(ts, zs)):
            v = e4_v(w, t)
            zd = rhs(t, [z])[0]
            q['w.%d.samples.%d.t' % (i, j)] = t
            q['w.%d.samples.%d.v' % (i, j)] = v
            q['w.%d.samples.%d.z' % (i, j)] = z
            q['w.%d.samples.%d.F' % (i, j)] = S0 * z + S1 * zd + S2 * v
    return q, None


def run_lag_mpmath(ws=(10.0, 25.0), dps=25):
    """mpmath.odefun (Taylor series) on the same ODE, the sample times taken as the exact binary
    values of the f64 times used above."""
    mpmath.mp.dps = dps
    q = {}
    for i, w in enumerate(E4_W):
        if w not in ws:
            continue
        W = mpmath.mpf(w)

        def f(t, z):
            v = mpmath.mpf('1e-3') * (mpmath.cos(W * t) + mpmath.mpf('1.5'))
            g = 1 + mpmath.mpf('0.5') * mpmath.exp(-(v / mpmath.mpf('1e-3')) ** 2)
            return v - S0 * v * z / g
        sol = mpmath.odefun(f, 0, mpmath.mpf(0))
        for j, t in enumerate(e4_times(w)):
            T = mpmath.mpf(t)
            z = sol(T)
            v = mpmath.mpf('1e-3') * (mpmath.cos(W * T) + mpmath.mpf('1.5'))
            F = S0 * z + mpmath.sqrt(mpmath.mpf(100000)) * f(T, z) + mpmath.mpf('0.4') * v
            q['w.%d.samples.%d.z' % (i, j)] = float(z)
            q['w.%d.samples.%d.F' % (i, j)] = float(F)
    return q


def floors_lag(name):
    if name.endswith('.z'):
        return 1.5e-5
    if name.endswith('.F'):
        return FS
    return 0.0


# 5. PID hunting (Fig. 8) ---------------------------------------------------------------------
E5_KP, E5_KI, E5_KV, E5_XD = 3.0, 4.0, 6.0, 1.0
E5_TIMES = [10.0 * k for k in range(1, 11)]
E5_ATOL12 = [1e-14, 1e-15, 1e-18, 1e-14]


def e5_drive(t, y):
    return (-E5_KV * y[1] - E5_KP * (y[0] - E5_XD) - E5_KI * y[3],
            [-E5_KP, -E5_KV, 0.0, -E5_KI])


def run_pid(method, rtol, vsplit, atol=None, peer=False, t_end=100.0):
    m = Model(e5_drive, n=4, xd=E5_XD)
    atol = atol if atol is not None else atol_for(E5_ATOL12, rtol)
    evs = [('xup', lambda t, y: y[0] - E5_XD, 1), ('xdn', lambda t, y: y[0] - E5_XD, -1),
           ('vsup', lambda t, y: y[1] - VS, 1), ('vsdn', lambda t, y: y[1] + VS, -1)]
    times = [t for t in E5_TIMES if t <= t_end]
    bps = [t_end] if peer else sorted(set(times + [t_end]))
    r = integrate(m, [0, 0, 0, 0], 0.0, bps, method, rtol, atol, vsplit, events=evs)
    q = {}
    for i, t in enumerate(times):
        if peer:
            y, m.sgn = dense(r, t)
        else:
            y = state_at(r, m, t)
        q['samples.%d.t' % i] = t
        q['samples.%d.x' % i] = y[0]
        q['samples.%d.v' % i] = y[1]
        q['samples.%d.z' % i] = y[2]
        q['samples.%d.I' % i] = y[3]
        q['samples.%d.u' % i] = m.Fd(t, y)
    ev = r['events']
    up = [te for te, _, _ in ev['xup']]
    dn = [te for te, _, _ in ev['xdn']]
    v0 = [(te, ye) for te, ye, _ in ev['v0']]
    for j, t in enumerate(up):
        q['xd_up.%d' % j] = t
    for j, t in enumerate(dn):
        q['xd_down.%d' % j] = t
    for j in range(1, len(up)):
        q['period_up.%d' % (j - 1)] = up[j] - up[j - 1]
    for j in range(1, len(dn)):
        q['period_down.%d' % (j - 1)] = dn[j] - dn[j - 1]
    # stops: first v = 0 after every crossing of xd; parking position = x there
    cross = sorted([(t, +1) for t in up] + [(t, -1) for t in dn])
    hi = lo = 0
    for t, d in cross:
        later = [(te, ye) for te, ye in v0 if te > t]
        if not later:
            continue
        te, ye = later[0]
        if d > 0:
            q['stops_high.%d.t' % hi] = te
            q['stops_high.%d.x' % hi] = ye[0]
            hi += 1
        else:
            q['stops_low.%d.t' % lo] = te
            q['stops_low.%d.x' % lo] = ye[0]
            lo += 1
    # slip onsets: |v| crossing vs outward after a stop (the first such crossing after it)
    outs = sorted([(te, ye, +1) for te, ye, _ in ev['vsup']] + [(te, ye, -1) for te, ye, _ in ev['vsdn']],
                  key=lambda a: a[0])
    k = 0
    for side in ('high', 'low'):
        j = 0
        while 'stops_%s.%d.t' % (side, j) in q:
            ts = q['stops_%s.%d.t' % (side, j)]
            nxt = [(te, ye) for te, ye, d in outs if te > ts]
            if nxt:
                q['slip_from_%s.%d.t' % (side, j)] = nxt[0][0]
                q['slip_from_%s.%d.x' % (side, j)] = nxt[0][1][0]
            j += 1
    q['check.n_v0_crossings'] = float(len(v0))
    return q, r


def floors_pid(name):
    if name.endswith('.z'):
        return 1.5e-5
    if name.endswith('.v'):
        return 0.3
    if name.endswith('.I'):
        return 0.1
    if name.endswith('.u'):
        return FS
    if name.endswith('.x'):
        return 1.0
    return 0.0


# --------------------------------------------------------------------------------------------
def flatten(node, prefix=''):
    out = {}
    items = node.items() if isinstance(node, dict) else enumerate(node)
    for k, v in items:
        key = '%s.%s' % (prefix, k) if prefix else str(k)
        if isinstance(v, (dict, list)):
            out.update(flatten(v, key))
        else:
            out[key] = v
    return out


def unflatten(flat):
    root = {}
    for key, val in flat.items():
        parts = key.split('.')
        cur = root
        for p in parts[:-1]:
            cur = cur.setdefault(p, {})
        cur[parts[-1]] = val

    def fix(node):
        if isinstance(node, dict):
            node = {k: fix(v) for k, v in node.items()}
            if node and all(k.isdigit() for k in node):
                return [node[str(i)] for i in range(len(node))]
        return node
    return fix(root)


def compare(ref, other, floors):
    """Per-quantity |difference| for the names both have; plus the worst relative one."""
    d = {}
    for k, v in ref.items():
        if k in other and not k.startswith('check.'):
            d[k] = abs(other[k] - v)
    worst = max(((dv / max(abs(ref[k]), floors(k)), k) for k, dv in d.items()
                 if max(abs(ref[k]), floors(k)) > 0), default=(0.0, ''))
    return d, worst


CONFIGS = [  # (label, method, rtol, vsplit)
    ('Radau 1e-11 split', 'Radau', 1e-11, True),
    ('Radau 1e-12 nosplit', 'Radau', 1e-12, False),
    ('LSODA 1e-12 split', 'LSODA', 1e-12, True),
    ('LSODA 1e-13 split', 'LSODA', 1e-13, True),
    ('LSODA 1e-13 nosplit', 'LSODA', 1e-13, False),
    ('DOP853 1e-12 split', 'DOP853', 1e-12, True),
]
REF_CFG = ('Radau 1e-12 split', 'Radau', 1e-12, True)
# the brief's settings (atol x 1e-14, v 1e-13, z 1e-16, I 1e-14), reported, not used for errors
BRIEF_ATOL = {3: [1e-14, 1e-13, 1e-16], 4: [1e-14, 1e-13, 1e-16, 1e-14]}
BRIEF_CFGS = [('Radau 1e-10 brief-atol', 'Radau', 1e-10, False),
              ('Radau 1e-11 brief-atol', 'Radau', 1e-11, False),
              ('LSODA 1e-10 brief-atol', 'LSODA', 1e-10, False),
              ('LSODA 1e-11 brief-atol', 'LSODA', 1e-11, False)]

EXPERIMENTS = [  # (key, runner, floors, state count for the brief's atol)
    ('presliding', run_presliding, floors_presliding, 3),
    ('breakaway', run_breakaway, floors_breakaway, 3),
    ('stickslip', run_stickslip, floors_stickslip, 3),
    ('lag', run_lag, floors_lag, None),
    ('pid', run_pid, floors_pid, 4),
]


def log(*a):
    print(*a, flush=True)


def main():
    if '--peers-only' in sys.argv:
        # re-measure the peer timings against the values already in reference.json
        path = os.path.join(HERE, 'reference.json')
        with open(path) as fh:
            out = json.load(fh)
        summary = {key: (flatten(out[key]['values']), None, floors)
                   for key, _, floors, _ in EXPERIMENTS}
        out['peers'] = peers(summary)
        with open(path, 'w') as fh:
            json.dump(out, fh, indent=1)
            fh.write('\n')
        return
    do_peers = '--no-peers' not in sys.argv
    do_mp = '--no-mpmath' not in sys.argv
    T0 = time.time()
    out = dict(
        meta=dict(
            generator='crates/lugre/tests/reference/dynamics/make_dynamics_reference.py',
            python=sys.version.split()[0], numpy=np.__version__, scipy=scipy.__version__,
            mpmath=mpmath.__version__,
            parameters=dict(sigma0=S0, sigma1=S1, sigma2=S2, Fc=FC, Fs=FS, vs=VS, M=M),
            reference_run='Radau (scipy), rtol 1e-12, analytic Jacobian, restart at every v = 0 '
                          'with the sign of v frozen per piece, atol (x, v, z[, I]) = presliding/breakaway (1e-16, 1e-15, 1e-18), stickslip (1e-14, 1e-15, 1e-18), pid (1e-14, 1e-15, 1e-18, 1e-14), scaled with rtol for the other runs, '
                          'stops exactly at kinks and sample times',
            abs_err='largest |difference| between the reference and: ' +
                    ', '.join(c[0] for c in CONFIGS) +
                    ' (lag: Radau 1e-12, LSODA 1e-13, DOP853 1e-13, mpmath.odefun at 25 digits for w = 10, 25)',
        ),
        definitions=dict(
            presliding='samples: states at the given t (step end values); x_extremes_after_T: the first '
                       'four local extremes of x (v = 0) after the force starts being held at T; '
                       'x_max / x_min: sup / inf of x over [0, 65], approached (not attained) as the mass '
                       'rings down to rest in the holds [10, 15] and [60, 65] / [35, 40].',
            breakaway='first local maximum of the friction force F(t) under F_drive = r t: first root of '
                      'dF/dt (analytic) crossing + to -, Brent on the dense output; check.* = bounded '
                      'scalar minimiser of -F on the dense output, re-integration to exactly t, and '
                      'F strictly increasing before it (1 = yes).  Up to ~30 N/s this is a sharp peak; '
                      'above ~35 N/s F has no real peak and the first local maximum is a shallow bump '
                      'just above Fc (r = 50: 1.00747 N, then a dip to 1.00394 N).',
            stickslip='slip onset = local maximum of the spring force k (0.1 t - x) = v crossing 0.1 m/s '
                      'upward; slip_onsets_vs = v crossing vs = 1e-3 m/s upward; stick onset = first '
                      'v = 0 after a slip onset; periods = differences of successive slip onsets; '
                      'peak_spring_force = max spring force at the onsets.',
            lag='prescribed v = 1e-3 (cos w t + 1.5), only z integrated; samples at k * 3 T / 12, '
                'k = 1..12, T = 2 pi / w.',
            pid='xd_up / xd_down: crossings of x = xd; period_up = successive xd_up differences; '
                'stops_high / stops_low: first v = 0 after an upward / downward xd crossing, x there '
                '= parking position (local extreme of x ending the slip); slip_from_*: first time '
                '|v| exceeds vs = 1e-3 m/s after that stop (x there: the parking position just before '
                'the next slip; the difference is creep while stuck).  limit_cycle: same from a run '
                'to 200 s, last values.',
        ),
    )
    summary = {}
    for key, runner, floors, nst in EXPERIMENTS:
        log('=' * 100)
        log('experiment', key)
        t0 = time.time()
        if key == 'lag':
            ref, _ = runner('Radau', 1e-12)
            ref = {k: float(v) for k, v in ref.items()}
            others = [('LSODA 1e-13', run_lag('LSODA', 1e-13)[0]),
                      ('DOP853 1e-13', run_lag('DOP853', 1e-13)[0])]
            if do_mp:
                tm = time.time()
                others.append(('mpmath odefun dps 25 (w = 10, 25)', run_lag_mpmath()))
                log('  mpmath check: %.1f s' % (time.time() - tm))
            brief = []
        else:
            kw = dict(checks=True) if key == 'breakaway' else {}
            ref, _ = runner(REF_CFG[1], REF_CFG[2], REF_CFG[3], **kw)
            ref = {k: float(v) for k, v in ref.items()}
            log('  reference run %.1f s' % (time.time() - t0))
            others = []
            for label, meth, rt, vs in CONFIGS:
                tt = time.time()
                q, _ = runner(meth, rt, vs)
                others.append((label, q))
                log('  %-24s %.2f s' % (label, time.time() - tt))
            brief = []
            for label, meth, rt, vs in BRIEF_CFGS:
                q, _ = runner(meth, rt, vs, atol=BRIEF_ATOL[nst])
                brief.append((label, q))
        abs_err = {k: 0.0 for k in ref}
        agreement = []
        for label, q in others:
            d, worst = compare(ref, q, floors)
            for k, dv in d.items():
                if not k.startswith('check.'):
                    abs_err[k] = max(abs_err[k], dv)
            agreement.append((label, worst))
        brief_agreement = [(label, compare(ref, q, floors)[1]) for label, q in brief]
        for label, (w, k) in agreement:
            log('  vs %-36s worst rel diff %.2e  (%s)' % (label, w, k))
        for label, (w, k) in brief_agreement:
            log('  vs %-36s worst rel diff %.2e  (%s)  [brief atol]' % (label, w, k))
        exp = dict(values=unflatten(ref), abs_err=unflatten({k: v for k, v in abs_err.items()
                                                             if not k.startswith('check.')}))
        exp['agreement'] = {label: dict(worst_rel=w, at=k) for label, (w, k) in agreement}
        exp['agreement_brief_atol'] = {label: dict(worst_rel=w, at=k)
                                       for label, (w, k) in brief_agreement}
        if key == 'pid':
            tt = time.time()
            lc, _ = run_pid('Radau', 1e-12, True, t_end=200.0)
            lc2, _ = run_pid('LSODA', 1e-13, True, t_end=200.0)
            lc3, _ = run_pid('DOP853', 1e-12, True, t_end=200.0)
            log('  limit-cycle runs to 200 s: %.1f s' % (time.time() - tt))
            exp['limit_cycle'] = limit_cycle(lc, [lc2, lc3])
        out[key] = exp
        summary[key] = (ref, abs_err, floors)
        log('  done in %.1f s' % (time.time() - t0))
        print_summary(key, ref, abs_err, floors, exp)
    if do_peers:
        out['peers'] = peers(summary)
    path = os.path.join(HERE, 'reference.json')
    with open(path, 'w') as fh:
        json.dump(out, fh, indent=1)
        fh.write('\n')
    log('wrote', path, 'total %.0f s' % (time.time() - T0))


def limit_cycle(q, others):
    def last(prefix):
        j = 0
        while '%s.%d' % (prefix, j) in q or '%s.%d.t' % (prefix, j) in q:
            j += 1
        return j - 1
    res = {}
    for name, key in (('period_up', 'period_up.%d'), ('period_down', 'period_down.%d'),
                      ('parking_high', 'stops_high.%d.x'), ('parking_low', 'stops_low.%d.x'),
                      ('slip_from_high_x', 'slip_from_high.%d.x'),
                      ('slip_from_low_x', 'slip_from_low.%d.x')):
        prefix = key.split('.%d')[0]
        j = last(prefix)
        k = key % j
        vals = [q[key % i] for i in range(j + 1)]
        err = max(abs(o[k] - q[k]) for o in others if k in o)
        res[name] = dict(value=float(q[k]), abs_err=float(err), history=[float(v) for v in vals])
    j = last('stops_high')
    k = 'stops_high.%d.t' % j
    k0 = 'stops_high.%d.t' % (j - 1)
    res['period_stops_high'] = dict(value=float(q[k] - q[k0]),
                                    abs_err=max(abs((o[k] - o[k0]) - (q[k] - q[k0])) for o in others))
    res['symmetry_check_parking'] = dict(
        value=float((res['parking_high']['value'] - E5_XD) - (E5_XD - res['parking_low']['value'])),
        note='0 for a cycle symmetric about xd')
    return res


def print_summary(key, ref, abs_err, floors, exp):
    log('  %-40s %-24s %-10s %-10s' % ('quantity', 'value', 'abs err', 'rel err'))
    for k in ref:
        if k.startswith('check.'):
            continue
        if k.endswith('.t') and ('samples' in k) or k.endswith('.rate') or k.endswith('.w'):
            continue
        sc = max(abs(ref[k]), floors(k))
        rel = abs_err[k] / sc if sc > 0 else float('nan')
        log('  %-40s %-24r %-10.1e %-10.1e' % (k, ref[k], abs_err[k], rel))
    if key == 'breakaway':
        for k in ref:
            if k.startswith('check.'):
                log('  %-40s %r' % (k, ref[k]))
    if 'limit_cycle' in exp:
        for k, v in exp['limit_cycle'].items():
            log('  limit cycle %-28s %r  (+- %s)' % (k, v['value'], '%.1e' % v['abs_err'] if 'abs_err' in v else '-'))


# --------------------------------------------------------------------------------------------
# scipy as the peer: the fastest method / tolerance meeting 1e-6 relative accuracy
# --------------------------------------------------------------------------------------------
PEER_RTOLS = [1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10]
PEER_TARGET = 1e-6


def peers(summary):
    log('=' * 100)
    log('peer timings: plain (no v-split, no restarts at sample times; kinks of the drive are kept as '
        'restart points), atol = the reference atol * rtol / 1e-12 (lag: rtol * 1e-6), error = max over the reported quantities '
        'of |q - ref| / max(|ref|, floor)')
    typ = dict(presliding=E1_ATOL12, breakaway=E2_ATOL12, stickslip=E3_ATOL12, pid=E5_ATOL12)
    res = {}
    for key, runner, floors, nst in EXPERIMENTS:
        ref, _, _ = summary[key]
        rows = []
        best = None
        for meth in ('Radau', 'BDF', 'LSODA'):
            for rt in PEER_RTOLS:
                if key == 'lag':
                    call = lambda: run_lag(meth, rt, atol=rt * 1e-6, peer=True)
                else:
                    call = lambda: runner(meth, rt, False, atol=atol_for(typ[key], rt), peer=True)
                t0 = time.perf_counter()
                try:
                    q, _ = call()
                except Exception as e:  # noqa: BLE001 (a failed loose run is just a failed row)
                    rows.append(dict(method=meth, rtol=rt, error=None, time=time.perf_counter() - t0,
                                     failed=str(e)[:80]))
                    continue
                el = time.perf_counter() - t0
                d, (worst, at) = compare(ref, q, floors)
                missing = [k for k in ref if k not in q and not k.startswith('check.')]
                if missing:
                    worst, at = float('inf'), 'missing ' + missing[0]
                if worst <= PEER_TARGET:
                    times = [el]
                    for _ in range(2):
                        t0 = time.perf_counter()
                        call()
                        times.append(time.perf_counter() - t0)
                    el = min(times)
                rows.append(dict(method=meth, rtol=rt, error=worst, at=at, time=el))
                log('  %-10s %-6s rtol %.0e  err %-9.2e  %.3f s  %s' % (key, meth, rt, worst, el,
                                                                        '' if worst <= PEER_TARGET else '(' + at + ')'))
                if worst <= PEER_TARGET:
                    if best is None or el < best['time']:
                        best = rows[-1]
                    break  # tighter tolerances of this method are slower
        bare = bare_time(key, best['method'], best['rtol'])
        res[key] = dict(fastest=best, bare_solve_ivp_time=bare, rows=rows)
        log('  -> %s: fastest meeting %.0e: %s rtol %.0e, %.3f s (err %.1e); the same as a bare '
            'solve_ivp (no events, no dense output): %.3f s' % (
                key, PEER_TARGET, best['method'], best['rtol'], best['time'], best['error'], bare))
    return res


def bare_time(key, method, rtol):
    """Best of 3 of plain solve_ivp over the experiment (restarts at the drive's kinks only), no
    events, no dense output: the integration alone."""
    from scipy.integrate import solve_ivp
    jobs = []  # (rhs, jac, y0, [(t0, t1), ...], atol)
    if key == 'presliding':
        m = Model(e1_drive)
        jobs.append((m, [0, 0, 0], list(zip(E1_KT[:-1], E1_KT[1:])), atol_for(E1_ATOL12, rtol)))
    elif key == 'breakaway':
        for rate in E2_RATES:
            m = Model(lambda t, y, rate=rate: (rate * t, [0.0, 0.0, 0.0]))
            jobs.append((m, [0, 0, 0], [(0.0, 1.5 / rate if rate < 10 else 2.0 / rate)],
                         atol_for(E2_ATOL12, rtol)))
    elif key == 'stickslip':
        jobs.append((Model(e3_drive), [0, 0, 0], [(0.0, 30.0)], atol_for(E3_ATOL12, rtol)))
    elif key == 'pid':
        jobs.append((Model(e5_drive, n=4, xd=E5_XD), [0, 0, 0, 0], [(0.0, 100.0)],
                     atol_for(E5_ATOL12, rtol)))
    elif key == 'lag':
        best = []
        for _ in range(3):
            t0 = time.perf_counter()
            run_lag(method, rtol, atol=rtol * 1e-6, peer=True)
            best.append(time.perf_counter() - t0)
        return min(best)
    best = []
    for _ in range(3):
        t0 = time.perf_counter()
        for m, y0, spans, atol in jobs:
            y = np.array(y0, float)
            for a, b in spans:
                s = solve_ivp(m.rhs, (a, b), y, method=method, rtol=rtol, atol=atol, jac=m.jac)
                y = s.y[:, -1]
        best.append(time.perf_counter() - t0)
    return min(best)


if __name__ == '__main__':
    main()
