"""The C binding used from outside this repository (issue 14): `make install PREFIX=...`
installs cbf.h, cbf-c and cbf.pc, and a consumer in a temporary folder compiles with
`pkg-config --cflags --libs cbf` alone, following the header's own usage block."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

import cbf
from cbf import tables as T

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
HAVE_TOOLS = all(shutil.which(t) for t in ("make", "gcc", "pkg-config"))


def _usage_block() -> str:
    """The reader loop the header documents, taken from the header itself."""
    text = (REPO / "generated" / "c" / "cbf.h").read_text(encoding="utf-8")
    start = text.index(" * Print the commands of a file")
    lines = text[start:].split("\n")[2:]
    code = []
    for line in lines:
        if not line.startswith(" *     "):
            break
        code.append(line[len(" *     "):])
    return "\n".join(code)


@pytest.mark.skipif(not HAVE_TOOLS, reason="needs make, gcc and pkg-config")
def test_install_then_a_consumer_builds_with_pkg_config(tmp_path: Path) -> None:
    prefix = tmp_path / "prefix"
    subprocess.run(["make", "-s", "-C", str(REPO), "install", f"PREFIX={prefix}"], check=True,
                   capture_output=True, text=True)
    assert (prefix / "include" / "cbf.h").read_bytes() == (REPO / "generated" / "c" / "cbf.h").read_bytes()
    assert os.access(prefix / "bin" / "cbf-c", os.X_OK)
    env = dict(os.environ, PKG_CONFIG_PATH=str(prefix / "lib" / "pkgconfig"))
    pc = subprocess.run(["pkg-config", "--modversion", "cbf"], env=env, capture_output=True, text=True, check=True)
    assert pc.stdout.strip() == cbf.__version__
    flags = subprocess.run(["pkg-config", "--cflags", "--libs", "cbf"], env=env, capture_output=True, text=True,
                           check=True).stdout.split()
    consumer = tmp_path / "consumer"
    consumer.mkdir()
    (consumer / "main.c").write_text(
        "#include <stdio.h>\n#include <stdlib.h>\n#define CBF_IMPLEMENTATION\n#include <cbf.h>\n"
        "int main(int argc, char **argv) {\n"
        "    static uint8_t buf[1 << 21];\n"
        "    FILE *f = fopen(argv[1], \"rb\");\n"
        "    size_t len;\n"
        "    if (argc < 2 || !f) return 3;\n"
        "    len = fread(buf, 1, sizeof buf, f);\n"
        "    fclose(f);\n"
        "    {\n" + _usage_block() + "\n    return rc == 0 ? 0 : 1;\n    }\n}\n", encoding="utf-8")
    exe = consumer / "consumer"
    subprocess.run(["gcc", "-std=c99", "-Wall", "-Werror", "-o", str(exe), str(consumer / "main.c"), *flags],
                   cwd=consumer, check=True, capture_output=True, text=True)
    golden = next(p for p in sorted(GOLDEN.glob("valid.*.cbf")) if len(cbf.decode(p.read_bytes()).records) > 3)
    out = subprocess.run([str(exe), str(golden)], capture_output=True, text=True, check=True).stdout
    expected = [f"{i} {T.BY_CODE[r.code].name}" for i, r in enumerate(cbf.decode(golden.read_bytes()).records)]
    assert out.splitlines() == expected
    assert re.search(r"SPDX-License-Identifier: \S+", (prefix / "include" / "cbf.h").read_text(encoding="utf-8"))
