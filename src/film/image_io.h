// Reading and writing images. Writers never leave a partial file behind: they write a
// temporary file in the destination's directory and rename it into place (atomic on POSIX
// file systems), so an interrupted or failed run leaves either the previous file or none.
// Failures throw std::runtime_error naming the file and the reason.
#pragma once

#include "film/image.h"

#include <cstdint>
#include <map>
#include <string>

namespace caustica {

enum class ExrPixelType { Float, Half };

// OpenEXR with R, G, B channels (ZIP compression), the image's crop as the data window within
// the full frame as the display window, and each metadata entry as a string attribute. Half
// floats (pbrt's "savefp16") clamp values above the largest half, 65504, as pbrt-v4 does.
void write_exr(const std::string &path, const Image &image,
               const std::map<std::string, std::string> &metadata,
               ExrPixelType pixel_type = ExrPixelType::Float);

// 8-bit sRGB PNG through the OpenImageIO plugin, tone mapped with tone_map_clamp_srgb8().
void write_png(const std::string &path, const Image &image);

// The R, G, B channels of an OpenEXR file as floats (a luminance-only "Y" file is read as
// grey), and its layers NAME.R/G/B; origin and full_resolution come from its data and display
// windows. With `metadata`, its string attributes too.
Image read_exr(const std::string &path, std::map<std::string, std::string> *metadata = nullptr);

// The sRGB transfer curve (IEC 61966-2-1) from linear to encoded values, for values in [0, 1].
float srgb_encode(float linear);

// The PNG tone map, named "clamp + sRGB": linear values are clamped to [0, 1] (no exposure
// change, no highlight compression; NaN counts as 0), encoded with the sRGB curve and rounded to
// the nearest 8-bit level. This is what pbrt-v4 does when it writes 8-bit images.
uint8_t tone_map_clamp_srgb8(float linear);

} // namespace caustica
