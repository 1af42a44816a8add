#!/usr/bin/env bash
# The HTML report (report/index.html) in a real browser, Debian's headless Chromium: for a study
# of the paper preset and a small ablation (a 2^2 design, two budgets: effects tables and figures),
# the DOM holds one <table> per table of the report and one <svg> per figure file, with JavaScript
# (the sort script ran: every table is marked js-sortable, and sorting a test table by a click
# gives the expected orders) and without it (plain tables); and the page makes no network request
# (Chromium's net log holds no request of the page's, a check shown to catch an <img> from
# http://example.invalid). Exits 77 (CTest: skipped) when Chromium is not installed.
# Usage: html_report_test.sh MHBENCH   (ctest -L browser runs it; scripts/browser-check.sh too)
set -euo pipefail

mhbench="$1"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
chromium="${MHB_CHROMIUM:-/usr/bin/chromium}"
python=/usr/bin/python3
if [ ! -x "$chromium" ]; then
    echo "SKIPPED: $chromium is not installed (bash scripts/setup-debian.sh browser)"
    exit 77
fi
[ -x "$python" ] || python=python3 # reads Chromium's net log (JSON)

work="$(mktemp -d "${TMPDIR:-/tmp}/mhb_browser_test.XXXXXX")"
trap 'rm -rf "$work"' EXIT
failures=0
fail() {
    echo "FAIL: $*" >&2
    failures=$((failures + 1))
}

# Chromium headless as root, with nothing of its own that would reach the network (a resolver
# that finds no host: even a request the page should not make goes nowhere, but is still logged).
browse() {
    local profile
    profile="$(mktemp -d "$work/profile.XXXXXX")"
    timeout 60 "$chromium" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
        --disable-background-networking --disable-component-update --disable-sync --disable-extensions \
        --host-resolver-rules="MAP * ~NOTFOUND" --user-data-dir="$profile" "$@" 2>>"$work/chromium.log"
}

# The same, without JavaScript; --dump-dom prints nothing then (it reads the DOM with a script),
# so the DOM is read through the DevTools protocol (dump_dom.py).
browse_without_script() {
    local profile
    profile="$(mktemp -d "$work/profile.XXXXXX")"
    timeout 60 "$python" "$here/dump_dom.py" "$chromium" "$1" --headless --no-sandbox --disable-gpu --disable-quic \
        --no-first-run --disable-background-networking --disable-component-update --disable-sync --disable-extensions \
        --host-resolver-rules="MAP * ~NOTFOUND" --user-data-dir="$profile" --blink-settings=scriptEnabled=false \
        2>>"$work/chromium.log"
}

# Fails unless the net log of loading PAGE_URL holds no URL request of the page's other than the
# page itself. Chromium's own background requests (initiator "not an origin", e.g. its updater)
# are not the page's and are only counted.
no_page_requests() { # NET_LOG PAGE_URL
    "$python" - "$1" "$2" <<'PY'
import json, sys
path, page = sys.argv[1], sys.argv[2]
try:
    log = json.load(open(path))
except ValueError as error:
    sys.exit("%s: not a complete net log (%s)" % (path, error))
names = {number: name for name, number in log["constants"]["logEventTypes"].items()}
own, requests = set(), set()
for event in log["events"]:
    params = event.get("params") or {}
    if names.get(event["type"]) != "URL_REQUEST_START_JOB" or "url" not in params:
        continue
    url = params["url"]
    if url.split("#")[0] == page:
        continue
    if params.get("initiator") == "not an origin" and "file://" not in params.get("network_isolation_key", ""):
        own.add(url.split("?")[0])
    else:
        requests.add(url)
for url in sorted(requests):
    print("request from the page: " + url)
print("net log: %d request(s) of the page, %d of Chromium's own" % (len(requests), len(own)))
sys.exit(1 if requests else 0)
PY
}

count() { grep -o -- "$1" "$2" | wc -l | tr -d ' '; }

check_report() { # NAME STUDY_DIR
    local name="$1" report="$2/report"
    local page="$report/index.html" url="file://$2/report/index.html"
    [ -f "$page" ] || { fail "$name: $page was not written"; return; }
    local tables figures
    tables="$(find "$report" -name '*.md' ! -name report.md ! -name README.md | wc -l | tr -d ' ')"
    figures="$(find "$report" -path '*/figures/*' -name '*.svg' ! -name '.*' | wc -l | tr -d ' ')"
    echo "$name: $tables tables, $figures figures, $(wc -c <"$page" | tr -d ' ') bytes"
    [ "$tables" -gt 0 ] || fail "$name: no table file in $report"
    if "$python" -c "import matplotlib" 2>/dev/null; then
        [ "$figures" -gt 0 ] || fail "$name: matplotlib is installed but no figures/*.svg was drawn"
    else
        echo "$name: no matplotlib, so no figures to check"
    fi

    browse --dump-dom --log-net-log="$work/$name.net.json" --net-log-capture-mode=Default "$url" \
        >"$work/$name.dom.html" || fail "$name: chromium failed (see its log below)"
    local dom="$work/$name.dom.html"
    [ "$(count '<table' "$dom")" = "$tables" ] || fail "$name (JavaScript on): $(count '<table' "$dom") <table> for $tables tables"
    [ "$(count '<svg' "$dom")" = "$figures" ] || fail "$name (JavaScript on): $(count '<svg' "$dom") <svg> for $figures figures"
    [ "$(count 'class="sortable js-sortable"' "$dom")" = "$tables" ] || fail "$name: the sort script did not mark every table"
    grep -q 'aria-sort="none"' "$dom" || fail "$name: the sort script did not mark the headers"
    no_page_requests "$work/$name.net.json" "$url" || fail "$name: the page made network requests"

    browse_without_script "$url" >"$work/$name.nojs.html" ||
        fail "$name: chromium failed without JavaScript"
    dom="$work/$name.nojs.html"
    [ "$(count '<table' "$dom")" = "$tables" ] || fail "$name (JavaScript off): $(count '<table' "$dom") <table> for $tables tables"
    [ "$(count '<svg' "$dom")" = "$figures" ] || fail "$name (JavaScript off): $(count '<svg' "$dom") <svg> for $figures figures"
    [ "$(count 'class="sortable js-sortable"' "$dom")" = 0 ] || fail "$name: the script ran with JavaScript off"
    grep -q '<td' "$dom" || fail "$name (JavaScript off): no table cell"
}

# 1. Two real studies: the paper's preset (one budget) and a 2^2 ablation under two budgets.
# Both at once: most of their time is the figures' Python, one process each.
cat >"$work/ablation.ini" <<'INI'
algorithms = itlbo:tutorial={on,off},obl={on,off}
problems = sphere:dim=2
runs = 4
seed = 1
budget = iterations=20
budget = evaluations=300
INI
"$mhbench" run --study paper --runs 3 --threads 1 --out "$work/paper" -q &
paper_study=$!
"$mhbench" run --study-file "$work/ablation.ini" --threads 1 --out "$work/ablation" -q &
ablation_study=$!
wait "$paper_study" || { echo "FAIL: mhbench run --study paper failed" >&2; exit 1; }
wait "$ablation_study" || { echo "FAIL: mhbench run of the ablation study failed" >&2; exit 1; }
grep -q 'Effect of each component' "$work/ablation/report/index.html" || fail "ablation: no effects table on the page"
check_report paper "$work/paper"
check_report ablation "$work/ablation"

# 2. The sort script on the real page: a test table sorted by a click, numerically with inf, -inf
# and an undefined cell (last in either direction), then as text, then back to the original order.
"$python" - "$work/paper/report/index.html" "$work/sort.html" <<'PY'
import sys
page = open(sys.argv[1]).read()
table = """<table class="sortable" id="sort-test"><thead><tr><th>Name</th><th>Value</th></tr></thead><tbody>
<tr><td>e</td><td>3</td></tr><tr><td>b</td><td>inf</td></tr><tr><td>d</td><td>\u2014</td></tr>
<tr><td>a</td><td>-inf</td></tr><tr><td>c</td><td>20/20</td></tr><tr><td>f</td><td data-value="2e-05">2.0e-05</td></tr>
</tbody></table>"""
check = """<script>
document.addEventListener("DOMContentLoaded", function () { // after the page's script has started

  var t = document.getElementById("sort-test"), out = [];
  function column(c) {
    return Array.prototype.map.call(t.tBodies[0].rows, function (r) { return r.cells[c].textContent.trim(); }).join(" ");
  }
  function click(c) { t.tHead.rows[0].cells[c].querySelector("button").click(); }
  function expect(what, got, want) { if (got !== want) out.push(what + ": " + got); }
  click(1); expect("ascending", column(0), "a f e c b d");
  click(1); expect("descending", column(0), "b c e f a d");
  click(1); expect("original", column(0), "e b d a c f");
  click(0); expect("text", column(0), "a b c d e f");
  document.body.setAttribute("data-sort-check", out.length ? out.join("; ") : "ok");
});
</script>"""
page = page.replace("</main>", table + "</main>", 1).replace("</body>", check + "</body>", 1)
open(sys.argv[2], "w").write(page)
PY
browse --dump-dom "file://$work/sort.html" >"$work/sort.dom.html" || fail "sort check: chromium failed"
result="$(grep -o 'data-sort-check="[^"]*"' "$work/sort.dom.html" || echo 'data-sort-check="(the check did not run)"')"
[ "$result" = 'data-sort-check="ok"' ] || fail "sort check: $result"

# 3. The network check can fail: a page with an image from outside is caught.
printf '<!DOCTYPE html>\n<html><body><p>x</p><img src="http://example.invalid/x.png"></body></html>\n' >"$work/outside.html"
browse --dump-dom --log-net-log="$work/outside.net.json" --net-log-capture-mode=Default "file://$work/outside.html" >/dev/null ||
    fail "network check: chromium failed"
if no_page_requests "$work/outside.net.json" "file://$work/outside.html" >"$work/outside.txt"; then
    fail "network check: a page loading http://example.invalid/x.png was not caught"
else
    grep -q 'example.invalid/x.png' "$work/outside.txt" || fail "network check: the request was not named"
fi

if [ "$failures" -gt 0 ]; then
    echo "--- chromium's log (last lines) ---" >&2
    tail -n 20 "$work/chromium.log" >&2 || true
    echo "$failures check(s) failed" >&2
    exit 1
fi
echo "browser checks passed"
