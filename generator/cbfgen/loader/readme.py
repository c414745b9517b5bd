"""Write the loader's pass list (``passes_markdown``) into a README between its markers.

    python -m cbfgen.loader.readme generator/README.md     (make loader-readme)
"""

from __future__ import annotations

import sys
from pathlib import Path

from . import passes_markdown

BEGIN = "<!-- loader-passes:begin (written by make loader-readme) -->"
END = "<!-- loader-passes:end -->"


def rewrite(text: str) -> str:
    """``text`` with the pass list between BEGIN and END (ValueError: a marker is missing)."""
    if BEGIN not in text or END not in text:
        raise ValueError(f"the README has no {BEGIN} ... {END} markers")
    head, rest = text.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    return f"{head}{BEGIN}\n{passes_markdown()}{END}{tail}"


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    if len(args) != 1:
        print("usage: python -m cbfgen.loader.readme README.md", file=sys.stderr)
        return 2
    path = Path(args[0])
    old = path.read_text(encoding="utf-8")
    new = rewrite(old)
    if new != old:
        tmp = path.with_name(path.name + ".tmp")
        tmp.write_text(new, encoding="utf-8")
        tmp.replace(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
