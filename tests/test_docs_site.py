"""The reference site: it builds with warnings as errors, every page renders in a real browser
(Debian's Chromium, headless) with no console errors, broken links or missing images, the
checker itself catches each of those faults, and the code on the pages runs.

Chromium missing is a FAILURE saying how to install it (`.ci/run` installs it), never a skip.
Screenshots of a few pages are written to $STELKROPP_DOCS_SHOTS (default: a temporary folder)
and checked by pixels here; look at them with an image viewer.
"""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest
import yaml

from tools.docs.browser import SHOT_PAGES, check_site, chromium_path

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def site(tmp_path_factory) -> Path:
    """The site built by the documented command into a fresh folder."""
    out = tmp_path_factory.mktemp("docs") / "site"
    proc = subprocess.run([sys.executable, "-m", "tools.docs", "build", "--out", str(out)],
                          cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, f"the strict build failed:\n{proc.stdout}\n{proc.stderr}"
    assert re.search(r"built \d+ pages", proc.stdout), proc.stdout
    return out


def _nav_pages(nav) -> list[str]:
    out = []
    for item in nav:
        value = next(iter(item.values())) if isinstance(item, dict) else item
        out += _nav_pages(value) if isinstance(value, list) else [value]
    return out


def test_every_nav_page_is_built(site):
    nav = _nav_pages(yaml.safe_load((ROOT / "mkdocs.yml").read_text())["nav"])
    assert len(nav) >= 20
    missing = [p for p in nav if not (site / p).with_suffix(".html").is_file()]
    assert not missing, f"pages in the nav that were not built: {missing}"
    # the repository files the pages link to (bench plots, the schema) were brought into the site
    assert (site / "repo/bench/results/pareto_pyramid20.png").is_file()
    assert (site / "repo/scenes/stelkropp.schema.json").is_file()


def test_generated_sections_hold_the_code_facts(site):
    """The solver settings and the command-line help are generated from the code at build time."""
    from physics import solvers
    html = (site / "solver-modes.html").read_text()
    for mode in ("soft_step", "sequential_impulse"):
        for key in solvers.get(mode).settings:
            assert f"<code>{key}</code>" in html, f"setting {mode}.{key} missing from solver-modes"
    cli = (site / "cli.html").read_text()
    assert "Pyramid" in cli and "ok (211 bodies" in cli  # real `info` and `validate` output
    assert "--record" in cli                              # `simulate --help`
    assert "<!-- stelkropp:" not in html + cli


def test_every_page_renders_in_chromium(site):
    chromium_path()  # fails with the install command when Chromium is missing
    shots = Path(os.environ.get("STELKROPP_DOCS_SHOTS") or site.parent / "shots")
    report = check_site(site, shots=shots)
    print(report.summary())
    assert report.ok, report.summary()
    assert report.pages == len(list(site.rglob("*.html")))
    assert report.images >= 10  # the plots and the screenshot, each decoded with a size
    assert report.search_hits >= 3  # the word appears on the tutorial, the guides and the API pages
    assert sorted(p.name for p in report.shots) == sorted(p.replace("/", "_").removesuffix(".html") + ".png"
                                                          for p in SHOT_PAGES)
    for path in report.shots:
        _looks_rendered(path)


def _looks_rendered(path: Path) -> None:
    """A screenshot of a rendered page: the theme's indigo header bar across the top, dark text
    on a light body, and the navigation's text on the left (an unstyled or blank page has none
    of these; the home page's sandbox screenshot keeps its body from being mostly light)."""
    from PIL import Image
    px = np.asarray(Image.open(path).convert("RGB")).astype(int)
    assert px.shape[:2] == (800, 1280), f"{path.name}: unexpected size {px.shape}"
    r, g, b = px[..., 0], px[..., 1], px[..., 2]
    header = (b[5:40] > 150) & (r[5:40] < 110) & (g[5:40] < 120)
    assert header.mean() > 0.8, f"{path.name}: no indigo header bar ({header.mean():.0%} of its pixels)"
    body = px[100:, 280:1000].sum(axis=2) / 3
    light, dark = (body > 230).mean(), (body < 120).mean()
    assert light > 0.3, f"{path.name}: page body not light ({light:.0%})"
    assert dark > 0.005, f"{path.name}: no text in the page body ({dark:.2%} dark pixels)"
    nav = px[100:780, 40:250].sum(axis=2) / 3
    assert (nav < 160).mean() > 0.01, f"{path.name}: no navigation text on the left"


def test_checker_catches_broken_sites(site, tmp_path):
    """Break a copy of the site in each way the checker claims to catch; it must name each."""
    chromium_path()
    bad = tmp_path / "bad"
    shutil.copytree(site, bad)
    (bad / "repo/bench/results/scaling.png").unlink()  # an image the benchmarks page shows
    page = bad / "tutorial.html"
    page.write_text(page.read_text().replace("</article>", (
        '<a href="no-such-page.html">x</a> <a href="#no-such-anchor">y</a>'
        '<img src="http://203.0.113.9/outside.png">'  # refused by the check before it leaves
        "<script>console.error('boom from the test')</script></article>"), 1))
    report = check_site(bad, only=["tutorial.html", "benchmarks.html"])
    text = "\n".join(report.problems)
    assert not report.ok
    for needle in ("repo/bench/results/scaling.png: HTTP 404", "no-such-page.html: HTTP 404",
                   "#no-such-anchor: no element with that id", "benchmarks.html: images not shown",
                   "tutorial.html: request outside the site: http://203.0.113.9/outside.png",
                   "tutorial.html: console error: boom from the test"):
        assert needle in text, f"the checker missed {needle!r}; it reported:\n{text}"


def _python_blocks(md: str) -> list[str]:
    """The ```python fenced blocks of a page (also indented ones, as inside content tabs)."""
    blocks = re.findall(r"^( *)```python\n(.*?)^\1```", md, flags=re.S | re.M)
    return [textwrap.dedent("\n".join(line[len(ind):] for line in body.splitlines())) for ind, body in blocks]


@pytest.mark.parametrize("page", ["getting-started.md", "tutorial.md", "coming-from.md"])
def test_code_on_the_pages_runs(page, tmp_path):
    """Each page's Stelkropp code, its blocks in order as one script (the tutorial's continue
    one another), runs without error."""
    blocks = [b for b in _python_blocks((ROOT / "docs" / page).read_text()) if "pymunk" not in b]
    assert blocks, f"{page} has no python blocks"
    script = tmp_path / "page.py"
    script.write_text("\n\n".join(blocks))
    proc = subprocess.run([sys.executable, str(script)], cwd=tmp_path, capture_output=True, text=True,
                          timeout=1200, env={**os.environ, "PYTHONPATH": str(ROOT)})
    assert proc.returncode == 0, f"{page}'s code failed:\n{proc.stderr[-3000:]}"


def test_links_outside_docs_resolve_only_to_existing_files():
    """The hook copies linked repository files into the site; a missing one must stay a broken
    link so that the strict build reports it (mkdocs: 'target is not found')."""
    from tools.docs.hooks import _outside_target
    docs = ROOT / "docs"
    assert _outside_target("benchmarks.md", "../bench/results/scaling.png", docs) == ROOT / "bench/results/scaling.png"
    assert _outside_target("reference/world.md", "../../scenes/pyramid.json", docs) == ROOT / "scenes/pyramid.json"
    assert _outside_target("benchmarks.md", "../bench/results/no-such-plot.png", docs) is None
    assert _outside_target("tutorial.md", "cli.md#info", docs) is None          # inside docs: mkdocs' own
    assert _outside_target("tutorial.md", "https://numba.pydata.org/", docs) is None


def test_docstring_coverage_counts_what_the_reference_shows(tmp_path):
    """`python -m tools.docs coverage` on a package made here: it must see exported names,
    class members (methods, properties, attributes set in __init__) and skip private ones."""
    from tools.docs.coverage import measure
    pkg = tmp_path / "pkgx"
    pkg.mkdir()
    (pkg / "__init__.py").write_text('from .core import Thing, helper\n__all__ = ["Thing", "helper"]\n')
    (pkg / "core.py").write_text(textwrap.dedent('''
        class Thing:
            """A thing."""
            def __init__(self):
                self.size = 1
            def grow(self, by):
                """Grow by ``by`` metres."""
            @property
            def mass(self):
                return 1.0
            def _hidden(self):
                pass
        def helper():
            pass
    '''))
    cov = measure("pkgx", search_path=tmp_path)
    assert sorted(cov.documented) == ["pkgx.Thing", "pkgx.Thing.grow"]
    assert sorted(cov.missing) == ["pkgx.Thing.mass", "pkgx.Thing.size", "pkgx.helper"]
    assert cov.by_owner() == {"pkgx.Thing": (2, 4), "pkgx.helper": (0, 1)}
