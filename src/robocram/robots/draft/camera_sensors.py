"""Camera fields of view from a URDF's Gazebo sensor tags, which links themselves lack.

``<gazebo reference="LINK"><sensor type="camera">`` (SDF: ``<horizontal_fov>`` [rad],
``<image><width>``, ``<height>``) and the older ``<sensor:camera>`` (``<hfov>`` [deg],
``<imageSize>W H</imageSize>``, ``<frameName>``) both name the frame they image.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path

from robocram.robots.safe_xml import XmlNode, decode_xml, parse_xml

ASPECT = 3 / 4  # height over width of an image whose size the tag does not give


@dataclass(frozen=True)
class CameraSensor:
    """One simulated camera: the link it is on, the frame it names, its fields of view."""

    name: str
    reference: str  # the <gazebo reference="..."> link
    frame: str | None  # a <frameName> it publishes in, if given
    horizontal_fov: float  # [rad]
    vertical_fov: float  # [rad]
    size: tuple[int, int] | None  # [pixels] width, height


def _walk(node: XmlNode) -> Iterator[XmlNode]:
    for child in node.children:
        yield child
        yield from _walk(child)


def _first(node: XmlNode, *tags: str) -> str | None:
    found = next((n for n in _walk(node) if n.tag in tags or n.tag.endswith(tags)), None)
    return None if found is None or not found.text.strip() else found.text.strip()


def _sensor(node: XmlNode, reference: str) -> CameraSensor | None:
    """The camera ``node`` describes, or None (another sensor, or no field of view)."""
    try:
        if node.tag == "sensor" and node.attrib.get("type") in ("camera", "depth"):
            hfov = float(_first(node, "horizontal_fov") or "nan")
            width, height = _first(node, "width"), _first(node, "height")
            size = (int(width), int(height)) if width and height else None
        elif node.tag.endswith(":camera") and node.tag.startswith("sensor"):
            hfov = math.radians(float(_first(node, "hfov") or "nan"))
            words = (_first(node, "imageSize") or "").split()
            size = (int(words[0]), int(words[1])) if len(words) == 2 else None
        else:
            return None
    except ValueError:
        return None
    if not math.isfinite(hfov) or not 0 < hfov < math.pi:
        return None
    aspect = size[1] / size[0] if size else ASPECT
    vfov = 2 * math.atan(math.tan(hfov / 2) * aspect)
    frame = _first(node, "frameName", "frame_name")
    return CameraSensor(node.attrib.get("name", ""), reference, frame, hfov, vfov, size)


def camera_sensors(urdf: Path) -> list[CameraSensor]:
    """Every camera sensor of the URDF's Gazebo tags, in file order."""
    root = parse_xml(decode_xml(urdf.read_bytes(), urdf), urdf)
    found = []
    for gazebo in root.findall("gazebo"):
        reference = gazebo.attrib.get("reference", "")
        for node in _walk(gazebo):
            sensor = _sensor(node, reference)
            if sensor is not None:
                found.append(sensor)
    return found


def sensor_for(frame: str, rigid: set[str], sensors: Sequence[CameraSensor]) -> CameraSensor | None:
    """The sensor imaging ``frame``: one naming it, else one on a link in ``rigid`` with it.

    Colour cameras come before depth and infrared ones.
    """

    def rank(sensor: CameraSensor) -> tuple[int, int]:
        named = 0 if sensor.frame == frame else 1 if sensor.reference == frame else 2
        colour = 0 if any(w in sensor.name.lower() for w in ("color", "rgb")) else 1
        return named, colour

    matching = [s for s in sensors if s.frame == frame or s.reference in rigid]
    return min(matching, key=rank, default=None)
