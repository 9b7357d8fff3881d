"""The sandbox's tuner process (the solver panel's Find settings button: ``app.find_settings``).

Reads one JSON line from stdin, ``{"scene": {...}, "steps": N, "metric": M, "budget": B}``, runs
``physics.tune`` on it in this process (``scheduler="inline"``: a Dask cluster would cost seconds
to start and two more processes on a machine the window already shares), and writes JSON lines to
stdout: ``{"progress": [stage, done, total]}`` as runs finish, then one of ``{"result": {...}}``
(see ``summary``), ``{"error": "..."}`` or ``{"cancelled": true}``.  Around each kernel numba
really compiles here (a cold cache: the first run compiles the scene's kernels, which takes far
longer than the run) it writes ``{"compile": ["start" | "end", kernel]}``, so the sandbox shows
that instead of a bar standing still; a kernel loaded from the cache says nothing.

A line ``cancel`` on stdin, or stdin closing (the sandbox quit or died), stops the search at the
next run boundary through the tuner's ``cancel`` hook.  A separate process, not a thread: the
runs are timed, and the window's own drawing and stepping would share the interpreter lock with
them (and the kernels of modes the window does not use load here, not in the window).
"""
from __future__ import annotations

import json
import sys
import threading


def emit(rec: dict) -> None:
    """One JSON line to the sandbox."""
    sys.stdout.write(json.dumps(rec) + "\n")
    sys.stdout.flush()


def measured(scene: dict, cand) -> dict:
    """What the candidate ran with: its mode, every setting of that mode, dt and integrator
    (``Apply`` sets exactly these, not only the ones the tuner varied)."""
    from physics.tuning.runs import build
    w = build(scene, cand)
    return {"solver": w.solver, "settings": w.settings.to_dict(), "dt": w.dt, "integrator": w.integrator}


def _row(row) -> dict:
    return {"key": row["key"], "error": row["error"], "seconds": row["seconds"], "within": row["within"]}


def summary(result, scene: dict) -> dict:
    """The result as JSON data: the choice (with ``measured``'s fields) or None, the scene-as-is
    row, the most accurate finished row, the note and the counts."""
    choice = None
    if result.choice is not None:
        choice = {**_row(result.choice), **measured(scene, result.choice["candidate"])}
    finished = [r for r in result.rows if r["refused"] is None and r["error"] == r["error"]]
    best = min(finished, key=lambda r: r["error"]) if finished else None
    return {"choice": choice, "baseline": _row(result.baseline), "best": _row(best) if best else None,
            "metric": result.metric, "budget": result.budget, "steps": result.steps,
            "converged": result.converged, "note": result.note, "candidates": len(result.rows)}


def _watch(stop: threading.Event) -> None:
    for line in sys.stdin:
        if line.strip() == "cancel":
            break
    stop.set()   # "cancel", or EOF: the sandbox is gone


def main() -> int:
    """Run one search as the first stdin line asks; 0 when a result, error or cancel was sent."""
    job = json.loads(sys.stdin.readline() or "{}")
    stop = threading.Event()
    threading.Thread(target=_watch, args=(stop,), name="tune-cancel", daemon=True).start()
    from .compile_worker import listen
    listen(lambda k: emit({"compile": ["start", k]}), lambda k: emit({"compile": ["end", k]}))
    import physics
    from physics.tuning import Cancelled
    try:
        result = physics.tune(job["scene"], steps=job["steps"], metric=job["metric"], budget=job["budget"],
                              scheduler="inline", progress=False, cancel=stop.is_set,
                              on_progress=lambda stage, done, total: emit({"progress": [stage, done, total]}))
    except Cancelled:
        emit({"cancelled": True})
        return 0
    except Exception as exc:  # noqa: BLE001  (a scene or option the tuner refuses: shown, never fatal)
        emit({"error": f"{type(exc).__name__}: {exc}" if not isinstance(exc, ValueError) else str(exc)})
        return 0
    emit({"result": summary(result, job["scene"])})
    return 0


if __name__ == "__main__":
    sys.exit(main())
