"""iai_oven_area: an environment description drafted by `robocram env draft` from kitchen.urdf.

Check it with `robocram env check THIS_FILE.py`; look at each `TODO doubt`.
"""

from __future__ import annotations

from pathlib import Path

from robocram.scenes import (
    ContainerDescription,
    EnvironmentDescription,
    StandIn,
    SurfaceDescription,
)

URDF = Path(__file__).resolve().parent / "kitchen.urdf"


def description() -> EnvironmentDescription:
    """The iai_oven_area description (unchecked; `robocram env check` drives it)."""
    return EnvironmentDescription(
        name="iai_oven_area",
        urdf=URDF,
        surfaces=(
            # why: an upward face 0.57 x 1.60 m at 0.850 m
            SurfaceDescription("sink_area_surface", height=0.85),
            # why: an upward face 0.80 x 2.45 m at 0.861 m
            SurfaceDescription("kitchen_island_surface", height=0.861),
            # why: an upward face 1.20 x 0.80 m at 0.750 m
            SurfaceDescription("table_area_main", height=0.72),
        ),
        containers=(
            # why: prismatic sink_area_trash_drawer_main_joint moves sink_area_trash_drawer_main;
            #   handle sink_area_trash_drawer_handle (by name)
            ContainerDescription(
                "sink_area_trash_drawer_main",
                "sink_area_trash_drawer_main_joint",
                "sink_area_trash_drawer_handle",
                "drawer",
                opening=0.43,
                front=3.1416,
            ),
            # why: prismatic sink_area_left_upper_drawer_main_joint moves
            #   sink_area_left_upper_drawer_main; handle sink_area_left_upper_drawer_handle (by
            #   name)
            ContainerDescription(
                "sink_area_left_upper_drawer_main",
                "sink_area_left_upper_drawer_main_joint",
                "sink_area_left_upper_drawer_handle",
                "drawer",
                opening=0.43,
                front=3.1416,
            ),
            # why: prismatic sink_area_left_middle_drawer_main_joint moves
            #   sink_area_left_middle_drawer_main; handle sink_area_left_middle_drawer_handle (by
            #   name)
            ContainerDescription(
                "sink_area_left_middle_drawer_main",
                "sink_area_left_middle_drawer_main_joint",
                "sink_area_left_middle_drawer_handle",
                "drawer",
                opening=0.43,
                front=3.1416,
            ),
            # why: prismatic sink_area_left_bottom_drawer_main_joint moves
            #   sink_area_left_bottom_drawer_main; handle sink_area_left_bottom_drawer_handle (by
            #   name)
            ContainerDescription(
                "sink_area_left_bottom_drawer_main",
                "sink_area_left_bottom_drawer_main_joint",
                "sink_area_left_bottom_drawer_handle",
                "drawer",
                opening=0.43,
                front=3.1416,
            ),
            # why: prismatic oven_area_area_middle_upper_drawer_main_joint moves
            #   oven_area_area_middle_upper_drawer_main; handle
            #   oven_area_area_middle_upper_drawer_handle (by name)
            ContainerDescription(
                "oven_area_area_middle_upper_drawer_main",
                "oven_area_area_middle_upper_drawer_main_joint",
                "oven_area_area_middle_upper_drawer_handle",
                "drawer",
                opening=0.43,
                front=3.1416,
            ),
            # why: prismatic oven_area_area_middle_lower_drawer_main_joint moves
            #   oven_area_area_middle_lower_drawer_main; handle
            #   oven_area_area_middle_lower_drawer_handle (by name)
            ContainerDescription(
                "oven_area_area_middle_lower_drawer_main",
                "oven_area_area_middle_lower_drawer_main_joint",
                "oven_area_area_middle_lower_drawer_handle",
                "drawer",
                opening=0.43,
                front=3.1416,
            ),
            # why: prismatic oven_area_area_left_drawer_main_joint moves
            #   oven_area_area_left_drawer_main; handle oven_area_area_left_drawer_handle (by name)
            ContainerDescription(
                "oven_area_area_left_drawer_main",
                "oven_area_area_left_drawer_main_joint",
                "oven_area_area_left_drawer_handle",
                "drawer",
                opening=0.43,
                front=3.1416,
            ),
            # why: prismatic oven_area_area_right_drawer_joint moves
            #   oven_area_area_right_drawer_main; handle oven_area_area_right_drawer_handle (by
            #   name)
            ContainerDescription(
                "oven_area_area_right_drawer_main",
                "oven_area_area_right_drawer_joint",
                "oven_area_area_right_drawer_handle",
                "drawer",
                opening=0.43,
                front=3.1416,
            ),
            # why: prismatic kitchen_island_left_upper_drawer_main_joint moves
            #   kitchen_island_left_upper_drawer_main; handle
            #   kitchen_island_left_upper_drawer_handle (by name)
            ContainerDescription(
                "kitchen_island_left_upper_drawer_main",
                "kitchen_island_left_upper_drawer_main_joint",
                "kitchen_island_left_upper_drawer_handle",
                "drawer",
                opening=0.43,
                front=0.0,
            ),
            # why: prismatic kitchen_island_left_lower_drawer_main_joint moves
            #   kitchen_island_left_lower_drawer_main; handle
            #   kitchen_island_left_lower_drawer_handle (by name)
            ContainerDescription(
                "kitchen_island_left_lower_drawer_main",
                "kitchen_island_left_lower_drawer_main_joint",
                "kitchen_island_left_lower_drawer_handle",
                "drawer",
                opening=0.43,
                front=0.0,
            ),
            # why: prismatic kitchen_island_middle_upper_drawer_main_joint moves
            #   kitchen_island_middle_upper_drawer_main; handle
            #   kitchen_island_middle_upper_drawer_handle (by name)
            ContainerDescription(
                "kitchen_island_middle_upper_drawer_main",
                "kitchen_island_middle_upper_drawer_main_joint",
                "kitchen_island_middle_upper_drawer_handle",
                "drawer",
                opening=0.43,
                front=0.0,
            ),
            # why: prismatic kitchen_island_middle_lower_drawer_main_joint moves
            #   kitchen_island_middle_lower_drawer_main; handle
            #   kitchen_island_middle_lower_drawer_handle (by name)
            ContainerDescription(
                "kitchen_island_middle_lower_drawer_main",
                "kitchen_island_middle_lower_drawer_main_joint",
                "kitchen_island_middle_lower_drawer_handle",
                "drawer",
                opening=0.43,
                front=0.0,
            ),
            # why: prismatic kitchen_island_right_upper_drawer_main_joint moves
            #   kitchen_island_right_upper_drawer_main; handle
            #   kitchen_island_right_upper_drawer_handle (by name)
            ContainerDescription(
                "kitchen_island_right_upper_drawer_main",
                "kitchen_island_right_upper_drawer_main_joint",
                "kitchen_island_right_upper_drawer_handle",
                "drawer",
                opening=0.43,
                front=0.0,
            ),
            # why: prismatic kitchen_island_right_lower_drawer_main_joint moves
            #   kitchen_island_right_lower_drawer_main; handle
            #   kitchen_island_right_lower_drawer_handle (by name)
            ContainerDescription(
                "kitchen_island_right_lower_drawer_main",
                "kitchen_island_right_lower_drawer_main_joint",
                "kitchen_island_right_lower_drawer_handle",
                "drawer",
                opening=0.43,
                front=0.0,
            ),
            # why: prismatic fridge_area_lower_drawer_main_joint moves
            #   fridge_area_lower_drawer_main; handle fridge_area_lower_drawer_handle (by name)
            ContainerDescription(
                "fridge_area_lower_drawer_main",
                "fridge_area_lower_drawer_main_joint",
                "fridge_area_lower_drawer_handle",
                "drawer",
                opening=0.43,
                front=3.1416,
            ),
            # why: revolute iai_fridge_door_joint moves iai_fridge_door; handle
            #   iai_fridge_door_handle (by name)
            ContainerDescription(
                "iai_fridge_main",
                "iai_fridge_door_joint",
                "iai_fridge_door_handle",
                "door",
                opening=1.3708,
                front=3.1416,
            ),
        ),
        stand_ins=(
            # why: sink_area_trash_drawer_main_joint travels 0.48 m: an open box 0.53 deep, 0.80
            #   wide (the spacing beside it), 0.12 high, behind its handle
            StandIn(
                "sink_area_trash_drawer_main",
                "open_box",
                size=(0.53, 0.8, 0.12),
                centre=(0.0375, 0.0, 0.2175),
            ),
            # why: sink_area_left_upper_drawer_main_joint travels 0.48 m: an open box 0.53 deep,
            #   0.56 wide (the spacing beside it), 0.10 high, behind its handle
            StandIn(
                "sink_area_left_upper_drawer_main",
                "open_box",
                size=(0.53, 0.56, 0.1025),
                centre=(0.0375, 0.0, 0.0063),
            ),
            # why: sink_area_left_middle_drawer_main_joint travels 0.48 m: an open box 0.53 deep,
            #   0.80 wide (the spacing beside it), 0.10 high, behind its handle
            StandIn(
                "sink_area_left_middle_drawer_main",
                "open_box",
                size=(0.53, 0.8, 0.1025),
                centre=(0.0375, 0.0, 0.0988),
            ),
            # why: sink_area_left_bottom_drawer_main_joint travels 0.48 m: an open box 0.53 deep,
            #   0.80 wide (the spacing beside it), 0.12 high, behind its handle
            StandIn(
                "sink_area_left_bottom_drawer_main",
                "open_box",
                size=(0.53, 0.8, 0.12),
                centre=(0.0375, 0.0, 0.09),
            ),
            # why: oven_area_area_middle_upper_drawer_main_joint travels 0.48 m: an open box 0.53
            #   deep, 0.41 wide (the spacing beside it), 0.11 high, behind its handle
            StandIn(
                "oven_area_area_middle_upper_drawer_main",
                "open_box",
                size=(0.53, 0.41, 0.11),
                centre=(0.0375, 0.0, 0.0025),
            ),
            # why: oven_area_area_middle_lower_drawer_main_joint travels 0.48 m: an open box 0.53
            #   deep, 0.80 wide (the spacing beside it), 0.11 high, behind its handle
            StandIn(
                "oven_area_area_middle_lower_drawer_main",
                "open_box",
                size=(0.53, 0.8, 0.11),
                centre=(0.0375, 0.0, 0.2225),
            ),
            # why: oven_area_area_left_drawer_main_joint travels 0.48 m: an open box 0.53 deep, 0.42
            #   wide (the spacing beside it), 0.12 high, behind its handle
            StandIn(
                "oven_area_area_left_drawer_main",
                "open_box",
                size=(0.53, 0.42, 0.12),
                centre=(0.0575, -0.0, -0.02),
            ),
            # why: kitchen_island_left_upper_drawer_main_joint travels 0.48 m: an open box 0.53
            #   deep, 0.77 wide (the spacing beside it), 0.12 high, behind its handle
            StandIn(
                "kitchen_island_left_upper_drawer_main",
                "open_box",
                size=(0.53, 0.77, 0.12),
                centre=(0.0375, 0.0, 0.09),
            ),
            # why: kitchen_island_left_lower_drawer_main_joint travels 0.48 m: an open box 0.53
            #   deep, 0.77 wide (the spacing beside it), 0.12 high, behind its handle
            StandIn(
                "kitchen_island_left_lower_drawer_main",
                "open_box",
                size=(0.53, 0.77, 0.12),
                centre=(0.0375, 0.0, 0.09),
            ),
            # why: kitchen_island_middle_upper_drawer_main_joint travels 0.48 m: an open box 0.53
            #   deep, 0.77 wide (the spacing beside it), 0.12 high, behind its handle
            StandIn(
                "kitchen_island_middle_upper_drawer_main",
                "open_box",
                size=(0.53, 0.77, 0.12),
                centre=(0.0375, 0.0, 0.09),
            ),
            # why: kitchen_island_middle_lower_drawer_main_joint travels 0.48 m: an open box 0.53
            #   deep, 0.77 wide (the spacing beside it), 0.12 high, behind its handle
            StandIn(
                "kitchen_island_middle_lower_drawer_main",
                "open_box",
                size=(0.53, 0.77, 0.12),
                centre=(0.0375, 0.0, 0.09),
            ),
            # why: kitchen_island_right_upper_drawer_main_joint travels 0.48 m: an open box 0.53
            #   deep, 0.77 wide (the spacing beside it), 0.12 high, behind its handle
            StandIn(
                "kitchen_island_right_upper_drawer_main",
                "open_box",
                size=(0.53, 0.77, 0.12),
                centre=(0.0375, 0.0, 0.09),
            ),
            # why: kitchen_island_right_lower_drawer_main_joint travels 0.48 m: an open box 0.53
            #   deep, 0.77 wide (the spacing beside it), 0.12 high, behind its handle
            StandIn(
                "kitchen_island_right_lower_drawer_main",
                "open_box",
                size=(0.53, 0.77, 0.12),
                centre=(0.0375, 0.0, 0.09),
            ),
            # why: fridge_area_lower_drawer_main_joint travels 0.48 m: an open box 0.53 deep, 0.80
            #   wide (the spacing beside it), 0.12 high, behind its handle
            StandIn(
                "fridge_area_lower_drawer_main",
                "open_box",
                size=(0.53, 0.8, 0.12),
                centre=(0.0375, 0.0, 0.09),
            ),
            # why: named like a table, its frame 0.00 m up: a table standing on the floor
            StandIn("table_area_main", "table", size=(1.6, 0.8, 0.72), centre=(0.0, 0.0, 0.36)),
        ),
        # TODO doubt: sink_area_dish_washer_main_joint: moves 0.000 only; left out
        # TODO doubt: sink_area_dish_washer_door_joint: moves 0.000 only; left out
        # TODO doubt: oven_area_oven_door_joint: moves 0.000 only; left out
        # TODO doubt: oven_area_oven_knob_stove_1_joint: a revolute joint with no handle (a knob, a
        #   tap?); left out
        # TODO doubt: oven_area_oven_knob_stove_2_joint: a revolute joint with no handle (a knob, a
        #   tap?); left out
        # TODO doubt: oven_area_oven_knob_stove_3_joint: a revolute joint with no handle (a knob, a
        #   tap?); left out
        # TODO doubt: oven_area_oven_knob_stove_4_joint: a revolute joint with no handle (a knob, a
        #   tap?); left out
        # TODO doubt: oven_area_oven_knob_oven_joint: a revolute joint with no handle (a knob, a
        #   tap?); left out
        # TODO doubt: 39 links have mesh shapes only, so no surface was looked for on them
        #   (fridge_area, fridge_area_lower_drawer_handle, iai_fridge_door, iai_fridge_door_handle,
        #   iai_fridge_main, kitchen_island, ...); add SurfaceDescription(link, height) and a
        #   StandIn for any you put things on
        usual_locations=(("bowl", "kitchen_island_left_upper_drawer_main"),),
    )
