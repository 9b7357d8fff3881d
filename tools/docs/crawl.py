"""Crawl a site served on localhost: every internal link, image, stylesheet and script must
load (HTTP 200), every ``#fragment`` must name an element id on its page, and every built
page must be reachable from the home page.

The crawl reads the HTML as served (html.parser), so it checks what mkdocs wrote; the
browser check (browser.py) then checks what a person sees.
"""
from __future__ import annotations

import html.parser
import urllib.error
import urllib.parse
import urllib.request
from dataclasses import dataclass, field

# (tag, attribute) pairs that point at something the page needs or offers
REFS = {("a", "href"), ("img", "src"), ("link", "href"), ("script", "src"), ("source", "src")}


class _Page(html.parser.HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.refs: list[tuple[str, str]] = []  # (tag, url as written)
        self.ids: set[str] = set()

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if a.get("id"):
            self.ids.add(a["id"])
        if tag == "a" and a.get("name"):
            self.ids.add(a["name"])
        for t, attr in REFS:
            if tag == t and a.get(attr):
                self.refs.append((tag, a[attr]))


@dataclass
class CrawlResult:
    """What the crawl found: pages (URL -> element ids), resources checked, problems."""
    pages: dict[str, set[str]] = field(default_factory=dict)
    resources: set[str] = field(default_factory=set)
    links: int = 0
    problems: list[str] = field(default_factory=list)


def _fetch(url: str) -> tuple[int, bytes, str]:
    try:
        with urllib.request.urlopen(url, timeout=10) as r:
            return r.status, r.read(), r.headers.get_content_type()
    except urllib.error.HTTPError as e:
        return e.code, b"", ""


def crawl(base: str, expected_pages: list[str]) -> CrawlResult:
    """Breadth-first from ``base`` (…/index.html); ``expected_pages`` are the site-relative paths
    of every built page, each of which must be reached (except 404.html)."""
    res = CrawlResult()
    fragments: list[tuple[str, str, str]] = []  # (from page, target page, fragment)
    queue = [urllib.parse.urljoin(base, "index.html")]
    seen = set(queue)
    while queue:
        url = queue.pop(0)
        status, body, ctype = _fetch(url)
        if status != 200:
            res.problems.append(f"{url}: HTTP {status}")
            continue
        if ctype != "text/html":
            res.resources.add(url)
            continue
        parser = _Page()
        parser.feed(body.decode("utf-8", errors="replace"))
        res.pages[url] = parser.ids
        for tag, ref in parser.refs:
            target = urllib.parse.urljoin(url, ref)
            if not target.startswith(base):
                continue  # external: the browser check flags any request that leaves the site
            res.links += 1
            page, _, frag = target.partition("#")
            if frag:
                fragments.append((url, page, urllib.parse.unquote(frag)))
            if page not in seen and (tag == "a" or tag in ("img", "link", "script", "source")):
                seen.add(page)
                queue.append(page)
    for src, page, frag in fragments:
        ids = res.pages.get(page)
        if ids is not None and frag not in ids:
            res.problems.append(f"{src}: link to {page}#{frag}: no element with that id")
    reached = {u[len(base):] for u in res.pages}
    for rel in expected_pages:
        if rel != "404.html" and rel not in reached:
            res.problems.append(f"{rel}: built but not reachable by links from the home page")
    return res
