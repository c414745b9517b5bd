"""Text and names from the spec never break the code they land in (issue #24 point 6).

Hostile text (quotes, backslash escapes, comment markers, trigraphs, markup, newlines, controls,
non-ASCII) goes into the real spec's docs: a command's, an argument's, a header field's, a check's,
a decision's, and the title. The Python codec must import with the text as its docstrings'
values; the .ksy must compile with ksc for every target, its Python and JavaScript parsers must
parse (per example), its Go parser must parse (gofmt, per example) and its Java parser hold no
Unicode escape (per example), and the Java and Go parsers compile (once, on the worst text).
Names reserved in any binding's language are refused with their YAML line; the spec reader
refuses alias bombs and deep nesting in one line, exit 2, fast.

escape.py's functions are also checked on their own against each target's reader (ast, yaml,
tomllib, html, markdown-it, gcc).
"""

from __future__ import annotations

import ast
import html
import inspect
import json
import os
import re
import shutil
import subprocess
import sys
import time
import tomllib
import types
from collections.abc import Iterator
from pathlib import Path
from typing import Any
from xml.dom import minidom

import pytest
import yaml
from conftest import HYPOTHESIS_PROFILE, REPO, dump_yaml, spec_doc
from hypothesis import Phase, example, given, settings
from hypothesis import strategies as st

from cbfgen import escape, prose
from cbfgen.emit import kaitai as kaitai_emit
from cbfgen.emit import python as python_emit
from cbfgen.loader import MAX_DEPTH, MAX_NODES, SpecError, load
from cbfgen.model import camel

# Each piece breaks some target when written raw: Python (\x, \u, \N{, """, a closing "),
# C and JS/Java/Go comments (/*, */), C (??/ trigraph, a trailing backslash), Java (\u in a
# comment), HTML (</script>, &), Markdown (`, |, *, [, #, 1.), YAML/TOML (": ", "#", quotes).
HOSTILE = ['"""', '"', "'''", "'", "\\x", "\\u", "\\U0001", "\\N{", "\\", "\\\\u0041", "/*", "*/", "//",
           "??/", "??=", "</script>", "<b>", "&amp;", "`", "``", "|", "*", "_", "[x](y)", "# ", "1. ", "- ",
           "{{ x }}", "{%", "${x}", "%s", "@see", ": ", " #", "\n", "\r\n", "\t", "\x07", "\x1b", "\x7f",
           "é", "€", "😀", "\u2028", "\ufeff", "\u202e"]
WORST = "".join(HOSTILE)
HAVE_NODE = (REPO / "node_modules" / "kaitai-struct-compiler").exists() and shutil.which("node") is not None
KSC_TARGETS = ("python", "javascript", "java", "go")


def hostile_text() -> st.SearchStrategy[str]:
    piece = st.sampled_from(HOSTILE) | st.text(st.characters(codec="utf-8", exclude_categories=["Cs"]),
                                               max_size=4)
    return st.lists(piece, min_size=1, max_size=10).map("".join).filter(lambda t: bool(t.strip()))


# -- escape.py against each target's own reader ---------------------------------------------------

TEXT = st.text(st.characters(codec="utf-8", exclude_categories=["Cs"]), max_size=40) | hostile_text()


@given(TEXT)
@example(WORST)
def test_python_literals_read_back_as_the_text(text: str) -> None:
    assert ast.literal_eval(escape.py_string(text)) == text
    assert "\n" not in escape.py_string(text)
    assert ast.literal_eval('"""' + escape.py_docstring(text) + '"""') == text
    # a docstring body next to more text, as the templates compose them
    assert ast.literal_eval('"""' + escape.py_docstring(text) + " Offset 4." + '"""') == text + " Offset 4."


@given(TEXT)
@example(WORST)
def test_data_formats_read_back_as_the_text(text: str) -> None:
    assert yaml.safe_load(escape.yaml_scalar(text)) == text
    assert "\n" not in escape.yaml_scalar(text)
    assert tomllib.loads("d = " + escape.toml_string(text))["d"] == text
    assert html.unescape(escape.html_text(text)) == "".join(
        "\ufffd" if c not in "\n\t" and not escape._is_plain(c) else c for c in text)
    assert "<" not in escape.html_text(text) and '"' not in escape.html_text(text)
    assert json.loads(escape.json_string(text)) == text and escape.json_string(text).isascii()
    shown = "".join(c if escape._is_plain(c) else "\ufffd" for c in escape.one_line(text))
    assert escape.line_comment(text) == shown
    comment = minidom.parseString(f"<a><!--{escape.xml_comment(text)}--></a>").documentElement.firstChild
    assert isinstance(comment, minidom.Comment) and comment.data.replace("- -", "--").strip() == shown.strip()


@given(TEXT)
@example(WORST)
@example("1. item")
@example("# heading")
@example("- list")
@example("a | b")
@example("<http://x>")
def test_markdown_renders_as_the_text(text: str) -> None:
    from markdown_it import MarkdownIt

    md = MarkdownIt("commonmark").enable("table").enable("strikethrough")
    shown = escape.one_line("".join(c if escape._is_plain(c) or c.isspace() else "\ufffd" for c in text))
    rendered = md.render(escape.markdown_inline(text)).strip()
    if shown:
        assert rendered.startswith("<p>") and rendered.endswith("</p>"), rendered  # no heading, list, quote
        assert html.unescape(rendered[3:-4]) == shown
    # a table cell: one row, one cell, holding the text
    table = md.render(f"| h |\n|---|\n| {escape.markdown_cell(text)} |\n")
    cells = re.findall(r"<td>(.*?)</td>", table, re.S)
    assert [html.unescape(c) for c in cells] == [shown]


@pytest.mark.skipif(shutil.which("gcc") is None, reason="no gcc")
def test_c_comments_and_strings_compile_and_read_back(tmp_path: Path) -> None:
    """One gcc run over many texts: comments pass -Werror=comment with trigraphs on, and each
    string literal's bytes are the text's UTF-8."""
    texts = [WORST, *HOSTILE, "a\\", "ends in ??", "x */ y /* z", "\\\n", "??/\n"]
    body = []
    for i, t in enumerate(texts):
        body.append(f"/* {escape.c_comment(t)} */")
        body.extend(f"// {line}" for line in escape.c_comment(t).split("\n"))
        body.append(f"static const char s{i}[] = {escape.c_string(t)};")
    body.append("#include <stdio.h>\nint main(void) {")
    body.extend(f'  fwrite(s{i}, 1, sizeof s{i} - 1, stdout); putchar(0);' for i in range(len(texts)))
    body.append("  return 0;\n}")
    src = tmp_path / "t.c"
    src.write_text("\n".join(body) + "\n", encoding="utf-8")
    subprocess.run(["gcc", "-std=c99", "-trigraphs", "-Wall", "-Wextra", "-Werror", "-Werror=comment",
                    "-o", str(tmp_path / "t"), str(src)], check=True, capture_output=True, text=True)
    out = subprocess.run([str(tmp_path / "t")], check=True, capture_output=True).stdout
    assert out.split(b"\0")[:-1] == [t.encode() for t in texts]


@given(TEXT)
@example(WORST)
@example("\\u000a")
@example("\\\\u")
@example('x"')
def test_kaitai_doc_reads_back_in_python_and_holds_no_java_unicode_escape(text: str) -> None:
    k = escape.kaitai_doc(text)
    assert "*/" not in k and "\n" not in k
    assert ast.literal_eval('"""' + k + '"""') == escape.one_line(text)
    assert not _java_unicode_escape(k), k


def _java_unicode_escape(src: str) -> bool:
    """JLS 3.3: a backslash preceded by an even number of backslashes, then u, is a Unicode escape
    (javac reads it everywhere, comments included)."""
    return re.search(r"(?<!\\)(\\\\)*\\u", src) is not None


# -- names ----------------------------------------------------------------------------------------

def _refused(tmp: Path, doc: dict[str, Any], needle: str) -> SpecError:
    text = dump_yaml(doc, sort_keys=False, width=200)
    path = tmp / "cbf.yaml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(SpecError) as info:
        load(path)
    lines = [i for i, line in enumerate(text.splitlines(), 1) if re.search(needle, line)]
    assert info.value.line in lines, (str(info.value), lines)
    assert "reserved in" in info.value.message
    return info.value


def _renamed(node: Any, old: str, new: str) -> Any:
    """The data with every string equal to old (a name and its references) replaced by new."""
    if isinstance(node, dict):
        return {k: _renamed(v, old, new) for k, v in node.items()}
    if isinstance(node, list):
        return [_renamed(v, old, new) for v in node]
    return new if node == old else node


@pytest.mark.parametrize("name", ["NONE", "TRUE", "CLASS"])
def test_a_command_name_reserved_in_a_binding_is_refused(tmp_path: Path, name: str) -> None:
    doc = spec_doc()
    err = _refused(tmp_path, _renamed(doc, doc["commands"][-1]["name"], name), rf"name: '?{name}'?$")
    assert repr(name) in err.message


# class/new/default: keywords; none: its Go/Python class is None; bytes: the codec's class bodies call
# bytes(); wait, get_class: java.lang.Object's final methods (javac refuses the getters); read: the
# Go parser's Read method; close: kaitaistruct.KaitaiStruct.close.
@pytest.mark.parametrize("name", ["class", "new", "default", "none", "bytes", "wait", "get_class", "read", "close"])
def test_an_argument_name_reserved_in_a_binding_is_refused(tmp_path: Path, name: str) -> None:
    doc = spec_doc()
    cmd = next(c for c in doc["commands"] if c["layouts"][0]["args"])
    arg = cmd["layouts"][-1]["args"][-1]
    old = arg["name"]
    arg["name"] = name
    for section in ("motion", "orientation", "shape", "cutter"):  # keep references valid
        for k, v in (cmd.get(section) or {}).items():
            if v == old:
                cmd[section][k] = name
    if cmd.get("progress") == old:
        cmd["progress"] = name
    err = _refused(tmp_path, doc, rf"name: {name}\b")
    assert repr(name) in err.message


def test_keyword_clash_names_the_languages() -> None:
    assert escape.keyword_clash("line_x") is None
    # a command's spellings are NAME, name, Name: WAIT is no Java getter, READ no Go field
    assert escape.keyword_clash("WAIT", what="command") is None and escape.keyword_clash("READ", what="command") is None
    assert escape.keyword_clash("wait", what="field") and escape.keyword_clash("read", what="field")
    assert escape.keyword_clash("WAIT")  # unqualified: the strictest, command and field alike
    assert "Python" in (escape.keyword_clash("NONE") or "")
    assert {"Java", "JavaScript", "C++"} <= set(re.findall(r"[\w+]+", escape.keyword_clash("new") or ""))
    # the spec's own names are all fine (else the real spec would not load)
    load(REPO / "spec" / "cbf.yaml")


# -- the spec reader's bounds -------------------------------------------------------------------

def _bomb(levels: int) -> str:
    lines = ["a0: &a0 [x, x, x, x, x, x, x, x, x]"]
    lines += [f"a{i}: &a{i} [" + ", ".join([f"*a{i - 1}"] * 9) + "]" for i in range(1, levels)]
    return "\n".join(lines) + "\n"


BAD_YAML = {
    "alias_bomb": (_bomb(12), rf"more than {MAX_NODES:,} nodes"),
    "deep_flow": ("a: " + "[" * 1000 + "]" * 1000 + "\n", f"nested more than {MAX_DEPTH} deep"),
    "deep_block": ("".join("  " * i + f"k{i}:\n" for i in range(1000)) + "  " * 1000 + "v: 1\n",
                   f"nested more than {MAX_DEPTH} deep"),
}


@pytest.mark.parametrize("case", sorted(BAD_YAML))
def test_the_spec_reader_refuses_bombs_fast_in_one_line(tmp_path: Path, case: str) -> None:
    text, message = BAD_YAML[case]
    path = tmp_path / f"{case}.yaml"
    path.write_text(text, encoding="utf-8")
    start = time.process_time()
    with pytest.raises(SpecError) as info:
        load(path)
    assert time.process_time() - start < 0.5
    assert re.search(message, info.value.message) and info.value.line >= 1
    spec = str(REPO / "spec" / "cbf.yaml")
    runs = [["--check-spec", "--spec", str(path)], ["diff", spec, str(path)]]
    if case == "alias_bomb":  # every entry point reads through load(): each once is enough
        runs += [["--spec", str(path), "--out", str(tmp_path / "out")], ["diff", str(path), spec]]
    for argv in runs:
        res = subprocess.run([sys.executable, "-m", "cbfgen", *argv], cwd=REPO, capture_output=True, text=True,
                             timeout=20)
        assert res.returncode == 2, (argv, res.stderr)
        assert res.stdout == "" and res.stderr.count("\n") == 1, res.stderr
        assert f"{path}:{info.value.line}: " in res.stderr and re.search(message, res.stderr)
    assert not (tmp_path / "out").exists()


def test_the_bounds_hold_without_libyaml(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    """The same reader over PyYAML's pure-Python parser (a Python without libyaml): the same
    refusals, and the real spec still loads."""
    from cbfgen import loader
    from cbfgen.loader import yaml_reader

    pure = type("PureLoader", (yaml_reader.BoundedComposer, yaml.SafeLoader),
                {"yaml_constructors": loader.Loader.yaml_constructors})
    monkeypatch.setattr(loader, "Loader", pure)
    for case, (text, message) in BAD_YAML.items():
        (tmp_path / f"{case}.yaml").write_text(text, encoding="utf-8")
        with pytest.raises(SpecError, match=message):
            load(tmp_path / f"{case}.yaml")
    assert load(REPO / "spec" / "cbf.yaml").commands


def test_aliases_within_the_bounds_still_load(tmp_path: Path) -> None:
    """The bounded composer keeps what YAML means: an anchored doc and its alias read the same, and
    a bomb one level smaller than the bound is not refused by the bound."""
    # The spec's node graph, not its text (a revised spec is dumped in another style): the second command's
    # doc node is made the first's, so the serializer writes it once with an anchor and then an alias.
    root = yaml.compose((REPO / "spec" / "cbf.yaml").read_text(encoding="utf-8"))
    commands = next(v for k, v in root.value if k.value == "commands")
    first, second = [c for c in commands.value if any(k.value == "doc" for k, _ in c.value)][:2]

    def field(command: yaml.MappingNode, key: str) -> Any:
        return next(v for k, v in command.value if k.value == key)

    first_doc, second_doc = field(first, "doc").value, field(second, "doc").value
    second.value = [(k, field(first, "doc") if k.value == "doc" else v) for k, v in second.value]
    text = yaml.serialize(root)
    assert re.search(r"^ *doc: &\w+ ", text, re.M) and re.search(r"^ *doc: \*\w+$", text, re.M), "no anchor"
    (tmp_path / "a.yaml").write_text(text, encoding="utf-8")
    spec = load(tmp_path / "a.yaml")
    assert spec.command(field(second, "name").value).doc == first_doc != second_doc
    levels = next(n for n in range(1, 20) if 9 ** (n + 1) > MAX_NODES)  # 9**levels <= MAX_NODES
    (tmp_path / "b.yaml").write_text(_bomb(levels), encoding="utf-8")
    with pytest.raises(SpecError) as info:
        load(tmp_path / "b.yaml")
    assert "nodes" not in info.value.message  # refused later, by the schema, not by the bound


# -- hostile text through the real spec into every binding --------------------------------------

KSC_WORKER = r"""
'use strict';
const ksc = require(process.argv[2]);
const vm = require('vm');
const readline = require('readline');
const rl = readline.createInterface({ input: process.stdin });
rl.on('line', async (line) => {
  const ksy = JSON.parse(line);
  const out = { files: {}, errors: [] };
  for (const lang of process.argv.slice(3)) {
    try {
      const files = await ksc.compile(lang, ksy, null, false);
      out.files[lang] = Object.values(files).join('\n');
      if (lang === 'javascript') new vm.Script(out.files[lang]);
    } catch (e) {
      out.errors.push(lang + ': ' + (e && e.stack ? e.stack.split('\n')[0] : JSON.stringify(e)));
    }
  }
  process.stdout.write(JSON.stringify(out) + '\n');
});
"""


class Ksc:
    """One node process running ksc for every example (its start-up is most of a compile)."""

    def __init__(self, folder: Path) -> None:
        script = folder / "ksc_worker.js"
        script.write_text(KSC_WORKER, encoding="utf-8")
        self.proc = subprocess.Popen(
            ["node", str(script), str(REPO / "node_modules" / "kaitai-struct-compiler"), *KSC_TARGETS],
            stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True, encoding="utf-8")

    def compile(self, ksy: dict[str, Any]) -> dict[str, str]:
        assert self.proc.stdin is not None and self.proc.stdout is not None
        self.proc.stdin.write(json.dumps(ksy) + "\n")
        self.proc.stdin.flush()
        out = json.loads(self.proc.stdout.readline())
        assert not out["errors"], out["errors"]
        files: dict[str, str] = out["files"]
        return files

    def close(self) -> None:
        assert self.proc.stdin is not None
        self.proc.stdin.close()
        self.proc.wait(timeout=10)


@pytest.fixture(scope="module")
def ksc(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Ksc]:
    if not HAVE_NODE:
        pytest.skip("kaitai-struct-compiler not installed (make kaitai-setup)")
    worker = Ksc(tmp_path_factory.mktemp("ksc"))
    yield worker
    worker.close()


def hostile_spec(text: str) -> tuple[dict[str, Any], dict[str, str]]:
    """The real spec with the text in one doc of each kind; returns it and where each went."""
    doc = spec_doc()
    cmd = next(c for c in doc["commands"] if c["layouts"][0]["args"])
    arg = cmd["layouts"][0]["args"][0]
    header = next(iter(doc["headers"].values()))
    field = header["fields"][-1]
    header["doc"] = cmd["layouts"][0]["doc"] = text  # a header's and a layout's own doc
    check = next(c for c in doc["checks"] if c["kind"] not in ("magic", "code_copy", "arg_size", "availability"))
    cmd["doc"] = arg["doc"] = field["doc"] = check["text"] = text
    # A decision's text may name a fact by placeholder ({{name}}, cbfgen.prose), rendered at load; any
    # other '{{' or '}}' there is refused (bad spec prose_unknown_fact). The decision gets the text with
    # those pairs spaced ("{ {"), so it still carries '{', '}', '{%' and the rest to every emitter.
    decision = text
    while "{{" in decision or "}}" in decision:
        decision = decision.replace("{{", "{ {").replace("}}", "} }")
    assert not prose.unknown(decision)
    doc["decisions"][0]["decision"] = decision
    doc["meta"]["title"] = doc["meta"]["document"] = text  # the title reaches packages, the document a doc-ref
    return doc, {"command": cmd["name"], "arg": arg["name"], "field": field["name"], "check": str(check["id"]),
                 "header": next(iter(doc["headers"]))}


def _string_constants(tree: ast.AST) -> list[str]:
    return [n.value for n in ast.walk(tree) if isinstance(n, ast.Constant) and isinstance(n.value, str)]


def check_python_codec(spec: Any, text: str, where: dict[str, str], folder: Path) -> None:
    files = python_emit.emit(spec)
    layouts = files[f"{python_emit.PKG}/layouts.py"].decode()
    tree = ast.parse(layouts)
    module = types.ModuleType("cbf_layouts_under_test")
    sys.modules[module.__name__] = module  # dataclasses look their module up
    try:
        exec(compile(tree, "layouts.py", "exec"), module.__dict__)  # the module imports
    finally:
        del sys.modules[module.__name__]
    value = text.strip()  # the loader strips docs
    # the docstrings' values hold the text itself (attribute docstrings: as ast reads them)
    strings = _string_constants(tree)
    assert value in strings, "CommandCode member docstring"
    assert any(s.startswith(value + " Offset ") for s in strings), "argument/field docstring"
    cls: Any = next(c for c in vars(module).values() if isinstance(c, type) and getattr(c, "NAME", None)
               == where["command"])
    node = next(n for n in ast.walk(tree) if isinstance(n, ast.ClassDef) and n.name == cls.__name__)
    raw = ast.get_docstring(node, clean=False)
    assert raw is not None and raw.startswith(f"{where['command']} (0x{cls.CODE:02X}): {value}\n")
    # Class.__doc__ is that value (Python 3.13 on: as inspect.cleandoc gives it)
    assert cls.__doc__ == (raw if sys.version_info < (3, 13) else inspect.cleandoc(raw))
    assert f"\n\n    {value}\n" in raw  # the layout's own doc
    header_class = f"Header{camel(where['header'])}"
    header = next(n for n in ast.walk(tree) if isinstance(n, ast.ClassDef) and n.name == header_class)
    assert (ast.get_docstring(header, clean=False) or "").startswith(value + "\n")
    assert module.__doc__ is not None and module.__doc__.startswith(f"Typed layouts of {text} (")
    description = tomllib.loads(files["python/pyproject.toml"].decode())["project"]["description"]
    assert description.startswith(text + " (")


def check_kaitai(spec: Any, text: str, ksc: Ksc) -> dict[str, str]:
    files = kaitai_emit.emit(spec)
    as_json = json.loads(files[f"{kaitai_emit.OUT}/cbf.ksy.json"])  # what ksc_driver.js compiles
    # the .ksy says the same (a user compiles that one)
    assert json.loads(json.dumps(yaml.safe_load(files[f"{kaitai_emit.OUT}/cbf.ksy"]))) == as_json
    out = ksc.compile(as_json)
    tree = ast.parse(out["python"])  # the Kaitai Python parser parses (JavaScript: vm.Script in the worker)
    flat = escape.one_line(text)
    assert any(flat in s for s in _string_constants(tree)), "the text in a Kaitai Python docstring"
    assert not _java_unicode_escape(out["java"])
    check_kaitai_packages(spec, text)
    if shutil.which("gofmt"):
        res = subprocess.run(["gofmt", "-e", "-l"], input=out["go"], capture_output=True, text=True)
        assert res.returncode == 0, res.stderr[:500]
    return out


def check_kaitai_packages(spec: Any, title: str) -> None:
    """The packages' metadata carry the spec's title and stay well-formed."""
    files = {k.removeprefix(f"{kaitai_emit.OUT}/"): v.decode() for k, v in kaitai_emit.emit(spec).items()}
    shown = "".join(c if escape._is_plain(c) or c in "\n\t" else "\ufffd" for c in title)  # as html_text
    pom = minidom.parseString(files["java/pom.xml"])
    description = pom.getElementsByTagName("description")[0].firstChild
    assert isinstance(description, minidom.Text) and description.data.startswith(
        f"Kaitai Struct Java parser of the {shown} (")
    assert json.loads(files["javascript/package.json"])["description"].startswith(
        f"Kaitai Struct JavaScript parser of the {title} (")
    assert tomllib.loads(files["python/pyproject.toml"])["project"]["description"].startswith(
        f"Kaitai Struct parser of the {title} (")
    init = ast.parse(files["python/cbf_kaitai/__init__.py"])
    assert (ast.get_docstring(init, clean=False) or "").startswith(f"Kaitai Struct parser of the {title} (")
    gomod = files["go/go.mod"].splitlines()
    assert gomod[0].startswith("// ") and gomod[1].startswith("module ")


EXAMPLES = 12 if HYPOTHESIS_PROFILE == "ci" else 200


# Each example costs about 0.3 CPU s (ksc, gofmt): no shrinking, which could take minutes; the cheap
# tests above shrink what escape.py gets wrong.
@settings(max_examples=EXAMPLES, phases=(Phase.explicit, Phase.reuse, Phase.generate))
@given(text=hostile_text())
@example(text=WORST)
def test_hostile_docs_reach_every_binding_intact(text: str, ksc: Ksc, tmp_path_factory: pytest.TempPathFactory) -> None:
    folder = tmp_path_factory.mktemp("hostile")
    doc, where = hostile_spec(text)
    path = folder / "cbf.yaml"
    path.write_text(dump_yaml(doc, sort_keys=False, allow_unicode=True), encoding="utf-8")
    spec = load(path)
    check_python_codec(spec, text, where, folder)
    check_kaitai(spec, text, ksc)


def test_hostile_docs_compile_in_java_and_go(ksc: Ksc, tmp_path: Path) -> None:
    """Once, on the text with every hostile piece: the Kaitai Java and Go parsers compile."""
    java_jar = REPO / "build" / "kaitai-java" / "lib" / "kaitai-struct-runtime-0.11.jar"
    go_build = REPO / "build" / "kaitai-go"
    doc, _ = hostile_spec(WORST)
    path = tmp_path / "cbf.yaml"
    path.write_text(dump_yaml(doc, sort_keys=False, allow_unicode=True), encoding="utf-8")
    out = check_kaitai(load(path), WORST, ksc)
    ran = []
    if java_jar.exists() and shutil.which("javac"):
        package = kaitai_emit.JAVA_PACKAGE
        src = tmp_path / "java" / "Cbf.java"
        src.parent.mkdir()
        src.write_text(re.sub(r"^(.*\n)", rf"\1\npackage {package};\n", out["java"], count=1), encoding="utf-8")
        res = subprocess.run(["javac", "-nowarn", "-encoding", "UTF-8", "--release", "11", "-d",
                              str(tmp_path / "classes"), "-cp", str(java_jar), str(src)],
                             capture_output=True, text=True)
        assert res.returncode == 0, res.stderr[-2000:]
        ran.append("java")
    if (go_build / "go.mod").exists() and shutil.which("go"):
        work = tmp_path / "go"
        (work / "cbf").mkdir(parents=True)
        for name in ("go.mod", "go.sum", "main.go"):
            shutil.copy(go_build / name, work / name)
        go_src = out["go"] if re.search(r"^package ", out["go"], re.M) else "package cbf\n\n" + out["go"]
        (work / "cbf" / "cbf.go").write_text(go_src, encoding="utf-8")
        testee = kaitai_emit.emit(load(path))[f"{kaitai_emit.OUT}/go-testee/testee.go"]
        (work / "cbf" / "testee.go").write_bytes(testee)
        res = subprocess.run(["go", "build", "-o", "testee", "."], cwd=work, capture_output=True, text=True,
                             env={**os.environ, "GOFLAGS": "-mod=readonly", "GOPROXY": "off"})
        assert res.returncode == 0, res.stderr[-2000:]
        ran.append("go")
    # the whole codec package, as a user imports it, in its own interpreter
    for rel, data in python_emit.emit(load(path)).items():
        (tmp_path / "py" / rel).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / "py" / rel).write_bytes(data)
    probe = ("import sys, cbf, cbf.layouts as L; "
             "sys.stdout.write(L.__doc__ + '\\0' + '\\0'.join(c.__doc__ for c in L.ARGS_CLASSES.values()))")
    raw = subprocess.run([sys.executable, "-c", probe], capture_output=True, cwd=tmp_path,  # bytes: \r stays
                         env={**os.environ, "PYTHONPATH": str(tmp_path / "py" / "python"), "PYTHONIOENCODING": "utf-8"})
    assert raw.returncode == 0, raw.stderr[-2000:]
    module_doc, *class_docs = raw.stdout.decode("utf-8").split("\0")
    assert module_doc.startswith(f"Typed layouts of {WORST} (") and any(WORST.strip() in d for d in class_docs)
    if not ran:
        pytest.skip("neither the Kaitai Java runtime nor the Go build folder is here (make conformance builds them)")

