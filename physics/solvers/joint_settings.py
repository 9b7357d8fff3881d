"""The joint settings the solver modes share (issue 14): how the equality rows are solved."""
from __future__ import annotations

from ..settings import Setting

JOINT_SOLVERS = ("global", "sequential")
GLOBAL = 0  # index of "global" in JOINT_SOLVERS (the kernels read the index)


def joint_solver_setting(default: str = "global") -> Setting:
    """The ``joint_solver`` setting: the equality rows of a structure together, or joint by joint."""
    return Setting("joint_solver", default, choices=JOINT_SOLVERS,
                   doc="global: the equality rows of each jointed structure solved together every pass "
                       "(sparse LDL^T: chains and cantilevers hold to a fraction of a millimetre); "
                       "sequential: one block per joint in turn (Box2D)")


def joint_position_setting() -> Setting:
    """``joint_position_iterations``: NGS passes that move the bodies back onto their joints."""
    return Setting("joint_position_iterations", 3, 0, 64,
                   "position passes per step that move jointed bodies back onto their joints "
                   "(non-linear Gauss-Seidel; a Newton step per pass for globally solved structures)")
