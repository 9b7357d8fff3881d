"""Figures of Box2D v3's Stacking and Robustness samples (definitions next to each measurement).

Each ``fig_*`` function runs one sample (via ``run``) and returns ``Fig`` records: a value with
its unit and an exact definition (body, time window, quantity). Times are simulated seconds from
the scene's creation; displacements are of body origins.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..suite import measures as M


@dataclass
class Fig:
    """One measured figure."""
    id: str
    scene: str
    value: object
    unit: str
    definition: str
    reference: dict = field(default_factory=dict)


def fig_single_box(run):
    tr, desc, sim = run("single_box", 3.0)
    i = tr.i("box")
    stop = float(tr.origin[tr.k(3.0), i, 0])
    ideal = 5.0 ** 2 / (2 * 0.6 * 10.0)
    return [Fig("single_box.slide_distance", "single_box", stop, "m",
                "x of the box origin at t = 3 s (it stops at ~0.83 s); launched at 5 m/s, friction 0.6, g 10",
                {"ideal": ideal, "relative_error": stop / ideal - 1}),
            Fig("single_box.height_error", "single_box", float(tr.origin[tr.k(3.0), i, 1] - 1.0), "m",
                "y of the box origin at t = 3 s minus its resting height 1 m"),
            Fig("single_box.max_tilt", "single_box", float(np.abs(tr.angle[:, i]).max()), "rad",
                "largest |angle| of the box over 0..3 s")]


def fig_tilted_stack(run):
    tr, desc, sim = run("tilted_stack", 10.0)
    d = [M.displacement(tr, f"top{j}", 10.0) for j in range(10)]
    return [Fig("tilted_stack.top_displacement_10s_max", "tilted_stack", max(d), "m",
                "largest over the 10 stacks of |origin(10 s) - origin(0)| of the stack's top box", {"per_stack": d}),
            Fig("tilted_stack.top_displacement_10s_min", "tilted_stack", min(d), "m",
                "smallest over the 10 stacks of the top box's displacement over 0..10 s")]


def fig_vertical_stack(run):
    tr, desc, sim = run("vertical_stack", 10.0)
    return [Fig("vertical_stack.top_displacement_10s", "vertical_stack", M.displacement(tr, "top", 10.0), "m",
                "|origin(10 s) - origin(0)| of the top (12th) box", {"issue_18_quotes": 0.047})]


def fig_circle_stack(run):
    tr, desc, sim = run("circle_stack", 10.0)
    k = tr.k(10.0)
    err = [float(tr.origin[k, tr.i(n), 1] - (0.5 + i)) for i, n in enumerate(("c0", "c1", "c2", "top"))]
    return [Fig("circle_stack.top_displacement_10s", "circle_stack", M.displacement(tr, "top", 10.0), "m",
                "|origin(10 s) - origin(0)| of the top (4th) disc"),
            Fig("circle_stack.height_error_10s", "circle_stack", max(map(abs, err)), "m",
                "largest |y(10 s) - (0.5 + i)| over the four discs (i = 0..3 from the bottom)", {"per_disc": err}),
            Fig("circle_stack.drift_10s", "circle_stack",
                float(np.abs(tr.origin[k, [tr.i(n) for n in ("c0", "c1", "c2", "top")], 0]).max()), "m",
                "largest |x(10 s)| of the discs (all start at x = 0)")]


def fig_capsule_stack(run):
    tr, desc, sim = run("capsule_stack", 10.0)
    y = float(tr.origin[tr.k(10.0), tr.i("top"), 1])
    return [Fig("capsule_stack.top_displacement_10s", "capsule_stack", M.displacement(tr, "top", 10.0), "m",
                "|origin(10 s) - origin(0)| of the top (20th) capsule"),
            Fig("capsule_stack.top_height_error_10s", "capsule_stack", y - 9.75, "m",
                "top capsule's y(10 s) minus its height in a perfect column (0.25 + 19 x 0.5 = 9.75 m)")]


def fig_cliff(run):
    tr, desc, sim = run("cliff", 5.0)
    names = [f"{kind}{i}" for kind in ("capsule", "square", "disc") for i in range(3)]
    k = tr.k(5.0)
    final = {n: [float(tr.origin[k, tr.i(n), 0]), float(tr.origin[k, tr.i(n), 1])] for n in names}
    idx = [tr.i(n) for n in names]
    landed = sum(1 for n in names if final[n][1] < 1.1)
    return [Fig("cliff.landed_5s", "cliff", landed, "bodies",
                "how many of the 9 bodies rest on the lower ground (origin y < 1.1 m) at t = 5 s", {"final": final}),
            Fig("cliff.max_upward_speed", "cliff", float(tr.v[:, idx, 1].max()), "m/s",
                "largest upward centre-of-mass speed of any of the 9 bodies over 0..5 s (0 for clean sliding "
                "and landing)")]


def fig_arch(run):
    tr, desc, sim = run("arch", 20.0)
    dyn = np.array([b.get("kind", "dynamic") == "dynamic" for b in desc["bodies"]])
    return [Fig("arch.creep_2_20s", "arch", M.max_displacement(tr, 20.0, 2.0, dyn), "m",
                "largest |origin(20 s) - origin(2 s)| over the 21 dynamic bodies", {"issue_18_quotes": "no creep"}),
            Fig("arch.top_displacement_10s", "arch", M.displacement(tr, "top", 10.0), "m",
                "|origin(10 s) - origin(0)| of the top box")]


def fig_double_domino(run):
    tr, desc, sim = run("double_domino", 10.0)
    idx = [tr.i(f"d{i}") for i in range(15)]
    fallen = np.abs(tr.angle[:, idx]) > 1.0
    first = [float(np.argmax(fallen[:, j]) * tr.dt) if fallen[:, j].any() else None for j in range(15)]
    return [Fig("double_domino.fallen_10s", "double_domino", int(fallen[-1].sum()), "dominoes",
                "dominoes with |angle| > 1 rad at t = 10 s (of 15)"),
            Fig("double_domino.last_fall_time", "double_domino",
                max(t for t in first if t is not None) if any(first) else None, "s",
                "first time the last domino to fall passes |angle| = 1 rad", {"per_domino": first})]


def fig_confined(run):
    tr, desc, sim = run("confined", 10.0)
    k = tr.k(10.0)
    c = tr.com[k, 1:]
    mx, mean = M.circle_overlaps(c, 0.5)
    outside = int(((np.abs(c[:, 0]) > 10.0) | (c[:, 1] < 0.5 - 1e-3) | (c[:, 1] > 20.0 + 1e-3)).sum())
    return [Fig("confined.max_overlap_10s", "confined", mx, "m",
                "deepest disc-disc overlap (1 m - centre distance) at t = 10 s (625 discs of r 0.5 in a box "
                "too small for them: some overlap must remain)", {"mean_overlap": mean}),
            Fig("confined.max_speed_8_10s", "confined", M.max_speed(tr, 8.0, 10.0), "m/s",
                "largest disc speed over 8..10 s"),
            Fig("confined.outside_10s", "confined", outside, "discs",
                "disc centres outside the box's inner region (|x| > 10 or y outside 0.5..20) at t = 10 s")]


def fig_card_house(run):
    tr, desc, sim = run("card_house", 10.0)
    dyn = np.array([b.get("kind", "dynamic") == "dynamic" for b in desc["bodies"]])
    drop = float(tr.origin[0, tr.i("top"), 1] - tr.origin[tr.k(10.0), tr.i("top"), 1])
    return [Fig("card_house.top_displacement_10s", "card_house", M.displacement(tr, "top", 10.0), "m",
                "|origin(10 s) - origin(0)| of the top card (the last card created, top storey)",
                {"issue_18_quotes": 0.04}),
            Fig("card_house.max_card_displacement_10s", "card_house", M.max_displacement(tr, 10.0, 0.0, dyn), "m",
                "largest |origin(10 s) - origin(0)| over all cards"),
            Fig("card_house.top_drop_10s", "card_house", drop, "m", "how far the top card's origin fell in 10 s")]


def fig_high_mass_ratio(run):
    out = []
    tr, desc, sim = run("high_mass_ratio_1", 10.0)
    dyn = np.array([b.get("kind", "dynamic") == "dynamic" for b in desc["bodies"]])
    d = [M.displacement(tr, f"top{j}", 10.0) for j in range(3)]
    out += [Fig("high_mass_ratio_1.top_displacement_10s_max", "high_mass_ratio_1", max(d), "m",
                "largest over the 3 pyramids of the heavy top box's |origin(10 s) - origin(0)| (it falls 2 m onto "
                "its pyramid: ~2 m = held, more = collapse)", {"per_pyramid": d, "issue_18_quotes": 2.2}),
            Fig("high_mass_ratio_1.max_displacement_10s", "high_mass_ratio_1", M.max_displacement(tr, 10.0, 0, dyn),
                "m", "largest |origin(10 s) - origin(0)| over all boxes"),
            Fig("high_mass_ratio_1.rest_displacement_10s", "high_mass_ratio_1", _from_rest(tr, desc, dyn), "m",
                "largest distance at t = 10 s of any box from where it rests: its start, a heavy top box's start "
                "2 m lower (on its pyramid; the pyramids crushed or not, whatever the fall)")]
    for n, rest in (("high_mass_ratio_2", 11.0), ("high_mass_ratio_3", 11.0)):
        tr, desc, sim = run(n, 10.0)
        y = float(tr.origin[tr.k(10.0), tr.i("big"), 1])
        side = max(M.displacement(tr, "left", 10.0), M.displacement(tr, "right", 10.0))
        out += [Fig(f"{n}.big_sink_10s", n, rest - y, "m",
                    f"big box's resting height {rest:g} m (on the small bodies) minus its origin y at t = 10 s"),
                Fig(f"{n}.small_displacement_10s", n, side, "m",
                    "larger |origin(10 s) - origin(0)| of the two small bodies")]
    return out


def _from_rest(tr, desc, dyn):
    """high_mass_ratio_1's largest distance of a dynamic box from its resting place at 10 s."""
    k = tr.k(10.0)
    rest = np.array(tr.origin[0], dtype=float)
    for j in range(3):
        rest[tr.i(f"top{j}"), 1] -= 2.0
    return float(np.linalg.norm(tr.origin[k] - rest, axis=1)[dyn].max())


def fig_overlap_recovery(run):
    tr, desc, sim = run("overlap_recovery", 10.0)
    i = tr.i("top")
    k = tr.k(10.0)
    return [Fig("overlap_recovery.max_push_speed", "overlap_recovery", M.max_speed(tr), "m/s",
                "largest centre-of-mass speed of any box over 0..10 s (the push-out speed)", {"issue_18_quotes": 3.4}),
            Fig("overlap_recovery.top_height_error_10s", "overlap_recovery", float(tr.origin[k, i, 1] - 3.5), "m",
                "top box's y(10 s) minus 3.5 m (its height in the same pyramid without overlap)",
                {"issue_18_quotes": "within 2 mm"}),
            Fig("overlap_recovery.top_dx_10s", "overlap_recovery", float(tr.origin[k, i, 0] - tr.origin[0, i, 0]),
                "m", "top box's sideways move over 0..10 s")]


def fig_tiny_pyramid(run):
    tr, desc, sim = run("tiny_pyramid", 10.0)
    d = M.displacement(tr, "top", 10.0)
    return [Fig("tiny_pyramid.top_displacement_10s", "tiny_pyramid", d / 0.05, "box sizes",
                "|origin(10 s) - origin(0)| of the top box, in box sizes (0.05 m)", {"metres": d,
                                                                                        "issue_18_quotes": 1.34})]


def fig_cart(run):
    out = []
    for sub in (4, 12):
        tr, desc, sim = run("cart", 10.0, substeps=sub, scene_kw={"substeps": sub})
        i = tr.i("chassis")
        k5 = tr.k(5.0)
        vy = tr.v[k5:, i, 1]
        sep = float(np.abs(tr.joint_sep[k5:]).max())
        out += [Fig(f"cart.chassis_sink_10s.substeps{sub}", "cart", 0.25 - float(tr.origin[tr.k(10.0), i, 1]), "m",
                    f"{sub} sub-steps: chassis origin's resting height 0.25 m (wheels r 0.1 on the ground, axles 0.15 m "
                    "below the origin) minus its y at t = 10 s (0.25: the wheels were pushed into the ground and the "
                    "chassis rests on it)", {"wheel_y_10s": [float(tr.origin[tr.k(10.0), tr.i(w), 1])
                                                             for w in ("wheel1", "wheel2")]}),
                Fig(f"cart.chassis_vy_rms_5_10s.substeps{sub}", "cart", float(math.sqrt((vy ** 2).mean())), "m/s",
                    f"{sub} sub-steps: rms vertical speed of the chassis over 5..10 s (bounce)"),
                Fig(f"cart.max_joint_separation_5_10s.substeps{sub}", "cart", sep, "m",
                    f"{sub} sub-steps: largest axle joint separation over 5..10 s")]
    return out


def fig_multiple_prismatic(run):
    tr, desc, sim = run("multiple_prismatic", 10.0)
    k = tr.k(10.0)
    return [Fig("multiple_prismatic.top_sag_10s", "multiple_prismatic",
                6.6 - float(tr.origin[k, tr.i("top"), 1]), "m",
                "top box's design height 6.6 m minus its origin y at t = 10 s"),
            Fig("multiple_prismatic.max_joint_separation_10s", "multiple_prismatic",
                float(np.abs(tr.joint_sep[k]).max()), "m", "largest prismatic joint separation at t = 10 s")]


SAMPLE_FIGURES = (fig_single_box, fig_tilted_stack, fig_vertical_stack, fig_circle_stack, fig_capsule_stack,
                  fig_cliff, fig_arch, fig_double_domino, fig_confined, fig_card_house, fig_high_mass_ratio,
                  fig_overlap_recovery, fig_tiny_pyramid, fig_cart, fig_multiple_prismatic)
