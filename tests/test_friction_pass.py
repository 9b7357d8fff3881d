"""soft_step's ``friction_pass`` (physics/constraints/contact_soft.py): wherever the friction rows
are solved (both passes, the relax pass only as Box2D v3, or relax only for face contacts between
two moving bodies), Coulomb's law holds.

A 1 m box slides at 3 m/s on an 8 x 0.5 m plank of four times its mass that rests on
frictionless ground (mu 0.5 between them, g 10; a 1 m box tips only above mu 1).  Friction
mu m g decelerates the box at 5 m/s^2 and drives the plank at 1.25 m/s^2 until they move
together at the shared momentum's 0.6 m/s, at t = 3 / 6.25 = 0.48 s, the box 0.72 m further on.
Their contact is a face contact between two moving bodies: the case "faces_in_relax" moves
to the relax pass.
"""
import numpy as np
import pytest

import physics
from builders import DT, ground, world

MU, G, V0 = 0.5, 10.0, 3.0


def sliding(fp):
    w = world(settings={"friction_pass": fp})
    ground(w, width=60.0, friction=0.0)
    plank = w.add_body(physics.Polygon.box(8.0, 0.5), position=(0.0, 0.25), friction=MU)
    box = w.add_body(physics.Polygon.box(1.0, 1.0), position=(-2.0, 1.0), friction=MU, velocity=(V0, 0.0))
    return w, plank, box


@pytest.mark.parametrize("fp", ["both", "relax", "faces_in_relax"])
def test_sliding_box_follows_coulomb(fp):
    w, plank, box = sliding(fp)
    for _ in range(12):  # 0.2 s: still sliding
        w.step()
    t = 12 * DT
    # a step's impulse acts over the whole step: at most one step (5/60 m/s) off the law
    assert box.velocity[0] == pytest.approx(V0 - MU * G * t, abs=0.09)
    assert plank.velocity[0] == pytest.approx(MU * G * t / 4.0, abs=0.03)
    for _ in range(48):  # 1 s: stuck, moving together
        w.step()
    assert box.velocity[0] == pytest.approx(0.6, abs=0.01)
    assert plank.velocity[0] == pytest.approx(0.6, abs=0.01)
    assert abs(box.angular_velocity) < 0.05 and abs(plank.angular_velocity) < 0.05


def test_friction_pass_is_validated():
    w = world()
    with pytest.raises(ValueError, match="friction_pass"):
        w.settings["friction_pass"] = "sometimes"
    assert w.settings["friction_pass"] == "faces_in_relax"
