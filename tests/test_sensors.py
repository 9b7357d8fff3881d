"""Sensor fixtures (issue 15): no mass, no contact response in any mode, exact-shape overlap
reported as begin/end events; filtering, sleeping visitors, other sensors; the scene field."""
import math

import numpy as np
import pytest

import physics
from physics.scene import scene_from_dict, scene_to_dict
from tests.event_pairs import Pairing

MODES = ["soft_step", "sequential_impulse", "impulse", "penalty", "hybrid"]


def _zone_world(solver="soft_step"):
    w = physics.World(solver=solver)
    w.add_body(physics.Polygon.box(20, 1), kind="static", position=(0, -0.5))
    zone = w.add_body(physics.Polygon.box(5, 1), kind="static", position=(0, 5), name="zone")
    zone.fixtures[0].sensor = True
    return w, zone.fixtures[0]


@pytest.mark.parametrize("solver", MODES)
def test_five_balls_falling_through_a_zone_begin_and_end_once_each(solver):
    w, zone = _zone_world(solver)
    balls = [w.add_body(physics.Circle(0.3), position=(x, 10)) for x in (-2, -1, 0, 1, 2)]
    log = Pairing()
    inside_max = 0
    for _ in range(150):  # 2.5 s: they pass the zone (y 4.5..5.5) by 1.15 s and rest on the ground
        w.step()
        log.sensors(w)
        inside_max = max(inside_max, len(zone.visitors))
    assert (log.begins, log.ends) == (5, 5)
    assert inside_max == 5  # side by side, all five were inside at once
    assert log.open == set() and w.sensor_overlaps() == []
    # the zone made no contact: every ball lies on the ground, none on the sensor
    assert all(abs(b.position[1] - 0.3) < 0.02 for b in balls)


@pytest.mark.parametrize("solver", MODES)
def test_a_sensor_never_pushes_and_weighs_nothing(solver):
    """A ball dropped through a sensor plate follows the same path as without the plate."""
    def run(with_plate):
        w = physics.World(solver=solver, sleeping=False)
        if with_plate:
            plate = w.add_body(physics.Polygon.box(4, 0.2), kind="static", position=(0, 2))
            plate.fixtures[0].sensor = True
        ball = w.add_body(physics.Circle(0.3), position=(0, 4))
        ys = []
        for _ in range(60):
            w.step()
            ys.append(ball.position[1])
            assert all(c.fixture_a.sensor is False and c.fixture_b.sensor is False for c in w.contacts())
        return ys
    assert run(True) == run(False)  # bit for bit: the plate changed nothing


def test_sensor_fixture_adds_no_mass_and_does_not_move_the_centre():
    w = physics.World()
    b = w.add_body(physics.Polygon.box(1, 1), position=(0, 0))
    m, com, inertia = b.mass, b.center_of_mass, b.inertia
    f = b.add_fixture(physics.Circle(2.0, offset=(3, 0)), sensor=True)
    assert f.sensor is True
    assert (b.mass, b.center_of_mass, b.inertia) == (m, com, inertia)
    f.sensor = False  # a solid disc of radius 2 at x = 3 now outweighs the box
    assert b.mass == pytest.approx(1.0 + math.pi * 4.0)
    assert b.center_of_mass[0] == pytest.approx(3 * math.pi * 4 / (1 + math.pi * 4))


def test_overlap_is_exact_shape_not_the_box():
    """A small box inside the circle sensor's AABB corner but outside the circle is not a visitor."""
    w = physics.World(gravity=(0, 0))
    zone = w.add_body(physics.Circle(1.0), kind="static")
    zone.fixtures[0].sensor = True
    corner = w.add_body(physics.Polygon.box(0.1, 0.1), position=(0.85, 0.85))  # |c| - 0.07 > 1
    inside = w.add_body(physics.Polygon.box(0.1, 0.1), position=(0.6, 0.6))   # |c| + 0.07 < 1
    w.step()
    assert w.sensor_events().begin == [(zone.fixtures[0], inside.fixtures[0])]
    assert zone.fixtures[0].visitors == [inside.fixtures[0]]
    assert corner.fixtures[0] not in zone.fixtures[0].visitors


def test_sensors_do_not_detect_sensors_and_a_moving_sensor_sees_static_fixtures():
    w = physics.World(gravity=(0, 0))
    ground = w.add_body(physics.Polygon.box(4, 1), kind="static", position=(0, -0.5))
    zone = w.add_body(physics.Polygon.box(4, 4), kind="static", position=(0, 2))
    zone.fixtures[0].sensor = True
    probe = w.add_body(physics.Polygon.box(0.2, 0.2), position=(0, 0.3))
    halo = probe.add_fixture(physics.Circle(0.5), sensor=True)  # reaches the ground and the zone
    w.step()
    begins = set(w.sensor_events().begin)
    assert begins == {(zone.fixtures[0], probe.fixtures[0]), (halo, ground.fixtures[0])}


def test_the_filter_applies_to_sensors():
    w, zone = _zone_world()
    zone.category = 0x2
    ball = w.add_body(physics.Circle(0.3), position=(0, 5))
    ball.fixtures[0].mask = 0x1  # collides with category 1 only: the zone does not see it
    w.step()
    assert w.sensor_events().begin == []
    ball.fixtures[0].mask = 0x3
    w.step()
    assert w.sensor_events().begin == [(zone, ball.fixtures[0])]


def test_a_visitor_asleep_inside_stays_inside_until_it_leaves():
    w = physics.World()
    w.add_body(physics.Polygon.box(20, 1), kind="static", position=(0, -0.5))
    zone = w.add_body(physics.Polygon.box(3, 3), kind="static", position=(0, 1.5))
    zone.fixtures[0].sensor = True
    box = w.add_body(physics.Polygon.box(1, 1), position=(0, 0.5))
    far = w.add_body(physics.Circle(0.3), position=(8, 60))  # keeps the world stepping while box sleeps
    log = Pairing()
    slept = False
    for _ in range(180):
        w.step()
        log.sensors(w)
        slept |= not box.awake
    assert slept and far.awake  # the box slept while the steps still ran
    assert log.open == {(zone.fixtures[0].id, box.fixtures[0].id)} and log.ends == 0
    box.position = (6, 0.5)  # out of the zone (wakes it)
    w.step()
    log.sensors(w)
    assert log.open == set() and log.ends == 1


def test_removing_a_visitor_ends_its_overlap_with_the_removed_fixture():
    w, zone = _zone_world()
    ball = w.add_body(physics.Circle(0.3), position=(0, 5))
    w.add_body(physics.Circle(0.3), position=(6, 8))
    w.step()
    assert len(w.sensor_events().begin) == 1
    f = ball.fixtures[0]
    w.remove(ball)
    w.step()
    assert w.sensor_events().end == [(zone, f)] and not f.alive
    w.step()
    assert w.sensor_events() == physics.SensorEvents([], [])


def test_sensor_property_validates():
    w = physics.World()
    b = w.add_body(physics.Polygon.box(1, 1))
    with pytest.raises(ValueError, match="sensor"):
        b.fixtures[0].sensor = "yes"
    with pytest.raises(ValueError, match="sensor"):
        b.fixtures[0].sensor = True  # a dynamic body needs a solid shape
    with pytest.raises(ValueError, match="sensor"):
        b.add_fixture(physics.Circle(1), sensor=1)
    assert b.fixtures[0].sensor is False and len(b.fixtures) == 1


def test_render_data_marks_sensor_fixtures():
    w, zone = _zone_world()
    rows = w.render_data().fixtures
    assert rows["sensor"].tolist() == [False, True]
    assert rows["id"][rows["sensor"]].tolist() == [zone.id]


def test_scene_round_trip_keeps_sensor():
    w, zone = _zone_world()
    b = w.add_body(physics.Polygon.box(1, 1), position=(0, 8))
    b.add_fixture(physics.Circle(1.5), sensor=True, name="halo")
    data = scene_to_dict(w)
    assert data["bodies"][1]["shape"]["sensor"] is True
    w2 = scene_from_dict(data)
    assert [f.sensor for bd in w2.bodies for f in bd.fixtures] == [False, True, False, True]
    assert scene_to_dict(w2) == data
    for _ in range(30):
        w.step()
        w2.step()
    assert w.state().tobytes() == w2.state().tobytes()


@pytest.mark.parametrize("value", ["yes", 1, None])
def test_scene_refuses_a_bad_sensor_value_naming_the_field(value):
    data = scene_to_dict(_zone_world()[0])
    data["bodies"][1]["shape"]["sensor"] = value
    with pytest.raises(physics.SceneError, match=r"bodies\[1\]\.shape\.sensor"):
        scene_from_dict(data)


def test_scene_refuses_a_dynamic_body_of_sensors_only():
    data = scene_to_dict(_zone_world()[0])
    data["bodies"][1]["kind"] = "dynamic"
    with pytest.raises(physics.SceneError, match=r"bodies\[1\].*sensor"):
        scene_from_dict(data)
