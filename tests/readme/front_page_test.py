#!/usr/bin/python3
"""Runs every command block of the README's front page, in order, as a new user would.

Usage: front_page_test.py REPOSITORY BUILD_DIR

The front page is README.md up to the comment that ends it. Its ```sh blocks run in one bash
session (so `export PATH=...` carries over) and each ```python block runs with /usr/bin/python3
where it stands, all in a scratch workspace that looks like a clone after the quick start: the
repository's scripts/ and the build tree linked in, studies/ written there. MHB_QUICKSTART_CHECK=1
shortens the two quick-start commands (scripts/build.sh then skips apt and the build, which CTest
has already done; scripts/run-tests.sh runs one quick test instead of the suite that runs this
one). A command that fails fails the test, with the command and its output.
"""
import os
import re
import shlex
import subprocess
import sys
import tempfile

END_MARKER = "<!-- The front page ends here"


def front_page_blocks(readme_text):
    """(language, code) of each fenced block before the end marker."""
    front, found, _ = readme_text.partition(END_MARKER)
    if not found:
        raise SystemExit("README.md has no front-page end marker (%r)" % END_MARKER)
    return [(m.group(1), m.group(2)) for m in
            re.finditer(r"^```(\w*)\n(.*?)^```\s*$", front, re.S | re.M)]


def session_script(blocks, workspace):
    """One bash script: the sh blocks as written, each python block saved and run in its place."""
    lines = ["set -euo pipefail", "set -x"]
    for index, (language, code) in enumerate(blocks):
        if language == "sh":
            lines.append(code)
        elif language == "python":
            path = os.path.join(workspace, "front_page_block_%d.py" % index)
            with open(path, "w") as out:
                out.write(code)
            lines.append("/usr/bin/python3 %s" % shlex.quote(path))
    return "\n".join(lines) + "\n"


def make_workspace(repository, build_dir, workspace):
    for name in ("scripts", "CMakePresets.json"):
        os.symlink(os.path.join(repository, name), os.path.join(workspace, name))
    os.makedirs(os.path.join(workspace, "build"))
    os.symlink(os.path.abspath(build_dir), os.path.join(workspace, "build", "release"))


def main():
    repository, build_dir = sys.argv[1], sys.argv[2]
    with open(os.path.join(repository, "README.md"), encoding="utf-8") as f:
        blocks = front_page_blocks(f.read())
    runnable = [b for b in blocks if b[0] in ("sh", "python")]
    if len(runnable) < 5:
        raise SystemExit("the front page has %d command blocks; expected the quick start, the "
                         "three jobs and the own-optimiser example" % len(runnable))
    with tempfile.TemporaryDirectory(prefix="mhb-front-page-") as workspace:
        make_workspace(repository, build_dir, workspace)
        env = dict(os.environ, MHB_QUICKSTART_CHECK="1")
        result = subprocess.run(["bash", "-c", session_script(blocks, workspace)], cwd=workspace,
                                env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        sys.stdout.write(result.stdout[-20000:])
        if result.returncode != 0:
            raise SystemExit("a command of the README's front page failed (exit %d); its trace "
                             "is above" % result.returncode)
        for expected in ("studies/paper/runs.csv", "studies/compare/runs.csv",
                         "studies/ablation/runs.csv", "studies/compare/median-gap.pdf"):
            if not os.path.exists(os.path.join(workspace, expected)):
                raise SystemExit("the front page's commands did not write " + expected)
    print("%d command blocks of the front page ran" % len(runnable))


if __name__ == "__main__":
    main()
