"""mkdocs hooks (loaded by mkdocs.yml): repository files in the site, generated sections.

1. Pages under docs/ link to files beside it (``../bench/results/scaling.png``,
   ``../scenes/stelkropp.schema.json``): those links are right on GitHub and in an editor, and
   the pages are written by other tools (bench/ generates benchmarks.md), so they are not
   edited.  Instead every such target that exists is copied into the site under ``repo/`` and
   the link is rewritten while the page is rendered.  A target that does not exist is left
   alone, so the strict build reports it as a broken link.
2. ``<!-- stelkropp:NAME args -->`` markers are replaced by sections generated from the code
   (tools/docs/generated.py), so tables of settings and command-line help never go stale.
"""
from __future__ import annotations

import re
import sys
from pathlib import Path

from mkdocs.structure.files import File

ROOT = Path(__file__).resolve().parents[2]
if str(ROOT) not in sys.path:  # mkdocs imports this file by path; generated.py needs the repo
    sys.path.insert(0, str(ROOT))

from tools.docs import generated  # noqa: E402

# a Markdown link or image target: ](target) or ](target "title"), no spaces inside
LINK = re.compile(r"(\]\()([^)\s]+)((?:\s+\"[^\"]*\")?\))")
# a marker stands alone on its line (so one quoted in `code` or a table is left as text)
MARKER = re.compile(r"^<!--\s*stelkropp:([a-z-]+)\s*(.*?)\s*-->[ \t]*$", re.M)
REPO_DIR = "repo"


def _outside_target(page_src: str, target: str, docs_dir: Path) -> Path | None:
    """The repository file a relative link from docs page ``page_src`` points to, when it lies
    outside docs_dir (else None: mkdocs resolves it as usual)."""
    if "://" in target or target.startswith(("#", "/", "mailto:")):
        return None
    path = target.split("#", 1)[0]
    if not path:
        return None
    resolved = ((docs_dir / page_src).parent / path).resolve()
    try:
        resolved.relative_to(docs_dir)
        return None
    except ValueError:
        pass
    try:
        resolved.relative_to(ROOT)
    except ValueError:
        return None
    return resolved if resolved.is_file() else None


def on_files(files, config):
    """Add every repository file a page links to (outside docs/) to the site under repo/."""
    docs_dir = Path(config["docs_dir"]).resolve()
    wanted: set[Path] = set()
    for f in files.documentation_pages():
        text = Path(f.abs_src_path).read_text(encoding="utf-8")
        for m in LINK.finditer(text):
            target = _outside_target(f.src_uri, m.group(2), docs_dir)
            if target is not None:
                wanted.add(target)
    for target in sorted(wanted):
        uri = f"{REPO_DIR}/{target.relative_to(ROOT).as_posix()}"
        if files.get_file_from_path(uri) is None:
            files.append(File.generated(config, uri, abs_src_path=str(target)))
    return files


def on_page_markdown(markdown, page, config, files):
    """Rewrite links to repository files, then expand the generated-section markers."""
    docs_dir = Path(config["docs_dir"]).resolve()
    depth = page.file.src_uri.count("/")
    up = "../" * depth

    def relink(m):
        target = _outside_target(page.file.src_uri, m.group(2), docs_dir)
        if target is None:
            return m.group(0)
        frag = "#" + m.group(2).split("#", 1)[1] if "#" in m.group(2) else ""
        new = f"{up}{REPO_DIR}/{target.relative_to(ROOT).as_posix()}{frag}"
        return m.group(1) + new + m.group(3)

    markdown = LINK.sub(relink, markdown)
    return MARKER.sub(lambda m: generated.expand(m.group(1), m.group(2), page.file.src_uri), markdown)
