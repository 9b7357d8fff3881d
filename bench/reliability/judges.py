"""Judges: a scenario's figures (bench/scenarios/extremes) -> held, degraded or failed.

The bounds are the reliability table's own; tests/extremes asserts its own bounds on the same
figures.  A refused step (SimulationError) is failed unless the judge says it is an honest
answer (a stiff spring in an explicit mode).
"""
from __future__ import annotations

from ..scenarios.extremes import was_refused
from .outcome import DEGRADED, FAILED, HELD, Outcome, graded, refusal


def _refusal_fails(judge):
    def judged(m):
        return refusal(m) if was_refused(m) else judge(m)
    judged.__name__, judged.__doc__ = judge.__name__, judge.__doc__
    return judged


@_refusal_fails
def mass_ratio_stack(m):
    """Held: sink < 2 cm and at rest (< 0.05 m/s); degraded: sink < 25 cm."""
    fig = f"sink {m['sink'] * 1000:.1f} mm, speed {m['speed']:.2g} m/s"
    if not m["order_kept"] or not m["finite"]:
        return Outcome(FAILED, "heavy box passed through the light one", m)
    if m["sink"] < 0.02 and m["speed"] < 0.05:
        return Outcome(HELD, fig, m)
    return Outcome(DEGRADED if m["sink"] < 0.25 else FAILED, fig, m)


@_refusal_fails
def spring_chain(m):
    """Failed: energy rises by 1% of what the fall releases; held: rest error < 5% of the stretch
    and at rest; degraded: rest error < 0.5 m."""
    fig = f"rest error {100 * m['error'] / m['stretch']:.1f}% of stretch, energy rise {m['energy_rise']:.2g} J"
    if not m["finite"] or m["energy_rise"] > 0.01 * m["energy_scale"]:
        return Outcome(FAILED, fig, m)
    if m["error"] < 0.05 * m["stretch"] and m["speed"] < 0.01:
        return Outcome(HELD, fig, m)
    return Outcome(DEGRADED if m["error"] < 0.5 else FAILED, fig, m)


def stiff_spring(m):
    """Held: energy never above 1.01 E0.  A refused step is degraded when the world was reverted
    and no accepted step grew the energy by 1%; energy creeping up is failed."""
    if was_refused(m):
        ok = m["reverted"] and m["growth"] <= 1.01
        out = refusal(m, DEGRADED if ok else FAILED)
        if not ok and m["reverted"]:
            out.figure = f"energy grew x{m['growth']:.3g} before SimulationError at step {m['error_step']}"
        return out
    fig = f"peak energy x{m['growth']:.4g}, after 10 s x{m['retained']:.2g}, drift x{m['drift']:.4g}"
    if not m["finite"]:
        return Outcome(FAILED, fig, m)
    if m["growth"] <= 1.01:
        return Outcome(HELD, fig, m)
    return Outcome(DEGRADED if m["drift"] <= 1.01 else FAILED, fig, m)


@_refusal_fails
def bullets(m):
    """Held: nothing tunnelled and nothing left faster than it came."""
    fig = f"{m['tunnelled']}/{m['shots']} tunnelled, max speed after {m['max_speed']:.0f} m/s"
    if m["tunnelled"] or m["max_speed"] > m["speed"] * (1 + 1e-6) or not m["finite"]:
        return Outcome(FAILED, fig, m)
    return Outcome(HELD, fig, m)


@_refusal_fails
def scaled_stack(m):
    """Held: sink and drift below 10% of the box size; degraded below 50%."""
    fig = f"sink {100 * m['sink']:.1f}%, drift {100 * m['drift']:.1f}% of size"
    if not m["finite"]:
        return Outcome(FAILED, fig, m)
    return graded(max(m["sink"], m["drift"]), 0.1, 0.5, fig, m)


@_refusal_fails
def far_pyramid(m):
    """Held: the far run matches the origin's within 1 cm and drifts < 5 cm; degraded < 50 cm."""
    fig = (f"far vs origin {m['difference'] * 1000:.2g} mm; drift {m['drift_far'] * 1000:.3g} mm "
           f"(origin {m['drift_origin'] * 1000:.3g} mm)")
    if not m["finite"]:
        return Outcome(FAILED, fig, m)
    if m["difference"] < 0.01 and m["drift_far"] < 0.05:
        return Outcome(HELD, fig, m)
    return Outcome(DEGRADED if m["difference"] < 0.5 and m["drift_far"] < 0.5 else FAILED, fig, m)


@_refusal_fails
def ten_thousand(m):
    """Held: finite, nothing through the ground, no energy gained."""
    fig = f"{m['ms_per_step']:.0f} ms/step, {m['below']} through ground, energy {m['energy_rise']:+.3g} J"
    if not m["finite"] or m["below"] or m["energy_rise"] > 1e-6 * abs(m["e0"]):
        return Outcome(FAILED, fig, m)
    return Outcome(HELD, fig, m)


@_refusal_fails
def near_collinear(m):
    """Held: at rest with sink < 2 cm, upright; degraded: sink < 50 cm."""
    fig = f"sink {m['sink'] * 1000:.1f} mm, speed {m['speed']:.2g} m/s"
    if not m["finite"]:
        return Outcome(FAILED, fig, m)
    if m["sink"] < 0.02 and m["speed"] < 0.05 and m["upright"]:
        return Outcome(HELD, fig, m)
    return Outcome(DEGRADED if m["sink"] < 0.5 else FAILED, fig, m)


@_refusal_fails
def slivers(m):
    """Failed: 25 cm below ground or 50 mJ gained; held: never 5 mm below, at rest, < 1 mJ gained."""
    fig = f"deepest {m['deepest'] * 1000:.2g} mm, energy rise {m['energy_rise']:.2g} J, speed {m['speed']:.2g} m/s"
    if not m["finite"] or m["deepest"] < -0.25 or m["energy_rise"] > 0.05:
        return Outcome(FAILED, fig, m)
    if m["deepest"] > -0.005 and m["speed"] < 0.05 and m["energy_rise"] <= 1e-3:
        return Outcome(HELD, fig, m)
    return Outcome(DEGRADED, fig, m)


@_refusal_fails
def coincident(m):
    """Failed: faster than 100 m/s; held: at most 10 m/s and < 2 cm overlap left."""
    fig = f"max speed {m['max_speed']:.2g} m/s, overlap left {m['depth'] * 1000:.1f} mm"
    if not m["finite"] or m["max_speed"] > 100:
        return Outcome(FAILED, fig, m)
    if m["max_speed"] <= 10 and m["depth"] < 0.02:
        return Outcome(HELD, fig, m)
    return Outcome(DEGRADED if m["depth"] < 0.5 else FAILED, fig, m)


@_refusal_fails
def long_run(m):
    """Held: none escaped and late energy at most 1.5x early; degraded at most 3x."""
    fig = (f"late/early energy {m['ratio']:.2f} (peak {m['peak_ratio']:.2f}), {m['escaped']} escaped, "
           f"{m['seconds']:.0f} s for {m['steps']} steps")
    if not m["finite"] or m["escaped"]:
        return Outcome(FAILED, fig, m)
    if m["ratio"] <= 1.5:
        return Outcome(HELD, fig, m)
    return Outcome(DEGRADED if m["ratio"] <= 3 else FAILED, fig, m)
