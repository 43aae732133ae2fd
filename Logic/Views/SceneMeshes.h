/// \file SceneMeshes.h
/// What the report's 3-D view shows (RenderScene.h): the lumen's surface and the traced outer wall,
/// translucent, and the simulated graft with each component in its own colour — the paper's
/// figures 4 and 5 (Egger et al. 2007), from the plan.
///
///  - **Lumen**: the boundary of the lumen mask inside an LPS box, by surface nets (one vertex per
///    voxel cell the boundary crosses, at the mean of the crossed edges' midpoints; one quad per
///    crossed voxel edge between the four cells around it), then smoothed by `smoothing` rounds of
///    moving each vertex half-way to its neighbours' mean (the voxel staircase otherwise shows).
///    Red, opacity 0.3.
///  - **Outer wall**: each vessel's traced contours (VesselWall) joined plane to plane into a tube,
///    across consecutive usable planes. Tan, opacity 0.15.
///  - **Graft**: the fitted surface's triangles, each vertex coloured by its component
///    (ComponentColour). Opaque.
/// Input: LPS mm; the mask on its own grid (spacing and direction honoured). Pure; no errors
/// beyond an empty box (an empty mesh).
#pragma once

#include <array>

#include "Device/DeployGraft.h"
#include "Views/RenderScene.h"
#include "Wall/VesselWall.h"

namespace sgp
{

/// The lumen's surface inside the box {lo, hi} (LPS mm).
SceneMesh LumenSurface(const LabelImage& mask, const Point3& lo, const Point3& hi, int smoothing = 6);

/// The outer wall's traced contours as tubes.
SceneMesh OuterWallSurface(const VesselWall& wall);

/// The simulated graft, coloured by component.
SceneMesh GraftSurface(const DeployedGraft& graft);

/// A component's colour (0…1 RGB) by its role and side: main body blue, ipsilateral limb green,
/// contralateral limb orange, iliac extension purple, aortic cuff teal (the same in the report's
/// legend and the Slicer panel).
Eigen::Vector3d ComponentColour(const ConfiguredComponent& component);

/// The box around the graft's vertices, grown by `marginMm`, as {lo, hi} (LPS mm).
std::array<Point3, 2> GraftBox(const DeployedGraft& graft, double marginMm);

} // namespace sgp
