"""lugre.fit for the models of the zoo: the slow-loop fit of lugre fit --model NAME, on the
records of an independent generator (crates/lugre/tests/reference/zoo_fit_reference.py), and
the full fit of lugre fit --model NAME --fit full (zoo_full_fit_reference.py)."""

import pathlib

import numpy as np
import pytest

import lugre

RECORDS = pathlib.Path(__file__).resolve().parents[2] / "lugre/tests/reference/zoo_fit"


def record(name):
    data = np.loadtxt(RECORDS / f"{name}.csv", delimiter=",", skiprows=1)
    return data[:, 0], data[:, 1]


def test_a_name_fits_every_parameter_of_the_slow_loop():
    u, f = record("bouc-wen")
    r = lugre.fit(u, f, model="bouc-wen")
    assert r["model"] == "bouc-wen" and r["kind"] == "slow" and r["converged"]
    # The generator's values, noise-free: to 1e-8.
    for name, want in {"kx": 0.1, "kw": 1.5, "rho": 2.0, "sigma": 0.75, "n": 2.0}.items():
        assert r["parameters"][name]["value"] == pytest.approx(want, rel=1e-8)
        assert r["values"][name] == r["parameters"][name]["value"]
    fitted = lugre.ZooModel(r["model"], **r["values"])
    assert fitted.name == "bouc-wen"
    assert r["fitted"].shape == u.shape and np.abs(r["residuals"]).max() < 1e-8


def test_a_model_object_gives_the_starts_and_the_thresholds():
    u, f = record("maxwell-slip-noisy")
    grid = [0.25, 0.75, 1.25, 1.75]
    model = lugre.ZooModel("maxwell-slip", stiffness=[1, 1, 1, 1], slip_force=grid)
    r = lugre.fit(u, f, model=model)
    np.testing.assert_allclose(r["fixed"]["slip_displacement"], grid, rtol=1e-15)
    for i, want in enumerate([0.4, 0.3, 0.2, 0.1]):
        e = r["parameters"][f"stiffness[{i}]"]
        assert abs(e["value"] - want) < 4 * e["stderr"], (i, e)
    assert r["noise"]["force"] == pytest.approx(0.01, rel=0.2)


def test_elements_and_fix():
    u, f = record("prandtl-ishlinskii")
    r = lugre.fit(u, f, model="prandtl-ishlinskii", elements=4, fix={"linear_weight": 0.3})
    assert "linear_weight" not in r["parameters"]
    assert r["fixed"]["linear_weight"] == 0.3
    np.testing.assert_allclose(r["fixed"]["thresholds"], [0.25, 0.75, 1.25, 1.75])
    w = [r["parameters"][f"weights[{i}]"]["value"] for i in range(4)]
    np.testing.assert_allclose(w, [0.5, 0.25, 0.2, 0.1], rtol=1e-8)


def test_refusals_name_the_argument():
    u, f = record("elastoplastic")
    with pytest.raises(ValueError, match="fc does not enter the slow loop"):
        lugre.fit(u, f, model="elastoplastic", free=["fc"])
    with pytest.raises(ValueError, match="kind='presliding'.*slow loop"):
        lugre.fit(u, f, model="elastoplastic", kind="presliding")
    with pytest.raises(ValueError, match="bounds does not apply to the Elasto-plastic fit"):
        lugre.fit(u, f, model="elastoplastic", bounds={"fs": (0, 3)})
    with pytest.raises(ValueError, match="elements: the number of elements must be from 1 to 64, got 0"):
        lugre.fit(u, f, model="maxwell-slip", elements=0)
    with pytest.raises(ValueError, match="elements applies to an element model"):
        lugre.fit(u, f, elements=3)
    with pytest.raises(ValueError, match="fix: the bouc-wen model has no parameter 'nn'"):
        lugre.fit(u, f, model="bouc-wen", fix={"nn": 1})
    u, f = record("bouc-wen-small")
    with pytest.raises(ValueError, match="kx, kw, rho cannot be identified") as e:
        lugre.fit(u, f, model="bouc-wen")
    assert e.value.parameters == ("kx", "kw", "rho")


def test_a_model_on_its_defaults_starts_the_fit():
    # Bouc-Wen's defaults kx = 0 and n = 1 lie on the edge of their domains: those start
    # from the data, the others from the model.
    u, f = record("bouc-wen")
    r = lugre.fit(u, f, model=lugre.ZooModel("bouc-wen"))
    assert r["parameters"]["n"]["value"] == pytest.approx(2.0, rel=1e-8)
    assert r["parameters"]["kx"]["value"] == pytest.approx(0.1, rel=1e-8)


def timed_record(name):
    data = np.loadtxt(RECORDS / f"{name}.csv", delimiter=",", skiprows=1)
    return data[:, 0], data[:, 1], data[:, 2]


def test_the_full_fit_is_the_commands(lugre_cli):
    """kind="full" on a record t,u,F of the generator (zoo_full_fit_reference.py: the
    elasto-plastic model integrated by scipy's Radau at rtol 1e-12, force noise 0.01): the
    numbers of `lugre fit --model elastoplastic --fit full --json` to the last bit, and every
    95 % interval holds the generator's value."""
    t, u, f = timed_record("elastoplastic-full-noisy")
    r = lugre.fit(u, f, t=t, model="elastoplastic", kind="full")
    assert r["model"] == "elastoplastic" and r["kind"] == "full" and r["converged"]
    assert r["starts"] == 3 and r["turning_points"] is None
    path = str(RECORDS / "elastoplastic-full-noisy.csv")
    j = lugre_cli(["fit", "--model", "elastoplastic", "--fit", "full", "--input", path, "--json"])
    assert j["fit"] == "full"
    assert list(r["parameters"]) == list(j["parameters"])
    for name, e in r["parameters"].items():
        c = j["parameters"][name]
        assert e["value"] == c["value"] and e["stderr"] == c["stderr"], name
        assert list(e["ci95"]) == c["ci95"], name
        assert r["values"][name] == j["values"][name], name
    for key in ("rms", "iterations", "evaluations", "dof", "condition_number"):
        assert r[key] == j[key], key
    truth = {"sigma0": 2.0, "fc": 1.0, "fs": 1.5, "zba": 0.3, "sigma1": 0.5, "sigma2": 0.2,
             "vs": 0.5, "beta": 2.0}
    for name, want in truth.items():
        lo, hi = r["parameters"][name]["ci95"]
        assert lo <= want <= hi, name


def test_the_full_fit_refuses_by_argument():
    t, u, f = timed_record("elastoplastic-full")
    with pytest.raises(ValueError, match=r"^kind='full': the bouc-wen model has no finite-rate "
                       r"form \(the models of the zoo with one: maxwell-slip, elastoplastic\); "
                       r"fit its slow loop \(kind='slow'\)$"):
        lugre.fit(u, f, t=t, model="bouc-wen", kind="full")
    with pytest.raises(ValueError, match="^a full fit needs the samples' times: give t"):
        lugre.fit(u, f, model="elastoplastic", kind="full")
    with pytest.raises(ValueError, match="^x0 = 0.1: the full fit of the elastoplastic model"):
        lugre.fit(u, f, t=t, model="elastoplastic", kind="full", x0=0.1)
    with pytest.raises(ValueError, match="^starts: the number of starts must be from 1"):
        lugre.fit(u, f, t=t, model="elastoplastic", kind="full", starts=0)
    with pytest.raises(ValueError, match="^gate applies to the slow fit"):
        lugre.fit(u, f, t=t, model="elastoplastic", kind="full", gate=0.1)
    with pytest.raises(ValueError, match=r"^starts applies to the full fit \(add kind='full'\)"):
        lugre.fit(u, f, model="elastoplastic", starts=2)
    with pytest.raises(ValueError, match="^kind='stribeck': the Elasto-plastic model is fitted"):
        lugre.fit(u, f, model="elastoplastic", kind="stribeck")
