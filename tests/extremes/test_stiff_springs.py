"""Extremes: stiff springs, k = 1e6 N/m on 1 kg at dt = 1/60 (issue 9)."""
import numpy as np
import pytest

import physics
from bench.scenarios.extremes import STIFF_K, stiff_spring, was_refused
from extremes_common import CONTINUOUS, MODES, integrators


@pytest.mark.parametrize("solver", CONTINUOUS)
def test_stiff_spring_stays_finite_and_energy_does_not_grow(solver):
    """Regime: k = 1e6 N/m, 1 kg, dt = 1/60 (k dt^2/m = 278), undamped, stretched 0.1 m (5000 J).

    Outcome: 600 steps finite, no SimulationError, the total energy never exceeds its initial
    value by more than 1% (the implicit form damps it instead)."""
    m = stiff_spring(solver)
    assert not was_refused(m), m
    assert m["finite"]
    assert m["growth"] <= 1.01
    assert m["retained"] <= 1.0


SEED = [(m, i) for m in MODES if m not in CONTINUOUS for i in integrators(m)]


@pytest.mark.parametrize("solver,integrator", SEED)
def test_explicit_modes_substep_or_report_instability(solver, integrator):
    """Regime: the same k = 1e6 spring in each explicit seed mode and integrator.

    Outcome: either finite (automatic sub-stepping) with no secular energy growth -- a
    symplectic method's energy oscillates about its shadow Hamiltonian, so the peak energy in
    the last quarter of the run may not exceed the first quarter's by more than 1% -- or a
    SimulationError while the world stays finite and was reverted, with no step accepted
    before it that grew the energy by more than 1% (no garbage before the error)."""
    m = stiff_spring(solver, integrator=integrator)
    if was_refused(m):
        assert m["growth"] <= 1.01, m
        assert m["reverted"], m
        assert m["stage"]
    else:
        assert m["finite"], m
        assert m["drift"] <= 1.01, m


def test_stiff_spring_energy_is_measured_right():
    """Regime: the probe's own energy bookkeeping (a guard for the figures above).

    Outcome: the initial energy is 1/2 k (0.1 m)^2 = 5000 J to 1e-9."""
    w = physics.World(gravity=(0, 0))
    b = w.add_body(physics.Polygon.box(1, 1), position=(1.1, 0.0))
    w.add_spring(b, None, anchor_b=(0, 0), stiffness=STIFF_K, rest_length=1.0)
    assert w.kinetic_energy() + w.potential_energy() == pytest.approx(0.5 * STIFF_K * 0.01, rel=1e-9)
    assert np.isfinite(w.potential_energy())
