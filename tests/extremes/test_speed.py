"""Extremes: speed and tunnelling (issue 9)."""
import pytest

from bench.scenarios.extremes import bullets, volley
from extremes_common import CONTINUOUS


@pytest.mark.parametrize("solver", CONTINUOUS)
def test_bullets_do_not_tunnel_thin_wall(solver):
    """Regime: 14 bodies (boxes, rotated boxes, discs, a 1 m x 5 mm sliver end-on, a pentagon;
    e = 0..1) at 1000 m/s (16.7 m per step) against a 1 cm static wall.

    Outcome: none ends beyond the wall, none leaves faster than it came, all finite."""
    m = bullets(solver)
    assert m["finite"]
    assert m["tunnelled"] == 0, m["names"]
    assert m["max_speed"] <= 1000.0 * (1 + 1e-6)


@pytest.mark.parametrize("solver", CONTINUOUS)
def test_bullets_at_300_mps_do_not_tunnel(solver):
    """Regime: the same bodies at 300 m/s.  Outcome: no tunnelling, no speed gained."""
    m = bullets(solver, speed=300.0)
    assert m["tunnelled"] == 0 and m["max_speed"] <= 300.0 * (1 + 1e-6)


@pytest.mark.parametrize("solver", CONTINUOUS)
def test_volley_does_not_tunnel(solver):
    """Regime: the 14 bodies 3 m apart at 1000 m/s (a volley).

    Outcome wanted: no tunnelling, no speed gained."""
    m = volley(solver)
    assert m["tunnelled"] == 0 and m["max_speed"] <= 1000.0 * (1 + 1e-6)
