"""Scene files are read and written only as regular files: saving never renames over a FIFO or a
device (run as root, ``--out /dev/null`` replaced the system's /dev/null), and loading or
validating a FIFO with no writer is refused at once instead of blocking forever."""
import os
import stat
import subprocess
import sys
from pathlib import Path

import pytest

import physics
import physics.scene.atomic as atomic

ROOT = Path(__file__).resolve().parent.parent
SCENE = ROOT / "scenes" / "pyramid.json"
pytestmark = pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="needs FIFOs (POSIX)")


@pytest.fixture
def fifo(tmp_path):
    p = tmp_path / "pipe.json"
    os.mkfifo(p)
    return p


@pytest.fixture
def device(tmp_path):
    """A private node of the null device (never the system's /dev/null: a regression would replace it)."""
    p = tmp_path / "null"
    try:
        os.mknod(p, stat.S_IFCHR | 0o666, os.makedev(1, 3))
    except (PermissionError, AttributeError):
        pytest.skip("cannot make a device node here")
    return p


@pytest.fixture
def no_rename(monkeypatch):
    """Even a regression must not replace a special file while the test runs."""
    def refuse(src, dst):
        raise AssertionError(f"renamed over {dst}")
    monkeypatch.setattr(atomic.os, "replace", refuse)


def small_world():
    w = physics.World()
    w.add_body(physics.Circle(0.5), name="ball")
    return w


def test_save_scene_refuses_a_fifo_and_leaves_it(fifo, no_rename):
    with pytest.raises(OSError, match="FIFO"):
        small_world().save_scene(fifo)
    assert stat.S_ISFIFO(os.stat(fifo).st_mode)
    assert [p.name for p in fifo.parent.iterdir()] == ["pipe.json"]  # no temporary file left


def test_save_scene_refuses_a_device(device, no_rename):
    with pytest.raises(OSError, match="character device"):
        small_world().save_scene(device)
    assert stat.S_ISCHR(os.stat(device).st_mode)


def test_save_scene_through_a_link_to_a_fifo_is_refused(tmp_path, fifo, no_rename):
    link = tmp_path / "link.json"
    link.symlink_to(fifo)
    with pytest.raises(OSError, match="not a regular file"):
        physics.save_scene(small_world(), link)
    assert stat.S_ISFIFO(os.stat(fifo).st_mode) and link.is_symlink()


def _cli(*args, timeout=60):
    return subprocess.run([sys.executable, "-m", "physics", *map(str, args)], cwd=ROOT, capture_output=True,
                          text=True, timeout=timeout)


@pytest.mark.parametrize("target", ["fifo", "device"])
def test_simulate_out_refuses_special_files_before_the_run(fifo, device, target):
    out = fifo if target == "fifo" else device
    before = os.stat(out)
    res = _cli("simulate", SCENE, "--steps", 2, "--out", out)
    assert res.returncode == 1 and "not a regular file" in res.stderr, res.stderr
    after = os.stat(out)
    assert (after.st_ino, after.st_mode) == (before.st_ino, before.st_mode)


def test_load_scene_on_a_fifo_is_refused_without_blocking(fifo):
    code = ("import physics, sys\ntry:\n    physics.load_scene(sys.argv[1])\nexcept physics.SceneError as e:\n"
            "    print(e)\n")
    res = subprocess.run([sys.executable, "-c", code, str(fifo)], cwd=ROOT, capture_output=True, text=True,
                         timeout=60)
    assert "FIFO" in res.stdout and "not a regular file" in res.stdout, (res.stdout, res.stderr)


def test_validate_on_a_fifo_and_a_device_is_refused_without_blocking(fifo):
    res = _cli("validate", fifo, "/dev/zero", SCENE)  # reading never writes: the real device is safe
    assert res.returncode == 1
    assert "FIFO" in res.stdout and "character device" in res.stdout and "pyramid.json: ok" in res.stdout
