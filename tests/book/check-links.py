#!/usr/bin/env python3
"""Check every internal link and anchor of a built HTML book (mdBook's output, target/book).

    python3 tests/book/check-links.py [BOOK_DIR]      (default: target/book)

Parses every .html file under BOOK_DIR (Python's standard library only) and follows each
relative reference -- <a href>, <link href>, <script src>, <img src>, <iframe src>,
<source src>, SVG <image>/<use> href -- to a file under BOOK_DIR and, when it carries a
#fragment, to an element with that id (or an <a name>) in the target page. A <base href> is
honoured (mdBook's 404.html has one; an absolute one, "/", means BOOK_DIR).

Prints the external references (http:, https:, protocol-relative //host, mailto:) once each,
as "external: URL (N pages)", without fetching them, then one line per broken reference,
"BROKEN: page: href (why)", and exits 1 if there was any; 0 otherwise; 2 on a usage error
(no such directory, or no HTML in it).
"""

import os
import sys
from html.parser import HTMLParser
from urllib.parse import unquote, urlsplit

# (tag, attribute) pairs that name another resource.
REFERENCE_ATTRS = {
    ("a", "href"),
    ("link", "href"),
    ("script", "src"),
    ("img", "src"),
    ("iframe", "src"),
    ("source", "src"),
    ("image", "href"),
    ("image", "xlink:href"),
    ("use", "href"),
    ("use", "xlink:href"),
}
EXTERNAL_SCHEMES = {"http", "https", "mailto", "ftp", "tel"}
IGNORED_SCHEMES = {"data", "javascript", "about", "blob"}


class Page(HTMLParser):
    """One HTML file: the ids it defines, its references and its <base href>."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.ids = set()
        self.refs = []
        self.base = None

    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if value is None:
                continue
            if name == "id" or (tag == "a" and name == "name"):
                self.ids.add(value)
            if tag == "base" and name == "href" and self.base is None:
                self.base = value
            if (tag, name) in REFERENCE_ATTRS:
                self.refs.append(value)

    handle_startendtag = handle_starttag


def parse(path):
    page = Page()
    with open(path, encoding="utf-8", errors="replace") as f:
        page.feed(f.read())
    page.close()
    return page


def main(argv):
    root = os.path.realpath(argv[1] if len(argv) > 1 else "target/book")
    if not os.path.isdir(root):
        print(f"check-links: no such directory: {root}", file=sys.stderr)
        return 2
    pages = {}
    for directory, _, files in os.walk(root):
        for name in files:
            if name.endswith((".html", ".htm")):
                path = os.path.join(directory, name)
                pages[path] = parse(path)
    if not pages:
        print(f"check-links: no HTML files under {root}", file=sys.stderr)
        return 2

    external = {}
    broken = []
    checked = 0
    for path, page in sorted(pages.items()):
        rel_page = os.path.relpath(path, root)
        base_dir = os.path.dirname(path)
        if page.base is not None:
            if page.base.startswith("/"):
                base_dir = os.path.join(root, page.base.lstrip("/"))
            elif not urlsplit(page.base).scheme:
                base_dir = os.path.normpath(os.path.join(base_dir, page.base))
        for href in page.refs:
            href = href.strip()
            parts = urlsplit(href)
            scheme = parts.scheme.lower()
            if scheme in IGNORED_SCHEMES:
                continue
            if scheme in EXTERNAL_SCHEMES or (not scheme and parts.netloc):
                external.setdefault(href, set()).add(rel_page)
                continue
            if scheme:
                broken.append(f"{rel_page}: {href} (unknown scheme {scheme}:)")
                continue
            checked += 1
            if parts.path:
                if parts.path.startswith("/"):
                    target = os.path.join(root, unquote(parts.path).lstrip("/"))
                else:
                    target = os.path.join(base_dir, unquote(parts.path))
                target = os.path.realpath(target)
                if os.path.isdir(target):
                    target = os.path.join(target, "index.html")
            else:
                target = path  # "#fragment" alone: this page
            if target != root and not target.startswith(root + os.sep):
                broken.append(f"{rel_page}: {href} (leaves the book: {target})")
                continue
            if not os.path.isfile(target):
                broken.append(f"{rel_page}: {href} (no file {os.path.relpath(target, root)})")
                continue
            fragment = unquote(parts.fragment)
            if fragment and target.endswith((".html", ".htm")):
                ids = pages[target].ids if target in pages else parse(target).ids
                if fragment not in ids:
                    broken.append(
                        f"{rel_page}: {href} (no id \"{fragment}\" in "
                        f"{os.path.relpath(target, root)})"
                    )

    for url in sorted(external):
        print(f"external: {url} ({len(external[url])} pages)")
    for line in broken:
        print(f"BROKEN: {line}")
    print(
        f"check-links: {len(pages)} pages, {checked} internal references checked, "
        f"{len(broken)} broken, {len(external)} external URLs (not fetched)"
    )
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
