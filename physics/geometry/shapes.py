"""Convex shapes: validated once in Python, then stored as plain arrays.

A shape knows its geometry in body coordinates and its mass properties per
unit density.  Vertices are normalised to counter-clockwise order, which the
narrow phase relies on (outward normals are the edge direction rotated by -90
degrees).
"""
from __future__ import annotations

import math
import sys

import numpy as np

from .rounded import rounded_mass, successors

MAX_POLYGON_VERTICES = 64
# a vertex turn smaller than this (sine of the angle) counts as collinear
_COLLINEAR_SINE = 1e-9
# a polygon's area must be at least this fraction of its extent squared to be told from a line
_MIN_AREA_RATIO = 1e-12
# |coordinate| limit for shape geometry (m): keeps sums and squares in the checks finite; the mass
# check refuses anything over about 1e76 m anyway (its second moment, ~size^4, would overflow)
MAX_COORDINATE = 1e150


class Shape:
    """Base of all shapes: geometry in body coordinates plus mass properties."""

    kind: str = ""

    def mass_properties(self, density: float):
        """(mass, centroid (2,), inertia about the centroid) for a density."""
        raise NotImplementedError

    @property
    def bounding_radius(self) -> float:
        raise NotImplementedError


def _as_points(vertices, what="vertices") -> np.ndarray:
    try:
        if np.asarray(vertices).dtype.kind in "USVa":  # numpy would parse "1.5"; text is not a number
            raise TypeError("coordinates must be numbers, not text")
        pts = np.array(vertices, dtype=np.float64)
    except (TypeError, ValueError, OverflowError) as exc:
        raise ValueError(f"{what}: expected a list of (x, y) pairs ({_clip(str(exc))})") from None
    if pts.ndim != 2 or pts.shape[1] != 2:
        raise ValueError(f"{what}: expected a list of (x, y) pairs, got shape {pts.shape}")
    if not np.all(np.isfinite(pts)):
        raise ValueError(f"{what}: coordinates must be finite (found NaN or inf)")
    if np.any(np.abs(pts) > MAX_COORDINATE):
        raise ValueError(f"{what}: coordinates beyond {MAX_COORDINATE:g} m; the shape is too large to represent")
    return pts


def _clip(text: str, limit: int = 120) -> str:
    return text if len(text) <= limit else text[: limit - 3] + "..."


def _show(value) -> str:
    """repr(value) for a message, clipped (a 5000-digit integer has no repr in Python 3.11+)."""
    try:
        return _clip(repr(value))
    except ValueError:
        return f"an integer of {value.bit_length()} bits"


def _number(value, what: str) -> float:
    """``value`` as a float: a real number (not text or a boolean) within float range, or ValueError."""
    if isinstance(value, (bool, str, bytes, bytearray)):
        raise ValueError(f"{what} must be a number, got {_show(value)}")
    try:
        return float(value)
    except OverflowError:
        raise ValueError(f"{what} is beyond the range of a float") from None
    except (TypeError, ValueError):
        raise ValueError(f"{what} must be a number, got {_show(value)}") from None


def _positive(value, what: str) -> float:
    x = _number(value, what)
    if not math.isfinite(x) or x <= 0:
        raise ValueError(f"{what} must be positive and finite, got {_show(value)}")
    return x


def _check_mass_scale(area: float, inertia: float, what: str, size: float) -> None:
    """Refuse geometry whose area or second moment (per unit density) no float can hold."""
    if not (math.isfinite(area) and math.isfinite(inertia)):
        raise ValueError(f"{what} is too large: {size:g} m across, its moment of inertia overflows a float "
                         "(sizes up to about 1e76 m can be represented)")
    if area < sys.float_info.min or inertia < sys.float_info.min:
        raise ValueError(f"{what} is too small: {size:g} m across, its area or moment of inertia underflows "
                         "a float")


def _signed_area(p: np.ndarray) -> float:
    q = successors(p)
    return 0.5 * float(np.sum(p[:, 0] * q[:, 1] - q[:, 0] * p[:, 1]))


class Polygon(Shape):
    """A convex polygon.  ``Polygon(vertices)`` accepts either winding.

    Raises ``ValueError`` naming the problem for fewer than 3 or more than
    ``MAX_POLYGON_VERTICES`` vertices, non-finite coordinates, repeated
    vertices, zero area, collinear vertices, and non-convex or
    self-intersecting outlines.  ``Polygon.hull(points)`` builds the convex
    hull for callers who want one from arbitrary points.
    """

    kind = "polygon"
    """The shape type's name in scene files: "polygon"."""

    outline = None
    """The simple outline (CCW, read-only array) this polygon is a convex piece of, when
    physics.decompose made it; None otherwise (scene files save the outline, not the pieces)."""

    _mp = None  # (vertices, radius, unit-density moments): see _moments

    def __init__(self, vertices, radius=0.0, *, _spec=None):
        """``vertices`` (m, body coordinates, either winding) and ``radius`` (m, >= 0): a radius
        rounds the polygon (its outline is the set of points within ``radius`` of the convex core,
        as Box2D v3's rounded polygons).  ValueError naming the problem (see the class)."""
        r = _number(radius, "polygon radius")
        if not math.isfinite(r) or r < 0.0:
            raise ValueError(f"polygon radius must be >= 0 and finite, got {_show(radius)}")
        pts = _as_points(vertices)
        n = len(pts)
        if n < 3:
            raise ValueError(f"polygon needs at least 3 vertices, got {n}")
        if n > MAX_POLYGON_VERTICES:
            raise ValueError(f"polygon has {n} vertices; at most {MAX_POLYGON_VERTICES} are supported")
        scale = float(np.max(np.abs(pts - pts.mean(axis=0)))) or 0.0
        area = _signed_area(pts - pts.mean(axis=0))  # centred: see centroid
        if scale == 0.0 or area == 0.0:
            raise ValueError("polygon has zero area (all vertices coincide or lie on one line)")
        if abs(area) <= _MIN_AREA_RATIO * scale * scale:  # scale <= 1e150: the square is finite
            raise ValueError(f"polygon is too thin: its area is {abs(area) / (scale * scale):.1e} of its extent "
                             f"squared (at least {_MIN_AREA_RATIO:g}, else it cannot be told from a line)")
        if area < 0:
            pts = pts[::-1].copy()
            area = -area
        _check_convex(pts, scale)
        self.vertices = pts
        """Vertices in body coordinates (m), counter-clockwise, as a read-only (n, 2) array."""
        self.vertices.setflags(write=False)
        self.radius = r
        """Rounding radius in metres (>= 0; 0 is a sharp polygon)."""
        self._spec = dict(_spec) if _spec is not None else {"polygon": pts.tolist()}
        if r > 0.0:
            self._spec["radius"] = r
        with np.errstate(over="ignore"):  # overflow is what the check looks for
            m, _, inertia = self.mass_properties(1.0)
        _check_mass_scale(m, inertia, "polygon", 2 * scale)

    # -- constructors -------------------------------------------------
    @classmethod
    def box(cls, width: float, height: float, radius: float = 0.0) -> "Polygon":
        """An axis-aligned box ``width`` x ``height`` (m, each > 0) centred on the body origin, its
        corners rounded by ``radius`` (m, >= 0: the rounding adds to the size, as in Box2D v3);
        ValueError for sizes that are not positive finite numbers or too large, small or thin."""
        w, h = _number(width, "box width"), _number(height, "box height")
        if not (math.isfinite(w) and math.isfinite(h)) or w <= 0 or h <= 0:
            raise ValueError(f"box size must be positive and finite, got ({_show(width)}, {_show(height)})")
        if max(w, h) > 2 * MAX_COORDINATE:
            raise ValueError(f"box size ({w:g}, {h:g}) m is too large to represent (its moment of inertia "
                             "overflows a float beyond about 1e76 m)")
        hw, hh = 0.5 * w, 0.5 * h
        return cls([(-hw, -hh), (hw, -hh), (hw, hh), (-hw, hh)], radius, _spec={"box": [w, h]})

    @classmethod
    def regular(cls, sides: int, radius: float, corner_radius: float = 0.0) -> "Polygon":
        """A regular polygon of ``sides`` (an integer 3..64) with circumradius ``radius`` (m, > 0)
        and a flat bottom edge, rounded by ``corner_radius`` (m, >= 0); ValueError naming the bad
        argument."""
        try:  # comparisons first: int() of inf, NaN or text would raise something else
            whole = not isinstance(sides, (bool, str, bytes)) and 3 <= sides <= MAX_POLYGON_VERTICES \
                and int(sides) == sides
        except (TypeError, ValueError, OverflowError):
            whole = False
        if not whole:
            raise ValueError(f"regular polygon needs an integer 3..{MAX_POLYGON_VERTICES} sides, "
                             f"got {_show(sides)}")
        r = _positive(radius, "regular polygon radius")
        sides = int(sides)
        a0 = -0.5 * math.pi + math.pi / sides
        pts = [(r * math.cos(a0 + 2 * math.pi * k / sides), r * math.sin(a0 + 2 * math.pi * k / sides))
               for k in range(sides)]
        return cls(pts, corner_radius, _spec={"regular": {"sides": sides, "radius": r}})

    @classmethod
    def hull(cls, points, radius: float = 0.0) -> "Polygon":
        """The convex hull of arbitrary points (Andrew's monotone chain), rounded by ``radius``.

        Collinear and repeated points are dropped.
        """
        pts = _as_points(points, "points")
        h = _prune_degenerate(convex_hull(pts))
        c = h - h.mean(axis=0) if len(h) else h
        if len(h) < 3 or abs(_signed_area(c)) <= _MIN_AREA_RATIO * float(np.max(np.abs(c))) ** 2:
            raise ValueError("points have no area: their convex hull is a point, a segment or too thin to "
                             "tell from one")
        if len(h) > MAX_POLYGON_VERTICES:
            raise ValueError(f"hull has {len(h)} vertices; at most {MAX_POLYGON_VERTICES} are supported")
        return cls(h, radius)

    # -- properties ---------------------------------------------------
    @property
    def spec(self) -> dict:
        """The scene-file form of this shape (``{"box": ...}`` etc.)."""
        return self._spec

    @property
    def bounding_radius(self) -> float:
        """Radius (m) of the smallest circle about the body origin holding every vertex."""
        c = self.centroid
        reach = float(np.max(np.hypot(*(self.vertices - c).T)))
        return reach + self.radius if self.radius > 0.0 else reach

    @property
    def area(self) -> float:
        """Area in m^2 (> 0), the rounding included."""
        if self.radius > 0.0:
            return rounded_mass(self.vertices, self.radius)[0]
        return _signed_area(self.vertices - self.vertices.mean(axis=0))

    def _moments(self):
        """(area, centroid, S) at unit density, S = sum cross(p_i, p_i+1)(p_i.p_i + p_i.p_i+1 +
        p_i+1.p_i+1) about the centroid (12 J / rho), for a rounded polygon its total second
        moment; computed once per vertices and radius (both fixed after construction)."""
        m = self._mp
        if m is not None and m[0] is self.vertices and m[1] == self.radius:
            return m[2]
        if self.radius > 0.0:
            area, c, j = rounded_mass(self.vertices, self.radius)
            out = (area, c, j)
        else:
            # taken about the vertex mean: cross products of raw coordinates far
            # from the origin cancel catastrophically (off by 4e-3 m at 1e5 m)
            o = self.vertices.mean(axis=0)
            p = self.vertices - o
            q = successors(p)
            cr = p[:, 0] * q[:, 1] - q[:, 0] * p[:, 1]
            a = 0.5 * cr.sum()
            c = o + ((p + q) * cr[:, None]).sum(axis=0) / (6.0 * a)
            p = self.vertices - c
            q = successors(p)
            cr = p[:, 0] * q[:, 1] - q[:, 0] * p[:, 1]
            dots = (p * p).sum(1) + (p * q).sum(1) + (q * q).sum(1)
            out = (0.5 * cr.sum(), c, float((cr * dots).sum()))
        c.setflags(write=False)
        self._mp = (self.vertices, self.radius, out)
        return out

    @property
    def centroid(self) -> np.ndarray:
        """Area centre in body coordinates (m), as a 2-array."""
        return self._moments()[1].copy()

    def mass_properties(self, density: float):
        """Mass, centroid and inertia about the centroid.

        Second moment of a polygon about the origin (sum over edge triangles):
        J_o = rho/12 * sum cross(p_i, p_i+1) (p_i.p_i + p_i.p_i+1 + p_i+1.p_i+1);
        the parallel-axis theorem moves it to the centroid.  Vertices are
        shifted to the centroid first to avoid cancellation far from the origin.
        A rounded polygon sums its core, edge strips and corner sectors (geometry/rounded.py).
        """
        area, c, s = self._moments()
        if self.radius > 0.0:
            return density * area, c.copy(), density * s
        return density * area, c.copy(), density * s / 12.0

    def __repr__(self):
        if self.radius > 0.0:
            return f"Polygon({self.vertices.tolist()}, radius={self.radius})"
        return f"Polygon({self.vertices.tolist()})"

    def __eq__(self, other):
        return (isinstance(other, Polygon) and np.array_equal(self.vertices, other.vertices)
                and self.radius == other.radius)

    __hash__ = None


class Circle(Shape):
    """A disc of ``radius`` centred at ``offset`` in body coordinates."""

    kind = "circle"
    """The shape type's name in scene files: "circle"."""

    def __init__(self, radius: float, offset=(0.0, 0.0)):
        """``radius`` (m, > 0) and ``offset`` (m, the centre in body coordinates); ValueError for
        a radius that is not a positive finite number or is too large or small to represent."""
        r = _positive(radius, "circle radius")
        area = math.pi * (r * r)  # products, not **: a huge radius gives inf here, never OverflowError
        _check_mass_scale(area, 0.5 * area * r * r, "circle", 2 * r)
        off = _as_points([offset], "offset")[0]
        self.radius = r
        """Radius in metres (> 0)."""
        self.offset = off
        """Centre of the disc in body coordinates (m), as a 2-array."""
        self.offset.setflags(write=False)

    @property
    def spec(self) -> dict:
        """The circle as scene-file data (what save_scene writes): radius and offset."""
        if np.any(self.offset):
            return {"circle": {"radius": self.radius, "offset": self.offset.tolist()}}
        return {"circle": self.radius}

    @property
    def bounding_radius(self) -> float:
        """Radius (m) of the smallest circle about the body origin holding the disc: |offset| + radius."""
        return self.radius

    @property
    def area(self) -> float:
        """Area in m^2: pi r^2."""
        return math.pi * (self.radius * self.radius)

    @property
    def centroid(self) -> np.ndarray:
        """The disc's centre in body coordinates (m): its offset."""
        return self.offset.copy()

    def mass_properties(self, density: float):
        """(mass kg, centre (2,), inertia about the centre kg m^2 = m r^2 / 2) for ``density`` in kg/m^2."""
        m = density * self.area
        return m, self.offset.copy(), 0.5 * m * (self.radius * self.radius)

    def __repr__(self):
        return f"Circle({self.radius}, offset={self.offset.tolist()})"

    def __eq__(self, other):
        return (isinstance(other, Circle) and self.radius == other.radius
                and np.array_equal(self.offset, other.offset))

    __hash__ = None


def _check_convex(pts: np.ndarray, scale: float) -> None:
    """Raise ValueError unless ``pts`` (CCW) is a strictly convex simple polygon."""
    n = len(pts)
    edges = successors(pts) - pts
    lengths = np.hypot(edges[:, 0], edges[:, 1])
    for i in range(n):
        if lengths[i] <= 1e-12 * scale:
            raise ValueError(f"polygon has repeated vertices at index {i} and {(i + 1) % n}")
    turning = 0.0
    for i in range(n):
        e0, e1 = edges[i - 1], edges[i]
        s = (e0[0] * e1[1] - e0[1] * e1[0]) / (lengths[i - 1] * lengths[i])
        if s < -_COLLINEAR_SINE:
            raise ValueError(f"polygon is not convex (reflex vertex at index {i}); "
                             "use Polygon.hull(points) for the convex hull")
        if s <= _COLLINEAR_SINE:
            raise ValueError(f"polygon has collinear vertices (vertex {i} lies on the line of its neighbours)")
        turning += math.atan2(e0[0] * e1[1] - e0[1] * e1[0], e0[0] * e1[0] + e0[1] * e1[1])
    # a convex simple polygon turns exactly once; a star (pentagram) turns twice
    if abs(turning - 2 * math.pi) > 1e-6:
        raise ValueError("polygon is self-intersecting (its outline winds more than once)")


def convex_hull(pts: np.ndarray) -> np.ndarray:
    """Counter-clockwise convex hull without collinear points (monotone chain)."""
    uniq = np.unique(pts, axis=0)
    order = np.lexsort((uniq[:, 1], uniq[:, 0]))
    p = uniq[order]
    if len(p) < 3:
        return p

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for pt in p:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], pt) <= 0:
            lower.pop()
        lower.append(pt)
    for pt in p[::-1]:
        while len(upper) >= 2 and cross(upper[-2], upper[-1], pt) <= 0:
            upper.pop()
        upper.append(pt)
    return np.array(lower[:-1] + upper[:-1])


def _prune_degenerate(h: np.ndarray) -> np.ndarray:
    """Drop hull vertices that ``Polygon`` would reject as repeated or collinear.

    The monotone chain keeps any exactly positive turn, so nearly coincident or
    nearly collinear points (1e-94 off a line, say) survive it and then fail
    validation; the 4x margin keeps the two tolerances from disagreeing after
    a removal shifts the vertex mean.
    """
    if len(h) < 3:
        return h
    scale = float(np.max(np.abs(h - h.mean(axis=0))))
    pts = [np.asarray(v) for v in h]
    changed = True
    while changed and len(pts) >= 3:
        changed = False
        for i in range(len(pts)):
            e0 = pts[i] - pts[i - 1]
            e1 = pts[(i + 1) % len(pts)] - pts[i]
            l0, l1 = math.hypot(*e0), math.hypot(*e1)
            if min(l0, l1) <= 4e-12 * scale or (e0[0] * e1[1] - e0[1] * e1[0]) <= 4 * _COLLINEAR_SINE * l0 * l1:
                del pts[i]
                changed = True
                break
    return np.array(pts).reshape(-1, 2)
