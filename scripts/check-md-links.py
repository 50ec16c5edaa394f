#!/usr/bin/env python3
"""Checks the relative links of the repository's Markdown files: every [text](target) and
![alt](target) whose target is not a URL must name an existing file, and a #fragment must name a
heading of that file (GitHub's anchor rule). Prints one line per broken link; exit 1 if any.

    python3 scripts/check-md-links.py            # README.md, CONTRIBUTING.md, docs/*.md, ...
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")
FENCE = re.compile(r"^(```|~~~)")


def anchors(path):
    """GitHub's anchors of a Markdown file's headings."""
    seen, result = {}, set()
    in_fence = False
    for line in path.read_text(encoding="utf-8").splitlines():
        if FENCE.match(line):
            in_fence = not in_fence
        if in_fence or not line.startswith("#"):
            continue
        text = line.lstrip("#").strip().lower()
        text = text.replace("`", "")
        slug = re.sub(r"[^\w\- ]", "", text, flags=re.UNICODE).replace(" ", "-")
        n = seen.get(slug, 0)
        seen[slug] = n + 1
        result.add(slug if n == 0 else f"{slug}-{n}")
    return result


def links(path):
    in_fence = False
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if FENCE.match(line):
            in_fence = not in_fence
            continue
        if in_fence:
            continue
        for match in LINK.finditer(re.sub(r"`[^`]*`", "", line)):
            yield number, match.group(1)


def main():
    files = [p for p in ROOT.rglob("*.md")
             if not any(part in {"node_modules", "runs"} or part.startswith(("build", "."))
                        for part in p.relative_to(ROOT).parts)]
    broken = 0
    for path in sorted(files):
        for number, target in links(path):
            if re.match(r"^[a-z][a-z0-9+.-]*:", target):  # http:, https:, mailto:
                continue
            name, _, fragment = target.partition("#")
            dest = (path.parent / name).resolve() if name else path
            where = f"{path.relative_to(ROOT)}:{number}: {target}"
            if not dest.exists():
                print(f"{where}: no such file")
                broken += 1
            elif fragment and dest.suffix == ".md" and fragment not in anchors(dest):
                print(f"{where}: no heading with anchor #{fragment}")
                broken += 1
    print(f"{len(files)} Markdown files, {broken} broken links")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
