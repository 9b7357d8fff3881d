"""Sensors (issue 15) as the sandbox sees them: fixtures with ``fixture.sensor == True`` are drawn
translucent, and lit while something is inside.  Both questions are asked of the core here and
nowhere else."""
from __future__ import annotations


def is_sensor(fixture) -> bool:
    """Is ``fixture`` a sensor (``Fixture.sensor``)?"""
    return bool(fixture.sensor)


def visited(world, sensors) -> set:
    """Ids of the ``sensors`` (fixtures) with a visitor inside.

    Asked of the geometry where it is now (``world.overlap`` with each sensor's shape; queries
    never see sensors), not of the core's ``Fixture.visitors``: those are the last step's, and
    the sandbox also shows a paused scene being edited, and a static body dragged into a static
    sensor, which the step's sensor stage never pairs (it pairs only where a body is dynamic).
    Any fixture of another body, touching included, is a visitor.  One query per sensor a frame."""
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
