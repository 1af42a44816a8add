// The style sheet and the script of the HTML report, inlined in every page (the page loads nothing).
#pragma once

namespace mhb {

// Readable on a laptop, wide tables scroll sideways, and print-friendly (no scroll boxes, tables
// wrap, figures and table rows not split across pages).
const char* html_report_style();

// Makes every <table class="sortable"> sort by a click on a header: numerically when every defined
// cell of the column starts with a number (inf and -inf included; "20/20" sorts as 20), else as
// text; undefined cells (empty, the em dash, nan) last in either direction; a third click restores
// the original order. It marks each table it handled with the class "js-sortable" and each header
// with aria-sort; without JavaScript the tables are plain HTML and nothing depends on it.
const char* html_report_script();

} // namespace mhb
