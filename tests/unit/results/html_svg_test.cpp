// inline_svg: a matplotlib SVG file made fit to sit in the HTML report beside other figures.
#include <gtest/gtest.h>
#include <stdexcept>
#include <string>

#include "results/html/html_svg.hpp"
#include "support/text.hpp"

namespace mhb {
namespace {

using mhb::test_support::count;

// The head and a few elements of what matplotlib 3.6 writes with svg.fonttype = none.
const std::string matplotlib_svg =
    "<?xml version=\"1.0\" encoding=\"utf-8\" standalone=\"no\"?>\n"
    "<!DOCTYPE svg PUBLIC \"-//W3C//DTD SVG 1.1//EN\"\n"
    "  \"http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd\">\n"
    "<svg xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"432pt\" height=\"288pt\" "
    "viewBox=\"0 0 432 288\" xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\">\n"
    " <metadata>\n  <rdf:RDF xmlns:dc=\"http://purl.org/dc/elements/1.1/\"><dc:title>x</dc:title>"
    "</rdf:RDF>\n </metadata>\n"
    " <defs>\n  <style type=\"text/css\">*{stroke-linejoin: round; stroke-linecap: butt}</style>\n </defs>\n"
    " <g id=\"figure_1\">\n"
    "  <path d=\"M 0 0 L 1 1\" clip-path=\"url(#p1a2b)\" style=\"fill: url(#grad)\"/>\n"
    "  <use xlink:href=\"#m0f\" x=\"1\" y=\"2\"/>\n"
    "  <a href=\"https://example.org/\"><text x='1' y=\"2\">a &lt; b</text></a>\n"
    "  <image xlink:href=\"data:image/png;base64,AAAA\"/>\n"
    "  <!-- a comment with <svg inside -->\n"
    "  <script>alert(1)</script>\n"
    " </g>\n"
    " <defs><clipPath id=\"p1a2b\"><rect x=\"0\"/></clipPath><path id=\"m0f\" d=\"M 0 0\"/></defs>\n"
    "</svg>\n";

TEST(HtmlSvg, DropsThePrologMetadataNamespacesAndScripts) {
    const std::string svg = inline_svg(matplotlib_svg, "s1", "convergence_iteration_sphere");
    EXPECT_EQ(svg.rfind("<svg ", 0), 0u) << svg.substr(0, 80);
    EXPECT_EQ(svg.substr(svg.size() - 6), "</svg>");
    EXPECT_EQ(svg.find("<?xml"), std::string::npos);
    EXPECT_EQ(svg.find("DOCTYPE"), std::string::npos);
    EXPECT_EQ(svg.find("metadata"), std::string::npos);
    EXPECT_EQ(svg.find("xmlns"), std::string::npos);
    EXPECT_EQ(svg.find("http"), std::string::npos) << svg;
    EXPECT_EQ(svg.find("<script"), std::string::npos);
    EXPECT_EQ(svg.find("alert"), std::string::npos);
    EXPECT_EQ(svg.find("comment"), std::string::npos);
    // What the figure shows stays: geometry, text (still escaped), the embedded raster image.
    EXPECT_NE(svg.find("viewBox=\"0 0 432 288\""), std::string::npos);
    EXPECT_NE(svg.find(">a &lt; b</text>"), std::string::npos);
    EXPECT_NE(svg.find("xlink:href=\"data:image/png;base64,AAAA\""), std::string::npos);
    EXPECT_NE(svg.find("<style type=\"text/css\">*{stroke-linejoin"), std::string::npos);
}

TEST(HtmlSvg, PrefixesEveryIdAndEveryReferenceToOne) {
    const std::string svg = inline_svg(matplotlib_svg, "s7", "name");
    EXPECT_NE(svg.find("<svg id=\"s7\" role=\"img\""), std::string::npos);
    EXPECT_NE(svg.find("id=\"s7-figure_1\""), std::string::npos);
    EXPECT_NE(svg.find("id=\"s7-p1a2b\""), std::string::npos);
    EXPECT_NE(svg.find("clip-path=\"url(#s7-p1a2b)\""), std::string::npos);
    EXPECT_NE(svg.find("style=\"fill: url(#s7-grad)\""), std::string::npos);
    EXPECT_NE(svg.find("xlink:href=\"#s7-m0f\""), std::string::npos);
    EXPECT_EQ(count(svg, "id=\"figure_1\""), 0u);
    EXPECT_EQ(count(svg, "url(#p"), 0u);
    // Two figures with the same ids no longer share one.
    const std::string other = inline_svg(matplotlib_svg, "s8", "name");
    EXPECT_EQ(count(svg + other, "id=\"s7-p1a2b\""), 1u);
    EXPECT_EQ(count(svg + other, "id=\"s8-p1a2b\""), 1u);
}

TEST(HtmlSvg, AddsATitleOnlyWhenTheFileHasNone) {
    const std::string svg = inline_svg(matplotlib_svg, "s1", "final_values_<pmsm>");
    EXPECT_NE(svg.find("<title>final_values_&lt;pmsm&gt;</title>"), std::string::npos);
    const std::string titled = inline_svg("<svg><title>Mine</title><g/></svg>", "s2", "other");
    EXPECT_EQ(titled, "<svg id=\"s2\" role=\"img\"><title>Mine</title><g/></svg>");
}

TEST(HtmlSvg, RejectsTextWithoutAnSvgElement) {
    EXPECT_THROW(inline_svg("", "s1", "x"), std::runtime_error);
    EXPECT_THROW(inline_svg("<?xml version=\"1.0\"?><svgfoo/>", "s1", "x"), std::runtime_error);
    EXPECT_THROW(inline_svg("<svg width=\"1\">truncated", "s1", "x"), std::runtime_error);
}

} // namespace
} // namespace mhb
