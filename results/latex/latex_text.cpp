#include "results/latex/latex_text.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>
#include <vector>

#include "results/table_model/latex_escape.hpp" // escaping lives beside the model
#include "results/table_model/table.hpp"        // a renderer sees tables, never runs

namespace mhb {

namespace {

bool is_word_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

bool is_digit(char c) {
    return c >= '0' && c <= '9';
}

// Prose spellings of symbols and their maths, longest first where one starts another.
struct Symbol {
    const char* text;
    const char* latex;
};
constexpr std::array<Symbol, 24> symbols = {{
    {"log10(max(f - f*, floor))", "$\\log_{10}(\\max(f - f^*, \\mathrm{floor}))$"},
    {"log10(inf - f*)", "$\\log_{10}(\\infty - f^*)$"},
    {"log10(f - f*)", "$\\log_{10}(f - f^*)$"},
    {"sqrt(k(k+1)/(6N))", "$\\sqrt{k(k+1)/(6N)}$"},
    {"R_j - R_ref", "$R_j - R_\\mathrm{ref}$"},
    {"|f*|", "$|f^*|$"},
    {"f - f*", "$f - f^*$"},
    {"theta*", "$\\theta^*$"},
    {"f*", "$f^*$"},
    {"A12", "$A_{12}$"},
    {"A x B", "$A \\times B$"},
    {"alpha", "$\\alpha$"},
    {"eps", "$\\varepsilon$"},
    {"2^k", "$2^k$"},
    {"chi-square", "$\\chi^2$"},
    {"+inf", "$+\\infty$"},
    {"-inf", "$-\\infty$"},
    {"inf", "$\\infty$"},
    {"p", "$p$"},
    {"z", "$z$"},
    {"V", "$V$"},
    {"W", "$W$"},
    {"U", "$U$"},
    {"N", "$N$"},
}};

// A number starting at i ("-4.57", "1e-300", "2^3"), as maths when it needs any; 0 when none starts.
std::size_t number_at(const std::string& text, std::size_t i, std::string& latex) {
    std::size_t j = i;
    const bool negative = text[j] == '-';
    if (negative)
        ++j;
    if (j >= text.size() || !is_digit(text[j]))
        return 0;
    const std::size_t mantissa_start = j;
    while (j < text.size() && is_digit(text[j]))
        ++j;
    if (j + 1 < text.size() && text[j] == '.' && is_digit(text[j + 1]))
        for (++j; j < text.size() && is_digit(text[j]);)
            ++j;
    const std::string mantissa = text.substr(mantissa_start, j - mantissa_start);
    std::string exponent;
    if (j + 1 < text.size() && text[j] == 'e') {
        std::size_t k = j + 1;
        std::string sign;
        if (text[k] == '+' || text[k] == '-')
            sign = text[k++] == '-' ? "-" : "";
        const std::size_t digits = k;
        while (k < text.size() && is_digit(text[k]))
            ++k;
        if (k > digits) {
            std::size_t first = digits;
            while (first + 1 < k && text[first] == '0')
                ++first; // 1e-09 -> 10^{-9}
            exponent = sign + text.substr(first, k - first);
            j = k;
        }
    }
    if (j < text.size() && (std::isalpha(static_cast<unsigned char>(text[j])) != 0 || text[j] == '_'))
        return 0; // part of a word ("2nd", "10x")
    if (j + 1 < text.size() && text[j] == '^' && is_digit(text[j + 1]) && !negative && exponent.empty()) {
        std::size_t k = j + 1;
        while (k < text.size() && is_digit(text[k]))
            ++k;
        latex = "$" + mantissa + "^{" + text.substr(j + 1, k - j - 1) + "}$";
        return k - i;
    }
    if (!negative && exponent.empty()) {
        latex = mantissa;
        return j - i;
    }
    latex = negative ? "$-" : "$";
    latex += mantissa;
    if (!exponent.empty())
        latex.append("\\times10^{").append(exponent).append("}");
    latex += "$";
    return j - i;
}

// Widths in pt at \footnotesize of the printable ASCII characters (T1 Latin Modern 8 pt, measured
// with pdflatex), from '!' (33) to '~' (126).
constexpr std::array<double, 94> char_widths = {
    2.36, 3.23, 7.08, 4.25, 7.08, 6.61, 2.36, 3.31, 3.31, 4.25, 6.61, 2.36, 2.83, 2.36, 4.25, 4.25,
    4.25, 4.25, 4.25, 4.25, 4.25, 4.25, 4.25, 4.25, 4.25, 2.36, 2.36, 6.61, 6.61, 6.61, 4.01, 6.61,
    6.37, 6.02, 6.14, 6.49, 5.78, 5.54, 6.67, 6.37, 3.06, 4.36, 6.60, 5.31, 7.78, 6.37, 6.61, 5.78,
    6.61, 6.25, 4.72, 6.14, 6.37, 6.37, 8.73, 6.37, 6.37, 5.19, 2.36, 4.25, 2.36, 4.44, 6.37, 2.36,
    4.25, 4.72, 3.78, 4.72, 3.78, 2.60, 4.25, 4.72, 2.36, 2.60, 4.49, 2.36, 7.08, 4.72, 4.25, 4.72,
    4.49, 3.31, 3.35, 3.31, 4.72, 4.49, 6.14, 4.49, 4.49, 3.78, 4.25, 2.36, 4.25, 4.44};
constexpr double space_width = 2.67;
constexpr double script_scale = 0.72;

double char_width(char c) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 33 && u <= 126)
        return char_widths[u - 33];
    return u >= 0xC0 ? 5.0 : 0.0; // the first byte of a UTF-8 character; the rest add nothing
}

double command_width(const std::string& name) {
    struct Known {
        const char* name;
        double width;
    };
    static const Known known[] = {{"times", 10.2},
                                  {"infty", 8.5},
                                  {"theta", 3.9},
                                  {"alpha", 5.1},
                                  {"varepsilon", 3.7},
                                  {"log", 9.4},
                                  {"max", 14.6},
                                  {"sqrt", 6.6},
                                  {"chi", 5.0},
                                  {"psi", 5.5},
                                  {"textbackslash", 4.25},
                                  {"textasciitilde", 4.25},
                                  {"textasciicircum", 4.25},
                                  {"textless", 6.61},
                                  {"textgreater", 6.61},
                                  {"textbar", 2.36},
                                  {"ldots", 8.5}};
    for (const auto& k : known)
        if (name == k.name)
            return k.width;
    static const char* const silent[] = {"allowbreak", "phantom", "mathrm",      "textbf",     "boldmath",
                                         "bfseries",   "mbox",    "scriptstyle", "emph",       "text",
                                         "ensuremath", "relax",   "hfill",       "raggedright"};
    for (const char* s : silent)
        if (name == s)
            return 0.0;
    return 5.0;
}

// Lines and unbreakable pieces of LaTeX text, measured token by token.
struct Measure {
    double line = 0.0;
    double longest_line = 0.0;
    double piece = 0.0;
    double longest_piece = 0.0;

    void add(double width) {
        line += width;
        piece += width;
    }
    void end_piece() {
        longest_piece = std::max(longest_piece, piece);
        piece = 0.0;
    }
    void end_line() {
        end_piece();
        longest_line = std::max(longest_line, line);
        line = 0.0;
    }
};

Measure measure(const std::string& latex) {
    Measure m;
    bool math = false;
    std::vector<double> scales = {1.0};
    bool script_next = false; // after ^ or _: the next token or group is an exponent or index
    const auto scale = [&] { return scales.back() * (script_next ? script_scale : 1.0); };
    for (std::size_t i = 0; i < latex.size();) {
        const char c = latex[i];
        if (c == '$') {
            math = !math;
            ++i;
            continue;
        }
        if (c == '{') {
            scales.push_back(scale());
            script_next = false;
            ++i;
            continue;
        }
        if (c == '}') {
            if (scales.size() > 1)
                scales.pop_back();
            ++i;
            continue;
        }
        if (c == '^' || c == '_') {
            script_next = true;
            ++i;
            continue;
        }
        double width = 0.0;
        if (c == '\\') {
            std::size_t j = i + 1;
            while (j < latex.size() && std::isalpha(static_cast<unsigned char>(latex[j])) != 0)
                ++j;
            if (j == i + 1) { // a control symbol: \\, \%, \_, \,
                const char s = j < latex.size() ? latex[j] : ' ';
                i = j + 1;
                if (s == '\\') {
                    m.end_line();
                    continue;
                }
                width = s == ',' ? 1.33 : (s == ' ' ? space_width : char_width(s));
            } else {
                const std::string name = latex.substr(i + 1, j - i - 1);
                i = j;
                if (name == "allowbreak") {
                    m.end_piece();
                    continue;
                }
                width = command_width(name);
            }
        } else if (c == ' ' || c == '~') {
            ++i;
            if (math)
                continue;
            m.add(space_width);
            if (c == ' ')
                m.end_piece();
            continue;
        } else if (latex.compare(i, 3, "---") == 0 && !math) {
            width = 8.5;
            i += 3;
        } else if (latex.compare(i, 2, "--") == 0 && !math) {
            width = 4.25;
            i += 2;
        } else {
            width = char_width(c);
            if (math && (c == '-' || c == '+' || c == '='))
                width += 3.0; // the space around a binary operator or relation
            ++i;
        }
        m.add(width * scale());
        script_next = false;
    }
    m.end_line();
    return m;
}

} // namespace

std::string latex_spec_text(const std::string& text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        out += latex_escape(std::string(1, text[i]));
        if ((text[i] == ',' || text[i] == ':') && i + 1 < text.size() && text[i + 1] != ' ')
            out += "\\allowbreak{}";
    }
    return out;
}

std::string latex_prose(const std::string& text) {
    std::string out;
    std::size_t i = 0;
    while (i < text.size()) {
        const char before = i == 0 ? ' ' : text[i - 1];
        const bool boundary = !is_word_char(before) && before != '.';
        if (boundary) {
            bool matched = false;
            for (const auto& s : symbols) {
                const std::size_t n = std::strlen(s.text);
                if (text.compare(i, n, s.text) != 0)
                    continue;
                const char after = i + n < text.size() ? text[i + n] : ' ';
                if (is_word_char(s.text[n - 1]) && is_word_char(after))
                    continue; // only a whole word: "p" is not the p of "paired"
                if ((s.text[0] == '+' || s.text[0] == '-') && is_word_char(before))
                    continue;
                out += s.latex;
                i += n;
                matched = true;
                break;
            }
            if (matched)
                continue;
            std::string number;
            if (const std::size_t n = number_at(text, i, number); n > 0) {
                out += number;
                i += n;
                continue;
            }
            // A lone +, - or = (a marker, a minus sign between spaces) is maths.
            const char c = text[i];
            const char after = i + 1 < text.size() ? text[i + 1] : ' ';
            if ((c == '+' || c == '-' || c == '=') && (before == ' ' || before == '(' || before == '/') &&
                (after == ' ' || after == ':' || after == ',' || after == ')' || after == '/' ||
                 after == '.')) {
                out += std::string("$") + c + "$";
                ++i;
                continue;
            }
        }
        // The em dash and other multi-byte characters pass through latex_escape whole.
        const std::string dash = undefined_text;
        if (text.compare(i, dash.size(), dash) == 0) {
            out += "---";
            i += dash.size();
            continue;
        }
        out += latex_escape(std::string(1, text[i]));
        ++i;
    }
    return out;
}

double latex_text_width(const std::string& latex) {
    return measure(latex).longest_line;
}

double latex_longest_piece(const std::string& latex) {
    return measure(latex).longest_piece;
}

} // namespace mhb
