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

The zoo's models (Maxwell-slip, Prandtl-Ishlinskii, ...; ``lugre.ZOO_MODELS`` is the core's table
of them with their parameters, units, domains and defaults) through one class:
``lugre.ZooModel("maxwell-slip", stiffness=[1, 2], slip_force=[1, 0.5]).loop([3, 1, 2, -3])``
returns a ``ZooLoop`` with the surface of ``HysteresisLoop`` (loops and their energies, samples);
``lugre.simulate(model=m, t=t, u=u)`` (or ``m.simulate(...)``) the force at each sample from rest,
as ``lugre simulate --model NAME --json`` gives it (keys model, t, u, y).

Histories too large for one machine: ``lugre.dask`` (``pip install lugre[dask]``) counts a
``dask.array`` or a list of ``.npy`` files chunk by chunk, equal to ``lugre.cycles`` row for row;
the chunk functions it schedules (``chunk_count``, ``chunk_merge``, ``ChunkPlan``, ...) are in
``lugre.chunk``.

Results are plain values: models, loops and result dicts pickle (multiprocessing, joblib,
Dask), and tables go straight into pandas (``lugre.cycles(...).to_frame()``,
``lugre.dynamics(...).to_frame()``, ``hl.sample(n).to_frame()``,
``pandas.DataFrame(model.simulate(...))``, ``pandas.DataFrame(hl.loop_table)``).

Steady-state sweeps (``lugre sweep``): ``lugre.sweep(model, amplitudes=..., frequencies=...,
offset=None, tol=None, loop_samples=None)`` returns the energy per cycle, peak force, equivalent
stiffness and damping and describing function of the periodic steady state under each sine of
the grid (``help(lugre.sweep)``).

Data files: ``lugre.read(path, columns=None, scale=None, delimiter=None, *, roles=None)``
returns a file's columns by role ("t", "u", "F", ...) with their units, read by the same reader
as the ``lugre`` command's ``--input`` (see ``help(lugre.read)``).

Parameter identification (``lugre fit``): ``lugre.fit(u, f, *, t=None, model="lugre",
kind="slow", fix=(), free=(), start=None, bounds=None, x0=None, starts=None)`` returns a dict of
the estimates with standard errors, 95 % intervals and correlations, and the fitted curve (see
``help(lugre.fit)``).
"""

import warnings as _warnings

from . import chunk
from ._lugre import (
    CYCLE_COLUMNS,
    DYNAMICS_COLUMNS,
    DYNAMICS_FIELDS,
    LOOP_COLUMNS,
    PARAMETERS,
    SWEEP_COLUMNS,
    ZOO_MODELS,
    Curve,
    Dahl,
    HysteresisLoop,
    Loop,
    LoopPoint,
    LuGre,
    TheoremA,
    ZooLoop,
    ZooModel,
    __version__,
    cycles,
    dynamics,
    fit,
    sweep,
)
from ._read import Columns, read

__all__ = [
    "CYCLE_COLUMNS",
    "DYNAMICS_COLUMNS",
    "DYNAMICS_FIELDS",
    "Columns",
    "LOOP_COLUMNS",
    "PARAMETERS",
    "SWEEP_COLUMNS",
    "ZOO_MODELS",
    "Curve",
    "CyclesResult",
    "Dahl",
    "DynamicsResult",
    "HysteresisLoop",
    "Loop",
    "LoopPoint",
    "LuGre",
    "TheoremA",
    "ZooLoop",
    "ZooModel",
    "__version__",
    "chunk",
    "cycles",
    "dynamics",
    "fit",
    "read",
    "simulate",
    "sweep",
    "SweepResult",
]


def __getattr__(name):
    """The chunk protocol's old top-level names (``lugre.chunk_count``, ...): deprecated
    aliases of ``lugre.chunk``'s, kept for this release only (see CHANGELOG.md)."""
    # chunk_start_entry came after the move: it never had a top-level name.
    if name in chunk.__all__ and name != "chunk_start_entry":
        _warnings.warn(
            f"lugre.{name} is deprecated and will be removed in the next release: "
            f"use lugre.chunk.{name}",
            DeprecationWarning,
            stacklevel=2,
        )
        return getattr(chunk, name)
    raise AttributeError(f"module 'lugre' has no attribute {name!r}")


class CyclesResult(dict):
    """What ``lugre.cycles`` returns: a dict with "reversals" (columns "index", "u", or None),
    "cycles" (the cycle table: one numpy array per column, all of one length) and "summary";
    ``to_frame()`` gives the cycle table as a ``pandas.DataFrame`` (as
    ``pandas.DataFrame(r["cycles"])``). Picklable like any dict."""

    __slots__ = ()

    def to_frame(self):
        """The cycle table as a ``pandas.DataFrame``, one row per cycle in the order they
        close (pandas is imported here, only)."""
        import pandas as pd

        return pd.DataFrame(self["cycles"])


class SweepResult(dict):
    """What ``lugre.sweep`` returns: a dict with one numpy array per column of
    ``SWEEP_COLUMNS`` (one entry per point, amplitude-major), and "loops" (a list of dicts t, u,
    force) when ``loop_samples`` was given; ``to_frame()`` gives the columns as a
    ``pandas.DataFrame``. Picklable like any dict."""

    __slots__ = ()

    def columns(self):
        """The points' columns, in the order of ``lugre sweep --csv``, as a dict of arrays."""
        return {key: self[key] for key in SWEEP_COLUMNS}

    def to_frame(self):
        """The points as a ``pandas.DataFrame``, one row per point (pandas is imported here,
        only)."""
        import pandas as pd

        return pd.DataFrame(self.columns())


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


def simulate(model=None, *args, **keywords):
    """The response of ``model`` to one input, as ``lugre simulate [--model NAME]`` computes it.

    * a ``LuGre`` or ``Dahl`` (None: ``LuGre()``, the paper's defaults): ``model.simulate(...)``
      with the same arguments (``help(lugre.LuGre.simulate)``); a dict of float64 arrays t, u,
      z, dz, y;
    * a ``ZooModel``: ``model.simulate(...)`` from rest, with ``t, u`` or ``turning_points`` at
      ``speed``; a dict model (its name as "kind" and each parameter by name), t, u, y (the
      force): the keys and values of ``lugre simulate --model NAME --json``. LuGre's own
      keywords (x0, gamma, ...) raise ValueError.
    """
    if model is None:
        model = LuGre()
    if not isinstance(model, (LuGre, Dahl, ZooModel)):
        raise TypeError(f"model must be a lugre.LuGre, lugre.Dahl or lugre.ZooModel, got {type(model).__name__}")
    return model.simulate(*args, **keywords)
