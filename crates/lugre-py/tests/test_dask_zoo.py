"""lugre.dask with the models of the zoo: the chunked count with a ``lugre.ZooModel`` equals
``lugre.cycles(u, model=...)`` row for row and bit for bit (energies and totals), for a Masing
model (exact entry states from the merged residues) and a single-state one (entry states
guessed and verified in order), on the threaded scheduler and on a 2-worker LocalCluster."""

import numpy as np
import pandas as pd
import pytest

import dask
import dask.array as da

import lugre
import lugre.dask as ld

MODELS = {
    "maxwell-slip": lugre.ZooModel("maxwell-slip"),
    "prandtl-ishlinskii": lugre.ZooModel("prandtl-ishlinskii"),
    "bouc-wen": lugre.ZooModel("bouc-wen", n=2.5),
    "elastoplastic": lugre.ZooModel("elastoplastic"),
}
MASING = {"maxwell-slip", "prandtl-ishlinskii"}


def walk(n, seed):
    return np.cumsum(np.random.default_rng(seed).standard_normal(n))


def single(u, model):
    r = lugre.cycles(u, model=model, reversals=False)
    return pd.DataFrame(r["cycles"]), r["summary"]


def check(u, chunks, model, fan_in=2):
    x = da.from_array(np.asarray(u, dtype=float), chunks=chunks)
    with dask.config.set(scheduler="threads"):
        r = ld.count(x, model=model, merge_fan_in=fan_in)
        got = r["cycles"].compute()
    want, summary = single(np.asarray(u, dtype=float), model)
    pd.testing.assert_frame_equal(got, want, check_exact=True)
    assert r["summary"] == summary
    assert len(want) > 0 and np.isfinite(want["dissipation"]).any()
    return r


@pytest.mark.parametrize("name", sorted(MODELS))
def test_energies_bit_identical(name):
    u = walk(20_000, 11)
    r = check(u, 1_777, MODELS[name])
    assert r["entries"]["chunks"] == 11
    if name in MASING:
        # Exact from the residues: every entry holds.
        assert r["entries"]["held"] == 11


@pytest.mark.parametrize("name", sorted(MODELS))
@pytest.mark.parametrize("seed", range(3))
def test_small_integers_ties_and_one_sample_chunks(name, seed):
    rng = np.random.default_rng(seed)
    u = rng.integers(-3, 4, size=int(rng.integers(2, 60))).astype(float) * 1.5
    check(u, 1, MODELS[name])
    check(u, int(rng.integers(1, 8)), MODELS[name], fan_in=int(rng.integers(2, 9)))


def test_x0_is_refused_with_a_zoo_model():
    x = da.from_array(walk(100, 1), chunks=10)
    with pytest.raises(ValueError, match="x0"):
        ld.cycles(x, model=MODELS["bouc-wen"], x0=0.5)


def test_on_a_two_worker_local_cluster(tmp_path):
    from dask.distributed import Client, LocalCluster

    u = walk(300_000, 5)
    paths = []
    for k, part in enumerate(np.array_split(u, 8)):
        p = tmp_path / f"h{k:02d}.npy"
        np.save(p, part)
        paths.append(str(p))
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                      dashboard_address=None) as cluster, Client(cluster):
        for name in ["maxwell-slip", "bouc-wen"]:
            r = ld.count(paths, model=MODELS[name])
            got = r["cycles"].compute()
            want, summary = single(u, MODELS[name])
            pd.testing.assert_frame_equal(got, want, check_exact=True)
            assert r["summary"] == summary
            assert r["entries"]["chunks"] == 7


def test_the_chunk_functions_take_a_zoo_model_and_refuse_what_it_cannot_be():
    import lugre.chunk as lc

    u = walk(50, 2)
    ms, bw = MODELS["maxwell-slip"], MODELS["bouc-wen"]
    start = lc.chunk_start_entry(ms, None, u[0])
    assert isinstance(start, bytes) and len(start) == 8 * (1 + 4)  # u and four elements
    assert lc.chunk_start_entry(lugre.LuGre(), 0.5, u[0]) == lugre.LuGre().sigma0 * 0.5
    with pytest.raises(ValueError, match="x0"):
        lc.chunk_start_entry(bw, 0.5, u[0])
    assert lc.chunk_bounds(u, 0, None, ms) is None
    upper, lower = lc.chunk_bounds(u, 0, None, bw)
    assert np.isfinite([upper, lower]).all()
    summary, _ = lc.chunk_count(u, 0)
    with pytest.raises(ValueError, match="leaves"):
        lc.chunk_guess_entries(ms, start, [None])
    with pytest.raises(ValueError, match=r"bounds\[0\] is None"):
        lc.chunk_guess_entries(lugre.LuGre(), 0.0, [None])
    with pytest.raises(TypeError, match="y_entry: the entry state of a model of the zoo is bytes"):
        lc.chunk_count_energy(u, 0, None, 0.0, ms, None)
    with pytest.raises(ValueError, match="y_entry is not a state of the Maxwell-slip model"):
        lc.chunk_count_energy(u, 0, None, lc.chunk_start_entry(bw, None, u[0]), ms, None)
    rows, passed, last = lc.chunk_count_energy(u, 0, None, start, ms, None)
    assert isinstance(passed, bytes) and isinstance(last, bytes) and len(last) == len(start)
    with pytest.raises(ValueError, match="cannot be read"):
        lc.chunk_history_energy(ms, start, [passed[:-1]])
