% Motions every robot understands (CRAM's cram_common_designators), as grounding rules.
% The command shapes are documented in robocram/designators/common_motions.py.

common_target_pose(Target, Pose) :- loc_desig(Target), !, designator_grounding(Target, Pose).
common_target_pose(Pose, Pose).

common_prop_or_default(D, Key, _, Value) :- desig_prop(D, Key, Value), !.
common_prop_or_default(_, _, Default, Default).

motion_grounding(D, move_base(Pose)) :-
    motion_desig(D), desig_prop(D, type, going),
    desig_prop(D, target, Target), common_target_pose(Target, Pose).

motion_grounding(D, move_torso(Angle)) :-
    motion_desig(D), desig_prop(D, type, 'moving-torso'),
    desig_prop(D, joint_angle, Angle).

motion_grounding(D, move_head(pose, Pose)) :-
    motion_desig(D), desig_prop(D, type, looking),
    desig_prop(D, target, Target), common_target_pose(Target, Pose).
motion_grounding(D, move_head(frame, Frame)) :-
    motion_desig(D), desig_prop(D, type, looking), desig_prop(D, frame, Frame).
motion_grounding(D, move_head(direction, Direction)) :-
    motion_desig(D), desig_prop(D, type, looking), desig_prop(D, direction, Direction).

motion_grounding(D, detect(Object)) :-
    motion_desig(D), desig_prop(D, type, detecting), desig_prop(D, object, Object).
motion_grounding(D, inspect(Object)) :-
    motion_desig(D), desig_prop(D, type, inspecting), desig_prop(D, object, Object).

motion_grounding(D, move_gripper_joint(Gripper, open, Effort)) :-
    motion_desig(D), desig_prop(D, type, opening), desig_prop(D, gripper, Gripper),
    common_prop_or_default(D, effort, none, Effort).
motion_grounding(D, move_gripper_joint(Gripper, close, Effort)) :-
    motion_desig(D), desig_prop(D, type, closing), desig_prop(D, gripper, Gripper),
    common_prop_or_default(D, effort, none, Effort).
motion_grounding(D, move_gripper_joint(Gripper, grip, Effort)) :-
    motion_desig(D), desig_prop(D, type, gripping), desig_prop(D, gripper, Gripper),
    common_prop_or_default(D, effort, none, Effort).
motion_grounding(D, move_gripper_joint(Gripper, Position, Effort)) :-
    motion_desig(D), desig_prop(D, type, 'moving-gripper-joint'),
    desig_prop(D, gripper, Gripper), desig_prop(D, joint_angle, Position),
    common_prop_or_default(D, effort, none, Effort).

motion_grounding(D, move_tcp_both(Left, Right, Mode)) :-
    motion_desig(D), desig_prop(D, type, 'moving-tcp'),
    desig_prop(D, left_target, LeftTarget), desig_prop(D, right_target, RightTarget),
    common_target_pose(LeftTarget, Left), common_target_pose(RightTarget, Right),
    common_prop_or_default(D, collision_mode, avoid_all, Mode).
motion_grounding(D, move_tcp(Arm, Pose, Mode)) :-
    motion_desig(D), desig_prop(D, type, 'moving-tcp'), \+ common_both_arms(D, target),
    common_arm_target(D, target, Arm, Target), common_target_pose(Target, Pose),
    common_prop_or_default(D, collision_mode, avoid_all, Mode).

motion_grounding(D, move_joints_both(Left, Right)) :-
    motion_desig(D), desig_prop(D, type, 'moving-arm-joints'),
    desig_prop(D, left_configuration, Left), desig_prop(D, right_configuration, Right).
motion_grounding(D, move_joints(Arm, Configuration)) :-
    motion_desig(D), desig_prop(D, type, 'moving-arm-joints'),
    \+ common_both_arms(D, configuration),
    common_arm_target(D, configuration, Arm, Configuration).

common_arm_target(D, target, left, T) :- desig_prop(D, left_target, T).
common_arm_target(D, target, right, T) :- desig_prop(D, right_target, T).
common_arm_target(D, configuration, left, C) :- desig_prop(D, left_configuration, C).
common_arm_target(D, configuration, right, C) :- desig_prop(D, right_configuration, C).
common_arm_target(D, Key, Arm, Value) :- desig_prop(D, arm, Arm), desig_prop(D, Key, Value).

common_both_arms(D, target) :-
    desig_prop(D, left_target, _), desig_prop(D, right_target, _).
common_both_arms(D, configuration) :-
    desig_prop(D, left_configuration, _), desig_prop(D, right_configuration, _).
