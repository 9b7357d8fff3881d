"""dt is bounded above as well as below (physics.world.DT_MAX, one hour): World(dt=1e308) stepped
world.time to infinity without a word.  The scene format's maximum is the same number."""
import math

import pytest

import physics
from physics.scene import scene_from_dict
from physics.scene import schema as fmt
from physics.world import DT_MAX


@pytest.mark.parametrize("dt", [1e308, 3600.5, 1e5])
def test_a_step_longer_than_an_hour_is_refused_naming_dt(dt):
    with pytest.raises(ValueError, match="dt: must be <= 3600"):
        physics.World(dt=dt)
    w = physics.World()
    with pytest.raises(ValueError, match="dt"):
        w.dt = dt
    w.add_body(physics.Circle(1))
    with pytest.raises(ValueError, match="dt"):
        w.step(dt)
    assert w.time == 0.0 and w.steps == 0


def test_time_stays_finite_at_the_largest_step():
    w = physics.World(dt=DT_MAX, gravity=(0, 0))
    w.add_body(physics.Circle(1))
    w.time = 1.7e308
    w.step()
    assert math.isfinite(w.time)


def test_the_scene_format_bounds_dt_the_same():
    assert fmt.SCHEMA["$defs"]["world"]["properties"]["dt"]["maximum"] == DT_MAX
    data = {"format": "stelkropp.scene", "version": 2, "world": {"dt": 1e308}, "bodies": []}
    with pytest.raises(physics.SceneError) as info:
        scene_from_dict(data)
    assert dict(info.value.problems) == {"world.dt": "must be <= 3600.0; got 1e+308"}
