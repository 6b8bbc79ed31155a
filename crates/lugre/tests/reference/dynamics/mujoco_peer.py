#!/usr/bin/env python3
"""MuJoCo's LuGre (`dcmotor` actuator with `lugre=`) on the break-away and stick-slip experiments,
timed and compared with reference.json (made by make_dynamics_reference.py).

    /tmp/venv-ref/bin/pip install mujoco        # 4.0.0 used
    /tmp/venv-ref/bin/python crates/lugre/tests/reference/dynamics/mujoco_peer.py \\
        > crates/lugre/tests/reference/dynamics/mujoco_peer.txt

A 1 kg body on a slide joint, gravity off; the actuator as a passive friction element (sigma2
through `damping`, the Stribeck exponent fixed at 2 as in the paper).  The drive goes through
data.qfrc_applied, set from the state at t_n before each mj_step; the friction force at t_n is
-(actuator_force + qfrc_passive) read after that step (mj_step's forward pass runs at t_n), paired
with x_n, v_n, z_n = act read before it.

Events on the discrete sequence, refined by the parabola through the three samples around it:
  * break-away: first n with F_{n-1} < F_n >= F_{n+1};
  * stick-slip slip onset: local maximum of the spring force k (0.1 t - x);
  * samples at t = 10, 20, 30: the step n = round(t / h) (no interpolation).
Errors are relative to max(|ref|, natural scale) as in make_dynamics_reference.py (x 5e-5 m for
break-away, 2.5 m for stick-slip; v 5e-3 / 0.2 m/s; z 1.5e-5 m; forces 1.5 N; times themselves).
Times are whole experiments (all six rates / 30 s), best of 3, Python loop included (it dominates:
a bare mj_step is ~1 us here).
"""

import json
import os
import sys
import time

import mujoco
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))

XML = '''<mujoco>
 <option gravity="0 0 0" timestep="{h}" integrator="{integrator}"/>
 <worldbody><body name="b"><joint name="slide" type="slide" axis="1 0 0"/>
   <inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/></body></worldbody>
 <actuator><dcmotor joint="slide" input="none" motorconst="0 0" resistance="1"
   lugre="1e5 316.22776601683796 1 1.5 0.001" damping="0.4"/></actuator>
</mujoco>'''

RATES = [1.0, 2.0, 5.0, 10.0, 20.0, 50.0]
K, VD = 2.0, 0.1


def make(h, integrator):
    m = mujoco.MjModel.from_xml_string(XML.format(h=repr(h), integrator=integrator))
    return m, mujoco.MjData(m)


def parabola(ts, ys, i):
    """Vertex of the parabola through (ts[i-1..i+1], ys[i-1..i+1]): (t, y, weights for others)."""
    y0, y1, y2 = ys[i - 1], ys[i], ys[i + 1]
    den = y0 - 2 * y1 + y2
    s = 0.5 * (y0 - y2) / den if den != 0 else 0.0   # offset in steps from i
    h = ts[i + 1] - ts[i]
    y = y1 - 0.25 * (y0 - y2) * s
    return ts[i] + s * h, y, s


def interp(arr, i, s):
    """Value of a sampled sequence at step i + s (quadratic through i-1, i, i+1)."""
    a0, a1, a2 = arr[i - 1], arr[i], arr[i + 1]
    return a1 + 0.5 * s * (a2 - a0) + 0.5 * s * s * (a2 - 2 * a1 + a0)


def breakaway(h, integrator):
    out = []
    for r in RATES:
        m, d = make(h, integrator)
        T, X, V, Z, F = [], [], [], [], []
        nmax = int(3.0 / r / h) + 3
        for n in range(nmax):
            t = n * h
            T.append(t)
            X.append(d.qpos[0])
            V.append(d.qvel[0])
            Z.append(d.act[0])
            d.qfrc_applied[0] = r * t
            mujoco.mj_step(m, d)
            F.append(-(d.actuator_force[0] + d.qfrc_passive[0]))
            if n >= 2 and F[-3] < F[-2] >= F[-1]:
                i = n - 1
                tb, Fb, s = parabola(T, F, i)
                out.append(dict(rate=r, t=tb, F=Fb, x=interp(X, i, s), v=interp(V, i, s),
                                z=interp(Z, i, s)))
                break
        else:
            out.append(dict(rate=r, t=float('nan'), F=float('nan'), x=float('nan'),
                            v=float('nan'), z=float('nan')))
    return out


def stickslip(h, integrator):
    m, d = make(h, integrator)
    N = int(round(30.0 / h))
    T, X, V, Z, S = [], [], [], [], []
    for n in range(N + 1):
        t = n * h
        x = d.qpos[0]
        T.append(t)
        X.append(x)
        V.append(d.qvel[0])
        Z.append(d.act[0])
        S.append(K * (VD * t - x))
        if n == N:
            break
        d.qfrc_applied[0] = K * (VD * t - x)
        mujoco.mj_step(m, d)
    onsets = []
    for i in range(1, N):
        if S[i - 1] < S[i] >= S[i + 1] and S[i] > 1.0:
            onsets.append(parabola(T, S, i)[:2])
    samples = []
    for t in (10.0, 20.0, 30.0):
        n = int(round(t / h))
        samples.append(dict(t=t, x=X[n], v=V[n], z=Z[n]))
    return dict(onsets=onsets, samples=samples)


def timed(fn, *a):
    best, res = None, None
    for _ in range(3):
        t0 = time.perf_counter()
        res = fn(*a)
        el = time.perf_counter() - t0
        best = el if best is None else min(best, el)
    return res, best


def rel(a, b, floor=0.0):
    return abs(a - b) / max(abs(b), floor)


def main():
    with open(os.path.join(HERE, 'reference.json')) as fh:
        ref = json.load(fh)
    rb = ref['breakaway']['values']['rates']
    rs = ref['stickslip']['values']
    print('mujoco', mujoco.__version__, 'python', sys.version.split()[0])
    rows = []
    for integrator, h in (('Euler', 1e-3), ('Euler', 2e-3), ('implicitfast', 1e-3),
                          ('RK4', 1e-3), ('Euler', 5e-4)):
        b, tb = timed(breakaway, h, integrator)
        s, ts = timed(stickslip, h, integrator)
        print('=' * 90)
        print('%s h = %g: break-away %.3f s, stick-slip %.3f s' % (integrator, h, tb, ts))
        eb = dict(t=0.0, F=0.0, x=0.0)
        for got, want in zip(b, rb):
            e = dict(t=rel(got['t'], want['t']), F=rel(got['F'], want['F']),
                     x=rel(got['x'], want['x'], 5e-5))
            for k in eb:
                eb[k] = max(eb[k], e[k]) if e[k] == e[k] else float('inf')
            print('  r = %-4g t %-12.6g (%.1e)  F %-12.6g (%.1e)  x %-12.6g (%.1e)' % (
                got['rate'], got['t'], e['t'], got['F'], e['F'], got['x'], e['x']))
        on = s['onsets']
        ref_on = rs['slip_onsets']
        e_on = max((rel(a[0], w['t']) for a, w in zip(on, ref_on)), default=float('inf'))
        e_pk = max((rel(a[1], w['spring_force']) for a, w in zip(on, ref_on)), default=float('inf'))
        per = [on[j][0] - on[j - 1][0] for j in range(1, len(on))]
        ref_per = rs['periods'][-1]
        e_per = max((rel(p, ref_per) for p in per), default=float('inf'))
        e_x = max(rel(g['x'], w['x'], 2.5) for g, w in zip(s['samples'], rs['samples']))
        e_v = max(rel(g['v'], w['v'], 0.2) for g, w in zip(s['samples'], rs['samples']))
        e_z = max(rel(g['z'], w['z'], 1.5e-5) for g, w in zip(s['samples'], rs['samples']))
        print('  stick-slip: %d onsets (ref %d): %s' % (len(on), len(ref_on),
                                                       ', '.join('%.5f' % a[0] for a in on)))
        print('    periods %s (ref %.6f); peak spring force %s (ref %.6f)' % (
            ', '.join('%.5f' % p for p in per), ref_per,
            ', '.join('%.5f' % a[1] for a in on), rs['peak_spring_force']))
        print('    samples x %s v %s z %s' % (
            ', '.join('%.6g' % g['x'] for g in s['samples']),
            ', '.join('%.4g' % g['v'] for g in s['samples']),
            ', '.join('%.4g' % g['z'] for g in s['samples'])))
        rows.append((integrator, h, tb, eb, ts, e_on, e_per, e_pk, e_x, e_v, e_z, len(on), len(ref_on)))
    print('=' * 90)
    print('| integrator | h | break-away time | worst rel err t / F / x | stick-slip time | onsets | '
          'onset t | period | peak spring F | samples x / v / z |')
    print('| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |')
    for (integ, h, tb, eb, ts, e_on, e_per, e_pk, e_x, e_v, e_z, n_on, n_ref) in rows:
        print('| %s | %g | %.3f s | %.1e / %.1e / %.1e | %.3f s | %d of %d | %.1e | %.1e | %.1e | '
              '%.1e / %.1e / %.1e |' % (integ, h, tb, eb['t'], eb['F'], eb['x'], ts, n_on, n_ref,
                                        e_on, e_per, e_pk, e_x, e_v, e_z))


if __name__ == '__main__':
    main()
