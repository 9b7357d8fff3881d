"""The algebra of joint rows on the body rows: every kind's rows go through here.

A row is C' = n . (v_a - v_b) + ka w_a - kb w_b (layout.py); an impulse lam
along it changes v_a by +m_a^-1 lam n, w_a by +I_a^-1 lam ka and b's by the
opposite, so C' changes by K lam with K = (m_a^-1 + m_b^-1)|n|^2 + I_a^-1 ka^2
+ I_b^-1 kb^2.  The solves are those of Box2D v3's joints (revolute_joint.c et
al.) in this one form:

- spring (soft in every pass): lam = -ms m (C' + rate C) - is acc;
- motor: lam = -m (C' - speed), accumulated impulse clamped to +-max;
- limit (C >= 0 when satisfied): speculative while C > 0 (bias C / h: may close
  the gap within the pass, no further), soft when violated in the biased pass,
  rigid without bias; accumulated impulse >= 0;
- the equality rows of one joint as one block (1 to 3 rows): b = K^-1 (C' + bias),
  lam_r = -ms_r b_r - is_r acc_r (Box2D's point block with per-row softness).
"""
from __future__ import annotations

from .jit import row_inline, row_part
from ...store.joints import LOWER, MOTOR_ROW, SPRING
from ..body_rows import II, IM, VX, VY, W
from .layout import CC, KA, KB, MASS, MAX_MOTOR, NX, NY, SOFT_EQ, SOFT_LIMIT, SOFT_SPRING

SINGULAR = 1e-12  # relative determinant below which a block is solved row by row


@row_inline
def set_row(JW, j, r, nx, ny, ka, kb, c, ims, iia, iib):
    """Write row r of joint j (ims = m_a^-1 + m_b^-1) with its effective mass."""
    JW.G[j, r, NX] = nx
    JW.G[j, r, NY] = ny
    JW.G[j, r, KA] = ka
    JW.G[j, r, KB] = kb
    JW.G[j, r, CC] = c
    k = ims * (nx * nx + ny * ny) + iia * ka * ka + iib * kb * kb
    JW.G[j, r, MASS] = 1.0 / k if k > 0.0 else 0.0


@row_inline
def clear_row(JW, j, r):
    for f in range(JW.G.shape[2]):
        JW.G[j, r, f] = 0.0


@row_inline
def idle(J, JW, j, r):
    """Row r of joint j takes no part and holds no impulse: nothing reads its geometry (the
    solves go by the row mask, the warm start and the reaction by the impulse)."""
    return ((JW.mask[j] >> r) & 1) == 0 and J.impulse[j, r] == 0.0


@row_inline
def local_speed(G, j, r, dvx, dvy, wa, wb):
    """C' of row r for the velocities dv = v_a - v_b, w_a and w_b."""
    return G[j, r, NX] * dvx + G[j, r, NY] * dvy + G[j, r, KA] * wa - G[j, r, KB] * wb


@row_inline
def row_speed(JW, a, b, j, r):
    """C' of row r now."""
    SB = JW.SB
    return local_speed(JW.G, j, r, SB[a, VX] - SB[b, VX], SB[a, VY] - SB[b, VY], SB[a, W], SB[b, W])


@row_inline
def load_pair(SB, a, b):
    """(v_a, w_a, v_b, w_b) as six locals: a joint's solve works on them and stores them once
    (``store_pair``), so its stores to SB do not make every row's geometry be loaded again."""
    return SB[a, VX], SB[a, VY], SB[a, W], SB[b, VX], SB[b, VY], SB[b, W]


@row_inline
def store_pair(SB, a, b, v):
    SB[a, VX] = v[0]
    SB[a, VY] = v[1]
    SB[a, W] = v[2]
    SB[b, VX] = v[3]
    SB[b, VY] = v[4]
    SB[b, W] = v[5]


@row_inline
def pushed(G, j, r, lam, ms, v):
    """The locals of ``load_pair`` after an impulse lam along row r; ms = (m_a^-1, I_a^-1,
    m_b^-1, I_b^-1)."""
    px = lam * G[j, r, NX]
    py = lam * G[j, r, NY]
    return (v[0] + ms[0] * px, v[1] + ms[0] * py, v[2] + ms[1] * lam * G[j, r, KA],
            v[3] - ms[2] * px, v[4] - ms[2] * py, v[5] - ms[3] * lam * G[j, r, KB])


@row_inline
def inverse_masses(SB, a, b):
    return SB[a, IM], SB[a, II], SB[b, IM], SB[b, II]


@row_inline
def apply_row(JW, a, b, j, r, lam):
    """Impulse lam along row r: +on a, -on b."""
    SB = JW.SB
    store_pair(SB, a, b, pushed(JW.G, j, r, lam, inverse_masses(SB, a, b), load_pair(SB, a, b)))


@row_inline
def warm_start_rows(J, JW, j, a, b):
    """Apply every row's accumulated impulse (rows a joint does not use hold 0)."""
    SB = JW.SB
    v = load_pair(SB, a, b)
    ms = inverse_masses(SB, a, b)
    for r in range(J.impulse.shape[1]):
        lam = J.impulse[j, r]
        if lam != 0.0:
            v = pushed(JW.G, j, r, lam, ms, v)
    store_pair(SB, a, b, v)


@row_inline
def solve_spring(J, JW, j, a, b):
    r = SPRING
    acc = J.impulse[j, r]
    vn = row_speed(JW, a, b, j, r)
    lam = (-JW.F[j, SOFT_SPRING + 1] * JW.G[j, r, MASS] * (vn + JW.F[j, SOFT_SPRING] * JW.G[j, r, CC])
           - JW.F[j, SOFT_SPRING + 2] * acc)
    J.impulse[j, r] = acc + lam
    apply_row(JW, a, b, j, r, lam)


@row_inline
def solve_motor(J, JW, j, a, b):
    r = MOTOR_ROW
    acc = J.impulse[j, r]
    vn = row_speed(JW, a, b, j, r) - J.motor_speed[j]
    top = JW.F[j, MAX_MOTOR]
    new = min(max(acc - JW.G[j, r, MASS] * vn, -top), top)
    J.impulse[j, r] = new
    apply_row(JW, a, b, j, r, new - acc)


@row_inline
def solve_limit(J, JW, j, r, a, b, use_bias, inv_h):
    c = JW.G[j, r, CC]
    bias = 0.0
    ms = 1.0
    isc = 0.0
    if c > 0.0:
        bias = c * inv_h  # speculative: may reach the limit in this pass, no further
    elif use_bias:
        bias = JW.F[j, SOFT_LIMIT] * c
        ms = JW.F[j, SOFT_LIMIT + 1]
        isc = JW.F[j, SOFT_LIMIT + 2]
    acc = J.impulse[j, r]
    vn = row_speed(JW, a, b, j, r)
    new = max(acc - ms * JW.G[j, r, MASS] * (vn + bias) - isc * acc, 0.0)
    J.impulse[j, r] = new
    apply_row(JW, a, b, j, r, new - acc)


@row_inline
def solve_free_rows(J, JW, j, a, b, mask, use_bias, inv_h):
    """Spring, motor, then the limits (Box2D v3's order), where the joint has them."""
    if mask & (1 << SPRING):
        solve_spring(J, JW, j, a, b)
    if mask & (1 << MOTOR_ROW):
        solve_motor(J, JW, j, a, b)
    if mask & (1 << LOWER):
        solve_limit(J, JW, j, LOWER, a, b, use_bias, inv_h)
    if mask & (1 << (LOWER + 1)):
        solve_limit(J, JW, j, LOWER + 1, a, b, use_bias, inv_h)


@row_inline
def block_entry(JW, a, b, j, r, s):
    """K_rs = (m_a^-1 + m_b^-1) n_r . n_s + I_a^-1 ka_r ka_s + I_b^-1 kb_r kb_s."""
    return ((JW.SB[a, IM] + JW.SB[b, IM]) * (JW.G[j, r, NX] * JW.G[j, s, NX] + JW.G[j, r, NY] * JW.G[j, s, NY])
            + JW.SB[a, II] * JW.G[j, r, KA] * JW.G[j, s, KA] + JW.SB[b, II] * JW.G[j, r, KB] * JW.G[j, s, KB])


@row_inline
def sym_factors(m, k00, k01, k02, k11, k12, k22):
    """(ok, c00, c01, c02, c11, c12, c22, inv) for the leading m x m part of a symmetric K (m = 1,
    2, 3): the cofactors C and 1/det, so that x = C g / det solves K x = g (``sym_solution``);
    m = 1 keeps c00 = K_00 (x = g0 / K_00).  Not ok for a degenerate block."""
    no = (False, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    if m == 1:
        if k00 <= 0.0:
            return no
        return True, k00, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0
    if m == 2:
        det = k00 * k11 - k01 * k01
        if det <= SINGULAR * k00 * k11 or det <= 0.0:
            return no
        return True, k11, -k01, 0.0, k00, 0.0, 0.0, 1.0 / det
    c00 = k11 * k22 - k12 * k12
    c01 = k02 * k12 - k01 * k22
    c02 = k01 * k12 - k02 * k11
    det = k00 * c00 + k01 * c01 + k02 * c02
    if det <= SINGULAR * k00 * k11 * k22 or det <= 0.0:
        return no
    return (True, c00, c01, c02, k00 * k22 - k02 * k02, k01 * k02 - k00 * k12, k00 * k11 - k01 * k01,
            1.0 / det)


@row_inline
def sym_solution(m, c00, c01, c02, c11, c12, c22, inv, g0, g1, g2):
    """K^-1 g from the factors of ``sym_factors``."""
    if m == 1:
        return g0 / c00, 0.0, 0.0
    if m == 2:
        return (c00 * g0 + c01 * g1) * inv, (c11 * g1 + c01 * g0) * inv, 0.0
    return ((c00 * g0 + c01 * g1 + c02 * g2) * inv, (c01 * g0 + c11 * g1 + c12 * g2) * inv,
            (c02 * g0 + c12 * g1 + c22 * g2) * inv)


@row_inline
def solve_sym(m, k00, k01, k02, k11, k12, k22, g0, g1, g2):
    """(solved, x) of K x = g for the leading m x m part of a symmetric K (m = 1, 2, 3)."""
    ok, c00, c01, c02, c11, c12, c22, inv = sym_factors(m, k00, k01, k02, k11, k12, k22)
    if not ok:
        return False, 0.0, 0.0, 0.0
    x0, x1, x2 = sym_solution(m, c00, c01, c02, c11, c12, c22, inv, g0, g1, g2)
    return True, x0, x1, x2


@row_inline
def block_factors(JW, j, a, b, m):
    """The equality block's factors for ``solve_equality``, from the rows as ``refresh_rows``
    wrote them (K depends on the positions and masses only, so one factoring serves every pass
    until the bodies move): ``K[j]`` holds ``sym_factors``' C and, in slot 6, 1/det, or 0 for a
    degenerate block."""
    k00 = block_entry(JW, a, b, j, 0, 0)
    k01 = k02 = k11 = k12 = k22 = 0.0
    if m > 1:
        k01 = block_entry(JW, a, b, j, 0, 1)
        k11 = block_entry(JW, a, b, j, 1, 1)
    if m > 2:
        k02 = block_entry(JW, a, b, j, 0, 2)
        k12 = block_entry(JW, a, b, j, 1, 2)
        k22 = block_entry(JW, a, b, j, 2, 2)
    ok, c00, c01, c02, c11, c12, c22, inv = sym_factors(m, k00, k01, k02, k11, k12, k22)
    K = JW.K
    K[j, 0] = c00
    K[j, 1] = c01
    K[j, 2] = c02
    K[j, 3] = c11
    K[j, 4] = c12
    K[j, 5] = c22
    K[j, 6] = inv if ok else 0.0


@row_inline
def block_solution(JW, j, m, g0, g1, g2):
    """K^-1 g for the factors of ``block_factors``; a degenerate block (e.g. nothing can rotate)
    row by row, each row on its own effective mass."""
    K = JW.K
    if K[j, 6] == 0.0:
        G = JW.G
        return g0 * G[j, 0, MASS], g1 * G[j, 1, MASS], g2 * G[j, 2, MASS]
    return sym_solution(m, K[j, 0], K[j, 1], K[j, 2], K[j, 3], K[j, 4], K[j, 5], K[j, 6], g0, g1, g2)


@row_inline
def solve_equality(J, JW, j, a, b, m, use_bias):
    """The joint's m equality rows as one block, soft as the pass asks (see the module doc), on
    the factors of the last refresh; the rows' impulses applied in turn, as ``apply_row`` does."""
    o = 0 if use_bias else 3
    SB = JW.SB
    G = JW.G
    F = JW.F
    v = load_pair(SB, a, b)
    dvx = v[0] - v[3]
    dvy = v[1] - v[4]
    g0 = local_speed(G, j, 0, dvx, dvy, v[2], v[5]) + F[j, SOFT_EQ + o] * G[j, 0, CC]
    g1 = 0.0
    g2 = 0.0
    if m > 1:
        g1 = local_speed(G, j, 1, dvx, dvy, v[2], v[5]) + F[j, SOFT_EQ + 6 + o] * G[j, 1, CC]
    if m > 2:
        g2 = local_speed(G, j, 2, dvx, dvy, v[2], v[5]) + F[j, SOFT_EQ + 12 + o] * G[j, 2, CC]
    x0, x1, x2 = block_solution(JW, j, m, g0, g1, g2)
    ms = inverse_masses(SB, a, b)
    for r in range(m):
        x = x0 if r == 0 else (x1 if r == 1 else x2)
        s = SOFT_EQ + 6 * r + o
        acc = J.impulse[j, r]
        lam = -F[j, s + 1] * x - F[j, s + 2] * acc
        J.impulse[j, r] = acc + lam
        v = pushed(G, j, r, lam, ms, v)
    store_pair(SB, a, b, v)
