"""Box2D v3's Stacking and Robustness samples, plus issue 18's extra cases and issue 14's joint cases.

``SAMPLES[name]()`` returns the scene description; ``bench.suite.measures`` defines the figures
measured on them (engine independent) and ``python -m bench.box2d.samples`` measures them in
Box2D v3 (``bench/results/box2d_v3_figures.{json,md}``).
"""
from . import cases, robustness, stacking

SAMPLES = {
    # sample_stacking.cpp
    "single_box": stacking.single_box,
    "tilted_stack": stacking.tilted_stack,
    "vertical_stack": stacking.vertical_stack,
    "circle_stack": stacking.circle_stack,
    "capsule_stack": stacking.capsule_stack,
    "cliff": stacking.cliff,
    "arch": stacking.arch,
    "double_domino": stacking.double_domino,
    "confined": stacking.confined,
    "card_house": stacking.card_house,
    # sample_robustness.cpp
    "high_mass_ratio_1": robustness.high_mass_ratio_1,
    "high_mass_ratio_2": robustness.high_mass_ratio_2,
    "high_mass_ratio_3": robustness.high_mass_ratio_3,
    "overlap_recovery": robustness.overlap_recovery,
    "tiny_pyramid": robustness.tiny_pyramid,
    "cart": robustness.cart,
    "multiple_prismatic": robustness.multiple_prismatic,
    # issue 18, beyond Box2D's samples
    "mass_ratio_1000": cases.mass_ratio_1000,
    "restitution_drop": cases.restitution_drop,
    "small_stack": cases.small_stack,
    # issue 14's joint figures
    "rod_pendulum": cases.rod_pendulum,
    "disc_pendulum": cases.disc_pendulum,
    "hanging_chain": cases.hanging_chain,
    "horizontal_chain": cases.horizontal_chain,
    "weld_cantilever": cases.weld_cantilever,
    "wheel_suspension": cases.wheel_suspension,
    "hanging_body": cases.hanging_body,
}

STACKING = ("single_box", "tilted_stack", "vertical_stack", "circle_stack", "capsule_stack", "cliff", "arch",
            "double_domino", "confined", "card_house")
ROBUSTNESS = ("high_mass_ratio_1", "high_mass_ratio_2", "high_mass_ratio_3", "overlap_recovery", "tiny_pyramid",
              "cart", "multiple_prismatic")

__all__ = ["SAMPLES", "STACKING", "ROBUSTNESS"]
