"""Exact references for tests/zoo.rs: Maxwell-slip and Prandtl-Ishlinskii in rational arithmetic.

Written from the models' definitions, independently of the Rust code: each element is updated
on its own along a monotone segment, and the work is the exact integral of the piecewise-linear
force over the segment (its breakpoints found element by element). All inputs are dyadic, so
they are exact in f64 too. Run: python3 crates/lugre/tests/reference/zoo_reference.py
"""
from fractions import Fraction as Q
import random

def maxwell_step(z, k, f, u0, u1):
    """Element deflections after the input moves monotonically from u0 to u1."""
    out = []
    for zi, ki, fi in zip(z, k, f):
        d = fi / ki
        zi = zi + (u1 - u0)
        out.append(max(-d, min(d, zi)))
    return out

def maxwell_force(z, k):
    return sum(ki * zi for ki, zi in zip(k, z))

def play_step(p, r, u0, u1):
    if u1 > u0:
        return [max(pi, u1 - ri) for pi, ri in zip(p, r)]
    return [min(pi, u1 + ri) for pi, ri in zip(p, r)]

def pi_force(u, p, w0, w):
    return w0 * u + sum(wi * pi for wi, pi in zip(w, p))

class Maxwell:
    def __init__(s, k, f): s.k, s.f = k, f
    def rest(s, u): return [Q(0)] * len(s.k)
    def step(s, st, u0, u1): return maxwell_step(st, s.k, s.f, u0, u1)
    def force(s, u, st): return maxwell_force(st, s.k)
    def kinks(s, st, u0, u1):
        # z_i saturates after moving |Delta_i - s z_i|
        out = []
        for zi, ki, fi in zip(st, s.k, s.f):
            d = fi / ki
            at = u0 + (d - zi) if u1 > u0 else u0 - (d + zi)
            out.append(at)
        return out

class PI:
    def __init__(s, w0, r, w): s.w0, s.r, s.w = w0, r, w
    def rest(s, u): return [u] * len(s.r)
    def step(s, st, u0, u1): return play_step(st, s.r, u0, u1)
    def force(s, u, st): return pi_force(u, st, s.w0, s.w)
    def kinks(s, st, u0, u1):
        return [pi + ri if u1 > u0 else pi - ri for pi, ri in zip(st, s.r)]

def segment_work(m, st, u0, u1):
    """Exact integral of F du from u0 to u1 (trapezoids between breakpoints); new state."""
    lo, hi = min(u0, u1), max(u0, u1)
    pts = sorted({x for x in m.kinks(st, u0, u1) if lo < x < hi} | {u0, u1}, reverse=u1 < u0)
    w, cur = Q(0), st
    for a, b in zip(pts, pts[1:]):
        nxt = m.step(cur, a, b)
        w += (m.force(a, cur) + m.force(b, nxt)) / 2 * (b - a)
        cur = nxt
    return w, cur

def rainflow(u):
    """(a, b, p) index triples of ASTM E1049 pairs of the periodic u rotated to its first max."""
    n = len(u)
    r = u.index(max(u))
    seq = [r + j for j in range(n + 1)]  # rotated indices, the last is the max again
    stack, pairs = [], []
    for j in seq:
        stack.append(j)
        while len(stack) >= 3:
            a, b, p = stack[-3], stack[-2], stack[-1]
            if abs(u[p % n] - u[b % n]) < abs(u[b % n] - u[a % n]) or a == r:
                break
            pairs.append((a, b, p))
            del stack[-3:-1]
    return r, pairs

def periodic(m, u):
    """Forces at the turning points and work of every loop, from rest at mid-range."""
    n = len(u)
    r, pairs = rainflow(u)
    hi, lo = max(u), min(u)
    st = m.rest((hi + lo) / 2)
    _, st = segment_work(m, st, (hi + lo) / 2, hi)
    states = {}
    for rep in range(2):  # two periods; keep the second
        for j in range(n):
            a, b = u[(r + j) % n], u[(r + j + 1) % n]
            states[r + j] = st
            _, st = segment_work(m, st, a, b)
    forces = [m.force(u[k], states[r + ((k - r) % n)]) for k in range(n)]
    loops = []
    for a, b, p in pairs:
        st, w = states[a], Q(0)
        for j in range(a, p - 1):
            dw, st = segment_work(m, st, u[j % n], u[(j + 1) % n])
            w += dw
        dw, st = segment_work(m, st, u[(p - 1) % n], u[a % n])
        loops.append((u[a % n], u[b % n], w + dw))
    # the major loop: the whole period
    st, w = states[r], Q(0)
    for j in range(n):
        dw, st = segment_work(m, st, u[(r + j) % n], u[(r + j + 1) % n])
        w += dw
    loops.append((hi, lo, w))
    return forces, loops

def dy(x):  # a dyadic rational
    return Q(x).limit_denominator(1 << 12) if not isinstance(x, Q) else x

def rnd(rng, lo, hi, bits=8):
    return Q(rng.randint(int(lo * (1 << bits)), int(hi * (1 << bits))), 1 << bits)

def f(x):
    return repr(float(x))

def emit_model(name, m, u0, segs, inputs):
    out = [f"// {name}"]
    st, u, rows = m.rest(u0), u0, []
    for x in segs:
        w, st2 = segment_work(m, st, u, x)
        rows.append(f"({f(x)}, {f(m.force(x, st2))}, {f(w)})")
        st, u = st2, x
    out.append(f"const {name}_SEGMENTS: [(f64, f64, f64); {len(rows)}] = [{', '.join(rows)}];")
    for i, inp in enumerate(inputs):
        forces, loops = periodic(m, inp)
        out.append(f"const {name}_INPUT_{i}: [f64; {len(inp)}] = [{', '.join(f(x) for x in inp)}];")
        out.append(f"const {name}_FORCE_{i}: [f64; {len(inp)}] = [{', '.join(f(x) for x in forces)}];")
        out.append(f"const {name}_LOOPS_{i}: [(f64, f64, f64); {len(loops)}] = [{', '.join(f'({f(a)}, {f(b)}, {f(w)})' for a, b, w in loops)}];")
    return "\n".join(out)

def alternate(rng, n, lo, hi):
    """n alternating turning points (a maximum after a minimum and so on)."""
    u = [rnd(rng, lo, hi)]
    while len(u) < n:
        x = rnd(rng, lo, hi)
        if x == u[-1] or (len(u) >= 2 and (x - u[-1]) * (u[-1] - u[-2]) >= 0):
            continue
        u.append(x)
    if (u[0] - u[-1]) * (u[-1] - u[-2]) >= 0 or (u[1] - u[0]) * (u[0] - u[-1]) >= 0:
        return alternate(rng, n, lo, hi)
    return u

rng = random.Random(28)
k = [Q(3), Q(3, 2), Q(3, 4), Q(2), Q(1, 4)]
fs = [Q(3, 8), Q(1, 2), Q(3, 4), Q(1, 4), Q(5, 4)]
mw = Maxwell(k, fs)
r = [Q(1, 16), Q(1, 8), Q(1, 4), Q(1, 2), Q(1)]
w = [Q(1, 2), Q(1, 4), Q(1), Q(-1, 2), Q(3, 8)]
pi = PI(Q(3, 4), r, w)
segs = alternate(rng, 40, -2, 2)
inputs = [
    [Q(0), Q(1), Q(1, 2), Q(3, 2)],
    [Q(-1), Q(3, 2), Q(-1, 2), Q(1), Q(0), Q(5, 4), Q(-3, 4), Q(2)],
    alternate(rng, 24, -3, 3),
]
print("// Generated by crates/lugre/tests/reference/zoo_reference.py (python3, fractions.Fraction)")
print(f"// MAXWELL: stiffness {[f(x) for x in k]}, slip_force {[f(x) for x in fs]}, rest at 0")
print(f"// PI: w0 0.75, thresholds {[f(x) for x in r]}, weights {[f(x) for x in w]}, rest at 0")
print(emit_model("MAXWELL", mw, Q(0), segs, inputs))
print(emit_model("PI", pi, Q(0), segs, inputs))
