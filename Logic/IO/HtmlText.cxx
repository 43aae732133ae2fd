#include "IO/HtmlText.h"

#include <cmath>
#include <cstdio>

#include "Common/Format.h"
#include "Pipeline/ValueText.h"

namespace sgp::html
{

std::string Escape(const std::string& text)
{
  std::string out;
  out.reserve(text.size());
  for (const char c : text)
    switch (c)
    {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  return out;
}

std::string Num(double value, int decimals)
{
  return std::isfinite(value) ? FormatNumber(value, decimals) : "n/a";
}

std::string C(double value)
{
  return FormatNumber(value, 2);
}

std::string ValueCell(const std::string& name, double value, const std::string& unit, const std::string& returned)
{
  return "<td class=\"num\" data-name=\"" + Escape(name) + "\" data-value=\"" + Escape(returned) + "\">" +
         Escape(ClinicalText(value, unit)) + "</td>";
}

std::string Rgb(const Eigen::Vector3d& rgb)
{
  char buffer[16];
  std::snprintf(buffer, sizeof(buffer), "#%02x%02x%02x", int(std::lround(255 * rgb[0])), int(std::lround(255 * rgb[1])),
                int(std::lround(255 * rgb[2])));
  return buffer;
}

std::string Polyline(const std::vector<std::pair<double, double>>& points)
{
  std::string s;
  for (const auto& [x, y] : points)
    s += C(x) + "," + C(y) + " ";
  return s;
}

} // namespace sgp::html
