"""big_kitchen: an environment description drafted by `robocram env draft` from big_kitchen.urdf.

Check it with `robocram env check THIS_FILE.py`; look at each `TODO doubt`.
"""

from __future__ import annotations

from pathlib import Path

from robocram.scenes import (
    ContainerDescription,
    EnvironmentDescription,
    SurfaceDescription,
)

URDF = Path(__file__).resolve().parent / "big_kitchen.urdf"


def description() -> EnvironmentDescription:
    """The big_kitchen description (unchecked; `robocram env check` drives it)."""
    return EnvironmentDescription(
        name="big_kitchen",
        urdf=URDF,
        surfaces=(
            # why: an upward face 3.00 x 0.62 m at 0.850 m
            SurfaceDescription("counter_top_north", height=0.85),
            # why: an upward face 0.62 x 2.40 m at 0.850 m
            SurfaceDescription("counter_top_east", height=0.85),
            # why: an upward face 0.45 x 0.40 m at 0.870 m
            SurfaceDescription("sink", height=0.87),
            # why: an upward face 0.55 x 0.50 m at 0.870 m
            SurfaceDescription("stove", height=0.87),
            # why: an upward face 0.62 x 3.00 m at 0.850 m
            SurfaceDescription("counter_top_west", height=0.85),
            # why: an upward face 1.40 x 0.90 m at 0.750 m
            SurfaceDescription("table_top", height=0.75),
        ),
        containers=(
            # why: revolute cupboard_door_joint moves cupboard_door; handle cupboard_door_handle (by
            #   name)
            ContainerDescription(
                "cupboard_body",
                "cupboard_door_joint",
                "cupboard_door_handle",
                "door",
                opening=1.4,
                front=-1.5708,
            ),
            # why: revolute sink_cabinet_door_joint moves sink_cabinet_door; handle
            #   sink_cabinet_door_handle (by name)
            ContainerDescription(
                "sink_cabinet_body",
                "sink_cabinet_door_joint",
                "sink_cabinet_door_handle",
                "door",
                opening=1.4,
                front=-1.5708,
            ),
            # why: prismatic drawer_unit_drawer_1_joint moves drawer_unit_drawer_1; handle
            #   drawer_unit_drawer_1_handle (by name)
            ContainerDescription(
                "drawer_unit_drawer_1",
                "drawer_unit_drawer_1_joint",
                "drawer_unit_drawer_1_handle",
                "drawer",
                opening=0.4,
                front=-1.5708,
            ),
            # why: prismatic drawer_unit_drawer_2_joint moves drawer_unit_drawer_2; handle
            #   drawer_unit_drawer_2_handle (by name)
            ContainerDescription(
                "drawer_unit_drawer_2",
                "drawer_unit_drawer_2_joint",
                "drawer_unit_drawer_2_handle",
                "drawer",
                opening=0.4,
                front=-1.5708,
            ),
            # why: prismatic drawer_unit_drawer_3_joint moves drawer_unit_drawer_3; handle
            #   drawer_unit_drawer_3_handle (by name)
            ContainerDescription(
                "drawer_unit_drawer_3",
                "drawer_unit_drawer_3_joint",
                "drawer_unit_drawer_3_handle",
                "drawer",
                opening=0.4,
                front=-1.5708,
            ),
            # why: prismatic stove_unit_drawer_1_joint moves stove_unit_drawer_1; handle
            #   stove_unit_drawer_1_handle (by name)
            ContainerDescription(
                "stove_unit_drawer_1",
                "stove_unit_drawer_1_joint",
                "stove_unit_drawer_1_handle",
                "drawer",
                opening=0.4,
                front=-1.5708,
            ),
            # why: prismatic stove_unit_drawer_2_joint moves stove_unit_drawer_2; handle
            #   stove_unit_drawer_2_handle (by name)
            ContainerDescription(
                "stove_unit_drawer_2",
                "stove_unit_drawer_2_joint",
                "stove_unit_drawer_2_handle",
                "drawer",
                opening=0.4,
                front=-1.5708,
            ),
            # why: prismatic cutlery_unit_drawer_1_joint moves cutlery_unit_drawer_1; handle
            #   cutlery_unit_drawer_1_handle (by name)
            ContainerDescription(
                "cutlery_unit_drawer_1",
                "cutlery_unit_drawer_1_joint",
                "cutlery_unit_drawer_1_handle",
                "drawer",
                opening=0.4,
                front=-1.5708,
            ),
            # why: prismatic cutlery_unit_drawer_2_joint moves cutlery_unit_drawer_2; handle
            #   cutlery_unit_drawer_2_handle (by name)
            ContainerDescription(
                "cutlery_unit_drawer_2",
                "cutlery_unit_drawer_2_joint",
                "cutlery_unit_drawer_2_handle",
                "drawer",
                opening=0.4,
                front=-1.5708,
            ),
            # why: prismatic cutlery_unit_drawer_3_joint moves cutlery_unit_drawer_3; handle
            #   cutlery_unit_drawer_3_handle (by name)
            ContainerDescription(
                "cutlery_unit_drawer_3",
                "cutlery_unit_drawer_3_joint",
                "cutlery_unit_drawer_3_handle",
                "drawer",
                opening=0.4,
                front=-1.5708,
            ),
            # why: prismatic cutlery_unit_drawer_4_joint moves cutlery_unit_drawer_4; handle
            #   cutlery_unit_drawer_4_handle (by name)
            ContainerDescription(
                "cutlery_unit_drawer_4",
                "cutlery_unit_drawer_4_joint",
                "cutlery_unit_drawer_4_handle",
                "drawer",
                opening=0.4,
                front=-1.5708,
            ),
            # why: revolute fridge_door_joint moves fridge_door; handle fridge_door_handle (by name)
            ContainerDescription(
                "fridge_body",
                "fridge_door_joint",
                "fridge_door_handle",
                "door",
                opening=1.4,
                front=-1.5708,
            ),
            # why: revolute wall_cupboard_1_door_joint moves wall_cupboard_1_door; handle
            #   wall_cupboard_1_door_handle (by name)
            ContainerDescription(
                "wall_cupboard_1_body",
                "wall_cupboard_1_door_joint",
                "wall_cupboard_1_door_handle",
                "door",
                opening=1.4,
                front=-1.5708,
            ),
            # why: revolute wall_cupboard_2_door_joint moves wall_cupboard_2_door; handle
            #   wall_cupboard_2_door_handle (by name)
            ContainerDescription(
                "wall_cupboard_2_body",
                "wall_cupboard_2_door_joint",
                "wall_cupboard_2_door_handle",
                "door",
                opening=1.4,
                front=-1.5708,
            ),
            # why: revolute wall_cupboard_3_door_joint moves wall_cupboard_3_door; handle
            #   wall_cupboard_3_door_handle (by name)
            ContainerDescription(
                "wall_cupboard_3_body",
                "wall_cupboard_3_door_joint",
                "wall_cupboard_3_door_handle",
                "door",
                opening=1.4,
                front=-1.5708,
            ),
            # why: revolute wall_cupboard_4_door_joint moves wall_cupboard_4_door; handle
            #   wall_cupboard_4_door_handle (by name)
            ContainerDescription(
                "wall_cupboard_4_body",
                "wall_cupboard_4_door_joint",
                "wall_cupboard_4_door_handle",
                "door",
                opening=1.4,
                front=-1.5708,
            ),
            # why: revolute wall_cupboard_5_door_joint moves wall_cupboard_5_door; handle
            #   wall_cupboard_5_door_handle (by name)
            ContainerDescription(
                "wall_cupboard_5_body",
                "wall_cupboard_5_door_joint",
                "wall_cupboard_5_door_handle",
                "door",
                opening=1.4,
                front=-1.5708,
            ),
            # why: prismatic east_drawers_1_drawer_1_joint moves east_drawers_1_drawer_1; handle
            #   east_drawers_1_drawer_1_handle (by name)
            ContainerDescription(
                "east_drawers_1_drawer_1",
                "east_drawers_1_drawer_1_joint",
                "east_drawers_1_drawer_1_handle",
                "drawer",
                opening=0.4,
                front=3.1416,
            ),
            # why: prismatic east_drawers_1_drawer_2_joint moves east_drawers_1_drawer_2; handle
            #   east_drawers_1_drawer_2_handle (by name)
            ContainerDescription(
                "east_drawers_1_drawer_2",
                "east_drawers_1_drawer_2_joint",
                "east_drawers_1_drawer_2_handle",
                "drawer",
                opening=0.4,
                front=3.1416,
            ),
            # why: prismatic east_drawers_1_drawer_3_joint moves east_drawers_1_drawer_3; handle
            #   east_drawers_1_drawer_3_handle (by name)
            ContainerDescription(
                "east_drawers_1_drawer_3",
                "east_drawers_1_drawer_3_joint",
                "east_drawers_1_drawer_3_handle",
                "drawer",
                opening=0.4,
                front=3.1416,
            ),
            # why: prismatic east_drawers_2_drawer_1_joint moves east_drawers_2_drawer_1; handle
            #   east_drawers_2_drawer_1_handle (by name)
            ContainerDescription(
                "east_drawers_2_drawer_1",
                "east_drawers_2_drawer_1_joint",
                "east_drawers_2_drawer_1_handle",
                "drawer",
                opening=0.4,
                front=3.1416,
            ),
            # why: prismatic east_drawers_2_drawer_2_joint moves east_drawers_2_drawer_2; handle
            #   east_drawers_2_drawer_2_handle (by name)
            ContainerDescription(
                "east_drawers_2_drawer_2",
                "east_drawers_2_drawer_2_joint",
                "east_drawers_2_drawer_2_handle",
                "drawer",
                opening=0.4,
                front=3.1416,
            ),
            # why: prismatic east_drawers_2_drawer_3_joint moves east_drawers_2_drawer_3; handle
            #   east_drawers_2_drawer_3_handle (by name)
            ContainerDescription(
                "east_drawers_2_drawer_3",
                "east_drawers_2_drawer_3_joint",
                "east_drawers_2_drawer_3_handle",
                "drawer",
                opening=0.4,
                front=3.1416,
            ),
            # why: prismatic east_drawers_3_drawer_1_joint moves east_drawers_3_drawer_1; handle
            #   east_drawers_3_drawer_1_handle (by name)
            ContainerDescription(
                "east_drawers_3_drawer_1",
                "east_drawers_3_drawer_1_joint",
                "east_drawers_3_drawer_1_handle",
                "drawer",
                opening=0.4,
                front=3.1416,
            ),
            # why: prismatic east_drawers_3_drawer_2_joint moves east_drawers_3_drawer_2; handle
            #   east_drawers_3_drawer_2_handle (by name)
            ContainerDescription(
                "east_drawers_3_drawer_2",
                "east_drawers_3_drawer_2_joint",
                "east_drawers_3_drawer_2_handle",
                "drawer",
                opening=0.4,
                front=3.1416,
            ),
            # why: prismatic east_drawers_3_drawer_3_joint moves east_drawers_3_drawer_3; handle
            #   east_drawers_3_drawer_3_handle (by name)
            ContainerDescription(
                "east_drawers_3_drawer_3",
                "east_drawers_3_drawer_3_joint",
                "east_drawers_3_drawer_3_handle",
                "drawer",
                opening=0.4,
                front=3.1416,
            ),
            # why: revolute east_cupboard_door_joint moves east_cupboard_door; handle
            #   east_cupboard_door_handle (by name)
            ContainerDescription(
                "east_cupboard_body",
                "east_cupboard_door_joint",
                "east_cupboard_door_handle",
                "door",
                opening=1.4,
                front=3.1416,
            ),
            # why: prismatic west_drawers_1_drawer_1_joint moves west_drawers_1_drawer_1; handle
            #   west_drawers_1_drawer_1_handle (by name)
            ContainerDescription(
                "west_drawers_1_drawer_1",
                "west_drawers_1_drawer_1_joint",
                "west_drawers_1_drawer_1_handle",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic west_drawers_1_drawer_2_joint moves west_drawers_1_drawer_2; handle
            #   west_drawers_1_drawer_2_handle (by name)
            ContainerDescription(
                "west_drawers_1_drawer_2",
                "west_drawers_1_drawer_2_joint",
                "west_drawers_1_drawer_2_handle",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic west_drawers_1_drawer_3_joint moves west_drawers_1_drawer_3; handle
            #   west_drawers_1_drawer_3_handle (by name)
            ContainerDescription(
                "west_drawers_1_drawer_3",
                "west_drawers_1_drawer_3_joint",
                "west_drawers_1_drawer_3_handle",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic west_drawers_1_drawer_4_joint moves west_drawers_1_drawer_4; handle
            #   west_drawers_1_drawer_4_handle (by name)
            ContainerDescription(
                "west_drawers_1_drawer_4",
                "west_drawers_1_drawer_4_joint",
                "west_drawers_1_drawer_4_handle",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic west_drawers_2_drawer_1_joint moves west_drawers_2_drawer_1; handle
            #   west_drawers_2_drawer_1_handle (by name)
            ContainerDescription(
                "west_drawers_2_drawer_1",
                "west_drawers_2_drawer_1_joint",
                "west_drawers_2_drawer_1_handle",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic west_drawers_2_drawer_2_joint moves west_drawers_2_drawer_2; handle
            #   west_drawers_2_drawer_2_handle (by name)
            ContainerDescription(
                "west_drawers_2_drawer_2",
                "west_drawers_2_drawer_2_joint",
                "west_drawers_2_drawer_2_handle",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic west_drawers_2_drawer_3_joint moves west_drawers_2_drawer_3; handle
            #   west_drawers_2_drawer_3_handle (by name)
            ContainerDescription(
                "west_drawers_2_drawer_3",
                "west_drawers_2_drawer_3_joint",
                "west_drawers_2_drawer_3_handle",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic west_drawers_2_drawer_4_joint moves west_drawers_2_drawer_4; handle
            #   west_drawers_2_drawer_4_handle (by name)
            ContainerDescription(
                "west_drawers_2_drawer_4",
                "west_drawers_2_drawer_4_joint",
                "west_drawers_2_drawer_4_handle",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic west_drawers_3_drawer_1_joint moves west_drawers_3_drawer_1; handle
            #   west_drawers_3_drawer_1_handle (by name)
            ContainerDescription(
                "west_drawers_3_drawer_1",
                "west_drawers_3_drawer_1_joint",
                "west_drawers_3_drawer_1_handle",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic west_drawers_3_drawer_2_joint moves west_drawers_3_drawer_2; handle
            #   west_drawers_3_drawer_2_handle (by name)
            ContainerDescription(
                "west_drawers_3_drawer_2",
                "west_drawers_3_drawer_2_joint",
                "west_drawers_3_drawer_2_handle",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic west_drawers_3_drawer_3_joint moves west_drawers_3_drawer_3; handle
            #   west_drawers_3_drawer_3_handle (by name)
            ContainerDescription(
                "west_drawers_3_drawer_3",
                "west_drawers_3_drawer_3_joint",
                "west_drawers_3_drawer_3_handle",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic west_drawers_3_drawer_4_joint moves west_drawers_3_drawer_4; handle
            #   west_drawers_3_drawer_4_handle (by name)
            ContainerDescription(
                "west_drawers_3_drawer_4",
                "west_drawers_3_drawer_4_joint",
                "west_drawers_3_drawer_4_handle",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic west_drawers_4_drawer_1_joint moves west_drawers_4_drawer_1; handle
            #   west_drawers_4_drawer_1_handle (by name)
            ContainerDescription(
                "west_drawers_4_drawer_1",
                "west_drawers_4_drawer_1_joint",
                "west_drawers_4_drawer_1_handle",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic west_drawers_4_drawer_2_joint moves west_drawers_4_drawer_2; handle
            #   west_drawers_4_drawer_2_handle (by name)
            ContainerDescription(
                "west_drawers_4_drawer_2",
                "west_drawers_4_drawer_2_joint",
                "west_drawers_4_drawer_2_handle",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic west_drawers_4_drawer_3_joint moves west_drawers_4_drawer_3; handle
            #   west_drawers_4_drawer_3_handle (by name)
            ContainerDescription(
                "west_drawers_4_drawer_3",
                "west_drawers_4_drawer_3_joint",
                "west_drawers_4_drawer_3_handle",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic west_drawers_4_drawer_4_joint moves west_drawers_4_drawer_4; handle
            #   west_drawers_4_drawer_4_handle (by name)
            ContainerDescription(
                "west_drawers_4_drawer_4",
                "west_drawers_4_drawer_4_joint",
                "west_drawers_4_drawer_4_handle",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic west_drawers_5_drawer_1_joint moves west_drawers_5_drawer_1; handle
            #   west_drawers_5_drawer_1_handle (by name)
            ContainerDescription(
                "west_drawers_5_drawer_1",
                "west_drawers_5_drawer_1_joint",
                "west_drawers_5_drawer_1_handle",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic west_drawers_5_drawer_2_joint moves west_drawers_5_drawer_2; handle
            #   west_drawers_5_drawer_2_handle (by name)
            ContainerDescription(
                "west_drawers_5_drawer_2",
                "west_drawers_5_drawer_2_joint",
                "west_drawers_5_drawer_2_handle",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic west_drawers_5_drawer_3_joint moves west_drawers_5_drawer_3; handle
            #   west_drawers_5_drawer_3_handle (by name)
            ContainerDescription(
                "west_drawers_5_drawer_3",
                "west_drawers_5_drawer_3_joint",
                "west_drawers_5_drawer_3_handle",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic west_drawers_5_drawer_4_joint moves west_drawers_5_drawer_4; handle
            #   west_drawers_5_drawer_4_handle (by name)
            ContainerDescription(
                "west_drawers_5_drawer_4",
                "west_drawers_5_drawer_4_joint",
                "west_drawers_5_drawer_4_handle",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: revolute west_cupboard_1_door_joint moves west_cupboard_1_door; handle
            #   west_cupboard_1_door_handle (by name)
            ContainerDescription(
                "west_cupboard_1_body",
                "west_cupboard_1_door_joint",
                "west_cupboard_1_door_handle",
                "door",
                opening=1.4,
                front=0.0,
            ),
            # why: revolute west_cupboard_2_door_joint moves west_cupboard_2_door; handle
            #   west_cupboard_2_door_handle (by name)
            ContainerDescription(
                "west_cupboard_2_body",
                "west_cupboard_2_door_joint",
                "west_cupboard_2_door_handle",
                "door",
                opening=1.4,
                front=0.0,
            ),
            # why: revolute west_cupboard_3_door_joint moves west_cupboard_3_door; handle
            #   west_cupboard_3_door_handle (by name)
            ContainerDescription(
                "west_cupboard_3_body",
                "west_cupboard_3_door_joint",
                "west_cupboard_3_door_handle",
                "door",
                opening=1.4,
                front=0.0,
            ),
            # why: revolute west_cupboard_4_door_joint moves west_cupboard_4_door; handle
            #   west_cupboard_4_door_handle (by name)
            ContainerDescription(
                "west_cupboard_4_body",
                "west_cupboard_4_door_joint",
                "west_cupboard_4_door_handle",
                "door",
                opening=1.4,
                front=0.0,
            ),
            # why: revolute west_cupboard_5_door_joint moves west_cupboard_5_door; handle
            #   west_cupboard_5_door_handle (by name)
            ContainerDescription(
                "west_cupboard_5_body",
                "west_cupboard_5_door_joint",
                "west_cupboard_5_door_handle",
                "door",
                opening=1.4,
                front=0.0,
            ),
        ),
        usual_locations=(("bowl", "west_drawers_1_drawer_4"), ("mug", "counter_top_west")),
    )
