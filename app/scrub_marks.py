"""Which edits a timeline scrub undoes: each snapshot is marked with where the document's
history stood when it was taken; scrubbing back to a snapshot taken while the scene was saved,
past edits the snapshot holds (positions, materials, world settings: ``world.restore`` puts them
back), leaves the scene as saved, so it is shown clean (no "*") until the next change."""
from __future__ import annotations

from .commands import Group, SetFixture, SetProperty, SetWorld

#: SetWorld labels a snapshot does not restore
NOT_RESTORED = ("solver",)


def restored(cmd) -> bool:
    """Does ``world.restore`` of an earlier snapshot undo ``cmd`` (names are not in snapshots)?"""
    if isinstance(cmd, Group):
        return all(restored(c) for c in cmd.commands)
    if isinstance(cmd, (SetProperty, SetFixture)):
        return cmd.field != "name"
    return isinstance(cmd, SetWorld) and cmd.label not in NOT_RESTORED


def mark(doc) -> tuple:
    """Where ``doc``'s history stands now (stored with a snapshot)."""
    return id(doc), doc.history.state(), len(doc.history.done)


def scrubbed(doc, at) -> None:
    """After a scrub to a snapshot marked ``at``: clean if that moment was saved and every edit
    since is one the snapshot undid (a scrub to a later moment shows the edits again)."""
    doc.clean_at = None
    if at is None or at[0] != id(doc) or at[1] != doc.saved_state:
        return
    if all(restored(c) for c in doc.history.done[at[2]:]):
        doc.clean_at = doc.history.version
