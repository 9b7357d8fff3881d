"""The seed's solver modes (impulse, penalty, hybrid) against analytic answers."""
import math

import numpy as np
import pytest

import physics
from seed_scenes import bounce_height, box_on, ground, resting_range, slope_run, world

MODES = ["impulse", "penalty", "hybrid"]


# RK4 keeps the free flight exact, so the figures measure the contact model alone
@pytest.mark.parametrize("mode", ["impulse", "hybrid"])
def test_restitution_bounce_heights(mode):
    h, _, _ = bounce_height(mode, 0.5, integrator="rk4")
    assert h == pytest.approx(0.25, rel=0.10)
    h, _, _ = bounce_height(mode, 0.0, integrator="rk4")
    assert h < 0.01
    h, _, _ = bounce_height(mode, 1.0, integrator="rk4")
    assert h == pytest.approx(1.0, rel=0.05)


def energy_after_elastic_bounce(correction, projection):
    w = world("impulse", "rk4", dt=1 / 30, energy_correction=correction, projection=projection)
    ground(w)
    b = box_on(w, height=1.0, restitution=1.0)
    e0 = w.kinetic_energy() + w.potential_energy()
    while not (b.velocity[1] > 0 and b.position[1] > 0.6):
        w.step()
    return (w.kinetic_energy() + w.potential_energy()) / e0 - 1.0


@pytest.mark.parametrize("projection", ["linear", "nonlinear"])
def test_energy_correction_removes_push_out_energy(projection):
    # the push-out lifts the body by the depth gravity pulled it in: without eq. 2 that
    # potential energy is a gain; with it the bounce conserves energy
    off = energy_after_elastic_bounce(False, projection)
    on = energy_after_elastic_bounce(True, projection)
    assert off > 0.02
    assert abs(on) < 0.005


@pytest.mark.parametrize("mode", MODES)
def test_static_friction_holds_on_20_degrees(mode):
    drift, _, _ = slope_run(mode, 20.0, 0.6)
    assert abs(drift) < 0.01


@pytest.mark.parametrize("mode", MODES)
def test_dynamic_friction_slide_on_30_degrees(mode):
    _, acc, _ = slope_run(mode, 30.0, (0.4, 0.2))
    th = math.radians(30)
    assert acc == pytest.approx(9.81 * (math.sin(th) - 0.2 * math.cos(th)), rel=0.05)


@pytest.mark.parametrize("mode", MODES)
def test_head_on_collision_conserves_momentum(mode):
    w = world(mode, gravity=(0.0, 0.0))
    a = w.add_body(physics.Polygon.box(1, 1), position=(-1.0, 0.0), velocity=(2.0, 0.0), restitution=1.0)
    b = w.add_body(physics.Polygon.box(1, 1), position=(1.0, 0.0), velocity=(-1.0, 0.0), density=2.0,
                   restitution=1.0)
    p0 = np.array(w.linear_momentum())
    k0 = w.kinetic_energy()
    for _ in range(90):
        w.step()
    assert np.abs(np.array(w.linear_momentum()) - p0).max() <= 1e-9 * np.abs(p0).max()
    assert a.velocity[0] < 0.0 < b.velocity[0]  # they did collide
    # a penalty spring with zeta = 0 gains ~2 % over a contact from the sub-step discretisation
    assert w.kinetic_energy() == pytest.approx(k0, rel=0.03 if mode == "penalty" else 0.01)


@pytest.mark.parametrize("mode", MODES)
def test_resting_box_does_not_jitter(mode):
    spread, speed, sink = resting_range(mode)
    assert spread < 1e-3 and speed < 1e-3 and sink < 1e-3


@pytest.mark.parametrize("mode,projection", [("impulse", "linear"), ("impulse", "nonlinear"),
                                             ("hybrid", "linear"), ("penalty", "linear")])
def test_stack_of_three_stays(mode, projection):
    w = world(mode, **({} if mode == "penalty" else {"projection": projection}))
    ground(w)
    boxes = [w.add_body(physics.Polygon.box(1, 1), position=(0.0, 0.5 + i)) for i in range(3)]
    for _ in range(300):
        w.step()
    top = boxes[-1].position
    # without warm starting the sequential impulses leave a slow sideways creep (mm/s)
    assert abs(top[0]) < 0.03 and abs(top[1] - 2.5) < 0.01 and abs(boxes[-1].angle) < 0.01


def test_nonlinear_projection_resolves_a_deep_corner():
    # a box tilted 30 degrees with a corner 5 cm into the ground and no velocity
    w = world("impulse", projection="nonlinear", gravity=(0.0, 0.0))
    ground(w)
    q = math.radians(30)
    low = 0.5 * (math.cos(q) + math.sin(q))  # centre height with the corner on the surface
    b = w.add_body(physics.Polygon.box(1, 1), position=(0.0, low - 0.05), angle=q)
    w.step()
    w.step()
    c = w.contacts()
    assert not c or max(x.depth for x in c) < 2e-3
    assert b.angle != q  # part of the push-out was a rotation (seed eqs. 3-7)


def test_penalty_settings_and_stages():
    w = world("penalty")
    box_on(w)
    assert w.settings["contact_hertz"] == 25.0
    assert "forces:penalty_contacts" in w.info()["stages"]
    w.solver = "hybrid"
    assert w.settings["impact_speed"] == -1.0
    w.solver = "impulse"
    assert "projection:linear" in w.info()["stages"]
    with pytest.raises(ValueError):
        w.settings["projection"] = "sideways"
