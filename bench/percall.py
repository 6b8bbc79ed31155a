"""The cost of one call through the Python binding with tiny inputs, to compare commits.

    python bench/percall.py                  # every case: the best of 7 timeit rounds, us per call
    python bench/percall.py --json out.json  # also as JSON (case -> list of the 7 rounds, us)
    python bench/percall.py --instructions   # instructions per call instead (valgrind)

With `--instructions`, each case runs under valgrind's cachegrind for K calls and for none, and
the difference over K is printed: a count the load of a shared machine does not change (the
interpreter's own work varies by a few tens of instructions from run to run).

Each case is a call a user makes with a handful of values (the engines' work is small, so the
time is that of the binding: reading the arguments, the request, building the result). Run
two environments (two commits) alternately to compare them under the same load.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import timeit

import numpy as np

import lugre

TP = [0.0, 1.0, 0.5, 1.5]
T = [0.0, 1.0, 1.5, 2.5]
WALK = np.array([0.0, 1.0, 0.2, 0.8, -0.5, 1.2, 0.1, 0.9])
U_FIT = np.array(TP * 3)
F_FIT = np.array([-1.2, 1.1, 0.2, 1.3, -1.3, 1.2, 0.1, 1.3, -1.25, 1.15, 0.15, 1.3])
MODEL = lugre.LuGre(sigma0=6.0)

CASES = {
    "LuGre(sigma0=6)": (lambda: lugre.LuGre(sigma0=6.0), 20000),
    "model.loop(4 points)": (lambda: MODEL.loop(TP), 20000),
    "model.simulate(t, u: 4 knots)": (lambda: MODEL.simulate(t=T, u=TP, times="knots"), 20000),
    "model.simulate(turning_points)": (lambda: MODEL.simulate(turning_points=TP), 2000),
    "lugre.cycles(8 samples)": (lambda: lugre.cycles(WALK), 20000),
    "lugre.cycles(8 samples, model)": (lambda: lugre.cycles(WALK, model=MODEL), 20000),
    "lugre.dynamics(breakaway, 4 times)": (
        lambda: lugre.dynamics(scenario="breakaway", times=[0.05, 0.1, 0.15, 0.2]),
        300,
    ),
    "lugre.fit(12 samples, slow)": (lambda: lugre.fit(U_FIT, F_FIT), 5000),
}


def instructions(name, calls):
    """The instructions of `calls` calls of case `name` in a fresh interpreter."""
    cmd = ["valgrind", "--tool=cachegrind", "--cache-sim=no", "--cachegrind-out-file=/dev/null",
           sys.executable, __file__, "--run", name, str(calls)]
    # A fixed hash seed (dict and set layouts, and so the interpreter's work, repeat) and
    # one BLAS thread: numpy's OpenBLAS threads spin while they wait, tens of millions of
    # instructions that differ from run to run.
    env = dict(os.environ, PYTHONHASHSEED="0", OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
    err = subprocess.run(cmd, capture_output=True, text=True, check=True, env=env).stderr
    return int(re.search(r"I\s+refs:\s+([\d,]+)", err).group(1).replace(",", ""))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--json", help="also write the rounds (or the counts) to this file")
    ap.add_argument("--rounds", type=int, default=7)
    ap.add_argument("--instructions", action="store_true", help="count instructions per call")
    ap.add_argument("--run", nargs=2, metavar=("CASE", "CALLS"), help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.run:
        call = CASES[args.run[0]][0]
        call()  # the first call's one-time work (imports, caches) is in both counts
        for _ in range(int(args.run[1])):
            call()
        return
    out = {}
    if args.instructions:
        for name, (call, number) in CASES.items():
            k = max(number // 4, 10)
            out[name] = (instructions(name, k) - instructions(name, 0)) / k
            print(f"{name:40s} {out[name]:11.0f} instructions", flush=True)
        if args.json:
            with open(args.json, "w") as fh:
                json.dump(out, fh, indent=1)
        return
    for name, (call, number) in CASES.items():
        call()  # a failure shows here, outside the timing
        rounds = timeit.repeat(call, number=number, repeat=args.rounds)
        out[name] = [1e6 * r / number for r in rounds]
        print(f"{name:40s} {min(out[name]):9.2f} us")
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(out, fh, indent=1)


if __name__ == "__main__":
    main()
