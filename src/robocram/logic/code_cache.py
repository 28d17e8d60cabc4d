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

import hashlib
import importlib.util
import marshal
from pathlib import Path
from types import CodeType

from robocram.logic.sealed_files import cache_folder, read_sealed, write_sealed

__all__ = ["compiled"]

FILENAME = "<robocram clause>"  # what tracebacks show for generated code
_KIND = "prolog-code"


def compiled(source: str) -> CodeType:
    """``compile(source)`` for ``exec``: read from disk, else compiled and written."""
    key = hashlib.sha256(importlib.util.MAGIC_NUMBER + source.encode("utf-8")).hexdigest()
    path = cache_folder(_KIND) / f"{key[:32]}.code"
    code = _read(path, key)
    if code is None:
        code = compile(source, FILENAME, "exec")
        _write(path, key, code)
    return code


def _read(path: Path, key: str) -> CodeType | None:
    """The code kept at ``path`` for ``key``, or None when missing or not to be trusted."""
    body = read_sealed(path)
    if body is None:
        return None
    try:
        stored = marshal.loads(body)
    except (ValueError, EOFError, TypeError):
        return None
    if not (isinstance(stored, tuple) and len(stored) == 2 and stored[0] == key):
        return None
    return stored[1] if isinstance(stored[1], CodeType) else None


def _write(path: Path, key: str, code: CodeType) -> None:
    write_sealed(path, marshal.dumps((key, code)))
