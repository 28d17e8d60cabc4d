"""Motions every robot understands (CRAM's ``cram_common_designators``), as one typed table.

:data:`MOTION_TYPES` holds one :class:`MotionType` per motion ``type``: its properties with
their types, the command terms it grounds to, the process module resource executing them
and what a recording module answers. ``install_common_motions(kb)`` loads the
``motion_grounding/2`` rules generated from it (fact group ``common_motions``);
``install_motion_family(kb, "flying")`` adds the motions of flying robots,
``install_motion_family(kb, "legged")`` those of robots standing on legs they bend.

Motion ``type`` (properties) -> command, resource:

- going (target) -> ``move_base(Pose)``, navigation
- moving-torso (joint_angle) -> ``move_torso(Angle)``, torso
- looking (target / frame / direction / configuration) ->
  ``move_head(pose | frame | direction | joints, X)``, ptu (``joints``: the head's
  ``{joint: value}`` or ``[[joint, value], ...]``, e.g. the neck's parking configuration)
- detecting (object) -> ``detect(ObjectDesig)``; inspecting (object) ->
  ``inspect(ObjectDesig)``, perception (inspecting looks at one object for all it shows)
- opening / closing / gripping (gripper[, effort]) ->
  ``move_gripper_joint(Gripper, open | close | grip, Effort)``, grippers
- moving-gripper-joint (gripper, joint_angle[, effort]) ->
  ``move_gripper_joint(Gripper, Position, Effort)``, grippers
- moving-tcp (left_target / right_target / arm + target[, collision_mode, touching]) ->
  ``move_tcp(Arm, Pose, Mode, Touching)``; with both side targets
  ``move_tcp_both(Left, Right, Mode)``
- moving-arm-joints (left_configuration / right_configuration / arm + configuration
  [, collision_mode, touching]) -> ``move_joints(Arm, Config, Mode, Touching)``; with both
  ``move_joints_both(Left, Right, Mode)``, arms
- flying (target) -> ``fly(Pose)``, flying; distance-sensing (direction) ->
  ``sense_distance(Direction)``, distance_sensor (family ``flying``)
- crouching (depth) -> ``crouch(Depth)``, legs (family ``legged``): the body ``depth``
  [m] below standing, the soles kept; 0 stands up

A ``target`` is a pose, a ``PoseStamped`` or a location designator (one command per
solution). ``Effort`` is the ``effort`` property [N] or ``none``; ``Mode`` the
``collision_mode`` or ``avoid_all``; ``Touching`` the object (or ``object/link``) an
``allow_hand`` motion's hand may touch, or ``none`` (any object, within the same
bound). ``left``/``right`` name the sides of a two-armed robot; its process modules map
them to its arms. Repeated ``gripper`` properties give one command per gripper, in order.
"""

from __future__ import annotations

import functools

from robocram.designators.errors import DesignatorArgumentError
from robocram.designators.motion_table import motion_types
from robocram.designators.motion_type import grounding_rules
from robocram.designators.prolog_access import install_designator_predicates
from robocram.logic import KnowledgeBase

COMMON_MOTIONS_GROUP = "common_motions"
FAMILY_GROUPS = {
    "common": COMMON_MOTIONS_GROUP,
    "flying": "flying_motions",
    "legged": "legged_motions",
}

_HELPERS = """
common_target_pose(Target, Pose) :- loc_desig(Target), !, designator_grounding(Target, Pose).
common_target_pose(Pose, Pose).
common_prop_or_default(D, Key, _, Value) :- desig_prop(D, Key, Value), !.
common_prop_or_default(_, _, Default, Default).
"""


@functools.cache  # the motion table is immutable; every simulated_robot asks again
def common_motions_text(family: str = "common") -> str:
    """Return the Prolog text of the grounding rules of ``family`` (with the helpers)."""
    helpers = _HELPERS if family == "common" else ""
    return helpers + grounding_rules(motion_types(family), f"{family}_motion_grounding")


def install_motion_family(kb: KnowledgeBase, family: str) -> KnowledgeBase:
    """Install the designator predicates and the groundings of ``family`` in ``kb``."""
    if family not in FAMILY_GROUPS:
        raise DesignatorArgumentError(
            f"motion family {family!r} is none of {sorted(FAMILY_GROUPS)}"
        )
    install_designator_predicates(kb)
    if family != "common" and not kb.defines("common_target_pose/2"):
        install_motion_family(kb, "common")
    # entering projection again (every ``simulated_robot`` does) consults the same text:
    # the knowledge base's own consult cache spares the parse, and the same clauses again
    # leave its predicates as they are
    kb.consult(common_motions_text(family), group=FAMILY_GROUPS[family])
    return kb


def install_common_motions(kb: KnowledgeBase) -> KnowledgeBase:
    """Install the designator predicates and the common motion groundings in ``kb``."""
    return install_motion_family(kb, "common")
