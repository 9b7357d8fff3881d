"""What the seed's three modes (impulse, penalty, hybrid) share.

Each step is: save the step-start state, prepare the contact point rows (arms,
effective masses), integrate the force generators with the world's
integrator (sub-stepped when a spring or a penalty contact is too stiff for
it), then resolve contacts: the seed moves first and responds afterwards.
The kernels (impulse.py, penalty.py) make those calls; this module holds the
settings the modes have in common, the derived parameters every classic kernel
reads, the work arrays, and the sub-step count.
"""
from __future__ import annotations

import math

import numpy as np

from ...constraints.joints.work import after_step, joint_args
from ...constraints.springs.force import spring_rate
from ...errors import SimulationError
from ...options import INTEGRATORS
from ...settings import Setting, declare
from ..base import SolverMode
from ..joint_settings import joint_position_setting, joint_solver_setting
from .contact_geometry import classic_points
from .integrators import LIMITS, allocate_work, substeps_for
from .penalty_load import stable_load

NO_PENALTY = np.zeros(6)
PROJECTIONS = ("none", "linear", "nonlinear")  # the projection setting's choices, by code


def share_factor(method: str, substeps: int) -> float:
    """Displacement per unit velocity change when the change comes from a constant force
    over the step (see impulses.position_share), in units of dt."""
    if method == "rk4":
        return 0.5
    if method == "symplectic_euler":
        return (substeps + 1) / (2.0 * substeps)
    return (substeps - 1) / (2.0 * substeps)


def auto_speed(value: float, gx: float, gy: float, dt: float) -> float:
    """A speed setting of -1 means three times the speed gained falling for one step."""
    if value >= 0.0:
        return value
    return max(3.0 * float(np.hypot(gx, gy)) * dt, 0.05)


COMMON = (
    joint_solver_setting(),
    Setting("joint_iterations", 4, 1, 256, "velocity passes over the joints per sub-step"),
    joint_position_setting(),
    Setting("max_substeps", 32, 1, 1024,
            "cap on automatic sub-steps (stiff springs / contacts); a step that would need more "
            "raises SimulationError instead of blowing up"),
    Setting("stick_speed", 0.01, 0.0, 10.0,
            "tangential speed (m/s) below which a point counts as sticking: static friction mu_s"),
)

IMPULSE_SETTINGS = (
    Setting("iterations", 10, 1, 200, "passes over the contact points per step (eq. 15 accumulated)"),
    Setting("projection", "linear", doc="push-out after the impulses: linear (seed 3.2), "
            "nonlinear (3.3, translation + explicit rotation) or none",
            choices=("linear", "nonlinear", "none")),  # (the kernels read the code of PROJECTIONS)
    Setting("projection_iterations", 4, 1, 100, "passes of the push-out over the contacts"),
    Setting("allowed_penetration", 0.0005, 0.0, 0.1, "depth (m) the push-out leaves in place"),
    Setting("min_linear_share", 0.2, 0.0, 1.0,
            "lower bound on the linear part of the non-linear push-out (seed 3.3, deep penetration)"),
    Setting("energy_correction", True,
            doc="seed eq. 2: remove the speed gravity added over the penetration before bouncing"),
)

PENALTY_SETTINGS = (
    Setting("contact_hertz", 25.0, 1.0, 500.0,
            "penalty spring frequency; sinking under gravity is about g / (2 (2 pi f)^2 m_eff/m) "
            "(0.5 mm for a resting 1 m box at 25 Hz)"),
    Setting("damping_ratio", 1.0, 0.0, 10.0,
            "penalty damping ratio for e = 0 (critical); bouncier contacts use the ratio that "
            "gives their restitution"),
    # 2 m/s, not soft_step's 3: without a relax pass a pushed pair keeps its separation speed, and
    # n bodies created in one place fan out at up to (n - 1) / 2 times the cap (8 boxes: 7 m/s;
    # soft_step at 3 m/s reaches 6.1)
    Setting("push_out_speed", 2.0, 0.1, 100.0,
            "largest relative speed (m/s) at which a penalty contact pushes deep overlap apart (bodies "
            "created inside each other); shallow contacts and bounces slower than it are untouched"),
)


IMPACT_SPEED = Setting("impact_speed", -1.0, -1.0, 100.0,
                       "approach speed (m/s) above which a contact is an impact (impulse), below which it is "
                       "resting (penalty); -1: 3 |g| dt")
RESTITUTION_THRESHOLD = Setting("restitution_threshold", -1.0, -1.0, 100.0,
                                "impacts slower than this (m/s) do not bounce; -1: 3 |g| dt (a resting box "
                                "gains |g| dt per step and must not hop)")
#: the fields of every classic mode's parameter record: each mode's settings are a part of it, so
#: the three modes' records are one numba type and the kernels they share compile once
RECORD = declare(IMPACT_SPEED, RESTITUTION_THRESHOLD, *IMPULSE_SETTINGS, *PENALTY_SETTINGS, *COMMON)


class SeedMode(SolverMode):
    uses_integrator = True
    record = RECORD
    # sub-steps of the force integration, the impact / restitution speed threshold, the
    # position share of the impulses (impulses.position_share), the projection (code in
    # PROJECTIONS) and the penalty parameters [on, omega, zeta, stick_speed, push_out_speed, load limit]
    derived = (("substeps", np.int64), ("thr", np.float64), ("share", np.float64), ("proj", np.int64),
               ("pen", np.float64, (6,)))

    def __init__(self):
        self.R = allocate_work(64)
        self.P = classic_points(256)

    def work(self, n: int, nc: int):
        """The body work arrays and the point rows, grown to n bodies and nc manifolds."""
        if n > len(self.R.Q0):
            self.R = allocate_work(2 * n)
        if nc > len(self.P.role):
            self.P = classic_points(2 * nc)
        return self.R, self.P

    def substeps(self, store, ctx, par, contact_rate: float = 0.0) -> int:
        """Sub-steps for the stiffest spring / penalty contact, within max_substeps."""
        rate = contact_rate
        S = store.springs
        if S.n:
            rate = max(rate, spring_rate(store.bodies.view, S.view, S.n))
        if rate <= 0.0:
            return 1
        dt = float(ctx.get("dt"))
        integrator = self.integrator_name(ctx)
        limit = int(par.get("max_substeps"))
        # compared as floats first: rate * dt may overflow an integer (or be inf / nan)
        want = rate * dt / LIMITS[integrator]
        need = substeps_for(rate, dt, integrator) if want <= limit else math.inf
        if need > limit:
            shown = f"{need}" if need < math.inf else f"{want:.3g}"
            raise SimulationError(
                f"solver '{self.name}': a spring or contact of rate {rate:.4g} 1/s needs {shown} sub-steps "
                f"of {integrator} at dt={dt:.4g} s (omega h <= {LIMITS[integrator]}), more "
                f"than max_substeps={limit}; raise max_substeps, lower the stiffness or dt",
                stage="solve")
        return need

    def joints(self, ctx, par, store):
        """(J, JW, JS) for the kernel: impulses per sub-step (Nones without joints)."""
        span = float(ctx.get("dt")) / int(par.get("substeps"))
        return joint_args(store, span, int(ctx.get("step")))

    @staticmethod
    def joints_done(store, J, broken: int) -> None:
        if J is not None:
            after_step(store, broken)

    @staticmethod
    def joint_stages(store, values) -> list[str]:
        if not store.joints.n:
            return []
        return [f"joints:sequential_impulse per sub-step ({values['joint_solver']}, ngs)"]

    @staticmethod
    def integrator_name(ctx) -> str:
        return INTEGRATORS[int(ctx.get("integrator"))]

    def force_stages(self, store, integrator: str) -> list[str]:
        out = ["forces:gravity"]
        if store.springs.n:
            out.append("forces:springs")
        return out + [f"integrate:{integrator}"]


def penalty_params(values: dict, dt: float = 0.0, substeps: int = 1) -> np.ndarray:
    """[on, omega, zeta, stick_speed, push_out_speed, load limit] of the penalty contacts; the
    load limit (penalty_load.py) is for the sub-step h = dt / substeps (inf before it is known)."""
    omega, zeta = 2.0 * math.pi * values["contact_hertz"], values["damping_ratio"]
    limit = stable_load(omega, zeta, dt / substeps) if dt > 0.0 else math.inf
    return np.array([1.0, omega, zeta, values["stick_speed"], values["push_out_speed"], limit])

def contact_rate(pen: np.ndarray) -> float:
    """Stiffness rate of a penalty contact for the sub-step count: omega (1 + 2 zeta), the
    spring plus its damper (symplectic Euler gets omega h <= 0.33 at zeta = 1)."""
    return float(pen[1] * (1.0 + 2.0 * pen[2]))
