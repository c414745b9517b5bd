"""The C tools' engine on buffers (issue #34, point 1): generated/c/cbf_tools.h validates and dumps bytes in
memory and reads option files from memory, printing through a sink; cbf-c's command line is a shell over it.
A host that is not the command line (here a small C program, later a WebAssembly page) gets from the same
entry points exactly what cbf-c prints, with no file opened by the engine."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest
from c_programs import built

REPO = Path(__file__).resolve().parents[1]
GEN = REPO / "generated" / "c"
GOLDEN = REPO / "conformance" / "golden"

# A host with no file layer of its own in the engine's calls: it reads the file itself, then hands the
# bytes over; the sink collects the text in memory and the host writes it out at the end.
HOST = r"""
#define CBF_IMPLEMENTATION
#define CBF_TOOLS_IMPLEMENTATION
#include "cbf.h"
#include "cbf_tools.h"

static char text[1 << 24];
static size_t ntext;
static char err[1 << 16];
static size_t nerr;

static void to_text(void *user, const char *s, size_t n)
{
    (void)user;
    if (n <= sizeof text - ntext) { memcpy(text + ntext, s, n); ntext += n; }
}

static void to_err(void *user, const char *s, size_t n)
{
    (void)user;
    if (n <= sizeof err - nerr) { memcpy(err + nerr, s, n); nerr += n; }
}

static uint8_t data[CBF_TOOL_MAX_FILE_SIZE + 1u];
static char table[1 << 20];

int main(int argc, char **argv)
{
    cbf_tool_sink sink = { to_text, to_err, NULL };
    cbf_tool_options o;
    const char *why;
    long n;
    int status;
    memset(&o, 0, sizeof o);
    o.max_findings = 0;
    if (argc < 3)
        return 3;
    if (argc == 4) { /* a cutter table, read by the host and handed over as text */
        long t = cbf_tool_read_file(argv[3], (uint8_t *)table, sizeof table, &why);
        if (t < 0 || !cbf_tool_cutters_buffer(argv[3], table, (size_t)t, &o.validate)) {
            fprintf(stderr, "%s\n", cbf_tool_why());
            return 4;
        }
    }
    n = cbf_tool_read_file(argv[2], data, sizeof data, &why);
    if (n < 0)
        return 5;
    status = strcmp(argv[1], "dump") == 0 ? cbf_tool_dump_buffer(argv[2], data, (size_t)n, &sink)
                                          : cbf_tool_validate_buffer(argv[2], data, (size_t)n, &o, &sink);
    fwrite(text, 1, ntext, stdout);
    fwrite(err, 1, nerr, stderr);
    return status;
}
"""


@pytest.fixture(scope="module")
def host(tmp_path_factory: pytest.TempPathFactory) -> Path:
    cc = shutil.which("gcc")
    if cc is None:
        pytest.skip("gcc not installed")
    tmp = tmp_path_factory.mktemp("host")
    src = tmp / "host.c"
    src.write_text(HOST, encoding="utf-8")
    exe = tmp / "host"
    argv = [cc, "-std=c99", "-O1", "-Wall", "-Wextra", "-Werror", "-I", str(GEN), "-o", str(exe), str(src), "-lm"]
    subprocess.run(argv, check=True, capture_output=True)
    return exe


def _cases() -> list[Path]:
    files = sorted(GOLDEN.glob("*.cbf"))
    assert files
    return files


def test_the_engine_on_a_buffer_prints_what_cbf_c_prints(host: Path) -> None:
    """Every golden file: validate and dump through a memory sink give cbf-c's stdout, stderr and status."""
    cbf_c = built("cbf-c")
    for path in _cases():
        for op, extra in (("validate", ["--max-findings", "0"]), ("dump", [])):
            want = subprocess.run([str(cbf_c), op, *extra, str(path)], capture_output=True)
            got = subprocess.run([str(host), op, str(path)], capture_output=True)
            assert (got.returncode, got.stdout, got.stderr) == (want.returncode, want.stdout, want.stderr), (op, path)


def test_not_a_cbf_file_is_one_line_on_the_error_sink(host: Path, tmp_path: Path) -> None:
    """The engine's framing checks (too short; no magic number right, text) come through the sink's err,
    the same line cbf-c says, and nothing on out."""
    cbf_c = built("cbf-c")
    short = tmp_path / "short.cbf"
    short.write_bytes(b"\x00" * 3)
    text = tmp_path / "notes.cbf"
    text.write_bytes(b"x" * 4096)
    for path in (short, text):
        want = subprocess.run([str(cbf_c), "validate", "--max-findings", "0", str(path)], capture_output=True)
        got = subprocess.run([str(host), "validate", str(path)], capture_output=True)
        assert got.returncode == want.returncode == 2
        assert got.stdout == b""
        assert got.stderr == want.stderr and got.stderr.count(b"\n") == 1


def test_a_cutter_table_from_memory(host: Path) -> None:
    """A cutter table handed over as text gives the findings cbf-c gives with --cutters."""
    cbf_c = built("cbf-c")
    tables = sorted(GOLDEN.glob("*.cutters.csv"))
    assert tables
    for table in tables:
        cbf = GOLDEN / table.name.replace(".cutters.csv", ".cbf")
        want = subprocess.run([str(cbf_c), "validate", "--max-findings", "0", "--cutters", str(table), str(cbf)],
                              capture_output=True)
        got = subprocess.run([str(host), "validate", str(cbf), str(table)], capture_output=True)
        assert (got.returncode, got.stdout) == (want.returncode, want.stdout)
        assert b"cutter" in got.stdout  # the table's findings are there
