"""Scene section: the file, the list of scenes, open, save and save as, the last load's errors."""
from __future__ import annotations

from pathlib import Path

from imgui_bundle import imgui

from ..scenes import scene_files, user_scenes_dir
from .base import Section, record
from .style import AMBER, DIM, ENTER, RED


class SceneSection(Section):
    title = "Scene"
    default_open = False

    def __init__(self, app):
        super().__init__(app)
        self.open_path = ""
        self.focus_save_as = False     # Ctrl+Shift+S: open the section and type in the Save-as field

    def force_open(self) -> bool:
        return self.app.files.errors != [] or self.focus_save_as

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
        save_as = imgui.button("Save as")
        imgui.same_line()
        imgui.set_next_item_width(-1)
        if self.focus_save_as:
            self.focus_save_as = False
            imgui.set_scroll_here_y()
            imgui.set_keyboard_focus_here()
        entered, files.save_as_path = imgui.input_text("##saveas", files.save_as_path, ENTER)
        record(app, "scene:save_as")
        if save_as or entered:
            files.save(Path(files.save_as_path))
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
        """Shipped scenes (read-only: saving one writes to the user's folder) and the user's own."""
        user_dir = user_scenes_dir()
        groups = ((f"yours: {user_dir}", scene_files(user_dir)), ("shipped (read-only)", scene_files()))
        rows = sum(len(f) for _, f in groups) + 3
        if imgui.begin_list_box("##scenes", imgui.ImVec2(-1, min(10, max(3, rows)) * 20 + 6)):
            for title, files in groups:
                imgui.text_colored(DIM, title)
                if not files:
                    imgui.text_colored(DIM, "  (none yet: save a scene)")
                for f in files:
                    self.scene_row(doc, f)
            imgui.end_list_box()

    def scene_row(self, doc, f):
        cur = doc.path is not None and Path(doc.path).resolve() == f.resolve()
        clicked, _ = imgui.selectable(f"  {f.name}##{f}", cur, imgui.SelectableFlags_.allow_double_click.value)
        record(self.app, f"scene:{f}")
        if clicked and imgui.is_mouse_double_clicked(0):
            self.app.files.request_open(f)
        elif clicked:
            self.open_path = str(f)
