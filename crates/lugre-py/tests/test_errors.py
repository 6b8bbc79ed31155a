"""Bad arguments raise ValueError (with the message the `lugre` command prints after
"lugre: error: ") or TypeError, never crash the interpreter."""

import math
import subprocess
import sys

import numpy as np
import pytest

import lugre

# (keyword arguments, the `lugre loop` flags that give the same error, the CLI's message)
MODEL_ERRORS = [
    (dict(sigma0=0), "--sigma0 0", "sigma0 must be > 0, got 0"),
    (dict(sigma0=-6.5), "--sigma0 -6.5", "sigma0 must be > 0, got -6.5"),
    (dict(sigma1=-1), "--sigma1 -1", "sigma1 must be >= 0, got -1"),
    (dict(sigma2=-0.5), "--sigma2 -0.5", "sigma2 must be >= 0, got -0.5"),
    (dict(fc=0), "--fc 0", "fc must be > 0, got 0"),
    (dict(fs=math.nan), "--fs nan", "fs must be a finite number, got NaN"),
    (dict(vs=math.inf), "--vs inf", "vs must be a finite number, got inf"),
    (dict(beta=-2), "--beta -2", "beta must be > 0, got -2"),
]


@pytest.mark.parametrize("kwargs, flags, message", MODEL_ERRORS)
def test_lugre_parameters(kwargs, flags, message):
    with pytest.raises(ValueError) as e:
        lugre.LuGre(**kwargs)
    assert str(e.value) == message


@pytest.mark.parametrize(
    "kwargs, message",
    [
        (dict(rho=0), "rho must be > 0, got 0"),
        (dict(fc=-1), "fc must be > 0, got -1"),
        (dict(rho=1e200, fc=1e200), "sigma0 = rho * fc must be a finite number, got inf"),
    ],
)
def test_dahl_parameters(kwargs, message):
    with pytest.raises(ValueError) as e:
        lugre.Dahl(**kwargs)
    assert str(e.value) == message


@pytest.mark.parametrize(
    "call",
    [
        lambda: lugre.LuGre(6),  # keyword arguments only
        lambda: lugre.Dahl(1, 1),
        lambda: lugre.LuGre(sigma_0=6),
        lambda: lugre.LuGre(sigma0="6"),
        lambda: lugre.LuGre(sigma0=b"6"),
        lambda: lugre.LuGre(sigma0=True),
        lambda: lugre.LuGre(sigma0=[6]),
        lambda: lugre.LuGre(sigma0=6 + 0j),
        lambda: lugre.Dahl(rho=object()),
    ],
)
def test_model_argument_types(call):
    with pytest.raises(TypeError):
        call()


def test_numpy_scalars_are_real_numbers():
    m = lugre.LuGre(sigma0=np.float32(6), fs=np.int64(2))
    assert (m.sigma0, m.fs) == (6.0, 2.0)


def test_huge_int_is_a_value_error():
    with pytest.raises(ValueError, match="sigma0"):
        lugre.LuGre(sigma0=10**400)


@pytest.mark.parametrize(
    "tp, message",
    [
        ([], "turning_points: the input is empty"),
        ([1, 1, 1], "turning_points: a periodic input needs at least 2 distinct values, got 1"),
        ([0, math.nan], "turning_points: u[1] must be a finite number, got NaN"),
        (np.array([0.0, 1.0, np.inf]), "turning_points: u[2] must be a finite number, got inf"),
        (
            [-1e308, 1e308],
            "turning_points: the input's total variation over one period overflows f64 (values too far apart)",
        ),
        ([[0, 1], [2, 3]], "turning_points must be one-dimensional, got an array of shape [2, 2]"),
    ],
)
def test_turning_point_values(tp, message):
    with pytest.raises(ValueError) as e:
        lugre.LuGre().loop(tp)
    assert str(e.value) == message


@pytest.mark.parametrize(
    "tp",
    ["0,1,0.2,1.5", b"01", None, 3.0, [0, "1"], [0, None], [0, 1 + 2j], np.array([0, 1], dtype=complex),
     np.array(["0", "1"]), np.array([True, False]), [[0, 1], [2]], {"a": 1}],
)
def test_turning_point_types(tp):
    with pytest.raises(TypeError, match="turning_points"):
        lugre.LuGre().loop(tp)


@pytest.mark.parametrize(
    "args, message",
    [
        ((0.3, 0.2, 1, 1.5), "bimodal input breaks Definition 1: umin1 <= umin2 fails (umin1 = 0.3, umin2 = 0.2)"),
        ((0, 1, 1, 1.5), "bimodal input breaks Definition 1: umin2 < umax1 fails (umin2 = 1, umax1 = 1)"),
        ((0, 0.2, 1.6, 1.5), "bimodal input breaks Definition 1: umax1 <= umax2 fails (umax1 = 1.6, umax2 = 1.5)"),
        (
            (0, 0, 1, 1),
            "bimodal input breaks Definition 1: umin1 != umin2 or umax1 != umax2 fails "
            "(umin1 = umin2 = 0 and umax1 = umax2 = 1)",
        ),
        ((0, math.nan, 1, 1.5), "bimodal[1] must be a finite number, got NaN"),
    ],
)
def test_bimodal_values(args, message):
    with pytest.raises(ValueError) as e:
        lugre.LuGre().loop_bimodal(*args)
    assert str(e.value) == message


def test_bimodal_types():
    with pytest.raises(TypeError, match="umax1"):
        lugre.LuGre().loop_bimodal(0, 0.5, "1", 1.5)
    with pytest.raises(TypeError):
        lugre.LuGre().loop_bimodal(0, 0.5, 1)
    # Keyword arguments work.
    hl = lugre.LuGre().loop_bimodal(umin1=0, umin2=0.5, umax1=1, umax2=1.5)
    assert hl.theorem_a.minor_loop == (1.0, 2.0)


def test_sample_arguments():
    hl = lugre.LuGre().loop([0, 1])
    with pytest.raises(ValueError) as e:
        hl.sample(1)
    assert str(e.value) == "n must be at least 2 (both ends of the period), got 1"
    with pytest.raises(ValueError, match=">= 0"):
        hl.sample(-3)
    with pytest.raises(ValueError, match="too large"):
        hl.sample(10**30)
    with pytest.raises(ValueError) as e:
        hl.sample(2**62)
    # The core's limit, as the CLI's --samples and the C ABI's n.
    assert str(e.value) == f"n must be at most 10000000 (memory for the points), got {2**62}"
    for bad in (2.5, "10", True, None.__class__):
        with pytest.raises(TypeError):
            hl.sample(bad)


@pytest.mark.parametrize("rho", ["1.0", None, [1.0, None], [1.0, "x"], np.array(["1"]), 1 + 1j, [[1.0], [2.0, 3.0]]])
def test_y_at_types(rho):
    hl = lugre.LuGre().loop([0, 1])
    with pytest.raises(TypeError, match="rho"):
        hl.y_at(rho)


def test_crashes_are_impossible_from_python():
    """A battery of bad calls in a child interpreter: it must exit normally."""
    code = r"""
import math, numpy as np, lugre
bad = [None, "x", b"x", [], [math.nan], [1e308, -1e308], np.zeros((2, 2, 2)), object(), 1e400, -0.0, 10**400]
for arg in bad:
    for call in (lambda a: lugre.LuGre(sigma0=a), lambda a: lugre.Dahl(rho=a), lambda a: lugre.LuGre().loop(a),
                 lambda a: lugre.LuGre().loop([0, 1]).y_at(a), lambda a: lugre.LuGre().loop([0, 1]).sample(a),
                 lambda a: lugre.LuGre().loop_bimodal(a, 0.5, 1, 1.5)):
        try:
            call(arg)
        except (TypeError, ValueError, MemoryError):
            pass
print("alive")
"""
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "alive"
