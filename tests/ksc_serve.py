"""One node process compiling many .ksy files, as `cbfgen` (cbfgen.ksc.compile_parsers) would one a process.

Each `cbfgen` run with the kaitai emitter starts node twice (the version probe, then ksc_driver.js) and ksc
loads again each time: about 1.3 CPU s for the four parsers, of which a warm ksc needs 0.3. The tests that
generate many specs (tests/near_miss.py, tests/test_registry.py) generate with --no-ksc and hand the .ksy to
this server instead: it runs ksc_driver.js's own compileTo (the files, the Java package and the Go package
line exactly as the driver writes them) for each request, and answers its error as the driver prints it.
"""

from __future__ import annotations

import json
import shutil
import subprocess
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path

from cbfgen import ksc as ksc_mod

REPO = Path(__file__).resolve().parents[1]

SERVER = r"""
'use strict';
const { compileTo, describe } = require(process.argv[1]);
const readline = require('readline');
const rl = readline.createInterface({ input: process.stdin });
let queue = Promise.resolve();
rl.on('line', (line) => {
  queue = queue.then(async () => {
    const job = JSON.parse(line);
    let error = null;
    try {
      await compileTo(job.ksy, job.out, job.langs, () => {});
    } catch (e) {
      error = describe(e);
    }
    process.stdout.write(JSON.stringify({ error }) + '\n');
  });
});
"""


def available() -> bool:
    return shutil.which("node") is not None and (REPO / "node_modules" / "kaitai-struct-compiler").exists()


class KscServer:
    """ksc_driver.js's compileTo in one node process; compile() waits for each answer."""

    def __init__(self) -> None:
        node = shutil.which("node")
        assert node is not None
        # run from the driver's folder so that node resolves kaitai-struct-compiler as the driver does
        self.proc = subprocess.Popen([node, "-e", SERVER, str(ksc_mod.DRIVER)], cwd=ksc_mod.DRIVER.parent,
                                     stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True, encoding="utf-8")

    def compile(self, ksy: Path, out: Path, langs: Sequence[str] = ksc_mod.LANGS) -> str | None:
        """Compile ksy's parsers into out/<lang>/ as `node ksc_driver.js ksy out langs...`; its error or None."""
        assert self.proc.stdin is not None and self.proc.stdout is not None
        self.proc.stdin.write(json.dumps({"ksy": str(ksy), "out": str(out), "langs": list(langs)}) + "\n")
        self.proc.stdin.flush()
        line = self.proc.stdout.readline()
        assert line, f"the ksc server stopped (exit {self.proc.poll()})"
        error: str | None = json.loads(line)["error"]
        return error

    def close(self) -> None:
        assert self.proc.stdin is not None
        self.proc.stdin.close()
        self.proc.wait(timeout=30)


@contextmanager
def server() -> Iterator[KscServer]:
    s = KscServer()
    try:
        yield s
    finally:
        s.close()
