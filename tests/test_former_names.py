"""Former names (issue 25, point 6): a command renamed with its old name kept in `former_names`
still reads under the old name in CUT and JSON, writers write the new name, and the C header and
the Python package keep the old name as a deprecated alias.

Read from the spec: every former name of every command, each tried on the valid golden files
holding that command. The spec of rev 03 renames nothing (the tests then have no case); the
revision drill's rename fixture adds one, and these tests run in the drill's copy of the tree."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import cbf
from cbf import tables as T
from cbf.cut import keyword

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
FORMER = [(old, str(c["name"])) for c in T.SPEC["commands"] for old in c.get("former_names", ())]


def _holding(name: str) -> list[Path]:
    code = T.BY_NAME[name].code
    return [p for p in sorted(GOLDEN.glob("valid.*.cbf"))
            if p.stat().st_size < 1 << 16 and any(r.code == code for r in cbf.decode(p.read_bytes()).records)]


@pytest.mark.parametrize(("old", "new"), FORMER)
def test_the_old_cut_keyword_and_json_name_read_as_the_new_command(old: str, new: str) -> None:
    files = _holding(new)
    assert files, f"no valid golden file holds {new}: nothing shows the former name {old} reads"
    new_kw = keyword(T.BY_NAME[new])
    old_kw = old.lower() if T.CUT["keyword_case"] == "lower" else old
    for path in files:
        model = cbf.decode(path.read_bytes())
        want = cbf.encode(model)
        text = cbf.to_cut(model)
        assert re.search(rf"^ *{re.escape(new_kw)}\b", text, re.M), "the writer writes the new keyword"
        as_old = re.sub(rf"^( *){re.escape(new_kw)}\b", rf"\g<1>{old_kw}", text, flags=re.M)
        assert as_old != text
        assert cbf.encode(cbf.from_cut(as_old)) == want, path.name
        doc = cbf.to_canonical(model)
        for r in doc["records"]:
            if r.get("command") == new:
                r["command"] = old
        back = cbf.from_canonical(doc)
        assert cbf.encode(back) == want, path.name
        names = [r.get("command") for r in cbf.to_canonical(back)["records"]]
        assert old not in names and new in names  # written as the new name


@pytest.mark.parametrize(("old", "new"), FORMER)
def test_the_bindings_keep_the_old_name_as_an_alias(old: str, new: str) -> None:
    assert cbf.CommandCode[old] is cbf.CommandCode[new]
    header = (REPO / "generated" / "c" / "cbf.h").read_text(encoding="utf-8")
    assert re.search(rf"^#define CBF_CMD_{old} CBF_CMD_{new}$", header, re.M), f"cbf.h has no alias CBF_CMD_{old}"
