#!/usr/bin/env python3
"""Check the relative links and #anchors of README.md and docs/*.md.

Usage: scripts/check_doc_links.py [ROOT] [FILE.md ...]

ROOT defaults to the repository root (the parent of scripts/). Without FILE
arguments it checks README.md, CHANGELOG.md and every docs/*.md. For each
Markdown link or image `[text](target)` outside code, a target that is not a
URL (http:, https:, mailto:) must name an existing file or directory of the
repository (never a path outside it), and a `#anchor` (alone, or after a
.md file) must match a heading of that file by GitHub's slug rule: lower
case, every character that is not a letter, mark, number, `_`, `-` or space
removed, spaces turned into `-`, repeated slugs suffixed -1, -2, ...
Explicit `<a id="...">` / `<a name="...">` anchors count too.

Exit status 0 when every link resolves; otherwise 1, with one line per
broken link: FILE:LINE: target: reason.
"""

import os
import re
import sys
import unicodedata

LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
HTML_ANCHOR = re.compile(r"<a\s+(?:id|name)=\"([^\"]+)\"", re.IGNORECASE)
FENCE = re.compile(r"^\s*(```|~~~)")
INLINE_CODE = re.compile(r"(`+)(.*?)\1")


def slug(text):
    """GitHub's anchor for a heading's text."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", text)  # links -> their text
    text = re.sub(r"<[^>]+>", "", text)  # HTML tags
    out = []
    for ch in text.lower():
        cat = unicodedata.category(ch)
        if ch in " -" or cat[0] in "LMN" or cat == "Pc":
            out.append(ch)
    return "".join(out).replace(" ", "-")


def lines_outside_code(path):
    """(line number, text) of the lines outside fenced code blocks."""
    inside = False
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            if FENCE.match(line):
                inside = not inside
                continue
            if not inside:
                yield number, line


_anchor_cache = {}


def anchors(path):
    if path not in _anchor_cache:
        seen = {}
        found = set()
        for _, line in lines_outside_code(path):
            for name in HTML_ANCHOR.findall(line):
                found.add(name)
            m = HEADING.match(line)
            if not m:
                continue
            base = slug(m.group(2))
            n = seen.get(base, 0)
            seen[base] = n + 1
            found.add(base if n == 0 else f"{base}-{n}")
        _anchor_cache[path] = found
    return _anchor_cache[path]


def check_file(root, path):
    errors = []
    rel = os.path.relpath(path, root)
    for number, line in lines_outside_code(path):
        line = INLINE_CODE.sub("", line)
        for target in LINK.findall(line):
            if re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", target):
                continue  # a URL (http:, https:, mailto:, ...)
            file_part, _, anchor = target.partition("#")
            if file_part:
                dest = os.path.normpath(os.path.join(os.path.dirname(path), file_part))
                if os.path.commonpath([os.path.abspath(dest), root]) != root:
                    errors.append(f"{rel}:{number}: {target}: points outside the repository")
                    continue
                if not os.path.exists(dest):
                    errors.append(f"{rel}:{number}: {target}: no such file")
                    continue
            else:
                dest = path
            if anchor:
                if not dest.endswith(".md") or os.path.isdir(dest):
                    continue  # anchors into other files (source lines) are not checked
                if anchor not in anchors(dest):
                    errors.append(f"{rel}:{number}: {target}: no heading with anchor "
                                  f"#{anchor} in {os.path.relpath(dest, root)}")
    return errors


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.abspath(argv[1]) if len(argv) > 1 else os.path.dirname(here)
    files = [os.path.abspath(f) for f in argv[2:]]
    if not files:
        files = [os.path.join(root, name) for name in ("README.md", "CHANGELOG.md")]
        docs = os.path.join(root, "docs")
        files += sorted(os.path.join(docs, f) for f in os.listdir(docs) if f.endswith(".md"))
    errors = []
    for f in files:
        if os.path.exists(f):
            errors += check_file(root, f)
    for e in errors:
        print(e)
    if errors:
        print(f"{len(errors)} broken link(s)", file=sys.stderr)
        return 1
    print(f"{len(files)} files: every relative link and anchor resolves")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
