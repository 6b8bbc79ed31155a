"""lugre: hysteresis loops and minor loops of the LuGre and Dahl friction models.

Exact and numerically stable at any stiffness, after Ikhouane, Mañosa and Pujol, "Minor loops
of the Dahl and LuGre models". The computations are the Rust library's (crate ``lugre``); this
package converts numpy arrays in and out.

>>> import lugre
>>> model = lugre.LuGre(sigma0=6)                 # the paper's Example 4
>>> hl = model.loop_bimodal(0, 0.5, 1, 1.5)      # umin1, umin2, umax1, umax2
>>> hl.theorem_a.minor_loop                      # the minor loop [rho_1, rho_5]
(1.0, 2.0)
>>> [l.kind for l in hl.loops]
['major', 'minor']
>>> rho, u, y = hl.sample(1001)                  # the loop, for plotting y against u
>>> r = model.simulate([0, 1, 0.5, 1.5], gamma=10, periods=3)   # eq. 5: t, u, z, dz, y
>>> c = lugre.cycles([-2, 1, -3, 5, -1, 3, -4, 4, -2])        # rainflow cycles of a history
>>> p = lugre.fit(u, y)["parameters"]             # sigma0 and g(0) = fs from (u, F) samples
>>> round(p["sigma0"]["value"], 6), round(p["fs"]["value"], 6)
(6.0, 2.0)

Models: LuGre(sigma0=1, sigma1=1, sigma2=0, fc=1, fs=2, vs=1, beta=1) and Dahl(rho=1, fc=1)
(keyword arguments; the defaults are the paper's). Invalid values raise ValueError with the
message the ``lugre`` command prints; arguments of the wrong type raise TypeError.

Histories too large for one machine: ``lugre.dask`` (``pip install lugre[dask]``) counts a
``dask.array`` or a list of ``.npy`` files chunk by chunk, equal to ``lugre.cycles`` row for row;
the chunk functions it schedules (``chunk_count``, ``chunk_merge``, ``ChunkPlan``, ...) are here.

Parameter identification (``lugre fit``): ``lugre.fit(u, f, *, t=None, model="lugre",
kind="slow", fix=(), free=(), start=None, bounds=None, x0=None, starts=None)`` returns a dict of
the estimates with standard errors, 95 % intervals and correlations, and the fitted curve (see
``help(lugre.fit)``).
"""

from ._lugre import (
    CYCLE_COLUMNS,
    DYNAMICS_COLUMNS,
    DYNAMICS_FIELDS,
    LOOP_COLUMNS,
    PARAMETERS,
    ChunkPlan,
    ChunkRows,
    ChunkSummary,
    Curve,
    Dahl,
    HysteresisLoop,
    Loop,
    LoopPoint,
    LuGre,
    TheoremA,
    __version__,
    chunk_assemble,
    chunk_bounds,
    chunk_close,
    chunk_count,
    chunk_count_energy,
    chunk_guess_entries,
    chunk_history_energy,
    chunk_merge,
    cycles,
    dynamics,
    fit,
)

__all__ = [
    "CYCLE_COLUMNS",
    "DYNAMICS_COLUMNS",
    "DYNAMICS_FIELDS",
    "LOOP_COLUMNS",
    "PARAMETERS",
    "ChunkPlan",
    "ChunkRows",
    "ChunkSummary",
    "Curve",
    "Dahl",
    "DynamicsResult",
    "HysteresisLoop",
    "Loop",
    "LoopPoint",
    "LuGre",
    "TheoremA",
    "__version__",
    "chunk_assemble",
    "chunk_bounds",
    "chunk_close",
    "chunk_count",
    "chunk_count_energy",
    "chunk_guess_entries",
    "chunk_history_energy",
    "chunk_merge",
    "cycles",
    "dynamics",
    "fit",
]


class DynamicsResult(dict):
    """What ``lugre.dynamics`` returns: a dict (``r["x"]``, ``r["events"]``, ...) whose sampled
    columns ``t, x, v, z, friction, drive`` (all of one length) ``to_frame()`` gives as a
    ``pandas.DataFrame``; the other keys are the run's events, statistics, energies and
    headlines. Picklable like any dict."""

    __slots__ = ()

    def columns(self):
        """The sampled columns, in the order of ``lugre dynamics --csv``, as a dict of arrays."""
        return {key: self[key] for key in DYNAMICS_COLUMNS}

    def to_frame(self):
        """The sampled columns as a ``pandas.DataFrame`` (pandas is imported here, only)."""
        import pandas as pd

        return pd.DataFrame(self.columns())
