#!/usr/bin/env python3
"""Writes examples/data/lab-slow-loop.tsv: a measured-like slow friction loop as a lab records
it (tab-separated, units in the header, mm and uN, the friction with the opposite sign, an extra
normal-force column), for the README's "From a lab file to parameters".

    python3 examples/data/make_lab_file.py        # from the repository root

The generating model: LuGre, Table I of Canudas de Wit et al. (1995) (sigma0 = 1e5 N/m,
Fs = g(0) = 1.5 N: all a slow loop depends on), the slow loop (rate-independent limit) between
-20 um and +20 um (`lugre loop --preset canudas1995 --turning-points -2e-5,2e-5 --samples 401`),
one sample per 10 ms, plus Gaussian noise of 0.5 % of the force's RMS (seed 2026).
"""

import csv
import math
import os
import random
import subprocess
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

with tempfile.TemporaryDirectory() as tmp:
    loop = os.path.join(tmp, "loop.csv")
    subprocess.run(["cargo", "run", "--quiet", "--release", "--", "loop", "--preset", "canudas1995",
                    "--turning-points", "-2e-5,2e-5", "--samples", "401", "--csv", loop],
                   check=True, cwd=ROOT, stdout=subprocess.DEVNULL)
    rows = list(csv.DictReader(open(loop)))
rng = random.Random(2026)
rms = math.sqrt(sum(float(r["y"]) ** 2 for r in rows) / len(rows))
with open(os.path.join(HERE, "lab-slow-loop.tsv"), "w") as f:
    f.write("Time [s]\tNormal [uN]\tPosition [mm]\tFriction [uN]\n")
    for i, r in enumerate(rows):
        u, y = float(r["u"]), float(r["y"]) + rng.gauss(0.0, 0.005 * rms)
        f.write(f"{i * 0.01:.2f}\t5000000\t{u * 1e3:.6f}\t{-y * 1e6:.1f}\n")
print("wrote examples/data/lab-slow-loop.tsv")
