#!/usr/bin/env python3
"""geomcheck nightly fuzzing as JUnit XML: one test case per fuzz target of
the run, read from WORK/report.json (tools/nightly_fuzz.py).

A test case's time is the target's fuzzing time. It fails when the target
found something new: the failure names each new signature, its case file,
the crash input it came from (WORK/findings/T/done/) and the commands that
replay them. It is an error when the target was interrupted, did not
finish, or was not fuzzed at all (libFuzzer did not start: its log is
named). Executions, coverage, corpus sizes and duplicates go to its
system-out. scripts/nightly.sh writes it after every run.
"""

import argparse
import json
import os
import sys
import xml.etree.ElementTree as ET


def shown(path):
    """A path as a person would type it from here (relative under the working directory)."""
    rel = os.path.relpath(path)
    return path if rel.startswith("..") else rel


def testcase(t, report, fuzz_dir, logs):
    name = t["name"]
    f = t.get("fuzz", {})
    fnd = t.get("findings", {})
    target = shown(os.path.join(fuzz_dir, name))
    log = os.path.join(logs, name + ".log")
    case = ET.Element("testcase", classname="geomcheck.nightly", name=name, time=f"{f.get('wall_seconds', 0):.1f}")
    new = fnd.get("new", [])
    if new:
        lines = []
        for x in new:
            filed = os.path.join(os.path.dirname(report["regressions"]), x["case"])
            crash = os.path.join(report["work"], "findings", name, "done", x["input"])
            replay = (f"geomcheck replay {shown(filed)}" if filed.endswith(".case")
                      else f"{target} -print_funcs=0 {shown(filed)}")
            lines += [f"signature: {x['signature']}", f"filed as: {shown(filed)}", f"crash file: {shown(crash)}",
                      f"replay: {replay}", f"rerun the crash file: {target} -print_funcs=0 {shown(crash)}", ""]
        failure = ET.SubElement(case, "failure", message=f"{len(new)} new finding{'s' if len(new) > 1 else ''}",
                                type="new finding")
        failure.text = "\n".join(lines)
    else:
        kind = error = None
        if t.get("status") == "interrupted":
            kind, error = "interrupted", "interrupted (nothing is lost: the next run fuzzes on and files what was pending)"
        elif t.get("status") != "done":
            kind, error = "unfinished", f"did not finish (status {t.get('status')!r})"
        elif report.get("seconds_per_target", 0) > 0 and f.get("execs", 0) == 0:
            kind = "not fuzzed"
            error = f"not fuzzed: libFuzzer exited {f.get('exit_code', '?')} without an execution (log {shown(log)})"
        if error:
            ET.SubElement(case, "error", message=error, type=kind).text = error
    out = []
    if f:
        out.append(f"{f.get('execs', 0):,} executions in {f.get('wall_seconds', 0)} s, coverage "
                   f"{f.get('cov_start', 0)} -> {f.get('cov_end', 0)} edges (log {shown(log)})")
    if "corpus_after_merge" in t:
        out.append(f"corpus {t.get('corpus_before', 0)} -> {t.get('corpus_after_fuzz', 0)} after fuzzing -> "
                   f"{t['corpus_after_merge']} after the merge ({t.get('pruned', 0)} pruned entries kept)")
    out.append(f"finding inputs {fnd.get('inputs', 0)}: {len(new)} new, {fnd.get('duplicates', 0)} duplicates "
               f"(signatures already filed), {fnd.get('not_reproduced', 0)} not reproduced")
    ET.SubElement(case, "system-out").text = "\n".join(out) + "\n"
    return case


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("work", help="the nightly job's state directory (its report.json)")
    ap.add_argument("fuzz_dir", help="where the fuzz targets are (for the replay commands)")
    ap.add_argument("out", help="the JUnit XML file to write")
    args = ap.parse_args()
    with open(os.path.join(args.work, "report.json")) as f:
        report = json.load(f)
    logs = os.path.join(report["work"], "logs", report["started"].replace(":", ""))
    cases = [testcase(t, report, args.fuzz_dir, logs) for t in report["targets"]]
    failures = sum(c.find("failure") is not None for c in cases)
    errors = sum(c.find("error") is not None for c in cases)
    time = f"{sum(float(c.get('time')) for c in cases):.1f}"
    counts = {"tests": str(len(cases)), "failures": str(failures), "errors": str(errors), "time": time}
    root = ET.Element("testsuites", name="geomcheck nightly fuzz", **counts)
    suite = ET.SubElement(root, "testsuite", name=f"nightly fuzz {report['started']}", timestamp=report["started"],
                          **counts)
    props = ET.SubElement(suite, "properties")
    for k in ("status", "seconds_per_target", "jobs"):
        ET.SubElement(props, "property", name=k, value=str(report.get(k, "")))
    suite.extend(cases)
    ET.indent(root)
    tmp = f"{args.out}.tmp{os.getpid()}"
    ET.ElementTree(root).write(tmp, encoding="UTF-8", xml_declaration=True)
    os.replace(tmp, args.out)
    print(f"nightly: JUnit {args.out}: {len(cases)} test cases, {failures} failing (new findings), {errors} errors")
    return 0


if __name__ == "__main__":
    sys.exit(main())
