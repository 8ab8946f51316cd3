#!/usr/bin/env python3
"""geomcheck nightly fuzzing: run every fuzz target for a budget, keep
everything it finds.

For each target, in turn:
  1. fuzz      libFuzzer -fork=JOBS -ignore_crashes=1 on the target's
               persistent corpus (WORK/corpus/T) plus the repository's seeds;
               crash, timeout and OOM inputs land in WORK/findings/T/.
  2. merge     libFuzzer -merge=1 into a fresh directory (the minimised
               corpus), swapped in by two renames; every entry the
               minimisation drops is first copied to WORK/pruned/T/.
  3. findings  every input in WORK/findings/T/ is re-run for its signature
               (the geomcheck property that failed and the fuzz mode, or the
               sanitizer's SUMMARY line, or timeout / out-of-memory); a new
               signature is minimised (-minimize_crash=1), converted into a
               case file (`geomcheck from-fuzz`) and filed as
               REGRESSIONS/<query>/NNNN-new-<slug>.case with a note marking
               it new; a known signature is counted as a duplicate. The input
               is then moved to WORK/findings/T/done/ (never deleted).
Then it writes WORK/report.json and WORK/report.html (executions, coverage
growth, corpus sizes, findings per target).

Interrupting it at any moment (Ctrl-C, SIGINT, SIGTERM) loses no finding and
no corpus entry: libFuzzer writes corpus entries and crash inputs to disk as
it finds them; a finding leaves WORK/findings/T/ only after its case file is
in place (written to a temporary name, then renamed), and a signature is
recorded in the case file itself, so a rerun neither loses nor duplicates
it; the corpus is replaced only by renames, and a rerun completes or undoes
a half-done swap. The next run picks up whatever was pending.
"""

import argparse
import datetime
import fcntl
import hashlib
import html
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time

STOP = {"signal": None}
CHILD = {"proc": None}
SANITIZER_ENV = {
    "ASAN_OPTIONS": "detect_leaks=1:allocator_may_return_null=1",
    "UBSAN_OPTIONS": "print_stacktrace=1:halt_on_error=1",
}
FINDING_PREFIXES = ("crash-", "leak-", "timeout-", "oom-")


def log(msg):
    print(f"nightly: {msg}", flush=True)


def on_signal(signum, frame):
    STOP["signal"] = signum
    p = CHILD["proc"]
    if p is not None and p.poll() is None:
        try:
            os.killpg(p.pid, signal.SIGINT)
        except ProcessLookupError:
            pass


class Interrupted(Exception):
    pass


def check_stop():
    if STOP["signal"] is not None:
        raise Interrupted()


def run(cmd, log_path=None, timeout=None, env_extra=None):
    """Runs cmd in its own process group (so that an interrupt reaches the
    fuzzer's fork-mode jobs too); returns (exit code, output text)."""
    env = dict(os.environ)
    env.update(SANITIZER_ENV)
    if env_extra:
        env.update(env_extra)
    out = open(log_path, "w") if log_path else subprocess.PIPE
    p = subprocess.Popen(cmd, stdout=out, stderr=subprocess.STDOUT, env=env, start_new_session=True, text=True)
    CHILD["proc"] = p
    if STOP["signal"] is not None:
        on_signal(STOP["signal"], None)
    try:
        text, _ = p.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        text, _ = p.communicate()
    finally:
        CHILD["proc"] = None
        # Fork-mode jobs that outlived their parent.
        try:
            os.killpg(p.pid, signal.SIGKILL)
        except (ProcessLookupError, PermissionError):
            pass
    if log_path:
        out.close()
        with open(log_path, errors="replace") as f:
            text = f.read()
    return p.returncode, text or ""


def write_atomic(path, data, mode="w"):
    tmp = f"{path}.tmp{os.getpid()}"
    with open(tmp, mode) as f:
        f.write(data)
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, path)


def list_files(d):
    try:
        return sorted(n for n in os.listdir(d) if os.path.isfile(os.path.join(d, n)) and ".tmp" not in n)
    except FileNotFoundError:
        return []


# ---------------------------------------------------------------- corpus


def recover_swap(cur):
    """Completes or undoes a corpus swap that an interrupt cut short."""
    old = cur + ".old"
    if os.path.isdir(old):
        if os.path.isdir(cur):
            shutil.rmtree(old)
        else:
            os.rename(old, cur)
    os.makedirs(cur, exist_ok=True)


def merge_corpus(target, cur, work, pruned_dir, fuzz_flags):
    """Minimises the corpus with -merge=1; returns (before, after, pruned)."""
    before = list_files(cur)
    merged = os.path.join(work, "tmp", os.path.basename(cur) + ".merged")
    control = merged + ".control"
    shutil.rmtree(merged, ignore_errors=True)
    os.makedirs(merged)
    if os.path.exists(control):
        os.remove(control)
    rc, text = run([target, "-merge=1", f"-merge_control_file={control}", *fuzz_flags, merged, cur])
    check_stop()
    after = list_files(merged)
    if rc != 0 or (before and not after):
        log(f"  merge failed (exit {rc}); corpus left as it was")
        return len(before), len(before), 0
    os.makedirs(pruned_dir, exist_ok=True)
    keep = set(after)
    dropped = [n for n in before if n not in keep]
    for n in dropped:  # copied, not moved: the corpus stays whole until the swap
        dst = os.path.join(pruned_dir, n)
        if not os.path.exists(dst):
            shutil.copy2(os.path.join(cur, n), dst + ".tmp")
            os.replace(dst + ".tmp", dst)
    check_stop()
    old = cur + ".old"
    os.rename(cur, old)
    os.rename(merged, cur)
    shutil.rmtree(old)
    if os.path.exists(control):
        os.remove(control)
    return len(before), len(after), len(dropped)


# ---------------------------------------------------------------- findings


def signature(text, kind):
    """What makes two findings the same bug."""
    m = re.search(r"==== geomcheck (\S+) property failed: (\S+)", text)
    if m:
        mode = re.search(r"found-by fuzz mode=(\w+)", text)
        return f"property {m.group(2)} ({mode.group(1) if mode else 'unknown'} mode)"
    m = re.search(r"SUMMARY: (\w+Sanitizer): (\S+) (\S+)", text)
    if m:
        where = re.sub(r":\d+$", "", os.path.basename(m.group(3)))  # file:line, no column
        return f"{m.group(1)} {m.group(2)} at {where}"
    if "ERROR: libFuzzer: timeout" in text or kind == "timeout":
        return "timeout"
    if "out-of-memory" in text or kind == "oom":
        return "out-of-memory"
    if "ERROR: libFuzzer: deadly signal" in text:
        frame = re.search(r"#\d+ 0x[0-9a-f]+ in (\S+) (/\S+)", text.split("deadly signal", 1)[1])
        return f"deadly signal in {frame.group(1) if frame else 'unknown'}"
    return None  # does not reproduce


def slug_of(sig):
    s = re.sub(r"[^a-z0-9]+", "-", sig.lower()).strip("-")
    return s[:48].strip("-") or "finding"


def known_signatures(regressions):
    """Signatures already filed, read back from the case files themselves."""
    known = {}
    raw = os.path.join(os.path.dirname(regressions), "regressions-raw")
    for root, _, files in [w for d in (regressions, raw) if os.path.isdir(d) for w in os.walk(d)]:
        for n in files:
            p = os.path.join(root, n)
            try:
                with open(p, errors="replace") as f:
                    for line in f:
                        m = re.match(r"(?:note|#) nightly-signature (\S+) (.*)$", line.rstrip("\n"))
                        if m:
                            known[(m.group(1), m.group(2))] = os.path.relpath(p, os.path.dirname(regressions))
            except OSError:
                pass
    return known


def next_case_path(folder, slug, ext):
    os.makedirs(folder, exist_ok=True)
    numbers = [int(n[:4]) for n in os.listdir(folder) if re.match(r"\d{4}-", n)]
    return os.path.join(folder, f"{max(numbers, default=0) + 1:04d}-new-{slug}{ext}")


def process_findings(t, args, known, stamp, summary):
    """Files every new signature among WORK/findings/T/, counting into summary
    as it goes (so that an interrupted run still reports what it filed)."""
    fdir = os.path.join(args.work, "findings", t["name"])
    done = os.path.join(fdir, "done")
    os.makedirs(done, exist_ok=True)
    for n in list_files(fdir):
        if not n.startswith(FINDING_PREFIXES):
            continue
        check_stop()
        path = os.path.join(fdir, n)
        kind = n.split("-", 1)[0]
        summary["inputs"] += 1
        rc, text = run([t["path"], *args.run_flags, path], timeout=300)
        check_stop()
        sig = signature(text, kind) if rc != 0 else None
        if sig is None:
            summary["not_reproduced"] += 1
            sig = "not reproduced"
        key = (t["name"], sig)
        if key in known:
            summary["duplicates"] += 1
        else:
            case = file_finding(t, args, path, n, sig, text, stamp)
            check_stop()
            known[key] = case
            summary["new"].append({"signature": sig, "case": case, "input": n})
            log(f"  NEW {t['name']}: {sig} -> {os.path.join(os.path.dirname(args.regressions), case)}")
        os.replace(path, os.path.join(done, n))


def file_finding(t, args, path, name, sig, text, stamp):
    """Minimises one finding and files it; returns its path under REGRESSIONS."""
    tmp = os.path.join(args.work, "tmp")
    data_path = path
    if sig not in ("timeout", "out-of-memory", "not reproduced"):
        mini = os.path.join(tmp, "minimised-" + name)
        if os.path.exists(mini):
            os.remove(mini)
        run([t["path"], "-minimize_crash=1", f"-max_total_time={args.minimise_seconds}", "-runs=100000",
             f"-exact_artifact_path={mini}", *args.run_flags, path], timeout=args.minimise_seconds + 120)
        check_stop()
        if os.path.exists(mini) and os.path.getsize(mini) > 0:
            rc, mtext = run([t["path"], *args.run_flags, mini], timeout=300)
            if rc != 0 and signature(mtext, "crash") == sig:
                data_path, text = mini, mtext
    with open(data_path, "rb") as f:
        data = f.read()
    sha1 = hashlib.sha1(data).hexdigest()
    marks = [
        f"nightly-signature {t['name']} {sig}",
        f"NEW: found by the nightly fuzz run of {stamp} ({t['name']}, input {name}, minimised to {len(data)} bytes,",
        f"sha1 {sha1}); not yet reviewed. Confirm it, fix production, then drop 'new-' from the file name.",
    ]
    if t["query"]:
        folder = os.path.join(args.regressions, t["query"])
        dest = next_case_path(folder, slug_of(sig), ".case")
        case_tmp = os.path.join(tmp, "case.tmp")
        rc, out = run([args.geomcheck, "from-fuzz", t["query"], data_path, "-o", case_tmp])
        if rc != 0:
            raise RuntimeError(f"geomcheck from-fuzz failed on {data_path}: {out.strip()}")
        with open(case_tmp) as f:
            lines = f.read().splitlines()
        at = next((i + 1 for i, l in enumerate(lines) if l.startswith("found-by")), 2)
        lines[at:at] = ["note " + m for m in marks]
        write_atomic(dest, "\n".join(lines) + "\n")
        os.remove(case_tmp)
    else:
        # A target without a registered query (the case-file parser, the
        # mesh): the raw input, bit-exact, in REGRESSIONS/../regressions-raw/T/
        # (replayed through the target by the fuzz preset's ctest), its
        # signature in a text file beside it.
        folder = os.path.join(os.path.dirname(args.regressions), "regressions-raw", t["name"])
        dest = next_case_path(folder, slug_of(sig), ".input")
        write_atomic(dest + ".txt", "".join("# " + m + "\n" for m in marks) + "\n" + text[-4000:])
        write_atomic(dest, data, "wb")
    return os.path.relpath(dest, os.path.dirname(args.regressions))


# ---------------------------------------------------------------- fuzzing


STAT = re.compile(r"^#(\d+):? +cov: (\d+) ft: (\d+) corp: (\d+).*?(?:time: (\d+)s)?", re.M)


def fuzz_target(t, args, seconds, log_path):
    corpus = os.path.join(args.work, "corpus", t["name"])
    dirs = [corpus]
    seeds = os.path.join(args.work, "seeds", t["query"] or t["name"].replace("fuzz_", "", 1))
    if os.path.isdir(seeds):
        dirs.append(seeds)
    cmd = [t["path"], f"-fork={args.jobs}", "-ignore_crashes=1", "-ignore_timeouts=1", "-ignore_ooms=1",
           f"-max_total_time={seconds}", f"-artifact_prefix={os.path.join(args.work, 'findings', t['name'])}/",
           "-print_final_stats=1", *args.run_flags, *dirs]
    start = time.time()
    rc, text = run(cmd, log_path=log_path, timeout=seconds + 600)
    stats = [(int(m.group(1)), int(m.group(2)), int(m.group(3)), int(m.group(4)), int(m.group(5) or 0))
             for m in STAT.finditer(text)]
    growth = [{"execs": s[0], "cov": s[1], "ft": s[2], "corpus": s[3], "time": s[4]} for s in stats]
    return {
        "exit_code": rc,
        "wall_seconds": round(time.time() - start, 1),
        "execs": stats[-1][0] if stats else 0,
        "cov_start": next((s[1] for s in stats if s[1] > 0), 0),
        "cov_end": stats[-1][1] if stats else 0,
        "ft_end": stats[-1][2] if stats else 0,
        "growth": growth,
    }


def discover_targets(args):
    queries = set()
    if args.geomcheck and os.path.exists(args.geomcheck):
        rc, out = run([args.geomcheck, "queries"])
        # Pair queries only: their findings become case files (from-fuzz); a
        # point-set target's (delaunay_2d) are filed as raw inputs.
        queries = {w[0] for w in (line.split() for line in out.splitlines()) if len(w) > 1 and w[1] == "pair"}
    names = args.targets or sorted(n for n in os.listdir(args.fuzz_dir) if n.startswith("fuzz_")
                                   and os.access(os.path.join(args.fuzz_dir, n), os.X_OK))
    targets = []
    for spec in names:
        name, _, query = spec.partition("=")
        path = os.path.join(args.fuzz_dir, name)
        if not os.access(path, os.X_OK):
            sys.exit(f"nightly: no fuzz target {path} (build the fuzz preset first)")
        if not query:
            q = name.replace("fuzz_", "", 1)
            query = q if q in queries else ""
        targets.append({"name": name, "path": path, "query": query})
    return targets


# ---------------------------------------------------------------- report


def write_report(args, report):
    write_atomic(os.path.join(args.work, "report.json"), json.dumps(report, indent=2) + "\n")
    e = html.escape
    rows, sections = [], []
    for t in report["targets"]:
        f = t.get("findings", {})
        rows.append(
            f"<tr><td>{e(t['name'])}</td><td>{t.get('fuzz', {}).get('wall_seconds', 0)}</td>"
            f"<td>{t.get('fuzz', {}).get('execs', 0):,}</td>"
            f"<td>{t.get('fuzz', {}).get('cov_start', 0)} &rarr; {t.get('fuzz', {}).get('cov_end', 0)}</td>"
            f"<td>{t.get('corpus_before', 0)} &rarr; {t.get('corpus_after_fuzz', 0)} &rarr; {t.get('corpus_after_merge', 0)}"
            f"</td><td>{f.get('inputs', 0)}</td><td class='{'bad' if f.get('new') else ''}'>{len(f.get('new', []))}</td>"
            f"<td>{f.get('duplicates', 0)}</td><td>{e(t.get('status', ''))}</td></tr>")
        g = t.get("fuzz", {}).get("growth", [])
        if len(g) > 1:
            xmax = max(1, g[-1]["execs"])
            ymax = max(1, max(p["cov"] for p in g))
            pts = " ".join(f"{10 + 300 * p['execs'] / xmax:.1f},{70 - 60 * p['cov'] / ymax:.1f}" for p in g)
            svg = (f"<svg width='320' height='80' role='img'><title>coverage (edges) against executions</title>"
                   f"<polyline fill='none' stroke='#36c' stroke-width='1.5' points='{pts}'/>"
                   f"<text x='10' y='79' font-size='9'>0</text><text x='250' y='79' font-size='9'>{xmax:,} execs</text>"
                   f"<text x='12' y='9' font-size='9'>cov {ymax}</text></svg>")
        else:
            svg = "<p>(no coverage lines: the target was not fuzzed in this run)</p>"
        items = "".join(f"<li><code>{e(x['signature'])}</code> &rarr; <code>{e(x['case'])}</code></li>"
                        for x in f.get("new", []))
        sections.append(f"<h2>{e(t['name'])}</h2>{svg}" + (f"<ul>{items}</ul>" if items else ""))
    page = (
        "<!doctype html><html lang='en'><head><meta charset='utf-8'><title>geomcheck nightly fuzz report</title>"
        "<style>body{font-family:sans-serif;margin:2em}td,th{border:1px solid #ccc;padding:3px 8px}"
        "table{border-collapse:collapse}.bad{background:#fdd}</style></head><body>"
        f"<h1>geomcheck nightly fuzz report</h1><p>Started {e(report['started'])}, {report['seconds_per_target']} s per "
        f"target, {report['jobs']} jobs, status <b>{e(report['status'])}</b>. New findings are filed under "
        f"<code>{e(report['regressions'])}</code> as <code>NNNN-new-*.case</code>.</p>"
        "<table><tr><th>target</th><th>seconds</th><th>executions</th><th>coverage (edges)</th>"
        "<th>corpus before &rarr; after fuzzing &rarr; after merge</th><th>finding inputs</th><th>new</th>"
        "<th>duplicates</th><th>status</th></tr>" + "".join(rows) + "</table>" + "".join(sections) + "</body></html>\n")
    write_atomic(os.path.join(args.work, "report.html"), page)


# ---------------------------------------------------------------- main


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(
        prog="nightly", description=__doc__.split("\n\n")[0],
        epilog="Interrupt it at any time: nothing is lost, and the next run picks up what was pending.")
    ap.add_argument("--seconds", type=int, default=3600,
                    help="fuzzing budget in all, split evenly over the targets (default 3600; 0: only merge and file "
                    "pending findings)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="libFuzzer -fork jobs (default: all cores)")
    ap.add_argument("--target", dest="targets", action="append",
                    help="a target name, or NAME=QUERY for a target of a registered query under another name; "
                    "repeat for several (default: every fuzz_* target)")
    ap.add_argument("--work", default=os.path.join(root, "fuzz-out", "nightly"),
                    help="state directory: corpora, findings, logs, report (default fuzz-out/nightly)")
    ap.add_argument("--fuzz-dir", default=os.path.join(root, "build", "fuzz", "fuzz"),
                    help="where the fuzz targets are (default build/fuzz/fuzz)")
    ap.add_argument("--geomcheck", default=os.path.join(root, "build", "release", "tools", "geomcheck"),
                    help="the geomcheck tool, for from-fuzz (default build/release/tools/geomcheck)")
    ap.add_argument("--regressions", default=os.path.join(root, "corpora", "regressions"),
                    help="where new findings are filed (default corpora/regressions)")
    ap.add_argument("--seeds", default=os.path.join(root, "corpora", "seeds"), help="seed case files")
    ap.add_argument("--minimise-seconds", type=int, default=60, help="per new finding (default 60)")
    args = ap.parse_args()
    if args.seconds < 0 or args.jobs < 1 or args.minimise_seconds < 1:
        ap.error("--seconds must be >= 0, --jobs and --minimise-seconds >= 1")
    args.work = os.path.abspath(args.work)
    args.regressions = os.path.abspath(args.regressions)
    args.run_flags = ["-max_len=512", "-timeout=10", "-rss_limit_mb=2560", "-print_funcs=0"]
    if not os.path.exists(args.geomcheck):
        sys.exit(f"nightly: {args.geomcheck} not found (cmake --build --preset release --target geomcheck)")

    for d in ("corpus", "findings", "pruned", "logs", "tmp"):
        os.makedirs(os.path.join(args.work, d), exist_ok=True)
    lock = open(os.path.join(args.work, "lock"), "w")
    try:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        sys.exit(f"nightly: another run holds {args.work}/lock")
    shutil.rmtree(os.path.join(args.work, "tmp"))
    os.makedirs(os.path.join(args.work, "tmp"))
    signal.signal(signal.SIGINT, on_signal)
    signal.signal(signal.SIGTERM, on_signal)

    targets = discover_targets(args)
    stamp = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
    per_target = args.seconds // len(targets) if targets else 0
    if args.seconds and per_target < 1:
        sys.exit("nightly: --seconds is less than one second per target")
    logs = os.path.join(args.work, "logs", stamp.replace(":", ""))
    os.makedirs(logs, exist_ok=True)
    report = {"started": stamp, "seconds_per_target": per_target, "jobs": args.jobs, "work": args.work,
              "regressions": args.regressions, "status": "running", "targets": []}
    log(f"{len(targets)} targets, {per_target} s each, {args.jobs} jobs; state in {args.work}; logs in {logs}")
    seeds_root = os.path.join(args.work, "seeds")
    make_seeds = os.path.join(args.fuzz_dir, "make_fuzz_seeds")
    if os.access(make_seeds, os.X_OK):
        run([make_seeds, args.seeds, seeds_root])
    known = known_signatures(args.regressions)
    try:
        for i, t in enumerate(targets):
            check_stop()
            entry = {"name": t["name"], "query": t["query"], "status": "started",
                     "findings": {"inputs": 0, "new": [], "duplicates": 0, "not_reproduced": 0}}
            report["targets"].append(entry)
            corpus = os.path.join(args.work, "corpus", t["name"])
            recover_swap(corpus)
            # Pending findings of an interrupted run first.
            process_findings(t, args, known, stamp, entry["findings"])
            entry["corpus_before"] = len(list_files(corpus))
            if per_target > 0:
                log(f"[{i + 1}/{len(targets)}] {t['name']}: fuzzing {per_target} s (corpus {entry['corpus_before']})")
                entry["fuzz"] = fuzz_target(t, args, per_target, os.path.join(logs, t["name"] + ".log"))
                f = entry["fuzz"]
                log(f"  {f['execs']:,} executions, coverage {f['cov_start']} -> {f['cov_end']} edges")
            check_stop()
            entry["corpus_after_fuzz"] = len(list_files(corpus))
            _, after, pruned = merge_corpus(t["path"], corpus, args.work,
                                            os.path.join(args.work, "pruned", t["name"]), args.run_flags)
            entry["corpus_after_merge"], entry["pruned"] = after, pruned
            log(f"  corpus {entry['corpus_before']} -> {entry['corpus_after_fuzz']} -> {after} after merge "
                f"({pruned} pruned entries kept in pruned/)")
            process_findings(t, args, known, stamp, entry["findings"])
            fnd = entry["findings"]
            log(f"  findings: {fnd['inputs']} inputs, {len(fnd['new'])} new, {fnd['duplicates']} duplicates")
            entry["status"] = "done"
            write_report(args, report)
        report["status"] = "finished"
    except Interrupted:
        report["status"] = "interrupted"
        if report["targets"]:
            report["targets"][-1]["status"] = "interrupted"
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_IGN)
    write_report(args, report)
    new = sum(len(t["findings"]["new"]) for t in report["targets"])
    log(f"{report['status']}: {new} new findings; report {os.path.join(args.work, 'report.html')}")
    if report["status"] == "interrupted":
        log("interrupted: nothing is lost; run again to fuzz on and to file what was pending")
        return 130
    return 1 if new else 0


if __name__ == "__main__":
    sys.exit(main())
