"""The judge of a near-miss spec (tests/test_near_miss.py): refused by the loader with a line, or
generated, compiled and agreed on by every binding.

Accepted specs are generated into a temporary folder by every emitter (the Python package, the C
header and testee, the .ksy, the docs: cbfgen's main() in this process, --no-ksc), ksc compiles the .ksy
to every Kaitai parser cbfgen compiles (ksc_driver.js in one node process for all examples:
tests/ksc_serve.py), the C testee is compiled (gcc -O0: the sanitizer build is `make c-build`'s),
and the bindings answer the conformance protocol on the golden files: Python and C must report the same
findings (check, severity, record, offset) and the same decode outcome on every file, and the Kaitai
parser must decode every file Python finds valid.
Golden expectations are not asked: a near-miss spec changes what a file means.
"""

from __future__ import annotations

import atexit
import json
import os
import subprocess
import sys
from collections import Counter
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import ksc_serve
from conftest import REPO, cbfgen_here, dump_yaml

from cbfgen.loader import SpecError, SpecErrors, load

GOLDEN = sorted(p for p in (REPO / "conformance" / "golden").glob("*.cbf") if p.stat().st_size <= 4096)


@dataclass(frozen=True)
class Verdict:
    refused: bool
    problems: tuple[str, ...] = ()


def write_spec(doc: dict[str, Any], folder: Path) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "cbf.yaml"
    path.write_text(dump_yaml(doc, sort_keys=False, width=1000, allow_unicode=True), encoding="utf-8")
    return path


def judge(doc: dict[str, Any], folder: Path) -> Verdict:
    """Refused with a line for every problem, or agreed on by every binding (AssertionError else)."""
    path = write_spec(doc, folder)
    nlines = len(path.read_text(encoding="utf-8").splitlines())
    try:
        load(path)
    except SpecError as exc:
        problems = exc.problems if isinstance(exc, SpecErrors) else ((exc.line, exc.message),)
        for line, message in problems:
            assert 1 <= line <= nlines and message, (line, message)
        text = str(exc).splitlines()
        assert text and all(t.startswith(f"{path}:") for t in text), text
        return Verdict(True, tuple(text))
    agree(path, folder / "out")
    return Verdict(False)


def _run(cmd: list[str], **kw: Any) -> subprocess.CompletedProcess[str]:
    done = subprocess.run(cmd, capture_output=True, text=True, check=False, **kw)
    assert done.returncode == 0, f"{' '.join(cmd)} exited {done.returncode}:\n{done.stderr[-3000:]}"
    return done


def _ask(cmd: list[str], requests: list[dict[str, Any]], env: dict[str, str] | None = None) -> list[dict[str, Any]]:
    text = "".join(json.dumps(r) + "\n" for r in [*requests, {"op": "quit"}])
    done = _run(cmd, input=text, env={**os.environ, **(env or {})}, cwd=REPO)
    answers = [json.loads(line) for line in done.stdout.splitlines() if line.strip()]
    assert len(answers) == len(requests), (cmd, len(answers), len(requests), done.stderr[-2000:])
    return answers


def _findings(answer: dict[str, Any]) -> Counter[tuple[Any, ...]]:
    return Counter((f["check"], f["severity"], f["record"], f["offset"]) for f in answer.get("findings", []))


_KSC: list[ksc_serve.KscServer] = []


def _ksc() -> ksc_serve.KscServer | None:
    """The process's ksc server (started by the first example that needs it), or None without node and ksc."""
    if not _KSC and ksc_serve.available():
        _KSC.append(ksc_serve.KscServer())
        atexit.register(close)
    return _KSC[0] if _KSC else None


def close() -> None:
    """Stop the ksc server (a test module's teardown: its CPU time is then counted, tests/cpu_budget.py)."""
    while _KSC:
        _KSC.pop().close()


def generate(spec: Path, out: Path) -> None:
    """`cbfgen --spec spec --out out` (every emitter, every Kaitai parser); AssertionError naming what failed."""
    code, _, err = cbfgen_here("--spec", str(spec), "--out", str(out), "--no-ksc")
    assert code == 0, f"cbfgen --spec {spec} exited {code}:\n{err[-3000:]}"
    ksc = _ksc()
    if ksc is not None:
        error = ksc.compile(out / "kaitai" / "cbf.ksy.json", out / "kaitai")
        assert error is None, f"kaitai-struct-compiler failed on {out / 'kaitai' / 'cbf.ksy.json'}: {error}"


def agree(spec: Path, out: Path) -> None:
    generate(spec, out)
    testee = out / "cbf_testee"
    _run(["gcc", "-std=c99", "-O0", "-o", str(testee), str(out / "c" / "cbf_testee.c"), "-lm"])
    requests: list[dict[str, Any]] = []
    for g in GOLDEN:
        requests.append({"op": "decode", "file": str(g)})
        requests.append({"op": "validate", "file": str(g), "profile": "default", "part_number": None,
                         "cutters": None, "machine": None})
    py = _ask([sys.executable, str(REPO / "conformance" / "testees" / "python" / "testee.py")], requests,
              {"PYTHONPATH": str(out / "python")})
    c = _ask([str(testee)], requests)
    valid: list[dict[str, Any]] = []
    decoded: dict[str, bool] = {}  # a file Python cannot decode is not valid, whatever checks a scope leaves out
    for req, a, b in zip(requests, py, c, strict=True):
        name = Path(req["file"]).name
        if req["op"] == "decode":
            decoded[name] = bool(a.get("ok"))
            assert a.get("ok") == b.get("ok"), (name, "decode", a.get("error"), b.get("error"))
            if not a.get("ok"):
                assert (a["error"]["kind"], a["error"]["offset"]) == (b["error"]["kind"], b["error"]["offset"]), name
        else:
            assert _findings(a) == _findings(b), (name, "python", _findings(a), "c", _findings(b))
            if a.get("ok") and not a.get("findings") and decoded.get(name, True):
                valid.append({"op": "decode", "file": req["file"]})
    parser = out / "kaitai" / "python" / "cbf_kaitai" / "cbf.py"
    # (a spec scoping a check Kaitai states as a `valid:` rule is refused by the loader: registry kaitai=True)
    if parser.exists() and valid:
        k = _ask([sys.executable, str(out / "kaitai" / "python" / "testee.py")], valid,
                 {"PYTHONPATH": str(out / "kaitai" / "python")})
        for req, ans in zip(valid, k, strict=True):
            assert ans.get("ok") or ans.get("skipped"), (Path(req["file"]).name, "kaitai", ans)
