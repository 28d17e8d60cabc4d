% Motions of a flying robot (CRAM's quadrotor projection), grounded for the projection.
% Commands are executed by robocram.projection.process_modules (FlyingPM, DistanceSensorPM).

motion_grounding(D, fly(Pose)) :-
    motion_desig(D), desig_prop(D, type, flying),
    desig_prop(D, target, Target), common_target_pose(Target, Pose).

motion_grounding(D, sense_distance(Direction)) :-
    motion_desig(D), desig_prop(D, type, 'distance-sensing'),
    desig_prop(D, direction, Direction).
