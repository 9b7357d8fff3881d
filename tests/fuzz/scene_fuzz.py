"""The scene-file fuzzer (issue 20, "keep it found"): mutations of the shipped scenes, fed to the
loader as files, with the invariants every case must hold.

    python tests/fuzz/scene_fuzz.py --cases 20000 [--seed 1]    # a long run; prints the counts

A case is a shipped scene (the big ones cut to their first bodies) with 1-4 mutations: wrong types,
extreme numbers, deep nesting, huge strings, duplicate keys, missing fields and references,
degenerate polygons, unknown keys, binary garbage, truncation.  Invariants (``check_case``): the
loader returns a World or raises physics.SceneError and nothing else; each problem names a JSON
path that exists in the document (or its missing last key), or "$" for the file; the message names
the file and stays short; a loaded world is finite and survives save -> load; each case ends within
CASE_SECONDS of CPU time and allocates at most MEMORY_BOUND bytes more than its input.
"""
from __future__ import annotations

import json
import math
import re
import signal
import sys
import time
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

import physics  # noqa: E402
from physics.scene import load_scene, scene_from_dict, scene_to_dict  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from mutations import make_case  # noqa: E402

CASE_SECONDS = 20.0                # CPU seconds one case may take (loading a 1e6-element file is ~2 s)
MEMORY_BOUND = 400 * 2**20         # bytes one case may allocate on top of 40x its file size
MESSAGE_BOUND = 60_000             # characters a SceneError message may have
BIG_SCENE_BODIES = 40              # the big shipped scenes are cut to this many bodies (speed)
SCENES = sorted(p for p in (ROOT / "scenes").glob("*.json") if p.name != "stelkropp.schema.json")


class Hang(Exception):
    """A case used more than CASE_SECONDS of CPU time."""


# -- the corpus -------------------------------------------------------------------------------
def corpus() -> list:
    """Each shipped scene as data; big ones keep their first bodies and the springs between them."""
    out = []
    for p in SCENES:
        d = json.loads(p.read_text())
        if len(d["bodies"]) > BIG_SCENE_BODIES:
            d["bodies"] = d["bodies"][:BIG_SCENE_BODIES]
            names = {b.get("name") for b in d["bodies"]}
            d["springs"] = [s for s in d.get("springs", []) if s["a"] in names and s["b"] in names | {None}]
        out.append((p.stem, d))
    return out


# -- the invariants ---------------------------------------------------------------------------
_TOKEN = re.compile(r'\.?([A-Za-z_][A-Za-z0-9_]*)|\[(\d+)\]|\[("(?:[^"\\]|\\.)*")\]')
KINDS = [("not valid JSON", "invalid JSON"), ("nested", "too deep"), ("not UTF-8", "not UTF-8"),
         ("lone surrogate", "lone surrogate"), ("duplicate key", "duplicate key"),
         ("beyond the range of a float", "integer beyond float range"), ("must be finite", "non-finite number"),
         ("unknown key", "unknown key"), ("required field", "missing field"), ("expected", "wrong type"),
         ("not a Stelkropp scene", "wrong format"), ("unsupported version", "wrong version"),
         ("no body named", "dangling reference"), ("duplicate", "duplicate name"), ("polygon", "bad polygon"),
         ("too large", "shape too large"), ("too small", "shape too small"), ("too thin", "shape too thin"),
         ("exactly one", "bad shape"), ("cannot represent", "unrepresentable mass"), ("solver", "bad solver"),
         ("setting", "bad setting"), ("must be", "out of range"), ("has ", "wrong length"), ("", "other")]


class Violation(AssertionError):
    """A case broke an invariant."""


def kind_of(reason: str) -> str:
    return next(k for words, k in KINDS if words in reason)


def _resolves(doc, path: str) -> bool:
    """Whether a problem's JSON path names a place in the document (its last key may be missing)."""
    if path == "$" or "... (" in path:  # the root, or a path clipped for length
        return True
    parts, i = [], 0
    while i < len(path):
        m = _TOKEN.match(path, i)
        if not m or m.end() == i:
            return False
        parts.append(m.group(1) if m.group(1) is not None else int(m.group(2)) if m.group(2) else json.loads(m.group(3)))
        i = m.end()
    node = doc
    for k, part in enumerate(parts):
        last = k == len(parts) - 1
        if isinstance(node, dict) and isinstance(part, str):
            if part not in node:
                return last
            node = node[part]
        elif isinstance(node, list) and isinstance(part, int) and part < len(node):
            node = node[part]
        else:
            return False
    return True


def _on_alarm(signum, frame):
    raise Hang(f"over {CASE_SECONDS} s of CPU time")


def _max_rss() -> int:
    import resource
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024


def check_case(path: Path, raw: bytes, what: str) -> list:
    """Load the file at ``path`` (holding ``raw``); raise Violation if an invariant breaks, else return the
    outcome: ["loaded"] or the kinds of the problems the SceneError listed."""
    from physics.scene.json_io import parse
    path.write_bytes(raw)
    rss0 = _max_rss()
    old = signal.signal(signal.SIGVTALRM, _on_alarm)
    signal.setitimer(signal.ITIMER_VIRTUAL, CASE_SECONDS)
    try:
        try:
            world = load_scene(path)
        except physics.SceneError as exc:
            return _check_error(exc, path, raw, what, parse)
        except Hang:
            raise Violation(f"{what}: loading took over {CASE_SECONDS} s of CPU time") from None
        except Exception as exc:  # noqa: BLE001 -- the invariant: nothing but SceneError escapes
            raise Violation(f"{what}: {type(exc).__name__} escaped load_scene: {str(exc)[:300]}") from exc
        _check_world(world, what)
        _check_nothing_hostile_loaded(raw, what)
        return ["loaded"]
    finally:
        signal.setitimer(signal.ITIMER_VIRTUAL, 0)
        signal.signal(signal.SIGVTALRM, old)
        grew = _max_rss() - rss0
        if grew > MEMORY_BOUND + 40 * len(raw):
            raise Violation(f"{what}: the process grew by {grew / 2**20:.0f} MB loading a {len(raw)}-byte file")


def _check_error(exc, path, raw, what, parse) -> list:
    msg = str(exc)
    if str(path) not in msg.splitlines()[0] or exc.path != str(path):
        raise Violation(f"{what}: the SceneError does not name the file: {msg[:200]}")
    if len(msg) > MESSAGE_BOUND:
        raise Violation(f"{what}: a {len(msg)}-character message")
    if not exc.problems:
        raise Violation(f"{what}: a SceneError with no problems: {msg[:200]}")
    try:
        doc = parse(raw.decode("utf-8"))
    except (ValueError, UnicodeDecodeError):
        doc = None
    for p, reason in exc.problems:
        if not (isinstance(p, str) and p and isinstance(reason, str) and reason.strip()):
            raise Violation(f"{what}: a problem without path or reason: {(p, reason)!r}")
        if f"{p}: {reason}" not in msg:
            raise Violation(f"{what}: problem {p!r} is not in the message")
        if doc is None and p != "$":
            raise Violation(f"{what}: the file does not parse, yet the problem is at {p!r}")
        if doc is not None and not _resolves(doc, p):
            raise Violation(f"{what}: problem path {p!r} is not in the document ({reason[:100]})")
    return [kind_of(r) for _, r in exc.problems]


def _check_nothing_hostile_loaded(raw: bytes, what: str) -> None:
    """An oracle independent of the loader: the standard json module on the same bytes.  A file
    that repeats a key, holds a lone surrogate or a non-finite number must not have loaded."""
    found = []

    def pairs(items):
        keys = [k for k, _ in items]
        if len(set(keys)) != len(keys):
            found.append("a repeated key")
        return dict(items)

    def constant(name):
        found.append(f"the literal {name}")

    try:
        doc = json.loads(raw.decode("utf-8"), object_pairs_hook=pairs, parse_constant=constant)
    except (ValueError, RecursionError) as exc:
        raise Violation(f"{what}: loaded a file the json module cannot read ({exc})") from None
    stack = [doc]
    while stack:
        v = stack.pop()
        if isinstance(v, dict):
            stack += [*v, *v.values()]
        elif isinstance(v, list):
            stack += v
        elif isinstance(v, str) and any(0xD800 <= ord(c) <= 0xDFFF for c in v):
            found.append("a lone surrogate")
        elif isinstance(v, float) and not math.isfinite(v):
            found.append(f"the number {v}")
        elif isinstance(v, int) and not isinstance(v, bool) and abs(v) > 1.8e308:
            found.append("an integer beyond float range")
    if found:
        raise Violation(f"{what}: loaded a file holding {found[0]}")


def _check_world(world, what) -> None:
    import numpy as np
    st = world.state()
    for f in ("position", "angle", "velocity", "angular_velocity"):
        if not np.all(np.isfinite(st[f])):
            raise Violation(f"{what}: loaded a world with non-finite {f}")
    try:
        again = scene_from_dict(json.loads(json.dumps(scene_to_dict(world), allow_nan=False)))
    except Exception as exc:  # noqa: BLE001
        raise Violation(f"{what}: a loaded world does not save and reload: {type(exc).__name__}: "
                        f"{str(exc)[:300]}") from exc
    if not np.array_equal(again.state(), st):
        raise Violation(f"{what}: save -> load changed the world's state")


# -- a run ------------------------------------------------------------------------------------
def run(cases: int, seed: int, folder: Path, progress=None) -> dict:
    """Run ``cases`` cases from ``seed``; returns the counts, with every broken invariant listed under
    "violations" (``crashes`` counts them)."""
    import random
    base = corpus()
    counts = {"cases": 0, "loaded": 0, "scene_errors": 0, "problems_by_kind": Counter(), "mutations": Counter(),
              "crashes": 0, "max_case_seconds": 0.0}
    for i in range(cases):
        rnd = random.Random(f"{seed}:{i}")
        name, raw, done = make_case(rnd, base)
        counts["cases"] += 1
        counts["mutations"].update(done)
        t0 = time.process_time()
        try:
            outcome = check_case(folder / "case.json", raw, f"case {seed}:{i} ({name}: {', '.join(done)})")
        except Violation as v:
            counts["crashes"] += 1
            counts.setdefault("violations", []).append(str(v)[:400])
            outcome = []
        counts["max_case_seconds"] = max(counts["max_case_seconds"], time.process_time() - t0)
        if outcome == ["loaded"]:
            counts["loaded"] += 1
        elif outcome:
            counts["scene_errors"] += 1
            counts["problems_by_kind"].update(set(outcome))
        if progress:
            progress(i)
    return counts


def main(argv=None) -> int:
    import argparse
    import tempfile
    from tqdm import tqdm
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", type=int, default=20_000)
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args(argv)
    bar = tqdm(total=args.cases, unit="case", file=sys.stderr)
    t0 = time.time()
    with tempfile.TemporaryDirectory() as d:
        counts = run(args.cases, args.seed, Path(d), progress=lambda i: bar.update(1))
    bar.close()
    counts["wall_seconds"] = round(time.time() - t0, 1)
    counts["max_case_seconds"] = round(counts["max_case_seconds"], 2)
    print(json.dumps(counts, indent=2, default=dict))
    return 1 if counts["crashes"] else 0


if __name__ == "__main__":
    sys.exit(main())
