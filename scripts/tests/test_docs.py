# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""The project's markdown: every relative link leads to a file or folder
of the tree (a renamed or moved file shows here, not to a reader)."""

import glob
import os
import re

TOP = os.path.normpath(os.path.join(os.path.dirname(__file__), "..", ".."))


def markdown_files():
    skip = (os.sep + "platforms" + os.sep, os.sep + "runs" + os.sep)
    return [f for f in glob.glob(os.path.join(TOP, "**", "*.md"),
                                 recursive=True)
            if not any(s in f for s in skip)]


def test_relative_links_resolve():
    assert len(markdown_files()) > 20
    broken = []
    for f in markdown_files():
        with open(f) as fh:
            text = fh.read()
        for m in re.finditer(r"\]\(([^)#\s]+)(#[^)]*)?\)", text):
            link = m.group(1)
            if re.match(r"[a-z]+:", link):
                continue
            target = os.path.join(os.path.dirname(f), link)
            if not os.path.exists(target):
                broken.append("%s: %s" % (os.path.relpath(f, TOP), link))
    assert broken == []
