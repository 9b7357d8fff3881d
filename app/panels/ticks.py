"""Time-axis ticks whose labels never crowd: the finest 1-2-5 step (... 0.1, 0.2, 0.5, 1, 2, 5,
10 ... s) that leaves at least ``MIN_GAP_PX`` between neighbouring labels."""
from __future__ import annotations

import math

MIN_GAP_PX = 10.0
MULTIPLES = (1, 2, 5)


def steps_from(lo: float):
    """The 1-2-5 steps, ascending, starting with the largest one <= ``lo`` (> 0)."""
    e = math.floor(math.log10(lo))
    while True:
        for m in MULTIPLES:
            yield m, e
        e += 1


def tick_labels(t0: float, t1: float, m: int, e: int):
    """Ticks at whole multiples of m x 10^e in [t0, t1]: (positions, labels). Positions come from
    integer multiples so 0.1-steps print as 0.3, not 0.30000000000000004."""
    step = m * 10.0 ** e
    decimals = max(0, -e)
    k0, k1 = math.ceil(t0 / step - 1e-9), math.floor(t1 / step + 1e-9)
    values = [round(k * m * 10.0 ** e, decimals) if e < 0 else float(k * m * 10 ** e) for k in range(k0, k1 + 1)]
    labels = [f"{v:.{decimals}f}" for v in values]
    return values, ["0" if float(s) == 0.0 else s for s in labels]


def gaps_px(values, labels, t0, t1, width_px, text_width):
    """Free pixels between each pair of neighbouring labels, each centred on its tick."""
    scale = width_px / (t1 - t0)
    xs = [(v - t0) * scale for v in values]
    ws = [text_width(s) for s in labels]
    return [(xs[i + 1] - ws[i + 1] / 2) - (xs[i] + ws[i] / 2) for i in range(len(xs) - 1)]


def spaced_ticks(t0: float, t1: float, width_px: float, text_width, min_gap: float = MIN_GAP_PX):
    """Tick positions and labels for an axis from ``t0`` to ``t1`` drawn ``width_px`` wide;
    ``text_width(label)`` is a label's width in px. Returns (positions, labels, step)."""
    if not (math.isfinite(t0) and math.isfinite(t1)) or t1 <= t0 or width_px <= 0:
        return [], [], 0.0
    span = t1 - t0
    # no step finer than one that puts ticks min_gap px apart can leave min_gap between labels
    finest = span * min_gap / width_px
    for m, e in steps_from(finest):
        values, labels = tick_labels(t0, t1, m, e)
        if len(values) < 2 or min(gaps_px(values, labels, t0, t1, width_px, text_width)) >= min_gap:
            return values, labels, m * 10.0 ** e
    raise AssertionError("unreachable: steps_from never ends")
