"""The base checker's shortcuts agree with checking every pose exactly: the local grid
round the start and goal, and the poses skipped within an exact check's gap."""

from __future__ import annotations

import numpy as np
import pytest

from robocram.motion.base_collision import BaseCollisionChecker
from robocram.motion.planar_motion import straight_poses
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import RobotHandle, World


def _first_touching(checker: BaseCollisionChecker, poses: np.ndarray) -> int | None:
    """The first pose where the exact check finds a contact, asked at every pose."""
    for k, pose in enumerate(poses):
        if checker.blockers(pose):
            return k
    return None


@pytest.mark.parametrize(
    ("start", "end"),
    [
        ((-0.8, 0.2, 1.5708), (1.6, 0.2, 1.5708)),  # along the counter, into the island
        ((-0.8, 0.2, 1.5708), (-0.8, 1.6, 1.5708)),  # towards the counter
        ((0.3, -0.2, 0.0), (0.3, 1.5, 3.0)),  # turning while driving at the counter
        ((-2.0, 1.5, 1.5708), (-0.4, 1.5, 1.5708)),  # along the counter, 2-3 cm off it
        ((-2.0, 1.5, 1.5708), (-0.4, 1.56, 1.5708)),  # ... closing in until it touches
    ],
)
def test_first_blocked_equals_the_exact_check_at_every_pose(
    kitchen: World, start: tuple[float, float, float], end: tuple[float, float, float]
) -> None:
    with kitchen.snapshots.stored_state():
        poses = straight_poses(np.array(start), np.array(end), 1.0)
        kitchen.set_pose("pr2", _pose(*start))
        with BaseCollisionChecker.build(RobotHandle.of(kitchen, "pr2"), end[:2]) as checker:
            truth = _first_touching(checker, poses)
            found = checker.first_blocked(poses)
        assert found == truth
        assert truth is None or truth > 5  # the case drives some way before it touches
        with BaseCollisionChecker.build(RobotHandle.of(kitchen, "pr2"), end[:2]) as whole:
            whole._widen()  # noqa: SLF001 - the same question on the whole world's grid
            assert whole.first_blocked(poses) == truth


def test_the_grid_widens_for_a_pose_beyond_the_start_and_goal(kitchen: World) -> None:
    with kitchen.snapshots.stored_state():
        kitchen.set_pose("pr2", _pose(-0.8, 0.2, 1.5708))
        with BaseCollisionChecker.build(RobotHandle.of(kitchen, "pr2"), (-0.5, 0.2)) as checker:
            local = checker.grid.masks.shape
            assert checker.covered != checker.bounds
            far = np.array([[1.5, -1.0, 0.0]])
            checker.fast_hits(far, boundary=False)
            assert checker.covered == checker.bounds
            assert checker.grid.masks.size > 2 * local[0] * local[1]


def test_a_gap_skips_exact_checks_near_furniture(kitchen: World) -> None:
    """Driving along the counter a few centimetres off it: fewer exact checks than poses
    the fast check flags, and no touching pose missed (the first test's equality)."""
    with kitchen.snapshots.stored_state():
        start, end = (-2.0, 1.5, 1.5708), (-0.4, 1.5, 1.5708)
        kitchen.set_pose("pr2", _pose(*start))
        poses = straight_poses(np.array(start), np.array(end), 1.0)
        with BaseCollisionChecker.build(RobotHandle.of(kitchen, "pr2"), end[:2]) as checker:
            flagged = int(checker.fast_hits(poses, boundary=False).sum())
            checker.exact_checks = 0
            result = checker.first_blocked(poses)
            exact = checker.exact_checks
            truth = _first_touching(checker, poses)
        assert result == truth
        assert flagged == len(poses) and exact < flagged / 2


def test_a_motion_asked_again_needs_no_exact_check(kitchen: World) -> None:
    """OMPL asks about motions from the same node again: the answers are kept."""
    with kitchen.snapshots.stored_state():
        start, end = (-2.0, 1.5, 1.5708), (-0.4, 1.56, 1.5708)
        kitchen.set_pose("pr2", _pose(*start))
        poses = straight_poses(np.array(start), np.array(end), 1.0)
        with BaseCollisionChecker.build(RobotHandle.of(kitchen, "pr2"), end[:2]) as checker:
            first = checker.first_blocked(poses)
            exact = checker.exact_checks
            assert first is not None and exact > 0
            assert checker.first_blocked(poses) == first
            assert checker.exact_checks == exact


def test_a_poses_kept_fast_answer_is_the_grids_counted_and_dropped_when_it_widens(
    kitchen: World,
) -> None:
    """A pose asked again (a tree node starting another edge) is answered from what the
    grid said, counted as a check all the same; a widened grid is asked anew."""
    with kitchen.snapshots.stored_state():
        kitchen.set_pose("pr2", _pose(-0.8, 0.2, 1.5708))
        with BaseCollisionChecker.build(RobotHandle.of(kitchen, "pr2"), (-0.8, 1.6)) as checker:
            fp = checker.footprint
            poses = straight_poses(
                np.array([-0.8, 0.2, 1.5708]), np.array([-0.8, 1.6, 1.5708]), 1.0
            )
            grid = [bool(h) for h in checker.grid.hits(poses, fp.points, fp.masks, False)]
            assert any(grid) and not all(grid)  # near the counter and away from it
            for _ in range(2):
                before = checker.fast_checks
                assert [checker._full_hit(p) for p in poses] == grid  # noqa: SLF001
                assert checker.fast_checks == before + len(poses)
            checker._widen()  # noqa: SLF001
            assert not checker._full_answers  # noqa: SLF001 - the old grid's answers
            assert [checker._full_hit(p) for p in poses] == grid  # noqa: SLF001


def _pose(x: float, y: float, yaw: float) -> Pose:
    return Pose((x, y, 0.0), quat.from_euler(0.0, 0.0, yaw))


def test_a_footprint_is_kept_per_posture(kitchen: World) -> None:
    with kitchen.snapshots.stored_state():
        kitchen.set_pose("pr2", _pose(-0.8, 0.2, 1.5708))
        with BaseCollisionChecker.build(RobotHandle.of(kitchen, "pr2"), (0.0, 0.0)) as first:
            pass
        kitchen.set_pose("pr2", _pose(0.5, -0.3, 0.4))  # moving the base keeps the posture
        with BaseCollisionChecker.build(RobotHandle.of(kitchen, "pr2"), (0.0, 0.0)) as second:
            pass
        assert second.footprint is first.footprint
        kitchen.set_joint_states("pr2", {"torso_lift_joint": 0.25})
        with BaseCollisionChecker.build(RobotHandle.of(kitchen, "pr2"), (0.0, 0.0)) as raised:
            pass
        assert raised.footprint is not first.footprint
        assert raised._bins is not None and first._bins is not None  # noqa: SLF001
        assert raised._bins.height > first._bins.height  # noqa: SLF001 - the head rose


def test_the_unclipped_lookup_equals_the_clipped_one(kitchen: World) -> None:
    with kitchen.snapshots.stored_state():
        kitchen.set_pose("pr2", _pose(-0.8, 0.2, 1.5708))
        with BaseCollisionChecker.build(RobotHandle.of(kitchen, "pr2"), (1.0, 1.2)) as checker:
            rng = np.random.default_rng(7)
            (x0, y0), (x1, y1) = checker.covered
            poses = np.column_stack(
                [rng.uniform(x0, x1, 500), rng.uniform(y0, y1, 500), rng.uniform(-4, 4, 500)]
            )
            fp = checker.footprint
            fast = checker.grid.hits(poses, fp.points, fp.masks, inside=True)
            clipped = checker.grid.hits(poses, fp.points, fp.masks, inside=False)
        assert np.array_equal(fast, clipped)
        assert 50 < fast.sum() < 450  # both kinds of pose are asked


def test_a_drive_through_open_floor_is_proven_in_blocks(kitchen: World) -> None:
    """Far from the furniture the grown footprint proves most poses free in blocks; the
    answer is the exact check's at every pose."""
    with kitchen.snapshots.stored_state():
        start, end = (-0.8, 0.2, 1.5708), (0.3, -0.2, 0.0)
        kitchen.set_pose("pr2", _pose(*start))
        poses = straight_poses(np.array(start), np.array(end), 1.0)
        with BaseCollisionChecker.build(RobotHandle.of(kitchen, "pr2"), end[:2]) as checker:
            runs = checker._unproven(poses)  # noqa: SLF001 - the blocks left to check
            left = sum(stop - first for first, stop in runs)
            assert left < len(poses) / 2
            assert checker.first_blocked(poses) == _first_touching(checker, poses)


def test_a_motion_standing_still_is_checked_as_it_is(kitchen: World) -> None:
    with kitchen.snapshots.stored_state():
        start = (-0.8, 0.2, 1.5708)
        kitchen.set_pose("pr2", _pose(*start))
        poses = np.array([start] * 40, dtype=float)
        with BaseCollisionChecker.build(RobotHandle.of(kitchen, "pr2"), start[:2]) as checker:
            assert checker.first_blocked(poses) == _first_touching(checker, poses)
