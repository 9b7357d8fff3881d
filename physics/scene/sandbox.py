"""The scene's ``sandbox`` section: the sandbox's lasers and tracers (app data, ignored by the
physics, like a body's ``color``).  The loader leaves them in ``world.metadata`` by body id and
the saver writes them back from there, naming the bodies they ride on.

    "sandbox": {"lasers":  [{"body": "arm", "point": [0.5, 0.0], "angle": 0.0}, ...],
                "tracers": [{"body": "bob", "point": [0.0, 0.0]}, ...]}

A laser's ``body`` may be null (fixed in the world): its ``point`` and ``angle`` (rad) are then
world coordinates, else the body's own frame.  A tracer follows a point of a body.  The section's
schema is ``schema.SANDBOX`` (beside the rest of the format's).
"""
from __future__ import annotations

from .problems import quoted

def sandbox_problems(bodies, sandbox, bad) -> list:
    """Lasers and tracers must name bodies of the scene."""
    if not isinstance(sandbox, dict):
        return []
    names = {b["name"] for b in bodies if isinstance(b, dict) and isinstance(b.get("name"), str)}
    out = []
    for key in ("lasers", "tracers"):
        items = sandbox.get(key)
        for i, item in enumerate(items if isinstance(items, list) else []):
            ref = item.get("body") if isinstance(item, dict) else None
            path = ("sandbox", key, i, "body")
            if isinstance(ref, str) and ref and path not in bad and ref not in names:
                out.append((path, f"no body named {quoted(ref)}"))
    return out


def load_sandbox(data, by_name, metadata) -> None:
    """Put the file's lasers and tracers in ``metadata`` (body ids, tuples)."""
    sandbox = data.get("sandbox") or {}
    lasers = [{"body": None if lz.get("body") is None else by_name[lz["body"]].id,
               "point": tuple(lz["point"]), "angle": float(lz.get("angle", 0.0))}
              for lz in sandbox.get("lasers", [])]
    tracers = [{"body": by_name[tr["body"]].id, "point": tuple(tr["point"])} for tr in sandbox.get("tracers", [])]
    if lasers:
        metadata["lasers"] = lasers
    if tracers:
        metadata["tracers"] = tracers


def sandbox_bodies(meta) -> set:
    """Ids of the bodies the lasers and tracers in ``meta`` ride on (they need a name in the file)."""
    items = list(meta.get("lasers") or []) + list(meta.get("tracers") or [])
    return {it["body"] for it in items if it.get("body") is not None}


def sandbox_dict(meta, names) -> dict | None:
    """The ``sandbox`` section for ``meta``'s lasers and tracers (bodies by ``names``: id ->
    name), skipping those on bodies no longer in the world; None if there is nothing."""
    def live(it):
        return it.get("body") is None or names.get(it["body"]) is not None
    lasers = [{"body": None if lz["body"] is None else names[lz["body"]], "point": [float(v) for v in lz["point"]],
               "angle": float(lz["angle"])} for lz in meta.get("lasers") or [] if live(lz)]
    tracers = [{"body": names[tr["body"]], "point": [float(v) for v in tr["point"]]}
               for tr in meta.get("tracers") or [] if live(tr) and tr.get("body") is not None]
    out = {k: v for k, v in (("lasers", lasers), ("tracers", tracers)) if v}
    return out or None
