/// \file GivenLandmarks.h
/// Landmarks a person gave, put into the labelled tree in place of the ones found (DESIGN.md,
/// "What the surgeon gives wins"); every stage after the labelling reads them through
/// FindAorticBifurcation and InternalIliacOriginAbscissa (VesselOrigins.h), so the lengths, the
/// landing zones, the configuration and the simulated graft's coverage follow.
///
///  - **Internal iliac origin** (per side): the nearest point of that side's iliac centerline
///    (its abscissa is the origin). The side branch of that iliac whose junction lies nearest to
///    it along the iliac, within SnapBranchMm, becomes the internal iliac (the one the labelling
///    took, if another, is numbered as an iliac branch): its centerline gives the ostium and the
///    radius the configuration and the fit check use. With no branch that near, the iliac has no
///    internal iliac centerline (the origin alone bounds the landing zone).
///  - **Aortic bifurcation**: used where it is given (the axes' meeting point lies in the merged
///    cross-section, off the skeleton); its abscissa is measured as the found one's, along the
///    aorta's end tangent from the centerline's last point.
///  - The lowest renal ostium is ProximalSite's (FindProximalSite with the point).
///
/// Input: the labelled tree (LPS mm) and the points (LPS mm). Output: the tree, changed in place.
/// Errors (InputError, naming the distance and the centerline): an internal iliac origin more
/// than MaxOriginDistanceMm from its iliac's centerline, or nearer the other side's iliac (a right
/// origin given on the patient's left); a bifurcation more than MaxBifurcationDistanceMm from the
/// aorta's lower end; a landmark given for an iliac the tree does not hold.
#pragma once

#include <array>
#include <optional>

#include "Centerlines/Centerlines.h"

namespace sgp
{

/// How far a given internal iliac origin may lie from its iliac's centerline, mm: an origin is on
/// the centerline's branching point, within the common iliac's radius (5–12 mm vessels) of it.
constexpr double MaxOriginDistanceMm = 10.0;
/// How far a given bifurcation may lie from the aorta's lower end (the skeleton's junction), mm:
/// the axes' meeting point lies 2–6 mm above it on the phantoms and real aneurysms, the flow
/// divider a few mm below.
constexpr double MaxBifurcationDistanceMm = 15.0;
/// A side branch whose junction lies this near a given origin (along the iliac) is its internal
/// iliac, mm: the skeleton's junction lies distal to the true origin by about the two radii.
constexpr double SnapBranchMm = 10.0;

struct GivenLandmarks
{
  std::optional<Point3> aorticBifurcationLps;
  std::array<std::optional<Point3>, 2> internalIliacOriginLps; ///< right (0), left (1)
  bool Any() const { return aorticBifurcationLps || internalIliacOriginLps[0] || internalIliacOriginLps[1]; }
};

/// Puts `given` into `tree` (file comment). \throws InputError as listed there.
void ApplyGivenLandmarks(CenterlineTree& tree, const GivenLandmarks& given);

} // namespace sgp
