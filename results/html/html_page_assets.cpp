#include "results/html/html_page_assets.hpp"

namespace mhb {

const char* html_report_style() {
    return R"css(
:root { color-scheme: light; }
body { font: 15px/1.45 system-ui, -apple-system, "Segoe UI", Roboto, "DejaVu Sans", sans-serif;
  color: #1c1c1c; background: #fff; margin: 0 auto; max-width: 84rem; padding: 1rem 1.5rem 4rem; }
h1 { font-size: 1.55rem; margin: .6rem 0 .3rem; overflow-wrap: anywhere; }
h2 { font-size: 1.3rem; border-bottom: 1px solid #d8d8d8; padding-bottom: .2rem; margin-top: 2.4rem; }
h3 { font-size: 1.08rem; margin: 1.8rem 0 .35rem; }
h4 { font-size: 1rem; margin: 1.5rem 0 .35rem; }
a { color: #0b57a4; }
pre { background: #f5f5f5; padding: .6rem .8rem; overflow-x: auto; font-size: .8rem; line-height: 1.35; }
dl.context { display: grid; grid-template-columns: max-content 1fr; gap: .1rem 1rem; margin: .5rem 0; }
dl.context dt { font-weight: 600; }
dl.context dd { margin: 0; overflow-wrap: anywhere; }
nav.toc { background: #f8f9fb; border: 1px solid #e2e5ea; border-radius: 6px; padding: .4rem 1.2rem; }
nav.toc h2 { margin-top: .6rem; border: 0; }
nav.toc ul { margin: .2rem 0; padding-left: 1.2rem; }
nav.toc li { margin: .1rem 0; }
.caption { color: #404040; font-size: .86rem; max-width: 62rem; margin: .2rem 0 .5rem; }
.note { background: #fff8e1; border-left: 4px solid #e0a800; padding: .5rem .8rem; max-width: 62rem; }
.scroll { overflow-x: auto; max-width: 100%; border: 1px solid #e3e3e3; border-radius: 4px; }
table { border-collapse: collapse; font-size: .84rem; font-variant-numeric: tabular-nums; }
th, td { padding: .25rem .6rem; border-bottom: 1px solid #ececec; white-space: nowrap; text-align: right;
  vertical-align: top; }
th { background: #f4f5f7; border-bottom: 2px solid #c9ccd1; font-weight: 600; }
.l { text-align: left; }
td.long { white-space: normal; min-width: 20rem; }
th button { all: inherit; cursor: pointer; padding: 0; border: 0; background: none; }
th button:focus-visible { outline: 2px solid #0b57a4; outline-offset: 2px; }
th[aria-sort] button::after { content: " \2195"; color: #9aa0a6; }
th[aria-sort="ascending"] button::after { content: " \25B2"; color: #1c1c1c; }
th[aria-sort="descending"] button::after { content: " \25BC"; color: #1c1c1c; }
.grid { display: grid; grid-template-columns: repeat(auto-fill, minmax(min(100%, 34rem), 1fr)); gap: 0 1.5rem; }
figure { margin: 1rem 0 1.6rem; break-inside: avoid; page-break-inside: avoid; min-width: 0; }
figure img { display: block; max-width: 100%; height: auto; }
.swatch { display: inline-block; width: .75em; height: .75em; border-radius: 2px; margin-right: .35em;
  vertical-align: -.05em; border: 1px solid rgba(0, 0, 0, .25); }
.pages { font-weight: 600; }
tbody tr { background: #fff; }
tbody tr:nth-child(even) { background: #fafafa; }
thead th:first-child, tbody td:first-child, tfoot td:first-child { position: sticky; left: 0; z-index: 1;
  background: inherit; box-shadow: inset -1px 0 0 #d5d8dc; }
thead th:first-child { background: #f4f5f7; }
tfoot tr { background: #fff; }
tbody tr:hover { background: #eef4ff; }
figcaption { font-size: .84rem; color: #404040; margin-top: .3rem; }
figcaption code { font-size: .8rem; }
@media print {
  body { max-width: none; padding: 0; font-size: 10pt; }
  nav.toc { break-after: page; }
  .scroll { overflow: visible; border: 0; }
  table { font-size: 7.5pt; }
  th, td { white-space: normal; padding: .1rem .25rem; }
  tr { break-inside: avoid; page-break-inside: avoid; }
  h2, h3, h4 { break-after: avoid; page-break-after: avoid; }
  th[aria-sort] button::after { content: ""; }
  a { color: inherit; text-decoration: none; }
  .grid { display: block; }
}
)css";
}

const char* html_report_script() {
    return R"js(
(function () {
  "use strict";
  // A leading number: 1.5, -2e-05, .3, inf, -inf (and "20/20" or "0.004 (0.002)" by their first number).
  var NUMBER = /^[+-]?(?:inf(?:inity)?\b|(?:\d+(?:\.\d*)?|\.\d+)(?:e[+-]?\d+)?)/i;
  var collator = new Intl.Collator(undefined, { numeric: true, sensitivity: "base" });
  function keyOf(cell) {
    if (!cell) return "";
    return (cell.hasAttribute("data-value") ? cell.getAttribute("data-value") : cell.textContent).trim();
  }
  var UNDEFINED = /^(?:\u2014|NaN)?$/i; // empty, the em dash, or NaN in any case
  function isUndefined(text) { return UNDEFINED.test(text); }
  function toNumber(text) {
    var match = NUMBER.exec(text);
    if (!match) return null;
    var token = match[0].toLowerCase();
    if (token.indexOf("inf") >= 0) return token.charAt(0) === "-" ? -Infinity : Infinity;
    return parseFloat(token);
  }
  function sortTable(table, original, headers, column) {
    var th = headers[column];
    var state = th.getAttribute("aria-sort");
    var next = state === "ascending" ? "descending" : state === "descending" ? "none" : "ascending";
    for (var h = 0; h < headers.length; h++) headers[h].setAttribute("aria-sort", "none");
    th.setAttribute("aria-sort", next);
    var order = original.map(function (_, i) { return i; });
    if (next !== "none") {
      var keys = original.map(function (row) { return keyOf(row.cells[column]); });
      var defined = keys.filter(function (k) { return !isUndefined(k); });
      var numeric = defined.length > 0 && defined.every(function (k) { return toNumber(k) !== null; });
      var values = keys.map(function (k) { return numeric && !isUndefined(k) ? toNumber(k) : null; });
      var sign = next === "ascending" ? 1 : -1;
      order.sort(function (i, j) {
        var ui = isUndefined(keys[i]), uj = isUndefined(keys[j]);
        if (ui || uj) return ui === uj ? i - j : ui ? 1 : -1; // undefined last, either direction
        var c = numeric ? (values[i] < values[j] ? -1 : values[i] > values[j] ? 1 : 0)
                        : collator.compare(keys[i], keys[j]);
        return c !== 0 ? sign * c : i - j; // stable: ties keep the original order
      });
    }
    var body = table.tBodies[0];
    order.forEach(function (i) { body.appendChild(original[i]); });
  }
  function makeSortable(table) {
    if (!table.tHead || !table.tBodies.length || !table.tHead.rows.length) return;
    var original = Array.prototype.slice.call(table.tBodies[0].rows);
    var headers = table.tHead.rows[0].cells;
    Array.prototype.forEach.call(headers, function (th, column) {
      var button = document.createElement("button");
      button.type = "button";
      button.title = "Sort by this column (again: descending; a third time: the original order)";
      while (th.firstChild) button.appendChild(th.firstChild);
      th.appendChild(button);
      th.setAttribute("aria-sort", "none");
      button.addEventListener("click", function () { sortTable(table, original, headers, column); });
    });
    table.classList.add("js-sortable");
  }
  function start() {
    Array.prototype.forEach.call(document.querySelectorAll("table.sortable"), makeSortable);
  }
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})();
)js";
}

} // namespace mhb
