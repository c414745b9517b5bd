"""The spec checks itself: broken variants are refused with file, YAML line and rule.

Each variant is an edit of the parsed spec (not of its text), and the
expected message and line are read from the model and from the variant's
YAML nodes, so the tests hold under any legitimate revision of the spec.
"""

from __future__ import annotations

import copy
import re
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
import yaml
from conftest import YAML_LOADER

from cbfgen.loader import SpecError, load

SPEC_PATH = Path(__file__).resolve().parents[1] / "spec" / "cbf.yaml"
TEXT = SPEC_PATH.read_text(encoding="utf-8")
RAW: dict[str, Any] = yaml.load(TEXT, Loader=YAML_LOADER)
SPEC = load(SPEC_PATH)


def _variant(tmp: Path, edit: Callable[[dict[str, Any]], None]) -> tuple[Path, str]:
    doc = copy.deepcopy(RAW)
    edit(doc)
    text = yaml.safe_dump(doc, sort_keys=False, width=1000)
    p = tmp / "cbf.yaml"
    p.write_text(text, encoding="utf-8")
    return p, text


def _key_line(text: str, *path: Any) -> int:
    """The 1-based line of the key path[-1] in the mapping at path[:-1] of the YAML text."""
    node = yaml.compose(text)
    for i, step in enumerate(path):
        if isinstance(node, yaml.SequenceNode):
            node = node.value[step]
            continue
        assert isinstance(node, yaml.MappingNode), path[: i + 1]
        for k, v in node.value:
            if k.value == step:
                if i == len(path) - 1:
                    return int(k.start_mark.line) + 1
                node = v
                break
        else:
            raise KeyError(path[: i + 1])
    raise KeyError(path)


def _index(doc_list: list[dict[str, Any]], key: str, value: Any) -> int:
    return next(i for i, x in enumerate(doc_list) if x[key] == value)


def test_the_real_spec_loads() -> None:
    assert [c.name for c in SPEC.commands] == [c["name"] for c in RAW["commands"]]
    assert [c.id for c in SPEC.checks] == [str(c["id"]) for c in RAW["checks"]]
    assert [v.id for v in SPEC.versions] == [v["id"] for v in RAW["versions"]]


def test_arguments_must_add_up(tmp_path: Path) -> None:
    # a layout with a float vector: one element fewer leaves it 4 bytes short
    ci, li, ai = next((ci, li, ai) for ci, c in enumerate(SPEC.commands) for li, lay in enumerate(c.layouts)
                      for ai, a in enumerate(lay.args) if a.is_vector)
    cmd, lay = SPEC.commands[ci], SPEC.commands[ci].layouts[li]

    def edit(doc: dict[str, Any]) -> None:
        doc["commands"][ci]["layouts"][li]["args"][ai]["count"] -= 1

    p, text = _variant(tmp_path, edit)
    with pytest.raises(SpecError) as err:
        load(p)
    line = _key_line(text, "commands", ci, "layouts", li, "size")
    vtext = "/".join("v" + v for v in lay.versions)
    want = f"{cmd.name} {vtext} arguments sum to {lay.size - 4} bytes, declared {lay.size}"
    assert str(err.value).splitlines()[0] == f"{p}:{line}: {want}"  # the first of every problem found
    assert err.value.line == line


def _duplicate_code(doc: dict[str, Any]) -> None:
    doc["commands"][-1]["code"] = doc["commands"][0]["code"]


def test_duplicate_codes_are_refused(tmp_path: Path) -> None:
    p, text = _variant(tmp_path, _duplicate_code)
    first, last = SPEC.commands[0], SPEC.commands[-1]
    want = rf"{last.name}: duplicate code 0x{first.code:02X}, already {first.name}"
    with pytest.raises(SpecError, match=want) as err:
        load(p)
    assert err.value.line == _key_line(text, "commands", len(SPEC.commands) - 1, "code")


def test_duplicate_names_are_refused(tmp_path: Path) -> None:
    def edit(doc: dict[str, Any]) -> None:
        doc["commands"][-1]["name"] = doc["commands"][0]["name"]

    p, _ = _variant(tmp_path, edit)
    with pytest.raises(SpecError, match=f"duplicate command name {SPEC.commands[0].name}"):
        load(p)


def test_header_must_tile_its_size(tmp_path: Path) -> None:
    hid = SPEC.version(SPEC.default_version).header
    h = SPEC.headers[hid]
    i = next(i for i, f in enumerate(h.fields[:-1]) if f.kind == "string" and f.size > 4)
    after = h.fields[i + 1]

    def edit(doc: dict[str, Any]) -> None:
        doc["headers"][hid]["fields"][i]["size"] -= 4

    p, _ = _variant(tmp_path, edit)
    with pytest.raises(SpecError, match=rf"field {after.name}: offset {after.offset} but the fields before end at "
                                        rf"{after.offset - 4}"):
        load(p)


def test_unknown_version_in_a_layout(tmp_path: Path) -> None:
    bad = f"{max(v.major for v in SPEC.versions) + 7}.5"
    cmd = SPEC.commands[-1]

    def edit(doc: dict[str, Any]) -> None:
        doc["commands"][-1]["layouts"][0]["versions"].append(bad)

    p, _ = _variant(tmp_path, edit)
    with pytest.raises(SpecError, match=rf"{cmd.name}: unknown version '{re.escape(bad)}'"):
        load(p)


def test_schema_violations_name_the_line(tmp_path: Path) -> None:
    ci = len(RAW["checks"]) - 1

    def edit(doc: dict[str, Any]) -> None:
        doc["checks"][ci]["severity"] = "fatal"

    p, text = _variant(tmp_path, edit)
    with pytest.raises(SpecError, match=rf"schema: checks/{ci}/severity: 'fatal' is not one of") as err:
        load(p)
    assert err.value.line == _key_line(text, "checks", ci, "severity")


def test_duplicate_yaml_keys(tmp_path: Path) -> None:
    # A duplicate key cannot be built as a mapping: repeat the line of meta.id in the text.
    line = _key_line(TEXT, "meta", "id")
    lines = TEXT.splitlines(keepends=True)
    lines.insert(line, lines[line - 1])
    p = tmp_path / "cbf.yaml"
    p.write_text("".join(lines), encoding="utf-8")
    with pytest.raises(SpecError, match="duplicate key 'id'") as err:
        load(p)
    assert err.value.line == line + 1


def test_a_check_naming_a_missing_argument(tmp_path: Path) -> None:
    check = next(c for c in SPEC.checks if c.targets)
    ci = _index(RAW["checks"], "id", check.id)
    target = check.targets[0]
    bad = target.args[0] + "_drill"

    def edit(doc: dict[str, Any]) -> None:
        doc["checks"][ci]["targets"][0]["args"][0] = bad

    p, _ = _variant(tmp_path, edit)
    with pytest.raises(SpecError, match=f"{target.command}: check {check.id} names '{bad}', which no layout has"):
        load(p)


def test_generator_refuses_a_bad_spec(tmp_path: Path) -> None:
    from cbfgen.__main__ import main

    p, _ = _variant(tmp_path, _duplicate_code)
    assert main(["--spec", str(p), "--out", str(tmp_path / "out")]) == 2
    assert not (tmp_path / "out").exists()
