"""Going to a container and opening it, and later closing it again from where it was opened.

CRAM opens a drawer when the object is known to be inside it and closes it once the object
is delivered. The stand comes from :func:`handle_stands` (in front of the handle, the
arm's shoulder in line with it); each stand is tried in turn, bounded, and a stand where
the robot would collide or the arm cannot hold the handle all the way gives the next one.
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.execution.failures import PlanFailure
from robocram.knowledge.scene_predicates import CONTAINER, CONTAINER_KIND
from robocram.logic import current_kb
from robocram.plans.attempt_log import AttemptLog
from robocram.plans.basic_actions import navigate, park_arms
from robocram.plans.containers import Container, close_container, container, open_container
from robocram.plans.environment_links import environment_link_pose
from robocram.plans.errors import PlanSetupError
from robocram.plans.robot_facts import current_robot, robot_arms
from robocram.plans.stands import HandleStand, handle_stands
from robocram.tf import Pose

OPEN_RETRIES = 6  # stands tried before opening gives up


@dataclass(frozen=True)
class OpenedContainer:
    """A container a plan opened, and the stand and arm that opened it."""

    container: Container
    stand: HandleStand


def is_container(environment: str, link: str) -> bool:
    """Whether the KB names ``link`` of ``environment`` a container."""
    return CONTAINER.holds(current_kb(), environment=environment, link=link)


def _handle_pose(part: Container) -> Pose:
    return environment_link_pose(part.environment, part.handle, "a handle")


def _is_drawer(part: Container) -> bool:
    return CONTAINER_KIND.holds(
        current_kb(), environment=part.environment, link=part.link, kind="drawer"
    )


def open_from_front(
    name: str, log: AttemptLog | None = None, retries: int = OPEN_RETRIES
) -> OpenedContainer:
    """Go in front of container ``name`` (link or handle) and open it fully.

    Raises:
        PlanFailure: the last failure, when no stand within ``retries`` worked.
    """
    log = log if log is not None else AttemptLog()
    part = container(name)
    robot = current_robot()
    stands = handle_stands(
        robot, robot_arms(robot), _handle_pose(part), part.opened, _is_drawer(part)
    )
    last: PlanFailure | None = None
    for _, stand in zip(range(retries), stands, strict=False):
        try:
            park_arms()
            navigate(stand.pose)
            open_container(part.link, arm=stand.arm)
            park_arms()
        except PlanFailure as failure:
            log.record("open", stand.pose, failure)
            last = failure
            continue
        log.record("open", stand.pose, None)
        log.opened.append(part.link)
        return OpenedContainer(part, stand)
    if last is None:
        raise PlanSetupError(f"no stand to open {part.link!r} from (retries={retries})")
    raise last


def close_again(opened: OpenedContainer, log: AttemptLog | None = None) -> None:
    """Go back to where ``opened`` was opened from and close it with the same arm."""
    log = log if log is not None else AttemptLog()
    try:
        park_arms()
        navigate(opened.stand.pose)
        close_container(opened.container.link, arm=opened.stand.arm)
        park_arms()
    except PlanFailure as failure:
        log.record("close", opened.stand.pose, failure)
        raise
    log.record("close", opened.stand.pose, None)
