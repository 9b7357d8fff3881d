"""Result tables: number formatting, text and markdown tables, the speed and accuracy tables."""
from __future__ import annotations

from .. import accuracy


def fmt(v, nd=3) -> str:
    """``v`` for a table: '-' for None, ``nd`` decimals, exponent form when tiny or huge."""
    if v is None:
        return "-"
    if isinstance(v, float):
        if v != 0 and (abs(v) < 10 ** -nd or abs(v) >= 1e5):
            return f"{v:.2e}"
        return f"{v:.{nd}f}"
    return str(v)


def speed_table(rows, defaults_only=False):
    """(header, rows) of the speed table for speed rows (``defaults_only``: default settings)."""
    hdr = ["scene", "configuration", "ms/step", "x pymunk", "x pybox2d", "x Box2D v3", "error", "first step s", "status"]
    out = []
    for r in rows:
        if defaults_only and not r.get("default"):
            continue
        out.append([r["scene"], r["label"], fmt(r.get("ms_step")), fmt(r.get("ratio_pymunk"), 2),
                    fmt(r.get("ratio_pybox2d"), 2), fmt(r.get("ratio_box2d_v3"), 2), fmt(r.get("error"), 4), fmt(r.get("first_step_s"), 2),
                    r.get("status", "")[:40]])
    return hdr, out


def text_table(hdr, rows) -> str:
    """A plain-text table with padded columns."""
    w = [max(len(str(x)) for x in col) for col in zip(hdr, *rows)] if rows else [len(h) for h in hdr]
    line = "  ".join(h.ljust(n) for h, n in zip(hdr, w))
    body = ["  ".join(str(x).ljust(n) for x, n in zip(r, w)) for r in rows]
    return "\n".join([line, "-" * len(line), *body])


def md_table(hdr, rows) -> str:
    """A markdown table ('|' inside cells becomes '/')."""
    return "\n".join(["| " + " | ".join(hdr) + " |", "|" + "---|" * len(hdr),
                      *["| " + " | ".join(str(x).replace("|", "/") for x in r) + " |" for r in rows]])


def accuracy_table(acc):
    """Metric rows x engines/modes (defaults, dt 1/60): value (error)."""
    cols = []
    for r in acc:
        if r.get("default") and abs(r["dt"] - 1 / 60) < 1e-12 and r["label"] not in cols:
            cols.append(r["label"])
    metrics = []
    for r in acc:
        if r["metric"] not in metrics and r["metric"] not in accuracy.SCENARIOS:
            metrics.append(r["metric"])
    exp = {}
    table = {}
    for r in acc:
        if r.get("default") and abs(r["dt"] - 1 / 60) < 1e-12:
            table[(r["metric"], r["label"])] = r
            exp.setdefault(r["metric"], r.get("expected"))
    rows = []
    for m in metrics:
        e = exp.get(m)
        row = [m, fmt(e, 3) if not isinstance(e, list) else str(e)]
        for c in cols:
            r = table.get((m, c))
            if r is None:
                failed = [x for x in acc if x["label"] == c and x.get("default") and abs(x["dt"] - 1 / 60) < 1e-12
                          and x["metric"] in accuracy.SCENARIOS and m.startswith(x["metric"].split("_")[0])]
                row.append("failed" if failed else "-")
                continue
            v = r.get("value")
            if v is None and "not at rest" in r.get("note", ""):
                row.append("> " + r["note"].split("after ")[-1])
                continue
            v = "/".join(fmt(x, 3) for x in v) if isinstance(v, list) else fmt(v, 4)
            row.append(v if r.get("note", "").startswith("failed") is False else "failed")
        rows.append(row)
    return ["metric", "expected", *cols], rows
