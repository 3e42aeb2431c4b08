#!/usr/bin/env python3
"""Runs every entry of tests/fuzz/corpus/manifest.json through the coilsim
binary and checks: the expected exit code (2 for a refused input, 0 for a
valid one), the expected text in the output (the file's name, the JSON path),
never a signal, never an uncaught exception ("terminate called"), never a
sanitizer report, never over the entry's time bound (the harness kills it).

Entries marked "open" (the fix lies outside the readers, tests/fuzz/OPEN.md)
are run and listed, but do not fail the test; one that passes is listed too,
so its mark can be removed.

usage: run_corpus.py --binary build/src/app/coilsim [--jobs N] [--filter REGEX] [--verbose]
exit: 0 when every entry not marked open passes, 1 otherwise, 2 on bad usage.
"""
import argparse
import concurrent.futures
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def run_entry(entry, binary, src, corpus, scratch, timeout_scale):
    out = tempfile.mkdtemp(prefix="e", dir=scratch)
    file = os.path.join(corpus, entry["file"]) if entry.get("file") else ""
    subst = {"{file}": file, "{dir}": os.path.dirname(file), "{src}": src, "{out}": out, "{corpus}": corpus}

    def expand(s):
        for k, v in subst.items():
            s = s.replace(k, v)
        return s

    args = [binary] + [expand(a) for a in entry["args"]]
    env = dict(os.environ)
    env.pop("DISPLAY", None)  # nothing may open a window
    env.pop("WAYLAND_DISPLAY", None)
    timeout = entry.get("timeout_s", 20) * timeout_scale
    start = time.monotonic()
    proc = subprocess.Popen(args, cwd=out, env=env, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, start_new_session=True)
    timed_out = False
    try:
        stdout, stderr = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        timed_out = True
        os.killpg(proc.pid, signal.SIGKILL)
        stdout, stderr = proc.communicate()
    seconds = time.monotonic() - start
    text_out = stdout.decode("utf-8", "replace")
    text_err = stderr.decode("utf-8", "replace")
    problems = []
    code = proc.returncode
    if timed_out:
        problems.append("over the time bound of %g s (killed)" % timeout)
    elif code < 0:
        problems.append("ended by signal %d (%s)" % (-code, signal.Signals(-code).name if -code in
                                                     signal.valid_signals() else "?"))
    else:
        if code != entry["exit"]:
            problems.append("exit %d, expected %d" % (code, entry["exit"]))
        if "terminate called" in text_err:
            problems.append("uncaught exception (terminate called)")
        if re.search(r"(AddressSanitizer|LeakSanitizer|runtime error:|UndefinedBehaviorSanitizer)", text_err):
            problems.append("sanitizer report")
        # A refusal names what is wrong on stderr; a valid run may say it anywhere.
        where = text_err if entry["exit"] == 2 else text_out + text_err
        for c in entry.get("contains", []):
            if expand(c) not in where:
                problems.append("output lacks %r" % expand(c))
    shutil.rmtree(out, ignore_errors=True)
    return {"entry": entry, "problems": problems, "seconds": seconds, "code": code, "stderr": text_err.strip(),
            "args": args}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--binary", required=True)
    ap.add_argument("--corpus", default=os.path.join(HERE, "corpus"))
    ap.add_argument("--src", default=os.path.normpath(os.path.join(HERE, "..", "..")))
    ap.add_argument("--jobs", type=int, default=min(2, os.cpu_count() or 1))
    ap.add_argument("--filter", default="", help="only entries whose name matches this regular expression")
    ap.add_argument("--timeout-scale", type=float, default=1.0, help="e.g. 3 under sanitizers")
    ap.add_argument("--verbose", action="store_true", help="print every entry and its stderr")
    a = ap.parse_args()
    binary = os.path.abspath(a.binary)
    if not os.access(binary, os.X_OK):
        print("run_corpus: %s is not an executable" % binary, file=sys.stderr)
        return 2
    with open(os.path.join(a.corpus, "manifest.json")) as f:
        entries = json.load(f)["entries"]
    entries = [e for e in entries if re.search(a.filter, e["name"])]
    # Entries that may run to their bound first, so that they overlap the quick ones.
    entries.sort(key=lambda e: ("open" not in e, -e.get("timeout_s", 20)))
    corpus = os.path.abspath(a.corpus)
    src = os.path.abspath(a.src)
    start = time.monotonic()
    results = []
    with tempfile.TemporaryDirectory(prefix="coilsim-fuzz-") as scratch:
        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as pool:
            futures = [pool.submit(run_entry, e, binary, src, corpus, scratch, a.timeout_scale) for e in entries]
            for fut in concurrent.futures.as_completed(futures):
                r = fut.result()
                results.append(r)
                if a.verbose:
                    print("%-6s %-70s %5.2fs exit %s\n        %s" % ("ok" if not r["problems"] else "FAIL",
                          r["entry"]["name"], r["seconds"], r["code"], r["stderr"][:300].replace("\n", "\n        ")))
    results.sort(key=lambda r: r["entry"]["name"])
    failed = [r for r in results if r["problems"] and "open" not in r["entry"]]
    still_open = [r for r in results if r["problems"] and "open" in r["entry"]]
    fixed = [r for r in results if not r["problems"] and "open" in r["entry"]]
    slowest = max(results, key=lambda r: r["seconds"]) if results else None

    def show(r):
        print("  %s (%.1f s)\n    problems: %s\n    command: %s" % (r["entry"]["name"], r["seconds"],
              "; ".join(r["problems"]), " ".join(r["args"])))
        if r["stderr"]:
            print("    stderr: " + r["stderr"][:400].replace("\n", "\n            "))

    if still_open:
        print("OPEN (known, fix outside the readers; tests/fuzz/OPEN.md), %d entries:" % len(still_open))
        for r in still_open:
            print("  %s: %s\n    reason: %s" % (r["entry"]["name"], "; ".join(r["problems"]), r["entry"]["open"]))
    if fixed:
        print("OPEN entries that now pass (remove their \"open\" mark in generate.py), %d:" % len(fixed))
        for r in fixed:
            print("  " + r["entry"]["name"])
    if failed:
        print("FAILED, %d entries:" % len(failed))
        for r in failed:
            show(r)
    print("fuzz corpus: %d entries, %d passed, %d failed, %d open (%d of them now pass), %.1f s with %d jobs%s" %
          (len(results), len(results) - len(failed) - len(still_open), len(failed), len(still_open) + len(fixed),
           len(fixed), time.monotonic() - start, a.jobs,
           "; slowest %s %.1f s" % (slowest["entry"]["name"], slowest["seconds"]) if slowest else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
