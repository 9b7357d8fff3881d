"""The tuner's result as text (the trade table), a plot of the Pareto front, and the command
or scene fragment that applies the choice."""
from __future__ import annotations

import json
import math

from .metrics import METRICS


def table(result, all_rows: bool = False) -> str:
    """The Pareto front (or every row) as an aligned text table, fastest first, with the choice
    and the scene as it is marked."""
    unit = METRICS[result.metric]
    rows = sorted(result.rows if all_rows else _front_and_marked(result), key=lambda r: r["seconds"])
    base = result.baseline["seconds"] or math.inf
    head = ["candidate", "seconds", "speed vs scene", f"{result.metric} ({unit})", "within"]
    lines = [head]
    for r in rows:
        mark = " <- chosen" if r is result.choice else ""
        mark += " (scene as is)" if r is result.baseline else ""
        err = "refused" if r["refused"] else f"{r['error']:.3g}"
        lines.append([r["key"] + mark, f"{r['seconds']:.3f}", f"{base / r['seconds']:.2f}x" if r["seconds"] else "-",
                      err, "yes" if r["within"] else "no"])
    widths = [max(len(str(row[i])) for row in lines) for i in range(len(head))]
    out = ["  ".join(str(c).ljust(w) for c, w in zip(row, widths)).rstrip() for row in lines]
    out.insert(1, "  ".join("-" * w for w in widths))
    return "\n".join(out)


def _front_and_marked(result) -> list:
    rows = list(result.front)
    for r in (result.choice, result.baseline):
        if r is not None and r not in rows:
            rows.append(r)
    return rows


def summary(result) -> str:
    """The lines around the table: where it ran, the reference check, the choice and how to apply it."""
    lines = [f"{len(result.rows)} candidates over {result.steps} steps on {result.where}", result.note]
    if result.choice is None:
        best = min(result.rows, key=lambda r: r["error"])
        lines.append(f"no candidate is within the budget {result.budget:g}; the most accurate is "
                     f"{best['key']} ({best['error']:.3g})")
    else:
        lines.append(f"chosen: {result.choice['key']} ({result.choice['error']:.3g} <= {result.budget:g})")
        lines.append("apply with --apply, or put this in the scene's \"world\" block: "
                     + json.dumps(result.fragment))
        lines.append("or run it: " + command(result))
    return "\n".join(lines)


def command(result) -> str:
    """A ``python -m physics simulate`` command line with the choice applied."""
    c = result.choice["candidate"]
    frag = result.fragment
    parts = ["python -m physics simulate SCENE", f"--steps {round(result.steps / c.dt_factor)}", f"--solver {c.solver}",
             f"--dt {frag['dt']:.17g}"]
    parts += [f"--set {k}={json.dumps(v)}" for k, v in c.settings]
    if c.integrator:
        parts.append(f"--set integrator={c.integrator}")
    return " ".join(parts)


def plot(result, path) -> None:
    """Seconds against error for every candidate (the front joined, the choice ringed), as an image."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.5), dpi=100)
    ok = [r for r in result.rows if math.isfinite(r["error"]) and r["error"] > 0]
    for mode in sorted({r["candidate"].solver for r in ok}):
        mine = [r for r in ok if r["candidate"].solver == mode]
        ax.scatter([r["seconds"] for r in mine], [r["error"] for r in mine], label=mode, s=18)
    front = [r for r in result.front if r in ok]
    ax.plot([r["seconds"] for r in front], [r["error"] for r in front], "k-", lw=1, label="Pareto front")
    if result.choice is not None and result.choice in ok:
        ax.scatter([result.choice["seconds"]], [result.choice["error"]], s=160, facecolors="none",
                   edgecolors="red", label="chosen")
    ax.axhline(result.budget, color="grey", ls="--", lw=1, label="budget")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("seconds stepping")
    ax.set_ylabel(f"{result.metric} ({METRICS[result.metric]})")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
