#!/usr/bin/env bash
# The HTML report (report/index.html and its budget pages) in a real browser, Debian's headless
# Chromium: for a study of the paper preset and a small ablation (a 2^2 design, two budgets: a page
# per budget, effects tables and figures), index.html opens with the verdict and ends with the
# study's metadata; the pages' DOMs hold one <table> per table of the report (and the verdicts') and
# one <img> per PNG figure, with JavaScript (the sort script ran: every table is marked js-sortable,
# and sorting a test table by a click gives the expected orders) and without it (plain tables);
# every image loads; and no page makes a network request or reads a file outside the report
# (Chromium's net log, a check shown to catch an <img> from http://example.invalid).
# Exits 77 (CTest: skipped) when Chromium is not installed.
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
report = page.rsplit("/", 1)[0] + "/"  # the report's own files (its figures) may be read
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
    if url.split("#")[0] == page or (url.startswith(report) and ".." not in url):
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

count() { { grep -o -- "$1" "$2" || true; } | wc -l | tr -d ' '; } # 0 when none (set -e, pipefail)

# Every page of a report, index.html first.
pages_of() { # REPORT_DIR
    echo "$1/index.html"
    find "$1" -maxdepth 1 -name 'budget_*.html' | sort
}

check_report() { # NAME STUDY_DIR
    local name="$1" report="$2/report"
    local page="$report/index.html" url="file://$2/report/index.html"
    [ -f "$page" ] || { fail "$name: $page was not written"; return; }
    local tables figures verdicts=0 bytes=0 dom_tables=0 dom_images=0 page_file
    tables="$(find "$report" -name '*.md' ! -name report.md ! -name README.md | wc -l | tr -d ' ')"
    figures="$(find "$report" -path '*/figures/*' -name '*.png' ! -name '.*' | wc -l | tr -d ' ')"
    if "$python" -c "import matplotlib" 2>/dev/null; then
        [ "$figures" -gt 0 ] || fail "$name: matplotlib is installed but no figures/*.png was drawn"
    else
        echo "$name: no matplotlib, so no figures to check"
    fi
    [ "$tables" -gt 0 ] || fail "$name: no table file in $report"

    local n=0
    for page_file in $(pages_of "$report"); do
        n=$((n + 1))
        local size
        size="$(wc -c <"$page_file" | tr -d ' ')"
        bytes=$((bytes + size))
        [ "$size" -lt 1048576 ] || fail "$name: $page_file is $size bytes (1 MB at most)"
        verdicts=$((verdicts + $(count 'class="table" id="[^"]*v-verdict' "$page_file")))
        browse --dump-dom --log-net-log="$work/$name.$n.net.json" --net-log-capture-mode=Default \
            "file://$page_file" >"$work/$name.$n.dom.html" || fail "$name: chromium failed on $page_file"
        local dom="$work/$name.$n.dom.html"
        dom_tables=$((dom_tables + $(count '<table' "$dom")))
        dom_images=$((dom_images + $(count '<img ' "$dom")))
        [ "$(count '<table' "$dom")" = "$(count 'class="sortable js-sortable"' "$dom")" ] ||
            fail "$name: the sort script did not mark every table of $page_file"
        no_page_requests "$work/$name.$n.net.json" "file://$page_file" || fail "$name: $page_file made network requests"
        browse_without_script "file://$page_file" >"$work/$name.$n.nojs.html" ||
            fail "$name: chromium failed without JavaScript on $page_file"
        [ "$(count '<table' "$work/$name.$n.nojs.html")" = "$(count '<table' "$dom")" ] ||
            fail "$name (JavaScript off): the tables of $page_file differ"
        [ "$(count 'class="sortable js-sortable"' "$work/$name.$n.nojs.html")" = 0 ] ||
            fail "$name: the script ran with JavaScript off"
    done
    echo "$name: $tables tables, $figures figures, $n pages, $bytes bytes"
    [ "$dom_tables" = "$((tables + verdicts))" ] ||
        fail "$name: $dom_tables <table> for $tables tables and $verdicts verdict tables"
    [ "$verdicts" -gt 0 ] || fail "$name: no verdict table"
    # Each key figure (convergence, final values) is on index.html and on its budget's page, when there
    # are budget pages; every figure once otherwise.
    local expected="$figures"
    if [ "$n" -gt 1 ]; then
        expected=$((figures + $(find "$report" -path '*/figures/*' \( -name 'convergence_*.png' -o -name 'final_values_*.png' \) ! -name '.*' | wc -l)))
    fi
    [ "$dom_images" = "$expected" ] || fail "$name: $dom_images <img> for $expected figures to show"
    grep -q 'aria-sort="none"' "$work/$name.1.dom.html" || fail "$name: the sort script did not mark the headers"

    # The verdict opens the page, before any other table and the contents; the metadata ends it.
    "$python" - "$work/$name.1.dom.html" <<'PY' || fail "$name: the verdict is not at the top or the metadata not last"
import re, sys
dom = open(sys.argv[1]).read()
main = dom[dom.index("<main>"):dom.index("</main>")]
sections = re.findall(r'<section[^>]* id="([^"]+)"', main)
first_table = main.index("<table")
ok = sections and sections[0] == "verdict" and main.index('id="verdict"') < first_table
ok = ok and main.index('id="verdict"') < main.index("<nav")
top_level = [s for s in sections if s in ("verdict", "key-figures", "pages", "tables", "figures", "context")]
ok = ok and top_level[-1] == "context"
print("sections of index.html:", " ".join(top_level))
sys.exit(0 if ok else 1)
PY
    # Every image of the pages loads (a broken one has naturalWidth 0 once the page is loaded).
    if [ "$figures" -gt 0 ]; then
        "$python" - "$page" "$work/$name.images.html" <<'PY'
import sys
page = open(sys.argv[1]).read()
check = """<script>
window.addEventListener("load", function () {
  var broken = Array.prototype.filter.call(document.images, function (i) { i.loading = "eager"; return i.naturalWidth === 0; });
  document.body.setAttribute("data-image-check", broken.length ? broken.map(function (i) { return i.src; }).join(" ") : "ok");
});
</script>"""
open(sys.argv[2], "w").write(page.replace(' loading="lazy"', "").replace("</body>", check + "</body>", 1))
PY
        cp "$work/$name.images.html" "$report/.image-check.html"
        browse --dump-dom --virtual-time-budget=10000 "file://$report/.image-check.html" >"$work/$name.images.dom.html" ||
            fail "$name: chromium failed on the image check"
        rm -f "$report/.image-check.html"
        grep -q 'data-image-check="ok"' "$work/$name.images.dom.html" ||
            fail "$name: images that do not load: $(grep -o 'data-image-check="[^"]*"' "$work/$name.images.dom.html" || echo '(the check did not run)')"
    fi
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
grep -q 'Effect of each component' "$work/ablation/report/"budget_*.html || fail "ablation: no effects table on a page"
grep -q 'Verdict on each component' "$work/ablation/report/index.html" || fail "ablation: no verdict on the components"
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
