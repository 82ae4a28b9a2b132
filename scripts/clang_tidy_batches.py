#!/usr/bin/env python3
"""clang-tidy on the project's own translation units, batched so a full run fits the test budget.

Most of clang-tidy's time on this code goes to matching over the declarations of the
headers every unit shares (gRPC, protobuf, GoogleTest, Eigen, spdlog, PCL): measured on
server/perception/supervoxels.cpp, 10 s of parsing and 30 s of matching, nearly all of
it in third-party headers. Units whose flags differ at most in their include folders and
macro definitions are therefore checked together, as one file that includes them all
with the union of those flags, so that each batch parses and matches the shared headers
once. Two units of a batch may not compile together (the same name in two anonymous
namespaces): the units a batch's compiler errors name are then checked apart from the
rest (or the batch is halved), and a unit checked alone gets exactly its own flags, so
a unit's own compiler error is reported like any other finding.

  clang_tidy_batches.py BUILD_DIR FILE_REGEX HEADER_REGEX [--jobs N] [--batch-size N] [--verbose]
"""

import argparse
import collections
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import threading
import time

FINDING = re.compile(r"^(/[^:]+):(\d+):(\d+): (warning|error): (.*)$")
COMPILER_ERROR = "[clang-diagnostic-error]"

# A unit: its source, the folder its command runs in, its flags (no source, no output),
# and the folder of the .clang-tidy that applies to it.
Unit = collections.namedtuple("Unit", "source directory flags config")


def config_folder(source):
    """The folder of the .clang-tidy nearest `source`, as clang-tidy looks for it."""
    folder = os.path.dirname(source)
    while not os.path.exists(os.path.join(folder, ".clang-tidy")):
        parent = os.path.dirname(folder)
        if parent == folder:
            return ""
        folder = parent
    return folder


def effective_config(source):
    """The configuration clang-tidy would use for `source`, inheritance resolved.

    A batch's file lies in the build folder, where clang-tidy would find the root
    .clang-tidy only; a batch of tests is given the tests' own."""
    return subprocess.run(["clang-tidy", "--dump-config", source], check=True,
                          stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True).stdout


def flags_of(entry):
    """The unit's compiler command without its source, output and dependency files."""
    if "arguments" in entry:
        arguments = list(entry["arguments"])
    else:
        arguments = shlex.split(entry["command"])
    flags = []
    skip_next = False
    for argument in arguments:
        if skip_next:
            skip_next = False
            continue
        if argument in ("-o", "-MF", "-MT", "-MQ"):
            skip_next = True
            continue
        if argument in ("-c", entry["file"]):
            continue
        flags.append(argument)
    return flags


def split_mergeable(flags):
    """(the flags but include folders and macro definitions, those two in order).

    Include folders and definitions are what a batch merges: a unit's own quoted includes
    are found beside it first, and definitions merge unless two units define one macro
    differently (`batches_of` keeps those apart)."""
    rest, mergeable = [], []
    index = 0
    while index < len(flags):
        flag = flags[index]
        if flag in ("-I", "-isystem", "-D") and index + 1 < len(flags):
            mergeable.append((flag, flags[index + 1]))
            index += 2
            continue
        if flag[:2] in ("-I", "-D") and len(flag) > 2:
            mergeable.append((flag[:2], flag[2:]))
        else:
            rest.append(flag)
        index += 1
    return rest, mergeable


def definitions(unit):
    """The unit's macro definitions, name to value."""
    defined = {}
    for kind, value in split_mergeable(unit.flags)[1]:
        if kind == "-D":
            name, _, text = value.partition("=")
            defined[name] = text
    return defined


def merged_flags(units):
    """One command line for a batch: the shared flags, every unit's folders and macros."""
    rest, _ = split_mergeable(units[0].flags)
    mergeable = []
    for unit in units:
        for item in split_mergeable(unit.flags)[1]:
            if item not in mergeable:
                mergeable.append(item)
    # The compiler stays first; the merged flags go right after it.
    flags = rest[:1]
    for kind, value in mergeable:
        flags += [kind, value]
    return flags + rest[1:]


def units_by_batch_key(database, file_regex):
    """Units to check, grouped by flags that differ at most in include folders and macros."""
    groups = collections.OrderedDict()
    seen = set()
    for entry in database:
        source = os.path.normpath(os.path.join(entry["directory"], entry["file"]))
        if source in seen or not file_regex.search(source):
            continue
        seen.add(source)
        unit = Unit(source, entry["directory"], flags_of(entry), config_folder(source))
        key = (unit.config, entry["directory"], tuple(split_mergeable(unit.flags)[0]))
        groups.setdefault(key, []).append(unit)
    return list(groups.values())


# Functions a program defines once: two units defining one cannot share a batch.
ENTRY_POINT = re.compile(r'^(?:extern "C" )?int (main|LLVMFuzzerTestOneInput)\s*\([^;]*$',
                         re.MULTILINE)


def entry_points(unit):
    with open(unit.source, errors="replace") as source:
        return set(ENTRY_POINT.findall(source.read()))


def batches_of(group, size):
    """A group's units in batches of at most `size` in which no macro has two values and
    no entry point (main, a fuzz target's) two definitions."""
    batches = []
    for unit in group:
        mine, entries = definitions(unit), entry_points(unit)
        for batch in batches:
            if len(batch["units"]) < size and not entries & batch["entries"] and all(
                    batch["defined"].get(name, value) == value for name, value in mine.items()):
                batch["units"].append(unit)
                batch["defined"].update(mine)
                batch["entries"] |= entries
                break
        else:
            batches.append({"units": [unit], "defined": dict(mine), "entries": set(entries)})
    return [batch["units"] for batch in batches]


class Batches:
    """A work queue of batches that grows as failing batches split."""

    def __init__(self, work_dir, header_regex, verbose, configs):
        self.work_dir = work_dir
        self.configs = configs  # config folder -> its effective configuration
        self.header_regex = header_regex
        self.verbose = verbose
        self.lock = threading.Lock()
        self.changed = threading.Condition(self.lock)
        self.pending = collections.deque()
        self.running = 0
        self.started = 0
        self.splits = 0
        self.findings = collections.OrderedDict()

    def add(self, units):
        with self.lock:
            self.pending.append(units)
            self.changed.notify_all()

    def take(self):
        """The next batch and its number, or None when no batch is left or can come."""
        with self.lock:
            while not self.pending and self.running:
                self.changed.wait()
            if not self.pending:
                return None
            self.running += 1
            self.started += 1
            return self.started, self.pending.popleft()

    def finish(self):
        with self.lock:
            self.running -= 1
            self.changed.notify_all()

    def run(self, number, units):
        batch_dir = os.path.join(self.work_dir, "batch-%d" % number)
        os.makedirs(batch_dir, exist_ok=True)
        file = os.path.join(batch_dir, "units.cpp")
        with open(file, "w") as out:
            for unit in units:
                # The include of a .cpp is this batch's whole point, not a mistake.
                out.write('#include "%s"  // NOLINT(bugprone-suspicious-include)\n' % unit.source)
        flags = units[0].flags if len(units) == 1 else merged_flags(units)
        command = " ".join(shlex.quote(a) for a in flags + ["-c", file])
        with open(os.path.join(batch_dir, "compile_commands.json"), "w") as out:
            json.dump([{"directory": units[0].directory, "file": file, "command": command}], out)
        started = time.monotonic()
        result = subprocess.run(
            ["clang-tidy", "--quiet", "-p", batch_dir, "--config", self.configs[units[0].config],
             "-header-filter", self.header_regex, file],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        output = result.stdout
        errors = [line for line in output.splitlines() if line.endswith(COMPILER_ERROR)]
        if self.verbose:
            print("batch %d: %d units from %s, %.1f s%s" % (
                number, len(units), os.path.relpath(units[0].source), time.monotonic() - started,
                "; split on " + errors[0] if errors and len(units) > 1 else ""),
                file=sys.stderr, flush=True)
        if errors and len(units) > 1:
            with self.lock:
                self.splits += 1
            for part in self.split(units, errors):
                self.add(part)
            return
        self.record(output, {unit.source for unit in units})
        if result.returncode != 0 and not any(FINDING.match(line) for line in output.splitlines()):
            # clang-tidy failed without saying where (a crash, an unreadable database).
            with self.lock:
                self.findings["%s: clang-tidy exited %d" % (units[0].source,
                                                            result.returncode)] = output

    @staticmethod
    def split(units, errors):
        """The units the compiler errors point at, apart from the others; halves otherwise.

        An error between two units of a batch (a name defined in both) is reported in the
        one included second, so taking out the units named in errors usually leaves a batch
        that compiles, at the cost of one more run rather than a bisection's several."""
        named = {FINDING.match(line).group(1) for line in errors if FINDING.match(line)}
        offenders = [unit for unit in units if unit.source in named]
        if offenders and len(offenders) < len(units):
            return [[unit for unit in units if unit.source not in named], offenders]
        half = len(units) // 2
        return [units[:half], units[half:]]

    def record(self, output, sources):
        lines = output.splitlines()
        for index, line in enumerate(lines):
            if not FINDING.match(line) or line.startswith(self.work_dir):
                continue
            if self.across_units(line, lines[index + 1:index + 8], sources):
                continue
            context = []
            for following in lines[index + 1:index + 3]:
                if FINDING.match(following):
                    break
                context.append(following)
            with self.lock:
                self.findings.setdefault(line, "\n".join(context))

    @staticmethod
    def across_units(line, following, sources):
        """A redundant declaration whose first one is in another unit of the batch: an
        artefact of batching (a program declaring the entry point another unit defines)."""
        if not line.endswith("[readability-redundant-declaration]") and \
                "[readability-redundant-declaration," not in line:
            return False
        for note in following:
            match = re.match(r"^(/[^:]+):\d+:\d+: note: previously declared here", note)
            if match:
                return match.group(1) in sources and match.group(1) != FINDING.match(line).group(1)
        return False


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build_dir")
    parser.add_argument("file_regex", help="the sources to check, as absolute paths")
    parser.add_argument("header_regex", help="the headers whose findings count")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--batch-size", type=int, default=24,
                        help="units per batch at most: larger batches share more, "
                             "smaller ones balance the jobs and split less")
    parser.add_argument("--verbose", action="store_true",
                        help="one line per clang-tidy run on standard error")
    args = parser.parse_args()

    start = time.monotonic()
    with open(os.path.join(args.build_dir, "compile_commands.json")) as database_file:
        database = json.load(database_file)
    groups = units_by_batch_key(database, re.compile(args.file_regex))
    work_dir = os.path.join(os.path.abspath(args.build_dir), "clang-tidy")
    shutil.rmtree(work_dir, ignore_errors=True)  # the batches of the last run
    # One resolved configuration per .clang-tidy folder, from any unit it applies to.
    example = {unit.config: unit.source for group in groups for unit in group}
    configs = {folder: effective_config(source) for folder, source in example.items()}
    batches = Batches(work_dir, args.header_regex, args.verbose, configs)
    planned = [batch for group in groups for batch in batches_of(group, args.batch_size)]
    # Largest first, so that the last batches to finish are short ones.
    for batch in sorted(planned, key=len, reverse=True):
        batches.add(batch)

    def worker():
        while True:
            taken = batches.take()
            if taken is None:
                return
            try:
                batches.run(*taken)
            finally:
                batches.finish()

    threads = [threading.Thread(target=worker) for _ in range(max(1, args.jobs))]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()

    for line, context in batches.findings.items():
        print(line)
        if context:
            print(context)
    print("clang-tidy: %d findings in %d units (%d clang-tidy runs, %d batches split) "
          "in %.0f s with %d jobs" % (
              len(batches.findings), sum(len(group) for group in groups), batches.started,
              batches.splits, time.monotonic() - start, args.jobs))
    return 1 if batches.findings else 0


if __name__ == "__main__":
    sys.exit(main())
