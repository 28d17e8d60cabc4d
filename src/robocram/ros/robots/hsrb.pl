% The HSR's ROS interfaces (Toyota's hsrb controllers). The torso (arm_lift_joint) is part
% of the arm trajectory controller, the head is a pan/tilt trajectory controller.
ros_action(hsrb, navigation, '/move_base/move', 'move_base_msgs/MoveBase').
ros_action(hsrb, torso, '/hsrb/arm_trajectory_controller/follow_joint_trajectory',
           'control_msgs/FollowJointTrajectory').
ros_action(hsrb, arm(arm), '/hsrb/arm_trajectory_controller/follow_joint_trajectory',
           'control_msgs/FollowJointTrajectory').
ros_action(hsrb, head, '/hsrb/head_trajectory_controller/follow_joint_trajectory',
           'control_msgs/FollowJointTrajectory').
ros_action(hsrb, gripper(arm), '/hsrb/gripper_controller/gripper_action',
           'control_msgs/GripperCommand').
ros_action(hsrb, perception, '/robocram/detect_objects', 'robocram_msgs/DetectObjects').

ros_topic(hsrb, joint_states, '/hsrb/joint_states').

ros_action_timeout(hsrb, navigation, 120.0).
ros_action_timeout(hsrb, Resource, 30.0) :- Resource \== navigation.

ros_connection_timeout(hsrb, 2.0).
ros_server_timeout(hsrb, 5.0).
ros_gripper_effort(hsrb, 30.0).
% The HSR's gripper command is hand_motor_joint's angle [rad] (the description's gripper
% joint, -0.798 .. 1.24 in hsrb_description). Holding = SUCCEEDED with stalled is the
% default semantics, stated here; the HSR's own tmc_control_msgs grasp actions are not
% covered (see docs/ros.md), so check it against the robot before relying on it.
ros_gripper_command(hsrb, arm, joint, -0.798, 1.24).
ros_gripper_holding(hsrb, arm, succeeded, -0.798).
ros_cancel_timeout(hsrb, 2.0).
ros_clock_skew_bound(hsrb, 0.5).

% How close a trajectory goal must end (see pr2.pl); other joints get the defaults.
ros_goal_tolerance(hsrb, arm_lift_joint, 0.005).
ros_goal_time_tolerance(hsrb, 0.5).
