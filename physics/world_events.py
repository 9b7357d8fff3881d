"""World's events: contact and sensor events, sensor overlaps, the hit threshold and the pair
filter (a part of World).

The arrays are the step's (physics/step/events.py); the Python objects physics/events.py's.
"""
from __future__ import annotations

from . import events as _events
from .events import ContactEvents, SensorEvents
from .validate import finite_num


class EventsMixin:
    """The events half of :class:`~physics.World` (see world.py for the state it uses)."""

    def contact_events(self) -> ContactEvents:
        """The contact events of the last step: ``begin`` (:class:`~physics.ContactBeginEvent`:
        fixtures, point, normal, approach speed), ``end`` ((fixture_a, fixture_b), the lower id
        first) and ``hit`` (:class:`~physics.ContactHitEvent`, approach speed above
        :attr:`hit_event_threshold`).

        A pair touches when a point is within ``linear_slop`` (what ``world.contacts()`` shows) or
        took a normal impulse; every begin is followed by one end, or the pair still touches
        (a pair that falls asleep still touches; removing a body or fixture ends its contacts
        at the next step, with the removed fixtures).  The next step replaces these events
        (Box2D); a step skipped because everything sleeps has none.  Made when asked: a world
        that never asks pays one compiled pass over its contacts per step.

        >>> import physics
        >>> w = physics.World(gravity=(0, -10))
        >>> ground = w.add_body(physics.Polygon.box(10, 1), kind="static", position=(0, -0.5))
        >>> ball = w.add_body(physics.Circle(0.5), position=(0, 2.5))
        >>> begins = []
        >>> for _ in range(60):
        ...     w.step()
        ...     begins += w.contact_events().begin
        >>> len(begins), round(begins[0].approach_speed)   # fell 2 m: sqrt(2 g h) = 6.3 m/s
        (1, 6)
        """
        return _events.contact_events(self)

    def sensor_events(self) -> SensorEvents:
        """The sensor events of the last step: ``begin`` and ``end`` lists of (sensor fixture,
        visitor fixture).

        A sensor (``body.add_fixture(shape, sensor=True)``) sees a fixture when their shapes
        overlap (exactly, not their boxes) at the step's start-of-step geometry, the filter
        (category, mask, group, joints, ``pair_filter``) lets the pair through, and the broad
        phase pairs them: at least one of the two bodies is dynamic (a static or kinematic
        sensor sees dynamic bodies; a sensor on a dynamic body also sees static ones).  Sensors
        never see other sensors (Box2D v3).  A visitor that falls asleep inside stays inside;
        pairing and replacement as :meth:`contact_events`."""
        return _events.sensor_events(self)

    def sensor_overlaps(self) -> list:
        """Every (sensor fixture, visitor fixture) overlapping after the last step (a new list)."""
        return _events._pairs(self, self._pipeline.events.sensors.keys)

    @property
    def hit_event_threshold(self) -> float:
        """Approach speed (m/s, >= 0; default 1) above which a touching contact is reported in
        ``contact_events().hit``.  ValueError for negative or non-finite values."""
        return self._hit_event_threshold

    @hit_event_threshold.setter
    def hit_event_threshold(self, value):
        self._hit_event_threshold = finite_num(value, "hit_event_threshold", lo=0.0)

    @property
    def pair_filter(self):
        """None (default) or ``fn(fixture_a, fixture_b) -> bool``, asked once when the broad phase
        first pairs two fixtures that the category/mask/group filter and the joints let collide
        (fixture_a the lower id; for a sensor pair the sensor first).  False drops the pair: no
        contact, no events, no sensor overlap, until their boxes part and meet again (then it is
        asked again).  Setting it forgets every verdict.  ValueError for a non-callable.

        It runs inside step(): it may read the world but not change it (adding or removing
        bodies, fixtures, springs or joints, restore, step, the solver raise RuntimeError), and
        anything it raises refuses the step: SimulationError, world reverted, world.fault set."""
        return self._pair_filter

    @pair_filter.setter
    def pair_filter(self, fn):
        if fn is not None and not callable(fn):
            raise ValueError(f"pair_filter: expected a callable or None, got {type(fn).__name__}")
        self._pair_filter = fn
        self._pipeline.events.filter.clear()
        self._pipeline.invalidate()

    # -- plumbing ------------------------------------------------------
    def _fixture_of(self, fid: int):
        """The handle of fixture ``fid``, also of one removed since the last step."""
        h = self._fixture_handles.get(fid)
        return h if h is not None else self._gone_fixtures.get(fid)

    def _events_freeze(self) -> None:
        _events.freeze(self)
