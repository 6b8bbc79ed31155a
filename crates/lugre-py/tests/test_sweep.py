"""lugre.sweep: the periodic steady state over a grid of amplitudes and frequencies."""

import math
import pickle

import numpy as np
import pytest

import lugre

CANUDAS = dict(sigma0=1e5, sigma1=math.sqrt(1e5), sigma2=0.4, fc=1.0, fs=1.5, vs=1e-3, beta=2.0)


def test_columns_in_grid_order():
    r = lugre.sweep(lugre.LuGre(**CANUDAS), amplitudes=[1e-6, 1e-5], frequencies="0.1,1")
    assert isinstance(r, lugre.SweepResult)
    assert list(r.columns()) == list(lugre.SWEEP_COLUMNS)
    assert list(r["amplitude"]) == [1e-6, 1e-6, 1e-5, 1e-5]
    assert list(r["frequency"]) == [0.1, 1.0, 0.1, 1.0]
    assert np.all(r["dissipation"] > 0) and np.all((r["phase"] > 0) & (r["phase"] < math.pi))
    # On the orbit the first harmonic carries the energy: D = pi A a1.
    assert np.allclose(r["dissipation"], math.pi * r["amplitude"] * r["a1"], rtol=1e-12, atol=0)
    assert "loops" not in r
    back = pickle.loads(pickle.dumps(r))
    assert isinstance(back, lugre.SweepResult)
    assert all(np.array_equal(back[k], r[k]) for k in lugre.SWEEP_COLUMNS)


def test_quasi_static_energy_is_the_loops():
    """At 1e-13 Hz the energy per cycle is the closed-form loop's (eq. 10) to 1e-12."""
    model = lugre.LuGre(**CANUDAS)
    amplitudes = [1e-6, 1e-5, 1e-4, 1e-3]
    r = lugre.sweep(model, amplitudes=amplitudes, frequencies=[1e-13])
    for a, d in zip(amplitudes, r["dissipation"]):
        want = model.loop([-a, a]).loops[0].dissipation
        assert abs(d - want) <= 1e-12 * want, (a, d, want)


def test_ranges_loops_and_frame():
    pd = pytest.importorskip("pandas")
    r = lugre.sweep(lugre.Dahl(rho=2.0, fc=1.0), amplitudes="0.1:10:3", frequencies=[1.0],
                    offset=5.0, loop_samples=11)
    assert list(r["amplitude"]) == [0.1, 1.0, 10.0]
    frame = r.to_frame()
    assert isinstance(frame, pd.DataFrame) and frame.shape == (3, len(lugre.SWEEP_COLUMNS))
    assert len(r["loops"]) == 3
    loop = r["loops"][2]
    assert loop["u"].shape == (11,) and loop["force"][0] == pytest.approx(loop["force"][-1], abs=1e-9)
    assert loop["u"].min() >= 5 - 10 - 1e-9 and loop["u"].max() <= 5 + 10 + 1e-9


@pytest.mark.parametrize(
    "kw, error, message",
    [
        (dict(amplitudes=[0.0], frequencies=[1.0]), ValueError,
         "amplitudes: amplitude must be a finite number > 0, got 0"),
        (dict(amplitudes=[1e-6], frequencies=[float("nan")]), ValueError,
         "frequencies: frequency must be a finite number > 0, got NaN"),
        (dict(amplitudes="1:2", frequencies=[1.0]), ValueError,
         "amplitudes: a range is START:STOP:COUNT"),
        (dict(amplitudes=[1e-6], frequencies=[1.0], loop_samples=1), ValueError,
         "loop_samples: the loop samples must be 0 (no loop) or at least 2, got 1"),
        (dict(amplitudes=[1e-6] * 1000, frequencies=[1.0] * 1000, loop_samples=10000), ValueError,
         "the grid of 1000000 points"),
        (dict(amplitudes=[1e-6], frequencies=[1.0], tol=0.0), ValueError,
         "tol: the tolerance must be a number in [1e-14, 1), got 0"),
        (dict(amplitudes=[1e-6], frequencies=[1.0], offset="x"), TypeError,
         "offset must be a real number"),
        (dict(amplitudes=None, frequencies=[1.0]), TypeError, "amplitudes must be"),
    ],
)
def test_bad_input_names_the_keyword(kw, error, message):
    with pytest.raises(error) as e:
        lugre.sweep(lugre.LuGre(**CANUDAS), **kw)
    assert message in str(e.value)


def test_releases_the_gil(assert_gil_released):
    model = lugre.LuGre(**CANUDAS)
    assert_gil_released(
        lambda: lugre.sweep(model, amplitudes="1e-7:1e-3:40", frequencies="0.1:100:40"))
