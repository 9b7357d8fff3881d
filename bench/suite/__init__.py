"""Scene descriptions rebuilt from Box2D v3's own code: its benchmark suite (``SUITE``) and its
Stacking / Robustness samples plus the joint and accuracy cases (``samples.SAMPLES``).

``SUITE[name]()`` returns a Stelkropp scene dict (version-2 keys where needed, Box2D-only
settings under ``box2d`` keys, scripts and step counts under ``bench``); ``NEEDS`` lists, per
suite scene, the Stelkropp features it uses that do not exist yet.
"""
from .benchmarks import compounds, joint_grid, junkyard, large_pyramid, many_pyramids, smash, spinner, tumbler, washer
from .ragdoll import rain

SUITE = {"compounds": compounds, "joint_grid": joint_grid, "junkyard": junkyard, "large_pyramid": large_pyramid,
         "many_pyramids": many_pyramids, "rain": rain, "smash": smash, "spinner": spinner, "tumbler": tumbler,
         "washer": washer}

# What each scene needs beyond Stelkropp's version-1 bodies (one convex polygon or disc per body).
NEEDS = {
    "large_pyramid": [],
    "many_pyramids": ["segment shapes (20 ground segments on one static body)", "several shapes per body"],
    "smash": ["bodies created asleep (box2d.awake = false; Stelkropp starts them awake)"],
    "joint_grid": ["revolute joints (19,800)", "collision filter (category 2, mask ~2)"],
    "rain": ["capsules", "rounded polygons (feet)", "several shapes per body", "revolute joints with limits, "
             "motor friction, springs and a reference angle", "collision groups and masks",
             "scripted creation/removal of bodies (bench.events)", "linear damping (box2d key)"],
    "spinner": ["chain loop (360 points)", "capsules", "rounded box", "revolute motor"],
    "tumbler": ["several shapes per body (hollow drum of 4 offset boxes)", "revolute motor"],
    "washer": ["several shapes per kinematic body (40 polygons)", "hit events (box2d key, cost only)"],
    "junkyard": ["several shapes per static body", "kinematic target drive (bench.drives)"],
    "compounds": ["several shapes per body (two triangles)", "segment shape"],
}

__all__ = ["SUITE", "NEEDS"]
