"""lugre.simulate(model=lugre.ZooModel(...)) and ZooModel.simulate: every model of the core's
table in turn, none named here. The answer is `lugre simulate --model NAME --json`'s (keys
model, t, u, y) to the last bit, from a record of samples and from turning points at a speed;
LuGre's own keywords and bad input are refused as the command line refuses them."""

import numpy as np
import pytest

import lugre
from test_zoo import flag, same_bits

MODELS = list(lugre.ZOO_MODELS)
# A record with reversals at unequal rates (t strictly increasing, in s).
T = [0.0, 0.5, 1.0, 2.0, 2.2, 3.7, 4.0]
U = [0.0, 1.0, 2.5, -1.0, -1.5, 0.25, 2.0]
TURNING = [3.0, 1.0, 2.0, -3.0]


def as_json(r):
    """The answer in the shape of the command line's JSON."""
    model = {k: v.tolist() if isinstance(v, np.ndarray) else v for k, v in r["model"].items()}
    return {"model": model, **{k: r[k].tolist() for k in ("t", "u", "y")}}


def record(tmp_path):
    path = tmp_path / "motion.csv"
    path.write_text("t,u\n" + "".join(f"{t!r},{u!r}\n" for t, u in zip(T, U)))
    return str(path)


@pytest.mark.parametrize("name", MODELS)
def test_a_record_equals_the_command_line(name, tmp_path, lugre_cli):
    want = lugre_cli(["simulate", "--model", name, "--input", record(tmp_path), "--json"])
    got = lugre.simulate(model=lugre.ZooModel(name), t=T, u=np.array(U))
    same_bits(as_json(got), want)
    assert sorted(got) == ["model", "t", "u", "y"]
    # The method is the same call.
    same_bits(as_json(lugre.ZooModel(name).simulate(t=T, u=U)), want)


@pytest.mark.parametrize("name", MODELS)
def test_turning_points_at_a_speed_equal_the_command_line(name, lugre_cli):
    tp = ",".join(repr(x) for x in TURNING)
    want = lugre_cli(["simulate", "--model", name, f"--turning-points={tp}", "--speed", "0.5", "--json"])
    got = lugre.simulate(lugre.ZooModel(name), turning_points=TURNING, speed=0.5)
    same_bits(as_json(got), want)


def test_elastoplastic_at_finite_rate_with_parameters_given(tmp_path, lugre_cli):
    args = ["simulate", "--model", "elastoplastic", "--sigma1", "2", "--sigma2", "0.5"]
    want = lugre_cli([*args, "--input", record(tmp_path), "--json"])
    m = lugre.ZooModel("elastoplastic", sigma1=2, sigma2=0.5)
    got = lugre.simulate(model=m, t=T, u=U)
    same_bits(as_json(got), want)
    # Rate dependence shows: the same path twice as slow gives another force.
    slow = lugre.simulate(model=m, t=2 * np.array(T), u=U)
    assert not np.array_equal(slow["y"], got["y"])


def test_elastoplastic_inside_the_breakaway_band_is_elastic():
    # Closed form: |u| <= zba = fc / (2 sigma0) = 0.5 m keeps z = u, F = sigma0 u (sigma1 =
    # sigma2 = 0: no rate term); sigma0 = 3 N/m.
    m = lugre.ZooModel("elastoplastic", sigma0=3, sigma1=0, sigma2=0)
    u = [0.0, 0.1, -0.125, 0.0625]
    r = lugre.simulate(model=m, t=[0, 1, 2, 3], u=u)
    assert r["y"].tolist() == [3 * x for x in u]


@pytest.mark.parametrize(
    "keyword, value",
    [("x0", 0.1), ("gamma", 10), ("periods", 2), ("tol", 1e-8), ("times", [0, 1]),
     ("interpolate", "cubic")],
)
def test_lugre_keywords_are_refused_in_the_command_lines_words(keyword, value, lugre_cli_error):
    cli_value = value if not isinstance(value, list) else ",".join(map(str, value))
    message = lugre_cli_error(["simulate", "--model", "bouc-wen", "--turning-points", "3,1,2,-3",
                               flag(keyword), str(cli_value)])
    with pytest.raises(ValueError) as e:
        lugre.simulate(model=lugre.ZooModel("bouc-wen"), turning_points=TURNING, **{keyword: value})
    spelled = "interpolate='cubic'" if keyword == "interpolate" else keyword
    cli_spelled = "--interpolate cubic" if keyword == "interpolate" else flag(keyword)
    assert str(e.value) == message.replace(cli_spelled, spelled)
    assert str(e.value).startswith(f"{spelled} is an option of LuGre's and Dahl's simulation")


def test_sine_is_refused_by_name():
    with pytest.raises(ValueError, match="^sine is an option of LuGre's"):
        lugre.ZooModel("maxwell-slip").simulate(sine=(1, 1))


@pytest.mark.parametrize(
    "keywords, error, pattern",
    [
        ({"t": [0, 1, 1], "u": [0, 1, 2]}, ValueError, r"\bt\b"),
        ({"t": [0, 1, 2], "u": [0, float("nan"), 2]}, ValueError, r"\bu\b"),
        ({"t": [0, 1, 2], "u": [0, 1]}, ValueError, r"\bt\b.*\bu\b"),
        ({"t": "abc", "u": [0, 1, 2]}, TypeError, r"\bt\b"),
        ({"turning_points": TURNING, "speed": -1}, ValueError, "speed"),
        ({"turning_points": TURNING, "t": [0, 1], "u": [0, 1]}, ValueError, "turning_points"),
        ({}, ValueError, r"^no input: give t and u \(samples, linear in between\) or turning_points \(at speed\)$"),
    ],
)
def test_bad_input_names_the_argument(keywords, error, pattern):
    with pytest.raises(error, match=pattern):
        lugre.simulate(model=lugre.ZooModel("prandtl-ishlinskii"), **keywords)


def test_a_model_of_another_type_is_a_type_error():
    with pytest.raises(TypeError, match="^model must be a lugre.LuGre, lugre.Dahl or lugre.ZooModel, got str"):
        lugre.simulate(model="elastoplastic", t=T, u=U)


def test_lugre_and_dahl_through_the_same_function():
    for m in (lugre.LuGre(sigma0=6), lugre.Dahl(rho=2)):
        got = lugre.simulate(m, turning_points=[0, 1, 0.5, 1.5], gamma=10)
        want = m.simulate(turning_points=[0, 1, 0.5, 1.5], gamma=10)
        assert sorted(got) == sorted(want) == ["dz", "t", "u", "y", "z"]
        for k in want:
            assert np.array_equal(got[k], want[k])
    default = lugre.simulate(turning_points=[0, 1], periods=2)
    assert np.array_equal(default["y"], lugre.LuGre().simulate(turning_points=[0, 1], periods=2)["y"])
