"""examples/hunting.py: the describing-function prediction of the PID experiment's hunting
(Canudas de Wit et al. 1995, Fig. 8) against the simulation, as the README states it."""

import math
import pathlib
import runpy

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[3]


def test_the_hunting_example_predicts_within_five_percent(capsys):
    example = runpy.run_path(str(ROOT / "examples" / "hunting.py"))
    sim, plain, pred = example["main"]()
    out = capsys.readouterr().out
    assert "predicted amplitude" in out and "no solution" in out
    # The simulated hunting (lugre dynamics): e within +-0.0639 m, a period of 24.44 s.
    assert abs(sim["amplitude"] - 0.0639) < 5e-4 and abs(sim["period"] - 24.44) < 0.05
    # The plain describing function cannot balance: it would need k_eq <= -2.33 N/m below
    # sqrt(Ki/Kv), or c_eq < 0 above.
    assert plain["k_eq_min"] > plain["k_eq_needed_max"] + 2.0
    assert plain["c_eq_min"] > 0.0
    # Mass + friction alone as the block: its gain jumps over the one needed at the break-away.
    gap = plain["open_loop"]
    assert gap["below"] < gap["need"] / 100.0 and gap["above"] > 5.0 * gap["need"]
    # In the simulated cycle the integrator's balance holds exactly for the first harmonics.
    w = 2.0 * math.pi / sim["period"]
    assert abs(np.angle(sim["ratio"]) + math.pi / 2) < 1e-4
    assert abs(abs(sim["ratio"]) * example["KI"] / w - 1.0) < 1e-4
    # The balance is solved (arg -90 deg, gain w / Ki) and lands within 5 % above the simulation.
    assert abs(np.angle(pred["N"]) + math.pi / 2) < 1e-8
    assert abs(abs(pred["N"]) * example["KI"] / pred["w"] - 1.0) < 1e-8
    for key in ("amplitude", "first_harmonic", "period"):
        assert 0.0 < pred[key] / sim[key] - 1.0 < 0.05, key
