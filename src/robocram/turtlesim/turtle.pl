% The tutorial turtle: how its motions and actions are grounded.
% Commands are executed by robocram.turtlesim.process_modules.

turtle_goal(Goal, Point) :- loc_desig(Goal), !, designator_grounding(Goal, Point).
turtle_goal(Goal, Goal).

turtle_prop_or_default(D, Key, _, Value) :- desig_prop(D, Key, Value), !.
turtle_prop_or_default(_, _, Default, Default).

motion_grounding(D, drive(Speed, Angle)) :-
    motion_desig(D), desig_prop(D, type, driving),
    desig_prop(D, speed, Speed), desig_prop(D, angle, Angle).
motion_grounding(D, go_to(Point)) :-
    motion_desig(D), desig_prop(D, type, moving),
    desig_prop(D, goal, Goal), turtle_goal(Goal, Point).
motion_grounding(D, set_pen(State, Colour)) :-
    motion_desig(D), desig_prop(D, type, 'setting-pen'),
    desig_prop(D, pen, State), turtle_prop_or_default(D, colour, keep, Colour).

action_grounding(D, navigate(Goal)) :-
    action_desig(D), desig_prop(D, type, navigating), desig_prop(D, target, Goal).
action_grounding(D, draw_house(Origin, Size)) :-
    action_desig(D), desig_prop(D, type, drawing), desig_prop(D, shape, house),
    turtle_prop_or_default(D, origin, [2, 2], Origin),
    turtle_prop_or_default(D, size, 4, Size).
