% Stretch behind ROS 2 (Hello Robot's stretch_driver names, Nav2 for the base): the facts
% robocram's plan side reads (docs/ros2.md, "A robot with a differential base").
ros_action(stretch_description, navigation, '/navigate_to_pose',
           'nav2_msgs/NavigateToPose').
ros_action(stretch_description, arm(arm), '/stretch_controller/follow_joint_trajectory',
           'control_msgs/FollowJointTrajectory').
ros_action(stretch_description, head, '/head_controller/follow_joint_trajectory',
           'control_msgs/FollowJointTrajectory').
ros_action(stretch_description, gripper(arm), '/gripper_controller/gripper_cmd',
           'control_msgs/GripperCommand').
ros_action(stretch_description, perception, '/robocram/detect_objects',
           'robocram_msgs/DetectObjects').
ros_topic(stretch_description, joint_states, '/joint_states').
ros_action_timeout(stretch_description, navigation, 120.0).
ros_action_timeout(stretch_description, Resource, 30.0) :- Resource \== navigation.
ros_connection_timeout(stretch_description, 2.0).
ros_server_timeout(stretch_description, 5.0).
ros_gripper_effort(stretch_description, 20.0).
