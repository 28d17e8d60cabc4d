% The PR2's ROS 2 interfaces, named as ros2_control and Nav2 name them (docs/ros2.md).
% ros_action(Robot, Resource, Server, ActionType): the action server of a resource.
% Resources: navigation, torso, head, perception, arm(Arm), gripper(Arm).
% Nav2's bt_navigator serves navigate_to_pose; every joint group is a
% joint_trajectory_controller (/<controller>/follow_joint_trajectory); the grippers are
% gripper_action_controllers (/<controller>/gripper_cmd).
ros_action(pr2, navigation, '/navigate_to_pose', 'nav2_msgs/NavigateToPose').
ros_action(pr2, torso, '/torso_controller/follow_joint_trajectory',
           'control_msgs/FollowJointTrajectory').
ros_action(pr2, arm(left), '/l_arm_controller/follow_joint_trajectory',
           'control_msgs/FollowJointTrajectory').
ros_action(pr2, arm(right), '/r_arm_controller/follow_joint_trajectory',
           'control_msgs/FollowJointTrajectory').
ros_action(pr2, head, '/head_controller/follow_joint_trajectory',
           'control_msgs/FollowJointTrajectory').
ros_action(pr2, gripper(left), '/l_gripper_controller/gripper_cmd',
           'control_msgs/GripperCommand').
ros_action(pr2, gripper(right), '/r_gripper_controller/gripper_cmd',
           'control_msgs/GripperCommand').
ros_action(pr2, perception, '/robocram/detect_objects', 'robocram_msgs/DetectObjects').

ros_topic(pr2, joint_states, '/joint_states').

% ros_action_timeout(Robot, Resource, Seconds): a goal running longer fails and is cancelled.
ros_action_timeout(pr2, navigation, 120.0).
ros_action_timeout(pr2, torso, 60.0).
ros_action_timeout(pr2, Resource, 30.0) :- Resource \== navigation, Resource \== torso.

% Seconds a running goal's server may be gone from the ROS graph before the goal is lost.
ros_connection_timeout(pr2, 2.0).
% Seconds to wait for an action server to appear before a goal fails.
ros_server_timeout(pr2, 5.0).
% Effort [N] the grippers grip with.
ros_gripper_effort(pr2, 50.0).

% The gripper_action_controller commands its joint, pr2_description's <side>_gripper_joint,
% so GripperCommand.position is the gap between the fingers [m]: it spans 0 .. 0.09 m with
% the safety_controller's soft upper limit 0.088 m, while the description's finger
% joint <side>_gripper_l_finger_joint spans 0 .. 0.548 rad. Open is sent as 0.085 m, inside
% the soft limit, so an opening reaches its goal instead of stalling at the limit.
ros_gripper_command(pr2, Arm, gap, 0.0, 0.085) :- member(Arm, [left, right]).
% A goal the fingers cannot reach because they stalled (on an object) ends ABORTED with
% stalled = true (gripper_action_controller with allow_stalling false, its default);
% 2 mm of gap or more is holding.
ros_gripper_holding(pr2, Arm, aborted, 0.002) :- member(Arm, [left, right]).
% Seconds a server may take to confirm a cancel before the robot may still be moving.
ros_cancel_timeout(pr2, 2.0).
% A robot clock further than this from ours is reported when entering ros_robot [s].
ros_clock_skew_bound(pr2, 0.5).

% How close a trajectory goal must end (FollowJointTrajectory goal_tolerance and
% goal_time_tolerance). Joints without a fact: 0.02 rad (revolute), 0.005 m (prismatic).
% ros_goal_tolerance(Robot, Joint, Tolerance) [rad | m]; ros_goal_time_tolerance(Robot, S).
ros_goal_tolerance(pr2, torso_lift_joint, 0.005).
ros_goal_tolerance(pr2, l_wrist_roll_joint, 0.05).
ros_goal_tolerance(pr2, r_wrist_roll_joint, 0.05).
ros_goal_time_tolerance(pr2, 0.5).
