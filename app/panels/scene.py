"""Scene section: the file, the list of scenes, open, save and save as, the last load's errors."""
from __future__ import annotations

from pathlib import Path

from imgui_bundle import imgui

from ..scenes import scene_files
from .base import Section
from .style import AMBER, DIM, RED


class SceneSection(Section):
    title = "Scene"
    default_open = False

    def __init__(self, app):
        super().__init__(app)
        self.open_path = ""

    def force_open(self) -> bool:
        return self.app.files.errors != []

    def draw(self):
        app, files = self.app, self.app.files
        doc = app.editor.doc
        imgui.text(f"file: {doc.path if doc.path else '(none)'}")
        if doc.dirty:
            imgui.same_line()
            imgui.text_colored(AMBER, "unsaved edits")
        self.scene_list(doc)
        ch, self.open_path = imgui.input_text("##openpath", self.open_path)
        imgui.same_line()
        if imgui.button("Open") and self.open_path:
            files.request_open(Path(self.open_path))
        if imgui.button("Save (Ctrl+S)"):
            files.save()
        imgui.same_line()
        if not files.save_as_path:
            files.save_as_path = str(doc.path) if doc.path else "scenes/my_scene.json"
        if imgui.button("Save as"):
            files.save(Path(files.save_as_path))
        imgui.same_line()
        imgui.set_next_item_width(-1)
        _, files.save_as_path = imgui.input_text("##saveas", files.save_as_path)
        imgui.text_colored(DIM, "Or drop a .json scene file onto the window.")
        if files.errors:
            imgui.push_text_wrap_pos(0)
            imgui.text_colored(RED, "Could not load the scene (the current one stays):")
            for line in files.errors[:30]:
                imgui.bullet_text(line)
            imgui.pop_text_wrap_pos()
            if imgui.small_button("dismiss##sceneerr"):
                files.errors = []

    def scene_list(self, doc):
        files = scene_files()
        if imgui.begin_list_box("##scenes", imgui.ImVec2(-1, min(8, max(2, len(files))) * 20 + 6)):
            for f in files:
                cur = doc.path is not None and Path(doc.path).resolve() == f.resolve()
                clicked, _ = imgui.selectable(f.name, cur, imgui.SelectableFlags_.allow_double_click.value)
                if clicked and imgui.is_mouse_double_clicked(0):
                    self.app.files.request_open(f)
                elif clicked:
                    self.open_path = str(f)
            imgui.end_list_box()
