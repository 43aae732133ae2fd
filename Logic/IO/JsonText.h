/// \file JsonText.h
/// The words and checks the JSON readers (device catalogue, hostile-neck rules) share in their
/// one-line errors: the value seen, briefly, what a field must be, and nlohmann's own message
/// without its code prefix.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sgp
{

/// "the string \"23\"", "the number 23", "an array [...]", "null" — at most 40 characters of it.
std::string DescribeJsonValue(const nlohmann::json& value);

/// "a number", "a string", "an array", "true or false" or "an object": what a field of that type
/// must be.
std::string JsonTypeWords(nlohmann::json::value_t type);

/// What is wrong with `object[key]` as a field of `type` (any number for number_float): "is
/// missing", "is the string \"23\"", …; empty when it is fine.
std::string JsonMemberMismatch(const nlohmann::json& object, const std::string& key, nlohmann::json::value_t type);

/// The first key of `object` not in `allowed`; empty when there is none.
std::string UnknownJsonKey(const nlohmann::json& object, const std::vector<std::string>& allowed);

/// nlohmann's exception text without its "[json.exception.parse_error.101] " prefix, on one line.
std::string JsonErrorMessage(const std::string& what);

} // namespace sgp
