"""Sensors (issue 15) as the sandbox sees them: fixtures with ``fixture.sensor == True`` are drawn
translucent, and lit while something is inside.  Both questions are asked of the core here and
nowhere else, so the sandbox follows the core's sensor API (branch events15) by changing these
two functions."""
from __future__ import annotations


def is_sensor(fixture) -> bool:
    """Is ``fixture`` a sensor?  (``Fixture.sensor`` comes with events15; until then no fixture is.)"""
    return bool(getattr(fixture, "sensor", False))


def visited(world, sensors) -> set:
    """Ids of the ``sensors`` (fixtures) with a visitor inside.

    ADAPTER: the core will report which sensors have visitors (events15).  Until then the app
    asks ``world.overlap`` with each sensor's shape where it is now: any fixture of another body
    that is not a sensor itself, touching included, is a visitor.  One query per sensor a frame."""
    lit = set()
    for f in sensors:
        b = f.body
        for other in world.overlap(f.shape, b.position, b.angle):
            if other.body.id != b.id and not is_sensor(other):
                lit.add(f.id)
                break
    return lit


class SensorView:
    """The sensor fixtures of the open scene (looked up again when ``key`` -- the document's
    version and body count -- changes, not every frame) and whether each is lit now."""

    def __init__(self):
        self._key = None
        self.fixtures: list = []

    def states(self, world, key) -> dict:
        """{sensor fixture id: lit} for the live sensors ({} in a scene without any)."""
        if key != self._key:
            self._key = key
            self.fixtures = [f for b in world.bodies for f in b.fixtures if is_sensor(f)]
        live = [f for f in self.fixtures if f.alive]
        if not live:
            return {}
        lit = visited(world, live)
        return {f.id: f.id in lit for f in live}
