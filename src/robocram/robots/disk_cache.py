"""What a process derives from a robot model once, kept on disk for the next process.

A script's first plan pays for tables every later plan reuses (IK start tables, the shape
of an arm's reach); a new process would build them again. Here they are built once per
machine: an entry is an ``.npz`` file under :func:`cache_dir`, named by a hash of what it
was built from: the caller's key (the model's geometry), the source of the modules that
build it and the versions of the libraries they use. A file holds that hash and a digest
of its arrays; one whose hash or digest does not match (cut short, damaged, written by
other code) is rebuilt and replaced, never used. A file is written under a temporary name
and renamed into place, so processes writing one entry at once each leave a whole file.
Set ``ROBOCRAM_CACHE_DIR`` to keep the files elsewhere.
"""

from __future__ import annotations

import contextlib
import functools
import hashlib
import importlib
import os
import tempfile
import zipfile
import zlib
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

Arrays = Mapping[str, NDArray[np.generic]]
_HASH = "_hash"  # the entry's full hash, stored in its file
_DIGEST = "_digest"  # the digest of its arrays
# what a damaged or foreign file raises when read: it is rebuilt
_UNREADABLE = (
    OSError,
    ValueError,
    KeyError,
    EOFError,
    TypeError,
    AttributeError,
    zipfile.BadZipFile,
)


def cache_dir() -> Path:
    """``$ROBOCRAM_CACHE_DIR``, else ``$XDG_CACHE_HOME/robocram``, else ``~/.cache/robocram``."""
    explicit = os.environ.get("ROBOCRAM_CACHE_DIR")
    if explicit:
        return Path(explicit)
    xdg = os.environ.get("XDG_CACHE_HOME")
    return (Path(xdg) if xdg else Path.home() / ".cache") / "robocram"


def kept_arrays(
    kind: str,
    key: str,
    built_by: Sequence[str],
    build: Callable[[], Arrays],
    versions: Sequence[str] = (),
) -> dict[str, NDArray[np.generic]]:
    """The arrays ``build()`` returns for ``key``: read from disk, else built and written.

    Args:
        kind: the entry's folder under :func:`cache_dir` (what it holds).
        key: everything the arrays depend on besides code (the model's geometry).
        built_by: names of the imported modules whose source computes the arrays.
        build: computes the arrays (names not starting with ``_``).
        versions: versions of the libraries ``build`` uses.
    """
    text = "\n".join((kind, key, *versions, np.__version__, *map(_source_digest, built_by)))
    full = hashlib.sha256(text.encode("utf-8")).hexdigest()
    path = cache_dir() / kind / f"{full[:32]}.npz"
    found = _read(path, full)
    if found is not None:
        return found
    arrays = {name: np.asarray(value) for name, value in build().items()}
    _write(path, full, arrays)
    return arrays


def file_key(path: Path) -> str:
    """A key for what a file holds: a hash of its bytes (a mesh moved or copied keeps its
    entries; one edited in place gets new ones)."""
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _read(path: Path, full: str) -> dict[str, NDArray[np.generic]] | None:
    """The arrays of the entry at ``path``, or None when it is missing or not to be trusted."""
    try:
        with np.load(path, allow_pickle=False) as data:
            arrays = {name: data[name] for name in data.files}
    except _UNREADABLE:  # missing (OSError) too
        return None
    stored_hash, stored_digest = arrays.pop(_HASH, None), arrays.pop(_DIGEST, None)
    if stored_hash is None or str(stored_hash) != full:
        return None
    if stored_digest is None or str(stored_digest) != _digest(arrays):
        return None
    return arrays


def _write(path: Path, full: str, arrays: Mapping[str, NDArray[np.generic]]) -> None:
    """Write the entry under a temporary name and rename it into place (a cache that
    cannot be written, a read-only home, is only slower: the arrays are returned anyway)."""
    with contextlib.suppress(OSError):
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, temporary = tempfile.mkstemp(dir=path.parent, suffix=".tmp")
        try:
            with os.fdopen(fd, "wb") as out:
                stored = {**arrays, _HASH: np.array(full), _DIGEST: np.array(_digest(arrays))}
                np.savez(out, **stored)  # type: ignore[arg-type]
            os.replace(temporary, path)
        finally:
            with contextlib.suppress(FileNotFoundError):
                os.unlink(temporary)


def _digest(arrays: Mapping[str, NDArray[np.generic]]) -> str:
    """A CRC-32 of the arrays' names, types, shapes and bytes: it finds damage, and is read
    with every entry (a start table is megabytes; SHA-256 took 5 times as long)."""
    crc = 0
    for name in sorted(arrays):
        value = np.ascontiguousarray(arrays[name])
        crc = zlib.crc32(f"{name}|{value.dtype.str}|{value.shape}|".encode(), crc)
        crc = zlib.crc32(value.data, crc)
    return f"{crc:08x}"


@functools.cache
def _source_digest(module: str) -> str:
    """A hash of ``module``'s source file (the code that builds the arrays)."""
    path = getattr(importlib.import_module(module), "__file__", None)
    if path is None:
        return module
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()
