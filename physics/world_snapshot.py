"""World's snapshots: save the complete dynamic state and go back to it (a part of World).

The copying is physics/snapshot.py's; this mixin is the public face.
"""
from __future__ import annotations

from . import snapshot as _snap
from .snapshot import Snapshot


class SnapshotMixin:
    """The snapshot half of :class:`~physics.World` (see world.py for the state it uses)."""

    def snapshot(self) -> Snapshot:
        """The complete dynamic state of the world, as a picklable :class:`~physics.snapshot.Snapshot`.

        Bodies (state, user forces, sleep timers), fixtures, springs, joints (impulses, broken
        flags), contacts with their warm-start impulses and penalty stick state, the settings
        (every solver mode's), time, step counter and the energy guard's reference, the touching and sensor-overlap sets (events): whatever the
        next step reads.  Restoring it and stepping gives the same bits as the run it came from.
        Copies arrays only (about 0.2 ms for 1000 bodies: ``python -m bench.snapshot``).

        >>> import physics
        >>> w = physics.World()
        >>> ball = w.add_body(physics.Circle(0.5), position=(0, 5))
        >>> snap = w.snapshot()
        >>> for _ in range(30):
        ...     w.step()
        >>> y = ball.position[1]
        >>> w.restore(snap)
        >>> ball.position[1], w.steps
        (5.0, 0)
        >>> for _ in range(30):
        ...     w.step()
        >>> ball.position[1] == y
        True
        """
        return _snap.take(self)

    def restore(self, snap: Snapshot) -> None:
        """Put the world back into the state of ``snap`` (from :meth:`snapshot` of this world, or
        unpickled); handles (bodies, fixtures, joints, springs) stay valid.

        The world must hold the same bodies, fixtures, springs and joints (by id) as when the
        snapshot was taken: after adding or removing any, ValueError names what differs and
        nothing changes.  Edits that keep the topology (positions, materials, kinds, settings,
        solver, shapes set with ``set_shape``) are undone.  ``world.fault`` and ``metadata`` are
        left as they are; the events of the step before the restore are cleared (the next
        step's are those the original run had).
        """
        self._check_editable("restore")
        _snap.restore(self, snap)
