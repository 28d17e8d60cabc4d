"""The turtle's process modules: navigation (driving, moving) and the pen.

Commands (grounded by ``turtle.pl``):

- ``drive(Speed, Angle)``: linear speed [m/s] and turn rate [rad/s] for one second.
- ``go_to(Goal)``: go to ``Goal`` = ``(x, y[, z])`` [m], a ``Pose`` or a ``TurtlePose``
  with the go-to controller; the result is the final ``TurtlePose``.
- ``set_pen(down | up, Colour)``: ``Colour`` is a colour name or ``keep``.
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable
from typing import Any

from robocram.execution.process_module import ProcessModule
from robocram.execution.task_context import checkpoint
from robocram.logic import Term
from robocram.turtlesim.controller import GoToGains, go_to
from robocram.turtlesim.errors import TurtleArgumentError
from robocram.turtlesim.world import TurtlePose, TurtleWorld


def goal_xy(goal: object) -> tuple[float, float]:
    """Read ``(x, y)`` [m] from a tuple/list ``(x, y[, z])``, a ``Pose`` or a ``TurtlePose``."""
    if isinstance(goal, TurtlePose):
        return goal.x, goal.y
    position = getattr(goal, "position", goal)
    if isinstance(position, (tuple, list)) and len(position) in (2, 3):
        x, y = position[0], position[1]
        if isinstance(x, (int, float)) and isinstance(y, (int, float)):
            return float(x), float(y)
    raise TurtleArgumentError(
        f"cannot read a turtle goal from {goal!r}; give (x, y), (x, y, 0) or a Pose"
    )


class TurtleNavigationPM(ProcessModule):
    """Owns the turtle's body: executes ``drive`` and ``go_to``."""

    name = "turtle_navigation"

    def __init__(self, world: TurtleWorld, gains: GoToGains | None = None) -> None:
        super().__init__()
        self.world = world
        self.gains = gains or GoToGains()

    def execute(self, command: object) -> Any:
        """Drive or go to a goal, stepping the simulation."""
        if isinstance(command, Term) and command.name == "drive" and command.arity == 2:
            speed, angle = (float(v) for v in command.args)
            return self._drive(speed, angle)
        if isinstance(command, Term) and command.name == "go_to" and command.arity == 1:
            x, y = self.goal(command.args[0])
            return go_to(self.world, x, y, self.gains, check=checkpoint)
        raise self.unsupported(command, ["drive/2", "go_to/1"])

    def goal(self, goal: object) -> tuple[float, float]:
        """Return the point [m] the turtle heads for (a hook for noisy variants)."""
        return goal_xy(goal)

    def _drive(self, speed: float, angle: float) -> TurtlePose:
        pose = self.world.pose
        for _ in range(round(1.0 / self.world.time_step)):
            checkpoint()
            pose = self.world.step(speed, angle)
        return pose


class NoisyTurtleNavigationPM(TurtleNavigationPM):
    """Navigation whose goals are off by Gaussian noise, and which logs what it did.

    Stands for a real robot: the same PERFORM calls, a less exact body.
    """

    name = "noisy_turtle_navigation"

    def __init__(
        self,
        world: TurtleWorld,
        sigma: float = 0.05,
        seed: int | None = None,
        log: Callable[[str], None] | None = None,
    ) -> None:
        super().__init__(world)
        if sigma < 0 or not math.isfinite(sigma):
            raise TurtleArgumentError(f"noise sigma must be a finite value >= 0 [m], got {sigma}")
        self.sigma = sigma
        self._rng = random.Random(seed)
        self._log = log

    def goal(self, goal: object) -> tuple[float, float]:
        """Return the goal plus noise, logging both."""
        x, y = goal_xy(goal)
        noisy = (x + self._rng.gauss(0.0, self.sigma), y + self._rng.gauss(0.0, self.sigma))
        if self._log is not None:
            self._log(f"go_to ({x:.2f}, {y:.2f}) -> heading for ({noisy[0]:.2f}, {noisy[1]:.2f})")
        return noisy


class TurtlePenPM(ProcessModule):
    """Owns the pen: executes ``set_pen``."""

    name = "turtle_pen"

    def __init__(self, world: TurtleWorld) -> None:
        super().__init__()
        self.world = world

    def execute(self, command: object) -> Any:
        """Put the pen down or up, maybe changing its colour."""
        if isinstance(command, Term) and command.name == "set_pen" and command.arity == 2:
            state, colour = command.args
            if state not in ("down", "up"):
                raise TurtleArgumentError(f"pen state must be 'down' or 'up', got {state!r}")
            self.world.set_pen(state == "down", None if colour == "keep" else str(colour))
            return None
        raise self.unsupported(command, ["set_pen/2"])
