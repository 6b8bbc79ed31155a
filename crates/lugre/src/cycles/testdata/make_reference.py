#!/usr/bin/env python3
"""Reference cycles for `lugre::cycles` from the Python package `rainflow` (3.2.0), the most
widely used public implementation of ASTM E1049-85 rainflow counting.

    python3 -m venv /tmp/rfvenv && /tmp/rfvenv/bin/pip install rainflow==3.2.0
    /tmp/rfvenv/bin/python make_reference.py > rainflow_reference.txt

The series are drawn from a 64-bit LCG that the Rust test replays bit for bit (same integer
arithmetic, same IEEE operations), so only the outputs are stored. Four kinds of series, in
turn: small integers (many ties and plateaus), a random walk with 20 % zero steps (plateaus),
uniform values with 20 % repeats, and an integer random walk (ties at every level). Lengths
3 to 40 (`rainflow` yields nothing for 2 samples; see the module docs).

Line format, one case per line:
    case|idx:u,idx:u,...|range:mean:count:start:end,...
with every float in Python's repr (shortest round trip).
"""

import sys

import rainflow

assert rainflow.__version__ == "3.2.0", rainflow.__version__

CASES = 300
MASK = (1 << 64) - 1


class Lcg:
    def __init__(self, seed):
        self.state = seed

    def next_u64(self):
        self.state = (self.state * 6364136223846793005 + 1442695040888963407) & MASK
        return self.state

    def next_f64(self):
        return (self.next_u64() >> 11) / float(1 << 53)


def series(rng, case):
    n = 3 + rng.next_u64() % 38
    kind = case % 4
    out = []
    x = 0.0
    for _ in range(n):
        if kind == 0:
            x = float((rng.next_u64() >> 33) % 7) - 3.0
        elif kind == 1:
            r = rng.next_f64()
            if r >= 0.2:
                x += rng.next_f64() - 0.5
        elif kind == 2:
            r = rng.next_f64()
            if r >= 0.2 or not out:
                x = rng.next_f64() * 10.0 - 5.0
        else:
            x += float((rng.next_u64() >> 33) % 5) - 2.0
        out.append(x)
    return out


def main():
    rng = Lcg(0x853C49E6748FEA9B)
    w = sys.stdout.write
    for case in range(CASES):
        s = series(rng, case)
        revs = ",".join(f"{i}:{u!r}" for i, u in rainflow.reversals(s))
        cycles = ",".join(
            f"{float(r)!r}:{float(m)!r}:{c!r}:{i}:{j}"
            for r, m, c, i, j in rainflow.extract_cycles(s)
        )
        w(f"{case}|{revs}|{cycles}\n")


main()
