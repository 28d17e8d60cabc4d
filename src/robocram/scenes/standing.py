"""How high a robot stands in a tabletop scene: feet on the floor, or on a pedestal.

A robot whose root link is not at its feet (TALOS's pelvis, Baxter's torso) is lifted
until its lowest part touches the floor. An arm whose shoulder is then too low for a
table under its hand (a Panda, a Z1 or an SO-101 on the floor) is put on a pedestal, as
such arms stand in a lab, so that its table comes out :data:`PEDESTAL_TABLE` high.
"""

from __future__ import annotations

from robocram.robots import LoadedDescription
from robocram.tf import Pose
from robocram.world import ShapeSpec, World

LOWEST_TABLE = 0.3  # [m] a table lower than this puts the robot on a pedestal
PEDESTAL_TABLE = 0.7  # [m] the table's height for a robot on a pedestal
PEDESTAL_GAP = 0.005  # [m] between the pedestal's top and the robot: nothing touches
PEDESTAL_SIDE = 0.15  # [m] the pedestal's top is at least this wide both ways
PEDESTAL_COLOR = (0.35, 0.35, 0.4, 1.0)
BELOW_FLOOR = 0.01  # [m] bounds reaching less than this under the floor are Bullet's margin


def root_fixed_links(desc: LoadedDescription) -> set[str]:
    """The root link and the links fixed to it (the body no joint moves)."""
    fixed = {desc.model.root_link}
    for joint in desc.model.joints.values():  # URDF order lists parents before children
        if joint.type == "fixed" and joint.parent in fixed:
            fixed.add(joint.child)
    return fixed


def stand_on_the_floor(world: World, robot: str) -> None:
    """Lift ``robot`` until its lowest part is on the floor, if something hangs below it."""
    low = world.aabb(robot)[0][2]
    if low < -BELOW_FLOOR:
        _raise_by(world, robot, -low)


def stand_on_a_pedestal(world: World, robot: str, rise: float) -> str:
    """Lift ``robot`` by ``rise`` [m] onto a box as wide as its body (the links fixed to
    its root, at least :data:`PEDESTAL_SIDE`), its top just below the robot; its name."""
    _raise_by(world, robot, rise)
    desc = world.robot(robot).description
    links = sorted(root_fixed_links(desc) & set(world.link_names(robot)))
    boxes = [
        box
        for box in (world.contacts.link_aabb(robot, link) for link in links)
        if box[0][0] <= box[1][0]
    ]
    low = [min(b[0][k] for b in boxes or [world.aabb(robot)]) for k in range(2)]
    high = [max(b[1][k] for b in boxes or [world.aabb(robot)]) for k in range(2)]
    top = world.aabb(robot)[0][2] - PEDESTAL_GAP
    size = (max(high[0] - low[0], PEDESTAL_SIDE), max(high[1] - low[1], PEDESTAL_SIDE), top)
    centre = ((low[0] + high[0]) / 2, (low[1] + high[1]) / 2, top / 2)
    spec = ShapeSpec("box", size, 0.0, PEDESTAL_COLOR)
    return world.add_object("pedestal", "pedestal", spec, Pose(centre)).name


def _raise_by(world: World, robot: str, rise: float) -> None:
    pose = world.pose(robot)
    x, y, z = pose.position
    world.set_pose(robot, Pose((x, y, z + rise), pose.orientation))
