// LaTeX escaping of plain text. It lives beside the table model, not with the LaTeX renderer,
// because a table builder that gives a cell its own LaTeX (TableCell::latex: an interaction's
// "obl x stepwise" with a times sign, say) must escape the rest of it, and builders do not reach up
// into the renderers (results/latex/ renders; it uses this too).
#pragma once

#include <string>

namespace mhb {

// Escapes the characters LaTeX treats specially in text mode (the em dash becomes ---).
std::string latex_escape(const std::string& text);

} // namespace mhb
