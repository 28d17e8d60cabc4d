import sys, time, warnings
warnings.simplefilter("ignore")
from robot_zoo import parked_in_kitchen
from pathlib import Path
from robocram.projection import ProjectedRobot
from robocram.projection.bar_opening import *
for name in sys.argv[1:]:
    t=time.time()
    s = parked_in_kitchen(name, Path("/tmp/handle_hold_probe_drafts"))
    r = ProjectedRobot.of(s.world, s.robot)
    arm = "right"
    g = r.arm(arm).gripper
    print(name, g.max_opening, gap_at(r, arm, 1.0), bar_thickness(r, "kitchen", "drawer_unit_drawer_3_handle"),
          bar_opening(r, arm, "kitchen", "drawer_unit_drawer_3_handle"), len(g.joints), g.curled_hand, r.arm(arm).gripper_links, time.time()-t)
    s.world.close()
