"""lugre.cycles on long histories: the same cycles as the `rainflow` package's algorithm (a
transcription below, so the suite needs no extra package), whatever the input's kind; the
columns asked for and only those; the input read in place; the GIL released."""

import time

import numpy as np
import pytest

import lugre

TABLE = ("range", "mean", "count", "start", "end")


def extract_cycles(series):
    """rainflow 3.2.0's reversals() and extract_cycles() (ASTM E1049-85 §5.4.4), transcribed:
    the tuples (range, mean, count, i_start, i_end) in the order rainflow yields them."""

    def reversals(series):
        series = iter(series)
        x_last, x = next(series, None), next(series, None)
        if x_last is None or x is None:
            return
        d_last = x - x_last
        yield 0, x_last
        index = None
        for index, x_next in enumerate(series, start=1):
            if x_next == x:
                continue
            d_next = x_next - x
            if d_last * d_next < 0:
                yield index, x
            x_last, x = x, x_next
            d_last = d_next
        if index is not None:
            yield index + 1, x_next

    def row(p1, p2, count):
        (i1, x1), (i2, x2) = p1, p2
        return abs(x1 - x2), 0.5 * (x1 + x2), count, i1, i2

    points = []
    for point in reversals(series):
        points.append(point)
        while len(points) >= 3:
            x1, x2, x3 = points[-3][1], points[-2][1], points[-1][1]
            if abs(x3 - x2) < abs(x2 - x1):
                break
            if len(points) == 3:
                yield row(points[0], points[1], 0.5)
                points.pop(0)
            else:
                yield row(points[-3], points[-2], 1.0)
                last = points.pop()
                del points[-2:]
                points.append(last)
    while len(points) > 1:
        yield row(points[0], points[1], 0.5)
        points.pop(0)


def table(c):
    """The cycles of a lugre.cycles result as rainflow's tuples."""
    cyc = c["cycles"]
    return list(zip(*(cyc[k].tolist() for k in TABLE)))


@pytest.fixture(scope="module")
def walks():
    rng = np.random.default_rng(8)
    return {
        # Gaussian steps: a reversal every other sample, deep stacks.
        "gaussian": rng.standard_normal(30_000).cumsum(),
        # Integer steps in -2..2: plateaus, ties, equal ranges.
        "integer": rng.integers(-2, 3, 30_000).cumsum().astype(np.float64),
        # A slow sine with noise: long runs, nested wiggles.
        "sine": np.sin(np.arange(30_000) / 3000.0) * (1 + np.arange(30_000) / 3e4)
        + 0.01 * rng.standard_normal(30_000),
    }


@pytest.mark.parametrize("kind", ["gaussian", "integer", "sine"])
def test_same_cycles_as_rainflow(walks, kind):
    x = walks[kind]
    want = list(extract_cycles(x.tolist()))
    c = lugre.cycles(x)
    assert table(c) == want
    s = c["summary"]
    assert s["full_cycles"] + s["half_cycles"] == len(want)
    assert s["full_cycles"] == sum(1 for r in want if r[2] == 1.0)
    # Every reversal starts or ends a cycle.
    ends = np.union1d(c["cycles"]["start"], c["cycles"]["end"])
    np.testing.assert_array_equal(c["reversals"]["index"], ends)
    np.testing.assert_array_equal(c["reversals"]["u"], x[ends])


def test_any_input_kind_gives_the_same_cycles(walks):
    x = walks["gaussian"][:5000]
    want = table(lugre.cycles(x))
    readonly = x.copy()
    readonly.flags.writeable = False
    strided = np.repeat(x, 2)[::2]
    assert not strided.flags.c_contiguous
    for arg in (x.tolist(), tuple(x), readonly, strided, x.astype(">f8"),
                np.asfortranarray(x), x.reshape(1, -1)[0]):
        assert table(lugre.cycles(arg)) == want
    ints = walks["integer"][:5000]
    assert table(lugre.cycles(ints.astype(np.int64))) == table(lugre.cycles(ints))
    assert table(lugre.cycles(ints.astype(np.float32))) == table(lugre.cycles(ints))


def test_input_is_read_not_kept_nor_changed(walks):
    x = walks["gaussian"].copy()
    before = x.copy()
    c = lugre.cycles(x)
    np.testing.assert_array_equal(x, before)
    for col in list(c["cycles"].values()) + list(c["reversals"].values()):
        assert col.flags.owndata or col.base is not None
        assert not np.shares_memory(col, x)
        assert col.flags.writeable and col.flags.c_contiguous and col.ndim == 1
    # The result does not change when the input does afterwards.
    r = c["cycles"]["range"].copy()
    x[:] = 0.0
    np.testing.assert_array_equal(c["cycles"]["range"], r)


def test_only_the_columns_asked_for(walks):
    x = walks["gaussian"]
    full = lugre.cycles(x)
    lean = lugre.cycles(x, reversals=False, closures=False)
    assert lean["reversals"] is None
    assert set(lean["cycles"]) == set(TABLE)
    assert set(full["cycles"]) == set(TABLE) | {"closure", "closure_position"}
    for k in TABLE:
        np.testing.assert_array_equal(lean["cycles"][k], full["cycles"][k])
        assert lean["cycles"][k].dtype == full["cycles"][k].dtype
    assert lean["summary"] == full["summary"]
    no_rev = lugre.cycles(x, reversals=False)
    assert no_rev["reversals"] is None
    np.testing.assert_array_equal(no_rev["cycles"]["closure_position"], full["cycles"]["closure_position"])
    no_cl = lugre.cycles(x, closures=False)
    assert "closure" not in no_cl["cycles"]
    np.testing.assert_array_equal(no_cl["reversals"]["u"], full["reversals"]["u"])
    # With a model the energies come whatever is left out.
    e = lugre.cycles(x[:3000], model=lugre.LuGre(), reversals=False, closures=False)
    assert {"work", "dissipation", "stored_energy_change", "closure_gap"} <= set(e["cycles"])
    assert "closure" not in e["cycles"] and e["reversals"] is None
    # Explicit defaults.
    assert table(lugre.cycles(x, reversals=True, closures=True)) == table(full)
    assert table(lugre.cycles(x, reversals=None, closures=None)) == table(full)
    for bad in (1, 0, "yes", np.float64(1.0)):
        with pytest.raises(TypeError, match="reversals"):
            lugre.cycles(x, reversals=bad)
        with pytest.raises(TypeError, match="closures"):
            lugre.cycles(x, closures=bad)
    with pytest.raises(TypeError):
        lugre.cycles(x, 0.0, None, 0.0, False)  # keyword-only


def test_closures_are_the_first_return_to_the_start(walks):
    x = walks["gaussian"][:4000]
    cyc = lugre.cycles(x)["cycles"]
    full = np.flatnonzero(cyc["count"] == 1.0)
    assert len(full) > 900
    for k in full[::7]:
        s, e = cyc["start"][k], cyc["end"][k]
        ua, ub = x[s], x[e]
        after = x[e + 1:]
        back = np.flatnonzero(after <= ua if ua < ub else after >= ua)[0] + e + 1
        assert cyc["closure"][k] == back
        assert back - 1 < cyc["closure_position"][k] <= back
    half = cyc["count"] == 0.5
    assert (cyc["closure"][half] == -1).all() and np.isnan(cyc["closure_position"][half]).all()


def test_empty_and_short_histories():
    # One rule in the core, as `lugre cycles` and the C ABI: a history of 0 or 1 samples has
    # no range and is refused (the rainflow package returns nothing).
    for h, message in (([], "the history is empty (no samples)"),
                       (np.array([]), "the history is empty (no samples)"),
                       ([1.0], "a history needs at least 2 samples, got 1"),
                       (np.array([2.5]), "a history needs at least 2 samples, got 1")):
        with pytest.raises(ValueError) as e:
            lugre.cycles(h)
        assert str(e.value) == message
        with pytest.raises(ValueError):
            lugre.cycles(h, model=lugre.LuGre())
    with pytest.raises(ValueError, match="gate"):
        lugre.cycles([], gate=-1.0)
    # Two samples are one half cycle (ASTM E1049); rainflow 3.2 gives none (its reversals()
    # yields the last sample only after a third one): the difference the README states.
    c = lugre.cycles(np.array([0.0, 1.0]), reversals=False)
    assert table(c) == [(1.0, 0.5, 0.5, 0, 1)]
    with pytest.raises(ValueError, match="one-dimensional"):
        lugre.cycles(np.zeros((3, 3)))
    with pytest.raises(ValueError, match=r"u\[7777\] must be a finite number"):
        x = np.arange(10_000.0)
        x[7777] = np.nan
        lugre.cycles(x)


def test_a_million_samples_quickly():
    x = np.random.default_rng(3).standard_normal(1_000_000).cumsum()
    t0 = time.perf_counter()
    c = lugre.cycles(x, reversals=False, closures=False)
    elapsed = time.perf_counter() - t0
    # ~10 ms on a 2-core EPYC; rainflow's Python loop takes ~300 ms.
    assert elapsed < 1.0, f"{elapsed:.2f} s"
    assert 240_000 < len(c["cycles"]["range"]) < 260_000


def test_gil_is_released_during_the_count(assert_gil_released):
    """Another Python thread runs while the cycles of a long history are counted (with
    energies, so that every sample goes through the walk: long enough to see)."""
    x = np.random.default_rng(5).standard_normal(3_000_000).cumsum()
    assert_gil_released(lambda: lugre.cycles(x, model=lugre.LuGre()))
