/// \file HtmlText.h
/// The small pieces the visual report (ReportHtml.h) writes its HTML and SVG with: escaped text,
/// numbers at the precision a person reads, SVG coordinates, value cells that carry the
/// return-file text for machines, colours. No state; nothing here throws.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace sgp::html
{

/// `text` with & < > " escaped, for element text and attribute values.
std::string Escape(const std::string& text);

/// `value` with `decimals` decimals (Format.h), "n/a" when not finite.
std::string Num(double value, int decimals = 1);

/// An SVG coordinate (mm in the viewBox), two decimals.
std::string C(double value);

/// A value cell a person reads: the value at clinical precision (ValueText.h), its return-file
/// text (full precision) in data-value, its return parameter's name in data-name.
std::string ValueCell(const std::string& name, double value, const std::string& unit, const std::string& returned);

/// An RGB colour, components 0…1, as "#rrggbb".
std::string Rgb(const Eigen::Vector3d& rgb);

/// The points of an SVG polyline or polygon, "x,y x,y …" in viewBox units.
std::string Polyline(const std::vector<std::pair<double, double>>& points);

} // namespace sgp::html
