/// \file EncodePng.h
/// A resliced CT plane (ResliceCt.h) as an 8-bit grey PNG in memory (VTK's PNG writer), a rendered
/// 3-D view (RenderScene.h) as an 8-bit RGB one, and the base64 data URI a self-contained HTML page
/// embeds them with.
///
/// Window: HU at or below `lowHu` is black, at or above `highHu` white, linear between. Row 0 of
/// the plane is the PNG's top row. Errors: InputError when the image is empty or the window empty
/// (lowHu ≥ highHu); std::runtime_error when VTK produces no bytes.
#pragma once

#include <string>
#include <string_view>

#include "Views/RenderScene.h"
#include "Views/ResliceCt.h"

namespace sgp
{

/// The PNG file's bytes.
std::string EncodeGreyPng(const PlaneImage& image, double lowHu, double highHu);

/// RFC 4648 base64 of `bytes` (with padding).
std::string Base64(std::string_view bytes);

/// "data:image/png;base64,…" of EncodeGreyPng.
std::string PngDataUri(const PlaneImage& image, double lowHu, double highHu);

/// A rendered RGB image (RenderScene.h) as a PNG file's bytes, row 0 the top row; InputError when
/// it is empty or its pixels do not match its size.
std::string EncodeRgbPng(const RenderedImage& image);

/// "data:image/png;base64,…" of EncodeRgbPng.
std::string PngDataUri(const RenderedImage& image);

} // namespace sgp
