"""Accuracy scenarios with known answers, run the same way in every engine.

Each scenario takes ``make(desc) -> Sim`` (bench/engines) (so one function serves
Stelkropp in any mode and setting, pymunk and pybox2d) and returns a list of
metrics ``{"metric", "value", "expected", "error", "unit"}``; ``error`` is
what the plots and the pareto fronts use (relative where the answer is
non-zero, absolute otherwise, always >= 0, ideal 0).

Scenarios (dt and gravity from the description, 1/60 s and -10 m/s^2 unless a
sweep changes dt):

* ``spring``      -- 1 kg on a 100 N/m spring to a world anchor, no gravity, no damping:
                     period against 2 pi sqrt(m/k); energy drift over 10 periods (ideal 0).
* ``bounce``      -- a ball dropped 2 m onto static ground with restitution 0.5: first
                     bounce height against e^2 h.
* ``incline``     -- a 1x1 box on a 20 degree slope with mu 0.6 (tan 20 < 0.6: must stick;
                     error is the slide in 2 s) and on a 35 degree slope with mu 0.3
                     (slides at g (sin - mu cos) = 3.278 m/s^2).
* ``collision``   -- head-on elastic collision of 1 kg and 3 kg discs (e = 1): final
                     velocities against the analytic -1.5 / +1.5 m/s; momentum conservation.
* ``momentum``    -- 40 boxes flying about with random velocities in zero gravity, inelastic,
                     with friction, 3 s: total momentum change relative to sum m|v| (ideal 0).
* ``pile_rest``   -- 100 boxes dropped into a 10 m wide container: the time until every body
                     moves slower than 0.05 m/s and 0.07 rad/s for 0.5 s (the pile at rest).
"""
from __future__ import annotations

import math

import numpy as np

from . import desc as _d
from .metrics import penetration

G = 10.0


def _desc(name, bodies, springs=(), gravity=(0.0, -G), dt=1 / 60):
    return _d.make_desc(name, name, bodies, springs, gravity=gravity, dt=dt)


# -- spring: period and energy ------------------------------------------------------------
def spring(make, dt=1 / 60, k=100.0, m=1.0, amplitude=0.5, periods=10):
    side = 0.5
    dens = m / (side * side)
    d = _desc("spring", [_d.box(side, side, 1.0 + amplitude, 0.0, density=dens, friction=0.0, name="bob")],
              [{"name": "s", "a": "bob", "b": None, "anchor_a": [0, 0], "anchor_b": [0, 0],
                "stiffness": k, "damping": 0.0, "rest_length": 1.0}], gravity=(0.0, 0.0), dt=dt)
    sim = make(d)
    T = 2 * math.pi * math.sqrt(m / k)
    nsteps = int(round(periods * T / sim.dt)) + 2

    def energy():
        com, _, v, _ = sim.state()
        r = float(np.hypot(*com[0]))
        return 0.5 * m * float(v[0] @ v[0]) + 0.5 * k * (r - 1.0) ** 2, com[0, 0]

    E0, x_prev = energy()
    es, crossings = [], []
    t = 0.0
    for _ in range(nsteps):
        sim.step()
        t += sim.dt
        E, x = energy()
        es.append(E)
        if x_prev > 1.0 >= x:  # downward crossing of the rest position
            f = (x_prev - 1.0) / (x_prev - x)
            crossings.append(t - sim.dt + f * sim.dt)
        x_prev = x
    out = []
    if len(crossings) >= 2:
        Tm = float(np.mean(np.diff(crossings)))
        out.append(dict(metric="spring_period", value=Tm, expected=T, error=abs(Tm - T) / T, unit="s"))
    else:
        out.append(dict(metric="spring_period", value=None, expected=T, error=None, unit="s",
                        note="did not oscillate"))
    last = max(1, int(round(T / sim.dt)))
    Eend = float(np.mean(es[-last:]))
    drift = Eend / E0 - 1.0
    out.append(dict(metric="spring_energy_drift", value=drift, expected=0.0, error=abs(drift), unit="rel"))
    return out


# -- restitution bounce height ----------------------------------------------------------------
def bounce(make, dt=1 / 60, e=0.5, h=2.0, r=0.25):
    ball = {"shape": {"circle": r}, "position": [0.0, h + r], "restitution": e, "friction": 0.6, "name": "ball"}
    d = _desc("bounce", [_d.box(10, 1, 0, -0.5, kind="static", name="ground"), ball], dt=dt)
    sim = make(d)
    ys, vys = [], []
    for _ in range(int(round(2.0 / sim.dt))):
        sim.step()
        com, _, v, _ = sim.state()
        ys.append(com[1, 1])
        vys.append(v[1, 1])
    vys = np.array(vys)
    ys = np.array(ys)
    up = np.nonzero((vys[:-1] < 0) & (vys[1:] > 0))[0]
    exp = e * e * h
    if len(up) == 0:
        return [dict(metric="bounce_height", value=0.0, expected=exp, error=1.0, unit="m", note="no bounce")]
    i0 = up[0] + 1
    down = np.nonzero(vys[i0:] <= 0)[0]
    i1 = i0 + (down[0] if len(down) else len(vys) - i0 - 1)
    # apex from the sampled peak, refined by the ballistic arc of its velocity
    k = i0 + int(np.argmax(ys[i0:i1 + 1]))
    apex = ys[k] + max(vys[k], 0.0) ** 2 / (2 * G)
    hb = apex - r
    return [dict(metric="bounce_height", value=hb, expected=exp, error=abs(hb - exp) / exp, unit="m")]


# -- incline: stick and slide ----------------------------------------------------------------------
def _incline_desc(theta, mu, dt):
    c, s = math.cos(theta), math.sin(theta)
    surf = np.array([-s * 0.5, c * 0.5])            # ground top-centre after rotating by theta
    ctr = surf + np.array([-s, c]) * (0.5 + 0.002)   # box centre just above the surface
    return _desc("incline", [_d.box(30, 1, 0, 0, kind="static", angle=theta, friction=mu, name="slope"),
                             _d.box(1, 1, float(ctr[0]), float(ctr[1]), angle=theta, friction=mu, name="box")],
                 dt=dt), np.array([-c, -s])


def incline(make, dt=1 / 60):
    out = []
    th = math.radians(20.0)
    d, down = _incline_desc(th, 0.6, dt)
    sim = make(d)
    p0 = None
    for i in range(int(round(2.0 / sim.dt))):
        sim.step()
        if i == int(round(0.1 / sim.dt)):
            p0 = sim.state()[0][1].copy()  # after touchdown
    slip = float((sim.state()[0][1] - p0) @ down)
    out.append(dict(metric="incline_stick_slip", value=slip, expected=0.0, error=abs(slip), unit="m"))

    th = math.radians(35.0)
    mu = 0.3
    d, down = _incline_desc(th, mu, dt)
    sim = make(d)
    a_exp = G * (math.sin(th) - mu * math.cos(th))
    t, v_at = 0.0, {}
    for i in range(int(round(1.5 / sim.dt))):
        sim.step()
        t = (i + 1) * sim.dt
        for mark in (0.5, 1.5):
            if mark not in v_at and t >= mark - 1e-9:
                v_at[mark] = (t, float(sim.state()[2][1] @ down))
    (t0, v0), (t1, v1) = v_at[0.5], v_at[1.5]
    a = (v1 - v0) / (t1 - t0)
    out.append(dict(metric="incline_slide_accel", value=a, expected=a_exp, error=abs(a - a_exp) / a_exp,
                    unit="m/s^2"))
    return out


# -- collisions: analytic velocities and momentum ---------------------------------------------------
def collision(make, dt=1 / 60):
    r = 0.5
    area = math.pi * r * r
    a = {"shape": {"circle": r}, "position": [-2.0, 0.0], "velocity": [3.0, 0.0], "density": 1.0 / area,
         "restitution": 1.0, "friction": 0.0, "name": "a"}
    b = {"shape": {"circle": r}, "position": [0.0, 0.0], "density": 3.0 / area, "restitution": 1.0,
         "friction": 0.0, "name": "b"}
    sim = make(_desc("collision", [a, b], gravity=(0.0, 0.0), dt=dt))
    P0 = sim.momentum()
    for _ in range(int(round(1.5 / sim.dt))):
        sim.step()
    _, _, v, _ = sim.state()
    err = max(abs(v[0, 0] + 1.5), abs(v[1, 0] - 1.5), abs(v[0, 1]), abs(v[1, 1])) / 3.0
    dp = float(np.hypot(*(sim.momentum() - P0)) / 3.0)
    return [dict(metric="elastic_collision_velocity", value=[float(v[0, 0]), float(v[1, 0])],
                 expected=[-1.5, 1.5], error=float(err), unit="rel"),
            dict(metric="elastic_collision_momentum", value=dp, expected=0.0, error=dp, unit="rel")]


def momentum(make, dt=1 / 60, n=40, seed=3):
    rng = np.random.default_rng(seed)
    bodies = []
    cols = int(math.ceil(math.sqrt(n)))
    for i in range(n):
        x, y = 1.4 * (i % cols) + rng.uniform(-0.2, 0.2), 1.4 * (i // cols) + rng.uniform(-0.2, 0.2)
        v = rng.uniform(-3, 3, 2)
        bodies.append(_d.box(0.8, 0.8, x, y, angle=float(rng.uniform(0, 1)), velocity=(float(v[0]), float(v[1])),
                               density=float(rng.uniform(0.5, 2.0))))
    sim = make(_desc("momentum", bodies, gravity=(0.0, 0.0), dt=dt))
    _, _, v0, _ = sim.state()
    scale = float((sim.masses[:, None] * np.abs(v0)).sum())
    P0 = sim.momentum()
    for _ in range(int(round(3.0 / sim.dt))):
        sim.step()
    dp = float(np.hypot(*(sim.momentum() - P0)) / scale)
    return [dict(metric="many_body_momentum", value=dp, expected=0.0, error=dp, unit="rel")]


# -- time to rest of a pile -----------------------------------------------------------------------
def pile_rest(make, dt=1 / 60, n=100, seed=5, t_max=20.0):
    rng = np.random.default_rng(seed)
    width = 10.0
    bodies = [_d.box(width + 2, 1, 0, -0.5, kind="static", name="floor"),
              _d.box(1, 12, -width / 2 - 0.5, 6, kind="static", name="left"),
              _d.box(1, 12, width / 2 + 0.5, 6, kind="static", name="right")]
    cols = 7
    for i in range(n):
        x = -0.5 * (cols - 1) * 1.3 + 1.3 * (i % cols) + rng.uniform(-0.1, 0.1)
        y = 1.0 + 1.3 * (i // cols)
        bodies.append(_d.box(1, 1, x, y, angle=float(rng.uniform(-0.2, 0.2))))
    sim = make(_desc("pile", bodies, dt=dt))
    dyn = sim.dynamic
    calm_since = None
    t = 0.0
    rest = None
    for i in range(int(round(t_max / sim.dt))):
        sim.step()
        t = (i + 1) * sim.dt
        _, _, v, w = sim.state()
        calm = (np.hypot(v[dyn, 0], v[dyn, 1]).max() < 0.05) and (np.abs(w[dyn]).max() < 0.07)
        if calm:
            if calm_since is None:
                calm_since = t
            elif t - calm_since >= 0.5:
                rest = calm_since
                break
        else:
            calm_since = None
    out = [dict(metric="pile_time_to_rest", value=rest, expected=None, error=rest if rest is not None else t_max,
                unit="s", note="" if rest is not None else f"not at rest after {t_max:g} s")]
    pen = penetration(sim)[0]
    out.append(dict(metric="pile_max_penetration", value=pen, expected=0.0, error=pen, unit="m"))
    return out


SCENARIOS = {
    "spring": spring,
    "bounce": bounce,
    "incline": incline,
    "collision": collision,
    "momentum": momentum,
    "pile_rest": pile_rest,
}
# scenarios whose answer depends on the time step (swept over dt as well)
DT_SCENARIOS = ("spring", "bounce", "incline")


def run_scenario(name, make, dt=1 / 60):
    """Metrics of scenario ``name`` (a key of SCENARIOS); a failure is one metric row with a note."""
    try:
        return SCENARIOS[name](make, dt=dt)
    except Exception as exc:  # a mode blowing up is a result, not a crash of the benchmark
        return [dict(metric=name, value=None, expected=None, error=None, unit="",
                     note=f"failed: {type(exc).__name__}: {exc}"[:300])]
