"""A URDF file's links and joints read once per machine, kept on disk for the next process.

Reading a URDF is most of a first scene's Python time: the PR2's 133 kB took ~15-29 ms to
parse into links and joints, the kitchen's ~20 ms, the same in every process; unpickling
the parts takes ~1-2 ms. An entry is keyed by the text, where it came from (relative
meshes are found from its folder), the package search folders and the reading code
(:func:`~robocram.robots.kept_object.kept_object`). What else the parts depend on is the
files each mesh reference names: every reference is resolved again and its file looked
for (~2 ms for the PR2's 76); an entry whose references now resolve elsewhere, or whose
mesh files came or went, is read anew and replaced, as is a damaged one.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

from robocram.robots.errors import DescriptionError, PackageNotFoundError
from robocram.robots.kept_object import kept_object
from robocram.robots.package_resolver import PackageResolver
from robocram.robots.safe_xml import parse_xml
from robocram.robots.urdf_reader import UrdfParts, read_urdf

__all__ = ["kept_urdf_parts"]

_BUILT_BY = (
    "robocram.robots.kept_urdf",
    "robocram.robots.urdf_reader",
    "robocram.robots.safe_xml",
    "robocram.robots.urdf_elements",
    "robocram.robots.stand_in_palm",
    "robocram.robots.stand_in_size",
    "robocram.robots.package_resolver",
    "robocram.tf.pose",
    "robocram.tf.quaternion",
)


def kept_urdf_parts(
    xml: str,
    source: str,
    base_dir: Path | None,
    resolver: PackageResolver,
    missing_packages_as_boxes: bool = False,
) -> UrdfParts:
    """``read_urdf(parse_xml(xml, source), ...)``: from disk while its mesh files are as
    they were, else read and kept. Errors are the reading's: nothing that failed is kept."""
    text = hashlib.sha256(xml.encode("utf-8")).hexdigest()
    key = (
        f"urdf {text} from {source!r} in {base_dir} lenient {missing_packages_as_boxes} "
        f"roots {resolver.search_roots} installed {resolver.installed}"
    )

    def read() -> UrdfParts:
        root = parse_xml(xml, source)
        return read_urdf(root, source, base_dir, resolver, missing_packages_as_boxes)

    def still_true(parts: UrdfParts) -> bool:
        return _meshes_as_they_were(parts, base_dir, resolver)

    return kept_object("urdf-parts", key, _BUILT_BY, read, UrdfParts, accept=still_true)


def _meshes_as_they_were(
    parts: UrdfParts, base_dir: Path | None, resolver: PackageResolver
) -> bool:
    """Whether each mesh reference resolves where it did, its file there or not as it was."""
    for uri, found, is_file in parts.mesh_checks:
        try:
            path: Path | None = resolver.resolve(uri, base_dir)
        except PackageNotFoundError:
            path = None
        except DescriptionError:  # refused now: reading it again says why
            return False
        if (None if path is None else str(path)) != found:
            return False
        if path is not None and path.is_file() != is_file:
            return False
    return True
