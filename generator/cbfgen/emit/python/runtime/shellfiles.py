"""Shell completion and a man page, written from the argument parser itself.

    python -m cbf.shellfiles bash [--parser MODULE:FUNCTION]   # a bash completion script on stdout
    python -m cbf.shellfiles man  [--parser MODULE:FUNCTION]   # a man page (roff, section 1) on stdout

The parser is `cbf.cli:parser` by default; any argparse parser can be named (``make shellfiles``
writes the ones of `cbf` and `cbf-conformance` into build/shellfiles/). Every subcommand, option
and choice comes from the parser, so neither file can go stale: install the script as
``~/.local/share/bash-completion/completions/cbf`` and the page as ``~/.local/share/man/man1/cbf.1``.
"""

from __future__ import annotations

import argparse
import importlib
import re
import sys
from collections.abc import Callable, Iterator
from dataclasses import dataclass


@dataclass(frozen=True)
class Command:
    """One parser (the program, or one of its subcommands) as the two files need it."""

    path: tuple[str, ...]  # () for the program, ("validate",) for a subcommand
    parser: argparse.ArgumentParser
    help: str


def _sub_actions(p: argparse.ArgumentParser) -> Iterator[argparse._SubParsersAction[argparse.ArgumentParser]]:
    for a in p._actions:
        if isinstance(a, argparse._SubParsersAction):
            yield a


def commands(p: argparse.ArgumentParser, path: tuple[str, ...] = (), help: str = "") -> list[Command]:
    """The program and each subcommand, depth first, in the parser's order."""
    out = [Command(path, p, help or (p.description or ""))]
    for sub in _sub_actions(p):
        helps = {c.dest: c.help or "" for c in sub._choices_actions}
        for name, child in sub.choices.items():
            out += commands(child, (*path, name), helps.get(name, ""))
    return out


def _options(p: argparse.ArgumentParser) -> list[argparse.Action]:
    return [a for a in p._actions if a.option_strings and a.help != argparse.SUPPRESS]


def _positionals(p: argparse.ArgumentParser) -> list[argparse.Action]:
    return [a for a in p._actions if not a.option_strings and not isinstance(a, argparse._SubParsersAction)
            and a.help != argparse.SUPPRESS]


def _takes_value(a: argparse.Action) -> bool:
    return a.nargs != 0


def _words(items: list[str]) -> str:
    return " ".join(items)


def bash(p: argparse.ArgumentParser) -> str:
    """A bash completion function: subcommands, their options, the choices of an option, else files."""
    prog = p.prog
    fn = "_" + re.sub(r"\W", "_", prog)
    cmds = commands(p)
    lines = [f"# bash completion for {prog}: written by `python -m cbf.shellfiles bash` from its argument parser.",
             f"{fn}() {{",
             "    local cur prev path i w",
             '    cur="${COMP_WORDS[COMP_CWORD]}"',
             '    prev="${COMP_WORDS[COMP_CWORD-1]}"',
             '    path=""',
             "    for ((i = 1; i < COMP_CWORD; i++)); do",
             '        w="${COMP_WORDS[i]}"',
             '        case "$path $w" in']
    for c in cmds:
        for sub in _sub_actions(c.parser):
            for name in sub.choices:
                lines.append(f'            "{" ".join(c.path)} {name}") path="{" ".join((*c.path, name))}" ;;')
    lines += ["        esac", "    done", '    case "$path" in']
    for c in cmds:
        opts = [s for a in _options(c.parser) for s in a.option_strings]
        subs = [n for sub in _sub_actions(c.parser) for n in sub.choices]
        value_cases = []
        for a in _options(c.parser):
            if not _takes_value(a):
                continue
            pats = "|".join(a.option_strings)
            if a.choices:
                words = _words([str(x) for x in a.choices])
                value_cases.append(f'                {pats}) COMPREPLY=($(compgen -W "{words}" -- "$cur")); return ;;')
            else:
                value_cases.append(f'                {pats}) COMPREPLY=($(compgen -f -- "$cur")); return ;;')
        lines.append(f'        "{" ".join(c.path)}")')
        if value_cases:
            lines += ['            case "$prev" in', *value_cases, "            esac"]
        lines += ['            if [[ "$cur" == -* ]]; then',
                  f'                COMPREPLY=($(compgen -W "{_words(opts)}" -- "$cur"))']
        if subs:
            lines += ["            else", f'                COMPREPLY=($(compgen -W "{_words(subs)}" -- "$cur"))']
        else:
            lines += ["            else", '                COMPREPLY=($(compgen -f -- "$cur"))']
        lines += ["            fi", "            ;;"]
    lines += ["    esac", "}", f"complete -o filenames -F {fn} {prog}", ""]
    return "\n".join(lines)


def _roff(text: str) -> str:
    """Text as roff: backslashes doubled, a leading dot or quote escaped, one line."""
    text = " ".join(str(text).split()).replace("\\", "\\e")
    text = text.replace("-", "\\-")
    return ("\\&" + text) if text[:1] in (".", "'") else text


def _expand(a: argparse.Action, p: argparse.ArgumentParser) -> str:
    if not a.help:
        return ""
    try:
        return p._get_formatter()._expand_help(a)
    except (KeyError, TypeError, ValueError):
        return a.help


def man(p: argparse.ArgumentParser, version: str = "") -> str:
    """A man page (section 1) of the program and every subcommand."""
    prog = p.prog
    out = [f'.TH "{prog.upper()}" "1" "" "{_roff(version)}" "User Commands"',
           ".SH NAME", f"{_roff(prog)} \\- {_roff((p.description or '').split('. ')[0].rstrip('.'))}",
           ".SH SYNOPSIS", ".nf", _roff(p.format_usage().replace("usage: ", "").strip()), ".fi",
           ".SH DESCRIPTION", _roff(p.description or "")]
    for c in commands(p):
        title = " ".join((prog, *c.path))
        if c.path:
            out += [f'.SH "{_roff(title.upper())}"', _roff(c.help), ".PP", ".nf",
                    _roff(c.parser.format_usage().replace("usage: ", "").strip()), ".fi"]
            if c.parser.description and c.parser.description != c.help:
                out += [".PP", _roff(c.parser.description)]
        elif _options(c.parser):
            out += [".SH OPTIONS"]
        for a in _positionals(c.parser):
            out += [".TP", f"\\fI{_roff(str(a.metavar or a.dest))}\\fR", _roff(_expand(a, c.parser))]
        for a in _options(c.parser):
            names = ", ".join(f"\\fB{_roff(s)}\\fR" for s in a.option_strings)
            if _takes_value(a):
                meta = a.metavar or ("{" + ",".join(map(str, a.choices)) + "}" if a.choices else a.dest.upper())
                names += f" \\fI{_roff(str(meta))}\\fR"
            out += [".TP", names, _roff(_expand(a, c.parser))]
    if p.epilog:
        out += [".SH EXIT STATUS", _roff(p.epilog)]
    return "\n".join(out) + "\n"


def _load(spec: str) -> Callable[[], argparse.ArgumentParser]:
    module, _, name = spec.partition(":")
    fn: Callable[[], argparse.ArgumentParser] = getattr(importlib.import_module(module), name or "parser")
    return fn


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m cbf.shellfiles",
                                 description="Write a bash completion script or a man page from a parser.")
    ap.add_argument("kind", choices=["bash", "man"])
    ap.add_argument("--parser", default="cbf.cli:parser", metavar="MODULE:FUNCTION",
                    help="the function that returns the argparse parser (default: %(default)s)")
    ap.add_argument("--version-text", default="", help="the man page's version line (default: the cbf version)")
    a = ap.parse_args(argv)
    p = _load(a.parser)()
    if a.kind == "bash":
        sys.stdout.write(bash(p))
    else:
        from .version import SPEC_REVISION, __version__

        sys.stdout.write(man(p, a.version_text or f"{__version__} (spec {SPEC_REVISION})"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
