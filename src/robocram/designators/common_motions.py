"""Motions every robot understands (CRAM's ``cram_common_designators``).

``install_common_motions(kb)`` loads ``common_motions.pl`` as fact group
``common_motions``. Process modules receive these command terms (``command.name``,
``command.args``); a target given as a location designator yields one command per
solution of the location, a raw pose yields one command.

Motion ``type`` (properties) -> command:

- going (target: location or pose) -> ``move_base(Pose)``
- moving-torso (joint_angle) -> ``move_torso(Angle)``
- looking (target / frame / direction) -> ``move_head(pose, P)``, ``move_head(frame, F)``
  or ``move_head(direction, D)``
- detecting (object) -> ``detect(ObjectDesig)``; inspecting (object) -> ``inspect(ObjectDesig)``
- opening / closing / gripping (gripper[, effort]) ->
  ``move_gripper_joint(Gripper, open | close | grip, Effort)``
- moving-gripper-joint (gripper, joint_angle[, effort]) ->
  ``move_gripper_joint(Gripper, Position, Effort)``
- moving-tcp (left_target / right_target / arm + target[, collision_mode]) ->
  ``move_tcp(Arm, Pose, Mode)``; with both arm targets ``move_tcp_both(LeftPose, RightPose, Mode)``
- moving-arm-joints (left_configuration / right_configuration / arm + configuration) ->
  ``move_joints(Arm, Config)``; with both ``move_joints_both(LeftConfig, RightConfig)``

``Effort`` is the ``effort`` property [N] or the atom ``none``; ``Mode`` is the
``collision_mode`` property or ``avoid_all``. Repeated ``gripper`` properties give one
command per gripper, in order.
"""

from __future__ import annotations

from importlib import resources

from robocram.designators.prolog_access import install_designator_predicates
from robocram.logic import KnowledgeBase

COMMON_MOTIONS_GROUP = "common_motions"


def common_motions_text() -> str:
    """Return the Prolog text of the common motion grounding rules."""
    return resources.files("robocram.designators").joinpath("common_motions.pl").read_text()


def install_common_motions(kb: KnowledgeBase) -> KnowledgeBase:
    """Install the designator predicates and the common motion groundings in ``kb``."""
    install_designator_predicates(kb)
    kb.consult(common_motions_text(), group=COMMON_MOTIONS_GROUP)
    return kb
