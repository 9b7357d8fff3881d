"""world.pair_filter (issue 15): asked once per new pair; False drops contact and events."""
import pytest

import physics


def _scene(sleeping=True):
    w = physics.World(sleeping=sleeping)
    ground = w.add_body(physics.Polygon.box(20, 1), kind="static", position=(0, -0.5))
    balls = [w.add_body(physics.Circle(0.3), position=(x, 1)) for x in (-2, 0, 2)]
    return w, ground, balls


def test_called_once_per_new_pair_and_false_drops_the_contact():
    w, ground, balls = _scene()
    calls = []
    dropped = balls[1].fixtures[0]

    def fn(a, b):
        calls.append((a.id, b.id))
        return dropped not in (a, b)
    w.pair_filter = fn
    begins = []
    for _ in range(120):  # two balls land and rest; the middle one falls through the ground
        w.step()
        begins += w.contact_events().begin
    assert sorted(calls) == sorted((ground.fixtures[0].id, b.fixtures[0].id) for b in balls)
    assert all(a < b for a, b in calls)  # fixture_a: the lower id
    assert sorted(e.fixture_b.id for e in begins) == [balls[0].fixtures[0].id, balls[2].fixtures[0].id]
    assert balls[1].position[1] < -5 and abs(balls[0].position[1] - 0.3) < 0.02
    assert all(dropped not in (c.fixture_a, c.fixture_b) for c in w.contacts())


def test_a_filtered_sensor_pair_reports_nothing():
    w, ground, balls = _scene()
    zone = w.add_body(physics.Polygon.box(8, 1), kind="static", position=(0, 1)).fixtures[0]
    zone.sensor = True
    seen = []
    w.pair_filter = lambda a, b: (seen.append((a, b)), b is not balls[0].fixtures[0])[1]
    w.step()
    assert set(w.sensor_events().begin) == {(zone, balls[1].fixtures[0]), (zone, balls[2].fixtures[0])}
    assert (zone, balls[0].fixtures[0]) in seen  # a sensor pair is asked with the sensor first


def test_setting_a_new_filter_asks_again_and_none_removes_it():
    w, ground, balls = _scene(sleeping=False)  # sleeping pairs are not reported: nothing to ask
    n = []
    w.pair_filter = lambda a, b: n.append(1) or True
    for _ in range(60):
        w.step()
    assert len(n) == 3
    w.pair_filter = lambda a, b: n.append(1) or True
    w.step()
    assert len(n) == 6
    w.pair_filter = None
    w.step()
    assert len(n) == 6 and len(w.contacts()) == 3


def test_pair_filter_must_be_callable():
    w = physics.World()
    with pytest.raises(ValueError, match="pair_filter"):
        w.pair_filter = 3
