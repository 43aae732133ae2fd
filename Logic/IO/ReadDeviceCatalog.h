/// \file ReadDeviceCatalog.h
/// Reads and validates the stent-graft device catalogue, a JSON file (Resources/devices.json).
///
/// Format, version 1 (all numbers JSON numbers; unknown fields are rejected, so that a
/// misspelt optional criterion cannot silently vanish):
///
///     { "formatVersion": 1, "description": "…",
///       "families": [ {
///         "name": "Endurant II", "manufacturer": "Medtronic",
///         "source": "…", "note": "verify against the current IFU",
///         "mainBodies": { "sizes": [ { "diameterMm": 23, "profileFr": 18 }, … ],
///                         "lengthRangeMm": { "min": 120, "max": 180 },   (optional)
///                         "lengthToFlowDividerMm": [ 55, 65 ],           (optional)
///                         "evidence": "[K] …" },
///         "limbs": { "sizes": [ … ], "lengthRangeMm": { … } (optional), "evidence": "…" },
///         "ifu": {
///           "neckLength": { "tiers": [ { "minMm": 10, "maxBetaDeg": 60 }, … ], "evidence": "…" },
///           "neckDiameterMm": { "min": 19, "max": 32, "evidence": "…" },
///           "neckAngleAlphaDeg": { "max": 45, "evidence": "…" },        (optional)
///           "iliacSealLengthMm": { "min": 15, "evidence": "…" },
///           "iliacDiameterMm": { "min": 8, "max": 25, "evidence": "…" } } } ] }
///
/// Required: formatVersion, families; per family name, source, mainBodies, limbs, ifu; per
/// component sizes; per size diameterMm and profileFr; per criterion its limits. Optional
/// strings (description, manufacturer, note, evidence) default to empty. Units: see
/// DeviceCatalog.h. The file is not checked beforehand (under Slicer a path may be a memory
/// reference); the read's failure becomes the message.
///
/// After parsing, ValidateDeviceCatalog checks the semantic rules (DeviceCatalog.h), with the
/// path as the catalogue's origin.
///
/// \throws InputError, one line, naming the file, and where it applies the entry
///         ("families[1] \"Excluder (C3)\"" or the index alone when the name is the problem),
///         the field (a path such as 'mainBodies.sizes[2].diameterMm'), the value seen and what
///         was expected: file unreadable; malformed JSON (with line and column); a missing
///         field; a wrong type; an unknown field; a format version other than 1; any semantic
///         rule.
#pragma once

#include <string>

#include "Device/DeviceCatalog.h"

namespace sgp
{

DeviceCatalog ReadDeviceCatalog(const std::string& path);

/// The same from JSON text already in memory; `origin` names it in messages.
DeviceCatalog ParseDeviceCatalog(const std::string& text, const std::string& origin);

} // namespace sgp
