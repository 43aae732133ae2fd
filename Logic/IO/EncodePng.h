/// \file EncodePng.h
/// A resliced CT plane (ResliceCt.h) as an 8-bit grey PNG in memory (VTK's PNG writer), and the
/// base64 data URI a self-contained HTML page embeds it with.
///
/// Window: HU at or below `lowHu` is black, at or above `highHu` white, linear between. Row 0 of
/// the plane is the PNG's top row. Errors: InputError when the image is empty or the window empty
/// (lowHu ≥ highHu); std::runtime_error when VTK produces no bytes.
#pragma once

#include <string>
#include <string_view>

#include "Views/ResliceCt.h"

namespace sgp
{

/// The PNG file's bytes.
std::string EncodeGreyPng(const PlaneImage& image, double lowHu, double highHu);

/// RFC 4648 base64 of `bytes` (with padding).
std::string Base64(std::string_view bytes);

/// "data:image/png;base64,…" of EncodeGreyPng.
std::string PngDataUri(const PlaneImage& image, double lowHu, double highHu);

} // namespace sgp
