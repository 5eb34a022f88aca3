# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Runs the shell commands of the README's and docs' code blocks, so that
what the pages tell a user to type keeps working.

    flapfoam doc_commands [-list] [-only FILE:LINE] [-tmp DIR]
                          [-timeout S] PAGE...

Every ```sh block of a page carries a marker on the line before it:

    <!-- test: run -->                  run as written, from the root
    <!-- test: run from DIR -->         from the folder DIR of the root
    <!-- test: run; A => B; C => D -->  run with each command rewritten,
                                        regular expression A replaced by B
                                        (in order; {tmp} is the page's
                                        scratch folder, {n} the block's
                                        line, {k} the command's index)
    <!-- test: skip REASON -->          not run (hours of CPU, a cluster,
                                        placeholders): the reason is shown

Each page has a scratch folder of its own (TMP/<page>, its path with
/ as _), so that two pages' run folders of the same name never meet;
a page's blocks share it, in order.  The rewrites make a documented
command cheap and keep it out of the user's run folders (the tiny mesh,
a few steps, a run folder under {tmp}), nothing else.  A block runs as
one bash script from the project's root (etc/bashrc sourced, set -e,
comments and trailing & dropped, lines joined at a trailing backslash),
under -timeout (default 300 s).  A sh
block without a marker is an error: each block says whether it is run.
One PASS, FAIL or SKIP line per block; exit status 1 if a block fails or
has no marker.
"""

import argparse
import os
import re
import subprocess
import sys
import tempfile
from dataclasses import dataclass, field

from flapfoam.errors import FlapFoamError, run_tool
from flapfoam.paths import project_dir

MARKER = re.compile(r"^<!--\s*test:\s*(.*?)\s*-->\s*$")


@dataclass
class Block:
    """A ```sh block of a page: where it starts, its marker (None if it
    has none) and its commands (continuation lines joined)."""
    page: str
    line: int
    marker: str = None
    commands: list = field(default_factory=list)

    @property
    def where(self):
        return "%s:%d" % (self.page, self.line)


def commands(lines):
    """The commands of a block's lines: comments (a # at the start or
    after a space) and a trailing & dropped, a trailing \\ joined."""
    out, pending = [], ""
    for raw in lines:
        line = re.sub(r"(^|\s)#.*$", "", raw).rstrip()
        if line.endswith("\\"):
            pending += line[:-1].strip() + " "
            continue
        line = (pending + line.strip()).strip()
        pending = ""
        line = re.sub(r"\s*(?<!&)&$", "", line)
        if line:
            out.append(line)
    return out


def blocks(page, text):
    """The page's sh blocks with their markers."""
    found, lines = [], text.split("\n")
    i = 0
    while i < len(lines):
        if lines[i].strip() == "```sh":
            m = MARKER.match(lines[i - 1].strip()) if i > 0 else None
            j = i + 1
            while j < len(lines) and lines[j].strip() != "```":
                j += 1
            found.append(Block(page, i + 1, m.group(1) if m else None,
                               commands(lines[i + 1:j])))
            i = j
        i += 1
    return found


def rewrites(block):
    """[(pattern, replacement)] of a run marker; FlapFoamError if the
    marker is neither run nor skip, or a rewrite has no =>."""
    parts = [p.strip() for p in block.marker.split(";")]
    if not re.fullmatch(r"run( from \S+)?", parts[0]):
        raise FlapFoamError("%s: marker 'test: %s': allowed 'run', 'run "
                            "from DIR', each with '; A => B; ...', or "
                            "'skip REASON'" % (block.where, block.marker))
    pairs = []
    for p in parts[1:]:
        if "=>" not in p:
            raise FlapFoamError("%s: rewrite '%s' has no '=>' (allowed: "
                                "A => B)" % (block.where, p))
        a, b = (s.strip() for s in p.split("=>", 1))
        pairs.append((re.compile(a), b))
    return pairs


def script(block, tmp):
    """The bash script of a run block: its commands rewritten."""
    pairs = rewrites(block)
    out = []
    for k, c in enumerate(block.commands):
        for pattern, repl in pairs:
            c = pattern.sub(repl.replace("{tmp}", tmp)
                            .replace("{n}", str(block.line))
                            .replace("{k}", str(k)), c)
        out.append(c)
    return out


def folder(block, root):
    """The folder a run block runs in: the root, or run from DIR's."""
    first = block.marker.split(";")[0].split()
    return os.path.join(root, first[2]) if len(first) == 3 else root


def scratch(block, tmp):
    """The page's scratch folder under tmp: TMP/<page path, / as _>."""
    return os.path.join(tmp, block.page.replace(os.sep, "_"))


def run(block, root, tmp, timeout):
    """Runs a block in its page's scratch folder; (ok, text)."""
    tmp = scratch(block, tmp)
    os.makedirs(tmp, exist_ok=True)
    lines = script(block, tmp)
    body = "set -e\n. %s/etc/bashrc > /dev/null\n%s\n" % (
        root, "\n".join(lines))
    log = os.path.join(tmp, "log.%d" % block.line)
    try:
        with open(log, "w") as fh:
            rc = subprocess.call(["bash", "-c", body],
                                 cwd=folder(block, root), stdout=fh,
                                 stderr=subprocess.STDOUT,
                                 stdin=subprocess.DEVNULL, timeout=timeout)
    except subprocess.TimeoutExpired:
        return False, "timed out after %d s (%s)" % (timeout, log)
    if rc != 0:
        return False, "exit %d (%s)" % (rc, log)
    return True, "%d command(s)" % len(lines)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("pages", nargs="+")
    ap.add_argument("-list", action="store_true",
                    help="print each block's commands as they would run")
    ap.add_argument("-only", help="the block at FILE:LINE alone")
    ap.add_argument("-tmp", help="the scratch folder (default: a new one)")
    ap.add_argument("-timeout", type=int, default=300)
    a = ap.parse_args(argv)
    root = project_dir()
    if a.list:
        tmp = a.tmp or "TMP"
    else:
        tmp = os.path.abspath(a.tmp or
                              tempfile.mkdtemp(prefix="flapFoam-doc-"))
        os.makedirs(tmp, exist_ok=True)
    failed = 0
    try:
        for page in a.pages:
            with open(page) as fh:
                text = fh.read()
            rel = os.path.relpath(os.path.abspath(page), root)
            for b in blocks(rel, text):
                if a.only and a.only != b.where:
                    continue
                if b.marker is None:
                    failed += 1
                    print("FAIL %s: a sh block without a '<!-- test: run "
                          "| skip REASON -->' line before it" % b.where)
                elif b.marker.startswith("skip"):
                    print("SKIP %s: %s" % (b.where, b.marker[4:].strip()))
                elif a.list:
                    print("%s:\n    %s" % (b.where, "\n    ".join(
                        script(b, scratch(b, tmp)))))
                else:
                    ok, text = run(b, root, tmp, a.timeout)
                    failed += not ok
                    print("%s %s: %s" % ("PASS" if ok else "FAIL", b.where,
                                         text), flush=True)
    except FlapFoamError as e:
        sys.exit("doc_commands: %s" % e)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(run_tool(main))
