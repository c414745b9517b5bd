"""A revision's new command reaches the workbench page (issue 34, done-when): the page is generated from
the spec like every binding. The drill's fixture that adds a command (tests/revisions/new_command.yaml)
revises the spec alone; the page written for it (no browser, no binding rebuilt: the module's bytes are
the page's payload, not read here) carries the command in its layout data, with its arguments, and the
check the fixture adds. Names are derived from the two specs, none written here."""

from __future__ import annotations

import json
import re
from pathlib import Path

from revisions import drill

from cbfgen.emit.docs import workbench
from cbfgen.loader import load

REPO = Path(__file__).resolve().parents[1]
_DATA = re.compile(r'<script id="cbf-data" type="application/json">(.*?)</script>', re.S)


def test_a_new_command_of_the_drill_appears_in_the_workbench_page(tmp_path: Path) -> None:
    base = load(REPO / drill.SPEC)
    fx = drill.load_fixture(drill.HERE / "new_command.yaml")
    revised = load(drill.revised_spec(fx, REPO / drill.SPEC, tmp_path))
    added = {c.name for c in revised.commands} - {c.name for c in base.commands}
    new_checks = {k.id for k in revised.checks} - {k.id for k in base.checks}
    assert added and new_checks
    text = workbench.page(revised, b"\0asm")
    m = _DATA.search(text)
    assert m is not None
    data = json.loads(m.group(1).replace("<\\/", "</"))
    commands = {c["name"]: c for c in data["layouts"]["commands"]}
    for name in added:
        spec_cmd = next(c for c in revised.commands if c.name == name)
        assert name in commands, f"{name} is not in the page's layouts"
        assert [[a["name"] for a in lay["args"]] for lay in commands[name]["layouts"]] == \
            [[a.name for a in lay.args] for lay in spec_cmd.layouts]
    assert new_checks <= set(data["checks"])
    # and the unrevised page does not carry it
    old = json.loads(_DATA.search(workbench.page(base, b"\0asm")).group(1).replace("<\\/", "</"))  # type: ignore[union-attr]
    assert not added & {c["name"] for c in old["layouts"]["commands"]}
