"""Which public names of ``physics`` have a docstring: what the API reference can show.

Reads the package the way the reference pages do (griffe, static: nothing is imported or
compiled): every name in ``physics.__all__`` and, for classes, each public member defined on
the class or inherited from the package's own base classes (methods, properties, and
attributes set in ``__init__``).

    python -m tools.docs coverage [--missing]
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


@dataclass
class Coverage:
    """Public names by documented or not, as dotted paths (``physics.World.step``)."""
    documented: list[str] = field(default_factory=list)
    missing: list[str] = field(default_factory=list)

    def by_owner(self) -> dict[str, tuple[int, int]]:
        """``{"physics.World": (documented, total), ...}`` over each top-level name and its members."""
        out: dict[str, list[int]] = {}
        for names, hit in ((self.documented, 1), (self.missing, 0)):
            for n in names:
                owner = ".".join(n.split(".")[:2])
                d, t = out.setdefault(owner, [0, 0])
                out[owner] = [d + hit, t + 1]
        return {k: (d, t) for k, (d, t) in sorted(out.items())}


def _public(name: str) -> bool:
    return not name.startswith("_")


def measure(package: str = "physics", search_path: Path = ROOT) -> Coverage:
    """Walk ``package.__all__`` (found under ``search_path``) and the public members of each
    class it exports."""
    import griffe
    pkg = griffe.load(package, search_paths=[str(search_path)], resolve_aliases=True, resolve_external=False)
    exported = pkg.exports if pkg.exports is not None else [n for n in pkg.members if _public(n)]
    cov = Coverage()
    for name in exported:
        obj = pkg[str(name)]
        target = obj.final_target if obj.is_alias else obj
        _record(cov, f"{package}.{name}", target)
        if target.is_class:
            # members defined on the class and those it inherits from the package's own bases
            # (World is composed of mixins: add_body lives in world_bodies.py)
            inherited = {k: m for k, m in target.inherited_members.items()
                         if str(m.final_target.path).startswith(package + ".")}
            for mname, member in {**inherited, **target.members}.items():
                if _public(mname) and mname != "__init__" and (mname in inherited or not member.is_alias):
                    _record(cov, f"{package}.{name}.{mname}", member.final_target if member.is_alias else member)
    return cov


def _record(cov: Coverage, path: str, obj) -> None:
    doc = obj.docstring.value.strip() if obj.docstring is not None else ""
    (cov.documented if doc else cov.missing).append(path)


def report(show_missing: bool = False) -> str:
    """A table of documented/total per exported name, and the total; optionally every gap."""
    cov = measure()
    lines = [f"{'name':<28} documented"]
    for owner, (d, t) in cov.by_owner().items():
        lines.append(f"{owner:<28} {d:>3} / {t}")
    total = len(cov.documented) + len(cov.missing)
    lines.append(f"{'all public names':<28} {len(cov.documented):>3} / {total}")
    if show_missing and cov.missing:
        lines += ["", "without a docstring:"] + [f"  {n}" for n in cov.missing]
    return "\n".join(lines)
