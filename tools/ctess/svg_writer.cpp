#include "svg_writer.hpp"

#include <fmt/core.h>

namespace ctess::cli {

SvgWriter::SvgWriter(double width, double height) : width_(width), height_(height) {}

void SvgWriter::line(double x0, double y0, double x1, double y1, const std::string& style) {
    body_ += fmt::format("<line x1=\"{:.2f}\" y1=\"{:.2f}\" x2=\"{:.2f}\" y2=\"{:.2f}\" {}/>\n", x0, y0, x1,
                         y1, style);
}

void SvgWriter::polygon(const double* xy, int points, const std::string& style) {
    body_ += "<polygon points=\"";
    for (int i = 0; i < points; ++i)
        body_ += fmt::format("{}{:.2f},{:.2f}", i ? " " : "", xy[2 * i], xy[2 * i + 1]);
    body_ += fmt::format("\" {}/>\n", style);
}

void SvgWriter::circle(double x, double y, double r, const std::string& style) {
    body_ += fmt::format("<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.2f}\" {}/>\n", x, y, r, style);
}

void SvgWriter::text(double x, double y, const std::string& content, const std::string& style) {
    body_ += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" {}>{}</text>\n", x, y, style, escape_xml(content));
}

void SvgWriter::raw(const std::string& element) {
    body_ += element;
}

std::string SvgWriter::finish() {
    return fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
        "font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n"
        "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n{2}</svg>\n",
        width_, height_, body_);
}

std::string escape_xml(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '&':
            out += "&amp;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

} // namespace ctess::cli
