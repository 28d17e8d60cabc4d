"""What a process derives from a robot model once, kept on disk for the next process.

A script's first plan pays for tables every later plan reuses (IK start tables, the shape
of an arm's reach); a new process would build them again. Here they are built once per
machine: an entry is a file under :func:`cache_dir`, named by a hash of what it was built
from: the caller's key (the model's geometry), the source of the modules that build it
(and of this one, which writes it) and the versions of the libraries they use. A file
holds that hash, a table of its arrays (name, type, shape, where) and their bytes, behind
a CRC-32 of all of it; one whose hash or CRC does not match (cut short, damaged, written
by other code) is rebuilt and replaced, never used. It is read in one piece and its
arrays are views of it: an ``.npz`` took three times as long (a zip member, a header to
parse and a CRC per array). A large file (an IK start table, 3.5 MB) is mapped instead of
copied (copy on write: its arrays stay writable and a write changes no file), so its
pages come from the page cache with no fresh memory to fault in and fill: three tables
read in 2.1 ms instead of 5.2. A file is written under a temporary name and renamed into
place, so processes writing one entry at once each leave a whole file, and a mapped file
is never changed under its reader (a rename leaves the mapped one as it was). Set
``ROBOCRAM_CACHE_DIR`` to keep the files elsewhere.
"""

from __future__ import annotations

import contextlib
import functools
import hashlib
import importlib
import json
import math
import mmap
import os
import struct
import tempfile
import zlib
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

Arrays = Mapping[str, NDArray[np.generic]]
SUFFIX = ".arrays"
_MAGIC = b"robocram arrays 1\n"
_LENGTHS = struct.Struct("<QI")  # the table's length [bytes], the CRC-32 of all that follows
_ALIGN = 64  # [bytes] each array starts at a multiple of this in the file
_MAP_FROM = 1 << 20  # [bytes] files this large are mapped, smaller ones read (a map costs
# two system calls more; a copy costs a page fault and a fill per 4 KB)
# what a table that is no table raises when read: the entry is rebuilt
_UNREADABLE = (ValueError, KeyError, TypeError, IndexError)


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
    accept: Callable[[Arrays], bool] | None = None,
) -> dict[str, NDArray[np.generic]]:
    """The arrays ``build()`` returns for ``key``: read from disk, else built and written.

    Args:
        kind: the entry's folder under :func:`cache_dir` (what it holds).
        key: everything the arrays depend on besides code (the model's geometry).
        built_by: names of the imported modules whose source computes the arrays.
        build: computes the arrays (names not starting with ``_``).
        versions: versions of the libraries ``build`` uses.
        accept: whether arrays read whole are usable too (an entry it refuses is rebuilt
            and replaced).
    """
    code = map(_source_digest, (__name__, *built_by))  # this file's format and the builders
    text = "\n".join((kind, key, *versions, np.__version__, *code))
    full = hashlib.sha256(text.encode("utf-8")).hexdigest()
    path = cache_dir() / kind / f"{full[:32]}{SUFFIX}"
    found = _read(path, full)
    if found is not None and (accept is None or accept(found)):
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
        data = _contents(path)
    except (OSError, ValueError):  # ValueError: mmap refuses a file emptied meanwhile
        return None
    if data is None:
        return None
    start = len(_MAGIC) + _LENGTHS.size
    if len(data) < start or data[: len(_MAGIC)].tobytes() != _MAGIC:
        return None
    length, crc = _LENGTHS.unpack_from(data.data, len(_MAGIC))
    if start + length > len(data) or zlib.crc32(data.data[start:]) != crc:
        return None
    arrays = {}
    try:
        table = json.loads(data[start : start + length].tobytes())
        if table["hash"] != full:
            return None
        for name, kind, shape, offset in table["arrays"]:
            array = _view(data, start + length + offset, np.dtype(kind), tuple(shape))
            if array is None:
                return None
            arrays[name] = array
    except _UNREADABLE:
        return None
    return arrays


def _contents(path: Path) -> NDArray[np.uint8] | None:
    """The bytes of the file at ``path``, writable as np.load's arrays were: mapped copy on
    write when large, else read into memory not zeroed first (a bytearray is: ~2x slower);
    None when it was cut short while being read."""
    with path.open("rb") as file:
        size = os.fstat(file.fileno()).st_size
        if size >= _MAP_FROM:
            return np.frombuffer(mmap.mmap(file.fileno(), size, access=mmap.ACCESS_COPY), np.uint8)
        data = np.empty(size, dtype=np.uint8)
        return data if file.readinto(data.data) == size else None


def _view(
    data: NDArray[np.uint8], at: int, kind: np.dtype[np.generic], shape: tuple[int, ...]
) -> NDArray[np.generic] | None:
    """The array of ``kind`` and ``shape`` whose bytes start at ``at`` in ``data``, or None
    for Python objects (never read from a file, as np.load's ``allow_pickle=False``) or an
    array outside ``data``."""
    count = math.prod(shape)
    if kind.hasobject or at < 0 or min(shape, default=0) < 0:
        return None
    if at + count * kind.itemsize > len(data):
        return None
    return np.frombuffer(data, kind, count, at).reshape(shape)


def _write(path: Path, full: str, arrays: Mapping[str, NDArray[np.generic]]) -> None:
    """Write the entry under a temporary name and rename it into place (a cache that
    cannot be written, a read-only home, is only slower: the arrays are returned anyway)."""
    with contextlib.suppress(OSError):
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, temporary = tempfile.mkstemp(dir=path.parent, suffix=".tmp")
        try:
            with os.fdopen(fd, "wb") as out:
                out.write(_encoded(full, arrays))
            os.replace(temporary, path)
        finally:
            with contextlib.suppress(FileNotFoundError):
                os.unlink(temporary)


def _encoded(full: str, arrays: Mapping[str, NDArray[np.generic]]) -> bytes:
    """The file of an entry: magic, lengths, the table (padded) and the arrays' bytes."""
    values = {name: np.asarray(arrays[name], order="C") for name in sorted(arrays)}
    rows, offset = [], 0
    for name, value in values.items():
        rows.append([name, value.dtype.str, list(value.shape), offset])
        offset += -(-value.nbytes // _ALIGN) * _ALIGN
    table = json.dumps({"hash": full, "arrays": rows}).encode("utf-8")
    table += b" " * (-(len(_MAGIC) + _LENGTHS.size + len(table)) % _ALIGN)
    body = bytearray(table)
    for (_, _, _, at), value in zip(rows, values.values(), strict=True):
        body += b"\0" * (len(table) + at - len(body))
        body += value.tobytes()
    return _MAGIC + _LENGTHS.pack(len(table), zlib.crc32(body)) + bytes(body)


@functools.cache
def _source_digest(module: str) -> str:
    """A hash of ``module``'s source file (the code that builds the arrays)."""
    path = getattr(importlib.import_module(module), "__file__", None)
    if path is None:
        return module
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()
