"""Opening, saving, resetting and restoring scenes: the file side of the editor.

``errors`` holds the problems of the last scene that failed to load (shown until dismissed; the
current scene stays).  ``ask(title, lines, buttons)`` puts a question to the user (see
``panels.dialogs.Dialogs.ask``): before unsaved edits are lost, and before a file is overwritten.
Shipped scenes are read-only: saving one writes it to the user's scene folder (``scenes.save_target``).
"""
from __future__ import annotations

from pathlib import Path

from .document import restore
from .scenes import format_scene_error, load_world, save_target, user_scenes_dir


class SceneFiles:
    def __init__(self, editor, autosaver, ask):
        self.editor = editor
        self.autosaver = autosaver
        self.ask = ask
        self.errors: list[str] = []
        self.save_as_path = self.default_save_as(editor.doc.path)   # the Save-as field of the scene panel
        editor.on_document.append(lambda world, path, keep: self.follow(path))

    @staticmethod
    def default_save_as(path) -> str:
        """What the Save-as field shows for a document from ``path`` (None: a new scene)."""
        return str(save_target(path) if path else user_scenes_dir() / "untitled.json")

    def follow(self, path):
        """The Save-as field follows the current scene."""
        self.save_as_path = self.default_save_as(path)

    def confirm_unsaved(self, message, then):
        """Run ``then`` now if nothing is unsaved; otherwise ask: save first, discard, or cancel."""
        if not self.editor.doc.dirty:
            then()
            return
        self.ask("Unsaved edits", [message, "The scene has unsaved edits."],
                 [("Save, then continue", lambda: self.save(then=then)), ("Discard edits", then), ("Cancel", None)])

    def request_open(self, path):
        path = Path(path)
        self.confirm_unsaved(f"Open {path.name}?", lambda: self.open_scene(path))

    def open_scene(self, path) -> bool:
        path = Path(path)
        try:
            world = load_world(path)
        except Exception as exc:  # noqa: BLE001  (SceneError with problems, or an unreadable file)
            self.errors = [f"{path.name}:"] + format_scene_error(exc)
            self.editor.notify(f"could not load {path.name}: the current scene stays", error=True)
            return False
        self.errors = []
        self.editor.set_document(world, path)
        self.editor.notify(f"opened {path.name}")
        return True

    def save(self, path=None, then=None) -> bool:
        """Save to ``path`` (default: the document's own file, else the Save-as field).  A shipped
        scene is written to the user's scene folder instead; a file other than the document's own
        is overwritten only after asking.  ``then`` runs after a successful save.  Returns True if
        the scene was written now."""
        doc = self.editor.doc
        wanted = Path(path) if path else (doc.path or Path(self.save_as_path))
        target = save_target(wanted)
        own = doc.path is not None and target.resolve() == Path(doc.path).resolve()
        if target.exists() and not own:
            self.ask("Overwrite?", [f"{target} exists.", "Replace it with this scene?"],
                     [("Overwrite", lambda: self.write(target, wanted, then)), ("Cancel", None)])
            return False
        return self.write(target, wanted, then)

    def write(self, target: Path, wanted: Path, then=None) -> bool:
        ed = self.editor
        ed.tools["select"].end_joint()
        try:
            target.parent.mkdir(parents=True, exist_ok=True)
            ed.sync_app_data()
            ed.world.save_scene(str(target))
        except Exception as exc:  # noqa: BLE001
            ed.notify(f"save failed: {exc}", error=True)
            return False
        ed.doc.mark_saved(target)
        self.autosaver.set_origin(target)
        self.save_as_path = str(target)
        if target != wanted:
            ed.notify(f"{wanted.name} ships with Stelkropp (read-only): saved as {target}")
        else:
            ed.notify(f"saved {target}")
        if then is not None:
            then()
        return True

    def request_reset(self):
        """Reset, asking first about unsaved edits.  What to reset to is taken now: "Save, then
        continue" saves the edits (a shipped scene to a copy in the user's folder), and the reset
        must still go back to the scene as it was loaded, not to the copy just saved."""
        doc = self.editor.doc
        loaded, path = doc.loaded, doc.path
        self.confirm_unsaved("Reset to the loaded state?", lambda: self.reset(loaded, path))

    def reset(self, loaded=None, path=None):
        """Back to the loaded state (as the file has it, bodies' colours too: the document is then
        clean), keeping the solver choice (the Solver panel: mode, every mode's settings,
        integrator, broad and narrow phase, sleeping) and the view.  ``loaded``/``path``: the
        state to go back to and its file (default: the document's)."""
        ed = self.editor
        if loaded is None:
            loaded, path = ed.doc.loaded, ed.doc.path
        ed.tool.cancel()
        old = ed.world
        meta = {k: v for k, v in old.metadata.items() if k != "colors"}   # colours: the file's (in loaded)
        world = restore(loaded)
        world.metadata.update(meta)    # name, description, camera: kept by a later save
        keep_solver_choice(old, world)
        ed.set_document(world, path, keep_camera=True)
        ed.notify(f"reset to the loaded state (solver {world.solver} kept)")

    def restore_autosave(self, path, origin):
        try:
            world = load_world(path)
        except Exception as exc:  # noqa: BLE001
            self.errors = ["autosave:"] + format_scene_error(exc)
            return
        self.editor.set_document(world, Path(origin) if origin else None)
        self.editor.doc.history.version += 1
        self.editor.doc.saved_state = -1       # restored edits are unsaved
        self.autosaver.discard(path)           # offered once: its edits are this session's now
        self.editor.notify("autosave restored (unsaved)")


SOLVER_CHOICE = ("integrator", "broadphase", "narrowphase", "sleeping")


def keep_solver_choice(old, new):
    """Give ``new`` the solver mode, every mode's settings and the other Solver-panel choices of
    ``old`` (a reset must not undo the comparison the user is making)."""
    for name in old.solvers:
        try:
            new.settings_for(name).update(old.settings_for(name).to_dict())
        except (ValueError, KeyError, ImportError):
            pass
    new.solver = old.solver
    for attr in SOLVER_CHOICE:
        setattr(new, attr, getattr(old, attr))
