"""Scene descriptions rebuilt from Box2D v3's own code: its benchmark suite (``SUITE``) and its
Stacking / Robustness samples plus the joint and accuracy cases (``samples.SAMPLES``).

``SUITE[name]()`` returns a Stelkropp scene dict (version-2 keys where needed, Box2D-only
settings under ``box2d`` keys, scripts and step counts under ``bench``); ``NEEDS`` says, per
suite scene, how it still differs from Box2D's (``LACKS``: the features Stelkropp's core lacks).
"""
from .benchmarks import compounds, joint_grid, junkyard, large_pyramid, many_pyramids, smash, spinner, tumbler, washer
from .ragdoll import rain

SUITE = {"compounds": compounds, "joint_grid": joint_grid, "junkyard": junkyard, "large_pyramid": large_pyramid,
         "many_pyramids": many_pyramids, "rain": rain, "smash": smash, "spinner": spinner, "tumbler": tumbler,
         "washer": washer}

# What Stelkropp's core still lacks that a suite scene asks of Box2D (tests/test_suite_speed.py
# checks each is still missing, so a line cannot outlive the feature). Everything else in the
# scenes is built as benchmarks.c builds it: shapes, compound bodies, joints, filters; and the
# scripts (rain's ragdolls, junkyard's pusher) and rain's sleep threshold are run for our side by
# the harness (suite/scripts.py) as Box2D's side runs them; smash's wall is created asleep in both
# (the format's "awake": false, read by both engines).
LACKS = {
    "linear_damping": "linear damping 0.1 on heads and lower arms (Box2D linearDamping): ours undamped",
    "hit_events": "hit events on every box (Box2D enableHitEvents, gathered in its step): ours makes "
                  "them only when world.contact_events is read, and the bench reads none",
}

# Per suite scene: how it still differs from Box2D's (empty: the same scene and script).
NEEDS = {
    "large_pyramid": [],
    "many_pyramids": [],
    "smash": [],
    "joint_grid": [],
    "rain": [LACKS["linear_damping"]],
    "spinner": [],  # the bar's enableSleep = false: its motor never lets it rest, in either engine
    "tumbler": [],
    "washer": [LACKS["hit_events"]],
    "junkyard": [],
    "compounds": [],
}

__all__ = ["SUITE", "NEEDS", "LACKS"]
