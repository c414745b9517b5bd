"""Issue 15: the published docs say exactly what the model says.

Every expectation here is read from the model (cbfgen.loader.load), the
golden files or the emitter; each checker is also run on a planted fault to
show that it can fail.
"""

from __future__ import annotations

import re
import shutil
import struct
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import yaml
from conftest import load_yaml
from markdown_it import MarkdownIt

import cbfgen.emit.docs as docs
from cbfgen import prose
from cbfgen.emit.docs import golden, hexdump, svg, text
from cbfgen.loader import SpecError, load

REPO = Path(__file__).resolve().parents[1]
SPEC = load(REPO / "spec" / "cbf.yaml")
CASES = golden.load_cases(docs.GOLDEN)
SVG_NS = "{http://www.w3.org/2000/svg}"


@pytest.fixture(scope="module")
def md_pages() -> dict[str, str]:
    return {rel[len("docs/"):]: data.decode() for rel, data in docs.emit(SPEC).items() if rel.endswith(".md")}


def _free_texts() -> list[str]:
    """Every free text of the spec the docs print."""
    out = [SPEC.meta["doc"], SPEC.record.doc, SPEC.cut["doc"], *SPEC.units.values()]
    out += [t.doc for t in SPEC.types.values()] + [v.doc for v in SPEC.versions]
    out += [h.doc for h in SPEC.headers.values()] + [f.doc for h in SPEC.headers.values() for f in h.fields]
    out += [c.doc for c in SPEC.commands] + [a.doc for c in SPEC.commands for lay in c.layouts for a in lay.args]
    out += [k.fails for k in SPEC.checks] + [k.text for k in SPEC.checks]
    out += [n.text for n in SPEC.decisions + SPEC.errata + SPEC.history] + [d.evidence for d in SPEC.decisions]
    return [t for t in out if t]


# -- Markdown emphasis accidents ---------------------------------------------------

def emphasis_problems(html: str) -> list[str]:
    """Emphasis the pages never ask for: any <em> or <strong> is an accident of unescaped * or _."""
    return re.findall(r"<(?:em|strong)>[^<]*</(?:em|strong)>", html)


def test_no_emphasis_accident_in_any_page(html_site: Path) -> None:
    pages = sorted(html_site.rglob("*.html"))
    assert pages
    for p in pages:
        assert emphasis_problems(p.read_text(encoding="utf-8")) == [], p


def test_emphasis_checker_fails_on_an_unescaped_star() -> None:
    """The accident of issue 15: (118*255, 68*255) rendered as 118<em>255, 68</em>255."""
    md = MarkdownIt("commonmark")
    assert emphasis_problems(md.render("(118*255, 68*255, under 1.3e9)"))
    assert emphasis_problems(md.render(text.md_escape("(118*255, 68*255, under 1.3e9)"))) == []


def test_every_star_of_the_spec_survives_as_text(html_site: Path) -> None:
    """A free text with * or _ reaches the reader unchanged (after whitespace folding)."""
    body = " ".join(re.sub(r"<[^>]+>", "", (html_site / "index.html").read_text(encoding="utf-8")).split())
    import html as html_mod

    body = html_mod.unescape(body)
    starred = [t for t in _free_texts() if "*" in t and not re.search(r"\b(tolerances|limits)\.", t)]
    assert starred, "the spec has no text with * any more: pick another probe"
    for t in starred:
        flat = re.sub(r"\b([A-Z]\d+)\b", r"\1", " ".join(t.split()))
        assert flat in body, flat


# -- values, not keys ------------------------------------------------------------------

def test_tolerances_and_limits_appear_as_values_with_the_key_in_a_tooltip(html_site: Path) -> None:
    index = (html_site / "index.html").read_text(encoding="utf-8")
    visible = re.sub(r'title="[^"]*"', "", index)
    visible = re.sub(r"<code>.*?</code>", "", visible)
    for table, values in (("tolerances", SPEC.tolerances), ("limits", SPEC.limits)):
        for key in values:
            assert f"{table}.{key}" not in visible, key
            assert f'<abbr title="{table}.{key}">{text.quantity(SPEC, table, key)}</abbr>' in index, key


def test_a_key_reference_in_prose_becomes_its_value() -> None:
    key = next(iter(SPEC.tolerances))
    out = text.prose(SPEC, f"within tolerances.{key} of it")
    assert out == f"within {text.value_html(SPEC, 'tolerances', key)} of it"
    assert f"tolerances.{key}<" not in out


def test_decision_ids_link_to_the_decisions(md_pages: dict[str, str]) -> None:
    d = SPEC.decisions[0]
    assert text.prose(SPEC, f"see {d.id}.") == f"see [{d.id}](#decision-{d.id.lower()})."
    assert text.prose(SPEC, f"see {d.id}.", "../index.md") == f"see [{d.id}](../index.md#decision-{d.id.lower()})."
    index = md_pages["index.md"]
    for note in SPEC.decisions:
        assert f'<a id="decision-{note.id.lower()}"></a>' in index


def test_no_page_and_no_spec_text_cites_a_file_the_reader_lacks(md_pages: dict[str, str]) -> None:
    assert "FORMAT-NOTES" not in (REPO / "spec" / "cbf.yaml").read_text(encoding="utf-8")
    for page, body in md_pages.items():
        assert "FORMAT-NOTES" not in body, page


# -- the units table ---------------------------------------------------------------------

def test_units_table_refuses_unknown_keys(tmp_path: Path) -> None:
    """An unquoted comma in a unit's doc splits it into two keys: the schema refuses the second."""
    unit, doc = next(iter(SPEC.units.items()))
    raw = load_yaml(REPO / "spec" / "cbf.yaml")
    raw["units"][unit] = yaml.safe_load(f"{{doc: {doc}, 0 to 100}}")  # what the unquoted comma parses to
    assert set(raw["units"][unit]) == {"doc", "0 to 100"}
    path = tmp_path / "cbf.yaml"
    path.write_text(yaml.safe_dump(raw, sort_keys=False), encoding="utf-8")
    with pytest.raises(SpecError):
        load(path)


def test_unit_docs_reach_the_docs_whole(md_pages: dict[str, str]) -> None:
    for unit, doc in SPEC.units.items():
        assert f"| {text.md_escape(unit)} | {text.prose(SPEC, doc)} |" in md_pages["index.md"], unit


# -- revision and version ------------------------------------------------------------------

def test_every_page_names_the_spec_revision_and_toolkit_version(md_pages: dict[str, str], html_site: Path) -> None:
    from cbfgen import __version__

    stamp = f"Spec {SPEC.revision} · toolkit cbfgen {__version__}"
    for page, body in md_pages.items():
        assert stamp in body, page
    for p in html_site.rglob("*.html"):
        body = p.read_text(encoding="utf-8")
        assert SPEC.revision in body and f"cbfgen {__version__}" in body, p


# -- byte-field diagrams ----------------------------------------------------------------------

def unlabelled_boxes(svg_text: str) -> list[str]:
    """Every field box of a diagram with no text inside it, and every continuation piece not marked so."""
    root = ET.fromstring(svg_text.encode())
    problems = []
    for g in root.iter(f"{SVG_NS}g"):
        name = (g.findtext(f"{SVG_NS}title") or "").split(":")[0]
        rects = list(g.iter(f"{SVG_NS}rect"))
        texts = [(float(t.attrib["x"]), float(t.attrib["y"]), "".join(t.itertext())) for t in g.iter(f"{SVG_NS}text")]
        for k, r in enumerate(rects):
            x, y, w, h = (float(r.attrib[a]) for a in ("x", "y", "width", "height"))
            inside = [s for tx, ty, s in texts if x <= tx <= x + w and y <= ty <= y + h and s.strip()]
            if not inside:
                problems.append(f"{name}: box {k} at ({x}, {y}) has no label")
            elif k > 0 and not any("cont" in s or s.endswith("+") for s in inside):
                problems.append(f"{name}: box {k} continues the field but does not say so")
    return problems


def test_every_diagram_box_is_labelled() -> None:
    figures = docs.figures(SPEC)
    wrapped = 0
    for rel, body in figures.items():
        if rel == docs.MOTION_SVG:
            continue
        assert unlabelled_boxes(body) == [], rel
        wrapped += body.count("(cont.)")
    assert wrapped  # the model has fields that wrap a row; each piece says so


def test_label_checker_fails_on_an_unlabelled_box() -> None:
    field = SPEC.record.fields[0]
    good = svg.byte_field("t", [field], field.size)
    assert unlabelled_boxes(good) == []
    bad = re.sub(r"<text x=\"[^\"]*\" y=\"[^\"]*\" text-anchor=\"middle\">[^<]*</text>", "", good)
    assert unlabelled_boxes(bad)


def test_a_wrapped_field_names_itself_on_every_piece() -> None:
    """A field of 20 bytes on 16-byte rows: two boxes, the second 'name (cont.)'."""
    from cbfgen.model import Field

    f = Field(name="centre", type="f4", kind="float", offset=8, elem_size=4, count=5, doc="", line=0)
    body = svg.byte_field("t", [f], 28)
    assert "centre (cont.)" in body and unlabelled_boxes(body) == []


# -- annotated hex -------------------------------------------------------------------------

@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
def test_annotated_hex_covers_every_byte_once(case: golden.Case) -> None:
    runs = list(hexdump.runs(SPEC, case.data))
    pos = 0
    for run in runs:
        assert run.offset == pos, (run.label, run.offset, pos)
        assert case.data[run.offset:run.offset + len(run.data)] == run.data
        pos += len(run.data)
    assert pos == len(case.data)


def test_annotated_hex_lines_give_back_the_file() -> None:
    """The dump's byte column, read back, is the .cbf; its labels name the model's header fields."""
    # a line holds at most hexdump.ROW bytes: a longer file cannot dump to fewer lines than that
    # (the 65,535-record case was dumped whole only to be left out); each dump made once
    dumps = {c.name: hexdump.dump(SPEC, c.data) for c in CASES
             if c.data and len(c.data) < golden.MAX_LINES * hexdump.ROW}
    small = [c for c in CASES if c.name in dumps and dumps[c.name].count("\n") < golden.MAX_LINES]
    assert small
    for case in small:
        dump = dumps[case.name]
        back = bytearray()
        for line in dump.splitlines():
            off, hexpart = int(line[:8], 16), line[10:10 + 3 * hexdump.ROW - 1].split()
            assert off == len(back), (case.name, line)
            back += bytes(int(b, 16) for b in hexpart)
        assert bytes(back) == case.data, case.name
        header = SPEC.header_for(hexdump.version_of(SPEC, case.data))
        for f in header.fields:
            if f.end <= len(case.data):
                assert f"header {f.name} = " in dump, (case.name, f.name)


def test_annotated_hex_names_each_record_field() -> None:
    case = next(c for c in CASES if c.name.startswith("valid.") and c.decode_ok)
    dump = hexdump.dump(SPEC, case.data)
    for rec in hexdump.records(SPEC, case.data):
        assert rec.command is not None and rec.layout is not None
        for f in SPEC.record.fields + rec.layout.args:
            assert f"#{rec.index} {rec.command.name} {f.name}" in dump


def test_case_pages_show_hex_not_assembler_source(md_pages: dict[str, str]) -> None:
    for case in CASES:
        page = md_pages[docs.case_page(case.name)]
        assert ("\u2502 header " in page) == bool(case.data), case.name
        assert "include _header" not in page and "set vmaj" not in page


# -- examples on command pages -----------------------------------------------------------------

def test_every_command_in_a_valid_case_has_an_example(md_pages: dict[str, str]) -> None:
    examples = golden.examples(SPEC, CASES)
    seen = {r.command.name for c in CASES if c.name.startswith("valid.") and c.decode_ok
            for r in hexdump.records(SPEC, c.data) if r.command is not None}
    assert seen and seen <= set(examples)
    for name, ex in examples.items():
        page = md_pages[docs.command_page(SPEC.command(name))]
        assert f"({'../' + docs.case_page(ex.case)})" in page
        assert ex.cut in page and ex.hex in page


def test_example_cut_lines_agree_with_the_cut_writer() -> None:
    """The docs write CUT lines from the model's cut section; the Python binding's writer must agree."""
    from cbf.codec import decode
    from cbf.cut import to_cut

    examples = golden.examples(SPEC, CASES)
    assert examples
    for ex in examples.values():
        case = next(c for c in CASES if c.name == ex.case)
        lines = to_cut(decode(case.data)).splitlines()
        assert ex.cut in lines, (ex.case, ex.record, ex.cut)


def test_shortest_float_round_trips() -> None:
    for value in (0.1, 1e-7, 123456.789, -0.0, 3.0):
        bits = struct.unpack("<I", struct.pack("<f", value))[0]
        s = hexdump.shortest_float(bits)
        assert "e" not in s
        assert struct.unpack("<I", struct.pack("<f", float(s)))[0] == bits


# -- traceability ------------------------------------------------------------------------------

def test_traceability_keeps_pass_not_expressible_and_fail_apart(monkeypatch: pytest.MonkeyPatch,
                                                                 tmp_path: Path) -> None:
    check = SPEC.checks[0]
    cases = ["case.a", "case.b", "case.c"]
    report = {"bindings": {"x": {"available": True, "results": {
        "case.a": {"status": "pass"}, "case.b": {"status": "fail"}, "case.c": {"status": "fail"}}}},
        "cases": {n: {"checks": [check.id]} for n in cases}}
    (tmp_path / "x.txt").write_text("# Why each one fails:\n#   case.b: cannot compute sums\ncase.b decode: x\n",
                                    encoding="utf-8")
    monkeypatch.setattr(docs, "FAILURES", tmp_path)
    row = docs._traceability(SPEC, report)[0]
    assert row["status"]["x"] == {"pass": 1, "not expressible": 1, "fail": 1, "not run": 0}
    assert docs.known_failures("x")[1] == ["case.b: cannot compute sums"]


def test_matrix_never_says_fail_for_a_listed_limitation(md_pages: dict[str, str]) -> None:
    index = md_pages["index.md"]
    matrix = index[index.index('<a id="traceability-matrix"></a>'):index.index('<a id="binding-limits"></a>')]
    rows = docs._traceability(SPEC, docs._report())
    fails = sum(st["fail"] for r in rows for st in r["status"].values())
    assert matrix.count("FAIL ") == sum(1 for r in rows for st in r["status"].values() if st["fail"])
    assert fails == 0 or "FAIL" in matrix
    assert "<details><summary>" in matrix  # a long case list folds


# -- CUT keyword table, field index ----------------------------------------------------------------

def test_cut_table_has_every_layout(md_pages: dict[str, str]) -> None:
    page = md_pages[docs.CUT_PAGE]  # the companion document (issue 26)
    table = page[page.index('<a id="cut-commands"></a>'):page.index('<a id="cut-version"></a>')]
    for c in SPEC.commands:
        kw = c.name.lower() if SPEC.cut["keyword_case"] == "lower" else c.name
        for lay in c.layouts:
            assert f"| [`{kw}`]({docs.command_page(c)}) | {lay.variant or 'primary'}" in table, (c.name, lay.variant)
            assert f"| {', '.join(lay.versions)} |" in table


def test_field_index_lists_every_field_and_check(md_pages: dict[str, str]) -> None:
    page = md_pages[docs.FIELD_INDEX]
    names = {f.name for h in SPEC.headers.values() for f in h.fields} | {f.name for f in SPEC.record.fields}
    names |= {a.name for c in SPEC.commands for lay in c.layouts for a in lay.args}
    names |= {k.id for k in SPEC.checks} | {c.name for c in SPEC.commands}
    for n in names:
        assert f"| `{n}` |" in page, n


# -- free text agrees with the data (issue 12 point 6) -------------------------------------------------

def _facts() -> prose.Facts:
    return prose.Facts(SPEC.versions, SPEC.checksums, SPEC.default_version, SPEC.fallback_version)


def test_free_text_agrees_with_the_model() -> None:
    """Version ids, writable versions and 'byte sum' claims in free text (rendered) must match the data;
    each stale sentence is named with its fix (a fact placeholder: cbfgen.prose)."""
    stale = [p for i, t in enumerate(_free_texts()) for p in prose.stale(f"free text {i} ({t[:40]!r}...)", t, _facts())]
    assert not stale, "\n".join(stale)
    for v in SPEC.versions:
        assert ("read only" in v.doc) == (not v.writable), v.id


def test_a_stale_sentence_is_named_with_its_fix() -> None:
    """The prose check can fail: a sentence naming writers' versions by hand, one version short, and a
    version the spec lacks, are each reported with the placeholder that fixes them."""
    writable = [v.id for v in SPEC.writable_versions]
    said = prose.stale("N9", f"Writers emit {' and '.join(writable[:-1] or ['0.0'])}.", _facts())
    assert len(said) == 1 and "{{writable_versions}}" in said[0], said
    gone = 1 + max(v.major for v in SPEC.versions)
    assert any(f"{gone}.x" in p for p in prose.stale("N10", f"{gone}.x is readable.", _facts()))
    assert any(f"{gone}.0" in p for p in prose.stale("N9", f"Version {gone}.0 forbids ARC.", _facts()))
    assert prose.stale("C1", prose.render("{{checksum_algorithms}} Writers emit {{writable_versions}}.", _facts()),
                       _facts()) == []


# -- the browser check can fail ----------------------------------------------------------------------

@pytest.mark.skipif(not shutil.which("chromium"), reason="Debian chromium not installed (make docs-check)")
def test_browser_check_fails_on_overflow_broken_image_and_console(tmp_path: Path) -> None:
    from cbfgen.emit.docs import browser
    from cbfgen.emit.docs.cdp import Browser

    head = '<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>t</title></head><body>'
    pages = {
        "ok.html": head + "<p>fits</p></body></html>",
        "wide.html": head + '<div style="width:900px">too wide at 390 px</div></body></html>',
        "wider.html": head + '<div style="width:1400px">too wide at 1280 px</div></body></html>',
        "image.html": head + '<img src="none.svg" alt="x"></body></html>',
        "console.html": head + "<script>console.log('hello')</script></body></html>",
    }
    for name, body in pages.items():
        (tmp_path / name).write_text(body, encoding="utf-8")
    chromium = browser.chromium()
    assert chromium
    with Browser(chromium) as b:
        assert browser.check_page(b, tmp_path / "ok.html", "ok.html") == []
        assert browser.check_page(b, tmp_path / "wide.html", "wide.html", (1280,)) == []
        assert any("@390px: horizontal overflow" in p for p in browser.check_page(b, tmp_path / "wide.html", "w"))
        # measured at 1280 after the 390 px load: the resize is seen
        assert any("@1280px: horizontal overflow" in p for p in browser.check_page(b, tmp_path / "wider.html", "w"))
        assert any("image not loaded" in p for p in browser.check_page(b, tmp_path / "image.html", "i", (1280,)))
        assert any("console" in p and "hello" in p
                   for p in browser.check_page(b, tmp_path / "console.html", "c", (1280,)))


def test_pdf_check_fails_when_the_contents_do_not_match_the_pages() -> None:
    from cbfgen.emit.docs.pdf import _key, verify

    texts = ["Contents A 2 B 3", "A\nchapter one", "B chapter two"]
    outline = [(_key("A"), 2), (_key("B"), 3)]
    assert verify("r.pdf", ["A", "B"], ["2", "3"], outline, texts) == []
    assert verify("r.pdf", ["A", "B"], ["2", "2"], outline, texts) == ["r.pdf: 'B' is on page 3, the contents say 2"]
    assert verify("r.pdf", ["A", "C"], ["2", "3"], outline, texts) == ["r.pdf: 'C' is on page None, the contents say 3"]
    assert verify("r.pdf", ["A", "B"], ["2", "3"], [(_key("A"), 2), (_key("B"), 2)], texts) != []
    assert verify("r.pdf", ["Profiles"], ["2"], [(_key("Profiles"), 2)], ["Contents", "Pro\ufb01les here"]) == []
    assert verify("r.pdf", ["Profiles"], ["1"], [(_key("Profiles"), 1)], ["Contents", "Profiles"]) != []


def test_pdf_check_fails_on_a_dangling_link_and_a_printed_navigation_line() -> None:
    from cbfgen.emit.docs.pdf import dangling, navigation_printed

    assert dangling('<a id="x"></a><a href="#x">x</a>') == []
    assert len(dangling('<a id="x"></a><a href="#y">y</a><a href="other.html">o</a>')) == 2
    assert navigation_printed(["300071 rev 03 · golden cases"], ["a page", "text"]) == []
    assert navigation_printed(["300071 rev 03 · golden cases"], ["x 300071 rev 03 · golden\ncases y"]) != []


@pytest.mark.skipif(not shutil.which("chromium"), reason="Debian chromium not installed (make docs-check)")
def test_pdf_check_fails_on_a_page_left_mostly_blank_by_a_forced_break(tmp_path: Path) -> None:
    """A page that ends after one line because the next starts on a new page is mostly blank, unless a
    part ends there; a page whose text reaches its foot is not. pdftotext (poppler-utils) is installed with
    chromium (.ci/setup-debian.sh): its absence fails here, not skips."""
    from cbfgen.emit.docs import browser
    from cbfgen.emit.docs.cdp import Browser
    from cbfgen.emit.docs.pdf import BLANK, blank_pages, pdf_pages

    doc = ('<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>t</title></head><body>'
           '<p>alpha, one line</p><div style="break-before: page; height: 220mm; display: flex; '
           'align-items: flex-end">beta, at the foot of its page</div>'
           '<p style="break-before: page">gamma, one line</p></body></html>')
    (tmp_path / "d.html").write_text(doc, encoding="utf-8")
    chromium = browser.chromium()
    assert chromium
    with Browser(chromium) as b:
        b.open((tmp_path / "d.html").resolve().as_uri(), 800, 1000)
        b.pdf(tmp_path / "d.pdf", "<span>page footer</span>", "<span>page header</span>")
    pages = pdf_pages(tmp_path / "d.pdf")
    assert [t for _, t in pages] == ["alpha, one line", "beta, at the foot of its page", "gamma, one line"]
    fills = [f for f, _ in pages]
    assert fills[0] < BLANK < fills[1] and fills[2] < BLANK
    assert blank_pages(fills, {2, 3}) == []  # pages 1 and 2 end parts, page 3 ends the document
    assert [p.split(" is ")[0] for p in blank_pages(fills, {3})] == ["page 1"]
    # a page that opens with a table's caption starts a table kept whole: the page before it may end early
    assert blank_pages(fills, {3}, frozenset({2})) == []


def test_pdf_places_every_page_of_the_site(monkeypatch: pytest.MonkeyPatch) -> None:
    """The PDF holds what the site holds: every Markdown page the docs emitter writes is in the PDF's
    order; a page it does not name stops the PDF (no silent gap)."""
    from cbfgen.emit.docs import pdf

    placed = {path for path, _ in pdf.site_pages(SPEC)}
    assert placed == {rel[len("docs/"):-3] + ".html" for rel in docs.emit(SPEC) if rel.endswith(".md")}
    real = docs.emit  # what pdf.py imported from the docs emitter
    monkeypatch.setattr(pdf, "emit", lambda spec, ctx=None: {**real(spec, ctx), "docs/extra.md": b"# Extra\n"})
    with pytest.raises(pdf.Unplaced, match="extra.md"):
        pdf.site_pages(SPEC)


def test_pdf_names_a_repository_file_it_does_not_hold() -> None:
    """A link of a site page to a repository file (copied under files/) becomes text in the PDF that names
    the file where its label does not, so the paper refers only to what it holds or to a named file."""
    from cbfgen.emit.docs.pdf import Page, _localise

    body = ('<p><a href="files/conformance/golden/README.html">the golden README</a>, '
            '<a href="files/spec/cbf.yaml.html"><code>spec/cbf.yaml</code></a>, <a href="cut.html#x">CUT</a></p>')
    out = _localise(Page("index.html", "", body), {"index.html": "", "cut.html": "cut"})
    assert "the golden README (<code>conformance/golden/README.md</code>)" in out
    assert "<code>spec/cbf.yaml</code>, " in out and "spec/cbf.yaml</code>)" not in out
    assert '<a href="#cut-x">CUT</a>' in out and "files/" not in out
