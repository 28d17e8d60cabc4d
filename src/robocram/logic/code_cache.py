"""Compiled clause code kept on disk: a new process reads what an earlier one compiled.

Python's ``compile`` of the generated clause sources is most of a first query's cost: a
PR2 transport's first run in a process compiled 29 sources (78 kB) in ~30 ms, each of
them the same in every process. An entry is the marshalled code object under the
user's cache folder (``$ROBOCRAM_CACHE_DIR``, else ``$XDG_CACHE_HOME/robocram``, else
``~/.cache/robocram``, as the robots' disk cache), in ``prolog-code``, named by a hash
of the source and this Python's bytecode magic number. A file starts with a SHA-256 of
the rest, which holds the full key and the code: a damaged, cut or foreign file is
compiled again and replaced, never run. Files are written under a temporary name and
renamed into place, so processes writing one entry at once each leave a whole file; a
cache that cannot be written only makes compiling cost what it did.
"""

from __future__ import annotations

import contextlib
import hashlib
import importlib.util
import marshal
import os
import tempfile
from pathlib import Path
from types import CodeType

__all__ = ["compiled"]

FILENAME = "<robocram clause>"  # what tracebacks show for generated code
_KIND = "prolog-code"
_DIGEST = 32  # bytes of SHA-256 in front of each file


def compiled(source: str) -> CodeType:
    """``compile(source)`` for ``exec``: read from disk, else compiled and written."""
    key = hashlib.sha256(importlib.util.MAGIC_NUMBER + source.encode("utf-8")).hexdigest()
    path = _folder() / f"{key[:32]}.code"
    code = _read(path, key)
    if code is None:
        code = compile(source, FILENAME, "exec")
        _write(path, key, code)
    return code


def _folder() -> Path:
    explicit = os.environ.get("ROBOCRAM_CACHE_DIR")
    if explicit:
        return Path(explicit) / _KIND
    xdg = os.environ.get("XDG_CACHE_HOME")
    return (Path(xdg) if xdg else Path.home() / ".cache") / "robocram" / _KIND


def _read(path: Path, key: str) -> CodeType | None:
    """The code kept at ``path`` for ``key``, or None when missing or not to be trusted."""
    try:
        data = path.read_bytes()
    except OSError:
        return None
    body = data[_DIGEST:]
    if len(data) <= _DIGEST or hashlib.sha256(body).digest() != data[:_DIGEST]:
        return None
    try:
        stored = marshal.loads(body)
    except (ValueError, EOFError, TypeError):
        return None
    if not (isinstance(stored, tuple) and len(stored) == 2 and stored[0] == key):
        return None
    return stored[1] if isinstance(stored[1], CodeType) else None


def _write(path: Path, key: str, code: CodeType) -> None:
    body = marshal.dumps((key, code))
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
