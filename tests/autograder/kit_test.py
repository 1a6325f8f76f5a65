#!/usr/bin/env python3
"""End-to-end test of the instructor's autograder kit (autograder/, docs/autograder.md).

Runs autograder/run_autograder, as Gradescope would, on each sample submission of
tests/autograder/submissions (correct, wrong, crashing, hanging, hostile) against a small scene
suite, and checks each results.json; checks that the hostile sample failed at every escape, by
its own report and independently (the file system, a listening socket, the process table); then
runs the two recipes: autograder/grade-many.sh over the folder of submissions with GNU parallel
(when `parallel` is installed) and autograder/slurm-grade.sh as two tasks of a Slurm array, with
Slurm's variables set by hand, merged with `fosssim-oracle merge`.

Usage: kit_test.py BIN_DIR SOURCE_DIR WORK_DIR
"""
import json
import os
import shutil
import socket
import subprocess
import sys
import threading
import time

BIN, SOURCE, WORK = (os.path.abspath(a) for a in sys.argv[1:4])
KIT = os.path.join(SOURCE, "autograder")
SAMPLES = os.path.join(SOURCE, "tests", "autograder", "submissions")
SCENES = os.path.join(SOURCE, "tests", "oracle", "data", "assets", "basics")
TOKEN = str(7_000_000 + os.getpid())  # the hostile sample's `sleep` seconds: unique to this run
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL: " + message, flush=True)


class Listener:
    """A TCP listener on 127.0.0.1 that counts the connections it accepts."""

    def __init__(self):
        self.server = socket.socket()
        self.server.bind(("127.0.0.1", 0))
        self.server.listen(8)
        self.server.settimeout(0.2)
        self.port = self.server.getsockname()[1]
        self.accepted = 0
        self.running = True
        self.thread = threading.Thread(target=self.serve, daemon=True)
        self.thread.start()

    def serve(self):
        while self.running:
            try:
                connection, _ = self.server.accept()
                self.accepted += 1
                connection.close()
            except socket.timeout:
                pass

    def close(self):
        self.running = False
        self.thread.join()
        self.server.close()


def processes_with(token):
    """The ids of the machine's processes whose command line holds `token` as a word."""
    found = []
    for pid in os.listdir("/proc"):
        if not pid.isdigit():
            continue
        try:
            with open("/proc/%s/cmdline" % pid, "rb") as f:
                words = f.read().split(b"\0")
        except OSError:
            continue
        if token.encode() in words:
            found.append(int(pid))
    return found


shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
outside = os.path.join(WORK, "outside")
os.makedirs(outside)
listener = Listener()
environment = dict(os.environ)
environment.update({
    "KIT_BIN": BIN,
    "KIT_SCENES": SCENES,
    "KIT_EXTRA_CREDIT": "",
    "KIT_WORK": WORK,
    "KIT_TIMEOUTS_FILE": os.path.join(WORK, "timeouts.tsv"),
    "KIT_TIMEOUT_FLOOR": "1",
    "KIT_TIMEOUT_MULTIPLE": "5",
    "KIT_ALLOW_READ": BIN,
    "FOSSSIM_REFERENCE": os.path.join(BIN, "FOSSSim"),
    "KIT_TEST_OUTSIDE": outside,
    "KIT_TEST_OTHER": os.path.join(SAMPLES, "correct", "build.sh"),
    "KIT_TEST_PORT": str(listener.port),
    "KIT_TEST_TOKEN": TOKEN,
})
environment.pop("KIT_TIMEOUT", None)
run_autograder = os.path.join(KIT, "run_autograder")

# The time-outs: measured from the reference, floor 1 s here (default 10 s).
measured = subprocess.run([run_autograder, "--measure"], env=environment, capture_output=True,
                          text=True, timeout=120)
check(measured.returncode == 0, "run_autograder --measure failed: " + measured.stderr)
with open(environment["KIT_TIMEOUTS_FILE"], encoding="utf-8") as f:
    lines = [line.split() for line in f if not line.startswith("#")]
check(len(lines) == 2, "timeouts.tsv has %d scenes, expected 2" % len(lines))
for name, seconds in lines:
    check(name.startswith("basics/") and float(seconds) >= 1.0,
          "timeouts.tsv line %s %s: expected a basics/ scene and at least the floor" % (name, seconds))

# A --timeouts file with a mistake is refused before anything runs, naming the file and line.
oracle = os.path.join(BIN, "fosssim-oracle")
for content, problem in (("basics/spring_chain_explicit.xml 0\n", "not a number above 0"),
                         ("basics/none.xml 3\n", "no scene \"basics/none.xml\""),
                         ("# c\nbasics/spring_chain_explicit.xml 3\nbasics/spring_chain_explicit.xml 4\n",
                          "already given on line 2"),
                         ("basics/spring_chain_explicit.xml\n", "expected a scene name and seconds")):
    bad = os.path.join(WORK, "bad-timeouts.tsv")
    with open(bad, "w", encoding="utf-8") as f:
        f.write(content)
    refused = subprocess.run([oracle, "grade", "--candidate", environment["FOSSSIM_REFERENCE"],
                              "--timeouts", bad, SCENES], capture_output=True, text=True, timeout=60)
    line = content.count("\n") if "already" in problem else 1
    check(refused.returncode == 2 and ("%s:%d: " % (bad, line)) in refused.stderr
          and problem in refused.stderr,
          "--timeouts %r: exit %d, %r" % (content, refused.returncode, refused.stderr))

expected = {  # sample: (score, the verdict text each scene's output starts with)
    "correct": (2, "PASS"),
    "wrong": (0, "FAIL"),
    "crashing": (0, "CRASH"),
    "hanging": (0, "TIMEOUT"),
    "hostile": (0, "EXIT"),
}
for sample, (score, verdict) in expected.items():
    results = os.path.join(WORK, "results", sample, "results.json")
    environment["KIT_SUBMISSION"] = os.path.join(SAMPLES, sample)
    environment["KIT_RESULTS"] = results
    start = time.monotonic()
    run = subprocess.run([run_autograder], env=environment, capture_output=True, text=True,
                         timeout=120)
    seconds = time.monotonic() - start
    print("%s: exit %d in %.1f s" % (sample, run.returncode, seconds), flush=True)
    check(run.returncode == 0, "%s: run_autograder exited %d: %s" % (sample, run.returncode,
                                                                       run.stderr[-2000:]))
    if run.returncode != 0:
        continue
    with open(results, encoding="utf-8") as f:
        report = json.load(f)
    check(report["score"] == score, "%s: score %s, expected %s" % (sample, report["score"], score))
    check(len(report["tests"]) == 2, "%s: %d tests, expected 2" % (sample, len(report["tests"])))
    for test in report["tests"]:
        # A passed scene's output starts with the verdict, a failed one's with the scene's name.
        check(test["output"].startswith((verdict + " (", test["name"] + ": " + verdict + " ("))
              and test["max_score"] == 1,
              "%s: %s: output %r, expected %s" % (sample, test["name"], test["output"][:200],
                                                  verdict))
    check("Time-out per scene: 5 x the reference simulator's own run time of the scene, "
          "at least 1 s" in report["output"], "%s: no time-out statement in %r"
          % (sample, report["output"]))
    if sample == "hanging":
        check(seconds < 30, "hanging: took %.1f s; the time-outs are about 1 s" % seconds)
    if sample == "hostile":
        text = json.dumps(report)
        for attempt in ("write outside", "write beside", "write own folder",
                        "read other submission", "open socket", "read other submission while built"):
            check("BLOCKED: " + attempt in text, "hostile: no 'BLOCKED: %s' in the report" % attempt)
        check("ESCAPED" not in text, "hostile: the report says it escaped: " + text[:3000])
        check("LEFT: sleep " + TOKEN in text, "hostile: it did not get to leave a process")

# The hostile sample, checked from outside.
time.sleep(0.5)
check(os.listdir(outside) == [], "hostile: wrote into the outside folder: %s" % os.listdir(outside))
check(not os.path.exists(os.path.join(SAMPLES, "escaped")) and
      not os.path.exists(os.path.join(SAMPLES, "hostile", "escaped")),
      "hostile: wrote beside or into its submission folder")
check(listener.accepted == 0, "hostile: %d connections reached the listener" % listener.accepted)
left = processes_with(TOKEN)
check(left == [], "hostile: processes left behind: %s" % left)
for pid in left:
    os.kill(pid, 9)
listener.close()

# Recipe 1: GNU parallel over a folder of submissions.
if shutil.which("parallel"):
    out = os.path.join(WORK, "many")
    many = subprocess.run([os.path.join(KIT, "grade-many.sh"), SAMPLES, out, "3"], env=environment,
                          capture_output=True, text=True, timeout=180)
    check(many.returncode == 0, "grade-many.sh exited %d: %s" % (many.returncode, many.stderr[-2000:]))
    for sample, (score, _) in expected.items():
        path = os.path.join(out, sample, "results.json")
        if not os.path.exists(path):
            check(False, "grade-many.sh: no %s" % path)
            continue
        with open(path, encoding="utf-8") as f:
            got = json.load(f)["score"]
        check(got == score, "grade-many.sh: %s scored %s, expected %s" % (sample, got, score))
    summary = os.path.join(out, "scores.tsv")
    check(os.path.exists(summary), "grade-many.sh: no scores.tsv")
else:
    print("SKIP: GNU parallel is not installed (tools/install-deps.sh installs it)")

# Recipe 2: a Slurm array of 2 tasks (ids 3 and 4, to check the count from the minimum), one
# submission, each task one shard of the scenes, then merged.
out = os.path.join(WORK, "slurm")
os.makedirs(out)
for task in ("3", "4"):
    slurm = dict(environment, SLURM_ARRAY_TASK_ID=task, SLURM_ARRAY_TASK_MIN="3",
                 SLURM_ARRAY_TASK_COUNT="2", KIT_SUBMISSION=os.path.join(SAMPLES, "correct"),
                 KIT_SHARD_DIR=out)
    task_run = subprocess.run([os.path.join(KIT, "slurm-grade.sh")], env=slurm,
                              capture_output=True, text=True, timeout=120)
    check(task_run.returncode == 0, "slurm-grade.sh task %s exited %d: %s"
          % (task, task_run.returncode, task_run.stderr[-2000:]))
shards = sorted(os.path.join(out, f) for f in os.listdir(out))
check([os.path.basename(s) for s in shards] == ["shard-1.json", "shard-2.json"],
      "slurm-grade.sh wrote %s, expected shard-1.json and shard-2.json" % shards)
merged = os.path.join(WORK, "slurm-results.json")
merge = subprocess.run([os.path.join(BIN, "fosssim-oracle"), "merge", *shards, "--gradescope",
                        merged], capture_output=True, text=True, timeout=60)
check(merge.returncode == 0, "merge exited %d: %s" % (merge.returncode, merge.stderr))
if merge.returncode == 0:
    with open(merged, encoding="utf-8") as f:
        report = json.load(f)
    check(report["score"] == 2 and len(report["tests"]) == 2,
          "the merged Slurm shards: score %s over %d tests, expected 2 over 2"
          % (report["score"], len(report["tests"])))

# The zip for Gradescope: setup.sh and run_autograder at its top, executable, and the
# repository's copy that setup.sh builds.
if shutil.which("git") and os.path.exists(os.path.join(SOURCE, ".git")):
    import zipfile
    archive = os.path.join(WORK, "autograder.zip")
    made = subprocess.run([os.path.join(KIT, "make-zip.sh"), archive], capture_output=True,
                          text=True, timeout=120)
    check(made.returncode == 0, "make-zip.sh exited %d: %s" % (made.returncode, made.stderr))
    if made.returncode == 0:
        with zipfile.ZipFile(archive) as z:
            names = set(z.namelist())
            for name in ("setup.sh", "run_autograder"):
                check(name in names and (z.getinfo(name).external_attr >> 16) & 0o111,
                      "the zip has no executable " + name)
            for name in ("fosssim/CMakeLists.txt", "fosssim/tools/install-deps.sh",
                         "fosssim/autograder/run_autograder", "fosssim/assets/t1m1/springs_single.xml"):
                check(name in names, "the zip has no " + name)
else:
    print("SKIP: make-zip.sh needs a git checkout")

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("all checks passed")
