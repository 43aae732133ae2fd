/// \file JsonText.h
/// The words the JSON readers (device catalogue, hostile-neck rules) use in their one-line
/// errors: the value seen, briefly, and nlohmann's own message without its code prefix.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace sgp
{

/// "the string \"23\"", "the number 23", "an array [...]", "null" — at most 40 characters of it.
std::string DescribeJsonValue(const nlohmann::json& value);

/// nlohmann's exception text without its "[json.exception.parse_error.101] " prefix, on one line.
std::string JsonErrorMessage(const std::string& what);

} // namespace sgp
