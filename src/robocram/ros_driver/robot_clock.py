"""The driver's robot clock: every stamp it publishes is on it, results as well as states.

A robot whose clock is ``offset`` seconds off ours (``--clock-offset``) stamps its joint
states, its transforms and its action servers' results, feedback and status by that one
clock; the plan side compares a result's stamp with the states' (docs/ros.md "state after
a goal"). actionlib stamps by ``rospy.Time.now()``, so its publishers are wrapped to
shift what they send; they read the offset as they send, so a reset may change it.
"""

from __future__ import annotations

from robocram.ros_driver.goals import RosMessage

PUBLISHERS = ("result_pub", "feedback_pub", "status_pub")  # actionlib's ActionServer's


class RobotClock:
    """Our clock shifted by ``offset`` [s] (ahead: +, behind: -)."""

    def __init__(self, offset: float) -> None:
        self.offset = offset

    def now(self) -> RosMessage:
        """Now on the robot's clock, as a ``rospy.Time``."""
        import rospy

        return rospy.Time.now() + rospy.Duration.from_sec(self.offset)

    def stamp_actions(self, server: RosMessage) -> None:
        """Make a started ``SimpleActionServer`` stamp its messages by this clock."""
        inner = server.action_server
        for name in PUBLISHERS:
            setattr(inner, name, _Shifted(getattr(inner, name), self))


class _Shifted:
    """A publisher whose messages' header stamps are moved by the clock's offset [s] on
    sending (none moved while it is 0)."""

    def __init__(self, publisher: RosMessage, clock: RobotClock) -> None:
        self._publisher = publisher
        self._clock = clock

    def publish(self, message: RosMessage) -> None:
        import rospy

        if self._clock.offset != 0.0:
            message.header.stamp += rospy.Duration.from_sec(self._clock.offset)
        self._publisher.publish(message)

    def unregister(self) -> None:
        self._publisher.unregister()
