// Radiance HDR (RGBE) images (Ward, "Real Pixels", Graphics Gems II, 1991; the format of
// Radiance's `ra_*` tools): a text header ("#?RADIANCE" or "#?RGBE", lines up to an empty
// one: FORMAT=32-bit_rle_rgbe, EXPOSURE=e any number of times), a resolution line
// "-Y H +X W" (rows top to bottom, the only orientation lat-long maps use), then H scanlines
// of W pixels of four bytes (R, G, B mantissas and a shared exponent E), each flat or
// run-length encoded per channel ("new" RLE: 2, 2, W >> 8, W & 255, then for each channel
// runs of a count c > 128 repeating one byte c - 128 times or c <= 128 literal bytes).
//
// A channel m with exponent E is (m + 0.5) 2^(E - 136) (the centre of its quantisation
// step, as Radiance's own colr_color), 0 where E = 0; divided by the product of the
// EXPOSURE values (Radiance multiplies pixels by each). Decoding is bounded: every read is
// checked against the bytes there are, every run against the scanline's width, so a
// truncated or corrupt file is an error, never a hang or a read past the end (stb_image
// 2.27, which Debian ships, spins forever on a scanline cut after its RLE header).
#pragma once

#include <string>

#include "shading/environment/environment_map.h"

namespace shadowlab {

// Throws std::runtime_error naming `name` and what is wrong. Width and height are at most
// maxSide each.
EnvironmentMap parseRadianceHdr(const std::string& bytes, const std::string& name, int maxSide);

}  // namespace shadowlab
