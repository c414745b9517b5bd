"""`make revision` (conformance/revise.py, issue 37 point 4): a revision that changes how existing golden
cases are judged gets each such case's new expectation proposed as a diff, never written."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import yaml
from conftest import REPO

from conformance import revise
from conformance.runner.compare import findings_difference

GOLDEN = REPO / "conformance" / "golden"


def _copy(tmp: Path, name: str) -> Path:
    for ext in (".cbf", ".expect.yaml"):
        shutil.copy(GOLDEN / f"{name}{ext}", tmp / f"{name}{ext}")
    return tmp / f"{name}.expect.yaml"


def _case_with(pred: object) -> str:
    """A golden case (smallest first) whose expectation pred accepts: the test reads no case by name."""
    for p in sorted(GOLDEN.glob("*.expect.yaml"), key=lambda p: (GOLDEN / p.name.replace(".expect.yaml", ".cbf"))
                    .stat().st_size):
        doc = yaml.safe_load(p.read_text(encoding="utf-8"))
        if pred(doc, p.read_text(encoding="utf-8")):  # type: ignore[operator]
            return p.name[: -len(".expect.yaml")]
    raise AssertionError("no golden case fits")


def test_a_changed_judgement_is_proposed_as_a_diff_and_not_written(tmp_path: Path) -> None:
    """Expectations made stale by hand (a finding dropped from a block-form validate, a command renamed in
    decode_subset) come back as the proposal; the golden files are left as they were."""
    block = _case_with(lambda d, t: "\nvalidate:\n" in t and any(len(v or []) > 1 for v in d["validate"].values()))
    named = _case_with(lambda d, t: any(k.endswith("/command") for k in (d.get("decode_subset") or {})))
    originals = {n: yaml.safe_load((GOLDEN / f"{n}.expect.yaml").read_text(encoding="utf-8")) for n in (block, named)}
    p = _copy(tmp_path, block)
    doc = originals[block]
    profile = next(k for k, v in doc["validate"].items() if len(v or []) > 1)
    text = p.read_text(encoding="utf-8")
    line = next(ln for ln in text.splitlines() if ln.strip().startswith(f"{profile}:"))
    stale_line = line.split(":")[0] + ": " + revise._flow(doc["validate"][profile][1:])
    p.write_text(text.replace(line, stale_line), encoding="utf-8")
    q = _copy(tmp_path, named)
    pointer, command = next((k, v) for k, v in originals[named]["decode_subset"].items() if k.endswith("/command"))
    text = q.read_text(encoding="utf-8")
    renamed = re.sub(rf'({re.escape(pointer)}: *"?){re.escape(command)}\b', rf"\g<1>{command}_FORMERLY", text, count=1)
    assert renamed != text, (named, pointer)  # the name as written, quoted or not
    q.write_text(renamed, encoding="utf-8")
    stale = {x: x.read_text(encoding="utf-8") for x in (p, q)}
    got = revise.proposed(tmp_path)
    assert set(got) == {p, q}
    assert all(x.read_text(encoding="utf-8") == stale[x] for x in (p, q))  # proposed, not written
    fixed = yaml.safe_load(got[p][1])
    assert findings_difference(doc["validate"][profile], fixed["validate"][profile]) is None
    assert {k: v for k, v in fixed.items() if k != "validate"} == {k: v for k, v in doc.items() if k != "validate"}
    assert yaml.safe_load(got[q][1]) == originals[named]
    patch = revise.proposals(tmp_path)
    assert f"+++ b/conformance/golden/{block}.expect.yaml" in patch and f"\n-{stale_line}\n" in patch
    assert revise.proposals(tmp_path / "none") == ""  # no case, nothing proposed
