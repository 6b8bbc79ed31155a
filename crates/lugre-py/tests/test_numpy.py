"""numpy in and out: any real sequence or array in (lists, tuples, float32/int dtypes,
non-contiguous views, any shape), float64 arrays out; speed and the GIL."""

import time

import numpy as np
import pytest

import lugre


@pytest.fixture(scope="module")
def hl():
    return lugre.LuGre(sigma0=6).loop_bimodal(0, 0.5, 1, 1.5)


def test_outputs_are_float64_arrays(hl):
    for a in (hl.rho, hl.u, hl.y, hl.theorem_a.rho, hl.theorem_a.y):
        assert isinstance(a, np.ndarray)
        assert a.dtype == np.float64
        assert a.ndim == 1
        assert a.flags.c_contiguous
    assert hl.rho.shape == hl.u.shape == hl.y.shape == (4,)
    assert hl.theorem_a.rho.shape == hl.theorem_a.y.shape == (6,)


def test_outputs_are_copies(hl):
    y = hl.y
    y[0] = 123.0
    assert hl.y[0] != 123.0


def test_y_at_accepts_any_real_sequence(hl):
    want = hl.y_at(np.array([0.0, 0.5, 1.0, 2.0]))
    for arg in (
        [0.0, 0.5, 1.0, 2.0],
        (0.0, 0.5, 1.0, 2.0),
        [0, 0.5, 1, 2],
        np.array([0.0, 0.5, 1.0, 2.0], dtype=np.float32),
        np.array([0.0, 0.5, 1.0, 2.0], dtype=np.float16),
        np.array([0.0, 0.5, 1.0, 2.0], dtype=np.longdouble),
        [np.float32(0), np.float64(0.5), np.int64(1), 2],
    ):
        got = hl.y_at(arg)
        assert isinstance(got, np.ndarray) and got.dtype == np.float64
        np.testing.assert_array_equal(got, want)
    ints = hl.y_at(np.array([0, 1, 2, 3], dtype=np.int32))
    np.testing.assert_array_equal(ints, hl.y_at([0.0, 1.0, 2.0, 3.0]))
    np.testing.assert_array_equal(hl.y_at(np.array([0, 1, 2], dtype=np.uint8)), hl.y_at([0.0, 1.0, 2.0]))


def test_y_at_non_contiguous_views(hl):
    base = np.linspace(-3.0, 9.0, 1201)
    want = hl.y_at(base.copy())
    for view, index in (
        (base[::3], slice(None, None, 3)),
        (base[::-1], slice(None, None, -1)),
        (base[5:900:7], slice(5, 900, 7)),
    ):
        assert not view.flags.c_contiguous or view.strides[0] < 0
        np.testing.assert_array_equal(hl.y_at(view), want[index])
    grid = base[:1200].reshape(40, 30)
    np.testing.assert_array_equal(hl.y_at(grid.T), want[:1200].reshape(40, 30).T)
    fortran = np.asfortranarray(grid)
    np.testing.assert_array_equal(hl.y_at(fortran), want[:1200].reshape(40, 30))


def test_y_at_byte_order_and_alignment(hl):
    r = np.linspace(0.0, 4.0, 17)
    want = hl.y_at(r)
    np.testing.assert_array_equal(hl.y_at(r.astype(">f8")), want)
    buf = np.zeros(17 * 8 + 1, dtype=np.uint8)
    misaligned = buf[1:].view(np.float64)
    misaligned[:] = r
    assert not misaligned.flags.aligned
    np.testing.assert_array_equal(hl.y_at(misaligned), want)


def test_y_at_keeps_the_shape(hl):
    r = np.linspace(0, 4, 24).reshape(2, 3, 4)
    out = hl.y_at(r)
    assert out.shape == (2, 3, 4) and out.dtype == np.float64
    np.testing.assert_array_equal(out.ravel(), hl.y_at(r.ravel()))
    assert hl.y_at([]).shape == (0,)
    assert hl.y_at(np.zeros((0, 3))).shape == (0, 3)


def test_scalars_in_scalars_out(hl):
    for arg in (2.0, 2, np.float64(2.0), np.float32(2.0), np.int64(2)):
        got = hl.y_at(arg)
        assert type(got) is float, type(got)
        assert got == hl.y_at([2.0])[0]
    # A 0-d array stays an array, as numpy's ufuncs do.
    zero_d = hl.y_at(np.array(2.0))
    assert isinstance(zero_d, np.ndarray) and zero_d.shape == ()


def test_y_at_is_periodic_and_nan_for_non_finite_rho(hl):
    r = np.array([0.3, 1.7, 3.9])
    np.testing.assert_allclose(hl.y_at(r + 8 * hl.period), hl.y_at(r), rtol=1e-12)
    np.testing.assert_allclose(hl.y_at(r - hl.period), hl.y_at(r), rtol=1e-12)
    out = hl.y_at([np.nan, np.inf, -np.inf, 0.0])
    assert np.isnan(out[:3]).all() and out[3] == hl.y[0]
    assert np.isnan(hl.u_at(np.nan))


def test_u_at_is_the_normalized_input(hl):
    # psi_u: 0 -> 1 on [0, 1], 1 -> 0.5 on [1, 1.5], 0.5 -> 1.5 on [1.5, 2.5], 1.5 -> 0 on [2.5, 4].
    r = [0.0, 0.25, 1.0, 1.25, 1.5, 2.0, 2.5, 3.25, 4.0]
    np.testing.assert_allclose(hl.u_at(r), [0.0, 0.25, 1.0, 0.75, 0.5, 1.0, 1.5, 0.75, 0.0], rtol=0, atol=1e-15)


def test_turning_points_accept_any_real_sequence():
    m = lugre.LuGre(sigma0=6)
    want = m.loop([0.0, 1.0, 0.5, 1.5]).y
    for arg in (
        (0, 1, 0.5, 1.5),
        np.array([0, 1, 0.5, 1.5], dtype=np.float32),
        np.array([0.0, 9.0, 1.0, 9.0, 0.5, 9.0, 1.5, 9.0])[::2],
        np.array([1.5, 0.5, 1.0, 0.0])[::-1],
        [np.float64(0), 1, 0.5, 1.5],
    ):
        np.testing.assert_array_equal(m.loop(arg).y, want)
    # Integer inputs are converted to float64.
    np.testing.assert_array_equal(m.loop(np.array([0, 2, 1, 3])).u, [0.0, 2.0, 1.0, 3.0])


def test_one_period_of_samples_gives_its_turning_points():
    # Only the turning points matter: the samples of a triangle wave through the same extrema
    # give the same loop.
    m = lugre.LuGre(sigma0=6)
    samples = np.concatenate([np.linspace(0, 1, 11), np.linspace(1, 0.5, 6)[1:], np.linspace(0.5, 1.5, 11)[1:], np.linspace(1.5, 0, 16)[1:]])
    hl = m.loop(samples)
    np.testing.assert_array_equal(hl.u, [0.0, 1.0, 0.5, 1.5])
    np.testing.assert_allclose(hl.y, m.loop([0, 1, 0.5, 1.5]).y, rtol=1e-15)


def test_sample(hl):
    c = hl.sample(5)
    rho, u, y = c
    for a in (rho, u, y, c.rho, c.u, c.y):
        assert isinstance(a, np.ndarray) and a.dtype == np.float64 and a.shape == (5,)
    np.testing.assert_array_equal(rho, [0.0, 1.0, 2.0, 3.0, 4.0])
    np.testing.assert_array_equal(u, hl.u_at(rho))
    np.testing.assert_array_equal(y, hl.y_at(rho))
    assert rho[-1] == hl.period and y[-1] == y[0]  # both ends of the period
    assert hl.sample().rho.shape == (1001,)
    assert hl.sample(np.int64(3)).rho.shape == (3,)
    assert "Curve" in repr(c)


def test_model_curves_are_vectorised():
    m = lugre.LuGre(sigma2=0.4)
    v = np.array([-1.0, 0.0, 1.0])
    np.testing.assert_allclose(m.g(v), 1 + np.exp(-np.abs(v)), rtol=1e-15)
    np.testing.assert_array_equal(m.f(v), 0.4 * v)
    assert m.g(0) == 2.0 and type(m.g(0)) is float


def test_a_million_points_are_vectorised(hl):
    """y_at on 10^6 points costs far less than 10^5 ten-point calls: no per-element Python."""
    big = np.linspace(-10.0, 10.0, 1_000_000)
    small = big[:10].copy()

    def best(f, repeat):
        times = []
        for _ in range(repeat):
            t0 = time.perf_counter()
            f()
            times.append(time.perf_counter() - t0)
        return min(times)

    t_big = best(lambda: hl.y_at(big), 5)
    t_small = best(lambda: [hl.y_at(small) for _ in range(1000)], 3) / 1000
    scaled = t_small * (len(big) / len(small))
    assert t_big < 0.5, f"10^6-point y_at took {t_big:.3f} s"
    # The ten-point call is dominated by per-call overhead; a per-element Python cost would
    # make the big call at least as slow as the scaled small one.
    assert t_big < scaled, f"10^6 points: {t_big:.4f} s; 10-point call scaled: {scaled:.4f} s"


def test_long_loop_computations_are_vectorised():
    rng = np.random.default_rng(5)
    tp = np.cumsum(rng.choice([-1.0, 1.0], 200_001) * rng.uniform(0.1, 1.0, 200_001))
    t0 = time.perf_counter()
    hl = lugre.LuGre(sigma0=3).loop(tp)
    loops = hl.loops
    elapsed = time.perf_counter() - t0
    assert len(hl) > 1000 and len(loops) > 100
    assert elapsed < 5.0, f"{elapsed:.2f} s"
    assert loops[0].kind == "major" and all(l.kind == "minor" for l in loops[1:])
    assert all(l.dissipation >= 0 for l in loops)


def test_gil_is_released_during_y_at(hl, assert_gil_released):
    """Another Python thread runs while y_at computes (the GIL is released)."""
    big = np.linspace(0.0, 1000.0, 6_000_000)
    assert_gil_released(lambda: hl.y_at(big))


def test_loop_table_is_loops_as_columns():
    """loop_table holds exactly what .loops holds, row for row, as numpy columns."""
    rng = np.random.default_rng(11)
    tp = np.cumsum(np.where(np.arange(2000) % 2 == 0, 1.0, -1.0) * rng.uniform(0.01, 1.0, 2000))
    hl = lugre.LuGre(sigma0=3).loop(tp)
    t, loops = hl.loop_table, hl.loops
    assert set(t) == {
        "kind", "parent", "depth", "work", "stored_energy_change", "dissipation", "closure_gap",
        *(f"{p}_{c}" for p in ("start", "reversal", "end") for c in ("rho", "u", "y")),
    }
    for name, column in t.items():
        assert isinstance(column, np.ndarray) and column.shape == (len(loops),), name
    assert t["kind"].dtype == np.int64 and t["parent"].dtype == np.int64
    for i, l in enumerate(loops):
        assert t["kind"][i] == (0 if l.kind == "major" else 1)
        assert t["parent"][i] == (-1 if l.parent is None else l.parent)
        assert t["depth"][i] == l.depth
        for p in ("start", "reversal", "end"):
            pt = getattr(l, p)
            assert (t[f"{p}_rho"][i], t[f"{p}_u"][i], t[f"{p}_y"][i]) == (pt.rho, pt.u, pt.y)
        for e in ("work", "stored_energy_change", "dissipation", "closure_gap"):
            assert t[e][i] == getattr(l, e)


def test_loop_table_is_fast_for_a_million_turning_points():
    rng = np.random.default_rng(12)
    n = 1_000_000
    tp = np.cumsum(np.where(np.arange(n) % 2 == 0, 1.0, -1.0) * rng.uniform(0.01, 1.0, n))
    hl = lugre.LuGre().loop(tp)
    t0 = time.perf_counter()
    t = hl.loop_table
    elapsed = time.perf_counter() - t0
    assert len(t["work"]) == n // 2 and (t["dissipation"] >= 0).all()
    # the loops themselves take ~0.2 s, the columns ~0.05 s; .loops (one object per loop)
    # takes ~0.6 s more
    assert elapsed < 3.0, f"{elapsed:.2f} s"
