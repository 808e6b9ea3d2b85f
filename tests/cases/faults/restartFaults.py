"""The fault tests of stopped runs and restarts, for either solver
(tests/cases/faults/stopAndRestart*/check): a run that is stopped (SIGTERM,
SIGINT, SIGKILL at random moments, a full disk) leaves its last complete
time directory intact and restarts from it into the same answer, byte for
byte, with the cloud in binary (the default) or ASCII, the fields in ASCII
at writePrecision 6 or binary, or compressed (writeCompression on); a
restart refuses, by name, an incomplete
directory it cannot fall back from, a complete one missing a piece, and a
corrupt (ASCII) cloud."""
import gzip
import os
import random
import re
import shutil
import signal
import subprocess
import time

import faultCheck as fc
from faultCheck import check


class Case:
    def __init__(self, solver, cloud, state, pieces, corruptions):
        self.solver, self.cloud, self.state = solver, cloud, state
        #: Files of a written time directory a restart requires, beyond
        #: the cloud's: {name: path}
        self.pieces = pieces
        #: Corrupt clouds: {name: (file in the cloud or "*" for every file,
        #: edit(text) -> text, words)}
        self.corruptions = corruptions

    def run(self, case, log=None):
        return fc.run([self.solver], case, log or "log." + self.solver)

    def finalFiles(self, case, t):
        state = os.path.join("uniform", self.state)
        if not os.path.isfile(os.path.join(case, t, state)):
            state += ".gz"  # writeCompression on
        return fc.cloudFiles(case, t, self.cloud) + [state]


def reference(c):
    ref = fc.newRun("ref")
    status, out = c.run(ref)
    fc.checkAccepted("ref", status, out)
    times = fc.timeDirs(ref)
    check(len(times) >= 3 and all(fc.complete(ref, t) for t in times),
          "ref: every time directory %s has uniform/%s" % (times, fc.recordName))
    return ref, times


def stopBySignal(c, ref, times, sig):
    name = signal.Signals(sig).name
    nRef = len(fc.summaryRows(ref, c.solver))
    # The signal goes halfway through the run. On a loaded machine the rest
    # of a short run can end before it arrives (exit 0), or it arrives just
    # after the last time is written (the run stops at endTime, and a
    # restart has nothing to run): run again, up to 5 times. Any other
    # outcome is the one checked
    for attempt in range(5):
        run = fc.newRun("stop" + name)
        p = fc.start(run, "log.stop")
        fc.waitForRows(p, run, c.solver, nRef // 2)
        p.send_signal(sig)
        status = p.wait(120)
        dirs = fc.timeDirs(run)
        late = status == 0 or (status == 128 + sig and dirs[-1:] == times[-1:])
        if not late:
            break
    else:
        check(False, "%s: the signal came before the last step in one of 5 runs" % name)
    log = open(os.path.join(run, "log.stop")).read()
    check(status == 128 + sig, "%s: the stopped run exits with 128 + %d (%s)" % (name, sig, status))
    check("Caught signal %d" % sig in log and "End" in log,
          "%s: the log says the signal was caught and the run ended" % name)
    stopTime = fc.timeDirs(run)[-1]
    check(fc.complete(run, stopTime), "%s: the stop time %s is written completely" % (name, stopTime))
    status, out = c.run(run, "log.restart")
    fc.checkAccepted(name + " restart", status, out)
    final = times[-1]
    fc.sameFiles(ref, run, final, c.finalFiles(ref, final), name + " restart")
    fc.sameRowsAfter(ref, run, c.solver, stopTime, name + " restart")


def formatVariant(c, ref, times, name, entries, cloudFormat):
    """A run with controlDict entries: its cloud written in cloudFormat,
    every summary row that of ref, and a restart from its first write that
    ends in its own final files, byte for byte. Returns the run."""
    run = fc.newRun(name, entries=entries)
    status, out = c.run(run)
    fc.checkAccepted(name, status, out)
    check(cloudWrittenIn(run, times[1], c.cloud, cloudFormat),
          "%s: the cloud is written in %s" % (name, cloudFormat))
    check(fc.summaryRows(run, c.solver) == fc.summaryRows(ref, c.solver),
          "%s: every summary row that of the reference run" % name)
    restart = fc.newRun(name + "Restart", base=run, times=[times[1]])
    status, out = c.run(restart)
    fc.checkAccepted(name + " restart", status, out)
    fc.sameFiles(run, restart, times[-1], c.finalFiles(run, times[-1]), name + " restart")
    return run


def cloudWrittenIn(case, time, cloud, fmt):
    positions = open(os.path.join(case, time, "lagrangian", cloud, "positions"), "rb").read()
    return ("format      %s;" % fmt).encode() in positions


def formats(c, ref, times):
    """The reference writes its cloud in binary (cloudFormat's default) and
    its fields in ASCII at writePrecision 6; everything in binary, and the
    cloud in ASCII (17 digits), give the same rows and restart exactly.
    Returns the run with the ASCII cloud."""
    check(cloudWrittenIn(ref, times[1], c.cloud, "binary"),
          "ref: the cloud is written in binary by default")
    formatVariant(c, ref, times, "binary", {"writeFormat": "binary"}, "binary")
    return formatVariant(c, ref, times, "asciiCloud", {"cloudFormat": "ascii"}, "ascii")


def compressed(c, ref, times):
    """writeCompression on: the background writer deflates the files (gzip,
    zlib's fastest level). Every summary row is that of ref, a restart from
    the first write ends in its own final files, byte for byte, and each
    time directory holds the files that the solver's own thread writes
    through OpenFOAM's compressed stream (writeInBackground no), the same
    text decompressed."""
    run = formatVariant(c, ref, times, "compressed", {"writeCompression": "on"}, "binary")
    own = fc.newRun("compressedForeground", entries={"writeCompression": "on", "writeInBackground": "no"})
    status, out = c.run(own)
    fc.checkAccepted("compressedForeground", status, out)
    check(fc.timeDirs(own) == times, "compressedForeground: the time directories %s" % times)
    text = lambda path: gzip.open(path).read() if path.endswith(".gz") else open(path, "rb").read()
    nCompressed = 0
    for t in times:
        listed = [fc.dp.files_below(os.path.join(case, t)) for case in (run, own)]
        check(listed[0] == listed[1], "compressed: the files of %s are the solver thread's (%s)"
              % (t, sorted(set(listed[0]) ^ set(listed[1])) or "the same"))
        differ = [f for f in listed[0] if text(os.path.join(run, t, f)) != text(os.path.join(own, t, f))]
        check(not differ, "compressed: %s decompressed as the solver thread's (differ: %s)"
              % (t, differ or "none"))
        links = [[os.stat(os.path.join(case, t, f)).st_nlink for f in listed[0]] for case in (run, own)]
        check(links[0] == links[1], "compressed: the links of %s are the solver thread's (%s)"
              % (t, [f for f, a, b in zip(listed[0], *links) if a != b] or "all"))
        nCompressed += sum(f.endswith(".gz") for f in listed[0])
    check(nCompressed > 0, "compressed: %d files compressed in %d time directories" % (nCompressed, len(times)))


def foreground(c, ref, times):
    """The reference's time directories are written by the background
    writer (writeInBackground's default); written by the solver's own thread
    (writeInBackground no) they hold the same files, byte for byte, with the
    same hard links (a static field linked from its first write)."""
    run = fc.newRun("foreground", entries={"writeInBackground": "no"})
    status, out = c.run(run)
    fc.checkAccepted("foreground", status, out)
    check(fc.timeDirs(run) == times, "foreground: the time directories %s" % times)
    for t in times:
        listed = [fc.dp.files_below(os.path.join(case, t)) for case in (ref, run)]
        check(listed[0] == listed[1], "foreground: the files of %s are the background's" % t)
        fc.sameFiles(ref, run, t, listed[0], "foreground")
        links = [[os.stat(os.path.join(case, t, f)).st_nlink for f in listed[0]] for case in (ref, run)]
        check(links[0] == links[1], "foreground: the links of %s are the background's (%s)"
              % (t, [f for f, a, b in zip(listed[0], *links) if a != b] or "all"))


def killed(c, times, nKills=8, seed=5):
    """SIGKILL at random moments of a run that writes every few steps and
    keeps 2 time directories (purgeWrite), restarted after every kill."""
    frequent = {"writeInterval": 0.01, "purgeWrite": 2}
    ref = fc.newRun("frequent", entries=frequent)
    started = time.time()
    status, out = c.run(ref)
    whole = time.time() - started
    fc.checkAccepted("frequent", status, out)
    run = fc.newRun("kill", entries=frequent)
    rng = random.Random(seed)
    kills = incomplete = 0
    for k in range(nKills):
        # Into the time loop (its first summary row: the time series of
        # the runs before are removed), then a random moment within a
        # share of the whole run's time such that all the kills come
        # before its end however fast this machine runs it
        shutil.rmtree(os.path.join(run, "postProcessing"), ignore_errors=True)
        p = fc.start(run, "log.kill%d" % k)
        fc.waitForRows(p, run, c.solver, 1)
        time.sleep(rng.uniform(0.0, whole / (2 * nKills)))
        if p.poll() is not None:
            break
        p.kill()
        p.wait()
        kills += 1
        dirs = fc.timeDirs(run)
        if dirs and not fc.complete(run, dirs[-1]):
            incomplete += 1
        check(any(fc.complete(run, d) for d in dirs),
              "kill %d: a complete time directory remains (%s)" % (k, dirs))
    check(kills == nKills, "%d of %d kills hit the run before it ended" % (kills, nKills))
    status, out = c.run(run, "log.kill.end")
    fc.checkAccepted("after %d kills" % kills, status, out)
    final = fc.timeDirs(ref)[-1]
    fc.sameFiles(ref, run, final, c.finalFiles(ref, final), "after %d kills (%d left an incomplete"
                 " time directory)" % (kills, incomplete))


def incompleteDirectories(c, ref, times):
    t1, t2 = times[1], times[2]

    def makeIncomplete(case):
        os.remove(os.path.join(case, t2, "uniform", fc.recordName))
        U = os.path.join(case, t2, "lagrangian", c.cloud, "U")
        data = open(U, "rb").read()
        open(U, "wb").write(data[:len(data) // 2])

    run = fc.newRun("incomplete", base=ref, times=times[:3])
    makeIncomplete(run)
    status, out = c.run(run)
    fc.checkAccepted("incomplete", status, out,
                     ["time directory %s is incomplete" % t2, "Starting from %s" % t1])
    fc.sameFiles(ref, run, times[-1], c.finalFiles(ref, times[-1]), "incomplete: fell back and")

    # A write stopped before its first file: an empty directory after a
    # complete one is incomplete, not a fresh start (no release again)
    run = fc.newRun("emptyLatest", base=ref, times=times[:2])
    os.makedirs(os.path.join(run, t2, "uniform"))
    status, out = c.run(run)
    fc.checkAccepted("emptyLatest", status, out,
                     ["time directory %s is incomplete" % t2, "Starting from %s" % t1])
    fc.sameFiles(ref, run, times[-1], c.finalFiles(ref, times[-1]), "emptyLatest: fell back and")

    run = fc.newRun("incompleteStartTime", base=ref, times=times[:3],
                    entries={"startFrom": "startTime", "startTime": t2})
    makeIncomplete(run)
    status, out = c.run(run)
    fc.checkRefused("incompleteStartTime", status, out,
                    [t2, "is incomplete", "last complete time directory is %s" % t1, "controlDict"],
                    run, written=times[:3])

    run = fc.newRun("incompleteFirst", base=ref, times=[t2])
    makeIncomplete(run)
    status, out = c.run(run)
    fc.checkRefused("incompleteFirst", status, out,
                    [t2, "is incomplete", "No complete time directory precedes it"], run, written=[t2])


def missingPieces(c, ref, times):
    t = times[1]
    pieces = dict(c.pieces)
    pieces["missingMass"] = os.path.join("lagrangian", c.cloud, "m")
    pieces["missingState"] = os.path.join("uniform", c.state)
    pieces["missingCloud"] = os.path.join("lagrangian", c.cloud)
    for name, path in pieces.items():
        run = fc.newRun(name, base=ref, times=[t], )
        target = os.path.join(run, t, path)
        shutil.rmtree(target) if os.path.isdir(target) else os.remove(target)
        status, out = c.run(run)
        fc.checkRefused(name, status, out, [os.path.basename(path), t], run, written=[t])


def corruptClouds(c, ref, times):
    """Edits of an ASCII cloud (ref: a run with cloudFormat ascii)."""
    t = times[1]
    for name, (field, edit, words) in c.corruptions.items():
        run = fc.newRun(name, base=ref, times=[t])
        cloudDir = os.path.join(run, t, "lagrangian", c.cloud)
        for f in os.listdir(cloudDir) if field == "*" else [field]:
            path = os.path.join(cloudDir, f)
            text = edit(open(path).read())
            open(path, "w").write(text)
        status, out = c.run(run)
        fc.checkRefused(name, status, out, words, run, written=[t])


def fullDisk(c, ref, times):
    """The case and its log on a file system too small for all its time
    directories (a tmpfs; where mounting is not allowed, a file-size limit,
    the output in a pipe): the run stops
    with a FatalError naming the last complete time directory, which a
    restart elsewhere continues into the same answer."""
    import resource
    work = os.path.abspath(os.path.join("variants", "fullDisk"))
    subprocess.run(["umount", work], capture_output=True)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    size = lambda d: sum(os.path.getsize(os.path.join(d, f)) for f in fc.dp.files_below(d))
    need = size(os.path.join(ref, "constant")) + size(os.path.join(ref, "system")) \
        + size(os.path.join(ref, times[0])) + size(os.path.join(ref, times[1]))
    room = need + size(os.path.join(ref, times[2])) // 2
    mounted = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=%dk" % (room // 1024 + 1), "tmpfs", work],
                             capture_output=True).returncode == 0
    case = os.path.join(work, "case")
    for d in ("system", "constant"):
        shutil.copytree(os.path.join(ref, d), os.path.join(case, d))
    limit = None
    if not mounted:
        # Files may not grow beyond the biggest file of the second write
        second = os.path.join(ref, times[2])
        biggest = max(os.path.getsize(os.path.join(second, f)) for f in fc.dp.files_below(second))
        limit = lambda: resource.setrlimit(resource.RLIMIT_FSIZE, (biggest - 1, biggest - 1))
    if mounted:
        # The whole output on the full disk, as runApplication writes it:
        # writes of the log that fail must not end in a signal (the log
        # may have no byte left for the message)
        with open(os.path.join(case, "log." + c.solver), "w") as log:
            status = subprocess.run([c.solver, "-case", case], stdout=log, stderr=subprocess.STDOUT).returncode
        check(status > 0, "fullDisk, the log on the full disk too: stops with an error exit code (%s)"
              % fc.describeStatus(status))
        for d in os.listdir(case):
            if d not in ("system", "constant"):
                shutil.rmtree(os.path.join(case, d)) if os.path.isdir(os.path.join(case, d)) \
                    else os.remove(os.path.join(case, d))
        # Again, the log there, the errors in a pipe
        logPath = os.path.join(case, "log." + c.solver)
        with open(logPath, "w") as log:
            r = subprocess.run([c.solver, "-case", case], stdout=log, stderr=subprocess.PIPE)
        status = r.returncode
        out = open(logPath, errors="replace").read() + r.stderr.decode("utf-8", "replace")
    else:
        r = subprocess.run([c.solver, "-case", case], capture_output=True, preexec_fn=limit)
        status, out = r.returncode, (r.stdout + r.stderr).decode("utf-8", "replace")
    how = "a tmpfs of %d kB" % (room // 1024) if mounted else "a file-size limit"
    fc.checkRefused("fullDisk (%s)" % how, status, out,
                    [("cannot write time directory", "cannot write")], None)
    written = [d for d in fc.timeDirs(case) if fc.complete(case, d)]
    check(len(written) >= 1, "fullDisk: complete time directories remain (%s)" % written)
    if "cannot write time directory" in out:
        check(("last complete time directory is %s" % written[-1]) in out,
              "fullDisk: the message names the last complete time directory (%s)" % written[-1:])
    # Room again: the case moved to a disk with space
    moved = fc.newRun("fullDiskMoved", base=case, times=fc.timeDirs(case))
    if mounted:
        subprocess.run(["umount", work], capture_output=True)
    status, out = c.run(moved)
    fc.checkAccepted("fullDisk restart", status, out)
    fc.sameFiles(ref, moved, times[-1], c.finalFiles(ref, times[-1]), "fullDisk restart")


# Edits of a cloud's files ----------------------------------------------------

def expandUniform(text):
    """A uniform list 'N{value}' (OpenFOAM writes one when every value is the
    same) as the list 'N ( value ... value )'."""
    m = re.search(r"\n(\d+)\{([^}]*)\}", text[text.index("}") + 1:])
    if not m:
        return text
    i = text.index("}") + 1 + m.start()
    n, value = int(m.group(1)), m.group(2)
    body = "\n%d\n(\n%s)" % (n, "".join(value + "\n" for _ in range(n)))
    return text[:i] + body + text[i + len(m.group(0)):]


def firstValue(text):
    """(start, end) of the first value of a cloud file's list: a number or a
    (...) group after 'N ('."""
    m = re.search(r"\n(\d+)\s*\(\s*", text[text.index("}"):])
    i = text.index("}") + m.end()
    if text[i] == "(":
        return i, text.index(")", i) + 1
    j = i
    while text[j] not in " \n)":
        j += 1
    return i, j


def setFirst(value):
    def edit(text):
        text = expandUniform(text)
        i, j = firstValue(text)
        return text[:i] + value + text[j:]
    return edit


def announceMore(text):
    """The list says one value more than it holds."""
    text = expandUniform(text)
    start = text.index("}")
    m = re.search(r"\n(\d+)\s*\(", text[start:])
    n = int(m.group(1))
    i = start + m.start(1)
    return text[:i] + str(n + 1) + text[i + len(m.group(1)):]


def emptyList(text):
    text = expandUniform(text)
    start = text.index("}")
    m = re.search(r"\n(\d+)\s*\(", text[start:])
    i = start + m.start(1)
    return text[:i] + "0\n(\n)\n\n// ************************************************************************* //\n"


def standardCorruptions(cloud):
    where = os.path.join("lagrangian", cloud)
    return {
        "positionOutside": ("positions", setFirst("(1e6 1 1)"),
                            ["positions", "outside the mesh", "1e+06"]),
        "hugeSpeed": ("U", setFirst("(1e200 0 0)"), [where + "/U", "1e+200", "|U| <= 100000"]),
        "negativeMass": ("m", setFirst("-1"), [where + "/m", "m = -1", "0 < m"]),
        "nanVolume": ("V", setFirst("nan"), [where + "/V"]),
        "countOneShort": ("positions", announceMore, [where + "/positions", "line"]),
        "fieldOneShort": ("U", announceMore, [where + "/U", "line"]),
        "emptyCloud": ("*", emptyList, ["holds no particle", "nothing to simulate"]),
    }
