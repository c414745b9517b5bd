"""What `cbf validate` prints for a batch of files, in each format CI systems read.

Formats: ``text`` (the lines `cbf-c validate` prints too), ``json``, ``junit`` (JUnit XML as
Jenkins, GitLab and GitHub test reporters read it), ``sarif`` (SARIF 2.1.0 as GitHub code scanning
accepts it: Microsoft's SARIF multitool, rules ``Gh;Sarif``, finds nothing), ``github`` (workflow
commands: ``::error file=PATH,title=...::message``) and ``gitlab`` (GitLab's code quality report,
schemas/gitlab-code-quality.schema.json). A CBF file is binary: no finding has a line. SARIF names
the byte offset (``region.byteOffset``) with line 1 (where GitHub shows a binary file's alert);
every format carries the offset in the message.

Every name from input goes through the one quoting rule (cbf.quoting): no path starts a line
or carries a line break. JSON and SARIF keep a name's exact bytes: JSON holds the name (or, for
bytes that are not UTF-8, ``quote``'s form, which ``unquote`` reverses), SARIF percent-encodes
the bytes in the URI. ``max_findings`` (``--max-findings``) caps the findings of each file in
every format, and SARIF caps a run at GitHub's 25,000 results; what is left out is counted in
the output.
"""

from __future__ import annotations

import json
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

from . import tables as T
from .findings import Finding
from .quoting import json_name, line, quote

FORMATS = ("text", "json", "junit", "sarif", "github", "gitlab")
SARIF_SCHEMA = "https://docs.oasis-open.org/sarif/sarif/v2.1.0/errata01/os/schemas/sarif-schema-2.1.0.json"
# GitHub code scanning refuses a run of more results (docs.github.com, "SARIF results exceed
# limit": results per run, 25,000; only the top 5,000 are shown).
SARIF_MAX_RESULTS = 25_000
# ... and a file over 10 MB ("SARIF file is too large"): the results stop short of that, uncompressed.
SARIF_MAX_BYTES = 10_000_000
INPUT_RULE = "cbf.input"  # the rule of an input that could not be validated (not CBF, unreadable)


@dataclass(frozen=True)
class FileResult:
    """One input's outcome: its findings, or why it could not be validated (``refused``, exit 2)."""

    path: str
    findings: tuple[Finding, ...] = ()
    refused: str | None = None

    @property
    def errors(self) -> int:
        return sum(f.severity == "error" for f in self.findings)

    @property
    def warnings(self) -> int:
        return len(self.findings) - self.errors

    @property
    def status(self) -> int:
        """The exit status of this input alone: 0 ok, 1 an error finding, 2 refused."""
        return 2 if self.refused is not None else 1 if self.errors else 0


def batch_status(results: Iterable[FileResult]) -> int:
    """The batch's one exit status: the worst of its inputs."""
    return max((r.status for r in results), default=0)


def _where(f: Finding) -> str:
    return f"record {f.record}" if f.record is not None else "header"


def shown(r: FileResult, max_findings: int) -> tuple[Finding, ...]:
    """The findings of a file that an output shows under ``--max-findings`` (0: all)."""
    return r.findings if max_findings == 0 else r.findings[:max_findings]


def finding_line(path: str, f: Finding) -> str:
    """One finding as `cbf validate` and `cbf-c validate` print it."""
    return f"{quote(path)}:{f.offset}: {f.severity} {f.check} ({_where(f)}): {line(f.message)}\n"


def more_line(path: str, hidden: int) -> str:
    return f"{quote(path)}: {hidden} more finding(s) not shown (--max-findings 0 prints all)\n"  # as cbf-c says it


def verdict_line(path: str, errors: int, warnings: int, profile: str) -> str:
    return (f"{quote(path)}: {'FAIL' if errors else 'ok'}: {errors} error(s), {warnings} warning(s) "
            f"[profile {profile}]\n")


def summary_line(results: Sequence[FileResult]) -> str:
    failed = sum(r.status == 1 for r in results)
    refused = sum(r.status == 2 for r in results)
    return (f"cbf validate: {len(results)} file(s): {len(results) - failed - refused} ok, {failed} failed, "
            f"{refused} not validated\n")


def text(r: FileResult, profile: str, max_findings: int) -> str:
    """A validated file's lines (a refused one is a line on stderr instead)."""
    some = shown(r, max_findings)
    out = [finding_line(r.path, f) for f in some]
    if len(some) < len(r.findings):
        out.append(more_line(r.path, len(r.findings) - len(some)))
    out.append(verdict_line(r.path, r.errors, r.warnings, profile))
    return "".join(out)


def as_json(results: Sequence[FileResult], profile: str, max_findings: int = 0) -> str:
    files = []
    for r in results:
        entry: dict[str, Any] = {"file": json_name(r.path), "status": r.status}
        if r.refused is not None:
            entry["error"] = line(r.refused)
        else:
            some = shown(r, max_findings)
            entry.update(errors=r.errors, warnings=r.warnings, findings=[f.as_dict() for f in some])
            if len(some) < len(r.findings):
                entry["not_shown"] = len(r.findings) - len(some)
        files.append(entry)
    return json.dumps({"profile": profile, "status": batch_status(results), "files": files}, indent=1) + "\n"


def _tool_version() -> tuple[str, str]:
    from .version import SPEC_REVISION, __version__

    return __version__, SPEC_REVISION


def junit(results: Sequence[FileResult], profile: str, max_findings: int = 0) -> str:
    """A test case per file: <failure> for error findings, <error> for a file not validated,
    warnings in <system-out>. Names and messages go through the quoting rule: nothing XML 1.0
    cannot carry reaches the document (it is escaped visibly, as ``\\x01``)."""
    import xml.etree.ElementTree as ET  # here, not at the top: the text of one file needs no XML

    version, rev = _tool_version()
    failures = sum(r.status == 1 for r in results)
    errors = sum(r.status == 2 for r in results)
    suites = ET.Element("testsuites", name="cbf validate", tests=str(len(results)), failures=str(failures),
                        errors=str(errors))
    suite = ET.SubElement(suites, "testsuite", name=f"cbf validate [profile {profile}]", tests=str(len(results)),
                          failures=str(failures), errors=str(errors), skipped="0")
    props = ET.SubElement(suite, "properties")
    for k, v in (("cbf.version", version), ("spec.revision", rev), ("profile", profile)):
        ET.SubElement(props, "property", name=k, value=v)
    for r in results:
        name = quote(r.path)
        tc = ET.SubElement(suite, "testcase", classname="cbf.validate", name=name, file=name)
        if r.refused is not None:
            ET.SubElement(tc, "error", message=line(r.refused), type="not validated").text = line(r.refused)
            continue
        some = shown(r, max_findings)
        lines = "".join(finding_line(r.path, f) for f in some)
        if len(some) < len(r.findings):
            lines += more_line(r.path, len(r.findings) - len(some))
        if r.errors:
            ET.SubElement(tc, "failure", message=f"{r.errors} error(s), {r.warnings} warning(s)",
                          type="error").text = lines
        elif lines:
            ET.SubElement(tc, "system-out").text = lines
    return ET.tostring(suites, encoding="unicode", xml_declaration=True) + "\n"


def _rule(c: dict[str, Any], docs_url: str | None) -> dict[str, Any]:
    """A spec check as a SARIF rule: its clause's text, what fails it, and the link to its anchor
    in the published document (with ``--docs-url``)."""
    clause = f"300071 clause {c['clause']}" if c.get("clause") else "the toolkit's own check"
    where = f"{docs_url}#{c['anchor']}" if docs_url else None
    link = f"[{clause}]({where})" if where else f"{clause} (the reference's section `{c['anchor']}`)"
    rule: dict[str, Any] = {
        "id": c["id"], "name": "".join(w.capitalize() for w in c["kind"].split("_")) + "Check",
        "shortDescription": {"text": _sentence(f"Spec check {c['id']} ({c['kind']})")},
        "fullDescription": {"text": _sentence(c["text"])},
        "help": {"text": _sentence(f"{c['text']} Fails when: {c['fails']} See {clause}"
                                   + (f", {where}" if where else f", section {c['anchor']} of the reference")),
                 "markdown": f"{_sentence(c['text'])}\n\n**Fails when:** {c['fails']}\n\nSee {link}."},
        "defaultConfiguration": {"level": "error" if c["severity"] == "error" else "warning"},
        "properties": {"clause": c.get("clause"), "kind": c["kind"]}}
    if where:
        rule["helpUri"] = where
    return rule


def _sentence(text: str) -> str:
    text = " ".join(text.split())
    return text if text.endswith((".", "!", "?")) else text + "."


def _input_rule() -> dict[str, Any]:
    text = "Every input is a CBF file the tool can read."
    fails = ("The input could not be validated: it cannot be read (missing, no permission, not a regular file), "
             "is larger than a CBF file can be, is shorter than the header, or neither magic number of the "
             "header is right (not a CBF file). No check of the spec runs on it.")
    return {"id": INPUT_RULE, "name": "ValidatableInput", "shortDescription": {"text": text},
            "fullDescription": {"text": fails}, "help": {"text": f"{text} {fails}", "markdown": f"{text}\n\n{fails}"},
            "defaultConfiguration": {"level": "error"}}


def _percent(raw: bytes) -> str:
    from urllib.parse import quote as pct

    return pct(raw, safe="/")


def _artifact(path: str, base: str) -> dict[str, Any]:
    """Where a file is, for SARIF: a percent-encoded URI relative to the base (uriBaseId SRCROOT),
    or an absolute file URI when it lies outside; its exact bytes are in the encoding."""
    import os

    if path == "-":
        return {"uri": "stdin", "description": {"text": "Standard input."}}
    full = os.path.abspath(path)
    rel = os.path.relpath(full, base)
    if rel != os.pardir and not rel.startswith(os.pardir + os.sep):
        return {"uri": _percent(os.fsencode(rel).replace(os.sep.encode(), b"/")), "uriBaseId": "SRCROOT"}
    return {"uri": "file://" + _percent(os.fsencode(full).replace(os.sep.encode(), b"/"))}


def _base_uri(base: str) -> str:
    import os

    full = os.fsencode(os.path.abspath(base)).replace(os.sep.encode(), b"/")
    return "file://" + _percent(full.rstrip(b"/") + b"/")


def sarif(results: Sequence[FileResult], profile: str, max_findings: int = 0, base: str = ".",
          docs_url: str | None = None, max_results: int = SARIF_MAX_RESULTS) -> str:
    """SARIF 2.1.0: one run, a rule per spec check (and one for an input not validated), a result
    per finding at its byte offset (line 1: where GitHub shows a binary file), at most
    ``max_results`` results with a notification saying how many were left out."""
    import hashlib

    version, rev = _tool_version()
    rules = [_rule(c, docs_url) for c in T.CHECKS] + [_input_rule()]
    index = {c["id"]: i for i, c in enumerate(T.CHECKS)}
    out: list[str] = []  # each result as its JSON text: the size is counted as they are made
    size = 0
    budget = SARIF_MAX_BYTES - 400_000  # the rules, the run and the notes stay well under this
    left = {"max_findings": 0, "max_results": 0}
    for r in results:
        artifact = _artifact(r.path, base)
        name = quote(r.path)
        items: list[tuple[str, str, int | None, str, str]] = []  # rule, level, offset, message, fingerprint data
        if r.refused is not None:
            items.append((INPUT_RULE, "error", None, _sentence(line(r.refused)), "input"))
        else:
            some = shown(r, max_findings)
            left["max_findings"] += len(r.findings) - len(some)
            for f in some:
                at = f" at offset {f.offset}" if f.offset is not None else ""
                items.append((f.check, "error" if f.severity == "error" else "warning", f.offset,
                              _sentence(f"{_where(f).capitalize()}{at}: {line(f.message)}"),
                              f"{f.check}\0{f.record}\0{f.offset}\0{f.message}"))
        for rule_id, level, offset, message, key in items:
            if len(out) >= max_results or size > budget:
                left["max_results"] += 1
                continue
            res: dict[str, Any] = {"ruleId": rule_id, "ruleIndex": index.get(rule_id, len(T.CHECKS)),
                                   "level": level, "message": {"text": message}}
            region: dict[str, Any] = {"startLine": 1}
            if offset is not None:
                region["byteOffset"] = offset
            res["locations"] = [{"physicalLocation": {"artifactLocation": artifact, "region": region}}]
            # stable across runs (code scanning matches alerts by it): the file, check, record, offset, message
            res["partialFingerprints"] = {"cbfFinding/v1": hashlib.sha256(
                f"{name}\0{key}".encode("utf-8", "surrogateescape")).hexdigest()[:32]}
            text = json.dumps(res, separators=(",", ":"))
            size += len(text) + 1
            out.append(text)
    notes: list[dict[str, Any]] = []
    if left["max_results"]:
        notes.append({"level": "warning", "message": {"text": (
            f"{left['max_results']} result(s) left out: GitHub code scanning accepts at most {max_results} "
            f"results per run and a file of at most {SARIF_MAX_BYTES // 1_000_000} MB; the first {len(out)} "
            f"in input order are here.")}})
    if left["max_findings"]:
        notes.append({"level": "note", "message": {"text": (
            f"{left['max_findings']} finding(s) left out by --max-findings {max_findings} "
            f"(--max-findings 0 gives all).")}})
    driver: dict[str, Any] = {"name": "cbf", "fullName": f"cbf {version} ({T.SPEC_TITLE}, spec {rev})",
                              "version": version, "semanticVersion": version, "rules": rules,
                              "properties": {"specRevision": rev}}
    if docs_url:
        driver["informationUri"] = docs_url
    run: dict[str, Any] = {
        "tool": {"driver": driver},
        "originalUriBaseIds": {"SRCROOT": {"uri": _base_uri(base)}},
        "invocations": [{"executionSuccessful": True, "toolExecutionNotifications": notes,
                         "properties": {"profile": profile}}],
        "results": [],
        "properties": {"resultsLeftOut": left["max_results"], "findingsLeftOut": left["max_findings"]}}
    head, tail = json.dumps({"$schema": SARIF_SCHEMA, "version": "2.1.0", "runs": [run]},
                            separators=(",", ":")).split('"results":[]', 1)  # the one such key: rules hold none
    return f'{head}"results":[{",".join(out)}]{tail}\n'


def _gh_data(s: str) -> str:
    return s.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")


def _gh_prop(s: str) -> str:
    return _gh_data(s).replace(":", "%3A").replace(",", "%2C")


def _gh_file(path: str) -> str:
    """A path as a workflow command's file= property: as it is (GitHub decodes the escapes),
    ``quote``'s form when it is not Unicode text."""
    name = json_name(path)
    return _gh_prop(line(name) if name is not path else name)


def github(r: FileResult, max_findings: int = 0) -> str:
    """GitHub Actions workflow commands, one per finding (and one for a file not validated)."""
    file = _gh_file(r.path)
    if r.refused is not None:
        return f"::error file={file},title=cbf validate::{_gh_data(line(r.refused))}\n"
    some = shown(r, max_findings)
    out = [f"::{f.severity if f.severity == 'error' else 'warning'} file={file},"
           f"title={_gh_prop(f'{f.check} ({_where(f)} @{f.offset})')}::"
           f"{_gh_data(f'{_where(f)} at offset {f.offset}: {line(f.message)}')}\n" for f in some]
    if len(some) < len(r.findings):
        out.append(f"::notice file={file},title=cbf validate::{len(r.findings) - len(some)} more finding(s) "
                   f"not shown (--max-findings 0 prints all)\n")
    return "".join(out)


def _relative(path: str, base: str) -> str:
    """A path relative to the base (GitLab's location.path is relative to the repository)."""
    import os

    if path == "-":
        return path
    rel = os.path.relpath(os.path.abspath(path), base)
    return path if rel == os.pardir or rel.startswith(os.pardir + os.sep) else rel.replace(os.sep, "/")


def gitlab(results: Sequence[FileResult], max_findings: int = 0, base: str = ".") -> str:
    """GitLab's code quality report (schemas/gitlab-code-quality.schema.json): an issue per finding,
    one for a file not validated, one saying how many findings --max-findings left out."""
    import hashlib

    issues = []
    for r in results:
        some = shown(r, max_findings)
        items: list[tuple[str, str, Finding | None, str]] = [("blocker", INPUT_RULE, None, line(r.refused))] \
            if r.refused is not None else \
            [("critical" if f.severity == "error" else "minor", f.check, f, line(f.message)) for f in some]
        if r.refused is None and len(some) < len(r.findings):
            items.append(("info", "cbf.not-shown", None, f"{len(r.findings) - len(some)} more finding(s) not shown "
                                                         f"(--max-findings 0 reports all)"))
        path = json_name(_relative(r.path, base))
        for n, (sev, check, f, msg) in enumerate(items):
            where = f" ({_where(f)}, offset {f.offset})" if f is not None else ""
            desc = f"{check}{where}: {msg}"
            fp = hashlib.sha256(f"{path}\0{n}\0{desc}".encode("utf-8", "surrogateescape")).hexdigest()
            issues.append({"type": "issue", "check_name": check, "description": desc, "severity": sev,
                           "categories": ["Bug Risk"], "fingerprint": fp,
                           "location": {"path": path, "lines": {"begin": 1}}})
    return json.dumps(issues, indent=1) + "\n"
