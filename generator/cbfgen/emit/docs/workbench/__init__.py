"""The workbench page of the published site (issue 34, point 3): choose or drop a .cbf file and see what
the C engine says of it, in the browser, with nothing installed and nothing sent anywhere.

The page runs build/wasm/cbf-c.wasm (the c-wasm binding: the C engine's own files, mk/wasm.mk) as a WASI
command, through a small in-page WASI layer (workbench.js) over an in-memory file system: the verdict
and findings are exactly what `cbf-c validate` prints, the records table is `cbf-c dump`, the toolpath
(top, side and 3D views) is `cbf-c dump --path` (each motion as the engine's geometry turns it). A file the
engine takes for CUT text (`cbf-c sniff`) is encoded by it (`cbf-c encode`) and shown as that CBF, with a note
and a download link (a blob URL); a refusal shows the engine's one line. What the page
knows of the format beyond that comes from the spec, as data: the byte layouts (the same
layouts.json the conformance kit ships), the profiles, and each check's anchor in the document.

The module is inlined (base64 in a classic script): from file:// Chromium refuses fetch() of a .wasm.
A Content-Security-Policy forbids every network request (default-src 'none'); the page's own script
and style are inline, and compiling WebAssembly needs 'wasm-unsafe-eval'.

    python -m cbfgen.emit.docs.workbench --spec spec/cbf.yaml --wasm build/wasm/cbf-c.wasm --out DIR
writes DIR/workbench.html (the built site's folder: the links into the document are index.html#...).
"""

from __future__ import annotations

import argparse
import base64
import html
import json
from pathlib import Path
from typing import Any

from ....loader import load
from ....model import Spec, ident
from ...python import layouts_data

HERE = Path(__file__).resolve().parent
PAGE = "workbench.html"
# Every network request is refused: no connect-src, img-src, font-src ... beyond 'none' (default-src);
# data: images only (none today); inline script and style (the page is one file), WebAssembly compile.
CSP = ("default-src 'none'; script-src 'unsafe-inline' 'wasm-unsafe-eval'; style-src 'unsafe-inline'; "
       "img-src data:; base-uri 'none'; form-action 'none'")


def _anchor(text: str) -> str:
    """The document's anchor of a check or clause id (the docs emitter's rule: cbfgen.model.ident)."""
    return ident(text).replace("_", "-")


def page_data(spec: Spec) -> dict[str, Any]:
    """What the page knows of the format, all from the spec."""
    return {
        "title": spec.meta["title"],
        "spec": f"{spec.meta['part_number']} rev {spec.meta['revision']}",
        "layouts": layouts_data(spec),
        "profiles": [{"id": p.id, "doc": p.doc} for p in spec.profiles],
        # the toolpath is the engine's (cbf-c dump --path); the commands that turn cutting on or off
        # (spec/cbf.yaml's `sets`) tell cutting from moving
        "cutting": {c.name: c.sets["cutting"] for c in spec.commands if c.sets and "cutting" in c.sets},
        "checks": {k.id: {"href": f"index.html#check-{_anchor(k.id)}", "severity": k.severity,
                          "clause": k.clause, "text": k.text} for k in spec.checks},
    }


def _script_json(data: Any) -> str:
    """JSON that cannot end its <script> element early."""
    return json.dumps(data, separators=(",", ":"), sort_keys=True).replace("</", "<\\/")


def page(spec: Spec, wasm: bytes) -> str:
    template = (HERE / "workbench.html").read_text(encoding="utf-8")
    parts = {
        "@CSP@": CSP,
        "@TITLE@": html.escape(f"Workbench: check a cut file ({spec.meta['part_number']} rev {spec.meta['revision']})"),
        "@CSS@": (HERE / "workbench.css").read_text(encoding="utf-8"),
        "@DATA@": _script_json(page_data(spec)),
        "@WASM@": base64.b64encode(wasm).decode("ascii"),
        "@JS@": (HERE / "workbench.js").read_text(encoding="utf-8").replace("</", "<\\/"),
    }
    for key, value in parts.items():
        assert template.count(key) == 1, key
        template = template.replace(key, value)
    return template


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="cbfgen-docs-workbench", description="Write the workbench page.")
    ap.add_argument("--spec", default="spec/cbf.yaml")
    ap.add_argument("--wasm", type=Path, required=True, help="cbf-c.wasm (make wasm-build)")
    ap.add_argument("--out", type=Path, required=True, help="the built site's folder")
    a = ap.parse_args(argv)
    a.out.mkdir(parents=True, exist_ok=True)
    target = a.out / PAGE
    tmp = target.with_suffix(".html.tmp")
    tmp.write_text(page(load(a.spec), a.wasm.read_bytes()), encoding="utf-8")
    tmp.replace(target)
    print(f"workbench: {target} ({target.stat().st_size:,} bytes)")
    return 0


