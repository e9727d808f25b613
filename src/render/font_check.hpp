// A TrueType file checked before stb_truetype sees it. stb_truetype trusts
// every offset and count in the file (its author says so), so a truncated or
// damaged font made it read past the buffer and crash. This walks what it
// will read: the table directory, head, hhea, hmtx, maxp, loca, every glyph's
// outline record and composite references, and the Unicode cmap subtables.
#pragma once

#include <string>
#include <string_view>

namespace tumble::render {

/// Empty when stb_truetype can read `font` (the whole file) within its bytes;
/// else what is wrong ("table 'glyf' ends past the end of the file").
std::string truetype_problem(std::string_view font);

}  // namespace tumble::render
