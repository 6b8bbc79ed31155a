"""lugre.chunk, the chunked count's protocol: where it lives (a submodule; the old top-level
names are deprecated aliases), and bad arguments refused with a ValueError naming them, never
NaN results, wrapped indices or a panic."""

import math
import pickle
import warnings

import numpy as np
import pytest

import lugre
import lugre.chunk as lc

U = np.cumsum(np.random.default_rng(1).standard_normal(100))


def test_the_protocol_is_a_submodule():
    assert set(lc.__all__) == {
        "ChunkPlan", "ChunkRows", "ChunkSummary", "chunk_assemble", "chunk_bounds", "chunk_close",
        "chunk_count", "chunk_count_energy", "chunk_guess_entries", "chunk_history_energy",
        "chunk_merge", "chunk_start_entry",
    }
    assert not set(lc.__all__) & set(lugre.__all__)
    # The old names: the same objects, with a DeprecationWarning naming the new place.
    with pytest.warns(DeprecationWarning, match=r"use lugre\.chunk\.chunk_count"):
        assert lugre.chunk_count is lc.chunk_count
    with pytest.warns(DeprecationWarning, match=r"lugre\.ChunkPlan is deprecated"):
        assert lugre.ChunkPlan is lc.ChunkPlan
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        lc.chunk_count(U, 0)  # the new place warns nothing
    with pytest.raises(AttributeError, match="no attribute 'chunk_nope'"):
        lugre.chunk_nope  # noqa: B018


def test_a_chunk_past_the_last_index_is_refused():
    with pytest.raises(ValueError) as e:
        lc.chunk_count(U[:10], 2**64 - 5)
    assert str(e.value) == (
        "offset: a chunk of 10 samples from u[18446744073709551611] runs past "
        "u[9223372036854775807], the last index a history can have (indices are int64)"
    )
    with pytest.raises(ValueError, match=r"^offset: a chunk of 10 samples from u\[9223372036854775800\]"):
        lc.chunk_count(U[:10], 2**63 - 8)
    summary, rows = lc.chunk_count(U[:10], 2**63 - 10)  # ends at the last index
    assert summary.end == 2**63 - 1
    with pytest.raises(ValueError, match=r"^offset must be >= 0, got -1$"):
        lc.chunk_count(U, -1)
    with pytest.raises(ValueError, match=r"^offset is too large"):
        lc.chunk_count(U, 2**64)
    with pytest.raises(TypeError, match=r"^offset must be an integer, got float$"):
        lc.chunk_count(U, 1.0)
    with pytest.raises(ValueError, match=r"^offset: a chunk of 100 samples"):
        lc.chunk_bounds(U, 2**64 - 1, None, lugre.LuGre())


def test_a_sample_before_the_chunk_must_be_one():
    m = lugre.LuGre()
    with pytest.raises(ValueError) as e:
        lc.chunk_bounds(U, 0, math.nan, m)
    assert str(e.value) == "prev: the chunk starts at u[0]: there is no sample before it, got NaN"
    with pytest.raises(ValueError) as e:
        lc.chunk_bounds(U, 10, math.nan, m)
    assert str(e.value) == "prev: u[9] must be a finite number, got NaN"
    with pytest.raises(ValueError, match=r"^prev: u\[9\] must be a finite number, got inf$"):
        lc.chunk_close(U, 10, math.inf, {"id": np.array([], dtype=np.int64),
                                         "after": np.array([], dtype=np.int64),
                                         "u_start": np.array([]), "u_end": np.array([])})
    with pytest.raises(ValueError, match=r"^prev: u\[9\] = 1e\+?308 is too large"):
        lc.chunk_count_energy(U, 10, 1e308, 0.0, m, None)
    upper, lower = lc.chunk_bounds(U, 10, U[0], m)
    assert math.isfinite(upper) and math.isfinite(lower)


def test_entry_states_must_be_states():
    m = lugre.LuGre()  # g(0) = 2
    with pytest.raises(ValueError) as e:
        lc.chunk_guess_entries(m, math.nan, [(0.5, 0.5)])
    assert str(e.value) == (
        "y_start must be a finite number with |y_start| <= g(0) = 2 (a state y* can hold), got NaN"
    )
    with pytest.raises(ValueError, match=r"^y_start must be .* got 3$"):
        lc.chunk_guess_entries(m, 3.0, [])
    with pytest.raises(ValueError, match=r"^bounds\[1\] = \(1, NaN\) must be finite numbers"):
        lc.chunk_guess_entries(m, 0.0, [(0.5, 0.5), (1.0, math.nan)])
    assert lc.chunk_guess_entries(m, 0.5, [(0.25, 0.25), (1.0, -1.0)]) == [0.5, 0.25]
    with pytest.raises(ValueError, match=r"^y_entry must be a finite number"):
        lc.chunk_count_energy(U, 0, None, math.inf, m, None)
    with pytest.raises(ValueError, match=r"^y_start must be a finite number"):
        lc.chunk_history_energy(m, math.nan, [])


def rows_of(u):
    return lc.chunk_count(u, 0)[1].to_dict()


def test_columns_of_different_lengths_are_refused_by_name():
    d = rows_of(U)
    n = len(d["range"])
    back = lc.ChunkRows.from_dict(d)
    assert len(back) == n and pickle.loads(pickle.dumps(back)).to_dict().keys() == d.keys()
    short = dict(d, mean=d["mean"][:-1])
    with pytest.raises(ValueError) as e:
        lc.ChunkRows.from_dict(short)
    assert str(e.value) == f"columns: column 'mean' has {n - 1} values, column 'range' has {n}"
    missing = {k: v for k, v in d.items() if k != "closure"}
    with pytest.raises(ValueError, match=r"^columns: no column 'closure'$"):
        lc.ChunkRows.from_dict(missing)
    with pytest.raises(TypeError, match=r"^columns: column 'start' must be a 1-D numpy array of int64"):
        lc.ChunkRows.from_dict(dict(d, start=d["start"].astype(float)))
    energy = lc.chunk_count_energy(U, 0, None, 0.0, lugre.LuGre(), None)[0].to_dict()
    with pytest.raises(ValueError, match=r"^columns: column 'closure_gap' has 0 values"):
        lc.ChunkRows.from_dict(dict(energy, closure_gap=np.array([])))
    queries = {"id": np.array([0, 1]), "after": np.array([3]),
               "u_start": np.array([0.0, 1.0]), "u_end": np.array([1.0, 0.0])}
    with pytest.raises(ValueError, match=r"^queries: column 'after' has 1 values, column 'id' has 2$"):
        lc.chunk_close(U, 0, None, queries)
    queries["after"] = np.array([3, -4])
    with pytest.raises(ValueError, match=r"^queries: column 'after' must hold indices >= 0, got -4$"):
        lc.chunk_close(U, 0, None, queries)
    own = lc.chunk_count(U, 0)[1]
    extras = dict(d, key=b"\0" * 3)
    with pytest.raises(ValueError, match=r"^extras: 'key' has 3 bytes"):
        lc.chunk_assemble(own, extras)


def test_an_empty_or_one_sample_array_on_dask_is_the_history_not_a_chunk():
    da = pytest.importorskip("dask.array")
    import lugre.dask as ld

    with pytest.raises(ValueError) as e:
        ld.cycles(da.from_array(np.array([]), chunks=1))
    assert str(e.value) == "lugre.dask: x: the history is empty (no samples)"
    with pytest.raises(ValueError) as e:
        ld.count(da.from_array(np.array([2.5]), chunks=1))
    assert str(e.value) == "lugre.dask: x: a history needs at least 2 samples, got 1"
    # The words of the single pass.
    with pytest.raises(ValueError) as e:
        lugre.cycles([])
    assert str(e.value) == "the history is empty (no samples)"
