// Images made from images: a smaller copy (sRGB-aware resampling, stb_image_resize)
// and one image pasted into another, e.g. the tiles of a contact sheet.
#pragma once

#include "io/image.hpp"

namespace tumble::io {

/// `image` resampled to width × height (Mitchell filter on linear light, as
/// stb_image_resize does for sRGB); `image` itself when the size is its own.
/// Deterministic: the same input gives the same bytes. Throws
/// std::invalid_argument on an empty size.
Image resized(const Image& image, int width, int height);

/// Copies `part` into `into` with its top-left corner at (x, y); what falls
/// outside `into` is left out.
void paste(Image& into, const Image& part, int x, int y);

/// A width × height image of one colour.
Image filled(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b);

}  // namespace tumble::io
