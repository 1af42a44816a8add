// Text for LaTeX: escaping, maths for the symbols our captions and headers use, and an estimate of
// the width a text takes, which the table layout (results/latex/latex_layout.hpp) needs before TeX runs.
#pragma once

#include <string>

#include "results/table_model/latex_escape.hpp" // escaping lives beside the model

namespace mhb {

// A spec or a label, as it is: escaped, with a line break allowed after every ',' and ':' that no
// space follows, so that "pmsm:load=2,speed=2500" can wrap in a narrow column.
std::string latex_spec_text(const std::string& text);

// Text mhbench wrote (captions, headers, readings), escaped, with maths where the plain text spells
// a symbol: f* -> $f^*$, f - f* -> $f - f^*$, theta* -> $\theta^*$, A12 -> $A_{12}$, alpha, eps,
// log10(...), 2^k, the words p, z, V, W, x (times), a standalone -, + or = (markers, minus signs),
// negative numbers and numbers in e-notation (1e-300 -> $1\times10^{-300}$).
std::string latex_prose(const std::string& text);

// Estimated width in pt of LaTeX text (as these functions write it) on one line at \footnotesize.
double latex_text_width(const std::string& latex);
// The width of its widest piece between the places a line may break (spaces, \allowbreak, "\\").
double latex_longest_piece(const std::string& latex);

} // namespace mhb
