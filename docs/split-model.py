#!/usr/bin/env python3
"""Split docs/model.md into the user guide's model chapters.

docs/model.md stays the single source of the model reference (the code and the tests cite
"docs/model.md §N"). This script writes, from it,

  docs/src/model/index.md       the text before chapter 1
  docs/src/model/NN-slug.md     one file per `## N. Title` heading (NN = N, two digits)

rewriting the links: `#anchor` to the chapter that holds the anchor (`NN-slug.md#anchor`, or
`#anchor` inside the same chapter), `model.md#anchor` likewise, and relative links to other files
so that they still point at the same file from docs/src/model/.

The generated files are not committed (docs/src/model/ is in .gitignore); run this before
`mdbook build docs`. It exits with status 1 when docs/src/SUMMARY.md's model entries and the
generated files differ (a chapter added, removed or renamed in docs/model.md without SUMMARY.md,
or the reverse), printing both lists.

Usage: python3 docs/split-model.py [--check]
  --check   generate nothing; only compare SUMMARY.md with the chapters docs/model.md would give.

Standard library only.
"""

import os
import re
import sys
import unicodedata

DOCS = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.join(DOCS, "model.md")
OUT = os.path.join(DOCS, "src", "model")
SUMMARY = os.path.join(DOCS, "src", "SUMMARY.md")

CHAPTER = re.compile(r"^## (\d+)\. (.+?)\s*$")
HEADING = re.compile(r"^(#{1,6}) (.+?)\s*#*\s*$")
FENCE = re.compile(r"^\s*(```|~~~)")
# [text](target) and ![alt](target); the target has no spaces or parentheses inside
LINK = re.compile(r"(!?\[[^\]]*\]\()([^()\s]+)(\))")


def slug(title):
    """File-name slug of a chapter title: ASCII letters and digits, words joined by '-'."""
    text = unicodedata.normalize("NFKD", title)
    text = text.encode("ascii", "ignore").decode("ascii").lower()
    text = re.sub(r"[^a-z0-9]+", "-", text).strip("-")
    return text[:48].rstrip("-") or "chapter"


def anchor(title):
    """The id mdBook gives a heading: lower case, spaces to '-', other punctuation dropped."""
    text = re.sub(r"<[^>]*>", "", title)
    out = []
    for ch in text.strip().lower():
        if ch.isalnum() or ch in "-_":
            out.append(ch)
        elif ch.isspace():
            out.append("-")
    return "".join(out)


def split(lines):
    """[(file name, title or None, lines)]: the preamble, then one entry per chapter."""
    parts = [("index.md", None, [])]
    fenced = False
    for line in lines:
        if FENCE.match(line):
            fenced = not fenced
        m = None if fenced else CHAPTER.match(line)
        if m:
            number, title = int(m.group(1)), m.group(2)
            parts.append((f"{number:02d}-{slug(title)}.md", f"{number}. {title}", []))
        parts[-1][2].append(line)
    return parts


def anchors_of(parts):
    """Map every heading id of docs/model.md to the file it lands in (first occurrence wins)."""
    where = {}
    for name, _, lines in parts:
        seen = {}
        fenced = False
        for line in lines:
            if FENCE.match(line):
                fenced = not fenced
                continue
            m = None if fenced else HEADING.match(line)
            if not m:
                continue
            base = anchor(m.group(2))
            n = seen.get(base, 0)
            seen[base] = n + 1
            ident = base if n == 0 else f"{base}-{n}"
            where.setdefault(ident, name)
    return where


def rewrite(line, here, where):
    """Rewrite the link targets of one line of the chapter `here`."""

    def target(m):
        dest = m.group(2)
        if re.match(r"^[a-z][a-z0-9+.-]*:", dest):  # http:, https:, mailto:
            return m.group(0)
        path, _, frag = dest.partition("#")
        if path in ("", "model.md", "./model.md"):
            if not frag:
                return m.group(1) + "index.md" + m.group(3)
            file = where.get(frag)
            if file is None:
                return m.group(0)
            new = f"#{frag}" if file == here else f"{file}#{frag}"
            return m.group(1) + new + m.group(3)
        # a relative link from docs/: the same file seen from docs/src/model/
        resolved = os.path.normpath(os.path.join(DOCS, path))
        new = os.path.relpath(resolved, OUT).replace(os.sep, "/")
        return m.group(1) + new + (f"#{frag}" if frag else "") + m.group(3)

    return LINK.sub(target, line)


def summary_entries():
    """The model/… files SUMMARY.md lists, in order."""
    with open(SUMMARY, encoding="utf-8") as f:
        text = f.read()
    return re.findall(r"\]\(model/([^)#\s]+)\)", text)


def main(argv):
    check_only = "--check" in argv[1:]
    with open(SOURCE, encoding="utf-8") as f:
        lines = f.read().split("\n")
    parts = split(lines)
    where = anchors_of(parts)
    names = [name for name, _, _ in parts]

    if not check_only:
        os.makedirs(OUT, exist_ok=True)
        for stale in os.listdir(OUT):
            if stale.endswith(".md") and stale not in names:
                os.remove(os.path.join(OUT, stale))
        for name, title, body in parts:
            out = []
            fenced = False
            for line in body:
                if FENCE.match(line):
                    fenced = not fenced
                if fenced:
                    out.append(line)
                    continue
                line = rewrite(line, name, where)
                # a chapter's `## N.` is its page title: every heading one level up
                if title is not None and line.startswith("##"):
                    line = line[1:]
                out.append(line)
            text = "\n".join(out).rstrip("\n") + "\n"
            if title is None:
                note = (
                    "\n> This part of the guide is generated from `docs/model.md` by "
                    "`docs/split-model.py`; edit `docs/model.md`.\n"
                )
                text = text + note
            with open(os.path.join(OUT, name), "w", encoding="utf-8") as f:
                f.write(text)

    listed = summary_entries()
    if sorted(listed) != sorted(names) or len(set(listed)) != len(listed):
        print("docs/src/SUMMARY.md's model entries differ from docs/model.md's chapters:", file=sys.stderr)
        print("  in SUMMARY.md:  " + ", ".join(listed), file=sys.stderr)
        print("  from model.md:  " + ", ".join(names), file=sys.stderr)
        missing = [n for n in names if n not in listed]
        extra = [n for n in listed if n not in names]
        if missing:
            print("  not listed:     " + ", ".join(missing), file=sys.stderr)
        if extra:
            print("  not generated:  " + ", ".join(extra), file=sys.stderr)
        return 1
    if not check_only:
        print(f"docs/src/model/: {len(names)} files from docs/model.md")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
