"""The reference site: build it (mkdocs-material + mkdocstrings) and check it in a real browser.

``python -m tools.docs build`` writes the site to ``site/``; ``python -m tools.docs check``
builds it and loads every page in headless Chromium (see :mod:`tools.docs.browser`).
"""
