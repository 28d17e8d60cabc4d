"""The driver's robot clock: every stamp it publishes is on it, results as well as states.

A robot whose clock is ``offset`` seconds off ours (``--clock-offset``) stamps its joint
states, its transforms and its action servers' results, feedback and status by that one
clock; the plan side compares a result's stamp with the states' (docs/ros.md "state after
a goal"). actionlib stamps by ``rospy.Time.now()``, so its publishers are wrapped to
shift what they send.
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
        if self.offset == 0.0:
            return
        inner = server.action_server
        for name in PUBLISHERS:
            setattr(inner, name, _Shifted(getattr(inner, name), self.offset))


class _Shifted:
    """A publisher whose messages' header stamps are moved by ``offset`` [s] on sending."""

    def __init__(self, publisher: RosMessage, offset: float) -> None:
        self._publisher = publisher
        self._offset = offset

    def publish(self, message: RosMessage) -> None:
        import rospy

        message.header.stamp += rospy.Duration.from_sec(self._offset)
        self._publisher.publish(message)

    def unregister(self) -> None:
        self._publisher.unregister()
