// A 5×7 pixel font for labels in relmap's pictures: digits, capitals and the
// punctuation of numbers and axis titles.
#pragma once

#include <array>
#include <cstdint>

namespace relmap::image {

// Seven rows, top first; bit 4 of a row is its leftmost pixel.
using Glyph = std::array<std::uint8_t, 7>;

// The glyph of `c` (lower case as upper case); a hollow box for characters the
// font does not have.
const Glyph& GlyphOf(char c);

}  // namespace relmap::image
