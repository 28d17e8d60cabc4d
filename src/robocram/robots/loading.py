"""Load a robot description: parse its URDF, add its frames and boxes, check every name.

``load_description("pr2")`` returns the built-in PR2 as a :class:`LoadedDescription`
(``model`` set); a user's own ``RobotDescription``, or a file defining one
(``load_description("my_robot.py")``), goes through the same checks.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import replace
from pathlib import Path

from robocram.robots.derived_values import derive_arm, derive_camera, derive_links
from robocram.robots.description import LoadedDescription, RobotDescription
from robocram.robots.description_check import (
    check_names,
    check_values,
    infer_arm,
    semantic_findings,
)
from robocram.robots.description_source import description_from
from robocram.robots.errors import DescriptionCheckError, DescriptionUsageError
from robocram.robots.findings import warn
from robocram.robots.grasp_space import clear_grasp_space
from robocram.robots.hand_envelope import without_hand_envelopes
from robocram.robots.hand_shapes import with_hand_shapes
from robocram.robots.limit_check import check_acceleration_limits, check_rate_limits
from robocram.robots.package_resolver import PackageResolver
from robocram.robots.robot_model import MODELS, RobotModel


def load_description(
    name_or_desc: str | Path | RobotDescription, package_paths: Iterable[str | Path] = ()
) -> LoadedDescription:
    """The checked description with ``model`` set and left-out values derived.

    Arm chains, grippers, hand links, camera heights, the torso link and the pan-tilt links
    come from the URDF where the description leaves them empty
    (:mod:`~robocram.robots.derived_values`); warnings of the checker are logged, issued
    as ``DescriptionWarning`` and kept in ``findings``.

    Raises:
        DescriptionCheckError: a joint, link or frame it names is not in the model, or a
            fault of the semantic checks (a tool frame pointing back, swapped heights, ...).
        GripperDescriptionError: a gripper that cannot open or close.
        JointValueError: a parking, carrying or neck value lies outside its joint limits.
        LimitValueError: an acceleration limit that is not finite and positive.
        UrdfError: the URDF cannot be read.
    """
    if isinstance(name_or_desc, str | Path):  # a built-in's name or a description file
        desc = description_from(str(name_or_desc))
    elif isinstance(name_or_desc, RobotDescription):
        desc = name_or_desc
    else:
        raise DescriptionUsageError(
            "load_description takes a robot name, a description file or a RobotDescription, got a "
            f"{type(name_or_desc).__name__}"
        )
    paths = tuple(dict.fromkeys([*desc.package_paths, *(Path(p) for p in package_paths)]))
    model = desc.model or _shared_model(desc, paths)
    check_names(desc, model)
    check_rate_limits(model)
    check_acceleration_limits(desc.name, desc.acceleration_limits)
    inferred = {key: infer_arm(arm, model) for key, arm in desc.arms.items()}
    model = with_hand_shapes(model, [arm.end_effector_link for arm in inferred.values()])
    arms = {key: derive_arm(desc.name, arm, model) for key, arm in inferred.items()}
    model = clear_grasp_space(model, arms)  # stand-in boxes out of the grippers' grasp
    model = without_hand_envelopes(model, arms)  # no safety box round a hand
    for arm in arms.values():
        check_values(desc.name, model, arm.parking)
        check_values(desc.name, model, arm.carrying)
    check_values(desc.name, model, desc.neck_parking)
    check_values(desc.name, model, desc.stance)
    cameras = tuple(derive_camera(desc, model, camera) for camera in desc.cameras)
    loaded = LoadedDescription.checked(
        desc, model, arms=arms, cameras=cameras, package_paths=paths, **derive_links(desc, model)
    )
    findings = semantic_findings(loaded)
    faults = [f for f in findings if f.severity == "fault"]
    if faults:
        raise DescriptionCheckError(desc.name, model.source, faults)
    if not (isinstance(desc, LoadedDescription) and desc.findings == findings):
        warn(desc.name, findings)  # once per description, not again each time it is passed on
    return replace(loaded, findings=findings)


def _shared_model(desc: RobotDescription, paths: tuple[Path, ...]) -> RobotModel:
    """The parsed URDF with the description's frames, boxes and joint couplings, shared by
    equal loads.

    A mesh package found nowhere (Stretch's camera mesh in ``realsense2_description``)
    gets boxes and a :class:`MissingMeshWarning`, as a missing mesh file does.
    """
    urdf = desc.urdf
    if isinstance(urdf, str) and urdf.startswith("package://"):
        urdf = PackageResolver.default(paths).resolve(urdf)
    file = Path(urdf).expanduser()

    def build() -> RobotModel:
        model = RobotModel.from_file(file, paths, missing_packages_as_boxes=True)
        for frame in desc.extra_frames:
            if frame.name not in model.links:
                model = model.with_frame(frame)
        for box in desc.extra_boxes:
            if box.name not in model.links:
                model = model.with_box(box)
        for coupling in desc.coupled_joints:
            model = model.with_coupling(coupling)
        return model

    return MODELS.model(
        file,
        paths,
        desc.extra_frames,
        desc.extra_boxes,
        build,
        lenient=True,
        couplings=desc.coupled_joints,
    )
