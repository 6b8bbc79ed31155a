"""Two builds of the `lugre` binary side by side on the same commands (loop, cycles, simulate,
dynamics, fit): the instructions each run executes (valgrind's cachegrind; the load of a
shared machine does not change them) and wall-clock times taken alternately, A, B, A, B, ...
(so that both see the same load), as the median and the range of each.

    python3 bench/cli_ab.py BEFORE/lugre AFTER/lugre                 # counts and 7 timed pairs
    python3 bench/cli_ab.py A B --pairs 11 --no-count --markdown t.md
    python3 bench/cli_ab.py --workloads A/workloads B/workloads --no-count   # the benches' cases

With `--workloads`, A and B are builds of bench/workloads.rs (see bench/instructions.sh, which
also counts their instructions) and each case of `cargo bench -p lugre` is run and timed as a
whole process (the inputs' setup included: compare the differences of B and A, not the
absolute times).

The inputs are made in a temporary folder from fixed seeds (stdlib only): 10^5 random turning
points, a 10^6-sample random walk, 10^5 samples of a noisy 1 mm sine, and the fits' records
from A's `lugre simulate` plus 1 % noise. Only flags both builds accept are used.
"""
import argparse
import csv
import math
import os
import random
import re
import statistics
import subprocess
import sys
import tempfile
import time


def make_inputs(d, lugre):
    r = random.Random(7)

    def write(name, header, rows):
        with open(os.path.join(d, name), "w") as fh:
            fh.write(header + "\n")
            fh.writelines(",".join(map(repr, row)) + "\n" for row in rows)

    u, tp = 0.0, []
    for i in range(100_000):
        s = 0.01 + 0.99 * r.random()
        u += s if i % 2 == 0 else -s
        tp.append((u,))
    write("tp.csv", "u", tp)
    u, walk = 0.0, []
    for _ in range(1_000_000):
        u += r.random() - 0.5
        walk.append((u,))
    write("walk.csv", "u", walk)
    write("path.csv", "t,u", [(i * 1e-4, 1e-3 * math.sin(math.pi * i * 1e-4)
                               + (r.random() - 0.5) * 2e-6) for i in range(100_000)])
    run = lambda *a: subprocess.run([lugre, *a], cwd=d, check=True, capture_output=True)
    run("simulate", "--sigma0", "6", "--turning-points", "0,1,0.5,1.5", "--gamma", "inf",
        "--periods", "5", "--samples-per-period", "20000", "--csv", "slowsim.csv")
    run("simulate", "--preset", "canudas1995", "--sine", "1e-3,2", "--periods", "3",
        "--samples-per-period", "20000", "--csv", "fullsim.csv")
    rows = list(csv.DictReader(open(os.path.join(d, "slowsim.csv"))))
    write("slow.csv", "u,F", [(float(x["u"]), float(x["y"]) + 0.01 * r.gauss(0, 1))
                              for x in rows if float(x["t"]) >= 12.0])
    rows = list(csv.DictReader(open(os.path.join(d, "fullsim.csv"))))
    write("full.csv", "t,u,F", [(float(x["t"]), float(x["u"]), float(x["y"]) + 0.01 * r.gauss(0, 1))
                                for x in rows])


CASES = {
    "loop, 4 turning points": ["loop", "--sigma0", "6", "--turning-points", "0,1,0.5,1.5", "--json"],
    "loop --input, 10^5 turning points": ["loop", "--input", "tp.csv", "--json"],
    "cycles --input, 10^6 samples": ["cycles", "--input", "walk.csv", "--csv", "out.csv"],
    "simulate, 4 turning points": ["simulate", "--sigma0", "6", "--turning-points", "0,1,0.5,1.5", "--json"],
    "simulate --input, 10^5 samples (canudas1995)": ["simulate", "--preset", "canudas1995", "--input", "path.csv", "--csv", "out.csv"],
    "dynamics --scenario stick-slip": ["dynamics", "--scenario", "stick-slip", "--csv", "out.csv"],
    "dynamics --scenario pid": ["dynamics", "--scenario", "pid", "--json"],
    "fit, slow, 4*10^4 samples": ["fit", "--input", "slow.csv", "--json"],
    "fit --fit full, 6*10^4 samples": ["fit", "--fit", "full", "--input", "full.csv", "--fix", "beta=2", "--json"],
}


def instructions(binary, args, d):
    out = subprocess.run(["valgrind", "--tool=cachegrind", "--cache-sim=no",
                          "--cachegrind-out-file=/dev/null", binary, *args],
                         cwd=d, capture_output=True, text=True)
    return int(re.search(r"I\s+refs:\s+([\d,]+)", out.stderr).group(1).replace(",", ""))


def wall(binary, args, d):
    t0 = time.perf_counter()
    subprocess.run([binary, *args], cwd=d, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - t0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--pairs", type=int, default=7, help="timed A/B pairs per case (default 7)")
    ap.add_argument("--no-count", action="store_true", help="skip the instruction counts")
    ap.add_argument("--markdown", help="also write the table as Markdown")
    ap.add_argument("--workloads", action="store_true",
                    help="A and B are builds of bench/workloads.rs: time its cases")
    args = ap.parse_args()
    a, b = os.path.abspath(args.a), os.path.abspath(args.b)
    with tempfile.TemporaryDirectory() as d:
        if args.workloads:
            names = subprocess.run([a, "list"], capture_output=True, text=True).stdout.split()
            cases = {n: [n, "10" if n.startswith("dynamics/") else "1"] for n in names}
        else:
            make_inputs(d, a)
            cases = CASES
        rows = []
        for name, cmd in cases.items():
            for binary in (a, b):  # a failure shows here, outside the timing
                subprocess.run([binary, *cmd], cwd=d, check=True, capture_output=True)
            counts = ("", "", "")
            if not args.no_count:
                ia, ib = instructions(a, cmd, d), instructions(b, cmd, d)
                counts = (f"{ia / 1e6:.2f} M", f"{ib / 1e6:.2f} M", f"{100 * (ib - ia) / ia:+.2f} %")
            ta, tb = [], []
            for _ in range(args.pairs):
                ta.append(wall(a, cmd, d))
                tb.append(wall(b, cmd, d))
            fmt = lambda ts: f"{1e3 * statistics.median(ts):.1f} ms [{1e3 * min(ts):.1f}, {1e3 * max(ts):.1f}]"
            ratio = statistics.median(tb) / statistics.median(ta)
            shown = " ".join(cmd) if args.workloads else f"lugre {' '.join(cmd)}"
            rows.append((f"`{shown}`", name, *counts, fmt(ta), fmt(tb), f"{ratio:.3f}"))
            print(" | ".join(rows[-1][1:]), flush=True)
    head = ("command", "case", "instructions A", "instructions B", "change",
            "wall A: median [min, max]", "wall B", "B/A (medians)")
    if args.markdown:
        with open(args.markdown, "w") as fh:
            fh.write("| " + " | ".join(head) + " |\n|" + "---|" * len(head) + "\n")
            fh.writelines("| " + " | ".join(r) + " |\n" for r in rows)


if __name__ == "__main__":
    sys.exit(main())
