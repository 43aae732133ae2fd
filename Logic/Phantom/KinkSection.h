/// \file KinkSection.h
/// The truth of a diameter at a level near the phantom's neck bend, where the bend's other straight
/// piece reaches into the level's plane.
///
/// The phantom's aorta bends by the neck angle β at one point (the sac's top): two straight pieces
/// of axis meeting at a kink. Away from it, the plane ⊥ a piece at a level cuts a disc of the
/// radius profile's value there, the truth's nominal diameter. Near it, the other piece's tube
/// reaches into that plane (the inner side of the bend overlaps, the outer side is cut by the
/// nearer-piece rule), and the section is neither a disc nor the nominal diameter — on issue 32's
/// sweep the lumen's section through the level's centre measured 1.1–7 mm wider than the nominal
/// value in every plane between the two pieces' normals. No plane there is *the* perpendicular
/// one (the axis' direction jumps), so the truth there is the section by the plane through the
/// level's centre that gives the smallest mean diameter, the plane a reader turns a double-oblique
/// reformat to; on a straight tube it is the perpendicular plane, the nominal value.
///
/// KinkReachMm: how far from the kink, along either piece, the other piece's solid can reach a
/// plane ⊥ the piece: max over u ≥ 0 of r(u)·sin β − u·cos β, where r(u) is the other piece's
/// radius u mm from the kink (`otherRadius`); 0 for β = 0. mm.
///
/// SectionMeanDiameterMm: the mean over `directions` diameters (equally spaced over 180°) of the
/// chords through `centre` in the plane ⊥ `normal`: along each half-ray the first point where
/// `inside` turns false (0.25 mm march, then bisection to 0.1 µm), at most 200 mm out.
///
/// SmallestSectionMeanDiameterMm: the smallest SectionMeanDiameterMm over planes through `centre`
/// whose normal lies within 10° of the arc from `from` to `to` (the two pieces' directions):
/// a 1° grid along the arc and out of its plane, then 0.2° around the best.
///
/// Input: LPS mm; `inside` the solid (true inside); `centre` inside it; directions need not be unit.
/// Errors: none.
#pragma once

#include <functional>

#include "Common/Types.h"

namespace sgp::phantom
{

double KinkReachMm(const std::function<double(double)>& otherRadius, double betaRad);

double SectionMeanDiameterMm(const std::function<bool(const Point3&)>& inside,
                             const Point3& centre,
                             const Eigen::Vector3d& normal,
                             int directions = 36);

double SmallestSectionMeanDiameterMm(const std::function<bool(const Point3&)>& inside,
                                     const Point3& centre,
                                     const Eigen::Vector3d& from,
                                     const Eigen::Vector3d& to);

} // namespace sgp::phantom
