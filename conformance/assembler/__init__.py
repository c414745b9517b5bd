"""A tiny assembler for annotated-hex golden files.

It knows bytes, little-endian numbers, NUL-padded strings and checksum
placeholders. How a checksum is computed (its field, algorithm and coverage,
and what a profile changes) it reads from spec/cbf.yaml with plain yaml
(spec.py), and it computes it with its own implementations (checksums.py):
it shares no code with generator/ or generated/ and imports no binding, so a
golden file is never made by the code it tests. The language is described in
conformance/golden/README.md.
"""

from __future__ import annotations

import ast
import functools
import math
import operator
import re
import struct
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from . import checksums
from .spec import SpecSums
from .spec import load as load_spec


class AsmError(Exception):
    def __init__(self, path: str, line: int, message: str) -> None:
        super().__init__(f"{path}:{line}: {message}")


@dataclass
class _Hole:
    """A checksum placeholder: the spec's `tag` checksum (under `profile` for the file checksum)."""

    offset: int
    width: int
    tag: str
    profile: str | None
    line: int


@dataclass
class _State:
    spec: SpecSums
    base: Path | None = None
    patches: list[tuple[int, bytes, bool, int]] = field(default_factory=list)  # offset, bytes, after sums, line
    truncate: int | None = None  # keep only this many bytes, after the sums
    cut: tuple[int, str, int] | None = None  # (bytes kept, checksum tag it precedes, line): `truncate N before TAG`
    overrides: list[tuple[int, bytes, int]] = field(default_factory=list)
    out: bytearray = field(default_factory=bytearray)
    holes: list[_Hole] = field(default_factory=list)


@functools.lru_cache(maxsize=8)
def _spec(path: Path | None) -> SpecSums:
    return load_spec() if path is None else load_spec(path)


def _env(spec: SpecSums) -> dict[str, int]:
    """Variables every source may use, read from the spec: spec_next_major is one above the
    newest major version, a version no revision of this spec has yet (never made real by
    adding a version: the next revision moves it on)."""
    return {"spec_next_major": max(spec.majors) + 1}


_OPS: dict[type, Any] = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
                         ast.FloorDiv: operator.floordiv, ast.Mod: operator.mod, ast.Div: operator.truediv,
                         ast.USub: operator.neg}


@functools.lru_cache(maxsize=4096)
def _parse(expr: str) -> ast.Expression:
    return ast.parse(expr, mode="eval")


Evaluator = Callable[[dict[str, int]], float]


@functools.lru_cache(maxsize=4096)
def _compile(expr: str) -> Evaluator:
    """expr as a function of the variables, its syntax tree walked once (a `repeat` body evaluates the same
    expressions thousands of times): +, -, *, /, //, %, unary minus, numbers and variable names."""

    def unsupported() -> ValueError:
        return ValueError(f"unsupported expression {expr!r}")

    def comp(node: ast.AST) -> Evaluator:
        if isinstance(node, ast.Expression):
            return comp(node.body)
        if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)):
            value = node.value
            return lambda env: value
        if isinstance(node, ast.Name):
            name = node.id

            def var(env: dict[str, int]) -> float:
                if name not in env:
                    raise unsupported()
                return env[name]
            return var
        if isinstance(node, ast.BinOp) and type(node.op) in _OPS:
            fn, left, right = _OPS[type(node.op)], comp(node.left), comp(node.right)
            return lambda env: float(fn(left(env), right(env)))
        if isinstance(node, ast.UnaryOp) and type(node.op) in _OPS:
            fn1, operand = _OPS[type(node.op)], comp(node.operand)
            return lambda env: float(fn1(operand(env)))
        raise unsupported()

    return comp(_parse(expr))


def _eval(expr: str, env: dict[str, int]) -> float:
    return _compile(expr)(env)


def _f32(tok: str, env: dict[str, int]) -> bytes:
    t = tok.lower()
    if t.startswith("nan:") or t.startswith("bits:"):
        return struct.pack("<I", int(t.split(":", 1)[1], 16))
    if t in ("inf", "+inf", "-inf", "nan", "-0", "-0.0"):
        return struct.pack("<f", float(t))
    value = _eval(tok, env)
    packed = struct.pack("<f", value)
    if math.isfinite(value) and not math.isfinite(struct.unpack("<f", packed)[0]):
        raise ValueError(f"{tok} overflows binary32")
    return packed


_TOKEN = re.compile(r'"(?:[^"\\]|\\.)*"|\S+')
_HEX_BYTE = re.compile(r"[0-9a-fA-F]{2}")


def _tokens(text: str) -> list[str]:
    return _TOKEN.findall(text)


@functools.lru_cache(maxsize=4096)
def _line(raw: str) -> tuple[str, tuple[str, ...]]:
    """A source line's code (the comment cut off) and its tokens, made once per line text."""
    code = raw.split("#", 1)[0].strip()
    return code, tuple(_tokens(code))


def assemble_text(text: str, path: str = "<text>", base: Path | None = None, spec: Path | None = None) -> bytes:
    lines = text.splitlines()
    st = _State(spec=_spec(spec), base=base)
    _run(lines, 0, len(lines), st, _env(st.spec), path)
    for off, data, after, line in st.patches:
        if not after:
            _patch(st, off, data, path, line)
    for off, data, line in st.overrides:
        hit = [h for h in st.holes if h.offset == off and h.width == len(data)]
        if not hit:
            raise AsmError(path, line, f"override at {off}: no {len(data)}-byte checksum placeholder there")
        st.holes.remove(hit[0])
        _patch(st, off, data, path, line)
    _fill(st, path)
    if st.cut is not None and st.cut[0] < len(st.out):  # no checksum of that tag or after it to wait for
        del st.out[st.cut[0]:]
    for off, data, after, line in st.patches:
        if after:
            _patch(st, off, data, path, line)
    if st.truncate is not None:
        return bytes(st.out[:st.truncate])
    return bytes(st.out)


def listing(text: str, path: str = "<text>", base: Path | None = None, spec: Path | None = None) -> str:
    """Offsets of every source line, to help a person write patches and expectations."""
    lines = text.splitlines()
    st = _State(spec=_spec(spec), base=base)
    env = _env(st.spec)
    rows = []
    for n, line in enumerate(lines):
        before = len(st.out)
        _run(lines, n, n + 1, st, env, path) if not line.strip().lower().startswith(("repeat", "end")) else None
        rows.append(f"{before:6d}  {line}")
    return "\n".join(rows)


def _patch(st: _State, off: int, data: bytes, path: str, line: int) -> None:
    if off < 0:
        off += len(st.out)
    if not 0 <= off <= len(st.out) - len(data):
        raise AsmError(path, line, f"patch at {off} runs past the end ({len(st.out)} bytes)")
    st.out[off:off + len(data)] = data


def _run(lines: list[str], start: int, end: int, st: _State, env: dict[str, int], path: str) -> None:
    i = start
    while i < end:
        code, toks = _line(lines[i])
        lineno = i + 1
        i += 1
        if not code:
            continue
        op = toks[0].lower()
        try:
            if op == "repeat":
                count, var = int(_eval(toks[1], env)), (toks[2] if len(toks) > 2 else "i")
                depth, j = 1, i
                while j < end and depth:
                    first = lines[j].split("#", 1)[0].strip().split(" ", 1)[0].lower()
                    depth += first == "repeat"
                    depth -= first == "end"
                    j += 1
                if depth:
                    raise ValueError("repeat without end")
                for k in range(count):
                    _run(lines, i, j - 1, st, {**env, var: k}, path)
                i = j
            elif op == "end":
                raise ValueError("end without repeat")
            else:
                _directive(op, toks, st, env, lineno)
        except (ValueError, IndexError, struct.error, SyntaxError, OverflowError) as exc:
            raise AsmError(path, lineno, f"{code!r}: {exc}") from None


def _directive(op: str, toks: tuple[str, ...], st: _State, env: dict[str, int], lineno: int) -> None:
    out = st.out
    args = toks[1:]
    if _HEX_BYTE.fullmatch(toks[0]):
        for t in toks:
            if not _HEX_BYTE.fullmatch(t):
                raise ValueError(f"{t!r} is not a hex byte")
            out.append(int(t, 16))
    elif op in ("u8", "u16", "u32", "u64", "i8", "i16", "i32", "i64"):  # u8: one byte; i*: two's complement
        fmt = {"u8": "<B", "u16": "<H", "u32": "<I", "u64": "<Q", "i8": "<b", "i16": "<h", "i32": "<i", "i64": "<q"}[op]
        for t in args:
            out += struct.pack(fmt, int(_eval(t, env)))
    elif op == "f32":
        for t in args:
            out += _f32(t, env)
    elif op == "str":
        size = int(args[0])
        text = ast.literal_eval(args[1]) if len(args) > 1 else ""
        raw = text.encode("latin-1") if isinstance(text, str) else bytes(text)
        if len(raw) > size:
            raise ValueError(f"{len(raw)} bytes do not fit {size}")
        out += raw + bytes(size - len(raw))
    elif op == "zeros":
        out += bytes(int(_eval(args[0], env)))
    elif op == "checksum":
        # checksum TAG [PROFILE]: the spec's TAG checksum, as wide as its field, computed at
        # the end with the spec's algorithm and coverage (the profile's, for the file checksum)
        if not 1 <= len(args) <= 2:
            raise ValueError("checksum TAG [PROFILE]")
        tag, profile = args[0], (args[1] if len(args) > 1 else None)
        st.spec.rule(tag, profile)  # refuse an unknown tag or profile at its line
        hole = _Hole(len(out), st.spec.slots[tag].width, tag, profile, lineno)
        out += bytes(hole.width)
        st.holes.append(hole)
    elif op == "include":
        if st.base is None:
            raise ValueError("include needs a file path")
        inc = st.base / args[0]
        inc_lines = inc.read_text(encoding="utf-8").splitlines()
        _run(inc_lines, 0, len(inc_lines), st, env, str(inc))
    elif op == "set":
        env[args[0]] = int(_eval(args[1], env))
    elif op == "override":
        # override OFFSET bytes: the stored value, literally, instead of the checksum placeholder at
        # OFFSET (a wrong checksum on purpose: it stays wrong under any algorithm)
        st.overrides.append((int(_eval(args[0], env)), bytes(int(t, 16) for t in args[1:]), lineno))
    elif op in ("patch", "patch_after_sums"):
        # patch OFFSET then bytes as for a hex line, u16/u32/f32/str directives are not allowed here
        data = bytes(int(t, 16) for t in args[1:])
        st.patches.append((int(_eval(args[0], env)), data, op == "patch_after_sums", lineno))
    elif op == "truncate":
        # truncate N: keep the first N bytes after everything else; truncate N before TAG: the
        # file loses its tail before the TAG checksum (and those after it in the fill order) is
        # computed, so that checksum covers the bytes that are left under any algorithm
        if len(args) == 3 and args[1] == "before":
            st.spec.rule(args[2], None if args[2] != "file" else st.spec.default_profile)
            st.cut = (int(_eval(args[0], env)), args[2], lineno)
        elif len(args) == 1:
            st.truncate = int(_eval(args[0], env))
        else:
            raise ValueError("truncate N [before TAG]")
    else:
        raise ValueError(f"unknown directive {op!r}")


def _coverage(st: _State, hole: _Hole, coverage: str) -> bytes:
    """The bytes a spec coverage feeds, in order, over the assembled file."""
    sp, buf = st.spec, st.out
    bo: Any = sp.byte_order
    parts: list[bytes] = []
    for seg in sp.coverages[coverage]:
        region = seg.get("region")
        if region == "file":
            parts.append(bytes(buf[seg["start"]:]))
        elif region == "header":
            parts.append(bytes(buf[seg["start"]:seg["end"]]))
        elif "fields" in seg and hole.tag in sp.arg_sums:
            parts.extend(_arg_fields(st, hole))
            break  # an argument's checksum covers its named fields only (the loader says so)
        elif "fields" in seg:
            parts.extend(_header_fields(st, hole, seg["fields"]))
        elif region == "args":
            rec = hole.offset - sp.slots["args"].offset
            nb = int.from_bytes(buf[rec + sp.arg_size.offset:rec + sp.arg_size.offset + sp.arg_size.width], bo)
            start = rec + sp.head_size
            if start + nb > len(buf):
                raise ValueError(f"the record at {rec} needs {nb} argument bytes, the file ends first")
            parts.append(bytes(buf[start:start + nb]))
        elif region == "records":
            skip = sorted((sp.record_fields[n].offset, sp.record_fields[n].width) for n in seg.get("exclude", []))
            pos = sp.header_size
            while pos + sp.head_size <= len(buf):
                nb = int.from_bytes(buf[pos + sp.arg_size.offset:pos + sp.arg_size.offset + sp.arg_size.width], bo)
                end = pos + sp.head_size + nb
                if end > len(buf):
                    break
                cur = pos
                for s_off, s_width in skip:
                    parts.append(bytes(buf[cur:pos + s_off]))
                    cur = pos + s_off + s_width
                parts.append(bytes(buf[cur:end]))
                pos = end
        else:
            raise ValueError(f"coverage {coverage}: unknown region {region!r}")
    return b"".join(parts)


def _arg_fields(st: _State, hole: _Hole) -> list[bytes]:
    """The bytes an argument's checksum covers: its record found by framing from the header, its
    layout by the record's code and nb and the checksum's place, its named fields in order."""
    sp, buf = st.spec, st.out
    bo: Any = sp.byte_order
    if sp.code is None:
        raise ValueError("the record has no code field")
    pos = sp.header_size
    while pos + sp.head_size <= len(buf):
        nb = int.from_bytes(buf[pos + sp.arg_size.offset:pos + sp.arg_size.offset + sp.arg_size.width], bo)
        if pos + sp.head_size <= hole.offset < pos + sp.head_size + nb:
            code = int.from_bytes(buf[pos + sp.code.offset:pos + sp.code.offset + sp.code.width], bo)
            at = hole.offset - pos - sp.head_size
            found = {a.ranges for a in sp.arg_sums[hole.tag] if (a.code, a.size, a.offset) == (code, nb, at)}
            if len(found) != 1:
                raise ValueError(f"no single layout of code 0x{code:02X} with {nb} argument bytes carries "
                                 f"{hole.tag} at argument offset {at}")
            ranges = next(iter(found))
            if pos + max(e for _, e in ranges) > len(buf):
                raise ValueError(f"the record at {pos} ends before its {hole.tag} coverage")
            return [bytes(buf[pos + s:pos + e]) for s, e in ranges]
        pos += sp.head_size + nb
    raise ValueError(f"checksum {hole.tag} at {hole.offset} lies in no record's arguments")


def _header_fields(st: _State, hole: _Hole, names: list[str]) -> list[bytes]:
    """The bytes of named header fields, as the header layouts that carry the checksum at the hole
    place them (they must agree)."""
    sp, buf = st.spec, st.out
    placed = set()
    for hid in sp.header_tags.get(hole.tag, ()):
        fields = sp.header_fields[hid]
        if all(n in fields for n in names):
            placed.add(tuple((fields[n].offset, fields[n].offset + fields[n].width) for n in names))
    if len(placed) != 1:
        raise ValueError(f"the header fields {', '.join(names)} of checksum {hole.tag} sit in "
                         f"{'no' if not placed else 'more than one'} place")
    return [bytes(buf[s:e]) for s, e in next(iter(placed))]


def _fill(st: _State, path: str) -> None:
    """Compute the checksums in the spec's fill order (each later one covers the earlier ones)."""
    order = {tag: i for i, tag in enumerate(st.spec.fill_order)}
    cut = st.cut
    for hole in sorted(st.holes, key=lambda h: (order.get(h.tag, len(order)), h.offset)):
        if cut is not None and order.get(hole.tag, len(order)) >= order.get(cut[1], len(order)):
            if not 0 <= cut[0] <= len(st.out):
                raise AsmError(path, cut[2], f"truncate at {cut[0]}: the file has {len(st.out)} bytes")
            del st.out[cut[0]:]
            cut = None
        if hole.offset + hole.width > len(st.out):
            raise AsmError(path, hole.line, f"checksum {hole.tag}: its field was cut off")
        try:
            kind, coverage = st.spec.rule(hole.tag, hole.profile)
            value = checksums.compute(kind, _coverage(st, hole, coverage), hole.width)
        except ValueError as exc:
            raise AsmError(path, hole.line, f"checksum {hole.tag}: {exc}") from None
        bo: Any = st.spec.byte_order
        st.out[hole.offset:hole.offset + hole.width] = value.to_bytes(hole.width, bo)


def assemble(path: Path, spec: Path | None = None) -> bytes:
    return assemble_text(path.read_text(encoding="utf-8"), str(path), base=path.parent, spec=spec)
