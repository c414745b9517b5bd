"""floats.format_floats (the batched CUT float formatter of issue 17) against the C twin of
format_float (exhaustive.c --print), on a strided sweep of the binary32 patterns.

    python tests/floats/batch_sweep.py EXHAUSTIVE [STRIDE [OFFSET [FIRST [LAST]]]]

EXHAUSTIVE is the built twin (make build/floats/exhaustive). Prints one summary line and
exits 1 on any mismatch. The full sweep (stride 1) takes hours in Python; `make
floats-exhaustive` proves the twin over every pattern, this ties the batch to the twin.
"""

from __future__ import annotations

import subprocess
import sys
import time

import numpy as np

from cbf.floats import format_floats


def main(argv: list[str]) -> int:
    twin = argv[0]
    stride, offset = (int(argv[1]) if len(argv) > 1 else 257), (int(argv[2]) if len(argv) > 2 else 0)
    first, last = (int(argv[3], 0) if len(argv) > 3 else 0), (int(argv[4], 0) if len(argv) > 4 else (1 << 32) - 1)
    t0, bad, total = time.time(), 0, 0
    for base in range(first + offset, last + 1, stride << 20):
        bits = np.arange(base, min(base + (stride << 20), last + 1), stride, dtype=np.uint64).astype(np.uint32)
        bits = bits[(bits & 0x7F800000) != 0x7F800000]
        ours = format_floats(bits)
        inp = "".join(f"{x:08x}\n" for x in bits.tolist())
        theirs = subprocess.run([twin, "--print"], input=inp, capture_output=True, text=True, check=True).stdout.split()
        if len(theirs) != len(ours):
            raise SystemExit(f"the twin printed {len(theirs)} texts for {len(ours)} patterns")
        for x, a, c in zip(bits.tolist(), ours, theirs, strict=True):
            if a != c:
                bad += 1
                if bad <= 10:
                    print(f"0x{x:08x}: format_floats {a!r}, the twin {c!r}", flush=True)
        total += len(bits)
    print(f"format_floats vs the C twin: {total} patterns (0x{first:08x}..0x{last:08x}, stride {stride}, "
          f"offset {offset}), {bad} mismatches, {time.time() - t0:.0f} s")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
