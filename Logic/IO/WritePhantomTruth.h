/// \file WritePhantomTruth.h
/// Writes the ground truth of a SyntheticAorticPhantom as JSON.
///
/// Layout (all lengths mm, points LPS unless the key says RAS):
/// `{ "frame": "LPS", "units": "mm", "grid": {"size", "spacing", "origin", "direction"},
///    "seedLps": [x,y,z], "seedRas": [x,y,z], "lumenVolumeMl": v,
///    "sizing": {"proximalNeckDiameter": …, … (the names of DESIGN.md's contract)},
///    "landmarks": {"aorticBifurcation": [x,y,z], …},
///    "vessels": [{"name": "aorta", "points": [[x,y,z], …], "radiusMm": […]}, …],
///    (the aorta of a phantom with a wall also has "outerRadiusMm": the outer wall's round
///    profile at each point, for the outer diameters' truth along the axis),
///    "labels": {"0": "tissue", "1": "lumen", "2": "bone", "3": "kidney"} }`.
/// "direction" lists the three axis directions one after another, as the CLI's directionLps.
///
/// \throws InputError naming the path when it cannot be written.
#pragma once

#include <string>

#include "Phantom/AorticPhantom.h"

namespace sgp
{

void WritePhantomTruth(const AorticPhantom& phantom, const std::string& path);

} // namespace sgp
