/// \file WriteStentModel.h
/// Writes a stent surface for 3D Slicer (through WriteModelLps: LPS, `SPACE` = `LPS`, .vtp/.vtk):
/// the triangles of the mesh at vertex positions `V` (#V×3, LPS mm), with point data `Segment`
/// (0 trunk, 1 right leg, 2 left leg), `Ring`, `Radius` (mm, from the ring's centerline point in
/// its plane) and `WallDistance` (mm, signed, negative inside the lumen).
/// \throws InputError naming the path when it cannot be written.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "Stent/StentMesh.h"

namespace sgp
{

void WriteStentModel(const StentMesh& mesh,
                     const Points& V,
                     const Eigen::VectorXd& radiusMm,
                     const Eigen::VectorXd& wallDistanceMm,
                     const std::string& path);

/// The same with further point-data arrays (name, #V values), e.g. the simulated graft's
/// Oversizing (%), Apposition (mm) and Sealing (0/1).
void WriteStentModel(const StentMesh& mesh,
                     const Points& V,
                     const Eigen::VectorXd& radiusMm,
                     const Eigen::VectorXd& wallDistanceMm,
                     const std::vector<std::pair<std::string, Eigen::VectorXd>>& extra,
                     const std::string& path);

/// A model with no points, standing for a stent graft that was not simulated: its field data holds
/// one string array `NotSimulated` with `reason` (why there is no graft), and `SPACE` = `LPS`.
/// Slicer loads it as an empty model; a plan without a fitting device is a result, not an error.
void WriteNotSimulatedModel(const std::string& reason, const std::string& path);

} // namespace sgp
