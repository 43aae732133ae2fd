/// \file ReadDeviceCatalog.h
/// Reads and validates the stent-graft device catalogue, a JSON file (Resources/devices.json).
///
/// Format, version 2 (all numbers JSON numbers; unknown fields are rejected, so that a
/// misspelt optional criterion cannot silently vanish):
///
///     { "formatVersion": 2, "description": "…",
///       "families": [ {
///         "name": "Endurant II", "manufacturer": "Medtronic",
///         "source": "…", "note": "verify against the current IFU", "verified": false,
///         "diameterReference": "outerWall",
///         "mainBodies": { "name": "Endurant II bifurcated main body", "evidence": "[S2 …] …",
///           "items": [ { "code": "ETBF2313C124E", "diameterMm": 23, "distalDiameterMm": 13,
///                        "lengthMm": 124, "profileFr": 18, "flowDividerMm": 40, "gateEndMm": 74,
///                        "gateDiameterMm": 12, "crotchWidthMm": 25 }, … ] },
///         "limbs": { "name": …, "evidence": …, "items": [ { "code": "ETLW1610C082E",
///                    "diameterMm": 16, "distalDiameterMm": 10, "lengthMm": 82, "profileFr": 14,
///                    "conflicts": [ { "field": "lengthMm", "values": [93, 95], "note": "…" } ] }, … ] },
///         "iliacExtensions": { … },                                       (optional)
///         "aorticCuffs": { … },                                           (optional)
///         "junctions": { "overlapMm": { "min": 30, "max": null, "evidence": "…" },
///                        "gateClearanceMm": { "min": 10, "evidence": "…" } },
///         "ifu": {
///           "neckLength": { "tiers": [ { "minMm": 10, "maxBetaDeg": 60 }, … ], "evidence": "…" },
///           "neckDiameterMm": { "min": 19, "max": 32, "evidence": "…" },
///           "neckAngleAlphaDeg": { "max": 45, "evidence": "…" },        (optional)
///           "iliacSealLengthMm": { "min": 15, "evidence": "…" },
///           "iliacDiameterMm": { "min": 8, "max": 25, "evidence": "…" } } } ] }
///
/// Required: formatVersion, families; per family name, source, verified, diameterReference,
/// mainBodies, limbs, junctions, ifu; per group items (at least one); per component code and
/// diameterMm, distalDiameterMm, lengthMm, profileFr (and on main bodies flowDividerMm, gateEndMm,
/// gateDiameterMm, crotchWidthMm) — each a value, or null where no public source gives it (a code
/// that is not public; a length not found): a *missing* field is an error, an unknown one is null.
/// A component's name and evidence default to its group's. Per criterion its limits. Optional
/// strings (description, manufacturer, note, evidence) default to empty. Units: see
/// DeviceCatalog.h. The selection's sizes are derived from the components
/// (DeriveSizesFromComponents). The file is not checked beforehand (under Slicer a path may be a
/// memory reference); the read's failure becomes the message.
///
/// After parsing, ValidateDeviceCatalog checks the semantic rules (DeviceCatalog.h), with the
/// path as the catalogue's origin.
///
/// \throws InputError, one line, naming the file, and where it applies the entry
///         ("families[1] \"Excluder (C3)\"" or the index alone when the name is the problem), the
///         component ("component mainBodies.items[3] ETBF2313C124E") and the field (a path such as
///         'mainBodies.items[2].lengthMm' while reading, the component's field once read), the
///         value seen and what was expected: file unreadable; malformed JSON (with line and
///         column); a missing field; a wrong type; an unknown field; a format version other than
///         2; any semantic rule.
#pragma once

#include <string>

#include "Device/DeviceCatalog.h"

namespace sgp
{

DeviceCatalog ReadDeviceCatalog(const std::string& path);

/// The same from JSON text already in memory; `origin` names it in messages.
DeviceCatalog ParseDeviceCatalog(const std::string& text, const std::string& origin);

} // namespace sgp
