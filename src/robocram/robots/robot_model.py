"""A parsed robot model: the URDF's links and joints as a checked tree of frozen values.

Models are treated as immutable: ``with_frame`` and ``with_box`` return new models, so
frames and collision boxes are added in code and the URDF text is never edited.
"""

from __future__ import annotations

import dataclasses
import warnings
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TypeVar, cast

from robocram.robots.errors import (
    DanglingMimicWarning,
    DescriptionError,
    MissingMeshWarning,
    UrdfError,
    closest_names,
)
from robocram.robots.kept_urdf import kept_urdf_parts
from robocram.robots.model_additions import BoxSpec, FrameSpec, JointCoupling
from robocram.robots.model_memo import ModelMemo
from robocram.robots.package_resolver import PackageResolver
from robocram.robots.safe_xml import decode_xml, parse_xml
from robocram.robots.urdf_elements import Collision, Geometry, Inertial, Joint, Link, Mimic
from robocram.robots.urdf_reader import UrdfParts, read_urdf
from robocram.robots.urdf_writer import write_urdf

# A frame added in code weighs 1 g: PyBullet would otherwise give it 1 kg and unit inertia.
_FRAME_INERTIA = Inertial(0.001, (1e-9, 0.0, 0.0, 1e-9, 0.0, 1e-9))

T = TypeVar("T")
MIMIC_BOUND = 1e3  # largest |multiplier| [-] and |offset| [rad | m] of a mimic joint


def kinematic_loop(links: Iterable[str], parent_joint: dict[str, Joint]) -> list[Joint]:
    """The joints of one loop of parent links (each link's parent first), or ``[]``.

    Following parents from any link either ends at a root or comes back to a link seen on
    the way: that link's loop is the kinematic cycle.
    """
    done: set[str] = set()  # links known to hang below a root
    for start in links:
        path: list[str] = []
        link: str | None = start
        while link is not None and link not in done:
            if link in path:
                cycle = path[path.index(link) :]
                return [parent_joint[name] for name in reversed(cycle)]
            path.append(link)
            joint = parent_joint.get(link)
            link = None if joint is None else joint.parent
        done.update(path)
    return []


def mimic_loop(joints: Mapping[str, Joint]) -> list[str]:
    """The joints of one loop of mimic masters (each followed by the joint it mimics), or
    ``[]``; masters that are not joints end a chain (reported elsewhere)."""
    done: set[str] = set()
    for start in joints:
        path: list[str] = []
        name: str | None = start
        while name is not None and name not in done:
            if name in path:
                return path[path.index(name) :]
            path.append(name)
            joint = joints.get(name)
            name = None if joint is None or joint.mimic is None else joint.mimic.joint
        done.update(path)
    return []


@dataclass(frozen=True, eq=False)
class RobotModel:
    """Links and joints of one robot, forming a tree below ``root_link``.

    ``source`` names where the model came from (a file name), for messages.
    """

    name: str
    links: dict[str, Link]
    joints: dict[str, Joint]
    source: str = "<string>"
    _parent_joint: dict[str, Joint] = field(init=False, repr=False)
    _derived: dict[Callable[[RobotModel], object], object] = field(
        init=False, repr=False, default_factory=dict
    )

    def __post_init__(self) -> None:
        parent_joint: dict[str, Joint] = {}
        for joint in self.joints.values():
            for link in (joint.parent, joint.child):
                if link not in self.links:
                    raise self._unknown("link", link, self.links, f"joint {joint.name!r}")
            if joint.child in parent_joint:
                other = parent_joint[joint.child].name
                raise UrdfError(
                    self.source,
                    f"link {joint.child!r} is the child of joints {other!r} and {joint.name!r}; "
                    "a URDF must be a tree",
                )
            parent_joint[joint.child] = joint
        object.__setattr__(self, "_parent_joint", parent_joint)
        loop = kinematic_loop(self.links, parent_joint)
        if loop:
            names = ", ".join(repr(j.name) for j in loop)
            path = " -> ".join([loop[0].parent, *(j.child for j in loop)])
            raise UrdfError(
                self.source,
                f"joints {names} close a kinematic loop ({path}); a URDF must be a tree: "
                "remove one of them or give it another parent",
            )
        roots = [name for name in self.links if name not in parent_joint]
        if len(roots) != 1:
            raise UrdfError(self.source, f"a URDF needs exactly one root link, found {roots}")
        for joint in self.joints.values():
            if joint.mimic is not None and joint.mimic.joint not in self.joints:
                raise self._unknown(
                    "joint", joint.mimic.joint, self.joints, f"mimic of {joint.name!r}"
                )
        self._check_mimics()

    def _check_mimics(self) -> None:
        """Refuse a mimic whose factors are past :data:`MIMIC_BOUND`, and mimic loops
        (joints following each other have no value)."""
        for joint in self.joints.values():
            mimic = joint.mimic
            if mimic is None:
                continue
            for what, value in (("multiplier", mimic.multiplier), ("offset", mimic.offset)):
                if abs(value) > MIMIC_BOUND:
                    raise UrdfError(
                        self.source,
                        f"joint {joint.name!r} mimics {mimic.joint!r} with {what} {value:g}, "
                        f"beyond the bound of {MIMIC_BOUND:g} (MIMIC_BOUND); give the real "
                        "gear ratio",
                    )
        loop = mimic_loop(self.joints)
        if loop:
            path = " -> ".join(repr(name) for name in [*loop, loop[0]])
            raise UrdfError(
                self.source,
                f"mimic joints follow each other in a loop ({path}); one of them must be "
                "a master: remove its <mimic>",
            )

    def _unknown(self, kind: str, name: str, pool: Iterable[str], where: str) -> UrdfError:
        close = closest_names(name, pool)
        hint = f"; did you mean {' or '.join(repr(c) for c in close)}?" if close else ""
        return UrdfError(self.source, f"{kind} {name!r} (named by {where}) is not defined{hint}")

    @property
    def root_link(self) -> str:
        """The one link that is no joint's child."""
        return next(name for name in self.links if name not in self._parent_joint)

    def parent_joint(self, link: str) -> Joint | None:
        """The joint whose child is ``link``; ``None`` for the root."""
        self.link(link)
        return self._parent_joint.get(link)

    def link(self, name: str) -> Link:
        """The link ``name``; a :class:`DescriptionError` suggests close names if it is absent."""
        if name not in self.links:
            raise DescriptionError(self._missing_message("link", name, self.links))
        return self.links[name]

    def joint(self, name: str) -> Joint:
        """The joint ``name``; a :class:`DescriptionError` suggests close names if it is absent."""
        if name not in self.joints:
            raise DescriptionError(self._missing_message("joint", name, self.joints))
        return self.joints[name]

    def _missing_message(self, kind: str, name: str, pool: Iterable[str]) -> str:
        close = closest_names(name, pool)
        hint = f"; did you mean {' or '.join(repr(c) for c in close)}?" if close else ""
        return f"{kind} {name!r} not in {self.source}{hint}"

    def chain(self, base_link: str, tip_link: str) -> list[Joint]:
        """Joints (fixed ones too) from ``base_link`` down to ``tip_link``, base first."""
        self.link(base_link)
        joints: list[Joint] = []
        link = tip_link
        while link != base_link:
            joint = self.parent_joint(link)
            if joint is None:
                raise DescriptionError(
                    f"link {tip_link!r} does not hang below {base_link!r} in {self.source}; "
                    "give a base_link that is an ancestor of the tip"
                )
            joints.append(joint)
            link = joint.parent
        return joints[::-1]

    def base_links(self) -> list[str]:
        """The root link and every link fixed to it: the part that is the mobile base (what
        a navigation stack's footprint stands for), root first."""
        found = [self.root_link]
        for link in found:
            found.extend(
                j.child for j in self.joints.values() if j.parent == link and j.type == "fixed"
            )
        return found

    def movable_joints(self) -> list[Joint]:
        """Joints with one degree of freedom (revolute, continuous, prismatic), in file order."""
        return [j for j in self.joints.values() if j.movable]

    def with_frame(self, spec: FrameSpec) -> RobotModel:
        """A copy with frame ``spec.name`` fixed to ``spec.parent`` at ``spec.pose``."""
        self._check_new_link(spec.name, spec.parent)
        joint = Joint(f"{spec.name}_joint", "fixed", spec.parent, spec.name, spec.pose)
        return self._extended(Link(spec.name, inertial=_FRAME_INERTIA), joint)

    def with_box(self, spec: BoxSpec) -> RobotModel:
        """A copy with a collision box on a new link ``spec.name`` fixed to ``spec.parent``."""
        self._check_new_link(spec.name, spec.parent)
        if any(s <= 0 for s in spec.size):
            raise DescriptionError(f"box {spec.name!r} needs positive sizes [m], got {spec.size}")
        box = Collision(Geometry("box", size=spec.size), name=spec.name)
        joint = Joint(f"{spec.name}_joint", "fixed", spec.parent, spec.name, spec.pose)
        return self._extended(Link(spec.name, collisions=(box,), inertial=_FRAME_INERTIA), joint)

    def with_coupling(self, spec: JointCoupling) -> RobotModel:
        """A copy whose ``spec.followers`` mimic ``spec.actuator`` (one actuator moves them).

        Raises:
            DescriptionError: a joint is unknown (with suggestions), not movable, already a
                ``<mimic>`` follower, or the actuator follows itself.
        """
        actuator = self.joint(spec.actuator)
        joints = dict(self.joints)
        for name in spec.followers:
            joint = self.joint(name)
            if name == actuator.name or not joint.movable or joint.mimic is not None:
                raise DescriptionError(
                    f"cannot couple {name!r} to {actuator.name!r} in {self.source}: a follower "
                    "must be another movable joint that mimics nothing yet"
                )
            mimic = Mimic(actuator.name, spec.multiplier, spec.offset)
            joints[name] = dataclasses.replace(joint, mimic=mimic)
        return RobotModel(self.name, dict(self.links), joints, self.source)

    def _check_new_link(self, name: str, parent: str) -> None:
        self.link(parent)
        if name in self.links:
            raise DescriptionError(
                f"cannot add {name!r} to {self.source}: a link of that name exists"
            )
        if f"{name}_joint" in self.joints:
            raise DescriptionError(
                f"cannot add {name!r}: joint '{name}_joint' exists in {self.source}"
            )

    def _extended(self, link: Link, joint: Joint) -> RobotModel:
        links = {**self.links, link.name: link}
        joints = {**self.joints, joint.name: joint}
        return RobotModel(self.name, links, joints, self.source)

    def derived(self, make: Callable[[RobotModel], T]) -> T:
        """``make(self)``, built on first use and kept with this model, one per ``make``.

        Upper layers keep what they build from a model here (kinematics keeps its pinocchio
        model and its IK caches), so it lives exactly as long as the model and no module
        holds a cache. Models never change, so a value derived once stays right.
        """
        found = self._derived.get(make)
        if found is None:  # two threads may both build; both get the one stored first
            found = self._derived.setdefault(make, make(self))
        return cast(T, found)

    def __getstate__(self) -> dict[str, object]:
        """Pickled without derived values: they are rebuilt where the copy is used."""
        return {**self.__dict__, "_derived": {}}

    def to_urdf(self, path: Path | None = None) -> str:
        """URDF XML of this model (absolute mesh paths); also written to ``path`` if given.

        Written once per model (a model is never changed: ``with_frame`` makes a new one),
        since caches key on it and a PR2's text takes milliseconds to write.
        """
        text = self.__dict__.get("_urdf_text")
        if text is None:
            text = write_urdf(self.name, self.links.values(), self.joints.values())
            object.__setattr__(self, "_urdf_text", text)
        if path is not None:
            Path(path).write_text(text, encoding="utf-8")
        return text

    @classmethod
    def from_file(
        cls,
        path: str | Path,
        package_paths: Iterable[str | Path] = (),
        missing_packages_as_boxes: bool = False,
    ) -> RobotModel:
        """Parse a URDF file; ``package_paths`` are searched first for ``package://`` URIs.

        ``missing_packages_as_boxes``: a package found nowhere gets boxes and a warning,
        as a missing mesh file does, instead of :class:`PackageNotFoundError`.

        Equal files share one model while it is held (:mod:`~robocram.robots.model_memo`).
        """
        file = Path(path).expanduser()
        paths = tuple(Path(p) for p in package_paths)

        def parse() -> RobotModel:
            try:
                data = file.read_bytes()
            except OSError as err:
                raise UrdfError(file, f"cannot read the URDF: {err.strerror}") from err
            text = decode_xml(data, file)
            resolver = PackageResolver.default(paths)
            source = str(file)
            base = file.resolve().parent
            parts = kept_urdf_parts(text, source, base, resolver, missing_packages_as_boxes)
            return cls._from_parts(parts, source, stacklevel=2)  # warned from here

        return MODELS.model(file, paths, (), (), parse, missing_packages_as_boxes)

    @classmethod
    def from_string(
        cls,
        xml: str,
        base_dir: str | Path | None = None,
        package_paths: Iterable[str | Path] = (),
        source: str = "<string>",
        missing_packages_as_boxes: bool = False,
    ) -> RobotModel:
        """Parse URDF text; relative mesh paths are taken from ``base_dir``."""
        resolver = PackageResolver.default(package_paths)
        base = None if base_dir is None else Path(base_dir)
        parts = read_urdf(parse_xml(xml, source), source, base, resolver, missing_packages_as_boxes)
        return cls._from_parts(parts, source)

    @classmethod
    def _from_parts(cls, parts: UrdfParts, source: str, stacklevel: int = 3) -> RobotModel:
        """The model of a URDF's parts, warning of what stands in for what is missing (as
        from ``stacklevel`` frames up: :meth:`from_string`'s caller by default)."""
        if parts.missing_packages:
            names = ", ".join(repr(p) for p in sorted(set(parts.missing_packages)))
            warnings.warn(
                f"{source}: package(s) {names} not found, boxes stand in for their meshes; "
                "pass `--package-path DIR` (package_paths=[DIR]) with the folder holding them",
                MissingMeshWarning,
                stacklevel=stacklevel,
            )
        if parts.dangling_mimics:
            listed = ", ".join(
                f"{j!r} (mimics {t!r}{_guess(t, parts.joints)})" for j, t in parts.dangling_mimics
            )
            warnings.warn(
                f"{source}: a <mimic> names a joint the URDF lacks, read as moving on its own: "
                f"{listed}; name the joint it follows to couple them",
                DanglingMimicWarning,
                stacklevel=stacklevel,
            )
        if parts.missing_meshes:
            listed = ", ".join(sorted(set(parts.missing_meshes)))
            warnings.warn(
                f"{source}: {len(set(parts.missing_meshes))} mesh file(s) missing, boxes stand in: "
                f"{listed}",
                MissingMeshWarning,
                stacklevel=stacklevel,
            )
        return cls(
            parts.name,
            parts.links,
            parts.joints,
            Path(source).name if source != "<string>" else source,
        )


def _guess(name: str, pool: Iterable[str]) -> str:
    close = closest_names(name, pool)
    return f"; did you mean {' or '.join(repr(c) for c in close)}?" if close else ""


MODELS: ModelMemo[RobotModel] = ModelMemo()  # weak: equal files share a model while it is held
