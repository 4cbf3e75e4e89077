"""Check the internal links of a built HTML site: every relative ``href``/``src`` points at a file
that exists, and every ``#anchor`` at an ``id`` in that file.

    python docs/check_links.py docs/_build/html

External links (http, https, mailto, ...) are not followed. Exit code 1 and one line per broken
link when any is broken; 0 otherwise.
"""
from __future__ import annotations

import sys
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urlsplit

__all__ = ["broken_links", "main"]


class _Page(HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.ids: set = set()
        self.links: list = []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        for key in ("id", "name"):
            if a.get(key) and (key == "id" or tag == "a"):
                self.ids.add(a[key])
        for key in ("href", "src"):
            if a.get(key) is not None and not (tag == "link" and key == "href"
                                                 and a.get("rel") in ("preconnect", "dns-prefetch")):
                self.links.append(a[key])


def _parse(path: Path) -> _Page:
    page = _Page()
    page.feed(path.read_text(encoding="utf-8", errors="replace"))
    return page


def broken_links(root) -> list:
    """``"page: link (reason)"`` for every broken internal link under ``root``."""
    root = Path(root)
    if not (root / "index.html").is_file():
        raise ValueError(f"{str(root)!r} holds no index.html; allowed: a built HTML site folder")
    cache: dict = {}

    def page(p: Path) -> _Page:
        if p not in cache:
            cache[p] = _parse(p)
        return cache[p]

    bad = []
    for html in sorted(root.rglob("*.html")):
        if "_static" in html.relative_to(root).parts:
            continue  # the theme's template snippets, not pages
        for link in page(html).links:
            parts = urlsplit(link)
            if parts.scheme or parts.netloc or link.startswith("//"):
                continue  # external: not checked here
            target = html if not parts.path else (html.parent / unquote(parts.path)).resolve()
            if target.is_dir():
                target = target / "index.html"
            rel = html.relative_to(root)
            if not target.exists():
                bad.append(f"{rel}: {link} (no file {target.name})")
                continue
            if parts.fragment and target.suffix == ".html":
                if unquote(parts.fragment) not in page(target).ids:
                    bad.append(f"{rel}: {link} (no id {parts.fragment!r})")
    return bad


def main(argv=None) -> int:
    args = sys.argv[1:] if argv is None else argv
    if len(args) != 1:
        print("usage: python docs/check_links.py BUILT_HTML_DIR", file=sys.stderr)
        return 2
    try:
        bad = broken_links(args[0])
    except ValueError as exc:
        print(exc, file=sys.stderr)
        return 2
    for line in bad:
        print(line)
    n = sum(1 for _ in Path(args[0]).rglob("*.html"))
    print(f"{n} pages, {len(bad)} broken internal link(s)", file=sys.stderr)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
