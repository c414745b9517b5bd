"""The workbench page in a real browser (issue 34, point 4): headless Chromium (playwright-core,
Debian's chromium) opens the page from file:// and is fed every golden file (and each other profile
on the files that profile judges otherwise). It must print exactly what native `cbf-c validate`
prints for the same file name (stdout, stderr, exit status); make no request but its own file;
refuse a fetch() from inside it (the Content-Security-Policy); not overflow at 390 px or 1280 px;
and one keyboard selection of a finding must mark its record row and its byte. Screenshots of that
selection go to build/workbench/ (the closing note shows them).

One page build and one browser for the whole file: the wasm module is make's (mk/wasm.mk)."""

from __future__ import annotations

import functools
import gzip
import json
import math
import re
import shutil
import subprocess
from pathlib import Path

import pytest
from c_programs import built

from cbf import codec
from cbf import geometry as G
from cbf.cut import to_cut
from cbf.errors import CbfError
from cbfgen.emit.docs import golden as docs_golden
from cbfgen.emit.docs import workbench
from cbfgen.loader import load
from cbfgen.model import Spec

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "conformance" / "golden"
WASM = REPO / "build" / "wasm" / "cbf-c.wasm"
SHOTS = REPO / "build" / "workbench"
DRIVER = Path(__file__).resolve().parent / "workbench" / "drive.mjs"


@pytest.fixture(scope="module")
def run(tmp_path_factory: pytest.TempPathFactory) -> dict[str, object]:
    if not (REPO / "node_modules" / "playwright-core").is_dir():
        pytest.fail("playwright-core is not installed: run make (npm ci)")
    if shutil.which("chromium") is None:
        pytest.fail("chromium is not installed (CBF_WANT_CHROMIUM=1 .ci/setup-debian.sh)")
    subprocess.run(["make", "-s", "-C", str(REPO), "build/wasm/cbf-c.wasm"], check=True, capture_output=True)
    spec = load(REPO / "spec" / "cbf.yaml")
    tmp = tmp_path_factory.mktemp("workbench")
    page = tmp / workbench.PAGE
    page.write_text(workbench.page(spec, WASM.read_bytes()), encoding="utf-8")
    profiles = [p.id for p in spec.profiles]
    files = sorted(GOLDEN.glob("*.cbf"))
    # a failing file whose first finding names a record: its row and its bytes light up with it
    firsts = {f: _native(f, profiles[0]) for f in files}
    failing = [f for f, (text, status) in firsts.items() if status == 1 and "(record " in text.split("\n", 1)[0]]
    # ... one whose record is a motion (the spec's role) in a toolpath of more than one: its segment too
    motions = {c.name: {a for k, a in c.motion.items() if k != "kind"} for c in spec.commands if c.motion}
    drawn = [f for f in failing if _motion_record(f, firsts[f][0], motions)]
    assert files and failing and drawn
    jobs = tmp / "jobs.json"
    # every file under the first profile; each other profile on the files it judges differently (the
    # page passes the profile on; the engine's profiles are the conformance suite's to test), at most 8
    feed = [(f, profiles[0]) for f in files]
    for p in profiles[1:]:
        feed += [(f, p) for f in files if _native(f, p) != firsts[f]][:8]
    # the file of the most drawn motion records (its Tab stops are paged), and an arc in the x-y plane
    paths = {f: _drawn(f) for f in files if _native(f, profiles[0])[1] != 2}
    paged = max(paths, key=lambda f: len(paths[f]))
    curve = _flat_arc(files)
    cuts = _cut_files(spec, tmp / "cut", files)
    jobs.write_text(json.dumps({"files": [[str(f), p] for f, p in feed], "shot": str(drawn[0]), "paged": str(paged),
                                "curve": [str(curve[0]), curve[1]], "cuts": [str(c) for c in cuts]}))
    SHOTS.mkdir(parents=True, exist_ok=True)
    res = subprocess.run(["node", str(DRIVER), str(page), str(SHOTS), str(jobs)], cwd=REPO, capture_output=True,
                         text=True, timeout=600)
    assert res.returncode == 0, res.stderr[-3000:]
    out: dict[str, object] = json.loads(res.stdout)
    out["expected"] = len(feed)
    out["page"] = str(page)
    out["circle"] = [*curve[2], curve[3]]
    return out


def _cut_files(spec: Spec, folder: Path, files: list[Path]) -> list[Path]:
    """The golden CUT forms to drop onto the page (the docs' complete example and each command's example
    line, cbfgen.emit.docs.golden; the CUT text Python writes for each valid golden file), and last one
    the engine refuses (its first keyword line's keyword made unknown)."""
    folder.mkdir()
    cases = docs_golden.load_cases(GOLDEN)
    example = docs_golden.cut_example(spec, cases)
    assert example is not None
    texts = {f"example.{example[0]}": example[1]}
    data = {c.name: c.data for c in cases}
    vkw = spec.cut["extensions"]["version_keyword"]
    for name, ex in docs_golden.examples(spec, cases).items():
        major, minor = codec.decode(data[ex.case]).version
        texts[f"line.{name}"] = f"{vkw} {major}.{minor}\n{ex.cut}\n"
    for f in files:
        if f.name.startswith("valid."):
            try:
                texts[f.stem] = to_cut(codec.decode(f.read_bytes()))
            except (CbfError, ValueError):
                continue
    kws = {c.name.lower() for c in spec.commands}
    lines = example[1].split("\n")
    k = next(i for i, line in enumerate(lines) if line.split(" ", 1)[0] in kws)
    unknown = next(w for w in (f"no_command_{n}" for n in range(100)) if w not in kws)
    texts["zz.refused"] = "\n".join(lines[:k] + [f"{unknown} {lines[k].partition(' ')[2]}"] + lines[k + 1:])
    out = []
    for name, text in texts.items():
        out.append(folder / f"{name}.cut")
        out[-1].write_text(text, encoding="ascii")
    return out


def _drawn(path: Path) -> list[str]:
    """The records `cbf-c dump --path` draws (the engine's toolpath, which the page draws)."""
    res = subprocess.run([str(_cbf_c()), "dump", "--path", path.name], cwd=path.parent, capture_output=True, text=True)
    return [line.split(" ", 1)[0] for line in res.stdout.splitlines()]


def _flat_arc(files: list[Path]) -> tuple[Path, int, tuple[float, float], float]:
    """A golden file's arc through a middle point (the spec's motion role) turning in the x-y plane: the
    file, the record, the circle's centre (x, y) and radius, as the Python codec's geometry has them."""
    for f in files:
        try:
            steps = list(G.walk(codec.decode(f.read_bytes())))
        except CbfError:
            continue
        for s in steps:
            c = s.curve
            if (c is not None and c.curved and s.cmd.motion is not None and "through" in s.cmd.motion
                    and c.e1[2] == 0.0 and c.e2[2] == 0.0):
                return f, s.index, (c.center[0], c.center[1]), c.radius
    raise AssertionError("no golden file has an arc in the x-y plane")


@functools.cache
def _cbf_c() -> Path:
    return built("cbf-c")


def _motion_record(path: Path, text: str, motions: dict[str, set[str]]) -> bool:
    """The first finding's record is a motion record of the file whose arguments cbf-c dump decodes, and the
    file has another."""
    record = text.split("(record ", 1)[1].split(")", 1)[0]
    dump = subprocess.run([str(_cbf_c()), "dump", path.name], cwd=path.parent, capture_output=True, text=True)
    rows = [line.split(" ", 3) for line in dump.stdout.splitlines()[1:]]
    moving = [r[0] for r in rows if len(r) > 3 and r[2] in motions
              and any(f"{a}=" in r[3].partition(" | ")[2] for a in motions[r[2]])]
    return record in moving and len(moving) > 1


@functools.cache
def _native(path: Path, profile: str) -> tuple[str, int]:
    """What cbf-c validate prints for the file under its own name (run in its folder), and its status."""
    res = subprocess.run([str(_cbf_c()), "validate", "--max-findings", "0", "--profile", profile, path.name],
                         cwd=path.parent, capture_output=True, text=True)
    return res.stdout + res.stderr, res.returncode


def test_the_page_prints_what_cbf_c_prints_for_every_golden_file(run: dict[str, object]) -> None:
    results = run["results"]
    assert isinstance(results, list) and len(results) == run["expected"]
    differ = []
    for r in results:
        text, status = _native(Path(r["path"]), r["profile"])
        if (r["text"], r["status"]) != (text, status):
            differ.append(f"{Path(r['path']).name} [{r['profile']}]: page {r['status']} {r['text']!r}, "
                          f"cbf-c {status} {text!r}")
    assert not differ, "\n".join(differ[:5])


def test_nothing_leaves_the_page(run: dict[str, object]) -> None:
    assert run["requests"] == [run["url"]], "the page asked for more than itself"
    fetched = run["fetched"]
    assert isinstance(fetched, list) and fetched and all(f.endswith(" refused") for f in fetched), fetched
    errors = run["errors"]
    assert isinstance(errors, list)
    assert all("Content Security Policy" in e for e in errors), errors  # only the refusals asked for


def test_a_finding_selected_by_keyboard_marks_its_record_and_byte_at_390_and_1280_px(run: dict[str, object]) -> None:
    # its segment in both views (top and side)
    assert run["selected"] == {"finding": 1, "row": 1, "hit": 1, "segments": 2}
    widths = run["widths"]
    assert isinstance(widths, dict)
    for w in ("390", "1280"):
        assert widths[w] <= int(w), f"the page overflows at {w} px: {widths[w]} px wide"
        assert (SHOTS / f"workbench-{w}.png").stat().st_size > 0


def test_a_segment_of_the_toolpath_selected_by_click_or_keyboard_selects_its_record(run: dict[str, object]) -> None:
    picked = run["picked"]
    assert isinstance(picked, list) and [p["how"] for p in picked] == ["click", "keyboard"]
    for p in picked:
        assert p["row"] == p["want"], p
        assert p["hex"].startswith(f"record {p['want']} "), p
        assert p["segments"] == [p["want"], p["want"]], p


def test_an_arc_is_drawn_on_its_circle_not_as_its_chord(run: dict[str, object]) -> None:
    # the top view's path of the record: "Mx -y Lx -y ..." (the page draws y downwards)
    drawn = run["curve"]
    assert isinstance(drawn, list) and len(drawn) == 1, drawn
    points = [tuple(float(v) for v in p.strip().split(" ")) for p in re.split("[ML]", drawn[0]) if p.strip()]
    circle = run["circle"]
    assert isinstance(circle, list)
    cx, cy, r = (float(v) for v in circle)
    assert len(points) > 2, f"the arc is drawn as {len(points) - 1} straight segment(s)"
    for x, y in points:
        assert math.isclose(math.hypot(x - cx, -y - cy), r, rel_tol=1e-6, abs_tol=1e-6), (x, y)


def test_the_toolpaths_tab_stops_are_paged_with_the_records(run: dict[str, object]) -> None:
    paged = run["paged"]
    assert isinstance(paged, list)
    first, second = paged
    for stops in (first, second):
        assert stops["tabbable"] and set(stops["tabbable"]) <= set(stops["rows"]), stops["tabbable"][:5]
    assert not set(first["tabbable"]) & set(second["tabbable"])
    assert int(first["segments"]) > len(first["tabbable"]) + len(second["tabbable"])


def test_the_3d_view_turns_zooms_and_shares_the_selection(run: dict[str, object]) -> None:
    three = run["three"]
    assert isinstance(three, dict)
    home = three["shared"]
    assert home["selected"] != "" and home["selected"] == home["row"], home  # the other views' selection
    keys = three["keyboard"]
    assert keys["yaw"] != home["yaw"] and keys["pitch"] != home["pitch"] and float(keys["zoom"]) > float(home["zoom"])
    after = three["next"]  # ] : the motion record after the selected one, selected everywhere
    assert after["selected"] == after["row"] and int(after["selected"]) > int(home["selected"]), after
    mouse = three["mouse"]  # dragged and wheeled from the view's start
    assert mouse["yaw"] != home["yaw"] and float(mouse["zoom"]) > float(home["zoom"]), mouse
    clicked = three["clicked"]  # a segment no other is drawn nearer to, clicked with the mouse
    assert clicked["selected"] == clicked["row"] == clicked["want"], clicked


GZIP_BOUND = 150 * 1024  # issue 34, point 6: the page's code, gzipped (the engine, the page's script and data)


def test_the_page_gzipped_stays_under_its_bound(run: dict[str, object]) -> None:
    page = Path(str(run["page"])).read_bytes()
    size = len(gzip.compress(page, 9))
    assert 0 < size < GZIP_BOUND, f"the workbench page is {size:,} bytes gzipped (bound {GZIP_BOUND:,})"


def _encoded(cut: Path) -> tuple[Path | None, str]:
    """Native cbf-c encode of a CUT file, written beside it under the name the page gives it (NAME.cbf), or
    None and the engine's one line."""
    out = cut.with_suffix(".cbf")
    res = subprocess.run([str(_cbf_c()), "encode", cut.name, "-o", out.name], cwd=cut.parent, capture_output=True)
    if res.returncode != 0:
        return None, res.stderr.decode()
    return out, ""


def test_a_dropped_cut_file_is_shown_as_the_cbf_it_encodes_to(run: dict[str, object]) -> None:
    cuts = run["cuts"]
    assert isinstance(cuts, list) and len(cuts) > 2
    differ = []
    shown = 0
    for r in cuts[:-1]:  # each golden CUT form: the findings of the CBF it encodes to, as cbf-c validate prints them
        cbf, why = _encoded(Path(r["path"]))
        if cbf is None:  # a version the writers do not write, say: the engine's one line, as for a refused text
            assert r["note"] is None and r["status"] == 2 and why.strip() in r["verdict"] and r["text"] == why, r
            continue
        shown += 1
        size = cbf.stat().st_size
        text, status = _native(cbf, "default")
        if (r["text"], r["status"]) != (text, status) or r["shown"] != cbf.name:
            differ.append(f"{cbf.name}: page {r['status']} {r['text']!r}, cbf-c {status} {text!r}")
        assert r["note"] is not None and f"CUT text, shown as the CBF it encodes to ({size} bytes)" in r["note"], r
        assert r["href"].startswith("blob:") and r["download"] == cbf.name, r
        assert r["records"] > 0 or "records" not in text
    assert not differ, "\n".join(differ[:5])
    assert shown > len(cuts) // 2, f"only {shown} of {len(cuts)} golden CUT forms encode"
    first = cuts[0]
    cbf, _ = _encoded(Path(first["path"]))
    assert cbf is not None and bytes(first["downloaded"]) == cbf.read_bytes()  # the download is that CBF
    assert first["segments"] > 0  # its toolpath drawn
    assert (SHOTS / "workbench-cut-1280.png").stat().st_size > 0


def test_a_cut_file_the_engine_refuses_shows_its_one_line(run: dict[str, object]) -> None:
    cuts = run["cuts"]
    assert isinstance(cuts, list)
    r = cuts[-1]
    cbf, why = _encoded(Path(r["path"]))
    assert cbf is None and why.count("\n") == 1 and ": line " in why
    assert r["note"] is None and r["status"] == 2 and r["records"] == 0
    assert why.strip() in r["verdict"] and r["text"] == why
