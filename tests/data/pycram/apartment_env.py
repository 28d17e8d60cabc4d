"""apartment: an environment description drafted by `robocram env draft` from apartment.urdf.

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

URDF = Path(__file__).resolve().parent / "apartment.urdf"


def description() -> EnvironmentDescription:
    """The apartment description (unchecked; `robocram env check` drives it)."""
    return EnvironmentDescription(
        name="apartment",
        urdf=URDF,
        surfaces=(
            # why: an upward face 0.70 x 1.20 m at 0.400 m
            SurfaceDescription("coffee_table", height=0.4),
            # why: an upward face 0.31 x 0.31 m at 0.460 m
            SurfaceDescription("bedside_table", height=0.46),
            # why: an upward face 1.00 x 2.75 m at 0.942 m
            SurfaceDescription("island_countertop", height=0.942),
            # why: an upward face 0.60 x 1.20 m at 0.928 m
            SurfaceDescription("countertop", height=0.928),
            # why: an upward face 1.20 x 0.80 m at 0.750 m
            SurfaceDescription("table_area_main", height=0.72),
        ),
        containers=(
            # why: revolute wardrobe_door_right_joint moves wardrobe_door_right; handle
            #   wardrobe_door_right_handle (by name)
            ContainerDescription(
                "wardrobe",
                "wardrobe_door_left_joint",
                "wardrobe_door_left_handle",
                "door",
                opening=1.3708,
                front=3.1416,
            ),
            # why: revolute wardrobe_door_right_joint moves wardrobe_door_right; handle
            #   wardrobe_door_right_handle (by name)
            ContainerDescription(
                "wardrobe",
                "wardrobe_door_right_joint",
                "wardrobe_door_right_handle",
                "door",
                opening=1.3708,
                front=3.1416,
            ),
            # why: prismatic coffee_table_drawer_joint moves coffee_table_drawer; handle
            #   coffee_table_drawer (none found: pulled by the drawer itself)
            ContainerDescription(
                "coffee_table_drawer",
                "coffee_table_drawer_joint",
                "coffee_table_drawer",
                "drawer",
                opening=0.45,
                front=-1.5708,
            ),
            # why: revolute cabinet1_door_top_left_joint moves cabinet1_door_top_left; handle
            #   handle_cab1_top_door (by name)
            ContainerDescription(
                "cabinet1",
                "cabinet1_door_top_left_joint",
                "handle_cab1_top_door",
                "door",
                opening=1.3708,
                front=0.0,
            ),
            # why: prismatic cabinet1_drawer_middle_joint moves cabinet1_drawer_middle; handle
            #   handle_cab1_drawer_mid (by name)
            ContainerDescription(
                "cabinet1_drawer_middle",
                "cabinet1_drawer_middle_joint",
                "handle_cab1_drawer_mid",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic cabinet1_drawer_bottom_joint moves cabinet1_drawer_bottom; handle
            #   handle_cab1_drawer_bottom (by name)
            ContainerDescription(
                "cabinet1_drawer_bottom",
                "cabinet1_drawer_bottom_joint",
                "handle_cab1_drawer_bottom",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: revolute cabinet2_door_left_joint moves cabinet2_door_left; handle
            #   handle_cab2_door (by name)
            ContainerDescription(
                "cabinet2_door_out_fancy",
                "cabinet2_door_left_joint",
                "handle_cab2_door",
                "door",
                opening=1.3708,
                front=0.0,
            ),
            # why: prismatic cabinet2_drawer_small_joint moves cabinet2_drawer_small; handle
            #   cabinet2_drawer_small (none found: pulled by the drawer itself)
            ContainerDescription(
                "cabinet2_drawer_small",
                "cabinet2_drawer_small_joint",
                "cabinet2_drawer_small",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic cabinet2_drawer_big_joint moves cabinet2_drawer_big; handle
            #   cabinet2_drawer_big (none found: pulled by the drawer itself)
            ContainerDescription(
                "cabinet2_drawer_big",
                "cabinet2_drawer_big_joint",
                "cabinet2_drawer_big",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: revolute cabinet3_door_top_left_joint moves cabinet3_door_top_left; handle
            #   handle_cab3_door_top (by name)
            ContainerDescription(
                "cabinet3_door_top_out_fancy",
                "cabinet3_door_top_left_joint",
                "handle_cab3_door_top",
                "door",
                opening=1.3708,
                front=0.0,
            ),
            # why: revolute cabinet3_door_bottom_left_joint moves cabinet3_door_bottom_left; handle
            #   handle_cab3_door_bottom (by name)
            ContainerDescription(
                "cabinet3_door_bottom_out_fancy",
                "cabinet3_door_bottom_left_joint",
                "handle_cab3_door_bottom",
                "door",
                opening=1.3708,
                front=0.0,
            ),
            # why: revolute cabinet4_door_bottom_bottom_joint moves cabinet4_door_bottom; handle
            #   handle_cab4_door_bottom (by name)
            ContainerDescription(
                "cabinet4_door_top",
                "cabinet4_door_bottom_bottom_joint",
                "handle_cab4_door_bottom",
                "door",
                opening=1.3708,
                front=3.1416,
            ),
            # why: prismatic cabinet5_drawer_top_joint moves cabinet5_drawer_top; handle
            #   handle_cab5_t (by name)
            ContainerDescription(
                "cabinet5_drawer_top",
                "cabinet5_drawer_top_joint",
                "handle_cab5_t",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic cabinet5_drawer_middle_joint moves cabinet5_drawer_middle; handle
            #   handle_cab5_m (by name)
            ContainerDescription(
                "cabinet5_drawer_middle",
                "cabinet5_drawer_middle_joint",
                "handle_cab5_m",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic cabinet5_drawer_bottom_joint moves cabinet5_drawer_bottom; handle
            #   handle_cab5_b (by name)
            ContainerDescription(
                "cabinet5_drawer_bottom",
                "cabinet5_drawer_bottom_joint",
                "handle_cab5_b",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic cabinet6_drawer_top_joint moves cabinet6_drawer_top; handle
            #   handle_cab6_t (by name)
            ContainerDescription(
                "cabinet6_drawer_top",
                "cabinet6_drawer_top_joint",
                "handle_cab6_t",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic cabinet6_drawer_middle_joint moves cabinet6_drawer_middle; handle
            #   handle_cab6_m (by name)
            ContainerDescription(
                "cabinet6_drawer_middle",
                "cabinet6_drawer_middle_joint",
                "handle_cab6_m",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: prismatic cabinet6_drawer_bottom_joint moves cabinet6_drawer_bottom; handle
            #   handle_cab6_b (by name)
            ContainerDescription(
                "cabinet6_drawer_bottom",
                "cabinet6_drawer_bottom_joint",
                "handle_cab6_b",
                "drawer",
                opening=0.4,
                front=0.0,
            ),
            # why: revolute cabinet7_door_bottom_left_joint moves cabinet7_door_bottom_left; handle
            #   handle_cab7 (by name)
            ContainerDescription(
                "cabinet7",
                "cabinet7_door_bottom_left_joint",
                "handle_cab7",
                "door",
                opening=1.3708,
                front=3.1416,
            ),
            # why: prismatic dishwasher_drawer_middle_joint moves dishwasher_drawer_middle; handle
            #   handle_cab7_middle (by name)
            ContainerDescription(
                "dishwasher_drawer_middle",
                "dishwasher_drawer_middle_joint",
                "handle_cab7_middle",
                "drawer",
                opening=0.4,
                front=3.1416,
            ),
            # why: prismatic cabinet8_drawer_middle_joint moves cabinet8_drawer_middle; handle
            #   cabinet8_drawer_middle (none found: pulled by the drawer itself)
            ContainerDescription(
                "cabinet8_drawer_middle",
                "cabinet8_drawer_middle_joint",
                "cabinet8_drawer_middle",
                "drawer",
                opening=0.35,
                front=3.1416,
            ),
            # why: prismatic cabinet8_drawer_bottom_joint moves cabinet8_drawer_bottom; handle
            #   handle_cab8 (by name)
            ContainerDescription(
                "cabinet8_drawer_bottom",
                "cabinet8_drawer_bottom_joint",
                "handle_cab8",
                "drawer",
                opening=0.4,
                front=3.1416,
            ),
            # why: prismatic cabinet9_drawer_top_joint moves cabinet9_drawer_top; handle
            #   handle_cab9_t (by name)
            ContainerDescription(
                "cabinet9_drawer_top",
                "cabinet9_drawer_top_joint",
                "handle_cab9_t",
                "drawer",
                opening=0.4,
                front=3.1416,
            ),
            # why: prismatic cabinet9_drawer_middle_joint moves cabinet9_drawer_middle; handle
            #   handle_cab9_m (by name)
            ContainerDescription(
                "cabinet9_drawer_middle",
                "cabinet9_drawer_middle_joint",
                "handle_cab9_m",
                "drawer",
                opening=0.4,
                front=3.1416,
            ),
            # why: prismatic cabinet9_drawer_bottom_joint moves cabinet9_drawer_bottom; handle
            #   handle_cab9_b (by name)
            ContainerDescription(
                "cabinet9_drawer_bottom",
                "cabinet9_drawer_bottom_joint",
                "handle_cab9_b",
                "drawer",
                opening=0.4,
                front=3.1416,
            ),
            # why: prismatic cabinet10_drawer_top_joint moves cabinet10_drawer_top; handle
            #   handle_cab10_t (by name)
            ContainerDescription(
                "cabinet10_drawer_top",
                "cabinet10_drawer_top_joint",
                "handle_cab10_t",
                "drawer",
                opening=0.4,
                front=3.1416,
            ),
            # why: prismatic cabinet10_drawer_middle_joint moves cabinet10_drawer_middle; handle
            #   handle_cab10_m (by name)
            ContainerDescription(
                "cabinet10_drawer_middle",
                "cabinet10_drawer_middle_joint",
                "handle_cab10_m",
                "drawer",
                opening=0.4,
                front=3.1416,
            ),
            # why: prismatic cabinet10_drawer_bottom_joint moves cabinet10_drawer_bottom; handle
            #   handle_cab10_b (by name)
            ContainerDescription(
                "cabinet10_drawer_bottom",
                "cabinet10_drawer_bottom_joint",
                "handle_cab10_b",
                "drawer",
                opening=0.4,
                front=3.1416,
            ),
            # why: prismatic cabinet11_drawer_top_joint moves cabinet11_drawer_top; handle
            #   handle_cab11_t (by name)
            ContainerDescription(
                "cabinet11_drawer_top",
                "cabinet11_drawer_top_joint",
                "handle_cab11_t",
                "drawer",
                opening=0.4,
                front=3.1416,
            ),
            # why: prismatic cabinet11_drawer_middle_joint moves cabinet11_drawer_middle; handle
            #   handle_cab11_m (by name)
            ContainerDescription(
                "cabinet11_drawer_middle",
                "cabinet11_drawer_middle_joint",
                "handle_cab11_m",
                "drawer",
                opening=0.4,
                front=3.1416,
            ),
            # why: prismatic cabinet11_drawer_bottom_joint moves cabinet11_drawer_bottom; handle
            #   handle_cab11_b (by name)
            ContainerDescription(
                "cabinet11_drawer_bottom",
                "cabinet11_drawer_bottom_joint",
                "handle_cab11_b",
                "drawer",
                opening=0.4,
                front=3.1416,
            ),
        ),
        stand_ins=(
            # why: cabinet1_drawer_middle_joint travels 0.45 m: an open box 0.50 deep, 0.80 wide
            #   (the spacing beside it), 0.12 high, behind its handle
            StandIn(
                "cabinet1_drawer_middle",
                "open_box",
                size=(0.5, 0.8, 0.12),
                centre=(0.02, -0.0, 0.09),
            ),
            # why: cabinet1_drawer_bottom_joint travels 0.45 m: an open box 0.50 deep, 0.80 wide
            #   (the spacing beside it), 0.12 high, behind its handle
            StandIn(
                "cabinet1_drawer_bottom",
                "open_box",
                size=(0.5, 0.8, 0.12),
                centre=(0.043, 0.0, 0.33),
            ),
            # why: cabinet2_drawer_small_joint travels 0.45 m: an open box 0.50 deep, 0.50 wide (no
            #   drawer beside it), 0.12 high, behind its handle
            StandIn(
                "cabinet2_drawer_small", "open_box", size=(0.5, 0.5, 0.12), centre=(-0.0, 0.0, 0.0)
            ),
            # why: cabinet2_drawer_big_joint travels 0.45 m: an open box 0.50 deep, 0.50 wide (no
            #   drawer beside it), 0.12 high, behind its handle
            StandIn(
                "cabinet2_drawer_big", "open_box", size=(0.5, 0.5, 0.12), centre=(-0.0, 0.0, 0.0)
            ),
            # why: cabinet5_drawer_top_joint travels 0.45 m: an open box 0.50 deep, 0.46 wide (the
            #   spacing beside it), 0.11 high, behind its handle
            StandIn(
                "cabinet5_drawer_top",
                "open_box",
                size=(0.5, 0.4595, 0.11),
                centre=(0.035, -0.0, 0.035),
            ),
            # why: cabinet5_drawer_middle_joint travels 0.45 m: an open box 0.50 deep, 0.47 wide
            #   (the spacing beside it), 0.11 high, behind its handle
            StandIn(
                "cabinet5_drawer_middle",
                "open_box",
                size=(0.5, 0.472, 0.11),
                centre=(0.035, -0.0, 0.115),
            ),
            # why: cabinet5_drawer_bottom_joint travels 0.45 m: an open box 0.50 deep, 0.47 wide
            #   (the spacing beside it), 0.12 high, behind its handle
            StandIn(
                "cabinet5_drawer_bottom",
                "open_box",
                size=(0.5, 0.472, 0.12),
                centre=(0.045, -0.0, 0.225),
            ),
            # why: cabinet6_drawer_top_joint travels 0.45 m: an open box 0.50 deep, 0.46 wide (the
            #   spacing beside it), 0.11 high, behind its handle
            StandIn(
                "cabinet6_drawer_top",
                "open_box",
                size=(0.5, 0.4595, 0.113),
                centre=(0.042, -0.0, 0.0335),
            ),
            # why: cabinet6_drawer_middle_joint travels 0.45 m: an open box 0.50 deep, 0.47 wide
            #   (the spacing beside it), 0.11 high, behind its handle
            StandIn(
                "cabinet6_drawer_middle",
                "open_box",
                size=(0.5, 0.472, 0.113),
                centre=(0.035, -0.0, 0.1135),
            ),
            # why: cabinet6_drawer_bottom_joint travels 0.45 m: an open box 0.50 deep, 0.47 wide
            #   (the spacing beside it), 0.12 high, behind its handle
            StandIn(
                "cabinet6_drawer_bottom",
                "open_box",
                size=(0.5, 0.472, 0.12),
                centre=(0.053, -0.0, 0.225),
            ),
            # why: dishwasher_drawer_middle_joint travels 0.45 m: an open box 0.50 deep, 0.50 wide
            #   (no drawer beside it), 0.12 high, behind its handle
            StandIn(
                "dishwasher_drawer_middle",
                "open_box",
                size=(0.5, 0.5, 0.12),
                centre=(-0.035, 0.0, 0.048),
            ),
            # why: cabinet8_drawer_middle_joint travels 0.40 m: an open box 0.45 deep, 0.50 wide (no
            #   drawer beside it), 0.12 high, behind its handle
            StandIn(
                "cabinet8_drawer_middle",
                "open_box",
                size=(0.45, 0.5, 0.12),
                centre=(-0.0, 0.0, 0.0),
            ),
            # why: cabinet8_drawer_bottom_joint travels 0.45 m: an open box 0.50 deep, 0.57 wide
            #   (the spacing beside it), 0.12 high, behind its handle
            StandIn(
                "cabinet8_drawer_bottom",
                "open_box",
                size=(0.5, 0.571, 0.12),
                centre=(0.042, 0.0, 0.63),
            ),
            # why: cabinet9_drawer_top_joint travels 0.45 m: an open box 0.50 deep, 0.47 wide (the
            #   spacing beside it), 0.11 high, behind its handle
            StandIn(
                "cabinet9_drawer_top",
                "open_box",
                size=(0.5, 0.471, 0.111),
                centre=(0.035, -0.0, 0.0345),
            ),
            # why: cabinet9_drawer_middle_joint travels 0.45 m: an open box 0.50 deep, 0.47 wide
            #   (the spacing beside it), 0.11 high, behind its handle
            StandIn(
                "cabinet9_drawer_middle",
                "open_box",
                size=(0.5, 0.471, 0.111),
                centre=(0.035, 0.0, 0.1145),
            ),
            # why: cabinet9_drawer_bottom_joint travels 0.45 m: an open box 0.50 deep, 0.47 wide
            #   (the spacing beside it), 0.12 high, behind its handle
            StandIn(
                "cabinet9_drawer_bottom",
                "open_box",
                size=(0.5, 0.471, 0.12),
                centre=(0.04, 0.0, 0.225),
            ),
            # why: cabinet10_drawer_top_joint travels 0.45 m: an open box 0.50 deep, 0.47 wide (the
            #   spacing beside it), 0.11 high, behind its handle
            StandIn(
                "cabinet10_drawer_top",
                "open_box",
                size=(0.5, 0.471, 0.112),
                centre=(0.037, 0.0, 0.034),
            ),
            # why: cabinet10_drawer_middle_joint travels 0.45 m: an open box 0.50 deep, 0.47 wide
            #   (the spacing beside it), 0.11 high, behind its handle
            StandIn(
                "cabinet10_drawer_middle",
                "open_box",
                size=(0.5, 0.471, 0.112),
                centre=(0.035, 0.0, 0.114),
            ),
            # why: cabinet10_drawer_bottom_joint travels 0.45 m: an open box 0.50 deep, 0.47 wide
            #   (the spacing beside it), 0.12 high, behind its handle
            StandIn(
                "cabinet10_drawer_bottom",
                "open_box",
                size=(0.5, 0.471, 0.12),
                centre=(0.035, -0.0, 0.225),
            ),
            # why: cabinet11_drawer_top_joint travels 0.45 m: an open box 0.50 deep, 0.62 wide (the
            #   spacing beside it), 0.11 high, behind its handle
            StandIn(
                "cabinet11_drawer_top",
                "open_box",
                size=(0.5, 0.621, 0.11),
                centre=(0.037, -0.0, 0.035),
            ),
            # why: cabinet11_drawer_middle_joint travels 0.45 m: an open box 0.50 deep, 0.62 wide
            #   (the spacing beside it), 0.11 high, behind its handle
            StandIn(
                "cabinet11_drawer_middle",
                "open_box",
                size=(0.5, 0.621, 0.11),
                centre=(0.035, 0.0, 0.115),
            ),
            # why: cabinet11_drawer_bottom_joint travels 0.45 m: an open box 0.50 deep, 0.62 wide
            #   (the spacing beside it), 0.12 high, behind its handle
            StandIn(
                "cabinet11_drawer_bottom",
                "open_box",
                size=(0.5, 0.621, 0.12),
                centre=(0.052, 0.0, 0.225),
            ),
            # why: named like a top, its frame 0.92 m up: a 0.04 m top reaching past the links on it
            # TODO doubt: island_countertop: its outline is in a missing mesh; 1.00 x 2.75 m is a
            #   guess
            StandIn("island_countertop", "box", size=(0.996, 2.748, 0.04), centre=(0.0, 0.0, 0.0)),
            # why: named like a top, its frame 0.91 m up: a 0.04 m top reaching past the links on it
            # TODO doubt: countertop: its outline is in a missing mesh; 0.60 x 1.20 m is a guess
            StandIn("countertop", "box", size=(0.6, 1.2, 0.04), centre=(0.0, 0.0, 0.0)),
            # why: named like a table, its frame 0.00 m up: a table standing on the floor
            StandIn("table_area_main", "table", size=(1.6, 0.8, 0.72), centre=(0.0, 0.0, 0.36)),
        ),
        # TODO doubt: coffee_table_drawer_joint: no handle found on coffee_table_drawer; it is
        #   pulled by itself
        # TODO doubt: cabinet2_door_out_joint: moves 0.020 only; left out
        # TODO doubt: cabinet2_drawer_small_joint: no handle found on cabinet2_drawer_small; it is
        #   pulled by itself
        # TODO doubt: cabinet2_drawer_big_joint: no handle found on cabinet2_drawer_big; it is
        #   pulled by itself
        # TODO doubt: cabinet3_door_top_out_joint: a revolute joint with no handle (a knob, a tap?);
        #   left out
        # TODO doubt: cabinet3_door_bottom_out_joint: moves 0.020 only; left out
        # TODO doubt: cabinet4_door_top_top_joint: a revolute joint with no handle (a knob, a tap?);
        #   left out
        # TODO doubt: cabinet8_drawer_middle_joint: no handle found on cabinet8_drawer_middle; it is
        #   pulled by itself
        # TODO doubt: tap_joint: a revolute joint with no handle (a knob, a tap?); left out
        # TODO doubt: tap_handle_open_joint: a revolute joint with no handle (a knob, a tap?); left
        #   out
        # TODO doubt: tap_handle_hot_cold_joint: a revolute joint with no handle (a knob, a tap?);
        #   left out
        # TODO doubt: 56 links have mesh shapes only, so no surface was looked for on them
        #   (armchair, cabinet1, cabinet10, cabinet11, cabinet1_door_top_left, cabinet2, ...); add
        #   SurfaceDescription(link, height) and a StandIn for any you put things on
        usual_locations=(("bowl", "cabinet10_drawer_top"),),
    )
