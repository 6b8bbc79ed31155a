"""Python at parity with the other front ends: results and models pickle (to other processes
too), tables go straight into pandas, and the core's one wording and one rule reach Python as
they reach the command line (and the C ABI, whose test checks the same text)."""

import concurrent.futures
import math
import multiprocessing
import pickle

import numpy as np
import pandas as pd
import pytest

import lugre

ASTM = [-2.0, 1.0, -3.0, 5.0, -1.0, 3.0, -4.0, 4.0, -2.0]


def same_loop(a, b):
    """Two HysteresisLoops are the same to the bit: input, model, loops and their energies."""
    assert type(a) is type(b) and a.model == b.model
    for name in ("rho", "u", "y"):
        assert getattr(a, name).tobytes() == getattr(b, name).tobytes(), name
    assert (a.period, a.work_per_period) == (b.period, b.work_per_period)
    assert [l.to_dict() for l in a.loops] == [l.to_dict() for l in b.loops]
    ta, tb = a.theorem_a, b.theorem_a
    assert (ta is None) == (tb is None)
    if ta is not None:
        assert ta.to_dict() == tb.to_dict()


def round_trip(obj):
    return pickle.loads(pickle.dumps(obj, protocol=pickle.HIGHEST_PROTOCOL))


@pytest.mark.parametrize("make", [
    lambda: lugre.LuGre(sigma0=6).loop_bimodal(0, 0.5, 1, 1.5),
    lambda: lugre.LuGre(sigma0=1e5, fs=1.5).loop([0, 1e-5, 2e-6, 8e-6]),
    lambda: lugre.Dahl(rho=3, fc=0.25).loop(np.array([0.0, 2.0, 0.5, 1.5, -1.0])),
    lambda: lugre.Dahl().loop_bimodal(0, 0.2, 1, 1.5),
])
def test_loops_pickle_to_the_bit(make):
    hl = make()
    back = round_trip(hl)
    same_loop(hl, back)
    for protocol in range(2, pickle.HIGHEST_PROTOCOL + 1):
        same_loop(hl, pickle.loads(pickle.dumps(hl, protocol=protocol)))


def test_what_a_loop_reports_pickles():
    hl = lugre.LuGre(sigma0=6).loop_bimodal(0, 0.5, 1, 1.5)
    for loop in hl.loops:
        back = round_trip(loop)
        assert type(back) is lugre.Loop and back.to_dict() == loop.to_dict()
        assert repr(back) == repr(loop)
    point = hl.loops[1].end
    assert round_trip(point) == point and type(round_trip(point)) is lugre.LoopPoint
    ta = round_trip(hl.theorem_a)
    assert type(ta) is lugre.TheoremA and str(ta) == str(hl.theorem_a)
    curve = hl.sample(101)
    back = round_trip(curve)
    assert type(back) is lugre.Curve
    for a, b in zip(curve, back):
        assert a.tobytes() == b.tobytes()


def test_result_dicts_pickle():
    m = lugre.LuGre(sigma0=6)
    c = lugre.cycles(ASTM, model=m)
    back = round_trip(c)
    assert type(back) is lugre.CyclesResult
    pd.testing.assert_frame_equal(back.to_frame(), c.to_frame(), check_exact=True)
    assert back["summary"] == c["summary"]
    s = m.simulate([0, 1, 0.5, 1.5], gamma=10, periods=2)
    back = round_trip(s)
    assert set(back) == set(s) and all(back[k].tobytes() == s[k].tobytes() for k in s)


def _cycles_in_worker(u):
    return lugre.cycles(u, model=lugre.LuGre(sigma0=6))


def test_a_process_pool_computes_loops_and_counts():
    """Models go to worker processes and loops and results come back (spawned workers: each
    imports lugre afresh, as on a cluster)."""
    model = lugre.LuGre(sigma0=6)
    inputs = [[0, 1, 0.5, 1.5], [0, 2, 1, 3, -1, 0.5]]
    context = multiprocessing.get_context("spawn")
    with concurrent.futures.ProcessPoolExecutor(max_workers=2, mp_context=context) as pool:
        loops = list(pool.map(lugre.LuGre.loop, [model] * len(inputs), inputs))
        counted = pool.submit(lugre.cycles, ASTM, 0.0, model).result()
    for hl, tp in zip(loops, inputs):
        same_loop(hl, model.loop(tp))
    here = lugre.cycles(ASTM, 0.0, model)
    pd.testing.assert_frame_equal(counted.to_frame(), here.to_frame(), check_exact=True)


def test_tables_go_straight_into_pandas():
    m = lugre.LuGre(sigma0=6)
    c = lugre.cycles(ASTM, model=m)
    frame = c.to_frame()
    assert list(frame.columns) == list(c["cycles"]) and len(frame) == 7
    pd.testing.assert_frame_equal(frame, pd.DataFrame(c["cycles"]), check_exact=True)
    assert frame["range"].tolist() == [3.0, 4.0, 4.0, 8.0, 9.0, 8.0, 6.0]
    s = pd.DataFrame(m.simulate([0, 1, 0.5, 1.5], gamma=10, periods=2))
    assert list(s.columns) == ["t", "u", "z", "dz", "y"] and len(s) > 10
    hl = m.loop_bimodal(0, 0.5, 1, 1.5)
    table = pd.DataFrame(hl.loop_table)
    assert len(table) == len(hl.loops) == 2
    assert table["work"].tolist() == [l.work for l in hl.loops]
    curve = hl.sample(11).to_frame()
    assert list(curve.columns) == ["rho", "u", "y"] and len(curve) == 11
    assert curve["y"].to_numpy().tobytes() == hl.sample(11).y.tobytes()


@pytest.mark.parametrize("values, message", [
    ([0.0, math.nan, 1.0], "u[1] must be a finite number, got NaN"),
    ([0.0, 1.0, -math.inf], "u[2] must be a finite number, got -inf"),
    ([0.0, 1e308], "u[1] = 1e308 is too large"),
    ([1.0], "a history needs at least 2 samples, got 1"),
])
def test_a_bad_history_is_worded_as_on_the_command_line(values, message, lugre_cli_error):
    """The core's wording, word for word in Python and after `--values: ` on the command line
    (the C ABI's test checks the same text for the same series)."""
    with pytest.raises(ValueError) as e:
        lugre.cycles(values)
    assert str(e.value).startswith(message)
    text = ",".join(repr(v) for v in values)
    want = f"--values: {e.value}"
    # A list on the command line counts its items from 1 (`u[1]` is its item 2).
    if "must be a finite number" in message:
        index = int(message[2:message.index("]")])
        want = f"--values: item {index + 1}" + str(e.value)[message.index("]") + 1:]
    assert lugre_cli_error(["cycles", "--values", text]) == want
