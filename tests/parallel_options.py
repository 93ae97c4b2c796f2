#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""ctest: every OIIO parallel loop in texsyn passes detail::split_every_item(...)
(core/src/image/parallel_pvt.h). OIIO's default options run a loop over fewer than 16384
items, such as the rows of a 1024 x 1024 image, on the calling thread alone: a loop that
leaves them out is silently serial. usage: parallel_options.py SOURCE_DIR"""
import pathlib
import re
import sys

EXEMPT = {"core/src/sanitize/tsan_parallel_for.cpp"}  # defines the loops it interposes
CALL = re.compile(r"\bOIIO::parallel_(for|for_chunked|for_range|for_2D|image)\s*\(")


def arguments(text, start):
    """The text between the '(' at text[start - 1] and its matching ')'."""
    depth = 1
    for i in range(start, len(text)):
        depth += {"(": 1, ")": -1}.get(text[i], 0)
        if depth == 0:
            return text[start:i]
    raise ValueError("unbalanced parentheses")


def main():
    root = pathlib.Path(sys.argv[1])
    calls, bad = 0, []
    for path in sorted(root.glob("core/src/**/*.[ch]*")):
        rel = path.relative_to(root).as_posix()
        if rel in EXEMPT:
            continue
        text = path.read_text()
        for m in CALL.finditer(text):
            calls += 1
            if "split_every_item(" not in arguments(text, m.end()):
                bad.append("%s:%d" % (rel, text.count("\n", 0, m.start()) + 1))
        if "OIIO::paropt(" in text and not rel.endswith("image/parallel_pvt.h"):
            bad.append("%s: constructs OIIO::paropt itself" % rel)
    if calls < 20:
        sys.exit("found only %d parallel loops under %s/core/src" % (calls, root))
    if bad:
        sys.exit("parallel loops without detail::split_every_item(nthreads):\n  "
                 + "\n  ".join(bad))
    print("%d parallel loops, each with split_every_item" % calls)


if __name__ == "__main__":
    main()
