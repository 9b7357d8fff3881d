"""``python -m tools.docs build|check|serve``: the reference site's one command.

    build [--out DIR]                      mkdocs build --strict (warnings are errors) into DIR (site/)
    check [--out DIR] [--shots DIR]        build, then load every page in headless Chromium
    serve [--out DIR] [--port N]           build, then serve DIR on http://127.0.0.1:N/
    coverage [--missing]                   which public names of physics have a docstring

Exit codes: 0 success, 1 the build warned or failed, or a page failed the browser check.
"""
from __future__ import annotations

import argparse
import os
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def build(out: Path) -> tuple[int, float, str]:
    """Run ``mkdocs build --strict`` into ``out``; (exit code, seconds, mkdocs' output)."""
    t0 = time.monotonic()
    # Material prints a banner about MkDocs 2.0 on every build; it is news, not a warning about
    # this site (the version pins in pyproject.toml's docs extra answer it)
    env = {**os.environ, "NO_MKDOCS_2_WARNING": "1"}
    proc = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "--clean",
                           "-f", str(ROOT / "mkdocs.yml"), "-d", str(out.resolve())],
                          cwd=ROOT, capture_output=True, text=True, env=env)
    return proc.returncode, time.monotonic() - t0, proc.stdout + proc.stderr


def pages(out: Path) -> list[Path]:
    """Every HTML page of a built site (404.html included)."""
    return sorted(out.rglob("*.html"))


def _build_or_exit(out: Path) -> None:
    print(f"building the site into {out} (mkdocs build --strict) ...", flush=True)
    code, secs, log = build(out)
    if code:
        sys.stdout.write(log)
        print(f"build FAILED after {secs:.1f} s (warnings count as errors)")
        sys.exit(1)
    print(f"built {len(pages(out))} pages in {secs:.1f} s: open {out / 'index.html'}")


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m tools.docs", description="Build and check the reference site.")
    sub = p.add_subparsers(dest="cmd", required=True)
    for name, text in (("build", "build the site (strict)"), ("check", "build, then check every page in Chromium"),
                       ("serve", "build, then serve it on localhost")):
        sp = sub.add_parser(name, help=text)
        sp.add_argument("--out", type=Path, default=ROOT / "site", help="output folder (default: site/)")
        if name == "check":
            sp.add_argument("--shots", type=Path, help="save screenshots of a few pages here")
        if name == "serve":
            sp.add_argument("--port", type=int, default=8000)
    cov = sub.add_parser("coverage", help="count the public names of physics that have a docstring")
    cov.add_argument("--missing", action="store_true", help="list every name without one")
    args = p.parse_args(argv)
    if args.cmd == "coverage":
        from .coverage import report
        print(report(args.missing))
        return 0
    _build_or_exit(args.out)
    if args.cmd == "check":
        from .browser import check_site
        report = check_site(args.out, shots=args.shots, progress=print)
        print(report.summary())
        return 0 if report.ok else 1
    if args.cmd == "serve":
        from .server import serve_forever
        serve_forever(args.out, args.port)
    return 0


if __name__ == "__main__":
    sys.exit(main())
