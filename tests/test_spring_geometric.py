"""Springs whose turning axis and arms are stiff (issue 20, item 1): no energy from nothing.

The issue's repro: a 10 g box (0.1 m side, I = 1.7e-5 kg m^2) on a k = 1e4 N/m spring
anchored 0.2 m off its centre, rest length 0, no gravity, dt = 1/60.  The initial energy
is 1/2 k |(0.2, 0) - (0, 1)|^2 = 5200 J.  Before the fix soft_step went to 1.6e102 J in
300 steps without an error: the tension T ~ 1e4 N on the arm r = 0.2 m gives the angle a
stiffness T r / I (omega ~ 1e4 rad/s, omega h ~ 40 at 240 Hz sub-steps) that the implicit
axis row did not contain.
"""
import math

import pytest

import physics
from physics.errors import SimulationError

E0 = 0.5 * 1e4 * (0.2 ** 2 + 1.0 ** 2)  # J, the repro's initial elastic energy


def total_energy(w):
    return w.kinetic_energy() + w.potential_energy()


def repro(solver, stiffness=1e4, density=1.0, arm=0.2):
    w = physics.World(gravity=(0, 0), solver=solver, sleeping=False)
    b = w.add_body(physics.Polygon.box(0.1, 0.1), density=density)
    w.add_spring(b, None, anchor_a=(arm, 0), anchor_b=(0, 1), stiffness=stiffness, rest_length=0)
    return w


def energies(w, steps):
    out = []
    for _ in range(steps):
        w.step()
        out.append(total_energy(w))
    return out


def test_repro_energy_is_the_stretch_energy():
    """Guard for the bounds below: the measured initial energy is 1/2 k d^2 = 5200 J."""
    assert total_energy(repro("soft_step")) == pytest.approx(E0, rel=1e-12)


@pytest.mark.parametrize("solver", ["soft_step", "sequential_impulse"])
def test_off_centre_stiff_spring_does_not_gain_energy(solver):
    """Backward Euler on the spring's full stiffness (axis and geometric rows, each positive
    semi-definite) only removes energy: no step may exceed the initial 5200 J by more than
    1e-6 relative (round-off), over 300 steps (the issue's run)."""
    w = repro(solver)
    es = energies(w, 300)
    assert all(math.isfinite(e) for e in es)
    assert max(es) <= E0 * (1 + 1e-6), max(es)


@pytest.mark.parametrize("solver", ["soft_step", "sequential_impulse"])
@pytest.mark.parametrize("stiffness", [1e6, 1e9])
def test_stiffer_off_centre_springs_do_not_gain_energy(solver, stiffness):
    """The same at the fuzzer's top stiffnesses (1e6, 1e9 N/m): 300 steps, no gain over E0."""
    w = repro(solver, stiffness=stiffness)
    e0 = total_energy(w)
    es = energies(w, 300)
    assert max(es) <= e0 * (1 + 1e-6), max(es) / e0


def test_soft_off_centre_spring_is_not_damped():
    """Where the geometric modes are soft for the sub-step they stay explicit (symplectic
    Euler), so a slow swing keeps its energy: 1 kg box (density 100), k = 100 N/m
    (omega h ~ 0.2 at 240 Hz sub-steps).  Symplectic Euler's measured energy oscillates about
    its shadow Hamiltonian by O(omega h) (here up to 11%), so the bounds are: no secular
    growth (the last quarter's peak within 1% of the first quarter's) and at least 90% of the
    energy still there after 600 steps (10 s)."""
    w = repro("soft_step", stiffness=100.0, density=100.0)
    e0 = total_energy(w)
    es = energies(w, 600)
    assert max(es[-150:]) <= max(es[:150]) * 1.01
    assert es[-1] >= 0.9 * e0, es[-1] / e0


@pytest.mark.parametrize("solver", ["impulse", "penalty", "hybrid"])
def test_seed_modes_count_the_geometric_rate(solver):
    """The explicit seed modes sub-step by the spring's fastest rate, which now includes the
    geometric omega sqrt(T r / I) ~ 1.2e4 rad/s (the axis alone gives 5e3): at dt = 1/60 that
    needs ~200 sub-steps, more than max_substeps = 32, so the step is refused (SimulationError
    at 'solve', world.fault set, nothing moved) instead of run unstably."""
    w = repro(solver)
    with pytest.raises(SimulationError) as info:
        w.step()
    assert info.value.stage == "solve"
    assert "sub-steps" in str(info.value)
    assert w.fault is info.value
    assert total_energy(w) == pytest.approx(E0, rel=1e-12)
