"""What a crouch would give a legged zoo robot in the kitchen: the drawer opened, the bowl.

Run: ``.venv/bin/python benchmarks/crouch_probe.py NAME [--depth 0.15] [--step open | bowl]
[--fetch]``.

The robot (a name of ``robot_zoo.CORPUS``, drafted as there) is put into a crouch ``depth``
[m] deep (``kinematics.crouch``: its root lowered straight down, its soles kept) by setting
its base's z and leg joints: a teleport, not the checked, timed motion a plan would need,
so this says only whether a crouch is worth building for a step. ``open``: crouched from
the start, it opens the bowl's drawer (``open_from_front``). ``bowl``: the kitchen's bowl
transport, crouched only while each container is opened and standing up again after (so
its camera looks from its usual height), and again while it closes them; ``--fetch``:
crouched while it fetches the bowl too (``transport``'s ``fetch``: its looks, stands and
grasp). Why it is kept: TALOS cannot open the bowl's drawer standing (issue 37); a crouch
of 0.15 m frees a hold of its handle (``handle_hold_probe.py --lower``), and this shows
which later steps need it too (0.25 m: it brings the bowl, zoo32).
"""

from __future__ import annotations

import argparse
import contextlib
import importlib
import time
import warnings
from collections.abc import Callable, Iterator
from pathlib import Path

from robot_zoo import CORPUS, _draft

import robocram.plans.bringing as bringing
import robocram.plans.search as search
from robocram.designators import ObjectDesignator, a, an
from robocram.execution.failures import PlanFailure
from robocram.kinematics.crouch import crouched
from robocram.plans import perform
from robocram.plans.basic_actions import navigate, park_arms
from robocram.plans.container_access import OpenedContainer, close_again, open_from_front
from robocram.projection import simulated_robot
from robocram.robots.draft.stance import legs
from robocram.scenes import kitchen_scene
from robocram.tf import Pose, transform_pose
from robocram.world import World

transport = importlib.import_module("robocram.plans.transport")  # the package exports a
# function of the module's name
DRAWER = "drawer_unit_drawer_3"  # the bowl's drawer
OUT = Path("/tmp/crouch_probe_drafts")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("name")
    parser.add_argument("--depth", type=float, default=0.15)
    parser.add_argument("--step", choices=("open", "bowl"), default="open")
    parser.add_argument("--fetch", action="store_true", help="crouched while fetching, too")
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    scene = kitchen_scene(_draft(next(r for r in CORPUS if r.name == args.name), OUT))
    world, robot = scene.world, scene.robot
    start = time.perf_counter()
    try:
        with simulated_robot(world, robot):
            if args.step == "open":
                with _crouched(world, robot, args.depth):
                    opened = open_from_front(DRAWER)
                print(f"opened {DRAWER} from {opened.stand.pose}")
            else:
                search.open_from_front = bringing.open_from_front = _opening_crouched(
                    world, robot, args.depth
                )
                transport.close_again = bringing.close_again = _closing_crouched(
                    world, robot, args.depth
                )
                if args.fetch:
                    transport.fetch = _fetching_crouched(world, robot, args.depth)
                target = a.location(on=("kitchen", "table_top"), for_="bowl-1")
                perform(an.action(type="transporting", object="bowl", target=target))
                x, y, z = world.pose("bowl-1").position
                shut = world.joint_states("kitchen")[f"{DRAWER}_joint"]
                print(f"brought the bowl: at ({x:.3f}, {y:.3f}, {z:.3f}), {DRAWER} at {shut:.3f}")
    except Exception as failure:  # noqa: BLE001 - a probe reports whatever stopped it
        print(f"stopped: {type(failure).__name__}: {str(failure)[:2000]}")
    finally:
        print(f"{time.perf_counter() - start:.1f} s")
        world.close()


def _opening_crouched(
    world: World, robot: str, depth: float
) -> Callable[[str, object], OpenedContainer]:
    """``open_from_front`` crouched ``depth`` [m] while it runs."""

    def opening(name: str, log: object = None) -> OpenedContainer:
        with _crouched(world, robot, depth):
            opened = open_from_front(name, log) if log is not None else open_from_front(name)
        print(
            f"opened {name} crouched {depth:.2f} m from {opened.stand.pose} "
            f"({opened.stand.arm} arm), stood up again",
            flush=True,
        )
        return opened

    return opening


def _closing_crouched(
    world: World, robot: str, depth: float
) -> Callable[[OpenedContainer, object], None]:
    """``close_again`` crouched ``depth`` [m] while it runs (the handle as low as when it
    was opened), crouched once back where it was opened from: crouched at the table, a
    hand that has just let the bowl go goes into the table's top."""

    def closing(opened: OpenedContainer, log: object = None) -> None:
        with contextlib.suppress(PlanFailure):
            park_arms()
            navigate(opened.stand.pose)
        with _crouched(world, robot, depth):
            close_again(opened, log) if log is not None else close_again(opened)
        print(f"closed {opened.container.link} crouched {depth:.2f} m", flush=True)

    return closing


def _fetching_crouched(world: World, robot: str, depth: float) -> Callable[..., object]:
    """``transport``'s ``fetch`` crouched ``depth`` [m] while it runs."""
    plain = transport.fetch

    def fetching(seen: object, *args: object, **kwargs: object) -> object:
        seen = _in_map(seen)  # before the crouch: a pose in the base's frame would sink with it
        with _crouched(world, robot, depth):
            return plain(seen, *args, **kwargs)

    return fetching


def _in_map(seen: object) -> object:
    """``seen`` with its pose in the map: the search leaves it in the base's frame, which
    a teleported crouch lowers, and ``fetch`` reads it only once it runs, crouched (it
    then looked for the bowl 0.15 m under where it lies, the tilt needed the same)."""
    pose = seen.get("pose") if isinstance(seen, ObjectDesignator) else None
    if not isinstance(seen, ObjectDesignator) or pose is None:
        return seen
    return seen.make_effective(seen.data or pose, pose=transform_pose(pose, "map"))


@contextlib.contextmanager
def _crouched(world: World, robot: str, depth: float) -> Iterator[None]:
    """Inside, ``robot`` crouches ``depth`` [m] (teleported); it stands up again after."""
    desc = world.robot(robot).description
    feet = [leg.foot for leg in legs(desc.model, [x.end_effector_link for x in desc.arms.values()])]
    standing = world.joint_states(robot)
    bent = crouched(desc.model, feet, standing, depth)
    _lower(world, robot, depth)
    world.set_joint_states(robot, bent)
    try:
        yield
    finally:
        _lower(world, robot, -depth)
        world.set_joint_states(robot, {joint: standing[joint] for joint in bent})


def _lower(world: World, robot: str, depth: float) -> None:
    at = world.pose(robot)
    x, y, z = at.position
    world.set_pose(robot, Pose((x, y, z - depth), at.orientation))


if __name__ == "__main__":
    main()
