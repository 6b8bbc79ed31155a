#!/usr/bin/env python3
"""The Monte Carlo: the servo-axis record, fitted N times with `lugre fit`.

Each record is made by the independent generator (crates/lugre/tests/reference/servo_axis.py:
scipy Radau at rtol 1e-10, then 0.5 um of position noise rounded to 0.1 um and 0.2 N of force
noise, seeds FIRST..FIRST+N-1) and fitted with

    lugre fit --fit full --beta 2 --scale u=1e-3 --fix sigma2=40 --json [EXTRA...]

Printed: per parameter the coverage of the 95 % intervals, the mean and RMS relative error, the
RMS of the reported standard errors (relative), and the median wall time of one fit (the process included).

    python3 scripts/servo_axis_monte_carlo.py [--records 200] [--first-seed 1] [--lugre PATH]
        [--position-noise UM] [--force-noise N] [--resolution UM] [-- EXTRA...]

Needs numpy and scipy; the binary defaults to target/release/lugre.
"""

import argparse
import importlib.util
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
GENERATOR = os.path.join(HERE, "..", "crates", "lugre", "tests", "reference", "servo_axis.py")
TRUTH = {"sigma0": 1e6, "sigma1": 1500.0, "fc": 15.0, "fs": 22.0, "vs": 4e-3}


def generator():
    spec = importlib.util.spec_from_file_location("servo_axis", GENERATOR)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--records", type=int, default=200)
    p.add_argument("--first-seed", type=int, default=1, help="seed of the first record (default 1)")
    p.add_argument("--position-noise", type=float, default=0.5, help="um (default 0.5)")
    p.add_argument("--force-noise", type=float, default=0.2, help="N (default 0.2)")
    p.add_argument("--resolution", type=float, default=0.1, help="um (default 0.1; 0: none)")
    p.add_argument("--lugre", default=os.path.join(HERE, "..", "target", "release", "lugre"))
    p.add_argument("extra", nargs="*")
    a = p.parse_args()
    gen = generator()
    t, u, f = gen.clean()
    covered = {k: 0 for k in TRUTH}
    errors = {k: [] for k in TRUTH}
    stderrs = {k: [] for k in TRUTH}
    times, warned, methods = [], 0, {}
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "record.csv")
        for seed in range(a.first_seed, a.first_seed + a.records):
            with open(path, "w") as fh:
                gen.write(fh, *gen.noisy(t, u, f, seed, a.position_noise, a.force_noise, a.resolution), 10)
            cmd = [a.lugre, "fit", "--input", path, "--fit", "full", "--beta", "2",
                   "--scale", "u=1e-3", "--fix", "sigma2=40", "--json"] + a.extra
            start = time.perf_counter()
            out = subprocess.run(cmd, capture_output=True, text=True)
            times.append(time.perf_counter() - start)
            if out.returncode != 0:
                sys.exit(f"record {seed}: {out.stderr.strip()}")
            doc = json.loads(out.stdout)
            warned += bool(doc.get("warnings"))
            m = doc.get("covariance", {}).get("method", "?")
            methods[m] = methods.get(m, 0) + 1
            for k, want in TRUTH.items():
                e = doc["parameters"][k]
                lo, hi = e["ci95"]
                covered[k] += lo <= want <= hi
                errors[k].append(e["value"] / want - 1.0)
                stderrs[k].append(e["stderr"] / want)
    n = a.records
    print(f"{n} records; covariance used: {methods}; records with a warning: {warned}")
    print(f"{'parameter':<8} {'coverage':>9} {'mean error':>11} {'RMS error':>10} {'RMS stderr':>11}")
    for k in TRUTH:
        mean = statistics.fmean(errors[k])
        rms = statistics.fmean(x * x for x in errors[k]) ** 0.5
        se = statistics.fmean(x * x for x in stderrs[k]) ** 0.5
        print(f"{k:<8} {covered[k] / n:>9.3f} {mean:>11.2e} {rms:>10.2e} {se:>11.2e}")
    print(f"median wall time of one fit (process included): {statistics.median(times) * 1e3:.1f} ms")


if __name__ == "__main__":
    main()
