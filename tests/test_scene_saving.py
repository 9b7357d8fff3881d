"""Issue 20 item 7: saving leaves no temporary files (not after a failure, and not after an earlier
kill -9 once the same name is saved again), writes through symbolic links, and saves any legal name."""
import os
import signal
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

import physics
from physics.scene import atomic, load_scene, save_scene, scene_from_dict

ROOT = Path(__file__).resolve().parent.parent
SCENE = {"format": "stelkropp.scene", "version": 1, "name": "s",
         "bodies": [{"name": "a", "shape": {"box": [1, 1]}, "position": [0, 0.5]}]}


def temps(folder):
    return sorted(n for n in os.listdir(folder) if n.endswith(".tmp"))


@pytest.mark.parametrize("exc", [OSError("disk full"), KeyboardInterrupt()])
def test_interrupted_save_cleans_up(tmp_path, monkeypatch, exc):
    w = scene_from_dict(SCENE)
    p = tmp_path / "scene.json"
    save_scene(w, p)
    before = p.read_text()

    def interrupt(*_):
        raise exc

    monkeypatch.setattr(os, "replace", interrupt)
    w.bodies[0].position = (3, 3)
    with pytest.raises(type(exc)):
        save_scene(w, p)
    assert temps(tmp_path) == [] and p.read_text() == before


def test_stale_temp_files_of_dead_writers_are_removed(tmp_path):
    """A kill -9 leaves its temporary file; the next save to that name removes it, but not the file
    of a writer that still runs, nor the temporary files of other names."""
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True,
                          text=True, check=True)
    dead_pid = int(dead.stdout)  # exited: no process has this id now (unless reused; then it is kept)
    stale = tmp_path / f".scene.json.{dead_pid}.0123abcd.tmp"
    live = tmp_path / f".scene.json.{os.getppid()}.0123abcd.tmp"
    other = tmp_path / f".other.json.{dead_pid}.0123abcd.tmp"
    for f in (stale, live, other):
        f.write_text("half a fi")
    save_scene(scene_from_dict(SCENE), tmp_path / "scene.json")
    assert temps(tmp_path) == sorted([live.name, other.name])


def test_kill_during_save_then_save_again_leaves_no_temp_file(tmp_path):
    """A real kill -9 while the temporary file is half written (the child stops inside fsync)."""
    target = tmp_path / "big.json"
    child = textwrap.dedent(f"""
        import os, sys, time
        sys.path.insert(0, {str(ROOT)!r})
        import physics
        from physics.scene import scene_from_dict
        w = scene_from_dict({SCENE!r})
        def hang(fd):
            print("writing", flush=True)
            time.sleep(600)
        os.fsync = hang
        physics.save_scene(w, {str(target)!r})
    """)
    proc = subprocess.Popen([sys.executable, "-c", child], stdout=subprocess.PIPE, text=True)
    try:
        assert proc.stdout.readline().strip() == "writing"
        assert len(temps(tmp_path)) == 1  # the state a kill leaves behind
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait(timeout=60)
    finally:
        if proc.poll() is None:
            proc.kill()
    assert not target.exists() and len(temps(tmp_path)) == 1
    physics.save_scene(scene_from_dict(SCENE), target)
    assert temps(tmp_path) == [] and load_scene(target).bodies[0].name == "a"


def test_saving_over_a_symlink_writes_its_target_and_keeps_the_link(tmp_path):
    real = tmp_path / "real" / "scene.json"
    real.parent.mkdir()
    save_scene(scene_from_dict(SCENE), real)
    link = tmp_path / "link.json"
    link.symlink_to(real)
    w = scene_from_dict(SCENE)
    w.metadata["name"] = "through the link"
    save_scene(w, link)
    assert link.is_symlink() and os.readlink(link) == str(real)
    assert load_scene(real).metadata["name"] == "through the link"
    assert temps(tmp_path) == [] and temps(real.parent) == []


def test_saving_through_a_dangling_symlink_creates_its_target(tmp_path):
    link = tmp_path / "link.json"
    link.symlink_to(tmp_path / "new.json")
    save_scene(scene_from_dict(SCENE), link)
    assert link.is_symlink() and load_scene(tmp_path / "new.json").bodies[0].name == "a"


@pytest.mark.parametrize("length", [242, 250, 255])
def test_names_up_to_name_max_can_be_saved(tmp_path, length):
    limit = os.pathconf(tmp_path, "PC_NAME_MAX")
    assert limit >= 255
    p = tmp_path / ("n" * (length - 5) + ".json")
    save_scene(scene_from_dict(SCENE), p)
    save_scene(scene_from_dict(SCENE), p)  # and again, over the existing file
    assert load_scene(p).bodies[0].name == "a" and temps(tmp_path) == []


def test_multibyte_long_name_is_shortened_at_a_character(tmp_path):
    p = tmp_path / ("ö" * 125 + ".json")  # 255 bytes in UTF-8
    save_scene(scene_from_dict(SCENE), p)
    assert p.exists() and temps(tmp_path) == []
    prefix = atomic._temp_prefix(str(tmp_path), p.name)
    assert len(os.fsencode(prefix)) + len("4294967295.0123abcd.tmp") <= 255  # the longest pid fits too


def test_new_file_mode_and_kept_mode(tmp_path):
    p = tmp_path / "m.json"
    save_scene(scene_from_dict(SCENE), p)
    assert os.stat(p).st_mode & 0o777 == 0o644
    os.chmod(p, 0o600)
    save_scene(scene_from_dict(SCENE), p)
    assert os.stat(p).st_mode & 0o777 == 0o600
