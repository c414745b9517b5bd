"""A tiny assembler for annotated-hex golden files.

It knows bytes, little-endian numbers, NUL-padded strings, ranges and byte
sums, and nothing about CBF: it shares no code with generator/ or
generated/ and imports no binding, so a golden file is never made by the
code it tests. The language is described in conformance/golden/README.md.
"""

from __future__ import annotations

import ast
import bisect
import functools
import math
import operator
import re
import struct
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any


class AsmError(Exception):
    def __init__(self, path: str, line: int, message: str) -> None:
        super().__init__(f"{path}:{line}: {message}")


@dataclass
class _Hole:
    offset: int
    width: int
    target: str  # range name
    line: int


@dataclass
class _State:
    base: Path | None = None
    patches: list[tuple[int, bytes, bool, int]] = field(default_factory=list)  # offset, bytes, after sums, line
    truncate: int | None = None  # keep only this many bytes, after the sums
    overrides: list[tuple[int, bytes, int]] = field(default_factory=list)
    out: bytearray = field(default_factory=bytearray)
    ranges: dict[str, list[tuple[int, int]]] = field(default_factory=dict)
    open: list[tuple[str, int]] = field(default_factory=list)
    holes: list[_Hole] = field(default_factory=list)
    pending_anon: list[_Hole] = field(default_factory=list)
    anon: int = 0


_OPS: dict[type, Any] = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
                         ast.FloorDiv: operator.floordiv, ast.Mod: operator.mod, ast.Div: operator.truediv,
                         ast.USub: operator.neg}


@functools.lru_cache(maxsize=4096)
def _parse(expr: str) -> ast.Expression:
    return ast.parse(expr, mode="eval")


def _eval(expr: str, env: dict[str, int]) -> float:
    def ev(node: ast.AST) -> float:
        if isinstance(node, ast.Expression):
            return ev(node.body)
        if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)):
            return node.value
        if isinstance(node, ast.Name) and node.id in env:
            return env[node.id]
        if isinstance(node, ast.BinOp) and type(node.op) in _OPS:
            return float(_OPS[type(node.op)](ev(node.left), ev(node.right)))
        if isinstance(node, ast.UnaryOp) and type(node.op) in _OPS:
            return float(_OPS[type(node.op)](ev(node.operand)))
        raise ValueError(f"unsupported expression {expr!r}")

    return ev(_parse(expr))


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


def _tokens(text: str) -> list[str]:
    return _TOKEN.findall(text)


def assemble_text(text: str, path: str = "<text>", base: Path | None = None) -> bytes:
    lines = text.splitlines()
    st = _State(base=base)
    _run(lines, 0, len(lines), st, {}, path)
    if st.open:
        raise AsmError(path, len(lines), f"range {st.open[-1][0]!r} never closed")
    if st.pending_anon:
        raise AsmError(path, st.pending_anon[0].line, "sum placeholder without a following { range")
    for off, data, after, line in st.patches:
        if not after:
            _patch(st, off, data, path, line)
    for off, data, line in st.overrides:
        hit = [h for h in st.holes if h.offset == off and h.width == len(data)]
        if not hit:
            raise AsmError(path, line, f"override at {off}: no {len(data)}-byte sum placeholder there")
        st.holes.remove(hit[0])
        _patch(st, off, data, path, line)
    _fill(st, path)
    for off, data, after, line in st.patches:
        if after:
            _patch(st, off, data, path, line)
    if st.truncate is not None:
        return bytes(st.out[:st.truncate])
    return bytes(st.out)


def listing(text: str, path: str = "<text>", base: Path | None = None) -> str:
    """Offsets of every source line, to help a person write patches and expectations."""
    lines = text.splitlines()
    st = _State(base=base)
    rows = []
    for n, line in enumerate(lines):
        before = len(st.out)
        _run(lines, n, n + 1, st, {}, path) if not line.strip().lower().startswith(("repeat", "end")) else None
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
        raw = lines[i]
        code = raw.split("#", 1)[0].strip()
        lineno = i + 1
        i += 1
        if not code:
            continue
        toks = _tokens(code)
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


def _directive(op: str, toks: list[str], st: _State, env: dict[str, int], lineno: int) -> None:
    out = st.out
    args = toks[1:]
    if re.fullmatch(r"[0-9a-fA-F]{2}", toks[0]):
        for t in toks:
            if not re.fullmatch(r"[0-9a-fA-F]{2}", t):
                raise ValueError(f"{t!r} is not a hex byte")
            out.append(int(t, 16))
    elif op in ("u8", "u16", "u32"):
        fmt = {"u8": "<B", "u16": "<H", "u32": "<I"}[op]
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
    elif op in ("sum16", "sum32"):
        hole = _Hole(len(out), 2 if op == "sum16" else 4, args[0], lineno)
        out += bytes(hole.width)
        if args[0] == ">":
            st.pending_anon.append(hole)
        else:
            st.holes.append(hole)
    elif op.startswith("{"):
        name = op[1:]
        if not name:
            if not st.pending_anon:
                raise ValueError("anonymous range without a sum placeholder before it")
            hole = st.pending_anon.pop(0)
            st.anon += 1
            name = hole.target = f"~{st.anon}"
            st.holes.append(hole)
        st.open.append((name, len(out)))
    elif op == "}":
        if not st.open:
            raise ValueError("} without an open range")
        name, begin = st.open.pop()
        st.ranges.setdefault(name, []).append((begin, len(out)))
    elif op == "include":
        if st.base is None:
            raise ValueError("include needs a file path")
        inc = st.base / args[0]
        inc_lines = inc.read_text(encoding="utf-8").splitlines()
        _run(inc_lines, 0, len(inc_lines), st, env, str(inc))
    elif op == "set":
        env[args[0]] = int(_eval(args[1], env))
    elif op == "override":
        # override OFFSET bytes: literal bytes that replace a sum placeholder (a wrong checksum on purpose)
        st.overrides.append((int(_eval(args[0], env)), bytes(int(t, 16) for t in args[1:]), lineno))
    elif op in ("patch", "patch_after_sums"):
        # patch OFFSET then bytes as for a hex line, u16/u32/f32/str directives are not allowed here
        data = bytes(int(t, 16) for t in args[1:])
        st.patches.append((int(_eval(args[0], env)), data, op == "patch_after_sums", lineno))
    elif op == "truncate":
        st.truncate = int(_eval(args[0], env))
    else:
        raise ValueError(f"unknown directive {op!r}")


def _fill(st: _State, path: str) -> None:
    """Resolve sums; a sum waits until no unresolved placeholder lies in its range."""
    todo = sorted(st.holes, key=lambda h: h.offset)
    while todo:
        waiting = [h.offset for h in todo]
        left: list[_Hole] = []
        done: list[_Hole] = []
        for hole in todo:
            spans = st.ranges.get(hole.target)
            if spans is None:
                raise AsmError(path, hole.line, f"no range named {hole.target!r}")
            blocked = False
            for b, e in spans:
                k = bisect.bisect_left(waiting, b)
                while k < len(waiting) and waiting[k] < e:
                    if waiting[k] != hole.offset:
                        blocked = True
                        break
                    k += 1
                if blocked:
                    break
            (left if blocked else done).append(hole)
        if not done:
            raise AsmError(path, todo[0].line, "sums depend on each other in a cycle")
        for hole in done:
            total = sum(sum(st.out[b:e]) for b, e in st.ranges[hole.target])
            st.out[hole.offset:hole.offset + hole.width] = (total % (1 << (8 * hole.width))).to_bytes(
                hole.width, "little")
        todo = left


def assemble(path: Path) -> bytes:
    return assemble_text(path.read_text(encoding="utf-8"), str(path), base=path.parent)
