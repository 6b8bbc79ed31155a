"""A history bigger than one process, counted on Dask: writes a random-walk history as chunked
.npy files, starts a LocalCluster, counts it with lugre.dask (rainflow cycles, closures and
the LuGre energies of every loop), checks the result against the single pass, and prints the
time of each stage.

    python examples/dask_rainflow.py                       # 10^8 samples in 64 files, 2 workers
    python examples/dask_rainflow.py --samples 1e7 --chunks 16
    python examples/dask_rainflow.py --workers 1 2         # the same count on 1, then 2 workers
    python examples/dask_rainflow.py --scheduler tcp://host:8786 --dir /shared/history

Needs ``pip install lugre[dask]``. On a real cluster, point --dir at storage every worker can
read and pass the scheduler's address.
"""

import argparse
import os
import tempfile
import time

import numpy as np
import pandas as pd
from dask.distributed import Client, LocalCluster

import lugre
import lugre.dask as ld


def write_history(directory, samples, chunks, step, seed=2026):
    """A random walk with Gaussian steps of standard deviation `step` in `chunks` files,
    written chunk by chunk (never all in memory); returns the paths in order."""
    rng = np.random.default_rng(seed)
    sizes = np.full(chunks, samples // chunks)
    sizes[: samples % chunks] += 1
    paths, x = [], 0.0
    for k, n in enumerate(sizes):
        part = x + np.cumsum(step * rng.standard_normal(int(n)))
        x = part[-1]
        path = os.path.join(directory, f"history-{k:05d}.npy")
        np.save(path, part)
        paths.append(path)
    return paths


def count_on(client_args, paths, model):
    with Client(**client_args) if "address" in client_args else _local(client_args) as client:
        # Start the workers before the clock (a fresh cluster imports lugre lazily).
        client.run(lambda: __import__("lugre.dask"))
        tic = time.perf_counter()
        r = ld.count(paths, model=model)
        elapsed = time.perf_counter() - tic
        table = r["cycles"].compute()
    return r, table, elapsed


class _local:
    def __init__(self, args):
        self.cluster = LocalCluster(n_workers=args["workers"], threads_per_worker=1,
                                    processes=True, host="127.0.0.1", dashboard_address=None)
        self.client = Client(self.cluster)

    def __enter__(self):
        return self.client

    def __exit__(self, *exc):
        self.client.close()
        self.cluster.close()


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--samples", type=float, default=1e8)
    p.add_argument("--chunks", type=int, default=64)
    p.add_argument("--workers", type=int, nargs="+", default=[2])
    p.add_argument("--scheduler", help="address of a running Dask scheduler (default: a LocalCluster)")
    p.add_argument("--dir", help="where the chunk files go (default: a temporary directory)")
    p.add_argument("--step", type=float, default=1e-5, help="step size of the walk, m (default 1e-5)")
    p.add_argument("--no-check", action="store_true", help="skip the single pass")
    a = p.parse_args()
    samples = int(a.samples)
    # The 1995 parameter set (sigma0 = 1e5 N/m, Fc = 1 N, Fs = 1.5 N, ...); the history is a
    # displacement in metres, steps of about 10 um (a sigma0 / Fs ~ 0.7 per step: pre-sliding
    # and sliding mixed).
    model = lugre.LuGre(sigma0=1e5, sigma1=316.0, sigma2=0.4, fc=1.0, fs=1.5, vs=1e-3, beta=2)

    with tempfile.TemporaryDirectory() as tmp:
        directory = a.dir or tmp
        os.makedirs(directory, exist_ok=True)
        tic = time.perf_counter()
        paths = write_history(directory, samples, a.chunks, a.step)
        print(f"wrote {samples:.3g} samples in {len(paths)} files ({directory}): "
              f"{time.perf_counter() - tic:.1f} s")
        runs = [{"address": a.scheduler}] if a.scheduler else [{"workers": w} for w in a.workers]
        results = []
        for args in runs:
            r, table, elapsed = count_on(args, paths, model)
            label = args.get("address") or f"{args['workers']} worker(s)"
            stages = ", ".join(f"{k} {v:.2f} s" for k, v in r["stages"].items())
            print(f"lugre.dask on {label}: {elapsed:.2f} s ({stages}); {len(table)} cycles, "
                  f"{r['entries']['held']} of {r['entries']['chunks']} chunk entry states "
                  "guessed right")
            results.append((label, elapsed, r, table))
        if len(results) > 1:
            base = results[0][1]
            for label, elapsed, _, _ in results[1:]:
                print(f"speed-up of {label} over {results[0][0]}: {base / elapsed:.2f}x")
        if a.no_check:
            return
        u = np.concatenate([np.load(p) for p in paths])
        tic = time.perf_counter()
        single = lugre.cycles(u, model=model, reversals=False)
        print(f"single pass (lugre.cycles, one core): {time.perf_counter() - tic:.2f} s")
        want = pd.DataFrame(single["cycles"])
        for label, _, r, table in results:
            same = table.equals(want) and r["summary"] == single["summary"]
            print(f"{label}: " + ("identical to the single pass" if same
                                  else "DIFFERENT from the single pass"))
            if not same:
                raise SystemExit(1)


if __name__ == "__main__":
    main()
