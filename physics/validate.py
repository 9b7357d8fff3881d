"""Validation of user input: every error is a ValueError that names the field.

Shared by the world, body, spring (and later fixture and joint) handles, so a
rule such as "densities between 1e-6 and 1e9 kg/m^2" lives in one place.
"""
from __future__ import annotations

import math
import numbers

import numpy as np

SHOWN_CHARS = 80  # a refused value is quoted up to this many characters


def shown(value) -> str:
    """A short repr of a refused value for an error message (never huge, never raising:
    an integer too long for str() or a million-element list is described, not printed)."""
    if isinstance(value, int) and not isinstance(value, bool) and value.bit_length() > 64:
        return f"an integer of about {int(value.bit_length() * 0.30103) + 1} digits"
    try:
        text = repr(value)
    except Exception:  # noqa: BLE001 (a repr that fails must not hide the real error)
        return f"a {type(value).__name__}"
    return text if len(text) <= SHOWN_CHARS else text[: SHOWN_CHARS - 3] + "..."


def text(value, field: str, empty: bool = False) -> str:
    """A string a scene file can hold, or ValueError naming ``field``: valid Unicode (JSON text is
    UTF-8, so a lone surrogate such as "a\\ud800b" is saved but refused on load) and, unless
    ``empty``, not empty."""
    if not isinstance(value, str):
        raise ValueError(f"{field}: expected a string, got {shown(value)}")
    if not value and not empty:
        raise ValueError(f"{field}: must not be empty")
    if not value.isascii():
        try:
            value.encode("utf-8")
        except UnicodeEncodeError as exc:
            raise ValueError(f"{field}: not valid Unicode: holds a lone surrogate ({value[exc.start]!r} at "
                             f"index {exc.start}); scene files could not hold it") from None
    return value


def is_number(value) -> bool:
    """A real number (Python or numpy int or float), not a bool, string or bytes."""
    t = type(value)
    if t is float or t is int:  # the common case, without the abstract-class check (bool is not int here)
        return True
    return isinstance(value, numbers.Real) and not isinstance(value, (bool, np.bool_))


def as_float(value, field: str) -> float:
    """``value`` as a float, or ValueError naming ``field`` (strings, bytes and bools are not
    numbers here; integers beyond the float range are refused, not an OverflowError)."""
    if not is_number(value):
        raise ValueError(f"{field}: expected a number, got {shown(value)}")
    try:
        return float(value)
    except (OverflowError, ValueError, TypeError):
        raise ValueError(f"{field}: {shown(value)} is beyond the range of a float") from None


def _pair_like(value) -> bool:
    """A sized container of two items (a tuple, list, or vector type), not a string or mapping."""
    if isinstance(value, (str, bytes, bytearray, dict, set, np.ndarray)):
        return False
    try:
        return len(value) == 2
    except TypeError:
        return False


_PLAIN = (float, int)  # not bool: type(True) is bool
_BIG_INT = 1e308  # ints beyond the float range take the slow path (its error)


def finite_vec(value, field: str) -> np.ndarray:
    """A pair of finite numbers as a float64 array, or ValueError naming ``field``."""
    if type(value) in (tuple, list) and len(value) == 2:  # the common case, without numpy's checks
        a, b = value
        if type(a) in _PLAIN and type(b) in _PLAIN and -_BIG_INT < a < _BIG_INT and -_BIG_INT < b < _BIG_INT:
            fa, fb = float(a), float(b)
            if math.isfinite(fa) and math.isfinite(fb):
                return np.array((fa, fb))
    if isinstance(value, np.ndarray) and value.dtype.kind in "iuf" and value.size == 2:
        items = list(value.reshape(2))
    elif _pair_like(value):
        items = list(value)
    else:
        raise ValueError(f"{field}: expected a pair of numbers, got {shown(value)}")
    v = np.array([as_float(x, f"{field}[{i}]") for i, x in enumerate(items)], dtype=np.float64)
    if not np.all(np.isfinite(v)):
        raise ValueError(f"{field}: must be finite, got {shown(value)}")
    return v


def finite_num(value, field: str, lo=None, hi=None, lo_open=False) -> float:
    """A finite number within [lo, hi] (lo excluded with ``lo_open``), or ValueError naming ``field``."""
    x = as_float(value, field)
    if not math.isfinite(x):
        raise ValueError(f"{field}: must be finite, got {shown(value)}")
    if lo is not None and (x < lo or (lo_open and x == lo)):
        raise ValueError(f"{field}: must be {'>' if lo_open else '>='} {lo}, got {shown(value)}")
    if hi is not None and x > hi:
        raise ValueError(f"{field}: must be <= {hi}, got {shown(value)}")
    return x


def whole(value, field: str, lo=None, hi=None) -> int:
    """A whole number within [lo, hi] (``3``, ``3.0``, ``numpy.int64(3)``), or ValueError naming ``field``."""
    x = finite_num(value, field, lo=lo, hi=hi)
    if x != math.floor(x):
        raise ValueError(f"{field}: must be a whole number, got {shown(value)}")
    return int(x)


def flag(value, field: str) -> bool:
    """A bool (Python or numpy), or ValueError naming ``field``: ``"false"`` is not false."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise ValueError(f"{field}: must be True or False, got {shown(value)}")


# densities (kg/m^2) the solvers are known to handle: a 1e-6 feather on a 1e9 anvil is a mass
# ratio of 1e15, past which no iterative solver transfers a load, and beyond this the inverse
# masses and impulses start to under- or overflow
DENSITY_MIN, DENSITY_MAX = 1e-6, 1e9


def checked_density(value, shape, field: str = "density") -> float:
    """A density that gives ``shape`` a finite, positive mass and inertia, or ValueError naming ``field``
    (a shape without area, a segment, has no mass whatever its density: only the range is checked)."""
    d = finite_num(value, field, lo=0.0, lo_open=True)
    if not DENSITY_MIN <= d <= DENSITY_MAX:
        raise ValueError(f"{field}: must be between {DENSITY_MIN:g} and {DENSITY_MAX:g} kg/m^2, got {shown(value)}")
    if getattr(shape, "area", None) == 0.0:
        return d
    m, _, inertia = shape.mass_properties(d)
    ok = all(math.isfinite(x) and x > 0.0 and math.isfinite(1.0 / x) for x in (m, inertia))
    if not ok:
        raise ValueError(f"{field}: {d:g} kg/m^2 gives this shape mass {m:g} kg and inertia {inertia:g} kg m^2, "
                         "which the solver cannot represent (choose a density or size nearer 1)")
    return d


def friction_pair(value, field: str = "friction") -> tuple[float, float]:
    """``0.6`` -> (0.6, 0.6); ``(static, dynamic)`` or ``{"static", "dynamic"}`` as given."""
    if isinstance(value, np.ndarray):
        value = value.tolist() if value.size <= 2 else value.ravel()
    if isinstance(value, dict):
        s, d = value.get("static"), value.get("dynamic")
    elif isinstance(value, (tuple, list, np.ndarray)):
        if len(value) != 2:
            raise ValueError(f"{field}: expected one number or a (static, dynamic) pair, got {shown(value)}")
        s, d = value
    else:
        s = d = value
    return finite_num(s, f"{field}.static", lo=0.0), finite_num(d, f"{field}.dynamic", lo=0.0)
