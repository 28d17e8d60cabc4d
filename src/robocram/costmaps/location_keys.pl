% Which designator keys make which costmap layers and which validators judge the poses.
% Fact group "location_costmaps"; every predicate here is extendable from other groups.

% location_cost(Key, Function): the key adds the layer of the Python cost function Function.
% Layers are built in this order, each only over the cells the ones before left possible:
% cheap layers that rule out most cells come first.
location_cost(visible_for, visibility).
location_cost(visible_for, occupancy).
location_cost(reachable_for, reachability).
location_cost(reachable_for, occupancy).
location_cost(on, on).
location_cost(in_, inside).
location_cost(near, near).
location_cost(at, at).
location_cost(left_of, left_of).
location_cost(right_of, right_of).
location_cost(in_front_of, in_front_of).
location_cost(behind, behind).

% location_robot_key(Key): the key's value names the robot the location is for.
location_robot_key(visible_for).
location_robot_key(reachable_for).

% location_option(Key): the key only qualifies others (which object, arm, grid...).
location_option(object).
location_option(target).
location_option(arm).
location_option(for_).
location_option(pose).
location_option(resolution).
location_option(size).
location_option(seed).
location_option(see_through).  % bodies the on/in_ rays look past (the robot asking)

% location_conflict(A, B): a designator may not have both keys.
location_conflict(on, in_).
location_conflict(visible_for, reachable_for).

% location_validator(Key, Validator): poses of designators with the key must pass it.
location_validator(visible_for, robot_collision_free).
location_validator(visible_for, visible).
location_validator(reachable_for, robot_collision_free).
location_validator(reachable_for, reachable).
location_validator(for_, object_collision_free).
