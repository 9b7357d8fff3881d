"""Build Box2D v3 (cmake + ninja, Release) and Stelkropp's C shim against it, once per source state.

The build goes to ``<cache>/box2d/<hash>/`` where ``<cache>`` is ``$STELKROPP_CACHE_DIR`` or
``~/.cache/stelkropp`` and ``<hash>`` covers every Box2D source file, our shim sources, the
compiler and the build flags: while none of them changes, the cached library is reused (about
10 ms to check). A cold build takes ~20-40 s on two cores; progress and timings go to stderr.

Command line: ``python -m bench.box2d.build [--box2d-src DIR] [--force]``.
"""
from __future__ import annotations

import argparse
import fcntl
import hashlib
import os
import platform
import shutil
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
HERE = Path(__file__).resolve().parent
SHIM_SOURCES = ("shim.c", "shim_ops.c", "shim_read.c", "shim_tasks.c", "shim.h")
DEFAULT_SRC = ROOT.parent / "shared" / "reference" / "box2d-v3"
SHIM_LIB = "libstelkropp_box2d.so"
# Deterministic, Release, no samples/tests (they need GLFW/imgui); benchmark app for validation.
# -fPIC: the static libbox2d.a is linked into our shared library.
CMAKE_FLAGS = ("-DBOX2D_SAMPLES=OFF", "-DBOX2D_UNIT_TESTS=OFF", "-DBOX2D_BENCHMARKS=ON",
               "-DCMAKE_BUILD_TYPE=Release", "-DCMAKE_POSITION_INDEPENDENT_CODE=ON")
SHIM_CFLAGS = ("-O2", "-fPIC", "-shared", "-std=gnu17", "-ffp-contract=off", "-pthread")


class BuildError(RuntimeError):
    """Box2D v3 or the shim could not be built; the message says why (tool, sources, log tail)."""


@dataclass(frozen=True)
class Build:
    """Where a finished build lives: the shim library, Box2D's benchmark app, the snapshot id."""
    directory: Path
    library: Path
    benchmark: Path
    source: Path
    snapshot: str


def find_source(box2d_src=None) -> Path:
    """The Box2D v3 source tree: ``box2d_src``, else ``$STELKROPP_BOX2D_SRC``, else the project's
    ``../shared/reference/box2d-v3``. Raises ``BuildError`` when it is not a Box2D v3 tree."""
    src = Path(box2d_src or os.environ.get("STELKROPP_BOX2D_SRC") or DEFAULT_SRC).expanduser().resolve()
    if not (src / "include" / "box2d" / "box2d.h").is_file() or not (src / "src" / "CMakeLists.txt").is_file():
        raise BuildError(f"no Box2D v3 sources at {src} (need include/box2d/box2d.h and src/CMakeLists.txt; "
                         "pass --box2d-src DIR pointing at a Box2D v3 checkout)")
    return src


def snapshot_id(src: Path) -> str:
    """The commit the tree was taken from (its ``SNAPSHOT`` file or ``git rev-parse``), else 'unknown'."""
    snap = src / "SNAPSHOT"
    if snap.is_file():
        return snap.read_text().strip()
    try:
        out = subprocess.run(["git", "-C", str(src), "rev-parse", "HEAD"], capture_output=True, text=True,
                             timeout=10)
        if out.returncode == 0:
            return out.stdout.strip()
    except (OSError, subprocess.SubprocessError):
        pass
    return "unknown"


def _tools():
    missing = [t for t in ("cmake", "ninja") if shutil.which(t) is None]
    cc = os.environ.get("CC") or shutil.which("cc") or shutil.which("gcc") or shutil.which("clang")
    if cc is None:
        missing.append("a C compiler (cc/gcc/clang)")
    if missing:
        raise BuildError("cannot build Box2D v3: missing " + ", ".join(missing)
                         + " (Debian: apt-get install cmake ninja-build gcc)")
    return cc


def _avx2() -> bool:
    try:
        return platform.machine() in ("x86_64", "AMD64") and " avx2" in Path("/proc/cpuinfo").read_text()
    except OSError:
        return False


def _fingerprint(src: Path, cc: str, flags) -> str:
    h = hashlib.sha256()
    for sub in ("src", "include", "shared", "benchmark"):
        for p in sorted((src / sub).rglob("*")):
            if p.is_file() and p.suffix in (".c", ".h", ".inl", ".txt", ".cpp"):
                h.update(str(p.relative_to(src)).encode())
                h.update(p.read_bytes())
    h.update((src / "CMakeLists.txt").read_bytes())
    ver = subprocess.run([cc, "--version"], capture_output=True, text=True).stdout
    h.update(ver.encode())
    h.update(repr(flags).encode())
    return h.hexdigest()[:16]


def _shim_fingerprint(box2d_key: str) -> str:
    h = hashlib.sha256(box2d_key.encode())
    for name in SHIM_SOURCES:
        h.update((HERE / name).read_bytes())
    h.update(repr(SHIM_CFLAGS).encode())
    return h.hexdigest()[:12]


def cache_root() -> Path:
    """``$STELKROPP_CACHE_DIR/box2d`` or ``~/.cache/stelkropp/box2d`` (XDG_CACHE_HOME respected)."""
    base = os.environ.get("STELKROPP_CACHE_DIR")
    if not base:
        base = os.path.join(os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"), "stelkropp")
    return Path(base) / "box2d"


def _run(cmd, cwd, log, what, quiet):
    t0 = time.perf_counter()
    with open(log, "a") as f:
        f.write("$ " + " ".join(map(str, cmd)) + "\n")
        f.flush()
        r = subprocess.run(list(map(str, cmd)), cwd=cwd, stdout=f, stderr=subprocess.STDOUT)
    if r.returncode != 0:
        tail = "".join(Path(log).read_text().splitlines(True)[-25:])
        raise BuildError(f"{what} failed (exit {r.returncode}); log {log}:\n{tail}")
    if not quiet:
        print(f"[box2d] {what}: {time.perf_counter() - t0:.1f} s", file=sys.stderr, flush=True)


def build(box2d_src=None, force=False, quiet=False) -> Build:
    """Build (or reuse) Box2D v3 and the shim; returns the ``Build``. Raises ``BuildError``."""
    src = find_source(box2d_src)
    cc = _tools()
    flags = CMAKE_FLAGS + (f"-DBOX2D_AVX2={'ON' if _avx2() else 'OFF'}",) + SHIM_CFLAGS
    key = _fingerprint(src, cc, flags)  # Box2D itself: rebuilt only when its sources change
    out = cache_root() / key
    lib = out / SHIM_LIB.replace(".so", f"-{_shim_fingerprint(key)}.so")  # the shim: rebuilt on edits
    bench = out / "build" / "bin" / "benchmark"
    result = Build(out, lib, bench, src, snapshot_id(src))
    if not force and lib.is_file() and bench.is_file():
        return result
    out.mkdir(parents=True, exist_ok=True)
    with open(out / ".lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)  # one build at a time (parallel tests, two shells)
        if not force and lib.is_file() and bench.is_file():
            return result
        t0 = time.perf_counter()
        log = out / "build.log"
        log.write_text("")
        bdir = out / "build"
        libbox2d = bdir / "src" / "libbox2d.a"
        if force or not (libbox2d.is_file() and bench.is_file()):
            if not quiet:
                print(f"[box2d] building Box2D v3 {result.snapshot[:12]} from {src} into {out}",
                      file=sys.stderr, flush=True)
            _run(["cmake", "-S", src, "-B", bdir, "-G", "Ninja", f"-DCMAKE_C_COMPILER={cc}", *flags[:6]],
                 out, log, "cmake configure", quiet)
            jobs = str(max(1, min(os.cpu_count() or 1, 4)))
            _run(["ninja", "-C", bdir, "-j", jobs, "box2d", "benchmark"], out, log,
                 "ninja (libbox2d.a, benchmark)", quiet)
        for old in out.glob(SHIM_LIB.replace(".so", "-*.so")):
            old.unlink(missing_ok=True)  # shims built from earlier versions of our sources
        tmp = out / (SHIM_LIB + ".tmp")
        _run([cc, *SHIM_CFLAGS, "-I", src / "include",
              *[HERE / n for n in SHIM_SOURCES if n.endswith(".c")], libbox2d, "-lm", "-o", tmp],
             out, log, "shim", quiet)
        os.replace(tmp, lib)  # atomic: a reader never sees half a library
        if not quiet:
            print(f"[box2d] ready in {time.perf_counter() - t0:.1f} s: {lib}", file=sys.stderr, flush=True)
    return result


_STATUS: dict = {}


def available(box2d_src=None) -> bool:
    """True when Box2D v3 and the shim are built (building them if needed); False, never an
    exception, when tools or sources are missing or the build fails (``why_unavailable`` says why)."""
    key = str(box2d_src)
    if key not in _STATUS:
        try:
            _STATUS[key] = (build(box2d_src), None)
        except BuildError as e:
            _STATUS[key] = (None, str(e))
        except OSError as e:
            _STATUS[key] = (None, f"cannot build Box2D v3: {e}")
    return _STATUS[key][0] is not None


def why_unavailable(box2d_src=None) -> str | None:
    """The reason ``available(box2d_src)`` is False (a sentence with the missing piece), else None."""
    available(box2d_src)
    return _STATUS[str(box2d_src)][1]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--box2d-src", help="Box2D v3 source tree (default: ../shared/reference/box2d-v3)")
    ap.add_argument("--force", action="store_true", help="rebuild even when the cache is current")
    a = ap.parse_args(argv)
    try:
        b = build(a.box2d_src, force=a.force)
    except BuildError as e:
        print(f"Box2D v3 unavailable: {e}", file=sys.stderr)
        return 1
    print(f"shim {b.library}\nbenchmark {b.benchmark}\nsnapshot {b.snapshot}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
