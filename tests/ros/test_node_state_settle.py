"""When our node calls the robot's state the state after a goal, messages fed in by hand.

The rules (``NodeState.op_wait_for_state``): state arriving after the goal's result; or
the robot's own stamps saying the joints, every moving frame and every environment were
reported at or just after the result (ROS 1 results are stamped); or the joints showing a
finished trajectory's end with every frame and environment stamped no earlier. A frame
whose transform lags (tf and joint states are separate topics, in no order) keeps the
wait going; a robot clock apart from the result's leaves the wait to the arrivals.
"""

from __future__ import annotations

import threading
from multiprocessing import Pipe

from robocram.ros.node_config import NodeConfig
from robocram.ros.node_state import NodeState

BASE = "base_footprint"
END = {"torso_lift_joint": 0.2, "r_shoulder_pan_joint": -0.5}
WAIT = 0.05  # [s] a wait that must not end times out this soon
SETTLES = 10.0  # [s] a wait that must end is given this long (it ends when fed)


class FedState(NodeState):
    """The node's state, fed by the test instead of ROS subscriptions."""

    def op_frames(self) -> list[str]:
        return [BASE, "mug-1"]

    def _lookups(
        self, target: str, sources: list[str]
    ) -> dict[str, tuple[tuple[float, ...], tuple[float, ...]]]:
        return {s: ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0)) for s in sources}

    def publish(self, stamp: float, joints: dict[str, float], frames: bool = True) -> None:
        """One cycle of a robot's state publisher, all stamped ``stamp`` [s]."""
        if frames:
            with self._state:
                self._frames_stamped([(BASE, stamp), ("mug-1", stamp)])
                self._base_arrived()
        self._environment_arrived("/kitchen/joint_states", ["drawer"], [0.1], stamp)
        self._joints_arrived(list(joints), list(joints.values()), stamp)


def fed() -> FedState:
    config = NodeConfig(
        "", "test", {}, "/joint_states", BASE, 1.0, 1.0,
        environment_topics=("/kitchen/joint_states",),
    )  # fmt: skip
    return FedState(Pipe()[0], config)


def test_a_trajectorys_end_shown_settles_only_once_every_frame_is_as_new() -> None:
    node = fed()
    node.publish(100.0, {"torso_lift_joint": 0.1, "r_shoulder_pan_joint": 0.0})
    mark = node._mark()
    assert not node.op_wait_for_state(mark, WAIT, END)  # the joints are not at the end
    node.publish(100.5, END, frames=False)  # joints at the end, tf still from 100.0
    assert not node.op_wait_for_state(mark, WAIT, END)
    with node._state:
        node._frames_stamped([(BASE, 100.5)])
    assert not node.op_wait_for_state(mark, WAIT, END)  # the mug's frame still lags
    with node._state:
        node._frames_stamped([("mug-1", 100.5)])
    assert node.op_wait_for_state(mark, WAIT, END)


def test_a_state_stamped_just_after_the_result_settles_in_any_arrival_order() -> None:
    node = fed()
    node.publish(200.0, END)
    node.publish(200.02, END)  # published after the result, arrived before it was marked
    mark = node._mark(result_stamp=200.01)
    assert node.op_wait_for_state(mark, WAIT)  # no newer arrival needed
    late = node._mark(result_stamp=200.03)
    assert not node.op_wait_for_state(late, WAIT)  # everything held predates the result


def test_a_robot_clock_apart_from_the_results_leaves_the_wait_to_the_arrivals() -> None:
    node = fed()
    node.publish(210.0, END)  # stamps 10 s ahead of the result's clock: no evidence
    mark = node._mark(result_stamp=200.0)
    assert not node.op_wait_for_state(mark, WAIT)
    node.publish(210.03, END)  # a newer arrival settles it
    assert node.op_wait_for_state(mark, WAIT)


def test_unstamped_states_settle_by_arrival_only() -> None:
    node = fed()
    node.publish(0.0, END)
    mark = node._mark()
    assert not node.op_wait_for_state(mark, WAIT, END)
    node.publish(0.0, END)
    assert node.op_wait_for_state(mark, WAIT, END)


def test_a_transform_handled_after_the_result_but_stamped_before_it_settles_nothing() -> None:
    node = fed()
    node.publish(300.0, END)
    mark = node._mark(result_stamp=300.01)  # the joints held are on the result's clock
    node._joints_arrived(list(END), list(END.values()), 300.02)  # after the result
    with node._state:  # a transform published before the result, handled after it
        node._frames_stamped([(BASE, 299.99), ("mug-1", 299.99)])
        node._base_arrived()
    assert not node.op_wait_for_state(mark, WAIT)
    node.publish(300.02, END)
    assert node.op_wait_for_state(mark, WAIT)


def test_by_arrivals_a_frame_lagging_behind_the_joints_keeps_the_wait_going() -> None:
    node = fed()
    node.publish(410.0, END)
    mark = node._mark(result_stamp=400.0)  # the result's clock apart: the arrivals decide
    assert mark[2] == 0.0
    node._environment_arrived("/kitchen/joint_states", ["drawer"], [0.1], 410.1)
    node._joints_arrived(list(END), list(END.values()), 410.1)
    with node._state:
        node._frames_stamped([(BASE, 410.05), ("mug-1", 410.05)])
        node._base_arrived()
    assert not node.op_wait_for_state(mark, WAIT)  # both arrived; tf older than the joints

    def one_publication_behind() -> None:  # tf lagging the joints steadily catches up
        node._environment_arrived("/kitchen/joint_states", ["drawer"], [0.1], 410.2)
        node._joints_arrived(list(END), list(END.values()), 410.2)
        with node._state:
            node._frames_stamped([(BASE, 410.1), ("mug-1", 410.1)])
            node._base_arrived()

    with node._state:  # held until the wait below waits: it starts from joints at 410.1
        threading.Thread(target=one_publication_behind).start()
        assert node.op_wait_for_state(mark, SETTLES)


def test_a_frame_not_published_along_and_an_unheard_environment_hold_no_wait() -> None:
    node = fed()  # no kitchen publisher: its topic is never heard
    with node._state:
        node._frames_stamped([("mug-1", 480.0), (BASE, 500.0)])  # the mug's sent once
        node._base_arrived()
    node._joints_arrived(list(END), list(END.values()), 500.0)
    mark = node._mark(result_stamp=500.01)
    with node._state:
        node._frames_stamped([(BASE, 500.02)])
    node._joints_arrived(list(END), list(END.values()), 500.02)
    assert node.op_wait_for_state(mark, WAIT)


def test_a_lookup_before_the_robots_first_state_waits_for_it_once() -> None:
    node = fed()
    answers: list[object] = []
    asking = threading.Thread(target=lambda: answers.append(node.op_lookups("map", [BASE])))
    asking.start()
    asking.join(WAIT)
    assert asking.is_alive() and not answers  # tf is still empty: the lookup waits
    node.publish(100.0, {"torso_lift_joint": 0.1})
    asking.join(SETTLES)
    assert answers == [{BASE: ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))}]
    assert node.op_lookup("map", BASE) == ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
