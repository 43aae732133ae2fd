/// \file Errors.h
/// The two exception types of StentGraftPlanner's Logic (STYLE.md B5).
///
/// Every message has four parts: what failed, the value observed (with units and frame), what
/// was expected, and what the user can do. ITK exceptions pass through as std::exception.
#pragma once

#include <stdexcept>

namespace sgp
{

/// The caller's data breaks a precondition (a seed outside the image, an inverted window, …).
class InputError : public std::invalid_argument
{
public:
  using std::invalid_argument::invalid_argument;
};

/// The input was valid but no trustworthy result came out (the region leaked, …).
class AlgorithmError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

} // namespace sgp
