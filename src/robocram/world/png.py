"""PNG encoding with the standard library only (zlib + struct), so no imaging dependency."""

from __future__ import annotations

import struct
import zlib
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from robocram.world.errors import WorldValueError


def _chunk(kind: bytes, data: bytes) -> bytes:
    crc = zlib.crc32(kind + data) & 0xFFFFFFFF
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", crc)


def encode_png(rgb: NDArray[np.uint8]) -> bytes:
    """PNG bytes of an ``H x W x 3`` (RGB) or ``H x W x 4`` (RGBA) uint8 image."""
    image = np.asarray(rgb)
    if image.ndim != 3 or image.shape[2] not in (3, 4) or image.dtype != np.uint8:
        raise WorldValueError(f"need an H x W x 3|4 uint8 image, got {image.shape} {image.dtype}")
    height, width, channels = image.shape
    colour_type = 2 if channels == 3 else 6
    header = struct.pack(">IIBBBBB", width, height, 8, colour_type, 0, 0, 0)
    rows = np.concatenate([np.zeros((height, 1), np.uint8), image.reshape(height, -1)], axis=1)
    body = zlib.compress(rows.tobytes(), 6)
    return (
        b"\x89PNG\r\n\x1a\n"
        + _chunk(b"IHDR", header)
        + _chunk(b"IDAT", body)
        + _chunk(b"IEND", b"")
    )


def write_png(path: str | Path, rgb: NDArray[np.uint8]) -> Path:
    """Write an RGB(A) image to ``path`` as PNG; return the path."""
    out = Path(path)
    out.write_bytes(encode_png(rgb))
    return out
