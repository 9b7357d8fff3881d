"""Steps whose numbers leave the float range are refused, not run or crashed (issue 20, items 1, 3, 8).

A refused step raises SimulationError naming its stage, sets ``world.fault`` and leaves the
world as it was before the step.  Each test is an issue's minimal repro.
"""
import math

import pytest

import physics
from physics.errors import SimulationError

PIPELINE_STAGES = {"begin", "broadphase", "collide", "solve", "sleep"}


def state(w):
    return w.state().tobytes()


@pytest.mark.parametrize("dt", [2e-323, 5e-324, 1e-300, 1e-12])
@pytest.mark.parametrize("solver", physics.solvers_available())
def test_tiny_dt_is_a_value_error_naming_dt(solver, dt):
    """dt ~ 2e-323 gave ZeroDivisionError in soft_step (1/dt overflows, then h = dt / n
    underflows to 0); every step below physics.world.DT_MIN (1e-9 s) is ValueError naming 'dt', in
    step() and in the dt setter, and the world is untouched."""
    w = physics.World(solver=solver)
    w.add_body(physics.Polygon.box(1, 1), position=(0, 1))
    with pytest.raises(ValueError, match="dt"):
        w.step(dt)
    with pytest.raises(ValueError, match="dt"):
        w.dt = dt
    assert w.steps == 0 and w.fault is None


@pytest.mark.parametrize("solver", ["impulse", "penalty", "hybrid"])
def test_seed_mode_rate_overflow_is_refused_with_fault(solver):
    """A spring whose rate x dt overflows an integer (k = 1e308 on 1 kg: omega ~ 1e154 1/s)
    gave OverflowError from the sub-step count and left world.fault unset."""
    w = physics.World(gravity=(0, 0), solver=solver, dt=1.0)
    b = w.add_body(physics.Polygon.box(1, 1), position=(2, 0))
    w.add_spring(b, None, anchor_b=(0, 0), stiffness=1e308, rest_length=1.0)
    before = state(w)
    with pytest.raises(SimulationError) as info:
        w.step()
    assert info.value.stage == "solve"
    assert w.fault is info.value
    assert state(w) == before


@pytest.mark.parametrize("solver", physics.solvers_available())
def test_infinite_kinetic_energy_at_finite_speed_is_refused(solver):
    """48 fuzzed runs reached finite speeds whose kinetic energy overflowed to inf and passed a
    check of the state alone.  1 kg at 1e160 m/s: 1/2 m v^2 = 5e319 J = inf.  The step is
    refused (SimulationError naming the body and a real stage, world.fault set, state kept)."""
    w = physics.World(gravity=(0, 0), solver=solver)
    b = w.add_body(physics.Circle(0.5), name="bullet", velocity=(1e160, 0.0))
    assert math.isfinite(b.velocity[0]) and not math.isfinite(w.kinetic_energy())
    before = state(w)
    with pytest.raises(SimulationError, match="energy") as info:
        w.step()
    assert info.value.bodies == ["bullet"]
    assert info.value.stage in PIPELINE_STAGES
    assert w.fault is info.value
    assert state(w) == before


def test_infinite_spring_energy_is_caught_by_the_finite_check():
    """Elastic energy overflowing at finite positions (k = 1e300 stretched 1e5 m: 5e309 J) is
    what the end-of-step check refuses too (checked on the check itself: a step from this state
    may legitimately end finite, e.g. sequential_impulse's implicit spring pulls the body in)."""
    from physics.step.checkpoint import Checkpoint
    w = physics.World(gravity=(0, 0))
    b = w.add_body(physics.Circle(0.5), name="far", position=(1e5, 0.0))
    w.add_spring(b, None, anchor_b=(0, 0), stiffness=1e300, rest_length=0.0)
    s = w._store
    ck = Checkpoint()
    assert ck.nonfinite(s.bodies.view, s.bodies.n, s.springs.view, s.springs.n) == [b._s]
    assert ck.energy
    b.position = (1.0, 0.0)  # 5e299 J: finite
    assert ck.nonfinite(s.bodies.view, s.bodies.n, s.springs.view, s.springs.n) == []


@pytest.mark.parametrize("solver", physics.solvers_available())
def test_finite_body_near_float_max_is_not_refused(solver):
    """The finite check added the components, so a finite body at (1e308, 1e308) (sum inf)
    was refused on every step; each component is checked now."""
    w = physics.World(gravity=(0, 0), solver=solver)
    b = w.add_body(physics.Circle(0.5), position=(1e308, 1e308), velocity=(1.0, 0.0))
    for _ in range(3):
        w.step()
    assert w.fault is None and w.steps == 3
    assert b.position[1] == 1e308


@pytest.mark.parametrize("solver", physics.solvers_available())
def test_fault_names_a_real_stage(solver):
    """Some fault messages named the stage '?'; every refusal names a pipeline stage."""
    w = physics.World(gravity=(0, 0), solver=solver)
    w.add_body(physics.Circle(0.5), velocity=(1e160, 0.0))
    with pytest.raises(SimulationError) as info:
        w.step()
    assert info.value.stage in PIPELINE_STAGES
    assert "'?'" not in str(info.value)
