/// \file CLPSupport.h
/// Helpers used by the generated `<Module>CLP.h` headers (CMake/GenerateCLP.py).
///
/// Slicer passes points and vectors as one comma-separated argument (`--seed 12.5,-3.25,40`).
/// SEM's GenerateCLP converts each component with `atof`, so `--seed a,b,c` silently becomes the
/// origin. Here every component must be a complete number, and a point must have exactly the
/// number of components it declares; anything else throws ParseError, which PARSE_ARGS turns into
/// one `ERROR: …` line on stderr and EXIT_FAILURE.
#pragma once

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace sgp::clp
{

/// A command-line value that cannot be converted; the message names the flag and the value.
class ParseError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// Splits "a,b,c" on commas (no trimming beyond spaces around each item).
inline std::vector<std::string> SplitStrings(const std::string& text)
{
  std::vector<std::string> items;
  std::string item;
  std::istringstream stream(text);
  while (std::getline(stream, item, ','))
  {
    const auto first = item.find_first_not_of(" \t");
    const auto last = item.find_last_not_of(" \t");
    items.push_back(first == std::string::npos ? std::string() : item.substr(first, last - first + 1));
  }
  return items;
}

/// Parses "x,y,z" into numbers of type T.
/// \param flag            the long flag, for the message
/// \param expectedCount   required number of components; 0 accepts any non-zero count
/// \throws ParseError     on an empty or non-numeric component or a wrong count
template<typename T>
std::vector<T> SplitNumbers(const std::string& text, const std::string& flag, std::size_t expectedCount)
{
  std::vector<T> values;
  for (const std::string& item : SplitStrings(text))
  {
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(item.c_str(), &end);
    // strtod reads "nan" and "inf" too: not a coordinate or a parameter.
    if (item.empty() || end != item.c_str() + item.size() || errno == ERANGE || !std::isfinite(value))
    {
      throw ParseError("--" + flag + " got '" + text + "': '" + item +
                       "' is not a number; expected comma-separated numbers, for example 1.5,-20,33");
    }
    if (std::is_integral<T>::value && value != static_cast<double>(static_cast<long long>(value)))
    {
      throw ParseError("--" + flag + " got '" + text + "': '" + item + "' is not a whole number");
    }
    values.push_back(static_cast<T>(value));
  }
  if (values.empty() || (expectedCount != 0 && values.size() != expectedCount))
  {
    throw ParseError(
      "--" + flag + " got '" + text + "' with " + std::to_string(values.size()) + " components; expected " +
      (expectedCount ? std::to_string(expectedCount) : std::string("one or more")) + " comma-separated numbers");
  }
  return values;
}

/// Replaces line breaks so that an error always stays on one stderr line.
inline std::string OneLine(std::string text)
{
  for (char& c : text)
  {
    if (c == '\n' || c == '\r')
    {
      c = ' ';
    }
  }
  return text;
}

template<typename T>
std::string Echo(const T& value)
{
  std::ostringstream out;
  out << value;
  return out.str();
}

template<typename T>
std::string Echo(const std::vector<T>& values)
{
  std::ostringstream out;
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    out << (i ? "," : "") << Echo(values[i]);
  }
  return out.str();
}

} // namespace sgp::clp
