# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam.harness.doc_commands: the blocks of a page, their markers, rewrites
and runs."""

import pytest

from flapfoam.harness import doc_commands as dc
from flapfoam.errors import FlapFoamError

PAGE = """# A page

<!-- test: run; Allrun => Allrun -case {tmp}/r{n}; -cycles \\d+ => -steps 2 -->
```sh
. etc/bashrc
cases/x/Allrun -cycles 20 \\
    -np 2 > log 2>&1 &   # the ascent
# a comment line
echo a#b
```

<!-- test: skip hours of CPU -->
```sh
cases/x/Allrun -level fine
```

```sh
no marker
```
"""


def test_blocks_markers_and_commands():
    b = dc.blocks("p.md", PAGE)
    assert [x.line for x in b] == [4, 13, 17]
    assert b[0].commands == [". etc/bashrc",
                             "cases/x/Allrun -cycles 20 -np 2 > log 2>&1",
                             "echo a#b"]
    assert b[1].marker == "skip hours of CPU"
    assert b[2].marker is None


def test_rewrites_in_order_with_tmp_and_line():
    b = dc.blocks("p.md", PAGE)[0]
    assert dc.script(b, "/T")[1] == \
        "cases/x/Allrun -case /T/r4 -steps 2 -np 2 > log 2>&1"


def test_bad_markers_are_refused():
    b = dc.Block("p.md", 3, "runn")
    with pytest.raises(FlapFoamError, match="p.md:3.*allowed 'run'"):
        dc.rewrites(b)
    b = dc.Block("p.md", 3, "run; a -> b")
    with pytest.raises(FlapFoamError, match="'a -> b' has no '=>'"):
        dc.rewrites(b)


def test_run_passes_fails_and_says_why(tmp_path, capsys, monkeypatch):
    (tmp_path / "etc").mkdir()
    (tmp_path / "etc" / "bashrc").write_text("")
    page = tmp_path / "p.md"
    page.write_text("<!-- test: run; ok => true -->\n```sh\nok\n```\n"
                    "<!-- test: run -->\n```sh\nfalse\ntrue\n```\n"
                    "```sh\nx\n```\n"
                    "<!-- test: run from sub -->\n```sh\ntest -f here\n```\n")
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "here").write_text("")
    monkeypatch.setenv("FLAPFOAM_PROJECT_DIR", str(tmp_path))
    rc = dc.main([str(page), "-tmp", str(tmp_path / "t")])
    out = capsys.readouterr().out.splitlines()
    assert rc == 1
    assert out[0].startswith("PASS p.md:2: 1 command(s)")
    assert out[1].startswith("FAIL p.md:6: exit 1")
    assert out[2].startswith("FAIL p.md:10: a sh block without")
    assert out[3].startswith("PASS p.md:14")


def test_each_page_has_its_own_scratch_folder(tmp_path, capsys, monkeypatch):
    """Two pages that make the same run folder under {tmp} do not meet
    (CI stop 53: two READMEs' {tmp}/hover); a page's blocks share its
    folder, in order, and each block's log lies in it."""
    (tmp_path / "etc").mkdir()
    (tmp_path / "etc" / "bashrc").write_text("")
    for d in ("a", "b"):
        (tmp_path / d).mkdir()
        (tmp_path / d / "README.md").write_text(
            "<!-- test: run; R => {tmp}/hover -->\n```sh\nmkdir R\n```\n"
            "<!-- test: run; R => {tmp}/hover -->\n```sh\ntest -d R\n```\n")
    monkeypatch.setenv("FLAPFOAM_PROJECT_DIR", str(tmp_path))
    monkeypatch.chdir(tmp_path)
    rc = dc.main(["a/README.md", "b/README.md", "-tmp", "t"])
    out = capsys.readouterr().out.splitlines()
    assert rc == 0, out
    assert [o.split(":")[0] for o in out] == ["PASS a/README.md"] * 2 + \
        ["PASS b/README.md"] * 2
    for d in ("a", "b"):
        assert (tmp_path / "t" / (d + "_README.md") / "hover").is_dir()
        assert (tmp_path / "t" / (d + "_README.md") / "log.6").is_file()
