"""Sections of the site generated from the code at build time (see tools/docs/hooks.py).

A page asks for one with an HTML comment alone on its line, ``<!-- stelkropp:NAME ARGS -->``:

* ``solver-settings``: every solver mode's description and declared settings (name,
  default, range, meaning), read from ``physics.solvers``;
* ``cli ARGS``: the output of ``python -m physics ARGS`` (run in-process; ``--help`` too);
* ``examples``: every script in ``examples/``: its docstring, how to run it and its source;
* ``joint-params KIND``: a joint kind's parameters (name, default, meaning), its creation-only
  geometry and its readouts, read from ``physics.joint_params`` and ``physics.joint_readouts``;
* ``joint-kinds``: every declared kind in turn: its class's reference and its ``joint-params``.

An unknown NAME raises, so a typo fails the build instead of vanishing from the page.
"""
from __future__ import annotations

import ast
import contextlib
import io
import os
import shlex
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
# the examples page lists these first, in this order (simplest first); any other script follows
EXAMPLE_ORDER = ("oscillator_period.py", "export_trajectory.py", "compare_solvers.py", "build_scene.py",
                 "pyglet_window.py")


def expand(name: str, args: str, page: str) -> str:
    """The Markdown for marker ``name`` with its argument string; ValueError for an unknown name."""
    if name == "solver-settings":
        return solver_settings()
    if name == "cli":
        return cli_output(args)
    if name == "examples":
        return examples()
    if name == "joint-params":
        return joint_params(args)
    if name == "joint-kinds":
        return joint_kinds()
    raise ValueError(f"{page}: unknown generated section 'stelkropp:{name}'")


def _cell(text) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ")


def _range(s) -> str:
    if s.choices:
        return ", ".join(f"`{c}`" for c in s.choices)
    if isinstance(s.default, bool):
        return "`true` / `false`"
    lo = "" if s.lo is None else f"{s.lo:g}"
    hi = "" if s.hi is None else f"{s.hi:g}"
    return f"{lo} .. {hi}" if (lo or hi) else "any"


def solver_settings() -> str:
    """One section per solver mode: its description and a table of its declared settings."""
    import physics
    from physics import solvers
    out = []
    for name in physics.solvers_available():
        mode = solvers.get(name)
        out.append(f"### `{name}`\n")
        if mode.description:
            out.append(mode.description.strip() + "\n")
        if getattr(mode, "uses_integrator", False):
            out.append("Integrates forces with `world.integrator` (`euler`, `symplectic_euler`, `rk4`).\n")
        out.append("| setting | default | range | meaning |\n|---|---|---|---|")
        for key, s in mode.settings.items():
            default = str(s.default).lower() if isinstance(s.default, bool) else s.default
            out.append(f"| `{key}` | `{default}` | {_range(s)} | {_cell(s.doc)} |")
        out.append("")
    return "\n".join(out)


def cli_output(args: str) -> str:
    """A console block: the command line and what ``physics.cli.main`` printed for it."""
    from physics import cli
    argv = shlex.split(args)
    buf = io.StringIO()
    old_cwd, old_cols = os.getcwd(), os.environ.get("COLUMNS")
    os.environ["COLUMNS"] = "96"  # argparse wraps help to the terminal: keep the page stable
    try:
        os.chdir(ROOT)
        with contextlib.redirect_stdout(buf), contextlib.redirect_stderr(buf):
            try:
                code = cli.main(argv)
            except SystemExit as exc:  # --help exits
                code = exc.code
    finally:
        os.chdir(old_cwd)
        if old_cols is None:
            os.environ.pop("COLUMNS", None)
        else:
            os.environ["COLUMNS"] = old_cols
    if code not in (0, None):
        raise RuntimeError(f"python -m physics {args} exited {code}:\n{buf.getvalue()}")
    text = buf.getvalue().replace("usage: stelkropp-sim", "usage: python -m physics")
    return f"```console\n$ python -m physics {args}\n{text.rstrip()}\n```\n"


def _docstring(path: Path) -> str:
    doc = ast.get_docstring(ast.parse(path.read_text(encoding="utf-8")))
    if not doc:
        raise ValueError(f"{path.relative_to(ROOT)}: an example needs a docstring saying what it shows")
    return doc


def examples() -> str:
    """Every examples/*.py: title (first docstring line), the rest of its docstring, its source."""
    out = []
    scripts = sorted((ROOT / "examples").glob("*.py"),
                     key=lambda p: (EXAMPLE_ORDER.index(p.name) if p.name in EXAMPLE_ORDER else len(EXAMPLE_ORDER), p.name))
    for path in scripts:
        doc = _docstring(path)
        title, _, rest = doc.partition("\n")
        rel = path.relative_to(ROOT).as_posix()
        out.append(f"## {title.strip().rstrip('.')}\n")
        out.append(f"`{rel}`\n")
        if rest.strip():
            out.append(rest.strip() + "\n")
        src = path.read_text(encoding="utf-8").rstrip()
        out.append(f'??? example "Source of {path.name}"\n')
        out.append("    ```python")
        out.extend(("    " + line) if line else "" for line in src.splitlines())
        out.append("    ```\n")
    return "\n".join(out)


def joint_kinds() -> str:
    """Each kind of physics/joint_params.py's declaration: its class (mkdocstrings' reference,
    without members: the table lists them) and its parameter tables."""
    from physics.joint_kinds import CLASS_OF
    out = []
    for kind, cls in CLASS_OF.items():
        out += [f"::: physics.{cls.__name__}", "    options:", "      members: false",
                "      inherited_members: false", "      heading_level: 3", "      show_bases: false", "",
                joint_params(kind)]
    return "\n".join(out)


def joint_params(kind: str) -> str:
    """Tables of joint ``kind``'s parameters (name, default, meaning) and readouts, and its
    creation-only geometry."""
    from physics import joint_params as jp
    from physics.joint_readouts import KINDS as READOUTS
    from physics.joint_readouts import Readouts
    if kind not in jp.PARAMS:
        raise ValueError(f"joint-params: unknown joint kind {kind!r}; one of {list(jp.PARAMS)}")
    out = ["| parameter | default | meaning |", "|---|---|---|"]
    out += [f"| `{name}` | `{p.default!r}` | {_cell(p.doc)} |" for name, p in jp.PARAMS[kind].items()]
    readouts = [f"| `{name}` | {_cell(vars(Readouts)[name].__doc__)} |" for name, kinds in READOUTS.items()
                if kind in kinds]
    out += ["", "| readout | meaning |", "|---|---|", *readouts] if readouts else []
    geometry = ", ".join(f"`{g}`" for g in jp.GEOMETRY[kind]) or "none"
    out += ["", f"Geometry, given at creation only: {geometry}.", ""]
    return "\n".join(out)
