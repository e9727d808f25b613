#!/usr/bin/env python3
"""Fails when a relative link or anchor in README.md or docs/*.md does not
resolve: the file (or folder) must exist in the tree, and a #fragment must be
a heading of the linked markdown file, slugged as GitHub slugs it.

    check_links.py ROOT      checks ROOT/README.md and ROOT/docs/*.md
"""
import pathlib
import re
import sys
import unicodedata

LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")


def strip_code(text):
    """The text without fenced blocks and inline code (links there are not links)."""
    text = re.sub(r"^```.*?^```", "", text, flags=re.S | re.M)
    return re.sub(r"`[^`\n]*`", "", text)


def slug(heading):
    """GitHub's anchor for a heading: lower case, markup and punctuation dropped, spaces to '-'."""
    h = re.sub(r"`([^`]*)`", r"\1", heading)
    h = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", h)
    h = re.sub(r"<[^>]+>", "", h).lower()
    out = []
    for c in h:
        cat = unicodedata.category(c)
        if c in "-_ " or cat[0] in "LN" or cat == "Mn":
            out.append("-" if c == " " else c)
    return "".join(out)


def anchors(path, cache={}):
    if path not in cache:
        seen, found = {}, set()
        text = re.sub(r"^```.*?^```", "", path.read_text(encoding="utf-8"), flags=re.S | re.M)
        for line in text.splitlines():
            m = HEADING.match(line)
            if not m:
                continue
            s = slug(m.group(2))
            n = seen.get(s, 0)
            seen[s] = n + 1
            found.add(s if n == 0 else f"{s}-{n}")
        for m in re.finditer(r"<a\s+(?:name|id)=\"([^\"]+)\"", text):
            found.add(m.group(1))
        cache[path] = found
    return cache[path]


def check(root):
    root = root.resolve()
    docs = [root / "README.md", *sorted((root / "docs").glob("*.md"))]
    problems, links = [], 0
    for doc in docs:
        if not doc.exists():
            problems.append(f"{doc}: missing")
            continue
        text = strip_code(doc.read_text(encoding="utf-8"))
        for lineno, line in enumerate(text.splitlines(), 1):
            for m in LINK.finditer(line):
                target = m.group(1)
                if re.match(r"^[a-z][a-z0-9+.-]*:", target):  # http:, mailto: ...
                    continue
                links += 1
                file_part, _, frag = target.partition("#")
                dest = doc if not file_part else (doc.parent / file_part).resolve()
                where = f"{doc.relative_to(root)}:{lineno}: ({target})"
                if not dest.exists():
                    problems.append(f"{where}: no file {file_part}")
                elif root not in dest.parents and dest != root:
                    problems.append(f"{where}: outside the repository")
                elif frag and dest.suffix == ".md" and frag not in anchors(dest):
                    problems.append(f"{where}: no heading #{frag} in {dest.relative_to(root)}")
    return problems, links, len(docs)


def main():
    problems, links, docs = check(pathlib.Path(sys.argv[1]))
    for p in problems:
        print(p)
    if problems:
        print(f"{len(problems)} broken link(s) of {links} in {docs} file(s)")
        return 1
    print(f"links: {links} relative links in {docs} files, all resolve")
    return 0


if __name__ == "__main__":
    sys.exit(main())
