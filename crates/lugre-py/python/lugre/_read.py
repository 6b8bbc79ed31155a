"""``lugre.read``: a data file's columns, read by the reader every lugre front end shares (the
Rust crate ``lugre-io``: the rules and messages of the ``lugre`` command's ``--input``)."""

from __future__ import annotations

import os
from typing import Mapping, Optional, Sequence, Union

from . import _lugre

__all__ = ["Columns", "read"]


class Columns(dict):
    """A data file's columns: a dict of float64 numpy arrays keyed by role ("t", "u", "v", "F",
    "N", or a column's own name), of equal lengths (``pandas.DataFrame(columns)`` works), with

    * ``units``: role -> the unit the header gives in brackets or parentheses (``"mm"`` for
      ``Position [mm]``), or None;
    * ``names``: role -> the header field as written, or None for a file without a header;
    * ``path``: the file read.

    The values are as read, times ``scale``: the units are the file's, for labels.
    """

    def __init__(self, values: dict, units: dict, names: dict, path: str):
        super().__init__(values)
        self.units = units
        self.names = names
        self.path = path

    def __repr__(self) -> str:
        n = len(next(iter(self.values()))) if self else 0
        cols = ", ".join(
            f"{k} [{u}]" if (u := self.units.get(k)) else k for k in self
        )
        return f"Columns({self.path!r}: {cols}; {n} rows)"

    def __reduce__(self):
        return (Columns, (dict(self), self.units, self.names, self.path))


def read(
    path: Union[str, os.PathLike],
    columns: Optional[Union[Mapping[str, Union[str, int]], str]] = None,
    scale: Optional[Union[Mapping[str, float], str]] = None,
    delimiter: Optional[str] = None,
    *,
    roles: Optional[Sequence[str]] = None,
) -> Columns:
    """The columns of the data file ``path``, as ``lugre.Columns`` (a dict of float64 arrays
    keyed by role, with ``units`` and ``names``), read as the ``lugre`` command reads
    ``--input`` files (README, "Data files"):

    * fields separated by tabs, semicolons, commas or runs of spaces (found from the first line
      that is not a comment; ``delimiter="comma"|"semicolon"|"tab"|"space"`` gives it), LF,
      CRLF or CR line ends, a UTF-8 byte-order mark, ``#`` comments and blank lines anywhere;
    * an optional header naming columns by their usual names, any case, with an optional unit
      in brackets or parentheses (kept in ``units``): "t" (t, time), "u" (u, x, position,
      displacement), "v" (v, velocity), "F" (F, force, friction, y), "N" (N, normal, normal
      force, load);
    * ``roles``: the value columns the file must hold (e.g. ``["u", "F"]``; a role by any of
      its names, or a column's own name such as ``"strain"``); "t" is read whenever the file
      has it. Default: every role the header has, columns of other names ignored; without a
      header, one column is "u", two are "t", "u", three "t", "u", "F";
    * ``columns``: which column holds a role, by header name (unit ignored, any case) or
      1-based number: ``{"t": "Time", "u": 3}`` (or the command's text, ``"t=Time,u=3"``);
    * ``scale``: a factor per role applied as read: ``{"u": 1e-3, "F": -1e-6}`` (or
      ``"u=1e-3,F=-1e-6"``).

    Values must be finite numbers and times strictly increasing. Every problem raises
    ValueError naming the file, the line (as an editor numbers it) and the column: a missing
    column, two columns of one role, a role given twice or a column given two roles in
    ``columns``, a role given twice in ``scale``, a value that is not a finite number, no data
    rows. Arguments of the wrong type raise TypeError.

    >>> import lugre, pathlib, tempfile
    >>> p = pathlib.Path(tempfile.mkdtemp()) / "lab.tsv"
    >>> _ = p.write_text("# rig 3\\nTime [s]\\tPosition [mm]\\tNote\\n0\\t1.5\\ta\\n0.5\\t2.5\\tb\\n")
    >>> d = lugre.read(p, scale={"u": 1e-3})
    >>> list(d), d["u"].tolist(), d.units["u"]
    (['t', 'u'], [0.0015, 0.0025], 'mm')
    """
    values, units, names = _lugre.read(path, columns, scale, delimiter, roles)
    return Columns(values, units, names, os.fspath(path))
