"""How far a candidate run is from the reference, by the metric the user chose.

    trajectory    RMS over the run's samples and the dynamic bodies of the pose error (m)
    final_state   RMS over the dynamic bodies of the pose error at the last sample (m)
    energy_drift  largest |E(t) - E_ref(t)| over the run, as a fraction of the energy scale
    penetration   deepest contact at any sample (m): needs no reference
    constraint    largest |L(t) - L_ref(t)| over the samples and the scene's springs and joints (m),
                  L a spring's length or a joint's anchor gap (for a pin joint, its position error)

The pose error of a body is sqrt(|x - x_ref|^2 + (r * dtheta)^2) with r the body's radius about
its centre, so a turned body counts by how far its outline moved (issue 19: "angles scaled by
body size").  The energy scale is the reference's largest kinetic energy plus the range of its
potential energy: what the scene has to move around, so a drift is judged against it.

When the reference has not converged (chaotic scenes), no trajectory can be compared and the
statistical measures stand in (``statistical``): the candidate's own energy gain, its
penetration and how far its resting bodies creep.
"""
from __future__ import annotations

import math

import numpy as np

#: metric -> unit of its budget
METRICS = {"trajectory": "m", "final_state": "m", "energy_drift": "of the energy scale", "penetration": "m",
           "constraint": "m"}
# statistical fallback: a candidate whose energy grows by more than this fraction of the scale
# without input fails whatever its other numbers (a seed-mode spring or penalty explosion)
ENERGY_GAIN_LIMIT = 0.05
# a body slower than this (m/s) over the last quarter of the run counts as resting
REST_SPEED = 0.05


def check_metric(metric) -> str:
    """``metric`` if it is one of METRICS, else ValueError naming the choices."""
    if not isinstance(metric, str) or metric not in METRICS:
        raise ValueError(f"metric: unknown metric {metric!r}; choose one of {list(METRICS)}")
    return metric


def check_budget(budget) -> float:
    """``budget`` as a positive finite float, else ValueError naming it."""
    try:
        b = float(budget) if not isinstance(budget, (bool, str, bytes)) else math.nan
    except (TypeError, ValueError, OverflowError):
        b = math.nan
    if not (math.isfinite(b) and b > 0):
        raise ValueError(f"budget: must be a positive finite number (the error allowed), got {budget!r}")
    return b


def energy_scale(ref) -> float:
    """The reference's largest kinetic energy plus the range of its potential energy (J, > 0)."""
    scale = float(np.max(ref.kinetic) + np.ptp(ref.potential))
    return scale if scale > 1e-12 else 1e-12


def pose_errors(run, ref) -> np.ndarray:
    """(K, n) pose errors (m) at the reference's samples; samples the run never reached are inf."""
    k = min(len(run.positions), len(ref.positions))
    dx = np.hypot(*(run.positions[:k] - ref.positions[:k]).transpose(2, 0, 1))
    da = np.angle(np.exp(1j * (run.angles[:k] - ref.angles[:k])))  # wrapped to (-pi, pi]
    err = np.hypot(dx, ref.sizes * da)
    missing = np.full((len(ref.positions) - k, err.shape[1]), np.inf)
    return np.vstack([err, missing])


def compare(run, ref, metric: str) -> dict:
    """Every measure of ``run`` against ``ref`` (``error`` is the one ``metric`` names)."""
    e = pose_errors(run, ref)
    n = e.shape[1]
    scale = energy_scale(ref)
    k = min(len(run.kinetic), len(ref.kinetic))
    drift = float(np.max(np.abs(run.energy[:k] - ref.energy[:k]))) / scale if k else math.inf
    if k < len(ref.kinetic):
        drift = math.inf
    out = {"rms": float(np.sqrt(np.mean(e ** 2))) if n else 0.0, "max": float(np.max(e)) if n else 0.0,
           "final": float(np.sqrt(np.mean(e[-1] ** 2))) if n else 0.0, "drift": drift, "depth": run.depth,
           "constraint": constraint_error(run, ref)}
    out["error"] = {"trajectory": out["rms"], "final_state": out["final"], "energy_drift": drift,
                    "penetration": run.depth, "constraint": out["constraint"]}[metric]
    return out


def constraint_error(run, ref) -> float:
    """Largest |L - L_ref| (m) over the samples and the springs' lengths and joints' anchor gaps
    (runs.links); inf if the run stopped early; 0 for a scene without springs or joints."""
    if ref.links.shape[1] == 0:
        return 0.0
    if len(run.links) < len(ref.links):
        return math.inf
    return float(np.max(np.abs(run.links - ref.links)))


def pin_gap(run) -> float:
    """Largest anchor gap (m) of the run's pin joints (revolute, weld): their error by their own
    definition, which needs no reference (0 without pin joints)."""
    if not np.any(run.pins):
        return 0.0
    return float(np.max(run.links[:, run.pins]))


def statistical(run, ref, metric: str) -> dict:
    """The fallback when the reference has not converged: energy gain (fraction of the scale),
    penetration (m) and resting drift (m).  ``error`` for trajectory and final_state is the larger
    of penetration and resting drift (m), inf if the energy gain exceeds ENERGY_GAIN_LIMIT; for
    energy_drift it is the run's own largest |E(t) - E(0)| over the scale; for constraint the pin
    joints' largest anchor gap (m, inf if the energy gain exceeds ENERGY_GAIN_LIMIT)."""
    scale = energy_scale(ref)
    e = run.energy
    gain = float(np.max(e - e[0])) / scale if len(e) else math.inf
    own = float(np.max(np.abs(e - e[0]))) / scale if len(e) else math.inf
    rest = resting_drift(run)
    if run.error is not None:
        gain = own = math.inf
    out = {"gain": gain, "drift": own, "depth": run.depth, "rest": rest, "pin_gap": pin_gap(run)}
    if metric == "energy_drift":
        out["error"] = own
    elif metric == "penetration":
        out["error"] = run.depth
    elif metric == "constraint":  # springs have no length to hold without a reference: pins only
        out["error"] = out["pin_gap"] if gain <= ENERGY_GAIN_LIMIT and run.error is None else math.inf
    else:
        out["error"] = max(run.depth, rest) if gain <= ENERGY_GAIN_LIMIT else math.inf
    return out


def resting_drift(run) -> float:
    """How far (m) the bodies that rest over the last quarter of the run move in it (0 if none)."""
    k = len(run.speeds)
    if k < 4 or run.speeds.shape[1] == 0:
        return 0.0
    tail = slice(k - max(2, k // 4), k)
    resting = np.all(run.speeds[tail] < REST_SPEED, axis=0)
    if not np.any(resting):
        return 0.0
    p = run.positions[tail][:, resting]
    return float(np.max(np.hypot(*(p - p[0]).transpose(2, 0, 1))))
