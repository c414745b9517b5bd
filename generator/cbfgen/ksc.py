"""The Kaitai Struct compiler, as cbfgen finds and runs it: Node.js (`node` on PATH) with the npm
package kaitai-struct-compiler 0.11 where Node resolves it from the driver (ksc_driver.js, shipped
in the wheel): a node_modules folder above the driver (this repository's, after `npm ci`) or one
named by NODE_PATH (e.g. `npm install --prefix ~/ksc kaitai-struct-compiler@0.11.0` and
NODE_PATH=~/ksc/node_modules). The npm build is an API only; the driver compiles the .ksy with it."""

from __future__ import annotations

import os
import shutil
import subprocess
from dataclasses import dataclass
from pathlib import Path

DRIVER = Path(__file__).resolve().parent / "emit" / "kaitai" / "ksc_driver.js"
VERSION = "0.11"  # the compiler's release line the .ksy and the runtimes are pinned to
LANGS = ("python", "javascript", "java", "go")  # as mk/kaitai.mk compiles them (KAITAI_LANGS)


@dataclass(frozen=True)
class Ksc:
    node: str
    version: str


class KscMissing(Exception):
    """What is missing to compile the Kaitai parsers: one line, exit 2."""


def find() -> Ksc:
    node = shutil.which("node")
    if node is None:
        raise KscMissing(f"the Kaitai parsers need Node.js (node on PATH) with the npm package "
                         f"kaitai-struct-compiler {VERSION}; or leave them out with --no-ksc")
    probe = "process.stdout.write(require('kaitai-struct-compiler/package.json').version)"
    res = subprocess.run([node, "-e", probe], cwd=DRIVER.parent, capture_output=True, text=True, env=dict(os.environ))
    if res.returncode != 0:
        raise KscMissing(f"the Kaitai parsers need the npm package kaitai-struct-compiler {VERSION}, which node "
                         f"does not find (install it, e.g. npm install --prefix DIR kaitai-struct-compiler@"
                         f"{VERSION}.0, and set NODE_PATH=DIR/node_modules); or leave them out with --no-ksc")
    version = res.stdout.strip()
    if not version.startswith(VERSION + "."):
        raise KscMissing(f"kaitai-struct-compiler {version} found; the Kaitai parsers need {VERSION}")
    return Ksc(node, version)


def compile_parsers(ksc: Ksc, out: Path) -> None:
    """Compile out/kaitai/cbf.ksy.json to the parsers in out/kaitai/<lang>/ (the driver writes them)."""
    ksy = out / "kaitai" / "cbf.ksy.json"
    res = subprocess.run([ksc.node, str(DRIVER), str(ksy), str(out / "kaitai"), *LANGS], capture_output=True,
                         text=True)
    if res.returncode != 0:
        detail = " ".join((res.stderr or res.stdout).split())[:300]
        raise KscMissing(f"kaitai-struct-compiler failed on {ksy}: {detail}")
