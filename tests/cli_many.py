"""Many `cbf` command lines in one Python process, each judged as if it had run alone.

A process per command line pays an interpreter start and the imports of cbf and numpy
(about 0.3 CPU s) for a command that then takes milliseconds. RUNNER_MANY runs the CLI's
main() for each command line in turn, each with its own stdout and stderr (encoded as the
process's own streams are), exit code and peak memory (VmHWM, reset through
/proc/self/clear_refs before each; where the reset is refused the peak so far is kept, an
upper bound). What escapes main() is printed as the interpreter would, a traceback on that
command's stderr, and SystemExit gives the exit code. Modules named in ``hide`` are made
unimportable first (``sys.modules[name] = None``), as for a user without them.
"""

from __future__ import annotations

import json
import subprocess
import sys
import tempfile
from collections.abc import Mapping, Sequence
from pathlib import Path

RUNNER_MANY = r"""
import io, json, sys, traceback
job = json.load(open(sys.argv[1]))
for name in job["hide"]:
    sys.modules[name] = None
from cbf.cli import main
out = []
for argv in job["argvs"]:
    try:
        open("/proc/self/clear_refs", "w").write("5")
    except OSError:
        pass
    real = sys.stdout, sys.stderr
    sys.stdout, sys.stderr = (io.TextIOWrapper(io.BytesIO(), encoding=s.encoding, errors=s.errors) for s in real)
    try:
        rc = main(argv)
    except SystemExit as exc:
        rc = exc.code if isinstance(exc.code, int) else 0 if exc.code is None else 1
    except BaseException:
        traceback.print_exc()
        rc = 1
    texts = []
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except Exception:
            traceback.print_exc(file=real[1])
        texts.append(stream.buffer.getvalue().decode(stream.encoding, "backslashreplace"))
    sys.stdout, sys.stderr = real
    peak = [l.split()[1] for l in open("/proc/self/status") if l.startswith("VmHWM")]
    out.append({"argv": argv, "rc": rc, "stdout": texts[0], "stderr": texts[1], "peak": int(peak[0] if peak else 0)})
json.dump(out, open(sys.argv[2], "w"))
"""


def run_many(argvs: Sequence[Sequence[str]], env: Mapping[str, str], prefix: Sequence[str] = (),
             hide: Sequence[str] = (),
             timeout: float | None = None) -> list[tuple[subprocess.CompletedProcess[str], int]]:
    """Each command line's result and peak resident memory in kB, in order, from one process (killed
    after ``timeout`` seconds: a command that blocks fails the test instead of hanging it)."""
    argvs = [list(a) for a in argvs]
    with tempfile.TemporaryDirectory(prefix="cli_many") as tmp:
        todo, done = Path(tmp) / "job.json", Path(tmp) / "results.json"
        todo.write_text(json.dumps({"argvs": argvs, "hide": list(hide)}), encoding="utf-8")
        res = subprocess.run([*prefix, sys.executable, "-c", RUNNER_MANY, str(todo), str(done)], env=dict(env),
                             capture_output=True, text=True, stdin=subprocess.DEVNULL, timeout=timeout)
        assert res.returncode == 0 and res.stderr == "", res.stderr
        results = json.loads(done.read_text(encoding="utf-8"))
    assert [r["argv"] for r in results] == argvs
    return [(subprocess.CompletedProcess(r["argv"], r["rc"], r["stdout"], r["stderr"]), r["peak"]) for r in results]
