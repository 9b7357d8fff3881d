"""Opening, saving, resetting and restoring scenes: the file side of the editor.

``errors`` holds the problems of the last scene that failed to load (shown until dismissed; the
current scene stays).  ``confirm(message, on_discard, on_save)`` asks before unsaved edits are lost.
"""
from __future__ import annotations

from pathlib import Path

from .document import restore
from .scenes import format_scene_error, load_world


class SceneFiles:
    def __init__(self, editor, autosaver, confirm):
        self.editor = editor
        self.autosaver = autosaver
        self.confirm = confirm
        self.errors: list[str] = []
        self.save_as_path = ""      # the Save-as field of the scene panel

    def request_open(self, path):
        path = Path(path)
        if self.editor.doc.dirty:
            self.confirm(f"Open {path.name}?", lambda: self.open_scene(path),
                         lambda: self.save() and self.open_scene(path))
        else:
            self.open_scene(path)

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

    def save(self, path=None) -> bool:
        ed = self.editor
        path = Path(path) if path else ed.doc.path
        if path is None:
            path = Path(self.save_as_path or "scenes/untitled.json")
        ed.tools["select"].end_joint()
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            ed.world.save_scene(str(path))
        except Exception as exc:  # noqa: BLE001
            ed.notify(f"save failed: {exc}", error=True)
            return False
        ed.doc.mark_saved(path)
        self.autosaver.set_origin(path)
        ed.notify(f"saved {path}")
        return True

    def request_reset(self):
        if self.editor.doc.dirty:
            self.confirm("Reset to the loaded state?", self.reset, lambda: self.save() and self.reset())
        else:
            self.reset()

    def reset(self):
        ed = self.editor
        loaded = ed.doc.loaded
        path = ed.doc.path
        ed.tool.cancel()
        meta = dict(ed.world.metadata)
        world = restore(loaded)
        world.metadata.update(meta)    # name, description, camera: kept by a later save
        ed.set_document(world, path, keep_camera=True)
        ed.notify("reset to the loaded state")

    def restore_autosave(self, path, origin):
        try:
            world = load_world(path)
        except Exception as exc:  # noqa: BLE001
            self.errors = ["autosave:"] + format_scene_error(exc)
            return
        self.editor.set_document(world, Path(origin) if origin else None)
        self.editor.doc.history.version += 1   # restored edits are unsaved
        self.editor.notify("autosave restored (unsaved)")
