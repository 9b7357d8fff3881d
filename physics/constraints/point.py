"""Contact points as arms and vectors: the rigid-row form of sequential impulses and the seed modes.

Each point is solved through its arms r_a, r_b (from each centre of mass to the
contact point, world frame): the relative velocity of the material points is
v_b + w_b x r_b - v_a - w_a x r_a, and an impulse P acts as +P on b and -P on a
at the arms.  Per step ``prepare_points`` fills, for every manifold point, the
arms, the effective masses along the normal and the tangent
(K = 1/m_a + 1/m_b + (r_a x n)^2/I_a + (r_b x n)^2/I_b, Catto 2005), the relative
normal velocity before solving (the reference for restitution), and which Coulomb
coefficient applies: static while the point sticks, dynamic once it slides (seed
eq. 23).  These live in the solver's own scratch (``point_rows``), never in the
contact table.

(soft_step solves contacts in the projected form of constraints/contact_soft.py,
where each row's anchor projections are computed once per step.)
"""
from __future__ import annotations

import math
from collections import namedtuple

import numpy as np

from .._jit import kernel

# per manifold point: arms, effective masses, normal speed before solving, friction coefficient
POINT_FIELDS = ("ra", "rb", "mass_n", "mass_t", "vn0", "mu")


def point_type(name: str, module: str, extra=()):
    """The namedtuple type of a solver's point rows: POINT_FIELDS plus ``extra`` (name, dtype).

    Define it once, at module level of ``module`` (the caller's ``__name__``) under the same
    ``name``: numba's disk cache pickles the argument types of each kernel, and a type that
    pickle cannot find by module and name is pickled by value and comes back as a new class
    in the next process, so every launch would miss the cache and compile again."""
    tup = namedtuple(name, list(POINT_FIELDS) + [k for k, _ in extra], module=module)
    tup._shapes = {"ra": ((2, 2), np.float64), "rb": ((2, 2), np.float64),
                   **{k: ((2,), np.float64) for k in POINT_FIELDS[2:]},
                   **{k: ((2,), dt) for k, dt in extra}}
    return tup


def point_rows(tup, cap: int):
    """Zeroed scratch rows of the point-row type ``tup`` (see ``point_type``) for ``cap`` manifolds."""
    return tup(**{k: np.zeros((cap,) + shp, dtype=dt) for k, (shp, dt) in tup._shapes.items()})


@kernel(entry=True)
def cross(ax, ay, bx, by):
    return ax * by - ay * bx


@kernel
def rel_velocity(B, a, b, rax, ray, rbx, rby):
    """Velocity of b's material point minus a's at the anchors (v + w x r)."""
    dvx = (B.v[b, 0] - B.w[b] * rby) - (B.v[a, 0] - B.w[a] * ray)
    dvy = (B.v[b, 1] + B.w[b] * rbx) - (B.v[a, 1] + B.w[a] * rax)
    return dvx, dvy


@kernel
def apply_impulse(B, a, b, rax, ray, rbx, rby, px, py):
    """Impulse P acts on b, -P on a (normal points from a to b)."""
    ima = B.inv_m[a]
    imb = B.inv_m[b]
    B.v[a, 0] -= ima * px
    B.v[a, 1] -= ima * py
    B.w[a] -= B.inv_i[a] * cross(rax, ray, px, py)
    B.v[b, 0] += imb * px
    B.v[b, 1] += imb * py
    B.w[b] += B.inv_i[b] * cross(rbx, rby, px, py)


@kernel
def prepare_points(B, C, nc, stick_speed, W):
    """Fill W's ra, rb, mass_n, mass_t, vn0 and mu for the first ``nc`` manifolds of C."""
    for k in range(nc):
        a = C.a[k]
        b = C.b[k]
        nx = C.normal[k, 0]
        ny = C.normal[k, 1]
        ima = B.inv_m[a]
        imb = B.inv_m[b]
        iia = B.inv_i[a]
        iib = B.inv_i[b]
        for p in range(C.count[k]):
            rax = C.point[k, p, 0] - B.x[a, 0]
            ray = C.point[k, p, 1] - B.x[a, 1]
            rbx = C.point[k, p, 0] - B.x[b, 0]
            rby = C.point[k, p, 1] - B.x[b, 1]
            W.ra[k, p, 0] = rax
            W.ra[k, p, 1] = ray
            W.rb[k, p, 0] = rbx
            W.rb[k, p, 1] = rby
            rna = cross(rax, ray, nx, ny)
            rnb = cross(rbx, rby, nx, ny)
            kn = ima + imb + iia * rna * rna + iib * rnb * rnb
            W.mass_n[k, p] = 1.0 / kn if kn > 0.0 else 0.0
            # tangent t = (-ny, nx)
            rta = cross(rax, ray, -ny, nx)
            rtb = cross(rbx, rby, -ny, nx)
            kt = ima + imb + iia * rta * rta + iib * rtb * rtb
            W.mass_t[k, p] = 1.0 / kt if kt > 0.0 else 0.0
            dvx, dvy = rel_velocity(B, a, b, rax, ray, rbx, rby)
            W.vn0[k, p] = dvx * nx + dvy * ny
            vt = -dvx * ny + dvy * nx
            # Coulomb (seed eq. 23): static coefficient while sticking, dynamic once sliding
            W.mu[k, p] = C.mu_s[k] if math.fabs(vt) <= stick_speed else C.mu_d[k]


@kernel
def zero_impulses(C, nc):
    """Forget the accumulated impulses (warm starting switched off)."""
    for k in range(nc):
        for p in range(2):
            C.jn[k, p] = 0.0
            C.jt[k, p] = 0.0
