#include "results/table_model/latex_escape.hpp"

#include "results/table_model/table.hpp"

namespace mhb {

std::string latex_escape(const std::string& text) {
    std::string out;
    const std::string dash = undefined_text;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text.compare(i, dash.size(), dash) == 0) { // the em dash, without relying on inputenc
            out += "---";
            i += dash.size() - 1;
            continue;
        }
        const char c = text[i];
        if (c == '-' && i + 1 < text.size() && text[i + 1] == '-') { // "--" would print an en dash
            out += "-{}";
            continue;
        }
        switch (c) {
        case '\\':
            out += "\\textbackslash{}";
            break;
        case '&':
        case '%':
        case '$':
        case '#':
        case '_':
        case '{':
        case '}':
            out += '\\';
            out += c;
            break;
        case '~':
            out += "\\textasciitilde{}";
            break;
        case '^':
            out += "\\textasciicircum{}";
            break;
        case '<':
            out += "\\textless{}";
            break;
        case '>':
            out += "\\textgreater{}";
            break;
        case '|':
            out += "\\textbar{}";
            break;
        default:
            out += c;
        }
    }
    return out;
}

} // namespace mhb
