"""What a restore puts back (issue 15): edits that keep the topology are undone, edits that
change it are refused, and every field a step carries is in the snapshot.

The field test scrambles the carried state (warm-start impulses, penalty stick springs and
approach speeds, sleep timers, joint impulses, the energy guard's reference)
after the snapshot and checks that the restored run matches the original; the same scramble
without the restore must change the run, or the test could not fail.
"""
import numpy as np
import pytest

import physics
from test_snapshot import LEAD, first_difference, run, scene

MODES = physics.solvers_available()


def test_restore_undoes_edits_that_keep_the_topology():
    w = scene("soft_step", sleeping=False)
    run(w, LEAD)
    snap = w.snapshot()
    original = run(w, 200)
    w.restore(snap)
    w.body("bob").position = (3.0, 3.0)
    w.body("compound").kind = "kinematic"
    w.body("hung").set_shape(physics.Circle(0.4))
    w.body("hung").friction = 0.1
    w.gravity = (1.0, -3.0)
    w.settings["substeps"] = 2
    w.solver = "penalty"
    w.settings["contact_hertz"] = 40.0
    w.dt = 1 / 30
    w.sleeping = True
    w.linear_slop = 0.01
    w.restore(snap)
    assert (w.solver, w.dt, w.gravity, w.sleeping) == ("soft_step", 1 / 60, (0.0, -9.81), False)
    assert w.settings["substeps"] == 4 and w.settings_for("penalty")["contact_hertz"] == 25.0
    assert isinstance(w.body("hung").fixtures[0].shape, physics.Polygon)
    assert first_difference(original, run(w, 200)) is None


@pytest.mark.parametrize("edit, named", [
    (lambda w: w.add_body(physics.Circle(0.2), position=(9, 9)), "bodies: 1 added"),
    (lambda w: w.remove(w.body("hung")), "bodies: 1 removed"),
    (lambda w: w.body("compound").add_fixture(physics.Circle(0.1)), "fixtures: 1 added"),
    (lambda w: w.remove(w.spring("spring")), "springs: 1 removed"),
    (lambda w: w.remove(w.joint("pin")), "joints: 1 removed"),
])
def test_restore_after_adding_or_removing_refuses_and_changes_nothing(edit, named):
    w = scene("soft_step")
    run(w, 10)
    snap = w.snapshot()
    run(w, 5)
    edit(w)
    before = (w.state().copy(), w.steps, w.time)
    with pytest.raises(ValueError, match=named):
        w.restore(snap)
    after = (w.state(), w.steps, w.time)
    assert np.array_equal(before[0], after[0]) and before[1:] == after[1:]


def test_restore_takes_only_snapshots():
    w = scene("soft_step")
    with pytest.raises(ValueError, match="expected a Snapshot"):
        w.restore({"bodies": []})


def test_a_removal_reorders_the_rows_and_the_restore_puts_the_order_back():
    """Swap-remove moves the last body into the hole; restoring after remove + re-add is refused
    (new id), but a snapshot taken after the removal restores the moved order exactly."""
    w = scene("sequential_impulse", sleeping=False)
    w.remove(w.body("ground"))  # the last body (the spring's box) moves into slot 0
    w.add_body(physics.Polygon.box(20, 1), kind="static", position=(0, -0.5))
    run(w, LEAD)
    snap = w.snapshot()
    original = run(w, 100)
    w.restore(snap)
    assert first_difference(original, run(w, 100)) is None


def _scramble(w, rng):
    """Change every piece of carried state a step reads (but no body pose or velocity)."""
    st = w._store
    c = st.contacts
    for k in ("jn", "jt", "stick", "approach"):
        a = getattr(c.cur, k)[: c.n]
        a += rng.uniform(0.5, 1.0, a.shape) * (1.0 if k != "approach" else -1.0)
    c.span_step += 1
    st.bodies.arrays["sleep_t"][: st.bodies.n] += 0.3
    st.joints.arrays["impulse"][: st.joints.n] += 0.5
    st.joints.span_step += 1
    w._pipeline._guard.e0 += 100.0  # more headroom: the scrambled run must not be refused


@pytest.mark.parametrize("solver", MODES)
def test_the_snapshot_holds_the_carried_state(solver):
    w = scene(solver, sleeping=True)
    run(w, 20)  # early: the stack still settles, contacts are loaded and nobody sleeps yet
    snap = w.snapshot()
    original = run(w, 100)
    w.restore(snap)
    _scramble(w, np.random.default_rng(1))
    scrambled = run(w, 100)
    assert first_difference(original, scrambled) is not None  # the scramble matters...
    w.restore(snap)
    _scramble(w, np.random.default_rng(1))
    w.restore(snap)  # ...and the restore undoes all of it
    assert first_difference(original, run(w, 100)) is None
