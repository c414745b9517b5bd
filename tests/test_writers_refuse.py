"""A writer in every binding refuses what the header's version does not have (issue 13 item 12).

A filling writer (Python ``encode`` with ``keep_stored=False``; C ``cbf_encode_record``
and ``cbf_encode_end(fill=1)``) writes a record only when the version lists the
command and one of the command's layouts in that version has the argument size.
Every case comes from the model: the commands a writable version lacks, and the
sizes that are not a layout of a command in a version.
"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

from cbf import tables as T
from cbf.errors import EncodeError
from cbf.model import Cbf, Record, new_header
from cbf.writer import encode

ROOT = Path(__file__).resolve().parents[1]
STRICT = ["-std=c99", "-Wall", "-Wextra", "-Wpedantic", "-Wconversion", "-Wsign-conversion", "-Wdouble-promotion",
          "-Werror"]

# One case a line on stdin: "major minor code nargs mode". Modes:
#   0  cbf_encode_record, then cbf_encode_end(fill=1)
#   1  cbf_encode_record_stored (a consistent head), then cbf_encode_end(fill=1)
#   2  cbf_encode_record_stored, then cbf_encode_end(fill=0): bytes kept as given
# Prints "record end" (the two return codes) per case, after a first line with
# CBF_ERR_NOT_WRITABLE.
PROGRAM = r"""
#define CBF_IMPLEMENTATION
#include "cbf.h"
#include <stdio.h>
#include <string.h>

int main(void)
{
    static uint8_t buf[1u << 16];
    static uint8_t args[CBF_MAX_ARG_SIZE + 1];
    unsigned major, minor, code, nargs, mode;
    printf("%d\n", (int)CBF_ERR_NOT_WRITABLE);
    memset(args, 0, sizeof args);
    while (scanf("%u %u %u %u %u", &major, &minor, &code, &nargs, &mode) == 5) {
        cbf_header h;
        cbf_writer w;
        int rc;
        long end;
        if (nargs > CBF_MAX_ARG_SIZE || cbf_header_init(&h, cbf_version_find(major, minor)) != CBF_OK)
            return 2;
        if (cbf_encode_begin(&w, buf, sizeof buf, &h) != CBF_OK)
            return 3;
        if (mode == 0) {
            rc = cbf_encode_record(&w, (int)code, args, nargs);
        } else {
            const cbf_field_info *rf;
            size_t nr = cbf_record_fields(&rf), i;
            cbf_record_head head;
            memset(&head, 0, sizeof head);
            for (i = 0; i < nr; i++) {
                uint32_t v = 0u;
                if (rf[i].role == CBF_ROLE_CODE || rf[i].role == CBF_ROLE_CODE_COPY) v = code;
                else if (rf[i].role == CBF_ROLE_ARG_SIZE) v = nargs;
                else if (rf[i].checksum) v = cbf_args_checksum(args, nargs);
                cbf_member_set_uint(&rf[i], &head, v);
            }
            rc = cbf_encode_record_stored(&w, &head, args, nargs);
        }
        end = cbf_encode_end(&w, 0, mode != 2);
        printf("%d %ld\n", rc, end);
    }
    return 0;
}
"""


def _writable() -> list[T.VersionInfo]:
    return [v for v in T.VERSIONS if v.writable]


def _missing() -> list[tuple[T.VersionInfo, T.CommandInfo, int]]:
    """(version, command, a size the command has elsewhere) for every command a writable version lacks."""
    return [(v, c, c.layouts[0].size) for v in _writable() for c in T.COMMANDS if not c.layouts_for(v.id)]


def _bad_size(cmd: T.CommandInfo, version: str) -> int:
    sizes = {lay.size for lay in cmd.layouts_for(version)}
    return next(n for n in range(T.LIMITS["max_arg_size"] + 1) if n not in sizes)


def _wrong_sizes() -> list[tuple[T.VersionInfo, T.CommandInfo, int]]:
    """(version, command, a size that is no layout of it there) for every command of a writable version."""
    return [(v, c, _bad_size(c, v.id)) for v in _writable() for c in T.COMMANDS if c.layouts_for(v.id)]


def _fitting() -> list[tuple[T.VersionInfo, T.CommandInfo, int]]:
    """Every (version, command, layout size) a filling writer must accept: the control."""
    return [(v, c, lay.size) for v in _writable() for c in T.COMMANDS for lay in c.layouts_for(v.id)
            if not lay.profiles]


def _id(case: tuple[T.VersionInfo, T.CommandInfo, int]) -> str:
    v, c, n = case
    return f"{c.name}-{n}B-in-{v.id}"


def test_the_model_has_cases() -> None:
    """Rev 03 has a command a writable version lacks; every command has a size that is not its layout."""
    assert _missing() and _wrong_sizes() and _fitting()


# -- Python ---------------------------------------------------------------------------------------
def _py_encode(v: T.VersionInfo, cmd: T.CommandInfo, n: int) -> bytes:
    model = Cbf(new_header(v.id), (Record(code=cmd.code, raw_args=bytes(n)),))
    return encode(model)


@pytest.mark.parametrize("case", _missing() + _wrong_sizes(), ids=_id)
def test_python_encoder_refuses(case: tuple[T.VersionInfo, T.CommandInfo, int]) -> None:
    v, cmd, n = case
    with pytest.raises(EncodeError) as exc:
        _py_encode(v, cmd, n)
    # The writer's own refusal, not the validation of a file it already wrote.
    assert str(exc.value).startswith(f"record 0: {cmd.name} "), str(exc.value)
    assert "would fail check" not in str(exc.value)


# -- C ----------------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def c_writer(tmp_path_factory: pytest.TempPathFactory) -> Path:
    cc = shutil.which("gcc")
    if cc is None:
        pytest.skip("gcc not installed")
    d = tmp_path_factory.mktemp("writer")
    (d / "writer.c").write_text(PROGRAM, encoding="utf-8")
    subprocess.run([cc, *STRICT, "-I", str(ROOT / "generated" / "c"), "-o", str(d / "writer"), str(d / "writer.c"),
                    "-lm"], check=True, capture_output=True)
    return d / "writer"


def _run_c(exe: Path, cases: list[tuple[T.VersionInfo, T.CommandInfo, int]], mode: int) -> tuple[int, list[list[int]]]:
    lines = "".join(f"{v.major} {v.minor or 0} {c.code} {n} {mode}\n" for v, c, n in cases)
    out = subprocess.run([str(exe)], input=lines, capture_output=True, text=True, check=True).stdout.split("\n")
    rows = [[int(x) for x in ln.split()] for ln in out[1:] if ln]
    assert len(rows) == len(cases)
    return int(out[0]), rows


@pytest.mark.parametrize("mode", [0, 1], ids=["encode_record", "stored+fill"])
def test_c_writer_refuses(c_writer: Path, mode: int) -> None:
    cases = _missing() + _wrong_sizes()
    not_writable, rows = _run_c(c_writer, cases, mode)
    assert not_writable < 0
    for case, (rec, end) in zip(cases, rows, strict=True):
        if mode == 0:
            assert rec == not_writable, _id(case)
        assert end == not_writable, _id(case)


def test_c_writer_accepts_every_layout_of_the_version(c_writer: Path) -> None:
    """The control: what the version has is written, by both C paths and by Python's record check."""
    cases = _fitting()
    for mode in (0, 1):
        _, rows = _run_c(c_writer, cases, mode)
        for case, (rec, end) in zip(cases, rows, strict=True):
            assert rec == 0 and end > 0, (_id(case), mode, rec, end)


def test_c_writer_keeps_a_faulty_file_when_not_filling(c_writer: Path) -> None:
    """cbf_encode_end(fill=0) reproduces the bytes as given (conformance's keep_stored)."""
    cases = _missing() + _wrong_sizes()
    _, rows = _run_c(c_writer, cases, 2)
    for case, (rec, end) in zip(cases, rows, strict=True):
        assert rec == 0 and end == T.HEADER_SIZE + T.HEAD_SIZE + case[2], _id(case)
