"""Fixture handles: one shape of a body, with its material and collision filter.

Like a body handle, a fixture handle keeps only its world and stable id; every
property reads and writes the fixture table (store/fixtures.py).  Setters
validate (a ValueError names the field), wake the body, and a new density
recomputes the body's mass, centre of mass and inertia.
"""
from __future__ import annotations

from .store.fixtures import ALL_BITS
from .validate import checked_density, finite_num, friction_pair, shown, text

_GROUP_LIMIT = 2 ** 31  # the group is stored as a 32-bit signed integer


def filter_bits(value, field: str) -> int:
    """A category or mask: a whole number 0 .. 2^64 - 1, or ValueError naming ``field``."""
    if isinstance(value, bool) or not isinstance(value, int):
        try:
            import numpy as np
            if isinstance(value, np.integer):
                value = int(value)
            else:
                raise TypeError
        except TypeError:
            raise ValueError(f"{field}: expected a whole number of filter bits, got {shown(value)}") from None
    if not 0 <= value <= ALL_BITS:
        raise ValueError(f"{field}: must be between 0 and 2^64 - 1, got {shown(value)}")
    return value


def filter_group(value, field: str = "group") -> int:
    """A collision group: a whole number in -2^31 .. 2^31 - 1, or ValueError naming ``field``."""
    if isinstance(value, bool) or not isinstance(value, int):
        try:
            import numpy as np
            if isinstance(value, np.integer):
                value = int(value)
            else:
                raise TypeError
        except TypeError:
            raise ValueError(f"{field}: expected a whole number, got {shown(value)}") from None
    if not -_GROUP_LIMIT <= value < _GROUP_LIMIT:
        raise ValueError(f"{field}: must be between -2^31 and 2^31 - 1, got {shown(value)}")
    return value


def fixture_name(value, field: str = "name"):
    """None or a non-empty string of valid Unicode (scene files hold it), or ValueError naming
    ``field`` (fixture names need not be unique)."""
    if value is not None and not isinstance(value, str):
        raise ValueError(f"{field}: expected a string or None, got {shown(value)}")
    return value if value is None else text(value, field)


class Fixture:
    """Handle of one shape of a body: ``shape``, ``body``, material and filter.

    ``density`` (kg/m^2), ``friction`` ((static, dynamic); assign one number or a pair),
    ``restitution`` ([0, 1]), ``category`` and ``mask`` (bits, 0 .. 2^64 - 1), ``group``
    (-2^31 .. 2^31 - 1) and ``name`` are assignable live.  Two fixtures collide when
    ``(a.category & b.mask) and (b.category & a.mask)``, unless they share a non-zero group:
    positive always collide, negative never (Box2D).  Fixtures of one body never collide.
    ``sensor`` makes it a sensor (no mass, no contact; it reports overlaps).
    """

    __slots__ = ("_world", "_id", "_shape", "_body", "_name")

    def __init__(self, world, oid: int, shape, body, name=None):
        self._world = world
        self._id = oid
        self._shape = shape
        self._body = body
        self._name = name

    # -- plumbing ------------------------------------------------------
    @property
    def _f(self) -> int:
        try:
            return self._world._store.fixtures.slot_of[self._id]
        except KeyError:
            raise ValueError(f"fixture {self._id} was removed from its body") from None

    @property
    def _F(self):
        return self._world._store.fixtures.view

    def _changed(self) -> None:
        self._world._touched(self._body._s)

    # -- identity ------------------------------------------------------
    @property
    def id(self) -> int:
        """Stable integer id of this fixture (never reused in its world)."""
        return self._id

    @property
    def alive(self) -> bool:
        """False once the fixture (or its body) was removed."""
        return self._id in self._world._store.fixtures.slot_of

    @property
    def shape(self):
        """The fixture's shape (a physics.Polygon, Circle, Capsule, Segment or chain piece; read-only)."""
        return self._shape

    @property
    def body(self):
        """The Body this fixture belongs to."""
        return self._body

    @property
    def name(self):
        """Optional name (str or None); names of fixtures need not be unique. ValueError for another type."""
        return self._name

    @name.setter
    def name(self, value):
        self._name = fixture_name(value)

    # -- material ------------------------------------------------------
    @property
    def density(self) -> float:
        """Density in kg/m^2; setting it recomputes the body's mass, centre of mass and inertia.
        ValueError for zero, negative, non-finite or mass-overflowing values."""
        return float(self._F.density[self._f])

    @density.setter
    def density(self, value):
        d = checked_density(value, self._shape)
        self._F.density[self._f] = d
        self._world._place_body(self._body)
        self._changed()

    @property
    def friction(self) -> tuple[float, float]:
        """(static, dynamic) Coulomb coefficients (>= 0); assign one number or a pair. A contact
        combines the two fixtures' by the geometric mean."""
        f = self._f
        return (float(self._F.mu_s[f]), float(self._F.mu_d[f]))

    @friction.setter
    def friction(self, value):
        f = self._f
        self._F.mu_s[f], self._F.mu_d[f] = friction_pair(value)
        self._world._mirror(self._body)
        self._changed()

    @property
    def restitution(self) -> float:
        """Coefficient of restitution in [0, 1]; a contact uses the larger of its two fixtures'.
        ValueError outside [0, 1] or non-finite."""
        return float(self._F.e[self._f])

    @restitution.setter
    def restitution(self, value):
        self._F.e[self._f] = finite_num(value, "restitution", lo=0.0, hi=1.0)
        self._world._mirror(self._body)
        self._changed()

    # -- filter ----------------------------------------------------------
    @property
    def category(self) -> int:
        """The filter bits this fixture is (default 1). ValueError outside 0 .. 2^64 - 1."""
        return int(self._F.category[self._f])

    @category.setter
    def category(self, value):
        self._F.category[self._f] = filter_bits(value, "category")
        self._changed()

    @property
    def mask(self) -> int:
        """The filter bits this fixture collides with (default all). ValueError outside 0 .. 2^64 - 1."""
        return int(self._F.mask[self._f])

    @mask.setter
    def mask(self, value):
        self._F.mask[self._f] = filter_bits(value, "mask")
        self._changed()

    @property
    def group(self) -> int:
        """Collision group (default 0): fixtures sharing a positive group always collide, a
        negative one never. ValueError outside -2^31 .. 2^31 - 1."""
        return int(self._F.group[self._f])

    @group.setter
    def group(self, value):
        self._F.group[self._f] = filter_group(value)
        self._changed()

    # -- sensor ----------------------------------------------------------
    @property
    def sensor(self) -> bool:
        """Whether this fixture is a sensor (default False): it adds no mass, makes no contact
        in any solver mode and reports the fixtures it overlaps in ``world.sensor_events()``
        (the filter applies; sensors never detect other sensors).  Settable: the body's mass
        follows, its contacts end or begin at the next step.  ValueError for a non-bool, or
        for leaving a dynamic body without a solid shape."""
        return bool(self._F.sensor[self._f])

    @sensor.setter
    def sensor(self, value):
        self._world._set_sensor(self, value)

    @property
    def visitors(self) -> list:
        """The fixtures this sensor overlaps after the last step (a new list; empty for a
        fixture that is not a sensor): the ``visitor`` of every begin without its end yet."""
        return [v for s, v in self._world.sensor_overlaps() if s is self]

    def __repr__(self):
        if not self.alive:
            return f"<Fixture {self._id} (removed)>"
        return f"<Fixture {self._name or self._id} {type(self._shape).__name__} of {self._body!r}>"
