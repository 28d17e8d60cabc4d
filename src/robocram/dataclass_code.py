"""Dataclasses' generated methods compiled once per machine, not once per process.

``@dataclass`` writes each class's ``__init__``, ``__repr__``, ``__eq__``, ... as Python
source and compiles it: importing robocram's plans, projection and scenes built 282
dataclasses whose 1,559 sources took 46 % of the import's instructions to parse and
compile (callgrind), the same sources in every process. :func:`install` gives
:mod:`dataclasses` an ``exec`` that, for a class of a robocram module only, looks the
source up in a table of code objects kept on disk and compiles only a source it has not
seen, exactly as ``exec`` would (file name ``<string>``, no inherited ``__future__``
flags): the same code, so the same classes. Any other class (a user's) is compiled by
``exec`` itself, as without robocram.

The table is one file per Python bytecode version under the user's cache folder
(``$ROBOCRAM_CACHE_DIR``, else ``$XDG_CACHE_HOME/robocram``, else ``~/.cache/robocram``),
in ``dataclass-code``: a SHA-256 of the rest, then the marshalled ``{source: code}``.
A source is its own key, so an edited class misses and is compiled; a damaged, cut or
foreign file is ignored and replaced. The sources compiled anew are added at the
process's exit, written under a temporary name and renamed into place (a concurrent
writer's additions may be lost: they are compiled again later); past ``MAX_ENTRIES`` the
file keeps only what this process used. A cache that cannot be read or written only makes
dataclasses cost what they did.
"""

from __future__ import annotations

import atexit
import builtins
import contextlib
import dataclasses
import hashlib
import importlib.util
import marshal
import os
import tempfile
import threading
from collections.abc import Mapping
from pathlib import Path
from types import CodeType

__all__ = ["MAX_ENTRIES", "CodeTable", "install"]

MAX_ENTRIES = 5_000  # sources kept before the file drops what this process left unused
_KIND = "dataclass-code"
_DIGEST = 32  # bytes of SHA-256 in front of the file


class CodeTable:
    """Code objects by the source they were compiled from, read from and added to a file."""

    def __init__(self, path: Path) -> None:
        self.path = path
        self._kept: dict[str, CodeType] | None = None  # read at the first look-up
        self._used: dict[str, CodeType] = {}
        self._added = False
        self._lock = threading.Lock()

    def code(self, source: str) -> CodeType:
        """``source`` compiled as ``exec`` compiles a string: kept, else compiled now."""
        with self._lock:
            if self._kept is None:
                self._kept = _read(self.path)
            found = self._kept.get(source)
        if type(found) is not CodeType:
            found = compile(source, "<string>", "exec", dont_inherit=True)
            with self._lock:
                self._added = True
                self._kept[source] = found
        self._used[source] = found
        return found

    def exec(
        self,
        source: str | CodeType,
        globals: dict[str, object] | None = None,  # noqa: A002  (exec's own names)
        locals: Mapping[str, object] | None = None,  # noqa: A002
    ) -> None:
        """``exec(source, globals, locals)``, with a string's code from the table for
        robocram's own classes (their module's globals); any other class is compiled as
        before, so a user's dataclasses neither enter the table nor come from it."""
        if type(source) is str and _ours(globals):
            builtins.exec(self.code(source), globals, locals)
        else:
            builtins.exec(source, globals, locals)

    def save(self) -> None:
        """Write the table with this process's additions, if it made any."""
        with self._lock:
            if not self._added or self._kept is None:
                return
            kept = self._kept if len(self._kept) <= MAX_ENTRIES else dict(self._used)
            body = marshal.dumps(kept)
            self._added = False
        _write(self.path, body)


def install() -> CodeTable | None:
    """Give :mod:`dataclasses` the table's ``exec`` (once per process); the table, or None
    when another ``exec`` is already in place there."""
    current = vars(dataclasses).get("exec")
    if isinstance(getattr(current, "__self__", None), CodeTable):
        return None
    if current is not None:  # someone else's: left alone
        return None
    table = CodeTable(_file())
    dataclasses.exec = table.exec  # type: ignore[attr-defined]
    atexit.register(table.save)
    return table


def _ours(space: Mapping[str, object] | None) -> bool:
    """Whether ``space`` are a robocram module's globals (dataclasses pass the class's
    module's)."""
    name = space.get("__name__") if space is not None else None
    return isinstance(name, str) and (name == "robocram" or name.startswith("robocram."))


def _file() -> Path:
    explicit = os.environ.get("ROBOCRAM_CACHE_DIR")
    if explicit:
        folder = Path(explicit)
    else:
        xdg = os.environ.get("XDG_CACHE_HOME")
        folder = (Path(xdg) if xdg else Path.home() / ".cache") / "robocram"
    return folder / _KIND / f"{importlib.util.MAGIC_NUMBER.hex()}.code"


def _read(path: Path) -> dict[str, CodeType]:
    """The table kept at ``path``; empty when missing or not to be trusted."""
    try:
        data = path.read_bytes()
    except OSError:
        return {}
    body = data[_DIGEST:]
    if len(data) <= _DIGEST or hashlib.sha256(body).digest() != data[:_DIGEST]:
        return {}
    try:
        stored = marshal.loads(body)
    except (ValueError, EOFError, TypeError):
        return {}
    return stored if isinstance(stored, dict) else {}  # its values checked when looked up


def _write(path: Path, body: bytes) -> None:
    with contextlib.suppress(OSError):
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, temporary = tempfile.mkstemp(dir=path.parent, suffix=".tmp")
        try:
            with os.fdopen(fd, "wb") as out:
                out.write(hashlib.sha256(body).digest() + body)
            os.replace(temporary, path)
        finally:
            with contextlib.suppress(FileNotFoundError):
                os.unlink(temporary)
