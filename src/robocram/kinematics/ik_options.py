"""What one IK query asks for besides the robot, the arm, the target and the seed.

:func:`~robocram.kinematics.solve_ik` takes these as one frozen value, so a caller that
asks the same kind of query many times (a costmap, a process module) builds it once.
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.kinematics.descent import IKSettings
from robocram.kinematics.planar_base import PlanarBase


@dataclass(frozen=True, kw_only=True)
class IKOptions:
    """The chain, tolerances and counted budget of an IK query.

    Attributes:
        frame: the frame put at the target; None: the arm's tool frame.
        use_torso: also move the description's ``torso_joint``.
        base: also move the base within this travel (planar x, y, yaw before the root
            link); the move comes back in ``IKResult.base_motion``. None keeps it still;
            :func:`~robocram.kinematics.base_in_ik` says whether the description wants it.
        max_restarts: descents after the first one (from the seed); with
            ``max_iterations`` steps per descent, the whole budget. It is counted, not
            timed, so the answer does not depend on the machine's load.
        max_iterations: steps per descent.
        position_tolerance: [m]. orientation_tolerance: [rad].
        random_seed: seeds the random restarts: the same query and seed give
            bit-identical joint values.
    """

    frame: str | None = None
    use_torso: bool = False
    base: PlanarBase | None = None
    max_restarts: int = 100
    max_iterations: int = 60
    position_tolerance: float = 1e-3  # [m]
    orientation_tolerance: float = 1e-2  # [rad]
    random_seed: int = 0

    def settings(self) -> IKSettings:
        """The descent's settings for these tolerances and budget."""
        return IKSettings(
            position_tolerance=self.position_tolerance,
            orientation_tolerance=self.orientation_tolerance,
            max_restarts=self.max_restarts,
            max_iterations=self.max_iterations,
        )


DEFAULT_IK = IKOptions()
