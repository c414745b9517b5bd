"""Text and names from the spec, made safe for the code and documents they land in.

Every emitter writes spec text (docs, units, titles, clauses) into some target language. This module
holds ONE escaping function per target, and the one rule for names (`keyword_clash`). Each function
takes any str (quotes, backslashes, comment markers, newlines, control and non-ASCII characters)
and returns text that the target reads back as the original, or, where a target has no way to
carry a character (a comment cannot contain its own terminator), a visible stand-in that changes
no other character. Registered as jinja filters in render.py (the name in brackets).

- `c_comment` [c_comment]: inside ``/* ... */`` or after ``//``.
- `c_string` [c_str]: a complete C string literal, quotes included.
- `py_docstring` [py_doc]: the body of a ``\"\"\"...\"\"\"`` docstring; its value is the text.
- `py_string` [py_str]: a complete Python string literal, quotes included.
- `kaitai_doc` [ksy_doc]: a .ksy `doc` or `doc-ref` value that ksc 0.11 copies, unescaped, into
  Python docstrings, JavaScript/Java/Go ``/** */`` comments and Java ``@see "..."``.
- `yaml_scalar` [yaml_str]: a complete YAML flow scalar (double-quoted), one line.
- `toml_string` [toml_str]: a complete TOML basic string, quotes included.
- `json_string` [json_str]: a complete JSON string, quotes included (also a JavaScript literal).
- `line_comment` [line_comment]: text after ``#`` or ``//`` (Python, TOML, YAML, Go, go.mod).
- `xml_comment` [xml_comment]: text inside ``<!-- ... -->``.
- `markdown_inline` [md]: Markdown (CommonMark/GFM) inline text, one line.
- `markdown_cell` [md_cell]: a GFM table cell.
- `html_text` [html]: HTML text or a quoted attribute value.
- `one_line` [one_line]: whitespace runs (newlines included) collapsed to one space.
"""

from __future__ import annotations

import html
import json
import keyword
import re
import unicodedata

import yaml

__all__ = [
    "NAME_MAX",
    "RESERVED",
    "RESERVED_MEMBERS",
    "c_comment",
    "c_string",
    "html_text",
    "json_string",
    "kaitai_doc",
    "keyword_clash",
    "line_comment",
    "markdown_cell",
    "markdown_inline",
    "one_line",
    "py_docstring",
    "py_string",
    "toml_string",
    "xml_comment",
    "yaml_scalar",
]


def one_line(text: str) -> str:
    """Every run of whitespace (newlines, tabs, U+2028 ...) becomes one space; ends stripped."""
    return " ".join(text.split())


def _no_surrogates(text: str) -> str:
    """A lone surrogate (no UTF-8 or JSON carries one) becomes U+FFFD."""
    return "".join("\ufffd" if unicodedata.category(ch) == "Cs" else ch for ch in text)


def _visible(ch: str) -> str:
    """A control or invisible separator as escape-like text: \\x07, \\u2028."""
    n = ord(ch)
    return f"\\x{n:02x}" if n < 0x100 else f"\\u{n:04x}" if n < 0x10000 else f"\\U{n:08x}"


def _is_plain(ch: str) -> bool:
    """A character any UTF-8 source file carries as itself: printable, or a space (not a control,
    a format character, a surrogate or a line/paragraph separator)."""
    return ch == " " or (ch.isprintable() and unicodedata.category(ch) not in ("Cs", "Zl", "Zp"))


# -- C --------------------------------------------------------------------------------------------

def c_comment(text: str) -> str:
    """Text safe inside a C block comment and a line comment, lines kept.

    ``*/`` would end the comment and ``/*`` inside one trips ``-Werror=comment``: a space goes
    between their characters. ``??`` starts a trigraph (``??/`` is a backslash, so a line
    splice): ``?`` ``?`` is written ``? ?``. A line ending in a backslash would splice the next
    line into a ``//`` comment, even with spaces after it: the backslash is followed by ``.``. Control
    characters become ``\\xNN`` text. Non-ASCII stays (the headers are UTF-8).
    """
    lines = []
    for raw in text.replace("\r\n", "\n").replace("\r", "\n").split("\n"):
        line = "".join(ch if _is_plain(ch) or ch == "\t" else _visible(ch) for ch in _no_surrogates(raw)).rstrip()
        while "*/" in line or "/*" in line:
            line = line.replace("*/", "* /").replace("/*", "/ *")
        while "??" in line:
            line = line.replace("??", "? ?")
        if line.endswith("\\"):
            line += "."
        lines.append(line)
    return "\n".join(lines)


_C_ESCAPES = {"\\": "\\\\", '"': '\\"', "?": "\\?", "\n": "\\n", "\r": "\\r", "\t": "\\t"}


def c_string(text: str) -> str:
    """A C string literal (quotes included) whose bytes are the text's UTF-8 encoding.

    Quotes, backslashes and ``?`` (trigraphs) are escaped; every byte outside printable ASCII is an
    octal escape of three digits (never ``\\x``, which would swallow a following hex digit).
    """
    out = ['"']
    for byte in _no_surrogates(text).encode("utf-8"):
        ch = chr(byte)
        if ch in _C_ESCAPES:
            out.append(_C_ESCAPES[ch])
        elif 0x20 <= byte < 0x7F:
            out.append(ch)
        else:
            out.append(f"\\{byte:03o}")
    out.append('"')
    return "".join(out)


# -- Python ---------------------------------------------------------------------------------------

_PY_NAMED = {"\n": "\\n", "\r": "\\r", "\t": "\\t"}


def _py_char(ch: str) -> str:
    if ch in _PY_NAMED:
        return _PY_NAMED[ch]
    n = ord(ch)
    return f"\\x{n:02x}" if n < 0x100 else f"\\u{n:04x}" if n < 0x10000 else f"\\U{n:08x}"


def py_docstring(text: str) -> str:
    """The body of a ``\"\"\"...\"\"\"`` literal whose value is exactly the text.

    Backslashes are doubled; a ``"`` is escaped where it would close the literal (next to another
    ``"`` or at the end); controls, carriage returns, surrogates and line separators are escapes.
    Newlines stay real newlines. (Python 3.13 strips a docstring's common indentation when it
    compiles it, as ``inspect.cleandoc`` does: the value is the text up to that.)
    """
    body = "".join(ch if _is_plain(ch) or ch in "\n\t" else _py_char(ch) for ch in text.replace("\\", "\\\\"))
    # Escaping a control above wrote a backslash into body; doubling came first, so it is single.
    return re.sub(r'"(?=")|"$', r'\\"', body)


def py_string(text: str) -> str:
    """A double-quoted Python str literal (quotes included) whose value is the text, on one line."""
    out = ['"']
    for ch in text:
        if ch in '\\"':
            out.append("\\" + ch)
        elif _is_plain(ch):
            out.append(ch)
        else:
            out.append(_py_char(ch))
    out.append('"')
    return "".join(out)


# -- Kaitai ---------------------------------------------------------------------------------------

def kaitai_doc(text: str) -> str:
    """A .ksy `doc` / `doc-ref` value safe in every ksc 0.11 target the project compiles.

    ksc copies the text verbatim (checked for 0.11.0): into a Python ``\"\"\"`` docstring (lines
    indented), into ``/** ... */`` comments for JavaScript, Java and Go (`` * `` before each line),
    and into ``@see "..."`` for a Java/Go doc-ref. Hence, on one line (whitespace collapsed):

    - a backslash is doubled: Python reads it back as one; in Java an even run of backslashes
      cannot start a ``\\uXXXX`` escape (which javac applies inside comments too);
    - ``*/`` is written ``*\\x2f``: it ends no comment, and the Python docstring reads ``*/``;
    - a ``"`` that would close the Python docstring is ``\\"``;
    - controls (NUL, which Python and Go refuse, ...) become ``\\xNN``, and format characters (a
      BOM, which Go refuses mid-file; bidi controls) ``\\N{NAME}``: the Python docstring reads them
      back; a lone surrogate, which neither UTF-8 nor JSON carries, becomes U+FFFD.

    The Python parser's docstrings therefore hold the original text; the comments of the other
    targets show it with doubled backslashes.
    """
    out = []
    for ch in one_line(text):
        category = unicodedata.category(ch)
        if ch == "\\":
            out.append("\\\\")
        elif category == "Cs":
            out.append("\ufffd")
        elif category == "Cc":
            out.append(f"\\x{ord(ch):02x}")
        elif category == "Cf":  # never \uXXXX, which javac would read; \N{NAME} is Python's own
            name = unicodedata.name(ch, "")
            out.append(f"\\N{{{name}}}" if name else "\ufffd")
        else:  # printable, or unassigned / private use: UTF-8 carries it into every target
            out.append(ch)
    body = "".join(out).replace("*/", "*\\x2f")
    return re.sub(r'"(?=")|"$', r'\\"', body)


# -- data and documents ---------------------------------------------------------------------------

def yaml_scalar(text: str) -> str:
    """A double-quoted YAML scalar (one line) that every YAML 1.1/1.2 reader reads as the text."""
    dumped = yaml.dump(text, Dumper=yaml.SafeDumper, default_style='"', width=float("inf"), allow_unicode=True)
    return dumped.removesuffix("\n...\n").removesuffix("\n")


def toml_string(text: str) -> str:
    """A TOML basic string (quotes included) whose value is the text."""
    out = ['"']
    for ch in _no_surrogates(text):
        if ch in '\\"':
            out.append("\\" + ch)
        elif ch in _PY_NAMED:
            out.append(_PY_NAMED[ch])
        elif _is_plain(ch):
            out.append(ch)
        else:
            n = ord(ch)
            out.append(f"\\u{n:04X}" if n < 0x10000 else f"\\U{n:08X}")
    out.append('"')
    return "".join(out)


def json_string(text: str) -> str:
    """A JSON string (quotes included) whose value is the text; ASCII only, so that it is also a
    JavaScript string literal whatever the engine (U+2028) and whatever the file's encoding."""
    return json.dumps(_no_surrogates(text), ensure_ascii=True)


def line_comment(text: str) -> str:
    """Text for a line comment (``#``, ``//``): one line, whitespace collapsed, no control or
    format character (a NUL or a BOM, which Go and TOML refuse): U+FFFD instead."""
    return "".join(ch if _is_plain(ch) else "\ufffd" for ch in _no_surrogates(one_line(text)))


def xml_comment(text: str) -> str:
    """Text inside ``<!-- ... -->``: one line, no ``--`` (XML forbids it in a comment), no ``-``
    last, no character XML 1.0 refuses."""
    body = line_comment(text)
    while "--" in body:
        body = body.replace("--", "- -")
    return body + " " if body.endswith("-") else body


# The ASCII punctuation that starts inline markup anywhere in a line (CommonMark and GFM: escapes,
# code, emphasis, links and images, autolinks and raw HTML, entities, tables, strikethrough, math).
# `(`, `)` and `!` are special only after `]` / before `[`, both escaped here.
_MD_SPECIAL = re.compile(r"([\\`*_\[\]<>|~&$])")
# What is special only at the start of a line: headings, lists, block quotes, thematic breaks.
_MD_LINE_START = re.compile(r"^([#+=-]|\d+[.)])")


def markdown_inline(text: str) -> str:
    """Markdown inline text that renders as the text: one line (whitespace collapsed), every markup
    character backslash-escaped, and a leading ``#``/``-``/``+``/``=``/``1.`` too, so that the text
    may also start a line."""
    shown = "".join(ch if _is_plain(ch) else "\ufffd" for ch in _no_surrogates(one_line(text)))
    escaped = _MD_SPECIAL.sub(r"\\\1", shown)
    return _MD_LINE_START.sub(lambda m: m.group(1)[:-1] + "\\" + m.group(1)[-1], escaped)


def markdown_cell(text: str) -> str:
    """A GFM table cell: inline Markdown (``|`` escaped too); a cell has no newline."""
    return markdown_inline(text)


def html_text(text: str) -> str:
    """HTML text, or an attribute value in quotes: ``& < > " '`` as references (so no
    ``</script>`` or tag can start); controls other than tab/newline dropped to U+FFFD."""
    cleaned = "".join(ch if _is_plain(ch) or ch in "\n\t" else "\ufffd" for ch in _no_surrogates(text))
    return html.escape(cleaned, quote=True)


# -- names ----------------------------------------------------------------------------------------

_C = """auto break case char const continue default do double else enum extern float for goto if inline
int long register restrict return short signed sizeof static struct switch typedef union unsigned void
volatile while _Bool _Complex _Imaginary _Alignas _Alignof _Atomic _Generic _Noreturn _Static_assert
_Thread_local bool true false nullptr alignas alignof static_assert thread_local typeof typeof_unqual
constexpr NULL errno assert main"""
_CPP = """and and_eq asm bitand bitor catch class compl concept const_cast consteval constinit co_await
co_return co_yield decltype delete dynamic_cast explicit export friend mutable namespace new noexcept not
not_eq operator or or_eq private protected public reinterpret_cast requires static_cast template this
throw try typeid typename using virtual wchar_t char8_t char16_t char32_t xor xor_eq"""
_JAVA = """abstract assert boolean break byte case catch char class const continue default do double else
enum extends final finally float for goto if implements import instanceof int interface long native new
package private protected public return short static strictfp super switch synchronized this throw
throws transient try void volatile while true false null var yield record sealed permits"""
_JS = """break case catch class const continue debugger default delete do else export extends false
finally for function if import in instanceof new null return super switch this throw true try typeof var
void while with yield let static enum await implements package protected interface private public
arguments eval undefined NaN Infinity constructor prototype"""
_GO = """break case chan const continue default defer else fallthrough for func go goto if import
interface map package range return select struct switch type var nil iota true false"""
# Kaitai Struct's expression language: operators and literals, and the names ksc gives every type.
_KAITAI = "and or not true false as sizeof bitsizeof _io _root _parent _index _on _is_le _sizeof _"
# Python: hard and soft keywords (`None`, `True`: a command NONE's layout class is `None`); the soft
# keywords of 3.12 named here, so that the rule does not change with the Python that runs cbfgen.
_PYTHON = " ".join([*keyword.kwlist, *keyword.softkwlist, "_", "case", "match", "type"])

# Language keywords: no spelling of any spec name (command, argument, header or record field) may
# be one of them.
RESERVED: dict[str, frozenset[str]] = {
    "Python": frozenset(_PYTHON.split()),
    "C": frozenset(_C.split()),
    "C++": frozenset((_C + " " + _CPP).split()),
    "Java": frozenset(_JAVA.split()),
    "JavaScript": frozenset(_JS.split()),
    "Go": frozenset(_GO.split()),
    "Kaitai": frozenset(_KAITAI.split()),
}

# Members the generated classes already have, beside which an argument or field becomes one more
# member: found by compiling ksc's parsers with each name as an argument (javac: "wait() in ArgsCutter
# cannot override wait() in Object"; go: "field and method with the same name Read"; Python:
# `self.close = ...` hides KaitaiStruct.close), and the codec's own class bodies (a dataclass field
# named `bytes` hides `bytes(6)`, the default of a later field).
RESERVED_MEMBERS: dict[str, frozenset[str]] = {
    "Java (java.lang.Object)": frozenset(
        "clone equals finalize getClass hashCode notify notifyAll toString wait".split()),
    "Python (kaitaistruct.KaitaiStruct)": frozenset("close from_file from_bytes from_io".split()),
    "Go (the Kaitai parser's Read method)": frozenset({"Read"}),
    "the generated code": frozenset(
        "bytes int float str bool tuple dict list type object CODE NAME VARIANT SIZE LAYOUT ClassVar dataclass "
        "IntEnum annotations".split()),
}


def _forms(name: str, what: str | None) -> set[str]:
    """The spellings the bindings give a spec name. A command: as written (Python enum member), lower
    (Kaitai enum id), UPPER (Java/JavaScript enum constant), CamelCase (its layout classes, e.g.
    `None`). A field: as written (Python, C, Kaitai), CamelCase (Go), lowerCamel (JavaScript
    property, Java getter)."""
    parts = [p for p in re.split(r"[_\W]+", name) if p]
    camel = "".join(p[:1].upper() + p[1:].lower() for p in parts)
    lower_camel = (parts[0].lower() + camel[len(parts[0]):]) if parts else name
    command = {name, name.lower(), name.upper(), camel}
    field = {name, name.lower(), camel, lower_camel}
    return command if what == "command" else field if what == "field" else command | field


# The longest spec name (command, argument, field, check id) every binding takes: C99 (5.2.4.1)
# guarantees 63 significant initial characters of an identifier, and the C binding's tables hold the
# names in string literals, which its strict build bounds (-Woverlength-strings: 4,095).
NAME_MAX = 63


def keyword_clash(name: str, *, what: str | None = None) -> str | None:
    """None when the spec name is safe as an identifier in every binding; otherwise why not, e.g.
    ``'class' is reserved in C++, Java, JavaScript, Python``.

    ``what`` is "command" (a command name) or "field" (an argument, header or record field); None
    (the default) checks the name as both, the strictest. The loader refuses such a name (with its
    YAML line) rather than renaming it: one spelling in every binding, the spec's, and no renaming
    rule for each binding to get wrong. Every spelling a binding derives from the name is checked
    (`_forms`) against every language's keywords (RESERVED): `NONE` is refused because its class
    is `None`, `default` because Java, JavaScript, Go and C reserve it; a field also against the
    members its class already has (RESERVED_MEMBERS): `wait`, `read`, `close`, `bytes`.
    """
    if what not in (None, "command", "field"):
        raise ValueError(f"what: {what!r} is not 'command', 'field' or None")
    forms = _forms(name, what)
    tables = [RESERVED] if what == "command" else [RESERVED, RESERVED_MEMBERS]
    hits: list[str] = []
    spelled: set[str] = set()
    for table in tables:
        for lang, words in table.items():
            if forms & words:
                hits.append(lang)
                spelled |= forms & words
    if not hits:
        return None
    as_ = ", ".join(sorted(f"'{s}'" for s in spelled - {name}))
    return f"{name!r}{f' (as {as_})' if as_ else ''} is reserved in {', '.join(sorted(hits))}"
