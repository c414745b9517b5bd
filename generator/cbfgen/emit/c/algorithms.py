"""The checksum algorithm kinds of the registry as C tables (issue 33, point 1).

runtime/checksums.c implements each family once (sum, CRC, Fletcher) and reads everything else
from ``cbf__algs[CBF__ALG_x]``: the parameters of registry.ALGORITHMS and, for a CRC, its byte
table, computed here from the parameters (static const data: no allocation, nothing computed at
run time, nothing shared between threads). A new algorithm kind is a registry entry; its row and
table follow.
"""

from __future__ import annotations

from dataclasses import dataclass

from ...registry import ALGORITHM_FAMILIES, ALGORITHMS, ChecksumAlgorithm
from .cnames import macro


def _reflect(value: int, bits: int) -> int:
    return int(format(value, f"0{bits}b")[::-1], 2)


def crc_table(a: ChecksumAlgorithm) -> tuple[int, ...]:
    """A CRC's byte table as checksums.c runs it: for refin, the register right-aligned and the
    polynomial reflected; else the register left-aligned in 32 bits (any width up to 32)."""
    width = a.width or 0
    rows = []
    for n in range(256):
        if a.refin:
            c, rpoly = n, _reflect(a.poly, width)
            for _ in range(8):
                c = (c >> 1) ^ rpoly if c & 1 else c >> 1
        else:
            c, apoly = n << 24, a.poly << (32 - width)
            for _ in range(8):
                c = ((c << 1) ^ apoly) & 0xFFFFFFFF if c & 0x80000000 else (c << 1) & 0xFFFFFFFF
        rows.append(c)
    return tuple(rows)


@dataclass(frozen=True)
class AlgorithmRow:
    """One row of cbf__algs (CBF__ALG_<macro>), its CRC table's rows when it is a CRC."""

    name: str
    macro: str
    family: str  # CBF__FAMILY_<family>
    width: int
    init: int  # the register's first value, in the form checksums.c keeps it (reflected or left-aligned)
    refin: bool
    refout: bool
    xorout: int
    doc: str
    table: tuple[int, ...]


def _row(a: ChecksumAlgorithm) -> AlgorithmRow:
    width = a.width or 0
    init = 0
    if a.family == "crc":
        init = _reflect(a.init, width) if a.refin else a.init << (32 - width)
    return AlgorithmRow(name=a.name, macro=macro(a.name), family=macro(a.family), width=width, init=init,
                        refin=a.refin, refout=a.refout, xorout=a.xorout, doc=a.doc,
                        table=crc_table(a) if a.family == "crc" else ())


@dataclass(frozen=True)
class AlgorithmTables:
    """cbf/algorithms.c.j2: the families (the enum checksums.c switches on) and every kind's row."""

    families: tuple[str, ...]
    rows: tuple[AlgorithmRow, ...]


def algorithm_tables() -> AlgorithmTables:
    return AlgorithmTables(families=tuple(macro(f) for f in ALGORITHM_FAMILIES),
                           rows=tuple(_row(a) for a in ALGORITHMS.values()))


# The kinds as the C enum names them (CBF__ALG_<macro>), in the registry's order.
ALGORITHM_MACROS: tuple[str, ...] = tuple(macro(k) for k in ALGORITHMS)
