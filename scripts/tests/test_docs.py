# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""The project's markdown: every relative link leads to a file or folder
of the tree (a renamed or moved file shows here, not to a reader); a
number whose link names its source (a results table, a bench's log) is
found there: a number a run produces is quoted from that run's output,
and a rerun that changes it shows here."""

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


# a link whose text starts with a number: [833.04 mm](../bench/.../x.log)
NUMBER_LINK = re.compile(r"\[([-+]?\d[\d.]*(?:e[-+]?\d+)?)[^\]]*\]"
                         r"\(([^)#\s]+)\)")


def quoted_numbers(text):
    """[(number, link)] of the text's links whose text is a number."""
    return NUMBER_LINK.findall(text)


def missing_numbers(f, text):
    """The quoted numbers of f's text that their source lacks."""
    missing = []
    for number, link in quoted_numbers(text):
        target = os.path.join(os.path.dirname(f), link)
        if not os.path.isfile(target):
            continue            # test_relative_links_resolve's business
        with open(target, errors="replace") as fh:
            source = fh.read()
        if not re.search(r"(?<![\d.])%s(?![\d])" % re.escape(number),
                         source):
            missing.append("%s: %s not in %s"
                           % (os.path.relpath(f, TOP), number, link))
    return missing


def test_a_quoted_number_is_found_in_its_source():
    missing = []
    for f in markdown_files():
        with open(f) as fh:
            missing += missing_numbers(f, fh.read())
    assert missing == []


def test_the_number_links_are_read_and_checked(tmp_path):
    text = ("climb [833.04 mm](a.log), x [-47.596 mm](a.log), a [link](b),"
            " [3.1e-08 %](a.log), [1.39](a.log)")
    assert quoted_numbers(text) == [("833.04", "a.log"), ("-47.596", "a.log"),
                                    ("3.1e-08", "a.log"), ("1.39", "a.log")]
    (tmp_path / "a.log").write_text("z = 833.04 mm, x = -47.596 mm, 3.1e-08,"
                                    " C 1.393")
    page = str(tmp_path / "page.md")
    # 1.39 is not 1.393: a rounded quote is not the source's number
    assert [m.split(": ")[1] for m in missing_numbers(page, text)] == \
        ["1.39 not in a.log"]
