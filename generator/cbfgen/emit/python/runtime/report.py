"""What `cbf validate` prints for a batch of files, in each format CI systems read.

Formats: ``text`` (the lines `cbf-c validate` prints too), ``json``, ``junit`` (JUnit XML as
Jenkins, GitLab and GitHub test reporters read it), ``sarif`` (SARIF 2.1.0, the OASIS schema),
``github`` (workflow commands: ``::error file=PATH,title=...::message``) and ``gitlab`` (the code
quality report, a JSON array). A CBF file is binary: no finding has a line. SARIF names the byte
offset (``region.byteOffset``); GitHub's annotation carries the file and the offset in its title;
GitLab's report, which requires a line, gives line 1 and the offset in the description.
"""

from __future__ import annotations

import json
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

from . import tables as T
from .findings import Finding

FORMATS = ("text", "json", "junit", "sarif", "github", "gitlab")
SARIF_SCHEMA = "https://docs.oasis-open.org/sarif/sarif/v2.1.0/errata01/os/schemas/sarif-schema-2.1.0.json"


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


def finding_line(path: str, f: Finding) -> str:
    """One finding as `cbf validate` and `cbf-c validate` print it."""
    return f"{path}:{f.offset}: {f.severity} {f.check} ({_where(f)}): {f.message}\n"


def more_line(path: str, hidden: int) -> str:
    return f"{path}: {hidden} more finding(s) not shown (--max-findings 0 prints all)\n"  # as cbf-c says it


def verdict_line(path: str, errors: int, warnings: int, profile: str) -> str:
    return f"{path}: {'FAIL' if errors else 'ok'}: {errors} error(s), {warnings} warning(s) [profile {profile}]\n"


def summary_line(results: Sequence[FileResult]) -> str:
    failed = sum(r.status == 1 for r in results)
    refused = sum(r.status == 2 for r in results)
    return (f"cbf validate: {len(results)} file(s): {len(results) - failed - refused} ok, {failed} failed, "
            f"{refused} not validated\n")


def text(r: FileResult, profile: str, max_findings: int) -> str:
    """A validated file's lines (a refused one is a line on stderr instead)."""
    shown = r.findings if max_findings == 0 else r.findings[:max_findings]
    out = [finding_line(r.path, f) for f in shown]
    if len(shown) < len(r.findings):
        out.append(more_line(r.path, len(r.findings) - len(shown)))
    out.append(verdict_line(r.path, r.errors, r.warnings, profile))
    return "".join(out)


def as_json(results: Sequence[FileResult], profile: str) -> str:
    files = []
    for r in results:
        entry: dict[str, Any] = {"file": r.path, "status": r.status}
        if r.refused is not None:
            entry["error"] = r.refused
        else:
            entry.update(errors=r.errors, warnings=r.warnings, findings=[f.as_dict() for f in r.findings])
        files.append(entry)
    return json.dumps({"profile": profile, "status": batch_status(results), "files": files}, indent=1) + "\n"


def _tool_version() -> tuple[str, str]:
    from .version import SPEC_REVISION, __version__

    return __version__, SPEC_REVISION


def junit(results: Sequence[FileResult], profile: str) -> str:
    """A test case per file: <failure> for error findings, <error> for a file not validated,
    warnings in <system-out>."""
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
        tc = ET.SubElement(suite, "testcase", classname="cbf.validate", name=r.path, file=r.path)
        if r.refused is not None:
            ET.SubElement(tc, "error", message=r.refused, type="not validated").text = r.refused
            continue
        lines = "".join(finding_line(r.path, f) for f in r.findings)
        if r.errors:
            ET.SubElement(tc, "failure", message=f"{r.errors} error(s), {r.warnings} warning(s)",
                          type="error").text = lines
        elif lines:
            ET.SubElement(tc, "system-out").text = lines
    return ET.tostring(suites, encoding="unicode", xml_declaration=True) + "\n"


def sarif(results: Sequence[FileResult], profile: str) -> str:
    """SARIF 2.1.0: one run, a rule per spec check, a result per finding at its byte offset."""
    import hashlib

    version, rev = _tool_version()
    rules = [{"id": c["id"], "shortDescription": {"text": f"spec check {c['id']} ({c['kind']})"},
              "defaultConfiguration": {"level": "error" if c["severity"] == "error" else "warning"}}
             for c in T.CHECKS]
    index = {c["id"]: i for i, c in enumerate(T.CHECKS)}
    out: list[dict[str, Any]] = []
    notes: list[dict[str, Any]] = []
    for r in results:
        artifact = {"uri": r.path}
        if r.refused is not None:
            notes.append({"level": "error", "message": {"text": r.refused},
                          "locations": [{"physicalLocation": {"artifactLocation": artifact}}]})
            continue
        for f in r.findings:
            res: dict[str, Any] = {"ruleId": f.check, "level": "error" if f.severity == "error" else "warning",
                                   "message": {"text": f.message}}
            if f.check in index:
                res["ruleIndex"] = index[f.check]
            phys: dict[str, Any] = {"artifactLocation": artifact}
            if f.offset is not None:
                phys["region"] = {"byteOffset": f.offset}
            res["locations"] = [{"physicalLocation": phys,
                                 "logicalLocations": [{"name": _where(f), "kind": "element"}]}]
            # stable across runs (code scanning matches alerts by it): the file, check, record, offset, message
            res["partialFingerprints"] = {"cbfFinding/v1": hashlib.sha256(
                f"{r.path}\0{f.check}\0{f.record}\0{f.offset}\0{f.message}".encode()).hexdigest()}
            out.append(res)
    doc = {"$schema": SARIF_SCHEMA, "version": "2.1.0",
           "runs": [{"tool": {"driver": {"name": "cbf", "version": version, "semanticVersion": version,
                                         "rules": rules, "properties": {"specRevision": rev}}},
                     "invocations": [{"executionSuccessful": not notes, "toolExecutionNotifications": notes,
                                      "properties": {"profile": profile}}],
                     "results": out}]}
    return json.dumps(doc, indent=1) + "\n"


def _gh_data(s: str) -> str:
    return s.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")


def _gh_prop(s: str) -> str:
    return _gh_data(s).replace(":", "%3A").replace(",", "%2C")


def github(r: FileResult) -> str:
    """GitHub Actions workflow commands, one per finding (and one for a file not validated)."""
    if r.refused is not None:
        return f"::error file={_gh_prop(r.path)},title=cbf validate::{_gh_data(r.refused)}\n"
    return "".join(f"::{f.severity if f.severity == 'error' else 'warning'} file={_gh_prop(r.path)},"
                   f"title={_gh_prop(f'{f.check} ({_where(f)} @{f.offset})')}::{_gh_data(f.message)}\n"
                   for f in r.findings)


def gitlab(results: Sequence[FileResult]) -> str:
    """GitLab's code quality report (a Code Climate issue array)."""
    import hashlib

    issues = []
    for r in results:
        items: list[tuple[str, str, Finding | None, str]] = [("blocker", "cbf validate", None, r.refused)] \
            if r.refused is not None else \
            [("critical" if f.severity == "error" else "minor", f.check, f, f.message) for f in r.findings]
        for n, (sev, check, f, msg) in enumerate(items):
            where = f" ({_where(f)}, offset {f.offset})" if f is not None else ""
            desc = f"{check}{where}: {msg}"
            fp = hashlib.sha256(f"{r.path}\0{n}\0{desc}".encode()).hexdigest()
            issues.append({"type": "issue", "check_name": check, "description": desc, "severity": sev,
                           "categories": ["Bug Risk"], "fingerprint": fp,
                           "location": {"path": r.path, "lines": {"begin": 1}}})
    return json.dumps(issues, indent=1) + "\n"
