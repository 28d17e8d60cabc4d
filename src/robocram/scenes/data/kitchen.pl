% robocram's kitchen: written by tools/make_kitchen_urdf.py (do not edit).
% supporting_surface(Env, Link): Link's top is a place to put things on.
supporting_surface(kitchen, counter_top_north).
supporting_surface(kitchen, counter_top_east).
supporting_surface(kitchen, sink).
supporting_surface(kitchen, stove).
supporting_surface(kitchen, table_top).
% container(Env, Link, Joint, Handle): things lie in Link; moving Joint opens it,
% pulling Handle moves Joint.
container(kitchen, cupboard_body, cupboard_door_joint, cupboard_door_handle).
container(kitchen, sink_cabinet_body, sink_cabinet_door_joint, sink_cabinet_door_handle).
container(kitchen, drawer_unit_drawer_1, drawer_unit_drawer_1_joint, drawer_unit_drawer_1_handle).
container(kitchen, drawer_unit_drawer_2, drawer_unit_drawer_2_joint, drawer_unit_drawer_2_handle).
container(kitchen, drawer_unit_drawer_3, drawer_unit_drawer_3_joint, drawer_unit_drawer_3_handle).
container(kitchen, stove_unit_drawer_1, stove_unit_drawer_1_joint, stove_unit_drawer_1_handle).
container(kitchen, stove_unit_drawer_2, stove_unit_drawer_2_joint, stove_unit_drawer_2_handle).
container(kitchen, cutlery_unit_drawer_1, cutlery_unit_drawer_1_joint, cutlery_unit_drawer_1_handle).
container(kitchen, cutlery_unit_drawer_2, cutlery_unit_drawer_2_joint, cutlery_unit_drawer_2_handle).
container(kitchen, cutlery_unit_drawer_3, cutlery_unit_drawer_3_joint, cutlery_unit_drawer_3_handle).
container(kitchen, cutlery_unit_drawer_4, cutlery_unit_drawer_4_joint, cutlery_unit_drawer_4_handle).
container(kitchen, fridge_body, fridge_door_joint, fridge_door_handle).
container(kitchen, wall_cupboard_1_body, wall_cupboard_1_door_joint, wall_cupboard_1_door_handle).
container(kitchen, wall_cupboard_2_body, wall_cupboard_2_door_joint, wall_cupboard_2_door_handle).
container(kitchen, wall_cupboard_3_body, wall_cupboard_3_door_joint, wall_cupboard_3_door_handle).
container(kitchen, wall_cupboard_4_body, wall_cupboard_4_door_joint, wall_cupboard_4_door_handle).
container(kitchen, wall_cupboard_5_body, wall_cupboard_5_door_joint, wall_cupboard_5_door_handle).
container(kitchen, east_drawers_1_drawer_1, east_drawers_1_drawer_1_joint, east_drawers_1_drawer_1_handle).
container(kitchen, east_drawers_1_drawer_2, east_drawers_1_drawer_2_joint, east_drawers_1_drawer_2_handle).
container(kitchen, east_drawers_1_drawer_3, east_drawers_1_drawer_3_joint, east_drawers_1_drawer_3_handle).
container(kitchen, east_drawers_2_drawer_1, east_drawers_2_drawer_1_joint, east_drawers_2_drawer_1_handle).
container(kitchen, east_drawers_2_drawer_2, east_drawers_2_drawer_2_joint, east_drawers_2_drawer_2_handle).
container(kitchen, east_drawers_2_drawer_3, east_drawers_2_drawer_3_joint, east_drawers_2_drawer_3_handle).
container(kitchen, east_drawers_3_drawer_1, east_drawers_3_drawer_1_joint, east_drawers_3_drawer_1_handle).
container(kitchen, east_drawers_3_drawer_2, east_drawers_3_drawer_2_joint, east_drawers_3_drawer_2_handle).
container(kitchen, east_drawers_3_drawer_3, east_drawers_3_drawer_3_joint, east_drawers_3_drawer_3_handle).
container(kitchen, east_cupboard_body, east_cupboard_door_joint, east_cupboard_door_handle).
% container_kind(Env, Link, Kind): drawer (prismatic) or door (revolute).
container_kind(kitchen, cupboard_body, door).
container_kind(kitchen, sink_cabinet_body, door).
container_kind(kitchen, drawer_unit_drawer_1, drawer).
container_kind(kitchen, drawer_unit_drawer_2, drawer).
container_kind(kitchen, drawer_unit_drawer_3, drawer).
container_kind(kitchen, stove_unit_drawer_1, drawer).
container_kind(kitchen, stove_unit_drawer_2, drawer).
container_kind(kitchen, cutlery_unit_drawer_1, drawer).
container_kind(kitchen, cutlery_unit_drawer_2, drawer).
container_kind(kitchen, cutlery_unit_drawer_3, drawer).
container_kind(kitchen, cutlery_unit_drawer_4, drawer).
container_kind(kitchen, fridge_body, door).
container_kind(kitchen, wall_cupboard_1_body, door).
container_kind(kitchen, wall_cupboard_2_body, door).
container_kind(kitchen, wall_cupboard_3_body, door).
container_kind(kitchen, wall_cupboard_4_body, door).
container_kind(kitchen, wall_cupboard_5_body, door).
container_kind(kitchen, east_drawers_1_drawer_1, drawer).
container_kind(kitchen, east_drawers_1_drawer_2, drawer).
container_kind(kitchen, east_drawers_1_drawer_3, drawer).
container_kind(kitchen, east_drawers_2_drawer_1, drawer).
container_kind(kitchen, east_drawers_2_drawer_2, drawer).
container_kind(kitchen, east_drawers_2_drawer_3, drawer).
container_kind(kitchen, east_drawers_3_drawer_1, drawer).
container_kind(kitchen, east_drawers_3_drawer_2, drawer).
container_kind(kitchen, east_drawers_3_drawer_3, drawer).
container_kind(kitchen, east_cupboard_body, door).
% container_opening(Env, Link, Goal): the joint value [m | rad] that opens it.
container_opening(kitchen, cupboard_body, 1.4).
container_opening(kitchen, sink_cabinet_body, 1.4).
container_opening(kitchen, drawer_unit_drawer_1, 0.4).
container_opening(kitchen, drawer_unit_drawer_2, 0.4).
container_opening(kitchen, drawer_unit_drawer_3, 0.4).
container_opening(kitchen, stove_unit_drawer_1, 0.4).
container_opening(kitchen, stove_unit_drawer_2, 0.4).
container_opening(kitchen, cutlery_unit_drawer_1, 0.4).
container_opening(kitchen, cutlery_unit_drawer_2, 0.4).
container_opening(kitchen, cutlery_unit_drawer_3, 0.4).
container_opening(kitchen, cutlery_unit_drawer_4, 0.4).
container_opening(kitchen, fridge_body, 1.4).
container_opening(kitchen, wall_cupboard_1_body, 1.4).
container_opening(kitchen, wall_cupboard_2_body, 1.4).
container_opening(kitchen, wall_cupboard_3_body, 1.4).
container_opening(kitchen, wall_cupboard_4_body, 1.4).
container_opening(kitchen, wall_cupboard_5_body, 1.4).
container_opening(kitchen, east_drawers_1_drawer_1, 0.4).
container_opening(kitchen, east_drawers_1_drawer_2, 0.4).
container_opening(kitchen, east_drawers_1_drawer_3, 0.4).
container_opening(kitchen, east_drawers_2_drawer_1, 0.4).
container_opening(kitchen, east_drawers_2_drawer_2, 0.4).
container_opening(kitchen, east_drawers_2_drawer_3, 0.4).
container_opening(kitchen, east_drawers_3_drawer_1, 0.4).
container_opening(kitchen, east_drawers_3_drawer_2, 0.4).
container_opening(kitchen, east_drawers_3_drawer_3, 0.4).
container_opening(kitchen, east_cupboard_body, 1.4).
