#!/usr/bin/env python3
"""lugre against the tools people use today, on identical inputs, in one run.

    python3 bench/compare.py            # from the repository root (or anywhere: paths are resolved)

1. Sets up its own virtual environment (bench/.venv, or $LUGRE_BENCH_VENV): numpy, scipy,
   rainflow 3.x, mpmath and maturin 1.16.* from PyPI; builds the Python package `lugre` from
   crates/lugre-py (release) into it and the `lugre` binary (cargo build --release), then
   re-runs itself inside that environment.
2. Simulation, eq. 5 of the paper (slowness gamma):

       z' = -sigma0 |u'| / g(u'/gamma) z + u',   y = sigma0 z + (sigma1/gamma) z' + f(u'/gamma),
       g(v) = Fc + (Fs - Fc) exp(-|v/vs|^beta),  f(v) = sigma2 v,

   on two piecewise-linear inputs: the paper's Example 3 (gamma = 10, 100 periods) and a stiff
   realistic case (Canudas de Wit et al. 1995 parameters, 10 periods). lugre's exact solution
   (Python binding, and the CLI for transparency) against scipy.integrate.solve_ivp with Radau
   and with LSODA, restarted at every kink, at several tolerances. Every method is scored by the
   max |y - y_exact| over the same output times, y_exact being the closed-form piecewise
   solution evaluated independently here with mpmath at 40 significant digits.
3. Rainflow counting (ASTM E1049-85) of 10^6 and 10^7 random-walk samples: lugre.cycles against
   rainflow.extract_cycles, checking that the cycles are identical (range, mean, count, start
   and end index, in order).
4. Closed-loop dynamics: the five experiments of Canudas de Wit et al. (1995) with
   lugre.dynamics, scipy's fastest method reaching the same accuracy and MuJoCo's LuGre
   (`dcmotor`, Euler h = 1e-3, 2e-3, implicitfast 1e-3), scored against the independent
   reference in crates/lugre/tests/reference/dynamics (bench/compare_dynamics.py).
5. Steady-state sweeps: lugre.sweep on a 50 x 50 grid of amplitudes and frequencies against
   scipy's Radau simulating points to their steady state at the same accuracy
   (bench/compare_sweep.py).
6. Bouc-Wen: lugre's exact segment map (lugre::zoo::BoucWen, timed through the example binary
   crates/lugre/examples/bouc_wen_loops.rs) against openseespy's BoucWen material on the same
   periodic strain history, both scored against scipy (bench/compare_bouc_wen.py).

Prints one table: case, method, time, error or agreement, ratio (time / lugre's time).
See bench/README.md for the options and what exactly is timed.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import platform
import shutil
import subprocess
import sys
import tempfile
import time
import warnings

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
VENV = os.environ.get("LUGRE_BENCH_VENV") or os.path.join(HERE, ".venv")
if not os.path.isabs(VENV):
    VENV = os.path.abspath(VENV)
STAGE_ENV = "LUGRE_BENCH_IN_VENV"
# Where cargo puts the `lugre` binary (cargo runs from the repository root).
TARGET = os.path.join(ROOT, os.environ.get("CARGO_TARGET_DIR", "target"))
LUGRE_EXE = os.path.join(TARGET, "release", "lugre")

REQUIREMENTS = ["numpy", "scipy", "rainflow>=3,<4", "mpmath", "mujoco>=3.7", "openseespy==3.7.1.2",
                "maturin==1.16.*"]


# --------------------------------------------------------------------------------------------
# Stage 1: the environment
# --------------------------------------------------------------------------------------------


def log(msg: str) -> None:
    print(f"[compare] {msg}", file=sys.stderr, flush=True)


def run(cmd: list[str], env: dict | None = None, cwd: str = ROOT) -> None:
    log("$ " + " ".join(cmd))
    subprocess.run(cmd, check=True, env=env, cwd=cwd)


def venv_python() -> str:
    return os.path.join(VENV, "bin", "python")


def setup(args: argparse.Namespace) -> None:
    """Creates the virtual environment, installs the packages, builds lugre."""
    py = venv_python()
    if not os.path.exists(py) or subprocess.run([py, "-c", "import sys"], capture_output=True).returncode:
        if os.path.exists(VENV) and not os.path.isfile(os.path.join(VENV, "pyvenv.cfg")):
            sys.exit(f"compare.py: {VENV} exists and is not a virtual environment")
        run([sys.executable, "-m", "venv", "--clear", VENV])
    env = dict(os.environ)
    env["VIRTUAL_ENV"] = VENV
    env["PATH"] = os.path.join(VENV, "bin") + os.pathsep + env.get("PATH", "")
    env.pop("PYTHONHOME", None)
    pip = [py, "-m", "pip", "install", "--quiet", "--disable-pip-version-check"]
    run(pip + REQUIREMENTS, env=env)
    if not args.no_build:
        # The environment's maturin builds the wheel in release (pip's default for maturin's
        # build backend); cargo rebuilds only what changed.
        run(pip + ["--no-build-isolation", "--force-reinstall", "--no-deps", "./crates/lugre-py"], env=env)
        if not args.no_cli:
            run(["cargo", "build", "--release", "--quiet", "-p", "lugre-cli"], env=env)


# --------------------------------------------------------------------------------------------
# Stage 2: the comparison (inside the environment)
# --------------------------------------------------------------------------------------------


def machine_info() -> dict:
    cpu = "?"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    try:
        load = " ".join(open("/proc/loadavg").read().split()[:3])
    except OSError:
        load = "?"
    return {"nproc": os.cpu_count(), "cpu": cpu, "load": load, "python": platform.python_version()}


def fmt_time(s: float | None) -> str:
    if s is None:
        return "-"
    if s < 1e-3:
        return f"{s * 1e6:.0f} us"
    if s < 1:
        return f"{s * 1e3:.3g} ms"
    return f"{s:.3g} s"


def fmt_ratio(r: float | None) -> str:
    if r is None:
        return "-"
    if r >= 100:
        return f"{r:,.0f}x"
    return f"{r:.3g}x"


def best_of(fn, *, repeats: int, budget: float, warmup: bool = True):
    """Minimum wall time of `fn()` over up to `repeats` calls, stopping once `budget` seconds
    have been spent (at least one timed call). Returns (best time, result of the last call)."""
    if warmup:
        result = fn()
    best = math.inf
    spent = 0.0
    for _ in range(repeats):
        t0 = time.perf_counter()
        result = fn()
        dt = time.perf_counter() - t0
        best = min(best, dt)
        spent += dt
        if spent >= budget:
            break
    return best, result


class TooSlow(Exception):
    pass


class Case:
    """A piecewise-linear input (knots t_k, u_k of one period, repeated) and a LuGre model."""

    def __init__(self, name, params, gamma, periods, turning_points=None, t=None, u=None, z_scale=1.0,
                 per_period=200):
        import lugre
        import numpy as np

        self.name = name
        self.params = params  # sigma0, sigma1, sigma2, fc, fs, vs, beta
        self.gamma = gamma
        self.periods = periods
        self.z_scale = z_scale  # size of the state z, for atol = rtol * z_scale
        self.model = lugre.LuGre(**params)
        if turning_points is not None:
            self.input = dict(turning_points=turning_points)
        else:
            self.input = dict(t=t, u=u)
        # The knots exactly as lugre places them (for turning points: cumulated |du| at unit
        # speed), taken from a knots-only run.
        knots = self.model.simulate(**self.input, gamma=gamma, periods=periods, times="knots")
        self.kt = np.asarray(knots["t"])  # every knot over all periods, the run's end last
        self.ku = np.asarray(knots["u"])
        nper = (len(self.kt) - 1) // periods
        period = self.kt[nper] - self.kt[0]
        one = self.model.simulate(**self.input, gamma=gamma, periods=1, samples_per_period=per_period)
        # The common output times: per_period evenly spaced times per period (as lugre's
        # samples_per_period computes them) plus every kink.
        j = np.arange(periods * per_period + 1)
        p, i = j // per_period, j % per_period
        uniform = (self.kt[0] + p * period) + period * (i / per_period)
        assert np.array_equal(uniform[: per_period + 1], one["t"]), "uniform times differ from lugre's"
        self.times = np.union1d(uniform, self.kt)
        self.period = period
        self.end = self.kt[-1]
        # Segments: slope s_k and rate c_k = sigma0 |s_k| / g(s_k / gamma) (float64, as scipy sees them).
        self.seg_t0 = self.kt[:-1]
        self.seg_t1 = self.kt[1:]
        # The input is periodic: every period has the first period's slopes (the knot times of
        # later periods are rounded to float64, their differences are not the slopes).
        self.nper = nper
        self.slope = np.tile(np.diff(self.ku[: nper + 1]) / np.diff(self.kt[: nper + 1]), periods)
        self.rate = np.array([self.c_float(s) for s in self.slope])
        # Which segment each output time lies in ([t_k, t_k+1), the end in the last one), and
        # the slope lugre uses for z' and y there: the one just after a kink, and at the run's
        # end the next period's first (the input is closed).
        seg = np.searchsorted(self.seg_t0, self.times, side="right") - 1
        self.seg_of_time = np.clip(seg, 0, len(self.seg_t0) - 1)
        self.y_seg = self.seg_of_time.copy()
        self.y_seg[self.times >= self.end] = 0
        self.bounds = np.searchsorted(self.times, self.seg_t0, side="left")

    def g_float(self, v):
        p = self.params
        return p["fc"] + (p["fs"] - p["fc"]) * math.exp(-abs(v / p["vs"]) ** p["beta"])

    def c_float(self, s):
        return self.params["sigma0"] * abs(s) / self.g_float(s / self.gamma)

    def y_from_z(self, z):
        """y at the output times from the state z there (the same formula for every method)."""
        p = self.params
        s = self.slope[self.y_seg]
        c = self.rate[self.y_seg]
        dz = s - c * z
        return p["sigma0"] * z + p["sigma1"] / self.gamma * dz + p["sigma2"] * s / self.gamma

    # -- the exact reference ------------------------------------------------------------------

    def reference(self, dps=40, ideal_kinks=False):
        """Closed-form solution on each segment, z(t) = z_inf + (z_k - z_inf) exp(-c (t - t_k)),
        z_inf = s / c, in mpmath with `dps` digits, the knots and times taken as exact numbers.

        The kinks t_k are the float64 knot times (lugre's, where scipy restarts), or with
        `ideal_kinks` the exact t_i + p P of the periodic input, which float64 cannot hold.
        The slopes are the first period's."""
        import mpmath as mp
        import numpy as np

        mp.mp.dps = dps
        p = {k: mp.mpf(v) for k, v in self.params.items()}
        gamma = mp.mpf(self.gamma)

        def seg_consts(k):
            i = k % self.nper  # the same segment of the first period
            s = (mp.mpf(self.ku[i + 1]) - mp.mpf(self.ku[i])) / (mp.mpf(self.kt[i + 1]) - mp.mpf(self.kt[i]))
            v = s / gamma
            g = p["fc"] + (p["fs"] - p["fc"]) * mp.exp(-abs(v / p["vs"]) ** p["beta"])
            c = p["sigma0"] * abs(s) / g
            return s, c

        consts = [seg_consts(k) for k in range(len(self.seg_t0))]
        period = mp.mpf(self.kt[self.nper]) - mp.mpf(self.kt[0])
        if ideal_kinks:
            kink = [mp.mpf(self.kt[k % self.nper]) + (k // self.nper) * period for k in range(len(self.kt))]
        else:
            kink = [mp.mpf(v) for v in self.kt]
        y = np.empty(len(self.times))
        z_ref = np.empty(len(self.times))
        zk = mp.mpf(0)  # x0 = 0
        for k, (s, c) in enumerate(consts):
            tk = kink[k]
            z_inf = s / c
            lo = self.bounds[k]
            hi = self.bounds[k + 1] if k + 1 < len(self.bounds) else len(self.times)
            for j in range(lo, hi):
                z = z_inf + (zk - z_inf) * mp.exp(-c * (mp.mpf(self.times[j]) - tk))
                sy, cy = consts[self.y_seg[j]]
                dz = sy - cy * z
                y[j] = float(p["sigma0"] * z + p["sigma1"] / gamma * dz + p["sigma2"] * sy / gamma)
                z_ref[j] = float(z)
            zk = z_inf + (zk - z_inf) * mp.exp(-c * (kink[k + 1] - tk))
        return y, z_ref

    # -- lugre ----------------------------------------------------------------------------------

    def lugre_run(self):
        return self.model.simulate(**self.input, gamma=self.gamma, periods=self.periods, times=self.times)["y"]

    def cli_args(self, tmpdir):
        p = self.params
        args = ["simulate", "--gamma", repr(float(self.gamma)), "--periods", str(self.periods)]
        for flag, key in [("--sigma0", "sigma0"), ("--sigma1", "sigma1"), ("--sigma2", "sigma2"),
                          ("--fc", "fc"), ("--fs", "fs"), ("--vs", "vs"), ("--beta", "beta")]:
            args += [flag, repr(float(p[key]))]
        if "turning_points" in self.input:
            args += ["--turning-points=" + ",".join(repr(float(v)) for v in self.input["turning_points"])]
        else:
            path = os.path.join(tmpdir, self.name.replace(" ", "_") + ".csv")
            with open(path, "w") as f:
                f.write("t,u\n")
                for t, u in zip(self.input["t"], self.input["u"]):
                    f.write(f"{float(t)!r},{float(u)!r}\n")
            args += ["--input", path]
            # An --input file is output at its samples by default: ask for the common times
            # (the CLI's default for turning points is already 200 per period plus the kinks).
            times = ",".join(repr(float(v)) for v in self.times)
            if len(times) < 100_000:  # one argument may not exceed 128 KiB on Linux
                args += ["--times", times]
            else:
                args += ["--samples-per-period", "200"]
        return args + ["--json"]

    # -- scipy ----------------------------------------------------------------------------------

    def scipy_run(self, method, rtol, atol, deadline):
        """solve_ivp restarted at every kink; z at the output times. Raises TooSlow past `deadline`."""
        import numpy as np
        from scipy.integrate import solve_ivp

        if method == "LSODA":
            # LSODA needs the Jacobian as a function: a constant matrix makes it stop with
            # "Illegal input detected" once it switches to its stiff method (scipy issue 10864).
            def jac(c):
                m = np.array([[-c]])
                return lambda t, y: m
        else:
            def jac(c):
                return np.array([[-c]])
        z_out = np.empty(len(self.times))
        z = 0.0
        nseg = len(self.seg_t0)
        for k in range(nseg):
            if time.perf_counter() > deadline:
                raise TooSlow(k, nseg)
            t0, t1 = self.seg_t0[k], self.seg_t1[k]
            s, c = self.slope[k], self.rate[k]
            lo = self.bounds[k]
            hi = self.bounds[k + 1] if k + 1 < nseg else len(self.times)
            te = self.times[lo:hi]
            last = k == nseg - 1
            if not last:
                te = np.append(te, t1)  # the state at the kink, to restart from
            sol = solve_ivp(lambda t, y: s - c * y, (t0, t1), [z], method=method, t_eval=te,
                            rtol=rtol, atol=atol, jac=jac(c))
            if not sol.success:
                raise RuntimeError(f"solve_ivp {method} failed on segment {k}: {sol.message}")
            zs = sol.y[0]
            if last:
                z_out[lo:hi] = zs
            else:
                z_out[lo:hi] = zs[:-1]
                z = zs[-1]
        return z_out


def simulation_rows(case: Case, args, rows: list, summary: list, tmpdir: str) -> None:
    import numpy as np

    log(f"{case.name}: {len(case.seg_t0)} segments, {len(case.times)} output times; exact reference (mpmath) ...")
    t0 = time.perf_counter()
    y_ref, _ = case.reference()
    y_ideal, _ = case.reference(ideal_kinks=True)
    log(f"{case.name}: references in {time.perf_counter() - t0:.1f} s")

    def err(y):
        return float(np.max(np.abs(np.asarray(y) - y_ref)))

    t_lugre, y_lugre = best_of(case.lugre_run, repeats=50, budget=1.0)
    e_lugre = err(y_lugre)
    e_lugre_ideal = float(np.max(np.abs(np.asarray(y_lugre) - y_ideal)))
    rows.append((case.name, "lugre (Python binding, exact)", fmt_time(t_lugre), f"max|dy| = {e_lugre:.1e}", fmt_ratio(1.0)))

    if not args.no_cli:
        cmd = [LUGRE_EXE] + case.cli_args(tmpdir)

        def cli():
            return subprocess.run(cmd, check=True, capture_output=True).stdout

        t_cli, out = best_of(cli, repeats=10, budget=2.0)
        d = json.loads(out)
        t_cli_out = np.asarray(d["t"])
        if np.array_equal(t_cli_out, case.times):
            note = f"max|dy| = {err(d['y']):.1e}"
        else:
            common = np.isin(case.times, t_cli_out)
            y_cli = np.asarray(d["y"])[np.isin(t_cli_out, case.times)]
            e_cli = float(np.max(np.abs(y_cli - y_ref[common])))
            note = f"max|dy| = {e_cli:.1e} (at the {common.sum()} common times)"
        rows.append((case.name, "lugre CLI (process, --json)", fmt_time(t_cli), note, fmt_ratio(t_cli / t_lugre)))

    best = None  # fastest scipy run correct to 1e-8
    for method in ("Radau", "LSODA"):
        prev = None
        for rtol in args.rtols:
            atol = rtol * case.z_scale
            label = f"scipy {method} rtol={rtol:.0e} atol={atol:.0e}"
            if prev is not None and prev * args.growth > args.budget:
                rows.append((case.name, label, "-", f"skipped: est. > {fmt_time(args.budget)} budget", "-"))
                continue
            deadline = time.perf_counter() + args.budget
            log(f"{case.name}: {label} ...")
            with warnings.catch_warnings(record=True) as warned:
                warnings.simplefilter("always")
                try:
                    t_first = time.perf_counter()
                    z = case.scipy_run(method, rtol, atol, deadline)
                    t_run = time.perf_counter() - t_first
                    if t_run < args.repeat_below:
                        t_more, z = best_of(lambda: case.scipy_run(method, rtol, atol, math.inf),
                                            repeats=2, budget=args.repeat_below, warmup=False)
                        t_run = min(t_run, t_more)
                except TooSlow as e:
                    k, n = e.args
                    rows.append((case.name, label, f"> {fmt_time(args.budget)}",
                                 f"too slow: stopped after {k} of {n} segments", "-"))
                    prev = math.inf
                    continue
                except Exception as e:  # a failed solver is a result, not a crash
                    rows.append((case.name, label, "-", f"failed: {e}"[:70], "-"))
                    prev = None
                    continue
            prev = t_run
            e = err(case.y_from_z(z))
            ok = e <= 1e-8
            if warned:
                log(f"{case.name}: {label}: {len(warned)} warnings, first: {warned[0].message}")
            note = f"max|dy| = {e:.1e}" + (" ok" if ok else "")
            if warned:
                note += f" ({len(warned)} solver warnings)"
            rows.append((case.name, label, fmt_time(t_run), note,
                         fmt_ratio(t_run / t_lugre)))
            log(f"{case.name}: {label}: {fmt_time(t_run)}, max|dy| = {e:.1e}")
            if ok and (best is None or t_run < best[0]):
                best = (t_run, e, label)
    if best is None:
        summary.append(f"{case.name}: no scipy run was correct to 1e-8 (lugre: {fmt_time(t_lugre)}, max|dy| = {e_lugre:.1e})")
    else:
        t_b, e_b, label = best
        summary.append(
            f"{case.name}: fastest scipy run correct to 1e-8 is {label}: {fmt_time(t_b)}, max|dy| = {e_b:.1e}; "
            f"lugre {fmt_time(t_lugre)}, max|dy| = {e_lugre:.1e}: {t_b / t_lugre:,.0f}x faster, "
            + (f"{e_b / e_lugre:,.0f}x smaller error" if e_lugre > 0 else "error 0 (exact in float64 at every output time)")
        )
    summary.append(
        f"{case.name}: against the kinks at the exact t_i + p P rather than at their float64 roundings, "
        f"lugre's max|dy| is {e_lugre_ideal:.1e}: the float64 rounding of the kink times, up to ~ulp(t) x |dy/dt| just after a kink")


def cycles_rows(n: int, args, rows: list, summary: list, tmpdir: str) -> None:
    import numpy as np
    import lugre
    import rainflow

    case = f"rainflow, 10^{round(math.log10(n))} samples" if n >= 10 and 10 ** round(math.log10(n)) == n else f"rainflow, {n} samples"
    rng = np.random.default_rng(args.seed)
    x = rng.standard_normal(n).cumsum()
    xs = x.tolist()  # rainflow's fastest input: a list of Python floats (not timed)

    # The table rainflow yields (range, mean, count, start, end per cycle), as numpy columns:
    # the same information, the primary row. Then everything lugre.cycles gives by default
    # (also the reversals and each full cycle's closure, which rainflow does not find).
    t_lugre, res = best_of(lambda: lugre.cycles(x, reversals=False, closures=False), repeats=30, budget=2.0)
    cyc = res["cycles"]
    nl = len(cyc["range"])
    rows.append((case, "lugre.cycles(x, reversals=False, closures=False)", fmt_time(t_lugre),
                 f"{nl} cycles ({res['summary']['full_cycles']} full)", fmt_ratio(1.0)))
    t_all, res_all = best_of(lambda: lugre.cycles(x), repeats=30, budget=2.0)
    same_all = all(np.array_equal(res_all["cycles"][k], cyc[k]) for k in ("range", "mean", "count", "start", "end"))
    del res_all
    rows.append((case, "lugre.cycles(x): + reversals, closures", fmt_time(t_all),
                 "same cycles" if same_all else "DIFFERENT cycles", fmt_ratio(t_all / t_lugre)))

    log(f"{case}: rainflow.extract_cycles ...")
    t0 = time.perf_counter()
    ref = list(rainflow.extract_cycles(xs))
    t_rf = time.perf_counter() - t0
    if t_rf < args.repeat_below:
        def rf():
            return list(rainflow.extract_cycles(xs))
        t_more, ref = best_of(rf, repeats=2, budget=args.repeat_below, warmup=False)
        t_rf = min(t_rf, t_more)
    log(f"{case}: rainflow {fmt_time(t_rf)}")
    a = np.array(ref, dtype=np.float64) if ref else np.empty((0, 5))
    del ref
    same = (len(a) == nl
            and np.array_equal(a[:, 0], cyc["range"])
            and np.array_equal(a[:, 1], cyc["mean"])
            and np.array_equal(a[:, 2], cyc["count"])
            and np.array_equal(a[:, 3], cyc["start"].astype(np.float64))
            and np.array_equal(a[:, 4], cyc["end"].astype(np.float64)))
    if same:
        agreement = f"identical: all {nl} cycles (range, mean, count, i_start, i_end, order)"
    else:
        m = min(len(a), nl)
        diff = np.nonzero(
            (a[:m, 0] != cyc["range"][:m]) | (a[:m, 1] != cyc["mean"][:m]) | (a[:m, 2] != cyc["count"][:m])
            | (a[:m, 3] != cyc["start"][:m]) | (a[:m, 4] != cyc["end"][:m]))[0]
        first = int(diff[0]) if len(diff) else m
        agreement = f"DIFFERENT: {len(a)} vs {nl} cycles, first difference at cycle {first}"
    rows.append((case, "rainflow.extract_cycles, list in", fmt_time(t_rf), agreement, fmt_ratio(t_rf / t_lugre)))
    # What a numpy user would write: the array itself (numpy scalars are slower to iterate).
    log(f"{case}: rainflow.extract_cycles on the numpy array ...")
    t0 = time.perf_counter()
    n_np = len(list(rainflow.extract_cycles(x)))
    t_np = time.perf_counter() - t0
    if t_np < args.repeat_below:
        t_more, n_np = best_of(lambda: len(list(rainflow.extract_cycles(x))), repeats=2,
                               budget=args.repeat_below, warmup=False)
        t_np = min(t_np, t_more)
    rows.append((case, "rainflow.extract_cycles, numpy array in", fmt_time(t_np),
                 f"{n_np} cycles" + (" (same count)" if n_np == nl else " (DIFFERENT count)"),
                 fmt_ratio(t_np / t_lugre)))
    summary.append(f"{case}: lugre.cycles {fmt_time(t_lugre)} (cycle table; {fmt_time(t_all)} with reversals "
                   f"and closures), rainflow {fmt_time(t_rf)}: {t_rf / t_lugre:,.0f}x faster "
                   f"({t_rf / t_all:,.0f}x with everything); cycles {'identical' if same else 'DIFFERENT'}")

    if not args.no_cli:
        path = os.path.join(tmpdir, f"walk_{n}.csv")
        with open(path, "w") as f:
            f.write("u\n")
            f.write("\n".join(map(repr, xs)))
            f.write("\n")
        out = os.path.join(tmpdir, f"cycles_{n}.csv")
        cmd = [LUGRE_EXE, "cycles", "--input", path, "--csv", out]

        def cli():
            subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)

        t_cli, _ = best_of(cli, repeats=3, budget=2.0, warmup=False)
        c = np.loadtxt(out, delimiter=",", skiprows=1, usecols=range(5), ndmin=2)
        same_cli = (len(c) == nl and np.array_equal(c[:, 0], cyc["range"]) and np.array_equal(c[:, 1], cyc["mean"])
                    and np.array_equal(c[:, 2], cyc["count"]) and np.array_equal(c[:, 3], cyc["start"])
                    and np.array_equal(c[:, 4], cyc["end"]))
        rows.append((case, "lugre CLI (CSV in, --csv out)", fmt_time(t_cli),
                     "identical to the binding's" if same_cli else "DIFFERENT from the binding's",
                     fmt_ratio(t_cli / t_lugre)))
        os.remove(path)
        os.remove(out)


def print_table(rows, file=sys.stdout, markdown=False):
    head = ("case", "method", "time", "error or agreement", "ratio")
    if markdown:
        print("| " + " | ".join(head) + " |", file=file)
        print("|" + "|".join(["---", "---", "---:", "---", "---:"]) + "|", file=file)
        for r in rows:
            print("| " + " | ".join(c.replace("|", "\\|") for c in r) + " |", file=file)
        return
    w = [max(len(h), *(len(r[i]) for r in rows)) for i, h in enumerate(head)]
    line = "  ".join(h.ljust(w[i]) if i not in (2, 4) else h.rjust(w[i]) for i, h in enumerate(head))
    print(line, file=file)
    print("-" * len(line), file=file)
    prev = None
    for r in rows:
        if prev is not None and r[0] != prev:
            print(file=file)
        prev = r[0]
        print("  ".join(c.ljust(w[i]) if i not in (2, 4) else c.rjust(w[i]) for i, c in enumerate(r)), file=file)


def compare(args: argparse.Namespace) -> None:
    import numpy as np
    import scipy
    import scipy.integrate  # imported here, not inside the first timed scipy run
    import rainflow
    import lugre

    start = time.perf_counter()
    if not args.no_cli and not os.access(LUGRE_EXE, os.X_OK):
        log(f"no {LUGRE_EXE}: skipping the CLI rows (run without --no-setup / --no-build to build it)")
        args.no_cli = True
    info = machine_info()
    header = (f"machine: {info['nproc']} cores, {info['cpu']}; load average at start {info['load']}\n"
              f"python {info['python']}, numpy {np.__version__}, scipy {scipy.__version__}, "
              f"rainflow {rainflow.__version__}, lugre {lugre.__version__}")
    log(header.replace("\n", "; "))
    rows: list = []
    summary: list = []
    periods_ex3 = 10 if args.quick else 100
    periods_stiff = 2 if args.quick else 10
    cases = []
    if args.only in (None, "simulation"):
        ex3 = Case(f"Example 3 (gamma=10, {periods_ex3} periods)",
                   dict(sigma0=1.0, sigma1=1.0, sigma2=0.0, fc=1.0, fs=2.0, vs=1.0, beta=1.0),
                   gamma=10.0, periods=periods_ex3, turning_points=[0.0, 1.0, 0.2, 1.5], z_scale=1.0)
        stiff = Case(f"stiff (sigma0=1e5, {periods_stiff} periods)",
                     dict(sigma0=1e5, sigma1=math.sqrt(1e5), sigma2=0.4, fc=1.0, fs=1.5, vs=1e-3, beta=2.0),
                     gamma=1.0, periods=periods_stiff,
                     t=[0.0, 0.8, 1.2, 1.8, 2.8], u=[0.0, 0.008, 0.004, 0.010, 0.0], z_scale=1e-5)
        cases = [ex3, stiff]
    with tempfile.TemporaryDirectory(prefix="lugre-bench-") as tmpdir:
        for case in cases:
            simulation_rows(case, args, rows, summary, tmpdir)
        if args.only in (None, "rainflow"):
            for n in args.sizes:
                cycles_rows(n, args, rows, summary, tmpdir)
    if args.only in (None, "dynamics"):
        sys.path.insert(0, HERE)
        from compare_dynamics import dynamics_rows
        dynamics_rows(rows, summary, log, fmt_time, fmt_ratio)
    if args.only in (None, "sweep"):
        sys.path.insert(0, HERE)
        from compare_sweep import sweep_rows
        sweep_rows(rows, summary, log, fmt_time, fmt_ratio)
    if args.only in (None, "bouc-wen"):
        sys.path.insert(0, HERE)
        from compare_bouc_wen import bouc_wen_rows
        bouc_wen_rows(rows, summary, log, fmt_time, fmt_ratio)
    elapsed = time.perf_counter() - start
    end_load = machine_info()["load"]

    print(header)
    print()
    print_table(rows)
    print()
    for s in summary:
        print("* " + s)
    print()
    print(f"Times: best of several runs for runs under {args.repeat_below:g} s, else one run; "
          f"ratio = time / lugre binding's time for the same case. max|dy| = max |y - y_exact| over the "
          f"common output times (200 per period plus every kink; right limits at kinks), y_exact from the "
          f"closed form in mpmath (40 digits). 'ok' = correct to 1e-8.")
    print(f"Whole run: {elapsed:.0f} s; load average at end {end_load}.")
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(header.replace("\n", "  \n") + "\n\n")
            print_table(rows, file=f, markdown=True)
            f.write("\n")
            for s in summary:
                f.write("* " + s + "\n")
            f.write(f"\nWhole run: {elapsed:.0f} s; load average at end {end_load}.\n")
        log(f"wrote {args.markdown}")


def parse_args(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--no-setup", action="store_true",
                    help="use the environment as it is (no pip install, no build)")
    ap.add_argument("--no-build", action="store_true", help="install the PyPI packages but do not rebuild lugre")
    ap.add_argument("--no-cli", action="store_true", help="skip the `lugre` CLI rows (and its build)")
    ap.add_argument("--only", choices=("simulation", "rainflow", "dynamics", "sweep", "bouc-wen"),
                    help="run only the simulation cases, the rainflow counting, the closed-loop dynamics, "
                         "the steady-state sweep or Bouc-Wen against openseespy")
    ap.add_argument("--quick", action="store_true",
                    help="a smoke test: 10 / 2 periods, 10^5 and 10^6 samples, rtol 1e-6 and 1e-10")
    ap.add_argument("--rtols", type=lambda s: [float(v) for v in s.split(",")], default=None,
                    help="scipy relative tolerances, comma-separated (default 1e-6,1e-8,1e-10,1e-12); "
                         "atol = rtol x the size of z (1 for Example 3, 1e-5 for the stiff case)")
    ap.add_argument("--budget", type=float, default=60.0,
                    help="seconds one scipy run may take before it is stopped and reported as too slow (default 60)")
    ap.add_argument("--growth", type=float, default=4.0,
                    help="a tighter tolerance is skipped when the previous run's time x this exceeds --budget (default 4)")
    ap.add_argument("--repeat-below", type=float, default=3.0,
                    help="runs shorter than this (s) are repeated, best of 3 (default 3)")
    ap.add_argument("--sizes", type=lambda s: [int(float(v)) for v in s.split(",")], default=None,
                    help="random-walk lengths for rainflow (default 1e6,1e7)")
    ap.add_argument("--seed", type=int, default=20240808, help="random-walk seed")
    ap.add_argument("--markdown", metavar="FILE", help="also write the table as Markdown to FILE")
    args = ap.parse_args(argv)
    if args.rtols is None:
        args.rtols = [1e-6, 1e-10] if args.quick else [1e-6, 1e-8, 1e-10, 1e-12]
    if args.sizes is None:
        args.sizes = [10**5, 10**6] if args.quick else [10**6, 10**7]
    return args


def main() -> None:
    args = parse_args(sys.argv[1:])
    in_venv = os.path.realpath(sys.prefix) == os.path.realpath(VENV)
    if os.environ.get(STAGE_ENV) == "1" or (args.no_setup and in_venv):
        compare(args)
        return
    if not args.no_setup:
        if shutil.which("cargo") is None:
            sys.exit("compare.py: cargo (a Rust toolchain) is needed to build lugre")
        setup(args)
    py = venv_python()
    if not os.path.exists(py):
        sys.exit(f"compare.py: no environment at {VENV}: run without --no-setup first")
    env = dict(os.environ)
    env[STAGE_ENV] = "1"
    env["VIRTUAL_ENV"] = VENV
    env["PATH"] = os.path.join(VENV, "bin") + os.pathsep + env.get("PATH", "")
    os.execve(py, [py, os.path.abspath(__file__)] + sys.argv[1:], env)


if __name__ == "__main__":
    main()
