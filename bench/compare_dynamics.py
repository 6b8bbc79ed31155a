"""The closed-loop dynamics section of bench/compare.py (`--only dynamics`): the five experiments of
Canudas de Wit et al. (1995) with lugre.dynamics, scipy's fastest method reaching the same
accuracy, and MuJoCo's LuGre (`dcmotor` actuator), side by side in one run.

Every tool is scored the same way, against the independent reference
crates/lugre/tests/reference/dynamics/reference.json (scipy Radau at rtol 1e-12, see the README
there): the worst relative error over the experiment's headline quantities, each relative to
max(|reference|, its natural scale) (make_dynamics_reference.py's floors):

  * pre-sliding: x, v, z, F at t = 5, 10, 15, 25, 35, 40, 50, 60, 65 s;
  * break-away: t, F, x of the first friction peak at the six force rates 1..50 N/s;
  * stick-slip: x, v, z at 10, 20, 30 s, the slip-onset times and the periods;
  * frictional lag (w = 10 rad/s): z and F at the twelve sample times;
  * PID: x, v, z at 10, 20, ..., 100 s.

lugre runs at its default tolerance (rtol 1e-8). scipy (solve_ivp with the analytic Jacobian,
driven as the reference's peers are: restarts at the drive's kinks, events on the dense output)
runs Radau, BDF and LSODA at rtol 1e-5, 1e-6, ... until a run is as accurate as lugre's; the
fastest such run is reported. MuJoCo (4.x, a 1 kg body on a slide joint, the paper's parameters
in `lugre=`, gravity off) steps with Euler at h = 1e-3 and 2e-3 and with implicitfast at 1e-3;
its drive is set from the state before each mj_step (the Python loop is part of its time, as for
a user of its Python API); events on its sample sequence are refined by a parabola
(mujoco_peer.py). MuJoCo has no prescribed-velocity joint drive with LuGre, so the lag
experiment has no MuJoCo row.

Times are best of 3 (lugre: best of 5), whole experiments, Python call included.
"""

from __future__ import annotations

import json
import math
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
REFDIR = os.path.join(ROOT, "crates", "lugre", "tests", "reference", "dynamics")

EXPERIMENTS = ("presliding", "breakaway", "stickslip", "lag", "pid")
SCIPY_RTOLS = [1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11]
MUJOCO_RUNS = [("Euler", 1e-3), ("Euler", 2e-3), ("implicitfast", 1e-3)]
LAG_W = 10.0  # the reference's w index 1


def _modules():
    if REFDIR not in sys.path:
        sys.path.insert(0, REFDIR)
    import make_dynamics_reference as mdr  # noqa: E402 (the reference's own drivers)
    return mdr


def _reference(mdr):
    with open(os.path.join(REFDIR, "reference.json")) as fh:
        ref = json.load(fh)
    out = {}
    for key in EXPERIMENTS:
        flat = mdr.flatten(ref[key]["values"])
        out[key] = {k: v for k, v in flat.items() if _headline(key, k)}
    return out


def _headline(key: str, name: str) -> bool:
    parts = name.split(".")
    if key in ("presliding", "stickslip", "pid") and parts[0] == "samples":
        return parts[-1] in ("x", "v", "z", "F") and not (key == "stickslip" and parts[-1] == "F")
    if key == "breakaway":
        return parts[0] == "rates" and parts[-1] in ("t", "F", "x")
    if key == "stickslip":
        return (parts[0] == "slip_onsets" and parts[-1] == "t") or parts[0] == "periods"
    if key == "lag":
        return parts[:2] == ["w", "1"] and parts[-1] in ("z", "F")
    return False


def _floors(mdr, key):
    return dict(presliding=mdr.floors_presliding, breakaway=mdr.floors_breakaway,
                stickslip=mdr.floors_stickslip, lag=mdr.floors_lag, pid=mdr.floors_pid)[key]


def score(mdr, ref, key, q) -> float:
    """Worst relative error of q over the experiment's headline quantities (inf if one is
    missing or not finite)."""
    floors = _floors(mdr, key)
    worst = 0.0
    for k, want in ref[key].items():
        got = q.get(k)
        if got is None or not math.isfinite(got):
            return math.inf
        worst = max(worst, abs(got - want) / max(abs(want), floors(k)))
    return worst


def _best(fn, n):
    out, best = None, math.inf
    for _ in range(n):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return out, best


# lugre ---------------------------------------------------------------------------------------


def lugre_run(mdr, ref, key, rtol=1e-8):
    import lugre

    def samples(r, names=("x", "v", "z")):
        q = {}
        for i in range(len(r["t"])):
            for n in names:
                q["samples.%d.%s" % (i, n)] = float(r["friction" if n == "F" else n][i])
        return q

    if key == "presliding":
        # The scenario's preset also computes its friction loops (as `lugre dynamics` does);
        # the peers give the motion only, so lugre is timed on the motion only.
        def call():
            return samples(lugre.dynamics(scenario="presliding", times=mdr.E1_TIMES, rtol=rtol,
                                          loops=False),
                           ("x", "v", "z", "F"))
    elif key == "breakaway":
        def call():
            q = {}
            for i, rate in enumerate(mdr.E2_RATES):
                b = lugre.dynamics(scenario="breakaway", force_rate=rate, samples=2, rtol=rtol)["breakaway"]
                q.update({"rates.%d.t" % i: b["t"], "rates.%d.F" % i: b["force"], "rates.%d.x" % i: b["x"]})
            return q
    elif key == "stickslip":
        def call():
            r = lugre.dynamics(scenario="stick-slip", times=mdr.E3_TIMES, rtol=rtol)
            q = samples(r)
            on = [float(t) for t in r["slip_onsets"]]
            q.update({"slip_onsets.%d.t" % j: t for j, t in enumerate(on)})
            q.update({"periods.%d" % j: on[j + 1] - on[j] for j in range(len(on) - 1)})
            return q
    elif key == "lag":
        times = mdr.e4_times(LAG_W)

        def call():
            r = lugre.dynamics(scenario="lag", times=times, rtol=rtol)
            return {("w.1.samples.%d.%s" % (j, n)): float(r["friction" if n == "F" else n][j])
                    for j in range(len(times)) for n in ("z", "F")}
    else:
        def call():
            return samples(lugre.dynamics(scenario="pid", times=mdr.E5_TIMES, rtol=rtol))
    q, t = _best(call, 5)
    return t, score(mdr, ref, key, q)


# scipy ---------------------------------------------------------------------------------------


def scipy_run(mdr, ref, key, method, rtol):
    """One peer run as the reference's peers() does it: (time, error), or (time, inf) on failure."""
    if key == "lag":
        def call():
            saved = mdr.E4_W
            mdr.E4_W = [LAG_W]
            try:
                q, _ = mdr.run_lag(method, rtol, atol=rtol * 1e-6, peer=True)
            finally:
                mdr.E4_W = saved
            return {k.replace("w.0.", "w.1.", 1): v for k, v in q.items()}
    else:
        runner = dict(presliding=mdr.run_presliding, breakaway=mdr.run_breakaway,
                      stickslip=mdr.run_stickslip, pid=mdr.run_pid)[key]
        atol12 = dict(presliding=mdr.E1_ATOL12, breakaway=mdr.E2_ATOL12,
                      stickslip=mdr.E3_ATOL12, pid=mdr.E5_ATOL12)[key]

        def call():
            return runner(method, rtol, False, atol=mdr.atol_for(atol12, rtol), peer=True)[0]
    t0 = time.perf_counter()
    try:
        q = call()
    except Exception:  # noqa: BLE001 (a failed loose run is a row that misses the target)
        return time.perf_counter() - t0, math.inf
    first = time.perf_counter() - t0
    err = score(mdr, ref, key, q)
    return first, err, call


def scipy_fastest(mdr, ref, key, target):
    """The fastest (method, rtol) whose error is <= target: (method, rtol, time, error)."""
    best = None
    for method in ("LSODA", "Radau", "BDF"):
        for rtol in SCIPY_RTOLS:
            got = scipy_run(mdr, ref, key, method, rtol)
            if len(got) == 2 or got[1] > target:
                continue
            first, err, call = got
            _, t = _best(call, 2)
            t = min(t, first)
            if best is None or t < best[2]:
                best = (method, rtol, t, err)
            break  # tighter tolerances of this method are slower
    return best


# MuJoCo --------------------------------------------------------------------------------------


def mujoco_run(mdr, ref, key, integrator, h):
    import mujoco_peer as mp  # noqa: E402 (needs mujoco)
    import mujoco

    def driven(drive, t_end, sample_times, n_extra=0):
        """Steps the body with qfrc_applied = drive(t, x, v, extra) before each mj_step;
        returns the states at the sample steps n = round(t / h) and every step's friction."""
        m, d = mp.make(h, integrator)
        n_end = int(round(t_end / h))
        extra = [0.0] * n_extra
        want = {int(round(t / h)): i for i, t in enumerate(sample_times)}
        out = {}
        for n in range(n_end + 1):
            t = n * h
            x, v, z = d.qpos[0], d.qvel[0], d.act[0]
            f_drive = drive(t, x, v, extra)
            d.qfrc_applied[0] = f_drive
            mujoco.mj_step(m, d)
            if n in want:
                out[want[n]] = (x, v, z, -(d.actuator_force[0] + d.qfrc_passive[0]))
            for k in range(n_extra):
                extra[k] += h * (x - mdr.E5_XD)
        return out

    if key == "breakaway":
        def call():
            q = {}
            for i, b in enumerate(mp.breakaway(h, integrator)):
                q.update({"rates.%d.t" % i: b["t"], "rates.%d.F" % i: b["F"], "rates.%d.x" % i: b["x"]})
            return q
    elif key == "stickslip":
        def call():
            s = mp.stickslip(h, integrator)
            q = {}
            for i, smp in enumerate(s["samples"]):
                q.update({"samples.%d.%s" % (i, n): smp[n] for n in ("x", "v", "z")})
            on = [o[0] for o in s["onsets"]]
            q.update({"slip_onsets.%d.t" % j: t for j, t in enumerate(on)})
            q.update({"periods.%d" % j: on[j + 1] - on[j] for j in range(len(on) - 1)})
            return q
    elif key == "presliding":
        def call():
            got = driven(lambda t, x, v, e: float(_interp(t, mdr.E1_KT, mdr.E1_KF)), 65.0, mdr.E1_TIMES)
            return {("samples.%d.%s" % (i, n)): got[i][k] for i in got
                    for k, n in enumerate(("x", "v", "z", "F"))}
    elif key == "pid":
        def call():
            got = driven(lambda t, x, v, e: -mdr.E5_KV * v - mdr.E5_KP * (x - mdr.E5_XD) - mdr.E5_KI * e[0],
                         100.0, mdr.E5_TIMES, n_extra=1)
            return {("samples.%d.%s" % (i, n)): got[i][k] for i in got
                    for k, n in enumerate(("x", "v", "z"))}
    else:
        return None
    q, t = _best(call, 3)
    return t, score(mdr, ref, key, q)


def _interp(t, ts, ys):
    for i in range(1, len(ts)):
        if t <= ts[i]:
            return ys[i - 1] + (ys[i] - ys[i - 1]) * (t - ts[i - 1]) / (ts[i] - ts[i - 1])
    return ys[-1]


# the section ---------------------------------------------------------------------------------


def dynamics_rows(rows: list, summary: list, log, fmt_time, fmt_ratio) -> None:
    """Appends (case, method, time, error, ratio) rows (strings) for the five experiments."""

    def fmt_err(e):
        return "worst rel. error " + ("failed" if not math.isfinite(e) else f"{e:.1e}")

    mdr = _modules()
    ref = _reference(mdr)
    try:
        import mujoco  # noqa: F401
        have_mujoco = True
    except ImportError:
        have_mujoco = False
        log("mujoco is not installed: no MuJoCo rows")
    totals = {"lugre": 0.0, "scipy": 0.0}
    for key in EXPERIMENTS:
        case = "dynamics: " + key
        t_l, e_l = lugre_run(mdr, ref, key)
        log(f"{key}: lugre {t_l * 1e3:.2f} ms, error {e_l:.1e}")
        rows.append((case, "lugre.dynamics rtol 1e-8", fmt_time(t_l), fmt_err(e_l), fmt_ratio(1.0)))
        totals["lugre"] += t_l
        target = max(e_l, 1e-12)
        best = scipy_fastest(mdr, ref, key, target)
        if best is None:
            rows.append((case, "scipy (none reached lugre's error)", "-", "-", "-"))
        else:
            method, rtol, t_s, e_s = best
            log(f"{key}: scipy {method} rtol {rtol:g}: {t_s:.3f} s, error {e_s:.1e}")
            rows.append((case, f"scipy {method} rtol {rtol:g}", fmt_time(t_s), fmt_err(e_s), fmt_ratio(t_s / t_l)))
            totals["scipy"] += t_s
        if have_mujoco:
            for integrator, h in MUJOCO_RUNS:
                got = mujoco_run(mdr, ref, key, integrator, h)
                if got is None:
                    continue
                t_m, e_m = got
                log(f"{key}: mujoco {integrator} h {h:g}: {t_m:.3f} s, error {e_m:.1e}")
                rows.append((case, f"MuJoCo {integrator} h = {h:g}", fmt_time(t_m), fmt_err(e_m), fmt_ratio(t_m / t_l)))
    summary.append(f"dynamics, the five experiments: lugre {totals['lugre'] * 1e3:.1f} ms, scipy's "
                   f"fastest at the same accuracy {totals['scipy']:.2f} s "
                   f"({totals['scipy'] / totals['lugre']:.0f}x)")
