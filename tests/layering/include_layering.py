#!/usr/bin/env python3
"""The arrows between mhbench's rooms, checked against every `#include "..."` of the libraries.

Usage: include_layering.py SOURCE_DIR     check the tree; one line per violation, exit 1 if any
       include_layering.py --self-test    show on small scratch trees that each rule can fail

ARCHITECTURE.md ("Rooms" and "Arrows") explains the rules; this file is where they are enforced, so
a change to the structure is a change here and there together. Python's standard library only.

Folders (one library target each; tests/ may include anything and is not checked):
  problems    includes problems only (the lowest room)
  algorithms  problems' contract (top level), core/ and external/ (the protocol the external
              optimiser shares with the external problem); never a problem family
  results     problems/core/ only (the plumbing: hashes, CSV fields, the child-process module;
              mhb_results links mhb_problems privately for it), never a problem's contract or family
  runner      anything of the four
Rooms inside a folder:
  problems/   core/ includes only core/; the contract files at the top include core/; a family
              (functions/, bbob/, cec/, pmsm/, fluxmap/, external/) includes itself, the top and
              core/, never another family
  results/    the order results/README.md draws: store/ < table_model/ < analysis/ < tables/ <
              text/, latex/, html/, exports/ < protocols/ < reporters/ < report/, each including only
              rooms below it; the renderers (text/, latex/, html/) read no analysis and no tables,
              exports/ and reporters/ no tables (results/exports/README.md), protocols/ no renderer
              (it builds tables and writes files, results/protocols/README.md); nothing includes
              report/
  runner/     the order runner/README.md lists: run/ < study/ < execution/ < distribution/ <
              plugins/ < single_problem/ < cli/, each including only rooms before it; the plug-in
              contract at the top (plugin_api.hpp) includes no runner room
A room this file does not know (a new folder) is a violation too: give it its arrows here.
"""
import os
import re
import sys
import tempfile

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
SOURCE_SUFFIXES = (".cpp", ".hpp", ".h", ".cpp.in")
LIBRARY_FOLDERS = ("problems", "algorithms", "results", "runner")
# Headers written into the build tree (cmake/MhbVersion.cmake), found on the include path.
GENERATED_HEADERS = {"mhb_version.hpp"}
TOP = ""  # the room of a file that sits directly in its folder
THIS_FILE = "tests/layering/include_layering.py"

PROBLEM_FAMILIES = {"functions", "bbob", "cec", "pmsm", "fluxmap", "external"}
ALGORITHMS_REACH_INTO_PROBLEMS = {TOP, "core", "external"}

RESULTS_BELOW = {
    "store": {"store"},
    "table_model": {"table_model", "store"},
    "analysis": {"analysis", "table_model", "store"},
    "tables": {"tables", "analysis", "table_model", "store"},
    "text": {"text", "table_model", "store"},
    "latex": {"latex", "table_model", "store"},
    "html": {"html", "table_model", "store"},
    "exports": {"exports", "analysis", "table_model", "store"},
    "protocols": {"protocols", "tables", "exports", "analysis", "table_model", "store"},
}
# The reporters hand the renderers and exports what a report made; they build no table themselves.
RESULTS_BELOW["reporters"] = {
    "reporters", "protocols", "text", "latex", "html", "exports", "analysis", "table_model", "store"
}
RESULTS_BELOW["report"] = set(RESULTS_BELOW) | {"report"}

RUNNER_ORDER = ["run", "study", "execution", "distribution", "plugins", "single_problem", "cli"]


def room_of(path):
    """(folder, room) of a path relative to the source tree: 'results/store/csv.hpp' gives
    ('results', 'store'), 'problems/objective.hpp' ('problems', TOP)."""
    parts = path.split("/")
    return parts[0], (parts[1] if len(parts) > 2 else TOP)


def shown(room):
    return "the top level" if room == TOP else room + "/"


def problems_rule(room, target_room):
    if room == "core":
        allowed, why = {"core"}, "core/ knows no problem"
    elif room == TOP:
        allowed, why = {TOP, "core"}, "the contract knows no family"
    elif room in PROBLEM_FAMILIES:
        allowed, why = {room, TOP, "core"}, "a family never includes another"
    else:
        return "problems/%s/ is not a room this test knows: give it its arrows in %s" % (room, THIS_FILE)
    if target_room in allowed:
        return None
    return "problems/%s may include only %s (%s)" % (
        "" if room == TOP else room + "/", ", ".join(sorted(shown(r) for r in allowed)), why)


def ordered_rule(folder, order, room, target_room):
    unknown = "%s/%s/ is not a room this test knows: give it its arrows in %s"
    if room == TOP:
        if target_room == TOP:
            return None
        return "the %s/ files at the top level (the plug-in contract) include no room of %s/" % (folder, folder)
    if room not in order:
        return unknown % (folder, room, THIS_FILE)
    if target_room == TOP or target_room in order[: order.index(room) + 1]:
        return None
    if target_room not in order:
        return unknown % (folder, target_room, THIS_FILE)
    return "%s/%s/ includes only the rooms before it in %s/README.md (%s), never %s" % (
        folder, room, folder, " < ".join(order), shown(target_room))


def results_rule(room, target_room):
    for r in (room, target_room):
        if r == TOP:
            return "a file directly in results/ belongs in one of its rooms (results/README.md)"
        if r not in RESULTS_BELOW:
            return "results/%s/ is not a room this test knows: give it its arrows in %s" % (r, THIS_FILE)
    allowed = RESULTS_BELOW[room]
    if target_room in allowed:
        return None
    return "results/%s/ may include only %s (results/README.md: data flows upwards)" % (
        room, ", ".join(r + "/" for r in sorted(allowed)))


def includes_of(root, path):
    """The quoted includes of a file, as (line number, text)."""
    found = []
    with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
        for number, line in enumerate(f, 1):
            m = INCLUDE.match(line)
            if m:
                found.append((number, m.group(1)))
    return found


def violation(root, path, target):
    """Why `path` may not include `target`, or None when it may."""
    folder, room = room_of(path)
    head = target.split("/")[0]
    if target in GENERATED_HEADERS:
        return None
    if head in ("tests", "scripts"):
        return "a library never includes %s/ (only tests include the libraries)" % head
    if head not in LIBRARY_FOLDERS:
        return "includes are written from the repository root (\"problems/...\", \"results/...\")"
    target_room = room_of(target)[1]
    if folder == "runner":
        if head != "runner":
            return None
        return ordered_rule("runner", RUNNER_ORDER, room, target_room)
    if folder == "problems":
        if head != "problems":
            return "problems/ is the lowest room: it includes nothing of %s/" % head
        return problems_rule(room, target_room)
    if folder == "algorithms":
        if head == "algorithms":
            return None
        if head != "problems":
            return "algorithms/ may include only algorithms/ and problems/, never %s/" % head
        if target_room in ALGORITHMS_REACH_INTO_PROBLEMS:
            return None
        return "an optimiser knows no problem family: algorithms/ may include problems' top level, core/ " \
               "and external/, not problems/%s/" % target_room
    if folder == "results":
        if head == "results":
            return results_rule(room, target_room)
        if head != "problems" or target_room != "core":
            return "results/ reads records, never problems: of problems/ it may include only core/ " \
                   "(the plumbing), not %s" % target
        return None
    return None


def library_sources(root):
    for folder in LIBRARY_FOLDERS:
        for directory, _, files in os.walk(os.path.join(root, folder)):
            for name in sorted(files):
                if name.endswith(SOURCE_SUFFIXES):
                    yield os.path.relpath(os.path.join(directory, name), root).replace(os.sep, "/")


def check(root):
    """Every violation in the tree at `root`, one line each, and the number of includes read."""
    lines = []
    count = 0
    for path in sorted(library_sources(root)):
        for number, target in includes_of(root, path):
            count += 1
            why = violation(root, path, target)
            if why:
                lines.append('%s:%d: #include "%s": %s' % (path, number, target, why))
    return lines, count


# Each case: a file, what it includes, and whether that is allowed. Every rule above has a case that
# must be refused, and each folder one that must pass, so that a rule that stopped refusing is seen.
SELF_TEST_CASES = [
    ("problems/core/a.hpp", "algorithms/optimizer.hpp", False),
    ("problems/core/a.hpp", "problems/objective.hpp", False),
    ("problems/pmsm/a.cpp", "problems/functions/classic_function.hpp", False),
    ("problems/pmsm/a.cpp", "problems/core/rng.hpp", True),
    ("problems/newroom/a.cpp", "problems/core/rng.hpp", False),
    ("algorithms/a.cpp", "problems/pmsm/dataset.hpp", False),
    ("algorithms/a.cpp", "results/store/run_record.hpp", False),
    ("algorithms/a.cpp", "problems/external/handshake.hpp", True),
    ("results/store/a.cpp", "results/tables/comparison_tables.hpp", False),
    ("results/store/a.cpp", "runner/study/study.hpp", False),
    ("results/html/a.cpp", "results/analysis/statistics.hpp", False),
    ("results/exports/a.cpp", "results/tables/table_cells.hpp", False),
    ("results/tables/a.cpp", "results/report/report.hpp", False),
    ("results/tables/a.cpp", "results/protocols/suite_protocol.hpp", False),
    ("results/exports/a.cpp", "results/protocols/suite_protocol.hpp", False),
    ("results/protocols/a.cpp", "results/report/report.hpp", False),
    ("results/protocols/a.cpp", "results/text/markdown_table.hpp", False),
    ("results/protocols/a.cpp", "results/exports/cec_result_files.hpp", True),
    ("results/report/a.cpp", "results/protocols/protocol_registry.hpp", True),
    ("results/store/a.cpp", "problems/problem.hpp", False),
    ("results/store/a.cpp", "problems/pmsm/dataset.hpp", False),
    ("results/report/a.cpp", "problems/core/process/child_process.hpp", True),
    ("results/store/a.cpp", "problems/core/fnv1a.hpp", True),
    ("results/report/a.cpp", "results/html/html_report.hpp", True),
    ("results/reporters/a.cpp", "results/latex/latex_document.hpp", True),
    ("results/reporters/a.cpp", "results/tables/comparison_tables.hpp", False),
    ("results/exports/a.cpp", "results/reporters/reporter.hpp", False),
    ("results/report/a.cpp", "results/reporters/reporter_registry.hpp", True),
    ("results/a.cpp", "results/store/csv.hpp", False),
    ("runner/run/a.cpp", "runner/study/study.hpp", False),
    ("runner/plugin_api.hpp", "runner/plugins/components.hpp", False),
    ("runner/cli/a.cpp", "runner/plugins/components.hpp", True),
    ("runner/study/a.cpp", "tests/support/x.hpp", False),
    ("runner/study/a.cpp", "../problems/problem.hpp", False),
    ("runner/cli/a.cpp", "mhb_version.hpp", True),
]


def write(root, path, text):
    os.makedirs(os.path.dirname(os.path.join(root, path)), exist_ok=True)
    with open(os.path.join(root, path), "w", encoding="utf-8") as f:
        f.write(text)


def self_test():
    failures = []
    for path, target, allowed in SELF_TEST_CASES:
        with tempfile.TemporaryDirectory(prefix="mhb-layering-") as root:
            write(root, "problems/core/fnv1a.hpp", "#pragma once\n")
            write(root, "problems/core/rng.hpp", "#pragma once\n")
            write(root, "problems/core/rng.cpp", '#include "problems/core/rng.hpp"\n')
            write(root, "problems/core/uses_rng.hpp", '#pragma once\n#include "problems/core/rng.hpp"\n')
            write(root, path, '// a file\n#include <vector>\n#include "%s"\n' % target)
            lines, _ = check(root)
            mine = [line for line in lines if line.startswith(path + ":")]
            if allowed and mine:
                failures.append("%s including %s was refused: %s" % (path, target, mine[0]))
            if not allowed and not mine:
                failures.append("%s including %s was not refused" % (path, target))
    for failure in failures:
        print("self-test: " + failure, file=sys.stderr)
    print("include layering self-test: %d cases, %d failed" % (len(SELF_TEST_CASES), len(failures)))
    return 1 if failures else 0


def main(argv):
    if argv[1:] == ["--self-test"]:
        return self_test()
    if len(argv) != 2 or not os.path.isdir(argv[1]):
        print("usage: include_layering.py SOURCE_DIR | --self-test", file=sys.stderr)
        return 2
    lines, count = check(argv[1])
    for line in lines:
        print(line, file=sys.stderr)
    if lines:
        print("include layering: %d of %d includes break the arrows (ARCHITECTURE.md, 'Arrows')"
              % (len(lines), count), file=sys.stderr)
        return 1
    print("include layering: %d includes, none against the arrows" % count)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
