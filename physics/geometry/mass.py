"""Mass properties of a body made of several fixtures: sums with the parallel-axis theorem.

m = sum m_i, c = sum m_i c_i / m, I = sum (I_i + m_i |c_i - c|^2), each I_i about its own
centroid c_i (Goldstein, Classical Mechanics, sec. 5.3).  One part is returned as it is, so a
body of one shape has exactly the numbers its shape gives (the end states recorded before
fixtures depend on it).  Parts without area (segments, chains) have m_i = 0 and add nothing.
"""
from __future__ import annotations

import numpy as np


def compound_mass(parts) -> tuple[float, np.ndarray, float]:
    """(mass, centre of mass (2,), inertia about it) of ``parts``: a list of (m_i, c_i, I_i).

    With zero total mass (only segments and chains) the centre is the mean of the part
    centres and the inertia 0.
    """
    if len(parts) == 1:
        m, c, i = parts[0]
        return float(m), np.array(c, dtype=np.float64), float(i)
    ms = np.array([p[0] for p in parts], dtype=np.float64)
    cs = np.array([p[1] for p in parts], dtype=np.float64)
    m = float(ms.sum())
    if m <= 0.0:
        return 0.0, cs.mean(axis=0), 0.0
    c = (ms[:, None] * cs).sum(axis=0) / m
    d = cs - c
    inertia = float(sum(p[2] for p in parts) + (ms * (d * d).sum(axis=1)).sum())
    return m, c, inertia
