"""Doxygen input filter: reads the headers' plain `//` comments as documentation.

The code base writes its comments with `//`, which Doxygen skips. Doxygen runs this filter on
each public header it documents (cmake/docs.cmake) and reads its output, the header itself is
left alone:
  - the comment block that opens the header (after #pragma once) becomes the file's doc;
  - a comment block directly above a declaration (no blank line between) becomes its `///` doc;
  - a trailing comment after a member or enumerator (`int x = 0;  // what`) becomes `///<`.
Blocks followed by a blank line (notes on a group of declarations) stay plain comments. Every
line stays on its line, so Doxygen's warnings point at the header's real lines.
"""
import re
import sys

COMMENT = re.compile(r"^(\s*)//(?![/!])\s?(.*)$")
TRAILING = re.compile(r"^(\s*[^/\s].*?[;,])(\s+)//(?![/!<])\s?(.*)$")


def filtered(lines):
    out = list(lines)
    i = 0
    opening = True  # before the first declaration: the file's own comment block
    while i < len(lines):
        if not COMMENT.match(lines[i]):
            m = TRAILING.match(lines[i])
            if m:
                out[i] = f"{m.group(1)}{m.group(2)}///< {m.group(3)}"
            if lines[i].strip():
                opening = opening and lines[i].startswith("#pragma")
            i += 1
            continue
        start = i
        while i < len(lines) and COMMENT.match(lines[i]):
            i += 1
        follower = lines[i] if i < len(lines) else ""
        if opening:
            mark = "//!"
        elif follower.strip() and not follower.lstrip().startswith("#"):
            mark = "///"
        else:
            continue
        for k in range(start, i):
            out[k] = COMMENT.sub(lambda m: f"{m.group(1)}{mark} {m.group(2)}", lines[k])
        if opening:
            out[i - 1] += r" \file"  # with no name after it: this file
        opening = False
    return out


if __name__ == "__main__":
    with open(sys.argv[1], encoding="utf-8") as f:
        sys.stdout.write("\n".join(filtered(f.read().split("\n"))))
