"""Files the logic layer keeps on disk between processes, sealed by a hash of their body.

The compiled clause code (:mod:`~robocram.logic.code_cache`) and the read texts
(:mod:`~robocram.logic.kept_reads`) live under the user's cache folder
(``$ROBOCRAM_CACHE_DIR``, else ``$XDG_CACHE_HOME/robocram``, else ``~/.cache/robocram``,
as the robots' disk cache). A file starts with a SHA-256 of the rest: a damaged or cut
file reads as missing, never as data. Files are written under a temporary name and
renamed into place, so processes writing one entry at once each leave a whole file; a
folder that cannot be written only leaves the entry unkept.
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import tempfile
from pathlib import Path

__all__ = ["cache_folder", "read_sealed", "write_sealed"]

_DIGEST = 32  # bytes of SHA-256 in front of each file


def cache_folder(kind: str) -> Path:
    """The folder of the cache entries of ``kind`` (e.g. ``prolog-code``)."""
    explicit = os.environ.get("ROBOCRAM_CACHE_DIR")
    if explicit:
        return Path(explicit) / kind
    xdg = os.environ.get("XDG_CACHE_HOME")
    return (Path(xdg) if xdg else Path.home() / ".cache") / "robocram" / kind


def read_sealed(path: Path) -> bytes | None:
    """The body kept at ``path``, or None when missing, cut or damaged."""
    try:
        data = path.read_bytes()
    except OSError:
        return None
    body = data[_DIGEST:]
    if len(data) <= _DIGEST or hashlib.sha256(body).digest() != data[:_DIGEST]:
        return None
    return body


def write_sealed(path: Path, body: bytes) -> None:
    """Keep ``body`` at ``path``, sealed, whole or not at all."""
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
