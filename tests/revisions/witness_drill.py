"""`make witness-drill` (issue 37, point 5): `cbfgen diff --witness` on every breaking drill fixture.

For each fixture of tests/revisions/ that is wire- or text-breaking, the spec it revises is written to
OUT/<fixture>/cbf.yaml and `python -m cbfgen diff spec/cbf.yaml OUT/<fixture>/cbf.yaml --witness
OUT/<fixture>` runs (the command a format owner runs): it must exit with the fixture's class (1
wire-breaking, 3 text-breaking only; 4 would be a change no file shows) and write a witness (.hex,
.cbf, .expect.yaml, .witness.yaml) per wire-breaking change, a JSON text per text-breaking one.
tests/test_witness.py checks the same in-process, cheaply, in `make test`.

    python tests/revisions/witness_drill.py [OUT]     (default build/witness)
"""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from revisions import drill  # noqa: E402


def main(argv: list[str]) -> int:
    out = Path(argv[0]) if argv else drill.REPO / "build" / "witness"
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(drill.REPO / "generator"), str(drill.REPO),
                                                      os.environ.get("PYTHONPATH", "")]))
    bad = 0
    for fx in drill.applicable():  # a fixture whose precondition this spec already holds is left out
        path = fx.path
        if not (fx.breaking or fx.text_breaking):
            continue
        where = out / path.stem
        revised = drill.revised_spec(fx, drill.REPO / drill.SPEC, where)
        t0 = time.monotonic()
        res = subprocess.run([sys.executable, "-m", "cbfgen", "diff", drill.SPEC, str(revised), "--witness",
                              str(where)], cwd=drill.REPO, env=env, capture_output=True, text=True)
        want = 1 if fx.breaking else 3
        hexes = sorted(where.glob("witness.*.hex"))
        texts = sorted(where.glob("text.*.json"))
        ok = res.returncode == want and (hexes if fx.breaking else texts)
        bad += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {path.stem}: exit {res.returncode} (want {want}), {len(hexes)} witness(es), "
              f"{len(texts)} text witness(es) (JSON, CUT), {time.monotonic() - t0:.1f} s")
        if not ok:
            print(res.stderr.strip()[-2000:], file=sys.stderr)
    print(f"witness-drill: {bad} fixture(s) failed; witnesses in {out}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
