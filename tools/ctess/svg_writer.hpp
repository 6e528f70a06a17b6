// A tiny SVG builder: the CLI's pictures are drawn with it so that every figure shares one look.
#pragma once
#include <string>

namespace ctess::cli {

class SvgWriter {
  public:
    SvgWriter(double width, double height);
    void line(double x0, double y0, double x1, double y1, const std::string& style);
    void polygon(const double* xy, int points, const std::string& style);
    void circle(double x, double y, double r, const std::string& style);
    void text(double x, double y, const std::string& content, const std::string& style);
    void raw(const std::string& element);
    std::string finish();

  private:
    std::string body_;
    double width_;
    double height_;
};

std::string escape_xml(const std::string& s);

} // namespace ctess::cli
