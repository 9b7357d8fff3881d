"""Check a built site as a reader sees it: Debian's Chromium, headless, driven by Playwright.

Every page is loaded from a local server and must: answer 200, log no console error and
throw no script error, load every request it makes (no 4xx/5xx, no failed request, nothing
fetched from outside 127.0.0.1: the site must work offline), show every image (decoded,
non-zero size) and carry visible text under its title.  Before that, ``crawl.crawl`` checks
every internal link, image and anchor in the HTML.  A few pages are also saved as
screenshots for a person (or a pixel test) to look at.
"""
from __future__ import annotations

import shutil
import time
import urllib.parse
from dataclasses import dataclass, field
from pathlib import Path

from .crawl import crawl
from .server import serving

CHROMIUM = "/usr/bin/chromium"
INSTALL = "apt-get install -y chromium (Debian's package; .ci/run installs it)"
# flags that work on this project's machines (no network but the package registries; root)
FLAGS = ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync"]
VIEWPORT = {"width": 1280, "height": 800}
SHOT_PAGES = ("index.html", "tutorial.html", "solver-modes.html", "reference/world.html")
# a rendered page has at least this much text in its main content (the shortest, an API page
# before its docstrings are written, still has signatures)
MIN_TEXT = 200
# typed into the search box of the home page: the index is built by mkdocs and searched by a
# web worker, so this proves both work from the local server
SEARCH_WORD = "restitution"

# what the page reports about itself once loaded
PAGE_FACTS = """() => {
  const main = document.querySelector('article') || document.body;
  const imgs = [...document.images];
  return {
    title: document.title,
    h1: (document.querySelector('h1') || {}).textContent || '',
    text: main.innerText.trim().length,
    broken: imgs.filter(i => !(i.complete && i.naturalWidth > 0)).map(i => i.getAttribute('src')),
    images: imgs.length,
  };
}"""


@dataclass
class Report:
    """Outcome of one site check: counts, problems (empty when all is well), screenshots."""
    pages: int = 0
    links: int = 0
    resources: int = 0
    requests: int = 0
    images: int = 0
    search_hits: int = 0
    problems: list[str] = field(default_factory=list)
    shots: list[Path] = field(default_factory=list)
    seconds: dict[str, float] = field(default_factory=dict)

    @property
    def ok(self) -> bool:
        return not self.problems

    def summary(self) -> str:
        head = (f"{self.pages} pages, {self.links} internal links, {self.resources} files, "
                f"{self.images} images, {self.requests} browser requests, "
                f"{self.search_hits} search results for {SEARCH_WORD!r}; "
                + ", ".join(f"{k} {v:.1f} s" for k, v in self.seconds.items()))
        if self.ok:
            return f"site check passed: {head}"
        return f"site check FAILED ({len(self.problems)} problems): {head}\n  " + "\n  ".join(self.problems)


def chromium_path() -> str:
    """Path of Debian's Chromium; RuntimeError saying how to install it when missing."""
    path = shutil.which("chromium") or (CHROMIUM if Path(CHROMIUM).exists() else None)
    if path is None:
        raise RuntimeError(f"the site check needs Chromium (not found); install it with: {INSTALL}")
    return path


def check_site(site: Path, shots: Path | None = None, progress=None, only: list[str] | None = None) -> Report:
    """Crawl the built ``site`` and load its pages in Chromium (all of them, or the site-relative
    paths in ``only``); screenshots of SHOT_PAGES go to ``shots`` if given."""
    say = progress or (lambda *_: None)
    site = Path(site)
    built = sorted(p.relative_to(site).as_posix() for p in site.rglob("*.html"))
    report = Report()
    with serving(site) as base:
        t0 = time.monotonic()
        found = crawl(base, built)
        report.seconds["crawl"] = time.monotonic() - t0
        report.links, report.resources = found.links, len(found.resources)
        report.problems += found.problems
        say(f"crawled {len(found.pages)} pages, {found.links} links: {len(found.problems)} problems")
        t0 = time.monotonic()
        urls = sorted(found.pages) + [base + "404.html"] * ("404.html" in built)
        if only is not None:
            urls = [u for u in urls if u[len(base):] in only]
        _load_pages(base, urls, report, shots, say)
        report.seconds["browser"] = time.monotonic() - t0
    return report


def _load_pages(base: str, urls: list[str], report: Report, shots: Path | None, say) -> None:
    """Load each URL in one browser tab; every problem is recorded against its page."""
    from playwright.sync_api import sync_playwright
    exe = chromium_path()
    if shots is not None:
        shots.mkdir(parents=True, exist_ok=True)
    with sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=exe, args=FLAGS, headless=True)
        try:
            page = browser.new_context(viewport=VIEWPORT).new_page()
            issues: list[str] = []
            _listen(page, issues, report)
            for url in urls:
                issues.clear()
                _load_one(page, base, url, report, shots, issues)
                report.pages += 1
            if base + "index.html" in urls:
                _search(page, base, report)
        finally:
            browser.close()
    say(f"loaded {report.pages} pages in Chromium")


def _listen(page, issues: list[str], report: Report) -> None:
    """Record console errors, script errors, failed or refused requests into ``issues``."""
    def on_request(route):
        url = route.request.url
        if urllib.parse.urlsplit(url).hostname not in ("127.0.0.1", None) and not url.startswith("data:"):
            issues.append(f"request outside the site: {url}")
            route.abort()
        else:
            report.requests += 1
            route.continue_()

    page.route("**/*", on_request)
    page.on("console", lambda m: m.type == "error" and issues.append(f"console error: {m.text}"))
    page.on("pageerror", lambda e: issues.append(f"script error: {e}"))
    page.on("requestfailed", lambda r: issues.append(f"request failed: {r.url} ({r.failure})"))
    page.on("response", lambda r: r.status >= 400 and issues.append(f"HTTP {r.status}: {r.url}"))


def _search(page, base: str, report: Report) -> None:
    """Type SEARCH_WORD into the home page's search box as a person would; count the results."""
    page.goto(base + "index.html", wait_until="networkidle")
    box = page.locator("input.md-search__input")
    box.click()
    box.press_sequentially(SEARCH_WORD, delay=30)  # the theme searches on key events
    try:
        page.wait_for_selector(".md-search-result__item", timeout=10_000)
    except Exception:  # noqa: BLE001 (playwright's TimeoutError: reported below)
        pass
    report.search_hits = page.locator(".md-search-result__item").count()
    if not report.search_hits:
        report.problems.append(f"index.html: searching for {SEARCH_WORD!r} found nothing")


def _load_one(page, base: str, url: str, report: Report, shots: Path | None, issues: list[str]) -> None:
    rel = url[len(base):]
    resp = page.goto(url, wait_until="load", timeout=30_000)
    if resp is None or resp.status != 200:
        issues.append(f"HTTP {None if resp is None else resp.status}")
    page.wait_for_load_state("networkidle", timeout=30_000)  # the search index loads after 'load'
    facts = page.evaluate(PAGE_FACTS)
    report.images += facts["images"]
    if facts["broken"]:
        issues.append(f"images not shown: {facts['broken']}")
    if rel != "404.html" and facts["text"] < MIN_TEXT:
        issues.append(f"almost empty: {facts['text']} characters of text")
    if not facts["h1"].strip():
        issues.append("no page heading (h1)")
    if shots is not None and rel in SHOT_PAGES:
        path = shots / (rel.replace("/", "_").removesuffix(".html") + ".png")
        page.screenshot(path=str(path))
        report.shots.append(path)
    report.problems += [f"{rel}: {msg}" for msg in issues]
