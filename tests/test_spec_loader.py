"""The spec checks itself: broken variants are refused with file, YAML line and rule."""

from __future__ import annotations

from pathlib import Path

import pytest

from cbfgen.loader import SpecError, load

SPEC = Path(__file__).resolve().parents[1] / "spec" / "cbf.yaml"
TEXT = SPEC.read_text(encoding="utf-8")


def _variant(tmp: Path, old: str, new: str, count: int = 1) -> tuple[Path, str]:
    assert TEXT.count(old) >= count, old
    text = TEXT.replace(old, new, count)
    p = tmp / "cbf.yaml"
    p.write_text(text, encoding="utf-8")
    return p, text


def _line_of(text: str, needle: str, nth: int = 1) -> int:
    pos = -1
    for _ in range(nth):
        pos = text.index(needle, pos + 1)
    return text[:pos].count("\n") + 1


def test_the_real_spec_loads() -> None:
    spec = load(SPEC)
    assert len(spec.commands) == 27
    assert {c.id for c in spec.checks} >= {"6.1.1", "6.2.1", "6.4.5", "7.2.3.1"}


def test_arguments_must_add_up(tmp_path: Path) -> None:
    p, text = _variant(tmp_path, "{name: end, type: f4, count: 3, unit: mm, doc: End point.}",
                       "{name: end, type: f4, count: 2, unit: mm, doc: End point.}")
    with pytest.raises(SpecError) as err:
        load(p)
    line = _line_of(text, "size: 24", nth=text[: text.index("name: LINE\n")].count("size: 24") + 1)
    assert str(err.value) == f"{p}:{line}: LINE v1.x/v2.x/v3.0/v4.0 arguments sum to 20 bytes, declared 24"
    assert err.value.line == line


def test_duplicate_codes_are_refused(tmp_path: Path) -> None:
    p, text = _variant(tmp_path, "code: 0x5A", "code: 0xB6")
    with pytest.raises(SpecError, match=r"COMMENT: duplicate code 0xB6, already LINE") as err:
        load(p)
    assert err.value.line == _line_of(text, "code: 0xB6", nth=2)


def test_duplicate_names_are_refused(tmp_path: Path) -> None:
    p, _ = _variant(tmp_path, "  - name: COMMENT\n", "  - name: LINE\n")
    with pytest.raises(SpecError, match="duplicate command name LINE"):
        load(p)


def test_header_must_tile_128_bytes(tmp_path: Path) -> None:
    p, text = _variant(tmp_path, "        type: str\n        size: 34\n", "        type: str\n        size: 30\n")
    with pytest.raises(SpecError, match=r"field command_count: offset 122 but the fields before end at 118"):
        load(p)


def test_unknown_version_in_a_layout(tmp_path: Path) -> None:
    p, _ = _variant(tmp_path, 'versions: ["2.x", "3.0"]', 'versions: ["2.x", "3.5"]')
    with pytest.raises(SpecError, match=r"HELIX: unknown version '3.5'"):
        load(p)


def test_schema_violations_name_the_line(tmp_path: Path) -> None:
    p, text = _variant(tmp_path, "    severity: warning\n", "    severity: fatal\n")
    with pytest.raises(SpecError, match=r"schema: checks/\d+/severity: 'fatal' is not one of") as err:
        load(p)
    assert err.value.line == _line_of(text, "severity: fatal")


def test_duplicate_yaml_keys(tmp_path: Path) -> None:
    p, _ = _variant(tmp_path, "  id: cbf\n", "  id: cbf\n  id: cbf2\n")
    with pytest.raises(SpecError, match="duplicate key 'id'"):
        load(p)


def test_a_check_naming_a_missing_argument(tmp_path: Path) -> None:
    p, _ = _variant(tmp_path, "targets: [{command: SPEED, args: [speed]}]", "targets: [{command: SPEED, args: [sped]}]")
    with pytest.raises(SpecError, match="SPEED: check speed_positive names 'sped', which no layout has"):
        load(p)


def test_generator_refuses_a_bad_spec(tmp_path: Path) -> None:
    from cbfgen.__main__ import main

    p, _ = _variant(tmp_path, "code: 0x5A", "code: 0xB6")
    assert main(["--spec", str(p), "--out", str(tmp_path / "out")]) == 2
    assert not (tmp_path / "out").exists()
