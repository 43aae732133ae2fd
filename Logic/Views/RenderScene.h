/// \file RenderScene.h
/// A small software renderer for the report's 3-D view of the graft in the vessel (issue 30): no
/// display, no OpenGL — Debian's VTK 9.1 renders through X/GLX only, which a headless CLI run does
/// not have. Triangles are projected orthographically, hidden surfaces removed with a z-buffer,
/// shaded by Lambert's law with a headlight (intensity 0.3 + 0.7 |n·d|, n the normal interpolated
/// from the vertices' normals, d the viewing direction), opaque meshes first, then the translucent
/// ones blended over what lies behind them (colour ← (1 − α) colour + α shade, front and back
/// faces alike, so a translucent vessel shows its two walls).
///
/// Frames: meshes in LPS mm. A view is an orthonormal (right, up, forward) frame: image x grows
/// along `right`, image y downward (against `up`), depth along `forward` (away from the viewer).
/// The image frames every mesh's vertices with `marginMm` around them, `widthPx` wide, square
/// pixels. Output: RGB, 8 bits a channel, row 0 at the top, background white.
/// Errors: InputError for a view whose axes are not orthonormal, a mesh whose colours or indices
/// do not match its vertices, or an empty scene.
/// Complexity: linear in the triangles plus the pixels each covers.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "Common/Types.h"

namespace sgp
{

/// A triangle mesh to draw: vertices (#V×3, LPS mm), triangles (#F×3 indices), a colour per
/// vertex (#V×3, each 0…1; interpolated across each triangle) or, when `faceRgb` is given, one per
/// triangle (#F×3: flat, for parts that must not blend into each other), and an opacity (1 opaque;
/// below 1 translucent, blended).
struct SceneMesh
{
  std::string name;
  Points V;
  Triangles F;
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> rgb;
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> faceRgb;
  double opacity = 1.0;
};

struct SceneView
{
  std::string name; ///< e.g. "anterior"
  Eigen::Vector3d right = Eigen::Vector3d::UnitX();
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d forward = Eigen::Vector3d::UnitY();
};

/// From the front (the patient's right on the image's left, superior up): forward = +y (LPS
/// posterior), right = +x (the patient's left).
SceneView AnteriorView();
/// From the patient's left (anterior on the image's left): forward = −x, right = +y.
SceneView LeftLateralView();

struct RenderedImage
{
  int width = 0;
  int height = 0;
  double pixelMm = 1.0;
  std::vector<std::uint8_t> rgb; ///< width × height × 3, row-major from the top
  const std::uint8_t* At(int col, int row) const { return &rgb[(static_cast<std::size_t>(row) * width + col) * 3]; }
};

RenderedImage RenderScene(const std::vector<SceneMesh>& meshes,
                          const SceneView& view,
                          int widthPx = 480,
                          double marginMm = 5.0);

/// Per-vertex unit normals: the area-weighted mean of the adjacent triangles' normals.
Points VertexNormals(const Points& V, const Triangles& F);

} // namespace sgp
