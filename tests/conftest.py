"""Shared test setup: the repository root is importable without an install, and the tests' own
helper modules (builders, end_states, extreme_pins, seed_scenes) from every test directory."""
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
for path in (ROOT, ROOT / "tests"):
    if str(path) not in sys.path:
        sys.path.insert(0, str(path))

# Property tests draw the same examples on every run: a CI verdict must not depend on the seed.
# `HYPOTHESIS_PROFILE=explore pytest ...` draws fresh examples when hunting for new failures.
from hypothesis import settings as _hypothesis_settings  # noqa: E402

_hypothesis_settings.register_profile("ci", derandomize=True, print_blob=True)
_hypothesis_settings.register_profile("explore", derandomize=False, print_blob=True)
import os as _os  # noqa: E402

_hypothesis_settings.load_profile(_os.environ.get("HYPOTHESIS_PROFILE", "ci"))


def pytest_addoption(parser):
    parser.addoption("--box2d-src", metavar="DIR", default=None,
                     help="Box2D v3 source tree for the tests that run it beside Stelkropp "
                          "(default: $STELKROPP_BOX2D_SRC, else ../shared/reference/box2d-v3; none: they skip)")


def pytest_configure(config):
    src = config.getoption("--box2d-src")
    if src:  # the bench's builder reads the variable (bench/box2d/build.py find_source)
        _os.environ["STELKROPP_BOX2D_SRC"] = str(Path(src).expanduser().resolve())


# Every kernel the tests compile is checked where numba's runtime stops (physics/compile_checks.py):
# a runtime-free kernel that returns arrays, or takes them from one with the runtime, fails the
# test that compiled it instead of corrupting the heap later.
from numba.core import event as _numba_event  # noqa: E402

from physics.compile_checks import ReturnCheck as _ReturnCheck  # noqa: E402

_numba_event.register("numba:compile", _ReturnCheck())
