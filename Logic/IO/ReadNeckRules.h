/// \file ReadNeckRules.h
/// Reads and validates a hostile-neck rule set, a JSON file (Resources/hostile-neck-rules.json,
/// installed beside the StentGraftSimulation CLI; `--neckRules` replaces it).
///
/// Format "sgp-hostile-neck-rules", version 1 (numbers are JSON numbers; unknown fields are
/// rejected, so that a misspelt field cannot silently vanish):
///
///     { "format": "sgp-hostile-neck-rules", "version": 1,
///       "name": "StentGraftPlanner default hostile-neck rules",
///       "description": "…",                                         (optional)
///       "rules": [ {
///         "id": "short-neck", "quantity": "neckLength", "hostileWhen": "below",
///         "threshold": 15, "unit": "mm",
///         "description": "…", "source": "[S] Leicester 2012, …" }, … ] }
///
/// Required: format, version, name, rules; every rule field (description may be an empty
/// string). `hostileWhen` is "below", "atOrBelow", "above" or "atOrAbove"; quantities, units,
/// ranges and the inclusivity convention are in Device/HostileNeck.h. The file is not checked
/// beforehand (under Slicer a path may be a memory reference); the read's failure becomes the
/// message. After parsing, ValidateNeckRuleSet checks the semantic rules with the path as the
/// set's origin.
///
/// \throws InputError, one line, naming the file, and where it applies the rule ("rules[2]
///         \"short-neck\"", or the index alone when the id is the problem), the field, the value
///         seen and what was expected: file unreadable; malformed JSON (with line and column); a
///         missing field; a wrong type; an unknown field; a format other than
///         "sgp-hostile-neck-rules" or a version other than 1; an unknown hostileWhen; any
///         semantic rule (empty rules, duplicate id, unknown quantity, wrong unit, non-finite
///         or out-of-range threshold, empty source).
#pragma once

#include <string>

#include "Device/HostileNeck.h"

namespace sgp
{

/// The `format` string of a rule file and the only version this build reads.
constexpr const char* NeckRulesFormat = "sgp-hostile-neck-rules";
constexpr int NeckRulesFormatVersion = 1;

/// The file name of the bundled rule set, installed beside the CLI.
constexpr const char* NeckRulesFileName = "hostile-neck-rules.json";

NeckRuleSet ReadNeckRules(const std::string& path);

/// The same from JSON text already in memory; `origin` names it in messages.
NeckRuleSet ParseNeckRules(const std::string& text, const std::string& origin);

/// The bundled rule set beside the running executable: <dir of /proc/self/exe, or of `argv0`
/// made absolute when that cannot be read>/hostile-neck-rules.json. CMake copies
/// Resources/hostile-neck-rules.json beside the CLIs in the build tree and on install, as it does
/// devices.json. Not checked for existence (the read reports it).
std::string DefaultNeckRulesPath(const std::string& argv0);

} // namespace sgp
