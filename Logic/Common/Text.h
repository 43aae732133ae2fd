/// \file Text.h
/// Small text helpers for names read from files (catalogue families, rule ids): compared
/// case-insensitively and without surrounding blanks, and listed in error messages.
#pragma once

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

namespace sgp
{

/// `text` in lower case (ASCII).
inline std::string LowerCase(const std::string& text)
{
  std::string lower = text;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return lower;
}

/// `text` without leading and trailing spaces and tabs.
inline std::string TrimBlanks(const std::string& text)
{
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos)
    return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

/// "a, b, c" (empty for no items): the lists of admissible names in error messages.
inline std::string JoinWithCommas(const std::vector<std::string>& items)
{
  std::string list;
  for (const std::string& item : items)
    list += (list.empty() ? "" : ", ") + item;
  return list;
}

/// A camelCase identifier in words, as a person reads it: "leftInternalIliac" → "left internal
/// iliac", "rightAccessoryRenal" → "right accessory renal", "aorta" → "aorta" (ASCII capitals are
/// split off and lowered). The one used for every name a person reads (vessels, landmarks, values).
inline std::string IdentifierWords(const std::string& identifier)
{
  std::string words;
  for (char c : identifier)
  {
    if (c >= 'A' && c <= 'Z')
    {
      if (!words.empty())
        words += ' ';
      words += char(c - 'A' + 'a');
    }
    else
      words += c;
  }
  return words;
}

} // namespace sgp
