// A figure's SVG file (as scripts/plot_study.py writes it with matplotlib) made fit to sit inside an
// HTML page: the XML prolog, DOCTYPE, comments-before-the-root and <metadata> (links to the
// RDF and Dublin Core schemas) are dropped, so are namespace declarations (HTML needs none for
// inline SVG) and scripts; every id gets the figure's own prefix and every reference to one
// (href="#x", url(#x)) follows, because matplotlib reuses ids such as "figure_1" or a clip path's
// hash in every figure, and two equal ids on one page would make one figure clip with another's
// path. A link to anything but a fragment or a data: URI is dropped: the page loads nothing.
#pragma once

#include <string>
#include <string_view>

namespace mhb {

// The <svg>...</svg> element of `svg_text` with the rewriting above, its root given id `prefix`,
// role="img" and, when the file has no <title>, `title` as one (the figure's accessible name).
// Throws std::runtime_error when the text holds no <svg> element.
std::string inline_svg(std::string_view svg_text, const std::string& prefix, const std::string& title);

} // namespace mhb
