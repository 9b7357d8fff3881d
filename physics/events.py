"""Contact and sensor events as Python objects, made from the step's arrays when asked.

``world.contact_events()`` and ``world.sensor_events()`` read what the last step's events
stage kept (physics/step/events.py); nothing here runs unless they are called.  The events of
a step replace those of the step before (Box2D); a step skipped because every body sleeps
has none; ``world.restore`` clears them.  Fixtures in end events may be removed ones
(``fixture.alive`` is False): a body or fixture removed mid-contact ends its contacts at the
next step.
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .store.contacts import PAIR_LOW as LOW


class ContactBeginEvent(NamedTuple):
    """Two fixtures started touching in the last step.

    ``fixture_a`` has the lower id; ``normal`` is the unit normal from fixture_a's body to
    fixture_b's, ``point`` (world, m) the contact point that approached fastest, and
    ``approach_speed`` (m/s) the relative normal velocity there before the solve, positive
    when the two approach."""

    fixture_a: object
    """The fixture with the lower id."""
    fixture_b: object
    """The other fixture (its body is where ``normal`` points)."""
    point: tuple
    """(x, y) world point (m), midway between the surfaces, where the approach was fastest."""
    normal: tuple
    """(x, y) unit normal from fixture_a's body to fixture_b's."""
    approach_speed: float
    """Relative normal speed (m/s) at ``point`` before the solve, positive when approaching."""


class ContactHitEvent(NamedTuple):
    """A touching contact whose approach speed (m/s, relative normal velocity before the solve,
    positive when approaching) exceeded ``world.hit_event_threshold`` in the last step; fields
    as :class:`ContactBeginEvent`."""

    fixture_a: object
    """The fixture with the lower id."""
    fixture_b: object
    """The other fixture (its body is where ``normal`` points)."""
    point: tuple
    """(x, y) world point (m), midway between the surfaces, where the approach was fastest."""
    normal: tuple
    """(x, y) unit normal from fixture_a's body to fixture_b's."""
    approach_speed: float
    """Relative normal speed (m/s) at ``point`` before the solve, positive when approaching."""


class ContactEvents(NamedTuple):
    """``world.contact_events()``: the last step's ``begin`` (ContactBeginEvent list), ``end``
    ((fixture_a, fixture_b) list, the lower id first) and ``hit`` (ContactHitEvent list)."""

    begin: list
    """ContactBeginEvent of each pair that started touching."""
    end: list
    """(fixture_a, fixture_b) of each pair that stopped touching (removed fixtures too)."""
    hit: list
    """ContactHitEvent of each touching contact faster than the hit threshold."""


class SensorEvents(NamedTuple):
    """``world.sensor_events()``: the last step's ``begin`` and ``end`` lists of (sensor
    fixture, visitor fixture)."""

    begin: list
    """(sensor, visitor) of each overlap that started."""
    end: list
    """(sensor, visitor) of each overlap that ended (removed fixtures too)."""


def _pairs(world, keys) -> list:
    look = world._fixture_of
    return [(look(k >> 32), look(k & LOW)) for k in keys.tolist()]


def approach_speeds(world) -> np.ndarray:
    """(rows, 2) relative normal speeds of the contact points before the solve (the
    checkpoint's start-of-step velocities), positive when approaching."""
    c = world._store.contacts
    n = c.n
    ck = world._pipeline._checkpoint
    a, b = c.cur.a[:n], c.cur.b[:n]
    p = c.cur.point[:n]
    nrm = c.cur.normal[:n]
    ra = p - ck.X[a][:, None, :]
    rb = p - ck.X[b][:, None, :]
    va = ck.V[a][:, None, :] + ck.W[a][:, None, None] * np.stack([-ra[..., 1], ra[..., 0]], -1)
    vb = ck.V[b][:, None, :] + ck.W[b][:, None, None] * np.stack([-rb[..., 1], rb[..., 0]], -1)
    return -np.einsum("rpk,rk->rp", vb - va, nrm)


def _contacts(world) -> ContactEvents:
    ev = world._pipeline.events
    tr = ev.contacts
    c = world._store.contacts
    n = c.n
    cur = c.cur
    live = np.arange(2)[None, :] < cur.count[:n, None]
    touch = live & ((cur.depth[:n] > -world.linear_slop) | (cur.jn[:n] > 0.0))
    speed = np.where(touch, approach_speeds(world), -np.inf)
    best = np.argmax(speed, axis=1) if n else np.zeros(0, np.int64)
    top = speed[np.arange(n), best]
    look = world._fixture_of

    def made(cls, r):
        key = int(cur.key[r])
        return cls(look(key >> 32), look(key & LOW), tuple(map(float, cur.point[r, best[r]])),
                   tuple(map(float, cur.normal[r])), float(top[r]))

    begin = [made(ContactBeginEvent, int(r)) for r in tr.begin[:tr.nb]]
    hits = np.nonzero(top > world.hit_event_threshold)[0]
    return ContactEvents(begin, _pairs(world, tr.ends), [made(ContactHitEvent, int(r)) for r in hits])


def contact_events(world) -> ContactEvents:
    """The last step's contact events (empty lists when the last step had none)."""
    ev = world._pipeline.events
    if ev.step != world.steps:
        return ContactEvents([], [], [])
    if "contacts" not in ev.cache:
        ev.cache["contacts"] = _contacts(world)
    got = ev.cache["contacts"]
    return ContactEvents(list(got.begin), list(got.end), list(got.hit))


def sensor_events(world) -> SensorEvents:
    """The last step's sensor events (empty lists when the last step had none)."""
    ev = world._pipeline.events
    if ev.step != world.steps:
        return SensorEvents([], [])
    if "sensors" not in ev.cache:
        ev.cache["sensors"] = SensorEvents(_pairs(world, ev.sensors.begin), _pairs(world, ev.sensors.ends))
    got = ev.cache["sensors"]
    return SensorEvents(list(got.begin), list(got.end))


def freeze(world) -> None:
    """Make the last step's events now: an edit is about to renumber the rows they read."""
    contact_events(world)
    sensor_events(world)
