"""`cbfgen diff --witness` (issue 37, point 5): every wire-breaking drill fixture gets a verified witness,
and the witnesses are golden cases: their hex assembles to their .cbf under the revised spec, and the
conformance runner's own rules pass them on NEW's codec and fail them on OLD's.

Cheap by design: one generated Python codec per spec (the unrevised one shared by every fixture),
imported side by side and run in-process (no subprocess, no other binding). The full drill
(`make revision-drill`) runs the real thing; `make witness-drill` writes every fixture's witnesses.
"""

from __future__ import annotations

import base64
import json
from pathlib import Path
from typing import Any

import pytest
from revisions import drill

from cbfgen import witness
from cbfgen.diff import EXIT_BAD_INPUT, EXIT_UNVERIFIED, diff
from cbfgen.loader import load
from conformance.assembler import assemble_text
from conformance.runner.run import load_cases, run_case

REPO = Path(__file__).resolve().parents[1]
SPEC = REPO / "spec" / "cbf.yaml"
# The fixtures that apply to this tree's spec (drill.applicable: one whose precondition a revision already met is
# left out, as the drill leaves it out).
WIRE = [fx.path for fx in drill.applicable() if fx.breaking]
TEXT = [fx.path for fx in drill.applicable() if fx.text_breaking and not fx.breaking]


@pytest.fixture(scope="module")
def old_codec(tmp_path_factory: pytest.TempPathFactory) -> Any:
    return witness.codec(load(SPEC), tmp_path_factory.mktemp("old"), "cbf_test_witness_old")


def _codecs(path: Path, tmp: Path, old_codec: Any) -> witness.Codecs:
    new_path = drill.revised_spec(drill.load_fixture(path), SPEC, tmp / "spec")
    new = load(new_path)
    return witness.Codecs(SPEC, new_path, load(SPEC), new, old_codec,
                          witness.codec(new, tmp / "new", f"cbf_test_witness_{path.stem}"))


class _InProcess:
    """A testee of PROTOCOL.md answered by a codec module in this process (what the runner asks)."""

    def __init__(self, cbf: Any) -> None:
        self.cbf = cbf

    def ask(self, req: dict[str, Any]) -> dict[str, Any]:
        cbf = self.cbf
        data = Path(req["file"]).read_bytes() if "file" in req else b""
        try:
            if req["op"] == "decode":
                return {"ok": True, "result": cbf.to_canonical(cbf.decode(data))}
            if req["op"] == "validate":
                return {"ok": True, "findings": [f.as_dict() for f in cbf.validate(data, profile=req["profile"])]}
            out = cbf.encode(cbf.from_canonical(req["json"]), keep_stored=bool(req.get("keep_stored")))
            return {"ok": True, "bytes": base64.b64encode(out).decode("ascii")}
        except cbf.CbfError as exc:
            return {"ok": False, "error": {"kind": exc.kind, "offset": exc.offset, "message": str(exc)}}


@pytest.mark.parametrize("path", WIRE, ids=[p.stem for p in WIRE])
def test_every_wire_breaking_fixture_gets_a_verified_witness(path: Path, tmp_path: Path, old_codec: Any) -> None:
    cx = _codecs(path, tmp_path, old_codec)
    changes = diff(cx.old, cx.new).changes
    found, missing = witness.witnesses(changes, cx)
    assert not missing, [m.kind for m in missing]
    assert len(found) == sum(c.breaking for c in changes) > 0
    out = tmp_path / "witness"
    witness.write(found, [], out)
    cases = {c.name: c for c in load_cases(out)}
    assert set(cases) == {w.name for w in found}
    for w in found:
        assert w.says and w.change.kind in w.hex.splitlines()[0]
        # a check's change is shown by that check's findings (record_crc: NEW's 9.x on a wrong CRC)
        assert witness._shows_check(witness._check_of(w.change), w.old, w.new), w.says
        # the hex is golden-style: the golden assembler makes the .cbf of it under the revised spec
        assert assemble_text((out / f"{w.name}.hex").read_text(encoding="utf-8"), w.name, spec=cx.new_path) == w.data
        # a golden case of the revised spec: NEW's codec passes it, OLD's does not
        assert run_case(_InProcess(cx.new_codec), cases[w.name]).status == "pass", w.name
        old = run_case(_InProcess(cx.old_codec), cases[w.name])
        assert old.status == "fail", (w.name, old)


@pytest.mark.parametrize("path", TEXT, ids=[p.stem for p in TEXT])
def test_a_text_breaking_fixture_gets_json_old_refuses(path: Path, tmp_path: Path, old_codec: Any) -> None:
    cx = _codecs(path, tmp_path, old_codec)
    texts = [t for c in diff(cx.old, cx.new).changes if c.text_breaking for t in [witness.text_witness(c, cx)] if t]
    assert texts
    for t in texts:
        assert "json" in t and "cut" in t, t  # a rename shows in both forms
        cx.new_codec.from_canonical(json.loads(t["json"]["text"]))
        cx.new_codec.from_cut(t["cut"]["text"])
        with pytest.raises(cx.old_codec.CbfError):
            cx.old_codec.from_canonical(json.loads(t["json"]["text"]))
        with pytest.raises(cx.old_codec.CbfError):
            cx.old_codec.from_cut(t["cut"]["text"])


def test_an_unverified_witness_is_refused(tmp_path: Path, old_codec: Any) -> None:
    """With the same codec on both sides no candidate differs: nothing is written, exit 4."""
    path = WIRE[0]
    cx = _codecs(path, tmp_path, old_codec)
    same = witness.Codecs(cx.old_path, cx.new_path, cx.old, cx.new, cx.new_codec, cx.new_codec)
    found, missing = witness.witnesses(diff(cx.old, cx.new).changes, same)
    assert not found and missing
    assert EXIT_UNVERIFIED not in (0, 1, 2, 3)


def test_a_witness_folder_that_is_a_file_is_bad_input(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "f").write_text("", encoding="utf-8")
    assert witness.run((), SPEC, SPEC, tmp_path / "f") == EXIT_BAD_INPUT
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "not a folder" in err
