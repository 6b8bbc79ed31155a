#!/usr/bin/env python3
"""lugre.dynamics on the break-away and stick-slip experiments of Canudas de Wit et al. (1995),
timed from Python and scored against crates/lugre/tests/reference/dynamics/reference.json the way
crates/lugre/tests/reference/dynamics/mujoco_peer.py scores MuJoCo (same definitions, same
scales), so that the two tables can be put side by side.

    python bench/dynamics_lugre.py          # with the package installed (scripts/test.sh's .venv)

Times are whole experiments (all six rates / 30 s), best of 5, Python call included.
"""

import json
import pathlib
import time

import lugre

ROOT = pathlib.Path(__file__).resolve().parents[1]
REF = json.loads((ROOT / "crates/lugre/tests/reference/dynamics/reference.json").read_text())


def best(fn, n=5):
    out, t = None, float("inf")
    for _ in range(n):
        s = time.perf_counter()
        out = fn()
        t = min(t, time.perf_counter() - s)
    return out, t


def rel(a, b, floor=0.0):
    return abs(a - b) / max(abs(b), floor)


def main():
    for rtol in (1e-6, 1e-8):
        rates = REF["breakaway"]["values"]["rates"]
        res, tb = best(lambda: [lugre.dynamics(scenario="breakaway", force_rate=c["rate"], samples=2, rtol=rtol)["breakaway"] for c in rates])
        et = max(rel(b["t"], c["t"]) for b, c in zip(res, rates))
        ef = max(rel(b["force"], c["F"], 1.5) for b, c in zip(res, rates))
        ex = max(rel(b["x"], c["x"], 5e-5) for b, c in zip(res, rates))
        ss = REF["stickslip"]["values"]
        r, ts = best(lambda: lugre.dynamics(scenario="stick-slip", times=[10.0, 20.0, 30.0], rtol=rtol))
        onsets = [o["t"] for o in ss["slip_onsets"]]
        eo = max(rel(a, b) for a, b in zip(r["slip_onsets"], onsets))
        ep = rel(r["period"], ss["periods"][0])
        exs = max(rel(a, s["x"], 2.5) for a, s in zip(r["x"], ss["samples"]))
        evs = max(rel(a, s["v"], 0.2) for a, s in zip(r["v"], ss["samples"]))
        ezs = max(rel(a, s["z"], 1.5e-5) for a, s in zip(r["z"], ss["samples"]))
        print(f"| lugre rtol {rtol:g} | - | {tb * 1e3:.2f} ms | {et:.1e} / {ef:.1e} / {ex:.1e} | "
              f"{ts * 1e3:.2f} ms | {len(r['slip_onsets'])} of 4 | {eo:.1e} | {ep:.1e} | - | "
              f"{exs:.1e} / {evs:.1e} / {ezs:.1e} |")


if __name__ == "__main__":
    main()
