"""A ceiling on the hand-written C (issue #33, point 6): no function of the C engine
(generator/cbfgen/emit/c/runtime/) or of the tools (generator/cbfgen/emit/c/tools/: the tools' engine,
cbf-c's command line, the testee, the fuzz harness) above cyclomatic complexity 25, counted by lizard
(a pinned dev dependency). The generated per-layout code is not hand-written and is not counted."""

from __future__ import annotations

from pathlib import Path

import lizard

ROOT = Path(__file__).resolve().parent.parent
HAND_WRITTEN_C = [ROOT / "generator" / "cbfgen" / "emit" / "c" / folder for folder in ("runtime", "tools")]
CEILING = 25


def _functions() -> list[tuple[str, str, int]]:
    found = []
    for folder in HAND_WRITTEN_C:
        for path in sorted(folder.glob("*.[ch]")):
            info = lizard.analyze_file(str(path))
            found.extend((path.name, f.name, f.cyclomatic_complexity) for f in info.function_list)
    return found


def test_no_hand_written_c_function_above_the_ceiling() -> None:
    functions = _functions()
    assert len(functions) > 100, "lizard found too few functions: the folders moved?"
    over = sorted((ccn, f"{file}:{name}") for file, name, ccn in functions if ccn > CEILING)
    assert not over, f"hand-written C functions above cyclomatic complexity {CEILING}: {over}"


def test_the_count_sees_a_complex_function(tmp_path: Path) -> None:
    """The measure itself: a function of 30 decisions is counted above the ceiling (so the test above can fail)."""
    body = "\n".join(f"    if (x == {i}) return {i};" for i in range(30))
    src = tmp_path / "complex.c"
    src.write_text(f"int f(int x)\n{{\n{body}\n    return -1;\n}}\n", encoding="utf-8")
    (fn,) = lizard.analyze_file(str(src)).function_list
    assert fn.cyclomatic_complexity > CEILING
