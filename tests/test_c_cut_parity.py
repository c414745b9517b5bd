"""The C CUT reader (cbf_cut_encode, `cbf-c encode`, issue 34: a dropped CUT file) against Python's
(cbf.cut.from_cut, then codec.pack_file with every derived value filled): the same text gives the
same bytes, or both refuse it, and the C refusal names the line Python names. As `cbf encode`,
`cbf-c encode` then refuses bytes that do not validate under the profile (writer.encode: an error, or a
string_ascii finding): such a text is refused by both with the same line (the record's CUT line, the
check and its message), which the bytes the reader made decide.

The texts come from the golden files, never from today's command list: the CUT text Python writes for
every golden .cbf under every profile, the docs' golden CUT forms (the companion document's complete
example, each command's example line: cbfgen.emit.docs.golden, which writes CUT from the model without
the binding), and hostile texts made from them (a bad number, an unknown keyword, an overlong line, a
NUL, CR LF and a lone CR, bytes that are not UTF-8, one command more than the count holds, a header
line twice, a wrong check_sum)."""

from __future__ import annotations

import atexit
import functools
import shutil
import subprocess
import tempfile
from pathlib import Path

import pytest
from c_programs import built

from cbf import codec
from cbf import tables as T
from cbf.cli import _cut_line_of
from cbf.cut import from_cut, to_cut
from cbf.errors import CbfError
from cbf.writer import encode
from cbfgen.emit.docs import golden as docs_golden
from cbfgen.loader import load

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
PROFILES = list(T.PROFILES)


@functools.cache
def _cbf_c() -> Path:
    return built("cbf-c")


# The C CUT reader alone (cbf_cut_encode, what the workbench page shows a dropped CUT file as): the bytes of a
# text whose file cbf-c encode then refuses (it does not validate) are compared through it.
READER = r"""
#define CBF_IMPLEMENTATION
#include "cbf.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
int main(int argc, char **argv)
{
    static char text[1 << 24];
    static uint8_t out[1 << 24];
    cbf_cut_error err;
    FILE *fp = argc == 3 ? fopen(argv[2], "rb") : NULL;
    size_t n = fp ? fread(text, 1, sizeof text, fp) : 0;
    long len = cbf_cut_encode(text, n, cbf_profile_find(argv[1]), out, sizeof out, &err);
    if (len < 0)
        return 2;
    return fwrite(out, 1, (size_t)len, stdout) == (size_t)len ? 0 : 3;
}
"""


@functools.cache
def _reader() -> Path:
    _cbf_c()  # skips without gcc
    folder = Path(tempfile.mkdtemp(prefix="cut_reader_"))
    atexit.register(shutil.rmtree, folder, True)
    src, exe = folder / "cut_reader.c", folder / "cut_reader"
    src.write_text(READER, encoding="utf-8")
    subprocess.run(["gcc", "-std=c99", "-O0", "-I", str(REPO / "generated" / "c"), "-o", str(exe), str(src), "-lm"],
                   check=True, capture_output=True)
    return exe


def _python(data: bytes, profile: str) -> tuple[bytes | None, int | None]:
    """Python's bytes for the text, or None and the line its refusal names (None: no line)."""
    want, line, _ = _python_said(data, profile)
    return want, line


def _python_said(data: bytes, profile: str) -> tuple[bytes | None, int | None, str | None]:
    """_python, and when the reader's bytes are refused by the writer's judgement (writer.encode validates
    them), what cbf encode says of it after "cbf: FILE: " (cli.py: the record's CUT line, else the offset)."""
    try:
        text = data.decode("utf-8")
        model = from_cut(text, profile=profile)
        codec.pack_file(model, profile=profile)  # the bytes the reader makes (the writer then judges them)
    except UnicodeDecodeError:
        return None, None, None
    except (CbfError, ValueError) as exc:
        return None, getattr(exc, "line", None), None
    try:
        return encode(model, profile=profile), None, None
    except CbfError as exc:
        line = _cut_line_of(text, str(exc))
        return None, line, (f"line {line}: {exc.message}" if line is not None else str(exc))


def _c(path: Path, profile: str) -> tuple[bytes | None, str, int]:
    res = subprocess.run([str(_cbf_c()), "encode", "--profile", profile, path.name, "-o", "-"], cwd=path.parent,
                         capture_output=True, timeout=60)
    return (res.stdout if res.returncode == 0 else None), res.stderr.decode("utf-8", "replace"), res.returncode


def _judge(tmp: Path, name: str, data: bytes, profile: str) -> str | None:
    """None when C and Python agree on the text, else what differs."""
    path = tmp / f"{name}.cut"
    path.write_bytes(data)
    want, line, said = _python_said(data, profile)
    got, err, status = _c(path, profile)
    if want is not None:
        if got != want:
            return f"{name} [{profile}]: C {'refused: ' + err.strip() if got is None else 'wrote other bytes'}"
        return None
    if got is not None or status != 2:
        return f"{name} [{profile}]: Python refuses the text, C wrote {len(got or b'')} bytes (status {status})"
    lines = err.splitlines()
    if len(lines) != 1 or not lines[0].startswith(f"cbf-c: {path.name}: "):
        return f"{name} [{profile}]: the refusal is not one line naming the file: {err!r}"
    if line is not None and f": line {line}" not in lines[0]:
        return f"{name} [{profile}]: Python names line {line}, C says {lines[0]!r}"
    if said is not None and lines[0] != f"cbf-c: {path.name}: {said}":
        return f"{name} [{profile}]: cbf says {said!r}, C says {lines[0]!r}"
    if said is not None:  # the writer refused the reader's bytes: C's reader made the same ones
        read = subprocess.run([str(_reader()), profile, str(path)], capture_output=True, timeout=60)
        if read.returncode != 0 or read.stdout != codec.pack_file(from_cut(data.decode(), profile=profile),
                                                                  profile=profile):
            return f"{name} [{profile}]: C's CUT reader (cbf_cut_encode) made other bytes than Python's"
    return None


def _golden_texts() -> dict[tuple[str, str], bytes]:
    """(name, profile) -> the CUT text Python writes for each golden .cbf that has one."""
    out: dict[tuple[str, str], bytes] = {}
    for f in sorted(GOLDEN.glob("*.cbf")):
        try:
            model = codec.decode(f.read_bytes())
        except CbfError:
            continue
        for p in PROFILES:
            try:
                out[(f.stem, p)] = to_cut(model, profile=p).encode()
            except ValueError:  # trailing bytes, a name the profile's reader cannot read: no CUT form
                continue
    return out


def _docs_texts() -> dict[str, bytes]:
    """The docs' golden CUT forms: the complete example, and each command's example line in its case's version."""
    spec = load(REPO / "spec" / "cbf.yaml")
    cases = docs_golden.load_cases(GOLDEN)
    out: dict[str, bytes] = {}
    example = docs_golden.cut_example(spec, cases)
    assert example is not None
    out[f"example.{example[0]}"] = example[1].encode()
    data = {c.name: c.data for c in cases}
    vkw = spec.cut["extensions"]["version_keyword"]
    for name, ex in docs_golden.examples(spec, cases).items():
        major, minor = codec.decode(data[ex.case]).version
        out[f"line.{name}"] = f"{vkw} {major}.{minor}\n{ex.cut}\n".encode()
    return out


def test_c_reads_every_golden_cut_form_into_pythons_bytes(tmp_path: Path) -> None:
    texts = _golden_texts()
    assert len({n for n, _ in texts}) >= len(list(GOLDEN.glob("valid.*.cbf")))
    differ = [d for (name, p), data in texts.items() if (d := _judge(tmp_path, name, data, p))]
    docs = _docs_texts()
    assert len(docs) > 1
    differ += [d for name, data in docs.items() for p in PROFILES if (d := _judge(tmp_path, name, data, p))]
    assert not differ, "\n".join(differ[:10])


def _keyword_lines(text: str) -> list[int]:
    """The indexes of the lines that are command keyword lines (the model's keywords)."""
    kws = {c.name.lower() if T.CUT["keyword_case"] == "lower" else c.name for c in T.COMMANDS}
    return [i for i, line in enumerate(text.split("\n")) if line.split(" ", 1)[0] in kws]


def _hostile() -> dict[str, bytes]:
    """Hostile texts, each made from a golden CUT text by one change."""
    base = max((t for t in _golden_texts().values()), key=lambda t: len(_keyword_lines(t.decode())))
    text = base.decode()
    lines = text.split("\n")
    kw_at = _keyword_lines(text)
    numbered = next(i for i in kw_at if any(ch.isdigit() for ch in lines[i]))
    cmds = {c.name.lower() for c in T.COMMANDS}
    unknown = next(w for w in (f"no_command_{k}" for k in range(100)) if w not in cmds)

    def at(i: int, line: str) -> bytes:
        return "\n".join(lines[:i] + [line] + lines[i + 1:]).encode()

    def number(i: int, new: str) -> bytes:
        words = lines[i].split(" ")
        k = next(j for j, w in enumerate(words) if w and w[0] in "-0123456789")
        return at(i, " ".join(words[:k] + [new] + words[k + 1:]))

    # a command of the default version with no arguments, and one with a text argument (the model's)
    bare = next(c for c in T.COMMANDS if any(lay.size == 0 for lay in c.layouts_for(T.DEFAULT_VERSION)))
    texty = next(c for c in T.COMMANDS for lay in c.layouts_for(T.DEFAULT_VERSION) if any(f.text for f in lay.args))
    text_size = max(f.size for lay in texty.layouts_for(T.DEFAULT_VERSION) for f in lay.args if f.text)
    header = T.CUT["header_keyword"]
    return {
        "bad_number": number(numbered, "1.2.3"),
        "bad_number_exponent": number(numbered, "1e5"),
        "bad_number_word": number(numbered, "one"),
        "number_beyond_binary32": number(numbered, "9" * 310),
        "number_long_fraction": number(numbered, "0." + "0" * 60 + "1" * 400),
        "unknown_keyword": at(kw_at[-1], f"{unknown} 1"),
        "overlong_line": at(kw_at[-1], f"{texty.name.lower()} " + "x" * (text_size * 4096)),
        "overlong_spaces": at(kw_at[-1], lines[kw_at[-1]].replace(" ", " " * 20000, 1)),
        "nul": at(numbered, lines[numbered][:3] + "\0" + lines[numbered][3:]),
        "crlf": text.replace("\n", "\r\n").encode(),
        "lone_cr": at(numbered, lines[numbered][:3] + "\r" + lines[numbered][3:]),
        "not_utf8": at(numbered, lines[numbered]) + b"\xff\xfe\n",
        "utf8_letter": ("\u00e9" + text).encode(),
        "huge_count": (f"{header} X\n" + f"{bare.name.lower()}\n" * (T.LIMITS["max_commands"] + 1)).encode(),
        "header_twice": (f"{header} A\n{header} A\n" + text).encode(),
        "wrong_check_sum": (text + f"{T.CUT['checksum_keyword']} 1\n").encode(),
        "bad_version": (f"{T.CUT['extensions']['version_keyword']} 99.9\n" + text).encode(),
        "trailing_text": at(numbered, lines[numbered] + " extra"),
    }


@pytest.mark.parametrize("name", list(_hostile()))
def test_hostile_cut_is_refused_by_both_with_its_line(name: str, tmp_path: Path) -> None:
    data = _hostile()[name]
    assert _judge(tmp_path, name, data, PROFILES[0]) is None
    want, _ = _python(data, PROFILES[0])
    if name not in ("crlf", "number_long_fraction", "overlong_spaces"):  # these read, the same in both
        assert want is None, f"{name}: Python reads it"
