"""Generate the shipped scenes (scenes/*.json) and the published schema.

    .venv/bin/python scenes/make_scenes.py            # every scene and stelkropp.schema.json
    .venv/bin/python scenes/make_scenes.py arch car   # just these scenes
    .venv/bin/python scenes/make_scenes.py --schema   # just the schema

The JSON files are committed; this script documents how they were made.
Each scene is plain data, then loaded and saved through physics.scene so
the file is in the canonical form ``world.save_scene`` writes (a reloaded
scene saves byte-for-byte the same).  Random placement uses fixed seeds.
"""
from __future__ import annotations

import math
import random
import sys
from pathlib import Path
from types import SimpleNamespace

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
sys.path.insert(0, str(HERE))

from physics.scene import scene_from_dict, scene_to_dict, scene_metadata  # noqa: E402
from physics.scene.atomic import write_atomic  # noqa: E402
from physics.scene.json_io import dumps  # noqa: E402
from physics.scene.schema import SCHEMA_FILE, schema_text  # noqa: E402

from scene_kit import DT, G, body, box, ground, poly, r, scene, spring, static  # noqa: E402,F401
from joint_scenes import JOINT_SCENES  # noqa: E402
import shape_scenes  # noqa: E402


# -- helpers ----------------------------------------------------------------
def domino(w, h, x, name, tip=0.0, **kw):
    """An upright box standing on y = 0 at x, or tipped forwards by ``tip`` radians about its
    bottom-right corner (past the tipping angle atan(w/h) it falls and starts the chain)."""
    c, s = math.cos(tip), math.sin(tip)
    cx = x + 0.5 * w - (0.5 * w * c - 0.5 * h * s)   # keep the pivot corner where it stood
    cy = 0.5 * w * s + 0.5 * h * c
    extra = {"angle": r(-tip)} if tip else {}
    return body(box(w, h), cx, cy, name, **extra, **kw)


def pyramid_boxes(base, x0=0.0, y0=0.0, size=1.0, gap=0.05, prefix="b"):
    out = []
    for row in range(base):
        count = base - row
        for i in range(count):
            x = x0 + (i - 0.5 * (count - 1)) * (size + gap)
            out.append(body(box(size, size), x, y0 + 0.5 * size + row * size, f"{prefix}{len(out)}",
                            friction=0.6))
    return out


# -- the scenes -------------------------------------------------------------
def pyramid(base=20, name="Pyramid 20"):
    n = base * (base + 1) // 2
    return scene(name, f"{n} unit boxes (friction 0.6) in a pyramid of base {base} on a static ground box. "
                       "A solver's stacking test: a good one holds it still and lets it fall asleep.",
                 [ground(max(40.0, base * 1.5))] + pyramid_boxes(base),
                 camera={"center": [0.0, base / 2.0], "zoom": 600.0 / (base * 1.3)},
                 settings={"substeps": 4})


def pyramid_large():
    return pyramid(40, "Pyramid 40")


def card_house():
    L, t, th = 1.2, 0.04, math.radians(18.0)
    floors = 4
    bodies = [ground(30.0, friction=0.9)]
    y = 0.0
    for level in range(floors):
        n = floors - level
        span = 1.0
        apexes = [(i - 0.5 * (n - 1)) * span for i in range(n)]
        cy = y + 0.5 * L * math.cos(th) + 0.5 * t * math.sin(th)
        for k, x0 in enumerate(apexes):
            # leaning pair: the top inner corners overlap by 2 mm so the two cards hold each other
            dx = 0.5 * L * math.sin(th) + 0.5 * t * math.cos(th) - 0.001
            for side, ang in ((-1, -th), (1, th)):
                bodies.append(body(box(t, L), x0 + side * dx, cy, f"card{level}_{k}{'lr'[side > 0]}",
                                   angle=r(ang), friction=0.9))
        top = cy + 0.5 * L * math.cos(th) + 0.5 * t * math.sin(th)
        if level < floors - 1:
            width = (n - 1) * span + 0.6
            bodies.append(body(box(width, t), 0.0, top + 0.5 * t, f"floor{level}", friction=0.9))
            y = top + t
    return scene("Card house", "A four-storey house of cards: leaning pairs held by friction (0.9) and by "
                               "each other, with flat cards between storeys.  Try dragging out one card of the "
                               "bottom storey and watch the house fall.",
                 bodies, camera={"center": [0.0, 2.5], "zoom": 110.0})


def arch():
    r_in, r_out, stones = 4.0, 5.0, 11
    bodies = [ground(30.0, friction=0.8)]
    for k in range(stones):
        a0, a1 = math.pi * k / stones, math.pi * (k + 1) / stones
        pts = [(r_in * math.cos(a0), r_in * math.sin(a0)), (r_out * math.cos(a0), r_out * math.sin(a0)),
               (r_out * math.cos(a1), r_out * math.sin(a1)), (r_in * math.cos(a1), r_in * math.sin(a1))]
        cx, cy = sum(p[0] for p in pts) / 4, sum(p[1] for p in pts) / 4
        # the end stones sit on the ground: snap their bottom edge to exactly y = 0
        if k == 0:
            pts[0], pts[1] = (r_in, 0.0), (r_out, 0.0)
        if k == stones - 1:
            pts[2], pts[3] = (-r_out, 0.0), (-r_in, 0.0)
        bodies.append(body(poly([(x - cx, y - cy) for x, y in pts]), cx, cy, f"voussoir{k}",
                           density=2.0, friction=0.8))
    # a few loads on the crown: general convex polygons too
    bodies.append(body(poly([(-0.6, 0.0), (0.6, 0.0), (0.4, 0.5), (-0.3, 0.6)]), 0.0, 5.05, "load_quad"))
    bodies.append(body({"regular": {"sides": 5, "radius": 0.4}}, 0.05, 6.1, "load_pentagon"))
    return scene("Arch", f"A semicircular arch of {stones} voussoirs (trapezoids computed from the two radii "
                         f"{r_in} and {r_out} m) standing by friction and compression alone, with loads on top.",
                 bodies, camera={"center": [0.0, 3.0], "zoom": 55.0})


def dominoes():
    bodies = [ground(60.0)]
    x, w, h = -16.0, 0.2, 1.0
    for k in range(18):
        bodies.append(domino(w, h, x, f"domino{k}", tip=0.35 if k == 0 else 0.0, friction=0.5))
        x += 0.75 * h + w
        w, h = w * 1.08, h * 1.08
    return scene("Dominoes", "18 dominoes, each 8% larger than the one before; the first is tipped "
                             "past its balance point and the chain reaction amplifies.",
                 bodies, camera={"center": [2.0, 3.0], "zoom": 22.0})


def friction_ramp():
    th = math.radians(25.0)
    c, s = math.cos(th), math.sin(th)
    bodies = []
    length, thick = 10.0, 0.5
    for lane, mu in enumerate((0.05, 0.2, 0.8)):
        base = 7.0 * lane
        # ramp descending to the right, its lower end at (0, base); top surface through that point
        mid_surface = (-0.5 * length * c, base + 0.5 * length * s)
        ramp_c = (mid_surface[0] + 0.5 * thick * -s, mid_surface[1] - 0.5 * thick * c)
        bodies.append(static(box(length, thick), ramp_c[0], ramp_c[1], f"ramp{lane}", angle=r(-th), friction=1.0))
        bodies.append(static(box(12.0, thick), 6.0 - 0.05, base - 0.5 * thick, f"shelf{lane}", friction=1.0))
        bodies.append(static(box(0.5, 1.5), 12.2, base + 0.75, f"stop{lane}"))
        along = -0.35 * length  # from the middle towards the top
        px = mid_surface[0] + along * c + 0.5 * s
        py = mid_surface[1] - along * s + 0.5 * c
        bodies.append(body(box(1.0, 1.0), px, py, f"box_mu{mu}", angle=r(-th), friction=mu))
    return scene("Friction ramp", "Three 25 degree ramps (friction 1) with one box each: friction 0.05, 0.2 "
                                  "and 0.8.  Friction combines by the geometric mean (0.22, 0.45, 0.89 against "
                                  "tan 25 = 0.47): the first slides fast, the second creeps, the third sticks.",
                 bodies, camera={"center": [1.5, 8.8], "zoom": 22.0})


def restitution_row():
    bodies = [ground(20.0)]
    for k, e in enumerate((0.0, 0.25, 0.5, 0.75, 1.0)):
        bodies.append(body({"circle": 0.4}, -4.0 + 2.0 * k, 6.0, f"ball_e{e}", restitution=e))
    return scene("Restitution row", "Five balls dropped from 6 m with restitution 0, 0.25, 0.5, 0.75 and 1 "
                                    "(contacts take the larger of the two coefficients; the ground's is 0).",
                 bodies, camera={"center": [0.0, 3.5], "zoom": 55.0})


def spring_playground():
    bodies, springs = [], []
    k, m = 40.0, 1.0
    for i in range(3):
        x = -9.0 + 2.5 * i
        bodies.append(body(box(1.0, 1.0), x, 3.75, f"mass{i}", density=m))
        # pulled 1 m down from the equilibrium (rest 2 m + sag m g / k = 0.25 m)
        springs.append(spring(f"mass{i}", None, [0.0, 0.5], [x, 7.5], k, 0.0, 2.0, f"oscillator{i}"))
    # a swinging spring pendulum and a two-mass chain, for play
    bodies.append(body({"circle": 0.35}, 3.5, 5.0, "bob"))
    springs.append(spring("bob", None, [0.0, 0.0], [1.0, 8.0], 30.0, 0.05, 2.5, "pendulum"))
    bodies.append(body({"regular": {"sides": 6, "radius": 0.4}}, 7.0, 5.5, "chain0"))
    bodies.append(body({"regular": {"sides": 6, "radius": 0.4}}, 7.0, 3.5, "chain1"))
    springs.append(spring("chain0", None, [0.0, 0.0], [7.0, 8.0], 60.0, 0.0, 2.0, "chain_top"))
    springs.append(spring("chain1", "chain0", [0.0, 0.0], [0.0, 0.0], 60.0, 0.0, 1.5, "chain_link"))
    return scene("Spring playground",
                 "Three identical undamped oscillators (1 kg on 40 N/m, released 1 m below equilibrium), a "
                 "spring pendulum and a two-mass chain.  The integrator is a world setting: switch it live in "
                 "the sandbox's solver panel (euler / symplectic_euler / rk4; it applies to the modes that "
                 "integrate forces explicitly, e.g. penalty and impulse), or headless with "
                 "`--set integrator=rk4`, and compare amplitudes: explicit Euler gains energy, symplectic "
                 "Euler keeps it bounded, RK4 loses a little.",
                 bodies, springs, camera={"center": [-1.0, 4.5], "zoom": 40.0})


def chain_bridge():
    planks, w, h = 16, 0.9, 0.2
    span = planks * w + (planks + 1) * 0.1
    bodies = [ground(40.0, y=-3.0),
              static(box(1.0, 3.0), -0.5 * span - 0.5, -1.5, "tower_left"),
              static(box(1.0, 3.0), 0.5 * span + 0.5, -1.5, "tower_right")]
    springs = []
    x0 = -0.5 * span + 0.1 + 0.5 * w
    for i in range(planks):
        bodies.append(body(box(w, h), x0 + i * (w + 0.1), -0.1, f"plank{i}", density=2.0))
    kw = dict(k=300.0, c=2.0)
    springs.append(spring("plank0", "tower_left", [-0.5 * w, 0.0], [0.5, 1.4], name="anchor_left", **kw))
    for i in range(planks - 1):
        springs.append(spring(f"plank{i}", f"plank{i + 1}", [0.5 * w, 0.0], [-0.5 * w, 0.0],
                              name=f"link{i}", **kw))
    springs.append(spring(f"plank{planks - 1}", "tower_right", [0.5 * w, 0.0], [-0.5, 1.4],
                          name="anchor_right", **kw))
    for k, x in enumerate((-3.0, -0.5, 2.5)):
        bodies.append(body(box(0.8, 0.8), x, 2.0 + k, f"crate{k}", density=0.5))
    return scene("Chain bridge", f"{planks} planks linked end to end by damped springs (300 N/m) between two "
                                 "towers, sagging under three crates.",
                 bodies, springs, camera={"center": [0.0, 0.5], "zoom": 45.0})


def soft_body():
    bodies, springs = [ground(30.0)], []
    # walls at the ground's ends: a blob that rolls off the edge would fall out of the world bound
    bodies += [static(box(1.0, 4.0), sx * 14.5, 2.0, f"wall_{side}") for sx, side in ((-1, "left"), (1, "right"))]
    bodies.append(static(poly([(-1.5, 0.0), (1.5, 0.0), (0.0, 1.2)]), 1.0, 0.0, "wedge"))
    nx = ny = 5
    gap, rad = 0.4, 0.15

    def nm(b, i, j):
        return f"blob{b}_{i}_{j}"

    for b, (bx, by) in enumerate(((-0.2, 4.0), (-4.0, 2.0))):
        for i in range(nx):
            for j in range(ny):
                bodies.append(body({"circle": rad}, bx + i * gap, by + j * gap, nm(b, i, j), friction=0.4))
        for i in range(nx):
            for j in range(ny):
                for di, dj in ((1, 0), (0, 1), (1, 1), (1, -1)):
                    ii, jj = i + di, j + dj
                    if 0 <= ii < nx and 0 <= jj < ny:
                        springs.append(spring(nm(b, i, j), nm(b, ii, jj), [0, 0], [0, 0], 30.0, 0.1))
    return scene("Soft body", "Two blobs of 25 small discs each, tied to their neighbours by springs "
                              "(structural and shear, 30 N/m), dropping onto a wedge and the ground between two walls.",
                 bodies, springs, camera={"center": [0.0, 3.0], "zoom": 28.0})


def mass_ratio():
    bodies = [ground(20.0)]
    bodies.append(body(box(1.0, 1.0), -3.0, 0.5, "light_bottom", density=1.0))
    bodies.append(body(box(1.0, 1.0), -3.0, 1.5, "heavy_top", density=100.0))
    bodies.append(body(box(0.6, 0.6), 2.0, 0.3, "small_bottom", density=1.0 / 0.36))
    bodies.append(body(box(2.0, 2.0), 2.0, 1.6, "big_top", density=25.0))
    bodies.append(body(box(1.0, 1.0), 6.0, 0.5, "tower0", density=1.0))
    bodies.append(body(box(1.0, 1.0), 6.0, 1.5, "tower1", density=10.0))
    bodies.append(body(box(1.0, 1.0), 6.0, 2.5, "tower2", density=100.0))
    return scene("Mass ratio", "A 100 kg box on a 1 kg box, a 100 kg 2 m box on a 1 kg 0.6 m box, and a "
                               "1 / 10 / 100 kg tower.  Iterative solvers struggle with large mass ratios.  Try "
                               "another solver mode (Solver panel) and see which keep the heavy boxes on top.",
                 bodies, camera={"center": [1.5, 2.0], "zoom": 60.0})


def rain():
    width, height = 40.0, 12.0
    bodies = [static(box(width + 2.0, 1.0), 0.0, -0.5, "floor"),
              static(box(1.0, height), -0.5 * width - 0.5, 0.5 * height, "wall_left"),
              static(box(1.0, height), 0.5 * width + 0.5, 0.5 * height, "wall_right")]
    rng = random.Random(1000)
    cols, spacing = 38, 1.02
    for k in range(1000):
        row, col = divmod(k, cols)
        # sizes keep every shape inside a 1 m circle whatever its angle: no overlaps at the start
        x = (col - 0.5 * (cols - 1)) * spacing
        y = 14.0 + row * spacing
        size = rng.uniform(0.3, 0.9)
        pick = rng.random()
        if pick < 0.4:
            shape = box(rng.uniform(0.3, 0.7), rng.uniform(0.3, 0.7))
        elif pick < 0.7:
            shape = {"circle": r(0.5 * size)}
        else:
            shape = {"regular": {"sides": rng.choice((3, 5, 6, 8)), "radius": r(0.5 * size)}}
        bodies.append(body(shape, x, y, None, angle=r(rng.uniform(0, math.pi)),
                           velocity=[r(rng.uniform(-0.5, 0.5)), -2.0], friction=0.5,
                           restitution=r(rng.choice((0.0, 0.0, 0.2)))))
    return scene("Rain", "1000 boxes, discs and polygons of mixed sizes (0.3 to 0.9 m) raining into a "
                         "40 m wide open static container.",
                 bodies, camera={"center": [0.0, 12.7], "zoom": 18.0})


def default():
    bodies, springs = [ground(60.0, friction=0.7)], []
    bodies.append(static(box(1.0, 4.0), -29.5, 2.0, "wall_left"))
    bodies.append(static(box(1.0, 4.0), 29.5, 2.0, "wall_right"))
    bodies += pyramid_boxes(10, x0=-14.0, prefix="pyramid")
    # dominoes in a row, the first already leaning in
    for k in range(12):
        bodies.append(domino(0.2, 1.2, -4.0 + 0.8 * k, f"domino{k}", tip=0.3 if k == 0 else 0.0, friction=0.5))
    # a tower of mixed polygons
    for k in range(8):
        shape = {"regular": {"sides": 6 if k % 2 else 8, "radius": 0.55}}
        bodies.append(body(shape, 9.5, 0.51 + 1.05 * k, f"tower{k}", friction=0.8))
    # bouncing balls
    for k, e in enumerate((0.3, 0.6, 0.9)):
        bodies.append(body({"circle": 0.4}, 13.0 + 1.2 * k, 6.0 + k, f"ball{k}", restitution=e))
    # a seesaw with a heavy box waiting above one end
    bodies.append(static(poly([(-0.6, 0.0), (0.6, 0.0), (0.0, 0.8)]), 19.0, 0.0, "fulcrum"))
    bodies.append(body(box(6.0, 0.2), 19.0, 0.9, "seesaw", friction=0.8))
    bodies.append(body(box(0.6, 0.6), 16.5, 1.3, "light_box", friction=0.8))
    bodies.append(body(box(1.0, 1.0), 21.5, 6.0, "heavy_box", density=5.0))
    # a hanging spring pendulum and a little soft chain
    bodies.append(body({"circle": 0.5}, 25.0, 6.5, "pendulum_bob", velocity=[-3.0, 0.0]))
    springs.append(spring("pendulum_bob", None, [0.0, 0.0], [25.0, 10.0], 80.0, 0.2, 3.0, "pendulum"))
    for k in range(6):
        bodies.append(body(box(0.5, 0.5), 2.0 + 0.9 * k, 9.0, f"chain{k}", friction=0.5))
    springs.append(spring("chain0", None, [-0.25, 0.0], [1.5, 9.0], 150.0, 1.0, name="chain_anchor_left"))
    for k in range(5):
        springs.append(spring(f"chain{k}", f"chain{k + 1}", [0.25, 0.0], [-0.25, 0.0], 150.0, 1.0,
                              name=f"chain_link{k}"))
    springs.append(spring("chain5", None, [0.25, 0.0], [6.9, 9.0], 150.0, 1.0, name="chain_anchor_right"))
    # a shower of mixed shapes over the middle
    rng = random.Random(42)
    for k in range(40):
        x, y = -28.0 + (k % 10) * 1.0, 6.0 + (k // 10) * 1.2
        pick = k % 4
        shape = (box(0.6, 0.6) if pick == 0 else {"circle": 0.35} if pick == 1
                 else {"regular": {"sides": 3 + k % 5, "radius": 0.4}} if pick == 2
                 else poly([(-0.4, -0.3), (0.45, -0.25), (0.3, 0.35), (-0.2, 0.4)]))
        bodies.append(body(shape, x, y, None, angle=r(rng.uniform(0, math.pi)), friction=0.6,
                           restitution=r(rng.choice((0.0, 0.2, 0.4)))))
    return scene("Welcome to Stelkropp",
                 "A bit of everything: a pyramid, dominoes, a polygon tower, bouncing balls, a seesaw about "
                 "to be hit, a spring pendulum, a chain of boxes on springs and a shower of shapes.  Grab "
                 "anything with the mouse; switch solvers in the solver panel.",
                 bodies, springs, camera={"center": [0.0, 4.5], "zoom": 14.5})


SCENES = {
    "pyramid": pyramid, "pyramid_large": pyramid_large, "card_house": card_house, "arch": arch,
    "dominoes": dominoes, "friction_ramp": friction_ramp, "restitution_row": restitution_row,
    "spring_playground": spring_playground, "chain_bridge": chain_bridge, "soft_body": soft_body,
    "mass_ratio": mass_ratio, "rain": rain, "default": default,
    **JOINT_SCENES,
}
# the scenes of bodies made of many shapes (the tumbler's drum among them): shape_scenes.py
SCENES.update(shape_scenes.scenes(SimpleNamespace(scene=scene, body=body, static=static, box=box, r=r,
                                                  ground=ground)))


def canonical(data: dict) -> str:
    """Validate, build and save through the library: the file is what save_scene writes."""
    world = scene_from_dict(data, source=data["name"])
    return dumps(scene_to_dict(world, scene_metadata(world)))


def write_schema() -> None:
    write_atomic(HERE / SCHEMA_FILE, schema_text())


def main(argv) -> None:
    names = [a for a in argv if not a.startswith("-")]
    if "--schema" in argv and not names:
        write_schema()
        return
    write_schema()
    for name in names or SCENES:
        text = canonical(SCENES[name]())
        write_atomic(HERE / f"{name}.json", text)
        print(f"scenes/{name}.json: {text.count(chr(10))} lines")


if __name__ == "__main__":
    main(sys.argv[1:])
