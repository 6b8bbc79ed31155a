"""The chunked rainflow count (core ``lugre::cycles::chunk``): the pieces ``lugre.dask``
schedules as tasks, for drivers of other schedulers.

A history cut into chunks is counted chunk by chunk (``chunk_count``), the chunks' summaries
merged in any tree order (``chunk_merge``), the cycles only the merges complete closed by a
second, read-only pass (``ChunkPlan.queries``, ``chunk_close``), and each chunk's rows put in
the single pass's order (``ChunkPlan.extras``, ``chunk_assemble``); with a model, each chunk is
counted with energies from its entry state (``chunk_start_entry``, ``chunk_bounds``,
``chunk_guess_entries``, ``chunk_count_energy``, ``ChunkPlan.attach_energy``,
``chunk_history_energy``). The result equals ``lugre.cycles`` row for row. ``lugre.dask`` is
the worked driver.

The model is a ``lugre.LuGre``/``lugre.Dahl`` (entry states are floats, ``y*``) or a
``lugre.ZooModel`` (entry states are bytes: the model's state as little-endian doubles, equal
states giving equal bytes); the same calls take either.

Bad arguments raise ValueError naming them: an ``offset`` whose chunk would run past the
last index a history can have (int64), a ``prev`` (the sample before the chunk) before u[0] or
not a finite number, a ``y_start``/``y_entry`` that is not a state y* can hold, a dict of
columns with a column missing or of another length. ``ChunkSummary`` and ``ChunkRows``
pickle.

These names were also at the package's top level (``lugre.chunk_count``, ...); those aliases
are deprecated and go in the next release.
"""

from ._lugre import (
    ChunkPlan,
    ChunkRows,
    ChunkSummary,
    chunk_assemble,
    chunk_bounds,
    chunk_close,
    chunk_count,
    chunk_count_energy,
    chunk_guess_entries,
    chunk_history_energy,
    chunk_merge,
    chunk_start_entry,
)

__all__ = [
    "ChunkPlan",
    "ChunkRows",
    "ChunkSummary",
    "chunk_assemble",
    "chunk_bounds",
    "chunk_close",
    "chunk_count",
    "chunk_count_energy",
    "chunk_guess_entries",
    "chunk_history_energy",
    "chunk_merge",
    "chunk_start_entry",
]
