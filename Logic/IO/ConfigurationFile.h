/// \file ConfigurationFile.h
/// The configuration file a surgeon gives (--configuration) and the plan writes
/// (--outputConfiguration): one JSON object, schema Resources/configuration.schema.json, format
/// version 1. Round trip: plan → --outputConfiguration → edit one line → --configuration.
///
///     { "format": "StentGraftPlanner configuration", "formatVersion": 1,
///       "family": "Endurant II",
///       "mainBodySide": "right",                         (optional; "right" or "left")
///       "bodyLegLandsAlone": false,                      (optional)
///       "components": [
///         { "role": "mainBody", "code": "ETBF2816C145EE",
///           "proximalEdgeBelowLowestRenalMm": 2.5 },     (optional position)
///         { "role": "limb", "side": "right", "code": "ETLW1616C124E", "overlapMm": 35.0 },
///         { "role": "limb", "side": "left", "distalDiameterMm": 16, "lengthMm": 124,
///           "distalEdgeAboveInternalIliacMm": 8.0 },
///         { "role": "iliacExtension", "side": "left", "code": "…" } ] }
///
/// Per component: role ("mainBody", "limb", "iliacExtension"), side for limbs and extensions,
/// code or diameterMm / distalDiameterMm / lengthMm (the catalogue's fields and meanings), and at
/// most one position (GivenConfiguration.h). Unknown fields are rejected, so that a misspelt
/// position cannot silently vanish; "description" is free text. The resolution against the
/// catalogue and every rule between components are GivenConfiguration.h's.
/// \throws InputError "Configuration '<origin>', <field>: <value seen>; expected …" — one line.
#pragma once

#include <string>

#include "Device/GivenConfiguration.h"

namespace sgp
{

constexpr const char* ConfigurationFormat = "StentGraftPlanner configuration";
constexpr int ConfigurationFormatVersion = 1;

/// Parses the text of a configuration file (`origin` names it in messages).
GivenConfiguration ParseConfiguration(const std::string& text, const std::string& origin);

/// Reads the file at `path`. \throws InputError when it cannot be read, or as ParseConfiguration.
GivenConfiguration ReadConfiguration(const std::string& path);

/// The file's text for `configuration` (keys in the order above, positions at full precision so that
/// the round trip is exact, NaN fields left out), with `description` when not empty.
std::string ConfigurationJson(const GivenConfiguration& configuration, const std::string& description);

} // namespace sgp
