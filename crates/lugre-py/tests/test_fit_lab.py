"""lugre.fit(kind="stribeck" | "presliding" | "staged"): the lab's experiments, on the example
data of the README's "Identifying LuGre as a lab does" (examples/data/lab-*.csv, written by
examples/data/make_lab_experiments.py with scipy's Radau, independently of lugre).

The reference is the command line: every number of `lugre fit --fit ... --json` on the same
file must come back from Python to the last digit (both call the same core; the command reads
the file with the reader lugre.read shares). The CLI's own tests (crates/lugre-cli/tests/
fit_lab.rs) check the estimates against the generator's truth; here a loose check (2 %) that
the files are the ones meant."""

import math
import pathlib

import numpy as np
import pytest

import lugre

DATA = pathlib.Path(__file__).resolve().parents[3] / "examples" / "data"
STRIBECK = DATA / "lab-stribeck.csv"
TABLE = DATA / "lab-stribeck-table.csv"
PRESLIDING = DATA / "lab-presliding.csv"
SINE = DATA / "lab-sine.csv"

# The generator's truth: Canudas de Wit et al. (1995), SI units.
TRUTH = dict(sigma0=1e5, sigma1=math.sqrt(1e5), sigma2=0.4, fc=1.0, fs=1.5, vs=1e-3)
# The Stribeck curve held in the presliding fit, as the command's flags and as a model.
CURVE_FLAGS = ["--fc", "1", "--fs", "1.5", "--vs", "1e-3", "--beta", "2", "--sigma2", "0.4"]
CURVE = lugre.LuGre(fc=1, fs=1.5, vs=1e-3, beta=2, sigma2=0.4)

# The keys of a fit's report that `lugre fit --json` writes too, compared exactly.
REPORT_KEYS = ("fixed", "rms", "samples", "dof", "t_quantile", "condition_number", "iterations",
               "evaluations", "starts", "converged", "termination", "model")


def read(path):
    return lugre.read(str(path))


def same_estimates(py, cli):
    """Every parameter's value, standard error, interval and bound flag, to the last digit."""
    assert set(py) == set(cli)  # the command's JSON objects are ordered by key
    for name, e in cli.items():
        p = py[name]
        assert p["value"] == e["value"], name
        assert p["stderr"] == e["stderr"], name
        assert list(p["ci95"]) == e["ci95"], name
        assert p["at_bound"] == e["at_bound"], name
        if "stage" in e:
            assert p["stage"] == e["stage"], name


def same_report(py, cli):
    """A fit's dict against the command's document of the same fit."""
    same_estimates(py["parameters"], cli["parameters"])
    for key in REPORT_KEYS:
        assert py[key] == cli[key], key
    assert py["kind"] == cli["fit"]
    assert py["correlation"].tolist() == cli["correlation"]


def same_points(py, cli):
    """The points of a Stribeck fit and the curve at them."""
    points = cli["points"]
    assert py["points"]["v"].tolist() == [p["v"] for p in points]
    assert py["points"]["F"].tolist() == [p["F"] for p in points]
    stderr = [p["stderr"] for p in points]
    if py["points"]["stderr"] is None:
        assert stderr == [None] * len(points)
    else:
        assert py["points"]["stderr"].tolist() == stderr
    assert py["fitted"].tolist() == [p["fit"] for p in points]
    np.testing.assert_array_equal(py["residuals"], py["points"]["F"] - py["fitted"])


def near_truth(parameters, names, rel=0.02):
    for name in names:
        value = parameters[name]["value"]
        assert abs(value / TRUTH[name] - 1) < rel, (name, value)


@pytest.fixture(scope="module")
def records():
    return {p.stem: read(p) for p in (STRIBECK, TABLE, PRESLIDING, SINE)}


def test_stribeck_from_a_record_is_the_commands(records, lugre_cli):
    c = records["lab-stribeck"]
    r = lugre.fit(c["u"], c["F"], t=c["t"], kind="stribeck", fix={"beta": 2})
    cli = lugre_cli(["fit", "--fit", "stribeck", "--input", str(STRIBECK), "--beta", "2", "--json"])
    same_report(r, cli)
    same_points(r, cli)
    runs, want = r["plateaus"]["runs"], cli["plateaus"]
    assert r["plateaus"]["skipped"] == want["skipped"]
    assert r["plateaus"]["velocity_noise"] == want["velocity_noise"]
    for key in ("v", "F", "stderr", "sd", "samples", "t_start", "t_end"):
        assert runs[key].tolist() == [run[key] for run in want["runs"]], key
    assert r["kind"] == "stribeck" and set(r["parameters"]) == {"sigma2", "fc", "fs", "vs"}
    near_truth(r["parameters"], ["sigma2", "fc", "fs", "vs"])
    # The fitted model: the curve's estimates, beta as held.
    assert r["values"]["beta"] == 2 and r["values"]["fs"] == r["parameters"]["fs"]["value"]
    # beta given by a model object instead: the same fit.
    other = lugre.fit(c["u"], c["F"], t=c["t"], kind="stribeck", model=lugre.LuGre(beta=2))
    same_estimates(other["parameters"], cli["parameters"])


def test_stribeck_from_a_velocity_record():
    """(None, F, t=t, v=v): the runs found in the velocity itself."""
    c = read(STRIBECK)
    t, u = c["t"], c["u"]
    v = np.gradient(u, t)
    r = lugre.fit(None, c["F"], t=t, v=v, kind="stribeck", fix={"beta": 2})
    assert r["plateaus"]["runs"]["v"].size >= 40
    near_truth(r["parameters"], ["sigma2", "fc", "fs", "vs"])


def test_stribeck_from_a_table_is_the_commands(records, lugre_cli):
    c = records["lab-stribeck-table"]
    r = lugre.fit(None, c["F"], v=c["v"], kind="stribeck", fix={"beta": 2})
    cli = lugre_cli(["fit", "--fit", "stribeck", "--input", str(TABLE), "--beta", "2", "--json"])
    same_report(r, cli)
    same_points(r, cli)
    assert r["plateaus"] is None and r["points"]["stderr"] is None
    near_truth(r["parameters"], ["sigma2", "fc", "fs", "vs"])


def test_stribeck_frees_beta_on_request(records, lugre_cli):
    c = records["lab-stribeck-table"]
    r = lugre.fit(None, c["F"], v=c["v"], kind="stribeck", start={"beta": 2}, free="beta")
    cli = lugre_cli(["fit", "--fit", "stribeck", "--input", str(TABLE), "--beta", "2", "--free", "beta",
                     "--json"])
    same_report(r, cli)
    assert "beta" in r["parameters"]


def test_presliding_is_the_commands(records, lugre_cli):
    c = records["lab-presliding"]
    r = lugre.fit(c["u"], c["F"], t=c["t"], kind="presliding", model=CURVE)
    cli = lugre_cli(["fit", "--fit", "presliding", "--input", str(PRESLIDING), *CURVE_FLAGS, "--json"])
    same_report(r, cli)
    assert set(r["parameters"]) == {"sigma0", "sigma1"}
    near_truth(r["parameters"], ["sigma0", "sigma1"])
    assert r["fitted"].shape == c["F"].shape
    # The curve held through fix= instead of a model: the same fit.
    held = dict(fc=1, fs=1.5, vs=1e-3, beta=2, sigma2=0.4)
    other = lugre.fit(c["u"], c["F"], t=c["t"], kind="presliding", fix=held)
    same_estimates(other["parameters"], cli["parameters"])


@pytest.mark.parametrize("final", [False, True])
def test_staged_is_the_commands(records, lugre_cli, final):
    args = ["fit", "--fit", "staged", "--stribeck", str(STRIBECK), "--presliding", str(PRESLIDING),
            "--beta", "2", "--json"]
    stages = dict(stribeck=records["lab-stribeck"], presliding=records["lab-presliding"])
    if final:
        s = records["lab-sine"]
        r = lugre.fit(s["u"], s["F"], t=s["t"], kind="staged", fix={"beta": 2}, **stages)
        cli = lugre_cli([*args, "--input", str(SINE)])
    else:
        r = lugre.fit(None, None, kind="staged", fix={"beta": 2}, **stages)
        cli = lugre_cli(args)
    assert r["kind"] == "staged" and r["model"] == "lugre"
    same_estimates(r["parameters"], cli["parameters"])
    assert r["fixed"] == cli["fixed"]
    assert set(r["stages"]) == set(cli["stages"])
    for name, stage in r["stages"].items():
        same_report(stage, cli["stages"][name])
        assert "values" not in stage
    same_points(r["stages"]["stribeck"], cli["stages"]["stribeck"])
    near_truth(r["parameters"], ["sigma0", "sigma1", "fc", "fs", "vs"])
    want = "full" if final else "stribeck"
    assert r["parameters"]["fs"]["stage"] == want
    assert r["parameters"]["sigma0"]["stage"] == ("full" if final else "presliding")
    # "values" is the identified model: every parameter, estimated or held.
    model = lugre.LuGre(**r["values"])
    assert model.beta == 2 and r["values"]["sigma0"] == r["parameters"]["sigma0"]["value"]


def test_staged_records_as_tuples(records):
    """(t, u, F) tuples and a (v, F) table are the same records as lugre.read's columns."""
    s, p, table = records["lab-stribeck"], records["lab-presliding"], records["lab-stribeck-table"]
    by_columns = lugre.fit(None, None, kind="staged", fix={"beta": 2}, stribeck=s, presliding=p)
    by_tuples = lugre.fit(None, None, kind="staged", fix={"beta": 2}, stribeck=(s["t"], s["u"], s["F"]),
                          presliding=(p["t"], p["u"], p["F"]))
    assert by_tuples["parameters"] == by_columns["parameters"]
    from_table = lugre.fit(None, None, kind="staged", fix={"beta": 2}, stribeck=(table["v"], table["F"]),
                           presliding=p)
    alone = lugre.fit(None, table["F"], v=table["v"], kind="stribeck", fix={"beta": 2})
    for name in ("sigma2", "fc", "fs", "vs"):
        assert from_table["parameters"][name]["value"] == alone["parameters"][name]["value"]


def test_bad_lab_requests_raise_value_error(records):
    s, p, sine = records["lab-stribeck"], records["lab-presliding"], records["lab-sine"]
    table = records["lab-stribeck-table"]
    stages = dict(stribeck=s, presliding=p)
    ramp = np.linspace(0.0, 1.0, 1001)
    cases = [
        # beta is held in the Stribeck fit and has no value.
        (lambda: lugre.fit(None, table["F"], v=table["v"], kind="stribeck"), "fix={'beta': value}"),
        # No constant-velocity run: the velocity grows 0.5 % a sample; runs too short: the
        # presliding test's 20 Hz sine.
        (lambda: lugre.fit(np.exp(5 * ramp), np.ones(1001), t=ramp, kind="stribeck", fix={"beta": 2}),
         "the record has no constant-velocity run"),
        (lambda: lugre.fit(p["u"], p["F"], t=p["t"], kind="stribeck", fix={"beta": 2}),
         "the constant-velocity runs are too short"),
        (lambda: lugre.fit(s["u"], s["F"], kind="stribeck", fix={"beta": 2}), "give t"),
        (lambda: lugre.fit(None, table["F"][:-1], v=table["v"], kind="stribeck", fix={"beta": 2}),
         "48 velocities and 47 forces"),
        (lambda: lugre.fit(s["u"], s["F"], t=s["t"], v=s["u"], kind="stribeck", fix={"beta": 2}), "not both"),
        # A "presliding test" that slides: the constant-velocity runs.
        (lambda: lugre.fit(s["u"], s["F"], t=s["t"], kind="presliding", model=CURVE), "breaks away"),
        (lambda: lugre.fit(p["u"], p["F"], kind="presliding", model=CURVE), "give t"),
        (lambda: lugre.fit(p["u"], p["F"], t=p["t"], kind="presliding"), "sigma2 is held in the presliding fit but has no value"),
        (lambda: lugre.fit(None, None, kind="staged", fix={"beta": 2}, stribeck=s, presliding=s),
         "presliding stage: the presliding test breaks away"),
        (lambda: lugre.fit(None, None, kind="staged", fix={"beta": 2}, stribeck=p, presliding=p),
         "stribeck: the constant-velocity runs are too short"),
        (lambda: lugre.fit(None, None, kind="staged", fix={"beta": 2}, stribeck=s), "needs stribeck="),
        (lambda: lugre.fit(None, None, kind="staged", fix={"beta": 2}, stribeck=s, presliding=(p["u"], p["F"])),
         "presliding must be a record (t, u, F)"),
        (lambda: lugre.fit(None, None, kind="staged", fix={"beta": 2}, stribeck={"t": s["t"]}, presliding=p),
         "stribeck has no force column 'F'"),
        (lambda: lugre.fit(None, None, kind="staged", fix={"beta": 2}, stribeck=(table["v"], table["F"][:3]),
                           presliding=p), "stribeck: the table of constant-velocity runs has 48 velocities"),
        (lambda: lugre.fit(sine["u"], sine["F"], kind="staged", fix={"beta": 2}, **stages),
         "the final full fit needs the samples' times: give t"),
        # The options and records of the other fits.
        (lambda: lugre.fit(p["u"], p["F"], t=p["t"], kind="presliding", model=CURVE, x0=0.0),
         "x0 applies to the full fit, not to kind='presliding'"),
        (lambda: lugre.fit(None, table["F"], v=table["v"], kind="stribeck", fix={"beta": 2}, interpolate="cubic"),
         "interpolate='cubic' applies to the full fit, not to kind='stribeck'"),
        (lambda: lugre.fit(None, table["F"], v=table["v"], kind="stribeck", fix={"beta": 2},
                           normal=np.ones(48)), "normal applies to the slow and full fits"),
        (lambda: lugre.fit(sine["u"], sine["F"], t=sine["t"], kind="full", stribeck=s),
         "stribeck is a record of the staged fit (kind='staged'), not of kind='full'"),
        (lambda: lugre.fit(None, table["F"], v=table["v"], kind="stribeck", fix={"beta": 2}, presliding=p),
         "presliding is a record of the staged fit"),
        (lambda: lugre.fit(None, table["F"], v=table["v"], kind="stribeck", model="dahl"), "Dahl"),
    ]
    for call, words in cases:
        with pytest.raises(ValueError) as e:
            call()
            pytest.fail(f"no error: {words}")
        assert words in str(e.value), (words, str(e.value))


def test_bad_lab_arguments_raise_type_error(records):
    s, p = records["lab-stribeck"], records["lab-presliding"]
    cases = [
        (dict(stribeck=5, presliding=p), "stribeck"),
        (dict(stribeck="lab-stribeck.csv", presliding=p), "stribeck"),
        (dict(stribeck=s, presliding=[1.0, 2.0, "x"]), "presliding"),
        (dict(stribeck={"F": "x", "v": [1.0]}, presliding=p), "stribeck['F']"),
        (dict(stribeck=s, presliding=(p["t"], None, p["F"])), "presliding[1]"),
    ]
    for kwargs, word in cases:
        with pytest.raises(TypeError) as e:
            lugre.fit(None, None, kind="staged", fix={"beta": 2}, **kwargs)
        assert word in str(e.value), (word, str(e.value))
    with pytest.raises(TypeError, match="f must be"):
        lugre.fit(None, None, kind="stribeck", v=[1.0, 2.0], fix={"beta": 2})
