"""Rainflow counts of histories too large for one machine, on Dask (``pip install lugre[dask]``).

``lugre.dask.cycles(x, model=None, x0=None)`` counts a 1-D ``dask.array`` (or a list of ``.npy``
files read as one history, in order) chunk by chunk and returns a ``dask.dataframe`` with the
columns of ``lugre.cycles(...)["cycles"]``, **equal to the single pass row for row**: the same
ranges, means, counts, start/end indices, closure indices and positions, in the same order
(the frame's index is the row number of the single pass), and with a model the same energies
and totals, bit for bit but for a rare difference in the last place (the arcs' double-double
sums are added in another order: README, "The contract").

How (``lugre::cycles::chunk``): each chunk is counted on its own (its own full cycles and an
irreducible residue, at the single pass's speed); the residues are merged pairwise as a tree
of small tasks; the cycles only the merges complete get their closures from a second,
read-only pass over the chunks that can hold them (found from each chunk's extremes); with a
model, every chunk is counted again with energies from its entry state ``y*``, guessed from
the chunk before (both extreme states run through it land on the same double on any record
that moves) and verified in order, a wrong guess costing one chunk counted again; the rows
are put back in the single pass's order per chunk. ``count`` also returns the summary and the
time of each stage.

The core package never imports Dask; this module needs ``dask[distributed,dataframe]``. It
runs on the scheduler Dask would use anyway: a ``distributed.Client`` if one is active
(``Client("tcp://scheduler:8786")`` for a real cluster), else threads.

A model of the zoo (``lugre.ZooModel``) is taken alike, its energies along the model's path
from rest at the history's first sample equal to ``lugre.cycles(u, model=...)``'s: each chunk
is counted from its entry state, the model's state at the sample before it. A Masing model's
(Maxwell-slip, Prandtl-Ishlinskii) is exact from the merged residue of the chunks before it
(the wiping-out property); a single-state model's (Bouc-Wen, elasto-plastic) is guessed from
both bounds of its state run through the chunk before and verified in order, as LuGre's. The
core decides which; this module passes the model through. ``x0`` is refused with a zoo model
(it starts from rest), and each chunk may hold at most 2^27 samples (the whole history may
hold more).

The noise gate is not available here (``gate`` must be 0): whether a turn is a reversal
depends on how far the history later comes back, which a chunk cannot know; count gated
histories with ``lugre.cycles``. Records that are independent (one test each) are counted or
fitted one task per file by ``cycles_many`` and ``fit_many``.
"""

from __future__ import annotations

import os
import re
import time
from typing import Any, Callable, Optional, Sequence

import numpy as np

try:
    import dask
    import dask.array as da
    import dask.dataframe as dd
    import pandas as pd
except ImportError as e:  # pragma: no cover - the message is the point
    raise ImportError(
        "lugre.dask needs Dask: pip install 'lugre[dask]' (dask[distributed,dataframe])"
    ) from e

from ._read import read as _read
from . import _lugre
from . import chunk as _chunk
from . import cycles as _single_cycles
from . import fit as _single_fit

__all__ = ["count", "cycles", "cycles_many", "fit_many"]

# The core's cycle columns (lugre.CYCLE_COLUMNS): the count's and the closure's, then the four
# energies over the arc.
_COLUMNS = list(_lugre.CYCLE_COLUMNS[:-4])
_ENERGY = list(_lugre.CYCLE_COLUMNS[-4:])
# Samples at a chunk's end over which its end state is first guessed.
_TAIL = 1 << 14


class _Chunks:
    """The history's chunks: a delayed reader per chunk, and each chunk's first index."""

    def __init__(self, readers: list, lengths: list[int], names: list[str]):
        self.readers = readers
        self.offsets = [int(o) for o in np.cumsum([0] + lengths[:-1])]
        self.lengths = lengths
        self.names = names

    def __len__(self) -> int:
        return len(self.readers)

    def where(self, k: int) -> str:
        a = self.offsets[k]
        return f"chunk {k} of {len(self)} ({self.names[k]}u[{a}..={a + self.lengths[k] - 1}])"


def _as_floats(block: Any) -> np.ndarray:
    """A chunk as contiguous float64 (the dtype was checked before any task ran)."""
    return np.ascontiguousarray(np.asarray(block).reshape(-1), dtype=np.float64)


def _read_npy(path: str) -> np.ndarray:
    return _as_floats(np.load(path, mmap_mode="r"))


def _natural_key(name: str) -> list:
    return [int(t) if t.isdigit() else t for t in re.split(r"(\d+)", name)]


def _check_dtype(dtype: np.dtype, what: str) -> None:
    # The kinds lugre.cycles takes: integers and floats (not bool, complex, text, objects).
    if np.dtype(dtype).kind not in "iuf":
        raise TypeError(
            f"{what} must hold real numbers, got dtype {np.dtype(dtype)}"
        )


def _from_files(paths: Sequence[Any], check_order: bool) -> _Chunks:
    names = [os.fspath(p) for p in paths]
    if not names:
        raise ValueError("lugre.dask: the list of files is empty")
    lengths = []
    for k, p in enumerate(names):
        if not os.path.isfile(p):
            raise ValueError(f"lugre.dask: file {k} of {len(names)} ({p}) does not exist")
        if not p.endswith(".npy"):
            raise ValueError(
                f"lugre.dask: file {k} ({p}) is not a .npy file (write chunks with numpy.save)"
            )
        a = np.load(p, mmap_mode="r")  # reads the header only
        if a.ndim != 1:
            raise ValueError(
                f"lugre.dask: file {k} ({p}) must hold a 1-D array, got shape {list(a.shape)}"
            )
        _check_dtype(a.dtype, f"lugre.dask: file {k} ({p})")
        if a.size == 0:
            raise ValueError(f"lugre.dask: file {k} ({p}) is empty")
        lengths.append(int(a.size))
    if check_order:
        base = [os.path.basename(p) for p in names]
        for k in range(1, len(base)):
            if _natural_key(base[k]) < _natural_key(base[k - 1]):
                raise ValueError(
                    f"lugre.dask: files are not in order: {names[k]} comes after {names[k - 1]} "
                    "(pass them in the history's order, e.g. sorted by name; "
                    "check_order=False takes them as given)"
                )
    readers = [dask.delayed(_read_npy)(p) for p in names]
    return _Chunks(readers, lengths, [f"{p}: " for p in names])


def _from_array(x: Any) -> _Chunks:
    if x.ndim != 1:
        raise ValueError(f"series must be one-dimensional, got a dask array of shape {list(x.shape)}")
    _check_dtype(x.dtype, "series")
    lengths = list(x.chunks[0])
    if any(np.isnan(n) for n in lengths):
        raise ValueError(
            "lugre.dask: the dask array has unknown chunk sizes; call x.compute_chunk_sizes() first"
        )
    lengths = [int(n) for n in lengths]
    _check_length(sum(lengths))
    for k, n in enumerate(lengths):
        if n == 0:
            a = sum(lengths[:k])
            raise ValueError(
                f"lugre.dask: chunk {k} of {len(lengths)} (before u[{a}]) is empty; "
                "rechunk the array (x.rechunk(...))"
            )
    readers = [dask.delayed(_as_floats)(b) for b in x.to_delayed().ravel()]
    return _Chunks(readers, lengths, ["" for _ in lengths])


def _check_length(total: int) -> None:
    """A history of 0 or 1 samples is refused, with ``lugre.cycles``' own words (the core's one
    rule, as ``lugre cycles`` and the C ABI refuse it)."""
    if total < 2:
        try:
            _single_cycles(np.zeros(total), reversals=False)
        except ValueError as e:
            raise ValueError(f"lugre.dask: x: {e}") from None


def _chunks_of(x: Any, check_order: bool) -> _Chunks:
    if isinstance(x, da.Array):
        return _from_array(x)
    if isinstance(x, (list, tuple)) and all(isinstance(p, (str, os.PathLike)) for p in x):
        return _from_files(x, check_order)
    raise TypeError(
        "lugre.dask: x must be a 1-D dask.array or a list of .npy file paths, "
        f"got {type(x).__name__}"
    )


def _in_chunk(where: str, f: Callable, *args: Any) -> Any:
    """Runs one chunk's step; a bad sample's message names the chunk."""
    try:
        return f(*args)
    except ValueError as e:
        raise ValueError(f"{where}: {e}") from None


# --- the tasks (module-level functions: they pickle by reference) -------------------------------


def _leaf(u: np.ndarray, offset: int, where: str, model: Any) -> tuple:
    summary, rows = _in_chunk(where, _chunk.chunk_count, u, offset)
    bounds = None
    if model is not None:
        # The state at the chunk's end from both extremes over its last samples; the whole
        # chunk where these do not agree (a quiet stretch). A guess either way: verified.
        tail = max(len(u) - _TAIL, 0)
        bounds = _in_chunk(where, _chunk.chunk_bounds, u[tail:], offset + tail, None, model)
        # None: the model's entry states follow from the summaries alone (exact).
        if bounds is not None and bounds[0] != bounds[1] and tail > 0:
            bounds = _in_chunk(where, _chunk.chunk_bounds, u, offset, None, model)
        rows = None  # counted again with energies
    return summary, rows, bounds


def _pick(t: tuple, i: int) -> Any:
    return t[i]


def _merge(*summaries: Any) -> tuple:
    """Merges adjacent summaries left to right: the summary of all and the open cycles."""
    acc, opens = summaries[0], []
    for s in summaries[1:]:
        acc, o = _chunk.chunk_merge(acc, s)
        opens.append(o)
    return acc, opens


def _close(u: np.ndarray, offset: int, prev: Optional[float], queries: dict, where: str) -> dict:
    return _in_chunk(where, _chunk.chunk_close, u, offset, prev, queries)


def _energy(u: np.ndarray, offset: int, prev: Optional[float], y: float, model: Any,
            spans: Optional[dict], where: str) -> tuple:
    return _in_chunk(where, _chunk.chunk_count_energy, u, offset, prev, y, model, spans)


def _bits(state: Any) -> bytes:
    """An entry state's bits: equal states, equal bits (0.0 and -0.0 differ)."""
    return state if isinstance(state, bytes) else np.float64(state).tobytes()


def _energy_small(t: tuple) -> tuple:
    return t[1], t[2]


def _assemble(own: dict, extras: dict, first_row: int, energy: bool) -> "pd.DataFrame":
    rows = _chunk.chunk_assemble(own, extras)
    columns = _COLUMNS + (_ENERGY if energy else [])
    n = len(rows["range"])
    # copy=False: one block per column, as the arrays come (no consolidating copy).
    return pd.DataFrame({c: rows[c] for c in columns},
                        index=pd.RangeIndex(first_row, first_row + n), copy=False)


def _meta(energy: bool) -> "pd.DataFrame":
    types = {"range": "f8", "mean": "f8", "count": "f8", "start": "i8", "end": "i8",
             "closure": "i8", "closure_position": "f8"}
    if energy:
        types.update({c: "f8" for c in _ENERGY})
    return pd.DataFrame({c: np.array([], dtype=t) for c, t in types.items()})


# --- the driver -----------------------------------------------------------------------------------


def _merge_tree(summaries: list, fan_in: int) -> tuple:
    """Merges as a tree of delayed tasks, ``fan_in`` summaries per task (a merge costs about a
    microsecond: tasks of one merge each would cost the scheduler more than the merges):
    (root, [lists of open cycles])."""
    level, opens = list(summaries), []
    while len(level) > 1:
        nxt = []
        for i in range(0, len(level), fan_in):
            group = level[i:i + fan_in]
            if len(group) == 1:
                nxt.append(group[0])
                continue
            m = dask.delayed(_merge)(*group)
            nxt.append(dask.delayed(_pick)(m, 0))
            opens.append(dask.delayed(_pick)(m, 1))
        level = nxt
    return level[0], opens


def _check_model(model: Any, x0: Optional[float], gate: float) -> None:
    if gate != 0:
        raise ValueError(
            "lugre.dask: gate > 0 is not available in distributed mode (whether a turn is a "
            "reversal depends on how far the history later comes back, which a chunk cannot "
            "know); count with gate=0, or count the whole history with lugre.cycles"
        )
    # The single pass's own checks (model type, x0 finite and |sigma0 x0| <= g0), before
    # any task runs.
    _single_cycles([0.0, 1.0], 0.0, model, x0, reversals=False)


def count(x: Any, model: Any = None, x0: Optional[float] = None, gate: float = 0.0, *,
          check_order: bool = True, merge_fan_in: int = 8) -> dict:
    """Counts the history ``x`` in chunks on Dask; returns a dict with "cycles" (a persisted
    ``dask.dataframe``, see ``cycles``), "summary" (that of ``lugre.cycles``), "chunks", "stages"
    (seconds per stage: count, merge, closures, energies, assemble) and "entries" (with a
    model: how many chunks' guessed entry states held, of how many; the others were counted
    again from the exact state).

    ``x``: a 1-D ``dask.array`` of real numbers (no empty chunks, known chunk sizes) or a list
    of ``.npy`` files holding 1-D arrays, read as one history in the given order (checked to be
    in natural name order unless ``check_order=False``). ``merge_fan_in``: summaries merged
    per task (>= 2; any tree gives the same result). ``model``: None, a ``lugre.LuGre`` or
    ``lugre.Dahl`` (from ``x0``), or a ``lugre.ZooModel`` (from rest at the first sample).
    """
    if not isinstance(merge_fan_in, int) or merge_fan_in < 2:
        raise ValueError(f"lugre.dask: merge_fan_in must be an integer >= 2, got {merge_fan_in!r}")
    _check_model(model, x0, gate)
    chunks = _chunks_of(x, check_order)
    n = len(chunks)
    total = sum(chunks.lengths)
    _check_length(total)
    energy = model is not None
    stages: dict[str, float] = {}

    tic = time.perf_counter()
    leaves = [dask.delayed(_leaf)(r, chunks.offsets[k], chunks.where(k), model)
              for k, r in enumerate(chunks.readers)]
    leaves = list(dask.persist(*leaves, optimize_graph=False))
    summaries = [dask.delayed(_pick)(lf, 0) for lf in leaves]
    bounds = [dask.delayed(_pick)(lf, 2) for lf in leaves]
    summaries_v, bounds_v = dask.compute(summaries, bounds, optimize_graph=False)
    stages["count"] = time.perf_counter() - tic

    tic = time.perf_counter()
    root, opens = _merge_tree(summaries, merge_fan_in)
    root_v, opens_v = dask.compute(root, opens, optimize_graph=False)
    plan = _chunk.ChunkPlan(list(summaries_v))
    for group in opens_v:
        for o in group:
            plan.add_open(o)
    summary = plan.finish(root_v)
    stages["merge"] = time.perf_counter() - tic

    tic = time.perf_counter()
    prevs = [None] + [s.last for s in summaries_v[:-1]]
    closes = [dask.delayed(_close)(chunks.readers[k], chunks.offsets[k], prevs[k], q,
                                              chunks.where(k))
              for k, q in enumerate(plan.queries()) if q is not None]
    for found in dask.compute(*closes, optimize_graph=False):
        plan.resolve(found)
    stages["closures"] = time.perf_counter() - tic

    entries = None
    if energy:
        tic = time.perf_counter()
        spans = plan.energy_spans()
        # The entry states are the core's: floats (y*) or bytes (a zoo model's state), alike
        # here; the first is exact.
        y0 = _chunk.chunk_start_entry(model, x0, summaries_v[0].first)
        guesses = _chunk.chunk_guess_entries(model, y0, list(bounds_v), list(summaries_v))

        def energy_task(k: int, y: float) -> Any:
            return dask.delayed(_energy)(
                chunks.readers[k], chunks.offsets[k], prevs[k], y, model, spans[k],
                chunks.where(k))

        passes = list(dask.persist(*[energy_task(k, guesses[k]) for k in range(n)],
                                   optimize_graph=False))
        small = list(dask.compute(*[dask.delayed(_energy_small)(p) for p in passes],
                                  optimize_graph=False))
        held = 0
        # Verified in order: chunk 0 enters exactly; chunk k's guess holds when it is the
        # state chunk k-1's (exact) pass ended at, else chunk k is counted again from it.
        for k in range(1, n):
            exact = small[k - 1][1]
            if _bits(exact) == _bits(guesses[k]):
                held += 1
                continue
            (passes[k],) = dask.persist(energy_task(k, exact), optimize_graph=False)
            small[k] = dask.compute(dask.delayed(_energy_small)(passes[k]),
                                    optimize_graph=False)[0]
        plan.attach_energy(model, [s[0] for s in small])
        summary["energy"] = _chunk.chunk_history_energy(model, y0, [s[0] for s in small])
        own = [dask.delayed(_pick)(p, 0) for p in passes]
        entries = {"held": held, "chunks": n - 1}
        stages["energies"] = time.perf_counter() - tic
    else:
        own = [dask.delayed(_pick)(lf, 1) for lf in leaves]

    tic = time.perf_counter()
    extras = plan.extras(energy)
    first, parts = 0, []
    for k in range(n):
        parts.append(dask.delayed(_assemble)(own[k], extras[k], first, energy))
        first += summaries_v[k].full_cycles + len(extras[k]["range"])
    parts = list(dask.persist(*parts, optimize_graph=False))
    # Waits for every partition (a failed task raises here, never a partial table).
    lengths = dask.compute(*[dask.delayed(len)(p) for p in parts], optimize_graph=False)
    df = dd.from_delayed(parts, meta=_meta(energy), verify_meta=False)
    if int(np.sum(lengths)) != first:
        raise RuntimeError(f"lugre.dask: assembled {int(np.sum(lengths))} rows, expected {first}")
    stages["assemble"] = time.perf_counter() - tic
    return {"cycles": df, "summary": summary, "chunks": n, "stages": stages, "entries": entries}


def cycles(x: Any, model: Any = None, x0: Optional[float] = None, gate: float = 0.0, *,
           check_order: bool = True) -> "dd.DataFrame":
    """The rainflow cycles of the history ``x`` (see ``count``) as a persisted
    ``dask.dataframe`` with the columns of ``lugre.cycles(...)["cycles"]`` ("range", "mean",
    "count", "start", "end", "closure", "closure_position"; with a model "work",
    "stored_energy_change", "dissipation", "closure_gap"), one partition per chunk, indexed by
    the single pass's row number: ``cycles(x).compute()`` equals
    ``pandas.DataFrame(lugre.cycles(x.compute(), reversals=False)["cycles"])``."""
    return count(x, model, x0, gate, check_order=check_order)["cycles"]


# --- independent records, one task per file ------------------------------------------------------


def _series_of(path: str, column: Optional[str]) -> np.ndarray:
    if path.endswith(".npy"):
        return _read_npy(path)
    # The reader of lugre.read and the lugre command (its errors name the file and the line).
    d = _read(path, roles=[column or "u"])
    (role,) = [k for k in d if k != "t"]
    return d[role]


def _cycles_file(path: str, column: Optional[str], gate: float, model: Any,
                 x0: Optional[float]) -> "pd.DataFrame":
    u = _series_of(path, column)
    try:
        r = _single_cycles(u, gate, model, x0, reversals=False)
    except (ValueError, TypeError) as e:
        raise type(e)(f"{path}: {e}") from None
    df = pd.DataFrame(r["cycles"])
    df.insert(0, "file", path)
    return df


def cycles_many(paths: Sequence[Any], model: Any = None, x0: Optional[float] = None,
                gate: float = 0.0, *,
                column: Optional[str] = None) -> "pd.DataFrame":
    """The cycles of independent records, one task per file, as one pandas table with a "file"
    column first; the gate is allowed (each file is counted whole). A file is a ``.npy`` array,
    or a data file read by ``lugre.read`` (the ``lugre`` command's reader): the series is its
    column ``column`` (default "u": a header's u, x, position or displacement; or a column's
    own name), other columns ignored, a time column checked. A ``lugre.ZooModel`` is taken
    here (each file is held whole, as by ``lugre.cycles``), as by ``count``."""
    names = [os.fspath(p) for p in paths]
    for p in names:
        if not os.path.isfile(p):
            raise ValueError(f"lugre.dask: file {p} does not exist")
    _single_cycles([0.0, 1.0], gate, model, x0, reversals=False)
    tasks = [dask.delayed(_cycles_file)(p, column, gate, model, x0) for p in names]
    frames = dask.compute(*tasks)
    if not frames:
        return pd.DataFrame(columns=["file"] + _COLUMNS)
    return pd.concat(frames, ignore_index=True)


def _fit_file(path: str, names: dict, kwargs: dict) -> dict:
    # Columns by name where given, else by role; the reader's errors name the file and the line.
    d = _read(path, columns={k: v for k, v in names.items() if v is not None} or None,
              roles=["u", "F"])
    try:
        r = _single_fit(d["u"], d["F"], t=d.get("t"), **kwargs)
    except (ValueError, TypeError) as e:
        raise ValueError(f"{path}: {e}") from None
    row = {"file": path, "rms": r["rms"], "samples": r["samples"], "converged": r["converged"]}
    for name, p in r["parameters"].items():
        row[name] = p["value"]
        row[f"{name}_stderr"] = p["stderr"]
    return row


def fit_many(paths: Sequence[Any], *, u: Optional[str] = None, f: Optional[str] = None,
             t: Optional[str] = None, **kwargs: Any) -> "pd.DataFrame":
    """``lugre.fit`` on independent records, one task per file, as one pandas table: "file",
    "rms", "samples", "converged", and each fitted parameter's value and "<name>_stderr".
    Files are read by ``lugre.read`` (the ``lugre`` command's reader): the columns u, F and t
    (when the file has one) by their usual names (u, x, position, displacement; F, force,
    friction, y; t, time), or those ``u``, ``f`` and ``t`` name (header names, units ignored);
    other columns ignored. ``kwargs`` go to ``lugre.fit``."""
    names = [os.fspath(p) for p in paths]
    for p in names:
        if not os.path.isfile(p):
            raise ValueError(f"lugre.dask: file {p} does not exist")
    columns = {"u": u, "F": f, "t": t}
    rows = dask.compute(*[dask.delayed(_fit_file)(p, columns, kwargs) for p in names])
    return pd.DataFrame(list(rows))
