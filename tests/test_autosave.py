"""The sandbox's autosave (issue 9): written every interval while there are unsaved edits,
offered after a crash, never after a clean exit.  Headless: only app.autosave is exercised."""
import json
import subprocess
import sys
from types import SimpleNamespace

import physics
from app.autosave import Autosaver
from builders import ground


def document(world, dirty=True, version=1):
    return SimpleNamespace(world=world, dirty=dirty, path=None, history=SimpleNamespace(version=version))


def small_world():
    w = physics.World()
    ground(w, width=4)
    w.add_body(physics.Polygon.box(1, 1), position=(0.25, 3), name="box")
    return w


def test_autosaves_edits_after_the_interval_only(tmp_path):
    a = Autosaver(interval=3600.0, directory=tmp_path)
    doc = document(small_world())
    assert not a.tick(doc)                    # interval not yet passed
    a.interval = 0.0
    assert not a.tick(document(small_world(), dirty=False))  # nothing unsaved: nothing written
    assert a.tick(doc)
    assert physics.load_scene(a.file).body("box").position == (0.25, 3.0)
    assert not a.tick(doc)                    # same version: not written again


def test_offered_after_a_crash_not_after_a_clean_exit(tmp_path):
    a = Autosaver(interval=0.0, directory=tmp_path)
    a.begin_session("scenes/default.json")
    a.save(document(small_world()))
    # a session whose process died: its marker names a pid that no longer exists
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                          capture_output=True, text=True, check=True)
    info = json.loads(a.marker.read_text())
    info["pid"] = int(dead.stdout)
    a.marker.write_text(json.dumps(info))
    offer = Autosaver(directory=tmp_path).previous_crash()
    assert offer is not None and offer[0] == a.file and offer[2] == "scenes/default.json"
    a.end_session()
    assert Autosaver(directory=tmp_path).previous_crash() is None


def test_a_file_name_that_is_not_utf8_still_autosaves(tmp_path):
    """Such a name reaches Python with lone surrogates, which a scene file cannot hold: the
    title takes U+FFFD for those bytes instead of the autosave failing."""
    from pathlib import Path
    a = Autosaver(interval=0.0, directory=tmp_path)
    doc = document(small_world())
    doc.path = Path("caf\udce9.json")  # os.fsdecode(b"caf\xe9.json")
    assert a.save(doc), a.error
    assert physics.load_scene(a.file).metadata["name"] == "caf\ufffd (autosave)"
